//! Polars: α sweeps of a point solver with warm starts and recovery of failed points, and one
//! operating point solved whole under several transition settings (`polargen point`).

mod grid;
mod operating_point;
mod point_cases;
mod range;
mod recovery;
mod series;
mod sweep;
mod target_cl;
mod viscous_sweep;

pub use grid::{run_grid, GridNode, GridPolar};
pub use operating_point::{solve_operating_point, OperatingPoint, OperatingPointError};
pub use point_cases::{solve_point_cases, PointCaseError};
pub use range::{
    check_alphas, march_order, parse_alpha_range, RangeError, MAX_ALPHA_DEG, MAX_ALPHA_POINTS,
};
pub use sweep::{sweep, SweepParams, WarmStartSolver};
pub use target_cl::{solve_at_cl, TargetClError, TargetClParams};
