//! Errors of table construction, lookup setup and file input/output.

use crate::limits::short_number;
use std::path::PathBuf;
use thiserror::Error;

/// Why a table could not be built, read or written. Every message is one line naming the
/// problem.
#[derive(Debug, Error)]
pub enum TableError {
    /// An axis (Re or Mach) has no values.
    #[error("table has no {0} values")]
    EmptyAxis(&'static str),
    /// An axis is not strictly increasing.
    #[error("{axis} axis is not strictly increasing: {} follows {}", short_number(*value), short_number(*previous))]
    AxisOrder {
        /// `Re` or `Mach`.
        axis: &'static str,
        /// The earlier value.
        previous: f64,
        /// The value that is not larger.
        value: f64,
    },
    /// A Reynolds number is not a positive finite number.
    #[error(
        "Re must be positive and at most {}, got {}",
        short_number(crate::table::MAX_RE),
        short_number(*.0)
    )]
    BadRe(f64),
    /// A Mach number is outside [0, 1).
    #[error("Mach must be in [0, 1), got {}", short_number(*.0))]
    BadMach(f64),
    /// The number of polars does not match the Re × Mach grid.
    #[error("ragged grid: {n_re} Re × {n_mach} Mach needs {expected} polars, got {got}")]
    Ragged {
        /// Re count.
        n_re: usize,
        /// Mach count.
        n_mach: usize,
        /// n_re · n_mach.
        expected: usize,
        /// Polars supplied.
        got: usize,
    },
    /// A (Re, M) node of the grid has no polar.
    #[error("ragged grid: no polar at Re {}, M {}", short_number(*re), short_number(*mach))]
    MissingPolar {
        /// Reynolds number of the empty node.
        re: f64,
        /// Mach number of the empty node.
        mach: f64,
    },
    /// The same (Re, M) node was given twice.
    #[error("duplicate polar at Re {}, M {}", short_number(*re), short_number(*mach))]
    DuplicatePolar {
        /// Reynolds number.
        re: f64,
        /// Mach number.
        mach: f64,
    },
    /// The same α appears twice in one polar.
    #[error("duplicate alpha {} in polar Re {}, M {}", short_number(*alpha), short_number(*re), short_number(*mach))]
    DuplicateAlpha {
        /// Reynolds number.
        re: f64,
        /// Mach number.
        mach: f64,
        /// Repeated α (deg).
        alpha: f64,
    },
    /// A converged point (or any α) holds NaN or infinity, or α is outside ±180°.
    #[error("{field} is {} at Re {}, M {}, alpha {} (must be finite)", short_number(*value), short_number(*re), short_number(*mach), short_number(*alpha))]
    NotFinite {
        /// Column name.
        field: &'static str,
        /// The bad value.
        value: f64,
        /// Reynolds number.
        re: f64,
        /// Mach number.
        mach: f64,
        /// α (deg).
        alpha: f64,
    },
    /// α outside [−180°, 180°].
    #[error("alpha {} outside [-180, 180] in polar Re {}, M {}", short_number(*alpha), short_number(*re), short_number(*mach))]
    AlphaRange {
        /// Reynolds number.
        re: f64,
        /// Mach number.
        mach: f64,
        /// α (deg).
        alpha: f64,
    },
    /// A converged point with negative drag (no physical section has it).
    #[error("cd {} < 0 at alpha {} in polar Re {}, M {}", short_number(*cd), short_number(*alpha), short_number(*re), short_number(*mach))]
    NegativeDrag {
        /// Reynolds number.
        re: f64,
        /// Mach number.
        mach: f64,
        /// α (deg).
        alpha: f64,
        /// The drag coefficient.
        cd: f64,
    },
    /// A metadata field is outside its range (NaN, a negative transition setting, …).
    #[error("table {field} = {value} is invalid (must be {rule})")]
    BadMeta {
        /// Field name.
        field: &'static str,
        /// The value as text (numbers in short form).
        value: String,
        /// The allowed range.
        rule: &'static str,
    },
    /// A polar without any point.
    #[error("polar Re {}, M {} has no points", short_number(*re), short_number(*mach))]
    EmptyPolar {
        /// Reynolds number.
        re: f64,
        /// Mach number.
        mach: f64,
    },
    /// A table holds more points than [`MAX_TABLE_POINTS`](crate::limits::MAX_TABLE_POINTS).
    #[error("table of {points} points: more than the {limit} a table may hold (docs/limits.md)")]
    TooManyPoints {
        /// Points of the table.
        points: usize,
        /// The limit.
        limit: usize,
    },
    /// A polar of a table computed by polargen lacks α values its other polars have.
    #[error(
        "polar Re {}, M {} has {got} alpha values where the table's first polar has {expected} \
         and ends at alpha {}: a table computed by polargen keeps every alpha in every polar, \
         so the file is cut short or was edited",
        short_number(*re),
        short_number(*mach),
        short_number(*last_alpha)
    )]
    AlphaListDiffers {
        /// Reynolds number of the polar.
        re: f64,
        /// Mach number of the polar.
        mach: f64,
        /// Its α values.
        got: usize,
        /// The α values of the first polar.
        expected: usize,
        /// Its last α.
        last_alpha: f64,
    },
    /// The file a writer would produce is larger than polargen reads back.
    #[error(
        "the {format} file would be larger than {limit_mib} MiB, the most polargen reads back \
         (docs/limits.md); nothing written: write fewer points or another format"
    )]
    TooLargeToReadBack {
        /// Format name.
        format: &'static str,
        /// The read limit in MiB.
        limit_mib: u64,
    },
    /// The transition location of a converged point is not a chord fraction.
    #[error(
        "{field} = {} at alpha {} in polar Re {}, M {} is not a chord fraction in [0, 1]",
        short_number(*value),
        short_number(*alpha),
        short_number(*re),
        short_number(*mach)
    )]
    TransitionRange {
        /// Column name.
        field: &'static str,
        /// The value.
        value: f64,
        /// Reynolds number.
        re: f64,
        /// Mach number.
        mach: f64,
        /// Angle of attack.
        alpha: f64,
    },
    /// A converged coefficient beyond what any section produces.
    #[error(
        "{field} = {} at alpha {} in polar Re {}, M {} is beyond the plausible range \
         (|{field}| <= {})",
        short_number(*value),
        short_number(*alpha),
        short_number(*re),
        short_number(*mach),
        short_number(*bound)
    )]
    Implausible {
        /// Column name.
        field: &'static str,
        /// The value.
        value: f64,
        /// Its bound.
        bound: f64,
        /// Reynolds number.
        re: f64,
        /// Mach number.
        mach: f64,
        /// α (deg).
        alpha: f64,
    },
    /// A 360°-extension parameter is out of its range.
    #[error("post-stall parameter {name} = {} is invalid (must be {rule})", short_number(*value))]
    BadPostStall {
        /// Field name.
        name: &'static str,
        /// The value.
        value: f64,
        /// The allowed range.
        rule: &'static str,
    },
    /// No polar of the table has the two usable points (converged, not in massive
    /// separation) a lookup needs.
    #[error(
        "empty table: no polar has at least 2 converged points outside massive separation \
         (docs/limits.md)"
    )]
    Empty,
    /// The table's α range misses part of the attached-flow range a rotor, propeller or wing
    /// section works in ([`LOOKUP_ALPHA_COVER_DEG`](crate::table::LOOKUP_ALPHA_COVER_DEG)).
    #[error(
        "its α spans only {}…{}°: a rotor, propeller or wing needs the section from {}° to at \
         least {}° from the table, not from the post-stall extension{}",
        short_number(*low),
        short_number(*high),
        crate::table::LOOKUP_ALPHA_COVER_DEG.0,
        crate::table::LOOKUP_ALPHA_COVER_DEG.1,
        if high.abs().max(low.abs()) <= std::f64::consts::FRAC_PI_2 {
            " (α in radians? the table's α must be in degrees)"
        } else {
            ""
        }
    )]
    AlphaCover {
        /// Smallest α of the table \[deg\].
        low: f64,
        /// Largest α of the table \[deg\].
        high: f64,
    },
    /// A CSV record could not be parsed.
    #[error("CSV line {line}: {message}")]
    Csv {
        /// 1-based line number in the file.
        line: u64,
        /// What is wrong.
        message: String,
    },
    /// A JSON or XFOIL polar file is not UTF-8 text.
    #[error("not UTF-8 text")]
    NotText,
    /// A CSV header names neither a polargen table nor a single polar.
    #[error(
        "CSV header lacks column '{0}' of a polargen table and the columns alpha, cl, cd of a \
         single polar"
    )]
    CsvLayout(&'static str),
    /// The CSV header lacks a required column.
    #[error("CSV header lacks column '{0}'")]
    MissingColumn(String),
    /// The JSON text is malformed or does not describe a valid table.
    #[error("JSON line {line}, column {column}: {message}")]
    Json {
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// The JSON text is well formed but does not describe a valid table (the check names
    /// what is wrong; serde gives it no position).
    #[error("JSON table: {0}")]
    JsonTable(String),
    /// An XFOIL polar file could not be parsed.
    #[error("XFOIL polar line {line}: {message}")]
    Polar {
        /// 1-based line number.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// The output format cannot be inferred from a file name.
    #[error("cannot infer table format from '{0}' (use .csv, .json, .jsonl, .pol or .c81)")]
    UnknownExtension(String),
    /// An explicit format name is not known.
    #[error("unknown table format '{0}' (expected csv, json, jsonl, xfoil, c81 or aerodyn)")]
    UnknownFormat(String),
    /// A format that writes several files was asked to write to standard output.
    #[error("{format} writes one file per {per}: give a file name, not standard output")]
    NeedsFile {
        /// The format's command-line name.
        format: &'static str,
        /// What each file holds (`polar`, `Re`, `Mach number`).
        per: &'static str,
    },
    /// A format's header needs a number the table does not know.
    #[error(
        "{field} is unknown (the table was read from a file without it): {format} needs a number"
    )]
    UnknownInHeader {
        /// The metadata field.
        field: &'static str,
        /// The format, as in a sentence.
        format: &'static str,
    },
    /// An AeroDyn airfoil file does not follow the format.
    #[error("AeroDyn line {line}: {message}")]
    AeroDyn {
        /// Line number (1-based).
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// The tables of an AeroDyn file cannot make one table.
    #[error("AeroDyn file: {0}")]
    AeroDynTables(String),
    /// A C81 file does not follow the format.
    #[error("C81 line {line}: {message}")]
    C81 {
        /// Line number (1-based).
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A C81 table would exceed the format's 2-digit counts.
    #[error("C81 table needs {count} {what} but the format allows at most 99")]
    C81TooLarge {
        /// `alpha rows` or `Mach columns`.
        what: &'static str,
        /// Count needed.
        count: usize,
    },
    /// A positive header value prints as zero in the XFOIL polar header.
    #[error(
        "{field} = {} is below the resolution of the XFOIL polar header (it would read back as 0)",
        short_number(*value)
    )]
    HeaderResolution {
        /// `Re`, `ncrit`, `ncrit_top` or `ncrit_bot`.
        field: &'static str,
        /// The value.
        value: f64,
    },
    /// A value does not fit a fixed-width field of a text format.
    #[error("value {} does not fit a {width}-character field", short_number(*value))]
    FieldOverflow {
        /// The value.
        value: f64,
        /// Field width.
        width: usize,
    },
    /// Writing an output file failed.
    #[error(transparent)]
    Output(#[from] crate::output::OutputError),
    /// Writing into an output stream failed (before it is known which file the stream is;
    /// the writers turn it into [`TableError::Output`] naming the file).
    #[error("write failed: {0}")]
    Write(#[source] std::io::Error),
    /// An input file is missing, not a regular file, too large or unreadable.
    #[error("cannot read table {}: {}", .0.path.display(), .0.problem)]
    Input(#[source] crate::input::InputError),
    /// The content of the table file `path` is wrong.
    #[error("{path}: {source}")]
    File {
        /// The file.
        path: PathBuf,
        /// What is wrong in it.
        source: Box<TableError>,
    },
    /// Reading a file failed.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating-system error.
        source: std::io::Error,
    },
}

impl TableError {
    /// This error with a failed stream write ([`TableError::Write`]) attributed to the output
    /// file `path`, as the user named it.
    pub fn in_output(self, path: &std::path::Path) -> Self {
        match self {
            Self::Write(source) => Self::Output(crate::output::OutputError::io(path, source)),
            other => other,
        }
    }

    /// Wrap an I/O error with the path it concerns.
    pub fn io(path: impl Into<PathBuf>, source: std::io::Error) -> Self {
        Self::Io {
            path: path.into(),
            source,
        }
    }
}
