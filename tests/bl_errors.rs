//! Invalid inputs give one-line errors, never panics or non-finite results.

use polargen::boundary_layer::{BlConditions, BlError, BlModel, BlParams, Regime, StationVars};

fn model() -> BlModel {
    BlModel::new(&BlConditions::default(), BlParams::default()).expect("valid conditions")
}

fn good() -> StationVars {
    StationVars {
        x: 0.3,
        u: 1.1,
        theta: 5e-4,
        dstar: 8e-4,
        s: 0.06,
        dw: 0.0,
    }
}

#[test]
fn invalid_conditions_are_rejected() {
    let p = BlParams::default();
    for (re, mach, ncrit) in [
        (0.0, 0.0, 9.0),
        (f64::NAN, 0.0, 9.0),
        (1e6, 1.0, 9.0),
        (1e6, -0.1, 9.0),
        (1e6, 0.3, 0.0),
    ] {
        let e = BlModel::new(
            &BlConditions {
                reynolds: re,
                mach,
                ncrit,
            },
            p,
        )
        .unwrap_err();
        let msg = e.to_string();
        assert!(
            msg.starts_with("boundary layer:") && !msg.contains('\n'),
            "{msg}"
        );
    }
}

#[test]
fn invalid_stations_are_rejected() {
    let m = model();
    let v1 = good();
    let v2 = StationVars { x: 0.32, ..good() };
    let bad = [
        StationVars { theta: 0.0, ..v2 },
        StationVars {
            theta: f64::NAN,
            ..v2
        },
        StationVars { u: -1.0, ..v2 },
        StationVars {
            dstar: 1e-4,
            dw: 2e-4,
            ..v2
        },
        StationVars { s: 0.0, ..v2 },
        StationVars { dw: -1e-3, ..v2 },
    ];
    for b in bad {
        let e = m.interval(Regime::Turbulent, &v1, &b).unwrap_err();
        assert!(matches!(e, BlError::Station { .. }), "{e}");
        assert!(m.properties(&b, Regime::Turbulent).is_err());
    }
    // interval must advance downstream
    let e = m.interval(Regime::Laminar, &v2, &v1).unwrap_err();
    assert!(matches!(e, BlError::Interval { .. }));
    assert!(m.transition_interval(&v2, &v1, None).is_err());
    assert!(m.amplification_check(&v1, &v1, None).is_err());
    assert!(m.stagnation_guess(0.0, 1.0).is_err());
    assert!(m.te_junction(&v1, &v2, &v2, -1.0).is_err());
    // a laminar station may have N = 0, a turbulent one needs √Cτ > 0
    assert!(m
        .interval(Regime::Laminar, &StationVars { s: 0.0, ..v1 }, &v2)
        .is_ok());
}

#[test]
fn extreme_but_valid_stations_stay_finite() {
    let m = model();
    // very thin and very thick layers, Hk below the clamp and deep in separation
    for (theta, h) in [(1e-7, 2.5), (1e-2, 1.02), (2e-3, 0.9), (1e-3, 12.0)] {
        for regime in [Regime::Laminar, Regime::Turbulent, Regime::Wake] {
            let v1 = StationVars {
                theta,
                dstar: h * theta,
                ..good()
            };
            let v2 = StationVars { x: 0.31, ..v1 };
            match m.interval(regime, &v1, &v2) {
                Ok(eq) => assert!(eq
                    .res
                    .iter()
                    .chain(eq.d2.iter().flatten())
                    .all(|r| r.is_finite())),
                Err(e) => assert!(matches!(e, BlError::NonFinite(_)), "{e}"),
            }
        }
    }
}
