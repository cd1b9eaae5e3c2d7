//! The boundary-layer equations as the coupling sees them: the discrete equations of one
//! interval, the similarity station, transition intervals, the trailing-edge junction and the
//! station post-processing (the decomposition of XFOIL xblsys.f BLSYS/TRDIF/TESYS).
//!
//! The global Newton solve is written against the [`BoundaryLayerModel`] trait so that it only
//! depends on this small surface; the XFOIL-class closures of `crate::boundary_layer` implement it
//! (see `xfoil_bl.rs`).
//!
//! Sign convention: every `res` is the residual f(vars) itself (XFOIL's VSREZ is −f); the Newton
//! step solves `d1·δ1 + d2·δ2 = −res`. Jacobian columns are ordered (s, θ, δ*, u, ξ) as XFOIL's
//! VS1/VS2 columns 1..5.

use super::error::ViscousError;

/// Station variables, flow regime and interval equations are the boundary-layer layer's own
/// types: the coupling works on exactly what the closures take and return.
pub use crate::boundary_layer::{
    DownstreamEquations, IntervalEquations, Regime, StationVars, UpstreamStation,
};

/// An interval in which the layer becomes turbulent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TransitionInterval {
    /// Combined laminar-part + turbulent-part equations (XFOIL TRDIF).
    pub equations: IntervalEquations,
    /// ξ of the transition point.
    pub xi_transition: f64,
    /// True if forced (trip), false if free (e^n).
    pub forced: bool,
}

/// Equations of the first wake station from both trailing-edge stations (XFOIL TESYS).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct JunctionEquations {
    /// Residuals of the √Cτ, θ and δ* junction conditions.
    pub res: [f64; 3],
    /// ∂f/∂(upper TE station variables).
    pub d_upper: [[f64; 5]; 3],
    /// ∂f/∂(lower TE station variables).
    pub d_lower: [[f64; 5]; 3],
    /// ∂f/∂(first wake station variables).
    pub d_wake: [[f64; 5]; 3],
}

/// Derived quantities of one station for distributions and force integration.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct StationProperties {
    /// Skin-friction coefficient based on the edge dynamic pressure.
    pub cf: f64,
    /// Shape factor H = δ*/θ (δ* without the wake gap).
    pub h: f64,
    /// Kinematic shape factor Hk.
    pub hk: f64,
    /// Compressible edge speed / V∞.
    pub ue_compressible: f64,
    /// Edge density / ρ∞.
    pub rho_e: f64,
    /// Edge Mach number squared.
    pub mach_edge_sq: f64,
    /// Kinematic shape factor sensitivities ∂Hk/∂(θ, δ*, u).
    pub hk_d: [f64; 3],
}

/// The boundary-layer physics needed by the viscous–inviscid coupling.
pub trait BoundaryLayerModel {
    /// Similarity-station equations (XFOIL SIMI: station 1 = station 2); the Jacobian w.r.t. the
    /// station is `d1 + d2`.
    fn similarity(&self, st: &StationVars) -> Result<IntervalEquations, ViscousError>;

    /// Equations of an interval without transition (XFOIL BLDIF).
    fn interval(
        &self,
        regime: Regime,
        st1: &StationVars,
        st2: &StationVars,
    ) -> Result<IntervalEquations, ViscousError> {
        self.interval_from(regime, &UpstreamStation::new(st1, regime), st2)
    }

    /// [`BoundaryLayerModel::interval`] from an upstream station whose secondary variables are
    /// kept between calls (the local iterations of a march vary station 2 only).
    fn interval_from(
        &self,
        regime: Regime,
        st1: &UpstreamStation,
        st2: &StationVars,
    ) -> Result<IntervalEquations, ViscousError>;

    /// [`BoundaryLayerModel::interval_from`] with the Jacobian of station 2 only (the local
    /// iterations of a march); [`BoundaryLayerModel::complete_interval`] adds station 1's.
    fn interval_downstream(
        &self,
        regime: Regime,
        st1: &UpstreamStation,
        st2: &StationVars,
    ) -> Result<DownstreamEquations, ViscousError>;

    /// The full equations of an interval evaluated by
    /// [`BoundaryLayerModel::interval_downstream`] from the same upstream station.
    fn complete_interval(
        &self,
        st1: &UpstreamStation,
        eq: &DownstreamEquations,
    ) -> Result<IntervalEquations, ViscousError>;

    /// Transition check of a laminar interval (XFOIL TRCHEK2 + TRDIF): `Some` if free (N reaches
    /// Ncrit) or forced transition (`xi_forced`) happens inside, whichever is earlier.
    fn transition(
        &self,
        st1: &StationVars,
        st2: &StationVars,
        xi_forced: Option<f64>,
    ) -> Result<Option<TransitionInterval>, ViscousError> {
        self.transition_from(&UpstreamStation::new(st1, Regime::Laminar), st2, xi_forced)
    }

    /// [`BoundaryLayerModel::transition`] from an upstream station whose secondary variables
    /// are kept between calls.
    fn transition_from(
        &self,
        st1: &UpstreamStation,
        st2: &StationVars,
        xi_forced: Option<f64>,
    ) -> Result<Option<TransitionInterval>, ViscousError>;

    /// Trailing-edge junction equations for the first wake station (XFOIL TESYS).
    fn junction(
        &self,
        upper: &StationVars,
        lower: &StationVars,
        wake: &StationVars,
        ante: f64,
    ) -> Result<JunctionEquations, ViscousError>;

    /// Post-processing quantities of one station.
    fn properties(
        &self,
        regime: Regime,
        st: &StationVars,
    ) -> Result<StationProperties, ViscousError>;

    /// Unclamped kinematic shape factor Hk = (H − 0.29 Me²)/(1 + 0.113 Me²) (Whitfield; XFOIL
    /// HKIN) with H = (δ* − dw)/θ, and its derivatives with respect to (θ, δ*, u).
    fn kinematic_shape_factor(&self, st: &StationVars) -> (f64, [f64; 3]);

    /// Squire–Young drag coefficient from the last wake station (XFOIL CDCALC).
    fn squire_young(&self, last: &StationVars) -> Result<f64, ViscousError>;

    /// Shape factor limits for the initial march: (laminar, turbulent) Hk above which the
    /// march switches to inverse mode (XFOIL MRCHUE HLMAX = 3.8, HTMAX = 2.5).
    fn march_hk_limits(&self) -> (f64, f64) {
        (3.8, 2.5)
    }

    /// Critical amplification ratio.
    fn ncrit(&self) -> f64;
}
