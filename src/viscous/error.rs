//! Errors of the viscous–inviscid solver.

use thiserror::Error;

use crate::boundary_layer::BlError;
use crate::inviscid::InviscidError;

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
    #[error("inviscid panel solution")]
    Inviscid(#[from] InviscidError),
    /// The boundary-layer model rejected the flow conditions.
    #[error("boundary-layer flow conditions")]
    FlowConditions(#[source] BlError),
    /// The boundary-layer equations rejected a station state.
    #[error("boundary layer at station {station}")]
    BoundaryLayer {
        /// System station index.
        station: usize,
        /// What the boundary-layer equations rejected.
        #[source]
        source: BlError,
    },
    /// A non-finite number appeared in the boundary-layer state.
    #[error("non-finite boundary-layer state at station {station}")]
    NonFinite {
        /// System station index.
        station: usize,
    },
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::error::Error as _;

    /// A boundary-layer error names its station and keeps the boundary layer's own error as its
    /// source, unflattened.
    #[test]
    fn boundary_layer_errors_keep_their_source() {
        let cause = BlError::NonFinite("interval equations");
        let e = ViscousError::BoundaryLayer {
            station: 7,
            source: cause.clone(),
        };
        assert_eq!(e.to_string(), "boundary layer at station 7");
        let source = e.source().expect("a source");
        assert_eq!(source.downcast_ref::<BlError>(), Some(&cause));
        let inviscid = ViscousError::from(InviscidError::SingularSystem);
        assert!(inviscid.source().is_some());
    }
}
