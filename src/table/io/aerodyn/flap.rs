//! AeroDyn files of a flap sweep: the tables of one section at several flap deflections,
//! one file per (Re, M) holding one table per deflection, told apart by `UserProp`.
//!
//! OpenFAST interpolates between the tables of a file in `UserProp` with `AFTabMod = 3`
//! (AeroDyn input): `AFI_Init` in OpenFAST's `modules/aerodyn/src/AirfoilInfo.f90` then
//! refuses a file whose tables do not all have the Re of the first table, or whose `UserProp`
//! values are not unique and increasing (`CheckValuesAreUniqueMonotonicIncreasing`). So each
//! file holds one (Re, M) of the sweep's common grid, its tables ordered by increasing
//! deflection.

use super::write::{user_prop, write_file};
use super::Entry;
use crate::output::OutputSet;
use crate::table::io::xfoil_polar::re_label;
use crate::table::io::{extension_or, stem_or};
use crate::table::{PolarTable, TableError};
use std::path::{Path, PathBuf};

/// The file of the grid point (`re`, `mach`) of a flap sweep over a grid of `count` (Re, M)
/// points written to `path`: `path` itself for one, else `<stem>_Re<re>_M<mach>.<ext>`
/// beside it (Re as in XFOIL polar file names, `1.9e6`).
pub(crate) fn flap_sweep_path(path: &Path, count: usize, re: f64, mach: f64) -> PathBuf {
    if count == 1 {
        return path.to_path_buf();
    }
    let (stem, ext) = (stem_or(path, "airfoil"), extension_or(path, "dat"));
    path.with_file_name(format!("{stem}_Re{}_M{mach}.{ext}", re_label(re)))
}

/// The files [`write_aerodyn_flap_sweep`] writes for a sweep over the grid `re` × `mach`, in
/// the order Re, then Mach.
pub(crate) fn flap_sweep_files(path: &Path, re: &[f64], mach: &[f64]) -> Vec<PathBuf> {
    let count = re.len() * mach.len();
    re.iter()
        .flat_map(|&r| {
            mach.iter()
                .map(move |&m| flap_sweep_path(path, count, r, m))
        })
        .collect()
}

/// Write the tables of a flap sweep (one per deflection, all on the same Re × Mach grid with
/// the same 360°-extension parameters, deflections distinct: `UserProp` is each table's
/// [`flap_deg`](crate::table::TableMeta::flap_deg), 0 without a flap) as AeroDyn files, one
/// per (Re, M) (`flap_sweep_path`), each with one table per deflection in increasing
/// order; all files or none. Returns the files written.
pub fn write_aerodyn_flap_sweep(
    tables: &[PolarTable],
    path: &Path,
) -> Result<Vec<PathBuf>, TableError> {
    let mut sorted: Vec<&PolarTable> = tables.iter().collect();
    sorted.sort_by(|a, b| user_prop(a).total_cmp(&user_prop(b)));
    check_sweep(&sorted)?;
    let first = sorted[0];
    let (re, mach) = (first.re(), first.mach());
    let count = re.len() * mach.len();
    let mut set = OutputSet::new();
    for (i_re, &r) in re.iter().enumerate() {
        for (i_mach, &m) in mach.iter().enumerate() {
            let file = flap_sweep_path(path, count, r, m);
            let entries: Vec<Entry> = sorted.iter().map(|&t| (t, i_re)).collect();
            set.write(&file, |w| {
                write_file(
                    &entries,
                    i_mach,
                    "one table per flap deflection (UserProp)",
                    w,
                )
                .map_err(|e| e.in_output(&file))
            })?;
        }
    }
    Ok(set.commit()?)
}

