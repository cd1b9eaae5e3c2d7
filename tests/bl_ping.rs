//! "Ping" tests: every Jacobian entry of the interval equations (laminar, turbulent, wake,
//! similarity, transition, TE junction, Squire–Young) against central finite differences,
//! for randomised realistic station pairs. Each interval is also evaluated in two parts (station
//! 2's Jacobian, then station 1's added), which must give the same numbers bit for bit.

use polargen::boundary_layer::{BlModel, Regime, StationVars, UpstreamStation};

mod bl_support;
use bl_support::model;

#[path = "../src/numerics/test_random.rs"]
mod test_random;
use test_random::Lcg;

fn get(v: &StationVars, k: usize) -> f64 {
    [v.s, v.theta, v.dstar, v.u, v.x][k]
}

fn set(v: &mut StationVars, k: usize, val: f64) {
    match k {
        0 => v.s = val,
        1 => v.theta = val,
        2 => v.dstar = val,
        3 => v.u = val,
        _ => v.x = val,
    }
}

/// Relative step for the central difference of variable k.
fn step(v: &StationVars, k: usize) -> f64 {
    1e-6 * get(v, k).abs().max(if k == 0 { 1e-2 } else { 1e-4 })
}

/// Compares an analytic Jacobian row-set against central differences of `f` w.r.t. the
/// variables of `v` (which `f` receives perturbed). Tolerance: relative 1e-5 of the row's
/// largest entry scale.
fn ping(
    label: &str,
    v: &StationVars,
    jac: &[[f64; 5]; 3],
    f: impl Fn(&StationVars) -> [f64; 3],
    tol: f64,
) {
    for k in 0..5 {
        let h = step(v, k);
        let mut vp = *v;
        set(&mut vp, k, get(v, k) + h);
        let mut vm = *v;
        set(&mut vm, k, get(v, k) - h);
        let fp = f(&vp);
        let fm = f(&vm);
        for row in 0..3 {
            let fd = (fp[row] - fm[row]) / (2.0 * h);
            let an = jac[row][k];
            let scale = jac[row]
                .iter()
                .zip([v.s, v.theta, v.dstar, v.u, v.x])
                .map(|(j, x)| (j * x).abs())
                .fold(0.0, f64::max)
                / get(v, k).abs().max(1e-12);
            let err = (fd - an).abs() / (an.abs().max(fd.abs()).max(1e-3 * scale).max(1e-12));
            assert!(
                err < tol,
                "{label}: row {row} col {k}: analytic {an:e} vs fd {fd:e} (rel err {err:e})"
            );
        }
    }
}

fn station(x: f64, u: f64, theta: f64, h: f64, s: f64, dw: f64) -> StationVars {
    StationVars {
        x,
        u,
        theta,
        dstar: h * theta + dw,
        s,
        dw,
    }
}

fn check_interval(m: &BlModel, regime: Regime, v1: &StationVars, v2: &StationVars, tol: f64) {
    let eq = m.interval(regime, v1, v2).expect("valid interval");
    let up = UpstreamStation::new(v1, regime);
    let part = m
        .interval_downstream(regime, &up, v2)
        .expect("valid interval");
    // The local part: residuals and the (s, θ, δ*, u) columns of station 2, bit for bit.
    let d2_local = eq.d2.map(|[ds, dt, dd, du, _]| [ds, dt, dd, du]);
    assert_eq!(
        (part.res, part.d2),
        (eq.res, d2_local),
        "{regime:?} station-2 part"
    );
    let whole = m.complete_interval(&up, &part).expect("valid interval");
    assert_eq!(whole, eq, "{regime:?} completed equations");
    ping(
        &format!("{regime:?} st1"),
        v1,
        &eq.d1,
        |p| m.interval(regime, p, v2).unwrap().res,
        tol,
    );
    ping(
        &format!("{regime:?} st2"),
        v2,
        &eq.d2,
        |p| m.interval(regime, v1, p).unwrap().res,
        tol,
    );
}

