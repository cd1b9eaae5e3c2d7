//! C81: the airfoil-table format of rotorcraft comprehensive codes (C81, CAMRAD, RCAS,
//! MBDyn, DUST).
//!
//! Layout, as documented in the header comment of MBDyn's `c81data.cc` (Politecnico di
//! Milano):
//!
//! ```text
//! name, NML, NAL, NMD, NAD, NMM, NAM               A30, 6I2
//! ML(1..NML)                                        7X, 9F7.0   (continuation lines 7X, 9F7.0)
//! AL(i), CL(i, 1..NML)        for i = 1..NAL        10F7.0 / (7X, 9F7.0)
//! MD(1..NMD); AD(i), CD(i, 1..NMD)                  the same for drag
//! MM(1..NMM); AM(i), CM(i, 1..NMM)                  the same for moment
//! ```
//!
//! i.e. a block per coefficient: a row of Mach numbers, then one row per α with the value at
//! each Mach number, in 7-character fields, at most 9 values per line (the α field counts as
//! the tenth on the first line), continuation lines starting with 7 blanks.
//!
//! What this writer chooses:
//! * One table per Reynolds number (file `<stem>_Re<re>.c81`, or `path` itself when the table
//!   has one Re), or a single table at a chosen Re (interpolated in ln Re).
//! * The three blocks share the Mach list (the table's Mach axis) and the α list.
//! * α rows: every usable α (converged, not in massive separation) of the polars used (the
//!   nearest Re row of the grid), thinned uniformly if needed to fit the 99-row limit of the
//!   I2 counts, plus rows every
//!   `outer_step_deg` from −180° and up to +180° outside that range, kept at least half a
//!   step away from it; any rows left of the 99 then split the widest gaps outside the
//!   computed range, weighted towards it (the extension changes fastest after stall), while
//!   gaps wider than 2° remain. Values come from [`SectionAero::lookup`], so they include the
//!   360° extension and never use unconverged points or points in massive separation (the
//!   extension starts from the last usable point and replaces them).
//! * Fields: Mach F7.3, α F7.2; each coefficient block with one decimal count for all its
//!   values, the largest (≤ 4) that leaves every field a leading blank, so that free-format
//!   (whitespace-splitting) readers work too. A negative value drops the zero before the
//!   point (`-.0100`, which Fortran F7.0, C `strtod` and Python `float` all read), so it keeps
//!   the digits of a positive one (`0.0089`).
//! * A one-Mach table is written as two identical Mach columns, at its Mach number M and at
//!   M + 0.1 (or halfway to 1 when that reaches 1), because some readers (c81utils) need two
//!   Mach values; the values do not depend on Mach. [`parse_c81`] reads such a table back as
//!   one Mach column.
//! * The format has no comment line and no field for the minimum pressure, the supercritical
//!   or the massive-separation flag, so a deck cannot carry them: supercritical points enter it
//!   like any other, points in massive separation not at all (the extension stands in for
//!   them). The CSV, JSON and XFOIL-polar forms of the same table hold them.
//!
//! The reader ([`parse_c81`], [`parse_c81_with`]) takes the fixed 7-column fields of the
//! format's definition (MBDyn files need not leave blanks between fields) and the counts from
//! columns 31–42 of the first line. Each block is read on its own Mach and α lists, as decks
//! from other tools have them (MBDyn's `naca0012.c81`: CL at 11 Mach numbers and 39 angles,
//! CD at 11 and 65, CM at 9 and 47). The table's Mach axis is the union of the three Mach
//! lists below 1 (a column at M ≥ 1 is dropped, and said: a table holds subsonic polars), each
//! polar's α rows the union of the three α lists; each coefficient is interpolated on its
//! own block, linearly in α and M, held at the block's edges. Every row is a converged point.
//! A deck carries no Reynolds number and no N_crit or transition setting: the Reynolds number
//! comes from a `Re<number>` word of the name (as written here), else from the file name
//! (`…_Re1e6…`), else [`ReadOptions::re`](crate::table::ReadOptions), else 10⁶ — the last two
//! said in a note; N_crit and the transition settings are unknown (NaN).

