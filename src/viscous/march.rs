//! Initial boundary-layer march with the edge speed prescribed (direct mode) or, where the
//! layer separates, with the shape factor prescribed and the edge speed solved for (inverse
//! mode) — the initial condition of the global Newton solve (XFOIL xbl.f MRCHUE,
//! Drela 1989 §4.2) — and the controls of both marches ([`MarchParams`]).

use super::local_newton::{equation_rows, iterate, Evaluation, LocalProblem, Next};
use super::params::SideModels;
use super::state::BlState;
use super::stations::{Station, StationKind, StationLayout, Surface};
use crate::boundary_layer::{BlModel, IntervalEquations, Regime, StationVars};

/// Controls of the local station Newton iterations of the march.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MarchParams {
    /// Maximum Newton iterations per station (XFOIL MRCHUE: 25).
    pub max_iterations: usize,
    /// Convergence threshold on the largest relative change (XFOIL: 1e-5).
    pub tolerance: f64,
    /// Largest relative change allowed per local iteration (XFOIL DMAX limiting to 0.3).
    pub max_relative_step: f64,
    /// Initial √Cτ of the first turbulent station, in the marches and in the Newton
    /// assembly (XFOIL MRCHUE CTI = 0.03).
    pub ctau_sqrt_initial: f64,
    /// Kinematic shape factor Hk of a laminar station above which the initial march switches
    /// to inverse mode, Hk prescribed (XFOIL MRCHUE HLMAX = 3.8).
    pub hk_max_laminar: f64,
    /// The same for a turbulent or wake station (XFOIL MRCHUE HTMAX = 2.5).
    pub hk_max_turbulent: f64,
    /// Convergence threshold on the largest relative change of the local iterations of the
    /// mixed-mode re-march before each global Newton iteration (XFOIL MRCHDU DEPS = 5e-6).
    /// The re-march only prepares the state for the global Newton step, whose own tolerance
    /// decides the converged result, so converged points do not depend on it beyond that
    /// tolerance; the looser default is one of the speed levers of docs/performance.md.
    pub mixed_mode_tolerance: f64,
    /// Largest relative correction of the upstream station carried over as the start of a
    /// station's local iterations in the mixed-mode re-march (MRCHDU); larger ones are clipped
    /// to ± this value.
    pub carried_correction_limit: f64,
    /// A turbulent or wake station of the re-march whose local iteration fails right after its
    /// upstream station's did keeps the state the Newton step gave it, instead of XFOIL's
    /// extrapolation from the (already extrapolated) upstream station (in the mixed-mode
    /// re-march, MRCHDU).
    /// Off: XFOIL's fallback everywhere.
    pub keep_state_in_fallback_chains: bool,
}

impl Default for MarchParams {
    fn default() -> Self {
        Self {
            max_iterations: 25,
            tolerance: 1e-5,
            max_relative_step: 0.3,
            ctau_sqrt_initial: 0.03,
            hk_max_laminar: 3.8,
            hk_max_turbulent: 2.5,
            mixed_mode_tolerance: 1.0e-4,
            carried_correction_limit: 0.5,
            keep_state_in_fallback_chains: true,
        }
    }
}

