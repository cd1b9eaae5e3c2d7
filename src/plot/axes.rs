//! Axis scales: limits from the data, "nice" tick positions and their labels, and the
//! plotters coordinate type that puts the grid at those ticks.

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};

use super::figure::{AxisRange, MarkerKind, Panel};
use crate::output::fixed_decimals;

/// Sign of the plotted y of `panel`: −1 when its y axis is inverted (plot coordinates are −y).
pub(crate) fn y_sign(panel: &Panel) -> f64 {
    if panel.y_inverted {
        -1.0
    } else {
        1.0
    }
}

/// Axis limits (x, y) of `panel` in plot coordinates (y negated on an inverted axis): fixed
/// ranges as given, automatic ones from the finite series points and the markers, padded by
/// `padding` of the span.
pub(crate) fn panel_limits(panel: &Panel, padding: f64) -> ((f64, f64), (f64, f64)) {
    let sign = y_sign(panel);
    let mut xs: Vec<f64> = Vec::new();
    let mut ys: Vec<f64> = Vec::new();
    for s in &panel.series {
        for (&x, &y) in s.x.iter().zip(&s.y) {
            if x.is_finite() && y.is_finite() {
                xs.push(x);
                ys.push(sign * y);
            }
        }
    }
    for m in &panel.markers {
        match m.kind {
            MarkerKind::VLine(x) => xs.push(x),
            MarkerKind::HLine(y) => ys.push(sign * y),
            MarkerKind::Point(x, y) => {
                xs.push(x);
                ys.push(sign * y);
            }
        }
    }
    let y_range = match panel.y_range {
        AxisRange::Fixed { min, max } if panel.y_inverted => AxisRange::Fixed {
            min: -max,
            max: -min,
        },
        r => r,
    };
    (
        axis_limits(panel.x_range, &xs, padding),
        axis_limits(y_range, &ys, padding),
    )
}

/// Axis limits in plot coordinates for one axis: fixed, or the padded extent of `values`.
pub(crate) fn axis_limits(range: AxisRange, values: &[f64], padding: f64) -> (f64, f64) {
    if let AxisRange::Fixed { min, max } = range {
        return (min, max);
    }
    let (lo, hi) = values
        .iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        return (0.0, 1.0);
    }
    if hi - lo <= 1e-12 * (1.0 + lo.abs().max(hi.abs())) {
        let half = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        return (lo - half, hi + half);
    }
    let pad = padding * (hi - lo);
    (lo - pad, hi + pad)
}

/// Tick positions of one axis: labelled (major) and grid-only (minor) values and the number
/// of decimals that prints every major tick exactly.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Ticks {
    /// Labelled tick values, ascending.
    pub(crate) major: Vec<f64>,
    /// Minor grid values, ascending.
    pub(crate) minor: Vec<f64>,
    /// Decimals for the tick labels; `None` (steps below 1e-8) prints in scientific notation.
    pub(crate) decimals: Option<usize>,
}

/// Ticks for the axis `[lo, hi]`: multiples of `step` if given (and not absurdly fine), else
/// of the smallest "nice" step {1, 2, 2.5, 5} × 10^k giving at most `max_ticks` labels.
pub(crate) fn ticks(lo: f64, hi: f64, max_ticks: usize, step: Option<f64>) -> Ticks {
    let span = hi - lo;
    // A given step that would put more than this many ticks on the axis is ignored.
    const MAX_GIVEN_TICKS: f64 = 1000.0;
    let step = step.filter(|s| span / s <= MAX_GIVEN_TICKS);
    let (step, minor_div) = match step {
        // Given steps get minor lines at thirds (e.g. 15° for 45°) when that divides evenly,
        // else at fifths.
        Some(s) => {
            let thirds = (s / 3.0) * 1e6;
            (
                s,
                if (thirds - thirds.round()).abs() < 1e-6 {
                    3.0
                } else {
                    5.0
                },
            )
        }
        None => {
            let raw = span / max_ticks.max(1) as f64;
            let mag = 10f64.powf(raw.log10().floor());
            [(1.0, 5.0), (2.0, 4.0), (2.5, 5.0), (5.0, 5.0), (10.0, 5.0)]
                .into_iter()
                .map(|(m, d)| (m * mag, d))
                .find(|(s, _)| *s >= raw * (1.0 - 1e-9))
                .unwrap_or((10.0 * mag, 5.0))
        }
    };
    let decimals = (0..=8).find(|&d| {
        let scaled = step * 10f64.powi(d as i32);
        scaled.round() >= 1.0 && (scaled - scaled.round()).abs() < 1e-6 * scaled
    });
    // Multiples of h in [lo, hi], rounded to `d` decimals (if any) so that 3 × 0.2 is 0.6.
    let multiples = |h: f64, d: Option<usize>| -> Vec<f64> {
        let k0 = (lo / h - 1e-9).ceil() as i64;
        let k1 = (hi / h + 1e-9).floor() as i64;
        (k0..=k1)
            .map(|k| {
                let v = k as f64 * h;
                let v = match d {
                    Some(d) => {
                        let scale = 10f64.powi(d as i32);
                        (v * scale).round() / scale
                    }
                    None => v,
                };
                v + 0.0
            })
            .collect()
    };
    Ticks {
        major: multiples(step, decimals),
        minor: multiples(step / minor_div, decimals.map(|d| d + 2)),
        decimals,
    }
}

