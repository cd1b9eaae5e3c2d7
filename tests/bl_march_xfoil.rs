//! Direct march of the boundary-layer equations along an XFOIL 6.99 edge-velocity
//! distribution (its `DUMP` files in tests/data/xfoil): starting from the similarity station,
//! laminar with the e^n check, through the transition interval (free or forced), then
//! turbulent with the shear-lag equation, and for the tripped cases across the trailing edge
//! into the wake. Because XFOIL's converged solution satisfies the same discrete equations with
//! that Ue, the marched θ and Hk must reproduce the dumped ones (up to the dump's printed
//! digits). Guards every equation of every regime, the transition interval and the
//! compressibility corrections together: each quantity within about three times the largest
//! deviation measured when its limit was set (in the comments), not above the first limits
//! (0.002 in x_tr, 1.5 % in θ, 2 % in Hk and in the wake's H, 1 % in wake θ, 0.5 % in CD) and not
//! below the dump's rounding (5e-5 in x_tr, 2e-4 of θ at the trailing edge).

use polargen::boundary_layer::{BlModel, IntervalEquations, Regime, StationVars, TransitionKind};

mod bl_support;
use bl_support::xfoil_support::{at_alpha, polar};
use bl_support::{incompressible, load_dump, model};

/// XFOIL's polar row of `case` at `alpha` (the α of its dump).
fn xfoil_point(case: &str, alpha: f64) -> bl_support::xfoil_support::PolarRow {
    *at_alpha(&polar(&format!("{case}.csv")), alpha).expect("XFOIL converged there")
}

/// One dumped station: (ξ, x, Ue compressible, θ, Hk; wake rows carry H in the last slot).
type Row = (f64, f64, f64, f64, f64);

/// Upper surface (stagnation point → TE), lower surface (stagnation point → TE) and wake
/// (TE → end) of a dump; lower-surface speeds made positive, wake rows carry H = δ*/θ.
fn surfaces(name: &str) -> (Vec<Row>, Vec<Row>, Vec<Row>) {
    let d = load_dump(name);
    let row = |(xi, r): &(f64, bl_support::Row), ue: f64, h: f64| (*xi, r.x, ue, r.theta, h);
    (
        d.upper.iter().map(|p| row(p, p.1.ue, p.1.h)).collect(),
        d.lower.iter().map(|p| row(p, -p.1.ue, p.1.h)).collect(),
        d.wake
            .iter()
            .map(|p| row(p, p.1.ue, p.1.dstar / p.1.theta))
            .collect(),
    )
}

/// Upper surface only.
fn upper_surface(name: &str) -> Vec<Row> {
    surfaces(name).0
}

fn solve3(a: [[f64; 3]; 3], b: [f64; 3]) -> [f64; 3] {
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(a);
    std::array::from_fn(|k| {
        let mut m = a;
        for i in 0..3 {
            m[i][k] = b[i];
        }
        det(m) / d
    })
}

/// Newton on (s, θ, δ*) of station 2 (XFOIL MRCHUE direct mode, no Hk limiting needed here).
fn newton(mut v: StationVars, eqs: impl Fn(&StationVars) -> IntervalEquations) -> StationVars {
    for _ in 0..60 {
        let e = eqs(&v);
        let a = std::array::from_fn(|i| [e.d2[i][0], e.d2[i][1], e.d2[i][2]]);
        let dx = solve3(a, [-e.res[0], -e.res[1], -e.res[2]]);
        let mut rlx: f64 = 1.0;
        for (d, x) in [(dx[1], v.theta), (dx[2], v.dstar)] {
            rlx = rlx.min(0.3 * x / d.abs().max(1e-30));
        }
        if v.s > 0.0 && dx[0] < 0.0 {
            rlx = rlx.min(0.5 * v.s / -dx[0]);
        }
        v.s += rlx * dx[0];
        v.theta += rlx * dx[1];
        v.dstar += rlx * dx[2];
        if dx[1].abs() < 1e-11 * v.theta && dx[2].abs() < 1e-11 * v.dstar {
            return v;
        }
    }
    panic!("station at xi = {} did not converge", v.x);
}

