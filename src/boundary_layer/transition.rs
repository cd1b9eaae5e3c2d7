//! Laminar–turbulent transition inside an interval: the implicit second-order amplification
//! check (XFOIL 6.99 xblsys.f TRCHEK2, December 1994 version) and the combined equations of
//! a transition interval (XFOIL TRDIF), with derivatives through the transition point.
//!
//! The amplification equation between station 1 and the point T is
//! (N_T − N1)/(ξ_T − ξ1) = ā(1, T) (rms average of the envelope rate, XFOIL AXSET), where
//! T = 2 if N2 < Ncrit and otherwise the point where linear interpolation of N reaches
//! Ncrit; it is solved for N2 by Newton iteration. Forced transition at ξ_f wins when it lies
//! in the interval upstream of the free transition point.

use super::amplification::average_amplification_rate_d;
use super::closures::transition_ctau_factor_d;
use super::equations::{bldif, DiffKind, IntervalEquations};
use super::params::Regime;
use super::station::{compressible_speed_d, validate, Station, StationVars};
use super::{check_advance, check_finite, BlError, BlModel, UpstreamStation};
use super::{Dual, NVARS};

/// Whether transition in an interval is free (e^n) or forced (trip).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TransitionKind {
    /// N reached Ncrit inside the interval.
    Free,
    /// The prescribed transition location lies inside the interval, upstream of free
    /// transition.
    Forced,
}

/// Result of the amplification check of one laminar interval (XFOIL TRCHEK2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AmplificationCheck {
    /// Amplification factor at station 2 from the implicit equation (may exceed Ncrit).
    pub n2: f64,
    /// Transition inside the interval, if any: location ξ_tr and kind.
    pub transition: Option<(f64, TransitionKind)>,
    /// Whether the Newton iteration for N2 converged (XFOIL continues regardless).
    pub converged: bool,
}

/// Combined equations of a transition interval (XFOIL TRDIF).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TransitionInterval {
    /// Rows: 0 = shear-lag equation of the turbulent part T→2 (with √Cτ_T =
    /// CTRCON·exp(−CTRCEX/(Hk_T−1))·√Cτ_eq,T), 1 and 2 = momentum and shape-parameter
    /// equations summed over the laminar part 1→T and the turbulent part T→2. Jacobian
    /// columns: station 1 (N1, θ1, δ*1, u1, ξ1), station 2 (√Cτ2, θ2, δ*2, u2, ξ2), including
    /// the dependence of ξ_T on both stations (implicit for free transition).
    pub eqs: IntervalEquations,
    /// Transition location ξ_T.
    pub xi_tr: f64,
    /// ∂ξ_T/∂(station 1 variables).
    pub dxi_tr_d1: [f64; 5],
    /// ∂ξ_T/∂(station 2 variables) (the √Cτ2 entry is zero).
    pub dxi_tr_d2: [f64; 5],
    /// Free or forced.
    pub kind: TransitionKind,
    /// Amplification factor at station 2 from the check.
    pub n2: f64,
}

/// Laminar primaries of station 2 for the interpolation to T (compressible u, δ* − gap).
struct Primaries<const N: usize = NVARS> {
    x: Dual<N>,
    u: Dual<N>,
    t: Dual<N>,
    d: Dual<N>,
}

impl<const N: usize> Primaries<N> {
    fn new(v: &StationVars, offset: Option<usize>, model: &BlModel) -> Self {
        let var = |value: f64, k: usize| match offset {
            Some(o) => Dual::variable(value, o + k),
            None => Dual::constant(value),
        };
        Self {
            x: var(v.x, 4),
            u: compressible_speed_d(var(v.u, 3), &model.flow),
            t: var(v.theta, 1),
            d: var(v.dstar, 2) - v.dw,
        }
    }
}

/// Forced-transition fraction of the interval (XFOIL TRCHEK2 SFX): (ξ_f − ξ1)/(ξ2 − ξ1) if
/// ξ1 < ξ_f < ξ2, else 1 (a trip at or upstream of ξ1 is ignored: station 1 should already
/// be turbulent; a trip at or beyond ξ2 does not act inside the interval).
fn forced_fraction<const N: usize>(
    s1: &Station<N>,
    p2: &Primaries<N>,
    xi_forced: Option<f64>,
) -> Dual<N> {
    match xi_forced {
        Some(xf) if xf > s1.x.v && xf < p2.x.v => (xf - s1.x) / (p2.x - s1.x),
        _ => Dual::constant(1.0),
    }
}

