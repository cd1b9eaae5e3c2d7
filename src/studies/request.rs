//! One study as a command line asks for it, run end to end: check the settings and the output
//! folder, load the aircraft, solve or read the tables, run, write the files, and hand back the
//! text table or the JSON records to print.

use super::{airfoil, contamination, speed, wing};
use super::{check_study_out, command_line_cache, StudiesError, StudyFiles, TableCache};
use crate::progress::Progress;
use crate::rotor::Aircraft;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Which study, with its settings.
#[derive(Clone, Debug)]
pub enum StudyKind {
    /// Trip location, one surface, N_crit and spanwise coverage of one airfoil.
    Contamination {
        /// Airfoil name or coordinate file.
        airfoil: String,
        /// The settings besides the clean reference.
        options: contamination::ContaminationOptions,
    },
    /// Each airfoil clean and tripped at 7 % chord.
    Airfoil {
        /// Airfoil names or coordinate files (at least one).
        airfoils: Vec<String>,
    },
    /// The contamination penalty against airspeed.
    Speed {
        /// Airfoil name or coordinate file.
        airfoil: String,
        /// Trip location x/c on both surfaces.
        xtr: f64,
        /// Airspeeds \[kt\].
        speeds_kt: Vec<f64>,
    },
    /// The aircraft's wing scaled to several areas, trimmed at several airspeeds.
    Wing(wing::WingOptions),
}

/// A study run: what, on which aircraft, where the files and the table cache go.
#[derive(Clone, Debug)]
pub struct StudyRequest {
    /// The study and its settings.
    pub kind: StudyKind,
    /// The aircraft (loaded by the caller: a preset file, or a built-in one).
    pub aircraft: Aircraft,
    /// Folder for the CSV table and the figures (all or none), if any.
    pub out: Option<PathBuf>,
    /// Table cache folder (else [`default_cache_dir`](super::default_cache_dir)).
    pub cache: Option<PathBuf>,
    /// JSON records instead of the text table.
    pub json: bool,
}

/// What a finished study hands back to print.
#[derive(Clone, Debug, Default)]
pub struct StudyOutcome {
    /// The text table or the JSON records (per [`StudyRequest::json`]).
    pub stdout: String,
    /// Files written under `out`.
    pub written: Vec<PathBuf>,
    /// Settings that produced no result, and why.
    pub notes: Vec<String>,
}

/// Records as a pretty JSON array with a final newline.
pub fn records_json<T: Serialize>(records: &[T]) -> String {
    let mut s = serde_json::to_string_pretty(records).unwrap_or_else(|_| "[]".into());
    s.push('\n');
    s
}

impl StudyRequest {
    /// Checks the settings, the output folder and the cache folder (before any work; also the
    /// first thing [`run`](Self::run) does).
    pub fn check(&self) -> Result<TableCache, StudiesError> {
        let (csv_stem, figures): (&str, &[&str]) = match &self.kind {
            StudyKind::Contamination { options, .. } => {
                options.settings()?;
                (contamination::CSV_STEM, &contamination::FIGURE_STEMS)
            }
            StudyKind::Airfoil { airfoils } => {
                if airfoils.iter().all(|a| a.trim().is_empty()) {
                    let e =
                        crate::arguments::ArgumentError::with_text("--airfoils", "", "empty list");
                    return Err(e.into());
                }
                (airfoil::CSV_STEM, &airfoil::FIGURE_STEMS)
            }
            StudyKind::Speed { .. } => (speed::CSV_STEM, &speed::FIGURE_STEMS),
            StudyKind::Wing(options) => {
                options.checked()?;
                (wing::CSV_STEM, &wing::FIGURE_STEMS)
            }
        };
        if let Some(dir) = &self.out {
            check_study_out(dir, csv_stem, figures)?;
        }
        command_line_cache(self.cache.clone())
    }

    /// Run the study, after [`check`](Self::check).
    pub fn run(&self, progress: &dyn Progress) -> Result<StudyOutcome, StudiesError> {
        let cache = self.check()?;
        let ac = &self.aircraft;
        let mut outcome = StudyOutcome::default();
        let (json, text, files) = match &self.kind {
            StudyKind::Contamination { airfoil, options } => {
                let s =
                    contamination::ContaminationStudy::run(ac, airfoil, options, &cache, progress)?;
                (
                    records_json(&s.records),
                    s.text(),
                    self.files(|| s.files())?,
                )
            }
            StudyKind::Airfoil { airfoils } => {
                let s = airfoil::AirfoilStudy::run(ac, airfoils, &cache, progress)?;
                (
                    records_json(&s.records),
                    s.text(),
                    self.files(|| s.files())?,
                )
            }
            StudyKind::Speed {
                airfoil,
                xtr,
                speeds_kt,
            } => {
                let s = speed::SpeedStudy::run(ac, airfoil, *xtr, speeds_kt, &cache, progress)?;
                outcome.notes = s.notes.clone();
                (
                    records_json(&s.records),
                    s.text(),
                    self.files(|| s.files())?,
                )
            }
            StudyKind::Wing(options) => {
                let s = wing::WingStudy::run(ac, options, &cache, progress)?;
                (
                    records_json(&s.records),
                    s.text(),
                    self.files(|| s.files())?,
                )
            }
        };
        outcome.written = files;
        outcome.notes.extend(cache.notes());
        outcome.stdout = if self.json { json } else { text };
        Ok(outcome)
    }

    /// Write the study's files under `out`, if asked.
    fn files(
        &self,
        files: impl FnOnce() -> Result<StudyFiles, StudiesError>,
    ) -> Result<Vec<PathBuf>, StudiesError> {
        self.out
            .as_deref()
            .map_or(Ok(Vec::new()), |dir: &Path| files()?.write(dir))
    }
}
