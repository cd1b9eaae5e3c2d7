//! The paper report: the comparison with the DLR contamination study in one folder.
//!
//! [`write_report`] reads the shipped polar tables, runs the cruise trim (Table 3), the takeoff
//! (Table 4), the blade α(ψ) (Fig. 10), the power-required sweep and the sensitivity to the
//! preset's estimates for the clean and the contaminated 8-H-12 rotor
//! ([`studies::paper`](crate::studies::paper)), looks up Cd at Cl = 0.8 (Table 5) for both
//! airfoils, draws every figure (PNG and SVG) and writes `README.md` with our numbers beside
//! the flight test's and the paper's and the differences in words; and the same rotor model on
//! a second rotor, the PCA-2 autogiro against its tunnel and flight tests
//! ([`studies::pca2`](crate::studies::pca2)). Everything is computed on each
//! run; nothing in the report is typed in except the paper's own values.

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

mod beyond;
pub mod console;
mod fidelity;
mod figures;
mod markdown;
mod second_rotor;
mod shipped;
mod words;

pub use figures::{rotor_figure, RotorFigure};
pub use shipped::{
    ShippedInputs, SHIPPED_AIRCRAFT, SHIPPED_CONTAMINATED_TABLE, SHIPPED_POLARS, SHIPPED_TABLE,
};

use crate::geometry::airfoil_key;
use crate::output::{check_output_path, OutputError, OutputSet};
use crate::plot::{render_into_set, Figure, PlotError};
use crate::progress::{Progress, Work};
use crate::rotor::{
    sweep_speeds, Aircraft, AircraftError, BladeAlpha, Powerplant, PropellerError, TakeoffResult,
    TrimResult,
};
use crate::studies::paper::published::{Table5Row, SECTION_MACH, SECTION_RE, TABLE5, TABLE5_CL};
use crate::studies::paper::sensitivity::{sensitivity, Sensitivity};
use crate::studies::paper::{
    blade_alpha_cases, case_notes, paper_runs, sweep_cases, SpeedSweep, StudyError, CASE_LABELS,
    PAPER_TRIM_SPEED_KT,
};
use crate::table::{alpha_at_cl, LiftMatch, PolarTable, TableError};
use fidelity::PropellerFacts;
use std::path::{Path, PathBuf};

/// Radius fraction of the blade α(ψ) curve (paper Fig. 10: ≈ 90 % R).
const FIG10_RADIUS: f64 = 0.9;

/// Azimuth samples of the blade α(ψ) curve (1° resolution).
const FIG10_SAMPLES: usize = 360;

/// Speed range of the power-required sweep \[kt\]: from, to, step.
const SWEEP_KT: (f64, f64, f64) = (30.0, 90.0, 5.0);

/// α interval searched for Cl = 0.8 \[deg\] (the attached-flow branch of both airfoils).
const TABLE5_ALPHA_RANGE: (f64, f64) = (-5.0, 15.0);

/// Suffix of the free-transition and the fixed-transition table files.
const TRANSITIONS: [&str; 2] = ["free", "xtr0.07"];

/// Transition setting (x/c on both surfaces) of the free and the fixed-transition tables.
const TRANSITION_XTR: [f64; 2] = [1.0, 0.07];

/// Image formats of every report figure.
const FIGURE_FORMATS: [&str; 2] = ["png", "svg"];

/// File stems of the rotor figures: blade α(ψ), takeoff, power required.
const ROTOR_FIGURES: [&str; 3] = ["blade_alpha", "takeoff", "power_required"];

/// The report's text file.
const REPORT_README: &str = "README.md";

