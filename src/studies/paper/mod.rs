//! The clean-versus-contaminated rotor study of the paper (Duda, Sachs, Seewald, Rohardt,
//! DLR): the same aircraft computed with the clean and with the contaminated blade section.
//!
//! * [`paper_runs`] — the paper's two computations per section: the cruise trim at
//!   [`PAPER_TRIM_SPEED_KT`] (Table 3) and the takeoff (Table 4), both sections in parallel;
//! * [`blade_alpha_cases`], [`takeoff_cases`], [`sweep_cases`] — blade α(ψ) in trimmed cruise
//!   (Fig. 10), takeoff time histories (Fig. 11) and power-required sweeps for one or more
//!   sections, in parallel;
//! * [`published`] — the paper's published values, each beside the accessor of ours;
//! * [`sensitivity`] — the study again with each estimated value of the preset at the ends of
//!   its range.
//!
//! Everything here only calls the trim, takeoff and cruise models; no new physics.

pub mod published;
pub mod sensitivity;

use crate::rotor::{
    cruise_blade_alpha, simulate_takeoff, speed_sweep, trim_aircraft, Aircraft, BladeAlpha,
    BladeSection, LookupShares, TakeoffError, TakeoffResult, TrimError, TrimParams, TrimResult,
};
use rayon::prelude::*;

/// Airspeed of the paper's cruise trim (Table 3) \[kt\].
pub const PAPER_TRIM_SPEED_KT: f64 = 60.0;

/// Names of the blade-section cases, in the order clean, contaminated.
pub const CASE_LABELS: [&str; 2] = ["clean", "contaminated"];

/// Why a computation of the study failed; `case` names the blade section.
#[derive(Debug, thiserror::Error)]
pub enum StudyError {
    /// A trim failed.
    #[error("{case} trim")]
    Trim {
        /// The case (e.g. `clean`).
        case: String,
        /// Why.
        #[source]
        source: TrimError,
    },
    /// A takeoff failed.
    #[error("{case} takeoff")]
    Takeoff {
        /// The case.
        case: String,
        /// Why.
        #[source]
        source: TakeoffError,
    },
    /// No speed of a sweep could be trimmed.
    #[error("{}no trim point in the speed range", prefix(case.as_deref()))]
    NoTrimInRange {
        /// The case, if the sweep is one of several.
        case: Option<String>,
    },
}

/// `"<case>: "`, or nothing without a case.
fn prefix(case: Option<&str>) -> String {
    case.map_or(String::new(), |c| format!("{c}: "))
}

/// The paper's two computations for one blade section.
#[derive(Clone, Debug, PartialEq)]
pub struct PaperRun {
    /// Trim at [`PAPER_TRIM_SPEED_KT`], ISA sea level, the preset's mass (Table 3).
    pub trim: TrimResult,
    /// Takeoff (Table 4).
    pub takeoff: TakeoffResult,
}

impl PaperRun {
    /// The trim's and the takeoff's notes ([`case_notes`]).
    pub fn notes(&self, case: &str) -> Vec<String> {
        case_notes(case, &self.trim.notes(), &self.takeoff.notes())
    }
}

/// The notes of one case (`note: …` lines: a trim's, a takeoff's, a blade α trim's lookup
/// shares), the `trim` ones first, each after `case: `.
pub fn case_notes(case: &str, trim: &[String], takeoff: &[String]) -> Vec<String> {
    trim.iter()
        .chain(takeoff)
        .map(|n| match n.strip_prefix("note: ") {
            Some(rest) => format!("note: {case}: {rest}"),
            None => format!("{case}: {n}"),
        })
        .collect()
}

/// The paper's trim and takeoff with `section`; `case` names it in errors.
pub fn paper_run<S: BladeSection + ?Sized>(
    aircraft: &Aircraft,
    section: &S,
    case: &str,
) -> Result<PaperRun, StudyError> {
    let trim = trim_aircraft(
        aircraft,
        section,
        PAPER_TRIM_SPEED_KT,
        aircraft.mass_kg,
        0.0,
        &TrimParams::default(),
    )
    .map_err(|source| StudyError::Trim {
        case: case.to_string(),
        source,
    })?;
    let takeoff = simulate_takeoff(aircraft, section).map_err(|source| StudyError::Takeoff {
        case: case.to_string(),
        source,
    })?;
    Ok(PaperRun { trim, takeoff })
}

/// [`paper_run`] for the clean and the contaminated section, in parallel.
pub fn paper_runs<S: BladeSection + Sync + ?Sized>(
    aircraft: &Aircraft,
    clean: &S,
    contaminated: &S,
) -> Result<[PaperRun; 2], StudyError> {
    let (c, d) = rayon::join(
        || paper_run(aircraft, clean, CASE_LABELS[0]),
        || paper_run(aircraft, contaminated, CASE_LABELS[1]),
    );
    Ok([c?, d?])
}

/// The notes of [`paper_runs`]' two runs, each after its case label (`clean: note: …`).
pub fn paper_runs_notes(runs: &[PaperRun; 2]) -> Vec<String> {
    runs.iter()
        .zip(CASE_LABELS)
        .flat_map(|(run, case)| run.notes(case))
        .collect()
}