use super::xfoil_polar::re_label;
use super::{extension_or, stem_or};
use crate::output::{fixed_decimals, write_output, OutputSet};
use crate::section::{PolarPoint, SectionAero};
use crate::table::{PolarTable, ReadOptions, TableError, TableMeta, TableRead};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Width of every C81 field.
pub const FIELD: usize = 7;
/// Largest α or Mach count the 2-digit header allows.
pub const MAX_COUNT: usize = 99;

/// Choices of the C81 writer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct C81Options {
    /// Write one table at this Re instead of one per Re of the grid.
    pub re: Option<f64>,
    /// α spacing (deg) of the rows outside the computed range.
    pub outer_step_deg: f64,
}

impl Default for C81Options {
    fn default() -> Self {
        Self {
            re: None,
            outer_step_deg: 10.0,
        }
    }
}

/// The α rows of the C81 table at grid Re row `i_re`; see the module docs.
pub fn c81_alphas(table: &PolarTable, i_re: usize, outer_step_deg: f64) -> Vec<f64> {
    let mut inner: Vec<f64> = (0..table.mach().len())
        .filter_map(|j| table.polar_at(i_re, j))
        .flatten()
        .filter(|p| p.usable())
        .map(|p| p.alpha)
        .collect();
    inner.sort_by(f64::total_cmp);
    inner.dedup();
    let (lo, hi) = match (inner.first(), inner.last()) {
        (Some(&lo), Some(&hi)) => (lo, hi),
        _ => {
            let (lo, hi) = table.alpha_range(i_re, 0).unwrap_or((0.0, 0.0));
            inner = vec![lo, hi];
            (lo, hi)
        }
    };
    let step = if outer_step_deg > 0.0 {
        outer_step_deg
    } else {
        10.0
    };
    let below: Vec<f64> = (0..)
        .map(|k| -180.0 + k as f64 * step)
        .take_while(|&a| a <= lo - 0.5 * step)
        .collect();
    let mut above: Vec<f64> = (0..)
        .map(|k| 180.0 - k as f64 * step)
        .take_while(|&a| a >= hi + 0.5 * step)
        .collect();
    above.reverse();
    let budget = MAX_COUNT.saturating_sub(below.len() + above.len()).max(2);
    if inner.len() > budget {
        let k = inner.len().div_ceil(budget - 1);
        let last = inner[inner.len() - 1];
        inner = inner.iter().copied().step_by(k).collect();
        if inner.last() != Some(&last) {
            inner.push(last);
        }
    }
    let (first_inner, last_inner) = (inner[0], inner[inner.len() - 1]);
    let mut rows: Vec<f64> = below.into_iter().chain(inner).chain(above).collect();
    // Spend the remaining row budget on the extension, most where it changes fastest (just
    // past stall): repeatedly split the gap outside the computed range with the largest
    // width / (1 + distance from the range / outer step), until the budget is used or no
    // such gap is wider than 2·MIN_OUTER_GAP_DEG.
    while rows.len() < MAX_COUNT {
        let outside = |k: usize| rows[k] < first_inner || rows[k + 1] > last_inner;
        let priority = |k: usize| {
            let distance = (first_inner - rows[k + 1])
                .max(rows[k] - last_inner)
                .max(0.0);
            (rows[k + 1] - rows[k]) / (1.0 + distance / step)
        };
        let widest = (0..rows.len() - 1)
            .filter(|&k| outside(k))
            .max_by(|&a, &b| priority(a).total_cmp(&priority(b)));
        match widest {
            Some(k) if rows[k + 1] - rows[k] > 2.0 * MIN_OUTER_GAP_DEG => {
                let mid = ((rows[k] + rows[k + 1]) / 2.0 * 100.0).round() / 100.0;
                rows.insert(k + 1, mid);
            }
            _ => break,
        }
    }
    rows
}

/// Extension rows are not split below this spacing (deg).
const MIN_OUTER_GAP_DEG: f64 = 1.0;

