//! XFOIL polar text: the layout of the file XFOIL 6.99 writes with `PACC` (a 12-line header
//! with the airfoil name, transition settings, Mach, Re and N_crit, then the columns
//! `alpha CL CD CDp CM Top_Xtr Bot_Xtr` in Fortran F8.3, F9.4, F10.5, F10.5, F9.4, F9.4, F9.4
//! fields). Only converged points are written, sorted by α. The version line names this
//! table's solver instead of XFOIL.

use super::atomic::write_atomic;
use crate::polar::PolarPoint;
use crate::table::{PolarTable, TableError, TableMeta};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Write one polar in XFOIL's polar-file layout to `w`.
pub fn write_polar_to(
    meta: &TableMeta,
    re: f64,
    mach: f64,
    points: &[PolarPoint],
    w: &mut dyn Write,
) -> Result<(), TableError> {
    let solver = if meta.solver.is_empty() {
        "polargen"
    } else {
        meta.solver.as_str()
    };
    let mut s = String::new();
    s.push_str(" \n");
    s.push_str(&format!("       {solver}\n"));
    s.push_str(" \n");
    s.push_str(&format!(" Calculated polar for: {}\n", meta.airfoil));
    s.push_str(" \n");
    s.push_str(" 1 1 Reynolds number fixed          Mach number fixed         \n");
    s.push_str(" \n");
    s.push_str(&format!(
        " xtrf = {:7.3} (top)      {:7.3} (bottom)  \n",
        meta.xtr_top_set, meta.xtr_bot_set
    ));
    s.push_str(&format!(
        " Mach = {:7.3}     Re = {:9.3} e 6     Ncrit = {:7.3}\n",
        mach,
        re / 1e6,
        meta.ncrit
    ));
    s.push_str(" \n");
    s.push_str("   alpha    CL        CD       CDp       CM     Top_Xtr  Bot_Xtr\n");
    s.push_str("  ------ -------- --------- --------- -------- -------- --------\n");
    for p in points.iter().filter(|p| p.converged) {
        s.push_str(&format!(
            "{:8.3}{:9.4}{:10.5}{:10.5}{:9.4}{:9.4}{:9.4}\n",
            p.alpha, p.cl, p.cd, p.cdp, p.cm, p.xtr_top, p.xtr_bot
        ));
    }
    w.write_all(s.as_bytes())
        .map_err(|e| TableError::io("<polar writer>", e))
}

/// File name of the polar at (Re, M) for output stem `stem`: `<stem>_Re<re>_M<mach>.pol`,
/// with Re as mantissa and exponent (`1.9e6`) and M in shortest decimal form (`0.41`).
pub fn polar_file_name(stem: &str, re: f64, mach: f64) -> String {
    format!("{stem}_Re{}_M{mach}.pol", re_label(re))
}

/// Re as `<mantissa>e<exponent>` with at most 6 significant digits, e.g. `2.5e5`, `1.9e6`.
pub fn re_label(re: f64) -> String {
    let mut exp = re.abs().log10().floor();
    let mut m = format!("{:.5}", re / 10f64.powf(exp));
    if m.starts_with("10") {
        exp += 1.0;
        m = format!("{:.5}", re / 10f64.powf(exp));
    }
    while m.ends_with('0') {
        m.pop();
    }
    if m.ends_with('.') {
        m.pop();
    }
    format!("{m}e{exp}")
}

/// Write the converged points of every polar of `table` as XFOIL polar files: `path` itself
/// when the table has one polar, otherwise `<dir>/<stem>_Re<re>_M<mach>.pol` for each
/// (Re, M), where `<stem>` is `path` without extension. Returns the files written.
pub fn write_xfoil_polars(table: &PolarTable, path: &Path) -> Result<Vec<PathBuf>, TableError> {
    let single = table.re().len() * table.mach().len() == 1;
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "polar".to_string());
    let mut written = Vec::new();
    for (re, mach, points) in table.polars() {
        let file = if single {
            path.to_path_buf()
        } else {
            path.with_file_name(polar_file_name(&stem, re, mach))
        };
        write_atomic(&file, |w| write_polar_to(table.meta(), re, mach, points, w))?;
        written.push(file);
    }
    Ok(written)
}
