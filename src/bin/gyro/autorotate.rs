//! `gyro autorotate`: the isolated rotor in a wind tunnel ([`polargen::rotor::autorotate`]);
//! parse, run, print.

use crate::TOOL;
use anyhow::Result;
use clap::Args;
use polargen::cli::values;
use polargen::report::{console as print, ShippedInputs, SHIPPED_TABLE};
use polargen::rotor::{cases_csv, read_tunnel_cases, tunnel_case, tunnel_run, MAX_ISA_ALTITUDE_M};
use std::path::PathBuf;

/// `gyro autorotate` options.
#[derive(Args)]
#[command(group(clap::ArgGroup::new("wind").required(true).args(["speed_m_s", "mu", "cases"])))]
pub struct AutorotateArgs {
    /// Aircraft or rotor preset (TOML); only its [rotor] is read [default:
    /// aircraft/mtosport.toml, built in when absent].
    #[arg(long)]
    aircraft: Option<PathBuf>,
    /// Section polar table: polargen CSV or JSON, XFOIL .pol, C81, or a CSV of one polar with
    /// columns alpha, cl, cd[, cm] [default: polars/naca8h12_free.csv, built in when absent].
    #[arg(long)]
    table: Option<PathBuf>,
    /// Rotor angle of attack in degrees: the wind against the plane normal to the shaft,
    /// positive with the disc tilted back.
    #[arg(long, allow_hyphen_values = true, required_unless_present = "cases")]
    alpha_deg: Option<f64>,
    /// Wind speed in m/s.
    #[arg(long, allow_hyphen_values = true)]
    speed_m_s: Option<f64>,
    /// Tip-speed ratio μ at --reference-rpm instead of a wind speed: V = μ·Ω_ref·R/cos α.
    #[arg(long, allow_hyphen_values = true, requires = "reference_rpm")]
    mu: Option<f64>,
    /// Rotor speed in rpm that --mu refers to.
    #[arg(long, allow_hyphen_values = true, requires = "mu")]
    reference_rpm: Option<f64>,
    /// CSV of cases with columns alpha_deg,speed_m_s (others ignored; - for stdin): one
    /// output row per case, the same columns after those two, and `error`.
    #[arg(long, conflicts_with = "alpha_deg")]
    cases: Option<PathBuf>,
    /// Blade pitch setting in degrees, in place of the preset's rotor.incidence_deg.
    #[arg(long, allow_hyphen_values = true)]
    pitch_deg: Option<f64>,
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true, value_parser = values::altitude_m,
          help = format!("ISA altitude in metres, 0 to {MAX_ISA_ALTITUDE_M}"))]
    altitude_m: f64,
    /// Print JSON (an array with --cases) instead of text (CSV with --cases).
    #[arg(long)]
    json: bool,
}

/// Runs `gyro autorotate`, appending its standard output to `buf`; `say` prints a note.
pub fn run(args: AutorotateArgs, buf: &mut String, say: &dyn Fn(String)) -> Result<()> {
    let mut shipped = ShippedInputs::default();
    let mut preset = shipped.rotor_preset(&args.aircraft)?;
    if let Some(pitch) = args.pitch_deg {
        preset.rotor.set_pitch(pitch)?;
    }
    let cases = match &args.cases {
        Some(path) => read_tunnel_cases(path)?,
        None => vec![tunnel_case(
            args.alpha_deg.unwrap_or(f64::NAN),
            args.speed_m_s,
            args.mu.zip(args.reference_rpm),
            preset.rotor.radius_m,
            ["--alpha-deg", "--speed-m-s", "--mu", "--reference-rpm"],
        )?],
    };
    let section = shipped.table(&args.table, SHIPPED_TABLE)?;
    shipped.notes().into_iter().for_each(say);
    let progress = TOOL.progress();
    let outcomes = tunnel_run(
        &preset.rotor,
        &section,
        &cases,
        args.altitude_m,
        &progress,
        say,
    )?;
    match (args.cases.is_some(), args.json) {
        (false, false) => print::autorotation(buf, &outcomes[0].result),
        (false, true) => *buf += &print::json(&outcomes[0].result)?,
        (true, true) => *buf += &print::json(&outcomes)?,
        (true, false) => *buf += &cases_csv(&outcomes)?,
    }
    Ok(())
}
