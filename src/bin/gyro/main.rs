//! `gyro` — gyroplane rotor performance from airfoil polar tables: cruise trim, takeoff,
//! clean-versus-contaminated comparison (paper Tables 3 and 4), power-required sweeps, rotor
//! plots ([`plot`]) and the paper report ([`report`]).

use anyhow::{bail, Context, Result};
use clap::{Args, Parser, Subcommand};
use paper::{PAPER_TAKEOFF, PAPER_TRIM};
use polargen::diagnostics::error_line;
use polargen::output::{check_output_path, write_output, OutputError};
use polargen::rotor::aircraft::{MAX_MASS_KG, MAX_SPEED_KT};
use polargen::rotor::cruise::{cruise_blade_alpha, speed_sweep, sweep_speeds};
use polargen::rotor::trim::{trim_aircraft, TrimParams, TrimResult};
use polargen::rotor::MAX_ISA_ALTITUDE_M;
use polargen::rotor::{simulate_takeoff, Aircraft, TakeoffResult};
use polargen::section::PolarPoint;
use polargen::table::{read_table, PolarTable, TableMeta};
use serde::Serialize;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// Appends one formatted line to an output `String` (writing to a `String` cannot fail).
macro_rules! outln {
    ($buf:expr) => {
        $buf.push('\n')
    };
    ($buf:expr, $($arg:tt)*) => {{
        let _ = writeln!($buf, $($arg)*);
    }};
}

mod paper;
mod plot;
mod report;

