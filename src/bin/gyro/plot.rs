//! `gyro plot alpha|takeoff|power`: rotor figures of the clean and (optionally) the
//! contaminated blade section overlaid — blade α vs azimuth (paper Fig. 10), takeoff time
//! histories (Fig. 11) and the power-required curve — written as SVG or PNG by the extension
//! of `--out`. The figure builders here turn rotor results into plot descriptions; `gyro
//! report` reuses them.

use anyhow::{Context, Result};
use clap::{Args, Subcommand};
use polargen::plot::rotor_plots::{
    alpha_azimuth_figure, power_required_figure, takeoff_figure, AzimuthCase, PowerCase,
    TakeoffCase,
};
use polargen::plot::{check_image_path, render_with, Figure, RenderParams, Style};
use polargen::rotor::cruise::cruise_blade_alpha;
use polargen::rotor::trim::TrimParams;
use polargen::rotor::{simulate_takeoff, TakeoffResult, TrimResult, KT_TO_MS};
use polargen::table::PolarTable;
use rayon::prelude::*;
use std::path::{Path, PathBuf};

/// The rotor figures `gyro plot` draws.
#[derive(Subcommand)]
pub enum PlotKind {
    /// Blade local angle of attack vs azimuth in trimmed cruise (paper Fig. 10; ψ = 0 rear).
    Alpha {
        #[command(flatten)]
        cases: CaseArgs,
        /// Airspeed in knots.
        #[arg(long, default_value_t = 60.0, allow_hyphen_values = true)]
        speed_kt: f64,
        /// Radius as a fraction of R.
        #[arg(long, default_value_t = 0.9, allow_hyphen_values = true)]
        radius: f64,
        /// Azimuth samples per revolution.
        #[arg(long, default_value_t = 360, allow_hyphen_values = true)]
        samples: usize,
    },
    /// Takeoff time histories: speed, height, rotor rpm, flapping (paper Fig. 11).
    Takeoff {
        #[command(flatten)]
        cases: CaseArgs,
    },
    /// Power and propeller thrust required vs airspeed (trim at each speed of a sweep).
    Power {
        #[command(flatten)]
        cases: CaseArgs,
        #[command(flatten)]
        speeds: crate::SpeedRange,
    },
}

/// Inputs shared by all rotor plots.
#[derive(Args)]
pub struct CaseArgs {
    /// Aircraft preset (TOML).
    #[arg(long)]
    aircraft: PathBuf,
    /// Polar table of the clean blade section.
    #[arg(long)]
    clean: PathBuf,
    /// Polar table of the contaminated blade section (optional: without it only the clean
    /// rotor is drawn).
    #[arg(long)]
    contaminated: Option<PathBuf>,
    /// Output image: FILE.svg or FILE.png.
    #[arg(long, value_name = "FILE")]
    out: PathBuf,
    /// Figure title (default: what is drawn, the aircraft and the airfoil).
    #[arg(long)]
    title: Option<String>,
}

/// Legend labels of the cases, in the order clean, contaminated.
pub const CASE_LABELS: [&str; 2] = ["clean", "contaminated"];

/// Line style of case `i`: clean solid blue, contaminated dashed red (distinct in grey print).
pub fn case_style(i: usize) -> Style {
    if i == 0 {
        Style::solid(0)
    } else {
        Style::dashed(1)
    }
}

/// Blade α vs azimuth for the cases given as (label, (ψ \[deg\], α \[deg\]) samples over one
/// revolution from ψ = 0); each curve is closed at ψ = 360° with its ψ = 0 value.
pub fn alpha_figure(curves: &[(&str, &[(f64, f64)])], title: &str) -> Figure {
    let closed: Vec<(Vec<f64>, Vec<f64>)> = curves
        .iter()
        .map(|(_, samples)| {
            let mut psi: Vec<f64> = samples.iter().map(|s| s.0).collect();
            let mut alpha: Vec<f64> = samples.iter().map(|s| s.1).collect();
            if let Some(&(psi0, a0)) = samples.first() {
                psi.push(psi0 + 360.0);
                alpha.push(a0);
            }
            (psi, alpha)
        })
        .collect();
    let cases: Vec<AzimuthCase> = curves
        .iter()
        .zip(&closed)
        .enumerate()
        .map(|(i, ((label, _), (psi, alpha)))| AzimuthCase {
            label,
            style: case_style(i),
            psi_deg: psi,
            alpha_deg: alpha,
        })
        .collect();
    alpha_azimuth_figure(&cases, title)
}

/// Takeoff time histories of the cases given as (label, result): speed \[kt\], height \[m\], rotor
/// rpm and flapping \[deg\] vs time, lift-off marked.
pub fn takeoff_plot(runs: &[(&str, &TakeoffResult)], title: &str) -> Figure {
    let columns: Vec<[Vec<f64>; 5]> = runs
        .iter()
        .map(|(_, r)| {
            let h = &r.history;
            [
                h.iter().map(|s| s.t).collect(),
                h.iter().map(|s| s.v / KT_TO_MS).collect(),
                h.iter().map(|s| s.h).collect(),
                h.iter().map(|s| s.rotor_rpm).collect(),
                h.iter().map(|s| s.beta_deg).collect(),
            ]
        })
        .collect();
    let cases: Vec<TakeoffCase> = runs
        .iter()
        .zip(&columns)
        .enumerate()
        .map(|(i, ((label, r), [t, v, h, rpm, beta]))| TakeoffCase {
            label,
            style: case_style(i),
            t,
            speed_kt: v,
            height_m: h,
            rotor_rpm: rpm,
            flapping_deg: beta,
            liftoff_t: Some(r.liftoff_time_s),
        })
        .collect();
    takeoff_figure(&cases, title)
}

