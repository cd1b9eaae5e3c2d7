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
mod paneling;
mod registry;
mod spline;

pub use coordinates::{
    parse_airfoil_bytes, parse_airfoil_text, read_airfoil_file, to_selig_string, CoordinateFormat,
    MIN_POINTS,
};
pub use error::GeometryError;
pub use naca::{naca, NacaOptions, NacaSection, TrailingEdge};
pub use paneling::{PaneledAirfoil, PanelingParams, DEFAULT_PANEL_NODES};
pub use registry::{airfoil_by_name_or_path, airfoil_key, naca8h12};
pub use spline::{ContourSpline, CubicSpline, EndCondition};

/// Deviation of the chord from 1 and of the leading-edge point from the origin (chord units)
/// up to which [`Airfoil::in_chord_units`] keeps a contour as given.
pub const CHORD_UNITS_TOLERANCE: f64 = 0.01;

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

    /// Checks the contour as the file reader does: equal x/y lengths, at least
    /// [`MIN_POINTS`] finite points, no duplicate consecutive points, no
    /// crossing segments. Errors name the airfoil and the 1-based point number.
    pub fn validate(&self) -> Result<(), GeometryError> {
        if self.x.len() != self.y.len() {
            return Err(GeometryError::LengthMismatch {
                name: self.name.clone(),
                nx: self.x.len(),
                ny: self.y.len(),
            });
        }
        let numbers: Vec<usize> = (1..=self.x.len()).collect();
        coordinates::validate_contour(&self.x, &self.y, &numbers, &self.name)
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

    /// Copy translated, derotated and scaled so that the leading-edge point is at the
    /// origin and the TE midpoint at (1, 0) (XFOIL `NORM` plus derotation).
    pub fn normalized(&self) -> Result<Airfoil, GeometryError> {
        let sp = self.spline()?;
        let (xl, yl) = sp.point(sp.leading_edge()?);
        let (xt, yt) = sp.te_midpoint();
        let (dx, dy) = (xt - xl, yt - yl);
        let c2 = dx * dx + dy * dy;
        if !(c2 > 0.0 && c2.is_finite()) {
            return Err(GeometryError::Paneling(format!(
                "{}: zero chord, cannot normalise",
                self.name
            )));
        }
        // Rotation by −atan2(dy, dx) and scaling by 1/c in one step: (u, v) = R·(p − LE)/c.
        let (ca, sa) = (dx / c2, dy / c2);
        let (x, y) = self
            .x
            .iter()
            .zip(&self.y)
            .map(|(&px, &py)| {
                let (rx, ry) = (px - xl, py - yl);
                (ca * rx + sa * ry, ca * ry - sa * rx)
            })
            .unzip();
        Ok(Airfoil {
            name: self.name.clone(),
            x,
            y,
        })
    }

    /// The contour in chord units. A contour whose chord is 1 and whose leading-edge point is
    /// at the origin within [`CHORD_UNITS_TOLERANCE`] is returned as given (like XFOIL, which
    /// does not normalise, so results on standard files match XFOIL's); any other (e.g.
    /// ordinates in millimetres or percent, or a shifted contour) is [`normalized`]. The flag
    /// says whether it was normalised.
    ///
    /// [`normalized`]: Self::normalized
    pub fn in_chord_units(&self) -> Result<(Airfoil, bool), GeometryError> {
        let sp = self.spline()?;
        let (xl, yl) = sp.point(sp.leading_edge()?);
        let (xt, yt) = sp.te_midpoint();
        let chord = (xt - xl).hypot(yt - yl);
        let tol = CHORD_UNITS_TOLERANCE;
        if (chord - 1.0).abs() <= tol && xl.hypot(yl) <= tol {
            Ok((self.clone(), false))
        } else {
            Ok((self.normalized()?, true))
        }
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

    /// The note a user reads when [`solver_nodes`](Self::solver_nodes) normalised the contour
    /// of the airfoil given as `given` (a name or a path).
    pub fn normalisation_note(given: &str) -> String {
        format!(
            "{given}: chord is not 1 or the leading edge is not at the origin; coordinates \
             normalised to unit chord (LE at 0,0, TE at 1,0)"
        )
    }

    /// The nodes the solvers work on: the contour [`in chord units`] repaneled to `panels`
    /// nodes with the default [`PanelingParams`] (XFOIL `PANE`), as the command-line tools and
    /// the Python package prepare every airfoil. The flag says whether the contour was
    /// normalised on the way. Errors name the step and the airfoil
    /// ([`GeometryError::Preparing`]).
    ///
    /// [`in chord units`]: Self::in_chord_units
    pub fn solver_nodes(&self, panels: usize) -> Result<(Airfoil, bool), GeometryError> {
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
        let nodes = raw
            .repanel(panels, &PanelingParams::default())
            .map_err(step("paneling"))?;
        Ok((nodes, normalised))
    }
}
