//! `gyro` — gyroplane rotor performance from airfoil polar tables: cruise trim, takeoff,
//! clean-versus-contaminated comparison (paper Tables 3 and 4), power-required sweeps, rotor
//! plots ([`plot`]) and the paper report ([`polargen::report`]). Text output is formatted in
//! [`print`](mod@print).

mod autorotate;
mod plot;
use polargen::report::console as print;
mod study;

use anyhow::{Context, Result};
use clap::{Args, CommandFactory, Parser, Subcommand};
use polargen::cli::{self, values, Tool};
use polargen::output::{check_output_path, is_stdout, write_stdout};
use polargen::report::{self as paper, check_report_paths, write_report, ReportInputs};
use polargen::report::{
    ShippedInputs, SHIPPED_AIRCRAFT, SHIPPED_CONTAMINATED_TABLE, SHIPPED_POLARS,
};
use polargen::rotor::{
    check_blade_radius, checked_sweep_speeds, cruise_blade_alpha, simulate_takeoff, trim_aircraft,
    Aircraft, TrimParams, MAX_ISA_ALTITUDE_M,
};
use polargen::studies::paper::{paper_runs, paper_runs_notes, SpeedSweep};
use polargen::table::PolarTable;
use std::path::PathBuf;
use std::process::ExitCode;

/// This tool's name and error prefix.
static TOOL: Tool = Tool::new("gyro");

#[derive(Parser)]
#[command(
    name = "gyro",
    version,
    about = "Gyroplane rotor strip model driven by airfoil polar tables",
    arg_required_else_help = true
)]
struct Cli {
    #[command(subcommand)]
    command: Command,

    /// No notes on stderr (errors are still printed).
    #[arg(long, short, global = true)]
    quiet: bool,
}

