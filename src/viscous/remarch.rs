//! Mixed-mode re-march of the boundary layer before each global Newton iteration (XFOIL xbl.f
//! MRCHDU, Drela 1989 §4.2): each station's local Newton iteration ([`super::local_newton`])
//! with a prescribed combination of Ue and Hk, the equations it leaves for the assembly, and
//! what a station that fails falls back to.

mod local;

use local::{KeptEquations, OscillationDamping};

use super::local_newton::iterate;
use super::march::MarchParams;
use super::newton::CachedEquations;
use super::params::SideModels;
use super::state::BlState;
use super::stations::{Station, StationKind, StationLayout, Surface};
use super::update::UpdateLimits;
use crate::boundary_layer::{BlModel, Regime, StationVars, UpstreamStation};

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
/// gave them (the measured effect is in docs/performance.md).
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
/// ([`super::ViscousParams::carry_corrections_below`]).
#[allow(clippy::too_many_arguments)]
pub fn remarch_mixed(
    models: &SideModels,
    layout: &StationLayout,
    state: &mut BlState,
    xi_forced: [Option<f64>; 2],
    turbulent_fraction: [Option<f64>; 2],
    carry_corrections: bool,
    ante: f64,
    params: &MarchParams,
    limits: &UpdateLimits,
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
        let side = usize::from(layout.stations[k].surface != Surface::Upper);
        let march = Remarch {
            model: &models[side],
            layout,
            xi_forced: xi_forced[side],
            turbulent_fraction: turbulent_fraction[side],
            old_turbulent: &old_turbulent,
            ante,
            params,
            hk_floor: limits.hk_floor(layout.stations[k].surface == Surface::Wake),
        };
        let mut station = march.start(state, k, surface_turbulent[side], carried[side], sens);
        iterate(
            &mut station,
            params.max_iterations,
            params.max_relative_step,
        );
        sens = station.sens;
        cache[k] = station.kept_equations();
        let fell_back = station.failed();
        if fell_back {
            let keep = upstream_fell_back
                && station.turbulent
                && station.was_turbulent
                && params.keep_state_in_fallback_chains;
            station.fall_back(state, keep);
        }
        upstream_fell_back = fell_back;
        if station.turbulent && !station.wake {
            surface_turbulent[side] = true;
        }
        let lim = params.carried_correction_limit;
        carried[side] = (carry_corrections
            && lim > 0.0
            && station.converged
            && station.turbulent
            && station.was_turbulent)
            .then(|| {
                let now = [station.cti, station.th, station.ds, station.u];
                let start = station.start;
                std::array::from_fn(|i| (now[i] / start[i] - 1.0).clamp(-lim, lim))
            });
        state.s[k] = if station.turbulent {
            station.cti
        } else {
            station.n_amp.max(0.0)
        };
        state.theta[k] = station.th;
        state.ue[k] = station.u;
        state.mass[k] = station.ds * station.u;
        state.turbulent[k] = station.turbulent || station.wake;
    }
    cache
}

/// What a re-march shares between its stations.
struct Remarch<'a> {
    model: &'a BlModel,
    layout: &'a StationLayout,
    /// ξ of forced transition on the surface of the station.
    xi_forced: Option<f64>,
    /// Turbulent fraction of the old transition interval on that surface.
    turbulent_fraction: Option<f64>,
    /// The regimes of the state before the re-march.
    old_turbulent: &'a [bool],
    /// Trailing-edge gap (XFOIL ANTE), for the first wake station.
    ante: f64,
    params: &'a MarchParams,
    /// Lowest Hk of the station (XFOIL DSLIM HKLIM).
    hk_floor: f64,
}

/// One station of the re-march with its local unknowns, its references and what its local
/// iteration left.
struct MixedStation<'a> {
    march: Remarch<'a>,
    k: usize,
    st: Station,
    wake: bool,
    /// The station was turbulent before the re-march.
    was_turbulent: bool,
    /// The state the Newton step left, (√Cτ, θ, δ*, Ue).
    start: [f64; 4],
    /// Reference (Ue, Hk) of a carried start, if any.
    reference: Option<(f64, f64)>,
    /// The fixed upstream station of an interval, its closures evaluated once (laminar: the
    /// transition check and the laminar interval share it).
    upstream: Option<UpstreamStation>,
    /// Both trailing-edge stations, for the first wake station.
    trailing_edge: Option<(StationVars, StationVars)>,
    /// Unknowns: √Cτ, N, θ, δ*, Ue (the shear variable is √Cτ or N by regime).
    cti: f64,
    n_amp: f64,
    th: f64,
    ds: f64,
    u: f64,
    turbulent: bool,
    /// Transition was found in the interval ending here.
    transitioned: bool,
    /// Reference Ue and Hk of the prescribed combination.
    ueref: f64,
    hkref: f64,
    /// Ue–Hk characteristic slope (XFOIL SENS), carried from station to station.
    sens: f64,
    /// Hk and its sensitivities at the current (u, θ, δ*), if already known.
    hk_at_state: Option<(f64, [f64; 3])>,
    /// Damping of oscillating iterations, where the transition check runs.
    damping: Option<OscillationDamping>,
    /// Equations of the last local iteration, the variables they were evaluated at
    /// (s, θ, δ*, u) and whether the regime changed in that iteration.
    last: Option<(KeptEquations, [f64; 4], bool)>,
    converged: bool,
    /// Largest relative change of the last step.
    last_dmax: f64,
}

