//! Section data: the vocabulary shared by the solver that produces polars and the models
//! that consume them.
//!
//! * [`PolarPoint`] — one solved operating point (α, Cl, Cd, Cm, transition, convergence,
//!   minimum pressure and the supercritical flag, separation and the massive-separation flag).
//! * [`massive_separation`] — the rule that marks a converged point outside the method's
//!   validity in separated flow.
//! * [`FlowCondition`] — the (Re, M) pair a polar or a table node is computed at.
//! * [`Transition`] — the transition setting a polar is computed with (N_crit and trip x/c per
//!   surface), with the one rule for its values ([`Transition::check`]).
//! * [`SectionAero`] and [`Lookup`] — section coefficients at any (α, Re, M) with the flags a
//!   consumer needs to judge them (clamped, post-stall, bridged, supercritical, massive
//!   separation).
//!
//! * [`wrap_deg`] — an angle of attack brought onto the circle the tables cover.
//!
//! A leaf module: it imports nothing from the solver layers, so every layer may use it.

use crate::limits::short_number;
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

/// The N_crit of the e^n method for a low-turbulence free stream: XFOIL's default (Drela,
/// *XFOIL 6.9 User Primer*, VPAR `N`).
pub const DEFAULT_NCRIT: f64 = 9.0;

/// The trip location x/c that means free transition (XFOIL VPAR `XTR` 1, its default).
pub const FREE_XTR: f64 = 1.0;

/// Where the boundary layer of a section turns turbulent (XFOIL VPAR): the critical
/// amplification ratio N_crit of the e^n method and the forced-transition (trip) location of
/// each surface. The setting a solver runs with, a table records and a study looks its tables
/// up by; [`check`](Self::check) is the one rule for its values, wherever they come from.
///
/// A trip location is x/c along the chord line from the leading edge (the point of the
/// contour farthest from the trailing edge), on that surface: 0 trips at the leading edge,
/// 1 leaves transition free. Where the stagnation point lies downstream of the trip on a
/// surface, the flow on that surface never passes the trip and transition there is free
/// (XFOIL XIFSET).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transition {
    /// N_crit on the upper surface (XFOIL ACRIT(1), VPAR `NT`).
    pub ncrit_top: f64,
    /// N_crit on the lower surface; the wake, which XFOIL marches as part of the lower side,
    /// uses it too (XFOIL ACRIT(2), VPAR `NB`).
    pub ncrit_bot: f64,
    /// Trip x/c on the upper surface (XFOIL XSTRIP(1), VPAR `XT`); [`FREE_XTR`] = free.
    pub xtr_top: f64,
    /// Trip x/c on the lower surface (XFOIL XSTRIP(2), VPAR `XB`).
    pub xtr_bot: f64,
}

impl Default for Transition {
    /// Free transition on both surfaces with [`DEFAULT_NCRIT`] (XFOIL's defaults).
    fn default() -> Self {
        Self::free(DEFAULT_NCRIT)
    }
}

impl Transition {
    /// Free transition on both surfaces with N_crit `ncrit`.
    pub const fn free(ncrit: f64) -> Self {
        Self {
            ncrit_top: ncrit,
            ncrit_bot: ncrit,
            xtr_top: FREE_XTR,
            xtr_bot: FREE_XTR,
        }
    }

    /// Transition forced at `xtr` on both surfaces, N_crit [`DEFAULT_NCRIT`] ahead of the trip.
    pub const fn tripped(xtr: f64) -> Self {
        Self::sides(DEFAULT_NCRIT, DEFAULT_NCRIT, xtr, xtr)
    }

    /// The setting of each surface: N_crit and trip x/c of the upper, then the lower surface.
    pub const fn sides(ncrit_top: f64, ncrit_bot: f64, xtr_top: f64, xtr_bot: f64) -> Self {
        Self {
            ncrit_top,
            ncrit_bot,
            xtr_top,
            xtr_bot,
        }
    }

    /// The setting of a table whose file does not record it (a C81 deck, an AeroDyn file from
    /// another tool): every value NaN, unknown.
    pub const UNKNOWN: Self = Self::sides(f64::NAN, f64::NAN, f64::NAN, f64::NAN);

    /// Checks every value against its rule ([`TransitionField::rule`]); the first that breaks
    /// it is the error.
    pub fn check(&self) -> Result<(), TransitionError> {
        self.check_fields(false)
    }

    /// [`check`](Self::check) for a setting read from a table file, where a value may be
    /// unknown (NaN, as in [`Transition::UNKNOWN`]).
    pub fn check_recorded(&self) -> Result<(), TransitionError> {
        self.check_fields(true)
    }