/// The sweep's tables (sorted by `UserProp`) can share files: at least one, each usable for
/// lookups, one grid and one extension, no deflection twice.
fn check_sweep(sorted: &[&PolarTable]) -> Result<(), TableError> {
    let Some(first) = sorted.first() else {
        return Err(TableError::AeroDynTables(
            "a flap sweep needs at least one table".to_string(),
        ));
    };
    for table in sorted {
        table.require_lookup()?;
        if table.re() != first.re() || table.mach() != first.mach() {
            return Err(TableError::AeroDynTables(
                "the tables of a flap sweep must share one Re x Mach grid".to_string(),
            ));
        }
        if table.post_stall_params() != first.post_stall_params() {
            return Err(TableError::AeroDynTables(
                "the tables of a flap sweep must share one 360-degree extension".to_string(),
            ));
        }
    }
    if let Some(w) = sorted
        .windows(2)
        .find(|w| user_prop(w[0]) == user_prop(w[1]))
    {
        return Err(TableError::AeroDynTables(format!(
            "two tables of the flap sweep at UserProp (flap deflection) {}",
            user_prop(w[0])
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::ShapeOp;
    use crate::section::PolarPoint;
    use crate::table::io::ReadOptions;
    use crate::table::{PostStallParams, TableMeta};

    /// A one-polar table of the NACA 0012 with a flap deflected `deg`: Cl = 0.1·α + 0.05·deg
    /// from `lo` to 8° every 2°.
    fn flapped(deg: f64, lo: i32) -> PolarTable {
        let meta = TableMeta {
            geometry: vec![ShapeOp::Flap {
                hinge_x: 0.75,
                hinge_y: 0.0,
                deflection_deg: deg,
            }],
            thickness: 0.12,
            ..TableMeta::unknown("naca0012", "test")
        };
        let points = (lo..=4)
            .map(|k| {
                let a = 2.0 * f64::from(k);
                PolarPoint::from_coefficients(a, 0.1 * a + 0.05 * deg, 0.01, -0.01 * deg)
            })
            .collect();
        PolarTable::with_params(
            meta,
            vec![1e6],
            vec![0.2],
            vec![points],
            PostStallParams::default(),
        )
        .unwrap()
    }

    /// The file of a sweep: tables by increasing deflection (as OpenFAST's AFTabMod 3 needs),
    /// UserProp the deflection, and each table read back whole with its own metadata and α
    /// range (the −5° table is written first and has a different range).
    #[test]
    fn a_sweep_file_orders_the_deflections_and_reads_back_each() {
        let tables = [flapped(5.0, -3), flapped(-5.0, -1), flapped(0.0, -2)];
        let sorted: Vec<&PolarTable> = vec![&tables[1], &tables[2], &tables[0]];
        let entries: Vec<Entry> = sorted.iter().map(|&t| (t, 0)).collect();
        let mut bytes = Vec::new();
        write_file(&entries, 0, "flaps", &mut bytes).unwrap();
        let text = String::from_utf8(bytes).unwrap();
        let props: Vec<&str> = text
            .lines()
            .filter(|l| l.contains(" UserProp "))
            .map(|l| l.split_whitespace().next().unwrap())
            .collect();
        assert_eq!(props, ["-5", "0", "5"]);
        for table in &tables {
            let deg = table.meta().flap_deg().unwrap();
            let options = ReadOptions {
                user_prop: Some(deg),
                ..ReadOptions::default()
            };
            let back = super::super::parse_aerodyn(&text, "f", &options)
                .unwrap()
                .table;
            assert_eq!(back.meta(), table.meta());
            assert_eq!(back.mach(), &[0.2]);
            let rows = |t: &PolarTable| -> Vec<[f64; 4]> {
                t.polar_at(0, 0)
                    .unwrap()
                    .iter()
                    .map(|p| [p.alpha, p.cl, p.cd, p.cm])
                    .collect()
            };
            assert_eq!(rows(&back), rows(table));
        }
        // Two tables at one deflection, or on different grids, cannot share the files.
        let twice = [flapped(5.0, -3), flapped(5.0, -2)];
        let err = write_aerodyn_flap_sweep(&twice, Path::new("/nonexistent/f.dat"));
        assert!(err.unwrap_err().to_string().contains("UserProp"));
    }

    #[test]
    fn sweep_files_are_named_by_re_and_mach() {
        let path = Path::new("d/f.dat");
        assert_eq!(flap_sweep_files(path, &[1e6], &[0.0]), [path]);
        assert_eq!(
            flap_sweep_files(path, &[1e6, 2.5e6], &[0.0, 0.3]),
            [
                "d/f_Re1e6_M0.dat",
                "d/f_Re1e6_M0.3.dat",
                "d/f_Re2.5e6_M0.dat",
                "d/f_Re2.5e6_M0.3.dat"
            ]
            .map(PathBuf::from)
        );
    }
}
