//! Re × Mach × α polar tables: grid, interpolating lookup with a 360° extension, file formats.

/// Section coefficients returned by a table lookup.
#[derive(Clone, Copy, Debug, PartialEq)]
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
}

/// Anything that gives section coefficients at (α [deg], Re, M): the interface the rotor
/// model consumes. [`PolarTable`](self) implements it; tests may use analytic sections.
pub trait SectionAero {
    /// Coefficients at angle of attack `alpha_deg` (any value, wrapped to ±180°), Reynolds
    /// number `re` and Mach number `mach`.
    fn lookup(&self, alpha_deg: f64, re: f64, mach: f64) -> Lookup;
}
