//! CSV, long form: one row per point, the table's metadata repeated on every row.
//!
//! Columns: `airfoil,re,mach,ncrit,xtr_top_set,xtr_bot_set,alpha,cl,cd,cdp,cm,xtr_top,xtr_bot,
//! converged,cdf,iterations,residual,panels,solver,cpmin,supercritical,xsep_top,xsep_bot,
//! massive_separation,thickness`; a table whose
//! surfaces have different N_crit has the two columns `ncrit_top,ncrit_bot` in place of
//! `ncrit`. Floats are written with Rust's shortest round-trip formatting (`NaN`, `-inf`
//! where not finite), so reading a file back gives the identical table. The reader needs the
//! first fourteen columns (any order; `ncrit` or both `ncrit_top` and `ncrit_bot`); `cdf` (default cd − cdp), `iterations`, `residual`, `panels` (default 0), `solver`
//! (default empty), `cpmin`, `supercritical` and `thickness` (the airfoil's t/c, default
//! NaN: unknown) are optional. Unknown metadata (a table converted from a C81 deck has no
//! N_crit) is written `NaN`. A file without `cpmin` reads as
//! minimum pressure unknown (NaN); without `supercritical` the flag follows from `cpmin` and
//! the Mach number (Cp_min < Cp*), unknown (empty field, `None`) when `cpmin` is; likewise
//! `xsep_top`, `xsep_bot` (NaN when absent) and `massive_separation`, which follows from them
//! when absent ([`massive_separation`]). A (Re, M) node without rows cannot be represented and
//! reads back as a ragged grid. A table whose section was made by geometry operations has two
//! more columns at the end: `geometry`, the operations in their text form (`thickness 0.24;
//! flap 0.75:0:10`, read back into the metadata), and `flap_deg`, the flap deflection when a
//! flap is among them (empty otherwise), so that the tables of a flap sweep are told apart by
//! one number.

use super::supercritical_from_cpmin;
use crate::geometry::{parse_shape_ops, shape_ops_text};
use crate::output::write_output;
use crate::section::{massive_separation, FlowCondition, PolarPoint, Transition};
use crate::table::{PolarTable, TableError, TableMeta};
use std::collections::HashMap;
use std::io::{Read, Write};
use std::path::Path;

/// Column names written, in order.
pub const COLUMNS: [&str; 25] = [
    "airfoil",
    "re",
    "mach",
    "ncrit",
    "xtr_top_set",
    "xtr_bot_set",
    "alpha",
    "cl",
    "cd",
    "cdp",
    "cm",
    "xtr_top",
    "xtr_bot",
    "converged",
    "cdf",
    "iterations",
    "residual",
    "panels",
    "solver",
    "cpmin",
    "supercritical",
    "xsep_top",
    "xsep_bot",
    "massive_separation",
    "thickness",
];

/// Columns a CSV file must have.
pub const REQUIRED: usize = 14;

/// Columns after [`COLUMNS`] of a table whose section was made by geometry operations.
pub const SHAPE_COLUMNS: [&str; 2] = ["geometry", "flap_deg"];

/// Index of `ncrit` in [`COLUMNS`], and the per-side columns that replace it.
const NCRIT: usize = 3;
const NCRIT_SIDES: [&str; 2] = ["ncrit_top", "ncrit_bot"];

/// `fields` in [`COLUMNS`] order with the N_crit field replaced by `ncrit` (one or two fields).
fn with_ncrit<'a>(fields: [&'a str; COLUMNS.len()], ncrit: &'a [String]) -> Vec<&'a str> {
    let mut out = fields.to_vec();
    out.splice(NCRIT..=NCRIT, ncrit.iter().map(String::as_str));
    out
}

