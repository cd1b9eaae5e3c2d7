//! Induced inflow of the rotor: Glauert's momentum theory in forward flight, Drees' linear
//! inflow distribution, the tip-loss models ([`TipLoss`]: Prandtl's factor from the local
//! inflow angle, Gessow–Myers, the chord rule, none) and the yawed-flow profile-drag switch
//! ([`YawedFlow`]).
//!
//! Sign convention (gyroplane): the free stream passes *up* through a disc tilted back by
//! α; the induced velocity `v_i` is positive *downwards* (opposing positive thrust), so the
//! net upflow through the disc is V·sin α − v_i.

use crate::numerics::roots::{bracketed_root_of, first_rising_bracket};
use serde::Deserialize;

/// Induced-inflow model, as named in an aircraft preset (`inflow = "glauert"` or `"drees"`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum InflowModel {
    /// Uniform inflow from Glauert's momentum theory.
    Glauert,
    /// Glauert's mean value with Drees' linear fore-aft and lateral gradients.
    Drees,
}

/// Tip-loss model of the rotor, as named in an aircraft preset (`tip_loss = "…"`). Each lets
/// the outermost part of the blade carry drag but less or no lift.
///
/// Why Prandtl's factor is the physical choice for an autorotating rotor: the classical hover
/// factors describe the tip vortices of a wake that leaves the disc slowly along the axis. In
/// autorotation at μ ≈ 0.2 the net inflow ratio is small (λ ≈ 0.01) and the wake is swept away
/// edgewise; Prandtl's factor, evaluated from each strip's own inflow angle, tends to the right
/// limit there (from the mean inflow alone B = 1 − 2 ln 2·λ/N_b ≈ 0.998; the local angles
/// include the blades' flapping velocity, B ≈ 0.98), while
/// Gessow–Myers' hover relation B = 1 − √(2C_T)/N_b takes the tip loss of a hovering rotor of the
/// same thrust (B ≈ 0.96). The chord rule bounds the finite-span tip unloading that remains.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
pub enum TipLoss {
    /// Prandtl's factor F = (2/π) acos(e^(−f)), f = (N_b/2)(1 − r/R)/((r/R) sin φ), scaling
    /// each strip's lift by the mean of F over the strip (Prandtl's appendix to Betz,
    /// "Schraubenpropeller mit geringstem Energieverlust", Göttinger Nachrichten 1919; Leishman,
    /// *Principles of Helicopter Aerodynamics*, 2nd ed., ch. 3, the tip-loss function of
    /// blade-element momentum theory). φ is the local inflow angle of each strip and azimuth
    /// measured against the blade's rotation, atan(|U_P|/Ωr): U_P carries the 1/rev flapping
    /// velocity (at 60 kt about ten times the mean inflow; equivalent B ≈ 0.986 clean, 0.981
    /// contaminated for the MTOsport), while the in-plane free-stream component, which skews the
    /// wake sideways but does not steepen the tip-vortex helix, is left out (taken with the
    /// whole U_T, which vanishes at the reverse-flow circle, φ would reach 90° on the retreating
    /// side and unload its whole outer blade).
    #[serde(rename = "prandtl")]
    Prandtl,
    /// B = 1 − √(2C_T)/N_b from the current thrust coefficient (Gessow & Myers, *Aerodynamics of
    /// the Helicopter*, 1952; a hover relation).
    #[serde(rename = "gessow_myers")]
    GessowMyers,
    /// B = 1 − c/(2R): the lift-free tip is half a chord long, the finite-span unloading of a
    /// blade tip (Gessow & Myers 1952; Bailey's lifting-rotor charts, NACA Report 716, 1941,
    /// use B = 0.97, the MTOsport's 1 − 0.2/8.4 = 0.976).
    #[serde(rename = "chord")]
    Chord,
    /// No tip loss: B = 1.
    #[serde(rename = "none")]
    NoLoss,
}

