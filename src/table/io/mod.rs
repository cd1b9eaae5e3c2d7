//! Table files: CSV and JSON (written and read back exactly), XFOIL polar text (written, and
//! read as a one-polar table) and C81 (written).
//! Every writer goes through [`write_output`](crate::output::write_output), so a failure
//! never leaves half a file and missing folders are created.

pub mod c81;
pub mod csv;
pub mod json;
pub mod xfoil_polar;

use super::{PolarTable, TableError};
use std::path::{Path, PathBuf};
use std::str::FromStr;

pub use self::c81::C81Options;

/// A table file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TableFormat {
    /// Long-form CSV (`.csv`), readable.
    Csv,
    /// Serde JSON (`.json`), readable.
    Json,
    /// XFOIL polar text, one file per (Re, M) (`.pol`); readable as a one-polar table.
    XfoilPolar,
    /// C81 rotorcraft airfoil table, one file per Re (`.c81`).
    C81,
}

impl TableFormat {
    /// The format implied by a file's extension (case-insensitive: `.csv`, `.json`, `.pol`
    /// or `.polar`, `.c81`).
    pub fn from_path(path: &Path) -> Result<Self, TableError> {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase())
            .unwrap_or_default();
        match ext.as_str() {
            "csv" => Ok(Self::Csv),
            "json" => Ok(Self::Json),
            "pol" | "polar" => Ok(Self::XfoilPolar),
            "c81" => Ok(Self::C81),
            _ => Err(TableError::UnknownExtension(path.display().to_string())),
        }
    }

    /// Lower-case name as used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Self::Csv => "csv",
            Self::Json => "json",
            Self::XfoilPolar => "xfoil",
            Self::C81 => "c81",
        }
    }
}

impl FromStr for TableFormat {
    type Err = TableError;

    /// Parse `csv`, `json`, `xfoil` (or `pol`) or `c81`, case-insensitive.
    fn from_str(s: &str) -> Result<Self, TableError> {
        match s.to_ascii_lowercase().as_str() {
            "csv" => Ok(Self::Csv),
            "json" => Ok(Self::Json),
            "xfoil" | "pol" | "polar" => Ok(Self::XfoilPolar),
            "c81" => Ok(Self::C81),
            _ => Err(TableError::UnknownFormat(s.to_string())),
        }
    }
}

/// Write `table` to `path` in `format` (inferred from the extension when `None`); C81 files
/// use the default [`C81Options`]. Returns the files written (several for XFOIL polars of a
/// multi-polar table and for C81 of a multi-Re table).
pub fn write_table(
    table: &PolarTable,
    path: &Path,
    format: Option<TableFormat>,
) -> Result<Vec<PathBuf>, TableError> {
    let format = match format {
        Some(f) => f,
        None => TableFormat::from_path(path)?,
    };
    match format {
        TableFormat::Csv => csv::write_csv(table, path).map(|()| vec![path.to_path_buf()]),
        TableFormat::Json => json::write_json(table, path).map(|()| vec![path.to_path_buf()]),
        TableFormat::XfoilPolar => xfoil_polar::write_xfoil_polars(table, path),
        TableFormat::C81 => c81::write_c81(table, path, &C81Options::default()),
    }
}

/// Read a table from a CSV, JSON or XFOIL polar file (format from the extension; a polar
/// file gives a one-polar table).
pub fn read_table(path: &Path) -> Result<PolarTable, TableError> {
    match TableFormat::from_path(path)? {
        TableFormat::Csv => csv::read_csv(path),
        TableFormat::Json => json::read_json(path),
        TableFormat::XfoilPolar => xfoil_polar::read_xfoil_polar(path),
        TableFormat::C81 => Err(TableError::NotReadable("C81")),
    }
}
