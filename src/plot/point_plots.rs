//! Distributions at one operating point: pressure coefficient Cp(x/c) and boundary-layer
//! quantities (shape factor H, skin friction Cf, amplification factor N) along a surface, with
//! the transition location marked, for several cases overlaid (e.g. clean vs fixed transition);
//! the airfoil contour drawn to scale under the Cp panel.

use super::figure::{Figure, Marker, Panel, Series, Style};
use crate::geometry::Airfoil;
use crate::viscous::distributions::SurfaceDistributions;
use crate::viscous::ViscousSolution;

/// x/c axis limits of all chordwise panels (here and the polars' transition panel): the chord
/// with a small margin.
pub(crate) const CHORD_LIMITS: (f64, f64) = (-0.02, 1.02);

/// One case (e.g. one transition setting, one surface) at one α. Each distribution is a pair
/// of equally long slices (x/c, value); empty slices mean "not available" and draw nothing.
#[derive(Clone, Copy, Debug, Default)]
pub struct PointCase<'a> {
    /// Legend label, e.g. `"free transition, upper"`.
    pub label: &'a str,
    /// Colour and line kind.
    pub style: Style,
    /// Pressure coefficient Cp(x/c).
    pub cp: (&'a [f64], &'a [f64]),
    /// Shape factor H = δ*/θ (as [`SurfaceDistributions::h`]).
    pub h: (&'a [f64], &'a [f64]),
    /// Skin-friction coefficient as given by the solver (XFOIL normalises τw by ½ ρ V∞²).
    pub cf: (&'a [f64], &'a [f64]),
    /// Amplification factor N of the e^n method.
    pub n: (&'a [f64], &'a [f64]),
    /// Transition location x/c, marked by a vertical line in the boundary-layer panels.
    pub x_transition: Option<f64>,
}

/// Pressure distribution Cp(x/c) of all cases in one panel, y axis inverted (suction up).
/// All point panels show x/c ∈ \[−0.02, 1.02\]; wake points beyond are clipped.
pub fn cp_figure(cases: &[PointCase], title: &str) -> Figure {
    Figure::new(title).with_panel(cp_panel(cases))
}

/// Boundary-layer panels H, Cf and N (three in a row) with the transition locations marked and,
/// if given, the critical amplification factor `ncrit` as a horizontal line in the N panel.
pub fn bl_figure(cases: &[PointCase], title: &str, ncrit: Option<f64>) -> Figure {
    let [h, cf, n] = bl_panels(cases, ncrit);
    Figure::new(title)
        .with_panel(h)
        .with_panel(cf)
        .with_panel(n)
}

/// All four distributions (2 × 2): Cp, H, Cf and N, transition locations marked.
pub fn point_figure(cases: &[PointCase], title: &str, ncrit: Option<f64>) -> Figure {
    let [h, cf, n] = bl_panels(cases, ncrit);
    Figure::new(title)
        .with_panel(cp_panel(cases))
        .with_panel(h)
        .with_panel(cf)
        .with_panel(n)
}

/// y-axis label of the pressure-coefficient panel.
const CP_LABEL: &str = "Cp [-]";

/// The figure with the contour of `airfoil` (in chords, as the solver saw it) drawn to scale
/// in a strip under each Cp panel, on its x/c axis.
pub fn with_airfoil_contour(mut figure: Figure, airfoil: &Airfoil) -> Figure {
    let contour: Vec<(f64, f64)> = airfoil
        .x
        .iter()
        .copied()
        .zip(airfoil.y.iter().copied())
        .collect();
    for panel in figure.panels.iter_mut().filter(|p| p.y_label == CP_LABEL) {
        panel.contour = contour.clone();
    }
    figure
}

/// The Cp panel (inverted y axis).
fn cp_panel(cases: &[PointCase]) -> Panel {
    let mut panel = Panel::new("Pressure distribution", "x/c [-]", CP_LABEL)
        .with_y_inverted()
        .with_x_range(CHORD_LIMITS.0, CHORD_LIMITS.1);
    for c in cases {
        panel
            .series
            .push(Series::from_slices(c.label, c.cp.0, c.cp.1, c.style));
    }
    panel
}