/// Profile drag of a blade element in yawed flow, as named in an aircraft preset
/// (`yawed_flow = "…"`).
///
/// In forward flight the air also runs along the blade, U_R = V cos α_H cos ψ. By the
/// independence principle of the yawed boundary layer (Jones, NACA Report 884, 1947) lift,
/// α, Re and M follow from the chord-normal components alone; whether the skin friction acts
/// along the whole relative wind is the switch. With it the forward-flight profile power
/// (σc_d0/8)(1 + Kμ²) has K ≈ 4.6–4.7 instead of 3 (Leishman, *Principles of Helicopter
/// Aerodynamics*, 2nd ed., ch. 5, profile power in forward flight; Johnson, *Helicopter
/// Theory*, 1980, ch. 5; Stepniewski & Keys, *Rotary-Wing Aerodynamics*, 1984). Harris
/// (NASA/CR-2008-215370) compares such profile-power models with rotor tests at high μ.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
pub enum YawedFlow {
    /// Profile drag ½ρc·c_d·W₃·(U_T, U_P, U_R) along the full relative wind,
    /// W₃ = √(U_T² + U_P² + U_R²).
    #[serde(rename = "radial_drag")]
    RadialDrag,
    /// The radial component is ignored: profile drag on the chord-normal speed only.
    #[serde(rename = "none")]
    Ignored,
}

/// Prandtl exponents above this give F = 1 to within 2e-9.
const PRANDTL_EXPONENT_CAP: f64 = 20.0;

/// Simpson intervals of the strip mean of Prandtl's factor on a strip that reaches the tip,
/// where F falls to zero. Largest error of the mean against 2 048 intervals, MTOsport tip strip
/// (x 0.912 … 1, two blades), sin φ ∈ [0.001, 1]: 8e-6.
const PRANDTL_SIMPSON_INTERVALS_TIP: usize = 16;

/// Simpson intervals of the strip mean of Prandtl's factor on a strip inboard of the tip,
/// where F is smooth and above zero. Largest error against 2 048 intervals, the nine inboard
/// MTOsport strips, sin φ ∈ [0.001, 1]: 3e-7 (16 intervals: 2e-8), below the tip strip's.
const PRANDTL_SIMPSON_INTERVALS_INBOARD: usize = 8;

/// Prandtl's tip-loss factor at radius fraction `x` for `blades` blades and inflow angle with
/// sine `sin_phi`: F = (2/π) acos(e^(−f)), f = (N_b/2)(1 − x)/(x sin φ) ([`TipLoss::Prandtl`]).
pub fn prandtl_factor(x: f64, sin_phi: f64, blades: u32) -> f64 {
    let den = x * sin_phi.abs();
    if den.is_nan() || den <= 0.0 {
        return 1.0;
    }
    let f = 0.5 * f64::from(blades) * (1.0 - x).max(0.0) / den;
    if f >= PRANDTL_EXPONENT_CAP {
        1.0
    } else {
        std::f64::consts::FRAC_2_PI * (-f).exp().acos()
    }
}

/// Mean of [`prandtl_factor`] over the strip x1 … x2 (radius fractions, x2 ≤ 1) at one inflow
/// angle: composite Simpson in w = √(1 − x), in which F rises linearly from the tip instead of
/// like √(1 − x), so that the thin unloaded tip is resolved; 16 intervals on the tip strip, 8
/// inboard (the constants give the measured errors).
pub fn prandtl_strip_mean(x1: f64, x2: f64, sin_phi: f64, blades: u32) -> f64 {
    if prandtl_factor(x2.min(1.0), sin_phi, blades) >= 1.0 || x2 <= x1 {
        return 1.0;
    }
    let (w_lo, w_hi) = ((1.0 - x2.min(1.0)).sqrt(), (1.0 - x1).sqrt());
    // A strip whose outer edge lies at the tip to round-off.
    let n = if x2 > 1.0 - 1e-9 {
        PRANDTL_SIMPSON_INTERVALS_TIP
    } else {
        PRANDTL_SIMPSON_INTERVALS_INBOARD
    };
    let h = (w_hi - w_lo) / n as f64;
    // ∫ F dx = ∫ F(1 − w²)·2w dw.
    let g = |w: f64| prandtl_factor(1.0 - w * w, sin_phi, blades) * 2.0 * w;
    let inner: f64 = (1..n)
        .map(|k| (if k % 2 == 1 { 4.0 } else { 2.0 }) * g(w_lo + k as f64 * h))
        .sum();
    (h / 3.0 * (g(w_lo) + inner + g(w_hi)) / (x2 - x1)).min(1.0)
}

