//! Section data: the vocabulary shared by the solver that produces polars and the models
//! that consume them.
//!
//! * [`PolarPoint`] — one solved operating point (α, Cl, Cd, Cm, transition, convergence,
//!   minimum pressure and the supercritical flag, separation and the massive-separation flag).
//! * [`massive_separation`] — the rule that marks a converged point outside the method's
//!   validity in separated flow.
//! * [`FlowCondition`] — the (Re, M) pair a polar or a table node is computed at.
//! * [`SectionAero`] and [`Lookup`] — section coefficients at any (α, Re, M) with the flags a
//!   consumer needs to judge them (clamped, post-stall, bridged, supercritical, massive
//!   separation).
//!
//! * [`wrap_deg`] — an angle of attack brought onto the circle the tables cover.
//!
//! A leaf module: it imports nothing from the solver layers, so every layer may use it.

use serde::{Deserialize, Serialize};

/// The flow condition of a polar: chord Reynolds number and free-stream Mach number.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FlowCondition {
    /// Chord Reynolds number V∞·c/ν.
    pub reynolds: f64,
    /// Free-stream Mach number.
    pub mach: f64,
}

impl FlowCondition {
    /// The condition at Reynolds number `reynolds` and Mach number `mach`.
    pub fn new(reynolds: f64, mach: f64) -> Self {
        Self { reynolds, mach }
    }
}

/// One operating point of a polar: the result of the solver at one (Re, M, α).
///
/// Unconverged points are kept (with `converged = false`) so that tables can flag them;
/// their coefficients must never be used as results. Nor are those of a converged point in
/// massive separation ([`massive_separation`]): [`usable`](Self::usable) says which points'
/// coefficients are results.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PolarPoint {
    /// Angle of attack \[deg\].
    pub alpha: f64,
    /// Lift coefficient.
    pub cl: f64,
    /// Total drag coefficient (Squire–Young at the wake end; 0 for inviscid).
    pub cd: f64,
    /// Pressure (form) drag coefficient CD − CDf: the `CDp` XFOIL prints after each viscous
    /// solution, not the surface pressure integral in XFOIL's polar-file `CDp` column (a
    /// table read from an XFOIL file keeps that file's value).
    pub cdp: f64,
    /// Skin-friction drag coefficient (NaN when a file read does not give it).
    pub cdf: f64,
    /// Pitching-moment coefficient about the quarter chord.
    pub cm: f64,
    /// Transition location x/c on the upper surface (1 if laminar to the TE; NaN when a file
    /// read does not give it, as C81).
    pub xtr_top: f64,
    /// Transition location x/c on the lower surface.
    pub xtr_bot: f64,
    /// Whether the solver converged at this point.
    pub converged: bool,
    /// Newton iterations used.
    pub iterations: u32,
    /// Final residual norm of the Newton system.
    pub residual: f64,
    /// Smallest Karman–Tsien pressure coefficient on the surface, from the viscous edge
    /// speeds (XFOIL CPMIN; [`KarmanTsien::minimum_pressure`]); −∞ where the correction
    /// breaks down; NaN when unknown (a point that could not be solved, or a table file
    /// written without the column).
    ///
    /// [`KarmanTsien::minimum_pressure`]: crate::compressibility::KarmanTsien::minimum_pressure
    #[serde(default = "unknown_cpmin")]
    pub cpmin: f64,
    /// Cp_min < Cp*: the flow is locally supersonic somewhere on the surface, outside the
    /// validity of the method (no shocks). `None` when unknown, as `cpmin`.
    #[serde(default)]
    pub supercritical: Option<bool>,
    /// x/c on the upper surface where the reversed flow (Cf < 0) that reaches the trailing edge
    /// begins, interpolated where Cf changes sign; the trailing edge's x (1) when the flow is
    /// attached there (a separation bubble that reattaches does not count). NaN when unknown
    /// (a point that could not be solved, a file without the column).
    #[serde(default = "unknown_x")]
    pub xsep_top: f64,
    /// The same on the lower surface.
    #[serde(default = "unknown_x")]
    pub xsep_bot: f64,
    /// The point lies in massive separation ([`massive_separation`] of `xsep_top`,
    /// `xsep_bot`), outside the validity of the integral boundary-layer method: its
    /// coefficients are not results, even when the solver converged. `None` when unknown.
    #[serde(default)]
    pub massive_separation: Option<bool>,
}

