//! Table files: CSV, JSON and JSON Lines (written and read back exactly), XFOIL polar text
//! (written, and read as a one-polar table), C81 (written, and read as a one-Re table),
//! OpenFAST AeroDyn airfoil files (written, and read as a one-Mach table) and single-polar CSV
//! (read). [`read_table`] is the one reader: it reads a file once and recognises its layout;
//! [`read_table_with`] also takes what to assume where a file does not say
//! ([`ReadOptions`]) and says what it assumed.
//! Every writer goes through [`write_output`](crate::output::write_output), so a failure
//! never leaves half a file and missing folders are created.

mod aerodyn;
mod c81;
mod csv;
mod json;
mod json_lines;
mod write;
mod xfoil_polar;

use super::{PolarTable, TableError};
use crate::arguments::ArgumentError;
use crate::compressibility::KarmanTsien;
use crate::input::read_input;
use std::path::Path;
use std::str::FromStr;

pub use self::aerodyn::{write_aerodyn, write_aerodyn_flap_sweep};
pub use self::c81::{parse_c81, write_c81, C81Options};
pub use self::write::{
    check_flap_sweep_output, check_table_output, flap_sweep_files, table_files, write_table,
    write_table_into,
};

/// What a reader assumes where a file does not say, and which part of a file it reads.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ReadOptions {
    /// Reynolds number of a file that carries none (a C81 deck without `Re…` in its name);
    /// 10⁶ when not given (and said in a note).
    pub re: Option<f64>,
    /// Mach number of a file that carries none (an AeroDyn file from another tool); 0 when
    /// not given (and said in a note).
    pub mach: Option<f64>,
    /// The `UserProp` of the tables to read from an AeroDyn file whose tables differ in it.
    pub user_prop: Option<f64>,
}

impl ReadOptions {
    /// The options, `re` and `mach` checked as the command-line checks a Reynolds and a Mach
    /// number; errors name the argument by `names` (`--assume-re`, `--assume-mach` for the
    /// CLI).
    pub fn checked(
        names: [&str; 2],
        re: Option<f64>,
        mach: Option<f64>,
        user_prop: Option<f64>,
    ) -> Result<Self, crate::arguments::ArgumentError> {
        re.map_or(Ok(()), |re| crate::arguments::reynolds(names[0], re))?;
        mach.map_or(Ok(()), |m| crate::arguments::mach(names[1], m))?;
        Ok(Self {
            re,
            mach,
            user_prop,
        })
    }
}

/// A table read from a file, with what the reader assumed (one line each).
#[derive(Clone, Debug)]
pub struct TableRead {
    /// The table.
    pub table: PolarTable,
    /// Assumptions and choices, e.g. the Reynolds number of a C81 deck.
    pub notes: Vec<String>,
}

/// A table file format (with the `cli` feature also a clap value enum: `--format` lists and
/// completes these names).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
pub enum TableFormat {
    /// Long-form CSV (`.csv`), readable.
    Csv,
    /// Serde JSON (`.json`), readable.
    Json,
    /// JSON Lines (`.jsonl`): one flat record per point with the CSV's columns, the form
    /// `pandas.read_json(path, lines=True)` reads; readable.
    #[cfg_attr(feature = "cli", value(name = "jsonl"))]
    JsonLines,
    /// XFOIL polar text, one file per (Re, M) (`.pol`); readable as a one-polar table.
    #[cfg_attr(feature = "cli", value(name = "xfoil", alias = "pol", alias = "polar"))]
    XfoilPolar,
    /// C81 rotorcraft airfoil table, one file per Re (`.c81`); readable as a one-Re table.
    C81,
    /// OpenFAST AeroDyn airfoil file, one table per Re, one file per Mach number (a flap
    /// sweep: one table per deflection, one file per Re and Mach number; chosen with
    /// `--format aerodyn`); readable as a one-Mach table, recognised by its content.
    #[cfg_attr(feature = "cli", value(name = "aerodyn"))]
    AeroDyn,
}

