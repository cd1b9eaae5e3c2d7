//! `gyro plot alpha|takeoff|power`: rotor figures of the clean and (optionally) the
//! contaminated blade section overlaid — blade α vs azimuth (paper Fig. 10), takeoff time
//! histories (Fig. 11) and the power-required curve — written as SVG or PNG by the extension
//! of `--out`.

use anyhow::{Context, Result};
use clap::{Args, Subcommand};
use polargen::cli::values;
use polargen::plot::{check_image_path, render_with_legend_room};
use polargen::report::{rotor_figure, RotorFigure, ShippedInputs, SHIPPED_TABLE};
use polargen::rotor::check_blade_radius;
use polargen::table::PolarTable;
use std::path::PathBuf;

/// The rotor figures `gyro plot` draws.
#[derive(Subcommand)]
pub enum PlotKind {
    /// Blade local angle of attack vs azimuth in trimmed cruise (paper Fig. 10; ψ = 0 rear).
    Alpha {
        #[command(flatten)]
        cases: CaseArgs,
        /// Airspeed in knots.
        #[arg(long, default_value_t = 60.0, allow_hyphen_values = true, value_parser = values::speed_kt)]
        speed_kt: f64,
        /// Radius as a fraction of R.
        #[arg(long, default_value_t = 0.9, allow_hyphen_values = true, value_parser = values::fraction)]
        radius: f64,
        /// Azimuth samples per revolution.
        #[arg(long, default_value_t = 360, allow_hyphen_values = true, value_parser = values::azimuth_samples)]
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
    /// Aircraft preset (TOML) [default: aircraft/mtosport.toml, built in when absent].
    #[arg(long)]
    aircraft: Option<PathBuf>,
    /// Polar table of the clean blade section (any format polargen convert reads) [default:
    /// polars/naca8h12_free.csv, built in when absent].
    #[arg(long)]
    clean: Option<PathBuf>,
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
    let mut shipped = ShippedInputs::default();
    let aircraft = shipped.aircraft(&cases.aircraft)?;
    let mut tables: Vec<PolarTable> = vec![shipped.table(&cases.clean, SHIPPED_TABLE)?];
    if cases.contaminated.is_some() {
        tables.push(shipped.table(&cases.contaminated, "")?);
    }
    crate::note_shipped(shipped);
    let figure = match &kind {
        &PlotKind::Alpha {
            speed_kt,
            radius,
            samples,
            ..
        } => {
            check_blade_radius("--radius", radius, &aircraft)?;
            RotorFigure::Alpha {
                speed_kt,
                radius,
                samples,
            }
        }
        PlotKind::Takeoff { .. } => RotorFigure::Takeoff,
        PlotKind::Power { speeds, .. } => RotorFigure::Power {
            speeds_kt: speeds.checked(&aircraft)?,
        },
    };
    let say = |n| crate::TOOL.say(n);
    let figure = rotor_figure(&figure, &aircraft, &tables, cases.title.as_deref(), &say)?;
    render_with_legend_room(&figure, &cases.out)?;
    Ok(())
}
