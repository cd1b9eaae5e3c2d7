//! The viscous–inviscid solver of one airfoil at one flow condition (XFOIL VISCAL,
//! Drela 1989): initial march, global Newton iterations with relaxation and stagnation-point
//! moves, retry from a fresh march on failure, and the integrated results.

use std::sync::Arc;

use crate::boundary_layer::BlModel;
use crate::geometry::Airfoil;
use crate::inviscid::PanelGeometry;
use crate::numerics::cycle::repeating_period;
use crate::section::PolarPoint;
use crate::section::{Transition, FREE_XTR};

use super::error::ViscousError;
use super::march::march;
use super::newton::{assemble, Coupling};
use super::panel_model::{PanelModel, SharedPanels};
use super::params::{SideModels, ViscousParams};
use super::remarch::remarch_mixed;
use super::solution::{failed_solution, solution, Attempt, ViscousSolution};
use super::state::BlState;
use super::stations::{StationLayout, Surface};
use super::tangent::Tangent;
#[cfg(test)]
use super::update::UpdateLimits;
use super::update::{apply_update, UpdateResult};

/// Memory of a [`ViscousSolver::settled_state`] per node of the panel model (airfoil and wake):
/// its station layout (≈ 56 bytes a station) and boundary-layer variables (33), measured as
/// 17.5 kB a state on the default 160-panel NACA 8-H-12 (183 nodes; a default table's 3 904
/// states took 68 MB).
pub const SETTLED_STATE_BYTES_PER_NODE: usize = 96;

/// Opaque snapshot of a solver's warm-start state (see [`ViscousSolver::warm_start`]).
#[derive(Clone, Debug)]
pub struct WarmStart(Option<WarmState>);

/// Converged state kept for warm starts.
#[derive(Clone, Debug)]
struct WarmState {
    layout: StationLayout,
    state: BlState,
    /// Its derivative along α, for the predicted start of the next point.
    tangent: Option<Tangent>,
    /// Per surface, the turbulent fraction of the transition interval of the converged state
    /// ([`super::newton::TransitionPoint::turbulent_fraction`]).
    turbulent_fraction: [Option<f64>; 2],
    /// The predictor step that moved the state from the converged one (None: not moved).
    predicted: Option<UpdateResult>,
}

/// Where the inviscid data come from.
#[derive(Debug)]
enum PanelSource {
    /// Fixed data, independent of α (prepared by the caller).
    Fixed,
    /// A panel system; wake and source influence follow α (XFOIL re-traces the wake when α
    /// changes: LWAKE, QDCALC), built once per α for all solvers sharing the store.
    Airfoil(Arc<SharedPanels>),
}

/// A trip this far (in chords of arc length) upstream of the stagnation point on its surface
/// counts as at the stagnation point: a trip at x/c = 0 on a symmetric section at α = 0 acts
/// on both surfaces, not on whichever side round-off puts the stagnation point.
const TRIP_AT_STAGNATION: f64 = 1e-6;

/// How many repeats of a block of RMS changes make a cycle ([`ViscousParams::cycle_period`]):
/// two, so that the block is seen three times in a row.
const CYCLE_REPEATS: usize = 2;

/// Relative tolerance within which RMS changes count as repeats
/// ([`ViscousParams::cycle_period`]). The cycles of failing attempts repeat to 1e-9…1e-12;
/// the first attempt that converged anyway appears at 1e-2 (NACA 8-H-12 default table).
const CYCLE_RTOL: f64 = 1e-6;

/// Where in the first interval a trip between the stagnation point and the first station acts,
/// as a fraction of the interval ([`ViscousSolver::forced_xi`]): at its start, just inside the
/// interval so that the interval's transition check meets it.
const FIRST_STATION_TRIP: f64 = 1e-6;

