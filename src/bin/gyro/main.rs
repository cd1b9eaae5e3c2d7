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
use polargen::cli::{self, Tool};
use polargen::output::{check_output_path, write_output, OutputError};
use polargen::report::{
    check_report_paths, write_report, ReportInputs, SHIPPED_AIRCRAFT, SHIPPED_POLARS,
};
use polargen::rotor::{
    check_altitude_m, check_azimuth_samples, check_blade_radius, check_mass_kg, check_speed_kt,
    checked_sweep_speeds, cruise_blade_alpha, simulate_takeoff, trim_aircraft, Aircraft,
    TrimParams, MAX_ISA_ALTITUDE_M,
};
use polargen::studies::paper::{paper_runs, SpeedSweep};
use polargen::table::read_lookup_table;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// This tool's name and error prefix.
static TOOL: Tool = Tool::new("gyro");

/// Appends one formatted line to an output `String` (writing to a `String` cannot fail).
macro_rules! outln {
    ($buf:expr) => {
        $buf.push('\n')
    };
    ($buf:expr, $($arg:tt)*) => {{
        use std::fmt::Write as _;
        let _ = writeln!($buf, $($arg)*);
    }};
}

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
        #[arg(long, default_value_t = 60.0, allow_hyphen_values = true)]
        speed_kt: f64,
        /// Mass in kg (default: the preset's).
        #[arg(long, allow_hyphen_values = true)]
        mass: Option<f64>,
        #[arg(long, default_value_t = 0.0, allow_hyphen_values = true,
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
        #[arg(long, allow_hyphen_values = true)]
        mass: Option<f64>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        /// Write the time history (t, x, h, v, rotor_rpm, alpha_r_deg, beta_deg) to this CSV.
        #[arg(long)]
        history: Option<PathBuf>,
    },
    /// Clean versus contaminated rotor: paper Tables 3 and 4 side by side with ours.
    Compare {
        /// Aircraft preset (TOML).
        #[arg(long)]
        aircraft: PathBuf,
        /// Table of the clean blade section (any format --table reads).
        #[arg(long)]
        clean: PathBuf,
        /// Table of the contaminated blade section (any format --table reads).
        #[arg(long)]
        contaminated: PathBuf,
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
        #[arg(long, allow_hyphen_values = true)]
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
        #[arg(long, default_value_t = 60.0, allow_hyphen_values = true)]
        speed_kt: f64,
        /// Radius as a fraction of R.
        #[arg(long, default_value_t = 0.9, allow_hyphen_values = true)]
        radius: f64,
        /// Azimuth samples per revolution.
        #[arg(long, default_value_t = 36, allow_hyphen_values = true)]
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
    /// Man page (roff) on standard output (`gyro man > gyro.1; man ./gyro.1`).
    Man,
    /// What-if studies beyond the paper (section tables solved and cached).
    Study {
        #[command(subcommand)]
        study: study::Study,
    },
}

