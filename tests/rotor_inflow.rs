//! Momentum-theory limits of the inflow models and the tip-loss factor.

use polargen::rotor::inflow::{
    drees_coefficients, gessow_myers_tip_loss, glauert_induced_velocity, glauert_thrust,
};

const RHO: f64 = 1.225;
/// MTOsport disc area π·4.2² [m²].
const AREA: f64 = std::f64::consts::PI * 4.2 * 4.2;

#[test]
fn hover_limit_is_sqrt_t_over_2_rho_a() {
    for thrust in [500.0, 4414.0, 9000.0] {
        let v = glauert_induced_velocity(thrust, RHO, AREA, 0.0, 0.0);
        let expected = (thrust / (2.0 * RHO * AREA)).sqrt();
        assert!(
            (v - expected).abs() < 1e-9 * expected,
            "T={thrust}: {v} vs {expected}"
        );
    }
}

#[test]
fn high_speed_limit_is_t_over_2_rho_a_v() {
    // λ_i → T/(2ρAV) when V ≫ v_i (Glauert); relative error is O((v_i/V)²).
    let thrust = 4414.0;
    for (v, tol) in [(30.0, 5e-3), (60.0, 1.5e-3), (120.0, 3e-4)] {
        let vi = glauert_induced_velocity(thrust, RHO, AREA, v, 5f64.to_radians());
        let expected = thrust / (2.0 * RHO * AREA * v);
        assert!(
            (vi / expected - 1.0).abs() < tol,
            "V={v}: {vi} vs {expected}"
        );
    }
}

#[test]
fn momentum_inverse_round_trip_and_mirror() {
    let (v, a) = (25.0, 8f64.to_radians());
    for thrust in [100.0, 2000.0, 4414.0] {
        let vi = glauert_induced_velocity(thrust, RHO, AREA, v, a);
        let back = glauert_thrust(vi, RHO, AREA, v, a);
        assert!((back - thrust).abs() < 1e-6 * thrust, "{back} vs {thrust}");
    }
    // Negative thrust: the mirrored problem (flow reversed through the disc).
    let vp = glauert_induced_velocity(3000.0, RHO, AREA, v, a);
    let vn = glauert_induced_velocity(-3000.0, RHO, AREA, v, -a);
    assert!((vp + vn).abs() < 1e-9, "{vp} vs {vn}");
}

#[test]
fn windmill_state_takes_the_small_root() {
    // Axial upflow of 20 m/s, no edgewise speed: v(U − v) = T/(2ρA) has two roots; the
    // physical windmill-brake branch is v = (U − √(U² − 4 T/(2ρA)))/2.
    let (u, thrust) = (20.0, 4414.0);
    let s = thrust / (2.0 * RHO * AREA);
    let expected = 0.5 * (u - (u * u - 4.0 * s).sqrt());
    let v = glauert_induced_velocity(thrust, RHO, AREA, u, std::f64::consts::FRAC_PI_2);
    assert!((v - expected).abs() < 1e-6, "{v} vs {expected}");
}

#[test]
fn drees_gradients() {
    let (kx, ky) = drees_coefficients(0.0, 0.02);
    assert!(kx.abs() < 1e-12 && ky.abs() < 1e-12, "hover: {kx} {ky}");
    // Edgewise limit χ → 90°: k_x → (4/3)(1 − 1.8 μ²), k_y = −2μ.
    let mu = 0.2;
    let (kx, ky) = drees_coefficients(mu, 1e-9);
    assert!(
        (kx - 4.0 / 3.0 * (1.0 - 1.8 * mu * mu)).abs() < 1e-6,
        "{kx}"
    );
    assert!((ky + 0.4).abs() < 1e-12, "{ky}");
    // χ = 45°: (4/3)(1 − cos45° − 1.8·0.01)/sin45°.
    let (kx, _) = drees_coefficients(0.1, 0.1);
    let c = std::f64::consts::FRAC_1_SQRT_2;
    assert!(
        (kx - 4.0 / 3.0 * (1.0 - c - 0.018) / c).abs() < 1e-9,
        "{kx}"
    );
}

#[test]
fn gessow_myers_tip_loss_value() {
    // C_T = 0.0028 (MTOsport cruise), N_b = 2: B = 1 − √0.0056/2 = 0.96258.
    let b = gessow_myers_tip_loss(0.0028, 2);
    assert!((b - 0.962_583).abs() < 1e-5, "{b}");
    assert_eq!(gessow_myers_tip_loss(0.0, 2), 1.0);
}
