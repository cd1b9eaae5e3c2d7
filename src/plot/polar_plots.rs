//! Polar overlays: Cl–α, the drag polar Cl–Cd, the transition locations Cl–x_tr, Cl/Cd–α and
//! Cm–α for one or more polars (e.g. clean vs fixed transition, or ours vs XFOIL).

use super::drag_axis::CdAxis;
use super::figure::{Figure, Line, Marker, Panel, Series, Style};
use super::point_plots::CHORD_LIMITS;
use crate::output::fixed_decimals;
use crate::section::{FlowCondition, PolarPoint};

/// y-axis label of the panels that plot the lift coefficient.
const CL_LABEL: &str = "Cl [-]";

/// Palette index of case-independent reference lines (grey).
const REFERENCE_COLOR: usize = 7;

/// One polar to overlay: legend label, points (any order) and line style.
#[derive(Clone, Copy, Debug)]
pub struct PolarCurve<'a> {
    /// Legend label, e.g. `"NACA 8-H-12 free transition"`.
    pub label: &'a str,
    /// Solved points; unconverged ones are skipped, those in massive separation drawn apart.
    pub points: &'a [PolarPoint],
    /// Colour and line kind.
    pub style: Style,
}

/// Polar overlay with automatic styles (polar `i` gets palette colour `i`, solid) and the Cd
/// axis of [`CdAxis::Attached`]; panels as [`polar_figure_styled`].
pub fn polar_figure(polars: &[(&str, &[PolarPoint])], title: &str) -> Figure {
    let curves: Vec<PolarCurve> = polars
        .iter()
        .enumerate()
        .map(|(i, &(label, points))| PolarCurve {
            label,
            points,
            style: Style::solid(i),
        })
        .collect();
    polar_figure_styled(&curves, title, CdAxis::Attached)
}

/// The overlay of one polar per name (`names[i]` labels `polars[i]`), each in the next
/// solid style: the figure of `polargen plot` and of Python's `plot.polars`.
pub fn overlay_figure<P: AsRef<[PolarPoint]>>(
    names: &[String],
    polars: &[P],
    title: &str,
    cd_axis: CdAxis,
) -> Figure {
    let curves: Vec<PolarCurve> = names
        .iter()
        .zip(polars)
        .enumerate()
        .map(|(i, (label, points))| PolarCurve {
            label,
            points: points.as_ref(),
            style: Style::solid(i),
        })
        .collect();
    polar_figure_styled(&curves, title, cd_axis)
}

/// Polar overlay with the styles given per curve, the drag polar's Cd axis chosen by `cd_axis`.
///
/// Panels: Cl–α, the drag polar Cl–Cd and the transition locations Cl–x_tr (Cl on y in all
/// three, as XFOIL's polar plot, so that a row reads across at one Cl), then Cl/Cd–α and Cm–α.
/// The transition panel draws x_tr/c of the upper surface in the curve's style and of the
/// lower surface dashed; it is left out when no polar carries transition locations (C81).
/// Points with `converged == false` or non-finite Cl, Cd, Cm are left out of every line;
/// converged points in massive separation ([`PolarPoint::usable`]) are drawn as unconnected
/// points in the curve's colour, labelled `(massive separation)`, not joined to the line;
/// Cl/Cd skips Cd ≤ 0 (inviscid). Drag beyond the Cd axis is marked by arrowheads at its right
/// edge and counted in its label.
pub fn polar_figure_styled(curves: &[PolarCurve], title: &str, cd_axis: CdAxis) -> Figure {
    let mut lift = Panel::new("Lift", "α [deg]", CL_LABEL);
    let mut drag = Panel::new("Drag polar", "Cd [-]", CL_LABEL).with_clipped_marked();
    let mut transition = Panel::new(
        "Transition: upper solid, lower dashed",
        "x_tr/c [-]",
        CL_LABEL,
    )
    .with_x_range(CHORD_LIMITS.0, CHORD_LIMITS.1);
    let mut ratio = Panel::new("Lift-to-drag ratio", "α [deg]", "Cl/Cd [-]");
    let mut moment = Panel::new("Pitching moment", "α [deg]", "Cm (c/4) [-]");
    let usable: Vec<Vec<PolarPoint>> = curves
        .iter()
        .map(|c| finite_points(c.points, PolarPoint::usable))
        .collect();
    for (c, pts) in curves.iter().zip(&usable) {
        let series = |f: &dyn Fn(&PolarPoint) -> Option<(f64, f64)>| {
            Series::from_pairs(c.label, pts.iter().filter_map(f), c.style)
        };
        lift.series.push(series(&|p| Some((p.alpha, p.cl))));
        drag.series.push(series(&|p| Some((p.cd, p.cl))));
        ratio
            .series
            .push(series(&|p| (p.cd > 0.0).then(|| (p.alpha, p.cl / p.cd))));
        moment.series.push(series(&|p| Some((p.alpha, p.cm))));
        transition.series.push(series(&|p| Some((p.xtr_top, p.cl))));
        let lower = Style {
            line: match c.style.line {
                Line::None => Line::None,
                _ => Line::Dashed,
            },
            ..c.style
        };
        transition.series.push(Series::from_pairs(
            "",
            pts.iter().map(|p| (p.xtr_bot, p.cl)),
            lower,
        ));
    }
    for c in curves {
        // Converged points in massive separation: drawn as unconnected points, not as results.
        let separated = finite_points(c.points, |p| p.converged && !p.usable());
        if separated.is_empty() {
            continue;
        }
        let label = format!("{} (massive separation)", c.label);
        let style = Style::points(c.style.color);
        let series = |f: &dyn Fn(&PolarPoint) -> Option<(f64, f64)>| {
            Series::from_pairs(label.as_str(), separated.iter().filter_map(f), style)
        };
        lift.series.push(series(&|p| Some((p.alpha, p.cl))));
        drag.series.push(series(&|p| Some((p.cd, p.cl))));
        ratio
            .series
            .push(series(&|p| (p.cd > 0.0).then(|| (p.alpha, p.cl / p.cd))));
        moment.series.push(series(&|p| Some((p.alpha, p.cm))));
    }
    let polars: Vec<&[PolarPoint]> = usable.iter().map(Vec::as_slice).collect();
    if let Some(limit) = cd_axis.upper_limit(&polars) {
        drag = drag.with_x_range(0.0, limit);
        let beyond = polars
            .iter()
            .flat_map(|p| p.iter())
            .filter(|p| p.cd > limit);
        let (count, largest) = beyond.fold((0, 0.0_f64), |(n, m), p| (n + 1, m.max(p.cd)));
        if count > 0 {
            let digits = (2 - limit.log10().floor() as i32).max(0) as usize;
            drag.x_label = format!(
                "Cd [-]   ({count} points beyond {} up to {} →)",
                fixed_decimals(limit, digits),
                fixed_decimals(largest, digits)
            );
        }
    }
    let has_transition = usable
        .iter()
        .flatten()
        .any(|p| p.xtr_top.is_finite() || p.xtr_bot.is_finite());
    let mut figure = Figure::new(title).with_panel(lift).with_panel(drag);
    if has_transition {
        figure = figure.with_panel(transition);
    }
    figure.with_panel(ratio).with_panel(moment)
}