/// `v` with `d` decimals, a negative value without the zero before the point (`-.0100`).
fn c81_number(v: f64, d: usize) -> String {
    let s = fixed_decimals(v, d);
    match s.strip_prefix("-0.") {
        Some(rest) => format!("-.{rest}"),
        None => s,
    }
}

/// The largest decimal count ≤ `max_dec` with which every value of `values` fits a field,
/// keeping at least one leading blank if `blank` is set.
fn block_decimals(values: &[f64], max_dec: usize, blank: bool) -> Result<usize, TableError> {
    let limit = if blank { FIELD - 1 } else { FIELD };
    for d in (0..=max_dec).rev() {
        match values.iter().find(|&&v| c81_number(v, d).len() > limit) {
            None => return Ok(d),
            Some(&v) if d == 0 => {
                return Err(TableError::FieldOverflow {
                    value: v,
                    width: FIELD,
                })
            }
            Some(_) => {}
        }
    }
    Ok(0)
}

/// `values` in 7-character fields, one decimal count for all (see [`block_decimals`]).
fn fields(values: &[f64], max_dec: usize, blank: bool) -> Result<Vec<String>, TableError> {
    let d = block_decimals(values, max_dec, blank)?;
    Ok(values
        .iter()
        .map(|&v| format!("{:>FIELD$}", c81_number(v, d)))
        .collect())
}

/// A value in a 7-character field with at most `max_dec` decimals.
fn field(v: f64, max_dec: usize, blank: bool) -> Result<String, TableError> {
    Ok(fields(&[v], max_dec, blank)?.remove(0))
}

/// The Mach columns written for a table Mach axis `mach`: the axis, or for one Mach number M
/// two columns, M and M + 0.1 (halfway to 1 when that reaches 1).
fn written_mach(mach: &[f64]) -> Vec<f64> {
    match mach {
        [m] => vec![
            *m,
            if m + 0.1 < 1.0 {
                m + 0.1
            } else {
                (m + 1.0) / 2.0
            },
        ],
        _ => mach.to_vec(),
    }
}

/// Append `lead` (a field or 7 blanks) and `values` as lines of at most 9 values each.
fn push_rows(out: &mut String, lead: &str, values: &[String]) {
    let blank = " ".repeat(FIELD);
    for (k, chunk) in values.chunks(9).enumerate() {
        out.push_str(if k == 0 { lead } else { &blank });
        for v in chunk {
            out.push_str(v);
        }
        out.push('\n');
    }
}

/// Write one C81 table of `table` at Reynolds number `re` to `w`.
pub fn write_c81_to(
    table: &PolarTable,
    re: f64,
    outer_step_deg: f64,
    w: &mut dyn Write,
) -> Result<(), TableError> {
    table.require_lookup()?;
    let ln = re.ln();
    let i_re = (0..table.re().len())
        .min_by(|&a, &b| {
            (table.re()[a].ln() - ln)
                .abs()
                .total_cmp(&(table.re()[b].ln() - ln).abs())
        })
        .unwrap_or(0);
    let alphas = c81_alphas(table, i_re, outer_step_deg);
    let mach = table.mach();
    if alphas.len() > MAX_COUNT {
        return Err(TableError::C81TooLarge {
            what: "alpha rows",
            count: alphas.len(),
        });
    }
    if mach.len() > MAX_COUNT {
        return Err(TableError::C81TooLarge {
            what: "Mach columns",
            count: mach.len(),
        });
    }
    let columns = written_mach(mach);
    let (na, nm) = (alphas.len(), columns.len());
    let mut name: String = format!("{} Re{}", table.meta().airfoil, re_label(re))
        .chars()
        .take(30)
        .collect();
    while name.chars().count() < 30 {
        name.push(' ');
    }
    let mut out = format!("{name}{nm:2}{na:2}{nm:2}{na:2}{nm:2}{na:2}\n");
    let mut blocks = [Vec::new(), Vec::new(), Vec::new()];
    for &a in &alphas {
        for &m in &columns {
            // A second column of a one-Mach table repeats the first (see the module docs).
            let l = table.lookup(a, re, m.min(mach[mach.len() - 1]));
            blocks[0].push(l.cl);
            blocks[1].push(l.cd);
            blocks[2].push(l.cm);
        }
    }
    let mach_fields = fields(&columns, 3, true)?;
    for block in &blocks {
        push_rows(&mut out, &" ".repeat(FIELD), &mach_fields);
        let values = fields(block, 4, true)?;
        for (&a, row) in alphas.iter().zip(values.chunks(nm)) {
            push_rows(&mut out, &field(a, 2, false)?, row);
        }
    }
    w.write_all(out.as_bytes()).map_err(TableError::Write)
}

