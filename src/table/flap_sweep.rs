//! Flap sweeps: one table per flap deflection of one section (the axis OpenFAST AeroDyn calls
//! `UserProp`), each written beside the others under a name that carries the deflection.

use crate::arguments::ArgumentError;
use crate::geometry::{flap_deflection, flap_deg, with_flap_deflection, ShapeOp};
use crate::output::STDOUT_PATH;
use std::path::{Path, PathBuf};

/// The members of a flap sweep over the deflections `list` (comma-separated degrees, each in
/// (−90°, 90°); flag `--flap-deg`) of the flap among `ops`: each member's operations (the
/// flap's deflection set) and its output file, `<stem>_flap<DEG>.<ext>` beside `out` (for
/// `out` = `tables/t.csv` and 10°: `tables/t_flap10.csv`). Several members need a file, not
/// standard output.
pub fn flap_sweep(
    ops: &[ShapeOp],
    list: &str,
    out: &Path,
) -> Result<Vec<(Vec<ShapeOp>, PathBuf)>, ArgumentError> {
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
    if degs.len() > 1 && out == Path::new(STDOUT_PATH) {
        return Err(ArgumentError::with_text(
            name,
            list,
            "one table per deflection needs --out FILE",
        ));
    }
    let stem = out.file_stem().unwrap_or_default().to_string_lossy();
    let ext = out
        .extension()
        .map_or(String::new(), |e| format!(".{}", e.to_string_lossy()));
    Ok(degs
        .into_iter()
        .map(|deg| {
            let file = out.with_file_name(format!("{stem}_flap{deg}{ext}"));
            (with_flap_deflection(ops, deg), file)
        })
        .collect())
}
