//! `gyro report`: the paper comparison in one folder. Reads the shipped polar tables, runs
//! the cruise trim (Table 3), the takeoff (Table 4), the blade α(ψ) (Fig. 10) and the
//! power-required sweep for the clean and the contaminated 8-H-12 rotor, looks up Cd at
//! Cl = 0.8 (Table 5) for both airfoils, draws every figure (PNG and SVG) and writes
//! `README.md` with our numbers beside the paper's and the differences in words. Everything is
//! computed on each run; nothing in the report is typed in except the paper's own values.

use crate::paper::{
    Table5Row, PAPER_CLEAN_TAKEOFF_TEXT, PAPER_FIG10_MAX_ALPHA, PAPER_FIG10_PSI, PAPER_MACH,
    PAPER_RE, PAPER_TABLE5, PAPER_TABLE5_CL, PAPER_TAKEOFF, PAPER_TRIM,
};
use crate::plot::{alpha_figure, power_plot, takeoff_plot, write_figure, CASE_LABELS};
use crate::{load_aircraft, load_section, paper_cases, rel, trimmed_speeds, PAPER_TRIM_SPEED_KT};
use anyhow::{bail, Context, Result};
use clap::Args;
use polargen::geometry::airfoil_key;
use polargen::output::{check_output_path, write_output, OutputError};
use polargen::plot::polar_plots::{mark_lift_coefficient, polar_figure};
use polargen::plot::{AxisRange, Figure, Marker};
use polargen::rotor::cruise::{cruise_blade_alpha, sweep_speeds};
use polargen::rotor::trim::TrimParams;
use polargen::rotor::{rpm_to_rad_s, Aircraft, Atmosphere, TakeoffResult, TrimResult};
use polargen::table::fixed_condition::{alpha_at_cl, sample_polar, LiftMatch};
use polargen::table::PolarTable;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// `gyro report` options.
#[derive(Args)]
pub struct ReportArgs {
    /// Aircraft preset (TOML).
    #[arg(long, default_value = "aircraft/mtosport.toml")]
    aircraft: PathBuf,
    /// Folder holding naca8h12_free.csv, naca8h12_xtr0.07.csv, naca23012_free.csv and
    /// naca23012_xtr0.07.csv (the shipped default-grid tables).
    #[arg(long, default_value = "polars")]
    polars: PathBuf,
    /// Output folder (created if missing): README.md and the figures.
    #[arg(long, default_value = "report")]
    out: PathBuf,
}

/// Radius fraction of the blade α(ψ) curve (paper Fig. 10: ≈ 90 % R).
const FIG10_RADIUS: f64 = 0.9;

/// Azimuth samples of the blade α(ψ) curve (1° resolution).
const FIG10_SAMPLES: usize = 360;

/// Speed range of the power-required sweep \[kt\]: from, to, step.
const SWEEP_KT: (f64, f64, f64) = (30.0, 90.0, 5.0);

/// α interval searched for Cl = 0.8 \[deg\] (the attached-flow branch of both airfoils).
const TABLE5_ALPHA_RANGE: (f64, f64) = (-5.0, 15.0);

/// Rounding of the paper's Table 5 values (printed with three decimals).
const PAPER_TABLE5_ROUNDING: f64 = 0.0005;

/// Upper Cd limit of the drag-polar panels of the polar figures.
const DRAG_POLAR_CD_MAX: f64 = 0.04;

/// Relative differences up to this [%] are called a match in the report's words.
const MATCH_PERCENT: f64 = 5.0;

/// Relative differences up to this [%] are called close; larger ones differ.
const CLOSE_PERCENT: f64 = 15.0;

/// Suffix of the free-transition and the fixed-transition table files.
const TRANSITIONS: [&str; 2] = ["free", "xtr0.07"];

/// Transition settings as printed in Table 5: free, fixed.
const TRANSITION_NAMES: [&str; 2] = ["free", "fixed 7 %"];

/// Both tables of one airfoil and its Table 5 lookups.
struct Airfoil {
    row: &'static Table5Row,
    /// Free, fixed-transition table.
    tables: [PolarTable; 2],
    /// Table file paths as given.
    paths: [PathBuf; 2],
    /// Cl = 0.8 matches at Re 1.9e6, M 0.41: free, fixed.
    at_cl: [Option<LiftMatch>; 2],
}

/// Everything computed for the rotor (8-H-12 blade section), clean and contaminated.
struct RotorResults {
    trims: [TrimResult; 2],
    takeoffs: [TakeoffResult; 2],
    alpha: [Vec<(f64, f64)>; 2],
    sweeps: [Vec<TrimResult>; 2],
}

