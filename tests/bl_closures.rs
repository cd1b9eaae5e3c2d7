//! Closure relations: value at known points against an independent evaluation of the
//! published formula (Drela & Giles 1987; Drela 1989; XFOIL 6.99 xblsys.f), and every
//! partial derivative against central finite differences.

use polargen::boundary_layer::amplification::amplification_rate;
use polargen::boundary_layer::closures::{
    bl_thickness, ctau_eq_sqrt, density_shape_factor, dissipation_outer, dissipation_turbulent,
    kinematic_shape_factor, laminar_dissipation, laminar_energy_shape_factor,
    laminar_skin_friction, laminar_wake_dissipation, slip_velocity, transition_ctau_factor,
    turbulent_energy_shape_factor, turbulent_skin_friction, Partials,
};
use polargen::boundary_layer::BlParams;

/// Checks every partial of `f` at `x` against central differences (relative 1e-6 plus the
/// round-off of the difference quotient).
fn fd_check<const N: usize>(name: &str, x: [f64; N], f: impl Fn([f64; N]) -> Partials<N>) {
    let p = f(x);
    for k in 0..N {
        let h = 1e-6 * x[k].abs().max(1e-2);
        let (mut xp, mut xm) = (x, x);
        xp[k] += h;
        xm[k] -= h;
        let fd = (f(xp).value - f(xm).value) / (2.0 * h);
        // truncation (relative 1e-6) plus round-off of the difference quotient
        let tol = 1e-6 * p.d[k].abs().max(fd.abs()) + 1e-14 * p.value.abs() / h;
        assert!(
            (fd - p.d[k]).abs() <= tol,
            "{name} at {x:?}: d/dx{k} analytic {} vs fd {fd}",
            p.d[k]
        );
    }
}

/// The closure's value at `x` is `want` (relative 1e-12) and its partials there match central
/// differences.
fn check_closure<const N: usize>(
    name: &str,
    x: [f64; N],
    f: impl Fn([f64; N]) -> Partials<N>,
    want: f64,
) {
    close(name, f(x).value, want);
    fd_check(name, x, f);
}

fn close(name: &str, got: f64, want: f64) {
    assert!(
        (got - want).abs() <= 1e-12 * want.abs().max(1e-12),
        "{name}: {got} vs {want}"
    );
}

#[test]
fn kinematic_shape_parameter() {
    // Whitfield: Hk = (H − 0.29 M²)/(1 + 0.113 M²)
    let (h, m2) = (2.0, 0.3);
    check_closure(
        "kinematic_shape_factor",
        [h, m2],
        |a| kinematic_shape_factor(a[0], a[1]),
        (2.0 - 0.087) / 1.0339,
    );
}

#[test]
fn laminar_hstar_both_branches() {
    // attached branch (Hk < 4.35)
    let hk: f64 = 2.6;
    let t = hk - 4.35;
    let want = 0.0111 * t * t / (hk + 1.0) - 0.0278 * t.powi(3) / (hk + 1.0) + 1.528
        - 0.0002 * (t * hk).powi(2);
    close(
        "laminar_energy_shape_factor attached",
        laminar_energy_shape_factor(hk, 500.0, 0.0).value,
        want,
    );
    // Blasius (H = 2.591, H* = 1.5725): the Falkner–Skan fit is within 4e-3
    assert!((laminar_energy_shape_factor(2.591, 500.0, 0.0).value - 1.5725).abs() < 4e-3);
    // separated branch
    let hk: f64 = 6.0;
    close(
        "laminar_energy_shape_factor separated",
        laminar_energy_shape_factor(hk, 500.0, 0.0).value,
        0.015 * (hk - 4.35).powi(2) / hk + 1.528,
    );
    for hk in [1.8, 2.6, 3.5, 5.0, 7.0] {
        fd_check("laminar_energy_shape_factor", [hk, 300.0, 0.1], |a| {
            laminar_energy_shape_factor(a[0], a[1], a[2])
        });
    }
}

/// Independent evaluation of XFOIL HST (attached/separated, Re_θ floors, Whitfield factor).
fn hst_ref(hk: f64, rt: f64, msq: f64) -> f64 {
    let ho = if rt > 400.0 { 3.0 + 400.0 / rt } else { 4.0 };
    let rtz = if rt > 200.0 { rt } else { 200.0 };
    let hs = if hk < ho {
        let hr = (ho - hk) / (ho - 1.0);
        (2.0 - 1.5 - 4.0 / rtz) * hr * hr * 1.5 / (hk + 0.5) + 1.5 + 4.0 / rtz
    } else {
        let grt = rtz.ln();
        let hdif = hk - ho;
        let rtmp = hk - ho + 4.0 / grt;
        let htmp = 0.007 * grt / (rtmp * rtmp) + 0.015 / hk;
        hdif * hdif * htmp + 1.5 + 4.0 / rtz
    };
    (hs + 0.028 * msq) / (1.0 + 0.014 * msq)
}

