//! The viscous–inviscid solver of one airfoil at one flow condition (XFOIL VISCAL,
//! Drela 1989): initial march, global Newton iterations with relaxation and stagnation-point
//! moves, retry from a fresh march on failure, and the integrated results.

use std::sync::Arc;

use crate::boundary_layer::{BlConditions, BlModel, BlParams, Regime};
use crate::geometry::Airfoil;
use crate::section::PolarPoint;

use super::error::ViscousError;
use super::forces::{friction_drag, lift_and_moment, transition_x};
use super::march::{march, remarch_mixed, MarchParams};
use super::newton::{assemble, Coupling};
use super::panel_model::{PanelModel, SharedPanels};
use super::state::BlState;
use super::stations::{StationLayout, Surface};
use super::update::{apply_update, UpdateLimits};

/// Parameters of a viscous solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViscousParams {
    /// Chord Reynolds number V∞c/ν.
    pub reynolds: f64,
    /// Free-stream Mach number (Karman–Tsien compressibility).
    pub mach: f64,
    /// Critical amplification ratio of the e^n method (XFOIL default 9).
    pub ncrit: f64,
    /// Forced transition x/c on the upper surface (≥ 1 = free transition).
    pub xtr_top: f64,
    /// Forced transition x/c on the lower surface (≥ 1 = free transition).
    pub xtr_bot: f64,
    /// Newton iteration cap per attempt.
    pub max_iterations: u32,
    /// Convergence threshold on the RMS relative Newton change. XFOIL's EPS1 is 1e-4; the
    /// default here is 1e-3. Newton converges quadratically at this stage, so the change a
    /// further iteration would make is far smaller: logged over the four default rotor grids,
    /// its median was 8e-7 and its 99th percentile 5e-5 (largest 9e-4, a slowly converging
    /// stall point). Against 1e-4, the points of those grids moved by a median |ΔCl| of 1e-8
    /// (99th percentile 1.5e-5) and |ΔCd|/Cd of 1e-7 (4e-5), except stall points that changed
    /// branch; the agreement with XFOIL's printed polars moved by ≤ 0.001 % in the median
    /// |ΔCd|/Cd and ≤ 4e-7 in the largest |ΔCl| (`tests/viscous_polars.rs`). The paper's free
    /// sweep needs 179 Newton iterations instead of 275.
    pub tolerance: f64,
    /// Relaxation and clipping limits of the update (XFOIL UPDATE).
    pub limits: UpdateLimits,
    /// Controls of the initial march (XFOIL MRCHUE).
    pub march: MarchParams,
    /// The mixed-mode re-march before each Newton iteration (XFOIL MRCHDU) is skipped once the
    /// RMS relative Newton change is below this value (0 = always re-march, as XFOIL).
    pub remarch_below: f64,
    /// In warm-started attempts, the re-march starts turbulent and wake stations from their
    /// upstream station's corrections ([`MarchParams::carried_correction_limit`]) after a Newton
    /// step whose RMS relative change was below this value. After larger steps (the first
    /// iteration of an attempt, and the wandering iterations of hard points) and in fresh
    /// starts, XFOIL's plain start is kept: with the carried start there too, hard points at
    /// Re 2.5e5 (NACA 8-H-12 xtr 0.07, M 0.2, α 12–18°; NACA 23012 free, M 0.3, α 11–16°)
    /// wandered onto a branch with 6–8 % less lift than XFOIL's, which they had followed, and
    /// the fresh start of the 8-H-12 at Re 5e5, M 0.3, α 0° no longer converged.
    pub carry_corrections_below: f64,
    /// Lowest accepted pressure (form) drag cd − cdf. A Newton-converged state whose
    /// Squire–Young drag lies further below its skin-friction drag has negative form drag: a
    /// spurious solution branch (seen in negative stall), reported as not converged so that a
    /// sweep retries the point. −2e-4 leaves room for the round-off of attached flow, where the
    /// form drag is near zero.
    pub min_pressure_drag: f64,
    /// Largest relative change of a Newton step (XFOIL RMXBL) above which the step is taken to
    /// come from a near-singular system (stagnation point almost on a node); the next
    /// iteration then goes without the stagnation-point terms of ξ.
    pub exploded_step: f64,
}

