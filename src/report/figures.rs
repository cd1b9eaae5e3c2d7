//! The report's own figures: the polar overlay of one airfoil at the paper's section
//! condition with the Table 5 lift line, and the blade α(ψ) with the paper's maxima marked;
//! and the rotor figures of the clean and the contaminated section that the report and
//! `gyro plot` share ([`rotor_figure`]).

use super::{FoilTables, RotorResults, FIG10_RADIUS};
use crate::plot::polar_plots::{mark_lift_coefficient, polar_figure};
use crate::plot::rotor_plots::{alpha_figure, power_plot, takeoff_plot};
use crate::plot::{Figure, Marker};
use crate::rotor::{Aircraft, TakeoffResult};
use crate::studies::paper::published::{
    FIG10_MAX_ALPHA_DEG, FIG10_PSI_DEG, SECTION_MACH, SECTION_RE, TABLE5_CL,
};
use crate::studies::paper::{
    blade_alpha_cases, case_notes, sweep_cases, takeoff_cases, SpeedSweep,
};
use crate::studies::paper::{StudyError, CASE_LABELS, PAPER_TRIM_SPEED_KT};
use crate::table::{sample_polar, PolarTable};

/// A rotor figure of the clean and (optionally) the contaminated blade section.
#[derive(Clone, Debug, PartialEq)]
pub enum RotorFigure {
    /// Blade α against azimuth in trimmed level flight (paper Fig. 10).
    Alpha {
        /// Airspeed \[kt\].
        speed_kt: f64,
        /// Radius as a fraction of R.
        radius: f64,
        /// Azimuth samples per revolution.
        samples: usize,
    },
    /// Takeoff time histories: speed, height, rotor rpm, flapping (paper Fig. 11).
    Takeoff,
    /// Power and propeller thrust required against airspeed.
    Power {
        /// The airspeeds of the sweep \[kt\].
        speeds_kt: Vec<f64>,
    },
}

/// What a rotor figure is of: the aircraft and the airfoil of `section`.
pub(super) fn subject(aircraft: &Aircraft, section: &PolarTable) -> String {
    format!("{}, {}", aircraft.name, section.meta().airfoil)
}

/// `kind` for `aircraft` with each of `tables` (the clean section first; legends
/// [`CASE_LABELS`]), titled `title`, else by what is drawn, the aircraft and the airfoil.
/// `say` gets the notes of each speed sweep, before the sweep is required to have trimmed
/// somewhere. The radius and the speeds are taken as given (checked against the aircraft by
/// the caller).
pub fn rotor_figure(
    kind: &RotorFigure,
    aircraft: &Aircraft,
    tables: &[PolarTable],
    title: Option<&str>,
    say: &dyn Fn(String),
) -> Result<Figure, StudyError> {
    let sections: Vec<&PolarTable> = tables.iter().collect();
    let sections = sections.as_slice();
    let labels = &CASE_LABELS[..sections.len()];
    let subject = subject(aircraft, &tables[0]);
    let title = |default: String| title.map_or(default, str::to_string);
    Ok(match kind {
        &RotorFigure::Alpha {
            speed_kt,
            radius,
            samples,
        } => {
            let curves = blade_alpha_cases(aircraft, sections, labels, speed_kt, radius, samples)?;
            for (label, c) in labels.iter().zip(&curves) {
                case_notes(label, &c.notes(), &[]).into_iter().for_each(say);
            }
            let refs: Vec<(&str, &[(f64, f64)])> = labels
                .iter()
                .zip(&curves)
                .map(|(l, c)| (*l, c.points.as_slice()))
                .collect();
            let default =
                format!("Blade α at r = {radius:.2} R, level flight at {speed_kt} kt — {subject}");
            alpha_figure(&refs, &title(default))
        }
        RotorFigure::Takeoff => {
            let runs = takeoff_cases(aircraft, sections, labels)?;
            for (label, run) in labels.iter().zip(&runs) {
                case_notes(label, &[], &run.notes())
                    .into_iter()
                    .for_each(say);
            }
            takeoff_figure(&runs, &title(format!("Takeoff to 15 m — {subject}")))
        }
        RotorFigure::Power { speeds_kt } => {
            let sweeps = sweep_cases(aircraft, sections, labels, speeds_kt);
            for sweep in &sweeps {
                sweep.notes().into_iter().for_each(say);
                sweep.require_trims()?;
            }
            let default = format!("Level flight, power required — {subject}");
            power_figure(&sweeps, &title(default))
        }
    })
}

/// Takeoff time histories of the cases `runs` (in [`CASE_LABELS`] order).
pub(super) fn takeoff_figure(runs: &[TakeoffResult], title: &str) -> Figure {
    let refs: Vec<(&str, &TakeoffResult)> = CASE_LABELS.iter().copied().zip(runs).collect();
    takeoff_plot(&refs, title)
}

/// Power required of the speed sweeps of the cases `sweeps` (in [`CASE_LABELS`] order).
pub(super) fn power_figure(sweeps: &[SpeedSweep], title: &str) -> Figure {
    let refs: Vec<(&str, &[_])> = CASE_LABELS
        .iter()
        .zip(sweeps)
        .map(|(l, s)| (*l, s.trims.as_slice()))
        .collect();
    power_plot(&refs, title)
}

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
        .map(|(l, a)| (*l, a.points.as_slice()))
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
