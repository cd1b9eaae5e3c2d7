//! The local problem of a re-march station (XFOIL MRCHDU): its equations, with transition
//! re-located on the way, the prescribed combination of Ue and Hk quasi-normal to the local
//! Ue–Hk characteristic, and the damping of iterations that oscillate.

use super::MixedStation;
use crate::boundary_layer::{
    BlError, DownstreamEquations, IntervalEquations, Regime, StationVars, TransitionKind,
};
use crate::numerics::small_dense::solve;
use crate::viscous::local_newton::{equation_rows, Evaluation, LocalProblem, Next};
use crate::viscous::newton::CachedEquations;
use crate::viscous::stations::StationKind;

/// Weight of the prescribed Ue–Hk combination of the mixed-mode march (XFOIL MRCHDU SENSWT).
const MIXED_MODE_WEIGHT: f64 = 1000.0;

impl LocalProblem for MixedStation<'_> {
    fn evaluate(&mut self, itbl: usize) -> Evaluation {
        let model = self.march.model;
        let s_now = if self.turbulent { self.cti } else { self.n_amp };
        let was_turbulent_now = self.turbulent;
        let v2 = StationVars {
            x: self.st.xi,
            u: self.u,
            theta: self.th,
            dstar: self.ds,
            s: s_now,
            dw: self.st.wake_gap,
        };
        let Ok((kept, transition_ctau)) = self.equations(&v2) else {
            self.last = None;
            return Evaluation::Failed;
        };
        let (res, jac) = kept.local_system();
        let s_eval = transition_ctau.unwrap_or(s_now);
        let (th, ds, u) = (self.th, self.ds, self.u);
        self.last = Some((
            kept,
            [s_eval, th, ds, u],
            self.turbulent != was_turbulent_now,
        ));
        let v2 = StationVars {
            s: if self.turbulent { self.cti } else { self.n_amp },
            ..v2
        };
        let (hk, hk_d) = self.hk_at_state.take().unwrap_or_else(|| {
            let hk = model.kinematic_shape(&v2);
            (hk.value, hk.d)
        });
        if itbl == 0 {
            self.set_references(hk);
        }
        let (mut a, mut b) = equation_rows(&res, &jac);
        let (ueref, hkref) = (self.ueref, self.hkref);
        if matches!(
            self.st.kind,
            StationKind::Similarity | StationKind::WakeStart
        ) {
            a[3] = [0.0, 0.0, 0.0, 1.0];
            b[3] = ueref - u;
        } else {
            // Ue–Hk characteristic slope: response of Ue to a unit Hk change (XFOIL
            // MRCHDU: set in the first 5 iterations, averaged until the 15th, then frozen).
            if itbl < 15 {
                let mut at = a;
                let mut bt = b;
                at[3] = [0.0, hk_d[0], hk_d[1], hk_d[2]];
                bt[3] = 1.0;
                if let Some(z) = solve(at, bt) {
                    let sennew = MIXED_MODE_WEIGHT * z[3] * hkref / ueref;
                    if itbl < 5 {
                        self.sens = sennew;
                    } else {
                        self.sens = 0.5 * (self.sens + sennew);
                    }
                }
            }
            let sens = self.sens;
            a[3] = [
                0.0,
                hk_d[0] * hkref,
                hk_d[1] * hkref,
                hk_d[2] * hkref + sens / ueref,
            ];
            b[3] = -(hkref * hkref * (hk / hkref - 1.0) + sens * (u / ueref - 1.0));
        }
        Evaluation::System(a, b)
    }

    fn largest_change(&self, dx: &[f64; 4]) -> f64 {
        let mut dmax = (dx[1] / self.th)
            .abs()
            .max((dx[2] / self.ds).abs())
            .max((dx[3] / self.u).abs());
        if self.turbulent {
            dmax = dmax.max((dx[0] / (10.0 * self.cti)).abs());
        }
        dmax
    }

    fn damping(&mut self, dx: &[f64; 4]) -> f64 {
        let turbulent = self.turbulent;
        let rel = [
            if turbulent {
                dx[0] / self.cti
            } else {
                dx[0] / 10.0
            },
            dx[1] / self.th,
            dx[2] / self.ds,
            dx[3] / self.u,
        ];
        match self.damping.as_mut() {
            Some(d) => d.factor(rel, turbulent),
            None => 1.0,
        }
    }

    fn step(&mut self, dx: &[f64; 4], rlx: f64, dmax: f64) -> Next {
        self.last_dmax = dmax;
        if self.turbulent {
            self.cti = (self.cti + rlx * dx[0]).clamp(1e-7, 0.30);
        } else {
            self.n_amp += rlx * dx[0];
        }
        self.th += rlx * dx[1];
        self.ds += rlx * dx[2];
        self.u += rlx * dx[3];
        let (th, ds, u) = (self.th, self.ds, self.u);
        if !(th > 0.0 && u > 0.0 && ds.is_finite()) {
            return Next::Stop;
        }
        // Shape-factor floor (XFOIL DSLIM).
        let hk_new = self.march.model.kinematic_shape(&StationVars {
            x: self.st.xi,
            u,
            theta: th,
            dstar: ds,
            s: 0.0,
            dw: self.st.wake_gap,
        });
        let hk_floor = self.march.hk_floor;
        if hk_new.value < hk_floor && hk_new.d[1] > 0.0 {
            self.ds += (hk_floor - hk_new.value) / hk_new.d[1];
        } else {
            // Hk does not depend on the shear variable: the next iteration's Hk.
            self.hk_at_state = Some((hk_new.value, hk_new.d));
        }
        if dmax <= self.march.params.mixed_mode_tolerance {
            self.converged = true;
            return Next::Stop;
        }
        Next::Continue
    }
}