impl Default for ViscousParams {
    fn default() -> Self {
        Self {
            reynolds: 1.0e6,
            mach: 0.0,
            ncrit: 9.0,
            xtr_top: 1.0,
            xtr_bot: 1.0,
            max_iterations: 100,
            tolerance: 1e-3,
            limits: UpdateLimits::default(),
            march: MarchParams::default(),
            remarch_below: 0.0,
            carry_corrections_below: 1.0,
            min_pressure_drag: -2e-4,
            exploded_step: 1e6,
        }
    }
}

impl ViscousParams {
    /// The defaults at one flow condition: Reynolds number, Mach number, and transition forced
    /// at x/c = `xtr` on both surfaces (1 = free transition).
    pub fn at(reynolds: f64, mach: f64, xtr: f64) -> Self {
        Self {
            reynolds,
            mach,
            xtr_top: xtr,
            xtr_bot: xtr,
            ..Self::default()
        }
    }
}

/// One boundary-layer station of a solution, for plots and debugging.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlStation {
    /// ξ: arc length from the stagnation point, in chords.
    pub s: f64,
    /// x coordinate of the station.
    pub x: f64,
    /// y coordinate of the station.
    pub y: f64,
    /// Edge speed Ue/V∞ (incompressible, as the panel method sees it).
    pub ue: f64,
    /// Displacement thickness δ* (wake: including the wake gap).
    pub dstar: f64,
    /// Momentum thickness θ.
    pub theta: f64,
    /// Skin-friction coefficient based on the edge dynamic pressure (0 in the wake).
    pub cf: f64,
    /// Skin friction referred to the free-stream dynamic pressure, τw/(½ρ∞V∞²) = Cf·ρe·Ue,c²
    /// (the "Cf" column of XFOIL's DUMP).
    pub cf_inf: f64,
    /// Shape factor H = δ*/θ.
    pub h: f64,
    /// Kinematic shape factor Hk.
    pub hk: f64,
    /// N (laminar) or Cτ (turbulent).
    pub n_or_ctau: f64,
    /// Whether the station is turbulent.
    pub turbulent: bool,
}

/// Result of one viscous operating point.
#[derive(Clone, Debug, PartialEq)]
pub struct ViscousSolution {
    /// Integrated coefficients and convergence information.
    pub point: PolarPoint,
    /// Upper-surface stations, stagnation point → TE.
    pub upper: Vec<BlStation>,
    /// Lower-surface stations, stagnation point → TE.
    pub lower: Vec<BlStation>,
    /// Wake stations, TE → wake end.
    pub wake: Vec<BlStation>,
}

/// Opaque snapshot of a solver's warm-start state (see [`ViscousSolver::warm_start`]).
#[derive(Clone, Debug)]
pub struct WarmStart(Option<WarmState>);

/// Converged state kept for warm starts.
#[derive(Clone, Debug)]
struct WarmState {
    layout: StationLayout,
    state: BlState,
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
    bl: BlModel,
    warm: Option<WarmState>,
    /// α of the last fresh-start attempt that failed. A fresh start depends on α alone, so
    /// it is not repeated at that α (sweep recoveries revisit a failed α several times).
    fresh_failed_at: Option<f64>,
}

/// Outcome of one Newton attempt.
struct Attempt {
    layout: StationLayout,
    state: BlState,
    converged: bool,
    iterations: u32,
    residual: f64,
    transition: [Option<f64>; 2],
}