#[test]
fn turbulent_hstar_all_branches() {
    for (hk, rt, msq) in [
        (1.4, 2000.0, 0.0),
        (1.6, 300.0, 0.2),
        (2.0, 150.0, 0.1),
        (3.5, 2000.0, 0.0),
        (4.5, 300.0, 0.3),
        (5.0, 100.0, 0.0),
    ] {
        check_closure(
            "turbulent_energy_shape_factor",
            [hk, rt, msq],
            |a| turbulent_energy_shape_factor(a[0], a[1], a[2]),
            hst_ref(hk, rt, msq),
        );
    }
}

#[test]
fn laminar_skin_friction_and_dissipation() {
    let (hk, rt): (f64, f64) = (2.59, 400.0);
    close(
        "laminar_skin_friction",
        laminar_skin_friction(hk, rt, 0.0).value,
        (0.0727 * (5.5 - hk).powi(3) / (hk + 1.0) - 0.07) / rt,
    );
    // Blasius: Cf·Re_θ = 0.664² = 0.441; the Falkner–Skan fit is within 3 % (0.429)
    assert!((laminar_skin_friction(2.591, 1.0, 0.0).value - 0.441).abs() < 0.03 * 0.441);
    let hk: f64 = 6.5;
    let t = 1.0 - 1.0 / (hk - 4.5);
    close(
        "laminar_skin_friction sep",
        laminar_skin_friction(hk, rt, 0.0).value,
        (0.015 * t * t - 0.07) / rt,
    );
    close(
        "laminar_dissipation",
        laminar_dissipation(2.59, rt).value,
        (0.00205 * (4.0f64 - 2.59).powf(5.5) + 0.207) / rt,
    );
    let hkb: f64 = 5.0 - 4.0;
    close(
        "laminar_dissipation sep",
        laminar_dissipation(5.0, rt).value,
        (-0.0016 * hkb * hkb / (1.0 + 0.02 * hkb * hkb) + 0.207) / rt,
    );
    let hs = laminar_energy_shape_factor(2.2, rt, 0.0).value;
    close(
        "laminar_wake_dissipation",
        laminar_wake_dissipation(2.2, rt).value,
        2.0 * 1.10 * (1.0 - 1.0 / 2.2f64).powi(2) / 2.2 / (hs * rt),
    );
    for hk in [2.2, 3.0, 4.5, 6.0] {
        fd_check("laminar_skin_friction", [hk, rt, 0.1], |a| {
            laminar_skin_friction(a[0], a[1], a[2])
        });
        fd_check("laminar_dissipation", [hk, rt], |a| {
            laminar_dissipation(a[0], a[1])
        });
        fd_check("laminar_wake_dissipation", [hk, rt], |a| {
            laminar_wake_dissipation(a[0], a[1])
        });
    }
}

/// ln 10 as rounded in XFOIL CFT.
#[allow(clippy::approx_constant)]
const XFOIL_LN10: f64 = 2.3026;

#[test]
fn turbulent_skin_friction_fit() {
    for (hk, rt, msq) in [(1.4f64, 3000.0, 0.0), (1.8, 800.0, 0.3), (2.5, 20.0, 0.1)] {
        let fc = (1.0f64 + 0.2 * msq).sqrt();
        let grt = (rt / fc).ln().max(3.0);
        let cfo = 0.3 * (-1.33 * hk).exp() * (grt / XFOIL_LN10).powf(-1.74 - 0.31 * hk);
        let want = (cfo + 1.1e-4 * ((4.0 - hk / 0.875).tanh() - 1.0)) / fc;
        check_closure(
            "turbulent_skin_friction",
            [hk, rt, msq],
            |a| turbulent_skin_friction(a[0], a[1], a[2]),
            want,
        );
    }
    // flat-plate order of magnitude: Hk 1.4, Re_θ 3000 → Cf ≈ 0.0033
    let cf = turbulent_skin_friction(1.4, 3000.0, 0.0).value;
    assert!(
        (0.0030..0.0036).contains(&cf),
        "turbulent_skin_friction = {cf}"
    );
}

#[test]
fn density_shape_and_slip_velocity() {
    check_closure(
        "density_shape_factor",
        [1.6, 0.25],
        |a| density_shape_factor(a[0], a[1]),
        0.25 * (0.064 / 0.8 + 0.251),
    );
    let gb = BlParams::default().equilibrium_locus_b;
    check_closure(
        "us",
        [1.75, 1.5, 1.55],
        |a| slip_velocity(a[0], a[1], a[2], gb),
        0.5 * 1.75 * (1.0 - 0.5 / (0.75 * 1.55)),
    );
}

