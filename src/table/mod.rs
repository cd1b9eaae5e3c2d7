//! Re × Mach × α polar tables: grid, interpolating lookup with a 360° extension, file formats.
//!
//! * [`grid`] — [`PolarTable`]: one polar per (Re, M) node, metadata, validation, accessors.
//! * [`lookup`] — the α curve of one polar (monotone cubic, gaps bridged) and the
//!   [`SectionAero`] implementation (linear in ln Re and in M between polars).
//! * [`post_stall`] — the 360° extension beyond the computed α range (Viterna–Corrigan and a
//!   flat plate).
//! * [`io`] — CSV, JSON, XFOIL polar and C81 files, written atomically.
//! * [`error`] — [`TableError`].

pub mod error;
pub mod grid;
pub mod io;
pub mod lookup;
pub mod post_stall;

pub use error::TableError;
pub use grid::{PolarTable, TableMeta};
pub use io::{read_table, write_table, TableFormat};
pub use post_stall::PostStallParams;

/// Section coefficients returned by a table lookup.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Lookup {
    /// Lift coefficient.
    pub cl: f64,
    /// Drag coefficient.
    pub cd: f64,
    /// Pitching-moment coefficient about c/4.
    pub cm: f64,
    /// The requested Re was outside the table and was clamped to its edge.
    pub re_clamped: bool,
    /// The requested Mach number was outside the table and was clamped to its edge.
    pub mach_clamped: bool,
    /// α was outside the computed range: the value comes from the 360° post-stall model.
    pub post_stall: bool,
    /// The value was interpolated across a gap of unconverged (or missing) points, or a polar
    /// with too few converged points was replaced by its nearest usable neighbour.
    pub bridged: bool,
}

impl Lookup {
    /// Coefficients with all flags cleared (for analytic sections implementing
    /// [`SectionAero`]).
    pub fn new(cl: f64, cd: f64, cm: f64) -> Self {
        Self {
            cl,
            cd,
            cm,
            ..Self::default()
        }
    }
}

/// Anything that gives section coefficients at (α [deg], Re, M): the interface the rotor
/// model consumes. [`PolarTable`] implements it; tests may use analytic sections.
pub trait SectionAero {
    /// Coefficients at angle of attack `alpha_deg` (any value, wrapped to ±180°), Reynolds
    /// number `re` and Mach number `mach`.
    fn lookup(&self, alpha_deg: f64, re: f64, mach: f64) -> Lookup;
}
