//! `polargen` — airfoil polars and Re × Mach × α tables from the command line.
//!
//! * `polargen --airfoil naca8h12 --xtr 0.07` — the default rotor grid (Re 0.25…2.5·10⁶ ×
//!   M 0…0.5 × α −10…20°) as a long-form CSV table;
//! * `--re`, `--mach` (comma lists) and `--alpha A0:A1:DA` override each axis; one value each
//!   gives a single polar;
//! * `--inviscid` — the panel solution only (`alpha,cl,cd,cm,converged`).
//!
//! Every error is one line on stderr with a non-zero exit status; no output file is left
//! half-written (files are written to a temporary name and renamed).

use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Instant;

use anyhow::{bail, Context, Result};
use clap::{Args, Parser, Subcommand};

use polargen::diagnostics::error_line;
use polargen::geometry::{airfoil_by_name_or_path, Airfoil, PanelingParams};
use polargen::inviscid::PanelSystem;
use polargen::output::{check_output_path, write_output, OutputError};
use polargen::plot::point_plots::{point_figure, PointCase};
use polargen::plot::polar_plots::polar_figure;
use polargen::plot::{check_image_path, render, Style};
use polargen::polar::{
    parse_alpha_range, run_grid, solve_at_cl, SweepParams, TargetClParams, ViscousSweep,
};
use polargen::section::PolarPoint;
use polargen::table::io::csv::write_csv_to;
use polargen::table::io::json::write_json_to;
use polargen::table::io::{read_table, write_table, TableFormat};
use polargen::table::{PolarTable, TableError, TableMeta};
use polargen::viscous::forces::karman_tsien_cp;
use polargen::viscous::{BlStation, SharedPanels, ViscousParams, ViscousSolution, ViscousSolver};

/// Smallest and largest panel-node counts accepted by `--panels`.
const PANEL_RANGE: (usize, usize) = (20, 1000);

/// Reynolds numbers of the default rotor grid.
const DEFAULT_RE: [f64; 6] = [0.25e6, 0.5e6, 1.0e6, 1.5e6, 2.0e6, 2.5e6];
/// Mach numbers of the default rotor grid.
const DEFAULT_MACH: [f64; 5] = [0.0, 0.2, 0.3, 0.4, 0.5];
/// α range of the default rotor grid.
const DEFAULT_ALPHA: &str = "-10:20:0.5";

/// Airfoil polars and Re × Mach × α tables with an XFOIL-class viscous–inviscid solver.
#[derive(Parser, Debug)]
#[command(
    name = "polargen",
    version,
    about,
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,

    #[command(flatten)]
    run: RunArgs,
}

/// Subcommands besides the main job (computing polars and tables).
#[derive(Subcommand, Debug)]
enum Command {
    /// Overlay polars from tables (CSV or JSON): Cl–α, Cd–Cl, Cl/Cd–α, Cm–α; SVG or PNG by
    /// the extension of --out.
    Plot(PlotArgs),
    /// Convert a table (CSV, JSON or XFOIL polar) to another format: csv, json, xfoil or c81.
    Convert(ConvertArgs),
    /// Cp(x) and boundary-layer distributions (H, Cf, N) at one α or Cl, one case per
    /// transition setting overlaid (e.g. --xtr 1,0.07: clean vs tripped).
    PlotPoint(PlotPointArgs),
}

/// `polargen plot-point` options.
#[derive(Args, Debug)]
struct PlotPointArgs {
    /// Airfoil: a name (naca8h12, nacaDDDD, nacaDDDDD) or a coordinate file.
    #[arg(long, value_name = "NAME|PATH")]
    airfoil: String,

    /// Chord Reynolds number.
    #[arg(long, allow_hyphen_values = true)]
    re: f64,

    /// Mach number, 0 ≤ M < 1.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    mach: f64,

