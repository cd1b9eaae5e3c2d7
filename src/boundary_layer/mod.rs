//! Integral boundary layer (Drela & Giles 1987; Drela 1989): closures with their partial
//! derivatives, e^n amplification and transition, and the discrete equations of one interval.
//!
//! The decomposition follows XFOIL 6.99 xblsys.f so the viscous coupling (XFOIL SETBL) can
//! be assembled from these pieces:
//! * [`StationVars`] — primary variables of a station (BLPRV): ξ, incompressible Ue, θ, δ*,
//!   N or √Cτ, wake gap.
//! * [`BlModel::interval`] / [`BlModel::similarity`] — the three equations of an interval
//!   (BLSYS/BLDIF) with Jacobians in the column order (s, θ, δ*, u, ξ).
//! * [`BlModel::interval_downstream`] / [`BlModel::complete_interval`] — the same equations in
//!   two parts for a march's local iterations: station 2's Jacobian, then station 1's.
//! * [`BlModel::amplification_check`] / [`BlModel::transition_interval`] — implicit transition
//!   inside an interval (TRCHEK2) and the combined laminar + turbulent equations (TRDIF).
//! * [`BlModel::te_junction`] — first wake station from the two trailing-edge stations (TESYS).
//! * [`BlModel::squire_young`] — drag from the last wake station (CDCALC).
//! * [`BlModel::properties`] — Cf, H, Hk, Re_θ, … of a station for output.
//! * [`BlModel::kinematic_shape`] — Hk with its sensitivities (inverse march).
//! * [`BlModel::stagnation_guess`] — Thwaites starting values for the similarity station.
//!
//! Residual convention: R itself (XFOIL's VSREZ is −R); Newton solves J·Δ = −R.
//!
//! ```
//! use polargen::boundary_layer::{BlConditions, BlModel, BlParams, Regime, StationVars};
//!
//! let model = BlModel::new(
//!     &BlConditions { reynolds: 1.9e6, mach: 0.41, ncrit: 9.0 },
//!     BlParams::default(),
//! )?;
//! // two turbulent stations: ξ, incompressible Ue, θ, δ*, √Cτ, wake gap
//! let st1 = StationVars { x: 0.50, u: 1.10, theta: 1.0e-3, dstar: 1.5e-3, s: 0.07, dw: 0.0 };
//! let st2 = StationVars { x: 0.52, u: 1.09, theta: 1.05e-3, dstar: 1.6e-3, s: 0.07, dw: 0.0 };
//! let eq = model.interval(Regime::Turbulent, &st1, &st2)?;
//! // rows: shear-lag, momentum, shape; columns (s, θ, δ*, u, ξ)
//! assert!(eq.d2[1][1] > 0.0); // momentum residual grows with θ2
//! let cf = model.properties(&st2, Regime::Turbulent)?.cf;
//! assert!(cf > 0.002 && cf < 0.005);
//! # Ok::<(), polargen::boundary_layer::BlError>(())
//! ```

pub mod amplification;
pub mod closures;
mod equations;
mod params;
mod station;
mod trailing_edge;
mod transition;

pub use equations::{DownstreamEquations, IntervalEquations};
pub use params::{BlConditions, BlParams, FlowConstants, Regime};
pub use station::{StationProperties, StationVars};
pub use trailing_edge::{SquireYoung, TeJunction};
pub use transition::{AmplificationCheck, TransitionInterval, TransitionKind};

use equations::{bldif, DiffKind};

/// Number of independent variables of one interval: (s, θ, δ*, u, ξ) of station 1 in gradient
/// slots 0..5 and of station 2 in slots 5..10, the column order of XFOIL's VS1/VS2 matrices
/// (xblsys.f BLSYS). A station's secondary variables depend on its own (s, θ, δ*, u) only, not
/// on ξ; they are computed with 4-slot numbers and then embedded, ξ getting a slot of its own.
pub(crate) const NVARS: usize = 10;

/// Derivative numbers over the variables of one interval (by default) or of fewer.
pub(crate) type Dual<const N: usize = NVARS> = crate::numerics::dual::Dual<N>;
use std::cell::OnceCell;

use crate::compressibility::{MachOutOfRange, GAMMA_MINUS_ONE};

use station::{validate, Station};