/// Runs `gyro report`, listing the files written in `buf`.
pub fn run(args: &ReportArgs, buf: &mut String) -> Result<()> {
    check_report_paths(&args.out)?;
    let ac = load_aircraft(&args.aircraft, None)?;
    let foils = PAPER_TABLE5
        .iter()
        .map(|row| load_airfoil(&args.polars, row))
        .collect::<Result<Vec<_>>>()?;
    let rotor = rotor_results(&ac, &foils[0].tables)?;
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("cannot create report folder {}", args.out.display()))?;

    let mut written = Vec::new();
    let mut figure = |name: &str, fig: &Figure| -> Result<()> {
        for ext in FIGURE_FORMATS {
            let path = args.out.join(format!("{name}.{ext}"));
            write_figure(fig, &path)?;
            written.push(path);
        }
        Ok(())
    };
    for foil in &foils {
        figure(&polar_figure_name(foil.row), &polar_overlay(foil))?;
    }
    let subject = format!("{}, {}", ac.name, foils[0].tables[0].meta().airfoil);
    let [blade_alpha, takeoff, power_required] = ROTOR_FIGURES;
    figure(blade_alpha, &fig10(&rotor, &subject))?;
    let runs: Vec<(&str, &TakeoffResult)> =
        CASE_LABELS.iter().copied().zip(&rotor.takeoffs).collect();
    figure(
        takeoff,
        &takeoff_plot(&runs, &format!("Takeoff to 15 m — {subject}")),
    )?;
    let sweeps: Vec<(&str, &[TrimResult])> = CASE_LABELS
        .iter()
        .zip(&rotor.sweeps)
        .map(|(l, s)| (*l, s.as_slice()))
        .collect();
    figure(
        power_required,
        &power_plot(
            &sweeps,
            &format!("Level flight, power required — {subject}"),
        ),
    )?;

    let text = markdown(args, &ac, &foils, &rotor);
    let readme = args.out.join(REPORT_README);
    write_output(&readme, |w| {
        w.write_all(text.as_bytes())
            .map_err(|e| OutputError::io(&readme, e))
    })
    .with_context(|| format!("cannot write {}", readme.display()))?;
    written.push(readme);
    for path in written {
        outln!(buf, "wrote {}", path.display());
    }
    Ok(())
}

/// Image formats of every report figure.
const FIGURE_FORMATS: [&str; 2] = ["png", "svg"];

/// File stems of the rotor figures: blade α(ψ), takeoff, power required.
const ROTOR_FIGURES: [&str; 3] = ["blade_alpha", "takeoff", "power_required"];

/// The report's text file.
const REPORT_README: &str = "README.md";

/// File stem of the polar figure of one Table 5 airfoil.
fn polar_figure_name(row: &Table5Row) -> String {
    format!("polar_{}", row.stem)
}

/// Check, before any computation, that the report folder and every file the report writes
/// into it can be written (`--out` not a regular file; no figure or README path a folder),
/// so that a bad path cannot leave a half-written report behind.
fn check_report_paths(out: &Path) -> Result<()> {
    if out.exists() && !out.is_dir() {
        bail!("--out {}: is not a folder", out.display());
    }
    let stems = PAPER_TABLE5
        .iter()
        .map(polar_figure_name)
        .chain(ROTOR_FIGURES.iter().map(|s| s.to_string()));
    let mut files: Vec<PathBuf> = stems
        .flat_map(|stem| FIGURE_FORMATS.map(|ext| out.join(format!("{stem}.{ext}"))))
        .collect();
    files.push(out.join(REPORT_README));
    for file in files {
        check_output_path(&file).context("--out")?;
    }
    Ok(())
}

/// Transition setting (x/c on both surfaces) of the free and the fixed-transition tables.
const TRANSITION_XTR: [f64; 2] = [1.0, 0.07];

/// Check that a table file holds the case its name promises: the airfoil of `stem` (names
/// compared by [`airfoil_key`], `NACA 8-H-12` ~ `naca8h12`) at transition `xtr` on both
/// surfaces, so that a misnamed file cannot enter the report.
fn check_table_case(table: &PolarTable, path: &Path, stem: &str, xtr: f64) -> Result<()> {
    let meta = table.meta();
    if airfoil_key(&meta.airfoil) != stem || meta.xtr_top_set != xtr || meta.xtr_bot_set != xtr {
        bail!(
            "{}: holds {} with transition at {}/{} (upper/lower), expected {stem} at {xtr}",
            path.display(),
            meta.airfoil,
            meta.xtr_top_set,
            meta.xtr_bot_set
        );
    }
    Ok(())
}

/// Reads the free and fixed-transition tables of one airfoil and looks up Table 5.
fn load_airfoil(dir: &Path, row: &'static Table5Row) -> Result<Airfoil> {
    let paths = TRANSITIONS.map(|t| dir.join(format!("{}_{t}.csv", row.stem)));
    let [free, fixed] = [load_section(&paths[0])?, load_section(&paths[1])?];
    for ((table, path), xtr) in [&free, &fixed].iter().zip(&paths).zip(TRANSITION_XTR) {
        check_table_case(table, path, row.stem, xtr)?;
    }
    let at_cl = [&free, &fixed].map(|t| {
        alpha_at_cl(
            t,
            PAPER_TABLE5_CL,
            PAPER_RE,
            PAPER_MACH,
            TABLE5_ALPHA_RANGE.0,
            TABLE5_ALPHA_RANGE.1,
        )
    });
    Ok(Airfoil {
        row,
        tables: [free, fixed],
        paths,
        at_cl,
    })
}