/// Call `record` with the header (the column names) and then each point's fields, as the CSV
/// writes them: the one definition of the columns, shared with JSON Lines.
pub(super) fn for_each_record<E>(
    table: &PolarTable,
    mut record: impl FnMut(&[&str]) -> Result<(), E>,
) -> Result<(), E> {
    let m = table.meta();
    let t = &m.transition;
    let (ncrit, ncrit_names) = match t.common_ncrit() {
        Some(n) => (vec![n.to_string()], vec![COLUMNS[NCRIT].to_string()]),
        None => (
            vec![t.ncrit_top.to_string(), t.ncrit_bot.to_string()],
            NCRIT_SIDES.map(str::to_string).to_vec(),
        ),
    };
    // The geometry columns, only for a section made by geometry operations.
    let (shape_names, shape): (&[&str], Vec<String>) = if m.geometry.is_empty() {
        (&[], Vec::new())
    } else {
        let flap = m
            .flap_deg()
            .map_or(String::new(), crate::limits::exact_number);
        (&SHAPE_COLUMNS, vec![shape_ops_text(&m.geometry), flap])
    };
    let mut header = with_ncrit(COLUMNS, &ncrit_names);
    header.extend(shape_names);
    record(&header)?;
    let panels = m.panels.to_string();
    let thickness = m.thickness.to_string();
    let (xt, xb) = (t.xtr_top.to_string(), t.xtr_bot.to_string());
    for (FlowCondition { reynolds: re, mach }, points) in table.polars() {
        let (re, mach) = (re.to_string(), mach.to_string());
        for p in points {
            let fields = [
                m.airfoil.as_str(),
                &re,
                &mach,
                "",
                &xt,
                &xb,
                &p.alpha.to_string(),
                &p.cl.to_string(),
                &p.cd.to_string(),
                &p.cdp.to_string(),
                &p.cm.to_string(),
                &p.xtr_top.to_string(),
                &p.xtr_bot.to_string(),
                if p.converged { "true" } else { "false" },
                &p.cdf.to_string(),
                &p.iterations.to_string(),
                &p.residual.to_string(),
                &panels,
                &m.solver,
                &p.cpmin.to_string(),
                flag_field(p.supercritical),
                &p.xsep_top.to_string(),
                &p.xsep_bot.to_string(),
                flag_field(p.massive_separation),
                &thickness,
            ];
            let mut fields = with_ncrit(fields, &ncrit);
            fields.extend(shape.iter().map(String::as_str));
            record(&fields)?;
        }
    }
    Ok(())
}

/// Write `table` as long-form CSV to `w`.
pub fn write_csv_to(table: &PolarTable, w: &mut dyn Write) -> Result<(), TableError> {
    // Records of text fields fail only in the stream below.
    let werr = |e: csv::Error| {
        let text = e.to_string();
        match e.into_kind() {
            csv::ErrorKind::Io(io) => TableError::Write(io),
            _ => TableError::Write(std::io::Error::other(text)),
        }
    };
    let mut out = csv::Writer::from_writer(w);
    for_each_record(table, |fields| out.write_record(fields).map_err(werr))?;
    out.flush().map_err(TableError::Write)
}

/// The field of an optional flag: `true`, `false`, or empty when unknown.
fn flag_field(flag: Option<bool>) -> &'static str {
    match flag {
        Some(true) => "true",
        Some(false) => "false",
        None => "",
    }
}

/// Write `table` as CSV to `path` (atomically).
pub fn write_csv(table: &PolarTable, path: &Path) -> Result<(), TableError> {
    write_output(path, |w| {
        write_csv_to(table, w).map_err(|e| e.in_output(path))
    })
}