impl TableFormat {
    /// The format implied by a file's extension (case-insensitive: `.csv`, `.json`, `.jsonl`,
    /// `.pol` or `.polar`, `.c81`).
    pub fn from_path(path: &Path) -> Result<Self, TableError> {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase())
            .unwrap_or_default();
        match ext.as_str() {
            "csv" => Ok(Self::Csv),
            "json" => Ok(Self::Json),
            "jsonl" => Ok(Self::JsonLines),
            "pol" | "polar" => Ok(Self::XfoilPolar),
            "c81" => Ok(Self::C81),
            _ => Err(TableError::UnknownExtension(path.display().to_string())),
        }
    }

    /// [`for_output`](Self::for_output) for the flags `--format` and `--out`: a name whose
    /// format cannot be told, or a per-polar format to a stream, is a usage error.
    pub fn for_flags(format: Option<Self>, out: Option<&Path>) -> Result<Self, ArgumentError> {
        Self::for_output(format, out)
            .map_err(|e| ArgumentError::with_text("--format/--out", "", e.to_string()))
    }

    /// Refuses, as a usage error, a format whose rows are the table's lookups (C81, AeroDyn)
    /// for a grid of fewer than two angles of attack: lookups need two converged points.
    pub fn check_alpha_count(self, alphas: usize) -> Result<(), ArgumentError> {
        if alphas >= 2 || !matches!(self, Self::C81 | Self::AeroDyn) {
            return Ok(());
        }
        Err(ArgumentError::with_text(
            "--alpha",
            "",
            format!(
                "--format {} needs at least two angles of attack (its rows are the table's \
                 lookups, which need two converged points)",
                self.name()
            ),
        ))
    }

    /// The format a table is written in: `format` when given, else the extension of `out`;
    /// CSV for standard output (`out` absent or `-`). XFOIL polars and C81 write one file
    /// per polar or per Re and need a file name.
    pub fn for_output(format: Option<Self>, out: Option<&Path>) -> Result<Self, TableError> {
        // Standard output, a device or a FIFO: one stream, CSV unless told otherwise.
        let stdout = out.is_none_or(|p| !crate::output::names_a_file(p));
        let chosen = match (format, out) {
            (Some(f), _) => f,
            (None, Some(path)) if !stdout => Self::from_path(path)?,
            (None, _) => Self::Csv,
        };
        let per = match chosen {
            Self::XfoilPolar => Some("polar"),
            Self::C81 => Some("Re"),
            Self::AeroDyn => Some("Mach number"),
            Self::Csv | Self::Json | Self::JsonLines => None,
        };
        if let (true, Some(per)) = (stdout, per) {
            return Err(TableError::NeedsFile {
                format: chosen.name(),
                per,
            });
        }
        Ok(chosen)
    }

    /// Lower-case name as used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Self::Csv => "csv",
            Self::Json => "json",
            Self::JsonLines => "jsonl",
            Self::XfoilPolar => "xfoil",
            Self::C81 => "c81",
            Self::AeroDyn => "aerodyn",
        }
    }
}

impl FromStr for TableFormat {
    type Err = TableError;

    /// Parse `csv`, `json`, `jsonl`, `xfoil` (or `pol`), `c81` or `aerodyn`, case-insensitive.
    fn from_str(s: &str) -> Result<Self, TableError> {
        match s.to_ascii_lowercase().as_str() {
            "csv" => Ok(Self::Csv),
            "json" => Ok(Self::Json),
            "jsonl" => Ok(Self::JsonLines),
            "xfoil" | "pol" | "polar" => Ok(Self::XfoilPolar),
            "c81" => Ok(Self::C81),
            "aerodyn" => Ok(Self::AeroDyn),
            _ => Err(TableError::UnknownFormat(s.to_string())),
        }
    }
}

/// The file name stem of `path` (the name of a file set's members is built on it), or
/// `default` when `path` has none.
pub(crate) fn stem_or(path: &Path, default: &str) -> String {
    path.file_stem()
        .map_or_else(|| default.to_string(), |s| s.to_string_lossy().into_owned())
}

/// The extension of `path`, or `default` when it has none.
pub(crate) fn extension_or(path: &Path, default: &str) -> String {
    path.extension()
        .map_or_else(|| default.to_string(), |e| e.to_string_lossy().into_owned())
}

/// The supercritical flag a point's minimum pressure `cpmin` implies at free-stream Mach
/// number `mach` (Cp_min < Cp*, see
/// [`MinimumPressure`](crate::compressibility::MinimumPressure)); `None` when `cpmin` is
/// unknown (NaN) or the Mach number is outside the subsonic range.
pub(crate) fn supercritical_from_cpmin(cpmin: f64, mach: f64) -> Option<bool> {
    if cpmin.is_nan() {
        return None;
    }
    KarmanTsien::new(mach)
        .ok()
        .map(|kt| mach > 0.0 && cpmin < kt.cp_sonic())
}

