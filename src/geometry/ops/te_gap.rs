//! Trailing-edge gap (XFOIL GDES `TGAP`).
//!
//! Each point moves along the direction of the present gap (lower to upper trailing-edge
//! point; for a closed trailing edge the normal to the mean of the two end tangents), the
//! upper surface one way and the lower surface the other, by
//! ½ Δgap · (x/c) · exp(−(1 − x/c)(1/d − 1)), where x/c is the point's position along the
//! chord line and d ∈ [0, 1] the blending distance: d = 1 spreads the change linearly over
//! the whole chord, a small d confines it to the trailing edge (d = 0 moves only the two end
//! points).

use super::super::{Airfoil, GeometryError};

/// Largest exponent of the blending factor (XFOIL: 15, a factor of 3·10⁻⁷).
const MAX_BLEND_EXPONENT: f64 = 15.0;

impl Airfoil {
    /// The section with trailing-edge gap `gap` (chord units, the distance between the end
    /// points), the change blended over `blend` ∈ [0, 1] of the chord from the trailing edge
    /// (XFOIL GDES `TGAP`; see the module documentation).
    pub fn with_te_gap(&self, gap: f64, blend: f64) -> Result<Airfoil, GeometryError> {
        let sp = self.spline()?;
        let sle = sp.leading_edge()?;
        let (xle, yle) = sp.point(sle);
        let (xte, yte) = sp.te_midpoint();
        let chord_sq = (xte - xle).powi(2) + (yte - yle).powi(2);
        let n = self.len();
        let (dxn, dyn_) = (self.x[0] - self.x[n - 1], self.y[0] - self.y[n - 1]);
        let old = dxn.hypot(dyn_);
        let (ux, uy) = if old > 0.0 {
            (dxn / old, dyn_ / old)
        } else {
            let (x0, y0) = sp.tangent(sp.s()[0]);
            let (x1, y1) = sp.tangent(sp.s()[n - 1]);
            (-0.5 * (y1 - y0), 0.5 * (x1 - x0))
        };
        let blend = blend.clamp(0.0, 1.0);
        let change = gap - old;
        let (x, y) = (0..n)
            .map(|i| {
                let (px, py) = (self.x[i], self.y[i]);
                let xoc = ((px - xle) * (xte - xle) + (py - yle) * (yte - yle)) / chord_sq;
                let factor = if blend == 0.0 {
                    if i == 0 || i == n - 1 {
                        1.0
                    } else {
                        0.0
                    }
                } else {
                    (-((1.0 - xoc) * (1.0 / blend - 1.0)).min(MAX_BLEND_EXPONENT)).exp()
                };
                let side = if sp.s()[i] <= sle { 0.5 } else { -0.5 };
                let d = side * change * xoc * factor;
                (px + d * ux, py + d * uy)
            })
            .unzip();
        Ok(Airfoil {
            name: self.name.clone(),
            x,
            y,
        })
    }
}
