//! `polargen` — airfoil polars from the command line.
//!
//! `polargen --airfoil <NAME|PATH> --inviscid [--mach M] [--alpha A0:A1:DA] [--panels N]
//! [--out FILE]` writes an inviscid polar as CSV (`alpha,cl,cd,cm,converged`).
//!
//! Every error is one line on stderr with a non-zero exit status; no output file is left
//! half-written (files are written to a temporary name and renamed).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{bail, Context, Result};
use clap::Parser;

use polargen::geometry::{airfoil_by_name_or_path, Airfoil, PanelingParams};
use polargen::inviscid::PanelSystem;
use polargen::polar::parse_alpha_range;
use polargen::table::io::write_atomic;
use polargen::table::TableError;

/// Smallest and largest panel-node counts accepted by `--panels`.
const PANEL_RANGE: (usize, usize) = (20, 1000);

/// Airfoil polars with an XFOIL-class panel method.
#[derive(Parser, Debug)]
#[command(name = "polargen", version, about)]
struct Cli {
    /// Airfoil: naca8h12, naca23012, nacaDDDD, nacaDDDDD, or a coordinate file (Selig,
    /// Lednicer or plain x y).
    #[arg(long, value_name = "NAME|PATH")]
    airfoil: String,

    /// Inviscid panel solution only (cd = 0).
    #[arg(long)]
    inviscid: bool,

    /// Freestream Mach number (Karman–Tsien), 0 ≤ M < 1 and below the critical Mach.
    #[arg(long, default_value = "0", allow_hyphen_values = true)]
    mach: String,

    /// Angles of attack in degrees: A0:A1:DA (inclusive) or a single value.
    #[arg(long, default_value = "-10:20:0.5", allow_hyphen_values = true)]
    alpha: String,

    /// Number of panel nodes after curvature-based repaneling (XFOIL PANE).
    #[arg(long, default_value_t = polargen::geometry::DEFAULT_PANEL_NODES)]
    panels: usize,

    /// Output file (CSV); standard output when absent.
    #[arg(long, value_name = "FILE")]
    out: Option<PathBuf>,
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
                let _ = e.print();
                return ExitCode::SUCCESS;
            }
            // One line: clap's message without the usage block.
            let text = e.render().to_string();
            let msg: Vec<&str> = text
                .lines()
                .take_while(|l| !l.starts_with("Usage:"))
                .map(str::trim)
                .filter(|l| !l.is_empty())
                .collect();
            eprintln!("polargen: {}", msg.join(" ").trim_start_matches("error: "));
            return ExitCode::from(2);
        }
    };
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("polargen: error: {}", one_line(&e));
            ExitCode::FAILURE
        }
    }
}

/// An error and its causes on one line, skipping causes whose text the line already holds
/// (many error types print their source in their own message).
fn one_line(e: &anyhow::Error) -> String {
    let mut line = String::new();
    for cause in e.chain() {
        let msg = cause.to_string();
        if line.contains(&msg) {
            continue;
        }
        if !line.is_empty() {
            line.push_str(": ");
        }
        line.push_str(&msg);
    }
    line.replace('\n', " ")
}

/// Parse a number option, naming the flag in the error.
fn parse_number(flag: &str, text: &str) -> Result<f64> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => bail!("--{flag} '{text}' is not a finite number"),
    }
}

fn run(cli: &Cli) -> Result<()> {
    let mach = parse_number("mach", &cli.mach)?;
    if !(0.0..1.0).contains(&mach) {
        bail!("--mach {mach}: the Mach number must be in [0, 1)");
    }
    let alphas = parse_alpha_range(&cli.alpha).context("--alpha")?;
    if !(PANEL_RANGE.0..=PANEL_RANGE.1).contains(&cli.panels) {
        bail!(
            "--panels {}: must be between {} and {}",
            cli.panels,
            PANEL_RANGE.0,
            PANEL_RANGE.1
        );
    }
    if !cli.inviscid {
        bail!("the viscous solver is not available yet: use --inviscid");
    }
    let foil = load_airfoil(&cli.airfoil, cli.panels)?;
    let system = PanelSystem::new(&foil).context("panel system")?;
    let mut csv = String::from("alpha,cl,cd,cm,converged\n");
    for &alpha in &alphas {
        let sol = system
            .solve(alpha, mach)
            .with_context(|| format!("alpha {alpha}"))?;
        csv.push_str(&format!(
            "{alpha},{},0,{},true\n",
            fixed6(sol.cl),
            fixed6(sol.cm)
        ));
    }
    emit(cli.out.as_deref(), &csv)
}

/// `v` with 6 decimals, without the sign of a value that rounds to zero.
fn fixed6(v: f64) -> String {
    let s = format!("{v:.6}");
    if s == "-0.000000" {
        s[1..].to_string()
    } else {
        s
    }
}

/// Load an airfoil by name or path and repanel it to `panels` nodes.
fn load_airfoil(spec: &str, panels: usize) -> Result<Airfoil> {
    let raw = airfoil_by_name_or_path(spec)?;
    let foil = raw
        .repanel(panels, &PanelingParams::default())
        .with_context(|| format!("paneling {}", raw.name))?;
    Ok(foil)
}

/// Write `text` to `out` atomically, or to standard output.
fn emit(out: Option<&Path>, text: &str) -> Result<()> {
    match out {
        Some(path) => {
            write_atomic(path, |w| {
                w.write_all(text.as_bytes())
                    .map_err(|e| TableError::io(path, e))
            })?;
        }
        None => {
            let mut stdout = std::io::stdout().lock();
            stdout.write_all(text.as_bytes())?;
            stdout.flush()?;
        }
    }
    Ok(())
}