/// Read a table file, once, recognising its layout from its extension and content: a
/// polargen CSV, JSON or JSON Lines table, an XFOIL polar file (a one-polar table), a C81
/// deck (a one-Re table), an OpenFAST AeroDyn airfoil file (a one-Mach table, whatever its
/// extension), or a single-polar CSV with columns `alpha, cl, cd[, cdp, cm, xtr_top,
/// xtr_bot]` such as the XFOIL reference polars (a one-polar table at the Re and M of a file
/// name like `…_Re1.9e6_M0.41_…`, else Re 10⁶, M 0). Every error names the file. What the
/// reader assumed is dropped: [`read_table_with`] returns it.
pub fn read_table(path: &Path) -> Result<PolarTable, TableError> {
    read_table_with(path, &ReadOptions::default()).map(|read| read.table)
}

/// [`read_table`], assuming `options` where the file does not say; the notes say what was
/// assumed or chosen.
pub fn read_table_with(path: &Path, options: &ReadOptions) -> Result<TableRead, TableError> {
    let bytes = read_input(path).map_err(TableError::Input)?;
    // Name the file, unless the error already does.
    let in_file = |source: TableError| {
        if source.to_string().contains(&path.display().to_string()) {
            source
        } else {
            TableError::File {
                path: path.to_path_buf(),
                source: Box::new(source),
            }
        }
    };
    let layout = Layout::detect(path, &bytes).map_err(in_file)?;
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("");
    parse_layout(&bytes, layout, stem, options).map_err(in_file)
}

/// Parse a table held in memory in `format` (CSV is polargen's long form).
pub fn parse_table(bytes: &[u8], format: TableFormat) -> Result<PolarTable, TableError> {
    let layout = match format {
        TableFormat::Csv => Layout::Csv,
        TableFormat::Json => Layout::Json,
        TableFormat::JsonLines => Layout::JsonLines,
        TableFormat::XfoilPolar => Layout::XfoilPolar,
        TableFormat::C81 => Layout::C81,
        TableFormat::AeroDyn => Layout::AeroDyn,
    };
    parse_layout(bytes, layout, "", &ReadOptions::default()).map(|read| read.table)
}

/// Parse `bytes` laid out as `layout`; `stem` is the file stem a single-polar CSV takes its
/// flow condition from (and a C81 deck its Reynolds number, an AeroDyn file its name).
fn parse_layout(
    bytes: &[u8],
    layout: Layout,
    stem: &str,
    options: &ReadOptions,
) -> Result<TableRead, TableError> {
    let text = || std::str::from_utf8(bytes).map_err(|_| TableError::NotText);
    let plain = |table: PolarTable| TableRead {
        table,
        notes: Vec::new(),
    };
    match layout {
        Layout::Csv => csv::parse_csv(bytes).map(plain),
        Layout::PolarCsv => csv::parse_polar_csv(bytes, stem).map(plain),
        Layout::Json => json::parse_json(text()?).map(plain),
        Layout::JsonLines => json_lines::parse_json_lines(text()?).map(plain),
        Layout::XfoilPolar => xfoil_polar::parse_xfoil_polar(text()?).map(plain),
        Layout::C81 => c81::parse_c81_with(text()?, stem, options),
        Layout::AeroDyn => aerodyn::parse_aerodyn(text()?, stem, options),
    }
}

/// `table` with the post-stall drag coefficient `cd_max` (broadside, α = ±90°) of its 360°
/// extension, when given (the extension C81 and AeroDyn files carry).
pub fn with_cd_max(table: PolarTable, cd_max: Option<f64>) -> Result<PolarTable, TableError> {
    match cd_max {
        Some(cd_max) => {
            let params = *table.post_stall_params();
            table.with_post_stall(super::PostStallParams { cd_max, ..params })
        }
        None => Ok(table),
    }
}

/// The α range \[deg\] a table read for lookups must cover: a rotor blade, a propeller blade
/// or a wing works from about zero lift (α ≈ 0° for a cambered section, slightly above for
/// the 8-H-12's reflexed camber) up towards stall; at 10° a 12 % section gives Cl ≈ 1.1, the
/// order of the retreating blade's working lift coefficient (6·C_T/σ ≈ 0.6–0.8 on average for
/// a gyroplane, more on the retreating side). Below or above the table the 360° extension
/// (Viterna–Corrigan, a flat plate) takes over, which stands in for massive separation, not
/// for the attached-flow lift curve: a table that ends inside this range (α −2…2°, or α in
/// radians) would make the rotor's trim fail or mislead, so it is refused on reading.
pub const LOOKUP_ALPHA_COVER_DEG: (f64, f64) = (0.0, 10.0);

/// [`read_table`], for a consumer that looks coefficients up (the rotor model): a table
/// without two converged points in any polar is refused ([`PolarTable::require_lookup`]),
/// and so is one whose α range does not cover [`LOOKUP_ALPHA_COVER_DEG`].
pub fn read_lookup_table(path: &Path) -> Result<PolarTable, TableError> {
    read_lookup_table_with(path, &ReadOptions::default()).map(|read| read.table)
}

