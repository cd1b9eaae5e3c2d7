//! Polars: α sweeps of a point solver with warm starts and recovery of failed points.

pub mod grid;
pub mod range;
pub mod sweep;
pub mod target_cl;
pub mod viscous_sweep;

pub use grid::{run_grid, GridPolar};
pub use range::{march_order, parse_alpha_range, RangeError};
pub use sweep::{sweep, SweepParams, WarmStartSolver};
pub use target_cl::{solve_at_cl, TargetClError, TargetClParams};
pub use viscous_sweep::ViscousSweep;
