//! `polargen` — airfoil polars and Re × Mach × α tables from the command line.
//!
//! * `polargen --airfoil naca8h12 --xtr 0.07` — the default rotor grid (Re 10⁵…3·10⁶ ×
//!   M 0…0.65 × α −10…20°) as a long-form CSV table;
//! * `--re`, `--mach` (comma lists) and `--alpha A0:A1:DA` override each axis; one value each
//!   gives a single polar;
//! * `--inviscid` — the panel solution only (`alpha,cl,cd,cm,converged`).
//!
//! Every error is one line on stderr with a non-zero exit status; no output file is left
//! half-written (files are written to a temporary name and renamed).

mod args;

use std::io::IsTerminal;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

use anyhow::{bail, Context, Result};
use args::{
    BatchArgs, Cli, Command, ConvertArgs, GridArgs, Ncrit, PlotArgs, PlotPointArgs, PointCase,
    ReadArgs, RunArgs, Shape, SummaryArgs,
};
use clap::CommandFactory;

use polargen::arguments;
use polargen::cli::{self, Tool};
use polargen::geometry::{solver_airfoil, Airfoil};
use polargen::inviscid::PanelSystem;
use polargen::output::{check_output_path, fixed_decimals, write_output, OutputError, STDOUT_PATH};
use polargen::plot::point_plots::{solutions_figure, solutions_title, with_airfoil_contour};
use polargen::plot::polar_plots::transition_label;
use polargen::plot::table_plots::{table_overlay_figure, TableOverlay};
use polargen::plot::{check_image_path, render};
use polargen::polar::{parse_alpha_range, solve_operating_point, OperatingPoint, TargetClParams};
use polargen::table::{
    build_table, read_table_with, summary_csv, summary_json, summary_text, with_cd_max,
    write_table, Batch, BatchSettings, GridSpec, PolarTable, ReadOptions, TableFormat,
    DEFAULT_ALPHA, DEFAULT_MACH, DEFAULT_RE,
};
use polargen::viscous::distributions::write_distributions_file;
use polargen::viscous::{ViscousParams, ViscousSolution, ViscousSolver};

/// This tool's name and error prefix.
static TOOL: Tool = Tool::new("polargen");

fn main() -> ExitCode {
    polargen::output::remove_staged_files_on_signals();
    let cli = match TOOL.parse(|c: &Cli| c.quiet) {
        Ok(c) => c,
        Err(code) => return code,
    };
    TOOL.finish(match &cli.command {
        Some(Command::Plot(args)) => plot_tables(args),
        Some(Command::Convert(args)) => convert_table(args),
        Some(Command::Summary(args)) => summary(args),
        Some(Command::PlotPoint(args)) => plot_point(args),
        Some(Command::Batch(args)) => run_batch(args),
        Some(Command::Point { case, csv }) => point(case, csv),
        Some(Command::Completions(args)) => {
            to_stdout(&cli::completions(Cli::command(), args.shell))
        }
        Some(Command::Man) => cli::man_page(Cli::command())
            .map_err(Into::into)
            .and_then(|page| to_stdout(&page)),
        None if cli.run.inviscid => run_inviscid(&cli.run),
        None => run_viscous(&cli.run),
    })
}

/// Write `bytes` to standard output.
fn to_stdout(bytes: &[u8]) -> Result<()> {
    let path = Path::new(STDOUT_PATH);
    write_output(path, |w| {
        w.write_all(bytes).map_err(|e| OutputError::io(path, e))
    })?;
    Ok(())
}

/// Mach numbers from `--mach` (or `default`), each checked to lie in [0, 1).
fn mach_list(cli: &GridArgs, default: &[f64]) -> Result<Vec<f64>> {
    let list = match &cli.mach {
        Some(t) => arguments::number_list("--mach", t)?,
        None => default.to_vec(),
    };
    list.iter()
        .try_for_each(|&m| arguments::mach("--mach", m))?;
    Ok(list)
}

/// Check the panel count, load the airfoil and prepare it for the solver
/// ([`solver_airfoil`]); say on stderr what was changed.
fn load_airfoil(spec: Option<&str>, panels: usize, shape: &Shape) -> Result<Airfoil> {
    arguments::panels("--panels", panels)?;
    let spec = spec.context("--airfoil is required")?;
    let (foil, notes) = solver_airfoil(spec, panels, shape.derotate).context("--airfoil")?;
    notes.iter().for_each(|n| TOOL.say(format!("note: {n}")));
    Ok(foil)
}

