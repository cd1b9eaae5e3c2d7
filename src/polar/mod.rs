//! Polars: α sweeps of a point solver with warm starts and recovery of failed points.

pub mod grid;
pub mod range;
pub mod sweep;
pub mod target_cl;
pub mod viscous_sweep;

pub use grid::{run_grid, GridPolar};
pub use range::{march_order, parse_alpha_range, RangeError};
use serde::{Deserialize, Serialize};
pub use sweep::{sweep, SweepParams, WarmStartSolver};
pub use target_cl::{solve_at_cl, TargetClError, TargetClParams};
pub use viscous_sweep::ViscousSweep;

/// One operating point of a polar: the result of the solver at one (Re, M, α).
///
/// Unconverged points are kept (with `converged = false`) so that tables can flag them;
/// their coefficients must never be used as results.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PolarPoint {
    /// Angle of attack \[deg\].
    pub alpha: f64,
    /// Lift coefficient.
    pub cl: f64,
    /// Total drag coefficient (Squire–Young at the wake end; 0 for inviscid).
    pub cd: f64,
    /// Pressure drag coefficient, cd − cdf.
    pub cdp: f64,
    /// Skin-friction drag coefficient.
    pub cdf: f64,
    /// Pitching-moment coefficient about the quarter chord.
    pub cm: f64,
    /// Transition location x/c on the upper surface (1 if laminar to the TE).
    pub xtr_top: f64,
    /// Transition location x/c on the lower surface.
    pub xtr_bot: f64,
    /// Whether the solver converged at this point.
    pub converged: bool,
    /// Newton iterations used.
    pub iterations: u32,
    /// Final residual norm of the Newton system.
    pub residual: f64,
}