/// Trim, takeoff, blade α(ψ) and the speed sweep for the clean and the contaminated section.
fn rotor_results(ac: &Aircraft, tables: &[PolarTable; 2]) -> Result<RotorResults> {
    let alpha_of = |t: &PolarTable, label: &str| {
        cruise_blade_alpha(
            ac,
            t,
            PAPER_TRIM_SPEED_KT,
            0.0,
            FIG10_RADIUS,
            FIG10_SAMPLES,
            &TrimParams::default(),
        )
        .with_context(|| format!("{label} trim"))
    };
    let speeds = sweep_speeds(SWEEP_KT.0, SWEEP_KT.1, SWEEP_KT.2);
    let (cases, (alpha, sweeps)) = rayon::join(
        || paper_cases(ac, &tables[0], &tables[1]),
        || {
            rayon::join(
                || -> Result<_> {
                    Ok([
                        alpha_of(&tables[0], CASE_LABELS[0])?,
                        alpha_of(&tables[1], CASE_LABELS[1])?,
                    ])
                },
                || -> Result<_> {
                    Ok([
                        trimmed_speeds(ac, &tables[0], &speeds, Some(CASE_LABELS[0]))?,
                        trimmed_speeds(ac, &tables[1], &speeds, Some(CASE_LABELS[1]))?,
                    ])
                },
            )
        },
    );
    let ((tc, oc), (td, od)) = cases?;
    Ok(RotorResults {
        trims: [tc, td],
        takeoffs: [oc, od],
        alpha: alpha?,
        sweeps: sweeps?,
    })
}

/// Label of a table's transition setting for legends.
fn transition_label(i: usize) -> &'static str {
    if i == 0 {
        "free transition"
    } else {
        "transition fixed at 7 % chord"
    }
}

/// Four-panel polar overlay of one airfoil, free vs fixed transition, interpolated in the
/// tables at the paper's Re and M, with the Table 5 line Cl = 0.8.
fn polar_overlay(foil: &Airfoil) -> Figure {
    let polars: Vec<Vec<_>> = foil
        .tables
        .iter()
        .map(|t| {
            let (_, _, node) = t.nearest_polar(PAPER_RE, PAPER_MACH);
            let alphas: Vec<f64> = node.iter().map(|p| p.alpha).collect();
            sample_polar(t, &alphas, PAPER_RE, PAPER_MACH)
        })
        .collect();
    let labels: Vec<String> = (0..2)
        .map(|i| format!("{} {}", foil.row.name, transition_label(i)))
        .collect();
    let curves: Vec<(&str, &[_])> = labels
        .iter()
        .zip(&polars)
        .map(|(l, p)| (l.as_str(), p.as_slice()))
        .collect();
    let title = format!(
        "{} — Re 1.9e6, M {PAPER_MACH} (interpolated in the shipped tables)",
        foil.row.name
    );
    let mut fig = mark_lift_coefficient(polar_figure(&curves, &title), PAPER_TABLE5_CL);
    // The drag polar panel (Cd on x) shows the drag bucket of Table 5, not the stalled tail.
    for panel in fig
        .panels
        .iter_mut()
        .filter(|p| p.x_label.starts_with("Cd"))
    {
        panel.x_range = AxisRange::Fixed {
            min: 0.0,
            max: DRAG_POLAR_CD_MAX,
        };
    }
    fig
}

/// Blade α(ψ) at 0.9 R with the paper's maxima marked.
fn fig10(rotor: &RotorResults, subject: &str) -> Figure {
    let curves: Vec<(&str, &[(f64, f64)])> = CASE_LABELS
        .iter()
        .zip(&rotor.alpha)
        .map(|(l, a)| (*l, a.as_slice()))
        .collect();
    let mut fig = alpha_figure(
        &curves,
        &format!(
            "Blade α at r = {FIG10_RADIUS:.1} R, level flight at {PAPER_TRIM_SPEED_KT} kt — {subject}"
        ),
    );
    let (clean, dirty) = PAPER_FIG10_MAX_ALPHA;
    if let Some(panel) = fig.panels.first_mut() {
        for (i, (label, a)) in [
            ("paper max clean", clean),
            ("paper max contaminated", dirty),
        ]
        .into_iter()
        .enumerate()
        {
            panel.markers.push(Marker::point(
                PAPER_FIG10_PSI,
                a,
                format!("{label}: {a}° at ψ = {PAPER_FIG10_PSI}°"),
                [2, 3][i],
            ));
        }
    }
    fig
}

