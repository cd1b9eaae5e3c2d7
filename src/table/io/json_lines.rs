//! JSON Lines: the CSV's rows as flat JSON records, one per line — the form pandas reads in
//! one call (`pandas.read_json(path, lines=True)`), with the CSV's column names and order.
//!
//! Each field is written as its JSON type: `airfoil` and `solver` as strings, `true`/`false`
//! as booleans, an empty field (an unknown supercritical flag) and a non-finite number (NaN,
//! ±∞) as `null` — pandas reads it as NaN —, every other field as a number (integers without a
//! fraction). Reading converts the records back to the CSV's fields and takes them through
//! the CSV reader, so both accept the same tables; a `null` number reads as NaN (an ∞ of a
//! `cpmin` where the compressibility correction broke down comes back NaN, the one value
//! this form does not keep).

use super::csv::{for_each_record, parse_csv};
use crate::output::write_output;
use crate::table::{PolarTable, TableError};
use serde_json::{Map, Number, Value};
use std::io::Write;
use std::path::Path;

/// Columns written as JSON strings (every other field is a number, a boolean or null).
const TEXT_COLUMNS: [&str; 2] = ["airfoil", "solver"];

/// Columns whose empty field means "unknown" (null), not a number.
const FLAG_COLUMNS: [&str; 1] = ["supercritical"];

/// The JSON value of CSV field `text` of column `name`.
fn value(name: &str, text: &str) -> Value {
    if TEXT_COLUMNS.contains(&name) {
        return Value::String(text.to_string());
    }
    match text {
        "true" => Value::Bool(true),
        "false" => Value::Bool(false),
        _ => match (text.parse::<i64>(), text.parse::<f64>()) {
            (Ok(i), _) => Value::Number(i.into()),
            (_, Ok(v)) => Number::from_f64(v).map_or(Value::Null, Value::Number),
            _ => Value::Null,
        },
    }
}

/// Write `table` as JSON Lines to `w`.
pub fn write_json_lines_to(table: &PolarTable, w: &mut dyn Write) -> Result<(), TableError> {
    let mut names: Vec<String> = Vec::new();
    for_each_record(table, |fields| {
        if names.is_empty() {
            names = fields.iter().map(|f| f.to_string()).collect();
            return Ok(());
        }
        // By hand, to keep the CSV's column order (a serde_json map sorts its keys).
        let members: Vec<String> = names
            .iter()
            .zip(fields)
            .map(|(n, f)| format!("{}:{}", Value::String(n.clone()), value(n, f)))
            .collect();
        writeln!(w, "{{{}}}", members.join(",")).map_err(TableError::Write)
    })
}

/// Write `table` as JSON Lines to `path` (atomically).
pub fn write_json_lines(table: &PolarTable, path: &Path) -> Result<(), TableError> {
    write_output(path, |w| {
        write_json_lines_to(table, w).map_err(|e| e.in_output(path))
    })
}

/// Parse a table from JSON Lines (the keys of the first record are the columns; every
/// record must have them).
pub fn parse_json_lines(text: &str) -> Result<PolarTable, TableError> {
    let mut csv = csv::Writer::from_writer(Vec::new());
    let mut names: Vec<String> = Vec::new();
    let werr = |e: csv::Error| TableError::JsonTable(e.to_string());
    for (k, line) in text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
    {
        let error = |message: String| TableError::Json {
            line: k + 1,
            column: 1,
            message,
        };
        let record: Map<String, Value> =
            serde_json::from_str(line).map_err(|e| error(e.to_string()))?;
        if names.is_empty() {
            names = record.keys().cloned().collect();
            csv.write_record(&names).map_err(werr)?;
        }
        let fields = names
            .iter()
            .map(|n| match record.get(n) {
                Some(Value::String(s)) => Ok(s.clone()),
                Some(Value::Bool(b)) => Ok(b.to_string()),
                Some(Value::Number(v)) => Ok(v.to_string()),
                Some(Value::Null) if FLAG_COLUMNS.contains(&n.as_str()) => Ok(String::new()),
                Some(Value::Null) => Ok("NaN".to_string()),
                Some(other) => Err(error(format!("'{n}' is {other}, not a field"))),
                None => Err(error(format!("no '{n}' in this record"))),
            })
            .collect::<Result<Vec<String>, TableError>>()?;
        csv.write_record(&fields).map_err(werr)?;
    }
    let bytes = csv
        .into_inner()
        .map_err(|e| TableError::JsonTable(e.to_string()))?;
    parse_csv(bytes.as_slice())
}
