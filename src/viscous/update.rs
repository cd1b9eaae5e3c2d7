//! Relaxed Newton update of the boundary-layer state (XFOIL xbl.f UPDATE and DSLIM,
//! Drela 1989 §4): one under-relaxation factor for all stations, chosen so that no relative
//! change of √Cτ/N, θ, δ* or Ue exceeds the limits, then clipping of √Cτ and of the shape factor.
//! One departure from XFOIL: see [`UpdateLimits::clip_first_turbulent`].

use super::error::ViscousError;
use super::newton::Coupling;
use super::state::BlState;
use super::stations::{StationLayout, Surface};
use crate::boundary_layer::BlModel;
use crate::numerics::dense::mat_vec;

/// Limits of the relaxed update (XFOIL UPDATE/DSLIM constants).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UpdateLimits {
    /// Largest allowed relative increase of any variable per iteration (XFOIL DHI = 1.5).
    pub dhi: f64,
    /// Largest allowed relative decrease (XFOIL DLO = −0.5).
    pub dlo: f64,
    /// Scale of N changes in the laminar region (XFOIL: ΔN/10).
    pub n_scale: f64,
    /// Scale of Ue changes (XFOIL: ΔUe/0.25).
    pub ue_scale: f64,
    /// Upper clip of √Cτ (XFOIL 0.25).
    pub ctau_sqrt_max: f64,
    /// Minimum Hk on the airfoil (XFOIL HKLIM = 1.02).
    pub hk_min_airfoil: f64,
    /// Minimum Hk in the wake (XFOIL 1.00005).
    pub hk_min_wake: f64,
    /// A decrease of √Cτ at the first turbulent station of each surface does not set the
    /// relaxation factor; that one value is clipped at the `dlo` limit instead. Where free
    /// transition moves, the station next to it is re-initialised turbulent each iteration,
    /// and the Newton step asks for √Cτ to fall by a factor 10–20 there; in XFOIL that alone
    /// sets RLX to 0.03–0.1 for the whole update, and transition then creeps one station per
    /// iteration. (Not in XFOIL.)
    pub clip_first_turbulent: bool,
}

impl Default for UpdateLimits {
    fn default() -> Self {
        Self {
            dhi: 1.5,
            dlo: -0.5,
            n_scale: 10.0,
            ue_scale: 0.25,
            ctau_sqrt_max: 0.25,
            hk_min_airfoil: 1.02,
            hk_min_wake: 1.00005,
            clip_first_turbulent: true,
        }
    }
}

impl UpdateLimits {
    /// The lowest Hk of a station (XFOIL DSLIM HKLIM), on the airfoil or in the wake: the
    /// update and the mixed-mode re-march raise δ* to keep Hk above it.
    pub fn hk_floor(&self, wake: bool) -> f64 {
        if wake {
            self.hk_min_wake
        } else {
            self.hk_min_airfoil
        }
    }
}

/// Outcome of one update.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UpdateResult {
    /// Relaxation factor used (XFOIL RLX).
    pub rlx: f64,
    /// RMS of the relative changes (XFOIL RMSBL), the convergence measure.
    pub rms_change: f64,
    /// Largest relative change (XFOIL RMXBL).
    pub max_change: f64,
}

/// Applies the Newton step `w` = (δs, δθ, δm) per station with XFOIL's relaxation.
pub fn apply_update(
    model: &BlModel,
    coupling: &Coupling<'_>,
    state: &mut BlState,
    w: &[[f64; 3]],
    mismatch: &[f64],
    limits: &UpdateLimits,
) -> Result<UpdateResult, ViscousError> {
    let due = edge_speed_change(coupling.dv, w, mismatch);
    apply_step(model, coupling.layout, state, w, &due, limits)
}