impl MixedStation<'_> {
    /// The station's equations at `v2` (√Cτ or N in `v2.s` by the current regime) and, for a
    /// transition interval, the √Cτ they were evaluated at. Regime changes found by the
    /// transition check are applied to the station.
    fn equations(&mut self, v2: &StationVars) -> Result<(KeptEquations, Option<f64>), BlError> {
        let (model, params) = (self.march.model, self.march.params);
        match self.st.kind {
            StationKind::Similarity => model.similarity(v2).map(|e| {
                let eq = IntervalEquations {
                    res: e.res,
                    d1: [[0.0; 5]; 3],
                    d2: e.combined_jacobian(),
                };
                (
                    KeptEquations::Complete(CachedEquations::Interval(eq, None)),
                    None,
                )
            }),
            StationKind::WakeStart => {
                let Some((vu, vl)) = self.trailing_edge.as_ref() else {
                    unreachable!("the first wake station has the trailing-edge stations")
                };
                model
                    .te_junction(vu, vl, v2, self.march.ante)
                    .map(|j| (KeptEquations::Complete(CachedEquations::Junction(j)), None))
            }
            StationKind::Interval => {
                let Some(up) = self.upstream.as_ref() else {
                    unreachable!("interval stations have an upstream station")
                };
                // Intervals without transition: station 2's Jacobian with respect to
                // (s, θ, δ*, u) only (all the local iteration uses, at fixed ξ); station 1's
                // and the ξ column are added for the kept iteration.
                let station2_only = |regime: Regime, v: &StationVars| {
                    model
                        .interval_downstream(regime, up, v)
                        .map(|d| (KeptEquations::Downstream(d), None))
                };
                if up.regime() != Regime::Laminar {
                    return station2_only(up.regime(), v2);
                }
                // Laminar surface so far: check this interval for transition.
                let v2t = StationVars { s: self.cti, ..*v2 };
                match model.transition_from(up, &v2t, self.march.xi_forced)? {
                    Some(t) => {
                        let ctau = self.cti;
                        if !self.transitioned {
                            self.transitioned = true;
                            self.turbulent = true;
                            if !self.was_turbulent {
                                self.cti = params.ctau_sqrt_initial;
                            }
                        }
                        let tr = Some((t.xi_tr, t.kind == TransitionKind::Forced));
                        Ok((
                            KeptEquations::Complete(CachedEquations::Interval(t.eqs, tr)),
                            Some(ctau),
                        ))
                    }
                    None => {
                        if self.transitioned {
                            self.transitioned = false;
                            self.turbulent = false;
                        }
                        station2_only(
                            Regime::Laminar,
                            &StationVars {
                                s: self.n_amp,
                                ..*v2
                            },
                        )
                    }
                }
            }
        }
    }

    /// The references of the prescribed Ue–Hk combination, set in the first iteration from
    /// the station's Hk `hk` there (or from a carried start's unscaled state).
    fn set_references(&mut self, hk: f64) {
        let (u, st, k) = (self.u, self.st, self.k);
        (self.ueref, self.hkref) = self.reference.unwrap_or((u, hk));
        // A station that was turbulent and is laminar now: extrapolate the reference
        // Hk from upstream (XFOIL MRCHDU), weighted by the turbulent fraction of the
        // old transition interval if the station was the first turbulent one.
        if !self.turbulent && self.was_turbulent && st.kind == StationKind::Interval {
            let p = st.upstream.unwrap_or(k - 1);
            let Some(up) = self.upstream.as_ref() else {
                return;
            };
            let hk_upstream = self.march.model.kinematic_shape(up.vars()).value;
            let weight = match self.march.turbulent_fraction {
                Some(f) if !self.march.old_turbulent[p] => f,
                _ => 1.0,
            };
            self.hkref = hk + weight * (hk_upstream - hk);
        }
    }
}