/// Write C81 files: one per Re of the grid (`<stem>_Re<re>.c81` next to `path`, or `path`
/// itself for a single-Re table), all together or none ([`OutputSet`]), or only `path` at
/// `options.re`. Returns the files written.
pub fn write_c81(
    table: &PolarTable,
    path: &Path,
    options: &C81Options,
) -> Result<Vec<PathBuf>, TableError> {
    if let Some(re) = options.re {
        if !(re.is_finite() && re > 0.0) {
            return Err(TableError::BadRe(re));
        }
        write_output(path, |w| {
            write_c81_to(table, re, options.outer_step_deg, w).map_err(|e| e.in_output(path))
        })?;
        return Ok(vec![path.to_path_buf()]);
    }
    let mut set = OutputSet::new();
    for &re in table.re() {
        let file = re_path(path, table.re().len(), re);
        set.write(&file, |w| {
            write_c81_to(table, re, options.outer_step_deg, w).map_err(|e| e.in_output(&file))
        })?;
    }
    Ok(set.commit()?)
}

/// The file of the deck at `re` of a table of `count` Reynolds numbers written to `path`:
/// `path` itself for one, else `<stem>_Re<re>.<ext>` beside it.
pub(super) fn re_path(path: &Path, count: usize, re: f64) -> PathBuf {
    if count == 1 {
        return path.to_path_buf();
    }
    let (stem, ext) = (stem_or(path, "table"), extension_or(path, "c81"));
    path.with_file_name(format!("{stem}_Re{}.{ext}", re_label(re)))
}

/// The 7-character fields of a C81 data line from field `first` on: at most `count` numbers,
/// empty fields at the end of a short line ending the list.
fn line_fields(line: &str, first: usize, count: usize, at: usize) -> Result<Vec<f64>, TableError> {
    let chars: Vec<char> = line.chars().collect();
    let mut out = Vec::new();
    for k in first..first + count {
        let start = k * FIELD;
        if start >= chars.len() {
            break;
        }
        let text: String = chars[start..(start + FIELD).min(chars.len())]
            .iter()
            .collect();
        let text = text.trim();
        if text.is_empty() {
            break;
        }
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => out.push(v),
            _ => {
                return Err(TableError::C81 {
                    line: at,
                    message: format!("'{text}' is not a number"),
                })
            }
        }
    }
    Ok(out)
}

/// One coefficient block: its Mach list, α list and values (α-major).
struct C81Block {
    mach: Vec<f64>,
    alpha: Vec<f64>,
    values: Vec<f64>,
}

/// The lines of a C81 file and the next one to read.
struct Cursor<'a> {
    lines: Vec<&'a str>,
    /// Index (0-based) of the next line.
    next: usize,
}

