//! OpenFAST AeroDyn airfoil files ("AirfoilInfo v1.01"): one file per airfoil and Mach number,
//! one table per Reynolds number.
//!
//! Layout (OpenFAST `modules/aerodyn/src/AirfoilInfo.f90`, `ReadAFfile`; the AeroDyn user
//! guide, "Airfoil Data Input File"): comment lines start with `!`; every other line is
//! `value name [comment]`, read in this order: `InterpOrd`, `NonDimArea`, `NumCoords`,
//! `BL_file`, `NumTabs`, then per table `Re` (in millions), `UserProp`, `InclUAdata`, `NumAlf`
//! and `NumAlf` rows `alpha cl cd cm` (α in degrees, strictly increasing, from −180° to 180°
//! with equal coefficients at both ends). The optional `RelThickness` line is left out (the
//! table does not know t/c; only UA_Mod 7 uses it). `BL_file` is written because the
//! `openfast_io` reader (5.0.0) requires it.
//!
//! What this writer chooses:
//! * One table per Re of the grid, Re strictly increasing, `UserProp` 0 (AeroDyn interpolates
//!   between tables in ln Re with `AFTabMod = 2`). A table with several Mach numbers gives one
//!   file per Mach number (`<stem>_M<mach>.dat`), all together or none ([`OutputSet`]).
//! * α rows: every usable α (converged, not in massive separation) of the polar at that
//!   (Re, M), and outside that range
//!   rows every [`OUTER_STEP_DEG`] from −180° and up to 180°, kept at least half a step away
//!   from it. Values come from [`SectionAero::lookup`], so they include the 360° extension
//!   (Viterna–Corrigan, then a flat plate, with the table's `cd_max`) and never use
//!   unconverged points or points in massive separation (the extension replaces them, from the
//!   last usable point; a comment line says so); the +180° row repeats the −180° row.
//! * Numbers in shortest round-trip form (reading the file gives back the same doubles).
//! * `InclUAdata False` for every table: no unsteady-aerodynamics parameters from us. In
//!   current OpenFAST this does **not** switch unsteady aerodynamics off (that is `UA_Mod = 0`
//!   in the AeroDyn primary file): it makes OpenFAST derive every UA parameter itself
//!   (`CalculateUACoeffs`) from the very table written here. Deriving them here as well would
//!   be a second implementation of OpenFAST's method on the same data, and openfast_toolbox's
//!   other method disagrees with it on Cd0 and Cn1 — so the one derivation is OpenFAST's own.

use super::xfoil_polar::re_label;
use super::{extension_or, stem_or};
use crate::output::{write_output, OutputSet};
use crate::section::SectionAero;
use crate::table::{PolarTable, TableError};
use std::fmt::Write as _;
use std::io::Write;
use std::path::{Path, PathBuf};

/// α spacing (deg) of the rows outside the computed range.
pub const OUTER_STEP_DEG: f64 = 5.0;

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

/// Write one AeroDyn airfoil file of `table` at Mach column `i_mach` to `w`.
pub fn write_aerodyn_to(
    table: &PolarTable,
    i_mach: usize,
    w: &mut dyn Write,
) -> Result<(), TableError> {
    table.require_lookup()?;
    let mach = table.mach()[i_mach];
    let meta = table.meta();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "! AeroDyn airfoil file (AirfoilInfo v1.01) written by {}: {}, M {mach}, Ncrit {}, \
         transition x/c {} (top) {} (bottom)",
        if meta.solver.is_empty() {
            "polargen"
        } else {
            &meta.solver
        },
        meta.airfoil.replace(['\n', '\r'], " "),
        meta.transition.ncrit_text(),
        meta.transition.xtr_top,
        meta.transition.xtr_bot
    );
    let _ = writeln!(
        s,
        "! Beyond the usable alpha range (converged points outside massive separation): \
         360-degree extension (Viterna-Corrigan, flat plate), Cd_max {}",
        table.post_stall_params().cd_max
    );
    s.push_str("\"DEFAULT\"   InterpOrd    ! interpolation order: OpenFAST's default\n");
    s.push_str("1           NonDimArea   ! unused\n");
    s.push_str("0           NumCoords    ! no airfoil coordinates\n");
    s.push_str("\"unused\"    BL_file      ! aeroacoustics only\n");
    let _ = writeln!(
        s,
        "{:<11} NumTabs      ! one table per Re",
        table.re().len()
    );
    for (i_re, &re) in table.re().iter().enumerate() {
        let alphas = aerodyn_alphas(table, i_re, i_mach);
        let _ = writeln!(s, "! ---- table {}: Re {} ----", i_re + 1, re_label(re));
        let _ = writeln!(
            s,
            "{:<11} Re           ! Reynolds number in millions",
            re / 1e6
        );
        s.push_str("0           UserProp     ! no control setting\n");
        s.push_str(
            "False       InclUAdata   ! OpenFAST derives the UA parameters from this table\n",
        );
        let _ = writeln!(
            s,
            "{:<11} NumAlf       ! rows: alpha [deg], Cl, Cd, Cm",
            alphas.len()
        );
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
    w.write_all(s.as_bytes()).map_err(TableError::Write)
}

/// The file of the Mach number `mach` of a table of `count` Mach numbers written to `path`:
/// `path` itself for one, else `<stem>_M<mach>.<ext>` beside it.
pub(super) fn mach_path(path: &Path, count: usize, mach: f64) -> PathBuf {
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
    for (i_mach, &mach) in table.mach().iter().enumerate() {
        let file = mach_path(path, table.mach().len(), mach);
        set.write(&file, |w| {
            write_aerodyn_to(table, i_mach, w).map_err(|e| e.in_output(&file))
        })?;
    }
    Ok(set.commit()?)
}
