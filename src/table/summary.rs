//! [`PolarSummary`]: the numbers rotor codes and unsteady-aerodynamics models take from a
//! polar — zero-lift angle, lift slope and its range, Cl_max, Cd_min, best L/D, Cm0 — and the
//! α range the method trusts; as text, CSV and JSON (`polargen summary`, the batch index,
//! `Polar.summary()` in Python).
//!
//! Cl_max and Cl_min are the stall peaks: walking out of the attached range, the largest
//! (smallest) Cl met before the curve falls [`PEAK_DROP`] below it. Every number comes from
//! the trusted points only ([`trusted`]), within their contiguous
//! run around zero lift ([`lift_slope`](super::lift_slope)); the lift slope and zero-lift angle are
//! those of [`attached_fit`]. A number the polar cannot give (no trusted point, no attached
//! range, a zero-lift angle outside the trusted run for Cm0) is absent (`None`: an empty CSV
//! field, JSON `null`).

use super::lift_slope::{attached_fit, trusted, trusted_run};
use super::PolarTable;
use crate::section::PolarPoint;
use serde::Serialize;
use std::fmt::Write as _;

/// The summary of one polar. Angles in degrees, the lift slope per radian.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct PolarSummary {
    /// Points of the polar.
    pub points: usize,
    /// Points the method trusts (converged, not supercritical).
    pub trusted: usize,
    /// Smallest α of the contiguous run of trusted points around zero lift.
    pub alpha_trusted_min: Option<f64>,
    /// Largest α of that run.
    pub alpha_trusted_max: Option<f64>,
    /// Zero-lift angle α0.
    pub alpha_zero_lift: Option<f64>,
    /// Attached-flow lift slope dCl/dα \[1/rad\].
    pub lift_slope: Option<f64>,
    /// Smallest α of the range the lift slope was fitted on.
    pub lift_slope_alpha_min: Option<f64>,
    /// Largest α of that range.
    pub lift_slope_alpha_max: Option<f64>,
    /// Largest Cl of the trusted run.
    pub cl_max: Option<f64>,
    /// α of `cl_max`.
    pub alpha_cl_max: Option<f64>,
    /// `cl_max` is at the end of the trusted run: a lower bound, the stall peak was not
    /// reached with trusted points.
    pub cl_max_at_edge: Option<bool>,
    /// Smallest Cl of the trusted run (the negative stall peak when reached).
    pub cl_min: Option<f64>,
    /// α of `cl_min`.
    pub alpha_cl_min: Option<f64>,
    /// Smallest Cd of the trusted run.
    pub cd_min: Option<f64>,
    /// Cl at `cd_min`.
    pub cl_at_cd_min: Option<f64>,
    /// Largest Cl/Cd of the trusted run.
    pub ld_max: Option<f64>,
    /// α of `ld_max`.
    pub alpha_ld_max: Option<f64>,
    /// Cm (quarter chord) at the zero-lift angle, linear between trusted points.
    pub cm0: Option<f64>,
}