impl Cursor<'_> {
    /// Up to `count` fields of the next line from field `first` on.
    fn take(&mut self, first: usize, count: usize, what: &str) -> Result<Vec<f64>, TableError> {
        let at = self.next + 1;
        let line = self.lines.get(self.next).ok_or_else(|| TableError::C81 {
            line: at,
            message: format!("the {what} block ends early"),
        })?;
        self.next += 1;
        line_fields(line, first, count, at)
    }

    /// `first_line` completed to `n` values from continuation lines (7 blanks, ≤ 9 fields).
    fn complete(
        &mut self,
        first_line: Vec<f64>,
        n: usize,
        what: &str,
    ) -> Result<Vec<f64>, TableError> {
        let mut v = first_line;
        while v.len() < n {
            let more = self.take(1, 9.min(n - v.len()), what)?;
            if more.is_empty() {
                break;
            }
            v.extend(more);
        }
        Ok(v)
    }

    /// The block of `nm` Mach and `na` α values that starts at the next line.
    fn block(&mut self, nm: usize, na: usize, what: &str) -> Result<C81Block, TableError> {
        let mach_line = self.next + 1;
        let first = self.take(1, 9.min(nm), what)?;
        let mach = self.complete(first, nm, what)?;
        if mach.len() != nm || mach.windows(2).any(|w| w[1] <= w[0]) {
            return Err(TableError::C81 {
                line: mach_line,
                message: format!("the {what} Mach list is not {nm} increasing numbers"),
            });
        }
        let mut alpha: Vec<f64> = Vec::with_capacity(na);
        let mut values = Vec::with_capacity(na * nm);
        for _ in 0..na {
            let at = self.next + 1;
            let row = self.take(0, 1 + 9.min(nm), what)?;
            let error = |message: String| TableError::C81 { line: at, message };
            let Some((&a, rest)) = row.split_first() else {
                return Err(error(format!("{what} row without an alpha")));
            };
            if alpha.last().is_some_and(|&last| a <= last) {
                return Err(error(format!(
                    "the {what} alpha list is not strictly increasing"
                )));
            }
            let row = self.complete(rest.to_vec(), nm, what)?;
            if row.len() != nm {
                return Err(error(format!(
                    "{what} row has {} values for {nm} Mach numbers",
                    row.len()
                )));
            }
            alpha.push(a);
            values.extend(row);
        }
        Ok(C81Block {
            mach,
            alpha,
            values,
        })
    }
}

impl C81Block {
    /// The value at Mach number `mach` and `alpha`, linear in both on this block's lists,
    /// held at their ends.
    fn at(&self, mach: f64, alpha: f64) -> f64 {
        let nm = self.mach.len();
        let (j, u) = bracket(&self.mach, mach);
        let (k, t) = bracket(&self.alpha, alpha);
        let v = |k: usize, j: usize| self.values[k * nm + j];
        // a + t·(b − a): equal neighbours give their value exactly.
        let lerp = |a: f64, b: f64, t: f64| a + t * (b - a);
        let row = |k: usize| match j {
            Some(j) => lerp(v(k, j), v(k, j + 1), u),
            None => v(k, 0),
        };
        match k {
            Some(k) => lerp(row(k), row(k + 1), t),
            None => row(0),
        }
    }
}

/// The interval `k` of `axis` (increasing) holding `x` and the fraction `t` along it, `x`
/// clamped to the axis; `None` for an axis of one value.
fn bracket(axis: &[f64], x: f64) -> (Option<usize>, f64) {
    if axis.len() < 2 {
        return (None, 0.0);
    }
    let k = axis.partition_point(|&a| a <= x).clamp(1, axis.len() - 1) - 1;
    let t = ((x - axis[k]) / (axis[k + 1] - axis[k])).clamp(0.0, 1.0);
    (Some(k), t)
}

/// Whether `head` (the start of a file) looks like a C81 deck: six counts of two digits in
/// columns 31–42 of the first line and a second line of numbers in 7-column fields after 7
/// blanks (the Mach list).
pub(crate) fn looks_like_c81(head: &str) -> bool {
    let mut lines = head.lines();
    let (Some(first), Some(second)) = (lines.next(), lines.next()) else {
        return false;
    };
    header_counts(first).is_some()
        && second
            .get(..FIELD)
            .is_some_and(|lead| lead.trim().is_empty())
        && line_fields(second, 1, 9, 2).is_ok_and(|v| !v.is_empty())
}

/// The six counts NML NAL NMD NAD NMM NAM of a C81 header line (columns 31–42).
fn header_counts(line: &str) -> Option<Vec<usize>> {
    let header: Vec<char> = line.chars().collect();
    (0..6)
        .map(|k| {
            let field: String = header.iter().skip(30 + 2 * k).take(2).collect();
            field.trim().parse::<usize>().ok().filter(|&n| n > 0)
        })
        .collect()
}