/// Where the report reads from and writes to.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReportInputs {
    /// Aircraft preset (TOML); the built-in copy when it is [`SHIPPED_AIRCRAFT`] and absent.
    /// The PCA-2 rotor preset `pca2.toml` is read from the same folder (built in likewise).
    pub aircraft: PathBuf,
    /// Folder holding `naca8h12_free.csv`, `naca8h12_xtr0.07.csv`, `naca23012_free.csv`,
    /// `naca23012_xtr0.07.csv` (the shipped default-grid tables), `goe429_free.csv` and
    /// `goe429_xtr0.07.csv` (the PCA-2's); built-in copies when it is [`SHIPPED_POLARS`] and
    /// they are absent.
    pub polars: PathBuf,
    /// Output folder (created if missing): `README.md` and the figures.
    pub out: PathBuf,
    /// Table cache folder of the section "Beyond the paper" ([`crate::studies`]); `None`
    /// leaves the section out.
    pub studies: Option<PathBuf>,
}

/// What a report run wrote, and what a user should read beside it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ReportOutcome {
    /// The files written, figures first, `README.md` last.
    pub written: Vec<PathBuf>,
    /// Notes on the computations (speeds without a trim, lookups beyond a table's range).
    pub notes: Vec<String>,
}

/// Why the report could not be written.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    /// The output folder or a file in it cannot be written.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// The aircraft preset is wrong.
    #[error(transparent)]
    Aircraft(#[from] AircraftError),
    /// A table cannot be read.
    #[error(transparent)]
    Table(#[from] TableError),
    /// A table holds another case than its file name promises.
    #[error(
        "{}: holds {airfoil} with transition at {xtr_top}/{xtr_bot} (upper/lower), expected \
         {stem} at {xtr}",
        path.display()
    )]
    MisnamedTable {
        /// The table file.
        path: PathBuf,
        /// The airfoil it holds.
        airfoil: String,
        /// Its upper-surface transition setting.
        xtr_top: f64,
        /// Its lower-surface transition setting.
        xtr_bot: f64,
        /// The airfoil its name promises.
        stem: &'static str,
        /// The transition setting its name promises.
        xtr: f64,
    },
    /// A rotor computation failed.
    #[error(transparent)]
    Study(#[from] StudyError),
    /// The propeller could not be calibrated or solved.
    #[error(transparent)]
    Propeller(#[from] PropellerError),
    /// A figure cannot be drawn or written.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// A study of the section "Beyond the paper" failed.
    #[error("beyond the paper")]
    Studies(#[from] crate::studies::StudiesError),
    /// The report's text cannot be written.
    #[error("cannot write {}", path.display())]
    Text {
        /// `README.md` in the output folder.
        path: PathBuf,
        /// Why.
        #[source]
        source: OutputError,
    },
}

/// Both tables of one airfoil and its Table 5 lookups.
struct FoilTables {
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
    /// Blade α(ψ) samples (ψ, α) \[deg\] per case, with the trims' lookup shares.
    alpha: Vec<BladeAlpha>,
    /// The power-required sweep per case.
    sweeps: Vec<SpeedSweep>,
    /// The calibrated propeller and its static thrust.
    propeller: PropellerFacts,
    /// The study again at the ends of each estimate's range.
    sensitivity: Sensitivity,
}

/// Writes the report (see the module documentation) after [`check_report_paths`], telling
/// `progress` the phases of its computations (the rotor cases, then the studies' tables and
/// runs when asked for).
pub fn write_report(
    inputs: &ReportInputs,
    progress: &dyn Progress,
) -> Result<ReportOutcome, ReportError> {
    check_report_paths(&inputs.out)?;
    let ac = shipped::aircraft(&inputs.aircraft)?;
    let foils = TABLE5
        .iter()
        .map(|row| load_foil(&inputs.polars, row))
        .collect::<Result<Vec<_>, _>>()?;
    let rotor = rotor_results(&ac, &foils[0].tables, progress)?;
    let second = second_rotor_results(inputs)?;
    let beyond = match &inputs.studies {
        Some(cache) => Some(beyond::run(&ac, cache, progress)?),
        None => None,
    };
    // Every file of the report appears together with the others, or none does.
    let mut set = OutputSet::new();
    let mut figure = |name: &str, fig: &Figure| -> Result<(), ReportError> {
        for ext in FIGURE_FORMATS {
            render_into_set(fig, &inputs.out.join(format!("{name}.{ext}")), &mut set)?;
        }
        Ok(())
    };
    for foil in &foils {
        figure(&polar_figure_name(foil.row), &figures::polar_overlay(foil))?;
    }
    let subject = figures::subject(&ac, &foils[0].tables[0]);
    let [blade_alpha, takeoff, power_required] = ROTOR_FIGURES;
    figure(blade_alpha, &figures::fig10(&rotor, &subject))?;
    let title = format!("Takeoff to 15 m — {subject}");
    figure(takeoff, &figures::takeoff_figure(&rotor.takeoffs, &title))?;
    let title = format!("Level flight, power required — {subject}");
    figure(
        power_required,
        &figures::power_figure(&rotor.sweeps, &title),
    )?;

    let mut text = markdown::markdown(inputs, &ac, &foils, &rotor);
    for (name, fig) in second.figures() {
        figure(name, &fig)?;
    }
    text.push_str(&second.markdown());
    if let Some(b) = &beyond {
        for (name, fig) in b.figures()? {
            figure(&name, &fig)?;
        }
        text.push_str(&b.markdown(&beyond::studies_doc_reference(&inputs.out)));
    }
    let readme = inputs.out.join(REPORT_README);
    set.write(&readme, |w| {
        w.write_all(text.as_bytes())
            .map_err(|e| OutputError::io(&readme, e))
    })
    .map_err(|source| ReportError::Text {
        path: readme.clone(),
        source,
    })?;
    let written = set.commit()?;
    let mut notes: Vec<String> = CASE_LABELS
        .iter()
        .enumerate()
        .flat_map(|(k, case)| case_notes(case, &rotor.trims[k].notes(), &rotor.takeoffs[k].notes()))
        .collect();
    notes.extend(rotor.sweeps.iter().flat_map(SpeedSweep::notes));
    notes.extend(beyond.into_iter().flat_map(|b| b.cache_notes));
    Ok(ReportOutcome { written, notes })
}

/// File stem of the polar figure of one Table 5 airfoil.
fn polar_figure_name(row: &Table5Row) -> String {
    format!("polar_{}", row.stem)
}

/// Check, before any computation, that the report folder and every file the report writes
/// into it can be written (`out` not a regular file; no figure or README path a folder), so
/// that a bad path cannot leave a half-written report behind.
pub fn check_report_paths(out: &Path) -> Result<(), OutputError> {
    if out.exists() && !out.is_dir() {
        return Err(OutputError::BadPath {
            path: out.to_path_buf(),
            reason: "is not a folder",
        });
    }
    let stems = TABLE5
        .iter()
        .map(polar_figure_name)
        .chain(ROTOR_FIGURES.iter().map(|s| s.to_string()))
        .chain(second_rotor::FIGURE_STEMS.iter().map(|s| s.to_string()))
        .chain(beyond::figure_stems().into_iter().map(String::from));
    let mut files: Vec<PathBuf> = stems
        .flat_map(|stem| FIGURE_FORMATS.map(|ext| out.join(format!("{stem}.{ext}"))))
        .collect();
    files.push(out.join(REPORT_README));
    for file in files {
        check_output_path(&file)?;
    }
    Ok(())
}

/// Check that a table file holds the case its name promises: the airfoil of `stem` (names
/// compared by [`airfoil_key`], `NACA 8-H-12` ~ `naca8h12`, `GOE 429 AIRFOIL` ~ `goe429`) at
/// transition `xtr` on both
/// surfaces, so that a misnamed file cannot enter the report.
fn check_table_case(
    table: &PolarTable,
    path: &Path,
    stem: &'static str,
    xtr: f64,
) -> Result<(), ReportError> {
    let meta = table.meta();
    // A UIUC coordinate file's header names the section "GOE 429 AIRFOIL".
    let key = airfoil_key(&meta.airfoil);
    let name = key.strip_suffix("airfoil").unwrap_or(&key);
    let t = &meta.transition;
    if name != stem || t.xtr_top != xtr || t.xtr_bot != xtr {
        return Err(ReportError::MisnamedTable {
            path: path.to_path_buf(),
            airfoil: meta.airfoil.clone(),
            xtr_top: t.xtr_top,
            xtr_bot: t.xtr_bot,
            stem,
            xtr,
        });
    }
    Ok(())
}

/// Reads the free and fixed-transition tables of one airfoil and looks up Table 5.
fn load_foil(dir: &Path, row: &'static Table5Row) -> Result<FoilTables, ReportError> {
    let paths = TRANSITIONS.map(|t| dir.join(format!("{}_{t}.csv", row.stem)));
    let [free, fixed] = [
        shipped::table(&paths[0])?.table,
        shipped::table(&paths[1])?.table,
    ];
    for ((table, path), xtr) in [&free, &fixed].iter().zip(&paths).zip(TRANSITION_XTR) {
        check_table_case(table, path, row.stem, xtr)?;
    }
    let at_cl = [&free, &fixed].map(|t| {
        alpha_at_cl(
            t,
            TABLE5_CL,
            SECTION_RE,
            SECTION_MACH,
            TABLE5_ALPHA_RANGE.0,
            TABLE5_ALPHA_RANGE.1,
        )
    });
    Ok(FoilTables {
        row,
        tables: [free, fixed],
        paths,
        at_cl,
    })
}

/// The PCA-2 rotor preset beside the aircraft preset and its Göttingen 429 tables (free,
/// 7 % trip) in the table folder, compared with its tunnel and flight tests.
fn second_rotor_results(inputs: &ReportInputs) -> Result<second_rotor::SecondRotor, ReportError> {
    let folder = inputs.aircraft.parent().unwrap_or(Path::new(""));
    let preset = shipped::rotor_preset(&folder.join("pca2.toml"))?;
    let [free, fixed] = TRANSITIONS.map(|t| inputs.polars.join(format!("goe429_{t}.csv")));
    let tables = [shipped::table(&free)?.table, shipped::table(&fixed)?.table];
    for ((table, path), xtr) in tables.iter().zip([&free, &fixed]).zip(TRANSITION_XTR) {
        check_table_case(table, path, "goe429", xtr)?;
    }
    Ok(second_rotor::run(&preset, &tables)?)
}

/// Trim, takeoff, blade α(ψ) and the speed sweep for the clean and the contaminated section.
fn rotor_results(
    ac: &Aircraft,
    tables: &[PolarTable; 2],
    progress: &dyn Progress,
) -> Result<RotorResults, ReportError> {
    let sections = [&tables[0], &tables[1]];
    let speeds = sweep_speeds(SWEEP_KT.0, SWEEP_KT.1, SWEEP_KT.2);
    let propeller = PropellerFacts::of(&Powerplant::from_aircraft(ac)?)?;
    progress.start(&Work::new(
        4,
        "computations",
        "the paper report: trim and takeoff, sensitivity, blade α and power sweep of the \
         clean and the contaminated rotor",
    ));
    let ((runs, sens), (alpha, sweeps)) = rayon::join(
        || {
            rayon::join(
                || paper_runs(ac, sections[0], sections[1]).inspect(|_| progress.advance(1)),
                || sensitivity(ac, sections[0], sections[1]).inspect(|_| progress.advance(1)),
            )
        },
        || {
            rayon::join(
                || {
                    blade_alpha_cases(
                        ac,
                        &sections,
                        &CASE_LABELS,
                        PAPER_TRIM_SPEED_KT,
                        FIG10_RADIUS,
                        FIG10_SAMPLES,
                    )
                    .inspect(|_| progress.advance(1))
                },
                || {
                    let sweeps = sweep_cases(ac, &sections, &CASE_LABELS, &speeds);
                    progress.advance(1);
                    sweeps
                },
            )
        },
    );
    progress.finish();
    let [clean, dirty] = runs?;
    let alpha = alpha?;
    for sweep in &sweeps {
        sweep.require_trims()?;
    }
    Ok(RotorResults {
        trims: [clean.trim, dirty.trim],
        takeoffs: [clean.takeoff, dirty.takeoff],
        alpha,
        sweeps,
        propeller,
        sensitivity: sens?,
    })
}
