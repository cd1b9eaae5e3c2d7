//! The report's own figures: the polar overlay of one airfoil at the paper's section
//! condition with the Table 5 lift line, and the blade α(ψ) with the paper's maxima marked.

use super::{FoilTables, RotorResults, FIG10_RADIUS};
use crate::plot::polar_plots::{mark_lift_coefficient, polar_figure};
use crate::plot::rotor_plots::alpha_figure;
use crate::plot::{Figure, Marker};
use crate::studies::paper::published::{
    FIG10_MAX_ALPHA_DEG, FIG10_PSI_DEG, SECTION_MACH, SECTION_RE, TABLE5_CL,
};
use crate::studies::paper::{CASE_LABELS, PAPER_TRIM_SPEED_KT};
use crate::table::sample_polar;

/// Label of a table's transition setting for legends.
fn transition_label(i: usize) -> &'static str {
    if i == 0 {
        "free transition"
    } else {
        "transition fixed at 7 % chord"
    }
}

/// Four-panel polar overlay of one airfoil, free vs fixed transition, interpolated in the
/// tables at the paper's Re and M, with the Table 5 line Cl = 0.8.
pub(super) fn polar_overlay(foil: &FoilTables) -> Figure {
    let polars: Vec<Vec<_>> = foil
        .tables
        .iter()
        .map(|t| {
            let (_, node) = t.nearest_polar(SECTION_RE, SECTION_MACH);
            let alphas: Vec<f64> = node.iter().map(|p| p.alpha).collect();
            sample_polar(t, &alphas, SECTION_RE, SECTION_MACH)
        })
        .collect();
    let labels: Vec<String> = (0..2)
        .map(|i| format!("{} {}", foil.row.name, transition_label(i)))
        .collect();
    let curves: Vec<(&str, &[_])> = labels
        .iter()
        .zip(&polars)
        .map(|(l, p)| (l.as_str(), p.as_slice()))
        .collect();
    let title = format!(
        "{} — Re 1.9e6, M {SECTION_MACH} (interpolated in the shipped tables)",
        foil.row.name
    );
    // The drag polar's Cd axis (attached-flow rule) shows the drag bucket of Table 5.
    mark_lift_coefficient(polar_figure(&curves, &title), TABLE5_CL)
}

/// Blade α(ψ) at 0.9 R with the paper's maxima marked.
pub(super) fn fig10(rotor: &RotorResults, subject: &str) -> Figure {
    let curves: Vec<(&str, &[(f64, f64)])> = CASE_LABELS
        .iter()
        .zip(&rotor.alpha)
        .map(|(l, a)| (*l, a.as_slice()))
        .collect();
    let mut fig = alpha_figure(
        &curves,
        &format!(
            "Blade α at r = {FIG10_RADIUS:.1} R, level flight at {PAPER_TRIM_SPEED_KT} kt — {subject}"
        ),
    );
    let (clean, dirty) = (FIG10_MAX_ALPHA_DEG.clean, FIG10_MAX_ALPHA_DEG.contaminated);
    if let Some(panel) = fig.panels.first_mut() {
        for (i, (label, a)) in [
            ("paper max clean", clean),
            ("paper max contaminated", dirty),
        ]
        .into_iter()
        .enumerate()
        {
            panel.markers.push(Marker::point(
                FIG10_PSI_DEG,
                a,
                format!("{label}: {a}° at ψ = {FIG10_PSI_DEG}°"),
                [2, 3][i],
            ));
        }
    }
    fig
}