/// Power and propeller thrust required vs airspeed for the cases given as (label, trims of a
/// speed sweep in increasing speed).
pub fn power_plot(sweeps: &[(&str, &[TrimResult])], title: &str) -> Figure {
    let columns: Vec<[Vec<f64>; 3]> = sweeps
        .iter()
        .map(|(_, trims)| {
            [
                trims.iter().map(|t| t.airspeed_kt).collect(),
                trims.iter().map(|t| t.power_required_kw).collect(),
                trims.iter().map(|t| t.prop_thrust_n).collect(),
            ]
        })
        .collect();
    let cases: Vec<PowerCase> = sweeps
        .iter()
        .zip(&columns)
        .enumerate()
        .map(|(i, ((label, _), [v, p, f]))| PowerCase {
            label,
            style: case_style(i),
            speed_kt: v,
            power_kw: p,
            thrust_n: f,
        })
        .collect();
    power_required_figure(&cases, title)
}

/// Airfoil name of a table for titles, e.g. `NACA 8-H-12`.
pub fn airfoil_name(table: &PolarTable) -> &str {
    &table.meta().airfoil
}

/// Runs `gyro plot …`.
pub fn run(kind: PlotKind) -> Result<()> {
    let cases = match &kind {
        PlotKind::Alpha { cases, .. }
        | PlotKind::Takeoff { cases }
        | PlotKind::Power { cases, .. } => cases,
    };
    check_image_path(&cases.out).context("--out")?;
    let aircraft = crate::load_aircraft(&cases.aircraft, None)?;
    let mut sections = vec![crate::load_section(&cases.clean)?];
    if let Some(path) = &cases.contaminated {
        sections.push(crate::load_section(path)?);
    }
    let labels = &CASE_LABELS[..sections.len()];
    let subject = format!("{}, {}", aircraft.name, airfoil_name(&sections[0]));
    let figure = match &kind {
        PlotKind::Alpha {
            speed_kt,
            radius,
            samples,
            ..
        } => {
            let (speed_kt, radius, samples) = (*speed_kt, *radius, *samples);
            crate::check_speed("speed-kt", speed_kt)?;
            crate::check_radius(radius, &aircraft)?;
            crate::check_samples(samples)?;
            let curves = sections
                .par_iter()
                .zip(labels)
                .map(|(s, label)| {
                    cruise_blade_alpha(
                        &aircraft,
                        s,
                        speed_kt,
                        0.0,
                        radius,
                        samples,
                        &TrimParams::default(),
                    )
                    .with_context(|| format!("{label} trim"))
                })
                .collect::<Result<Vec<_>>>()?;
            let refs: Vec<(&str, &[(f64, f64)])> = labels
                .iter()
                .zip(&curves)
                .map(|(l, c)| (*l, c.as_slice()))
                .collect();
            let title = cases.title.clone().unwrap_or_else(|| {
                format!("Blade α at r = {radius:.2} R, level flight at {speed_kt} kt — {subject}")
            });
            alpha_figure(&refs, &title)
        }
        PlotKind::Takeoff { .. } => {
            let runs = sections
                .par_iter()
                .zip(labels)
                .map(|(s, label)| {
                    simulate_takeoff(&aircraft, s).with_context(|| format!("{label} takeoff"))
                })
                .collect::<Result<Vec<_>>>()?;
            let refs: Vec<(&str, &TakeoffResult)> = labels.iter().copied().zip(&runs).collect();
            let title = cases
                .title
                .clone()
                .unwrap_or_else(|| format!("Takeoff to 15 m — {subject}"));
            takeoff_plot(&refs, &title)
        }
        PlotKind::Power { speeds, .. } => {
            let speeds = speeds.checked()?;
            let sweeps = sections
                .iter()
                .zip(labels)
                .map(|(s, label)| crate::trimmed_speeds(&aircraft, s, &speeds, Some(label)))
                .collect::<Result<Vec<_>>>()?;
            let refs: Vec<(&str, &[TrimResult])> = labels
                .iter()
                .zip(&sweeps)
                .map(|(l, t)| (*l, t.as_slice()))
                .collect();
            let title = cases
                .title
                .clone()
                .unwrap_or_else(|| format!("Level flight, power required — {subject}"));
            power_plot(&refs, &title)
        }
    };
    write_figure(&figure, &cases.out)
}

/// Width of a one-panel figure (px): wider than a grid cell, so the legend of the blade α plot
/// (curves, maxima, paper values) fits in two rows.
const SINGLE_PANEL_WIDTH: u32 = 960;

/// Renders `figure` to `path`, SVG or PNG by the extension; a one-panel figure is drawn wider.
pub fn write_figure(figure: &Figure, path: &Path) -> Result<()> {
    let mut params = RenderParams::default();
    if figure.panels.len() == 1 {
        params.panel_width = SINGLE_PANEL_WIDTH;
    }
    render_with(figure, path, &params)?;
    Ok(())
}
