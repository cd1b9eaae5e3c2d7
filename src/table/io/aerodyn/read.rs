//! Reading AeroDyn airfoil files (see the [module docs](super)).

use super::Header;
use crate::section::PolarPoint;
use crate::table::io::{ReadOptions, TableRead};
use crate::table::{PolarTable, PostStallParams, TableError, TableMeta};

/// The unsteady-aerodynamics lines a table may hold after `InclUAdata True` (any order, any
/// subset, as OpenFAST reads them): skipped.
const UA_NAMES: [&str; 36] = [
    "alpha0",
    "alpha1",
    "alpha2",
    "alphaUpper",
    "alphaLower",
    "eta_e",
    "C_nalpha",
    "C_lalpha",
    "T_f0",
    "T_V0",
    "T_p",
    "T_VL",
    "b1",
    "b2",
    "b5",
    "A1",
    "A2",
    "A5",
    "S1",
    "S2",
    "S3",
    "S4",
    "Cn1",
    "Cn2",
    "St_sh",
    "Cd0",
    "Cm0",
    "k0",
    "k1",
    "k2",
    "k3",
    "k1_hat",
    "x_cp_bar",
    "UACutout",
    "UACutout_delta",
    "filtCutOff",
];

/// Whether a line is an OpenFAST comment (or blank).
fn is_comment(line: &str) -> bool {
    let t = line.trim_start();
    t.is_empty() || t.starts_with(['!', '#', '%'])
}

/// Whether `text` looks like an AeroDyn airfoil file: among its first value lines, one named
/// `InterpOrd` or `NumTabs` (the names OpenFAST requires before the first table).
pub(crate) fn looks_like_aerodyn(text: &str) -> bool {
    text.lines().filter(|l| !is_comment(l)).take(12).any(|l| {
        let words: Vec<&str> = l.split_whitespace().take(2).collect();
        words
            .iter()
            .any(|w| w.eq_ignore_ascii_case("InterpOrd") || w.eq_ignore_ascii_case("NumTabs"))
    })
}

/// The value lines of a file, with their 1-based line numbers, and the next one to read.
struct Lines<'a> {
    lines: Vec<(usize, &'a str)>,
    next: usize,
}

impl<'a> Lines<'a> {
    /// The line number of the next line (or one past the end).
    fn at(&self) -> usize {
        self.lines
            .get(self.next)
            .map_or_else(|| self.lines.last().map_or(1, |l| l.0 + 1), |l| l.0)
    }

    /// An error at the next line.
    fn error(&self, message: String) -> TableError {
        TableError::AeroDyn {
            line: self.at(),
            message,
        }
    }

    /// The value of the next line when it is named `name` (as its first or second word,
    /// case-insensitive, as OpenFAST's `ParseVar` accepts), which is then consumed; `None`
    /// (nothing consumed) otherwise.
    fn optional(&mut self, name: &str) -> Option<&'a str> {
        let (_, line) = *self.lines.get(self.next)?;
        let text = line.split('!').next().unwrap_or("");
        let words: Vec<&str> = text.split_whitespace().take(2).collect();
        let value = match words.as_slice() {
            [value, n] if n.eq_ignore_ascii_case(name) => value,
            [n, value] if n.eq_ignore_ascii_case(name) => value,
            _ => return None,
        };
        self.next += 1;
        Some(value.trim_matches('"'))
    }

    /// The value of the next line, which must be named `name`.
    fn required(&mut self, name: &str) -> Result<&'a str, TableError> {
        self.optional(name)
            .ok_or_else(|| self.error(format!("expected the line '{name}'")))
    }

    /// The number of the next line, which must be named `name`.
    fn number(&mut self, name: &str) -> Result<f64, TableError> {
        let at = self.at();
        let text = self.required(name)?;
        text.parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or(TableError::AeroDyn {
                line: at,
                message: format!("{name} '{text}' is not a number"),
            })
    }

    /// The count of the next line, which must be named `name`.
    fn count(&mut self, name: &str) -> Result<usize, TableError> {
        let at = self.at();
        let text = self.required(name)?;
        text.parse::<usize>().map_err(|_| TableError::AeroDyn {
            line: at,
            message: format!("{name} '{text}' is not a count"),
        })
    }

    /// The next line as numbers (up to a `!` comment).
    fn row(&mut self, what: &str) -> Result<Vec<f64>, TableError> {
        let (at, line) = *self
            .lines
            .get(self.next)
            .ok_or_else(|| self.error(format!("the file ends inside the {what}")))?;
        self.next += 1;
        line.split('!')
            .next()
            .unwrap_or("")
            .split_whitespace()
            .map(|w| w.parse::<f64>().ok().filter(|v| v.is_finite()))
            .collect::<Option<Vec<f64>>>()
            .ok_or(TableError::AeroDyn {
                line: at,
                message: format!("a row of the {what} that is not all numbers"),
            })
    }
}