/// Arc length s of the trip on each surface (upper, lower) of the contour: where the chord
/// fraction ([`ContourSpline::chord_fraction`]) first reaches the trip x/c, walking from the
/// leading edge along that surface (XFOIL XIFSET: SINVRT on the chord-based x/c). `None` for
/// free transition; the surface's TE end for a trip the surface never reaches.
///
/// [`ContourSpline::chord_fraction`]: crate::geometry::ContourSpline::chord_fraction
#[derive(Clone, Copy, Debug, PartialEq)]
struct TripArcs([Option<f64>; 2]);

impl TripArcs {
    fn new(contour: &PanelGeometry, transition: &Transition) -> Self {
        let s = &contour.s;
        let ends = [s[0], s[s.len() - 1]];
        let arc = |side: usize, xtr: f64| {
            (xtr < FREE_XTR).then(|| {
                contour
                    .spline
                    .arc_at_chord_fraction(contour.s_le, xtr, side == 0)
                    .unwrap_or(ends[side])
            })
        };
        Self([arc(0, transition.xtr_top), arc(1, transition.xtr_bot)])
    }
}

/// Viscous–inviscid solver for one airfoil and one (Re, M, Ncrit, trip) condition.
/// Holds its own state; many solvers can run in parallel.
#[derive(Debug)]
pub struct ViscousSolver {
    params: ViscousParams,
    source: PanelSource,
    /// Inviscid data of the current α (or the fixed data).
    panels: Arc<PanelModel>,
    /// α of `panels` for an airfoil source.
    panels_alpha: Option<f64>,
    /// Boundary-layer models of the two sides.
    bl: SideModels,
    /// Where the trips are on the contour.
    trips: TripArcs,
    warm: Option<WarmState>,
    /// α of the last fresh-start attempt that failed. A fresh start depends on α alone, so
    /// it is not repeated at that α (sweep recoveries revisit a failed α several times).
    fresh_failed_at: Option<f64>,
    /// Work done so far.
    work: SolverWork,
    /// The attempts' n × n matrices, kept between attempts.
    memory: AttemptMemory,
}

/// Memory of an attempt's two n × n matrices (n ≈ 200 stations, ≈ 0.3 MB each), kept by the
/// solver from one attempt to the next: a new allocation of that size would be fresh pages
/// from the system at every α (page faults and zero-filling).
#[derive(Debug, Default)]
struct AttemptMemory {
    /// The Schur complement of the block solve ([`BlockSystem::factor_and_solve`]).
    schur: Vec<f64>,
    /// dUe/dm between the stations ([`PanelModel::edge_speed_influence_into`]).
    dv: Vec<f64>,
}

/// The work a solver has done since it was built: what the cost of a sweep is counted in
/// (the cost model of `benches/`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SolverWork {
    /// Newton attempts: from a converged neighbour (directly or predicted) or a fresh march.
    pub attempts: u64,
    /// Global Newton iterations of all attempts.
    pub newton_iterations: u64,
}

impl ViscousSolver {
    /// Solver from prepared inviscid data (see [`PanelModel`]).
    pub fn from_panel_model(
        panels: PanelModel,
        params: ViscousParams,
    ) -> Result<Self, ViscousError> {
        panels.check()?;
        params.check()?;
        let bl = params.boundary_layer()?;
        let trips = TripArcs::new(&panels.airfoil, &params.transition);
        Ok(Self {
            params,
            source: PanelSource::Fixed,
            panels: Arc::new(panels),
            panels_alpha: None,
            bl,
            trips,
            warm: None,
            fresh_failed_at: None,
            work: SolverWork::default(),
            memory: AttemptMemory::default(),
        })
    }

    /// Solver for an already paneled airfoil (XFOIL order, e.g. from the geometry module's
    /// repaneling): builds the panel system and its unit solutions once.
    pub fn new(airfoil: &Airfoil, params: ViscousParams) -> Result<Self, ViscousError> {
        params.check()?;
        Self::with_panels(Arc::new(SharedPanels::new(airfoil)?), params)
    }

