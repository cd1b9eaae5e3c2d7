//! One blade element (strip): velocity triangle → (α, Re, M) → section coefficients → loads.
//!
//! Section frame: `t` points along the blade's direction of rotation (towards the leading
//! edge in normal flow), `n` is normal to the blade, upwards. U_T is the air speed relative to
//! the blade along −t seen from the blade (positive in normal flow), U_P the air speed coming
//! up through the rotor (positive = upflow, as in autorotation).
//!
//! The flow angle φ = atan2(U_P, U_T) is kept over the full circle, so in the reverse-flow
//! region (U_T < 0, the air arrives at the trailing edge) α = θ + φ lies near ±180° and the
//! section's 360° model supplies the coefficients. Lift is perpendicular to the relative wind
//! with the same orientation for every α, so its sign follows from c_l without special cases
//! (blade-element theory: Leishman, *Principles of Helicopter Aerodynamics*, 2nd ed., §3.2).
//!
//! Yawed (radial) flow: in forward flight the air also runs along the blade, U_R = V cos α_H cos ψ.
//! By the independence principle lift, α, Re and M follow from the chord-normal components
//! (U_T, U_P) alone; with the radial component set ([`StripFlow::with_radial`]) skin friction
//! acts along the whole relative wind, so the profile drag is ½ρc·c_d·W₃·(U_T, U_P, U_R) with
//! W₃ = √(U_T² + U_P² + U_R²). This raises the forward-flight profile power from
//! (σc_d0/8)(1 + 3μ²) to about (σc_d0/8)(1 + 4.6μ²); the preset switches it
//! ([`YawedFlow`](super::YawedFlow), where the sources are).

use super::spanwise::BladeSection;
use crate::section::{wrap_deg, Lookup};

/// Air state used by a strip (density, viscosity and speed of sound).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AirState {
    /// Density [kg/m³].
    pub density: f64,
    /// Dynamic viscosity [Pa s].
    pub viscosity: f64,
    /// Speed of sound \[m/s\].
    pub speed_of_sound: f64,
}

/// Local flow at one strip.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StripFlow {
    /// In-plane (tangential) air speed, positive when the air meets the leading edge \[m/s\].
    pub ut: f64,
    /// Upflow through the rotor normal to the blade \[m/s\].
    pub up: f64,
    /// Radial (spanwise) air speed along the blade, outwards positive \[m/s\]; it adds profile
    /// drag only (see the module documentation). Zero unless set with [`StripFlow::with_radial`].
    pub ur: f64,
    /// Resultant speed W = √(U_T² + U_P²) \[m/s\].
    pub speed: f64,
    /// Section angle of attack α = θ + atan2(U_P, U_T), wrapped to (−180°, 180°] \[deg\].
    pub alpha_deg: f64,
    /// Chord Reynolds number ρWc/μ.
    pub reynolds: f64,
    /// Mach number W/a.
    pub mach: f64,
}

impl StripFlow {
    /// Velocity triangle of a strip with pitch `theta` \[rad\] and chord `chord` \[m\].
    pub fn new(ut: f64, up: f64, theta: f64, chord: f64, air: &AirState) -> Self {
        let speed = ut.hypot(up);
        let phi = up.atan2(ut);
        Self {
            ut,
            up,
            ur: 0.0,
            speed,
            alpha_deg: wrap_deg((theta + phi).to_degrees()),
            reynolds: air.density * speed * chord / air.viscosity,
            mach: speed / air.speed_of_sound,
        }
    }

    /// The same strip with radial (spanwise) air speed `ur` \[m/s\], outwards positive.
    pub fn with_radial(self, ur: f64) -> Self {
        Self { ur, ..self }
    }

    /// Resultant speed including the radial component, W₃ = √(W² + U_R²) \[m/s\].
    pub fn speed_with_radial(&self) -> f64 {
        self.speed.hypot(self.ur)
    }

    /// True when the air arrives at the trailing edge (U_T < 0).
    pub fn is_reversed(&self) -> bool {
        self.ut < 0.0
    }

    /// Section coefficients from `section` at this strip's (α, Re, M), the strip centred at
    /// radius fraction `r_over_r`.
    pub fn coefficients<S: BladeSection + ?Sized>(&self, section: &S, r_over_r: f64) -> Lookup {
        section.lookup_at(r_over_r, self.alpha_deg, self.reynolds, self.mach)
    }
}

/// Aerodynamic load per unit span of a strip [N/m].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StripLoad {
    /// Force along the direction of rotation (positive drives the rotor).
    pub tangential: f64,
    /// Force normal to the blade, upwards (thrust and flap moment).
    pub normal: f64,
    /// Force along the blade, outwards (radial-flow profile drag; H-force and side force).
    pub radial: f64,
}

/// Loads per unit span from the velocity triangle: lift on the chord-normal speed W, profile
/// drag on the full speed W₃ (yawed flow, module documentation),
/// F_t = ½ρc (c_l·W·U_P − c_d·W₃·U_T), F_n = ½ρc (c_l·W·U_T + c_d·W₃·U_P), F_r = ½ρc·c_d·W₃·U_R.
/// `lift_factor` ∈ [0, 1] scales the lift only (tip loss: the part of the strip outboard of
/// B·R carries drag but no lift).
pub fn strip_load(
    flow: &StripFlow,
    coeffs: &Lookup,
    density: f64,
    chord: f64,
    lift_factor: f64,
) -> StripLoad {
    let k_lift = 0.5 * density * flow.speed * chord * coeffs.cl * lift_factor;
    let k_drag = 0.5 * density * flow.speed_with_radial() * chord * coeffs.cd;
    StripLoad {
        tangential: k_lift * flow.up - k_drag * flow.ut,
        normal: k_lift * flow.ut + k_drag * flow.up,
        radial: k_drag * flow.ur,
    }
}