/// Marches the upper surface; returns (x, θ, Hk, regime) per station and the transition x.
fn march(
    m: &BlModel,
    surf: &[Row],
    xi_forced: Option<f64>,
) -> (Vec<(f64, f64, f64)>, f64, TransitionKind, StationVars) {
    let st = |k: usize, th: f64, h: f64, s: f64| StationVars {
        x: surf[k].0,
        u: incompressible(m, surf[k].2),
        theta: th,
        dstar: h * th,
        s,
        dw: 0.0,
    };
    // similarity station from Thwaites' starting values (XFOIL MRCHUE)
    let (th0, ds0) = m
        .stagnation_guess(surf[0].0, incompressible(m, surf[0].2))
        .unwrap();
    let mut v1 = newton(st(0, th0, ds0 / th0, 0.0), |v| m.similarity(v).unwrap());
    // Thwaites and the closures' stagnation-point solution agree to a few per cent
    assert!(
        (v1.theta - th0).abs() < 0.1 * th0,
        "similarity θ {} vs Thwaites {th0}",
        v1.theta
    );
    let mut out = vec![(
        surf[0].1,
        v1.theta,
        m.properties(&v1, Regime::Laminar).unwrap().hk,
    )];
    let mut turbulent = false;
    let mut x_tr = f64::NAN;
    let mut kind = TransitionKind::Free;
    for k in 1..surf.len() {
        let guess = st(k, v1.theta, v1.dstar / v1.theta, v1.s);
        let v2 = if turbulent {
            newton(guess, |v| m.interval(Regime::Turbulent, &v1, v).unwrap())
        } else {
            let lam = newton(guess, |v| m.interval(Regime::Laminar, &v1, v).unwrap());
            let chk = m.amplification_check(&v1, &lam, xi_forced).unwrap();
            match chk.transition {
                None => StationVars { s: chk.n2, ..lam },
                Some(_) => {
                    // transition interval: station 2 turbulent, √Cτ from the equilibrium value
                    let cq = m
                        .properties(&lam, Regime::Turbulent)
                        .map(|p| p.ctau_eq_sqrt);
                    let g2 = StationVars {
                        s: 0.7 * cq.unwrap_or(0.03),
                        ..lam
                    };
                    let v2 = newton(g2, |v| {
                        m.transition_interval(&v1, v, xi_forced)
                            .unwrap()
                            .expect("interval keeps transitioning")
                            .eqs
                    });
                    let tr = m.transition_interval(&v1, &v2, xi_forced).unwrap().unwrap();
                    let f = (tr.xi_tr - surf[k - 1].0) / (surf[k].0 - surf[k - 1].0);
                    x_tr = surf[k - 1].1 + f * (surf[k].1 - surf[k - 1].1);
                    kind = tr.kind;
                    turbulent = true;
                    v2
                }
            }
        };
        let regime = if turbulent {
            Regime::Turbulent
        } else {
            Regime::Laminar
        };
        out.push((surf[k].1, v2.theta, m.properties(&v2, regime).unwrap().hk));
        v1 = v2;
    }
    (out, x_tr, kind, v1)
}

/// ξ of the trip at x/c = xf, by linear interpolation between the dumped stations.
fn trip_xi(surf: &[Row], xf: f64) -> f64 {
    let k = surf
        .iter()
        .position(|p| p.1 >= xf)
        .expect("trip on the surface");
    let (a, b) = (surf[k - 1], surf[k]);
    a.0 + (b.0 - a.0) * (xf - a.1) / (b.1 - a.1)
}

/// Marches the upper surface of `<case>_bl_a<alpha>.txt` (a trip at x/c `xf_x` if given) and
/// compares transition and the stations with the dump and with XFOIL's polar: |Δx_tr|,
/// relative θ and Hk within `limits`.
#[allow(clippy::too_many_arguments)]
fn compare(
    case: &str,
    alpha: f64,
    re: f64,
    mach: f64,
    xf_x: Option<f64>,
    kind_ref: TransitionKind,
    limits: [f64; 3],
) {
    let name = format!("{case}_bl_a{alpha}.txt");
    let xtr_ref = xfoil_point(case, alpha).xtr_top;
    let m = model(re, mach);
    let surf = upper_surface(&name);
    let xi_forced = xf_x.map(|xf| trip_xi(&surf, xf));
    let (out, x_tr, kind, _) = march(&m, &surf, xi_forced);
    assert_eq!(kind, kind_ref, "{name}: transition kind");
    let mut worst_t: f64 = 0.0;
    let mut worst_h: f64 = 0.0;
    for (o, r) in out.iter().zip(&surf) {
        // skip the first stations (start-up from the rounded stagnation point) and the TE
        if r.1 < 0.02 || r.1 > 0.99 || r.0 < 0.03 {
            continue;
        }
        worst_t = worst_t.max((o.1 - r.3).abs() / r.3);
        worst_h = worst_h.max((o.2 - r.4).abs() / r.4);
    }
    let worst = [(x_tr - xtr_ref).abs(), worst_t, worst_h];
    eprintln!(
        "{name}: |dx_tr| {:.1e}, θ {:.1e}, Hk {:.1e}",
        worst[0], worst[1], worst[2]
    );
    for (what, (w, l)) in ["x_tr", "θ", "Hk"].iter().zip(worst.iter().zip(limits)) {
        assert!(
            *w <= l,
            "{name}: {what} differs from XFOIL by {w:.2e} > {l:.1e}"
        );
    }
}

#[test]
fn march_naca0012_free_transition_reproduces_xfoil() {
    let case = "naca0012_Re1e6_M0_free";
    // measured 1.1e-5, 5.4e-3, 1.4e-4
    let limits = [5e-5, 0.015, 4.2e-4];
    compare(case, 4.0, 1e6, 0.0, None, TransitionKind::Free, limits);
}