    /// Solver on a panel store shared with other solvers of the same airfoil (other flow
    /// conditions, other threads): each per-α inviscid model is built once for all of them.
    pub fn with_panels(
        shared: Arc<SharedPanels>,
        params: ViscousParams,
    ) -> Result<Self, ViscousError> {
        params.check()?;
        let panels = shared.model(0.0)?;
        let bl = params.boundary_layer()?;
        let trips = TripArcs::new(&panels.airfoil, &params.transition);
        Ok(Self {
            params,
            source: PanelSource::Airfoil(shared),
            panels,
            panels_alpha: Some(0.0),
            bl,
            trips,
            warm: None,
            fresh_failed_at: None,
            work: SolverWork::default(),
            memory: AttemptMemory::default(),
        })
    }

    /// The work done since the solver was built.
    pub fn work(&self) -> SolverWork {
        self.work
    }

    /// The parameters of this solver.
    pub fn params(&self) -> &ViscousParams {
        &self.params
    }

    /// Snapshot of the warm-start state (the converged boundary layer of the last point), for
    /// sweeps that branch from a saved point.
    pub fn warm_start(&self) -> WarmStart {
        WarmStart(self.warm.clone())
    }

    /// [`warm_start`](Self::warm_start) without the state's tangent along α: for a start at the
    /// same α under another condition (another Reynolds number of a table's grid), where
    /// there is no step to predict. About [`SETTLED_STATE_BYTES_PER_NODE`] per node of the
    /// panel model.
    pub fn settled_state(&self) -> WarmStart {
        WarmStart(self.warm.as_ref().map(|w| WarmState {
            layout: w.layout.clone(),
            state: w.state.clone(),
            tangent: None,
            turbulent_fraction: w.turbulent_fraction,
            predicted: w.predicted,
        }))
    }

    /// Return to a snapshot taken with [`warm_start`](Self::warm_start).
    pub fn set_warm_start(&mut self, snapshot: &WarmStart) {
        self.warm = snapshot.0.clone();
    }

    /// Forgets the warm-start state; the next point starts from a fresh march.
    pub fn reset(&mut self) {
        self.warm = None;
    }

    /// The boundary-layer closures and compressibility constants, which both sides share (the
    /// side models differ in N_crit only, which enters the amplification equation alone).
    fn closures(&self) -> &BlModel {
        &self.bl[0]
    }

    /// ξ of forced transition on each surface for the stagnation point of `layout` (XFOIL
    /// XIFSET), from the trips' arc lengths ([`TripArcs`]): the distance from the stagnation
    /// point to the trip along the surface, at most the TE ξ (XFOIL forces transition at the
    /// TE at the latest). Two cases XIFSET leaves to the marches:
    ///
    /// * the stagnation point lies downstream of the trip (ξ < 0, by more than
    ///   [`TRIP_AT_STAGNATION`]): the flow of that surface never passes the trip, transition is
    ///   free there (XIFSET's "stagnation point is past trip");
    /// * the trip lies between the stagnation point and the first station: transition at the
    ///   first station, the whole first interval turbulent. XFOIL's transition check starts at
    ///   the first interval and never meets such a trip, which leaves transition free on a
    ///   surface whose flow passes the trip.
    fn forced_xi(&self, layout: &StationLayout) -> [Option<f64>; 2] {
        let sst = layout.stagnation.sst;
        let mut out = [None, None];
        for (side, surface) in [Surface::Upper, Surface::Lower].into_iter().enumerate() {
            let sts = &layout.stations[layout.range(surface)];
            let xi_te = sts.last().map(|s| s.xi).unwrap_or(0.0);
            let xi_trip = match self.trips.0[side] {
                None => xi_te,
                Some(s_trip) => {
                    let xi = if surface == Surface::Upper {
                        sst - s_trip
                    } else {
                        s_trip - sst
                    };
                    match sts {
                        _ if xi < -TRIP_AT_STAGNATION => xi_te,
                        [first, second, ..] if xi <= first.xi => {
                            first.xi + FIRST_STATION_TRIP * (second.xi - first.xi)
                        }
                        _ => xi,
                    }
                }
            };
            out[side] = Some(xi_trip.min(xi_te));
        }
        out
    }

