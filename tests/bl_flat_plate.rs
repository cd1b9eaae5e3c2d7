//! Zero-pressure-gradient flat plate marched with the interval equations (each station
//! solved by Newton on its own three variables, as XFOIL's direct march MRCHUE does):
//! laminar against Blasius, turbulent against the Coles–Fernholz skin-friction law, and the
//! e^n transition Reynolds number.

use polargen::boundary_layer::{
    BlConditions, BlModel, BlParams, IntervalEquations, Regime, StationVars,
};

/// Model with the similarity station set for the Blasius profile (d ln Ue/d ln ξ = 0
/// instead of XFOIL's stagnation-point value 1).
fn model(re: f64) -> BlModel {
    BlModel::new(
        &BlConditions {
            reynolds: re,
            mach: 0.0,
            ncrit: 9.0,
        },
        BlParams {
            similarity_ue_exponent: 0.0,
            ..BlParams::default()
        },
    )
    .expect("valid conditions")
}

/// Solves the 3×3 system a·x = b by Cramer's rule.
fn solve3(a: [[f64; 3]; 3], b: [f64; 3]) -> [f64; 3] {
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(a);
    let mut x = [0.0; 3];
    for (k, xk) in x.iter_mut().enumerate() {
        let mut m = a;
        for i in 0..3 {
            m[i][k] = b[i];
        }
        *xk = det(m) / d;
    }
    x
}

/// Newton on (s, θ, δ*) of station 2 with `eqs(v2)`; returns the converged station.
fn newton(mut v: StationVars, eqs: impl Fn(&StationVars) -> IntervalEquations) -> StationVars {
    for _ in 0..50 {
        let e = eqs(&v);
        let a = [
            [e.d2[0][0], e.d2[0][1], e.d2[0][2]],
            [e.d2[1][0], e.d2[1][1], e.d2[1][2]],
            [e.d2[2][0], e.d2[2][1], e.d2[2][2]],
        ];
        let dx = solve3(a, [-e.res[0], -e.res[1], -e.res[2]]);
        // limit relative changes of θ and δ* to 30 %
        let rlx = [dx[1] / v.theta, dx[2] / v.dstar]
            .iter()
            .fold(1.0f64, |r, q| r.min(0.3 / q.abs().max(1e-30)));
        v.s += rlx * dx[0];
        v.theta += rlx * dx[1];
        v.dstar += rlx * dx[2];
        if dx[1].abs() < 1e-12 * v.theta && dx[2].abs() < 1e-12 * v.dstar {
            return v;
        }
    }
    panic!("station at x = {} did not converge", v.x);
}

fn stations(x0: f64, x1: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| x0 * (x1 / x0).powf(i as f64 / (n - 1) as f64))
        .collect()
}

#[test]
fn laminar_flat_plate_matches_blasius() {
    let re = 1e6;
    let m = model(re);
    let xs = stations(1e-3, 1.0, 60);
    let guess = |x: f64| StationVars {
        x,
        u: 1.0,
        theta: 0.664 * (x / re).sqrt(),
        dstar: 2.59 * 0.664 * (x / re).sqrt(),
        s: 0.0,
        dw: 0.0,
    };
    let mut v1 = newton(guess(xs[0]), |v| m.similarity(v).unwrap());
    assert_eq!(v1.s, 0.0);
    for &x in &xs[1..] {
        let g = StationVars {
            x,
            s: v1.s,
            ..guess(x)
        };
        let v2 = newton(g, |v| m.interval(Regime::Laminar, &v1, v).unwrap());
        let blasius = v2.theta * (re / x).sqrt();
        let h = v2.dstar / v2.theta;
        // XFOIL's Falkner–Skan closures reproduce Blasius θ√(Re/x) = 0.664, H = 2.59 within 2 %
        assert!(
            (blasius - 0.664).abs() < 0.02 * 0.664,
            "x = {x}: θ√(Re/x) = {blasius}"
        );
        assert!((h - 2.59).abs() < 0.02 * 2.59, "x = {x}: H = {h}");
        v1 = v2;
    }
    // Re_x = 1e6 < transition: N stays below Ncrit but grows past Re_θcrit
    assert!(v1.s > 1.0 && v1.s < 9.0, "N at Re_x = 1e6: {}", v1.s);
}

