//! The attached-flow lift slope of a polar: which points the method trusts, the α range of
//! attached flow and the slope there — the numbers of the polar summary and of the
//! unsteady-aerodynamics block of AeroDyn files (its C_nα), fitted by one method.
//!
//! The method, for points sorted by α:
//!
//! 1. **Trusted points** ([`trusted`]): converged and not supercritical. The run used is the
//!    contiguous run of trusted points around zero lift, the one holding the trusted point of
//!    smallest |Cl| (an unconverged or supercritical point ends a run).
//! 2. **Candidate range**: the points from the negative lift peak (smallest Cl of the run) to the
//!    positive one (largest Cl); where a peak was not reached the run's end stands in.
//! 3. **Slope**: the median of the local slopes ΔCl/Δα of consecutive points, each weighted
//!    by its Δα. A secant or least-squares line is pulled up by the step in Cl that the
//!    laminar drag bucket of a free-transition polar puts across one or two intervals (the
//!    transition point jumps; the 8-H-12 at Re 1.9·10⁶, M 0.41 has local slopes of 9–12 /rad
//!    there against 7.3 on both sides); the median of local slopes is not, as long as such
//!    intervals are fewer than half the range. It is the slope of the lift curve where it is
//!    straight, which is what unsteady-aerodynamics models take as the attached circulatory
//!    slope (Leishman & Beddoes 1989, "A semi-empirical model for dynamic stall", J. AHS
//!    34(3): C_Nα of the attached-flow normal force).
//! 4. **Attached range**: the longest contiguous run of intervals whose local slope is at
//!    least [`STALL_SLOPE_FRACTION`] of that median — where the lift curve has not yet bent
//!    over into stall; the slope is then the weighted median over this range (the value
//!    reported, with the range).
//! 5. **Zero-lift angle**: where the curve crosses zero inside the attached range (linear
//!    between points; the crossing nearest the line's zero when there are several), else the
//!    line through the nearer end of the range with the fitted slope.

use crate::section::PolarPoint;

/// A local slope below this fraction of the median slope marks the lift curve bending into
/// stall (our choice: half the attached slope is well past the first rounding of the curve,
/// and well above the slope of a laminar-bucket interval, about 0.7 of it on the 8-H-12).
pub const STALL_SLOPE_FRACTION: f64 = 0.5;

/// Whether the method trusts a point: it is usable (converged, not in massive separation:
/// [`PolarPoint::usable`]) and its flow is not supercritical (Cp_min < Cp*, shocks the method
/// does not model). Points whose flags are unknown (tables from files without them) are
/// trusted.
pub fn trusted(p: &PolarPoint) -> bool {
    p.usable() && p.supercritical != Some(true)
}

/// The run of attached flow around zero lift: the contiguous run of trusted points of
/// `points` (sorted by α) that holds the trusted point of smallest |Cl|, as an index range
/// `first..=last`; `None` when no point is trusted.
pub(crate) fn trusted_run(points: &[PolarPoint]) -> Option<(usize, usize)> {
    run_around_zero_lift(points, trusted)
}

/// The contiguous run of points that pass `keep` holding the one of smallest |Cl| (see
/// [`trusted_run`]).
pub(crate) fn run_around_zero_lift(
    points: &[PolarPoint],
    keep: fn(&PolarPoint) -> bool,
) -> Option<(usize, usize)> {
    let centre = (0..points.len())
        .filter(|&k| keep(&points[k]))
        .min_by(|&a, &b| points[a].cl.abs().total_cmp(&points[b].cl.abs()))?;
    let first = (0..centre)
        .rev()
        .take_while(|&k| keep(&points[k]))
        .last()
        .unwrap_or(centre);
    let last = (centre + 1..points.len())
        .take_while(|&k| keep(&points[k]))
        .last()
        .unwrap_or(centre);
    Some((first, last))
}