/// Number of scan intervals used to bracket the smallest momentum-theory root.
const SCAN_INTERVALS: usize = 64;

/// Relative width of the bracket at which the momentum-theory root is accepted.
const ROOT_TOLERANCE: f64 = 1e-12;

/// Most refinement steps of the momentum-theory root.
const ROOT_ITERATIONS: usize = 100;

/// Uniform induced velocity from Glauert's momentum theory in forward flight,
/// T = 2ρA·v_i·V′ with V′ = √((V cos α)² + (V sin α − v_i)²)
/// (Glauert 1926; Leishman, *Principles of Helicopter Aerodynamics*, 2nd ed., §2.14, with the
/// sign of the axial free-stream component reversed for an autorotating disc).
///
/// `thrust` \[N\], `density` [kg/m³], `area` \[m²\], `airspeed` \[m/s\], `disc_aoa` \[rad\] (positive
/// = disc tilted back, flow up through the disc). Returns v_i \[m/s\], positive downwards.
/// For negative thrust the mirrored problem is solved. Where several momentum solutions exist
/// (windmill-brake state) the smallest |v_i| is returned, the physical branch.
pub fn glauert_induced_velocity(
    thrust: f64,
    density: f64,
    area: f64,
    airspeed: f64,
    disc_aoa: f64,
) -> f64 {
    if !(thrust.is_finite() && density > 0.0 && area > 0.0) || thrust == 0.0 {
        return 0.0;
    }
    let sign = thrust.signum();
    let target = thrust.abs() / (2.0 * density * area);
    let edge = airspeed * disc_aoa.cos();
    // Mirror for negative thrust: v → −v and the axial component changes sign.
    let axial = sign * airspeed * disc_aoa.sin();
    let g = |v: f64| v * (edge * edge + (axial - v).powi(2)).sqrt() - target;
    // g(0) = −target < 0 and g(v) ≥ v (v − axial) ≥ target beyond this bound.
    let upper = axial.max(0.0) + target.sqrt() + 1e-9;
    let step = upper / SCAN_INTERVALS as f64;
    let grid = (0..=SCAN_INTERVALS).map(|k| step * k as f64);
    let (lo, hi) = first_rising_bracket(grid, g).unwrap_or(((0.0, g(0.0)), (upper, g(upper))));
    sign * bracketed_root_of(g, lo, hi, ROOT_TOLERANCE * (1.0 + upper), ROOT_ITERATIONS)
}

/// Thrust that momentum theory associates with a uniform induced velocity `v_i`:
/// T = 2ρA·v_i·V′ (the inverse of [`glauert_induced_velocity`] on its physical branch).
pub fn glauert_thrust(v_i: f64, density: f64, area: f64, airspeed: f64, disc_aoa: f64) -> f64 {
    let edge = airspeed * disc_aoa.cos();
    let axial = airspeed * disc_aoa.sin();
    2.0 * density * area * v_i * (edge * edge + (axial - v_i).powi(2)).sqrt()
}