/// Parse a C81 table (see the module docs); `stem` is the file stem the Reynolds number may
/// come from. What [`parse_c81_with`] would say in notes is dropped.
pub fn parse_c81(text: &str, stem: &str) -> Result<PolarTable, TableError> {
    parse_c81_with(text, stem, &ReadOptions::default()).map(|read| read.table)
}

/// Parse a C81 table, assuming `options.re` when neither the deck's name nor `stem` gives a
/// Reynolds number; the notes say what was assumed or dropped.
pub fn parse_c81_with(
    text: &str,
    stem: &str,
    options: &ReadOptions,
) -> Result<TableRead, TableError> {
    let mut cursor = Cursor {
        lines: text.lines().collect(),
        next: 1,
    };
    let first = cursor.lines.first().copied().unwrap_or("");
    let counts = header_counts(first).ok_or_else(|| TableError::C81 {
        line: 1,
        message: "columns 31-42 must hold six counts of two digits (NML NAL NMD NAD NMM NAM)"
            .to_string(),
    })?;
    let name: String = first
        .chars()
        .take(30)
        .collect::<String>()
        .trim()
        .to_string();
    let cl = cursor.block(counts[0], counts[1], "CL")?;
    let cd = cursor.block(counts[2], counts[3], "CD")?;
    let cm = cursor.block(counts[4], counts[5], "CM")?;
    let mut notes = Vec::new();
    let union = |lists: [&[f64]; 3]| {
        let mut all: Vec<f64> = lists.concat();
        all.sort_by(f64::total_cmp);
        all.dedup();
        all
    };
    let mut mach = union([&cl.mach, &cd.mach, &cm.mach]);
    let supersonic: Vec<String> = mach
        .iter()
        .filter(|&&m| m >= 1.0)
        .map(|m| m.to_string())
        .collect();
    if !supersonic.is_empty() {
        notes.push(format!(
            "C81 deck: the column at Mach {} dropped (tables hold 0 <= M < 1)",
            supersonic.join(", ")
        ));
        mach.retain(|&m| m < 1.0);
    }
    let mut alpha = union([&cl.alpha, &cd.alpha, &cm.alpha]);
    alpha.retain(|a| a.abs() <= 180.0);
    let polar = |m: f64| -> Vec<PolarPoint> {
        alpha
            .iter()
            .map(|&a| PolarPoint::from_coefficients(a, cl.at(m, a), cd.at(m, a), cm.at(m, a)))
            .collect()
    };
    let mut polars: Vec<Vec<PolarPoint>> = mach.iter().map(|&m| polar(m)).collect();
    // Identical columns throughout: a one-Mach table written for two-column readers.
    let coefficients =
        |p: &[PolarPoint]| -> Vec<[f64; 3]> { p.iter().map(|q| [q.cl, q.cd, q.cm]).collect() };
    if polars.len() > 1
        && polars
            .iter()
            .all(|p| coefficients(p) == coefficients(&polars[0]))
    {
        polars.truncate(1);
        mach.truncate(1);
    }
    let re_word = |s: &str| {
        s.split(|c: char| c.is_whitespace() || c == '_')
            .find_map(|w| w.strip_prefix("Re").and_then(|v| v.parse::<f64>().ok()))
    };
    let re = match re_word(&name).or_else(|| re_word(stem)) {
        Some(re) => re,
        None => {
            let re = options.re.unwrap_or(1e6);
            notes.push(format!(
                "C81 deck: it gives no Reynolds number; Re {re} assumed{}",
                if options.re.is_some() {
                    ""
                } else {
                    " (set it with --assume-re)"
                }
            ));
            re
        }
    };
    let airfoil = name
        .split_whitespace()
        .filter(|w| re_word(w).is_none())
        .collect::<Vec<_>>()
        .join(" ");
    let airfoil = if airfoil.is_empty() { stem } else { &airfoil };
    let meta = TableMeta::unknown(airfoil, "C81 deck");
    let table = PolarTable::new(meta, vec![re], mach, polars)?;
    Ok(TableRead { table, notes })
}
