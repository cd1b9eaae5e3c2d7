//! Karman–Tsien compressibility correction of incompressible panel results (von Kármán 1941,
//! Tsien 1939; as applied in XFOIL xfoil.f CPCALC, CLCALC and COMSET/QCOMP).
//!
//! With β = √(1 − M²) and λ = M²/(1 + β)²:
//! * Cp_c = Cp_i / (β + λ(1 + β)·Cp_i/2)            (CPCALC, `BFAC = λ(1+β)/2 = ½M²/(1+β)`)
//! * q_c = q_i·(1 − λ) / (1 − λ·q_i²)                (QCOMP, speeds per V∞)

use super::error::InviscidError;

/// Ratio of specific heats of air.
const GAMMA_AIR: f64 = 1.4;

/// Karman–Tsien correction factors for one freestream Mach number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KarmanTsien {
    /// Freestream Mach number M∞.
    pub mach: f64,
    /// Prandtl–Glauert factor β = √(1 − M²).
    pub beta: f64,
    /// λ = M²/(1 + β)² (XFOIL TKLAM).
    pub lambda: f64,
    /// λ(1 + β)/2 = ½M²/(1 + β) (XFOIL BFAC).
    pub bfac: f64,
}

impl KarmanTsien {
    /// Factors for Mach `mach`; errors unless 0 ≤ M < 1.
    pub fn new(mach: f64) -> Result<Self, InviscidError> {
        if !(0.0..1.0).contains(&mach) {
            return Err(InviscidError::InvalidMach(mach));
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

    /// Corrected Cp from an incompressible surface speed q/V∞, Cp_i = 1 − q².
    pub fn cp_from_speed(&self, q: f64) -> Option<f64> {
        self.cp(1.0 - q * q)
    }

    /// Compressible speed from the incompressible one, q_c = q(1 − λ)/(1 − λq²) (XFOIL QCOMP).
    pub fn speed(&self, q: f64) -> f64 {
        q * (1.0 - self.lambda) / (1.0 - self.lambda * q * q)
    }

    /// Sonic pressure coefficient Cp* for isentropic flow of air,
    /// Cp* = 2/(γM²)·[((2 + (γ−1)M²)/(γ+1))^(γ/(γ−1)) − 1]; −∞ at M = 0.
    pub fn cp_sonic(&self) -> f64 {
        let m2 = self.mach * self.mach;
        if m2 == 0.0 {
            return f64::NEG_INFINITY;
        }
        let g = GAMMA_AIR;
        2.0 / (g * m2) * (((2.0 + (g - 1.0) * m2) / (g + 1.0)).powf(g / (g - 1.0)) - 1.0)
    }
}