    /// Angle of attack in degrees.
    #[arg(
        long,
        allow_hyphen_values = true,
        required_unless_present = "cl",
        conflicts_with = "cl"
    )]
    alpha: Option<f64>,

    /// Lift coefficient instead of α: each case is solved at the α giving this Cl.
    #[arg(long, allow_hyphen_values = true)]
    cl: Option<f64>,

    /// Transition settings to overlay, comma-separated x/c on both surfaces (1 = free).
    #[arg(
        long,
        value_name = "LIST",
        default_value = "1",
        allow_hyphen_values = true
    )]
    xtr: String,

    /// Critical amplification ratio N of the e^n criterion.
    #[arg(long, default_value_t = 9.0, allow_hyphen_values = true)]
    ncrit: f64,

    /// Number of panel nodes.
    #[arg(long, default_value_t = polargen::geometry::DEFAULT_PANEL_NODES, allow_hyphen_values = true)]
    panels: usize,

    /// Newton convergence threshold on the RMS relative change of the boundary-layer
    /// variables (XFOIL uses 1e-4).
    #[arg(long, default_value_t = ViscousParams::default().tolerance, allow_hyphen_values = true)]
    tolerance: f64,

    /// Output image: FILE.svg or FILE.png.
    #[arg(long, value_name = "FILE")]
    out: PathBuf,

    /// Also write the distributions as CSV (one row per station, surfaces and wake).
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,

    /// Figure title (default: airfoil, Re, M, α or Cl).
    #[arg(long)]
    title: Option<String>,
}

/// `polargen convert` options.
#[derive(Args, Debug)]
struct ConvertArgs {
    /// Table written by polargen (.csv, .json) or an XFOIL polar file (.pol).
    #[arg(value_name = "TABLE")]
    table: PathBuf,

    /// Output file; the format follows its extension unless --format is given (xfoil and
    /// c81 may write one file per (Re, M) or per Re, named after it).
    #[arg(long, value_name = "FILE")]
    out: PathBuf,

    /// Output format: csv, json, xfoil or c81.
    #[arg(long)]
    format: Option<String>,
}

/// `polargen plot` options.
#[derive(Args, Debug)]
struct PlotArgs {
    /// Tables written by polargen (.csv or .json).
    #[arg(required = true, value_name = "TABLE")]
    tables: Vec<PathBuf>,

    /// Output image: FILE.svg or FILE.png.
    #[arg(long, value_name = "FILE")]
    out: PathBuf,

    /// Reynolds number of the polar to draw from a grid table (nearest node).
    #[arg(long, allow_hyphen_values = true)]
    re: Option<f64>,

    /// Mach number of the polar to draw from a grid table (nearest node).
    #[arg(long, allow_hyphen_values = true)]
    mach: Option<f64>,

    /// Figure title (default: airfoils and the Re, M drawn).
    #[arg(long)]
    title: Option<String>,
}

/// Options of the main job: polars and tables.
#[derive(Args, Debug)]
struct RunArgs {
    /// Airfoil: naca8h12, naca23012, nacaDDDD, nacaDDDDD, or a coordinate file (Selig,
    /// Lednicer or plain x y).
    #[arg(long, value_name = "NAME|PATH", required = true)]
    airfoil: Option<String>,

    /// Inviscid panel solution only (cd = 0); output `alpha,cl,cd,cm,converged`.
    #[arg(long)]
    inviscid: bool,

    /// Chord Reynolds numbers, comma-separated (default: the rotor grid 0.25e6,…,2.5e6).
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    re: Option<String>,

    /// Mach numbers, comma-separated, 0 ≤ M < 1 (default: 0,0.2,0.3,0.4,0.5; inviscid: 0).
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    mach: Option<String>,

    /// Angles of attack in degrees: A0:A1:DA (inclusive) or one value (default −10:20:0.5).
    #[arg(long, allow_hyphen_values = true)]
    alpha: Option<String>,

    /// Forced transition x/c on both surfaces (1 = free transition, e^n).
    #[arg(long, value_name = "X", allow_hyphen_values = true, conflicts_with_all = ["xtr_top", "xtr_bot"])]
    xtr: Option<f64>,

    /// Forced transition x/c on the upper surface (1 = free).
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    xtr_top: Option<f64>,

    /// Forced transition x/c on the lower surface (1 = free).
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    xtr_bot: Option<f64>,

    /// Critical amplification ratio N of the e^n transition criterion.
    #[arg(long, default_value_t = 9.0, allow_hyphen_values = true)]
    ncrit: f64,

