//! Viscous–inviscid coupling: wake, boundary-layer stations, global Newton solve of the
//! boundary-layer equations together with the edge velocity (XFOIL's approach).

pub mod bl_model;
pub mod block_solver;
pub mod error;
pub mod forces;
pub mod march;
pub mod newton;
pub mod solver;
pub mod state;
pub mod stations;
pub mod update;
pub mod xfoil_bl;

pub use error::ViscousError;
pub use solver::{BlStation, PanelModel, ViscousParams, ViscousSolution, ViscousSolver, WarmStart};