    /// Solves the viscous flow at angle of attack `alpha_deg` in one attempt, warm-starting
    /// from the previous converged state if there is one and from a fresh march otherwise. A
    /// point that fails is returned with `converged = false`, and so is a Newton-converged state
    /// with negative form drag ([`ViscousParams::min_pressure_drag`]); neither is kept as a warm
    /// start, so the next solve starts fresh. Retrying a failed point (from a nearer converged
    /// neighbour, or fresh) is the caller's choice: the sweeps' recovery does it. A fresh start
    /// that failed at some α is not repeated there (it would fail again).
    pub fn solve(&mut self, alpha_deg: f64) -> ViscousSolution {
        if !alpha_deg.is_finite() {
            return failed_solution(alpha_deg, 0);
        }
        if let PanelSource::Airfoil(shared) = &self.source {
            if self.panels_alpha != Some(alpha_deg) {
                match shared.model(alpha_deg) {
                    Ok(p) => {
                        self.panels = p;
                        self.panels_alpha = Some(alpha_deg);
                    }
                    Err(_) => return failed_solution(alpha_deg, 0),
                }
            }
        }
        let warm = self.warm.take();
        let fresh = warm.is_none();
        if fresh && self.fresh_failed_at == Some(alpha_deg) {
            return failed_solution(alpha_deg, 0);
        }
        let converged = |r: &Result<Attempt, ViscousError>| matches!(r, Ok(a) if a.converged);
        let (max, cap) = (self.params.max_iterations, self.params.predicted_iterations);
        let mut iterations = 0;
        let mut extra_attempts = 0;
        let mut memory = std::mem::take(&mut self.memory);
        let mut attempt = |warm, cap, iterations: &mut u32| {
            self.attempt(alpha_deg, warm, cap, iterations, &mut memory)
        };
        let result = match warm {
            // From the predicted state first; where that does not converge within its shorter
            // cap, from the converged state itself, as without a predictor.
            Some(w) => match self.predicted(&w, alpha_deg) {
                Some(p) => {
                    let r = attempt(Some(p), cap, &mut iterations);
                    if converged(&r) {
                        r
                    } else {
                        extra_attempts += 1;
                        attempt(Some(w), max, &mut iterations)
                    }
                }
                None => attempt(Some(w), max, &mut iterations),
            },
            None => attempt(None, max, &mut iterations),
        };
        self.memory = memory;
        self.work.attempts += 1 + extra_attempts;
        self.work.newton_iterations += u64::from(iterations);
        if fresh && !converged(&result) {
            self.fresh_failed_at = Some(alpha_deg);
        }
        match result {
            Ok(a) => {
                let mut sol = solution(&self.panels, self.closures(), alpha_deg, &a);
                // Every Newton iteration of the solve, a failed predicted attempt's included.
                sol.point.iterations = iterations;
                let physical = sol.point.cd - sol.point.cdf >= self.params.min_pressure_drag;
                if a.converged && sol.point.cl.is_finite() && sol.point.cd.is_finite() && physical {
                    self.warm = Some(WarmState {
                        layout: a.layout,
                        state: a.state,
                        tangent: a.tangent,
                        turbulent_fraction: a.turbulent_fraction,
                        predicted: None,
                    });
                    sol
                } else {
                    ViscousSolution {
                        point: PolarPoint {
                            converged: false,
                            ..sol.point
                        },
                        ..sol
                    }
                }
            }
            Err(_) => failed_solution(alpha_deg, iterations),
        }
    }

