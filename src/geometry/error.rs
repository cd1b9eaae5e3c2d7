//! Errors of the geometry layer: coordinate files, NACA designations, the name registry,
//! splines and paneling. Every message is one line naming the problem (and for files the
//! file name and line number, for contours made in memory their name and point number:
//! [`Place`]).

use crate::input::InputError;
use crate::limits::{short_number, short_text};
use thiserror::Error;

/// How an error numbers a contour's points: by their line in a coordinate file, or by their
/// place (1-based) in a contour made in memory (a shaped or generated section).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// Line numbers of a file: `foil.dat:12: …`.
    Line,
    /// Point numbers of a contour: `NACA 2412 (flap 0.75:0:85), point 228: …`.
    Point,
}

impl Place {
    /// The location after the file or contour name: `:12` or `, point 12`.
    fn at(self, number: usize) -> String {
        match self {
            Self::Line => format!(":{number}"),
            Self::Point => format!(", point {number}"),
        }
    }

    /// What a number counts: `line` or `point`.
    fn word(self) -> &'static str {
        match self {
            Self::Line => "line",
            Self::Point => "point",
        }
    }
}

/// Everything that can go wrong while building, reading or paneling an airfoil.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GeometryError {
    /// The file could not be read: missing, not a regular file, too large or unreadable.
    #[error("cannot read airfoil file {}: {}", .0.path.display(), .0.problem)]
    Input(#[source] InputError),
    /// The file is not UTF-8 text.
    #[error("{file}: not a text file (invalid UTF-8 at byte {offset})")]
    NotUtf8 {
        /// File name as given.
        file: String,
        /// Byte offset of the first invalid byte.
        offset: usize,
    },
    /// The file contains control characters typical of binary data.
    #[error("{file}:{line}: binary data (control character 0x{byte:02x}) in a coordinate file")]
    Binary {
        /// File name as given.
        file: String,
        /// 1-based line number.
        line: usize,
        /// The offending byte.
        byte: u8,
    },
    /// The file has no coordinate data at all.
    #[error("{file}: empty file, no coordinates found")]
    Empty {
        /// File name as given.
        file: String,
    },
    /// A token that should be a number is not one.
    #[error("{file}:{line}: cannot parse '{}' as a number", short_text(token))]
    BadNumber {
        /// File name as given.
        file: String,
        /// 1-based line number.
        line: usize,
        /// The token.
        token: String,
    },
    /// A coordinate is NaN or infinite.
    #[error("{file}{}: coordinate '{}' is not finite", place.at(*line), short_text(token))]
    NonFinite {
        /// File name as given (or airfoil name).
        file: String,
        /// 1-based line (or point) number.
        line: usize,
        /// Whether `line` is a file line or a point number.
        place: Place,
        /// The token.
        token: String,
    },
    /// A data line does not have exactly two columns.
    #[error("{file}:{line}: expected 2 columns (x y), found {found}")]
    ColumnCount {
        /// File name as given.
        file: String,
        /// 1-based line number.
        line: usize,
        /// Number of columns found.
        found: usize,
    },
    /// Too few points to describe an airfoil.
    #[error("{file}: only {found} points, at least {min} are needed")]
    TooFewPoints {
        /// File name (or airfoil name).
        file: String,
        /// Points found.
        found: usize,
        /// Minimum accepted.
        min: usize,
    },
    /// More points than [`MAX_CONTOUR_POINTS`](crate::limits::MAX_CONTOUR_POINTS).
    #[error("{file}: {found} points, more than the limit of {max}")]
    TooManyPoints {
        /// File name (or airfoil name).
        file: String,
        /// Points found.
        found: usize,
        /// Most accepted.
        max: usize,
    },
    /// A coordinate beyond [`MAX_COORDINATE`](crate::limits::MAX_COORDINATE).
    #[error(
        "{file}{}: coordinate {} is beyond the limit of ±{} (chord units, or a length \
         unit such as mm)",
        place.at(*line),
        short_number(*value),
        short_number(*limit)
    )]
    CoordinateTooLarge {
        /// File name (or airfoil name).
        file: String,
        /// 1-based line (or point) number.
        line: usize,
        /// Whether `line` is a file line or a point number.
        place: Place,
        /// The coordinate.
        value: f64,
        /// The limit.
        limit: f64,
    },
    /// The contour spans less than [`MIN_CONTOUR_EXTENT`](crate::limits::MIN_CONTOUR_EXTENT).
    #[error(
        "{file}: the contour spans only {}, less than {}: too small to be resolved",
        short_number(*extent),
        short_number(*limit)
    )]
    TooSmall {
        /// File name (or airfoil name).
        file: String,
        /// The larger of the x and y spans.
        extent: f64,
        /// The limit.
        limit: f64,
    },
    /// Every point of the contour is the same point.
    #[error(
        "{file}: all {count} points are the point ({}, {}): the contour spans nothing \
         (coordinates printed with too few decimals for their size?)",
        short_number(*x),
        short_number(*y)
    )]
    SinglePoint {
        /// File name (or airfoil name).
        file: String,
        /// Number of points.
        count: usize,
        /// x of the point.
        x: f64,
        /// y of the point.
        y: f64,
    },
    /// A point repeats an earlier, non-adjacent point.
    #[error(
        "{file}{}: point ({}, {}) repeats the point at {} {first_line}: the contour passes \
         through it twice (listed twice, or folded back)",
        place.at(*line),
        short_number(*x),
        short_number(*y),
        place.word()
    )]
    RepeatedPoint {
        /// File name (or airfoil name).
        file: String,
        /// 1-based line (or point) number of the repetition.
        line: usize,
        /// 1-based line (or point) number of the first occurrence.
        first_line: usize,
        /// Whether the numbers are file lines or point numbers.
        place: Place,
        /// x of the point.
        x: f64,
        /// y of the point.
        y: f64,
    },
    /// The contour does not go once around the section.
    #[error(
        "{file}: the contour turns through {:.0}° from its first to its last segment, more \
         than one pass around a section (180° and the trailing-edge angle): is it listed \
         twice?",
        degrees.abs()
    )]
    Turning {
        /// File name (or airfoil name).
        file: String,
        /// The total turning in degrees.
        degrees: f64,
    },
    /// The contour folds back on itself at a point other than the leading edge.
    #[error(
        "{file}{}: the contour folds back at point ({}, {}) (a turn of {:.0}°): a stray \
         point or a spike, not a smooth surface",
        place.at(*line),
        short_number(*x),
        short_number(*y),
        degrees
    )]
    Spike {
        /// File name (or airfoil name).
        file: String,
        /// 1-based line (or point) number of the point.
        line: usize,
        /// Whether `line` is a file line or a point number.
        place: Place,
        /// x of the point.
        x: f64,
        /// y of the point.
        y: f64,
        /// The turn at the point (degrees).
        degrees: f64,
    },
    /// The contour turns back and forth: many turns against its sense add up to more than a
    /// real section's concave stretches do.
    #[error(
        "{file}{}: the contour zigzags: {reversals} turns against its sense between {}s {line} \
         and {last_line} add up to {degrees:.1}° (a smooth section stays below {limit:.0}°, and \
         the coordinates' rounding is allowed for): a sawtooth or a noisy surface, not a smooth \
         one",
        place.at(*line),
        place.word()
    )]
    Zigzag {
        /// File name (or airfoil name).
        file: String,
        /// 1-based line (or point) number of the first point turning against the sense of the
        /// contour.
        line: usize,
        /// 1-based line (or point) number of the point where the total passed the limit.
        last_line: usize,
        /// Whether the numbers are file lines or point numbers.
        place: Place,
        /// Number of points turning against the sense of the contour up to there.
        reversals: usize,
        /// Their turns against the sense of the contour, beyond what rounding explains, added.
        degrees: f64,
        /// The most a smooth section turns against its sense ([`MAX_REVERSE_TURNING_DEG`]).
        ///
        /// [`MAX_REVERSE_TURNING_DEG`]: super::MAX_REVERSE_TURNING_DEG
        limit: f64,
    },
    /// The contour encloses (almost) no area.
    #[error(
        "{file}: the contour encloses almost no area ({} of the chord squared): a section of \
         zero thickness cannot be solved",
        short_number(*ratio)
    )]
    ZeroThickness {
        /// File name (or airfoil name).
        file: String,
        /// Enclosed area / chord².
        ratio: f64,
    },
    /// The end points are far apart: the contour is cut short.
    #[error(
        "{file}: the trailing-edge gap is {} of the contour's size (at most 0.3): the contour \
         is open (a surface missing or cut short)",
        short_number(*ratio)
    )]
    OpenContour {
        /// File name (or airfoil name).
        file: String,
        /// Gap / extent.
        ratio: f64,
    },
    /// Two consecutive points coincide.
    #[error(
        "{file}{}: point ({}, {}) duplicates the previous point",
        place.at(*line),
        short_number(*x),
        short_number(*y)
    )]
    DuplicatePoint {
        /// File name (or airfoil name).
        file: String,
        /// 1-based line (or point) number.
        line: usize,
        /// Whether `line` is a file line or a point number.
        place: Place,
        /// x of the point.
        x: f64,
        /// y of the point.
        y: f64,
    },
    /// Two non-adjacent contour segments cross.
    #[error(
        "{file}{}: surfaces cross: segment at {word} {line_a} intersects segment at {word} \
         {line_b} near ({}, {})",
        place.at(*line_a),
        short_number(*x),
        short_number(*y),
        word = place.word()
    )]
    SelfIntersecting {
        /// File name (or airfoil name).
        file: String,
        /// Line (or point number) starting the first segment.
        line_a: usize,
        /// Line (or point number) starting the second segment.
        line_b: usize,
        /// Whether the numbers are file lines or point numbers.
        place: Place,
        /// Approximate x of the crossing.
        x: f64,
        /// Approximate y of the crossing.
        y: f64,
    },
    /// A Lednicer header announces point counts that the file does not contain.
    #[error("{file}:{line}: Lednicer header announces {upper} upper + {lower} lower points but {found} were read")]
    LednicerCount {
        /// File name.
        file: String,
        /// Line of the count header.
        line: usize,
        /// Announced upper-surface points.
        upper: usize,
        /// Announced lower-surface points.
        lower: usize,
        /// Points actually read.
        found: usize,
    },
    /// x and y arrays of an airfoil differ in length.
    #[error("{name}: x has {nx} values but y has {ny}")]
    LengthMismatch {
        /// Airfoil name.
        name: String,
        /// Length of x.
        nx: usize,
        /// Length of y.
        ny: usize,
    },
    /// A NACA designation that is not a supported 4- or 5-digit section.
    #[error("invalid NACA designation '{designation}': {reason}")]
    NacaDesignation {
        /// The designation as given.
        designation: String,
        /// Why it is rejected.
        reason: String,
    },
    /// Neither a known airfoil name nor an existing file.
    #[error("unknown airfoil '{name}': not a known name and no such file (accepted: naca8h12, naca23012, nacaDDDD, nacaDDDDD, 'NACA 2412', or a path to a Selig/Lednicer/plain coordinate file)")]
    UnknownAirfoil {
        /// The name as given.
        name: String,
    },
    /// The name is a folder, not a coordinate file.
    #[error("airfoil '{name}' is a folder, not a coordinate file")]
    AirfoilIsFolder {
        /// The name as given.
        name: String,
    },
    /// A geometry operation (thickness, camber, trailing-edge gap, flap, blend) cannot be
    /// applied to the section.
    #[error("{op} on {airfoil}: {reason}")]
    Operation {
        /// The operation.
        op: &'static str,
        /// Airfoil name.
        airfoil: String,
        /// Why not.
        reason: String,
    },
    /// A spline could not be built or evaluated.
    #[error("spline: {0}")]
    Spline(String),
    /// Paneling failed.
    #[error("paneling: {0}")]
    Paneling(String),
    /// A step of making an airfoil ready for the solvers failed ([`Airfoil::solver_nodes`]).
    ///
    /// [`Airfoil::solver_nodes`]: super::Airfoil::solver_nodes
    #[error("{step} {airfoil}")]
    Preparing {
        /// The step: `locating the chord of` or `paneling`.
        step: &'static str,
        /// Airfoil name.
        airfoil: String,
        /// Why the step failed.
        #[source]
        source: Box<GeometryError>,
    },
}