/// Errors of the boundary-layer routines.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BlError {
    /// The Reynolds number is not a positive finite number.
    #[error("boundary layer: Reynolds number {0} is not positive and finite")]
    Reynolds(f64),
    /// The Mach number is outside [0, 1).
    #[error("boundary layer: {0}")]
    Mach(#[source] MachOutOfRange),
    /// The critical amplification factor is not positive.
    #[error("boundary layer: Ncrit {0} is not positive and finite")]
    Ncrit(f64),
    /// A station variable is out of its valid range.
    #[error("boundary layer: station {what} = {value} is out of range")]
    Station {
        /// Which variable.
        what: &'static str,
        /// Its value.
        value: f64,
    },
    /// The equations produced a non-finite value (variables far outside the closures' range).
    #[error("boundary layer: non-finite {0} (station variables outside the closures' range)")]
    NonFinite(&'static str),
    /// The interval does not advance downstream.
    #[error("boundary layer: interval xi1 = {x1} to xi2 = {x2} does not advance downstream")]
    Interval {
        /// ξ of station 1.
        x1: f64,
        /// ξ of station 2.
        x2: f64,
    },
}

/// Station 1 of an interval with its secondary variables (XFOIL BLPRV → BLKIN → BLVAR)
/// evaluated on first use and kept, so that the intervals of a march's local Newton
/// iterations, which vary only station 2, do not re-evaluate the closures of the fixed upstream
/// station. Built for one regime; the laminar one also serves the transition check.
#[derive(Clone, Debug)]
pub struct UpstreamStation {
    vars: StationVars,
    regime: Regime,
    valid: Result<(), BlError>,
    /// With derivatives with respect to its own variables (s, θ, δ*, u) at fixed ξ.
    own: OnceCell<Station<4>>,
    /// Values with four zero derivative slots (station 1 of a station-2-only evaluation).
    frozen: OnceCell<Station<4>>,
    /// Seeded in the station-1 slots of an interval (0..5).
    seeded: OnceCell<Station>,
    /// Values with one zero derivative slot (the transition check's fixed station 1).
    constant: OnceCell<Station<1>>,
    // `frozen`, `seeded` and `constant` are all taken from `own`: the closures are evaluated
    // once per station (values do not depend on the number of derivative slots).
}

impl UpstreamStation {
    /// Station 1 with primary variables `vars`, evaluated with the closures of `regime`.
    pub fn new(vars: &StationVars, regime: Regime) -> Self {
        Self {
            vars: *vars,
            regime,
            valid: validate(vars, regime),
            own: OnceCell::new(),
            frozen: OnceCell::new(),
            seeded: OnceCell::new(),
            constant: OnceCell::new(),
        }
    }

    /// The primary variables.
    pub fn vars(&self) -> &StationVars {
        &self.vars
    }

    /// The regime whose closures the station is evaluated with.
    pub fn regime(&self) -> Regime {
        self.regime
    }

    pub(crate) fn own(&self, model: &BlModel) -> &Station<4> {
        self.own
            .get_or_init(|| Station::own(&self.vars, self.regime, &model.flow, &model.params))
    }

    pub(crate) fn frozen(&self, model: &BlModel) -> &Station<4> {
        self.frozen.get_or_init(|| self.own(model).frozen())
    }

    pub(crate) fn seeded(&self, model: &BlModel) -> &Station {
        self.seeded.get_or_init(|| self.own(model).embed(0))
    }

    pub(crate) fn constant(&self, model: &BlModel) -> &Station<1> {
        self.constant.get_or_init(|| self.own(model).frozen())
    }
}

/// Station 1 evaluated with the closures of `regime`: `up` itself, or a copy stored in `other`
/// if `up` was built for another regime.
fn in_regime<'a>(
    regime: Regime,
    up: &'a UpstreamStation,
    other: &'a mut Option<UpstreamStation>,
) -> &'a UpstreamStation {
    if up.regime == regime {
        up
    } else {
        other.insert(UpstreamStation::new(&up.vars, regime))
    }
}

/// [`in_regime`] after checking both stations and that the interval advances.
fn checked_upstream<'a>(
    regime: Regime,
    up: &'a UpstreamStation,
    other: &'a mut Option<UpstreamStation>,
    v2: &StationVars,
) -> Result<&'a UpstreamStation, BlError> {
    let up = in_regime(regime, up, other);
    up.valid.clone()?;
    validate(v2, regime)?;
    check_advance(&up.vars, v2)?;
    Ok(up)
}

/// Checks that station 2 lies strictly downstream of station 1.
pub(crate) fn check_advance(v1: &StationVars, v2: &StationVars) -> Result<(), BlError> {
    if v2.x.partial_cmp(&v1.x) == Some(std::cmp::Ordering::Greater) {
        Ok(())
    } else {
        Err(BlError::Interval { x1: v1.x, x2: v2.x })
    }
}

/// Rejects equations with non-finite residuals or Jacobian entries.
pub(crate) fn check_finite(
    eq: IntervalEquations,
    what: &'static str,
) -> Result<IntervalEquations, BlError> {
    let all = eq
        .res
        .iter()
        .chain(eq.d1.iter().flatten())
        .chain(eq.d2.iter().flatten());
    if all.into_iter().all(|v| v.is_finite()) {
        Ok(eq)
    } else {
        Err(BlError::NonFinite(what))
    }
}

