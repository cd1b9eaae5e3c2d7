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
//! The public face is the solver ([`ViscousSolver`] with [`ViscousParams`], returning
//! [`ViscousSolution`]s), the per-α inviscid data it works on ([`PanelModel`], shared between
//! solvers through [`SharedPanels`]) and its errors. Inside (private), one Newton iteration is:
//! `stations` (stagnation point, station ↔ node mapping, ξ, wake gap; XFOIL STFIND, IBLPAN,
//! XICALC), `state` (the Newton unknowns), `march` and `remarch` (MRCHUE initial march and
//! MRCHDU mixed-mode re-march, each station solved by the `local_newton` loop), `newton`
//! (SETBL assembly), `block_solver` (the structured solve, BLSOLV's role), `update`
//! (UPDATE/DSLIM relaxation); `solution` and `forces` integrate Cl, Cm, Cd, cdf and xtr
//! (CLCALC, CDCALC), and `solver` drives the iterations (VISCAL). `params` holds the
//! controls of `march` and `update` (their records, `MarchParams` and `UpdateLimits`, live
//! beside the code they control) and those use the parameters in turn: one algorithm, one
//! set of knobs, so that import cycle inside the folder is kept on purpose.

mod block_solver;
pub mod distributions;
mod error;
mod forces;
mod local_newton;
mod march;
mod newton;
mod panel_model;
mod params;
mod remarch;
mod solution;
mod solver;
mod state;
mod stations;
mod tangent;
mod update;

pub use error::ViscousError;
pub use march::MarchParams;
pub use panel_model::{PanelModel, SharedPanels};
pub use params::ViscousParams;
pub use solution::{BlStation, ViscousSolution};
pub use solver::{SolverWork, ViscousSolver, WarmStart, SETTLED_STATE_BYTES_PER_NODE};
pub use update::UpdateLimits;