/// Marches the boundary layer over all stations of `layout` with edge speed `ue_inv`
/// (XFOIL MRCHUE). Transition is checked in every laminar interval; the wake starts from the
/// trailing-edge junction. Never fails: a station whose local Newton does not converge keeps its
/// last iterate (the global Newton corrects it).
pub fn march(
    models: &SideModels,
    layout: &StationLayout,
    ue_inv: &[f64],
    xi_forced: [Option<f64>; 2],
    ante: f64,
    params: &MarchParams,
) -> BlState {
    let n = layout.len();
    let mut state = BlState::zeros(n);
    let mut order: Vec<usize> = layout.range(Surface::Upper).collect();
    order.extend(layout.range(Surface::Lower));
    order.extend(layout.range(Surface::Wake));
    let mut surface_turbulent = [false, false];
    for k in order {
        let st = layout.stations[k];
        let side = match st.surface {
            Surface::Upper => 0,
            _ => 1,
        };
        let model = &models[side];
        let u0 = ue_inv[k].max(1e-6);
        state.ue[k] = u0;
        // Initial guess for this station.
        let (mut s, th, ds) = match st.kind {
            StationKind::Similarity => {
                // Thwaites' stagnation-point solution (XFOIL MRCHUE); a guess that cannot be
                // formed falls back like a failed station below.
                let (th, ds) = model
                    .stagnation_guess(st.xi.max(1e-9), u0)
                    .unwrap_or((f64::NAN, f64::NAN));
                (0.0, th, ds)
            }
            StationKind::WakeStart => {
                let (ku, kl) = (layout.upper_te(), layout.lower_te());
                let th = state.theta[ku] + state.theta[kl];
                let s = (state.s[ku] * state.theta[ku] + state.s[kl] * state.theta[kl]) / th;
                (s, th, state.dstar(ku) + state.dstar(kl) + ante)
            }
            StationKind::Interval => {
                let p = st.upstream.unwrap_or(k - 1);
                (state.s[p], state.theta[p], state.dstar(p))
            }
        };
        let turbulent = st.surface == Surface::Wake || surface_turbulent[side];
        if turbulent && st.kind == StationKind::Interval {
            let p = st.upstream.unwrap_or(k - 1);
            if !state.turbulent[p] && st.surface != Surface::Wake {
                s = params.ctau_sqrt_initial;
            }
        }
        let mut station = DirectStation {
            model,
            layout,
            state: &state,
            k,
            st,
            xi_forced: xi_forced[side],
            ante,
            params,
            u0,
            vars: [s, th, ds, u0],
            turbulent,
            transitioned: false,
            inverse: false,
            hk_target: 0.0,
            regime: Regime::Laminar,
        };
        iterate(
            &mut station,
            params.max_iterations,
            params.max_relative_step,
        );
        let [mut s, mut th, mut ds, mut u] = station.vars;
        let turbulent = station.turbulent;
        if !(s.is_finite() && th.is_finite() && ds.is_finite() && u.is_finite()) {
            // Fall back to the upstream station so the global Newton starts from finite values.
            let p = st.upstream.unwrap_or(k.saturating_sub(1));
            s = state.s[p];
            th = state.theta[p].max(1e-6);
            ds = state.dstar(p).max(2.0 * th);
            u = u0;
        }
        if turbulent && st.surface != Surface::Wake {
            surface_turbulent[side] = true;
        }
        state.s[k] = s;
        state.theta[k] = th;
        state.ue[k] = u;
        state.mass[k] = ds * u;
        state.turbulent[k] = turbulent || st.surface == Surface::Wake;
    }
    state
}

/// One station of the initial march: Ue prescribed (direct mode) until Hk passes the
/// separation limit, then Hk prescribed at that limit (inverse mode, XFOIL MRCHUE).
struct DirectStation<'a> {
    model: &'a BlModel,
    layout: &'a StationLayout,
    /// The march's state so far (the stations upstream of this one).
    state: &'a BlState,
    /// System index of the station.
    k: usize,
    st: Station,
    /// ξ of forced transition on the station's surface.
    xi_forced: Option<f64>,
    /// Trailing-edge gap (XFOIL ANTE), for the first wake station.
    ante: f64,
    params: &'a MarchParams,
    /// The inviscid edge speed, prescribed in direct mode.
    u0: f64,
    /// The unknowns (s, θ, δ*, Ue).
    vars: [f64; 4],
    turbulent: bool,
    /// Transition was found in the interval ending here.
    transitioned: bool,
    /// Hk is prescribed instead of Ue.
    inverse: bool,
    /// The prescribed Hk in inverse mode.
    hk_target: f64,
    /// Regime of the last evaluation.
    regime: Regime,
}

/// What a station's evaluation does when it has no equations.
enum Instead {
    /// The regime changed: evaluate again.
    Again,
    /// The equations cannot be evaluated.
    Fail,
}