/// Boundary-layer model for one flow condition: closure constants plus the derived
/// compressibility constants. Cheap to copy; holds no mutable state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlModel {
    /// Closure and shear-lag constants.
    pub params: BlParams,
    /// Compressibility/Reynolds constants derived from the flow conditions.
    pub flow: FlowConstants,
}

impl BlModel {
    /// Model for the given flow conditions and constants (validates the conditions).
    pub fn new(cond: &BlConditions, params: BlParams) -> Result<Self, BlError> {
        Ok(Self {
            flow: FlowConstants::new(cond, &params)?,
            params,
        })
    }

    /// Secondary station variables seeded in the slots of station 1 (offset 0) or 2 (5).
    pub(crate) fn station(
        &self,
        v: &StationVars,
        offset: Option<usize>,
        regime: Regime,
    ) -> Station {
        Station::seeded(v, offset, regime, &self.flow, &self.params)
    }

    /// Equations of the interval from station 1 to station 2 in the given regime (XFOIL
    /// BLSYS → BLDIF(1|2|3)): amplification (laminar) or shear-lag (turbulent/wake),
    /// momentum and shape-parameter equations with Jacobians (see [`IntervalEquations`]).
    /// Both stations are evaluated with the closures of `regime`. Transition intervals go
    /// through [`BlModel::transition_interval`] instead.
    pub fn interval(
        &self,
        regime: Regime,
        v1: &StationVars,
        v2: &StationVars,
    ) -> Result<IntervalEquations, BlError> {
        self.interval_from(regime, &UpstreamStation::new(v1, regime), v2)
    }

    /// [`BlModel::interval`] with station 1 given as an [`UpstreamStation`], whose secondary
    /// variables are evaluated once and reused by every interval that starts there (the local
    /// Newton iterations of a march vary station 2 only).
    pub fn interval_from(
        &self,
        regime: Regime,
        up: &UpstreamStation,
        v2: &StationVars,
    ) -> Result<IntervalEquations, BlError> {
        let mut other = None;
        let up = checked_upstream(regime, up, &mut other, v2)?;
        let s1 = up.seeded(self);
        let s2 = self.station(v2, Some(5), regime);
        check_finite(
            IntervalEquations::from_duals(&bldif(
                DiffKind::of(regime),
                s1,
                &s2,
                &self.flow,
                &self.params,
            )),
            "interval equations",
        )
    }

    /// [`BlModel::interval_from`] without the station-1 Jacobian, for the local iterations of a
    /// march, which vary station 2 alone; [`BlModel::complete_interval`] adds it for the
    /// iteration whose equations are kept. About half the cost of an evaluation with both
    /// Jacobians, and bit-identical to it (see [`DownstreamEquations`]).
    pub fn interval_downstream(
        &self,
        regime: Regime,
        up: &UpstreamStation,
        v2: &StationVars,
    ) -> Result<DownstreamEquations, BlError> {
        let mut other = None;
        let up = checked_upstream(regime, up, &mut other, v2)?;
        let station = Station::<4>::own(v2, regime, &self.flow, &self.params);
        let r = bldif(
            DiffKind::of(regime),
            up.frozen(self),
            &station,
            &self.flow,
            &self.params,
        );
        let res = r.map(|d| d.v);
        let d2 = r.map(|d| d.g);
        if res.iter().chain(d2.iter().flatten()).all(|v| v.is_finite()) {
            Ok(DownstreamEquations {
                res,
                d2,
                regime,
                station: station.frozen(),
            })
        } else {
            Err(BlError::NonFinite("interval equations"))
        }
    }

    /// The full equations of an interval evaluated by [`BlModel::interval_downstream`] from
    /// the same upstream station: adds the station-1 Jacobian (station 1 seeded, station 2
    /// held fixed) and the ξ column of station 2's (slot 5, the only station-2 variable
    /// seeded), bit-identical to an evaluation of both Jacobians at once.
    pub fn complete_interval(
        &self,
        up: &UpstreamStation,
        eq: &DownstreamEquations,
    ) -> Result<IntervalEquations, BlError> {
        let mut other = None;
        let up = in_regime(eq.regime, up, &mut other);
        let r = bldif(
            DiffKind::of(eq.regime),
            &up.own(self).embed::<6>(0),
            &eq.station.frozen_but_xi::<6>(5),
            &self.flow,
            &self.params,
        );
        let d2 = std::array::from_fn(|i| {
            let [ds, dt, dd, du] = eq.d2[i];
            [ds, dt, dd, du, r[i].g[5]]
        });
        check_finite(
            IntervalEquations {
                res: eq.res,
                d1: r.map(|d| d.slots(0)),
                d2,
            },
            "interval equations",
        )
    }

