//! Boundary-layer closures, amplification and interval equations checked against converged
//! XFOIL 6.99 solutions (DUMP files of `tests/data/bl/`, α = 4°): skin friction and H* from
//! the dumped θ, H, Ue; the free-transition location predicted by marching the e^n equation
//! along the dumped laminar boundary layer; the momentum-equation residual between dumped
//! stations; and the Squire–Young drag of the last wake point against the polar's CD.

use polargen::boundary_layer::{BlModel, Regime, StationVars, TransitionKind};

mod bl_support;
use polargen::compressibility::GAMMA;

use bl_support::{incompressible, load_dump as load, model, Row};

/// Station variables from a dump row. The dump's "H" column is XFOIL's kinematic Hk
/// (BLDUMP calls HKIN), so H is recovered by inverting Whitfield's relation with the edge
/// Mach number of the dumped Ue.
fn vars(m: &BlModel, xi: f64, r: &Row, s: f64) -> StationVars {
    let ue = r.ue.abs();
    let u2h = ue * ue * m.flow.inverse_stagnation_enthalpy;
    let msq = u2h / ((GAMMA - 1.0) * (1.0 - 0.5 * u2h));
    let h = r.h * (1.0 + 0.113 * msq) + 0.29 * msq;
    StationVars {
        x: xi,
        u: incompressible(m, r.ue),
        theta: r.theta,
        dstar: h * r.theta,
        s,
        dw: 0.0,
    }
}

/// The dumped cases: file, Re, M, XFOIL polar (xtr_top, xtr_bot, cd) at that α; the free
/// transition cases come first.
#[rustfmt::skip]
const CASES: [(&str, f64, f64, f64, f64, f64); 7] = [
    ("naca0012_Re1e6_M0_free_bl_a0.txt", 1e6, 0.0, 0.687, 0.687, 0.0054),
    ("naca0012_Re1e6_M0_free_bl_a4.txt", 1e6, 0.0, 0.2537, 0.9685, 0.00728),
    ("naca0012_Re1e6_M0_free_bl_a8.txt", 1e6, 0.0, 0.0381, 1.0, 0.01211),
    ("naca8h12_Re1.9e6_M0.41_free_bl_a4.txt", 1.9e6, 0.41, 0.3989, 0.9963, 0.00597),
    ("naca23012_Re1.9e6_M0.41_free_bl_a4.txt", 1.9e6, 0.41, 0.1867, 0.968, 0.00727),
    ("naca8h12_Re1.9e6_M0.41_xtr0.07_bl_a4.txt", 1.9e6, 0.41, 0.07, 0.07, 0.0109),
    ("naca23012_Re1.9e6_M0.41_xtr0.07_bl_a4.txt", 1.9e6, 0.41, 0.07, 0.07, 0.01065),
];

/// Number of free-transition cases at the start of [`CASES`].
const N_FREE: usize = 5;

/// Closure check: XFOIL's dumped Cf (= 2τw/ρ∞V∞²) and H* against ours from the dumped
/// θ, Hk, Ue, laminar upstream of the polar's transition point and turbulent downstream.
#[test]
fn skin_friction_and_hstar_match_xfoil_dumps() {
    for (file, re, mach, xtr_top, xtr_bot, _) in CASES {
        let m = model(re, mach);
        let d = load(file);
        let mut n = 0;
        for (surface, xtr) in [(&d.upper, xtr_top), (&d.lower, xtr_bot)] {
            for (xi, r) in surface.iter() {
                // thin LE stations carry only 2-3 printed digits of θ
                if r.theta < 6e-5 || (r.x - xtr).abs() < 0.01 {
                    continue;
                }
                let regime = if r.x < xtr {
                    Regime::Laminar
                } else {
                    Regime::Turbulent
                };
                let p = m.properties(&vars(&m, *xi, r, 0.05), regime).unwrap();
                let cf = 2.0 * p.tau_wall;
                let cf_tol = 0.012 * r.cf.abs() + 2e-6;
                assert!(
                    (cf - r.cf).abs() <= cf_tol,
                    "{file} x = {} ({regime:?}): Cf {cf} vs XFOIL {}",
                    r.x,
                    r.cf
                );
                let hs = r.hs.expect("airfoil rows have H*");
                assert!(
                    (p.h_star - hs).abs() <= 1.5e-3,
                    "{file} x = {} ({regime:?}): H* {} vs XFOIL {hs}",
                    r.x,
                    p.h_star
                );
                n += 1;
            }
        }
        assert!(n > 100, "{file}: only {n} stations compared");
    }
}