impl DirectStation<'_> {
    /// Primary variables of the station at unknowns `[s, θ, δ*, u]`.
    fn station_vars(&self, [s, theta, dstar, u]: [f64; 4]) -> StationVars {
        StationVars {
            x: self.st.xi,
            u,
            theta,
            dstar,
            s,
            dw: self.st.wake_gap,
        }
    }

    /// The station's three equations at `v2`, or what to do instead: evaluate again after a
    /// regime change, or stop.
    fn equations(&mut self, v2: &StationVars) -> Result<IntervalEquations, Instead> {
        let (model, layout, st, params) = (self.model, self.layout, self.st, self.params);
        let fail = |_| Instead::Fail;
        match st.kind {
            StationKind::Similarity => {
                let e = model.similarity(v2).map_err(fail)?;
                Ok(IntervalEquations {
                    res: e.res,
                    d1: [[0.0; 5]; 3],
                    d2: e.combined_jacobian(),
                })
            }
            StationKind::WakeStart => {
                let (ku, kl) = (layout.upper_te(), layout.lower_te());
                let (vu, vl) = (self.state.vars(layout, ku), self.state.vars(layout, kl));
                let j = model.te_junction(&vu, &vl, v2, self.ante).map_err(fail)?;
                Ok(IntervalEquations {
                    res: j.res,
                    d1: [[0.0; 5]; 3],
                    d2: j.d_wake,
                })
            }
            StationKind::Interval => {
                let p = st.upstream.unwrap_or(self.k - 1);
                let v1 = self.state.vars(layout, p);
                let regime = if st.surface == Surface::Wake {
                    Regime::Wake
                } else if self.turbulent && !self.transitioned {
                    Regime::Turbulent
                } else {
                    Regime::Laminar
                };
                if regime != Regime::Laminar {
                    return model.interval(regime, &v1, v2).map_err(fail);
                }
                // A laminar interval, or the transition interval found before: check it.
                let mut v2t = *v2;
                if !self.transitioned {
                    v2t.s = params.ctau_sqrt_initial;
                }
                let tr = model
                    .transition_interval(&v1, &v2t, self.xi_forced)
                    .map_err(fail)?;
                match (tr, self.transitioned) {
                    (Some(t), true) => Ok(t.eqs),
                    (Some(_), false) => {
                        self.vars[0] = params.ctau_sqrt_initial;
                        self.transitioned = true;
                        self.turbulent = true;
                        Err(Instead::Again)
                    }
                    (None, true) => {
                        self.transitioned = false;
                        self.turbulent = false;
                        self.vars[0] = v1.s;
                        Err(Instead::Again)
                    }
                    (None, false) => model.interval(Regime::Laminar, &v1, v2).map_err(fail),
                }
            }
        }
    }
}

impl LocalProblem for DirectStation<'_> {
    fn evaluate(&mut self, _iteration: usize) -> Evaluation {
        let v2 = self.station_vars(self.vars);
        let eq = match self.equations(&v2) {
            Ok(eq) => eq,
            Err(Instead::Again) => return Evaluation::Again,
            Err(Instead::Fail) => return Evaluation::Failed,
        };
        self.regime = if self.st.surface == Surface::Wake {
            Regime::Wake
        } else if self.turbulent {
            Regime::Turbulent
        } else {
            Regime::Laminar
        };
        let Ok(props) = self.model.properties(&v2, self.regime) else {
            return Evaluation::Failed;
        };
        let own = eq.d2.map(|[ds, dt, dd, du, _]| [ds, dt, dd, du]);
        let (mut a, mut b) = equation_rows(&eq.res, &own);
        if self.inverse {
            let hk_d = self.model.kinematic_shape(&v2).d;
            a[3] = [0.0, hk_d[0], hk_d[1], hk_d[2]];
            b[3] = self.hk_target - props.hk;
        } else {
            a[3] = [0.0, 0.0, 0.0, 1.0];
            b[3] = self.u0 - self.vars[3];
        }
        Evaluation::System(a, b)
    }

    fn largest_change(&self, dx: &[f64; 4]) -> f64 {
        let [s, th, ds, u] = self.vars;
        let rel = [
            if self.turbulent {
                dx[0] / s.max(1e-7)
            } else {
                dx[0] / 10.0
            },
            dx[1] / th,
            dx[2] / ds,
            dx[3] / u,
        ];
        rel.iter().fold(0.0_f64, |m, v| m.max(v.abs()))
    }

    fn step(&mut self, dx: &[f64; 4], rlx: f64, largest: f64) -> Next {
        let [mut s, mut th, mut ds, mut u] = self.vars;
        s += rlx * dx[0];
        th += rlx * dx[1];
        ds += rlx * dx[2];
        u += rlx * dx[3];
        if self.turbulent {
            s = s.clamp(1e-7, 0.25);
        } else {
            s = s.max(0.0);
        }
        th = th.max(1e-12);
        ds = ds.max(1.0001 * th + self.st.wake_gap);
        u = u.max(1e-6);
        self.vars = [s, th, ds, u];
        // Switch to inverse mode when the layer separates (XFOIL MRCHUE HLMAX/HTMAX).
        let hk_max = if self.turbulent {
            self.params.hk_max_turbulent
        } else {
            self.params.hk_max_laminar
        };
        if !self.inverse && self.st.kind != StationKind::Similarity {
            let v = self.station_vars(self.vars);
            let hk = self
                .model
                .properties(&v, self.regime)
                .map(|p| p.hk)
                .unwrap_or(0.0);
            if hk > hk_max {
                self.inverse = true;
                self.hk_target = hk_max;
                return Next::Continue;
            }
        }
        if largest < self.params.tolerance {
            Next::Stop
        } else {
            Next::Continue
        }
    }
}