#[test]
fn flat_plate_transition_reynolds_number() {
    let re = 1e7;
    let m = model(re);
    let xs = stations(1e-4, 1.0, 200);
    let guess = |x: f64| StationVars {
        x,
        u: 1.0,
        theta: 0.664 * (x / re).sqrt(),
        dstar: 2.59 * 0.664 * (x / re).sqrt(),
        s: 0.0,
        dw: 0.0,
    };
    let mut v1 = newton(guess(xs[0]), |v| m.similarity(v).unwrap());
    let mut x_tr = None;
    for &x in &xs[1..] {
        let g = StationVars {
            x,
            s: v1.s,
            ..guess(x)
        };
        let v2 = newton(g, |v| m.interval(Regime::Laminar, &v1, v).unwrap());
        let chk = m.amplification_check(&v1, &v2, None).unwrap();
        if let Some((xt, _)) = chk.transition {
            x_tr = Some(xt);
            break;
        }
        v1 = v2;
    }
    let re_tr = x_tr.expect("transition before x = 1") * re;
    // Semi-analytic e^n result for the closures' own Blasius solution: H solves
    // Cf·Re_θ/2 = (2CD/H*)·Re_θ (zero-pressure-gradient similarity of the momentum and
    // kinetic-energy equations with the Falkner–Skan fits), Re_θ = √(Cf Re_θ · Re_x), and
    // N = (dN/dRe_θ)(H)·(Re_θ − Re_θcrit(H)) (Drela & Giles 1987 eqs. 21, 23).
    let cf_ret = |h: f64| 0.0727 * (5.5 - h).powi(3) / (h + 1.0) - 0.07;
    let di_ret = |h: f64| 0.00205 * (4.0 - h).powf(5.5) + 0.207;
    let (mut lo, mut hi) = (2.3, 3.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if cf_ret(mid) / 2.0 - di_ret(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let h = 0.5 * (lo + hi);
    let hmi = 1.0 / (h - 1.0);
    let log_rcrit = 2.492 * hmi.powf(0.43) + 0.7 * ((14.0 * hmi - 9.24).tanh() + 1.0);
    let dndr = 0.028 * (h - 1.0) - 0.0345 * (-(3.87 * hmi - 2.52f64).powi(2)).exp();
    let ret_tr = 10f64.powf(log_rcrit) + 9.0 / dndr;
    let re_tr_analytic = ret_tr * ret_tr / cf_ret(h);
    assert!((h - 2.568).abs() < 0.01, "closure Blasius H = {h}");
    // the discrete march includes the smooth onset ramp of the rate: within 8 %
    assert!(
        (re_tr - re_tr_analytic).abs() < 0.08 * re_tr_analytic,
        "Re_x,tr = {re_tr:e} vs semi-analytic {re_tr_analytic:e}"
    );
}

#[test]
fn turbulent_flat_plate_matches_log_law_skin_friction() {
    let re = 1e7;
    let m = model(re);
    // start from a turbulent profile at x = 0.05 and march to the trailing edge
    let x0 = 0.05;
    // 1/7-power-law momentum thickness θ = 0.036 x Re_x^(−1/5) (Schlichting)
    let th0 = 0.036 * x0 * (re * x0).powf(-0.2);
    let mut v1 = StationVars {
        x: x0,
        u: 1.0,
        theta: th0,
        dstar: 1.4 * th0,
        s: 0.05,
        dw: 0.0,
    };
    v1.s = m.properties(&v1, Regime::Turbulent).unwrap().ctau_eq_sqrt;
    let mut last = v1;
    for &x in &stations(x0, 1.0, 80)[1..] {
        let g = StationVars { x, ..v1 };
        let v2 = newton(g, |v| m.interval(Regime::Turbulent, &v1, v).unwrap());
        v1 = v2;
        last = v2;
    }
    // far downstream of the start the layer has forgotten its initial state
    let p = m.properties(&last, Regime::Turbulent).unwrap();
    // Coles–Fernholz law Cf = 2/(ln(Re_θ)/κ + C)², κ = 0.384, C = 4.127 (Nagib et al. 2007)
    let cf_cf = 2.0 / (p.re_theta.ln() / 0.384 + 4.127).powi(2);
    assert!(
        (p.cf - cf_cf).abs() < 0.03 * cf_cf,
        "Cf {} vs Coles–Fernholz {cf_cf}",
        p.cf
    );
    // momentum-thickness growth of the 1/7 power law, Re_θ = 0.036 Re_x^0.8, within 5 %
    let ret_pl = 0.036 * (re * last.x).powf(0.8);
    assert!(
        (p.re_theta - ret_pl).abs() < 0.05 * ret_pl,
        "Re_θ {} vs {ret_pl}",
        p.re_theta
    );
    assert!((1.25..1.45).contains(&p.h), "H = {}", p.h);
    // equilibrium: the lag variable relaxes to its equilibrium value
    assert!((last.s - p.ctau_eq_sqrt).abs() < 0.1 * p.ctau_eq_sqrt);
}
