//! 360° extension of a polar beyond its computed α range.
//!
//! A viscous solver gives coefficients only up to (and a little past) stall. A rotor blade
//! element sees every angle: deep stall on the retreating side and reverse flow (α near ±180°)
//! near the root. Beyond the last converged point on either side this module continues the
//! polar with the model rotor and wind-turbine codes use (AeroDyn's AirfoilPrep, Hansen 2004):
//!
//! * from the junction α_s to ±90°: **Viterna–Corrigan** (Viterna & Corrigan 1982, "Fixed
//!   pitch rotor performance of large horizontal axis wind turbines", NASA CP-2230, eqs. for
//!   C_L and C_D in deep stall):
//!   `cl = A1·sin 2α + A2·cos²α / sin α`, `cd = B1·sin²α + B2·cos α`, with `B1 = cd_max`,
//!   `A1 = B1/2`, `A2 = (cl_s − cd_max·sin α_s·cos α_s)·sin α_s / cos²α_s`,
//!   `B2 = (cd_s − cd_max·sin²α_s) / cos α_s`, so that cl and cd equal the polar at α_s and
//!   reach the flat plate (cl = 0, cd = cd_max) at ±90°;
//! * from ±90° to ±180°: a **flat plate** whose normal force is `cn = cd_max·sin α` (Hoerner,
//!   Fluid-Dynamic Drag, 1965, ch. 3: normal-force coefficient ≈ 2 for a 2-D plate):
//!   `cl = cn·cos α`, `cd = cn·sin α + cd_reverse·cos²α`, and a centre of pressure moving from
//!   c/4 at 0° to c/2 at 90° and 3c/4 at 180° (`x_cp = ½ − ¼·cos α`), so
//!   `cm = −cn·(x_cp − ¼) = −¼·cd_max·sin α·(1 − cos α)`.
//!
//! The pitching moment has no Viterna–Corrigan form: between α_s and ±90° it is blended from
//! the polar's value to the flat plate's with the weight `w = cos²(½π·(α − α_s)/(±90° − α_s))`
//! (1 at the junction, 0 at ±90°, zero slope at both ends). The same blend is used for cl and
//! cd when α_s is too close to 0° or on the wrong side of it for Viterna–Corrigan (a polar that
//! converged only in a narrow range), and between α_s and ±180° when the data already extend
//! past ±90°. All pieces meet continuously (cl, cd, cm) at α_s and ±90°, and both sides end at
//! the same flat-plate values at ±180°, so the extension is periodic.

use super::TableError;
use serde::{Deserialize, Serialize};
use std::f64::consts::{FRAC_PI_2, PI};

/// Tunable constants of the 360° extension.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PostStallParams {
    /// Drag coefficient of the section broadside to the flow (α = ±90°), the flat-plate normal
    /// force coefficient. Viterna & Corrigan give `1.11 + 0.018·AR` (2.01 for AR ≥ 50); a
    /// two-dimensional plate is ≈ 2.0 (Hoerner 1965, ch. 3).
    pub cd_max: f64,
    /// Drag coefficient at α = ±180° (section in reverse flow, trailing edge first). A few
    /// hundredths, the order measured on a reversed NACA 0012 (Critzos, Heyson & Boswinkle
    /// 1955, NACA TN 3361).
    pub cd_reverse: f64,
    /// Smallest |α_s| (deg) at the junction for which Viterna–Corrigan is used; below it (or
    /// with α_s on the wrong side of 0°) the cos² blend to the flat plate is used instead,
    /// because the A2 term ∝ 1/sin α would blow up.
    pub vc_min_junction_deg: f64,
}

impl Default for PostStallParams {
    fn default() -> Self {
        Self {
            cd_max: 2.0,
            cd_reverse: 0.03,
            vc_min_junction_deg: 3.0,
        }
    }
}

impl PostStallParams {
    /// Check the ranges: 0 < `cd_max` ≤ [`MAX_CD_MAX`](crate::limits::MAX_CD_MAX),
    /// `cd_reverse` ≥ 0, 0 ≤ `vc_min_junction_deg` < 90, all finite.
    pub fn validate(&self) -> Result<(), TableError> {
        let checks = [
            (
                "cd_max",
                self.cd_max,
                self.cd_max > 0.0 && self.cd_max <= crate::limits::MAX_CD_MAX,
                "in (0, 3]",
            ),
            (
                "cd_reverse",
                self.cd_reverse,
                self.cd_reverse >= 0.0,
                "non-negative",
            ),
            (
                "vc_min_junction_deg",
                self.vc_min_junction_deg,
                (0.0..90.0).contains(&self.vc_min_junction_deg),
                "in [0, 90)",
            ),
        ];
        for (name, value, ok, rule) in checks {
            if !(ok && value.is_finite()) {
                return Err(TableError::BadPostStall { name, value, rule });
            }
        }
        Ok(())
    }