impl ViscousSolver {
    /// Solver from prepared inviscid data (see [`PanelModel`]).
    pub fn from_panel_model(
        panels: PanelModel,
        params: ViscousParams,
    ) -> Result<Self, ViscousError> {
        panels.check()?;
        Self::check_params(&params)?;
        let bl = boundary_layer_model(&params)?;
        Ok(Self {
            params,
            source: PanelSource::Fixed,
            panels: Arc::new(panels),
            panels_alpha: None,
            bl,
            warm: None,
            fresh_failed_at: None,
        })
    }

    /// Solver for an already paneled airfoil (XFOIL order, e.g. from the geometry module's
    /// repaneling): builds the panel system and its unit solutions once.
    pub fn new(airfoil: &Airfoil, params: ViscousParams) -> Result<Self, ViscousError> {
        Self::check_params(&params)?;
        Self::with_panels(Arc::new(SharedPanels::new(airfoil)?), params)
    }

    /// Solver on a panel store shared with other solvers of the same airfoil (other flow
    /// conditions, other threads): each per-α inviscid model is built once for all of them.
    pub fn with_panels(
        shared: Arc<SharedPanels>,
        params: ViscousParams,
    ) -> Result<Self, ViscousError> {
        Self::check_params(&params)?;
        let panels = shared.model(0.0)?;
        let bl = boundary_layer_model(&params)?;
        Ok(Self {
            params,
            source: PanelSource::Airfoil(shared),
            panels,
            panels_alpha: Some(0.0),
            bl,
            warm: None,
            fresh_failed_at: None,
        })
    }

