//! Compressibility of subsonic air, shared by every layer: the ratio of specific heats and the
//! Karman–Tsien correction of incompressible speeds and pressure coefficients (von Kármán 1941,
//! Tsien 1939; as applied in XFOIL xfoil.f CPCALC/CLCALC, xbl.f SETBL and xblsys.f BLPRV).
//!
//! With β = √(1 − M∞²) (Prandtl–Glauert factor) and λ = M∞²/(1 + β)² (XFOIL TKLAM, TKBL):
//! * Cp_c = Cp_i / (β + λ(1 + β)·Cp_i/2)   (CPCALC, `BFAC = λ(1+β)/2 = ½M∞²/(1+β)`)
//! * q_c = q_i·(1 − λ) / (1 − λ·q_i²)       (BLPRV, QCOMP; speeds per V∞)
//!
//! ```
//! use polargen::compressibility::KarmanTsien;
//!
//! let kt = KarmanTsien::new(0.5)?;
//! assert!((kt.cp(-1.0).unwrap() + 1.251505).abs() < 1e-6); // suction amplified
//! assert_eq!(kt.speed(1.0), 1.0); // the free stream keeps its speed
//! # Ok::<(), polargen::compressibility::MachOutOfRange>(())
//! ```

use std::ops::{Div, Mul, Sub};

/// Ratio of specific heats of air, γ = c_p/c_v (ISA, ISO 2533; XFOIL GAMMA).
pub const GAMMA: f64 = 1.4;

/// γ − 1.
pub(crate) const GAMMA_MINUS_ONE: f64 = GAMMA - 1.0;

/// A free-stream Mach number outside the subsonic range [0, 1) of the correction.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[error("free-stream Mach number {0} is outside [0, 1)")]
pub struct MachOutOfRange(pub f64);

/// The lowest Karman–Tsien pressure coefficient on a surface and the supercritical flag that
/// follows from it (XFOIL reports the same CPMIN; its COMSET defines CPSTAR).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MinimumPressure {
    /// Smallest corrected Cp on the surface; −∞ where the correction breaks down (its
    /// denominator β + BFAC·Cp_i is not positive: the local speed is far beyond sonic).
    pub cp: f64,
    /// Cp_min < Cp*: somewhere on the surface the local Mach number exceeds 1, where an
    /// XFOIL-class method (subsonic Karman–Tsien, no shocks) is no longer valid. Never at
    /// M∞ = 0 (Cp* = −∞).
    pub supercritical: bool,
}

/// Karman–Tsien correction factors for one free-stream Mach number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KarmanTsien {
    /// Free-stream Mach number M∞.
    pub mach: f64,
    /// Prandtl–Glauert factor β = √(1 − M∞²).
    pub beta: f64,
    /// λ = M∞²/(1 + β)² (XFOIL TKLAM, TKBL).
    pub lambda: f64,
    /// λ(1 + β)/2 = ½M∞²/(1 + β) (XFOIL BFAC).
    pub bfac: f64,
}

impl KarmanTsien {
    /// Factors for Mach `mach`; errors unless 0 ≤ M∞ < 1.
    pub fn new(mach: f64) -> Result<Self, MachOutOfRange> {
        if !(0.0..1.0).contains(&mach) {
            return Err(MachOutOfRange(mach));
        }
        let beta = (1.0 - mach * mach).sqrt();
        Ok(Self {
            mach,
            beta,
            lambda: mach * mach / ((1.0 + beta) * (1.0 + beta)),
            bfac: 0.5 * mach * mach / (1.0 + beta),
        })
    }

    /// Corrected Cp from an incompressible Cp (XFOIL CPCALC); `None` when the denominator
    /// β + BFAC·Cp_i is not positive (local speed too high for the correction).
    pub fn cp(&self, cp_incompressible: f64) -> Option<f64> {
        let den = self.beta + self.bfac * cp_incompressible;
        (den > 0.0).then(|| cp_incompressible / den)
    }

    /// The relation of [`KarmanTsien::cp`] evaluated whatever the sign of its denominator, as
    /// XFOIL CPCALC does: a value past the correction's range is not meaningful.
    pub fn cp_unchecked(&self, cp_incompressible: f64) -> f64 {
        cp_incompressible / (self.beta + self.bfac * cp_incompressible)
    }

    /// Corrected Cp from an incompressible surface speed q/V∞, Cp_i = 1 − q².
    pub fn cp_from_speed(&self, q: f64) -> Option<f64> {
        self.cp(1.0 - q * q)
    }

    /// Compressible speed from the incompressible one, q_c = q(1 − λ)/(1 − λq²) (XFOIL BLPRV,
    /// QCOMP).
    pub fn speed(&self, q: f64) -> f64 {
        self.speed_of(q)
    }

    /// [`KarmanTsien::speed`] on any number type, e.g. derivative numbers.
    pub(crate) fn speed_of<T>(&self, q: T) -> T
    where
        T: Copy + Mul<Output = T> + Mul<f64, Output = T> + Div<Output = T>,
        f64: Sub<T, Output = T>,
    {
        q * self.speed_factor() / (1.0 - q * q * self.lambda)
    }

    /// 1 − λ (outside the generic [`KarmanTsien::speed_of`], whose bound on `f64 − T` would
    /// otherwise be taken for this `f64 − f64`).
    fn speed_factor(&self) -> f64 {
        1.0 - self.lambda
    }

    /// The lowest surface pressure of a contour with surface speeds `speeds` (|q|/V∞,
    /// incompressible) and whether the flow is supercritical there (see [`MinimumPressure`]).
    /// The lowest corrected Cp sits at the highest speed, because the correction is monotone
    /// in Cp_i wherever it is defined.
    pub fn minimum_pressure(&self, speeds: impl IntoIterator<Item = f64>) -> MinimumPressure {
        let q_max = speeds.into_iter().fold(0.0_f64, |m, q| m.max(q.abs()));
        let cp = self.cp_from_speed(q_max).unwrap_or(f64::NEG_INFINITY);
        MinimumPressure {
            cp,
            supercritical: self.mach > 0.0 && cp < self.cp_sonic(),
        }
    }

    /// Sonic pressure coefficient Cp* for isentropic flow of air,
    /// Cp* = 2/(γM²)·[((2 + (γ−1)M²)/(γ+1))^(γ/(γ−1)) − 1]; −∞ at M = 0.
    pub fn cp_sonic(&self) -> f64 {
        let m2 = self.mach * self.mach;
        if m2 == 0.0 {
            return f64::NEG_INFINITY;
        }
        let (g, gm1) = (GAMMA, GAMMA_MINUS_ONE);
        2.0 / (g * m2) * (((2.0 + gm1 * m2) / (g + 1.0)).powf(g / gm1) - 1.0)
    }
}