#[derive(Parser)]
#[command(
    name = "gyro",
    version,
    about = "Gyroplane rotor strip model driven by airfoil polar tables"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Level-cruise trim: rotor rpm, rotor AoA, drags, propeller thrust, engine rpm, L/D.
    Trim {
        /// Aircraft preset (TOML).
        #[arg(long)]
        aircraft: PathBuf,
        /// Section polar table (CSV with columns alpha, cl, cd[, cm]).
        #[arg(long)]
        table: PathBuf,
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
        /// Aircraft preset (TOML).
        #[arg(long)]
        aircraft: PathBuf,
        /// Section polar table (CSV with columns alpha, cl, cd[, cm]).
        #[arg(long)]
        table: PathBuf,
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
        /// Table of the clean blade section.
        #[arg(long)]
        clean: PathBuf,
        /// Table of the contaminated blade section.
        #[arg(long)]
        contaminated: PathBuf,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Trim over a speed range: power-required curve.
    Sweep {
        /// Aircraft preset (TOML).
        #[arg(long)]
        aircraft: PathBuf,
        /// Section polar table (CSV with columns alpha, cl, cd[, cm]).
        #[arg(long)]
        table: PathBuf,
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
        /// Aircraft preset (TOML).
        #[arg(long)]
        aircraft: PathBuf,
        /// Section polar table (CSV with columns alpha, cl, cd[, cm]).
        #[arg(long)]
        table: PathBuf,
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
    /// Rotor figures, clean vs contaminated, to SVG or PNG: alpha, takeoff or power.
    Plot {
        #[command(subcommand)]
        kind: plot::PlotKind,
    },
    /// The paper report: Tables 3, 4, 5 beside the paper's values and all figures, in one folder.
    Report(report::ReportArgs),
}

/// Reads the section table given with `--table`: a polargen table file (long-form CSV or
/// JSON, [`read_table`]) or, as a fallback, a single XFOIL-style polar CSV with columns
/// `alpha, cl, cd[, cdp, cm, xtr_top, xtr_bot]` (the XFOIL reference polars). A single polar
/// becomes a one-node table at the Re and M parsed from a file name like `…_Re1.9e6_M0.41_…`
/// (Re 1e6, M 0 if absent); lookups at other Re/M are clamped to that node.
fn load_section(path: &Path) -> Result<PolarTable> {
    if path.is_dir() {
        bail!("cannot read table {}: is a folder", path.display());
    }
    if !path.is_file() {
        bail!("cannot read table {}: no such file", path.display());
    }
    let table = match read_table(path) {
        Ok(t) => t,
        // A file with polargen's columns is a polargen table with an error in it: report
        // that error, not the fallback reader's.
        Err(table_err) if has_polargen_header(path) => {
            return Err(anyhow::Error::new(table_err))
                .with_context(|| format!("table {}", path.display()))
        }
        Err(table_err) => single_polar_table(path).with_context(|| {
            format!("not a polargen table ({table_err}) nor an XFOIL polar CSV")
        })?,
    };
    table
        .require_lookup()
        .with_context(|| format!("{}", path.display()))?;
    Ok(table)
}

/// Whether `path` starts like a polargen table: JSON, or a CSV header naming the `airfoil`,
/// `re` and `mach` columns.
fn has_polargen_header(path: &Path) -> bool {
    let Ok(text) = std::fs::read(path) else {
        return false;
    };
    let head = String::from_utf8_lossy(&text[..text.len().min(4096)]);
    let first = head.trim_start();
    if first.starts_with('{') {
        return true;
    }
    let header = first.lines().next().unwrap_or("");
    let cols: Vec<&str> = header.split(',').map(str::trim).collect();
    ["airfoil", "re", "mach"].iter().all(|c| cols.contains(c))
}

/// Number after `key` in a file stem such as `naca8h12_Re1.9e6_M0.41_free`.
fn stem_number(stem: &str, key: &str) -> Option<f64> {
    stem.split('_')
        .find_map(|part| part.strip_prefix(key).and_then(|v| v.parse::<f64>().ok()))
}

fn single_polar_table(path: &Path) -> Result<PolarTable> {
    let mut rd = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_path(path)
        .with_context(|| format!("cannot read table {}", path.display()))?;
    let headers = rd.headers()?.clone();
    let col = |name: &str| headers.iter().position(|h| h.eq_ignore_ascii_case(name));
    let (Some(ia), Some(il), Some(id)) = (col("alpha"), col("cl"), col("cd")) else {
        bail!("table {} needs columns alpha, cl, cd", path.display());
    };
    let (icdp, icm, ixt, ixb) = (col("cdp"), col("cm"), col("xtr_top"), col("xtr_bot"));
    let mut points = Vec::new();
    for (n, rec) in rd.records().enumerate() {
        let rec = rec.with_context(|| format!("table {} row {}", path.display(), n + 2))?;
        let get = |i: usize| -> Result<f64> {
            let s = rec.get(i).unwrap_or("");
            s.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .with_context(|| {
                    format!("table {} row {}: bad number '{s}'", path.display(), n + 2)
                })
        };
        let opt = |i: Option<usize>, default: f64| -> Result<f64> {
            i.map(get).transpose().map(|v| v.unwrap_or(default))
        };
        let cd = get(id)?;
        let cdp = opt(icdp, 0.0)?;
        points.push(PolarPoint {
            alpha: get(ia)?,
            cl: get(il)?,
            cd,
            cdp,
            cdf: cd - cdp,
            cm: opt(icm, 0.0)?,
            xtr_top: opt(ixt, 1.0)?,
            xtr_bot: opt(ixb, 1.0)?,
            converged: true,
            iterations: 0,
            residual: 0.0,
        });
    }
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("");
    let re = stem_number(stem, "Re").unwrap_or(1e6);
    let mach = stem_number(stem, "M").unwrap_or(0.0);
    let meta = TableMeta {
        airfoil: stem.split('_').next().unwrap_or("polar").to_string(),
        ncrit: 9.0,
        xtr_top_set: 1.0,
        xtr_bot_set: 1.0,
        panels: 0,
        solver: "XFOIL polar file".to_string(),
    };
    PolarTable::new(meta, vec![re], vec![mach], vec![points])
        .with_context(|| format!("table {}", path.display()))
}

fn load_aircraft(path: &Path, mass: Option<f64>) -> Result<Aircraft> {
    let mut ac = Aircraft::from_toml_file(path)?;
    if let Some(m) = mass {
        if !(m.is_finite() && m > 0.0 && m <= MAX_MASS_KG) {
            bail!("--mass {m}: must be a positive number of kg, at most {MAX_MASS_KG}");
        }
        ac.mass_kg = m;
    }
    Ok(ac)
}

/// Most trims one speed sweep may ask for.
const MAX_SWEEP_SPEEDS: usize = 1000;

/// An airspeed flag: above 0 and below [`MAX_SPEED_KT`].
fn check_speed(flag: &str, kt: f64) -> Result<()> {
    if !(kt.is_finite() && kt > 0.0 && kt < MAX_SPEED_KT) {
        bail!("--{flag} {kt}: must be above 0 and below {MAX_SPEED_KT} kt");
    }
    Ok(())
}

/// The `--altitude-m` flag: inside the ISA troposphere of the atmosphere model.
fn check_altitude(m: f64) -> Result<()> {
    if !(0.0..=MAX_ISA_ALTITUDE_M).contains(&m) {
        bail!("--altitude-m {m}: must be within the ISA troposphere, 0 to {MAX_ISA_ALTITUDE_M} m");
    }
    Ok(())
}

/// The `--radius` flag: a fraction of R on the blade, outboard of the root cut-out.
fn check_radius(radius: f64, aircraft: &Aircraft) -> Result<()> {
    let root = aircraft.rotor.root_cutout_m / aircraft.rotor.radius_m;
    if !(radius > root && radius <= 1.0) {
        bail!(
            "--radius {radius}: must be a fraction of R on the blade, in ({root:.3}, 1] \
             (outboard of the {} m root cut-out)",
            aircraft.rotor.root_cutout_m
        );
    }
    Ok(())
}

fn check_samples(samples: usize) -> Result<()> {
    if !(4..=3600).contains(&samples) {
        bail!("--samples {samples}: must be between 4 and 3600");
    }
    Ok(())
}

/// Notes on stderr about a trim that is a valid rotor solution but not one the aircraft can
/// fly as computed: the engine cannot reach the thrust, or the table did not cover the rotor.
fn trim_notes(t: &TrimResult) {
    if t.engine_rpm.is_none() {
        eprintln!(
            "gyro: note: at {:.1} kt the propeller needs more than the engine's maximum rpm \
             for {:.0} N of thrust: the aircraft cannot fly this speed level",
            t.airspeed_kt, t.prop_thrust_n
        );
    }
    if t.table_clamped_fraction > 0.0 {
        eprintln!(
            "gyro: note: at {:.1} kt, {:.1} % of the blade-element lookups lie outside the \
             table's Reynolds/Mach range and use its edge values",
            t.airspeed_kt,
            100.0 * t.table_clamped_fraction
        );
    }
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
    /// The speeds of the sweep \[kt\], checked.
    fn checked(&self) -> Result<Vec<f64>> {
        let Self {
            from_kt,
            to_kt,
            step_kt,
        } = *self;
        check_speed("from-kt", from_kt)?;
        check_speed("to-kt", to_kt)?;
        if to_kt < from_kt {
            bail!("--to-kt {to_kt}: below --from-kt {from_kt}");
        }
        if !(step_kt.is_finite() && step_kt > 0.0) {
            bail!("--step-kt {step_kt}: must be a positive number of knots");
        }
        let count = ((to_kt - from_kt) / step_kt).floor() + 1.0;
        if count > MAX_SWEEP_SPEEDS as f64 {
            bail!(
                "--step-kt {step_kt}: gives {count:.0} speeds from {from_kt} to {to_kt} kt \
                 (at most {MAX_SWEEP_SPEEDS})"
            );
        }
        Ok(sweep_speeds(from_kt, to_kt, step_kt))
    }
}

#[derive(Serialize)]
struct TrimJson {
    rotor_rpm: f64,
    rotor_aoa_deg: f64,
    engine_rpm: Option<f64>,
    rotor_drag_n: f64,
    parasitic_drag_n: f64,
    prop_thrust_n: f64,
    lift_to_drag: f64,
    hub_aoa_deg: f64,
    power_required_kw: f64,
    beta1c_deg: f64,
    beta1s_deg: f64,
    speed_kt: f64,
}

impl From<&TrimResult> for TrimJson {
    fn from(t: &TrimResult) -> Self {
        Self {
            rotor_rpm: t.rotor_rpm,
            rotor_aoa_deg: t.rotor_aoa_deg,
            engine_rpm: t.engine_rpm,
            rotor_drag_n: t.rotor_drag_n,
            parasitic_drag_n: t.parasitic_drag_n,
            prop_thrust_n: t.prop_thrust_n,
            lift_to_drag: t.lift_to_drag,
            hub_aoa_deg: t.hub_aoa_deg,
            power_required_kw: t.power_required_kw,
            beta1c_deg: t.beta1c_deg,
            beta1s_deg: t.beta1s_deg,
            speed_kt: t.airspeed_kt,
        }
    }
}

#[derive(Serialize)]
struct TakeoffJson {
    takeoff_roll_m: f64,
    distance_15m_m: f64,
    max_flapping_deg: f64,
    liftoff_speed_kt: f64,
    screen_speed_kt: f64,
    liftoff_rotor_rpm: f64,
    screen_time_s: f64,
}

impl From<&TakeoffResult> for TakeoffJson {
    fn from(t: &TakeoffResult) -> Self {
        Self {
            takeoff_roll_m: t.takeoff_roll_m,
            distance_15m_m: t.distance_15m_m,
            max_flapping_deg: t.max_flapping_deg,
            liftoff_speed_kt: t.liftoff_speed_kt,
            screen_speed_kt: t.screen_speed_kt,
            liftoff_rotor_rpm: t.liftoff_rotor_rpm,
            screen_time_s: t.screen_time_s,
        }
    }
}

fn engine_text(e: Option<f64>) -> String {
    e.map_or_else(|| "above max".to_string(), |v| format!("{v:.0}"))
}

fn print_trim(buf: &mut String, t: &TrimResult) {
    outln!(buf, "trim at {:.1} kt", t.airspeed_kt);
    outln!(buf, "  rotor rpm n_R          {:8.1}", t.rotor_rpm);
    outln!(
        buf,
        "  rotor AoA alpha_R [deg]{:8.2}   (hub {:.2})",
        t.rotor_aoa_deg,
        t.hub_aoa_deg
    );
    outln!(
        buf,
        "  engine rpm             {:>8}",
        engine_text(t.engine_rpm)
    );
    outln!(buf, "  rotor drag D_R [N]     {:8.1}", t.rotor_drag_n);
    outln!(buf, "  parasitic D_P [N]      {:8.1}", t.parasitic_drag_n);
    outln!(buf, "  prop thrust F_prop [N] {:8.1}", t.prop_thrust_n);
    outln!(buf, "  L/D                    {:8.2}", t.lift_to_drag);
    outln!(buf, "  power required [kW]    {:8.1}", t.power_required_kw);
    outln!(
        buf,
        "  flapping b1c, b1s [deg]{:8.2} {:.2}",
        t.beta1c_deg,
        t.beta1s_deg
    );
}

fn print_takeoff(buf: &mut String, t: &TakeoffResult) {
    outln!(buf, "takeoff");
    outln!(buf, "  takeoff roll s_TO [m]      {:7.1}", t.takeoff_roll_m);
    outln!(buf, "  distance to 15 m s_15 [m]  {:7.1}", t.distance_15m_m);
    outln!(
        buf,
        "  max flapping beta_max [deg]{:7.2}{}",
        t.max_flapping_deg,
        if t.flap_stops_reached {
            "  (on the stops)"
        } else {
            ""
        }
    );
    outln!(
        buf,
        "  lift-off speed [kt]        {:7.1}  at {:.1} s, rotor {:.0} rpm",
        t.liftoff_speed_kt,
        t.liftoff_time_s,
        t.liftoff_rotor_rpm
    );
    outln!(
        buf,
        "  speed at 15 m [kt]         {:7.1}  at {:.1} s",
        t.screen_speed_kt,
        t.screen_time_s
    );
}

/// Trims of a speed sweep at the preset's mass, ISA sea level, that succeeded, in increasing
/// speed; a speed without a trim is reported on stderr as skipped, prefixed with the case
/// `label` if given. Error if no speed trims.
fn trimmed_speeds(
    aircraft: &Aircraft,
    section: &PolarTable,
    speeds_kt: &[f64],
    label: Option<&str>,
) -> Result<Vec<TrimResult>> {
    let prefix = label.map_or(String::new(), |l| format!("{l}: "));
    let mut trims = Vec::new();
    for (v, r) in speed_sweep(
        aircraft,
        section,
        speeds_kt,
        aircraft.mass_kg,
        0.0,
        &TrimParams::default(),
    ) {
        match r {
            Ok(t) => trims.push(t),
            Err(e) => eprintln!("gyro: {prefix}skipped {v:.1} kt: {e}"),
        }
    }
    if trims.is_empty() {
        bail!("{prefix}no trim point in the speed range");
    }
    let clamped: Vec<&TrimResult> = trims
        .iter()
        .filter(|t| t.table_clamped_fraction > 0.0)
        .collect();
    if let Some(worst) = clamped.iter().max_by(|a, b| {
        a.table_clamped_fraction
            .total_cmp(&b.table_clamped_fraction)
    }) {
        eprintln!(
            "gyro: note: {prefix}at {} of {} speeds some blade-element lookups lie outside the \
             table's Reynolds/Mach range and use its edge values (most: {:.1} % at {:.1} kt)",
            clamped.len(),
            trims.len(),
            100.0 * worst.table_clamped_fraction,
            worst.airspeed_kt
        );
    }
    Ok(trims)
}

/// Airspeed of the paper's cruise trim (Table 3) \[kt\].
const PAPER_TRIM_SPEED_KT: f64 = 60.0;

/// The paper's two computations for one blade section: trim at 60 kt, ISA sea level, the
/// preset's mass (Table 3) and the takeoff (Table 4); `label` names the case in errors.
fn paper_case(
    ac: &Aircraft,
    section: &PolarTable,
    label: &str,
) -> Result<(TrimResult, TakeoffResult)> {
    let t = trim_aircraft(
        ac,
        section,
        PAPER_TRIM_SPEED_KT,
        ac.mass_kg,
        0.0,
        &TrimParams::default(),
    )
    .with_context(|| format!("{label} trim"))?;
    let o = simulate_takeoff(ac, section).with_context(|| format!("{label} takeoff"))?;
    Ok((t, o))
}

/// (trim, takeoff) of the clean and of the contaminated section.
type CasePair = ((TrimResult, TakeoffResult), (TrimResult, TakeoffResult));

/// [`paper_case`] for the clean and the contaminated section, run in parallel.
fn paper_cases(ac: &Aircraft, clean: &PolarTable, dirty: &PolarTable) -> Result<CasePair> {
    let (c, d) = rayon::join(
        || paper_case(ac, clean, "clean"),
        || paper_case(ac, dirty, "contaminated"),
    );
    Ok((c?, d?))
}

/// Relative change from `a` to `b` [%].
fn rel(a: f64, b: f64) -> f64 {
    100.0 * (b - a) / a
}

fn compare(
    buf: &mut String,
    ac: &Aircraft,
    clean: &PolarTable,
    dirty: &PolarTable,
    json: bool,
) -> Result<()> {
    let ((tc, oc), (td, od)) = paper_cases(ac, clean, dirty)?;
    let ours_trim = |t: &TrimResult| {
        [
            t.rotor_rpm,
            t.rotor_aoa_deg,
            t.engine_rpm.unwrap_or(f64::NAN),
            t.rotor_drag_n,
            t.parasitic_drag_n,
            t.prop_thrust_n,
            t.lift_to_drag,
        ]
    };
    let ours_to = |t: &TakeoffResult| [t.takeoff_roll_m, t.distance_15m_m, t.max_flapping_deg];
    if json {
        #[derive(Serialize)]
        struct Row {
            quantity: &'static str,
            paper_clean: f64,
            paper_contaminated: f64,
            ours_clean: f64,
            ours_contaminated: f64,
        }
        let rows = |paper: &[(&'static str, f64, f64)], c: &[f64], d: &[f64]| -> Vec<Row> {
            paper
                .iter()
                .zip(c.iter().zip(d))
                .map(|(&(q, pc, pd), (&oc, &od))| Row {
                    quantity: q,
                    paper_clean: pc,
                    paper_contaminated: pd,
                    ours_clean: oc,
                    ours_contaminated: od,
                })
                .collect()
        };
        let out = serde_json::json!({
            "trim": rows(&PAPER_TRIM, &ours_trim(&tc), &ours_trim(&td)),
            "takeoff": rows(&PAPER_TAKEOFF, &ours_to(&oc), &ours_to(&od)),
        });
        outln!(buf, "{}", serde_json::to_string_pretty(&out)?);
        return Ok(());
    }
    let table =
        |buf: &mut String, title: &str, paper: &[(&str, f64, f64)], c: &[f64], d: &[f64]| {
            outln!(buf, "{title}");
            outln!(
                buf,
                "  {:<28} {:>9} {:>9} {:>8} | {:>9} {:>9} {:>8}",
                "",
                "paper",
                "paper",
                "paper",
                "ours",
                "ours",
                "ours"
            );
            outln!(
                buf,
                "  {:<28} {:>9} {:>9} {:>8} | {:>9} {:>9} {:>8}",
                "quantity",
                "clean",
                "contam.",
                "change",
                "clean",
                "contam.",
                "change"
            );
            for (&(q, pc, pd), (&oc, &od)) in paper.iter().zip(c.iter().zip(d)) {
                outln!(
                    buf,
                    "  {q:<28} {pc:>9.1} {pd:>9.1} {:>+7.1}% | {oc:>9.1} {od:>9.1} {:>+7.1}%",
                    rel(pc, pd),
                    rel(oc, od)
                );
            }
        };
    table(
        buf,
        "Table 3 — trim at 60 kt, ISA sea level",
        &PAPER_TRIM,
        &ours_trim(&tc),
        &ours_trim(&td),
    );
    outln!(buf);
    table(
        buf,
        "Table 4 — takeoff, ISA sea level, no wind",
        &PAPER_TAKEOFF,
        &ours_to(&oc),
        &ours_to(&od),
    );
    Ok(())
}

/// Runs one command, appending its standard output to `buf`.
fn run(cli: Cli, buf: &mut String) -> Result<()> {
    match cli.command {
        Command::Trim {
            aircraft,
            table,
            speed_kt,
            mass,
            altitude_m,
            json,
        } => {
            check_speed("speed-kt", speed_kt)?;
            check_altitude(altitude_m)?;
            let ac = load_aircraft(&aircraft, mass)?;
            let section = load_section(&table)?;
            let t = trim_aircraft(
                &ac,
                &section,
                speed_kt,
                ac.mass_kg,
                altitude_m,
                &TrimParams::default(),
            )?;
            trim_notes(&t);
            if json {
                outln!(
                    buf,
                    "{}",
                    serde_json::to_string_pretty(&TrimJson::from(&t))?
                );
            } else {
                print_trim(buf, &t);
            }
        }
        Command::Takeoff {
            aircraft,
            table,
            mass,
            json,
            history,
        } => {
            if let Some(path) = &history {
                check_output_path(path).context("--history")?;
            }
            let ac = load_aircraft(&aircraft, mass)?;
            let section = load_section(&table)?;
            let t = simulate_takeoff(&ac, &section)?;
            if let Some(path) = history {
                write_output(&path, |w| {
                    t.write_history_csv(w)
                        .map_err(|e| OutputError::io(&path, e.into()))
                })
                .context("--history")?;
            }
            if json {
                outln!(
                    buf,
                    "{}",
                    serde_json::to_string_pretty(&TakeoffJson::from(&t))?
                );
            } else {
                print_takeoff(buf, &t);
            }
        }
        Command::Compare {
            aircraft,
            clean,
            contaminated,
            json,
        } => {
            let ac = load_aircraft(&aircraft, None)?;
            let c = load_section(&clean)?;
            let d = load_section(&contaminated)?;
            compare(buf, &ac, &c, &d, json)?;
        }
        Command::Sweep {
            aircraft,
            table,
            speeds,
            mass,
            json,
        } => {
            let speeds = speeds.checked()?;
            let ac = load_aircraft(&aircraft, mass)?;
            let section = load_section(&table)?;
            let rows: Vec<TrimJson> = trimmed_speeds(&ac, &section, &speeds, None)?
                .iter()
                .map(TrimJson::from)
                .collect();
            if json {
                outln!(buf, "{}", serde_json::to_string_pretty(&rows)?);
            } else {
                outln!(
                    buf,
                    "{:>7} {:>7} {:>7} {:>8} {:>8} {:>8} {:>8} {:>6} {:>7}",
                    "V[kt]",
                    "n_R",
                    "a_R",
                    "engine",
                    "D_R[N]",
                    "D_P[N]",
                    "F_P[N]",
                    "L/D",
                    "P[kW]"
                );
                for r in &rows {
                    outln!(
                        buf,
                        "{:7.1} {:7.1} {:7.2} {:>8} {:8.1} {:8.1} {:8.1} {:6.2} {:7.1}",
                        r.speed_kt,
                        r.rotor_rpm,
                        r.rotor_aoa_deg,
                        engine_text(r.engine_rpm),
                        r.rotor_drag_n,
                        r.parasitic_drag_n,
                        r.prop_thrust_n,
                        r.lift_to_drag,
                        r.power_required_kw
                    );
                }
            }
        }
        Command::Alpha {
            aircraft,
            table,
            speed_kt,
            radius,
            samples,
        } => {
            check_speed("speed-kt", speed_kt)?;
            check_samples(samples)?;
            let ac = load_aircraft(&aircraft, None)?;
            check_radius(radius, &ac)?;
            let section = load_section(&table)?;
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
        Command::Plot { kind } => plot::run(kind)?,
        Command::Report(args) => report::run(&args, buf)?,
    }
    Ok(())
}

fn main() {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if !e.use_stderr() => e.exit(),
        Err(e) => {
            let text = e.to_string();
            let message: Vec<&str> = text
                .lines()
                .take_while(|l| !l.starts_with("Usage:"))
                .map(str::trim)
                .filter(|l| !l.is_empty())
                .collect();
            eprintln!("gyro: {}", message.join(" ").trim_start_matches("error: "));
            std::process::exit(2);
        }
    };
    let mut buf = String::new();
    if let Err(e) = run(cli, &mut buf) {
        eprintln!("gyro: {}", error_line(e.as_ref()));
        std::process::exit(1);
    }
    // A closed pipe (e.g. `gyro … | head`) is not an error of ours: stop quietly.
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(buf.as_bytes())
        .and_then(|()| stdout.flush())
    {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            eprintln!("gyro: cannot write output: {e}");
            std::process::exit(1);
        }
        _ => {}
    }
}
