//! The files of a study under `--out`: its CSV table and its figures (SVG and PNG), written
//! together or not at all ([`OutputSet`]).

use super::StudiesError;
use crate::output::{check_output_path, OutputError, OutputSet};
use crate::plot::{render_into_set, Figure, Marker, Panel};
use serde::de::{Deserializer, MapAccess, Visitor};
use serde::{Deserialize, Serialize};
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

/// `records` as CSV: one column per serde key of the record type, in the order the record
/// serializes them (the JSON key order, flattened parts in place), so that the columns and the
/// JSON keys cannot differ. `null` is an empty field; no records give an empty text.
pub(crate) fn records_csv<T: Serialize>(records: &[T]) -> Result<String, StudiesError> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header: Option<Vec<String>> = None;
    for r in records {
        let fields = fields_in_order(r)?;
        let keys: Vec<&str> = fields.iter().map(|(k, _)| k.as_str()).collect();
        match &header {
            None => {
                w.write_record(&keys).map_err(StudiesError::Csv)?;
                header = Some(keys.iter().map(|k| k.to_string()).collect());
            }
            Some(h) if *h != keys => {
                return Err(StudiesError::BadSetting(format!(
                    "record keys {keys:?} differ from the header {h:?}"
                )))
            }
            Some(_) => {}
        }
        let cells = fields.iter().map(|(_, v)| match v {
            serde_json::Value::String(s) => s.clone(),
            serde_json::Value::Null => String::new(),
            v => v.to_string(),
        });
        w.write_record(cells).map_err(StudiesError::Csv)?;
    }
    let bytes = w
        .into_inner()
        .map_err(|e| StudiesError::Csv(csv::Error::from(e.into_error())))?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// The serde keys and values of `record` in the order it serializes them: its JSON text read
/// back entry by entry (a `serde_json::Map` would sort the keys).
fn fields_in_order<T: Serialize>(
    record: &T,
) -> Result<Vec<(String, serde_json::Value)>, StudiesError> {
    let bad = |e: serde_json::Error| StudiesError::BadSetting(format!("record: {e}"));
    let text = serde_json::to_string(record).map_err(bad)?;
    let InOrder(fields) = serde_json::from_str(&text).map_err(bad)?;
    Ok(fields)
}

/// The entries of a JSON object in their order.
struct InOrder(Vec<(String, serde_json::Value)>);

impl<'de> Deserialize<'de> for InOrder {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Entries;
        impl<'de> Visitor<'de> for Entries {
            type Value = InOrder;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a record (a JSON object)")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<InOrder, A::Error> {
                let mut entries = Vec::new();
                while let Some(entry) = map.next_entry()? {
                    entries.push(entry);
                }
                Ok(InOrder(entries))
            }
        }
        deserializer.deserialize_map(Entries)
    }
}

/// The flight-test band `(centre, half width)` as three horizontal lines on `panel` (for an x
/// axis that is not airspeed: every setting is at the flight test's 60 kt).
pub(crate) fn band_markers(panel: Panel, (centre, half): (f64, f64)) -> Panel {
    panel
        .with_marker(Marker::hline(centre, flight_test_label(centre), 1))
        .with_marker(Marker::hline(centre - half, band_label(half), 7))
        .with_marker(Marker::hline(centre + half, "", 7))
}

/// Legend of the flight test's Δ engine rpm (paper Table 2, at 60 kt).
pub(crate) fn flight_test_label(centre: f64) -> String {
    format!("flight test ≈ +{centre} at 60 kt (paper Table 2)")
}

/// Legend of the band drawn around it: an assumed tachometer reading band, not a measured one.
pub(crate) fn band_label(half: f64) -> String {
    format!("± {half}: assumed reading band")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Serialize)]
    struct Inner {
        b: f64,
        c: Option<f64>,
    }

    #[derive(Serialize)]
    struct Record {
        z: String,
        #[serde(flatten)]
        inner: Inner,
        a: bool,
    }

    /// Columns in declaration order (not sorted), the flattened part in place, `null` empty.
    #[test]
    fn columns_follow_the_record() {
        let records = [
            Record {
                z: "x, y".into(),
                inner: Inner { b: 1.0, c: None },
                a: true,
            },
            Record {
                z: "w".into(),
                inner: Inner {
                    b: 0.1 + 0.2,
                    c: Some(-2.5e-7),
                },
                a: false,
            },
        ];
        assert_eq!(
            records_csv(&records).unwrap(),
            "z,b,c,a\n\"x, y\",1.0,,true\nw,0.30000000000000004,-2.5e-7,false\n"
        );
        assert_eq!(records_csv::<Record>(&[]).unwrap(), "");
    }
}