/// `--inviscid`: the panel solution at one Mach number.
fn run_inviscid(cli: &RunArgs) -> Result<()> {
    let mach = match mach_list(&cli.grid, &[0.0])?.as_slice() {
        [m] => *m,
        _ => bail!("--mach: --inviscid takes one Mach number"),
    };
    let alphas =
        parse_alpha_range(cli.grid.alpha.as_deref().unwrap_or(DEFAULT_ALPHA)).context("--alpha")?;
    if let Some(path) = &cli.out {
        check_output_path(path).context("--out")?;
    }
    let foil = load_airfoil(cli.airfoil.as_deref(), cli.grid.panels, &cli.grid.shape)?;
    let system = PanelSystem::new(&foil).context("panel system")?;
    let mut csv = String::from("alpha,cl,cd,cm,converged\n");
    let mut supercritical: Vec<f64> = Vec::new();
    for &alpha in &alphas {
        let sol = system
            .solve(alpha, mach)
            .with_context(|| format!("alpha {alpha}"))?;
        if sol.supercritical {
            supercritical.push(alpha);
        }
        csv.push_str(&format!(
            "{alpha},{},0,{},true\n",
            fixed_decimals(sol.cl, 6),
            fixed_decimals(sol.cm, 6)
        ));
    }
    if let (Some(first), Some(last)) = (supercritical.first(), supercritical.last()) {
        TOOL.say(format!(
            "note: M {mach}: {} of {} points supercritical (alpha {first} … {last}): the \
             minimum Cp is below the sonic Cp*, beyond the validity of the Karman-Tsien \
             correction; those Cl and Cm are only indicative",
            supercritical.len(),
            alphas.len()
        ));
    }
    let path = cli.out.as_deref().unwrap_or(Path::new(STDOUT_PATH));
    write_output(path, |w| {
        w.write_all(csv.as_bytes())
            .map_err(|e| OutputError::io(path, e))
    })?;
    Ok(())
}

/// The transition setting of `--xtr` or `--xtr-top`/`--xtr-bot`, checked.
fn transition(cli: &GridArgs) -> Result<(f64, f64)> {
    let sides = match cli.xtr {
        Some(x) => [("--xtr", x), ("--xtr", x)],
        None => [("--xtr-top", cli.xtr_top), ("--xtr-bot", cli.xtr_bot)]
            .map(|(flag, x)| (flag, x.unwrap_or(1.0))),
    };
    for (flag, x) in sides {
        arguments::transition(flag, x)?;
    }
    Ok((sides[0].1, sides[1].1))
}

/// The grid and solver settings of the grid flags, checked.
fn grid_request(cli: &GridArgs) -> Result<(GridSpec, ViscousParams)> {
    // The default grid only when neither axis is given; Re alone runs at M 0, as XFOIL.
    let (reynolds, mach_default): (Vec<f64>, &[f64]) = match (&cli.re, &cli.mach) {
        (Some(t), _) => (arguments::number_list("--re", t)?, &[0.0]),
        (None, None) => (DEFAULT_RE.to_vec(), &DEFAULT_MACH),
        (None, Some(_)) => bail!("--mach: give the Reynolds numbers with --re too"),
    };
    reynolds
        .iter()
        .try_for_each(|&r| arguments::reynolds("--re", r))?;
    let grid = GridSpec {
        reynolds,
        mach: mach_list(cli, mach_default)?,
        alpha_deg: parse_alpha_range(cli.alpha.as_deref().unwrap_or(DEFAULT_ALPHA))
            .context("--alpha")?,
    };
    grid.check_size()?;
    let (xtr_top, xtr_bot) = transition(cli)?;
    let (ncrit_top, ncrit_bot) = ncrit_sides(&cli.ncrit)?;
    arguments::tolerance("--tolerance", cli.newton.tolerance)?;
    arguments::panels("--panels", cli.panels)?;
    let base = ViscousParams {
        ncrit_top,
        ncrit_bot,
        tolerance: cli.newton.tolerance,
        xtr_top,
        xtr_bot,
        ..ViscousParams::default()
    };
    Ok((grid, base))
}