/// The trims of a speed sweep at the preset's mass, ISA sea level.
#[derive(Debug)]
pub struct SpeedSweep {
    /// The case, if the sweep is one of several.
    pub case: Option<String>,
    /// The speeds that trimmed, in increasing speed.
    pub trims: Vec<TrimResult>,
    /// The speeds \[kt\] without a trim, and why.
    pub skipped: Vec<(f64, TrimError)>,
}

impl SpeedSweep {
    /// Sweep `speeds_kt` (in parallel) with `section`.
    pub fn run<S: BladeSection + Sync + ?Sized>(
        aircraft: &Aircraft,
        section: &S,
        speeds_kt: &[f64],
        case: Option<&str>,
    ) -> Self {
        let mut trims = Vec::new();
        let mut skipped = Vec::new();
        let params = TrimParams::default();
        for (v, r) in speed_sweep(aircraft, section, speeds_kt, aircraft.mass_kg, 0.0, &params) {
            match r {
                Ok(t) => trims.push(t),
                Err(e) => skipped.push((v, e)),
            }
        }
        Self {
            case: case.map(str::to_string),
            trims,
            skipped,
        }
    }

    /// Error when no speed trimmed.
    pub fn require_trims(&self) -> Result<(), StudyError> {
        if self.trims.is_empty() {
            return Err(StudyError::NoTrimInRange {
                case: self.case.clone(),
            });
        }
        Ok(())
    }

    /// What a user should read beside the results: each skipped speed and why, and (as
    /// notes) at how many speeds the aircraft cannot fly level (the engine's rpm is not
    /// enough) and at how many the blade-element lookups lie outside the table's
    /// Reynolds/Mach range, on supercritical points or in massive separation, with the worst
    /// speed. One line each.
    pub fn notes(&self) -> Vec<String> {
        let prefix = prefix(self.case.as_deref());
        let mut notes: Vec<String> = self
            .skipped
            .iter()
            .map(|(v, e)| format!("{prefix}skipped {v:.1} kt: {e}"))
            .collect();
        let n = self.trims.len();
        let beyond_engine: Vec<f64> = self
            .trims
            .iter()
            .filter(|t| t.engine_rpm.is_none())
            .map(|t| t.airspeed_kt)
            .collect();
        let lo = beyond_engine.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = beyond_engine
            .iter()
            .copied()
            .fold(f64::NEG_INFINITY, f64::max);
        match beyond_engine.as_slice() {
            [] => {}
            [v] => notes.push(format!(
                "note: {prefix}at {v:.1} kt the propeller needs more than the engine's maximum \
                 rpm: the aircraft cannot fly this speed level"
            )),
            [..] => notes.push(format!(
                "note: {prefix}at {} of {n} speeds ({lo:.1} to {hi:.1} kt) the propeller needs \
                 more than the engine's maximum rpm: the aircraft cannot fly them level",
                beyond_engine.len()
            )),
        }
        for (k, meaning) in LookupShares::MEANINGS.iter().enumerate() {
            let share = |t: &TrimResult| t.lookup_shares().values()[k];
            let flagged: Vec<&TrimResult> = self.trims.iter().filter(|t| share(t) > 0.0).collect();
            if let Some(worst) = flagged.iter().max_by(|a, b| share(a).total_cmp(&share(b))) {
                notes.push(format!(
                    "note: {prefix}at {} of {n} speeds some blade-element lookups {meaning} \
                     (most: {:.1} % at {:.1} kt)",
                    flagged.len(),
                    100.0 * share(worst),
                    worst.airspeed_kt
                ));
            }
        }
        notes
    }
}

/// Speed sweeps of several sections, one after the other (each sweep runs its speeds in
/// parallel); `cases` names them.
pub fn sweep_cases<S: BladeSection + Sync>(
    aircraft: &Aircraft,
    sections: &[&S],
    cases: &[&str],
    speeds_kt: &[f64],
) -> Vec<SpeedSweep> {
    sections
        .iter()
        .zip(cases)
        .map(|(s, case)| SpeedSweep::run(aircraft, *s, speeds_kt, Some(case)))
        .collect()
}

/// Blade α(ψ) at radius fraction `r_over_r` in trimmed level flight at `speed_kt` (ISA sea
/// level), `samples` azimuths, for each section in parallel; `cases` names them.
pub fn blade_alpha_cases<S: BladeSection + Sync>(
    aircraft: &Aircraft,
    sections: &[&S],
    cases: &[&str],
    speed_kt: f64,
    r_over_r: f64,
    samples: usize,
) -> Result<Vec<BladeAlpha>, StudyError> {
    sections
        .par_iter()
        .zip(cases)
        .map(|(s, case)| {
            cruise_blade_alpha(
                aircraft,
                *s,
                speed_kt,
                0.0,
                r_over_r,
                samples,
                &TrimParams::default(),
            )
            .map_err(|source| StudyError::Trim {
                case: case.to_string(),
                source,
            })
        })
        .collect()
}

/// The takeoff with each section, in parallel; `cases` names them.
pub fn takeoff_cases<S: BladeSection + Sync>(
    aircraft: &Aircraft,
    sections: &[&S],
    cases: &[&str],
) -> Result<Vec<TakeoffResult>, StudyError> {
    sections
        .par_iter()
        .zip(cases)
        .map(|(s, case)| {
            simulate_takeoff(aircraft, *s).map_err(|source| StudyError::Takeoff {
                case: case.to_string(),
                source,
            })
        })
        .collect()
}
