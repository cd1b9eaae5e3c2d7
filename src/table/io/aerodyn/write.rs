//! Writing AeroDyn airfoil files (see the [module docs](super) for the layout).

use super::{Entry, Header, LABEL_WIDTH};
use crate::output::{write_output, OutputSet};
use crate::section::SectionAero;
use crate::table::io::xfoil_polar::re_label;
use crate::table::io::{extension_or, stem_or};
use crate::table::{ua_parameters, PolarTable, TableError};
use std::fmt::Write as _;
use std::io::Write;
use std::path::{Path, PathBuf};

/// α spacing (deg) of the rows outside the computed range.
pub const OUTER_STEP_DEG: f64 = 5.0;

/// A dashed comment line, as OpenFAST's example files separate sections.
const RULE: &str =
    "! ------------------------------------------------------------------------------";

/// The α rows of the table at grid row (`i_re`, `i_mach`); see the module docs.
fn aerodyn_alphas(table: &PolarTable, i_re: usize, i_mach: usize) -> Vec<f64> {
    let mut inner: Vec<f64> = table
        .polar_at(i_re, i_mach)
        .unwrap_or(&[])
        .iter()
        .filter(|p| p.usable() && p.alpha.abs() < 180.0)
        .map(|p| p.alpha)
        .collect();
    inner.sort_by(f64::total_cmp);
    inner.dedup();
    let (lo, hi) = match (inner.first(), inner.last()) {
        (Some(&lo), Some(&hi)) => (lo, hi),
        _ => (0.0, 0.0),
    };
    let step = OUTER_STEP_DEG;
    let empty = inner.is_empty();
    let below = (0..)
        .map(|k| -180.0 + k as f64 * step)
        .take_while(|&a| a <= lo - 0.5 * step || (empty && a < 180.0));
    let mut above: Vec<f64> = (0..)
        .map(|k| 180.0 - k as f64 * step)
        .take_while(|&a| a >= hi + 0.5 * step || a == 180.0)
        .collect();
    above.reverse();
    let mut rows: Vec<f64> = below.chain(inner).collect();
    rows.retain(|&a| a < above[0]);
    rows.extend(above);
    rows
}

/// `v` in shortest round-trip form, with an exponent when it is tiny or huge (`2.45e-16`, not
/// sixteen zeros).
fn number(v: f64) -> String {
    if v == 0.0 || (1e-4..1e15).contains(&v.abs()) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// A `value name ! comment` line, the value padded so that the names line up.
fn keyed(s: &mut String, value: &str, name: &str, comment: &str) {
    let _ = writeln!(s, "{value:<LABEL_WIDTH$} {name:<14} ! {comment}");
}

/// Write one AeroDyn airfoil file of `table` at Mach column `i_mach` to `w`: one table per Re.
pub fn write_aerodyn_to(
    table: &PolarTable,
    i_mach: usize,
    w: &mut dyn Write,
) -> Result<(), TableError> {
    table.require_lookup()?;
    let entries: Vec<Entry> = (0..table.re().len()).map(|i_re| (table, i_re)).collect();
    write_file(&entries, i_mach, "one table per Reynolds number", w)
}

/// Write the AeroDyn airfoil file holding `entries` (not empty, all at the Mach number of
/// column `i_mach`) as its tables in this order to `w`; `tabs` says on the `NumTabs` line
/// what the tables are. The comment header and `RelThickness` are those of the first entry.
pub(super) fn write_file(
    entries: &[Entry],
    i_mach: usize,
    tabs: &str,
    w: &mut dyn Write,
) -> Result<(), TableError> {
    let table = entries[0].0;
    let mach = table.mach()[i_mach];
    let meta = table.meta();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "! ------------ AirfoilInfo v1.01 input file written by polargen {} ------------",
        env!("CARGO_PKG_VERSION")
    );
    let xtr = |x: f64| {
        if x.is_nan() {
            "unknown".to_string()
        } else {
            x.to_string()
        }
    };
    let _ = writeln!(
        s,
        "! {}: Mach {mach}, Ncrit {}, forced transition x/c {} (top) {} (bottom), {}",
        meta.airfoil,
        meta.transition.ncrit_text(),
        xtr(meta.transition.xtr_top),
        xtr(meta.transition.xtr_bot),
        if meta.solver.is_empty() {
            "solver not recorded"
        } else {
            &meta.solver
        }
    );
    let _ = writeln!(
        s,
        "! Beyond each table's usable alpha range (converged points outside massive \
         separation): 360-degree extension (Viterna-Corrigan, then a flat plate), Cd_max {}",
        table.post_stall_params().cd_max
    );
    s.push_str(
        "! UA coefficients: alpha0, alpha1, alpha2, C_nalpha, Cn1, Cn2, Cd0, Cm0, k0 from the \
         polar; the others OpenFAST's defaults\n",
    );
    if entries
        .iter()
        .any(|(t, _)| user_prop(t) != user_prop(table))
    {
        let degs: Vec<String> = entries
            .iter()
            .map(|(t, _)| crate::limits::exact_number(user_prop(t)))
            .collect();
        let _ = writeln!(
            s,
            "! One table per flap deflection (UserProp, deg): {}; the airfoil line names the first",
            degs.join(", ")
        );
    }
    let _ = writeln!(s, "! {}", Header::new(entries, i_mach).to_line());
    s.push_str(RULE);
    s.push('\n');
    keyed(
        &mut s,
        "\"DEFAULT\"",
        "InterpOrd",
        "interpolation order: OpenFAST's default",
    );
    let thickness = meta.thickness;
    if thickness.is_finite() {
        keyed(
            &mut s,
            &thickness.to_string(),
            "RelThickness",
            "largest thickness / chord of the contour",
        );
    }
    keyed(&mut s, "1", "NonDimArea", "unused by AeroDyn");
    keyed(&mut s, "0", "NumCoords", "no airfoil coordinates");
    keyed(&mut s, "\"unused\"", "BL_file", "aeroacoustics only");
    keyed(&mut s, &entries.len().to_string(), "NumTabs", tabs);
    for (k, &(table, i_re)) in entries.iter().enumerate() {
        write_table_block(&mut s, k, table, i_re, i_mach);
    }
    w.write_all(s.as_bytes()).map_err(TableError::Write)
}

