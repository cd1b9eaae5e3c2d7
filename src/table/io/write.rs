//! Writing a table: the files of each format for one table ([`write_table`], or staged with
//! other tables' files in one [`OutputSet`]: [`write_table_into`]), their names
//! ([`table_files`]) and the checks that they can be written, made before any solve.

use super::{aerodyn, c81, csv, json, json_lines, xfoil_polar, C81Options, TableFormat};
use crate::limits::MAX_INPUT_BYTES;
use crate::output::OutputSet;
use crate::table::{PolarTable, TableError};
use std::path::{Path, PathBuf};

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
    require_file_name(
        path,
        table_files(path, format, table.re(), table.mach()).len(),
    )?;
    if crate::output::names_a_file(path) {
        let mut set = OutputSet::new();
        let files = write_table_into(table, path, format, &mut set)?;
        set.commit()?;
        return Ok(files);
    }
    // A stream: the one file of a one-file table.
    check_readable_size(table, format)?;
    match format {
        TableFormat::Csv => csv::write_csv(table, path).map(|()| vec![path.to_path_buf()]),
        TableFormat::Json => json::write_json(table, path).map(|()| vec![path.to_path_buf()]),
        TableFormat::JsonLines => {
            json_lines::write_json_lines(table, path).map(|()| vec![path.to_path_buf()])
        }
        TableFormat::XfoilPolar => xfoil_polar::write_xfoil_polars(table, path),
        TableFormat::C81 => c81::write_c81(table, path, &C81Options::default()),
        TableFormat::AeroDyn => aerodyn::write_aerodyn(table, path),
    }
}

/// The files [`write_table`] writes for `table` at `path` (a file name, not a stream) in
/// `format`, staged in `set`: they appear when the set is committed, together with its other
/// files (the tables of a flap sweep), or not at all. Returns the files staged.
pub fn write_table_into(
    table: &PolarTable,
    path: &Path,
    format: TableFormat,
    set: &mut OutputSet,
) -> Result<Vec<PathBuf>, TableError> {
    check_readable_size(table, format)?;
    let one =
        |set: &mut OutputSet,
         write: fn(&PolarTable, &mut dyn std::io::Write) -> Result<(), TableError>| {
            set.write(path, |w| write(table, w).map_err(|e| e.in_output(path)))
                .map(|()| vec![path.to_path_buf()])
        };
    match format {
        TableFormat::Csv => one(set, csv::write_csv_to),
        TableFormat::Json => one(set, json::write_json_to),
        TableFormat::JsonLines => one(set, json_lines::write_json_lines_to),
        TableFormat::XfoilPolar => xfoil_polar::stage_xfoil_polars(table, path, set),
        TableFormat::C81 => c81::stage_c81(table, path, C81Options::default().outer_step_deg, set),
        TableFormat::AeroDyn => aerodyn::stage_aerodyn(table, path, set),
    }
}

/// Refuse, before anything is written, a CSV or JSON file of `table` larger than polargen
/// reads back ([`MAX_INPUT_BYTES`]): the file is produced once into a counting sink that stops
/// at the limit. XFOIL polars (one fixed-width file per polar of at most
/// [`MAX_TABLE_POINTS`](crate::limits::MAX_TABLE_POINTS) rows) and C81 decks (at most 99 × 99
/// rows) always fit; AeroDyn files are not read.
fn check_readable_size(table: &PolarTable, format: TableFormat) -> Result<(), TableError> {
    let mut sink = SizeLimit {
        written: 0,
        limit: MAX_INPUT_BYTES,
    };
    let result = match format {
        TableFormat::Csv => csv::write_csv_to(table, &mut sink),
        TableFormat::Json => json::write_json_to(table, &mut sink),
        TableFormat::JsonLines => json_lines::write_json_lines_to(table, &mut sink),
        TableFormat::XfoilPolar | TableFormat::C81 | TableFormat::AeroDyn => return Ok(()),
    };
    match result {
        Err(_) if sink.written > sink.limit => Err(TableError::TooLargeToReadBack {
            format: format.name(),
            limit_mib: MAX_INPUT_BYTES >> 20,
        }),
        other => other,
    }
}

/// A writer that counts the bytes given to it and fails once they pass `limit`.
struct SizeLimit {
    written: u64,
    limit: u64,
}

impl std::io::Write for SizeLimit {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.written += buf.len() as u64;
        if self.written > self.limit {
            return Err(std::io::Error::other("larger than the read limit"));
        }
        Ok(buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// The files [`write_table`] writes for a table of Reynolds numbers `re` × Mach numbers
/// `mach` in `format` at `path` (with the default [`C81Options`]).
pub fn table_files(path: &Path, format: TableFormat, re: &[f64], mach: &[f64]) -> Vec<PathBuf> {
    match format {
        TableFormat::Csv | TableFormat::Json | TableFormat::JsonLines => vec![path.to_path_buf()],
        TableFormat::XfoilPolar => re
            .iter()
            .flat_map(|&r| {
                mach.iter()
                    .map(move |&m| xfoil_polar::polar_path(path, re.len() * mach.len(), r, m))
            })
            .collect(),
        TableFormat::C81 => re
            .iter()
            .map(|&r| c81::re_path(path, re.len(), r))
            .collect(),
        TableFormat::AeroDyn => mach
            .iter()
            .map(|&m| aerodyn::mach_path(path, mach.len(), m))
            .collect(),
    }
}

/// Checks, before a table is solved, that every file [`table_files`] names can be written
/// ([`check_output_path`](crate::output::check_output_path)): a name too long for the file
/// system, a folder in the way or a folder that takes no files is found before the work.
pub fn check_table_output(
    path: &Path,
    format: TableFormat,
    re: &[f64],
    mach: &[f64],
) -> Result<(), crate::output::OutputError> {
    check_files(path, &table_files(path, format, re, mach))
}

/// The AeroDyn files [`write_aerodyn_flap_sweep`](super::write_aerodyn_flap_sweep) writes for a flap sweep over Reynolds
/// numbers `re` × Mach numbers `mach` at `path`: `path` itself for one (Re, M), else
/// `<stem>_Re<re>_M<mach>.<ext>` beside it, Re by Re.
pub fn flap_sweep_files(path: &Path, re: &[f64], mach: &[f64]) -> Vec<PathBuf> {
    aerodyn::flap_sweep_files(path, re, mach)
}

/// [`check_table_output`] for the files of [`flap_sweep_files`].
pub fn check_flap_sweep_output(
    path: &Path,
    re: &[f64],
    mach: &[f64],
) -> Result<(), crate::output::OutputError> {
    check_files(path, &flap_sweep_files(path, re, mach))
}

/// Every one of `files`, named after `path`, can be written.
fn check_files(path: &Path, files: &[PathBuf]) -> Result<(), crate::output::OutputError> {
    require_file_name(path, files.len())?;
    files
        .iter()
        .try_for_each(|f| crate::output::check_output_path(f))
}

/// A set of `count` files is named after `path`: refused when `path` is a stream or a device
/// (`/dev/null` would name files `/dev/null_Re1e6_M0.pol` beside the device).
fn require_file_name(path: &Path, count: usize) -> Result<(), crate::output::OutputError> {
    if count > 1 && !crate::output::names_a_file(path) {
        return Err(crate::output::OutputError::BadPath {
            path: path.to_path_buf(),
            reason: "is a stream or device: a set of files needs a file name to be named after",
        });
    }
    Ok(())
}
