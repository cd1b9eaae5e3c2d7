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
//! * α rows: every converged α of the polars used (the nearest Re row of the grid), thinned
//!   uniformly if needed to fit the 99-row limit of the I2 counts, plus rows every
//!   `outer_step_deg` from −180° and up to +180° outside that range, kept at least half a
//!   step away from it; any rows left of the 99 then split the widest gaps outside the
//!   computed range, weighted towards it (the extension changes fastest after stall), while
//!   gaps wider than 2° remain. Values come from [`SectionAero::lookup`], so they include the 360° extension
//!   and never use unconverged points.
//! * Fields: Mach F7.3, α F7.2, coefficients with as many decimals (≤ 4) as leave at least one
//!   leading blank, so that free-format (whitespace-splitting) readers work too.
//! * The format has no comment line and no field for the minimum pressure or the supercritical
//!   flag, so a deck cannot carry them: supercritical points enter it like any other. The CSV,
//!   JSON and XFOIL-polar forms of the same table hold them.

use super::xfoil_polar::re_label;
use crate::output::{fixed_decimals, write_output, OutputSet};
use crate::section::SectionAero;
use crate::table::{PolarTable, TableError};
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
        .filter(|p| p.converged)
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

/// Format a value in a 7-character field with at most `max_dec` decimals, keeping at least
/// one leading blank if `blank` is set.
fn field(v: f64, max_dec: usize, blank: bool) -> Result<String, TableError> {
    let limit = if blank { FIELD - 1 } else { FIELD };
    for d in (0..=max_dec).rev() {
        let s = fixed_decimals(v, d);
        if s.len() <= limit {
            return Ok(format!("{s:>FIELD$}"));
        }
    }
    Err(TableError::FieldOverflow {
        value: v,
        width: FIELD,
    })
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
    let (na, nm) = (alphas.len(), mach.len());
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
        for &m in mach {
            let l = table.lookup(a, re, m);
            blocks[0].push(l.cl);
            blocks[1].push(l.cd);
            blocks[2].push(l.cm);
        }
    }
    let mach_fields = mach
        .iter()
        .map(|&m| field(m, 3, true))
        .collect::<Result<Vec<_>, _>>()?;
    for block in &blocks {
        push_rows(&mut out, &" ".repeat(FIELD), &mach_fields);
        for (&a, row) in alphas.iter().zip(block.chunks(nm)) {
            let row = row
                .iter()
                .map(|&v| field(v, 4, true))
                .collect::<Result<Vec<_>, _>>()?;
            push_rows(&mut out, &field(a, 2, false)?, &row);
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
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "table".to_string());
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().into_owned())
        .unwrap_or_else(|| "c81".to_string());
    let mut set = OutputSet::new();
    for &re in table.re() {
        let file = if table.re().len() == 1 {
            path.to_path_buf()
        } else {
            path.with_file_name(format!("{stem}_Re{}.{ext}", re_label(re)))
        };
        set.write(&file, |w| {
            write_c81_to(table, re, options.outer_step_deg, w).map_err(|e| e.in_output(&file))
        })?;
    }
    Ok(set.commit()?)
}