    /// Flat-plate coefficients (cl, cd, cm about c/4) at `alpha` (rad); see the module docs.
    pub fn flat_plate(&self, alpha: f64) -> [f64; 3] {
        let (s, c) = alpha.sin_cos();
        self.flat_plate_sc(s, c)
    }

    /// Flat-plate coefficients from `(sin α, cos α)`.
    fn flat_plate_sc(&self, s: f64, c: f64) -> [f64; 3] {
        let cn = self.cd_max * s;
        [
            cn * c,
            cn * s + self.cd_reverse * c * c,
            -0.25 * cn * (1.0 - c),
        ]
    }
}

/// (sin α, cos α) of `alpha_deg`, exact (0, ±1) at the multiples of 90°, where converting to
/// radians first would leave round-off (sin 180° = 1.2e-16) in the extension's values.
pub(crate) fn sin_cos_deg(alpha_deg: f64) -> (f64, f64) {
    if alpha_deg % 90.0 == 0.0 {
        match (alpha_deg / 90.0).rem_euclid(4.0) as u8 {
            0 => (0.0, 1.0),
            1 => (1.0, 0.0),
            2 => (0.0, -1.0),
            _ => (-1.0, 0.0),
        }
    } else {
        alpha_deg.to_radians().sin_cos()
    }
}

/// The coefficients at the junction between computed data and the extension.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Junction {
    /// α_s (deg): the first (lower side) or last (upper side) converged α.
    pub alpha_deg: f64,
    /// Lift coefficient at α_s.
    pub cl: f64,
    /// Drag coefficient at α_s.
    pub cd: f64,
    /// Moment coefficient at α_s.
    pub cm: f64,
}

/// The extension on one side of the computed range.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Side {
    /// Junction angle (rad).
    a_s: f64,
    /// Junction values (cl, cd, cm).
    v_s: [f64; 3],
    /// End of the blended segment (rad): ±π/2, or ±π when the data pass ±90°.
    end: f64,
    /// Viterna–Corrigan coefficients (A2, B2) when it applies.
    vc: Option<(f64, f64)>,
}

/// The 360° extension of one polar: both sides, built from the two junctions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extension360 {
    params: PostStallParams,
    lower: Side,
    upper: Side,
}

impl Extension360 {
    /// Build the extension for a polar whose converged data span `lower.alpha_deg ..=
    /// upper.alpha_deg`.
    pub fn new(params: PostStallParams, lower: Junction, upper: Junction) -> Self {
        Self {
            params,
            lower: Side::new(&params, lower, -1.0),
            upper: Side::new(&params, upper, 1.0),
        }
    }

    /// (cl, cd, cm) at `alpha_deg`, which must lie outside the computed range, in
    /// [−180°, lower α_s) or (upper α_s, 180°], with `(sin α, cos α)` already known (shared by
    /// the four polars of one table lookup).
    pub fn eval_sc(&self, alpha_deg: f64, sin_a: f64, cos_a: f64) -> [f64; 3] {
        let a = alpha_deg.to_radians();
        let side = if a > self.upper.a_s {
            &self.upper
        } else {
            &self.lower
        };
        side.eval(&self.params, a, sin_a, cos_a)
    }
}

impl Side {
    /// One side; `sign` is +1 for the upper (positive-α) side, −1 for the lower one.
    fn new(p: &PostStallParams, j: Junction, sign: f64) -> Self {
        let a_s = j.alpha_deg.to_radians();
        let v_s = [j.cl, j.cd, j.cm];
        let past_90 = sign * a_s >= FRAC_PI_2 - 1e-9;
        let end = if past_90 { sign * PI } else { sign * FRAC_PI_2 };
        let vc_ok = !past_90 && sign * j.alpha_deg >= p.vc_min_junction_deg;
        let vc = vc_ok.then(|| {
            // Viterna & Corrigan (1982): A2 and B2 chosen so that cl, cd match at α_s.
            let (s, c) = a_s.sin_cos();
            let a2 = (j.cl - p.cd_max * s * c) * s / (c * c);
            let b2 = (j.cd - p.cd_max * s * s) / c;
            (a2, b2)
        });
        Self { a_s, v_s, end, vc }
    }

    /// Coefficients at `a` (rad) (with sine `s` and cosine `c`) beyond this side's junction.
    fn eval(&self, p: &PostStallParams, a: f64, s: f64, c: f64) -> [f64; 3] {
        let t = (a - self.a_s) / (self.end - self.a_s);
        let fp = p.flat_plate_sc(s, c);
        if t >= 1.0 {
            return fp;
        }
        let t = t.max(0.0);
        let w = (FRAC_PI_2 * t).cos().powi(2);
        let blend = |k: usize| w * self.v_s[k] + (1.0 - w) * fp[k];
        let cm = blend(2);
        match self.vc {
            Some((a2, b2)) => [
                p.cd_max * s * c + a2 * c * c / s,
                p.cd_max * s * s + b2 * c,
                cm,
            ],
            None => [blend(0), blend(1), cm],
        }
    }
}