    /// Rejects non-physical parameters.
    fn check_params(params: &ViscousParams) -> Result<(), ViscousError> {
        for (name, value, ok) in [
            ("reynolds", params.reynolds, params.reynolds > 0.0),
            ("mach", params.mach, (0.0..1.0).contains(&params.mach)),
            ("ncrit", params.ncrit, params.ncrit > 0.0),
            ("xtr_top", params.xtr_top, params.xtr_top >= 0.0),
            ("xtr_bot", params.xtr_bot, params.xtr_bot >= 0.0),
            ("tolerance", params.tolerance, params.tolerance > 0.0),
        ] {
            if !(value.is_finite() && ok) {
                return Err(ViscousError::BadParameter { name, value });
            }
        }
        Ok(())
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

    /// Return to a snapshot taken with [`warm_start`](Self::warm_start).
    pub fn set_warm_start(&mut self, snapshot: &WarmStart) {
        self.warm = snapshot.0.clone();
    }

    /// Forgets the warm-start state; the next point starts from a fresh march.
    pub fn reset(&mut self) {
        self.warm = None;
    }

    /// ξ of forced transition on each surface: the trip x/c converted to ξ along that surface
    /// (XFOIL XIFSET), at most the TE ξ (XFOIL forces transition at the TE at the latest).
    fn forced_xi(&self, layout: &StationLayout) -> [Option<f64>; 2] {
        let g = &self.panels.airfoil;
        let mut out = [None, None];
        for (side, (surface, xtr)) in [
            (Surface::Upper, self.params.xtr_top),
            (Surface::Lower, self.params.xtr_bot),
        ]
        .into_iter()
        .enumerate()
        {
            let range = layout.range(surface);
            let sts = &layout.stations[range];
            let xi_te = sts.last().map(|s| s.xi).unwrap_or(0.0);
            let mut xi_trip = xi_te;
            if xtr < 1.0 {
                for w in sts.windows(2) {
                    let (x1, x2) = (g.x[w[0].node], g.x[w[1].node]);
                    if x1 < xtr && x2 >= xtr {
                        let f = (xtr - x1) / (x2 - x1);
                        xi_trip = w[0].xi + f * (w[1].xi - w[0].xi);
                        break;
                    }
                }
            }
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
        let result = self.attempt(alpha_deg, warm);
        if fresh && !matches!(&result, Ok(a) if a.converged) {
            self.fresh_failed_at = Some(alpha_deg);
        }
        match result {
            Ok(a) => {
                let sol = self.solution(alpha_deg, &a);
                let physical = sol.point.cd - sol.point.cdf >= self.params.min_pressure_drag;
                if a.converged && sol.point.cl.is_finite() && sol.point.cd.is_finite() && physical {
                    self.warm = Some(WarmState {
                        layout: a.layout,
                        state: a.state,
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
            Err(_) => failed_solution(alpha_deg, self.params.max_iterations),
        }
    }

    /// One Newton attempt from a warm state or a fresh march.
    fn attempt(&self, alpha_deg: f64, warm: Option<WarmState>) -> Result<Attempt, ViscousError> {
        let n_af = self.panels.n_airfoil();
        let q_inv = self.panels.speeds(alpha_deg);
        let warm_started = warm.is_some();
        // The stagnation point of a warm start is where the warm state's viscous speed changes
        // sign (XFOIL VISCAL: GAMQV then STFIND), so that the remapped state and its edge speeds
        // agree; the Newton iterations then move it with the solution (STMOVE below).
        let q_start = match &warm {
            Some(w) => viscous_node_speed(&w.layout, &w.state, &q_inv),
            None => q_inv.clone(),
        };
        let mut layout = StationLayout::new(&self.panels, &q_start[..n_af])?;
        let mut ue_inv = layout.edge_speed(&q_inv);
        let mut dv = self.panels.edge_speed_influence(&layout);
        let mut xi_forced = self.forced_xi(&layout);
        let mut state = match warm {
            Some(w) => {
                let map = layout.map_from(&w.layout);
                let mut s = w.state.remap(&map, &w.layout, &layout);
                fix_crossed(&mut s, &map, &w.layout, &layout, &ue_inv);
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
        let mut residual = f64::INFINITY;
        // Memory of the n × n Schur complement, reused by every iteration's solve.
        let mut schur = Vec::new();
        let mut stagnation_terms = true;
        let mut transition = [None, None];
        let mut turbulent_fraction = [None, None];
        for iter in 1..=self.params.max_iterations {
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
                )
            } else {
                Vec::new()
            };
            let coupling = Coupling {
                layout: &layout,
                ue_inv: &ue_inv,
                dv: &dv,
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
            let w = asm.system.solve_with(&mut schur)?;
            let upd = apply_update(
                &self.bl,
                &coupling,
                &mut state,
                &w,
                &asm.mismatch,
                &self.params.limits,
            )?;
            residual = upd.rms_change;
            // A step whose relative changes reach 1e6 came from a near-singular system (the
            // stagnation point almost on a node, ξ → 0 at the first station): the next
            // iteration goes without the stagnation-point terms, whose linearisation is then
            // far outside its range.
            stagnation_terms = upd.max_change < self.params.exploded_step;
            // Move the stagnation point with the viscous surface speed (XFOIL STMOVE).
            let q_nodes = viscous_node_speed(&layout, &state, &q_inv);
            if let Ok(new_layout) = StationLayout::new(&self.panels, &q_nodes[..n_af]) {
                if new_layout.stagnation.ist != layout.stagnation.ist {
                    let map = new_layout.map_from(&layout);
                    let mut s = state.remap(&map, &layout, &new_layout);
                    let ue_new = new_layout.edge_speed(&q_nodes);
                    fix_crossed(&mut s, &map, &layout, &new_layout, &ue_new);
                    state = s;
                    ue_inv = new_layout.edge_speed(&q_inv);
                    self.panels.edge_speed_influence_into(&new_layout, &mut dv);
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
                });
            }
        }
        Ok(Attempt {
            layout,
            state,
            converged: false,
            iterations: self.params.max_iterations,
            residual,
            transition,
        })
    }

    /// Integrated coefficients and distributions of an attempt.
    fn solution(&self, alpha_deg: f64, a: &Attempt) -> ViscousSolution {
        let g = &self.panels.airfoil;
        let n_af = g.len();
        let mut q = vec![0.0; n_af];
        for (k, st) in a.layout.stations.iter().enumerate() {
            if st.node < n_af {
                q[st.node] = st.vti * a.state.ue[k];
            }
        }
        let kt = &self.bl.flow.karman_tsien;
        let (cl, cm) = lift_and_moment(&g.x, &g.y, &q, alpha_deg, kt);
        let dist = |surface: Surface| -> Vec<BlStation> {
            a.layout
                .range(surface)
                .map(|k| {
                    let st = a.layout.stations[k];
                    let v = a.state.vars(&a.layout, k);
                    let regime = a.state.regime(&a.layout, k);
                    let p = self.bl.properties(&v, regime).unwrap_or_default();
                    let s = a.state.s[k];
                    let (x, y) = self.panels.node(st.node);
                    BlStation {
                        s: st.xi,
                        x,
                        y,
                        ue: a.state.ue[k],
                        dstar: v.dstar,
                        theta: v.theta,
                        cf: p.cf,
                        cf_inf: p.cf * p.rho_edge * p.ue * p.ue,
                        h: p.h,
                        hk: p.hk,
                        n_or_ctau: if regime == Regime::Laminar { s } else { s * s },
                        turbulent: regime != Regime::Laminar,
                    }
                })
                .collect()
        };
        let upper = dist(Surface::Upper);
        let lower = dist(Surface::Lower);
        let wake = dist(Surface::Wake);
        // Friction drag from the wall shear τ = ½ρe·Ue,c²·Cf (XFOIL CDCALC).
        let mut cdf = 0.0;
        let mut xtr = [1.0, 1.0];
        for (side, surface) in [Surface::Upper, Surface::Lower].into_iter().enumerate() {
            let range = a.layout.range(surface);
            let mut xs = Vec::with_capacity(range.len());
            let mut ys = Vec::with_capacity(range.len());
            let mut xis = Vec::with_capacity(range.len());
            let mut tau = Vec::with_capacity(range.len());
            for k in range {
                let st = a.layout.stations[k];
                let v = a.state.vars(&a.layout, k);
                let p = self
                    .bl
                    .properties(&v, a.state.regime(&a.layout, k))
                    .unwrap_or_default();
                xs.push(g.x[st.node]);
                ys.push(g.y[st.node]);
                xis.push(st.xi);
                tau.push(p.tau_wall);
            }
            cdf += friction_drag(&xs, &ys, &tau, alpha_deg);
            xtr[side] = transition_x(&xis, &xs, a.transition[side]);
        }
        let last = a.layout.len() - 1;
        let cd = self
            .bl
            .squire_young(&a.state.vars(&a.layout, last))
            .map(|s| s.cd)
            .unwrap_or(f64::NAN);
        ViscousSolution {
            point: PolarPoint {
                alpha: alpha_deg,
                cl,
                cd,
                cdp: cd - cdf,
                cdf,
                cm,
                xtr_top: xtr[0],
                xtr_bot: xtr[1],
                converged: a.converged,
                iterations: a.iterations,
                residual: a.residual,
            },
            upper,
            lower,
            wake,
        }
    }
}

/// The boundary-layer model of a solver's flow condition, with XFOIL's closure constants.
fn boundary_layer_model(params: &ViscousParams) -> Result<BlModel, ViscousError> {
    let conditions = BlConditions {
        reynolds: params.reynolds,
        mach: params.mach,
        ncrit: params.ncrit,
    };
    BlModel::new(&conditions, BlParams::default()).map_err(ViscousError::FlowConditions)
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

/// The result reported for a point that could not be solved at all.
fn failed_solution(alpha_deg: f64, iterations: u32) -> ViscousSolution {
    ViscousSolution {
        point: PolarPoint {
            alpha: alpha_deg,
            cl: f64::NAN,
            cd: f64::NAN,
            cdp: f64::NAN,
            cdf: f64::NAN,
            cm: f64::NAN,
            xtr_top: f64::NAN,
            xtr_bot: f64::NAN,
            converged: false,
            iterations,
            residual: f64::NAN,
        },
        upper: Vec::new(),
        lower: Vec::new(),
        wake: Vec::new(),
    }
}