impl<'a> Remarch<'a> {
    /// Station `k` set up from `state`: its start, its upstream station and, with carried
    /// corrections of the upstream station, its scaled starting guess.
    fn start(
        self,
        state: &BlState,
        k: usize,
        surface_turbulent: bool,
        carried: Option<[f64; 4]>,
        sens: f64,
    ) -> MixedStation<'a> {
        let (model, layout, params) = (self.model, self.layout, self.params);
        let st = layout.stations[k];
        let wake = st.surface == Surface::Wake;
        let was_turbulent = self.old_turbulent[k];
        let mut u = state.ue[k].max(1e-6);
        let mut th = state.theta[k].max(1e-12);
        let hk_floor = self.hk_floor;
        let mut ds = (state.dstar(k) - st.wake_gap).max(hk_floor * th) + st.wake_gap;
        let (n_amp, mut cti) = if was_turbulent || wake {
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
        let turbulent = wake || surface_turbulent;
        if turbulent && !was_turbulent && !wake {
            let p = st.upstream.unwrap_or(k - 1);
            cti = state.s[p].clamp(1e-7, 0.25);
        }
        let start = [cti, th, ds, u];
        // Start from the upstream station's relative corrections where both stay turbulent.
        let upstream_stays_turbulent =
            st.upstream.is_some_and(|p| self.old_turbulent[p]) && (wake || surface_turbulent);
        let reference = match carried {
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
        let upstream = (st.kind == StationKind::Interval).then(|| {
            let regime = if wake {
                Regime::Wake
            } else if surface_turbulent {
                Regime::Turbulent
            } else {
                Regime::Laminar
            };
            let p = st.upstream.unwrap_or(k - 1);
            UpstreamStation::new(&state.vars(layout, p), regime)
        });
        let trailing_edge = (st.kind == StationKind::WakeStart).then(|| {
            let (ku, kl) = (layout.upper_te(), layout.lower_te());
            (state.vars(layout, ku), state.vars(layout, kl))
        });
        // Damping only where the transition check runs (laminar upstream station), the case it
        // is made for: on separated turbulent stations it steered negative-stall sweeps onto
        // another solution branch than XFOIL's (NACA 23012, Re 5e5, M 0.2, α ≤ −6°).
        let damping = upstream
            .as_ref()
            .is_some_and(|u| u.regime() == Regime::Laminar)
            .then(OscillationDamping::new);
        MixedStation {
            march: self,
            k,
            st,
            wake,
            was_turbulent,
            start,
            reference,
            upstream,
            trailing_edge,
            cti,
            n_amp,
            th,
            ds,
            u,
            turbulent,
            transitioned: false,
            ueref: u,
            hkref: 0.0,
            sens,
            hk_at_state: None,
            damping,
            last: None,
            converged: false,
            last_dmax: f64::INFINITY,
        }
    }
}

impl MixedStation<'_> {
    /// The kept equations, completed with station 1's Jacobian if they lack it, their
    /// residuals moved linearly to the final local state; `None` unless the local iteration
    /// converged without a regime change in its last iteration.
    fn kept_equations(&mut self) -> Option<CachedEquations> {
        let sane = self.sane();
        let (eqs, at) = match self.last.take() {
            Some((kept, at, false)) if self.converged && sane => match kept {
                KeptEquations::Complete(c) => (c, at),
                KeptEquations::Downstream(d) => {
                    let up = self.upstream.as_ref()?;
                    let e = self.march.model.complete_interval(up, &d).ok()?;
                    (CachedEquations::Interval(e, None), at)
                }
            },
            _ => return None,
        };
        let s_final = if self.turbulent { self.cti } else { self.n_amp };
        let delta = [
            s_final - at[0],
            self.th - at[1],
            self.ds - at[2],
            self.u - at[3],
        ];
        let shift = |res: &mut [f64; 3], d: &[[f64; 5]; 3]| {
            for (r, row) in res.iter_mut().zip(d) {
                *r += row[..4].iter().zip(&delta).map(|(a, b)| a * b).sum::<f64>();
            }
        };
        Some(match eqs {
            CachedEquations::Interval(mut e, tr) => {
                shift(&mut e.res, &e.d2);
                CachedEquations::Interval(e, tr)
            }
            CachedEquations::Junction(mut j) => {
                shift(&mut j.res, &j.d_wake);
                CachedEquations::Junction(j)
            }
        })
    }

    /// The unknowns are usable: finite, θ and Ue positive.
    fn sane(&self) -> bool {
        let (th, ds, u) = (self.th, self.ds, self.u);
        th > 0.0 && u > 0.0 && ds.is_finite() && th.is_finite() && u.is_finite()
    }

    /// An interval station whose local iteration failed: not converged, and its unknowns
    /// unusable or its last step still large.
    fn failed(&self) -> bool {
        !self.converged
            && (!self.sane() || self.last_dmax > 0.1)
            && self.st.kind == StationKind::Interval
    }

    /// Replaces the unknowns of a failed station: with `keep`, by the state the Newton step
    /// left (inside a chain of failed stations); otherwise by XFOIL MRCHDU's extrapolation
    /// from the upstream station.
    fn fall_back(&mut self, state: &BlState, keep: bool) {
        if keep {
            [self.cti, self.th, self.ds, self.u] = self.start;
            return;
        }
        let (st, k) = (self.st, self.k);
        let p = st.upstream.unwrap_or(k.saturating_sub(1));
        let xp = self.march.layout.stations[p].xi.max(1e-12);
        self.u = state.ue[p];
        if self.wake {
            self.th = state.theta[p];
            let ratlen = (st.xi - xp) / (10.0 * state.dstar(p));
            self.ds = (state.dstar(p) + self.th * ratlen) / (1.0 + ratlen);
        } else {
            let f = (st.xi / xp).sqrt();
            self.th = state.theta[p] * f;
            self.ds = state.dstar(p) * f;
        }
        if self.transitioned {
            self.cti = 0.05;
        } else if self.turbulent {
            self.cti = state.s[p].clamp(1e-7, 0.25);
        }
    }
}
