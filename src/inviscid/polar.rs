//! The inviscid polar (`polargen --inviscid`): the panel solution over α at one Mach number as
//! CSV rows `alpha,cl,cd,cm,converged` (cd 0, every point converged), with the note on the
//! points that are supercritical.

use super::{InviscidError, PanelSystem};
use crate::output::fixed_decimals;

/// The CSV of the solutions of `system` at each α of `alphas` \[deg\] and Mach number `mach`
/// (Cl and Cm with 6 decimals), and a note naming the supercritical points, if any: their
/// minimum Cp lies below the sonic Cp*, beyond the validity of the Karman–Tsien correction.
pub fn inviscid_polar_csv(
    system: &PanelSystem,
    alphas: &[f64],
    mach: f64,
) -> Result<(String, Option<String>), InviscidError> {
    let mut csv = String::from("alpha,cl,cd,cm,converged\n");
    let mut supercritical: Vec<f64> = Vec::new();
    for &alpha in alphas {
        let sol = system.solve(alpha, mach)?;
        if sol.supercritical {
            supercritical.push(alpha);
        }
        csv.push_str(&format!(
            "{alpha},{},0,{},true\n",
            fixed_decimals(sol.cl, 6),
            fixed_decimals(sol.cm, 6)
        ));
    }
    let note = match (supercritical.first(), supercritical.last()) {
        (Some(first), Some(last)) => Some(format!(
            "note: M {mach}: {} of {} points supercritical (alpha {first} … {last}): the \
             minimum Cp is below the sonic Cp*, beyond the validity of the Karman-Tsien \
             correction; those Cl and Cm are only indicative",
            supercritical.len(),
            alphas.len()
        )),
        _ => None,
    };
    Ok((csv, note))
}
