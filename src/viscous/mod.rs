//! Viscous–inviscid coupling: wake, boundary-layer stations, global Newton solve of the
//! boundary-layer equations together with the edge velocity (XFOIL's approach).

pub mod block_solver;
pub mod error;

pub use error::ViscousError;
