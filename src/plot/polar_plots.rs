//! Polar overlays: the four classic panels Cl–α, Cd–Cl (drag polar), Cl/Cd–α and Cm–α for one
//! or more polars (e.g. clean vs fixed transition, or ours vs XFOIL).

use super::figure::{Figure, Marker, Panel, Series, Style};
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
    /// Solved points; unconverged ones are skipped.
    pub points: &'a [PolarPoint],
    /// Colour and line kind.
    pub style: Style,
}

/// Four-panel polar overlay with automatic styles: polar `i` gets palette colour `i`, solid.
///
/// Panels: Cl–α, Cd–Cl (Cd on x, as XFOIL draws the drag polar), Cl/Cd–α and Cm–α. Points with
/// `converged == false` or non-finite coefficients are skipped; Cl/Cd skips Cd ≤ 0 (inviscid).
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
    polar_figure_styled(&curves, title)
}

/// Four-panel polar overlay with the styles given per curve (see [`polar_figure`]).
pub fn polar_figure_styled(curves: &[PolarCurve], title: &str) -> Figure {
    let mut lift = Panel::new("Lift", "α [deg]", CL_LABEL);
    let mut drag = Panel::new("Drag polar", "Cd [-]", CL_LABEL);
    let mut ratio = Panel::new("Lift-to-drag ratio", "α [deg]", "Cl/Cd [-]");
    let mut moment = Panel::new("Pitching moment", "α [deg]", "Cm (c/4) [-]");
    for c in curves {
        let pts = usable_points(c.points);
        let series = |f: &dyn Fn(&PolarPoint) -> Option<(f64, f64)>| {
            Series::from_pairs(c.label, pts.iter().filter_map(f), c.style)
        };
        lift.series.push(series(&|p| Some((p.alpha, p.cl))));
        drag.series.push(series(&|p| Some((p.cd, p.cl))));
        ratio
            .series
            .push(series(&|p| (p.cd > 0.0).then(|| (p.alpha, p.cl / p.cd))));
        moment.series.push(series(&|p| Some((p.alpha, p.cm))));
    }
    Figure::new(title)
        .with_panel(lift)
        .with_panel(drag)
        .with_panel(ratio)
        .with_panel(moment)
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

/// Converged points with finite α, Cl, Cd, Cm, sorted by α (sweeps may run 0 → up, 0 → down).
fn usable_points(points: &[PolarPoint]) -> Vec<PolarPoint> {
    let mut pts: Vec<PolarPoint> = points
        .iter()
        .filter(|p| {
            p.converged
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

/// Legend text of a transition setting (x/c on the upper and lower surface, 1 = free):
/// `free`, `xtr 0.07`, or `xtr 0.05/0.1` (upper/lower).
pub fn transition_label(xtr_top: f64, xtr_bot: f64) -> String {
    if xtr_top >= 1.0 && xtr_bot >= 1.0 {
        "free".to_string()
    } else if xtr_top == xtr_bot {
        format!("xtr {xtr_top}")
    } else {
        format!("xtr {xtr_top}/{xtr_bot}")
    }
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