/// A linear f64 axis whose grid and labels sit at precomputed [`Ticks`] (plotters' own f64
/// axis chooses its ticks itself and cannot take a given spacing).
#[derive(Clone, Debug)]
pub(super) struct TickedAxis {
    /// Axis limits.
    lo: f64,
    hi: f64,
    /// Tick positions.
    ticks: Ticks,
}

impl TickedAxis {
    pub(super) fn new((lo, hi): (f64, f64), ticks: Ticks) -> Self {
        Self { lo, hi, ticks }
    }
}

impl Ranged for TickedAxis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    /// Linear map of `value` onto the pixel interval `limit`.
    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let f = (value - self.lo) / (self.hi - self.lo);
        let px = limit.0 as f64 + f * (limit.1 - limit.0) as f64;
        px.round().clamp(-1e6, 1e6) as i32
    }

    /// Major ticks for labels and bold grid lines, minor ticks for light grid lines.
    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.ticks.minor.clone()
        } else {
            self.ticks.major.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

/// Formats a tick value with `decimals` decimals, or in scientific notation for `None`
/// (no "-0").
pub(super) fn format_tick(v: f64, decimals: Option<usize>) -> String {
    match decimals {
        Some(d) => fixed_decimals(v, d),
        None => format!("{v:.3e}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn auto_limits_pad_and_handle_degenerate_data() {
        let (lo, hi) = axis_limits(AxisRange::Auto, &[0.0, 10.0, f64::NAN], 0.05);
        assert!((lo + 0.5).abs() < 1e-12 && (hi - 10.5).abs() < 1e-12);
        assert_eq!(axis_limits(AxisRange::Auto, &[], 0.05), (0.0, 1.0));
        assert_eq!(axis_limits(AxisRange::Auto, &[0.0, 0.0], 0.05), (-1.0, 1.0));
        let (lo, hi) = axis_limits(AxisRange::Auto, &[2.0], 0.05);
        assert!((lo - 1.8).abs() < 1e-12 && (hi - 2.2).abs() < 1e-12);
    }

    #[test]
    fn nice_ticks() {
        let t = ticks(-0.6, 1.3, 9, None);
        assert_eq!(t.major, vec![-0.5, -0.25, 0.0, 0.25, 0.5, 0.75, 1.0, 1.25]);
        assert_eq!(t.decimals, Some(2));
        assert_eq!(t.minor.len(), 39);
        let t = ticks(0.0, 360.0, 9, Some(45.0));
        assert_eq!(t.major.len(), 9);
        assert_eq!((t.major[2], t.decimals), (90.0, Some(0)));
        assert_eq!(t.minor[1], 15.0);
        let t = ticks(0.0, 1.0, 9, Some(1e-9));
        assert_eq!(
            t.major,
            vec![0.0, 0.2, 0.4, 0.6, 0.8, 1.0],
            "automatic ticks"
        );
        let t = ticks(0.0, 0.012, 9, None);
        assert_eq!((t.major[1], t.decimals), (0.002, Some(3)));
        assert_eq!(format_tick(-0.0001, Some(2)), "0.00");
        assert_eq!(format_tick(0.0125, Some(4)), "0.0125");
        let t = ticks(1e-10, 5e-10, 9, None);
        assert_eq!((t.major.len(), t.decimals), (9, None));
        assert_eq!(format_tick(t.major[0], t.decimals), "1.000e-10");
    }
}