/// The attached range of a lift curve and its slope.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AttachedFit {
    /// Index of the first point of the range (into the arrays fitted).
    pub first: usize,
    /// Index of the last point of the range.
    pub last: usize,
    /// dCl/dα over the range \[1/rad\] (weighted median of the local slopes).
    pub slope: f64,
    /// Zero-lift angle \[deg\].
    pub alpha_zero: f64,
}

/// The attached range and lift slope of the curve `cl(alpha_deg)` (α strictly increasing,
/// every point trusted); `None` with fewer than three points between the lift peaks or a
/// curve that does not rise there.
pub(crate) fn attached_fit(alpha_deg: &[f64], cl: &[f64]) -> Option<AttachedFit> {
    let by = |better: fn(f64, f64) -> bool| {
        (0..cl.len()).reduce(|a, b| if better(cl[b], cl[a]) { b } else { a })
    };
    let (low, high) = (by(|x, y| x < y)?, by(|x, y| x > y)?);
    if high < low + 2 {
        return None;
    }
    let first_pass = median_slope(alpha_deg, cl, low, high);
    if first_pass.is_nan() || first_pass <= 0.0 {
        return None;
    }
    let steep = |k: usize| local_slope(alpha_deg, cl, k) >= STALL_SLOPE_FRACTION * first_pass;
    // The longest run of steep intervals (interval k joins points k and k + 1).
    let (mut best, mut start): (Option<(usize, usize)>, Option<usize>) = (None, None);
    for k in low..=high {
        match (k < high && steep(k), start) {
            (true, None) => start = Some(k),
            (false, Some(s)) => {
                let wider = best
                    .is_none_or(|(a, b)| alpha_deg[k] - alpha_deg[s] > alpha_deg[b] - alpha_deg[a]);
                if wider {
                    best = Some((s, k));
                }
                start = None;
            }
            _ => {}
        }
    }
    let (first, last) = best?;
    if last < first + 2 {
        return None;
    }
    let slope = median_slope(alpha_deg, cl, first, last);
    let alpha_zero = zero_crossing(alpha_deg, cl, first, last, slope);
    Some(AttachedFit {
        first,
        last,
        slope,
        alpha_zero,
    })
}

/// (y[k+1] − y[k]) / (α[k+1] − α[k]) per radian.
fn local_slope(alpha_deg: &[f64], y: &[f64], k: usize) -> f64 {
    (y[k + 1] - y[k]) / (alpha_deg[k + 1] - alpha_deg[k]).to_radians()
}

/// The median of the local slopes of `y(α)` between points `first` and `last`, each weighted
/// by its Δα \[1/rad\]: the slope at which the intervals steeper and the intervals less steep
/// each cover at most half of the α range. NaN with no interval.
pub(crate) fn median_slope(alpha_deg: &[f64], y: &[f64], first: usize, last: usize) -> f64 {
    let mut slopes: Vec<(f64, f64)> = (first..last)
        .map(|k| {
            (
                local_slope(alpha_deg, y, k),
                alpha_deg[k + 1] - alpha_deg[k],
            )
        })
        .collect();
    if slopes.is_empty() {
        return f64::NAN;
    }
    slopes.sort_by(|a, b| a.0.total_cmp(&b.0));
    let half = slopes.iter().map(|s| s.1).sum::<f64>() / 2.0;
    let mut covered = 0.0;
    for (k, &(s, w)) in slopes.iter().enumerate() {
        covered += w;
        if covered > half * (1.0 + 1e-12) {
            return s;
        }
        if (covered - half).abs() <= half * 1e-12 {
            // Exactly half below: the middle of the two central slopes.
            return slopes.get(k + 1).map_or(s, |next| 0.5 * (s + next.0));
        }
    }
    slopes[slopes.len() - 1].0
}

