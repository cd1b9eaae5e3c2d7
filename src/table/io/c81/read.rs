//! The C81 reader: the fixed 7-column fields, each coefficient block on its own Mach and α
//! lists (see the [module docs](super)).

use super::FIELD;
use crate::section::PolarPoint;
use crate::table::{PolarTable, ReadOptions, TableError, TableMeta, TableRead};

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
/// come from. What `parse_c81_with` would say in notes is dropped.
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