/// One table of an AeroDyn file.
struct AfTable {
    re: f64,
    user_prop: f64,
    /// (α, cl, cd, cm) rows.
    rows: Vec<[f64; 4]>,
    /// The table's computed α range and metadata, from a `polargen-table` line.
    written: Option<([f64; 2], TableMeta)>,
}

/// Parse an AeroDyn airfoil file; `stem` names the airfoil when the file does not.
pub fn parse_aerodyn(
    text: &str,
    stem: &str,
    options: &ReadOptions,
) -> Result<TableRead, TableError> {
    let mut header = None;
    for (k, line) in text.lines().enumerate() {
        if let Some(text) = line.trim_start().strip_prefix('!') {
            if let Some(parsed) = Header::from_comment(text) {
                header = Some(parsed.map_err(|e| TableError::AeroDyn {
                    line: k + 1,
                    message: format!("the polargen-table line is not valid: {e}"),
                })?);
            }
        }
    }
    let mut lines = Lines {
        lines: text
            .lines()
            .enumerate()
            .filter(|(_, l)| !is_comment(l))
            .map(|(k, l)| (k + 1, l))
            .collect(),
        next: 0,
    };
    lines.optional("InterpOrd");
    let thickness = match lines.optional("RelThickness") {
        Some(t) => t.parse::<f64>().unwrap_or(f64::NAN),
        None => f64::NAN,
    };
    lines.optional("NonDimArea");
    let coords = lines.required("NumCoords")?;
    if !coords.starts_with('@') {
        let n: usize = coords.parse().map_err(|_| {
            lines.error(format!("NumCoords '{coords}' is neither a count nor @file"))
        })?;
        for _ in 0..n {
            lines.row("airfoil coordinates")?;
        }
    }
    lines.optional("BL_file");
    let n_tables = lines.count("NumTabs")?;
    let mut tables = Vec::with_capacity(n_tables.min(1000));
    for k in 0..n_tables {
        let re = lines.number("Re")? * 1e6;
        let user_prop = match lines
            .optional("UserProp")
            .or_else(|| lines.optional("Ctrl"))
        {
            Some(v) => v.parse::<f64>().unwrap_or(0.0),
            None => 0.0,
        };
        let ua = lines
            .optional("InclUAdata")
            .is_some_and(|v| v.eq_ignore_ascii_case("true") || v.eq_ignore_ascii_case("t"));
        if ua {
            while UA_NAMES.iter().any(|n| lines.optional(n).is_some()) {}
        }
        let n = lines.count("NumAlf")?;
        let mut rows = Vec::with_capacity(n.min(100_000));
        for _ in 0..n {
            let at = lines.at();
            match lines.row("coefficient table")?.as_slice() {
                [a, cl, cd, cm, ..] => rows.push([*a, *cl, *cd, *cm]),
                _ => {
                    return Err(TableError::AeroDyn {
                        line: at,
                        message: "a row needs alpha, Cl, Cd and Cm".to_string(),
                    })
                }
            }
        }
        let written = header.as_ref().map(|h: &Header| {
            let range = h.computed_alpha.get(k).copied();
            (
                range.unwrap_or([f64::NEG_INFINITY, f64::INFINITY]),
                h.meta_of(k).clone(),
            )
        });
        tables.push(AfTable {
            re,
            user_prop,
            rows,
            written,
        });
    }
    let mut notes = Vec::new();
    let tables = choose_tables(tables, options, &mut notes)?;
    build(tables, header, thickness, stem, options, notes)
}

/// The tables to read: all when they share one UserProp, else those at
/// `options.user_prop` (required then), sorted by Re.
fn choose_tables(
    mut tables: Vec<AfTable>,
    options: &ReadOptions,
    notes: &mut Vec<String>,
) -> Result<Vec<AfTable>, TableError> {
    let mut props: Vec<f64> = tables.iter().map(|t| t.user_prop).collect();
    props.sort_by(f64::total_cmp);
    props.dedup();
    if props.len() > 1 {
        let list = props
            .iter()
            .map(|p| p.to_string())
            .collect::<Vec<_>>()
            .join(", ");
        let Some(want) = options.user_prop else {
            return Err(TableError::AeroDynTables(format!(
                "the tables are at UserProp {list}: choose one with --user-prop"
            )));
        };
        tables.retain(|t| t.user_prop == want);
        if tables.is_empty() {
            return Err(TableError::AeroDynTables(format!(
                "no table at UserProp {want} (the file has {list})"
            )));
        }
        notes.push(format!(
            "read the tables at UserProp {want} (the file has {list})"
        ));
    }
    tables.sort_by(|a, b| a.re.total_cmp(&b.re));
    if let Some(w) = tables.windows(2).find(|w| w[0].re == w[1].re) {
        return Err(TableError::AeroDynTables(format!(
            "two tables at Re {} and one UserProp",
            w[0].re
        )));
    }
    Ok(tables)
}