#[test]
fn equilibrium_shear_stress() {
    let p = BlParams::default();
    let ctcon = p.equilibrium_ctau_constant();
    assert!((ctcon - 0.5 / (6.7 * 6.7 * 0.75)).abs() < 1e-15);
    let (hs, us, hk, h, rt) = (1.75, 0.4, 1.5, 1.55, 2000.0);
    let hkc: f64 = hk - 1.0 - 18.0 / rt;
    let want = (ctcon * hs * (hk - 1.0) * hkc * hkc / ((1.0 - us) * h * hk * hk)).sqrt();
    close(
        "cq wall",
        ctau_eq_sqrt(hs, us, hk, h, rt, true, ctcon, p.equilibrium_low_re_offset).value,
        want,
    );
    let want_wake = (ctcon * hs * (hk - 1.0).powi(3) / ((1.0 - us) * h * hk * hk)).sqrt();
    close(
        "cq wake",
        ctau_eq_sqrt(hs, us, hk, h, rt, false, ctcon, p.equilibrium_low_re_offset).value,
        want_wake,
    );
    for wall in [true, false] {
        fd_check("cq", [hs, us, hk, h, rt], |a| {
            ctau_eq_sqrt(
                a[0],
                a[1],
                a[2],
                a[3],
                a[4],
                wall,
                ctcon,
                p.equilibrium_low_re_offset,
            )
        });
    }
    let f = transition_ctau_factor(2.6, p.transition_ctau_factor, p.transition_ctau_exponent);
    close("ctr", f.value, 1.8 * (-3.3f64 / 1.6).exp());
    fd_check("ctr", [2.6], |a| {
        transition_ctau_factor(a[0], p.transition_ctau_factor, p.transition_ctau_exponent)
    });
}

#[test]
fn turbulent_dissipation() {
    let (hs, us, cf, s, hk, rt): (f64, f64, f64, f64, f64, f64) =
        (1.75, 0.4, 0.003, 0.08, 1.5, 2000.0);
    let hmin = 1.0 + 2.1 / rt.ln();
    let dfac = 0.5 + 0.5 * ((hk - 1.0) / (hmin - 1.0)).tanh();
    let outer = s * s * (0.995 - us) * 2.0 / hs + 0.15 * (0.995 - us).powi(2) / rt * 2.0 / hs;
    close(
        "dit",
        dissipation_turbulent(hs, us, cf, s, hk, rt).value,
        cf * us / hs * dfac + outer,
    );
    close("dd", dissipation_outer(hs, us, s, rt).value, outer);
    fd_check("dit", [hs, us, cf, s, hk, rt], |a| {
        dissipation_turbulent(a[0], a[1], a[2], a[3], a[4], a[5])
    });
    fd_check("dd", [hs, us, s, rt], |a| {
        dissipation_outer(a[0], a[1], a[2], a[3])
    });
}

#[test]
fn bl_thickness_green() {
    close(
        "delta",
        bl_thickness(1.5, 1e-3, 1.5e-3).value,
        (3.15 + 1.72 / 0.5) * 1e-3 + 1.5e-3,
    );
    // limited to 12 θ for Hk → 1
    close("delta cap", bl_thickness(1.1, 1e-3, 1.1e-3).value, 12e-3);
    fd_check("delta", [1.5, 1e-3, 1.5e-3], |a| {
        bl_thickness(a[0], a[1], a[2])
    });
}

/// Independent evaluation of XFOIL DAMPL.
fn dampl_ref(hk: f64, th: f64, rt: f64) -> f64 {
    let hmi = 1.0 / (hk - 1.0);
    let grc = 2.492 * hmi.powf(0.43) + 0.7 * ((14.0 * hmi - 9.24).tanh() + 1.0);
    let gr = rt.log10();
    if gr < grc - 0.08 {
        return 0.0;
    }
    let rn = (gr - (grc - 0.08)) / 0.16;
    let rfac = if rn >= 1.0 {
        1.0
    } else {
        3.0 * rn * rn - 2.0 * rn.powi(3)
    };
    let arg = 3.87 * hmi - 2.52;
    let dadr = 0.028 * (hk - 1.0) - 0.0345 * (-arg * arg).exp();
    let af = -0.05 + 2.7 * hmi - 5.5 * hmi * hmi + 3.0 * hmi.powi(3);
    af * dadr / th * rfac
}

#[test]
fn envelope_amplification_rate() {
    // below critical Re_θ: zero; Blasius Re_θcrit ≈ 200 (log10 ≈ 2.3)
    assert_eq!(amplification_rate(2.59, 1e-4, 100.0).value, 0.0);
    assert!(amplification_rate(2.59, 1e-4, 400.0).value > 0.0);
    for (hk, th, rt) in [(2.59, 2e-4, 1000.0), (3.5, 3e-4, 300.0), (2.4, 1e-4, 195.0)] {
        check_closure(
            "amplification_rate",
            [hk, th, rt],
            |a| amplification_rate(a[0], a[1], a[2]),
            dampl_ref(hk, th, rt),
        );
    }
}
