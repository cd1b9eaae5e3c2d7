//! The files of a study under `--out`: its CSV table and its figures (SVG and PNG), written
//! together or not at all ([`OutputSet`]).

use super::StudiesError;
use crate::output::{check_output_path, OutputError, OutputSet};
use crate::plot::{render_into_set, Figure, Marker, Panel};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Image formats of every study figure.
const FIGURE_FORMATS: [&str; 2] = ["svg", "png"];

/// A study's output: one CSV file and its figures, by file stem.
pub struct StudyFiles {
    /// Stem of the CSV file (`<stem>.csv`).
    pub csv_stem: String,
    /// The CSV text.
    pub csv: String,
    /// Figures by stem (`<stem>.svg`, `<stem>.png`).
    pub figures: Vec<(String, Figure)>,
}

impl StudyFiles {
    /// The paths the files get under `dir`.
    pub fn paths(&self, dir: &Path) -> Vec<PathBuf> {
        study_paths(
            dir,
            &self.csv_stem,
            self.figures.iter().map(|f| f.0.as_str()),
        )
    }

    /// Write every file under `dir`, all together or none; returns the paths written.
    pub fn write(&self, dir: &Path) -> Result<Vec<PathBuf>, StudiesError> {
        let mut set = OutputSet::new();
        set.write(&dir.join(format!("{}.csv", self.csv_stem)), |w| {
            w.write_all(self.csv.as_bytes())
                .map_err(|e| OutputError::io(dir, e))
        })?;
        for (stem, fig) in &self.figures {
            for ext in FIGURE_FORMATS {
                render_into_set(fig, &dir.join(format!("{stem}.{ext}")), &mut set)?;
            }
        }
        Ok(set.commit()?)
    }
}

/// The files of a study with `csv_stem` and figure stems `figures` under `dir`.
fn study_paths<'a>(
    dir: &Path,
    csv_stem: &str,
    figures: impl Iterator<Item = &'a str>,
) -> Vec<PathBuf> {
    let mut paths = vec![dir.join(format!("{csv_stem}.csv"))];
    for stem in figures {
        paths.extend(
            FIGURE_FORMATS
                .iter()
                .map(|e| dir.join(format!("{stem}.{e}"))),
        );
    }
    paths
}

/// Check, before any computation, that the study files `csv_stem.csv` and
/// `<figure>.{svg,png}` can be written under `dir`.
pub fn check_study_out(dir: &Path, csv_stem: &str, figures: &[&str]) -> Result<(), StudiesError> {
    if dir.exists() && !dir.is_dir() {
        return Err(StudiesError::BadSetting(format!(
            "--out {}: exists and is not a folder",
            dir.display()
        )));
    }
    for p in study_paths(dir, csv_stem, figures.iter().copied()) {
        check_output_path(&p)?;
    }
    Ok(())
}

/// `records` as CSV with `columns` (their serde keys; nested records flattened), `null` as an
/// empty field.
pub(crate) fn records_csv<T: Serialize>(
    columns: &[&str],
    records: &[T],
) -> Result<String, StudiesError> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(columns).map_err(StudiesError::Csv)?;
    for r in records {
        let value = serde_json::to_value(r)
            .map_err(|e| StudiesError::BadSetting(format!("record: {e}")))?;
        let fields: Vec<String> = columns
            .iter()
            .map(|c| match value.get(*c) {
                Some(serde_json::Value::String(s)) => s.clone(),
                Some(serde_json::Value::Null) | None => String::new(),
                Some(v) => v.to_string(),
            })
            .collect();
        w.write_record(&fields).map_err(StudiesError::Csv)?;
    }
    let bytes = w
        .into_inner()
        .map_err(|e| StudiesError::Csv(csv::Error::from(e.into_error())))?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// The flight-test band `(centre, half width)` as three horizontal lines on `panel`.
pub(crate) fn band_markers(panel: Panel, (centre, half): (f64, f64)) -> Panel {
    panel
        .with_marker(Marker::hline(centre, format!("flight test +{centre}"), 1))
        .with_marker(Marker::hline(centre - half, format!("± {half}"), 7))
        .with_marker(Marker::hline(centre + half, "", 7))
}