/// (ψ, α) of the maximum of a blade α(ψ) curve.
fn alpha_max(curve: &[(f64, f64)]) -> (f64, f64) {
    curve
        .iter()
        .copied()
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap_or((f64::NAN, f64::NAN))
}

/// `v` with `prec` decimals, or "—" when not a number.
fn num(v: f64, prec: usize) -> String {
    if v.is_finite() {
        format!("{v:.prec$}")
    } else {
        "—".to_string()
    }
}

/// Signed percentage with one decimal.
fn pct(v: f64) -> String {
    if v.is_finite() {
        format!("{v:+.1} %")
    } else {
        "—".to_string()
    }
}

/// How far ours is from the paper, in words, by the report's bands.
fn verdict(diff_percent: f64) -> &'static str {
    let d = diff_percent.abs();
    if !d.is_finite() {
        "not computed"
    } else if d <= MATCH_PERCENT {
        "matches"
    } else if d <= CLOSE_PERCENT {
        "close"
    } else {
        "differs"
    }
}

/// Paper-vs-ours counts by verdict: matches, close, differs (names of the latter).
#[derive(Default)]
struct Tally {
    matches: usize,
    close: usize,
    differs: Vec<String>,
}

impl Tally {
    fn add(&mut self, name: &str, case: &str, diff_percent: f64) {
        match verdict(diff_percent) {
            "matches" => self.matches += 1,
            "close" => self.close += 1,
            _ => self
                .differs
                .push(format!("{name} {case} ({})", pct(diff_percent))),
        }
    }

    fn sentence(&self) -> String {
        let total = self.matches + self.close + self.differs.len();
        // Verb agreeing with a count: "1 matches", "2 match".
        let verb =
            |n: usize, one: &'static str, many: &'static str| if n == 1 { one } else { many };
        let mut s = format!(
            "Of {total} values, {} {} the paper within {MATCH_PERCENT} %, {} {} within \
             {CLOSE_PERCENT} %",
            self.matches,
            verb(self.matches, "matches", "match"),
            self.close,
            verb(self.close, "is", "are"),
        );
        if self.differs.is_empty() {
            s.push_str(" and none differs by more.");
        } else {
            let n = self.differs.len();
            let _ = write!(
                s,
                " and {n} {} by more: {}.",
                verb(n, "differs", "differ"),
                self.differs.join(", ")
            );
        }
        s
    }
}

/// One quantity of a paper table: name, paper (clean, contaminated), ours, decimals.
struct Row {
    name: &'static str,
    paper: (f64, f64),
    ours: (f64, f64),
    prec: usize,
}

/// Markdown table of paper vs ours, clean and contaminated, with the contamination changes.
fn comparison_table(out: &mut String, rows: &[Row]) {
    outln!(
        out,
        "| quantity | paper clean | ours clean | ours vs paper | paper contaminated | ours contaminated | ours vs paper | paper change | ours change |"
    );
    outln!(out, "|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for r in rows {
        outln!(
            out,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.name,
            r.paper.0,
            num(r.ours.0, r.prec),
            pct(rel(r.paper.0, r.ours.0)),
            r.paper.1,
            num(r.ours.1, r.prec),
            pct(rel(r.paper.1, r.ours.1)),
            pct(rel(r.paper.0, r.paper.1)),
            pct(rel(r.ours.0, r.ours.1)),
        );
    }
}

/// Paper-vs-ours verdicts of every value (clean and contaminated) of `rows`.
fn tally_of(rows: &[Row]) -> Tally {
    let mut tally = Tally::default();
    for r in rows {
        tally.add(r.name, "clean", rel(r.paper.0, r.ours.0));
        tally.add(r.name, "contaminated", rel(r.paper.1, r.ours.1));
    }
    tally
}

/// Clean → contaminated change of the paper (`pch`) and ours (`och`) [%] are both "changing"
/// when the paper's is at least this large [%]; smaller paper changes have no direction to
/// compare.
const CHANGE_THRESHOLD_PERCENT: f64 = 1.0;

/// Sentence on how often the clean → contaminated change has the paper's sign.
fn direction_sentence(rows: &[Row]) -> String {
    let changes: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (rel(r.paper.0, r.paper.1), rel(r.ours.0, r.ours.1)))
        .filter(|(pch, _)| pch.abs() >= CHANGE_THRESHOLD_PERCENT)
        .collect();
    let agree = changes
        .iter()
        .filter(|(pch, och)| pch.signum() == och.signum())
        .count();
    format!(
        "The direction of the clean → contaminated change agrees with the paper for {agree} of \
         the {} quantities the paper shows changing by {CHANGE_THRESHOLD_PERCENT} % or more.",
        changes.len()
    )
}

