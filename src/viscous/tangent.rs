//! Tangent (Euler) predictor along α, the predictor of a predictor–corrector continuation
//! (Allgower & Georg, "Numerical Continuation Methods", 1990, ch. 2; not in XFOIL, which
//! starts each α from the previous converged state).
//!
//! α enters the viscous residuals R through the stations' inviscid edge speed
//! Ue_inv(α) = cos α·Ue⁰ + sin α·Ue⁹⁰ (the unit solutions, XFOIL QISET/UICALC). The Newton
//! system eliminates Ue = Ue_inv + Dv·m, so a change of Ue_inv acts like an edge-speed mismatch
//! (XFOIL's DUE terms): the state's derivative along the unit direction k solves
//! J·t_k = −(∂R/∂Ue)·Ue^k, with J the Newton matrix already factored in the converged point's
//! last iteration; the stagnation point moves with it through the ξ terms of J. The predicted
//! start of α₁ is the relaxed step (cos α₁ − cos α₀)·t₀ + (sin α₁ − sin α₀)·t₉₀ — the
//! first Newton step from the converged state at α₁, without a new assembly and factorisation.
//!
//! Neglected: the wake's dependence on α (it is re-traced at every α, which moves the wake
//! stations, their ξ and inviscid speeds and the source influence Dv), the change of J between
//! the last Newton iteration and the converged state, and terms of second order in Δα. The
//! corrector iterations at α₁ absorb them.

use super::block_solver::FactoredSystem;
use super::error::ViscousError;
use super::state::BlState;
use super::stations::StationLayout;
use super::update::{apply_step, edge_speed_change, UpdateLimits, UpdateResult};
use crate::boundary_layer::BlModel;

/// Derivatives of a converged state with respect to the cosine and sine of α.
#[derive(Clone, Debug)]
pub struct Tangent {
    /// α of the converged state, degrees.
    alpha_deg: f64,
    /// (δs, δθ, δm) per station for a unit change of cos α and of sin α.
    step: [Vec<[f64; 3]>; 2],
    /// The edge-speed changes that go with them, δUe = Ue^k + Dv·δm.
    due: [Vec<f64>; 2],
}

impl Tangent {
    /// The tangent of the state converged at `alpha_deg` from the factored Newton matrix of
    /// its last iteration, with `ue_unit` the inviscid edge speeds of the α = 0° and 90° unit
    /// solutions per station and `dv` the edge-speed influence of the mass defects.
    pub fn new(
        system: &FactoredSystem<'_, '_>,
        ue_unit: &[Vec<f64>; 2],
        dv: &[f64],
        alpha_deg: f64,
    ) -> Result<Self, ViscousError> {
        let mut step = [Vec::new(), Vec::new()];
        let mut due = [Vec::new(), Vec::new()];
        for k in 0..2 {
            let rhs: Vec<[f64; 3]> = system
                .edge_speed_terms(&ue_unit[k])
                .iter()
                .map(|r| r.map(|v| -v))
                .collect();
            step[k] = system.solve(&rhs)?;
            due[k] = edge_speed_change(dv, &step[k], &ue_unit[k]);
        }
        Ok(Self {
            alpha_deg,
            step,
            due,
        })
    }

    /// The tangent step to `alpha_deg`: (δs, δθ, δm) and δUe per station.
    fn linear_step(&self, alpha_deg: f64) -> (Vec<[f64; 3]>, Vec<f64>) {
        let (s0, c0) = self.alpha_deg.to_radians().sin_cos();
        let (s1, c1) = alpha_deg.to_radians().sin_cos();
        let f = [c1 - c0, s1 - s0];
        let w: Vec<[f64; 3]> = self.step[0]
            .iter()
            .zip(&self.step[1])
            .map(|(a, b)| std::array::from_fn(|i| f[0] * a[i] + f[1] * b[i]))
            .collect();
        let due: Vec<f64> = self.due[0]
            .iter()
            .zip(&self.due[1])
            .map(|(a, b)| f[0] * a + f[1] * b)
            .collect();
        (w, due)
    }

    /// Moves `state` (converged at the tangent's α, on `layout`) to its prediction at
    /// `alpha_deg`, relaxed and clipped like a Newton update.
    pub fn predict(
        &self,
        model: &BlModel,
        layout: &StationLayout,
        state: &mut BlState,
        alpha_deg: f64,
        limits: &UpdateLimits,
    ) -> Result<UpdateResult, ViscousError> {
        let (w, due) = self.linear_step(alpha_deg);
        apply_step(model, layout, state, &w, &due, limits)
    }
}