    /// Number of panel nodes after curvature-based repaneling (XFOIL PANE).
    #[arg(long, default_value_t = polargen::geometry::DEFAULT_PANEL_NODES, allow_hyphen_values = true)]
    panels: usize,

    /// Newton convergence threshold on the RMS relative change of the boundary-layer
    /// variables (XFOIL uses 1e-4).
    #[arg(long, default_value_t = ViscousParams::default().tolerance, allow_hyphen_values = true)]
    tolerance: f64,

    /// Worker threads (0 = all cores); a polar's two α branches run in parallel, so more
    /// than two threads per polar are not started.
    #[arg(long, default_value_t = 0, allow_hyphen_values = true)]
    threads: usize,

    /// Output format: csv, json, xfoil (one .pol per Re, M) or c81 (one file per Re);
    /// default: from --out's extension, else csv.
    #[arg(long)]
    format: Option<String>,

    /// Output file; standard output when absent (csv and json only).
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
    let result = match &cli.command {
        Some(Command::Plot(args)) => plot_tables(args),
        Some(Command::Convert(args)) => convert_table(args),
        Some(Command::PlotPoint(args)) => plot_point(args),
        None if cli.run.inviscid => run_inviscid(&cli.run),
        None => run_viscous(&cli.run),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("polargen: error: {}", error_line(e.as_ref()));
            ExitCode::FAILURE
        }
    }
}

/// Parse a comma-separated list of distinct finite numbers, naming the flag in the error.
fn parse_list(flag: &str, text: &str) -> Result<Vec<f64>> {
    let mut out: Vec<f64> = Vec::new();
    for item in text.split(',').map(str::trim) {
        match item.parse::<f64>() {
            Ok(v) if v.is_finite() => {
                if out.contains(&v) {
                    bail!("--{flag} '{text}': '{item}' is given twice");
                }
                out.push(v)
            }
            _ => bail!("--{flag} '{text}': '{item}' is not a finite number"),
        }
    }
    Ok(out)
}

/// Check `--out` before any computation: a file name (not a folder), below a folder.
fn check_out(path: &std::path::Path) -> Result<()> {
    check_output_path(path).context("--out")?;
    Ok(())
}

/// Mach numbers from `--mach` (or `default`), each checked to lie in [0, 1).
fn mach_list(cli: &RunArgs, default: &[f64]) -> Result<Vec<f64>> {
    let list = match &cli.mach {
        Some(t) => parse_list("mach", t)?,
        None => default.to_vec(),
    };
    if let Some(m) = list.iter().find(|m| !(0.0..1.0).contains(*m)) {
        bail!("--mach {m}: the Mach number must be in [0, 1)");
    }
    Ok(list)
}

/// Check the panel count and load + repanel the airfoil.
fn load_airfoil(spec: Option<&str>, panels: usize) -> Result<Airfoil> {
    if !(PANEL_RANGE.0..=PANEL_RANGE.1).contains(&panels) {
        bail!(
            "--panels {panels}: must be between {} and {}",
            PANEL_RANGE.0,
            PANEL_RANGE.1
        );
    }
    let spec = spec.context("--airfoil is required")?;
    let given = airfoil_by_name_or_path(spec).context("--airfoil")?;
    let (raw, normalised) = given
        .in_chord_units()
        .with_context(|| format!("locating the chord of {}", given.name))?;
    if normalised {
        eprintln!(
            "polargen: note: {spec}: chord is not 1 or the leading edge is not at the origin; \
             coordinates normalised to unit chord (LE at 0,0, TE at 1,0)"
        );
    }
    let foil = raw
        .repanel(panels, &PanelingParams::default())
        .with_context(|| format!("paneling {}", raw.name))?;
    Ok(foil)
}

/// `--inviscid`: the panel solution at one Mach number.
fn run_inviscid(cli: &RunArgs) -> Result<()> {
    let mach = match mach_list(cli, &[0.0])?.as_slice() {
        [m] => *m,
        _ => bail!("--mach: --inviscid takes one Mach number"),
    };
    let alphas =
        parse_alpha_range(cli.alpha.as_deref().unwrap_or(DEFAULT_ALPHA)).context("--alpha")?;
    if let Some(path) = &cli.out {
        check_out(path)?;
    }
    let foil = load_airfoil(cli.airfoil.as_deref(), cli.panels)?;
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
    match &cli.out {
        Some(path) => write_output(path, |w| {
            w.write_all(csv.as_bytes())
                .map_err(|e| OutputError::io(path, e))
        })?,
        None => write_stdout(csv.as_bytes())?,
    }
    Ok(())
}

