//! polargen — airfoil polar tables from an XFOIL-class viscous–inviscid solver, and a
//! gyroplane rotor strip model that consumes them.
//!
//! Data flows one way through the module tree; a lower layer never imports a higher one:
//!
//! ```text
//! geometry → inviscid → boundary_layer → viscous → polar → table → rotor
//!                                                            ↘ plot (reads tables and rotor results)
//! ```
//!
//! * [`geometry`] — airfoil shapes (NACA 4/5-digit, coordinate files, named registry), splines,
//!   curvature-based paneling.
//! * [`inviscid`] — linear-vorticity stream-function panel method (Drela 1989), unit solutions,
//!   source influence for the viscous coupling, Karman–Tsien compressibility.
//! * [`boundary_layer`] — integral boundary-layer closures, amplification (e^n) and the
//!   discrete equations for one interval (Drela & Giles 1987).
//! * [`viscous`] — wake, viscous–inviscid coupling and the global Newton solve.
//! * [`polar`] — α sweeps with warm starts and recovery of failed points.
//! * [`table`] — Re × Mach × α tables, lookup with 360° extension, file formats.
//! * [`rotor`] — blade-element model of a teetering gyroplane rotor: trim and takeoff.
//! * [`plot`] — SVG/PNG plots of polars, point distributions and rotor results.
//! * [`section`] — the shared vocabulary of section data: polar points, flow conditions and
//!   the lookup interface the rotor consumes.
//! * [`diagnostics`] — one-line error text for the command-line tools.

#![warn(missing_docs)]

pub mod boundary_layer;
pub mod diagnostics;
pub mod geometry;
pub mod inviscid;
pub(crate) mod numerics;
pub mod output;
pub mod plot;
pub mod polar;
pub mod report;
pub mod rotor;
pub mod section;
pub mod table;
pub mod viscous;