/// Whether the trip at ξ_f lies in the interval (ξ1, ξ2] (XFOIL TRCHEK2 TRFORC).
fn trip_inside(xi_forced: Option<f64>, v1: &StationVars, v2: &StationVars) -> bool {
    matches!(xi_forced, Some(xf) if xf > v1.x && xf <= v2.x)
}

impl BlModel {
    /// Implicit amplification residual of TRCHEK2 for a trial N2 (`a2`):
    /// returns (R = N2 − N1 − ā(1,T)(ξ2 − ξ1), ξ_T, ā).
    /// Generic in the number of derivative slots: the N2 iteration needs ∂/∂N2 only (one
    /// slot), the transition-point sensitivities all ten interval variables.
    fn trchek_residual<const N: usize>(
        &self,
        s1: &Station<N>,
        p2: &Primaries<N>,
        a2: Dual<N>,
        xi_forced: Option<f64>,
    ) -> (Dual<N>, Dual<N>, Dual<N>) {
        let ncrit = self.flow.ncrit;
        let (amplt, sfa) = if a2.v <= ncrit {
            (a2, Dual::constant(1.0))
        } else {
            (Dual::constant(ncrit), (ncrit - s1.s) / (a2 - s1.s))
        };
        let sfx = forced_fraction(s1, p2, xi_forced);
        let wf2 = if sfa.v < sfx.v { sfa } else { sfx };
        let wf1 = 1.0 - wf2;
        let xt = s1.x * wf1 + p2.x * wf2;
        let tt = s1.t * wf1 + p2.t * wf2;
        let dt = s1.d * wf1 + p2.d * wf2;
        let ut = s1.u * wf1 + p2.u * wf2;
        let st = Station::from_primaries(
            xt,
            ut,
            tt,
            dt,
            amplt,
            0.0,
            Regime::Laminar,
            &self.flow,
            &self.params,
        );
        let ax = average_amplification_rate_d(s1.ax, s1.t, s1.s, st.ax, st.t, amplt, ncrit);
        let res = a2 - s1.s - ax * (p2.x - s1.x);
        (res, xt, ax)
    }

    /// Checks a laminar interval for transition (XFOIL TRCHEK2): solves the implicit
    /// amplification equation for N2 and reports the transition location if N2 ≥ Ncrit or
    /// the forced location `xi_forced` lies in (ξ1, ξ2]; the upstream one wins.
    /// `v1.s` is N1; `v2.s` is ignored.
    pub fn amplification_check(
        &self,
        v1: &StationVars,
        v2: &StationVars,
        xi_forced: Option<f64>,
    ) -> Result<AmplificationCheck, BlError> {
        let v2l = StationVars { s: 0.0, ..*v2 };
        validate(v1, Regime::Laminar)?;
        validate(&v2l, Regime::Laminar)?;
        check_advance(v1, v2)?;
        let s1 = Station::constant(v1, Regime::Laminar, &self.flow, &self.params);
        let p2 = Primaries::new(v2, None, self);
        let check = self.solve_n2(&s1, &p2, v1, v2, xi_forced);
        if check.n2.is_finite() {
            Ok(check)
        } else {
            Err(BlError::NonFinite("amplification factor"))
        }
    }

