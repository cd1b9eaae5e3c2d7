//! First-harmonic teeter motion of a two-bladed teetering rotor.
//!
//! Both blades are one rigid beam on the teeter bolt, so blade 2 (at ψ + π) has the opposite
//! teeter angle of blade 1: the coning β0 is fixed by the hub bar (precone) and only the first
//! harmonics β1c, β1s are free. For a centrally hinged rigid blade the flap natural frequency is
//! exactly 1/rev, so the inertial and centrifugal terms cancel for a 1/rev motion and the teeter
//! equation reduces to: the first harmonics of the aerodynamic flap moment about the teeter bolt
//! vanish (Leishman, *Principles of Helicopter Aerodynamics*, 2nd ed., §4.8 with ν_β = 1).

/// Blade flap angle β(ψ) = β0 + β1c cos ψ + β1s sin ψ (ψ = 0 at the rear, blade 1) \[rad\].
///
/// With this sign convention β1c < 0 means the blade is highest over the nose: the tip-path
/// plane is tilted *back* by −β1c; β1s > 0 tilts it towards the advancing side (ψ = 90°).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Teeter {
    /// Hub-bar coning (precone) β0 \[rad\].
    pub beta0: f64,
    /// Cosine coefficient β1c \[rad\].
    pub beta1c: f64,
    /// Sine coefficient β1s \[rad\].
    pub beta1s: f64,
}

impl Teeter {
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

    /// Teeter amplitude √(β1c² + β1s²) \[rad\]: the angle the hub swings to, checked against the
    /// teeter stops.
    pub fn amplitude(&self) -> f64 {
        self.beta1c.hypot(self.beta1s)
    }

    /// Backward tilt of the tip-path plane relative to the hub plane, −β1c \[rad\].
    pub fn tilt_back(&self) -> f64 {
        -self.beta1c
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
