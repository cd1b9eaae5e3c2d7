//! Airfoil geometry: shapes (NACA generators, coordinate files, the name registry), the
//! arc-length spline and curvature-based repaneling.

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
