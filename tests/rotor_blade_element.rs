//! Strip velocity triangle, sign handling and reverse flow.

mod rotor_support;

use polargen::rotor::{strip_load, AirState, StripFlow};
use polargen::section::{Lookup, SectionAero};

const AIR: AirState = AirState {
    density: 1.225,
    viscosity: 1.789e-5,
    speed_of_sound: 340.3,
};

/// Fore-aft symmetric flat plate (Hoerner): cl = 1.1 sin 2α, cd = 0.01 + 1.9 sin²α.
struct FlatPlate;

impl SectionAero for FlatPlate {
    fn lookup(&self, alpha_deg: f64, _re: f64, _mach: f64) -> Lookup {
        let a = alpha_deg.to_radians();
        Lookup::new(1.1 * (2.0 * a).sin(), 0.01 + 1.9 * a.sin().powi(2), 0.0)
    }
}

#[test]
fn normal_flow_triangle() {
    let theta = 2.5f64.to_radians();
    let f = StripFlow::new(150.0, 6.0, theta, 0.2, &AIR);
    let alpha = 2.5 + (6.0f64 / 150.0).atan().to_degrees();
    assert!((f.alpha_deg - alpha).abs() < 1e-12);
    assert!((f.speed - 150.0f64.hypot(6.0)).abs() < 1e-12);
    assert!((f.reynolds - 1.225 * f.speed * 0.2 / 1.789e-5).abs() < 1e-6 * f.reynolds);
    assert!((f.mach - f.speed / 340.3).abs() < 1e-15);
    assert!(!f.is_reversed());
    // Upflow and positive lift: the lift vector leans forward and drives the rotor when
    // cl·U_P > cd·U_T (autorotation), and the normal force is upward.
    let c = Lookup::new(0.6, 0.008, 0.0);
    let l = strip_load(&f, &c, 1.225, 0.2, 1.0);
    let q = 0.5 * 1.225 * f.speed * 0.2;
    assert!((l.tangential - q * (0.6 * 6.0 - 0.008 * 150.0)).abs() < 1e-9);
    assert!(l.tangential > 0.0 && l.normal > 0.0);
    // Tip loss removes lift only: the remaining tangential force is pure drag.
    let l0 = strip_load(&f, &c, 1.225, 0.2, 0.0);
    assert!((l0.tangential + q * 0.008 * 150.0).abs() < 1e-9);
}

#[test]
fn reverse_flow_angle_is_near_180_degrees() {
    let theta = 2.5f64.to_radians();
    let f = StripFlow::new(-10.0, 0.0, theta, 0.2, &AIR);
    assert!(f.is_reversed());
    assert!((f.alpha_deg - (-177.5)).abs() < 1e-9, "{}", f.alpha_deg);
    let f = StripFlow::new(-10.0, 1.0, theta, 0.2, &AIR);
    // atan2(1, −10) = 174.29°, + 2.5° = 176.79°.
    assert!(
        (f.alpha_deg - (2.5 + 1f64.atan2(-10.0).to_degrees())).abs() < 1e-9,
        "{}",
        f.alpha_deg
    );
}