#[test]
fn ping_laminar_intervals() {
    let mut rng = Lcg::new(1);
    for i in 0..40 {
        let m = model(rng.range(2e5, 5e6), if i % 2 == 0 { 0.0 } else { 0.41 });
        let x1 = rng.range(0.01, 0.6);
        let x2 = x1 + rng.range(0.003, 0.03);
        let th1 = rng.range(5e-5, 4e-4);
        let v1 = station(
            x1,
            rng.range(0.8, 1.6),
            th1,
            rng.range(2.2, 3.6),
            rng.range(0.0, 7.0),
            0.0,
        );
        let v2 = station(
            x2,
            v1.u * rng.range(0.97, 1.02),
            th1 * rng.range(1.0, 1.15),
            rng.range(2.2, 3.8),
            v1.s + rng.range(0.0, 1.0),
            0.0,
        );
        check_interval(&m, Regime::Laminar, &v1, &v2, 1e-5);
    }
}

#[test]
fn ping_turbulent_intervals() {
    let mut rng = Lcg::new(2);
    for i in 0..40 {
        let m = model(rng.range(5e5, 6e6), if i % 2 == 0 { 0.0 } else { 0.41 });
        let x1 = rng.range(0.1, 1.0);
        let x2 = x1 + rng.range(0.005, 0.04);
        let th1 = rng.range(3e-4, 3e-3);
        let v1 = station(
            x1,
            rng.range(0.7, 1.4),
            th1,
            rng.range(1.3, 2.5),
            rng.range(0.03, 0.12),
            0.0,
        );
        let v2 = station(
            x2,
            v1.u * rng.range(0.96, 1.01),
            th1 * rng.range(1.0, 1.1),
            rng.range(1.3, 2.6),
            v1.s * rng.range(0.9, 1.1),
            0.0,
        );
        check_interval(&m, Regime::Turbulent, &v1, &v2, 1e-5);
    }
}

#[test]
fn ping_wake_intervals() {
    let mut rng = Lcg::new(3);
    for i in 0..40 {
        let m = model(rng.range(5e5, 6e6), if i % 2 == 0 { 0.0 } else { 0.41 });
        let x1 = rng.range(1.0, 2.0);
        let x2 = x1 + rng.range(0.01, 0.1);
        let th1 = rng.range(1e-3, 6e-3);
        let dw1 = rng.range(0.0, 2e-3);
        let v1 = station(
            x1,
            rng.range(0.85, 1.0),
            th1,
            rng.range(1.1, 2.5),
            rng.range(0.02, 0.1),
            dw1,
        );
        let v2 = station(
            x2,
            v1.u * rng.range(1.0, 1.01),
            th1 * rng.range(0.98, 1.0),
            rng.range(1.05, 2.3),
            v1.s * rng.range(0.9, 1.0),
            dw1 * 0.8,
        );
        check_interval(&m, Regime::Wake, &v1, &v2, 1e-5);
    }
}

#[test]
fn ping_similarity_station() {
    let mut rng = Lcg::new(4);
    for i in 0..20 {
        let m = model(rng.range(2e5, 5e6), if i % 2 == 0 { 0.0 } else { 0.41 });
        let v = station(
            rng.range(1e-4, 2e-3),
            rng.range(0.01, 0.2),
            rng.range(1e-5, 5e-5),
            rng.range(2.1, 2.4),
            0.0,
            0.0,
        );
        let eq = m.similarity(&v).expect("valid station");
        assert!(eq.d1.iter().flatten().all(|&d| d == 0.0));
        ping(
            "similarity",
            &v,
            &eq.d2,
            |p| m.similarity(p).unwrap().res,
            1e-5,
        );
    }
}