/// First-harmonic gradients (k_x, k_y) of Drees' linear inflow
/// v_i(r, ψ) = v_0 (1 + k_x (r/R) cos ψ + k_y (r/R) sin ψ), ψ = 0 downstream:
/// k_x = (4/3)(1 − cos χ − 1.8 μ²)/sin χ, k_y = −2μ (Drees 1949; Leishman, *Principles of
/// Helicopter Aerodynamics*, 2nd ed., §10.2, Table 10.1).
///
/// `mu` = V cos α/(ΩR), `lambda` = net through-flow ratio |V sin α − v_0|/(ΩR). The wake skew
/// angle is taken as χ = atan(μ/|λ|) ∈ [0, 90°] (for an autorotating disc the through-flow is
/// upwards; the skew magnitude is what matters to the model).
pub fn drees_coefficients(mu: f64, lambda: f64) -> (f64, f64) {
    let chi = mu.abs().atan2(lambda.abs());
    let kx = if chi.sin() < 1e-6 {
        0.0
    } else {
        (4.0 / 3.0) * (1.0 - chi.cos() - 1.8 * mu * mu) / chi.sin()
    };
    (kx, -2.0 * mu)
}

/// Gessow–Myers tip-loss factor B = 1 − √(2 C_T)/N_b: blade elements outboard of B·R carry
/// drag but no lift (Gessow & Myers 1952, *Aerodynamics of the Helicopter*; Leishman,
/// *Principles of Helicopter Aerodynamics*, 2nd ed., §3.5). Negative C_T is treated as |C_T|.
pub fn gessow_myers_tip_loss(thrust_coefficient: f64, blades: u32) -> f64 {
    let nb = f64::from(blades.max(1));
    (1.0 - (2.0 * thrust_coefficient.abs()).sqrt() / nb).clamp(0.5, 1.0)
}

#[cfg(test)]
mod tests {
    //! Momentum-theory limits of the inflow models and the tip-loss factor.

    use super::*;

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
    fn prandtl_strip_mean_has_the_classical_lift_free_length() {
        for sin_phi in [0.005, 0.011, 0.03] {
            let x1 = 0.9;
            let deficit = (1.0 - prandtl_strip_mean(x1, 1.0, sin_phi, 2)) * (1.0 - x1);
            // Against a fine midpoint rule in x (10⁵ points).
            let n = 100_000;
            let dx = (1.0 - x1) / n as f64;
            let fine: f64 = (0..n)
                .map(|k| (1.0 - prandtl_factor(x1 + (k as f64 + 0.5) * dx, sin_phi, 2)) * dx)
                .sum();
            assert!(
                (deficit / fine - 1.0).abs() < 2e-3,
                "sin φ {sin_phi}: {deficit} vs {fine}"
            );
            // Small inflow angles: the lift-free tip length tends to 2 ln 2·sin φ/N_b
            // (∫₀^∞ (2/π) asin(e^(−s)) ds = ln 2), the classical equivalent B = 1 − 1.386 λ/N_b;
            // the 1/x of the exponent shortens it by about the relative length of the loss.
            let classical = 2.0 * std::f64::consts::LN_2 * sin_phi / 2.0;
            assert!(
                deficit < classical && deficit > classical * (1.0 - 3.0 * sin_phi),
                "sin φ {sin_phi}: {deficit} vs {classical}"
            );
        }
        // Inboard strips and zero inflow angle: no loss; the factor vanishes at the tip.
        assert_eq!(prandtl_strip_mean(0.5, 0.6, 0.011, 2), 1.0);
        assert_eq!(prandtl_strip_mean(0.9, 1.0, 0.0, 2), 1.0);
        assert_eq!(prandtl_factor(1.0, 0.011, 2), 0.0);
    }

    #[test]
    fn gessow_myers_tip_loss_value() {
        // C_T = 0.0028 (MTOsport cruise), N_b = 2: B = 1 − √0.0056/2 = 0.96258.
        let b = gessow_myers_tip_loss(0.0028, 2);
        assert!((b - 0.962_583).abs() < 1e-5, "{b}");
        assert_eq!(gessow_myers_tip_loss(0.0, 2), 1.0);
    }
}