#[test]
fn reverse_flow_loads_mirror_forward_flow() {
    // A fore-aft symmetric plate at pitch θ with the air arriving at the trailing edge is the
    // mirror image (t → −t) of the plate at pitch −θ in normal flow: same normal force,
    // opposite tangential force.
    let section = FlatPlate;
    for (theta_deg, ut, up) in [(2.5, 20.0, 0.0), (2.5, 20.0, 3.0), (6.0, 12.0, -2.0)] {
        let theta = f64::to_radians(theta_deg);
        let rev = StripFlow::new(-ut, up, theta, 0.2, &AIR);
        let fwd = StripFlow::new(ut, up, -theta, 0.2, &AIR);
        let lr = strip_load(&rev, &rev.coefficients(&section, 0.5), 1.225, 0.2, 1.0);
        let lf = strip_load(&fwd, &fwd.coefficients(&section, 0.5), 1.225, 0.2, 1.0);
        assert!(
            (lr.normal - lf.normal).abs() < 1e-9 * (1.0 + lf.normal.abs()),
            "{lr:?} {lf:?}"
        );
        assert!(
            (lr.tangential + lf.tangential).abs() < 1e-9 * (1.0 + lf.tangential.abs()),
            "{lr:?} {lf:?}"
        );
    }
    // Air from behind on a nose-up plate hits its upper surface: the normal force is down and
    // the drag pushes the blade backwards (along the air's motion, +t here).
    let rev = StripFlow::new(-20.0, 0.0, 2.5f64.to_radians(), 0.2, &AIR);
    let l = strip_load(&rev, &rev.coefficients(&section, 0.5), 1.225, 0.2, 1.0);
    assert!(l.normal < 0.0 && l.tangential > 0.0, "{l:?}");
}

#[test]
fn analytic_sections_are_continuous_over_the_circle() {
    for s in [
        rotor_support::AnalyticSection::clean(),
        rotor_support::AnalyticSection::contaminated(),
    ] {
        let mut prev = s.lookup(-180.0, 2e6, 0.4);
        for k in 1..=3600 {
            let a = -180.0 + 0.1 * k as f64;
            let c = s.lookup(a, 2e6, 0.4);
            assert!(
                (c.cl - prev.cl).abs() < 0.05 && (c.cd - prev.cd).abs() < 0.02,
                "jump at {a}"
            );
            assert!(c.cd > 0.0);
            prev = c;
        }
    }
}

#[test]
fn radial_flow_adds_profile_drag_only() {
    // Yawed flow: α, Re, M and the lift come from (U_T, U_P); the profile drag acts along the
    // full relative wind W₃ = √(U_T² + U_P² + U_R²) with magnitude ½ρW₃²c·c_d.
    let theta = 2.5f64.to_radians();
    let (ut, up, ur) = (120.0, 4.0, 30.0);
    let plain = StripFlow::new(ut, up, theta, 0.2, &AIR);
    let yawed = plain.with_radial(ur);
    assert_eq!(yawed.alpha_deg, plain.alpha_deg);
    assert_eq!(yawed.reynolds, plain.reynolds);
    assert_eq!(yawed.mach, plain.mach);
    let w3 = (ut * ut + up * up + ur * ur).sqrt();
    assert!((yawed.speed_with_radial() - w3).abs() < 1e-12);
    let (rho, c) = (1.225, 0.2);
    // Lift only: the radial speed changes nothing.
    let lift_only = Lookup::new(0.5, 0.0, 0.0);
    let a = strip_load(&plain, &lift_only, rho, c, 1.0);
    let b = strip_load(&yawed, &lift_only, rho, c, 1.0);
    assert_eq!(
        (a.tangential, a.normal, b.radial),
        (b.tangential, b.normal, 0.0)
    );
    // Drag only: the force is antiparallel to the blade's motion through the air (parallel to
    // the air's velocity (−U_T along t, U_P, U_R)) with magnitude ½ρW₃²c·c_d.
    let drag_only = Lookup::new(0.0, 0.01, 0.0);
    let d = strip_load(&yawed, &drag_only, rho, c, 1.0);
    let mag = (d.tangential.powi(2) + d.normal.powi(2) + d.radial.powi(2)).sqrt();
    assert!((mag - 0.5 * rho * w3 * w3 * c * 0.01).abs() < 1e-9 * mag);
    assert!((d.tangential / mag + ut / w3).abs() < 1e-12);
    assert!((d.normal / mag - up / w3).abs() < 1e-12);
    assert!((d.radial / mag - ur / w3).abs() < 1e-12);
    // The drag that opposes the rotation grows by W₃/W.
    let d0 = strip_load(&plain, &drag_only, rho, c, 1.0);
    assert!((d.tangential / d0.tangential - w3 / plain.speed).abs() < 1e-12);
}
