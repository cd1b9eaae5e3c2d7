//! Viscous–inviscid coupling: wake, boundary-layer stations, global Newton solve of the
//! boundary-layer equations together with the edge velocity (XFOIL's approach, Drela 1989).
//!
//! ```no_run
//! # use polargen::geometry::Airfoil;
//! # use polargen::viscous::{ViscousParams, ViscousSolver};
//! # fn f(foil: &Airfoil) -> Result<(), polargen::viscous::ViscousError> {
//! let params = ViscousParams::at(1.9e6, 0.41, 0.07); // Re, M, trip at 7 % chord
//! let mut solver = ViscousSolver::new(foil, params)?; // foil already paneled (XFOIL order)
//! for i in 0..=16 {
//!     let sol = solver.solve(0.5 * i as f64);        // warm start from the previous point
//!     if sol.point.converged { println!("{:?}", sol.point); }
//! }
//! solver.reset();                                     // next sweep starts from a fresh march
//! # Ok(()) }
//! ```
//!
//! Files: [`stations`] (stagnation point, station ↔ node mapping, ξ, wake gap), [`state`]
//! (Newton unknowns), [`march`] (MRCHUE initial march, MRCHDU mixed-mode re-march),
//! [`newton`] (SETBL assembly), [`panel_model`] (per-α inviscid data, shared between solvers),
//! [`block_solver`] (structured solve), `dense` (influence-matrix products), [`update`]
//! (UPDATE/DSLIM relaxation), [`forces`] (Cl, Cm, cdf, xtr), [`bl_model`] + [`xfoil_bl`] (the
//! boundary-layer equations seen by the coupling), [`solver`] (the [`ViscousSolver`]).

pub mod bl_model;
pub mod block_solver;
mod dense;
pub mod distributions;
pub mod error;
pub mod forces;
pub mod march;
pub mod newton;
pub mod panel_model;
pub mod solver;
pub mod state;
pub mod stations;
pub mod update;
pub mod xfoil_bl;

pub use error::ViscousError;
pub use panel_model::{PanelModel, SharedPanels};
pub use solver::{BlStation, ViscousParams, ViscousSolution, ViscousSolver, WarmStart};
