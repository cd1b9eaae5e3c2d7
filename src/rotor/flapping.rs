//! First-harmonic blade flapping and the hub that decides which of its coefficients are free.
//!
//! Every blade follows the same periodic motion in its own azimuth, β(ψ) = β0 + β1c cos ψ +
//! β1s sin ψ, so one blade at every azimuth stands for all of them ([`Flapping`]). The hub
//! ([`Hub`]) sets the equations the coefficients obey:
//!
//! * **teetering** — two blades on one beam on a bolt at the shaft: the coning β0 is the hub
//!   bar's precone and only β1c, β1s are free. A centrally hinged rigid blade pair has a flap
//!   frequency of exactly 1/rev, so the inertial and centrifugal terms cancel for a 1/rev motion
//!   and the first harmonics of the aerodynamic flap moment about the bolt vanish (Leishman,
//!   *Principles of Helicopter Aerodynamics*, 2nd ed., §4.8 with ν_β = 1).
//! * **articulated** — each blade on its own flapping hinge at distance e from the shaft, with
//!   flapping inertia I_β and first mass moment S_β about the hinge. Rigid-blade flapping,
//!   I_β (β̈ + ν_β² Ω² β) = M_β − M_W with ν_β² = 1 + e S_β/I_β (Leishman §4.3–4.5; Johnson,
//!   *Helicopter Theory*, 1980, §5.4; the hinge at the shaft, e = 0, is Wheatley's eq. 6-3, NACA
//!   Report 487), balanced harmonic by harmonic: the coning from the mean moment,
//!   I_β Ω² ν_β² β0 = M_0 − M_W, and (ν_β² − 1) I_β Ω² β1c,1s = M_1c,1s. The blade weight
//!   moment M_W = S_β g cos α_H acts along the shaft. The coning so comes out of the balance of
//!   aerodynamic and centrifugal moments, whose ratio is the Lock number γ = ρ a c R⁴/I_β.

use super::G0;

/// Blade flap angle β(ψ) = β0 + β1c cos ψ + β1s sin ψ (ψ = 0 at the rear) \[rad\].
///
/// With this sign convention β1c < 0 means the blade is highest over the nose: the tip-path
/// plane is tilted *back* by −β1c; β1s > 0 tilts it towards the advancing side (ψ = 90°). The
/// NACA reports write β = a0 − a1 cos ψ − b1 sin ψ: a0 = β0, a1 = −β1c, b1 = −β1s.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Flapping {
    /// Coning β0 \[rad\]: the hub bar's precone (teetering) or free (articulated).
    pub beta0: f64,
    /// Cosine coefficient β1c \[rad\].
    pub beta1c: f64,
    /// Sine coefficient β1s \[rad\].
    pub beta1s: f64,
}

impl Flapping {
    /// Flap angle β(ψ) \[rad\].
    pub fn beta(&self, psi: f64) -> f64 {
        self.beta_at(psi.sin(), psi.cos())
    }

    /// Flap rate per rotor angular speed, dβ/dψ = −β1c sin ψ + β1s cos ψ.
    pub fn beta_rate(&self, psi: f64) -> f64 {
        self.beta_rate_at(psi.sin(), psi.cos())
    }

    /// [`beta`](Self::beta) from (sin ψ, cos ψ) computed once per azimuth.
    pub(crate) fn beta_at(&self, sin_psi: f64, cos_psi: f64) -> f64 {
        self.beta0 + self.beta1c * cos_psi + self.beta1s * sin_psi
    }

    /// [`beta_rate`](Self::beta_rate) from (sin ψ, cos ψ) computed once per azimuth.
    pub(crate) fn beta_rate_at(&self, sin_psi: f64, cos_psi: f64) -> f64 {
        -self.beta1c * sin_psi + self.beta1s * cos_psi
    }

    /// First-harmonic amplitude √(β1c² + β1s²) \[rad\]: for the teetering rotor the angle the
    /// hub swings to, checked against the teeter stops.
    pub fn amplitude(&self) -> f64 {
        self.beta1c.hypot(self.beta1s)
    }

    /// Backward tilt of the tip-path plane relative to the hub plane, −β1c \[rad\].
    pub fn tilt_back(&self) -> f64 {
        -self.beta1c
    }
}

/// The rotor hub: how the blades are attached, which decides the flapping equations (module
/// documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Hub {
    /// Two blades on one teeter bolt at the shaft; the coning is fixed.
    Teetering {
        /// Hub-bar coning (precone) β0 \[rad\].
        precone: f64,
    },
    /// Blades on flapping hinges.
    Articulated(FlapHinge),
}

/// A blade on a flapping hinge: where the hinge is and the blade's mass about it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlapHinge {
    /// Distance of the hinge from the shaft e \[m\].
    pub offset: f64,
    /// Flapping moment of inertia of one blade about its hinge I_β \[kg m²\].
    pub inertia: f64,
    /// First mass moment of one blade about its hinge S_β = ∫ m (r − e) dr \[kg m\].
    pub mass_moment: f64,
}

impl FlapHinge {
    /// Square of the rotating flap frequency per rev, ν_β² = 1 + e S_β/I_β.
    pub fn frequency_squared(&self) -> f64 {
        1.0 + self.offset * self.mass_moment / self.inertia
    }

    /// Blade weight moment about the hinge M_W = S_β g cos α_H \[N m\] at hub angle `hub_aoa`
    /// \[rad\] (the shaft tilted back from the vertical by α_H).
    pub fn weight_moment(&self, hub_aoa: f64) -> f64 {
        self.mass_moment * G0 * hub_aoa.cos()
    }
}

impl Hub {
    /// Distance of the flapping axis from the shaft \[m\] (0 for the teeter bolt).
    pub fn hinge_offset(&self) -> f64 {
        match self {
            Self::Teetering { .. } => 0.0,
            Self::Articulated(h) => h.offset,
        }
    }
}

/// First Fourier harmonics (c, s) of samples f(ψ_k), ψ_k = 2πk/N:
/// c = (2/N) Σ f cos ψ_k, s = (2/N) Σ f sin ψ_k (exact for band-limited f, N > 2).
pub fn first_harmonics(samples: &[f64]) -> (f64, f64) {
    let n = samples.len();
    if n == 0 {
        return (0.0, 0.0);
    }
    let mut c = 0.0;
    let mut s = 0.0;
    for (k, f) in samples.iter().enumerate() {
        let psi = std::f64::consts::TAU * k as f64 / n as f64;
        c += f * psi.cos();
        s += f * psi.sin();
    }
    (2.0 * c / n as f64, 2.0 * s / n as f64)
}