/// The H, Cf and N panels with transition markers.
fn bl_panels(cases: &[PointCase], ncrit: Option<f64>) -> [Panel; 3] {
    let chord = |p: Panel| p.with_x_range(CHORD_LIMITS.0, CHORD_LIMITS.1);
    let mut h = chord(Panel::new("Shape factor", "x/c [-]", "H [-]"));
    let mut cf = chord(Panel::new("Skin friction", "x/c [-]", "Cf [-]"));
    let mut n = chord(Panel::new("Amplification", "x/c [-]", "N [-]"));
    for c in cases {
        for (panel, data) in [(&mut h, c.h), (&mut cf, c.cf), (&mut n, c.n)] {
            panel
                .series
                .push(Series::from_slices(c.label, data.0, data.1, c.style));
            if let Some(xtr) = c.x_transition {
                panel.markers.push(Marker::vline(
                    xtr,
                    format!("transition x/c = {xtr:.3} ({})", c.label),
                    c.style.color,
                ));
            }
        }
    }
    if let Some(ncrit) = ncrit {
        n.markers
            .push(Marker::hline(ncrit, format!("Ncrit = {ncrit}"), 7));
    }
    [h, cf, n]
}

/// All four distributions ([`point_figure`]) of viscous solutions given as (label, solution)
/// at free-stream Mach number `mach`: for case `k` the upper surface solid and the lower
/// surface dashed in palette colour `k`, labelled `<label> upper` and `<label> lower`, with the
/// transition locations marked.
pub fn solutions_figure(
    runs: &[(&str, &ViscousSolution)],
    mach: f64,
    title: &str,
    ncrit: Option<f64>,
) -> Figure {
    let distributions: Vec<SurfaceDistributions> = runs
        .iter()
        .flat_map(|(_, sol)| {
            [
                SurfaceDistributions::new(&sol.upper, mach),
                SurfaceDistributions::new(&sol.lower, mach),
            ]
        })
        .collect();
    let labels: Vec<String> = runs
        .iter()
        .flat_map(|(label, _)| [format!("{label} upper"), format!("{label} lower")])
        .collect();
    let cases: Vec<PointCase> = distributions
        .iter()
        .zip(&labels)
        .enumerate()
        .map(|(k, (d, label))| {
            let (point, upper) = (&runs[k / 2].1.point, k % 2 == 0);
            let (style, xtr) = if upper {
                (Style::solid(k / 2), point.xtr_top)
            } else {
                (Style::dashed(k / 2), point.xtr_bot)
            };
            PointCase {
                label,
                style,
                cp: (&d.x, &d.cp),
                h: (&d.x, &d.h),
                cf: (&d.x, &d.cf),
                n: (&d.x, &d.n),
                x_transition: xtr.is_finite().then_some(xtr),
            }
        })
        .collect();
    point_figure(&cases, title, ncrit)
}

/// Title of a [`solutions_figure`]: the airfoil, Re, M and either the angle of attack or, for
/// solutions at a target lift coefficient `cl`, that Cl and the α of each case.
pub fn solutions_title(
    airfoil: &str,
    reynolds: f64,
    mach: f64,
    alpha_deg: f64,
    cl: Option<f64>,
    runs: &[(&str, &ViscousSolution)],
) -> String {
    let at = match cl {
        Some(cl) => {
            let alphas: Vec<String> = runs
                .iter()
                .map(|(label, s)| format!("{:.2}° {label}", s.point.alpha))
                .collect();
            format!("Cl {cl} (α {})", alphas.join(", "))
        }
        None => format!("α {alpha_deg}°"),
    };
    format!(
        "{airfoil} — Re {}, M {mach}, {at}",
        super::polar_plots::compact_number(reynolds)
    )
}
