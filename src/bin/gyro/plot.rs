//! `gyro plot alpha|takeoff|power`: rotor figures of the clean and (optionally) the
//! contaminated blade section overlaid — blade α vs azimuth (paper Fig. 10), takeoff time
//! histories (Fig. 11) and the power-required curve — written as SVG or PNG by the extension
//! of `--out`.

use anyhow::{Context, Result};
use clap::{Args, Subcommand};
use polargen::plot::rotor_plots::{alpha_figure, power_plot, takeoff_plot};
use polargen::plot::{check_image_path, render_with_legend_room};
use polargen::rotor::{TakeoffResult, TrimResult};
use polargen::studies::paper::{blade_alpha_cases, sweep_cases, takeoff_cases, CASE_LABELS};
use polargen::table::{read_lookup_table, PolarTable};
use std::path::PathBuf;

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
    /// Polar table of the clean blade section (polargen CSV or JSON, XFOIL .pol, C81, or a
    /// CSV of one polar).
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

/// Runs `gyro plot …`.
pub fn run(kind: PlotKind) -> Result<()> {
    let cases = match &kind {
        PlotKind::Alpha { cases, .. }
        | PlotKind::Takeoff { cases }
        | PlotKind::Power { cases, .. } => cases,
    };
    check_image_path(&cases.out).context("--out")?;
    let aircraft = crate::load_aircraft(&cases.aircraft, None)?;
    let mut tables: Vec<PolarTable> = vec![read_lookup_table(&cases.clean)?];
    if let Some(path) = &cases.contaminated {
        tables.push(read_lookup_table(path)?);
    }
    let sections: Vec<&PolarTable> = tables.iter().collect();
    let labels = &CASE_LABELS[..sections.len()];
    let subject = format!("{}, {}", aircraft.name, tables[0].meta().airfoil);
    let title = |default: String| cases.title.clone().unwrap_or(default);
    let figure = match &kind {
        PlotKind::Alpha {
            speed_kt,
            radius,
            samples,
            ..
        } => {
            let (speed_kt, radius, samples) = (*speed_kt, *radius, *samples);
            crate::check_speed("speed-kt", speed_kt)?;
            polargen::rotor::check_blade_radius("--radius", radius, &aircraft)?;
            polargen::rotor::check_azimuth_samples("--samples", samples)?;
            let curves =
                blade_alpha_cases(&aircraft, &sections, labels, speed_kt, radius, samples)?;
            let refs: Vec<(&str, &[(f64, f64)])> = labels
                .iter()
                .zip(&curves)
                .map(|(l, c)| (*l, c.as_slice()))
                .collect();
            alpha_figure(
                &refs,
                &title(format!(
                    "Blade α at r = {radius:.2} R, level flight at {speed_kt} kt — {subject}"
                )),
            )
        }
        PlotKind::Takeoff { .. } => {
            let runs = takeoff_cases(&aircraft, &sections, labels)?;
            let refs: Vec<(&str, &TakeoffResult)> = labels.iter().copied().zip(&runs).collect();
            takeoff_plot(&refs, &title(format!("Takeoff to 15 m — {subject}")))
        }
        PlotKind::Power { speeds, .. } => {
            let speeds = speeds.checked(&aircraft)?;
            let sweeps = sweep_cases(&aircraft, &sections, labels, &speeds);
            for sweep in &sweeps {
                crate::report_sweep(sweep)?;
            }
            let refs: Vec<(&str, &[TrimResult])> = labels
                .iter()
                .zip(&sweeps)
                .map(|(l, s)| (*l, s.trims.as_slice()))
                .collect();
            power_plot(
                &refs,
                &title(format!("Level flight, power required — {subject}")),
            )
        }
    };
    render_with_legend_room(&figure, &cases.out)?;
    Ok(())
}
