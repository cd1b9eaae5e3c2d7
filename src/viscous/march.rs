//! Initial boundary-layer march with the edge speed prescribed (direct mode) or, where the
//! layer separates, with the shape factor prescribed and the edge speed solved for (inverse
//! mode) — the initial condition of the global Newton solve (XFOIL xbl.f MRCHUE,
//! Drela 1989 §4.2).

use super::newton::CachedEquations;
use super::state::BlState;
use super::stations::{StationKind, StationLayout, Surface};
use crate::boundary_layer::{
    BlModel, DownstreamEquations, IntervalEquations, Regime, StationVars, TransitionKind,
    UpstreamStation,
};
use crate::numerics::small_dense::solve;

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
    /// decides the converged result, so converged points do not depend on it (checked on the
    /// default grid: unchanged to < 1e-5 relative except where a stalled polar has two
    /// solutions); 1e-4 instead of 5e-6 cuts the default-grid time by 15–40 %.
    pub mixed_mode_tolerance: f64,
    /// Largest relative correction of the upstream station carried over as the start of a
    /// station's local iterations in the re-march ([`remarch_mixed`]); larger ones are clipped
    /// to ± this value.
    pub carried_correction_limit: f64,
    /// A turbulent or wake station of the re-march whose local iteration fails right after its
    /// upstream station's did keeps the state the Newton step gave it, instead of XFOIL's
    /// extrapolation from the (already extrapolated) upstream station ([`remarch_mixed`]).
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

/// Local equations of a station as a function of its own variables.
enum LocalEq {
    Similarity,
    Interval(Regime),
    Junction,
}