    /// Whether the interval certainly stays laminar, decided from one residual evaluation
    /// instead of the N2 iteration of [`BlModel::solve_n2`] (same outcome, a fraction of the
    /// cost on the many laminar intervals far from transition). With no trip in the interval
    /// and N2 ≤ Ncrit, T is station 2 and only the onset term of ā depends on N2, so the
    /// TRCHEK2 residual R(N2) is concave (R'' < 0). If R(Ncrit) > 0 and R'(Ncrit) > 0, R is
    /// increasing below Ncrit with its root there, and the damped Newton iteration (started
    /// below Ncrit, never stepping past a root of a concave increasing function) stays below
    /// Ncrit: no free transition.
    fn below_ncrit(
        &self,
        s1: &Station<1>,
        p2: &Primaries<1>,
        v1: &StationVars,
        v2: &StationVars,
        xi_forced: Option<f64>,
    ) -> bool {
        let ncrit = self.flow.ncrit;
        let tripped = trip_inside(xi_forced, v1, v2);
        if tripped || v1.s.is_nan() || v1.s >= ncrit {
            return false;
        }
        let (res, _, ax) = self.trchek_residual(s1, p2, Dual::variable(ncrit, 0), xi_forced);
        ax.v > 0.0 && res.v > 0.0 && res.g[0] > 0.0
    }

    /// Newton iteration of TRCHEK2 for N2 on one-slot derivative numbers (∂/∂N2); `s1` and
    /// `p2` are constants.
    fn solve_n2(
        &self,
        s1: &Station<1>,
        p2: &Primaries<1>,
        v1: &StationVars,
        v2: &StationVars,
        xi_forced: Option<f64>,
    ) -> AmplificationCheck {
        let ncrit = self.flow.ncrit;
        let dx = v2.x - v1.x;
        // initial guess from the rate at the unclipped interval
        let s2l: Station<1> = Station::constant(
            &StationVars { s: v1.s, ..*v2 },
            Regime::Laminar,
            &self.flow,
            &self.params,
        );
        let ax0 = average_amplification_rate_d(s1.ax, s1.t, s1.s, s2l.ax, s2l.t, s1.s, ncrit);
        let mut a2 = v1.s + ax0.v * dx;
        let mut converged = false;
        for _ in 0..30 {
            let (res, xt, ax) = self.trchek_residual(s1, p2, Dual::variable(a2, 0), xi_forced);
            if ax.v <= 0.0 {
                converged = true;
                break;
            }
            let res_a2 = res.g[0];
            let da2 = -res.v / res_a2;
            if !da2.is_finite() {
                break;
            }
            let dxt = xt.g[0] * da2;
            let mut rlx: f64 = 1.0;
            if rlx * (dxt / dx).abs() > 0.05 {
                rlx = 0.05 * (dx / dxt).abs();
            }
            if rlx * da2.abs() > 1.0 {
                rlx = 1.0 / da2.abs();
            }
            if da2.abs() < self.params.transition_n2_tolerance {
                converged = true;
                break;
            }
            let next = a2 + rlx * da2;
            if (a2 > ncrit && next < ncrit) || (a2 < ncrit && next > ncrit) {
                a2 = ncrit;
            } else {
                a2 = next;
            }
        }
        let (_, xt, _) = self.trchek_residual(s1, p2, Dual::constant(a2), xi_forced);
        let trfree = a2 >= ncrit;
        let trforc = trip_inside(xi_forced, v1, v2);
        let transition = match (trfree, trforc) {
            (false, false) => None,
            (true, false) => Some((xt.v, TransitionKind::Free)),
            (false, true) => Some((xi_forced.unwrap_or(xt.v), TransitionKind::Forced)),
            (true, true) => {
                let xf = xi_forced.unwrap_or(xt.v);
                if xf <= xt.v {
                    Some((xf, TransitionKind::Forced))
                } else {
                    Some((xt.v, TransitionKind::Free))
                }
            }
        };
        AmplificationCheck {
            n2: a2,
            transition,
            converged,
        }
    }

    /// Equations of a transition interval (XFOIL TRCHEK2 + TRDIF): station 1 is laminar
    /// (`v1.s` = N1), station 2 turbulent (`v2.s` = √Cτ2). Returns `Ok(None)` if the
    /// interval does not transition (neither N reaches Ncrit nor does `xi_forced` lie in
    /// (ξ1, ξ2]); then the laminar [`BlModel::interval`] applies.
    pub fn transition_interval(
        &self,
        v1: &StationVars,
        v2: &StationVars,
        xi_forced: Option<f64>,
    ) -> Result<Option<TransitionInterval>, BlError> {
        self.transition_from(&UpstreamStation::new(v1, Regime::Laminar), v2, xi_forced)
    }

