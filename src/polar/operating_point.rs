//! One operating point with its distributions, at a given α or at a target lift coefficient —
//! what `polargen plot-point` and the Python package's `point` solve.

use super::target_cl::{solve_at_cl, TargetClError, TargetClParams};
use crate::viscous::{ViscousSolution, ViscousSolver};

/// Where to solve one operating point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum OperatingPoint {
    /// At this angle of attack \[deg\], one solve from a fresh start.
    Alpha(f64),
    /// At the α where Cl equals this value ([`solve_at_cl`]).
    Cl(f64),
}

/// Why an operating point has no converged solution.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum OperatingPointError {
    /// The angle of attack is not a finite number.
    #[error("alpha {0}: not a finite angle")]
    BadAlpha(f64),
    /// The solution at the given α did not converge.
    #[error("the viscous solution did not converge at alpha {0} deg")]
    NotConverged(f64),
    /// No converged solution with the target lift was found.
    #[error(transparent)]
    TargetCl(#[from] TargetClError),
}

/// Solves `solver` at `at`: the converged solution with its surface and wake distributions,
/// or why there is none (a point that did not converge is an error, never a result).
pub fn solve_operating_point(
    solver: &mut ViscousSolver,
    at: OperatingPoint,
    params: &TargetClParams,
) -> Result<ViscousSolution, OperatingPointError> {
    match at {
        OperatingPoint::Cl(cl) => Ok(solve_at_cl(solver, cl, params)?),
        OperatingPoint::Alpha(alpha) if !alpha.is_finite() => {
            Err(OperatingPointError::BadAlpha(alpha))
        }
        OperatingPoint::Alpha(alpha) => {
            let solution = solver.solve(alpha);
            if solution.point.converged {
                Ok(solution)
            } else {
                Err(OperatingPointError::NotConverged(alpha))
            }
        }
    }
}
