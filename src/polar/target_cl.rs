//! Operating point at a prescribed lift coefficient: the α at which a viscous solution has
//! Cl = Cl_target (XFOIL's `CL` command), found by secant iteration on α with warm starts.

use super::recovery::{recover, AnchorMemo};
use super::sweep::SweepParams;
use crate::viscous::{ViscousSolution, ViscousSolver};

/// Controls of [`solve_at_cl`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TargetClParams {
    /// Accepted lift error |Cl − Cl_target|.
    pub tolerance: f64,
    /// Largest α change per secant step \[deg\] (keeps warm starts close).
    pub max_step_deg: f64,
    /// Most secant steps tried before giving up.
    pub max_solves: usize,
    /// Recovery of a solution that fails on the way: the sweeps' sub-steps from the last
    /// converged α and fresh start.
    pub recovery: SweepParams,
}

impl Default for TargetClParams {
    /// |ΔCl| ≤ 1e-4, α steps of at most 1.5°, 30 steps, the sweeps' default recovery.
    fn default() -> Self {
        Self {
            tolerance: 1e-4,
            max_step_deg: 1.5,
            max_solves: 30,
            recovery: SweepParams::default(),
        }
    }
}

/// Why no point with the requested lift was found.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TargetClError {
    /// The requested lift coefficient is not a finite number.
    #[error("Cl {0} is not a finite number")]
    BadTarget(f64),
    /// A viscous solution on the way did not converge.
    #[error(
        "the viscous solution did not converge at alpha {alpha:.2} deg on the way to Cl {target}"
    )]
    NotConverged {
        /// Requested lift coefficient.
        target: f64,
        /// α of the failed solution \[deg\].
        alpha: f64,
    },
    /// The iteration ran out of solutions (e.g. Cl beyond Cl_max).
    #[error("no alpha with Cl {target} found (closest Cl {closest:.4} at alpha {alpha:.2} deg; beyond Cl_max?)")]
    NotFound {
        /// Requested lift coefficient.
        target: f64,
        /// Closest lift coefficient reached.
        closest: f64,
        /// α of that solution \[deg\].
        alpha: f64,
    },
}

/// Thin-airfoil lift-curve slope 2π per radian, in 1/deg: the first secant guess.
const THIN_AIRFOIL_SLOPE_PER_DEG: f64 = 2.0 * std::f64::consts::PI * std::f64::consts::PI / 180.0;

/// Solve `solver` at the α where Cl = `target`: start at α = 0°, then secant steps on α
/// (the first with the thin-airfoil slope), each limited to `max_step_deg` so every solution
/// warm-starts from a near neighbour. A solution that fails is recovered as in a sweep
/// ([`TargetClParams::recovery`]) and then solved once more from its own converged state, which
/// returns its distributions. Returns the converged solution at that α.
pub fn solve_at_cl(
    solver: &mut ViscousSolver,
    target: f64,
    params: &TargetClParams,
) -> Result<ViscousSolution, TargetClError> {
    if !target.is_finite() {
        return Err(TargetClError::BadTarget(target));
    }
    let mut alpha = 0.0;
    let mut previous: Option<(f64, f64)> = None;
    let mut best: Option<(f64, f64)> = None;
    // The last converged α and the solver state there, the start of a recovery.
    let mut anchor = None;
    for _ in 0..params.max_solves {
        let mut sol = solver.solve(alpha);
        if !sol.point.converged {
            let mut memo = AnchorMemo::default();
            let spent = sol.point.iterations;
            if recover(
                solver,
                alpha,
                anchor.as_ref(),
                &params.recovery,
                &mut memo,
                spent,
            )
            .is_some()
            {
                sol = solver.solve(alpha);
            }
            if !sol.point.converged {
                return Err(TargetClError::NotConverged { target, alpha });
            }
        }
        anchor = Some((alpha, solver.warm_start()));
        let cl = sol.point.cl;
        if (cl - target).abs() <= params.tolerance {
            return Ok(sol);
        }
        let closer = match best {
            Some((_, c)) => (cl - target).abs() < (c - target).abs(),
            None => true,
        };
        if closer {
            best = Some((alpha, cl));
        }
        let slope = match previous {
            Some((a0, c0)) if (alpha - a0).abs() > 1e-9 && (cl - c0).abs() > 1e-9 => {
                (cl - c0) / (alpha - a0)
            }
            _ => THIN_AIRFOIL_SLOPE_PER_DEG,
        };
        // Past Cl_max the secant slope turns negative: keep stepping towards higher |Cl|
        // with the thin-airfoil slope instead, so the search ends at the iteration cap.
        let slope = if slope > 0.0 {
            slope
        } else {
            THIN_AIRFOIL_SLOPE_PER_DEG
        };
        let step = ((target - cl) / slope).clamp(-params.max_step_deg, params.max_step_deg);
        previous = Some((alpha, cl));
        alpha += step;
    }
    let (alpha, closest) = best.unwrap_or((alpha, f64::NAN));
    Err(TargetClError::NotFound {
        target,
        closest,
        alpha,
    })
}