#[test]
fn ping_transition_intervals() {
    let mut rng = Lcg::new(5);
    let mut n_free = 0;
    let mut n_forced = 0;
    for i in 0..60 {
        let m = model(rng.range(1e6, 4e6), if i % 2 == 0 { 0.0 } else { 0.41 });
        let x1 = rng.range(0.1, 0.5);
        let x2 = x1 + rng.range(0.01, 0.04);
        let th1 = rng.range(2e-4, 5e-4);
        let v1 = station(
            x1,
            rng.range(1.0, 1.4),
            th1,
            rng.range(2.6, 3.2),
            rng.range(8.3, 8.99),
            0.0,
        );
        let v2 = station(
            x2,
            v1.u * rng.range(0.97, 1.0),
            th1 * rng.range(1.02, 1.2),
            rng.range(1.6, 2.6),
            rng.range(0.02, 0.08),
            0.0,
        );
        let xf = if i % 3 == 0 {
            Some(x1 + rng.range(0.1, 0.9) * (x2 - x1))
        } else {
            None
        };
        let Some(tr) = m.transition_interval(&v1, &v2, xf).unwrap() else {
            continue;
        };
        match tr.kind {
            polargen::boundary_layer::TransitionKind::Free => n_free += 1,
            polargen::boundary_layer::TransitionKind::Forced => n_forced += 1,
        }
        assert!(tr.xi_tr > x1 && tr.xi_tr <= x2);
        let f1 = |p: &StationVars| m.transition_interval(p, &v2, xf).unwrap().unwrap().eqs.res;
        let f2 = |p: &StationVars| m.transition_interval(&v1, p, xf).unwrap().unwrap().eqs.res;
        ping("transition st1", &v1, &tr.eqs.d1, f1, 1e-4);
        ping("transition st2", &v2, &tr.eqs.d2, f2, 1e-4);
        // ξ_tr sensitivities
        for k in 0..5 {
            let h = step(&v1, k);
            let (mut p, mut q) = (v1, v1);
            set(&mut p, k, get(&v1, k) + h);
            set(&mut q, k, get(&v1, k) - h);
            let fd = (m.transition_interval(&p, &v2, xf).unwrap().unwrap().xi_tr
                - m.transition_interval(&q, &v2, xf).unwrap().unwrap().xi_tr)
                / (2.0 * h);
            let an = tr.dxi_tr_d1[k];
            assert!(
                (fd - an).abs() <= 1e-4 * an.abs().max(1e-3),
                "dxi_tr/dv1[{k}]: {an:e} vs {fd:e}"
            );
        }
    }
    assert!(n_free >= 5, "too few free transitions sampled: {n_free}");
    assert!(
        n_forced >= 5,
        "too few forced transitions sampled: {n_forced}"
    );
}

/// Transition intervals from two NACA 8-H-12 solutions where the global iteration can fall into
/// a fixed cycle: (a) Re 1.5e6, M 0.2, α −0.5°, lower surface, ξ_tr at 98 % of the
/// interval; (b) Re 2e6, M 0, α 7°, upper surface, N1 = 8.88 and the transition point inside
/// the onset ramp of the amplification rate (rate 0 at station 2), where ξ_tr reacts strongly
/// to δ*2. The Jacobians and the ξ_tr sensitivities must hold there too.
#[test]
fn ping_transition_near_interval_end_and_in_onset_ramp() {
    let cases = [
        (
            model(1.5e6, 0.2),
            StationVars {
                x: 0.10539491842063398,
                u: 1.1371131183427763,
                theta: 0.00019328116674495062,
                dstar: 0.0006084554904176235,
                s: 8.221278055143598,
                dw: 0.0,
            },
            StationVars {
                x: 0.12058936150026933,
                u: 1.125999239314099,
                theta: 0.00020790689282567908,
                dstar: 0.0006210973998565942,
                s: 0.028659745593961627,
                dw: 0.0,
            },
            (0.97, 0.99),
        ),
        (
            model(2e6, 0.0),
            StationVars {
                x: 0.20985674060139714,
                u: 1.5810042834249411,
                theta: 0.00018275635517096993,
                dstar: 0.00048747476559884425,
                s: 8.881321381330785,
                dw: 0.0,
            },
            StationVars {
                x: 0.22441280144888243,
                u: 1.5772,
                theta: 0.00019055,
                dstar: 0.0004590,
                s: 0.0315,
                dw: 0.0,
            },
            (0.5, 0.6),
        ),
    ];
    for (m, v1, v2, (lo, hi)) in cases {
        let tr = m
            .transition_interval(&v1, &v2, None)
            .unwrap()
            .expect("transition");
        let frac = (tr.xi_tr - v1.x) / (v2.x - v1.x);
        assert!(frac > lo && frac < hi, "transition fraction {frac}");
        let f1 = |p: &StationVars| {
            m.transition_interval(p, &v2, None)
                .unwrap()
                .unwrap()
                .eqs
                .res
        };
        let f2 = |p: &StationVars| {
            m.transition_interval(&v1, p, None)
                .unwrap()
                .unwrap()
                .eqs
                .res
        };
        ping("transition st1", &v1, &tr.eqs.d1, f1, 1e-4);
        ping("transition st2", &v2, &tr.eqs.d2, f2, 1e-4);
        for (v, grad, first) in [(&v1, tr.dxi_tr_d1, true), (&v2, tr.dxi_tr_d2, false)] {
            for (k, an) in grad.into_iter().enumerate() {
                let h = step(v, k);
                let (mut p, mut q) = (*v, *v);
                set(&mut p, k, get(v, k) + h);
                set(&mut q, k, get(v, k) - h);
                let xt = |w: &StationVars| {
                    let t = if first {
                        m.transition_interval(w, &v2, None)
                    } else {
                        m.transition_interval(&v1, w, None)
                    };
                    t.unwrap().unwrap().xi_tr
                };
                let fd = (xt(&p) - xt(&q)) / (2.0 * h);
                assert!(
                    (fd - an).abs() <= 1e-4 * an.abs().max(1e-3),
                    "dxi_tr/dv{}[{k}]: {an:e} vs {fd:e}",
                    if first { 1 } else { 2 }
                );
            }
        }
    }
}