/// The viscous polar(s) or table.
fn run_viscous(cli: &RunArgs) -> Result<()> {
    let re = match &cli.re {
        Some(t) => parse_list("re", t)?,
        None => DEFAULT_RE.to_vec(),
    };
    if let Some(r) = re.iter().find(|r| **r <= 0.0) {
        bail!("--re {r}: the Reynolds number must be positive");
    }
    let mach = mach_list(cli, &DEFAULT_MACH)?;
    let alphas =
        parse_alpha_range(cli.alpha.as_deref().unwrap_or(DEFAULT_ALPHA)).context("--alpha")?;
    let (xtr_top, xtr_bot) = match cli.xtr {
        Some(x) => (x, x),
        None => (cli.xtr_top.unwrap_or(1.0), cli.xtr_bot.unwrap_or(1.0)),
    };
    let flags = match cli.xtr {
        Some(_) => ["xtr", "xtr"],
        None => ["xtr-top", "xtr-bot"],
    };
    for (flag, x) in flags.into_iter().zip([xtr_top, xtr_bot]) {
        if !(0.0..=1.0).contains(&x) {
            bail!("--{flag} {x}: the transition location must be in [0, 1] (1 = free)");
        }
    }
    if !(cli.ncrit.is_finite() && cli.ncrit > 0.0) {
        bail!("--ncrit {}: must be a positive number", cli.ncrit);
    }
    check_tolerance(cli.tolerance)?;
    if let Some(path) = &cli.out {
        check_out(path)?;
    }
    let format = match (&cli.format, &cli.out) {
        (Some(f), _) => f.parse::<TableFormat>().context("--format")?,
        (None, Some(path)) => TableFormat::from_path(path).context("--out")?,
        (None, None) => TableFormat::Csv,
    };
    if cli.out.is_none() && matches!(format, TableFormat::XfoilPolar | TableFormat::C81) {
        bail!("--format {}: needs --out (it writes files)", format.name());
    }
    let foil = load_airfoil(cli.airfoil.as_deref(), cli.panels)?;

    let nodes: Vec<(f64, f64)> = re
        .iter()
        .flat_map(|&r| mach.iter().map(move |&m| (r, m)))
        .collect();
    let total = nodes.len() * alphas.len();
    let bar = progress_bar(total as u64);
    let start = Instant::now();
    let base = ViscousParams {
        ncrit: cli.ncrit,
        tolerance: cli.tolerance,
        xtr_top,
        xtr_bot,
        ..ViscousParams::default()
    };
    // One panel store for the whole grid: the per-α inviscid model does not depend on Re or M.
    let panels = Arc::new(SharedPanels::new(&foil).context("viscous solver")?);
    let polars = run_grid(
        &nodes,
        &alphas,
        cli.threads,
        &SweepParams::default(),
        |reynolds, mach| {
            ViscousSweep::with_panels(
                Arc::clone(&panels),
                ViscousParams {
                    reynolds,
                    mach,
                    ..base
                },
            )
        },
        |p| {
            if let Some(b) = &bar {
                b.inc(p.points.len() as u64);
            }
        },
    )
    .context("viscous solver")?;
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let converged: usize = polars
        .iter()
        .map(|p| p.points.iter().filter(|q| q.converged).count())
        .sum();
    eprintln!(
        "polargen: {converged} of {total} points converged ({:.1} %) in {:.1} s",
        100.0 * converged as f64 / total.max(1) as f64,
        start.elapsed().as_secs_f64()
    );
    if converged == 0 {
        bail!("no point converged; no table written");
    }

    let meta = TableMeta {
        airfoil: foil.name.clone(),
        ncrit: cli.ncrit,
        xtr_top_set: xtr_top,
        xtr_bot_set: xtr_bot,
        panels: cli.panels,
        solver: format!("polargen {}", env!("CARGO_PKG_VERSION")),
    };
    let table = PolarTable::from_polars(
        meta,
        polars
            .into_iter()
            .map(|p| (p.re, p.mach, p.points))
            .collect(),
    )
    .context("building the table")?;
    match &cli.out {
        Some(path) => {
            let files = write_table(&table, path, Some(format))?;
            if files.len() > 1 {
                eprintln!("polargen: wrote {} files", files.len());
            }
        }
        None => {
            let mut buf = Vec::new();
            match format {
                TableFormat::Json => write_json_to(&table, &mut buf)?,
                _ => write_csv_to(&table, &mut buf)?,
            }
            write_stdout(&buf)?;
        }
    }
    Ok(())
}

