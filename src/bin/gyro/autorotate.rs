//! `gyro autorotate`: the isolated rotor in a wind tunnel ([`polargen::rotor::autorotate`]);
//! parse, run, print.

use anyhow::{bail, Context, Result};
use clap::Args;
use polargen::rotor::{
    autorotate_outcomes, cases_csv, check_altitude_m, read_tunnel_cases, tunnel_case, Atmosphere,
    Rotor, RotorPreset, TrimParams, MAX_ISA_ALTITUDE_M,
};
use polargen::{report::console as print, table::read_lookup_table};
use std::path::PathBuf;

/// `gyro autorotate` options.
#[derive(Args)]
#[command(group(clap::ArgGroup::new("wind").required(true).args(["speed_m_s", "mu", "cases"])))]
pub struct AutorotateArgs {
    /// Aircraft or rotor preset (TOML); only its [rotor] is read.
    #[arg(long)]
    aircraft: PathBuf,
    /// Section polar table: polargen CSV or JSON, XFOIL .pol, C81, or a CSV of one polar with
    /// columns alpha, cl, cd[, cm].
    #[arg(long)]
    table: PathBuf,
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
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true,
          help = format!("ISA altitude in metres, 0 to {MAX_ISA_ALTITUDE_M}"))]
    altitude_m: f64,
    /// Print JSON (an array with --cases) instead of text (CSV with --cases).
    #[arg(long)]
    json: bool,
}

/// Runs `gyro autorotate`, appending its standard output to `buf`; `say` prints a note.
pub fn run(args: AutorotateArgs, buf: &mut String, say: impl Fn(&str)) -> Result<()> {
    check_altitude_m("--altitude-m", args.altitude_m)?;
    let mut preset = RotorPreset::from_toml_file(&args.aircraft)?;
    if let Some(pitch) = args.pitch_deg {
        preset.rotor.incidence_deg = pitch;
        preset.rotor.validate().context("--pitch-deg")?;
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
    let section = read_lookup_table(&args.table)?;
    let rotor = Rotor::from_params(&preset.rotor);
    let atm = Atmosphere::isa(args.altitude_m);
    let outcomes = autorotate_outcomes(&rotor, &section, &cases, &atm, &TrimParams::default());
    outcomes
        .iter()
        .flat_map(|o| o.notes())
        .for_each(|n| say(&n));
    if !outcomes.iter().any(|o| o.found()) {
        bail!("no case found an autorotating rotor speed");
    }
    match (args.cases.is_some(), args.json) {
        (false, false) => print::autorotation(buf, &outcomes[0].result),
        (false, true) => *buf += &(serde_json::to_string_pretty(&outcomes[0].result)? + "\n"),
        (true, true) => *buf += &(serde_json::to_string_pretty(&outcomes)? + "\n"),
        (true, false) => *buf += &cases_csv(&outcomes)?,
    }
    Ok(())
}