#[test]
fn ping_squire_young() {
    let m = model(1.9e6, 0.41);
    let v = station(2.0, 0.99, 3.7e-3, 1.04, 0.03, 1e-5);
    let sy = m.squire_young(&v).unwrap();
    for k in 1..4 {
        let h = step(&v, k);
        let (mut p, mut q) = (v, v);
        set(&mut p, k, get(&v, k) + h);
        set(&mut q, k, get(&v, k) - h);
        let fd = (m.squire_young(&p).unwrap().cd - m.squire_young(&q).unwrap().cd) / (2.0 * h);
        assert!(
            (fd - sy.d[k]).abs() <= 1e-6 * sy.d[k].abs(),
            "col {k}: {} vs {fd}",
            sy.d[k]
        );
    }
}

#[test]
fn ping_te_junction() {
    let m = model(1e6, 0.0);
    let up = station(1.0, 0.9, 4e-3, 1.8, 0.09, 0.0);
    let lo = station(1.01, 0.92, 2e-3, 1.6, 0.07, 0.0);
    let wk = station(1.0, 0.91, 6.1e-3, 1.75, 0.08, 2.5e-3);
    let gap = 2.5e-3;
    let te = m.te_junction(&up, &lo, &wk, gap).unwrap();
    ping(
        "te upper",
        &up,
        &te.d_upper,
        |p| m.te_junction(p, &lo, &wk, gap).unwrap().res,
        1e-6,
    );
    ping(
        "te lower",
        &lo,
        &te.d_lower,
        |p| m.te_junction(&up, p, &wk, gap).unwrap().res,
        1e-6,
    );
    ping(
        "te wake",
        &wk,
        &te.d_wake,
        |p| m.te_junction(&up, &lo, p, gap).unwrap().res,
        1e-6,
    );
}

#[test]
fn ping_kinematic_shape() {
    let m = model(1.9e6, 0.41);
    let v = station(0.3, 1.25, 4e-4, 2.4, 0.0, 0.0);
    let hk = m.kinematic_shape(&v);
    // Whitfield's Hk at the edge Mach number of this station (< H for Me > 0), the value the
    // station closures use
    let p = m.properties(&v, Regime::Laminar).unwrap();
    assert!((hk.value - p.hk).abs() < 1e-14 && hk.value < 2.4);
    // hand-derived ∂Hk/∂(θ, δ*, u) in the ping's column order (s, θ, δ*, u, ξ)
    let row = [0.0, hk.d[0], hk.d[1], hk.d[2], 0.0];
    let jac = [row, [0.0; 5], [0.0; 5]];
    ping(
        "kinematic shape",
        &v,
        &jac,
        |q| [m.kinematic_shape(q).value, 0.0, 0.0],
        1e-6,
    );
}
