//! Blending two sections by a fraction (XFOIL's `INTX`; XFLR5's foil interpolation pairs
//! points the same way).
//!
//! Points are paired at the same chordwise station of the same surface: for each point of the
//! first section, its fraction of the way from the leading-edge point to its surface's
//! trailing-edge point in x; the second section's point on the same surface at that fraction
//! of its own leading-edge-to-trailing-edge x range. The blend is (1 − f)·first + f·second in
//! x and y, on the first section's points. Pairing by chordwise station (rather than by arc
//! length, XFOIL's `INTE`) makes the blend of two thicknesses of one family the intermediate
//! thickness at every station.

use super::super::{Airfoil, GeometryError};
use super::{invert_x, op_error};

impl Airfoil {
    /// `(1 − fraction)` of this section plus `fraction` of `other`, points paired by chordwise
    /// station on each surface (see the module documentation); the result has this section's
    /// point count and name.
    pub fn blended(&self, other: &Airfoil, fraction: f64) -> Result<Airfoil, GeometryError> {
        let a = self.spline()?;
        let b = other.spline()?;
        let (sa, sb) = (a.s(), b.s());
        let (na, nb) = (sa.len(), sb.len());
        let (sle_a, sle_b) = (a.leading_edge()?, b.leading_edge()?);
        let (xle_a, xle_b) = (a.point(sle_a).0, b.point(sle_b).0);
        let ends_a = (self.x[0], self.x[na - 1]);
        let ends_b = (other.x[0], other.x[nb - 1]);
        let (f0, f1) = (1.0 - fraction, fraction);
        let mut x = Vec::with_capacity(na);
        let mut y = Vec::with_capacity(na);
        for (i, &si) in sa.iter().enumerate() {
            let upper = si < sle_a;
            let (te_a, te_b) = if upper {
                (ends_a.0, ends_b.0)
            } else {
                (ends_a.1, ends_b.1)
            };
            let station = (self.x[i] - xle_a) / (te_a - xle_a);
            let target = xle_b + (te_b - xle_b) * station;
            let (lo, hi) = if upper {
                (sb[0], sle_b)
            } else {
                (sle_b, sb[nb - 1])
            };
            let sj = invert_x(&b, target, lo, hi).ok_or_else(|| {
                op_error(
                    self,
                    "blend",
                    &format!(
                        "no point of {} at the chordwise station {station:.4}",
                        other.name
                    ),
                )
            })?;
            let (xb, yb) = b.point(sj);
            x.push(f0 * self.x[i] + f1 * xb);
            y.push(f0 * self.y[i] + f1 * yb);
        }
        Ok(Airfoil {
            name: self.name.clone(),
            x,
            y,
        })
    }
}
