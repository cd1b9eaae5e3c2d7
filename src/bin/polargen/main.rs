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

mod args;

use std::io::IsTerminal;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

use anyhow::{bail, Context, Result};
use args::{Cli, Command, ConvertArgs, Ncrit, PlotArgs, PlotPointArgs, PointCase, RunArgs, Shape};
use clap::CommandFactory;

use polargen::arguments;
use polargen::cli::{self, Tool};
use polargen::geometry::{airfoil_by_name_or_path, Airfoil, CHORD_UNITS_TOLERANCE};
use polargen::inviscid::PanelSystem;
use polargen::limits::{short_number, MAX_GRID_POINTS};
use polargen::output::{check_output_path, fixed_decimals, write_output, OutputError, STDOUT_PATH};
use polargen::plot::point_plots::{solutions_figure, solutions_title};
use polargen::plot::polar_plots::{compact_number, overlay_title, polar_figure, transition_label};
use polargen::plot::{check_image_path, render};
use polargen::polar::{parse_alpha_range, solve_operating_point, OperatingPoint, TargetClParams};
use polargen::section::{FlowCondition, PolarPoint};
use polargen::table::{
    build_table, read_table, with_cd_max, write_table, GridSpec, TableFormat, DEFAULT_ALPHA,
    DEFAULT_MACH, DEFAULT_RE,
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
        Some(Command::PlotPoint(args)) => plot_point(args),
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
fn mach_list(cli: &RunArgs, default: &[f64]) -> Result<Vec<f64>> {
    let list = match &cli.mach {
        Some(t) => arguments::number_list("--mach", t)?,
        None => default.to_vec(),
    };
    list.iter()
        .try_for_each(|&m| arguments::mach("--mach", m))?;
    Ok(list)
}

/// Check the panel count, load the airfoil (derotated on request), bring it into chord units
/// and repanel it ([`Airfoil::solver_nodes`]); say on stderr what was changed.
fn load_airfoil(spec: Option<&str>, panels: usize, shape: &Shape) -> Result<Airfoil> {
    arguments::panels("--panels", panels)?;
    let spec = spec.context("--airfoil is required")?;
    let mut given = airfoil_by_name_or_path(spec).context("--airfoil")?;
    let angle = given
        .chord_angle_deg()
        .with_context(|| format!("locating the chord of {}", given.name))?;
    if shape.derotate {
        given = given.derotated()?;
        TOOL.say(format!(
            "note: {spec}: rotated by {:.3} deg so that the chord line lies along x; alpha is \
             measured from the chord line",
            -angle
        ));
    } else if angle.to_radians().abs() > CHORD_UNITS_TOLERANCE {
        TOOL.say(format!(
            "note: {spec}: the chord line is inclined by {angle:.3} deg to the x axis; alpha is \
             measured from the x axis of the coordinates (--derotate measures it from the \
             chord line)"
        ));
    }
    let (foil, normalised) = given.solver_nodes(panels)?;
    if normalised {
        TOOL.say(format!("note: {}", Airfoil::normalisation_note(spec)));
    }
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
        check_output_path(path).context("--out")?;
    }
    let foil = load_airfoil(cli.airfoil.as_deref(), cli.panels, &cli.shape)?;
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
fn transition(cli: &RunArgs) -> Result<(f64, f64)> {
    let (xtr_top, xtr_bot) = match cli.xtr {
        Some(x) => (x, x),
        None => (cli.xtr_top.unwrap_or(1.0), cli.xtr_bot.unwrap_or(1.0)),
    };
    let flags = match cli.xtr {
        Some(_) => ["xtr", "xtr"],
        None => ["xtr-top", "xtr-bot"],
    };
    for (flag, x) in flags.into_iter().zip([xtr_top, xtr_bot]) {
        arguments::transition(&format!("--{flag}"), x)?;
    }
    Ok((xtr_top, xtr_bot))
}

/// The viscous polar(s) or table.
fn run_viscous(cli: &RunArgs) -> Result<()> {
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
    if grid.point_count() > MAX_GRID_POINTS {
        bail!(
            "{} Re x {} M x {} alpha = {} points: more than the limit of {MAX_GRID_POINTS} \
             points per run",
            grid.reynolds.len(),
            grid.mach.len(),
            grid.alpha_deg.len(),
            grid.point_count()
        );
    }
    let (xtr_top, xtr_bot) = transition(cli)?;
    let (ncrit_top, ncrit_bot) = ncrit_sides(&cli.ncrit)?;
    arguments::tolerance("--tolerance", cli.newton.tolerance)?;
    if let Some(path) = &cli.out {
        check_output_path(path).context("--out")?;
    }
    let format = TableFormat::for_output(cli.format.as_deref(), cli.out.as_deref())
        .context("--format/--out")?;
    let foil = load_airfoil(cli.airfoil.as_deref(), cli.panels, &cli.shape)?;

    let total = grid.point_count();
    let bar = progress_bar(total as u64);
    let start = Instant::now();
    let base = ViscousParams {
        ncrit_top,
        ncrit_bot,
        tolerance: cli.newton.tolerance,
        xtr_top,
        xtr_bot,
        ..ViscousParams::default()
    };
    let table = build_table(&foil, cli.panels, &grid, &base, cli.threads, |n| {
        if let Some(b) = &bar {
            b.inc(n as u64);
        }
    })?;
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
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
    let mut curves: Vec<(String, Vec<PolarPoint>)> = Vec::new();
    let mut conditions: Vec<FlowCondition> = Vec::new();
    for path in &args.tables {
        let table = read_table(path)?;
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
        let (at, points) = table.nearest_polar(re, mach);
        if !points.iter().any(|p| p.converged) {
            bail!(
                "{}: the polar at Re {}, M {} has no converged point to draw",
                path.display(),
                compact_number(at.reynolds),
                at.mach
            );
        }
        let meta = table.meta();
        let trip = transition_label(meta.xtr_top_set, meta.xtr_bot_set);
        curves.push((format!("{} {trip}", meta.airfoil), points.to_vec()));
        conditions.push(at);
    }
    let title = args.title.clone().unwrap_or_else(|| {
        let names: Vec<&str> = curves.iter().map(|c| c.0.as_str()).collect();
        let asked = args
            .re
            .zip(args.mach)
            .map(|(r, m)| FlowCondition::new(r, m));
        overlay_title(&names, &conditions, asked)
    });
    let refs: Vec<(&str, &[PolarPoint])> = curves
        .iter()
        .map(|(l, p)| (l.as_str(), p.as_slice()))
        .collect();
    render(&polar_figure(&refs, &title), &args.out)?;
    Ok(())
}

/// `polargen convert`: read a table and write it in another format.
fn convert_table(args: &ConvertArgs) -> Result<()> {
    check_output_path(&args.out).context("--out")?;
    let format = TableFormat::for_output(args.format.as_deref(), Some(&args.out))
        .context("--format/--out")?;
    let table = with_cd_max(read_table(&args.table)?, args.extension.cd_max).context("--cd-max")?;
    let files = write_table(&table, &args.out, Some(format))?;
    if files.len() > 1 {
        TOOL.say(format!("wrote {} files", files.len()));
    }
    Ok(())
}

/// `polargen plot-point`: Cp and the boundary-layer distributions of both surfaces.
fn plot_point(args: &PlotPointArgs) -> Result<()> {
    check_image_path(&args.out).context("--out")?;
    if let Some(path) = &args.csv {
        check_output_path(path).context("--csv")?;
    }
    let (name, runs) = solve_cases(&args.case)?;
    let cases: Vec<(&str, &ViscousSolution)> = runs.iter().map(|(l, s)| (l.as_str(), s)).collect();
    let c = &args.case;
    let title = args.title.clone().unwrap_or_else(|| {
        solutions_title(&name, c.re, c.mach, c.alpha.unwrap_or(0.0), c.cl, &cases)
    });
    // The Ncrit line of the N panel when both surfaces have the same Ncrit.
    let ncrit = Some(ncrit_sides(&c.ncrit)?).and_then(|(t, b)| (t == b).then_some(t));
    // The image first: if it cannot be written, no CSV is left behind either.
    render(&solutions_figure(&cases, c.mach, &title, ncrit), &args.out)?;
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

/// Solve each transition setting at the α (or Cl) asked for: the airfoil name and one labelled
/// solution per setting.
fn solve_cases(args: &PointCase) -> Result<(String, Vec<(String, ViscousSolution)>)> {
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
    Ok((foil.name, runs))
}

/// Error when `value` lies outside a table axis (beyond 0.1 % of the span).
fn check_inside(flag: &str, value: f64, axis: &[f64], path: &Path) -> Result<()> {
    let (lo, hi) = (axis[0], axis[axis.len() - 1]);
    let slack = 1e-3 * (hi - lo).abs().max(hi.abs() * 1e-3);
    if !value.is_finite() || value < lo - slack || value > hi + slack {
        bail!(
            "--{flag} {}: outside the table {} ({} … {})",
            short_number(value),
            path.display(),
            short_number(lo),
            short_number(hi)
        );
    }
    Ok(())
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