/// Damping of a station's local Newton iteration that oscillates instead of converging.
///
/// Close to transition the interval equations are strongly nonlinear in the station variables:
/// when the transition point lies where the amplification rate switches on (the onset ramp of
/// XFOIL DAMPL, only 0.16 decades of Re_θ wide), a change of δ*2 by 1 % moves ξ_tr by several
/// per cent of the interval, and the undamped Newton iteration jumps back and forth between
/// two states on either side of the solution for all its iterations (the global iteration then
/// sits in a fixed cycle too). A step that reverses the previous one (cosine below −½) without
/// being at most half as long halves the relaxation factor for the remaining iterations of the
/// station; a converging iteration is not affected. Used only for intervals checked for
/// transition (laminar upstream station).
pub(super) struct OscillationDamping {
    /// Relative step (s, θ, δ*, Ue) of the previous iteration and whether it was turbulent.
    previous: Option<([f64; 4], bool)>,
    /// Current factor applied to the relaxation.
    factor: f64,
}

impl OscillationDamping {
    pub(super) fn new() -> Self {
        Self {
            previous: None,
            factor: 1.0,
        }
    }

    /// Damping factor for the relative step `rel` of an iteration in the given regime
    /// (steps across a regime change are not compared).
    fn factor(&mut self, rel: [f64; 4], turbulent: bool) -> f64 {
        if let Some((prev, prev_turbulent)) = self.previous {
            let dot: f64 = rel.iter().zip(&prev).map(|(a, b)| a * b).sum();
            let norm = |v: &[f64; 4]| v.iter().map(|a| a * a).sum::<f64>().sqrt();
            let (n_new, n_old) = (norm(&rel), norm(&prev));
            if prev_turbulent == turbulent && dot < -0.5 * n_new * n_old && n_new > 0.5 * n_old {
                self.factor *= 0.5;
            }
        }
        self.previous = Some((rel, turbulent));
        self.factor
    }
}

/// Equations of a local iteration of the re-march, kept for the global assembly.
pub(super) enum KeptEquations {
    /// Complete equations (similarity, junction, transition interval).
    Complete(CachedEquations),
    /// An interval without transition, still without the Jacobian of its upstream station.
    Downstream(DownstreamEquations),
}

impl KeptEquations {
    /// What the local iteration solves: the residuals and their derivatives with respect to
    /// the station's own (s, θ, δ*, u).
    fn local_system(&self) -> ([f64; 3], [[f64; 4]; 3]) {
        let own4 = |d: &[[f64; 5]; 3]| d.map(|[ds, dt, dd, du, _]| [ds, dt, dd, du]);
        match self {
            Self::Complete(CachedEquations::Interval(e, _)) => (e.res, own4(&e.d2)),
            Self::Complete(CachedEquations::Junction(j)) => (j.res, own4(&j.d_wake)),
            Self::Downstream(d) => (d.res, d.d2),
        }
    }
}