/// The `--tolerance` flag: a Newton threshold in (0, 1).
fn check_tolerance(tolerance: f64) -> Result<()> {
    if !(tolerance > 0.0 && tolerance < 1.0) {
        bail!("--tolerance {tolerance}: must be a number in (0, 1)");
    }
    Ok(())
}

/// `polargen plot`: overlay one polar from each table.
fn plot_tables(args: &PlotArgs) -> Result<()> {
    check_image_path(&args.out).context("--out")?;
    let mut curves: Vec<(String, Vec<PolarPoint>)> = Vec::new();
    let mut conditions: Vec<(f64, f64)> = Vec::new();
    for path in &args.tables {
        let table = read_table_file(path)?;
        let grid = table.re().len() * table.mach().len() > 1;
        if grid && (args.re.is_none() || args.mach.is_none()) {
            bail!(
                "{}: a grid table ({} Re x {} M): give --re and --mach",
                path.display(),
                table.re().len(),
                table.mach().len()
            );
        }
        let re = args.re.unwrap_or(table.re()[0]);
        let mach = args.mach.unwrap_or(table.mach()[0]);
        check_inside("re", re, table.re(), path)?;
        check_inside("mach", mach, table.mach(), path)?;
        let (r, m, points) = table.nearest_polar(re, mach);
        if !points.iter().any(|p| p.converged) {
            bail!(
                "{}: the polar at Re {}, M {m} has no converged point to draw",
                path.display(),
                sci(r)
            );
        }
        let meta = table.meta();
        let trip = transition_label(meta.xtr_top_set, meta.xtr_bot_set);
        curves.push((format!("{} {trip}", meta.airfoil), points.to_vec()));
        conditions.push((r, m));
    }
    let title = match &args.title {
        Some(t) => t.clone(),
        None => {
            let names: Vec<&str> = curves.iter().map(|c| c.0.as_str()).collect();
            let (r, m) = conditions[0];
            let same = conditions.iter().all(|c| *c == (r, m));
            let at = if same {
                format!("Re {}, M {m}", sci(r))
            } else {
                "several Re, M".to_string()
            };
            let nearest = match (args.re, args.mach) {
                (Some(rq), Some(mq)) if same && (rq != r || mq != m) => {
                    format!(" (nearest to Re {}, M {mq})", sci(rq))
                }
                _ => String::new(),
            };
            format!("{} — {at}{nearest}", names.join(" vs "))
        }
    };
    let refs: Vec<(&str, &[PolarPoint])> = curves
        .iter()
        .map(|(l, p)| (l.as_str(), p.as_slice()))
        .collect();
    render(&polar_figure(&refs, &title), &args.out)?;
    Ok(())
}

/// `polargen convert`: read a table and write it in another format.
fn convert_table(args: &ConvertArgs) -> Result<()> {
    check_out(&args.out)?;
    let format = match &args.format {
        Some(f) => f.parse::<TableFormat>().context("--format")?,
        None => TableFormat::from_path(&args.out).context("--out")?,
    };
    let table = read_table_file(&args.table)?;
    let files = write_table(&table, &args.out, Some(format))?;
    if files.len() > 1 {
        eprintln!("polargen: wrote {} files", files.len());
    }
    Ok(())
}

/// One solved case of `plot-point`: its label, transition setting and solution.
struct PointRun {
    label: String,
    solution: ViscousSolution,
}

