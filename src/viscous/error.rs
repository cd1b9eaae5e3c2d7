//! Errors of the viscous–inviscid solver.

use thiserror::Error;

/// Everything that can go wrong when setting up or solving a viscous point.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum ViscousError {
    /// The airfoil has too few nodes or mismatched coordinate arrays.
    #[error("airfoil needs at least {min} nodes with equal x/y lengths, got {got}")]
    BadAirfoil {
        /// Minimum node count.
        min: usize,
        /// Node count found.
        got: usize,
    },
    /// A flow parameter is outside its physical range.
    #[error("invalid parameter {name} = {value}")]
    BadParameter {
        /// Parameter name.
        name: &'static str,
        /// Offending value.
        value: f64,
    },
    /// No sign change of the surface speed was found, so there is no stagnation point.
    #[error("no stagnation point found on the surface speed distribution")]
    NoStagnationPoint,
    /// A 3×3 diagonal block or the mass Schur complement of the Newton system is singular.
    #[error("singular Newton system at station {station}")]
    SingularSystem {
        /// System station index where the pivot vanished.
        station: usize,
    },
    /// The inviscid panel solution could not be built.
    #[error("inviscid solution failed: {0}")]
    Inviscid(String),
    /// The boundary-layer equations rejected a station state.
    #[error("boundary layer at station {station}: {message}")]
    BoundaryLayer {
        /// System station index (usize::MAX if not tied to one station).
        station: usize,
        /// The boundary-layer module's message.
        message: String,
    },
    /// A non-finite number appeared in the boundary-layer state.
    #[error("non-finite boundary-layer state at station {station}")]
    NonFinite {
        /// System station index.
        station: usize,
    },
}