/// [`read_lookup_table`] with [`ReadOptions`], returning the reader's notes.
pub fn read_lookup_table_with(path: &Path, options: &ReadOptions) -> Result<TableRead, TableError> {
    let read = read_table_with(path, options)?;
    check_lookup_table(&read.table).map_err(|e| TableError::File {
        path: path.to_path_buf(),
        source: Box::new(e),
    })?;
    Ok(read)
}

/// The checks of [`read_lookup_table`] on a table already read.
pub fn check_lookup_table(table: &PolarTable) -> Result<(), TableError> {
    table.require_lookup()?;
    let alphas = table
        .polars()
        .flat_map(|(_, points)| points.iter().map(|p| p.alpha));
    let (low, high) = alphas.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), a| {
        (lo.min(a), hi.max(a))
    });
    let (need_low, need_high) = LOOKUP_ALPHA_COVER_DEG;
    if low <= need_low && high >= need_high {
        Ok(())
    } else {
        Err(TableError::AlphaCover { low, high })
    }
}

/// How a table file is laid out, as far as reading it is concerned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Layout {
    /// polargen's long-form CSV.
    Csv,
    /// A CSV holding one polar: columns alpha, cl, cd and optional others.
    PolarCsv,
    /// polargen's JSON.
    Json,
    /// polargen's JSON Lines.
    JsonLines,
    /// XFOIL's polar-file text.
    XfoilPolar,
    /// C81 text.
    C81,
    /// An OpenFAST AeroDyn airfoil file.
    AeroDyn,
}

impl Layout {
    /// The layout of a file from its extension, and from its first line where the extension
    /// does not decide: a `.csv` whose header names the `airfoil`, `re` and `mach` columns is
    /// a polargen table, one naming `alpha`, `cl` and `cd` (and not those) a single polar, any
    /// other is refused naming what is missing (an empty one is left to the CSV reader). A file with
    /// another extension is recognised by its content: an AeroDyn airfoil file (a line named
    /// `InterpOrd` or `NumTabs`), `{` (JSON; a JSON Lines record ends its first line),
    /// `Calculated polar for:` (XFOIL), a CSV header as above, or a C81 header (six
    /// two-digit counts in columns 31–42 and a Mach row).
    fn detect(path: &Path, bytes: &[u8]) -> Result<Self, TableError> {
        let head = String::from_utf8_lossy(&bytes[..bytes.len().min(4096)]);
        let first = head.trim_start();
        let columns: Vec<String> = crate::input::text_lines(first)
            .next()
            .unwrap_or("")
            .split(',')
            .map(|c| c.trim().to_ascii_lowercase())
            .collect();
        let has = |names: &[&str]| names.iter().all(|n| columns.iter().any(|c| c == n));
        let csv = if has(&["airfoil", "re", "mach"]) {
            Some(Self::Csv)
        } else if has(&["alpha", "cl", "cd"]) {
            Some(Self::PolarCsv)
        } else {
            None
        };
        let neither = || match ["airfoil", "re", "mach"].into_iter().find(|n| !has(&[n])) {
            Some(missing) if columns.iter().any(|c| !c.is_empty()) => {
                Err(TableError::CsvLayout(missing))
            }
            _ => Ok(Self::Csv),
        };
        match TableFormat::from_path(path) {
            Ok(TableFormat::Csv) => csv.map_or_else(neither, Ok),
            Ok(TableFormat::Json) => Ok(Self::Json),
            Ok(TableFormat::JsonLines) => Ok(Self::JsonLines),
            Ok(TableFormat::XfoilPolar) => Ok(Self::XfoilPolar),
            Ok(TableFormat::C81) => Ok(Self::C81),
            Ok(TableFormat::AeroDyn) => Ok(Self::AeroDyn),
            Err(unknown) => {
                let first_line = crate::input::text_lines(first).next().unwrap_or("");
                if aerodyn::looks_like_aerodyn(&head) {
                    Ok(Self::AeroDyn)
                } else if first_line.starts_with('{')
                    && first_line.contains("\"alpha\"")
                    && !first_line.contains("\"polars\"")
                {
                    Ok(Self::JsonLines)
                } else if first.starts_with('{') {
                    Ok(Self::Json)
                } else if head.contains("Calculated polar for:") {
                    Ok(Self::XfoilPolar)
                } else if let Some(csv) = csv {
                    Ok(csv)
                } else if c81::looks_like_c81(&head) {
                    Ok(Self::C81)
                } else {
                    Err(unknown)
                }
            }
        }
    }
}
