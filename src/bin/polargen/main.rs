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

use std::path::Path;
use std::process::ExitCode;

use anyhow::{Context, Result};
use args::{
    BatchArgs, Cli, Command, ConvertArgs, GridArgs, Ncrit, PlotArgs, PlotPointArgs, PointCase,
    ReadArgs, RunArgs, Shape, SummaryArgs,
};
use clap::CommandFactory;

use polargen::arguments::{self, trip_flags, ArgumentError, TransitionArgs};
use polargen::cli::{self, Tool};
use polargen::geometry::{selig_file_text, shaped_airfoil, solver_airfoil, Airfoil, ShapeOp};
use polargen::inviscid::{inviscid_polar_csv, PanelSystem};
use polargen::output::{check_output_path, write_output_bytes, write_stdout, STDOUT_PATH};
use polargen::plot::point_plots::{solutions_figure, solutions_title, with_airfoil_contour};
use polargen::plot::table_plots::{table_overlay_figure, TableOverlay};
use polargen::plot::{check_image_path, render};
use polargen::polar::{solve_point_cases, OperatingPoint};
use polargen::section::{Transition, FREE_XTR};
use polargen::table::check_table_output;
use polargen::table::{
    read_table_with, summary_csv, summary_json, summary_text, with_cd_max, write_table, Batch,
    BatchSettings, FlapSweep, GridSpec, PolarTable, ReadOptions, TableFormat, TableJob,
};
use polargen::viscous::distributions::write_distributions_file;
use polargen::viscous::{ViscousParams, ViscousSolution};

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
            write_stdout(&cli::completions(Cli::command(), args.shell)).map_err(Into::into)
        }
        Some(Command::Man(args)) => {
            cli::man(Cli::command(), args).and_then(|page| Ok(write_stdout(&page)?))
        }
        Some(Command::Geometry {
            airfoil,
            shape,
            out,
        }) => write_geometry(airfoil, shape, out),
        None if cli.run.inviscid => run_inviscid(&cli.run),
        None => run_viscous(&cli.run),
    })
}

/// Load the airfoil, apply `ops` and prepare it for the solver ([`solver_airfoil`]); say on
/// stderr what was changed.
fn load_airfoil(spec: Option<&str>, panels: usize, rot: bool, ops: &[ShapeOp]) -> Result<Airfoil> {
    let spec = spec.context("--airfoil is required")?;
    let (foil, notes) = solver_airfoil(spec, panels, rot, ops).context("--airfoil")?;
    notes.iter().for_each(|n| TOOL.say(format!("note: {n}")));
    Ok(foil)
}

/// `polargen geometry`: the shaped airfoil as a Selig file, its thickness and camber said.
fn write_geometry(spec: &str, shape: &Shape, out: &Path) -> Result<()> {
    check_output_path(out).context("--out")?;
    let (foil, notes) =
        shaped_airfoil(spec, shape.derotate, &shape.ops()).context(spec.to_string())?;
    notes.iter().for_each(|n| TOOL.say(format!("note: {n}")));
    let text = selig_file_text(&foil)?;
    let gap = foil.te_gap();
    let measured = foil.thickness_camber()?;
    TOOL.say(format!("{}: {measured}, TE gap {gap:.5}", foil.name));
    Ok(write_output_bytes(out, text.as_bytes())?)
}

/// `--inviscid`: the panel solution at one Mach number, as CSV. The flags of the viscous
/// table that would change nothing here are refused, not ignored.
fn run_inviscid(cli: &RunArgs) -> Result<()> {
    let g = &cli.grid;
    let viscous_only = [
        ("--re", g.re.is_some()),
        ("--xtr", g.xtr.is_some()),
        ("--xtr-top", g.xtr_top.is_some()),
        ("--xtr-bot", g.xtr_bot.is_some()),
        ("--ncrit-top", g.ncrit.ncrit_top.is_some()),
        ("--ncrit-bot", g.ncrit.ncrit_bot.is_some()),
        ("--cd-max", cli.extension.cd_max.is_some()),
        ("--flap-deg", cli.flap_deg.is_some()),
    ];
    arguments::refuse_given(
        &viscous_only,
        "does not apply to --inviscid (the panel solution has no Reynolds number, transition, \
         post-stall extension or flap sweep; --ncrit and --tolerance, which have defaults, are \
         not read either)",
    )?;
    let format = TableFormat::for_flags(cli.format, cli.out.as_deref())?;
    if format != TableFormat::Csv {
        Err(ArgumentError::with_text(
            "--format/--out",
            format.name(),
            "--inviscid writes CSV (alpha,cl,cd,cm,converged) only",
        ))?;
    }
    let mach = cli.grid.mach.clone().unwrap_or(vec![0.0]);
    arguments::distinct("--mach", &mach)?;
    let mach = match mach.as_slice() {
        [m] => *m,
        _ => Err(ArgumentError::with_text(
            "--mach",
            "",
            "--inviscid takes one Mach number",
        ))?,
    };
    let alphas = cli.grid.alpha.as_ref().map(|a| a.0.clone());
    let alphas = alphas.unwrap_or_else(|| GridSpec::default().alpha_deg);
    if let Some(path) = &cli.out {
        check_output_path(path).context("--out")?;
    }
    let (spec, g) = (cli.airfoil.as_deref(), &cli.grid);
    let foil = load_airfoil(spec, g.panels, g.shape.derotate, &g.shape.ops())?;
    let system = PanelSystem::new(&foil).context("panel system")?;
    let (csv, note) = inviscid_polar_csv(&system, &alphas, mach)?;
    note.into_iter().for_each(|n| TOOL.say(n));
    let path = cli.out.as_deref().unwrap_or(Path::new(STDOUT_PATH));
    Ok(write_output_bytes(path, csv.as_bytes())?)
}