#[test]
fn march_naca0012_alpha0_late_free_transition_reproduces_xfoil() {
    let case = "naca0012_Re1e6_M0_free";
    // measured 7.2e-6, 6.0e-3, 2.4e-4
    let limits = [5e-5, 0.015, 7.2e-4];
    compare(case, 0.0, 1e6, 0.0, None, TransitionKind::Free, limits);
}

#[test]
fn march_naca8h12_forced_transition_m041_reproduces_xfoil() {
    let case = "naca8h12_Re1.9e6_M0.41_xtr0.07";
    // measured 0, 7.8e-3, 1.3e-2
    let limits = [5e-5, 0.015, 0.02];
    compare(
        case,
        4.0,
        1.9e6,
        0.41,
        Some(0.07),
        TransitionKind::Forced,
        limits,
    );
}

/// Both surfaces of the tripped NACA 8-H-12 case (the paper's "insects" configuration,
/// Re 1.9e6, M 0.41), the trailing-edge junction and the wake march on XFOIL's wake
/// velocities: wake θ and H against the dump and Squire–Young CD against XFOIL's polar.
#[test]
fn march_naca8h12_tripped_wake_and_drag_reproduce_xfoil() {
    // measured 6.3e-4, 6.4e-4, 2.1e-4, 5.5e-4
    tripped_wake_and_drag(
        "naca8h12_Re1.9e6_M0.41_xtr0.07",
        [1.9e-3, 1.9e-3, 6.3e-4, 1.7e-3],
    );
}

/// The same for the tripped NACA 23012 at Re 1.9e6, M 0.41.
#[test]
fn march_naca23012_tripped_wake_and_drag_reproduce_xfoil() {
    // measured 2.2e-5, 2.7e-3, 9.8e-3, 1.5e-3
    tripped_wake_and_drag(
        "naca23012_Re1.9e6_M0.41_xtr0.07",
        [2e-4, 8.1e-3, 0.02, 4.5e-3],
    );
}

/// Marches both surfaces of `<case>_bl_a4.txt` (trips at x/c = 0.07), joins them at the TE and
/// marches the wake; compares θ at the junction, wake θ and H with the dump and the
/// Squire–Young CD with XFOIL's polar at α = 4°, all relative, within `limits`.
fn tripped_wake_and_drag(case: &str, limits: [f64; 4]) {
    let name = format!("{case}_bl_a4.txt");
    let cd_ref = xfoil_point(case, 4.0).cd;
    let m = model(1.9e6, 0.41);
    let (upper, lower, wake) = surfaces(&name);
    let (_, _, ku, te_u) = march(&m, &upper, Some(trip_xi(&upper, 0.07)));
    let (_, _, kl, te_l) = march(&m, &lower, Some(trip_xi(&lower, 0.07)));
    assert_eq!((ku, kl), (TransitionKind::Forced, TransitionKind::Forced));
    // first wake station from the junction equations (sharp TE: no gap); they are linear
    // with identity wake Jacobian, so one Newton step solves them
    let w0 = StationVars {
        x: wake[0].0,
        u: incompressible(&m, wake[0].2),
        theta: 1e-3,
        dstar: 1e-3,
        s: 0.05,
        dw: 0.0,
    };
    let te = m.te_junction(&te_u, &te_l, &w0, 0.0).unwrap();
    let mut v1 = StationVars {
        s: w0.s - te.res[0],
        theta: w0.theta - te.res[1],
        dstar: w0.dstar - te.res[2],
        ..w0
    };
    assert!(m
        .te_junction(&te_u, &te_l, &v1, 0.0)
        .unwrap()
        .res
        .iter()
        .all(|r| r.abs() < 1e-15));
    let mut worst = [(v1.theta - wake[0].3).abs() / wake[0].3, 0.0, 0.0, 0.0];
    for r in &wake[1..] {
        let g = StationVars {
            x: r.0,
            u: incompressible(&m, r.2),
            ..v1
        };
        let v2 = newton(g, |v| m.interval(Regime::Wake, &v1, v).unwrap());
        worst[1] = worst[1].max((v2.theta - r.3).abs() / r.3);
        worst[2] = worst[2].max((v2.dstar / v2.theta - r.4).abs() / r.4);
        v1 = v2;
    }
    let cd = m.squire_young(&v1).unwrap().cd;
    worst[3] = (cd - cd_ref).abs() / cd_ref;
    eprintln!(
        "{name}: TE θ {:.1e}, wake θ {:.1e}, wake H {:.1e}, CD {cd} vs XFOIL {cd_ref}: {:.1e}",
        worst[0], worst[1], worst[2], worst[3]
    );
    let what = ["TE θ", "wake θ", "wake H", "CD"];
    for (what, (w, l)) in what.iter().zip(worst.iter().zip(limits)) {
        assert!(
            *w <= l,
            "{name}: {what} differs from XFOIL by {w:.2e} > {l:.1e}"
        );
    }
}