    /// Equations of the similarity (stagnation-point) station (XFOIL BLSYS with SIMI,
    /// BLDIF(0)): stations 1 and 2 coincide, the log-differences are those of stagnation
    /// flow (d ln Ue/d ln ξ = BULE = 1), and row 0 sets N = 0. The Jacobian is returned in
    /// `d2` (`d1` is zero), as XFOIL sums VS1 into VS2.
    pub fn similarity(&self, v: &StationVars) -> Result<IntervalEquations, BlError> {
        validate(v, Regime::Laminar)?;
        let s = self.station(v, Some(5), Regime::Laminar);
        check_finite(
            IntervalEquations::from_duals(&bldif(
                DiffKind::Similarity,
                &s,
                &s,
                &self.flow,
                &self.params,
            )),
            "similarity equations",
        )
    }

    /// Boundary-layer quantities of one station in the given regime, for output
    /// (Cf, H, Hk, Re_θ, H*, CD, …; XFOIL BLKIN/BLVAR values).
    pub fn properties(
        &self,
        v: &StationVars,
        regime: Regime,
    ) -> Result<StationProperties, BlError> {
        validate(v, regime)?;
        let p = StationProperties::from_station(&self.station(v, None, regime));
        if [p.cf, p.h_star, p.re_theta, p.cd, p.hk]
            .iter()
            .all(|x| x.is_finite())
        {
            Ok(p)
        } else {
            Err(BlError::NonFinite("station properties"))
        }
    }

    /// Kinematic shape parameter Hk = (H − 0.29 Me²)/(1 + 0.113 Me²) of a station (Whitfield's
    /// correlation as in XFOIL HKIN, without the regime's lower clamp; H = (δ* − dw)/θ, Me² from
    /// the Kármán–Tsien edge speed as in XFOIL BLPRV/BLKIN), with ∂Hk/∂(θ, δ*, u) (u
    /// incompressible, δ* total). These are the sensitivities XFOIL's inverse marches
    /// (MRCHUE, MRCHDU) use to drive Hk to a target; derived by hand because the march
    /// evaluates Hk in every local iteration. Hk is the station's own unclamped value to the
    /// last bit (the edge speed is the station's). Unchecked: a non-physical station gives a
    /// non-finite Hk, which the callers test.
    pub fn kinematic_shape(&self, v: &StationVars) -> closures::Partials<3> {
        let f = &self.flow;
        // Kármán–Tsien compressible edge speed and its derivative (XFOIL BLPRV).
        let uc = f.karman_tsien.speed_of(Dual::<1>::variable(v.u, 0));
        let (uc, uc_u) = (uc.v, uc.g[0]);
        // Edge Mach number squared (XFOIL BLKIN).
        let (gm1, hstinv) = (GAMMA_MINUS_ONE, f.inverse_stagnation_enthalpy);
        let a = uc * uc * hstinv;
        let msq = a / (gm1 * (1.0 - 0.5 * a));
        let msq_u = 2.0 * uc * hstinv * uc_u / (gm1 * (1.0 - 0.5 * a) * (1.0 - 0.5 * a));
        let h = (v.dstar - v.dw) / v.theta;
        let d = 1.0 + 0.113 * msq;
        let hk = (h - 0.29 * msq) / d;
        let hk_h = 1.0 / d;
        let hk_msq = (-0.29 * d - 0.113 * (h - 0.29 * msq)) / (d * d);
        closures::Partials {
            value: hk,
            d: [-hk_h * h / v.theta, hk_h / v.theta, hk_msq * msq_u],
        }
    }

    /// Starting guess (θ, δ*) for the similarity station at ξ with edge speed `u` from
    /// Thwaites' method, θ² = 0.45/(C·(5m + 1)·Re)·ξ^(1−m) with Ue = C·ξ^m, m = BULE, and
    /// δ* = 2.2θ (XFOIL xbl.f MRCHUE initialisation). Re is the boundary layer's Reynolds
    /// number, the one based on the stagnation viscosity (XFOIL REYBL), as in XFOIL.
    pub fn stagnation_guess(&self, x: f64, u: f64) -> Result<(f64, f64), BlError> {
        for (what, value) in [("xi", x), ("edge speed", u)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(BlError::Station { what, value });
            }
        }
        let m = self.params.similarity_ue_exponent;
        let ucon = u / x.powf(m);
        let tsq = 0.45 / (ucon * (5.0 * m + 1.0) * self.flow.stagnation_reynolds) * x.powf(1.0 - m);
        let theta = tsq.sqrt();
        Ok((theta, 2.2 * theta))
    }
}
