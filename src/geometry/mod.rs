//! Airfoil geometry: shapes (NACA generators, coordinate files, the name registry), the
//! arc-length spline and curvature-based repaneling.
//!
//! Typical use:
//! ```
//! use polargen::geometry::{airfoil_by_name_or_path, PanelingParams};
//! let foil = airfoil_by_name_or_path("NACA 2412").unwrap();
//! let paneled = foil.panel(160, &PanelingParams::default()).unwrap();
//! assert_eq!(paneled.len(), 160);
//! ```

mod coordinates;
mod error;
mod naca;
mod ops;
mod paneling;
mod registry;
mod spline;
mod validation;

use crate::limits::short_number;
pub use coordinates::{
    parse_airfoil_bytes, parse_airfoil_text, read_airfoil_file, to_selig_string, CoordinateFormat,
};
pub use error::{GeometryError, Place};
pub use naca::{naca, NacaOptions, NacaSection, TrailingEdge};
pub use ops::{
    apply_shape_ops, flap_deflection, flap_deg, parse_shape_ops, shape_ops_text,
    with_flap_deflection, LineMaximum, ShapeOp, ThicknessCamber, DEFAULT_TE_GAP_BLEND, MAX_CAMBER,
    MAX_FLAP_DEG, MAX_HINGE_Y, MAX_TE_GAP, MAX_THICKNESS,
};
pub use paneling::{PaneledAirfoil, PanelingParams, DEFAULT_PANEL_NODES};
pub use registry::{
    airfoil_by_name_or_path, airfoil_key, naca8h12, selig_file_text, shaped_airfoil, solver_airfoil,
};
pub use spline::{ContourSpline, CubicSpline, EndCondition, MEAN_LINE_STEPS};
pub use validation::{
    MAX_REVERSE_TURNING_DEG, MAX_REVERSE_TURN_DEG, MAX_TE_GAP_RATIO, MAX_TURNING_DEG,
    MIN_AREA_RATIO, MIN_POINTS, SPIKE_TURN_DEG,
};

/// Deviation of the chord (the distance from the leading-edge point to the TE midpoint, or the
/// length of the mean line) from 1 and of the leading-edge point from the origin (chord units)
/// up to which [`Airfoil::in_chord_units`] keeps a contour as given.
pub const CHORD_UNITS_TOLERANCE: f64 = 0.01;

/// How [`Airfoil::in_chord_units`] brought a contour to chord units: translated so that its
/// leading-edge point is at the origin and scaled by `scale`, the inverse of its chord (the
/// distance from the leading-edge point to the TE midpoint); never rotated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Normalisation {
    /// The leading-edge point as given (moved to the origin).
    pub leading_edge: (f64, f64),
    /// The factor the coordinates were multiplied by: 1 / chord.
    pub scale: f64,
    /// Inclination of the chord line to the x axis (degrees, positive with the trailing edge
    /// above the leading edge), which the normalisation keeps.
    pub chord_angle_deg: f64,
}

impl Normalisation {
    /// The note a user reads about the normalisation of the airfoil given as `given` (a name
    /// or a path): the chord and leading edge found, the scale factor, and the chord line's
    /// inclination, which stays the reference of α.
    pub fn note(&self, given: &str) -> String {
        let (xl, yl) = self.leading_edge;
        // No "-0.000" for a level chord line.
        let angle = if self.chord_angle_deg.abs() < 5e-4 {
            0.0
        } else {
            self.chord_angle_deg
        };
        format!(
            "{given}: normalised to unit chord: the chord (leading edge at ({}, {}) to the \
             trailing-edge midpoint) is {}; coordinates scaled by {} and translated to put the \
             leading edge at (0, 0), not rotated (the chord line stays at {:.3} deg to the x \
             axis)",
            short_number(xl),
            short_number(yl),
            short_number(1.0 / self.scale),
            short_number(self.scale),
            angle
        )
    }
}