/// The aircraft and the blade section of a single-section command.
#[derive(Args)]
struct Inputs {
    /// Aircraft preset (TOML).
    #[arg(long)]
    aircraft: PathBuf,
    /// Section polar table: polargen CSV or JSON, XFOIL .pol, C81, or a CSV of one polar with
    /// columns alpha, cl, cd[, cm].
    #[arg(long)]
    table: PathBuf,
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

fn load_aircraft(path: &Path, mass: Option<f64>) -> Result<Aircraft> {
    let mut ac = Aircraft::from_toml_file(path)?;
    if let Some(m) = mass {
        check_mass_kg("--mass", m)?;
        ac.mass_kg = m;
    }
    Ok(ac)
}

/// An airspeed flag ([`check_speed_kt`]).
fn check_speed(flag: &str, kt: f64) -> Result<()> {
    Ok(check_speed_kt(&format!("--{flag}"), kt)?)
}

/// The notes of a speed sweep on stderr, then an error if no speed trimmed.
fn report_sweep(sweep: &SpeedSweep) -> Result<()> {
    for note in sweep.notes() {
        TOOL.say(note);
    }
    Ok(sweep.require_trims()?)
}

/// Airspeed range of a speed sweep (`gyro sweep`, `gyro plot power`).
#[derive(Args, Debug, Clone, Copy)]
pub struct SpeedRange {
    /// Lowest airspeed in knots.
    #[arg(long, default_value_t = 30.0, allow_hyphen_values = true)]
    pub from_kt: f64,
    /// Highest airspeed in knots.
    #[arg(long, default_value_t = 90.0, allow_hyphen_values = true)]
    pub to_kt: f64,
    /// Speed step in knots.
    #[arg(long, default_value_t = 5.0, allow_hyphen_values = true)]
    pub step_kt: f64,
}

impl SpeedRange {
    /// The speeds of the sweep \[kt\] for `aircraft`, checked ([`checked_sweep_speeds`]).
    fn checked(&self, aircraft: &Aircraft) -> Result<Vec<f64>> {
        let cells = aircraft.rotor.cells();
        Ok(checked_sweep_speeds(
            self.from_kt,
            self.to_kt,
            self.step_kt,
            cells,
        )?)
    }
}

/// Runs one command, appending its standard output to `buf`.
fn run(cli: Cli, buf: &mut String) -> Result<()> {
    match cli.command {
        Command::Trim {
            inputs: Inputs { aircraft, table },
            speed_kt,
            mass,
            altitude_m,
            json,
        } => {
            check_speed("speed-kt", speed_kt)?;
            check_altitude_m("--altitude-m", altitude_m)?;
            let ac = load_aircraft(&aircraft, mass)?;
            let section = read_lookup_table(&table)?;
            let t = trim_aircraft(
                &ac,
                &section,
                speed_kt,
                ac.mass_kg,
                altitude_m,
                &TrimParams::default(),
            )?;
            t.notes().iter().for_each(|n| TOOL.say(n));
            if json {
                outln!(buf, "{}", serde_json::to_string_pretty(&t)?);
            } else {
                print::trim(buf, &t);
            }
        }
        Command::Takeoff {
            inputs: Inputs { aircraft, table },
            mass,
            json,
            history,
        } => {
            if let Some(path) = &history {
                check_output_path(path).context("--history")?;
            }
            let ac = load_aircraft(&aircraft, mass)?;
            let section = read_lookup_table(&table)?;
            let t = simulate_takeoff(&ac, &section)?;
            if let Some(path) = history {
                write_output(&path, |w| {
                    t.write_history_csv(w)
                        .map_err(|e| OutputError::io(&path, e.into()))
                })
                .context("--history")?;
            }
            if json {
                outln!(buf, "{}", serde_json::to_string_pretty(&t)?);
            } else {
                print::takeoff(buf, &t);
            }
        }
        Command::Compare {
            aircraft,
            clean,
            contaminated,
            json,
        } => {
            let ac = load_aircraft(&aircraft, None)?;
            let c = read_lookup_table(&clean)?;
            let d = read_lookup_table(&contaminated)?;
            let runs = paper_runs(&ac, &c, &d)?;
            if json {
                print::compare_json(buf, &runs)?;
            } else {
                print::compare(buf, &runs);
            }
        }
        Command::Sweep {
            inputs: Inputs { aircraft, table },
            speeds,
            mass,
            json,
        } => {
            let ac = load_aircraft(&aircraft, mass)?;
            let speeds = speeds.checked(&ac)?;
            let section = read_lookup_table(&table)?;
            let sweep = SpeedSweep::run(&ac, &section, &speeds, None);
            report_sweep(&sweep)?;
            if json {
                outln!(buf, "{}", serde_json::to_string_pretty(&sweep.trims)?);
            } else {
                print::sweep(buf, &sweep.trims);
            }
        }
        Command::Alpha {
            inputs: Inputs { aircraft, table },
            speed_kt,
            radius,
            samples,
        } => {
            check_speed("speed-kt", speed_kt)?;
            check_azimuth_samples("--samples", samples)?;
            let ac = load_aircraft(&aircraft, None)?;
            check_blade_radius("--radius", radius, &ac)?;
            let section = read_lookup_table(&table)?;
            let curve = cruise_blade_alpha(
                &ac,
                &section,
                speed_kt,
                0.0,
                radius,
                samples,
                &TrimParams::default(),
            )?;
            outln!(buf, "psi_deg,alpha_deg");
            for (psi, a) in curve {
                outln!(buf, "{psi:.1},{a:.3}");
            }
        }
        Command::Autorotate(args) => autorotate::run(args, buf, |n| TOOL.say(n))?,
        Command::Plot { kind } => plot::run(kind)?,
        Command::Completions(args) => {
            let script = cli::completions(Cli::command(), args.shell);
            buf.push_str(&String::from_utf8_lossy(&script));
        }
        Command::Man => buf.push_str(&String::from_utf8_lossy(&cli::man_page(Cli::command())?)),
        Command::Study { study } => {
            let outcome = study::request(study).run(&polargen::studies::Progress::on_terminal())?;
            outcome.notes.iter().for_each(|n| TOOL.say(n));
            for p in &outcome.written {
                TOOL.say(format!("wrote {}", p.display()));
            }
            buf.push_str(&outcome.stdout);
        }
        Command::Report(args) => {
            check_report_paths(&args.out).context("--out")?;
            let outcome = write_report(&ReportInputs {
                aircraft: args.aircraft,
                polars: args.polars,
                out: args.out,
                studies: args.studies.then(|| {
                    args.cache
                        .unwrap_or_else(polargen::studies::default_cache_dir)
                }),
            })?;
            for note in &outcome.notes {
                TOOL.say(note);
            }
            for path in &outcome.written {
                TOOL.say(format!("wrote {}", path.display()));
            }
        }
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
    let result = run(cli, &mut buf).and_then(|()| {
        let stdout = Path::new("-");
        write_output(stdout, |w| {
            w.write_all(buf.as_bytes())
                .map_err(|e| OutputError::io(stdout, e))
        })
        .context("cannot write output")
    });
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
