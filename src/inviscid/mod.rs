//! Inviscid flow: linear-vorticity stream-function panel method (Drela 1989), unit solutions
//! for α = 0° and 90°, source-panel influence for the viscous coupling, Karman–Tsien
//! compressibility ([`crate::compressibility`]).
//!
//! Conventions (XFOIL's): nodes in XFOIL order (upper TE → LE → lower TE, counter-clockwise),
//! chord ≈ 1, speeds per V∞. The nodal vorticity γ equals the signed surface speed: positive on
//! the upper surface, negative on the lower; wake speeds continue the lower-surface sign.
//! Sources σ (per V∞·c) relate to the boundary-layer mass defect m = Ue·δ* by σ = −m on the
//! upper surface and σ = +m on the lower surface and wake; the speed at every airfoil and wake
//! node is q = q_inv(α) + D·σ with D the source influence matrix (XFOIL DIJ).
//!
//! Inside (private): `contour` (the contour prepared for the panels: SCALC, SEGSPL, LEFIND,
//! TECALC), `influence` (PSILIN/PSWLIN kernels), `system` (matrix, Kutta/sharp-TE rows, LU,
//! unit solutions), `wake` (XYWAKE, QWCALC), `source_influence` (QDCALC), `forces` (CLCALC);
//! `polar` writes the inviscid polar of `polargen --inviscid`.
//! The viscous coupling (a higher layer) uses the wake and the source influence, which are
//! crate-internal.
//!
//! Typical use:
//! ```
//! use polargen::geometry::{airfoil_by_name_or_path, PanelingParams};
//! use polargen::inviscid::PanelSystem;
//!
//! let foil = airfoil_by_name_or_path("naca0012")?.repanel(160, &PanelingParams::default())?;
//! let sys = PanelSystem::new(&foil)?; // influence matrix, LU, unit solutions
//! let sol = sys.solve(4.0, 0.41)?; // α = 4°, M = 0.41: γ, Karman–Tsien Cp, Cl, Cm
//! assert!(sol.cl > 0.45 && sol.cl < 0.6);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod contour;
mod error;
pub(crate) mod forces;
mod influence;
mod polar;
pub(crate) mod source_influence;
mod system;
pub(crate) mod wake;

#[cfg(test)]
mod tests;

pub use contour::{PanelGeometry, PanelParams, TrailingEdge};
pub use error::InviscidError;
pub use polar::inviscid_polar_csv;
pub use system::{InviscidSolution, PanelSystem, MAX_SECTION_CL, MAX_UNIT_SPEED};

pub use source_influence::SourceInfluence;
pub(crate) use system::superpose;
pub(crate) use wake::Wake;