/// The lines of the file's table `k` (0-based), grid row (`i_re`, `i_mach`) of `table`: Re,
/// UserProp (the flap deflection in degrees, 0 without a flap), the UA block, NumAlf, the
/// column headers and the rows.
fn write_table_block(s: &mut String, k: usize, table: &PolarTable, i_re: usize, i_mach: usize) {
    let (re, mach) = (table.re()[i_re], table.mach()[i_mach]);
    let alphas = aerodyn_alphas(table, i_re, i_mach);
    let (lo, hi) = table.alpha_range(i_re, i_mach).unwrap_or((0.0, 0.0));
    s.push_str(RULE);
    s.push('\n');
    let flap = user_prop(table);
    let _ = writeln!(
        s,
        "! table {}: Re {}{}, computed alpha {lo} to {hi} deg",
        k + 1,
        re_label(re),
        table
            .meta()
            .flap_deg()
            .map_or(String::new(), |_| format!(", flap {flap} deg"))
    );
    s.push_str(RULE);
    s.push('\n');
    keyed(
        s,
        &(re / 1e6).to_string(),
        "Re",
        "Reynolds number in millions",
    );
    let note = if table.meta().flap_deg().is_some() {
        "flap deflection (deg, trailing edge down positive)"
    } else {
        "no flap: 0"
    };
    keyed(s, &crate::limits::exact_number(flap), "UserProp", note);
    match ua_parameters(table, i_re, i_mach) {
        Some(ua) => {
            keyed(s, "True", "InclUAdata", "unsteady-aero coefficients follow");
            let _ = writeln!(
                s,
                "!........ C_nalpha fitted on alpha {} to {} deg (median of the local slopes{})",
                ua.fit_alpha.0,
                ua.fit_alpha.1,
                if ua.supercritical_fit {
                    "; supercritical points included: the subcritical ones give no attached range"
                } else {
                    ""
                }
            );
            for (name, value, note) in ua.lines() {
                keyed(s, &number(value), name, note);
            }
            s.push_str("!........ end of the unsteady-aero coefficients\n");
        }
        None => keyed(
            s,
            "False",
            "InclUAdata",
            "no attached range in the polar: OpenFAST derives the UA coefficients",
        ),
    }
    keyed(
        s,
        &alphas.len().to_string(),
        "NumAlf",
        "number of rows of the table",
    );
    s.push_str("!    Alpha      Cl      Cd        Cm\n");
    s.push_str("!    (deg)      (-)     (-)       (-)\n");
    let first = table.lookup(-180.0, re, mach);
    for &a in &alphas {
        let l = if a == 180.0 {
            first
        } else {
            table.lookup(a, re, mach)
        };
        let _ = writeln!(s, "{a} {} {} {}", number(l.cl), number(l.cd), number(l.cm));
    }
}

/// A table's `UserProp`: its flap deflection in degrees, 0 without a flap (−0 written as 0).
pub(super) fn user_prop(table: &PolarTable) -> f64 {
    table.meta().flap_deg().unwrap_or(0.0) + 0.0
}

/// The file of the Mach number `mach` of a table of `count` Mach numbers written to `path`:
/// `path` itself for one, else `<stem>_M<mach>.<ext>` beside it.
pub(crate) fn mach_path(path: &Path, count: usize, mach: f64) -> PathBuf {
    if count == 1 {
        return path.to_path_buf();
    }
    let (stem, ext) = (stem_or(path, "airfoil"), extension_or(path, "dat"));
    path.with_file_name(format!("{stem}_M{mach}.{ext}"))
}

/// Write AeroDyn files: `path` for a one-Mach table, else one per Mach number
/// (`<stem>_M<mach>.<ext>` next to `path`), all together or none. Returns the files written.
pub fn write_aerodyn(table: &PolarTable, path: &Path) -> Result<Vec<PathBuf>, TableError> {
    if table.mach().len() == 1 {
        write_output(path, |w| {
            write_aerodyn_to(table, 0, w).map_err(|e| e.in_output(path))
        })?;
        return Ok(vec![path.to_path_buf()]);
    }
    let mut set = OutputSet::new();
    stage_aerodyn(table, path, &mut set)?;
    Ok(set.commit()?)
}

/// The files of [`write_aerodyn`], staged in `set` (written when it is committed). Returns
/// the files staged.
pub(crate) fn stage_aerodyn(
    table: &PolarTable,
    path: &Path,
    set: &mut OutputSet,
) -> Result<Vec<PathBuf>, TableError> {
    let mut files = Vec::with_capacity(table.mach().len());
    for (i_mach, &mach) in table.mach().iter().enumerate() {
        let file = mach_path(path, table.mach().len(), mach);
        set.write(&file, |w| {
            write_aerodyn_to(table, i_mach, w).map_err(|e| e.in_output(&file))
        })?;
        files.push(file);
    }
    Ok(files)
}
