//! JSON: the serde form of a [`PolarTable`] (metadata, axes, Re-major polars, post-stall
//! parameters), pretty-printed. Non-finite values of unconverged points are written as the
//! strings `"NaN"`, `"inf"`, `"-inf"`.

use crate::output::write_output;
use crate::table::{PolarTable, TableError};
use std::io::Write;
use std::path::Path;

/// Write `table` as JSON to `w`.
pub fn write_json_to(table: &PolarTable, w: &mut dyn Write) -> Result<(), TableError> {
    serde_json::to_writer_pretty(&mut *w, table).map_err(|e| {
        if e.is_io() {
            TableError::Write(e.into())
        } else {
            json_error(&e)
        }
    })?;
    w.write_all(b"\n").map_err(TableError::Write)
}

/// Write `table` as JSON to `path` (atomically).
pub fn write_json(table: &PolarTable, path: &Path) -> Result<(), TableError> {
    write_output(path, |w| {
        write_json_to(table, w).map_err(|e| e.in_output(path))
    })
}

/// Parse a table from JSON text (validated like [`PolarTable::new`], and a table computed by
/// polargen must keep every α in every polar: [`PolarTable::require_every_alpha`]).
pub fn parse_json(text: &str) -> Result<PolarTable, TableError> {
    serde_json::from_str::<PolarTable>(text)
        .map_err(|e| json_error(&e))?
        .require_every_alpha()
}

/// A serde_json error as a one-line [`TableError::Json`].
fn json_error(e: &serde_json::Error) -> TableError {
    let full = e.to_string();
    if e.line() == 0 {
        return TableError::JsonTable(full);
    }
    // serde_json appends " at line L column C"; the position is reported separately.
    let message = match full.rfind(" at line ") {
        Some(i) => full[..i].to_string(),
        None => full,
    };
    TableError::Json {
        line: e.line(),
        column: e.column(),
        message: message.replace('\n', " "),
    }
}
