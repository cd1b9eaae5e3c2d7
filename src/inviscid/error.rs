//! Errors of the inviscid panel method.

use thiserror::Error;

use crate::compressibility::MachOutOfRange;
use crate::geometry::GeometryError;
use crate::limits::short_number;

/// Everything that can go wrong when building or solving the panel system.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum InviscidError {
    /// The contour has too few nodes to form a closed panel system.
    #[error("airfoil has {got} nodes; the panel method needs at least {min}")]
    TooFewNodes {
        /// Number of nodes given.
        got: usize,
        /// Minimum accepted.
        min: usize,
    },
    /// x and y arrays differ in length.
    #[error("airfoil x has {x} entries but y has {y}")]
    LengthMismatch {
        /// Length of x.
        x: usize,
        /// Length of y.
        y: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("airfoil node {0} has a non-finite coordinate")]
    NonFiniteNode(usize),
    /// Two consecutive nodes coincide, giving a zero-length panel.
    #[error("airfoil node {0} coincides with the next node (zero-length panel)")]
    DuplicateNode(usize),
    /// The contour runs clockwise (e.g. lower surface first); XFOIL order is counter-clockwise.
    #[error("airfoil contour is clockwise; expected XFOIL order (upper TE -> LE -> lower TE)")]
    ClockwiseContour,
    /// The influence matrix could not be factorised into a usable solution.
    #[error("panel influence matrix is singular (self-intersecting or degenerate contour?)")]
    SingularSystem,
    /// The solution is outside what any airfoil can produce (see
    /// [`MAX_UNIT_SPEED`](crate::inviscid::MAX_UNIT_SPEED) and
    /// [`MAX_SECTION_CL`](crate::inviscid::MAX_SECTION_CL)): a contour the panel method cannot
    /// resolve.
    #[error(
        "the panel solution is not physical ({what} = {}): the contour is too irregular for \
         the panel method (a stray point, a fold, or surfaces nearly on top of each other)",
        short_number(*value)
    )]
    Implausible {
        /// `surface speed` or `Cl`.
        what: &'static str,
        /// Its value.
        value: f64,
    },
    /// Mach number outside the subsonic range [0, 1).
    #[error(transparent)]
    InvalidMach(#[from] MachOutOfRange),
    /// Angle of attack is NaN or infinite.
    #[error("angle of attack {0} deg is not finite")]
    InvalidAlpha(f64),
    /// Karman–Tsien denominator β + λ(1+β)Cp/2 became non-positive somewhere on the surface.
    #[error("local speed too large for the Karman-Tsien correction at Mach {mach} (alpha {alpha_deg} deg)")]
    CompressibilityBreakdown {
        /// Freestream Mach number.
        mach: f64,
        /// Angle of attack in degrees.
        alpha_deg: f64,
    },
    /// Wake parameters cannot produce a wake.
    #[error("invalid wake parameters: {0}")]
    InvalidWake(&'static str),
    /// The contour spline or its leading edge could not be found.
    #[error("airfoil contour")]
    Geometry(#[from] GeometryError),
    /// The streamline tracing of the wake met a stagnation point (zero velocity).
    #[error("wake tracing met zero velocity at wake node {0}")]
    WakeStagnation(usize),
}