/// Bullet list stating each row's agreement and its contamination change in words, then the
/// tally and direction sentences.
fn comparison_words(out: &mut String, rows: &[Row]) {
    for r in rows {
        let (dc, dd) = (rel(r.paper.0, r.ours.0), rel(r.paper.1, r.ours.1));
        let (pch, och) = (rel(r.paper.0, r.paper.1), rel(r.ours.0, r.ours.1));
        let change = if pch.abs() < CHANGE_THRESHOLD_PERCENT {
            format!(
                "Contamination changes it by {} in the paper and {} here.",
                pct(pch),
                pct(och)
            )
        } else {
            let ratio = och / pch;
            let size = if pch.signum() != och.signum() {
                "the opposite direction".to_string()
            } else if (ratio - 1.0).abs() <= 0.2 {
                "about the same size".to_string()
            } else if ratio > 1.0 {
                format!("{ratio:.1}× the paper's change")
            } else {
                format!("{:.0} % of the paper's change", 100.0 * ratio)
            };
            format!(
                "Contamination: paper {}, ours {} ({size}).",
                pct(pch),
                pct(och)
            )
        };
        outln!(
            out,
            "- **{}** — clean: ours {} vs paper {} ({}, {}); contaminated: ours {} vs paper {} ({}, {}). {change}",
            r.name,
            num(r.ours.0, r.prec),
            r.paper.0,
            pct(dc),
            verdict(dc),
            num(r.ours.1, r.prec),
            r.paper.1,
            pct(dd),
            verdict(dd),
        );
    }
    outln!(out);
    outln!(
        out,
        "{} {}",
        tally_of(rows).sentence(),
        direction_sentence(rows)
    );
}

/// The rows of Table 3 (same order and names as [`PAPER_TRIM`]).
fn trim_rows(t: &[TrimResult; 2]) -> Vec<Row> {
    let ours = |t: &TrimResult| {
        [
            (t.rotor_rpm, 1),
            (t.rotor_aoa_deg, 2),
            (t.engine_rpm.unwrap_or(f64::NAN), 0),
            (t.rotor_drag_n, 1),
            (t.parasitic_drag_n, 1),
            (t.prop_thrust_n, 1),
            (t.lift_to_drag, 2),
        ]
    };
    paired_rows(&PAPER_TRIM, &ours(&t[0]), &ours(&t[1]))
}

/// The rows of Table 4 (same order and names as [`PAPER_TAKEOFF`]).
fn takeoff_rows(o: &[TakeoffResult; 2]) -> Vec<Row> {
    let ours = |o: &TakeoffResult| {
        [
            (o.takeoff_roll_m, 1),
            (o.distance_15m_m, 1),
            (o.max_flapping_deg, 2),
        ]
    };
    paired_rows(&PAPER_TAKEOFF, &ours(&o[0]), &ours(&o[1]))
}