    /// The warm state moved along its tangent to `alpha_deg` ([`Tangent::predict`]), if it has
    /// one and the step is usable.
    fn predicted(&self, warm: &WarmState, alpha_deg: f64) -> Option<WarmState> {
        let tangent = warm.tangent.as_ref()?;
        let mut state = warm.state.clone();
        let limits = &self.params.limits;
        let step = tangent
            .predict(self.closures(), &warm.layout, &mut state, alpha_deg, limits)
            .ok()?;
        Some(WarmState {
            layout: warm.layout.clone(),
            state,
            tangent: None,
            turbulent_fraction: warm.turbulent_fraction,
            predicted: Some(step),
        })
    }

    /// One Newton attempt from a warm state or a fresh march.
    /// At most `max_iterations` Newton iterations, counted in `iterations`.
    fn attempt(
        &self,
        alpha_deg: f64,
        warm: Option<WarmState>,
        max_iterations: u32,
        iterations: &mut u32,
        memory: &mut AttemptMemory,
    ) -> Result<Attempt, ViscousError> {
        let n_af = self.panels.n_airfoil();
        let q_inv = self.panels.speeds(alpha_deg);
        let warm_started = warm.is_some();
        let predicted = warm.as_ref().and_then(|w| w.predicted);
        let mut turbulent_fraction = warm.as_ref().map_or([None, None], |w| w.turbulent_fraction);
        // The stagnation point of a warm start is where the warm state's viscous speed changes
        // sign (XFOIL VISCAL: GAMQV then STFIND), so that the remapped state and its edge speeds
        // agree; the Newton iterations then move it with the solution (STMOVE below).
        let q_start = match &warm {
            Some(w) => viscous_node_speed(&w.layout, &w.state, &q_inv),
            None => q_inv.clone(),
        };
        let mut layout = StationLayout::new(&self.panels, &q_start[..n_af])?;
        let mut ue_inv = layout.edge_speed(&q_inv);
        let dv = &mut memory.dv;
        self.panels.edge_speed_influence_into(&layout, dv);
        let mut xi_forced = self.forced_xi(&layout);
        let mut state = match warm {
            Some(w) => {
                let map = layout.map_from(&w.layout);
                let mut s = w.state.remap(&map, &w.layout, &layout);
                fix_crossed(
                    &mut s,
                    &map,
                    &w.layout,
                    &layout,
                    &layout.edge_speed(&q_start),
                );
                s
            }
            None => march(
                &self.bl,
                &layout,
                &ue_inv,
                xi_forced,
                self.panels.te_gap(),
                &self.params.march,
            ),
        };
        // A predicted start continues like the iteration after the step that moved it.
        let mut residual = predicted.map_or(f64::INFINITY, |p| p.rms_change);
        let mut stagnation_terms =
            !predicted.is_some_and(|p| p.max_change >= self.params.exploded_step);
        // Memory of the n × n Schur complement, reused by every iteration's solve.
        let schur = &mut memory.schur;
        let mut transition = [None, None];
        // RMS relative changes of the iterations so far, for the cycle check.
        let mut changes = Vec::with_capacity(max_iterations as usize);
        for iter in 1..=max_iterations {
            *iterations += 1;
            // Mixed-mode re-march (XFOIL MRCHDU) while the iteration is still far from
            // converged; close to convergence the Newton steps alone are quadratic.
            let remarch = residual > self.params.remarch_below;
            let cache = if remarch {
                remarch_mixed(
                    &self.bl,
                    &layout,
                    &mut state,
                    xi_forced,
                    turbulent_fraction,
                    warm_started && residual < self.params.carry_corrections_below,
                    self.panels.te_gap(),
                    &self.params.march,
                    &self.params.limits,
                )
            } else {
                Vec::new()
            };
            let coupling = Coupling {
                layout: &layout,
                ue_inv: &ue_inv,
                dv,
                xi_forced,
                ante: self.panels.te_gap(),
                ctau_sqrt_initial: self.params.march.ctau_sqrt_initial,
                regimes_known: remarch,
                stagnation_terms,
                cached: remarch.then_some(cache.as_slice()),
            };
            let asm = assemble(&self.bl, &coupling, &mut state)?;
            transition = [
                asm.transition[0].map(|t| t.xi),
                asm.transition[1].map(|t| t.xi),
            ];
            turbulent_fraction = asm
                .transition
                .map(|t| t.map(|t| t.turbulent_fraction(&layout)));
            let (system, w) = asm.system.factor_and_solve(schur)?;
            let upd = apply_update(
                self.closures(),
                &coupling,
                &mut state,
                &w,
                &asm.mismatch,
                &self.params.limits,
            )?;
            residual = upd.rms_change;
            changes.push(residual);
            // The converged state's tangent along α, from this iteration's factored matrix.
            let tangent = (residual < self.params.tolerance && self.params.tangent_predictor)
                .then(|| {
                    let ue_unit = self.panels.q_unit.each_ref().map(|q| layout.edge_speed(q));
                    Tangent::new(&system, &ue_unit, dv, alpha_deg).ok()
                })
                .flatten();
            drop(system);
            // A step whose relative changes reach 1e6 came from a near-singular system (the
            // stagnation point almost on a node, ξ → 0 at the first station): the next
            // iteration goes without the stagnation-point terms, whose linearisation is then
            // far outside its range.
            stagnation_terms = upd.max_change < self.params.exploded_step;
            // Move the stagnation point with the viscous surface speed (XFOIL STMOVE).
            let q_nodes = viscous_node_speed(&layout, &state, &q_inv);
            let mut tangent = tangent;
            if let Ok(new_layout) = StationLayout::new(&self.panels, &q_nodes[..n_af]) {
                if new_layout.stagnation.ist != layout.stagnation.ist {
                    // The tangent belongs to the old stations.
                    tangent = None;
                    let map = new_layout.map_from(&layout);
                    let mut s = state.remap(&map, &layout, &new_layout);
                    let ue_new = new_layout.edge_speed(&q_nodes);
                    fix_crossed(&mut s, &map, &layout, &new_layout, &ue_new);
                    state = s;
                    ue_inv = new_layout.edge_speed(&q_inv);
                    self.panels.edge_speed_influence_into(&new_layout, dv);
                }
                layout = new_layout;
                xi_forced = self.forced_xi(&layout);
            }
            if residual < self.params.tolerance {
                return Ok(Attempt {
                    layout,
                    state,
                    converged: true,
                    iterations: iter,
                    residual,
                    transition,
                    turbulent_fraction,
                    tangent,
                });
            }
            let period = self.params.cycle_period as usize;
            if period > 0 && repeating_period(&changes, period, CYCLE_REPEATS, CYCLE_RTOL).is_some()
            {
                break;
            }
        }
        Ok(Attempt {
            layout,
            state,
            converged: false,
            iterations: changes.len() as u32,
            residual,
            transition,
            turbulent_fraction,
            tangent: None,
        })
    }
}

/// Surface speed at every node from a boundary-layer state (XFOIL GAMQV: q = ±Ue at the
/// station's node); nodes without a station keep their value in `q_fallback`.
fn viscous_node_speed(layout: &StationLayout, state: &BlState, q_fallback: &[f64]) -> Vec<f64> {
    let mut q = q_fallback.to_vec();
    for (k, st) in layout.stations.iter().enumerate() {
        q[st.node] = st.vti * state.ue[k];
    }
    q
}

/// Gives stations whose node crossed the stagnation point the edge speed of the new layout and a
/// consistent mass defect.
fn fix_crossed(
    state: &mut BlState,
    map: &[usize],
    old: &StationLayout,
    new: &StationLayout,
    ue_new: &[f64],
) {
    for (k, &o) in map.iter().enumerate() {
        if old.stations[o].node != new.stations[k].node {
            let dstar = state.dstar(k);
            state.ue[k] = ue_new[k].max(1e-4);
            state.mass[k] = dstar * state.ue[k];
        }
    }
}

#[cfg(test)]
mod tests;
