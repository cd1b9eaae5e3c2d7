//! The boundary-layer state of all stations: the Newton unknowns (√Cτ or N, θ, mass defect m)
//! and the edge speed, stored per station in system order (XFOIL's CTAU, THET, MASS, UEDG).

use super::stations::{StationLayout, Surface};
use crate::boundary_layer::{Regime, StationVars};

/// Boundary-layer state per station, system order of a [`StationLayout`].
#[derive(Clone, Debug, Default)]
pub struct BlState {
    /// √Cτ (turbulent/wake) or N (laminar).
    pub s: Vec<f64>,
    /// Momentum thickness θ.
    pub theta: Vec<f64>,
    /// Mass defect m = Ue·δ* (δ* including the wake gap).
    pub mass: Vec<f64>,
    /// Edge speed Ue/V∞ (incompressible, positive downstream).
    pub ue: Vec<f64>,
    /// Whether the station is turbulent (wake stations always are).
    pub turbulent: Vec<bool>,
}

impl BlState {
    /// A zero state with `n` stations.
    pub fn zeros(n: usize) -> Self {
        Self {
            s: vec![0.0; n],
            theta: vec![0.0; n],
            mass: vec![0.0; n],
            ue: vec![0.0; n],
            turbulent: vec![false; n],
        }
    }

    /// Number of stations.
    pub fn len(&self) -> usize {
        self.theta.len()
    }

    /// Displacement thickness δ* = m/Ue of station k (including the wake gap).
    pub fn dstar(&self, k: usize) -> f64 {
        self.mass[k] / self.ue[k]
    }

    /// Primary variables of station k for the boundary-layer equations.
    pub fn vars(&self, layout: &StationLayout, k: usize) -> StationVars {
        let st = &layout.stations[k];
        StationVars {
            x: st.xi,
            u: self.ue[k],
            theta: self.theta[k],
            dstar: self.dstar(k),
            s: self.s[k],
            dw: st.wake_gap,
        }
    }

    /// Regime of station k.
    pub fn regime(&self, layout: &StationLayout, k: usize) -> Regime {
        if layout.stations[k].surface == Surface::Wake {
            Regime::Wake
        } else if self.turbulent[k] {
            Regime::Turbulent
        } else {
            Regime::Laminar
        }
    }

    /// Carries a state over to a new layout (XFOIL STMOVE): `map[k]` is the old station whose
    /// values initialise new station k (see [`StationLayout::map_from`]). The mass defect is kept
    /// and the edge speed taken from `ue_new` where the station changed surface.
    pub fn remap(&self, map: &[usize], old: &StationLayout, new: &StationLayout) -> Self {
        let n = map.len();
        let mut out = Self::zeros(n);
        for (k, &o) in map.iter().enumerate() {
            out.s[k] = self.s[o];
            out.theta[k] = self.theta[o];
            out.ue[k] = self.ue[o];
            out.mass[k] = self.mass[o];
            out.turbulent[k] = self.turbulent[o];
            if old.stations[o].node != new.stations[k].node {
                // A node that crossed the stagnation point: similarity-like values of the first
                // station, with its own (small) edge speed kept positive.
                out.turbulent[k] = false;
            }
        }
        out
    }
}