/// The summary of one polar (`points` sorted by α, as a table holds them).
pub fn summarize(points: &[PolarPoint]) -> PolarSummary {
    let mut s = PolarSummary {
        points: points.len(),
        trusted: points.iter().filter(|p| trusted(p)).count(),
        ..PolarSummary::default()
    };
    let Some((first, last)) = trusted_run(points) else {
        return s;
    };
    let run = &points[first..=last];
    let alpha: Vec<f64> = run.iter().map(|p| p.alpha).collect();
    let cl: Vec<f64> = run.iter().map(|p| p.cl).collect();
    s.alpha_trusted_min = Some(alpha[0]);
    s.alpha_trusted_max = Some(alpha[alpha.len() - 1]);
    let best = |key: &dyn Fn(&PolarPoint) -> f64| {
        run.iter()
            .enumerate()
            .filter(|(_, p)| key(p).is_finite())
            .max_by(|a, b| key(a.1).total_cmp(&key(b.1)))
    };
    if let Some((_, p)) = best(&|p| -p.cd) {
        (s.cd_min, s.cl_at_cd_min) = (Some(p.cd), Some(p.cl));
    }
    if let Some((_, p)) = best(&|p| if p.cd > 0.0 { p.cl / p.cd } else { f64::NAN }) {
        (s.ld_max, s.alpha_ld_max) = (Some(p.cl / p.cd), Some(p.alpha));
    }
    let fit = attached_fit(&alpha, &cl);
    // The stall peaks: walking out of the attached range (or from the smallest |Cl|).
    let (up, down) = fit.map_or_else(
        || {
            let k = (0..cl.len())
                .min_by(|&a, &b| cl[a].abs().total_cmp(&cl[b].abs()))
                .unwrap_or(0);
            (k, k)
        },
        |f| (f.last, f.first),
    );
    let k = stall_peak(&cl, up, 1.0);
    (s.cl_max, s.alpha_cl_max) = (Some(cl[k]), Some(alpha[k]));
    s.cl_max_at_edge = Some(k + 1 == run.len());
    let k = stall_peak(&cl, down, -1.0);
    (s.cl_min, s.alpha_cl_min) = (Some(cl[k]), Some(alpha[k]));
    if let Some(fit) = fit {
        s.lift_slope = Some(fit.slope);
        s.lift_slope_alpha_min = Some(alpha[fit.first]);
        s.lift_slope_alpha_max = Some(alpha[fit.last]);
        s.alpha_zero_lift = Some(fit.alpha_zero);
        let cm: Vec<f64> = run.iter().map(|p| p.cm).collect();
        s.cm0 = linear_at(&alpha, &cm, fit.alpha_zero);
    }
    s
}

/// A stall peak falls by this fraction of its |Cl| before the walk past it stops (so that a
/// small dip, a laminar separation bubble's, does not end it).
pub const PEAK_DROP: f64 = 0.1;

/// The index of the stall peak of `cl` walking from `start` upwards in α (`sign` +1, the
/// largest Cl) or downwards (−1, the smallest): the extreme of `sign·cl` met before it falls
/// [`PEAK_DROP`] of the extreme's magnitude below it, or before the run ends. A table read
/// from a file with its own 360° extension thus gets the stall peak, not a larger Cl of the
/// extension at 40°–50°.
fn stall_peak(cl: &[f64], start: usize, sign: f64) -> usize {
    let mut best = start;
    let mut k = start;
    loop {
        let next = if sign > 0.0 {
            k + 1
        } else if k > 0 {
            k - 1
        } else {
            return best;
        };
        if next >= cl.len() {
            return best;
        }
        k = next;
        let (v, peak) = (sign * cl[k], sign * cl[best]);
        if v > peak {
            best = k;
        } else if peak - v > PEAK_DROP * peak.abs() {
            return best;
        }
    }
}

/// `y` at `x` linear between the points of `xs` (increasing); `None` outside.
pub(crate) fn linear_at(xs: &[f64], y: &[f64], x: f64) -> Option<f64> {
    let k = xs.partition_point(|&v| v <= x);
    if k == 0 || (k == xs.len() && x > xs[xs.len() - 1]) {
        return None;
    }
    if k == xs.len() {
        return Some(y[k - 1]);
    }
    let t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
    Some(y[k - 1] + t * (y[k] - y[k - 1]))
}

/// The summary of one polar of a table, with its flow condition.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SummaryRow {
    /// Airfoil name (the table's).
    pub airfoil: String,
    /// Reynolds number of the polar.
    pub re: f64,
    /// Mach number of the polar.
    pub mach: f64,
    /// The numbers.
    #[serde(flatten)]
    pub summary: PolarSummary,
}

/// The column names of the summary's CSV, in order (also the keys of its JSON records).
pub const SUMMARY_COLUMNS: [&str; 21] = [
    "airfoil",
    "re",
    "mach",
    "points",
    "trusted",
    "alpha_trusted_min",
    "alpha_trusted_max",
    "alpha_zero_lift",
    "lift_slope",
    "lift_slope_alpha_min",
    "lift_slope_alpha_max",
    "cl_max",
    "alpha_cl_max",
    "cl_max_at_edge",
    "cl_min",
    "alpha_cl_min",
    "cd_min",
    "cl_at_cd_min",
    "ld_max",
    "alpha_ld_max",
    "cm0",
];

