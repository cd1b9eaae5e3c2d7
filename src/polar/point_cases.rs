//! One operating point of one airfoil under several transition settings, each solution kept
//! whole (Cp and boundary-layer distributions, not only the coefficients): the cases that
//! `polargen point` writes and `polargen plot-point` draws side by side.

use super::{solve_operating_point, OperatingPoint, OperatingPointError, TargetClParams};
use crate::geometry::Airfoil;
use crate::section::{Transition, FREE_XTR};
use crate::viscous::{ViscousError, ViscousParams, ViscousSolution, ViscousSolver};

/// Why a point case could not be solved.
#[derive(Debug, thiserror::Error)]
pub enum PointCaseError {
    /// The viscous solver could not be set up.
    #[error("viscous solver")]
    Solver(#[source] ViscousError),
    /// The operating point was not reached under the transition setting `label`.
    #[error("{label}")]
    Point {
        /// The setting's [`Transition::trip_label`].
        label: String,
        /// Why the point was not reached.
        #[source]
        source: OperatingPointError,
    },
}

/// `foil` at Reynolds number `re`, Mach number `mach` and the operating point `at` (an α or a
/// target Cl), solved under each of `settings` with the Newton `tolerance`: one solution per
/// setting, labelled by its [`Transition::trip_label`]. A converged point in massive
/// separation is kept, and `say` gets a note that its coefficients are not results.
pub fn solve_point_cases(
    foil: &Airfoil,
    (re, mach): (f64, f64),
    at: OperatingPoint,
    settings: &[Transition],
    tolerance: f64,
    say: &dyn Fn(String),
) -> Result<Vec<(String, ViscousSolution)>, PointCaseError> {
    let mut runs = Vec::new();
    for &transition in settings {
        let params = ViscousParams {
            transition,
            tolerance,
            ..ViscousParams::at(re, mach, FREE_XTR)
        };
        let mut solver = ViscousSolver::new(foil, params).map_err(PointCaseError::Solver)?;
        let label = transition.trip_label();
        let solution = solve_operating_point(&mut solver, at, &TargetClParams::default()).map_err(
            |source| PointCaseError::Point {
                label: label.clone(),
                source,
            },
        )?;
        let p = &solution.point;
        if p.massive_separation == Some(true) {
            say(format!(
                "note: {label}: alpha {:.3}: massive separation (separation at x/c {:.3} upper, \
                 {:.3} lower): converged, but outside the method's validity; the coefficients \
                 are not results (docs/limits.md)",
                p.alpha, p.xsep_top, p.xsep_bot
            ));
        }
        runs.push((label, solution));
    }
    Ok(runs)
}
