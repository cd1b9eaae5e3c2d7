//! The index of a batch run: one row per airfoil (name, input, points, converged points,
//! seconds, status), written as CSV and JSON, and the summary of every polar of every table
//! written (`polargen summary`'s columns, `airfoil` the name in the batch) as
//! `<index>-summary.csv` and `.json`, all four together through an
//! [`OutputSet`](crate::output::OutputSet), so that an interrupted run leaves a complete set
//! of files describing the tables written so far.

use crate::output::{OutputError, OutputSet};
use crate::table::{summary_csv, summary_json, SummaryRow};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// What became of one airfoil of a batch.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TableStatus {
    /// Not solved yet (an interrupted run leaves these).
    Pending,
    /// Solved in this run and written.
    Solved,
    /// A valid table of the same grid and settings was found and kept (`--resume`).
    Kept,
    /// No table written: the reason (no point converged, the solver could not start).
    Failed(String),
}

impl std::fmt::Display for TableStatus {
    /// `pending`, `solved`, `kept` or `failed: <reason>`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Pending => f.write_str("pending"),
            Self::Solved => f.write_str("solved"),
            Self::Kept => f.write_str("kept"),
            Self::Failed(why) => write!(f, "failed: {why}"),
        }
    }
}

/// The index columns, in the order of [`IndexRow`]'s fields.
const COLUMNS: [&str; 6] = [
    "airfoil",
    "file",
    "points",
    "converged",
    "seconds",
    "status",
];

/// One row of the index.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct IndexRow {
    /// The airfoil's name in the batch: its file stem, also the table's file stem.
    pub airfoil: String,
    /// The input as found: a coordinate file's path or an airfoil name.
    pub file: String,
    /// Points in the table (0 when none was written).
    pub points: usize,
    /// Converged points in the table.
    pub converged: usize,
    /// Wall-clock seconds of the solve (0 for a kept or pending table), rounded to 0.01 s.
    pub seconds: f64,
    /// [`TableStatus`] as text.
    #[serde(serialize_with = "as_text")]
    pub status: TableStatus,
    /// The summary of each polar of the table (none without a table), in the summary files.
    #[serde(skip)]
    pub summary: Vec<SummaryRow>,
}

/// Serialise through `Display`.
fn as_text<S: serde::Serializer>(v: &TableStatus, s: S) -> Result<S::Ok, S::Error> {
    s.collect_str(v)
}

/// The index file stem: `index`, or `index-K-of-N` for shard K of N (shards never collide).
pub(crate) fn index_stem(shard: Option<(usize, usize)>) -> String {
    match shard {
        Some((k, n)) => format!("index-{k}-of-{n}"),
        None => "index".to_string(),
    }
}

/// Whether an airfoil called `name` would be written over an index file of some batch (an
/// index or its summary).
pub(crate) fn is_index_name(name: &str) -> bool {
    let name = name.strip_suffix(SUMMARY_SUFFIX).unwrap_or(name);
    let numbers = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    name == "index"
        || name
            .strip_prefix("index-")
            .and_then(|rest| rest.split_once("-of-"))
            .is_some_and(|(k, n)| numbers(k) && numbers(n))
}

/// What the summary files add to the index stem.
const SUMMARY_SUFFIX: &str = "-summary";

/// Write `rows` as `<stem>.csv` and `<stem>.json` in `dir`, and their polars' summaries as
/// `<stem>-summary.csv` and `.json`, together; returns the index CSV's path.
pub(crate) fn write_index(
    dir: &Path,
    stem: &str,
    rows: &[IndexRow],
) -> Result<PathBuf, OutputError> {
    let csv_path = dir.join(format!("{stem}.csv"));
    let json_path = dir.join(format!("{stem}.json"));
    let mut set = OutputSet::new();
    set.write(&csv_path, |w| {
        // The header by hand: serde writes it only with the first row.
        let mut out = csv::WriterBuilder::new().has_headers(false).from_writer(w);
        out.write_record(COLUMNS)
            .map_err(|e| csv_error(&csv_path, e))?;
        for row in rows {
            out.serialize(row).map_err(|e| csv_error(&csv_path, e))?;
        }
        out.flush().map_err(|e| OutputError::io(&csv_path, e))
    })?;
    set.write(&json_path, |w| {
        serde_json::to_writer_pretty(&mut *w, rows)
            .map_err(|e| OutputError::io(&json_path, e.into()))?;
        w.write_all(b"\n")
            .map_err(|e| OutputError::io(&json_path, e))
    })?;
    let summaries: Vec<SummaryRow> = rows.iter().flat_map(|r| r.summary.clone()).collect();
    for (ext, text) in [
        ("csv", summary_csv(&summaries)),
        ("json", summary_json(&summaries)),
    ] {
        let path = dir.join(format!("{stem}{SUMMARY_SUFFIX}.{ext}"));
        set.write(&path, |w| {
            w.write_all(text.as_bytes())
                .map_err(|e| OutputError::io(&path, e))
        })?;
    }
    set.commit()?;
    Ok(csv_path)
}

/// A CSV writer error as an [`OutputError`] naming `path`.
fn csv_error(path: &Path, e: csv::Error) -> OutputError {
    let text = e.to_string();
    match e.into_kind() {
        csv::ErrorKind::Io(io) => OutputError::io(path, io),
        _ => OutputError::io(path, std::io::Error::other(text)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_names_are_recognised() {
        assert_eq!(index_stem(Some((2, 8))), "index-2-of-8");
        for name in [
            "index",
            "index-1-of-2",
            "index-10-of-12",
            "index-summary",
            "index-3-of-4-summary",
        ] {
            assert!(is_index_name(name), "{name}");
        }
        for name in [
            "indexer",
            "index-1",
            "index-a-of-2",
            "index-1-of-",
            "naca0012",
        ] {
            assert!(!is_index_name(name), "{name}");
        }
    }
}