/// Adds a horizontal reference line at lift coefficient `cl` (e.g. the paper's Table 5 compares
/// Cd at Cl = 0.8) to every panel whose y axis is Cl, labelled "Cl = …".
pub fn mark_lift_coefficient(mut figure: Figure, cl: f64) -> Figure {
    for panel in figure.panels.iter_mut().filter(|p| p.y_label == CL_LABEL) {
        panel
            .markers
            .push(Marker::hline(cl, format!("Cl = {cl}"), REFERENCE_COLOR));
    }
    figure
}

/// The points `keep` selects with finite α, Cl, Cd, Cm, sorted by α (sweeps may run 0 → up,
/// 0 → down).
fn finite_points(points: &[PolarPoint], keep: impl Fn(&PolarPoint) -> bool) -> Vec<PolarPoint> {
    let mut pts: Vec<PolarPoint> = points
        .iter()
        .filter(|p| {
            keep(p)
                && p.alpha.is_finite()
                && p.cl.is_finite()
                && p.cd.is_finite()
                && p.cm.is_finite()
        })
        .copied()
        .collect();
    pts.sort_by(|a, b| a.alpha.total_cmp(&b.alpha));
    pts
}

/// Compact number for titles: 1.9e6 → `1.9e6` (mantissa to three decimals), below 10⁴ as is.
pub fn compact_number(v: f64) -> String {
    if v >= 1e4 {
        let e = v.log10().floor() as i32;
        let m = v / 10f64.powi(e);
        format!("{}e{e}", (m * 1000.0).round() / 1000.0)
    } else {
        format!("{v}")
    }
}

/// Title of an overlay of polars taken from tables: the legend names joined by `vs`, then the
/// flow condition drawn (`Re 1.9e6, M 0.41`), with `(nearest to …)` when that is not the
/// condition `asked` for, or `several Re, M` when the polars were drawn at different ones.
pub fn overlay_title(
    names: &[&str],
    drawn: &[FlowCondition],
    asked: Option<FlowCondition>,
) -> String {
    let Some(&first) = drawn.first() else {
        return names.join(" vs ");
    };
    let same = drawn.iter().all(|c| *c == first);
    let at = if same {
        format!("Re {}, M {}", compact_number(first.reynolds), first.mach)
    } else {
        "several Re, M".to_string()
    };
    let nearest = match asked {
        Some(q) if same && q != first => {
            format!(
                " (nearest to Re {}, M {})",
                compact_number(q.reynolds),
                q.mach
            )
        }
        _ => String::new(),
    };
    format!("{} — {at}{nearest}", names.join(" vs "))
}
