//! The C81 writer: α rows, fixed-width fields and one deck per Reynolds number (see the
//! [module docs](super)).

use super::super::xfoil_polar::re_label;
use super::super::{extension_or, stem_or};
use super::{FIELD, MAX_COUNT};
use crate::output::{fixed_decimals, write_output, OutputSet};
use crate::section::SectionAero;
use crate::table::{PolarTable, TableError};
use std::io::Write;
use std::path::{Path, PathBuf};

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
    stage_c81(table, path, options.outer_step_deg, &mut set)?;
    Ok(set.commit()?)
}

/// The files of [`write_c81`] for every Re of `table` (α step `outer_step_deg` outside
/// ±20°), staged in `set` (written when it is committed). Returns the files staged.
pub(crate) fn stage_c81(
    table: &PolarTable,
    path: &Path,
    outer_step_deg: f64,
    set: &mut OutputSet,
) -> Result<Vec<PathBuf>, TableError> {
    let mut files = Vec::with_capacity(table.re().len());
    for &re in table.re() {
        let file = re_path(path, table.re().len(), re);
        set.write(&file, |w| {
            write_c81_to(table, re, outer_step_deg, w).map_err(|e| e.in_output(&file))
        })?;
        files.push(file);
    }
    Ok(files)
}

/// The file of the deck at `re` of a table of `count` Reynolds numbers written to `path`:
/// `path` itself for one, else `<stem>_Re<re>.<ext>` beside it.
pub(in crate::table::io) fn re_path(path: &Path, count: usize, re: f64) -> PathBuf {
    if count == 1 {
        return path.to_path_buf();
    }
    let (stem, ext) = (stem_or(path, "table"), extension_or(path, "c81"));
    path.with_file_name(format!("{stem}_Re{}.{ext}", re_label(re)))
}