/// e^n check: marching the implicit amplification equation (TRCHEK2) along the dumped
/// laminar boundary layer from N = 0 at the stagnation point must reach Ncrit = 9 where
/// XFOIL put free transition (polar xtr), within 0.001 c.
#[test]
fn free_transition_location_matches_xfoil() {
    for (file, re, mach, xtr_top, xtr_bot, _) in &CASES[..N_FREE] {
        let m = model(*re, *mach);
        let d = load(file);
        for (surface, xtr) in [(&d.upper, *xtr_top), (&d.lower, *xtr_bot)] {
            let mut n = 0.0;
            let mut found = None;
            for w in surface.windows(2) {
                let (x1, r1) = w[0];
                let (x2, r2) = w[1];
                let v1 = vars(&m, x1, &r1, n);
                let v2 = vars(&m, x2, &r2, 0.0);
                let chk = m.amplification_check(&v1, &v2, None).unwrap();
                assert!(chk.converged);
                if let Some((xi_tr, kind)) = chk.transition {
                    assert_eq!(kind, TransitionKind::Free);
                    let f = (xi_tr - x1) / (x2 - x1);
                    found = Some(r1.x + f * (r2.x - r1.x));
                    break;
                }
                n = chk.n2;
            }
            let x_tr = found.unwrap_or(1.0);

            assert!(
                (x_tr - xtr).abs() <= 0.001,
                "{file}: transition at x = {x_tr}, XFOIL {xtr}"
            );
        }
    }
}

/// Forced transition: the earlier of forced and free wins and is reported as forced.
#[test]
fn forced_transition_wins_when_upstream() {
    let (file, re, mach, _, _, _) = CASES[N_FREE];
    let m = model(re, mach);
    let d = load(file);
    let (x1, r1) = d.upper[10];
    let (x2, r2) = d.upper[11];
    let v1 = vars(&m, x1, &r1, 2.0);
    let v2 = vars(&m, x2, &r2, 0.05);
    let xf = 0.5 * (x1 + x2);
    let chk = m.amplification_check(&v1, &v2, Some(xf)).unwrap();
    assert_eq!(chk.transition, Some((xf, TransitionKind::Forced)));
    let tr = m
        .transition_interval(&v1, &v2, Some(xf))
        .unwrap()
        .expect("transition");
    assert_eq!(tr.kind, TransitionKind::Forced);
    assert!((tr.xi_tr - xf).abs() < 1e-15);
    assert!(tr
        .dxi_tr_d1
        .iter()
        .chain(tr.dxi_tr_d2.iter())
        .all(|&g| g == 0.0));
    // forced location downstream of the interval: no transition
    let none = m.amplification_check(&v1, &v2, Some(x2 + 0.01)).unwrap();
    assert!(none.transition.is_none());
    assert!(m
        .transition_interval(&v1, &v2, Some(x2 + 0.01))
        .unwrap()
        .is_none());
}

/// Discrete momentum (laminar and turbulent) and laminar shape-parameter equations:
/// XFOIL's converged solution satisfies them, so their residuals between consecutive dumped
/// stations must vanish to within the rounding of the dump (θ printed to 1e-6 gives
/// ln θ an uncertainty of 5e-7/θ per station; the Ue and Hk digits add about 1e-4).
#[test]
fn residuals_vanish_on_xfoil_solution() {
    for (file, re, mach, xtr_top, _, _) in CASES {
        let m = model(re, mach);
        let d = load(file);
        let mut n = 0;
        for w in d.upper.windows(2) {
            let (x1, r1) = w[0];
            let (x2, r2) = w[1];
            if r1.theta < 1e-4 || (r1.x - xtr_top).abs() < 0.02 || r2.x > 0.98 {
                continue;
            }
            let regime = if r2.x < xtr_top {
                Regime::Laminar
            } else {
                Regime::Turbulent
            };
            let eq = m
                .interval(regime, &vars(&m, x1, &r1, 1.0), &vars(&m, x2, &r2, 1.0))
                .unwrap();
            let tol = 2.0 * 5e-7 * (1.0 / r1.theta + 1.0 / r2.theta) + 3e-4;
            assert!(
                eq.res[1].abs() <= tol,
                "{file} x = {}: momentum residual {:e} > {tol:e}",
                r2.x,
                eq.res[1]
            );
            if regime == Regime::Laminar {
                assert!(
                    eq.res[2].abs() <= 2e-4,
                    "{file} x = {}: shape residual {:e}",
                    r2.x,
                    eq.res[2]
                );
            }
            n += 1;
        }
        assert!(n > 30, "{file}: only {n} intervals checked");
    }
}

/// Squire–Young drag from the last dumped wake point against XFOIL's polar CD.
#[test]
fn squire_young_matches_polar_drag() {
    for (file, re, mach, _, _, cd) in CASES {
        let m = model(re, mach);
        let d = load(file);
        let (_, last) = d.wake.last().expect("wake rows");
        let v = StationVars {
            x: 2.0,
            u: incompressible(&m, last.ue),
            theta: last.theta,
            dstar: last.dstar,
            s: 0.01,
            dw: 0.0,
        };
        let sy = m.squire_young(&v).unwrap();
        assert!(
            (sy.cd - cd).abs() <= 0.004 * cd + 5e-6,
            "{file}: CD {} vs XFOIL {cd}",
            sy.cd
        );
    }
}
