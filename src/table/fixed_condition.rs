//! Queries of a section at one fixed (Re, M), between the table's nodes: the polar sampled by
//! lookups over α, and the angle of attack at which the lift coefficient reaches a target
//! (the paper's Table 5 compares Cd at Cl = 0.8 at Re 1.9·10⁶, M 0.41).
//!
//! Both go through [`SectionAero::lookup`] — the same interpolation the rotor model sees — so
//! what they report is what the rotor uses.

use crate::numerics::roots::{bracketed_root_of, first_rising_bracket};
use crate::section::{Lookup, PolarPoint, SectionAero};

/// The polar of `section` at (`re`, `mach`), one point per α of `alphas` \[deg\], from lookups.
///
/// Lookups give only cl, cd and cm: `cdp`, `cdf`, `xtr_top`, `xtr_bot`, `residual` and `cpmin`
/// are NaN and `iterations` is 0; `supercritical` says whether a table point the value leans on
/// is supercritical (`None` if one of them does not say), `massive_separation` whether the
/// table's points at that α are in massive separation (and were replaced by the extension or
/// bridged), the separation locations are NaN. A point is marked `converged` unless it comes from the 360°
/// post-stall extension (outside the computed α range), so plots of the result show only
/// values interpolated from solved points.
pub fn sample_polar<S: SectionAero + ?Sized>(
    section: &S,
    alphas: &[f64],
    re: f64,
    mach: f64,
) -> Vec<PolarPoint> {
    alphas
        .iter()
        .map(|&alpha| {
            let l = section.lookup(alpha, re, mach);
            PolarPoint {
                converged: !l.post_stall,
                residual: f64::NAN,
                supercritical: if l.supercritical {
                    Some(true)
                } else {
                    (!l.supercritical_unknown).then_some(false)
                },
                massive_separation: if l.massive_separation {
                    Some(true)
                } else {
                    (!l.separation_unknown).then_some(false)
                },
                ..PolarPoint::from_coefficients(alpha, l.cl, l.cd, l.cm)
            }
        })
        .collect()
}

/// Where the lift coefficient reaches a target: α and the coefficients there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LiftMatch {
    /// Angle of attack \[deg\] at which cl equals the target.
    pub alpha_deg: f64,
    /// The lookup at that α (cl = target to within the root tolerance, cd, cm, flags).
    pub lookup: Lookup,
}

/// Step of the upward α scan that brackets the target lift coefficient \[deg\].
const SCAN_STEP_DEG: f64 = 0.25;

/// The root is accepted when its bracket is narrower than this \[deg\].
const ALPHA_TOLERANCE_DEG: f64 = 1e-9;

/// Most refinement steps of the root.
const ROOT_ITERATIONS: usize = 200;

/// The smallest α in [`alpha_min`, `alpha_max`] (deg) at which the lift coefficient of
/// `section` at (`re`, `mach`) rises through `cl` — the attached-flow branch, below stall —
/// found by an upward scan in 0.25° steps and the crate's bracketed root finder to 10⁻⁹°.
/// `None` if cl stays on one side of the target over the whole interval.
pub fn alpha_at_cl<S: SectionAero + ?Sized>(
    section: &S,
    cl: f64,
    re: f64,
    mach: f64,
    alpha_min: f64,
    alpha_max: f64,
) -> Option<LiftMatch> {
    if !(cl.is_finite() && alpha_min.is_finite() && alpha_max.is_finite()) || alpha_max < alpha_min
    {
        return None;
    }
    let excess = |a: f64| section.lookup(a, re, mach).cl - cl;
    let at = |alpha_deg: f64| LiftMatch {
        alpha_deg,
        lookup: section.lookup(alpha_deg, re, mach),
    };
    if excess(alpha_min) == 0.0 {
        return Some(at(alpha_min));
    }
    let steps = ((alpha_max - alpha_min) / SCAN_STEP_DEG).ceil() as usize;
    let grid = (0..=steps).map(|k| (alpha_min + k as f64 * SCAN_STEP_DEG).min(alpha_max));
    let (lo, hi) = first_rising_bracket(grid, excess)?;
    Some(at(bracketed_root_of(
        excess,
        lo,
        hi,
        ALPHA_TOLERANCE_DEG,
        ROOT_ITERATIONS,
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Thin-airfoil section cl = 2π α (α in rad) with a parabolic drag polar.
    struct ThinAirfoil;

    impl SectionAero for ThinAirfoil {
        fn lookup(&self, alpha_deg: f64, _re: f64, _mach: f64) -> Lookup {
            let cl = 2.0 * std::f64::consts::PI * alpha_deg.to_radians();
            Lookup::new(cl, 0.006 + 0.01 * cl * cl, -0.05)
        }
    }

    #[test]
    fn finds_the_analytic_angle_and_drag() {
        let m = alpha_at_cl(&ThinAirfoil, 0.8, 1.9e6, 0.41, -10.0, 20.0).unwrap();
        let exact = (0.8 / (2.0 * std::f64::consts::PI)).to_degrees();
        assert!((m.alpha_deg - exact).abs() < 1e-8, "{m:?} vs {exact}");
        assert!((m.lookup.cd - (0.006 + 0.01 * 0.64)).abs() < 1e-10, "{m:?}");
    }

    #[test]
    fn out_of_reach_is_none() {
        assert!(alpha_at_cl(&ThinAirfoil, 5.0, 1e6, 0.0, -10.0, 20.0).is_none());
        assert!(alpha_at_cl(&ThinAirfoil, 0.8, 1e6, 0.0, 10.0, 5.0).is_none());
    }

    #[test]
    fn sampled_polar_keeps_the_lookup_values() {
        let p = sample_polar(&ThinAirfoil, &[0.0, 4.0], 1e6, 0.0);
        assert_eq!(p.len(), 2);
        assert!(p.iter().all(|q| q.converged && q.cdp.is_nan()));
        assert!((p[1].cl - 2.0 * std::f64::consts::PI * 4f64.to_radians()).abs() < 1e-12);
    }
}