/// Parse a long-form CSV table from `r`.
pub fn parse_csv<R: Read>(r: R) -> Result<PolarTable, TableError> {
    let mut rd = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(r);
    let header = rd
        .headers()
        .map_err(|e| csv_error(&e, 1))?
        .iter()
        .map(str::to_string)
        .collect::<Vec<_>>();
    if header.iter().all(String::is_empty) {
        return Err(TableError::Csv {
            line: 1,
            message: "empty file: no header line".to_string(),
        });
    }
    let mut col = [usize::MAX; COLUMNS.len()];
    for (k, name) in COLUMNS.iter().enumerate() {
        match header.iter().position(|h| h == name) {
            Some(i) => col[k] = i,
            None if k < REQUIRED && k != NCRIT => {
                return Err(TableError::MissingColumn(name.to_string()))
            }
            None => {}
        }
    }
    // Without `ncrit`, the per-side columns.
    let ncrit_sides = match NCRIT_SIDES.map(|name| header.iter().position(|h| h == name)) {
        _ if col[NCRIT] != usize::MAX => None,
        [Some(top), Some(bot)] => Some([top, bot]),
        _ => return Err(TableError::MissingColumn(COLUMNS[NCRIT].to_string())),
    };
    let geometry_col = header.iter().position(|h| h == SHAPE_COLUMNS[0]);
    let mut meta: Option<(TableMeta, u64)> = None;
    let mut index: HashMap<(u64, u64), usize> = HashMap::new();
    let mut polars: Vec<(FlowCondition, Vec<PolarPoint>)> = Vec::new();
    for rec in rd.records() {
        let rec = rec.map_err(|e| csv_error(&e, 0))?;
        let line = rec.position().map_or(0, |p| p.line());
        let row = Row {
            rec: &rec,
            col: &col,
            line,
        };
        let [ncrit_top, ncrit_bot] = match ncrit_sides {
            None => [row.num(NCRIT)?; 2],
            Some([top, bot]) => [
                row.num_at(top, NCRIT_SIDES[0])?,
                row.num_at(bot, NCRIT_SIDES[1])?,
            ],
        };
        let this = TableMeta {
            airfoil: row.text(0)?.to_string(),
            transition: Transition::sides(ncrit_top, ncrit_bot, row.num(4)?, row.num(5)?),
            thickness: row.opt_num(24)?.unwrap_or(f64::NAN),
            panels: row.opt_int(17)?.unwrap_or(0) as usize,
            solver: row.opt_text(18).unwrap_or("").to_string(),
            geometry: match geometry_col.and_then(|i| rec.get(i)) {
                Some(text) => parse_shape_ops(text).map_err(|e| TableError::Csv {
                    line,
                    message: e.to_string(),
                })?,
                None => Vec::new(),
            },
        };
        match &meta {
            None => meta = Some((this, line)),
            Some((m, first)) => {
                if let Some(field) = meta_difference(m, &this) {
                    return Err(TableError::Csv {
                        line,
                        message: format!("{field} differs from line {first}"),
                    });
                }
            }
        }
        let (re, mach) = (row.num(1)?, row.num(2)?);
        if !(re.is_finite() && mach.is_finite()) {
            return Err(TableError::Csv {
                line,
                message: "re and mach must be finite".into(),
            });
        }
        let converged = row.flag(13)?;
        let cd = row.num(8)?;
        let cdp = row.num(9)?;
        let cpmin = row.opt_num(19)?.unwrap_or(f64::NAN);
        let xsep_top = row.opt_num(21)?.unwrap_or(f64::NAN);
        let xsep_bot = row.opt_num(22)?.unwrap_or(f64::NAN);
        let p = PolarPoint {
            alpha: row.num(6)?,
            cl: row.num(7)?,
            cd,
            cdp,
            cdf: row.opt_num(14)?.unwrap_or(cd - cdp),
            cm: row.num(10)?,
            xtr_top: row.num(11)?,
            xtr_bot: row.num(12)?,
            converged,
            iterations: row.opt_int(15)?.unwrap_or(0) as u32,
            residual: row.opt_num(16)?.unwrap_or(0.0),
            cpmin,
            supercritical: match row.opt_text(20) {
                Some("") => None,
                Some(_) => Some(row.flag(20)?),
                None => supercritical_from_cpmin(cpmin, mach),
            },
            xsep_top,
            xsep_bot,
            massive_separation: match row.opt_text(23) {
                Some("") => None,
                Some(_) => Some(row.flag(23)?),
                None => massive_separation(xsep_top, xsep_bot),
            },
        };
        if converged {
            for (name, v) in [("alpha", p.alpha), ("cl", p.cl), ("cd", p.cd), ("cm", p.cm)] {
                if !v.is_finite() {
                    return Err(TableError::Csv {
                        line,
                        message: format!("{name} is {v} in a converged point"),
                    });
                }
            }
        }
        let key = (re.to_bits(), mach.to_bits());
        let k = *index.entry(key).or_insert_with(|| {
            polars.push((FlowCondition::new(re, mach), Vec::new()));
            polars.len() - 1
        });
        polars[k].1.push(p);
    }
    let Some((meta, _)) = meta else {
        return Err(TableError::Csv {
            line: 2,
            message: "no data rows (empty table)".into(),
        });
    };
    PolarTable::from_polars(meta, polars)?.require_every_alpha()
}

