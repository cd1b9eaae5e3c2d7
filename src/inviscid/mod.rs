//! Inviscid flow: linear-vorticity stream-function panel method (Drela 1989), unit solutions
//! for α = 0° and 90°, source-panel influence for the viscous coupling, Karman–Tsien
//! compressibility ([`crate::compressibility`]).
//!
//! Conventions (XFOIL's): nodes in XFOIL order (upper TE → LE → lower TE, counter-clockwise),
//! chord ≈ 1, speeds per V∞. The nodal vorticity γ equals the signed surface speed: positive on
//! the upper surface, negative on the lower; wake speeds continue the lower-surface sign.
//! Sources σ (per V∞·c) relate to the boundary-layer mass defect m = Ue·δ* by σ = −m on the
//! upper surface and σ = +m on the lower surface and wake; the speed at every airfoil and wake
//! node is q = q_inv(α) + D·σ with D from [`SourceInfluence`].
//!
//! Files: [`contour`] (the contour prepared for the panels, TECALC), [`influence`]
//! (PSILIN/PSWLIN kernels), [`system`] (matrix, Kutta/sharp-TE
//! rows, LU, unit solutions), [`wake`] (XYWAKE), [`source_influence`] (QDCALC),
//! [`forces`] (CLCALC), [`error`].
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

pub mod contour;
pub mod error;
pub mod forces;
pub mod influence;
pub mod source_influence;
pub mod system;
pub mod wake;

pub use contour::{PanelGeometry, PanelParams, TrailingEdge};
pub use error::InviscidError;
pub use forces::{integrate_pressure, SectionForces};
pub use source_influence::{speeds_with_sources, SourceInfluence};
pub use system::{superpose, InviscidSolution, PanelSystem};
pub use wake::{Wake, WakeParams};