/// The table of the chosen AeroDyn tables (a file written here gives the metadata of the
/// first and each table's computed α range; any other the options' Mach number and `stem`).
fn build(
    tables: Vec<AfTable>,
    header: Option<Header>,
    thickness: f64,
    stem: &str,
    options: &ReadOptions,
    mut notes: Vec<String>,
) -> Result<TableRead, TableError> {
    let written_meta = tables
        .first()
        .and_then(|t| t.written.as_ref())
        .map(|w| w.1.clone());
    let (meta, mach, params) = match (header, written_meta) {
        (Some(h), Some(meta)) => (meta, h.mach, h.post_stall),
        _ => {
            let mach = options.mach.unwrap_or_else(|| {
                notes.push(
                    "the AeroDyn file does not give its Mach number: M 0 assumed (set it \
                     with --assume-mach)"
                        .to_string(),
                );
                0.0
            });
            let meta = TableMeta {
                thickness,
                ..TableMeta::unknown(stem, "AeroDyn airfoil file")
            };
            (meta, mach, PostStallParams::default())
        }
    };
    let re: Vec<f64> = tables.iter().map(|t| t.re).collect();
    let mut polars: Vec<Vec<PolarPoint>> = tables
        .iter()
        .map(|t| {
            let range = t.written.as_ref().map(|w| w.0);
            t.rows
                .iter()
                .filter(|r| range.is_none_or(|[lo, hi]| (lo..=hi).contains(&r[0])))
                .map(|&[a, cl, cd, cm]| PolarPoint::from_coefficients(a, cl, cd, cm))
                .collect()
        })
        .collect();
    if tables.iter().any(|t| t.written.is_some()) {
        pad_to_shared_alphas(&mut polars);
    }
    let table = PolarTable::with_params(meta, re, vec![mach], polars, params)?;
    Ok(TableRead { table, notes })
}

/// A table computed by polargen keeps every α of its grid in every polar; its AeroDyn file
/// keeps only each polar's usable rows. Each polar gets back the α values the others have as
/// unconverged points (no coefficients), so that the table holds one α list again and writes
/// to, and reads back from, the formats that keep every point.
fn pad_to_shared_alphas(polars: &mut [Vec<PolarPoint>]) {
    let mut alphas: Vec<f64> = polars.iter().flatten().map(|p| p.alpha).collect();
    alphas.sort_by(f64::total_cmp);
    alphas.dedup();
    for polar in polars.iter_mut() {
        for &a in &alphas {
            if !polar.iter().any(|p| p.alpha == a) {
                polar.push(PolarPoint {
                    converged: false,
                    ..PolarPoint::from_coefficients(a, f64::NAN, f64::NAN, f64::NAN)
                });
            }
        }
        polar.sort_by(|p, q| p.alpha.total_cmp(&q.alpha));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A file of another tool with two tables at one Re and UserProp 5 before −5 (AeroDyn's
    /// AFTabMod 3 needs them increasing; the reader does not).
    const TWO_USER_PROPS: &str = "\
! two flap settings
\"DEFAULT\" InterpOrd
1 NonDimArea
0 NumCoords
2 NumTabs
! first table
1.5 Re
5 UserProp
False InclUAdata
3 NumAlf
-180 0 0.02 0
0 0.55 0.011 -0.07
180 0 0.02 0
! second table
1.5 Re
-5 UserProp
False InclUAdata
2 NumAlf
-10 -1.1 0.012 0.01
10 0.6 0.013 0.05
";

    fn read(user_prop: Option<f64>) -> Result<TableRead, TableError> {
        let options = ReadOptions {
            user_prop,
            ..ReadOptions::default()
        };
        parse_aerodyn(TWO_USER_PROPS, "flaps", &options)
    }

    #[test]
    fn a_two_user_prop_file_reads_the_chosen_table() {
        let err = read(None).unwrap_err().to_string();
        assert_eq!(
            err,
            "AeroDyn file: the tables are at UserProp -5, 5: choose one with --user-prop"
        );
        let err = read(Some(0.0)).unwrap_err().to_string();
        assert!(
            err.contains("no table at UserProp 0 (the file has -5, 5)"),
            "{err}"
        );
        let five = read(Some(5.0)).unwrap();
        assert_eq!(five.table.re(), &[1.5e6]);
        let points = five.table.polar_at(0, 0).unwrap();
        let rows: Vec<[f64; 4]> = points.iter().map(|p| [p.alpha, p.cl, p.cd, p.cm]).collect();
        assert_eq!(
            rows,
            [
                [-180.0, 0.0, 0.02, 0.0],
                [0.0, 0.55, 0.011, -0.07],
                [180.0, 0.0, 0.02, 0.0]
            ]
        );
        assert!(five.notes[0].contains("UserProp 5"), "{:?}", five.notes);
        let minus = read(Some(-5.0)).unwrap();
        let alphas: Vec<f64> = minus
            .table
            .polar_at(0, 0)
            .unwrap()
            .iter()
            .map(|p| p.alpha)
            .collect();
        assert_eq!(alphas, [-10.0, 10.0]);
    }
}
