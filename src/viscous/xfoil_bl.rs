//! [`BoundaryLayerModel`] implemented by the XFOIL-class integral boundary layer of
//! `crate::boundary_layer` (closures of Drela & Giles 1987 / Drela 1989 as in XFOIL 6.99).

use crate::boundary_layer as bl;

use super::bl_model::{
    BoundaryLayerModel, DownstreamEquations, IntervalEquations, JunctionEquations, Regime,
    StationProperties, StationVars, TransitionInterval, UpstreamStation,
};
use super::error::ViscousError;

/// The XFOIL-class boundary layer for one flow condition.
#[derive(Clone, Copy, Debug)]
pub struct XfoilBoundaryLayer {
    /// The boundary-layer model (closure constants + compressibility constants).
    pub model: bl::BlModel,
}

impl XfoilBoundaryLayer {
    /// Model for Reynolds number, Mach number and Ncrit with XFOIL's default closure constants.
    pub fn new(reynolds: f64, mach: f64, ncrit: f64) -> Result<Self, ViscousError> {
        let cond = bl::BlConditions {
            reynolds,
            mach,
            ncrit,
        };
        let model = bl::BlModel::new(&cond, bl::BlParams::default()).map_err(err(usize::MAX))?;
        Ok(Self { model })
    }
}

fn err(station: usize) -> impl Fn(bl::BlError) -> ViscousError {
    move |e| ViscousError::BoundaryLayer {
        station,
        message: e.to_string(),
    }
}

impl BoundaryLayerModel for XfoilBoundaryLayer {
    fn similarity(&self, st: &StationVars) -> Result<IntervalEquations, ViscousError> {
        self.model.similarity(st).map_err(err(usize::MAX))
    }

    fn interval_from(
        &self,
        regime: Regime,
        st1: &UpstreamStation,
        st2: &StationVars,
    ) -> Result<IntervalEquations, ViscousError> {
        self.model
            .interval_from(regime, st1, st2)
            .map_err(err(usize::MAX))
    }

    fn interval_downstream(
        &self,
        regime: Regime,
        st1: &UpstreamStation,
        st2: &StationVars,
    ) -> Result<DownstreamEquations, ViscousError> {
        self.model
            .interval_downstream(regime, st1, st2)
            .map_err(err(usize::MAX))
    }

    fn complete_interval(
        &self,
        st1: &UpstreamStation,
        eq: &DownstreamEquations,
    ) -> Result<IntervalEquations, ViscousError> {
        self.model
            .complete_interval(st1, eq)
            .map_err(err(usize::MAX))
    }

    fn transition_from(
        &self,
        st1: &UpstreamStation,
        st2: &StationVars,
        xi_forced: Option<f64>,
    ) -> Result<Option<TransitionInterval>, ViscousError> {
        let t = self
            .model
            .transition_from(st1, st2, xi_forced)
            .map_err(err(usize::MAX))?;
        Ok(t.map(|t| TransitionInterval {
            equations: t.eqs,
            xi_transition: t.xi_tr,
            forced: t.kind == bl::TransitionKind::Forced,
        }))
    }

    fn junction(
        &self,
        upper: &StationVars,
        lower: &StationVars,
        wake: &StationVars,
        ante: f64,
    ) -> Result<JunctionEquations, ViscousError> {
        let j = self
            .model
            .te_junction(upper, lower, wake, ante.abs())
            .map_err(err(usize::MAX))?;
        Ok(JunctionEquations {
            res: j.res,
            d_upper: j.d_upper,
            d_lower: j.d_lower,
            d_wake: j.d_wake,
        })
    }

    fn properties(
        &self,
        regime: Regime,
        st: &StationVars,
    ) -> Result<StationProperties, ViscousError> {
        let p = self.model.properties(st, regime).map_err(err(usize::MAX))?;
        let (_, hk_d) = self.kinematic_shape_factor(st);
        // Edge density from the edge Mach number, isentropic (XFOIL BLKIN: R2 = RSTBL·TR2^(−1/γ−1)).
        let gm1 = self.model.flow.gm1;
        let tr = 1.0 + 0.5 * gm1 * p.mach_edge_sq;
        let rho_e = self.model.flow.rstbl * tr.powf(-1.0 / gm1);
        Ok(StationProperties {
            cf: p.cf,
            h: p.h,
            hk: p.hk,
            ue_compressible: p.ue,
            rho_e,
            mach_edge_sq: p.mach_edge_sq,
            hk_d,
        })
    }

    fn squire_young(&self, last: &StationVars) -> Result<f64, ViscousError> {
        self.model
            .squire_young(last)
            .map(|s| s.cd)
            .map_err(err(usize::MAX))
    }

    fn kinematic_shape_factor(&self, st: &StationVars) -> (f64, [f64; 3]) {
        let hk = self.model.kinematic_shape(st);
        (hk.value, hk.d)
    }

    fn ncrit(&self) -> f64 {
        self.model.flow.ncrit
    }
}