/// Parse a CSV holding one polar, such as the XFOIL reference polars: columns `alpha`, `cl`,
/// `cd` (any case, any order) and optionally `cdp` (default 0), `cm` (0), `xtr_top`,
/// `xtr_bot` (1); every row is a converged point, its minimum pressure and supercritical flag
/// unknown. The flow condition comes from the file stem
/// `stem`, e.g. `naca8h12_Re1.9e6_M0.41_free` (Re 10⁶ and M 0 when absent), the airfoil name
/// from its first `_`-separated part.
pub fn parse_polar_csv<R: Read>(r: R, stem: &str) -> Result<PolarTable, TableError> {
    let mut rd = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(r);
    let headers = rd.headers().map_err(|e| csv_error(&e, 1))?.clone();
    let col = |name: &str| headers.iter().position(|h| h.eq_ignore_ascii_case(name));
    let need = |name: &str| col(name).ok_or_else(|| TableError::MissingColumn(name.to_string()));
    let (ia, il, id) = (need("alpha")?, need("cl")?, need("cd")?);
    let (icdp, icm, ixt, ixb) = (col("cdp"), col("cm"), col("xtr_top"), col("xtr_bot"));
    // XFOIL's CDp column is its pressure integral, not CD − CDf: CDf only from its own column.
    let icdf = col("cdf");
    let mut points = Vec::new();
    for rec in rd.records() {
        let rec = rec.map_err(|e| csv_error(&e, 0))?;
        let line = rec.position().map_or(0, |p| p.line());
        let get = |i: usize| -> Result<f64, TableError> {
            let s = rec.get(i).unwrap_or("");
            s.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| TableError::Csv {
                    line,
                    message: format!("{} '{s}' is not a finite number", &headers[i]),
                })
        };
        let opt = |i: Option<usize>, default: f64| i.map_or(Ok(default), get);
        let cd = get(id)?;
        let cdp = opt(icdp, 0.0)?;
        points.push(PolarPoint {
            alpha: get(ia)?,
            cl: get(il)?,
            cd,
            cdp,
            cdf: opt(icdf, f64::NAN)?,
            cm: opt(icm, 0.0)?,
            xtr_top: opt(ixt, 1.0)?,
            xtr_bot: opt(ixb, 1.0)?,
            converged: true,
            iterations: 0,
            residual: 0.0,
            ..PolarPoint::from_coefficients(f64::NAN, f64::NAN, f64::NAN, f64::NAN)
        });
    }
    let stem_number = |key: &str| {
        stem.split('_')
            .find_map(|part| part.strip_prefix(key).and_then(|v| v.parse::<f64>().ok()))
    };
    // The file gives no N_crit or transition setting: unknown.
    let meta = TableMeta::unknown(stem.split('_').next().unwrap_or("polar"), "polar CSV");
    PolarTable::new(
        meta,
        vec![stem_number("Re").unwrap_or(1e6)],
        vec![stem_number("M").unwrap_or(0.0)],
        vec![points],
    )
}