#[derive(Subcommand)]
enum Command {
    /// Level-cruise trim: rotor rpm, both rotor angles, drags, thrust, engine rpm, static thrust.
    Trim {
        #[command(flatten)]
        inputs: Inputs,
        /// Airspeed in knots.
        #[arg(long, default_value_t = 60.0, allow_hyphen_values = true, value_parser = values::speed_kt)]
        speed_kt: f64,
        /// Mass in kg (default: the preset's).
        #[arg(long, allow_hyphen_values = true, value_parser = values::mass_kg)]
        mass: Option<f64>,
        #[arg(long, default_value_t = 0.0, allow_hyphen_values = true, value_parser = values::altitude_m,
              help = format!("ISA altitude in metres, 0 to {MAX_ISA_ALTITUDE_M}"))]
        altitude_m: f64,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Takeoff from brake release to the screen height: s_TO, s_15, β_max.
    Takeoff {
        #[command(flatten)]
        inputs: Inputs,
        /// Mass in kg (default: the preset's).
        #[arg(long, allow_hyphen_values = true, value_parser = values::mass_kg)]
        mass: Option<f64>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        /// Write the time history (t, x, h, v, rotor_rpm, alpha_r_deg, beta_deg) to this CSV;
        /// with - (standard output) the summary goes to stderr.
        #[arg(long, value_name = "FILE|-")]
        history: Option<PathBuf>,
    },
    /// Clean versus contaminated rotor: paper Tables 3 and 4 side by side with ours.
    Compare {
        /// Aircraft preset (TOML) [default: aircraft/mtosport.toml, built in when absent].
        #[arg(long)]
        aircraft: Option<PathBuf>,
        /// Table of the clean blade section (any format --table reads) [default:
        /// polars/naca8h12_free.csv, built in when absent].
        #[arg(long)]
        clean: Option<PathBuf>,
        /// Table of the contaminated blade section [default: polars/naca8h12_xtr0.07.csv,
        /// built in when absent].
        #[arg(long)]
        contaminated: Option<PathBuf>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Trim over a speed range: power-required curve.
    Sweep {
        #[command(flatten)]
        inputs: Inputs,
        #[command(flatten)]
        speeds: SpeedRange,
        /// Mass in kg (default: the preset's).
        #[arg(long, allow_hyphen_values = true, value_parser = values::mass_kg)]
        mass: Option<f64>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Blade angle of attack α(ψ) at one radius in trimmed cruise (paper Fig. 10; ψ = 0 rear).
    Alpha {
        #[command(flatten)]
        inputs: Inputs,
        /// Airspeed in knots.
        #[arg(long, default_value_t = 60.0, allow_hyphen_values = true, value_parser = values::speed_kt)]
        speed_kt: f64,
        /// Radius as a fraction of R.
        #[arg(long, default_value_t = 0.9, allow_hyphen_values = true, value_parser = values::fraction)]
        radius: f64,
        /// Azimuth samples per revolution.
        #[arg(long, default_value_t = 36, allow_hyphen_values = true, value_parser = values::azimuth_samples)]
        samples: usize,
    },
    /// Isolated rotor in a wind tunnel: autorotative rpm, C_L, C_D, L/D, coning and flapping.
    Autorotate(autorotate::AutorotateArgs),
    /// Rotor figures, clean vs contaminated, to SVG or PNG: alpha, takeoff or power.
    #[command(arg_required_else_help = true)]
    Plot {
        #[command(subcommand)]
        kind: plot::PlotKind,
    },
    /// The paper report: flight test, Tables 3–5, sensitivity and all figures, in one folder.
    Report(ReportArgs),
    /// Shell completion script on standard output (e.g. `gyro completions bash >
    /// ~/.local/share/bash-completion/completions/gyro`).
    Completions(cli::CompletionsArgs),
    /// Man pages (roff): the tool's or a subcommand's on standard output (`gyro man study
    /// wing > gyro-study-wing.1`), or all of them with --out DIR.
    Man(cli::ManArgs),
    /// What-if studies beyond the paper (section tables solved and cached).
    Study {
        #[command(subcommand)]
        study: study::Study,
    },
}

/// The aircraft and the blade section of a single-section command.
#[derive(Args)]
struct Inputs {
    /// Aircraft preset (TOML) [default: aircraft/mtosport.toml, built in when absent].
    #[arg(long)]
    aircraft: Option<PathBuf>,
    /// Section polar table: any format polargen convert reads (CSV, JSON, XFOIL .pol, C81,
    /// AeroDyn, a CSV of one polar with columns alpha, cl, cd[, cm]) [default:
    /// polars/naca8h12_free.csv, built in when absent].
    #[arg(long)]
    table: Option<PathBuf>,
}

/// The note naming the shipped inputs `used` in place of those not given, if any.
fn note_shipped(used: ShippedInputs) {
    used.notes().into_iter().for_each(|n| TOOL.say(n));
}

/// The aircraft (at `mass`, else its own), what `check` makes of it (flags checked against it
/// before the table is read) and the table of a single-section command; the shipped ones
/// when not given.
fn load<T>(
    inputs: &Inputs,
    mass: Option<f64>,
    check: impl FnOnce(&Aircraft) -> Result<T>,
) -> Result<(Aircraft, T, PolarTable)> {
    let mut shipped = ShippedInputs::default();
    let loaded = shipped.aircraft_and_table((&inputs.aircraft, &inputs.table), mass, check)?;
    note_shipped(shipped);
    Ok(loaded)
}

/// `gyro report` options.
#[derive(Args)]
pub struct ReportArgs {
    /// Aircraft preset (TOML); the default is built in, used when no such file exists (so
    /// the report runs outside the repository).
    #[arg(long, default_value = SHIPPED_AIRCRAFT)]
    aircraft: PathBuf,
    /// Folder holding naca8h12_free.csv, naca8h12_xtr0.07.csv, naca23012_free.csv and
    /// naca23012_xtr0.07.csv; the shipped default-grid tables are built in and used when
    /// the default folder does not hold them.
    #[arg(long, default_value = SHIPPED_POLARS)]
    polars: PathBuf,
    /// Output folder (created if missing): README.md and the figures.
    #[arg(long, default_value = "report")]
    out: PathBuf,
    /// Table cache of the section "Beyond the paper" (`gyro study`) [default: as gyro study].
    #[arg(long)]
    cache: Option<PathBuf>,
    /// Add the section "Beyond the paper" (`gyro study`; its tables take minutes to solve once).
    #[arg(long)]
    studies: bool,
}

/// Airspeed range of a speed sweep (`gyro sweep`, `gyro plot power`).
#[derive(Args, Debug, Clone, Copy)]
pub struct SpeedRange {
    /// Lowest airspeed in knots.
    #[arg(long, default_value_t = 30.0, allow_hyphen_values = true, value_parser = values::speed_kt)]
    pub from_kt: f64,
    /// Highest airspeed in knots.
    #[arg(long, default_value_t = 90.0, allow_hyphen_values = true, value_parser = values::speed_kt)]
    pub to_kt: f64,
    /// Speed step in knots.
    #[arg(long, default_value_t = 5.0, allow_hyphen_values = true, value_parser = values::positive)]
    pub step_kt: f64,
}

impl SpeedRange {
    /// The speeds of the sweep \[kt\] for `aircraft`, checked ([`checked_sweep_speeds`]).
    fn checked(&self, aircraft: &Aircraft) -> Result<Vec<f64>> {
        let cells = aircraft.rotor.cells();
        let speeds = checked_sweep_speeds(self.from_kt, self.to_kt, self.step_kt, cells)?;
        Ok(speeds)
    }
}

/// Runs one command, appending its standard output to `buf`.
fn run(cli: Cli, buf: &mut String) -> Result<()> {
    match cli.command {
        Command::Trim {
            inputs,
            speed_kt,
            mass,
            altitude_m,
            json,
        } => {
            let (ac, (), section) = load(&inputs, mass, |_| Ok(()))?;
            let params = TrimParams::default();
            let t = trim_aircraft(&ac, &section, speed_kt, ac.mass_kg, altitude_m, &params)?;
            t.notes().iter().for_each(|n| TOOL.say(n));
            match json {
                true => *buf += &print::json(&t)?,
                false => print::trim(buf, &t),
            }
        }
        Command::Takeoff {
            inputs,
            mass,
            json,
            history,
        } => {
            if let Some(path) = &history {
                check_output_path(path).context("--history")?;
            }
            let (ac, (), section) = load(&inputs, mass, |_| Ok(()))?;
            let t = simulate_takeoff(&ac, &section)?;
            t.notes().iter().for_each(|n| TOOL.say(n));
            // The history is data: when it takes standard output, the summary goes to stderr.
            let mut summary = String::new();
            match json {
                true => summary = print::json(&t)?,
                false => print::takeoff(&mut summary, &t),
            }
            if let Some(path) = &history {
                t.write_history_file(path).context("--history")?;
            }
            match history.as_deref().is_some_and(is_stdout) {
                true => TOOL.say_text(&summary),
                false => buf.push_str(&summary),
            }
        }
        Command::Compare {
            aircraft,
            clean,
            contaminated,
            json,
        } => {
            let mut shipped = ShippedInputs::default();
            let ac = shipped.aircraft(&aircraft)?;
            let c = shipped.table(&clean, paper::SHIPPED_TABLE)?;
            let d = shipped.table(&contaminated, SHIPPED_CONTAMINATED_TABLE)?;
            note_shipped(shipped);
            let runs = paper_runs(&ac, &c, &d)?;
            paper_runs_notes(&runs).iter().for_each(|n| TOOL.say(n));
            if json {
                print::compare_json(buf, &runs)?;
            } else {
                print::compare(buf, &runs);
            }
        }
        Command::Sweep {
            inputs,
            speeds,
            mass,
            json,
        } => {
            let (ac, speeds, section) = load(&inputs, mass, |ac| speeds.checked(ac))?;
            let sweep = SpeedSweep::run(&ac, &section, &speeds, None);
            sweep.notes().into_iter().for_each(|n| TOOL.say(n));
            sweep.require_trims()?;
            match json {
                true => *buf += &print::json(&sweep.trims)?,
                false => print::sweep(buf, &sweep.trims),
            }
        }
        Command::Alpha {
            inputs,
            speed_kt,
            radius,
            samples,
        } => {
            let check = |ac: &Aircraft| Ok(check_blade_radius("--radius", radius, ac)?);
            let (ac, (), section) = load(&inputs, None, check)?;
            let params = TrimParams::default();
            let curve = cruise_blade_alpha(&ac, &section, speed_kt, 0.0, radius, samples, &params)?;
            curve.notes().iter().for_each(|n| TOOL.say(n));
            print::blade_alpha(buf, &curve.points);
        }
        Command::Autorotate(args) => autorotate::run(args, buf, &|n| TOOL.say(n))?,
        Command::Plot { kind } => plot::run(kind)?,
        Command::Completions(args) => {
            let script = cli::completions(Cli::command(), args.shell);
            buf.push_str(&String::from_utf8_lossy(&script));
        }
        Command::Man(args) => {
            let page = cli::man(Cli::command(), &args)?;
            buf.push_str(&String::from_utf8_lossy(&page));
        }
        Command::Study { study } => {
            let mut shipped = ShippedInputs::default();
            let request = study::request(study, &mut shipped)?;
            request.check()?;
            note_shipped(shipped);
            let outcome = request.run(&TOOL.progress())?;
            buf.push_str(&outcome.stdout);
            flush_stdout(buf)?;
            outcome.notes.iter().for_each(|n| TOOL.say(n));
            for p in &outcome.written {
                TOOL.say(format!("wrote {}", p.display()));
            }
        }
        Command::Report(args) => {
            check_report_paths(&args.out).context("--out")?;
            let inputs = ReportInputs {
                aircraft: args.aircraft,
                polars: args.polars,
                out: args.out,
                studies: args.studies.then(|| {
                    args.cache
                        .unwrap_or_else(polargen::studies::default_cache_dir)
                }),
            };
            let outcome = write_report(&inputs, &TOOL.progress())?;
            for path in &outcome.written {
                TOOL.say(format!("wrote {}", path.display()));
            }
            flush_stdout(buf)?;
            outcome.notes.iter().for_each(|n| TOOL.say(n));
        }
    }
    Ok(())
}

/// Writes `buf` to standard output and empties it: the result goes out before the notes and
/// summaries that follow it on stderr (a result that cannot be written is an error).
fn flush_stdout(buf: &mut String) -> Result<()> {
    if !buf.is_empty() {
        write_stdout(buf.as_bytes()).context("cannot write output")?;
        buf.clear();
    }
    Ok(())
}

fn main() -> ExitCode {
    polargen::output::remove_staged_files_on_signals();
    let cli = match TOOL.parse(|c: &Cli| c.quiet) {
        Ok(cli) => cli,
        Err(code) => return code,
    };
    let mut buf = String::new();
    let result = run(cli, &mut buf).and_then(|()| flush_stdout(&mut buf));
    TOOL.finish(result)
}

#[cfg(test)]
mod tests {
    use clap::CommandFactory as _;

    #[test]
    fn cli_reference_is_current() {
        polargen::cli::check_reference(super::Cli::command());
    }
}