impl PolarPoint {
    /// A converged point known only by its coefficients (a C81 row, a table lookup): the
    /// drag split, transition, iteration count, `cpmin` and the supercritical flag unknown.
    pub fn from_coefficients(alpha: f64, cl: f64, cd: f64, cm: f64) -> Self {
        Self {
            alpha,
            cl,
            cd,
            cdp: f64::NAN,
            cdf: f64::NAN,
            cm,
            xtr_top: f64::NAN,
            xtr_bot: f64::NAN,
            converged: true,
            iterations: 0,
            residual: 0.0,
            cpmin: f64::NAN,
            supercritical: None,
            xsep_top: f64::NAN,
            xsep_bot: f64::NAN,
            massive_separation: None,
        }
    }

    /// Whether the coefficients are results: the solver converged and the point is not in
    /// massive separation (or its table does not say). Lookups, the C81 and AeroDyn rows
    /// and the 360° extension's junction use these points only; supercritical points are
    /// used, flagged.
    pub fn usable(&self) -> bool {
        self.converged && self.massive_separation != Some(true)
    }
}

/// The `cpmin` of a point that does not say (NaN).
fn unknown_cpmin() -> f64 {
    f64::NAN
}

/// The separation location of a point that does not say (NaN).
fn unknown_x() -> f64 {
    f64::NAN
}

/// The separation location x/c ahead of which a point is in massive separation: reversed flow
/// from mid-chord (or further forward) to the trailing edge.
///
/// Why half the chord (measured, docs/limits.md): the integral boundary layer coupled through
/// the displacement thickness (Drela 1989, XFOIL) follows trailing-edge separation through
/// C_l,max, and polargen and XFOIL 6.99 place the separation alike on every point compared
/// (NACA 0012, within 0.004 c); once the separation lies ahead of mid-chord the points stop
/// depending on α alone (α 30°, Re 2·10⁵: C_l 1.139 after a sweep from 0°, 0.674 from 20°,
/// both converged) and their drag falls to about half a flat plate's (Hoerner 1965, ch. 3).
/// In the shipped tables the first point past the bound lies at or past the first C_l
/// extremum of its α branch on 534 of 588 branches, and on a stall plateau on the others;
/// none lies on a linear part of a lift curve.
pub const MASSIVE_SEPARATION_XSEP: f64 = 0.5;

/// Whether a point with separation locations `xsep_top`, `xsep_bot` (x/c, see
/// [`PolarPoint::xsep_top`]) is in massive separation: either surface separated ahead of
/// [`MASSIVE_SEPARATION_XSEP`]. `None` when neither location is known.
pub fn massive_separation(xsep_top: f64, xsep_bot: f64) -> Option<bool> {
    if xsep_top.is_nan() && xsep_bot.is_nan() {
        return None;
    }
    Some(xsep_top < MASSIVE_SEPARATION_XSEP || xsep_bot < MASSIVE_SEPARATION_XSEP)
}

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
    /// A table point the value leans on is supercritical ([`PolarPoint::supercritical`]):
    /// the section data there are outside the method's validity.
    pub supercritical: bool,
    /// A table point the value leans on does not say whether it is supercritical (a table
    /// written without the flag).
    pub supercritical_unknown: bool,
    /// The table's points at this α are in massive separation
    /// ([`PolarPoint::massive_separation`]) and were not used: the value comes from the 360°
    /// extension (`post_stall` is set too) or bridges over them (`bridged` is set too).
    pub massive_separation: bool,
    /// A table point the value leans on does not say whether it is in massive separation (a
    /// table written without the flag).
    pub separation_unknown: bool,
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

/// Anything that gives section coefficients at (α (deg), Re, M): the interface the rotor
/// model consumes. [`PolarTable`](crate::table::PolarTable) implements it; tests may use analytic sections.
pub trait SectionAero {
    /// Coefficients at angle of attack `alpha_deg` (any value, wrapped to ±180°), Reynolds
    /// number `re` and Mach number `mach`.
    fn lookup(&self, alpha_deg: f64, re: f64, mach: f64) -> Lookup;
}

/// Wrap an angle (deg) into [−180°, 180°]; values already inside are returned unchanged.
#[inline]
pub fn wrap_deg(a: f64) -> f64 {
    if (-180.0..=180.0).contains(&a) {
        a
    } else {
        (a + 180.0).rem_euclid(360.0) - 180.0
    }
}

#[cfg(test)]
mod tests {
    use super::wrap_deg;

    #[test]
    fn angles_wrap_onto_the_closed_circle() {
        assert_eq!(wrap_deg(190.0), -170.0);
        assert_eq!(wrap_deg(-190.0), 170.0);
        assert_eq!(wrap_deg(-180.0), -180.0);
        assert_eq!(wrap_deg(180.0), 180.0);
        assert_eq!(wrap_deg(30.1), 30.1);
        assert_eq!(wrap_deg(720.0 + 45.0), 45.0);
    }
}