    fn check_fields(&self, unknown_allowed: bool) -> Result<(), TransitionError> {
        for (field, value) in [
            (TransitionField::NcritTop, self.ncrit_top),
            (TransitionField::NcritBot, self.ncrit_bot),
            (TransitionField::XtrTop, self.xtr_top),
            (TransitionField::XtrBot, self.xtr_bot),
        ] {
            if !(field.accepts(value) || (unknown_allowed && value.is_nan())) {
                return Err(TransitionError { field, value });
            }
        }
        Ok(())
    }

    /// Free transition on both surfaces (both trips at [`FREE_XTR`] or beyond).
    pub fn is_free(&self) -> bool {
        self.xtr_top >= FREE_XTR && self.xtr_bot >= FREE_XTR
    }

    /// The N_crit of both surfaces when they are equal (bit for bit), as the table files write
    /// it: one `ncrit` value, else one per side.
    pub fn common_ncrit(&self) -> Option<f64> {
        (self.ncrit_top.to_bits() == self.ncrit_bot.to_bits()).then_some(self.ncrit_top)
    }

    /// N_crit for a comment line: `9`, `9 (top) 3 (bottom)` when the surfaces differ,
    /// `unknown` when the table does not say.
    pub fn ncrit_text(&self) -> String {
        match self.common_ncrit() {
            Some(n) if n.is_nan() => "unknown".to_string(),
            Some(n) => n.to_string(),
            None => format!("{} (top) {} (bottom)", self.ncrit_top, self.ncrit_bot),
        }
    }

    /// The trips in a few words: `free`, `xtr 0.07`, or `xtr 0.05/0.1` (upper/lower).
    pub fn trip_label(&self) -> String {
        if self.is_free() {
            "free".to_string()
        } else if self.xtr_top == self.xtr_bot {
            format!("xtr {}", self.xtr_top)
        } else {
            format!("xtr {}/{}", self.xtr_top, self.xtr_bot)
        }
    }

    /// The setting in a few words: `free Ncrit 9` (N_crit per side when they differ), or the
    /// [`trip_label`](Self::trip_label) of a tripped setting.
    pub fn label(&self) -> String {
        if self.is_free() {
            match self.common_ncrit() {
                Some(n) => format!("free Ncrit {n}"),
                None => format!("free Ncrit {}/{}", self.ncrit_top, self.ncrit_bot),
            }
        } else {
            self.trip_label()
        }
    }
}

/// One value of a [`Transition`] setting.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TransitionField {
    /// [`Transition::ncrit_top`].
    NcritTop,
    /// [`Transition::ncrit_bot`].
    NcritBot,
    /// [`Transition::xtr_top`].
    XtrTop,
    /// [`Transition::xtr_bot`].
    XtrBot,
}

impl TransitionField {
    /// The field's name in the library (`ncrit_top`, `xtr_bot`, …); callers name it as their
    /// users know it (`--xtr`, `xtr_top_set`).
    pub fn name(self) -> &'static str {
        match self {
            Self::NcritTop => "ncrit_top",
            Self::NcritBot => "ncrit_bot",
            Self::XtrTop => "xtr_top",
            Self::XtrBot => "xtr_bot",
        }
    }

    /// Whether the field is an N_crit (else a trip location).
    pub fn is_ncrit(self) -> bool {
        matches!(self, Self::NcritTop | Self::NcritBot)
    }

    /// What a value of the field must be, as a sentence: N_crit a positive number, a trip
    /// location a chord fraction in [0, 1].
    pub fn rule(self) -> &'static str {
        if self.is_ncrit() {
            "N_crit must be a positive number"
        } else {
            "the transition location must be in [0, 1] (0 = leading edge, 1 = free)"
        }
    }

    /// The [`rule`](Self::rule) as the words after "must be": `a positive number`,
    /// `in [0, 1] (…)`.
    pub fn range(self) -> &'static str {
        if self.is_ncrit() {
            "a positive number"
        } else {
            "in [0, 1] (0 = leading edge, 1 = free)"
        }
    }

    /// Whether `value` obeys the [`rule`](Self::rule).
    pub fn accepts(self, value: f64) -> bool {
        if self.is_ncrit() {
            value.is_finite() && value > 0.0
        } else {
            (0.0..=FREE_XTR).contains(&value)
        }
    }
}

/// A [`Transition`] value that breaks its rule: `<field> <value>: <rule>`.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[error("{} {}: {}", field.name(), short_number(*value), field.rule())]
pub struct TransitionError {
    /// The field.
    pub field: TransitionField,
    /// Its value.
    pub value: f64,
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
/// extremum of its α branch on 536 of 590 branches, and on a stall plateau on the others;
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
