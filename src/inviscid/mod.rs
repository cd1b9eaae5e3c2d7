//! Inviscid flow: linear-vorticity stream-function panel method (Drela 1989), unit solutions
//! for α = 0° and 90°, source-panel influence for the viscous coupling, Karman–Tsien
//! compressibility.
//!
//! Typical use:
//! ```no_run
//! # use polargen::geometry::Airfoil;
//! # use polargen::inviscid::PanelSystem;
//! # fn f(foil: &Airfoil) -> Result<(), polargen::inviscid::InviscidError> {
//! let sys = PanelSystem::new(foil)?;          // influence matrix, LU, unit solutions
//! let sol = sys.solve(4.0, 0.41)?;            // α = 4°, M = 0.41: gamma, cp, cl, cm
//! # let _ = sol; Ok(()) }
//! ```

pub mod compressibility;
pub mod error;
pub mod forces;
pub mod panels;
pub mod system;

pub use compressibility::KarmanTsien;
pub use error::InviscidError;
pub use forces::{integrate_pressure, SectionForces};
pub use panels::{PanelGeometry, PanelParams, TrailingEdge};
pub use system::{InviscidSolution, PanelSystem};