/// Where `y(α)` crosses zero between points `first` and `last` (linear between points; the
/// crossing nearest the zero of the line of `slope` through the range's mean point when there
/// are several), else where that line through the nearer end of the range crosses zero \[deg\].
fn zero_crossing(alpha_deg: &[f64], y: &[f64], first: usize, last: usize, slope: f64) -> f64 {
    let slope_deg = slope.to_radians();
    let n = (last - first + 1) as f64;
    let mean_a = alpha_deg[first..=last].iter().sum::<f64>() / n;
    let mean_y = y[first..=last].iter().sum::<f64>() / n;
    let line_zero = mean_a - mean_y / slope_deg;
    let crossings = (first..last).filter_map(|k| {
        let (y0, y1) = (y[k], y[k + 1]);
        ((y0 <= 0.0 && y1 > 0.0) || (y0 >= 0.0 && y1 < 0.0))
            .then(|| alpha_deg[k] + (alpha_deg[k + 1] - alpha_deg[k]) * y0 / (y0 - y1))
    });
    crossings
        .min_by(|a, b| (a - line_zero).abs().total_cmp(&(b - line_zero).abs()))
        .unwrap_or_else(|| {
            let k = if y[first].abs() <= y[last].abs() {
                first
            } else {
                last
            };
            alpha_deg[k] - y[k] / slope_deg
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A lift curve 0.12/deg through α0 = −2° with a step of 0.1 across 1°…2° (a laminar
    /// bucket), rounding into stall above 10° and below −12°.
    fn curve() -> (Vec<f64>, Vec<f64>) {
        let alpha: Vec<f64> = (-30..=30).map(|k| k as f64 * 0.5).collect();
        let cl = alpha
            .iter()
            .map(|&a| {
                let step = 0.1 * ((a - 1.0).clamp(0.0, 1.0));
                let linear = 0.12 * (a + 2.0) + step;
                if a > 10.0 {
                    linear - 0.05 * (a - 10.0).powi(2)
                } else if a < -12.0 {
                    linear + 0.05 * (a + 12.0).powi(2)
                } else {
                    linear
                }
            })
            .collect();
        (alpha, cl)
    }

    #[test]
    fn a_step_does_not_move_the_slope_and_stall_bounds_the_range() {
        let (alpha, cl) = curve();
        let fit = attached_fit(&alpha, &cl).unwrap();
        // 0.12/deg = 6.8755/rad exactly: the step covers 2 of about 45 intervals.
        assert!((fit.slope - 0.12f64.to_degrees()).abs() < 1e-9, "{fit:?}");
        assert!((fit.alpha_zero + 2.0).abs() < 1e-9, "{fit:?}");
        // Stall: the local slope 0.12 − 0.1·(α − 10) falls below half at α ≈ 10.6°.
        assert_eq!((alpha[fit.first], alpha[fit.last]), (-12.5, 10.5));
        // A least-squares line over the same range is pulled up by the step.
        let (a, y) = (&alpha[fit.first..=fit.last], &cl[fit.first..=fit.last]);
        let n = a.len() as f64;
        let (ma, my) = (a.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
        let sxy: f64 = a.iter().zip(y).map(|(a, y)| (a - ma) * (y - my)).sum();
        let sxx: f64 = a.iter().map(|a| (a - ma).powi(2)).sum();
        assert!((sxy / sxx).to_degrees() > 1.03 * fit.slope);
    }

    #[test]
    fn the_median_is_weighted_by_the_interval() {
        // Slopes 1/rad over 3°, 3/rad over 1°: the median is 1.
        let a = [0.0, 3.0, 4.0];
        let y = [
            0.0,
            3f64.to_radians(),
            3f64.to_radians() + 3.0 * 1f64.to_radians(),
        ];
        assert!((median_slope(&a, &y, 0, 2) - 1.0).abs() < 1e-12);
        // Two equal halves: the middle.
        let y = [0.0, 1f64.to_radians(), 4f64.to_radians()];
        let a = [0.0, 1.0, 2.0];
        assert!((median_slope(&a, &y, 0, 2) - 2.0).abs() < 1e-12);
    }

    #[test]
    fn too_few_points_or_no_rise_give_no_fit() {
        assert!(attached_fit(&[0.0, 1.0], &[0.0, 0.1]).is_none());
        assert!(attached_fit(&[0.0, 1.0, 2.0, 3.0], &[0.3, 0.2, 0.1, 0.0]).is_none());
    }
}
