//! Inviscid flow: linear-vorticity stream-function panel method (Drela 1989), unit solutions
//! for α = 0° and 90°, source-panel influence for the viscous coupling, Karman–Tsien
//! compressibility.
//!
//! Typical use:
//! ```no_run
//! # use polargen::geometry::Airfoil;
//! # use polargen::inviscid::{PanelSystem, SourceInfluence, Wake};
//! # fn f(foil: &Airfoil) -> Result<(), polargen::inviscid::InviscidError> {
//! let sys = PanelSystem::new(foil)?;          // influence matrix, LU, unit solutions
//! let sol = sys.solve(4.0, 0.41)?;            // α = 4°, M = 0.41: gamma, cp, cl, cm
//! let wake = Wake::new(&sys, 4.0)?;           // wake streamline, unit wake speeds
//! let dij = SourceInfluence::new(&sys, &wake); // q = q_inv + D·σ on airfoil + wake nodes
//! # let _ = (sol, dij); Ok(()) }
//! ```

pub mod compressibility;
pub mod error;
pub mod forces;
pub mod panels;
pub mod source_influence;
pub mod system;
pub mod wake;

pub use compressibility::KarmanTsien;
pub use error::InviscidError;
pub use forces::{integrate_pressure, SectionForces};
pub use panels::{PanelGeometry, PanelParams, TrailingEdge};
pub use source_influence::{speeds_with_sources, SourceInfluence};
pub use system::{InviscidSolution, PanelSystem};
pub use wake::{Wake, WakeParams};