/// The viscous polar(s) or table.
fn run_viscous(cli: &RunArgs) -> Result<()> {
    let (grid, base) = grid_request(&cli.grid)?;
    if let Some(path) = &cli.out {
        check_output_path(path).context("--out")?;
    }
    let format = TableFormat::for_output(cli.format.as_deref(), cli.out.as_deref())
        .context("--format/--out")?;
    let foil = load_airfoil(cli.airfoil.as_deref(), cli.grid.panels, &cli.grid.shape)?;
    let bar = progress_bar(grid.point_count() as u64);
    let start = Instant::now();
    let table = build_table(
        &foil,
        cli.grid.panels,
        &grid,
        &base,
        cli.grid.threads,
        |n| bar.iter().for_each(|b| b.inc(n as u64)),
    )?;
    bar.iter().for_each(|b| b.finish_and_clear());
    let census = table.census();
    TOOL.say(format!(
        "{census} in {:.1} s",
        start.elapsed().as_secs_f64()
    ));
    if census.converged == 0 {
        bail!("no point converged; no table written");
    }
    let table = with_cd_max(table, cli.extension.cd_max).context("--cd-max")?;
    let path = cli.out.as_deref().unwrap_or(Path::new(STDOUT_PATH));
    let files = write_table(&table, path, Some(format))?;
    if files.len() > 1 {
        TOOL.say(format!("wrote {} files", files.len()));
    }
    Ok(())
}

/// `polargen batch`: one table per airfoil and the index ([`Batch`]).
fn run_batch(args: &BatchArgs) -> Result<()> {
    let (grid, base) = grid_request(&args.grid)?;
    let settings = BatchSettings {
        grid,
        base,
        panels: args.grid.panels,
        derotate: args.grid.shape.derotate,
        format: args.format,
        shard: args.shard,
        resume: args.resume,
        jobs: args.jobs,
        threads: args.grid.threads,
    };
    let batch = Batch::plan(&args.airfoils, &args.out, settings)?;
    batch
        .notes()
        .iter()
        .for_each(|n| TOOL.say(format!("note: {n}")));
    let bar = progress_bar(batch.point_count() as u64);
    let summary = batch.run(|n| bar.iter().for_each(|b| b.inc(n as u64)))?;
    bar.iter().for_each(|b| b.finish_and_clear());
    TOOL.say(&summary);
    match summary.failed.as_slice() {
        [] => Ok(()),
        names => bail!("no table for {} (see the index)", names.join(", ")),
    }
}

/// `--ncrit`, `--ncrit-top`, `--ncrit-bot` ([`arguments::ncrit_sides`]).
fn ncrit_sides(n: &Ncrit) -> Result<(f64, f64)> {
    let flags = ["--ncrit", "--ncrit-top", "--ncrit-bot"];
    Ok(arguments::ncrit_sides(
        flags,
        n.ncrit,
        n.ncrit_top,
        n.ncrit_bot,
    )?)
}

/// `polargen plot`: overlay one polar from each table.
fn plot_tables(args: &PlotArgs) -> Result<()> {
    check_image_path(&args.out).context("--out")?;
    let figure = table_overlay_figure(&TableOverlay {
        tables: &args.tables,
        labels: &args.label,
        re: args.re,
        mach: args.mach,
        title: args.title.as_deref(),
        cd_axis: args.cd_axis,
        read: read_options(&args.read)?,
    })?;
    render(&figure, &args.out)?;
    Ok(())
}

/// `polargen convert`: read a table and write it in another format.
fn convert_table(args: &ConvertArgs) -> Result<()> {
    check_output_path(&args.out).context("--out")?;
    let format = TableFormat::for_output(args.format.as_deref(), Some(&args.out))
        .context("--format/--out")?;
    let table =
        with_cd_max(read(&args.table, &args.read)?, args.extension.cd_max).context("--cd-max")?;
    let files = write_table(&table, &args.out, Some(format))?;
    if files.len() > 1 {
        TOOL.say(format!("wrote {} files", files.len()));
    }
    Ok(())
}

/// `--assume-re`, `--assume-mach`, `--user-prop`, checked.
fn read_options(r: &ReadArgs) -> Result<ReadOptions> {
    let (re, mach) = (r.assume_re, r.assume_mach);
    let names = ["--assume-re", "--assume-mach"];
    Ok(ReadOptions::checked(names, re, mach, r.user_prop)?)
}