impl SummaryRow {
    /// The fields in [`SUMMARY_COLUMNS`] order, numbers in shortest round-trip form, absent
    /// values empty.
    pub fn fields(&self) -> Vec<String> {
        let s = &self.summary;
        let opt = |v: Option<f64>| v.map_or_else(String::new, |v| v.to_string());
        let mut out = vec![
            self.airfoil.clone(),
            self.re.to_string(),
            self.mach.to_string(),
            s.points.to_string(),
            s.trusted.to_string(),
        ];
        out.extend(
            [
                s.alpha_trusted_min,
                s.alpha_trusted_max,
                s.alpha_zero_lift,
                s.lift_slope,
                s.lift_slope_alpha_min,
                s.lift_slope_alpha_max,
                s.cl_max,
                s.alpha_cl_max,
            ]
            .map(opt),
        );
        out.push(s.cl_max_at_edge.map_or_else(String::new, |b| b.to_string()));
        out.extend(
            [
                s.cl_min,
                s.alpha_cl_min,
                s.cd_min,
                s.cl_at_cd_min,
                s.ld_max,
                s.alpha_ld_max,
                s.cm0,
            ]
            .map(opt),
        );
        out
    }
}

impl PolarTable {
    /// The summary of every polar, Re-major.
    pub fn summaries(&self) -> Vec<SummaryRow> {
        self.polars()
            .map(|(c, points)| SummaryRow {
                airfoil: self.meta().airfoil.clone(),
                re: c.reynolds,
                mach: c.mach,
                summary: summarize(points),
            })
            .collect()
    }
}

/// `rows` as CSV: the header [`SUMMARY_COLUMNS`] and one line per polar, absent values empty.
pub fn summary_csv(rows: &[SummaryRow]) -> String {
    let mut out = csv::Writer::from_writer(Vec::new());
    // Writing text records to memory cannot fail.
    let _ = out.write_record(SUMMARY_COLUMNS);
    for r in rows {
        let _ = out.write_record(r.fields());
    }
    String::from_utf8(out.into_inner().unwrap_or_default()).unwrap_or_default()
}

/// `rows` as a JSON array of flat records with the keys [`SUMMARY_COLUMNS`], absent values
/// `null` (`pandas.read_json` reads it as one frame).
pub fn summary_json(rows: &[SummaryRow]) -> String {
    let mut text = serde_json::to_string_pretty(rows).unwrap_or_default();
    text.push('\n');
    text
}