/// The chord line of a contour: leading-edge point, TE midpoint and their distance, and the
/// length of the mean line.
struct ChordLine {
    le: (f64, f64),
    te: (f64, f64),
    chord: f64,
    mean_line: f64,
}

/// An airfoil contour as an ordered list of points in XFOIL order: from the upper-surface
/// trailing edge, forward over the upper surface, around the leading edge and back along the
/// lower surface to the lower-surface trailing edge (counter-clockwise for a normal airfoil).
///
/// Coordinates are in chord units once normalised (LE at the origin, TE at x = 1), but the
/// struct itself does not enforce that; see the paneling functions.
#[derive(Clone, Debug, PartialEq)]
pub struct Airfoil {
    /// Display name (first line of a Selig/Lednicer file, or e.g. `NACA 23012`).
    pub name: String,
    /// x coordinates, XFOIL order.
    pub x: Vec<f64>,
    /// y coordinates, XFOIL order.
    pub y: Vec<f64>,
}

impl Airfoil {
    /// Number of contour points.
    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// True if the contour has no points.
    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }

    /// Checks the contour as the file reader does: equal x/y lengths, then the checks of the
    /// file reader (point count and coordinate limits, no repeated points, no crossing
    /// segments, one turn around the section without spikes, a thickness). Errors name the
    /// airfoil and the 1-based point number.
    pub fn validate(&self) -> Result<(), GeometryError> {
        if self.x.len() != self.y.len() {
            return Err(GeometryError::LengthMismatch {
                name: self.name.clone(),
                nx: self.x.len(),
                ny: self.y.len(),
            });
        }
        let numbers: Vec<usize> = (1..=self.x.len()).collect();
        validation::validate_contour(&self.x, &self.y, &numbers, Place::Point, &self.name)
    }

    /// Trailing-edge gap: distance between the first and the last point (XFOIL `GAP`).
    pub fn te_gap(&self) -> f64 {
        match (self.x.first(), self.x.last(), self.y.first(), self.y.last()) {
            (Some(x0), Some(x1), Some(y0), Some(y1)) => (x0 - x1).hypot(y0 - y1),
            _ => 0.0,
        }
    }

    /// Arc-length spline through the points (XFOIL `SCALC` + `SEGSPL`).
    pub fn spline(&self) -> Result<ContourSpline, GeometryError> {
        self.validate()?;
        ContourSpline::new(&self.x, &self.y)
    }

    /// Leading-edge point of the splined contour (XFOIL `LEFIND`): where the tangent is
    /// perpendicular to the line to the TE midpoint.
    pub fn leading_edge(&self) -> Result<(f64, f64), GeometryError> {
        let sp = self.spline()?;
        Ok(sp.point(sp.leading_edge()?))
    }

    /// Index of the point closest in arc length to the leading-edge point.
    pub fn le_index(&self) -> Result<usize, GeometryError> {
        let sp = self.spline()?;
        let sle = sp.leading_edge()?;
        Ok(paneling::nearest_index(sp.s(), sle))
    }

    /// Chord: distance from the leading-edge point to the TE midpoint.
    pub fn chord(&self) -> Result<f64, GeometryError> {
        let sp = self.spline()?;
        let (xl, yl) = sp.point(sp.leading_edge()?);
        let (xt, yt) = sp.te_midpoint();
        Ok((xt - xl).hypot(yt - yl))
    }

    /// Copy translated and scaled so that the leading-edge point is at the origin and the
    /// chord (leading-edge point to TE midpoint) is 1 (XFOIL `NORM` on a level contour): never
    /// rotated, so that angles of attack keep the reference of the coordinates (their x axis).
    /// A TE midpoint that is not aft of the leading edge is an error.
    pub fn normalized(&self) -> Result<Airfoil, GeometryError> {
        Ok(self.normalised_by(&self.chord_line()?))
    }

    /// The leading-edge point and the TE midpoint (XFOIL `LEFIND`, the TE midpoint), checked:
    /// the trailing edge aft of the leading edge (the chord line less than 90° from the x axis).
    fn chord_line(&self) -> Result<ChordLine, GeometryError> {
        let sp = self.spline()?;
        let s_le = sp.leading_edge()?;
        let le = sp.point(s_le);
        let te = sp.te_midpoint();
        let chord = (te.0 - le.0).hypot(te.1 - le.1);
        if !(te.0 > le.0 && chord.is_finite()) {
            return Err(GeometryError::Paneling(format!(
                "{}: the trailing edge is not aft of the leading edge (x {} vs {}), cannot \
                 normalise",
                self.name,
                short_number(te.0),
                short_number(le.0)
            )));
        }
        Ok(ChordLine {
            le,
            te,
            chord,
            mean_line: sp.mean_line_length(s_le),
        })
    }

    /// Copy translated to put the leading edge of `line` at the origin and scaled by 1/chord.
    fn normalised_by(&self, line: &ChordLine) -> Airfoil {
        let (xl, yl) = line.le;
        let scale = 1.0 / line.chord;
        Airfoil {
            name: self.name.clone(),
            x: self.x.iter().map(|&px| (px - xl) * scale).collect(),
            y: self.y.iter().map(|&py| (py - yl) * scale).collect(),
        }
    }

    /// Largest thickness / chord, measured normal to the chord line (the airfoil's t/c, the
    /// `RelThickness` of AeroDyn files): the largest distance between the upper and the lower
    /// surface at one chordwise station, the contour taken in chord units along its chord
    /// line, each surface linear between its points.
    pub fn max_thickness(&self) -> Result<f64, GeometryError> {
        let foil = self.derotated()?.normalized()?;
        let le = foil.le_index()?;
        // Upper surface from the LE to the TE (x increasing), lower likewise.
        let upper: Vec<(f64, f64)> = (0..=le).rev().map(|k| (foil.x[k], foil.y[k])).collect();
        let lower: Vec<(f64, f64)> = (le..foil.len()).map(|k| (foil.x[k], foil.y[k])).collect();
        let at = |side: &[(f64, f64)], x: f64| -> Option<f64> {
            side.windows(2).find_map(|w| {
                let ((x0, y0), (x1, y1)) = (w[0], w[1]);
                (x0.min(x1) <= x && x <= x0.max(x1) && x1 != x0)
                    .then(|| y0 + (y1 - y0) * (x - x0) / (x1 - x0))
            })
        };
        let from_upper = upper
            .iter()
            .filter_map(|&(x, y)| at(&lower, x).map(|yl| y - yl));
        let from_lower = lower
            .iter()
            .filter_map(|&(x, y)| at(&upper, x).map(|yu| yu - y));
        Ok(from_upper.chain(from_lower).fold(0.0, f64::max))
    }

    /// Inclination of the chord line (leading-edge point to TE midpoint) to the x axis, in
    /// degrees, positive when the trailing edge is above the leading edge.
    pub fn chord_angle_deg(&self) -> Result<f64, GeometryError> {
        let sp = self.spline()?;
        let (xl, yl) = sp.point(sp.leading_edge()?);
        let (xt, yt) = sp.te_midpoint();
        Ok((yt - yl).atan2(xt - xl).to_degrees())
    }

    /// Copy rotated about the leading-edge point so that the chord line lies along +x (angles
    /// of attack are then measured from the chord line); not scaled or translated. Only on a
    /// user's explicit request: it changes the angle reference of the coordinates.
    pub fn derotated(&self) -> Result<Airfoil, GeometryError> {
        let sp = self.spline()?;
        let (xl, yl) = sp.point(sp.leading_edge()?);
        let (sa, ca) = (-self.chord_angle_deg()?.to_radians()).sin_cos();
        let (x, y) = self
            .x
            .iter()
            .zip(&self.y)
            .map(|(&px, &py)| {
                let (rx, ry) = (px - xl, py - yl);
                (xl + ca * rx - sa * ry, yl + sa * rx + ca * ry)
            })
            .unzip();
        Ok(Airfoil {
            name: self.name.clone(),
            x,
            y,
        })
    }

    /// The contour in chord units. A contour whose leading-edge point is at the origin and
    /// whose chord (the distance from the leading-edge point to the TE midpoint) or mean line
    /// ([`ContourSpline::mean_line_length`]: a deflected flap shortens the chord, not the mean
    /// line; strong camber lengthens the mean line, not the chord) is 1 within
    /// [`CHORD_UNITS_TOLERANCE`] is returned as given, whatever the inclination of its chord
    /// line (like XFOIL, which does not normalise, so results on standard files match
    /// XFOIL's); any other (e.g. ordinates in millimetres or percent, or a shifted contour) is
    /// [`normalized`]: translated and scaled by 1/chord, never rotated. With the
    /// [`Normalisation`] when it was normalised.
    ///
    /// [`normalized`]: Self::normalized
    pub fn in_chord_units(&self) -> Result<(Airfoil, Option<Normalisation>), GeometryError> {
        let line = self.chord_line()?;
        let (xl, yl) = line.le;
        let tol = CHORD_UNITS_TOLERANCE;
        let unit = |length: f64| (length - 1.0).abs() <= tol;
        if xl.hypot(yl) <= tol && (unit(line.chord) || unit(line.mean_line)) {
            return Ok((self.clone(), None));
        }
        let (xt, yt) = line.te;
        let normalisation = Normalisation {
            leading_edge: line.le,
            scale: 1.0 / line.chord,
            chord_angle_deg: (yt - yl).atan2(xt - xl).to_degrees(),
        };
        Ok((self.normalised_by(&line), Some(normalisation)))
    }

    /// Curvature-based repaneling to `n` nodes (XFOIL `PANGEN`), with helper data for the
    /// panel method. Not normalised, like XFOIL's `PANE`.
    pub fn panel(
        &self,
        n: usize,
        params: &PanelingParams,
    ) -> Result<PaneledAirfoil, GeometryError> {
        paneling::panel(self, n, params)
    }

    /// Curvature-based repaneling to `n` nodes; the nodes only (see [`Airfoil::panel`]).
    pub fn repanel(&self, n: usize, params: &PanelingParams) -> Result<Airfoil, GeometryError> {
        paneling::panel(self, n, params).map(|p| p.airfoil)
    }

    /// The nodes the solvers work on: the contour [`in chord units`] repaneled to `panels`
    /// nodes with the default [`PanelingParams`] (XFOIL `PANE`), as the command-line tools and
    /// the Python package prepare every airfoil; with the [`Normalisation`] if the contour was
    /// normalised on the way. Errors name the step and the airfoil
    /// ([`GeometryError::Preparing`]).
    ///
    /// [`in chord units`]: Self::in_chord_units
    pub fn solver_nodes(
        &self,
        panels: usize,
    ) -> Result<(Airfoil, Option<Normalisation>), GeometryError> {
        let step = |step: &'static str| {
            move |source: GeometryError| GeometryError::Preparing {
                step,
                airfoil: self.name.clone(),
                source: Box::new(source),
            }
        };
        let (raw, normalised) = self
            .in_chord_units()
            .map_err(step("locating the chord of"))?;
        Ok((raw.prepared_nodes(panels)?, normalised))
    }

    /// The nodes the solvers work on for a contour already in chord units (a shaped section,
    /// [`apply_shape_ops`]): repaneled to `panels` nodes with the default [`PanelingParams`],
    /// not normalised. Errors name the step and the airfoil ([`GeometryError::Preparing`]).
    pub fn prepared_nodes(&self, panels: usize) -> Result<Airfoil, GeometryError> {
        self.repanel(panels, &PanelingParams::default())
            .map_err(|source| GeometryError::Preparing {
                step: "paneling",
                airfoil: self.name.clone(),
                source: Box::new(source),
            })
    }
}