/// Edge-speed change of a step `w` = (δs, δθ, δm): δUe = e + Dv·δm, with e the change the
/// step makes at fixed mass defects (the mismatch of a Newton step).
pub fn edge_speed_change(dv: &[f64], w: &[[f64; 3]], e: &[f64]) -> Vec<f64> {
    let dm: Vec<f64> = w.iter().map(|x| x[2]).collect();
    let mut due = mat_vec(dv, &dm);
    for (d, e) in due.iter_mut().zip(e) {
        *d += e;
    }
    due
}

/// Applies the step `w` = (δs, δθ, δm) with the edge-speed change `due` per station, under
/// XFOIL's relaxation and clipping (UPDATE, DSLIM).
pub fn apply_step(
    model: &BlModel,
    layout: &StationLayout,
    state: &mut BlState,
    w: &[[f64; 3]],
    due: &[f64],
    limits: &UpdateLimits,
) -> Result<UpdateResult, ViscousError> {
    let n = state.len();
    let mut rlx: f64 = 1.0;
    let mut sumsq = 0.0;
    let mut max_change: f64 = 0.0;
    // First turbulent station of each airfoil surface, if its √Cτ decrease is clipped.
    let first_turbulent = [Surface::Upper, Surface::Lower].map(|surface| {
        limits
            .clip_first_turbulent
            .then(|| layout.range(surface).find(|&k| state.turbulent[k]))
            .flatten()
    });
    let clipped = |k: usize| first_turbulent.contains(&Some(k));
    for k in 0..n {
        let [ds, dth, dmk] = w[k];
        let u = state.ue[k];
        let dstar = state.dstar(k);
        let ddstar = (dmk - dstar * due[k]) / u;
        let dn1 = if state.turbulent[k] || layout.stations[k].surface == Surface::Wake {
            ds / state.s[k].max(1e-7)
        } else {
            ds / limits.n_scale
        };
        let dn2 = dth / state.theta[k];
        let dn3 = ddstar / dstar;
        let dn4 = due[k].abs() / limits.ue_scale;
        for (i, dn) in [dn1, dn2, dn3, dn4].into_iter().enumerate() {
            if !dn.is_finite() {
                return Err(ViscousError::NonFinite { station: k });
            }
            sumsq += dn * dn;
            max_change = max_change.max(dn.abs());
            if i == 0 && dn < 0.0 && clipped(k) {
                continue;
            }
            if rlx * dn > limits.dhi {
                rlx = limits.dhi / dn;
            }
            if rlx * dn < limits.dlo {
                rlx = limits.dlo / dn;
            }
        }
    }
    for k in 0..n {
        let [ds, dth, dmk] = w[k];
        let wake = layout.stations[k].surface == Surface::Wake;
        let s_old = state.s[k];
        state.s[k] += rlx * ds;
        if clipped(k) {
            state.s[k] = state.s[k].max(s_old * (1.0 + limits.dlo));
        }
        if state.turbulent[k] || wake {
            state.s[k] = state.s[k].clamp(1e-7, limits.ctau_sqrt_max);
        } else {
            state.s[k] = state.s[k].max(0.0);
        }
        state.theta[k] += rlx * dth;
        state.mass[k] += rlx * dmk;
        state.ue[k] += rlx * due[k];
        // Shape-factor floor (XFOIL DSLIM): raise δ* so that the unclamped
        // Hk = (H − 0.29 Me²)/(1 + 0.113 Me²) (Whitfield, XFOIL HKIN) is at least Hk_min.
        let hk_min = limits.hk_floor(wake);
        let v = state.vars(layout, k);
        let hk = model.kinematic_shape(&v);
        if hk.value < hk_min && hk.d[1] > 0.0 {
            state.mass[k] = (v.dstar + (hk_min - hk.value) / hk.d[1]) * state.ue[k];
        }
        if !(state.theta[k].is_finite() && state.mass[k].is_finite() && state.ue[k].is_finite())
            || state.theta[k] <= 0.0
        {
            return Err(ViscousError::NonFinite { station: k });
        }
    }
    Ok(UpdateResult {
        rlx,
        rms_change: (sumsq / (4 * n.max(1)) as f64).sqrt(),
        max_change,
    })
}

#[cfg(test)]
mod tests;
