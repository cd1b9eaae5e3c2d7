//! Flap sweeps: one table per flap deflection of one section (the axis OpenFAST AeroDyn calls
//! `UserProp`), each written beside the others under a name that carries the deflection, or,
//! as AeroDyn files, all together: one file per (Re, M) with one table per deflection.

use super::io::{check_flap_sweep_output, check_table_output, write_aerodyn_flap_sweep};
use super::{PolarTable, TableError, TableFormat};
use crate::arguments::ArgumentError;
use crate::geometry::{flap_deflection, flap_deg, with_flap_deflection, ShapeOp};
use crate::limits::exact_number;
use crate::output::{names_a_file, OutputError};
use std::path::{Path, PathBuf};

/// One table of a [`FlapSweep`].
#[derive(Clone, Debug, PartialEq)]
pub struct FlapMember {
    /// The section's geometry operations (the flap's deflection set).
    pub ops: Vec<ShapeOp>,
    /// The table's own output, or `None` when the sweep's tables are written together
    /// ([`FlapSweep::write_together`]).
    pub out: Option<PathBuf>,
}

/// The tables of a job (one, or one per flap deflection) and where they are written.
#[derive(Clone, Debug, PartialEq)]
pub struct FlapSweep {
    members: Vec<FlapMember>,
    /// The path the AeroDyn files of the tables written together are named after.
    together: Option<PathBuf>,
}

impl FlapSweep {
    /// The job's tables: without `list` one, of `ops`, written to `out`; with `list` (flag
    /// `--flap-deg`: comma-separated degrees, each in (−90°, 90°)) one per deflection of the
    /// flap among `ops`. In `format` AeroDyn, several deflections are written together
    /// ([`write_aerodyn_flap_sweep`]: one file per (Re, M) named after `out`, one table per
    /// deflection); otherwise each table goes to `<stem>_flap<DEG>.<ext>` beside `out` (for
    /// `out` = `tables/t.csv` and 10°: `tables/t_flap10.csv`; one deflection with `out` = `-`
    /// goes to standard output). Several tables need a file, not standard output; a
    /// deflection may not be given twice (−0 is 0).
    pub fn new(
        ops: &[ShapeOp],
        list: Option<&str>,
        out: &Path,
        format: TableFormat,
    ) -> Result<Self, ArgumentError> {
        let Some(list) = list else {
            return Ok(Self {
                members: vec![FlapMember {
                    ops: ops.to_vec(),
                    out: Some(out.to_path_buf()),
                }],
                together: None,
            });
        };
        let name = "--flap-deg";
        if flap_deg(ops).is_none() {
            return Err(ArgumentError::with_text(
                name,
                list,
                "needs the hinge: --flap X:Y",
            ));
        }
        let degs = list
            .split(',')
            .map(|d| {
                flap_deflection(d).map_err(|e| ArgumentError {
                    name: name.into(),
                    ..e
                })
            })
            .collect::<Result<Vec<f64>, _>>()?;
        // −0 is 0: one table, one file name.
        let degs: Vec<f64> = degs.into_iter().map(|d| d + 0.0).collect();
        crate::arguments::distinct(name, &degs)?;
        if !names_a_file(out) && degs.len() == 1 {
            return Ok(Self {
                members: vec![FlapMember {
                    ops: with_flap_deflection(ops, degs[0]),
                    out: Some(out.to_path_buf()),
                }],
                together: None,
            });
        }
        if degs.len() > 1 && !names_a_file(out) {
            return Err(ArgumentError::with_text(
                name,
                list,
                "one table per deflection needs --out FILE",
            ));
        }
        let together = degs.len() > 1 && format == TableFormat::AeroDyn;
        let stem = out.file_stem().unwrap_or_default().to_string_lossy();
        let ext = out
            .extension()
            .map_or(String::new(), |e| format!(".{}", e.to_string_lossy()));
        let members = degs
            .into_iter()
            .map(|deg| FlapMember {
                ops: with_flap_deflection(ops, deg),
                out: (!together)
                    .then(|| out.with_file_name(format!("{stem}_flap{}{ext}", exact_number(deg)))),
            })
            .collect();
        Ok(Self {
            members,
            together: together.then(|| out.to_path_buf()),
        })
    }

    /// The tables to solve, in the order of the list.
    pub fn members(&self) -> &[FlapMember] {
        &self.members
    }

    /// Refuses a sweep whose tables together hold more than
    /// [`MAX_GRID_POINTS`](crate::limits::MAX_GRID_POINTS) points on `grid` (the limit is per
    /// run, not per table), before any solve.
    pub fn check_size(&self, grid: &super::GridSpec) -> Result<(), ArgumentError> {
        let limit = crate::limits::MAX_GRID_POINTS;
        let points = self.members.len() * grid.point_count();
        if points <= limit {
            return Ok(());
        }
        Err(ArgumentError::with_text(
            "--flap-deg",
            "",
            format!(
                "{} tables of {} points = {points} points: more than the limit of {limit} \
                 points per run",
                self.members.len(),
                grid.point_count()
            ),
        ))
    }

    /// Checks, before anything is solved, that every file of the sweep over the grid `re` ×
    /// `mach` in `format` can be written ([`check_table_output`]).
    pub fn check_output(
        &self,
        format: TableFormat,
        re: &[f64],
        mach: &[f64],
    ) -> Result<(), OutputError> {
        if let Some(path) = &self.together {
            check_flap_sweep_output(path, re, mach)?;
        }
        self.members
            .iter()
            .filter_map(|m| m.out.as_deref())
            .try_for_each(|path| check_table_output(path, format, re, mach))
    }

    /// Write the tables of the members without an output of their own (in the members'
    /// order): the AeroDyn files of [`write_aerodyn_flap_sweep`]. Returns the files written
    /// (none when every member has its own output).
    pub fn write_together(&self, tables: &[PolarTable]) -> Result<Vec<PathBuf>, TableError> {
        match &self.together {
            Some(path) => write_aerodyn_flap_sweep(tables, path),
            None => Ok(Vec::new()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flap(deg: f64) -> Vec<ShapeOp> {
        vec![ShapeOp::Flap {
            hinge_x: 0.75,
            hinge_y: 0.0,
            deflection_deg: deg,
        }]
    }

    /// AeroDyn writes several deflections together; one deflection, or another format, gives
    /// each table its own file.
    #[test]
    fn aerodyn_writes_the_deflections_together() {
        let out = Path::new("dir/f.dat");
        let sweep = FlapSweep::new(&flap(0.0), Some("-5,0,5"), out, TableFormat::AeroDyn);
        let sweep = sweep.unwrap();
        assert_eq!(sweep.members().len(), 3);
        assert!(sweep.members().iter().all(|m| m.out.is_none()));
        assert_eq!(sweep.members()[2].ops, flap(5.0));
        assert_eq!(sweep.together.as_deref(), Some(out));
        let csv = FlapSweep::new(&flap(0.0), Some("-5,5"), out, TableFormat::Csv).unwrap();
        let names: Vec<_> = csv.members().iter().map(|m| m.out.clone()).collect();
        assert_eq!(
            names,
            [
                Some(PathBuf::from("dir/f_flap-5.dat")),
                Some(PathBuf::from("dir/f_flap5.dat"))
            ]
        );
        let one = FlapSweep::new(&flap(0.0), Some("5"), out, TableFormat::AeroDyn).unwrap();
        assert_eq!(
            one.members()[0].out.as_deref(),
            Some(Path::new("dir/f_flap5.dat"))
        );
        assert!(one.together.is_none());
    }
}