/// `rows` as an aligned text table for a terminal: one line per polar, absent values `-`,
/// angles to 0.01°, coefficients to 4 decimals.
pub fn summary_text(rows: &[SummaryRow]) -> String {
    let head = [
        "Re",
        "M",
        "trusted a",
        "a0",
        "dCl/da",
        "fit a",
        "Cl_max",
        "at a",
        "Cd_min",
        "Cl there",
        "L/D max",
        "at a",
        "Cm0",
    ];
    let f = |v: Option<f64>, d: usize| v.map_or_else(|| "-".to_string(), |v| format!("{v:.d$}"));
    let span = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => format!("{a:.1}..{b:.1}"),
        _ => "-".to_string(),
    };
    let lines: Vec<[String; 13]> = rows
        .iter()
        .map(|r| {
            let s = &r.summary;
            let edge = if s.cl_max_at_edge == Some(true) {
                ">"
            } else {
                ""
            };
            [
                format!("{:e}", r.re),
                r.mach.to_string(),
                span(s.alpha_trusted_min, s.alpha_trusted_max),
                f(s.alpha_zero_lift, 2),
                f(s.lift_slope, 3),
                span(s.lift_slope_alpha_min, s.lift_slope_alpha_max),
                format!("{edge}{}", f(s.cl_max, 4)),
                f(s.alpha_cl_max, 2),
                f(s.cd_min, 5),
                f(s.cl_at_cd_min, 4),
                f(s.ld_max, 1),
                f(s.alpha_ld_max, 2),
                f(s.cm0, 4),
            ]
        })
        .collect();
    let width = |k: usize| {
        lines
            .iter()
            .map(|l| l[k].chars().count())
            .chain([head[k].len()])
            .max()
            .unwrap_or(0)
    };
    let widths: Vec<usize> = (0..head.len()).map(width).collect();
    let mut out = String::new();
    if let Some(r) = rows.first() {
        let _ = writeln!(
            out,
            "{}: angles in deg, dCl/da per rad; '>' marks a Cl_max at the end of the trusted \
             range (stall not reached)",
            r.airfoil
        );
    }
    let row = |out: &mut String, cells: &[String]| {
        let line: Vec<String> = cells
            .iter()
            .zip(&widths)
            .map(|(c, &w)| format!("{c:>w$}"))
            .collect();
        let _ = writeln!(out, "{}", line.join("  "));
    };
    row(&mut out, &head.map(str::to_string));
    for l in &lines {
        row(&mut out, l);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(alpha: f64, cl: f64, cd: f64, cm: f64) -> PolarPoint {
        PolarPoint::from_coefficients(alpha, cl, cd, cm)
    }

    #[test]
    fn numbers_of_a_simple_polar() {
        // Cl = 0.1·(α + 2) up to 10°, then falling; Cd = 0.01 + 0.001·α²; Cm = −0.05 + 0.001·α.
        let points: Vec<PolarPoint> = (-8..=14)
            .map(|a| {
                let a = a as f64;
                let cl = if a <= 10.0 {
                    0.1 * (a + 2.0)
                } else {
                    1.2 - 0.02 * (a - 10.0)
                };
                point(a, cl, 0.01 + 0.001 * a * a, -0.05 + 0.001 * a)
            })
            .collect();
        let s = summarize(&points);
        assert_eq!((s.points, s.trusted), (23, 23));
        assert_eq!(
            (s.alpha_trusted_min, s.alpha_trusted_max),
            (Some(-8.0), Some(14.0))
        );
        assert!((s.lift_slope.unwrap() - 0.1f64.to_degrees()).abs() < 1e-9);
        assert!((s.alpha_zero_lift.unwrap() + 2.0).abs() < 1e-12);
        assert_eq!(
            (s.lift_slope_alpha_min, s.lift_slope_alpha_max),
            (Some(-8.0), Some(10.0))
        );
        assert!((s.cl_max.unwrap() - 1.2).abs() < 1e-12);
        assert_eq!(
            (s.alpha_cl_max, s.cl_max_at_edge),
            (Some(10.0), Some(false))
        );
        assert_eq!((s.cd_min, s.cl_at_cd_min), (Some(0.01), Some(0.2)));
        assert!((s.cm0.unwrap() + 0.052).abs() < 1e-12);
        // Best L/D: max of 0.1(α+2)/(0.01+0.001α²) over the integers.
        let best = (-8..=10)
            .map(|a| {
                (
                    a as f64,
                    0.1 * (a as f64 + 2.0) / (0.01 + 0.001 * (a * a) as f64),
                )
            })
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        assert_eq!((s.alpha_ld_max, s.ld_max), (Some(best.0), Some(best.1)));
    }

    #[test]
    fn untrusted_points_end_the_run_and_an_empty_polar_gives_nothing() {
        let mut points: Vec<PolarPoint> = (-4..=8)
            .map(|a| point(a as f64, 0.1 * a as f64, 0.01, 0.0))
            .collect();
        points[10].supercritical = Some(true); // α = 6
        let s = summarize(&points);
        assert_eq!((s.trusted, s.alpha_trusted_max), (12, Some(5.0)));
        assert_eq!((s.cl_max, s.cl_max_at_edge), (Some(0.5), Some(true)));
        for p in &mut points {
            p.converged = false;
        }
        let none = summarize(&points);
        assert_eq!(
            none,
            PolarSummary {
                points: 13,
                ..PolarSummary::default()
            }
        );
    }
}