    /// [`BlModel::transition_interval`] with station 1 given as an [`UpstreamStation`] (its
    /// laminar secondary variables evaluated once and reused across calls).
    pub fn transition_from(
        &self,
        up: &UpstreamStation,
        v2: &StationVars,
        xi_forced: Option<f64>,
    ) -> Result<Option<TransitionInterval>, BlError> {
        let other;
        let up = if up.regime() == Regime::Laminar {
            up
        } else {
            other = UpstreamStation::new(up.vars(), Regime::Laminar);
            &other
        };
        let v1 = up.vars();
        validate(v1, Regime::Laminar)?;
        validate(v2, Regime::Turbulent)?;
        check_advance(v1, v2)?;
        let s1c = up.constant(self);
        let p2c = Primaries::new(v2, None, self);
        if self.below_ncrit(s1c, &p2c, v1, v2, xi_forced) {
            return Ok(None);
        }
        let check = self.solve_n2(s1c, &p2c, v1, v2, xi_forced);
        let Some((xi_tr, kind)) = check.transition else {
            return Ok(None);
        };

        // ξ_T as a derivative number over the 10 interval variables
        let s1 = up.seeded(self);
        let p2 = Primaries::new(v2, Some(5), self);
        let xt = match kind {
            TransitionKind::Forced => Dual::constant(xi_tr),
            TransitionKind::Free => {
                // implicit function theorem on R(v, N2) = 0:
                // dξ_T/dv = ∂ξ_T/∂v − (∂ξ_T/∂N2)(∂R/∂v)/(∂R/∂N2)
                let (res_v, xt_v, _) =
                    self.trchek_residual(s1, &p2, Dual::constant(check.n2), xi_forced);
                let (res_a, xt_a, _) =
                    self.trchek_residual(s1c, &p2c, Dual::variable(check.n2, 0), xi_forced);
                let ratio = xt_a.g[0] / res_a.g[0];
                let mut g = xt_v.g;
                for (gi, ri) in g.iter_mut().zip(res_v.g.iter()) {
                    *gi -= ratio * ri;
                }
                Dual { v: xt_v.v, g }
            }
        };

        // TRDIF: interpolate primaries to T
        let wf2 = (xt - s1.x) / (p2.x - s1.x);
        let wf1 = 1.0 - wf2;
        let tt = s1.t * wf1 + p2.t * wf2;
        let dt = s1.d * wf1 + p2.d * wf2;
        let ut = s1.u * wf1 + p2.u * wf2;
        let (fc, pp) = (&self.flow, &self.params);

        // laminar part 1 → T (momentum and shape rows)
        let stl = Station::from_primaries(
            xt,
            ut,
            tt,
            dt,
            Dual::constant(fc.ncrit),
            0.0,
            Regime::Laminar,
            fc,
            pp,
        );
        let bl = bldif(DiffKind::Laminar, s1, &stl, fc, pp);

        // turbulent part T → 2, with the initial √Cτ at T
        let stq = Station::from_primaries(
            xt,
            ut,
            tt,
            dt,
            Dual::constant(0.0),
            0.0,
            Regime::Turbulent,
            fc,
            pp,
        );
        let sqt = transition_ctau_factor_d(
            stq.hk,
            pp.transition_ctau_factor,
            pp.transition_ctau_exponent,
        ) * stq.cq;
        let stt = Station::from_primaries(xt, ut, tt, dt, sqt, 0.0, Regime::Turbulent, fc, pp);
        let s2 = self.station(v2, Some(5), Regime::Turbulent);
        let bt = bldif(DiffKind::Turbulent, &stt, &s2, fc, pp);

        let rows = [bt[0], bl[1] + bt[1], bl[2] + bt[2]];
        if !xt.g.iter().all(|g| g.is_finite()) {
            return Err(BlError::NonFinite("transition point sensitivities"));
        }
        Ok(Some(TransitionInterval {
            eqs: check_finite(IntervalEquations::from_duals(&rows), "transition equations")?,
            xi_tr: xt.v,
            dxi_tr_d1: xt.slots(0),
            dxi_tr_d2: xt.slots(5),
            kind,
            n2: check.n2,
        }))
    }
}
