//! Analytic airfoil sections for the rotor tests: sin-type lift with a smooth blend into a
//! flat-plate model beyond stall (valid over ±180°, so reverse flow is covered), and a
//! "contaminated" variant with about twice the profile drag and a 15 % lower lift slope, as the
//! paper reports for the NACA 8-H-12 with transition fixed at 7 % chord.
#![allow(dead_code)]

use polargen::section::{Lookup, SectionAero};

/// Analytic section.
#[derive(Clone, Copy, Debug)]
pub struct AnalyticSection {
    /// Lift-curve slope [1/rad].
    pub a0: f64,
    /// Zero-lift angle [deg].
    pub alpha0_deg: f64,
    /// Minimum profile drag.
    pub cd0: f64,
    /// Drag-due-to-lift factor: cd = cd0 + k cl².
    pub k: f64,
    /// Stall angle (centre of the blend to the flat plate) [deg].
    pub stall_deg: f64,
    /// Width of the blend [deg].
    pub blend_deg: f64,
}

impl AnalyticSection {
    /// Clean NACA 8-H-12-like section at Re ≈ 2e6, M ≈ 0.4: slope 2π/√(1−M²) ≈ 6.9/rad,
    /// α0 = −1°, cd ≈ 0.006 at cl 0.8 (paper Table 5).
    pub fn clean() -> Self {
        Self {
            a0: 6.9,
            alpha0_deg: -1.0,
            cd0: 0.0055,
            k: 0.001,
            stall_deg: 13.0,
            blend_deg: 1.5,
        }
    }

    /// Contaminated variant: ~2× drag (cd ≈ 0.012 at cl 0.8), 15 % lower lift slope.
    pub fn contaminated() -> Self {
        Self {
            a0: 6.9 * 0.85,
            alpha0_deg: -1.0,
            cd0: 0.011,
            k: 0.002,
            stall_deg: 13.0,
            blend_deg: 1.5,
        }
    }
}

impl SectionAero for AnalyticSection {
    fn lookup(&self, alpha_deg: f64, _re: f64, _mach: f64) -> Lookup {
        let a = alpha_deg.to_radians();
        let cl_att = self.a0 * (a - self.alpha0_deg.to_radians()).sin();
        let cd_att = self.cd0 + self.k * cl_att * cl_att;
        let cl_fp = 1.1 * (2.0 * a).sin();
        let cd_fp = self.cd0 + 1.9 * a.sin().powi(2);
        let w = 1.0 / (1.0 + ((alpha_deg.abs() - self.stall_deg) / self.blend_deg).exp());
        Lookup {
            post_stall: w < 0.5,
            ..Lookup::new(
                w * cl_att + (1.0 - w) * cl_fp,
                w * cd_att + (1.0 - w) * cd_fp,
                0.0,
            )
        }
    }
}

/// Loads the repository's MTOsport preset.
pub fn mtosport() -> polargen::rotor::Aircraft {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("aircraft/mtosport.toml");
    polargen::rotor::Aircraft::from_toml_file(&path).expect("preset loads")
}