/// The grid and solver settings of the grid flags (each value checked by its parser).
fn grid_request(cli: &GridArgs) -> Result<(GridSpec, ViscousParams)> {
    let alpha = cli.alpha.as_ref().map(|a| a.0.as_slice());
    let grid = GridSpec::from_flags(cli.re.as_deref(), cli.mach.as_deref(), alpha)?;
    let base = ViscousParams {
        transition: transition(&cli.ncrit, trip_flags(cli.xtr, cli.xtr_top, cli.xtr_bot))?,
        tolerance: cli.newton.tolerance,
        ..ViscousParams::default()
    };
    Ok((grid, base))
}

/// The viscous polar(s) or table; with `--flap-deg` one table per flap deflection.
fn run_viscous(cli: &RunArgs) -> Result<()> {
    let (grid, base) = grid_request(&cli.grid)?;
    let out = cli.out.as_deref().unwrap_or(Path::new(STDOUT_PATH));
    check_output_path(out).context("--out")?;
    let format = TableFormat::for_flags(cli.format, cli.out.as_deref())?;
    format.check_alpha_count(grid.alpha_deg.len())?;
    let ops = cli.grid.shape.ops();
    let sweep = FlapSweep::new(&ops, cli.flap_deg.as_deref(), out, format)?;
    sweep.check_size(&grid)?;
    sweep
        .check_output(format, &grid.reynolds, &grid.mach)
        .context("--out")?;
    let job = TableJob {
        airfoil: cli.airfoil.as_deref().context("--airfoil is required")?,
        derotate: cli.grid.shape.derotate,
        panels: cli.grid.panels,
        grid: &grid,
        base: &base,
        threads: cli.grid.threads,
        cd_max: cli.extension.cd_max,
        format,
    };
    job.run(&sweep, &TOOL.progress(), &|line| TOOL.say(line))?;
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
        geometry: args.grid.shape.ops(),
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
    let summary = batch.run_with_progress(&TOOL.progress())?;
    TOOL.say(&summary);
    Ok(summary.require_all()?)
}

/// The transition setting of `--ncrit`, `--ncrit-top`, `--ncrit-bot` and the trips `xtr`
/// (flag and value of each surface), checked ([`arguments::transition`]).
fn transition(n: &Ncrit, xtr: [(&str, f64); 2]) -> Result<Transition> {
    Ok(arguments::transition(&TransitionArgs {
        ncrit: ("--ncrit", n.ncrit),
        ncrit_top: ("--ncrit-top", n.ncrit_top),
        ncrit_bot: ("--ncrit-bot", n.ncrit_bot),
        xtr_top: xtr[0],
        xtr_bot: xtr[1],
    })?)
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
    let format = TableFormat::for_flags(args.format, Some(&args.out))?;
    check_output_path(&args.out).context("--out")?;
    let table =
        with_cd_max(read(&args.table, &args.read)?, args.extension.cd_max).context("--cd-max")?;
    check_table_output(&args.out, format, table.re(), table.mach()).context("--out")?;
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
    Ok(write_stdout(text.as_bytes())?)
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
    let ncrit = transition(&c.ncrit, [("--xtr", FREE_XTR); 2])?.common_ncrit();
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
    arguments::point_cases(&args.xtr)?;
    let settings = args
        .xtr
        .iter()
        .map(|&x| transition(&args.ncrit, [("--xtr", x); 2]))
        .collect::<Result<Vec<_>>>()?;
    let (spec, shape) = (Some(args.airfoil.as_str()), &args.shape);
    let foil = load_airfoil(spec, args.panels, shape.derotate, &shape.ops())?;
    let at = args.cl.map_or(
        OperatingPoint::Alpha(args.alpha.unwrap_or(f64::NAN)),
        OperatingPoint::Cl,
    );
    let (point, tolerance) = ((args.re, args.mach), args.newton.tolerance);
    let runs = solve_point_cases(&foil, point, at, &settings, tolerance, &|l| TOOL.say(l))?;
    Ok((foil, runs))
}

#[cfg(test)]
mod tests {
    use clap::CommandFactory;

    #[test]
    fn cli_reference_is_current() {
        polargen::cli::check_reference(super::Cli::command());
    }
}