/// Name of the first metadata field in which `b` differs from `a`.
fn meta_difference(a: &TableMeta, b: &TableMeta) -> Option<&'static str> {
    if a.airfoil != b.airfoil {
        Some("airfoil")
    } else if a.transition.ncrit_top.to_bits() != b.transition.ncrit_top.to_bits() {
        Some("ncrit_top")
    } else if a.transition.ncrit_bot.to_bits() != b.transition.ncrit_bot.to_bits() {
        Some("ncrit_bot")
    } else if a.transition.xtr_top.to_bits() != b.transition.xtr_top.to_bits() {
        Some("xtr_top_set")
    } else if a.transition.xtr_bot.to_bits() != b.transition.xtr_bot.to_bits() {
        Some("xtr_bot_set")
    } else if a.thickness.to_bits() != b.thickness.to_bits() {
        Some("thickness")
    } else if a.panels != b.panels {
        Some("panels")
    } else if a.solver != b.solver {
        Some("solver")
    } else if a.geometry != b.geometry {
        Some("geometry")
    } else {
        None
    }
}

/// A csv-crate error as a one-line [`TableError::Csv`].
fn csv_error(e: &csv::Error, fallback_line: u64) -> TableError {
    let line = e.position().map_or(fallback_line, |p| p.line());
    let message = match e.kind() {
        csv::ErrorKind::UnequalLengths {
            expected_len, len, ..
        } => format!("{len} fields, expected {expected_len}"),
        csv::ErrorKind::Utf8 { .. } => "invalid UTF-8".to_string(),
        _ => e.to_string().replace('\n', " "),
    };
    TableError::Csv { line, message }
}

/// One record with the column map.
struct Row<'a> {
    rec: &'a csv::StringRecord,
    col: &'a [usize; COLUMNS.len()],
    line: u64,
}

impl Row<'_> {
    fn opt_text(&self, k: usize) -> Option<&str> {
        (self.col[k] != usize::MAX).then(|| self.rec.get(self.col[k]).unwrap_or(""))
    }

    fn text(&self, k: usize) -> Result<&str, TableError> {
        self.opt_text(k)
            .ok_or_else(|| TableError::MissingColumn(COLUMNS[k].to_string()))
    }

    fn bad(&self, k: usize, s: &str, what: &str) -> TableError {
        self.bad_named(COLUMNS[k], s, what)
    }

    fn bad_named(&self, name: &str, s: &str, what: &str) -> TableError {
        TableError::Csv {
            line: self.line,
            message: format!("{name} '{s}' is not {what}"),
        }
    }

    fn num(&self, k: usize) -> Result<f64, TableError> {
        let s = self.text(k)?;
        s.parse().map_err(|_| self.bad(k, s, "a number"))
    }

    /// The number in field `i` of the record (a column outside [`COLUMNS`], named `name`).
    fn num_at(&self, i: usize, name: &str) -> Result<f64, TableError> {
        let s = self.rec.get(i).unwrap_or("");
        s.parse().map_err(|_| self.bad_named(name, s, "a number"))
    }

    fn opt_num(&self, k: usize) -> Result<Option<f64>, TableError> {
        match self.opt_text(k) {
            None => Ok(None),
            Some(s) => s.parse().map(Some).map_err(|_| self.bad(k, s, "a number")),
        }
    }

    fn opt_int(&self, k: usize) -> Result<Option<u64>, TableError> {
        match self.opt_text(k) {
            None => Ok(None),
            Some(s) => s
                .parse()
                .map(Some)
                .map_err(|_| self.bad(k, s, "a non-negative integer")),
        }
    }

    fn flag(&self, k: usize) -> Result<bool, TableError> {
        let s = self.text(k)?;
        match s.to_ascii_lowercase().as_str() {
            "true" | "1" | "yes" => Ok(true),
            "false" | "0" | "no" => Ok(false),
            _ => Err(self.bad(k, s, "true or false")),
        }
    }
}