/// Read a table file, saying on stderr what the reader assumed.
fn read(path: &Path, r: &ReadArgs) -> Result<PolarTable> {
    let read = read_table_with(path, &read_options(r)?)?;
    read.notes
        .iter()
        .for_each(|n| TOOL.say(format!("note: {n}")));
    Ok(read.table)
}

/// `polargen summary`: per-polar numbers as text, CSV or JSON on standard output.
fn summary(args: &SummaryArgs) -> Result<()> {
    let rows = read(&args.table, &args.read)?.summaries();
    let text = match (args.json, args.csv) {
        (true, _) => summary_json(&rows),
        (_, true) => summary_csv(&rows),
        _ => summary_text(&rows),
    };
    to_stdout(text.as_bytes())
}

/// `polargen plot-point`: Cp and the boundary-layer distributions of both surfaces.
fn plot_point(args: &PlotPointArgs) -> Result<()> {
    check_image_path(&args.out).context("--out")?;
    if let Some(path) = &args.csv {
        check_output_path(path).context("--csv")?;
    }
    let (foil, runs) = solve_cases(&args.case)?;
    let cases: Vec<(&str, &ViscousSolution)> = runs.iter().map(|(l, s)| (l.as_str(), s)).collect();
    let c = &args.case;
    let title = args.title.clone().unwrap_or_else(|| {
        let alpha = c.alpha.unwrap_or(0.0);
        solutions_title(&foil.name, c.re, c.mach, alpha, c.cl, &cases)
    });
    // The Ncrit line of the N panel when both surfaces have the same Ncrit.
    let ncrit = Some(ncrit_sides(&c.ncrit)?).and_then(|(t, b)| (t == b).then_some(t));
    // The image first: if it cannot be written, no CSV is left behind either.
    let figure = solutions_figure(&cases, c.mach, &title, ncrit);
    render(&with_airfoil_contour(figure, &foil), &args.out)?;
    if let Some(path) = &args.csv {
        write_distributions_file(&cases, c.mach, path)?;
    }
    Ok(())
}

/// `polargen point`: the distributions as CSV to `csv`, without an image.
fn point(case: &PointCase, csv: &Path) -> Result<()> {
    check_output_path(csv).context("--csv")?;
    let (_, runs) = solve_cases(case)?;
    let cases: Vec<(&str, &ViscousSolution)> = runs.iter().map(|(l, s)| (l.as_str(), s)).collect();
    Ok(write_distributions_file(&cases, case.mach, csv)?)
}

/// Solve each transition setting at the α (or Cl) asked for: the airfoil and one labelled
/// solution per setting.
fn solve_cases(args: &PointCase) -> Result<(Airfoil, Vec<(String, ViscousSolution)>)> {
    arguments::reynolds("--re", args.re)?;
    arguments::mach("--mach", args.mach)?;
    let (ncrit_top, ncrit_bot) = ncrit_sides(&args.ncrit)?;
    arguments::tolerance("--tolerance", args.newton.tolerance)?;
    let xtrs = arguments::number_list("--xtr", &args.xtr)?;
    xtrs.iter()
        .try_for_each(|&x| arguments::transition("--xtr", x))?;
    let foil = load_airfoil(Some(&args.airfoil), args.panels, &args.shape)?;
    let mut runs: Vec<(String, ViscousSolution)> = Vec::new();
    for &xtr in &xtrs {
        let params = ViscousParams {
            ncrit_top,
            ncrit_bot,
            tolerance: args.newton.tolerance,
            ..ViscousParams::at(args.re, args.mach, xtr)
        };
        let mut solver = ViscousSolver::new(&foil, params).context("viscous solver")?;
        let label = transition_label(xtr, xtr);
        let at = args.cl.map_or(
            OperatingPoint::Alpha(args.alpha.unwrap_or(f64::NAN)),
            OperatingPoint::Cl,
        );
        let solution = solve_operating_point(&mut solver, at, &TargetClParams::default())
            .with_context(|| label.clone())?;
        runs.push((label, solution));
    }
    Ok((foil, runs))
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

#[cfg(test)]
mod tests {
    use clap::CommandFactory;

    #[test]
    fn cli_reference_is_current() {
        polargen::cli::check_reference(super::Cli::command());
    }
}
