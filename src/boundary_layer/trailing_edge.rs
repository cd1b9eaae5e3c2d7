//! Trailing-edge junction of the two surface boundary layers into the wake (XFOIL 6.99
//! xblsys.f TESYS with the TE sums of xbl.f SETBL) and the Squire–Young drag from the wake
//! end (XFOIL xfoil.f CDCALC).

use super::params::Regime;
use super::station::{compressible_speed_d, validate, StationVars};
use super::Dual;
use super::{BlError, BlModel};

/// Junction equations setting the first wake station from the upper and lower TE stations.
///
/// Residuals R (XFOIL VSREZ = −R), R = 0 at the solution:
/// 0: √Cτ_w − (√Cτ_u θ_u + √Cτ_l θ_l)/(θ_u + θ_l),
/// 1: θ_w − (θ_u + θ_l),
/// 2: δ*_w − (δ*_u + δ*_l + h_TE),
/// with δ* the total displacement thickness (the wake value includes the wake gap) and h_TE
/// the trailing-edge gap. Jacobian columns (s, θ, δ*, u, ξ) of each station.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TeJunction {
    /// Residuals R.
    pub res: [f64; 3],
    /// ∂R/∂(upper TE station variables).
    pub d_upper: [[f64; 5]; 3],
    /// ∂R/∂(lower TE station variables).
    pub d_lower: [[f64; 5]; 3],
    /// ∂R/∂(first wake station variables).
    pub d_wake: [[f64; 5]; 3],
}

/// Squire–Young drag coefficient and its derivatives with respect to the last wake station.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SquireYoung {
    /// CD = 2θ (Ue/V∞)^((5 + H)/2), Ue compressible, H = δ*/θ (XFOIL CDCALC).
    pub cd: f64,
    /// ∂CD/∂(s, θ, δ*, u, ξ) of the last wake station (u incompressible).
    pub d: [f64; 5],
}

impl BlModel {
    /// Trailing-edge junction equations (XFOIL TESYS); `te_gap` is the TE gap thickness
    /// (XFOIL ANTE). Both TE stations must be turbulent (√Cτ in `s`).
    pub fn te_junction(
        &self,
        upper: &StationVars,
        lower: &StationVars,
        wake: &StationVars,
        te_gap: f64,
    ) -> Result<TeJunction, BlError> {
        validate(upper, Regime::Turbulent)?;
        validate(lower, Regime::Turbulent)?;
        validate(wake, Regime::Wake)?;
        if !te_gap.is_finite() || te_gap < 0.0 {
            return Err(BlError::Station {
                what: "trailing-edge gap",
                value: te_gap,
            });
        }
        let tte = upper.theta + lower.theta;
        let cte = (upper.s * upper.theta + lower.s * lower.theta) / tte;
        let res = [
            wake.s - cte,
            wake.theta - tte,
            wake.dstar - (upper.dstar + lower.dstar + te_gap),
        ];
        // d cte/d s_u = θ_u/tte; d cte/d θ_u = (s_u − cte)/tte
        let d_upper = [
            [-upper.theta / tte, -(upper.s - cte) / tte, 0.0, 0.0, 0.0],
            [0.0, -1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, -1.0, 0.0, 0.0],
        ];
        let d_lower = [
            [-lower.theta / tte, -(lower.s - cte) / tte, 0.0, 0.0, 0.0],
            [0.0, -1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, -1.0, 0.0, 0.0],
        ];
        let d_wake = [
            [1.0, 0.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0, 0.0],
        ];
        Ok(TeJunction {
            res,
            d_upper,
            d_lower,
            d_wake,
        })
    }

    /// Squire–Young drag from the last wake station (XFOIL CDCALC):
    /// CD = 2θ (Ue/V∞)^((5 + H)/2) with the Karman–Tsien compressible Ue and H = δ*/θ.
    pub fn squire_young(&self, last_wake: &StationVars) -> Result<SquireYoung, BlError> {
        validate(last_wake, Regime::Wake)?;
        let t = Dual::<5>::variable(last_wake.theta, 1);
        let d = Dual::variable(last_wake.dstar, 2);
        let u = compressible_speed_d(Dual::variable(last_wake.u, 3), &self.flow);
        let h = d / t;
        let cd = t * 2.0 * ((h + 5.0) * 0.5 * u.ln()).exp();
        Ok(SquireYoung {
            cd: cd.v,
            d: cd.slots(0),
        })
    }
}