/// Rows pairing the paper's (name, clean, contaminated) values with ours, each of ours given
/// as (value, decimals to print); the clean entry's decimals are used for both.
fn paired_rows(
    paper: &[(&'static str, f64, f64)],
    clean: &[(f64, usize)],
    contaminated: &[(f64, usize)],
) -> Vec<Row> {
    paper
        .iter()
        .zip(clean.iter().zip(contaminated))
        .map(|(&(name, pc, pd), (&(oc, prec), &(od, _)))| Row {
            name,
            paper: (pc, pd),
            ours: (oc, od),
            prec,
        })
        .collect()
}

/// The whole `README.md` of the report.
fn markdown(args: &ReportArgs, ac: &Aircraft, foils: &[Airfoil], rotor: &RotorResults) -> String {
    let mut out = String::new();
    let o = &mut out;
    let rotor_foil = &foils[0];
    outln!(
        o,
        "# Paper report: clean vs contaminated rotor, ours beside the paper"
    );
    outln!(o);
    outln!(
        o,
        "Generated by `gyro report --aircraft {} --polars {} --out {}` (polargen {}). Do not edit \
         by hand: rerun the command to refresh it after a change of the tables or the rotor model.",
        args.aircraft.display(),
        args.polars.display(),
        args.out.display(),
        env!("CARGO_PKG_VERSION")
    );
    outln!(o);
    outln!(
        o,
        "Paper: Duda, Sachs, Seewald, Rohardt (DLR), \"Effects of rotor contamination on \
         gyroplane flight performance\". Aircraft: {} at {} kg, ISA sea level. Rotor blade \
         section {}: **clean** = free transition (e^N, Ncrit {}) from `{}`, **contaminated** = \
         transition fixed at 7 % chord on both surfaces from `{}`. All section data come from \
         lookups in these tables (monotone cubic in α, linear in ln Re and M).",
        ac.name,
        ac.mass_kg,
        rotor_foil.row.name,
        rotor_foil.tables[0].meta().ncrit,
        rotor_foil.paths[0].display(),
        rotor_foil.paths[1].display(),
    );
    outln!(o);
    outln!(
        o,
        "Words used below: *matches* = within {MATCH_PERCENT} % of the paper, *close* = within \
         {CLOSE_PERCENT} %, *differs* = further off. Percentages are (ours − paper) / paper; \
         \"change\" is (contaminated − clean) / clean."
    );
    outln!(o);
    summary(o, foils, rotor);

    outln!(
        o,
        "## Table 3 — trim at {PAPER_TRIM_SPEED_KT} kt, {} kg, ISA sea level",
        ac.mass_kg
    );
    outln!(o);
    let rows = trim_rows(&rotor.trims);
    comparison_table(o, &rows);
    outln!(o);
    comparison_words(o, &rows);
    outln!(o);
    let [clean, dirty] = &rotor.trims;
    let table = &rotor_foil.tables[0];
    // Advancing-tip Mach number (ΩR + V)/a of the clean trim, ISA sea level.
    let tip_speed = rpm_to_rad_s(clean.rotor_rpm) * ac.rotor.radius_m;
    let tip_mach = (tip_speed + clean.airspeed_ms) / Atmosphere::isa(0.0).speed_of_sound;
    let mach_max = table.mach()[table.mach().len() - 1];
    let tip = if tip_mach > mach_max {
        format!(", and the advancing tip, which reaches M {tip_mach:.2} (clean trim)")
    } else {
        String::new()
    };
    outln!(
        o,
        "Table coverage: at these trims {:.1} % (clean) and {:.1} % (contaminated) of the \
         blade-element lookups (strips × azimuths) fall outside the tables' range (Re {}…{}, \
         M {}…{mach_max}) and use its edge values: the inboard strips below the lowest \
         Reynolds number{tip}.",
        100.0 * clean.table_clamped_fraction,
        100.0 * dirty.table_clamped_fraction,
        table.re()[0],
        table.re()[table.re().len() - 1],
        table.mach()[0],
    );
    outln!(o);

    outln!(o, "## Table 4 — takeoff to 15 m, ISA sea level, no wind");
    outln!(o);
    let rows = takeoff_rows(&rotor.takeoffs);
    comparison_table(o, &rows);
    outln!(o);
    comparison_words(o, &rows);
    outln!(o);
    let (lo_kt, screen_kt, lo_rpm) = PAPER_CLEAN_TAKEOFF_TEXT;
    let c = &rotor.takeoffs[0];
    let d = &rotor.takeoffs[1];
    outln!(
        o,
        "The paper's text on the clean takeoff: lift-off at {lo_kt} kt, {screen_kt} kt at 15 m, \
         rotor ≈ {lo_rpm} rpm at lift-off. Ours, clean: lift-off at {:.1} kt ({}) after {:.1} s, \
         {:.1} kt at 15 m ({}), rotor {:.0} rpm at lift-off ({}); contaminated: lift-off at \
         {:.1} kt after {:.1} s, {:.1} kt at 15 m, rotor {:.0} rpm at lift-off.{}",
        c.liftoff_speed_kt,
        pct(rel(lo_kt, c.liftoff_speed_kt)),
        c.liftoff_time_s,
        c.screen_speed_kt,
        pct(rel(screen_kt, c.screen_speed_kt)),
        c.liftoff_rotor_rpm,
        pct(rel(lo_rpm, c.liftoff_rotor_rpm)),
        d.liftoff_speed_kt,
        d.liftoff_time_s,
        d.screen_speed_kt,
        d.liftoff_rotor_rpm,
        if c.flap_stops_reached || d.flap_stops_reached {
            " The blades reached the flapping stops."
        } else {
            ""
        }
    );
    outln!(o);
    outln!(o, "![Takeoff time histories](takeoff.png)");
    outln!(o);

    table5(o, foils);

    outln!(
        o,
        "## Fig. 10 — blade angle of attack at {FIG10_RADIUS:.1} R, {PAPER_TRIM_SPEED_KT} kt"
    );
    outln!(o);
    outln!(o, "| | paper max α [deg] | ours max α [deg] | ours vs paper | paper ψ of max [deg] | ours ψ of max [deg] |");
    outln!(o, "|---|---:|---:|---:|---:|---:|");
    let paper_max = [PAPER_FIG10_MAX_ALPHA.0, PAPER_FIG10_MAX_ALPHA.1];
    let ours_max = rotor.alpha.clone().map(|c| alpha_max(&c));
    for i in 0..2 {
        outln!(
            o,
            "| {} | {} | {} | {} | {PAPER_FIG10_PSI} | {} |",
            CASE_LABELS[i],
            paper_max[i],
            num(ours_max[i].1, 2),
            pct(rel(paper_max[i], ours_max[i].1)),
            num(ours_max[i].0, 0),
        );
    }
    outln!(o);
    let where_max = |psi: f64| {
        if (PAPER_FIG10_PSI - psi).abs() <= 30.0 {
            "on the retreating side as in the paper"
        } else if (180.0..=360.0).contains(&psi) {
            "on the retreating half but away from ψ = 270°"
        } else {
            "on the advancing half, unlike the paper"
        }
    };
    outln!(
        o,
        "Ours, clean: maximum {:.2}° at ψ = {:.0}° ({}, {}); contaminated: {:.2}° at ψ = {:.0}° \
         ({}, {}). Contamination raises the maximum by {:.2}° here and by {:.1}° in the paper.",
        ours_max[0].1,
        ours_max[0].0,
        verdict(rel(paper_max[0], ours_max[0].1)),
        where_max(ours_max[0].0),
        ours_max[1].1,
        ours_max[1].0,
        verdict(rel(paper_max[1], ours_max[1].1)),
        where_max(ours_max[1].0),
        ours_max[1].1 - ours_max[0].1,
        paper_max[1] - paper_max[0],
    );
    outln!(o);
    outln!(o, "![Blade angle of attack vs azimuth](blade_alpha.png)");
    outln!(o);

    power_section(o, rotor);

    outln!(o, "## Figures");
    outln!(o);
    outln!(
        o,
        "Each figure is also written as SVG next to its PNG. Polars interpolated in the tables at \
         Re 1.9e6, M {PAPER_MACH} (the condition of Table 5):"
    );
    outln!(o);
    for foil in foils {
        outln!(
            o,
            "![{} polars, free vs fixed transition](polar_{}.png)",
            foil.row.name,
            foil.row.stem
        );
        outln!(o);
    }
    out
}

/// Table 5 with words.
fn table5(o: &mut String, foils: &[Airfoil]) {
    outln!(
        o,
        "## Table 5 — section drag coefficient at Cl = {PAPER_TABLE5_CL}, Re 1.9e6, M {PAPER_MACH}"
    );
    outln!(o);
    outln!(
        o,
        "Ours: the α at which the table lookup gives Cl = {PAPER_TABLE5_CL} (bracketed root of the \
         interpolated lift curve), then Cd at that α. The paper prints XFOIL 6.94 values to three \
         decimals (a rounding of up to ±0.0005, i.e. ±4 … 8 % of these values); the XFOIL 6.99 \
         column is our reference run of the same cases (160 panels, Ncrit 9, linear \
         interpolation between its converged points), the sharper yardstick."
    );
    outln!(o);
    outln!(o, "| airfoil | transition | paper Cd | XFOIL 6.99 Cd | ours Cd | ours vs XFOIL 6.99 | ours vs paper | XFOIL 6.99 α [deg] | ours α [deg] |");
    outln!(o, "|---|---|---:|---:|---:|---:|---:|---:|---:|");
    let mut words = Vec::new();
    for foil in foils {
        let r = foil.row;
        let paper = [r.paper.0, r.paper.1];
        let xfoil = [r.xfoil.0, r.xfoil.1];
        let xfoil_alpha = [r.xfoil_alpha.0, r.xfoil_alpha.1];
        let ours = foil.at_cl.map(|m| m.map_or(f64::NAN, |m| m.lookup.cd));
        let ours_alpha = foil.at_cl.map(|m| m.map_or(f64::NAN, |m| m.alpha_deg));
        for i in 0..2 {
            outln!(
                o,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                r.name,
                TRANSITION_NAMES[i],
                paper[i],
                xfoil[i],
                num(ours[i], 5),
                pct(rel(xfoil[i], ours[i])),
                pct(rel(paper[i], ours[i])),
                num(xfoil_alpha[i], 2),
                num(ours_alpha[i], 2),
            );
            if (ours[i] - paper[i]).abs() > PAPER_TABLE5_ROUNDING {
                let cause = if (xfoil[i] - paper[i]).abs() > PAPER_TABLE5_ROUNDING {
                    "XFOIL 6.99 is outside it too, so the paper's XFOIL 6.94 run differs from \
                     the reference run here, not only ours"
                } else {
                    "XFOIL 6.99 is inside it, so this is a difference of ours"
                };
                words.push(format!(
                    "{} {}: ours {} is further from the paper's {} than its three-decimal \
                     rounding (±{PAPER_TABLE5_ROUNDING}) allows; XFOIL 6.99 gives {}: {cause}.",
                    r.name,
                    TRANSITION_NAMES[i],
                    num(ours[i], 5),
                    paper[i],
                    xfoil[i],
                ));
            }
            if let Some(m) = foil.at_cl[i] {
                if m.lookup.post_stall || m.lookup.bridged {
                    words.push(format!(
                        "The {} {} value comes from {} of the table.",
                        r.name,
                        TRANSITION_NAMES[i],
                        if m.lookup.post_stall {
                            "the post-stall extension"
                        } else {
                            "a bridged gap"
                        }
                    ));
                }
            } else {
                words.push(format!(
                    "The {} {} table never reaches Cl = {PAPER_TABLE5_CL} between α = {}° and {}°.",
                    r.name, TRANSITION_NAMES[i], TABLE5_ALPHA_RANGE.0, TABLE5_ALPHA_RANGE.1
                ));
            }
        }
        words.push(format!(
            "{}: ours {} (free) is {} from XFOIL 6.99 ({}), ours {} (fixed) is {} from it ({}); \
             fixing transition at 7 % multiplies Cd by {} here, {} in XFOIL 6.99 and {} in the \
             paper.",
            r.name,
            num(ours[0], 5),
            pct(rel(xfoil[0], ours[0])),
            verdict(rel(xfoil[0], ours[0])),
            num(ours[1], 5),
            pct(rel(xfoil[1], ours[1])),
            verdict(rel(xfoil[1], ours[1])),
            num(ours[1] / ours[0], 2),
            num(xfoil[1] / xfoil[0], 2),
            num(paper[1] / paper[0], 2),
        ));
    }
    outln!(o);
    for w in words {
        outln!(o, "- {w}");
    }
    outln!(o);
}

/// Power-required section: minimum-power speed and the 60 kt values of both sweeps.
fn power_section(o: &mut String, rotor: &RotorResults) {
    outln!(o, "## Power required (level flight, speed sweep)");
    outln!(o);
    outln!(
        o,
        "Not a figure of the paper: the propeller thrust times airspeed from trims at {} … {} kt \
         in {} kt steps (speeds without a trim are left out).",
        SWEEP_KT.0,
        SWEEP_KT.1,
        SWEEP_KT.2
    );
    outln!(o);
    let min = |s: &[TrimResult]| {
        s.iter()
            .min_by(|a, b| a.power_required_kw.total_cmp(&b.power_required_kw))
            .map_or((f64::NAN, f64::NAN), |t| {
                (t.airspeed_kt, t.power_required_kw)
            })
    };
    let (mc, md) = (min(&rotor.sweeps[0]), min(&rotor.sweeps[1]));
    let p60 = rotor.trims.clone().map(|t| t.power_required_kw);
    outln!(
        o,
        "Minimum power on the sweep's speed grid: clean {:.1} kW at {:.0} kt, contaminated {:.1} \
         kW at {:.0} kt ({}). At \
         {PAPER_TRIM_SPEED_KT} kt: clean {:.1} kW, contaminated {:.1} kW ({}).",
        mc.1,
        mc.0,
        md.1,
        md.0,
        pct(rel(mc.1, md.1)),
        p60[0],
        p60[1],
        pct(rel(p60[0], p60[1])),
    );
    outln!(o);
    outln!(o, "![Power required](power_required.png)");
    outln!(o);
}

/// The summary at the top of the report: one verdict line per table and figure.
fn summary(o: &mut String, foils: &[Airfoil], rotor: &RotorResults) {
    outln!(o, "## Summary");
    outln!(o);
    for (what, rows) in [
        ("Trim (Table 3)", trim_rows(&rotor.trims)),
        ("Takeoff (Table 4)", takeoff_rows(&rotor.takeoffs)),
    ] {
        outln!(
            o,
            "- **{what}:** {} {}",
            tally_of(&rows).sentence(),
            direction_sentence(&rows)
        );
    }
    let mut vs_xfoil: f64 = 0.0;
    let mut vs_paper: f64 = 0.0;
    for foil in foils {
        let xfoil = [foil.row.xfoil.0, foil.row.xfoil.1];
        let paper = [foil.row.paper.0, foil.row.paper.1];
        for i in 0..2 {
            let ours = foil.at_cl[i].map_or(f64::NAN, |m| m.lookup.cd);
            vs_xfoil = nan_max(vs_xfoil, rel(xfoil[i], ours).abs());
            vs_paper = nan_max(vs_paper, rel(paper[i], ours).abs());
        }
    }
    outln!(
        o,
        "- **Section drag at Cl = {PAPER_TABLE5_CL} (Table 5):** ours is within {} of XFOIL 6.99 \
         for both airfoils, free and fixed transition, and within {} of the values the paper \
         prints to three decimals.",
        num_pct(vs_xfoil),
        num_pct(vs_paper),
    );
    let ours_max = rotor.alpha.clone().map(|c| alpha_max(&c));
    let (pc, pd) = PAPER_FIG10_MAX_ALPHA;
    outln!(
        o,
        "- **Blade α at {FIG10_RADIUS:.1} R (Fig. 10):** maximum {:.2}° clean and {:.2}° \
         contaminated at ψ ≈ {:.0}° and {:.0}°; the paper has {pc}° and {pd}° at {PAPER_FIG10_PSI}° \
         ({} and {}).",
        ours_max[0].1,
        ours_max[1].1,
        ours_max[0].0,
        ours_max[1].0,
        pct(rel(pc, ours_max[0].1)),
        pct(rel(pd, ours_max[1].1)),
    );
    outln!(o);
}

/// The larger of two values, NaN if either is NaN (a missing value must not hide).
fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// Unsigned percentage with one decimal, "—" when not a number.
fn num_pct(v: f64) -> String {
    if v.is_finite() {
        format!("{v:.1} %")
    } else {
        "— (a value is missing)".to_string()
    }
}