/// `polargen plot-point`: solve each transition setting at the α (or Cl) asked for and draw
/// Cp and the boundary-layer distributions of both surfaces.
fn plot_point(args: &PlotPointArgs) -> Result<()> {
    if !(args.re.is_finite() && args.re > 0.0) {
        bail!("--re {}: the Reynolds number must be positive", args.re);
    }
    if !(0.0..1.0).contains(&args.mach) {
        bail!("--mach {}: the Mach number must be in [0, 1)", args.mach);
    }
    if !(args.ncrit.is_finite() && args.ncrit > 0.0) {
        bail!("--ncrit {}: must be a positive number", args.ncrit);
    }
    check_tolerance(args.tolerance)?;
    let xtrs = parse_list("xtr", &args.xtr)?;
    if let Some(x) = xtrs.iter().find(|x| !(0.0..=1.0).contains(*x)) {
        bail!("--xtr {x}: the transition location must be in [0, 1] (1 = free)");
    }
    check_image_path(&args.out).context("--out")?;
    if let Some(path) = &args.csv {
        check_output_path(path).context("--csv")?;
    }
    let foil = load_airfoil(Some(&args.airfoil), args.panels)?;
    let mut runs = Vec::new();
    for &xtr in &xtrs {
        let params = ViscousParams {
            ncrit: args.ncrit,
            tolerance: args.tolerance,
            ..ViscousParams::at(args.re, args.mach, xtr)
        };
        let mut solver = ViscousSolver::new(&foil, params).context("viscous solver")?;
        let label = transition_label(xtr, xtr);
        let solution = match (args.alpha, args.cl) {
            (_, Some(cl)) => solve_at_cl(&mut solver, cl, &TargetClParams::default())
                .with_context(|| label.clone())?,
            (Some(alpha), None) => {
                if !alpha.is_finite() {
                    bail!("--alpha {alpha}: not a finite angle");
                }
                let sol = solver.solve(alpha);
                if !sol.point.converged {
                    bail!("{label}: the viscous solution did not converge at alpha {alpha} deg");
                }
                sol
            }
            (None, None) => bail!("give --alpha or --cl"),
        };
        runs.push(PointRun { label, solution });
    }

    let distributions: Vec<SurfaceCurves> = runs
        .iter()
        .flat_map(|r| {
            [
                SurfaceCurves::new(&r.solution.upper, args.mach),
                SurfaceCurves::new(&r.solution.lower, args.mach),
            ]
        })
        .collect();
    let labels: Vec<String> = runs
        .iter()
        .flat_map(|r| [format!("{} upper", r.label), format!("{} lower", r.label)])
        .collect();
    let cases: Vec<PointCase> = distributions
        .iter()
        .zip(&labels)
        .enumerate()
        .map(|(k, (d, label))| {
            let (run, upper) = (&runs[k / 2], k % 2 == 0);
            let style = if upper {
                Style::solid(k / 2)
            } else {
                Style::dashed(k / 2)
            };
            let xtr = if upper {
                run.solution.point.xtr_top
            } else {
                run.solution.point.xtr_bot
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
    let title = match &args.title {
        Some(t) => t.clone(),
        None => {
            let at = match args.cl {
                Some(cl) => {
                    let alphas: Vec<String> = runs
                        .iter()
                        .map(|r| format!("{:.2}° {}", r.solution.point.alpha, r.label))
                        .collect();
                    format!("Cl {cl} (α {})", alphas.join(", "))
                }
                None => format!("α {}°", args.alpha.unwrap_or(0.0)),
            };
            format!("{} — Re {}, M {}, {at}", foil.name, sci(args.re), args.mach)
        }
    };
    // The image first: if it cannot be written, no CSV is left behind either.
    render(&point_figure(&cases, &title, Some(args.ncrit)), &args.out)?;
    if let Some(path) = &args.csv {
        write_output(path, |w| write_point_csv(&runs, args.mach, w))?;
    }
    Ok(())
}

/// Plot-ready distributions of one surface: x/c, Cp (Karman–Tsien), H, Cf (free-stream
/// based, as XFOIL plots it) and N on the laminar part (NaN where turbulent).
struct SurfaceCurves {
    x: Vec<f64>,
    cp: Vec<f64>,
    h: Vec<f64>,
    cf: Vec<f64>,
    n: Vec<f64>,
}

impl SurfaceCurves {
    fn new(stations: &[BlStation], mach: f64) -> Self {
        Self {
            x: stations.iter().map(|s| s.x).collect(),
            cp: stations
                .iter()
                .map(|s| karman_tsien_cp(1.0 - s.ue * s.ue, mach))
                .collect(),
            h: stations.iter().map(|s| s.h).collect(),
            cf: stations.iter().map(|s| s.cf_inf).collect(),
            n: stations
                .iter()
                .map(|s| if s.turbulent { f64::NAN } else { s.n_or_ctau })
                .collect(),
        }
    }
}

/// The distributions of every case as CSV: one row per station of the upper and lower
/// surface (stagnation point → TE) and the wake.
fn write_point_csv(
    runs: &[PointRun],
    mach: f64,
    w: &mut dyn Write,
) -> std::result::Result<(), TableError> {
    let io = |e| TableError::io("<plot-point csv>", e);
    writeln!(
        w,
        "case,alpha,surface,s,x,y,ue,cp,dstar,theta,cf,h,hk,n_or_ctau,turbulent"
    )
    .map_err(io)?;
    for r in runs {
        let sol = &r.solution;
        for (surface, stations) in [
            ("upper", &sol.upper),
            ("lower", &sol.lower),
            ("wake", &sol.wake),
        ] {
            for s in stations.iter() {
                writeln!(
                    w,
                    "{},{},{surface},{},{},{},{},{},{},{},{},{},{},{},{}",
                    r.label,
                    sol.point.alpha,
                    s.s,
                    s.x,
                    s.y,
                    s.ue,
                    karman_tsien_cp(1.0 - s.ue * s.ue, mach),
                    s.dstar,
                    s.theta,
                    s.cf_inf,
                    s.h,
                    s.hk,
                    s.n_or_ctau,
                    s.turbulent
                )
                .map_err(io)?;
            }
        }
    }
    Ok(())
}

/// Legend text of a transition setting: `free`, `xtr 0.07`, or `xtr 0.05/0.1` (upper/lower).
fn transition_label(xtr_top: f64, xtr_bot: f64) -> String {
    if xtr_top >= 1.0 && xtr_bot >= 1.0 {
        "free".to_string()
    } else if xtr_top == xtr_bot {
        format!("xtr {xtr_top}")
    } else {
        format!("xtr {xtr_top}/{xtr_bot}")
    }
}

/// Read a table file; the error names the file when the reader's message does not.
fn read_table_file(path: &std::path::Path) -> Result<PolarTable> {
    read_table(path).map_err(|e| {
        let msg = e.to_string();
        let name = path.display().to_string();
        if msg.contains(&name) {
            anyhow::Error::new(e)
        } else {
            anyhow::anyhow!("{name}: {msg}")
        }
    })
}

/// Error when `value` lies outside a table axis (beyond 0.1 % of the span).
fn check_inside(flag: &str, value: f64, axis: &[f64], path: &std::path::Path) -> Result<()> {
    let (lo, hi) = (axis[0], axis[axis.len() - 1]);
    let slack = 1e-3 * (hi - lo).abs().max(hi.abs() * 1e-3);
    if !value.is_finite() || value < lo - slack || value > hi + slack {
        bail!(
            "--{flag} {value}: outside the table {} ({lo} … {hi})",
            path.display()
        );
    }
    Ok(())
}

/// Compact number for titles: 1.9e6 → "1.9e6", 0 → "0".
fn sci(v: f64) -> String {
    if v >= 1e4 {
        let e = v.log10().floor() as i32;
        let m = v / 10f64.powi(e);
        format!("{}e{e}", (m * 1000.0).round() / 1000.0)
    } else {
        format!("{v}")
    }
}

/// A progress bar on stderr when stderr is a terminal; nothing otherwise.
fn progress_bar(total: u64) -> Option<indicatif::ProgressBar> {
    if !std::io::stderr().is_terminal() {
        return None;
    }
    let bar = indicatif::ProgressBar::new(total);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} points, eta {eta}")
    {
        bar.set_style(style);
    }
    Some(bar)
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

/// Write bytes to standard output.
fn write_stdout(bytes: &[u8]) -> Result<()> {
    let mut stdout = std::io::stdout().lock();
    stdout.write_all(bytes)?;
    stdout.flush()?;
    Ok(())
}