/// Marches the boundary layer over all stations of `layout` with edge speed `ue_inv`
/// (XFOIL MRCHUE). Transition is checked in every laminar interval; the wake starts from the
/// trailing-edge junction. Never fails: a station whose local Newton does not converge keeps its
/// last iterate (the global Newton corrects it).
pub fn march(
    model: &BlModel,
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
        let u0 = ue_inv[k].max(1e-6);
        state.ue[k] = u0;
        // Initial guess for this station.
        let (mut s, mut th, mut ds) = match st.kind {
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
        let mut turbulent = st.surface == Surface::Wake || surface_turbulent[side];
        if turbulent && st.kind == StationKind::Interval {
            let p = st.upstream.unwrap_or(k - 1);
            if !state.turbulent[p] && st.surface != Surface::Wake {
                s = params.ctau_sqrt_initial;
            }
        }
        let mut u = u0;
        let mut inverse = false;
        let mut htarget = 0.0;
        let mut transitioned = false;
        for _ in 0..params.max_iterations {
            let v2 = StationVars {
                x: st.xi,
                u,
                theta: th,
                dstar: ds,
                s,
                dw: st.wake_gap,
            };
            let kind = match st.kind {
                StationKind::Similarity => LocalEq::Similarity,
                StationKind::WakeStart => LocalEq::Junction,
                StationKind::Interval if st.surface == Surface::Wake => {
                    LocalEq::Interval(Regime::Wake)
                }
                StationKind::Interval if turbulent && !transitioned => {
                    LocalEq::Interval(Regime::Turbulent)
                }
                StationKind::Interval => LocalEq::Interval(Regime::Laminar),
            };
            let eq: IntervalEquations = match kind {
                LocalEq::Similarity => {
                    let Ok(e) = model.similarity(&v2) else { break };
                    IntervalEquations {
                        res: e.res,
                        d1: [[0.0; 5]; 3],
                        d2: e.combined_jacobian(),
                    }
                }
                LocalEq::Junction => {
                    let (ku, kl) = (layout.upper_te(), layout.lower_te());
                    let (vu, vl) = (state.vars(layout, ku), state.vars(layout, kl));
                    let Ok(j) = model.te_junction(&vu, &vl, &v2, ante) else {
                        break;
                    };
                    IntervalEquations {
                        res: j.res,
                        d1: [[0.0; 5]; 3],
                        d2: j.d_wake,
                    }
                }
                LocalEq::Interval(regime) => {
                    let p = st.upstream.unwrap_or(k - 1);
                    let v1 = state.vars(layout, p);
                    if regime == Regime::Laminar || transitioned {
                        let mut v2t = v2;
                        if !transitioned {
                            v2t.s = params.ctau_sqrt_initial;
                        }
                        let Ok(tr) = model.transition_interval(&v1, &v2t, xi_forced[side]) else {
                            break;
                        };
                        match tr {
                            Some(t) => {
                                if !transitioned {
                                    s = params.ctau_sqrt_initial;
                                    transitioned = true;
                                    turbulent = true;
                                    continue;
                                }
                                t.eqs
                            }
                            None => {
                                if transitioned {
                                    transitioned = false;
                                    turbulent = false;
                                    s = v1.s;
                                    continue;
                                }
                                let Ok(e) = model.interval(Regime::Laminar, &v1, &v2) else {
                                    break;
                                };
                                e
                            }
                        }
                    } else {
                        let Ok(e) = model.interval(regime, &v1, &v2) else {
                            break;
                        };
                        e
                    }
                }
            };
            let regime = if st.surface == Surface::Wake {
                Regime::Wake
            } else if turbulent {
                Regime::Turbulent
            } else {
                Regime::Laminar
            };
            let Ok(props) = model.properties(&v2, regime) else {
                break;
            };
            let mut a = [[0.0; 4]; 4];
            let mut b = [0.0; 4];
            for r in 0..3 {
                a[r] = [eq.d2[r][0], eq.d2[r][1], eq.d2[r][2], eq.d2[r][3]];
                b[r] = -eq.res[r];
            }
            if inverse {
                let hk_d = model.kinematic_shape(&v2).d;
                a[3] = [0.0, hk_d[0], hk_d[1], hk_d[2]];
                b[3] = htarget - props.hk;
            } else {
                a[3] = [0.0, 0.0, 0.0, 1.0];
                b[3] = u0 - u;
            }
            let Some(dx) = solve(a, b) else { break };
            let rel = [
                if turbulent {
                    dx[0] / s.max(1e-7)
                } else {
                    dx[0] / 10.0
                },
                dx[1] / th,
                dx[2] / ds,
                dx[3] / u,
            ];
            let dmax = rel.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let rlx = if dmax > params.max_relative_step {
                params.max_relative_step / dmax
            } else {
                1.0
            };
            s += rlx * dx[0];
            th += rlx * dx[1];
            ds += rlx * dx[2];
            u += rlx * dx[3];
            if turbulent {
                s = s.clamp(1e-7, 0.25);
            } else {
                s = s.max(0.0);
            }
            th = th.max(1e-12);
            ds = ds.max(1.0001 * th + st.wake_gap);
            u = u.max(1e-6);
            // Switch to inverse mode when the layer separates (XFOIL MRCHUE HLMAX/HTMAX).
            let hmax = if turbulent {
                params.hk_max_turbulent
            } else {
                params.hk_max_laminar
            };
            if !inverse && st.kind != StationKind::Similarity {
                let v = StationVars {
                    x: st.xi,
                    u,
                    theta: th,
                    dstar: ds,
                    s,
                    dw: st.wake_gap,
                };
                let hk = model.properties(&v, regime).map(|p| p.hk).unwrap_or(0.0);
                if hk > hmax {
                    inverse = true;
                    htarget = hmax;
                    continue;
                }
            }
            if dmax < params.tolerance {
                break;
            }
        }
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

/// Weight of the prescribed Ue–Hk combination of the mixed-mode march (XFOIL MRCHDU SENSWT).
pub const MIXED_MODE_WEIGHT: f64 = 1000.0;

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
struct OscillationDamping {
    /// Relative step (s, θ, δ*, Ue) of the previous iteration and whether it was turbulent.
    previous: Option<([f64; 4], bool)>,
    /// Current factor applied to the relaxation.
    factor: f64,
}

impl OscillationDamping {
    fn new() -> Self {
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
enum KeptEquations {
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

/// Re-marches the boundary layer in mixed mode from the current state (XFOIL xbl.f MRCHDU):
/// at every station the three interval equations are solved together with a prescribed
/// combination of Ue and Hk that lies quasi-normal to the local Ue–Hk characteristic, so that
/// separation does not make the march singular. Transition is re-located on the way, which
/// keeps the state consistent with the equations before each global Newton iteration.
/// Stations whose local iteration fails keep an extrapolated state (XFOIL's fallback), except
/// turbulent and wake stations right after another failed station
/// ([`MarchParams::keep_state_in_fallback_chains`]): once one station has been extrapolated
/// (Ue of its upstream neighbour, θ and δ* scaled by √ξ), every station after it tends to fail
/// too, and the Newton system at such a chain (Ue constant, H up to ≈ 10 over 50–70 stations)
/// has a solution growing ≈ 7× per station downstream: an "exploded" step of RMS change up to
/// 1e48, followed by 15–60 wandering iterations. Those stations keep the state the Newton step
/// gave them. On the four default rotor grids this took the exploded attempts from 13–18 % of
/// the Newton iterations to 1–3 % and the modelled time down by ≈ 9 %; 7 fewer negative- or
/// post-stall points converged (none in the normal range).
///
/// `turbulent_fraction` is, per surface (upper, lower), the fraction of the transition interval
/// downstream of the transition point for the regimes stored in `state`
/// ([`super::newton::TransitionPoint::turbulent_fraction`]; None: unknown). A station that was
/// turbulent and is laminar now takes its reference Hk as in XFOIL from the upstream station,
/// weighted by that fraction if it was the first turbulent station: a station whose old transition
/// point lay just upstream of it carries an essentially laminar state, and XFOIL's full
/// extrapolation (weight 1) pushed its Hk towards the upstream value, which moved transition
/// back into the interval and undid the global Newton step in every iteration (a fixed cycle;
/// XFOIL 6.99 has it as well, e.g. NACA 8-H-12, Re 1.5e6, M 0.2, α −0.5° from α −0.25°).
/// A station whose local iteration oscillates between two states without converging (transition
/// point inside the onset ramp of the amplification rate) has its relaxation halved per reversal.
///
/// Starting guess (not in XFOIL), with `carry_corrections`: the corrections the re-march makes
/// to the state left by the global Newton step are strongly correlated along a turbulent layer
/// or the wake, so a turbulent or wake station whose regime and whose upstream station's
/// regime are unchanged starts its local iterations from its state scaled by the upstream
/// station's relative corrections of √Cτ, θ, δ*, Ue (each clipped to
/// ± [`MarchParams::carried_correction_limit`]). The prescribed Ue–Hk combination keeps the
/// references of the unscaled state, so the station solves the same equations; only the start
/// moves. The solver carries corrections after moderate Newton steps only
/// ([`super::ViscousParams::carry_corrections_below`]). On the four default rotor grids this
/// cut the local iterations by 27 % and the Newton iterations by 8 %, and 9 more points
/// converged.
#[allow(clippy::too_many_arguments)]
pub fn remarch_mixed(
    model: &BlModel,
    layout: &StationLayout,
    state: &mut BlState,
    xi_forced: [Option<f64>; 2],
    turbulent_fraction: [Option<f64>; 2],
    carry_corrections: bool,
    ante: f64,
    params: &MarchParams,
) -> Vec<Option<CachedEquations>> {
    let mut cache = vec![None; layout.len()];
    let old_turbulent = state.turbulent.clone();
    let mut order: Vec<usize> = layout.range(Surface::Upper).collect();
    order.extend(layout.range(Surface::Lower));
    order.extend(layout.range(Surface::Wake));
    let mut surface_turbulent = [false, false];
    let mut sens = 0.0;
    // Per side (upper; lower and wake): the relative corrections (√Cτ, θ, δ*, Ue) the re-march
    // made at the last station, if it was a converged turbulent or wake station of unchanged
    // regime.
    let mut carried: [Option<[f64; 4]>; 2] = [None, None];
    // Whether the last station (the upstream one of an interval station) fell back.
    let mut upstream_fell_back = false;
    for k in order {
        let st = layout.stations[k];
        let side = usize::from(st.surface != Surface::Upper);
        let wake = st.surface == Surface::Wake;
        let was_turbulent = old_turbulent[k];
        let mut u = state.ue[k].max(1e-6);
        let mut th = state.theta[k].max(1e-12);
        let hk_floor = if wake { 1.00005 } else { 1.02 };
        let mut ds = (state.dstar(k) - st.wake_gap).max(hk_floor * th) + st.wake_gap;
        let (mut n_amp, mut cti) = if was_turbulent || wake {
            (
                0.0,
                if state.s[k] > 0.0 {
                    state.s[k]
                } else {
                    params.ctau_sqrt_initial
                },
            )
        } else {
            (state.s[k], params.ctau_sqrt_initial)
        };
        let mut turbulent = wake || surface_turbulent[side];
        if turbulent && !was_turbulent && !wake {
            let p = st.upstream.unwrap_or(k - 1);
            cti = state.s[p].clamp(1e-7, 0.25);
        }
        let mut transitioned = false;
        let mut ueref = u;
        let mut hkref = 0.0;
        let start = [cti, th, ds, u];
        // Start from the upstream station's relative corrections where both stay turbulent.
        let upstream_stays_turbulent =
            st.upstream.is_some_and(|p| old_turbulent[p]) && (wake || surface_turbulent[side]);
        let reference = match carried[side] {
            Some(rel)
                if st.kind == StationKind::Interval
                    && turbulent
                    && was_turbulent
                    && upstream_stays_turbulent =>
            {
                let hk = model.kinematic_shape(&StationVars {
                    x: st.xi,
                    u,
                    theta: th,
                    dstar: ds,
                    s: 0.0,
                    dw: st.wake_gap,
                });
                cti = (cti * (1.0 + rel[0])).clamp(1e-7, 0.3);
                th *= 1.0 + rel[1];
                ds *= 1.0 + rel[2];
                u *= 1.0 + rel[3];
                Some((start[3], hk.value))
            }
            _ => None,
        };
        let mut converged = false;
        let mut last_dmax = f64::INFINITY;
        // Equations of the last local iteration, the variables they were evaluated at
        // (s, θ, δ*, u) and whether the regime changed in that iteration.
        let mut last: Option<(KeptEquations, [f64; 4], bool)> = None;
        // The upstream station is fixed during the local iterations: its closures are
        // evaluated once (laminar: the transition check and the laminar interval share it).
        let upstream = (st.kind == StationKind::Interval).then(|| {
            let regime = if wake {
                Regime::Wake
            } else if surface_turbulent[side] {
                Regime::Turbulent
            } else {
                Regime::Laminar
            };
            let p = st.upstream.unwrap_or(k - 1);
            UpstreamStation::new(&state.vars(layout, p), regime)
        });
        // Hk and its sensitivities at the current (u, θ, δ*), if already known.
        let mut hk_at_state = None;
        // Damping only where the transition check runs (laminar upstream station), the case it
        // is made for: on separated turbulent stations it steered negative-stall sweeps onto
        // another solution branch than XFOIL's (NACA 23012, Re 5e5, M 0.2, α ≤ −6°).
        let mut damping = upstream
            .as_ref()
            .is_some_and(|u| u.regime() == Regime::Laminar)
            .then(OscillationDamping::new);
        for itbl in 0..params.max_iterations {
            let s_now = if turbulent { cti } else { n_amp };
            let was_turbulent_now = turbulent;
            // √Cτ the transition check evaluated the interval's turbulent part at, if it found
            // transition.
            let mut transition_ctau = None;
            let v2 = StationVars {
                x: st.xi,
                u,
                theta: th,
                dstar: ds,
                s: s_now,
                dw: st.wake_gap,
            };
            let kept = match st.kind {
                StationKind::Similarity => model.similarity(&v2).map(|e| {
                    let eq = IntervalEquations {
                        res: e.res,
                        d1: [[0.0; 5]; 3],
                        d2: e.combined_jacobian(),
                    };
                    KeptEquations::Complete(CachedEquations::Interval(eq, None))
                }),
                StationKind::WakeStart => {
                    let (ku, kl) = (layout.upper_te(), layout.lower_te());
                    let (vu, vl) = (state.vars(layout, ku), state.vars(layout, kl));
                    model
                        .te_junction(&vu, &vl, &v2, ante)
                        .map(|j| KeptEquations::Complete(CachedEquations::Junction(j)))
                }
                StationKind::Interval => {
                    let Some(up) = upstream.as_ref() else {
                        unreachable!("interval stations have an upstream station")
                    };
                    // Intervals without transition: station 2's Jacobian with respect to
                    // (s, θ, δ*, u) only (all the local iteration uses, at fixed ξ); station 1's
                    // and the ξ column are added for the kept iteration.
                    let station2_only = |regime: Regime, v: &StationVars| {
                        model
                            .interval_downstream(regime, up, v)
                            .map(KeptEquations::Downstream)
                    };
                    match up.regime() {
                        Regime::Wake | Regime::Turbulent => station2_only(up.regime(), &v2),
                        // Laminar surface so far: check this interval for transition.
                        Regime::Laminar => {
                            let v2t = StationVars { s: cti, ..v2 };
                            match model.transition_from(up, &v2t, xi_forced[side]) {
                                Ok(Some(t)) => {
                                    transition_ctau = Some(cti);
                                    if !transitioned {
                                        transitioned = true;
                                        turbulent = true;
                                        if !was_turbulent {
                                            cti = params.ctau_sqrt_initial;
                                        }
                                    }
                                    Ok(KeptEquations::Complete(CachedEquations::Interval(
                                        t.eqs,
                                        Some((t.xi_tr, t.kind == TransitionKind::Forced)),
                                    )))
                                }
                                Ok(None) => {
                                    if transitioned {
                                        transitioned = false;
                                        turbulent = false;
                                    }
                                    station2_only(Regime::Laminar, &StationVars { s: n_amp, ..v2 })
                                }
                                Err(e) => Err(e),
                            }
                        }
                    }
                }
            };
            let Ok(cached) = kept else {
                last = None;
                break;
            };
            let (res, jac) = cached.local_system();
            let s_eval = transition_ctau.unwrap_or(s_now);
            last = Some((cached, [s_eval, th, ds, u], turbulent != was_turbulent_now));
            let v2 = StationVars {
                s: if turbulent { cti } else { n_amp },
                ..v2
            };
            let (hk, hk_d) = hk_at_state.take().unwrap_or_else(|| {
                let hk = model.kinematic_shape(&v2);
                (hk.value, hk.d)
            });
            if itbl == 0 {
                (ueref, hkref) = reference.unwrap_or((u, hk));
                // A station that was turbulent and is laminar now: extrapolate the reference
                // Hk from upstream (XFOIL MRCHDU), weighted by the turbulent fraction of the
                // old transition interval if the station was the first turbulent one.
                if !turbulent && was_turbulent && st.kind == StationKind::Interval {
                    let p = st.upstream.unwrap_or(k - 1);
                    let hk_upstream = model.kinematic_shape(&state.vars(layout, p)).value;
                    let weight = match turbulent_fraction[side] {
                        Some(f) if !old_turbulent[p] => f,
                        _ => 1.0,
                    };
                    hkref = hk + weight * (hk_upstream - hk);
                }
            }
            let mut a = [[0.0; 4]; 4];
            let mut b = [0.0; 4];
            for r in 0..3 {
                a[r] = jac[r];
                b[r] = -res[r];
            }
            if matches!(st.kind, StationKind::Similarity | StationKind::WakeStart) {
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
                            sens = sennew;
                        } else {
                            sens = 0.5 * (sens + sennew);
                        }
                    }
                }
                a[3] = [
                    0.0,
                    hk_d[0] * hkref,
                    hk_d[1] * hkref,
                    hk_d[2] * hkref + sens / ueref,
                ];
                b[3] = -(hkref * hkref * (hk / hkref - 1.0) + sens * (u / ueref - 1.0));
            }
            let Some(dx) = solve(a, b) else { break };
            let mut dmax = (dx[1] / th)
                .abs()
                .max((dx[2] / ds).abs())
                .max((dx[3] / u).abs());
            if turbulent {
                dmax = dmax.max((dx[0] / (10.0 * cti)).abs());
            }
            last_dmax = dmax;
            let damping_factor = match damping.as_mut() {
                Some(d) => {
                    let rel = [
                        if turbulent { dx[0] / cti } else { dx[0] / 10.0 },
                        dx[1] / th,
                        dx[2] / ds,
                        dx[3] / u,
                    ];
                    d.factor(rel, turbulent)
                }
                None => 1.0,
            };
            let rlx = damping_factor
                * if dmax > params.max_relative_step {
                    params.max_relative_step / dmax
                } else {
                    1.0
                };
            if turbulent {
                cti = (cti + rlx * dx[0]).clamp(1e-7, 0.30);
            } else {
                n_amp += rlx * dx[0];
            }
            th += rlx * dx[1];
            ds += rlx * dx[2];
            u += rlx * dx[3];
            if !(th > 0.0 && u > 0.0 && ds.is_finite()) {
                break;
            }
            // Shape-factor floor (XFOIL DSLIM).
            let hk_new = model.kinematic_shape(&StationVars {
                x: st.xi,
                u,
                theta: th,
                dstar: ds,
                s: 0.0,
                dw: st.wake_gap,
            });
            if hk_new.value < hk_floor && hk_new.d[1] > 0.0 {
                ds += (hk_floor - hk_new.value) / hk_new.d[1];
            } else {
                // Hk does not depend on the shear variable: the next iteration's Hk.
                hk_at_state = Some((hk_new.value, hk_new.d));
            }
            if dmax <= params.mixed_mode_tolerance {
                converged = true;
                break;
            }
        }
        let sane = th > 0.0 && u > 0.0 && ds.is_finite() && th.is_finite() && u.is_finite();
        // The kept equations, completed with station 1's Jacobian if they lack it.
        let kept = match last {
            Some((kept, at, false)) if converged && sane => match kept {
                KeptEquations::Complete(c) => Some((c, at)),
                KeptEquations::Downstream(d) => upstream
                    .as_ref()
                    .and_then(|up| model.complete_interval(up, &d).ok())
                    .map(|e| (CachedEquations::Interval(e, None), at)),
            },
            _ => None,
        };
        if let Some((eqs, at)) = kept {
            // Residuals moved linearly to the final local state.
            let s_final = if turbulent { cti } else { n_amp };
            let delta = [s_final - at[0], th - at[1], ds - at[2], u - at[3]];
            let shift = |res: &mut [f64; 3], d: &[[f64; 5]; 3]| {
                for (r, row) in res.iter_mut().zip(d) {
                    *r += row[..4].iter().zip(&delta).map(|(a, b)| a * b).sum::<f64>();
                }
            };
            cache[k] = Some(match eqs {
                CachedEquations::Interval(mut e, tr) => {
                    shift(&mut e.res, &e.d2);
                    CachedEquations::Interval(e, tr)
                }
                CachedEquations::Junction(mut j) => {
                    shift(&mut j.res, &j.d_wake);
                    CachedEquations::Junction(j)
                }
            });
        }
        let fell_back =
            !converged && (!sane || last_dmax > 0.1) && st.kind == StationKind::Interval;
        if fell_back
            && upstream_fell_back
            && turbulent
            && was_turbulent
            && params.keep_state_in_fallback_chains
        {
            // Inside a chain of failed stations: keep the Newton step's state.
            [cti, th, ds, u] = start;
        } else if fell_back {
            // Garbage: extrapolate from upstream (XFOIL MRCHDU fallback).
            let p = st.upstream.unwrap_or(k.saturating_sub(1));
            let xp = layout.stations[p].xi.max(1e-12);
            u = state.ue[p];
            if wake {
                th = state.theta[p];
                let ratlen = (st.xi - xp) / (10.0 * state.dstar(p));
                ds = (state.dstar(p) + th * ratlen) / (1.0 + ratlen);
            } else {
                let f = (st.xi / xp).sqrt();
                th = state.theta[p] * f;
                ds = state.dstar(p) * f;
            }
            if transitioned {
                cti = 0.05;
            } else if turbulent {
                cti = state.s[p].clamp(1e-7, 0.25);
            }
        }
        upstream_fell_back = fell_back;
        if turbulent && !wake {
            surface_turbulent[side] = true;
        }
        let lim = params.carried_correction_limit;
        carried[side] = (carry_corrections && lim > 0.0 && converged && turbulent && was_turbulent)
            .then(|| {
                let now = [cti, th, ds, u];
                std::array::from_fn(|i| (now[i] / start[i] - 1.0).clamp(-lim, lim))
            });
        state.s[k] = if turbulent { cti } else { n_amp.max(0.0) };
        state.theta[k] = th;
        state.ue[k] = u;
        state.mass[k] = ds * u;
        state.turbulent[k] = turbulent || wake;
    }
    cache
}
