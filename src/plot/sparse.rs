//! Point symbols where data are sparse: a line through few or widely spaced points hides
//! where the data are and where the renderer only joined them, so such a series gets a symbol
//! on every point.
//!
//! The rule, on the points of a line inside the axes of its panel: the line is sparse when the
//! median distance between neighbouring points exceeds [`SPARSE_STEP`] of the axes (each axis
//! scaled to length 1; a line across the panel with fewer than about 40 points), or when a
//! single point of it is visible. The median, not the largest step, so that a dense curve with
//! one steep stretch (a Cp suction peak, a stall break) keeps a plain line; distances, not a
//! point count, so that a short but dense line (N up to a transition at 7 % chord) does too. When any line of a figure is sparse, every
//! line of the figure gets its symbols: the sampling is a property of the data, so two curves
//! sampled alike look alike, in every panel and in the legend.

use super::axes::{panel_limits, y_sign};
use super::figure::{Figure, Line, Series};

/// A line whose median step between neighbouring visible points is longer than this fraction
/// of the axes (x and y each scaled to 1) is sparse: 1/40, the spacing of 41 points spread
/// evenly along one axis.
pub(crate) const SPARSE_STEP: f64 = 1.0 / 40.0;

/// Whether the points inside `[x0, x1] × [y0, y1]` are sparse by the module's rule.
pub(crate) fn is_sparse(points: &[(f64, f64)], xlim: (f64, f64), ylim: (f64, f64)) -> bool {
    let inside = |&(x, y): &(f64, f64)| x >= xlim.0 && x <= xlim.1 && y >= ylim.0 && y <= ylim.1;
    let visible: Vec<(f64, f64)> = points.iter().copied().filter(inside).collect();
    match visible.len() {
        0 => return false,
        1 => return true,
        _ => {}
    }
    let (sx, sy) = (xlim.1 - xlim.0, ylim.1 - ylim.0);
    let mut steps: Vec<f64> = visible
        .windows(2)
        .map(|w| ((w[1].0 - w[0].0) / sx).hypot((w[1].1 - w[0].1) / sy))
        .collect();
    steps.sort_by(f64::total_cmp);
    steps[steps.len() / 2] > SPARSE_STEP
}

/// Whether any line of `figure` is sparse ([`is_sparse`] in its panel's axes, padded by
/// `padding` as drawn).
pub(crate) fn figure_is_sparse(figure: &Figure, padding: f64) -> bool {
    figure.panels.iter().any(|panel| {
        let (xlim, ylim) = panel_limits(panel, padding);
        let sign = y_sign(panel);
        panel
            .series
            .iter()
            .filter(|s| s.style.line != Line::None)
            .any(|s| {
                let pts: Vec<(f64, f64)> =
                    s.x.iter().zip(&s.y).map(|(&x, &y)| (x, sign * y)).collect();
                is_sparse(&pts, xlim, ylim)
            })
    })
}

/// Whether `series` is drawn with a symbol on every point: always with
/// [`Style::points`](super::Style::points), and every line of a figure whose data are sparse
/// (`sparse_figure`, [`figure_is_sparse`]).
pub(crate) fn shows_points(series: &Series, sparse_figure: bool) -> bool {
    series.style.points || (series.style.line != Line::None && sparse_figure)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `n` points evenly along the diagonal of the unit square.
    fn diagonal(n: usize) -> Vec<(f64, f64)> {
        (0..n)
            .map(|i| {
                let t = i as f64 / (n - 1) as f64;
                (t, t)
            })
            .collect()
    }

    #[test]
    fn few_or_widely_spaced_points_are_sparse() {
        let unit = (0.0, 1.0);
        // along the diagonal: 57 points, steps √2/56 = 0.0253, just sparse; 58: 0.0248, dense
        assert!(is_sparse(&diagonal(20), unit, unit));
        assert!(is_sparse(&diagonal(57), unit, unit));
        assert!(!is_sparse(&diagonal(58), unit, unit));
        // 58 points on an axis zoomed to a tenth of their span: only 6 visible, steps 10×
        assert!(is_sparse(&diagonal(58), (0.0, 0.1), (0.0, 0.1)));
        // a short dense line: 10 points within x/c 0…0.07, N 0…0.6 of a 0…1 × 0…9 panel
        let short: Vec<(f64, f64)> = (0..10)
            .map(|i| (0.007 * f64::from(i), 0.06 * f64::from(i)))
            .collect();
        assert!(!is_sparse(&short, unit, (0.0, 9.0)));
        // one visible point is invisible as a line
        assert!(is_sparse(&[(0.5, 0.5), (2.0, 2.0)], unit, unit));
        // a dense curve with one long jump keeps its plain line (median, not maximum)
        let mut jump = diagonal(100);
        jump[50].1 += 0.5;
        assert!(!is_sparse(&jump, unit, (0.0, 1.5)));
        // nothing visible: nothing to mark
        assert!(!is_sparse(&diagonal(10), (2.0, 3.0), unit));
    }
}
