//! Assembly of the global Newton system (XFOIL SETBL, Drela 1989 §4): the boundary-layer
//! equations of every station linearised in (√Cτ or N, θ, m) of all stations, with the edge speed
//! eliminated through Ue = Ue_inv + D·m and δ* = m/Ue.
//!
//! For an equation f with partials f_δ*, f_u at station j the chain rule gives
//! `∂f/∂m_j(local) = f_δ*/Ue_j` (block part) and the dense part
//! `(f_u − f_δ*·δ*_j/Ue_j)·D_j,·` (mass influence on the edge speed). The stored edge speed may
//! differ from Ue_inv + D·m (after an inverse march or a relaxed step); that mismatch e_j enters
//! the right-hand side like XFOIL's DUE terms.
//!
//! Every station's ξ moves with the stagnation point, which moves with the edge speeds of the
//! two stations next to it; those terms (XFOIL XI_ULE1/XI_ULE2) enter the mass columns of every
//! equation (`StagnationSensitivity`). A forced-transition interval gets none: its trip moves
//! with the stagnation point too, so a common shift of ξ acts on that interval mostly through
//! differences of ξ, which it does not change (XFOIL adds the trip's own sensitivity, VSX).

use super::block_solver::BlockSystem;
use super::error::ViscousError;
use super::params::SideModels;
use super::state::BlState;
use super::stations::{StationKind, StationLayout, Surface};
use crate::boundary_layer::{
    BlError, IntervalEquations, Regime, StationVars, TeJunction, TransitionKind,
};
use crate::numerics::dense::mat_vec;

/// Transition found on one surface during assembly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TransitionPoint {
    /// ξ of the transition point.
    pub xi: f64,
    /// System index of the first turbulent station.
    pub station: usize,
    /// Forced (trip) or free (e^n).
    pub forced: bool,
}

impl TransitionPoint {
    /// Fraction of the transition interval (upstream station → `station`) that lies downstream
    /// of the transition point, i.e. covered by the turbulent part of the interval equations
    /// (XFOIL TRDIF): 0 when transition sits at the station, 1 at the upstream station.
    pub fn turbulent_fraction(&self, layout: &StationLayout) -> f64 {
        let st = layout.stations[self.station];
        let p = st.upstream.unwrap_or(self.station.saturating_sub(1));
        let xi_p = layout.stations[p].xi;
        if st.xi > xi_p {
            ((st.xi - self.xi) / (st.xi - xi_p)).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }
}

/// Inputs of the assembly that do not change within one Newton iteration.
pub struct Coupling<'a> {
    /// Station layout.
    pub layout: &'a StationLayout,
    /// Inviscid edge speed per station.
    pub ue_inv: &'a [f64],
    /// Edge-speed influence of the mass defects in system order, row-major n×n:
    /// Ue_k = Ue_inv,k + Σ_j dv[k·n + j]·m_j.
    pub dv: &'a [f64],
    /// Forced-transition ξ on the upper and lower surface (None = free).
    pub xi_forced: [Option<f64>; 2],
    /// Trailing-edge gap normal to the TE bisector (XFOIL ANTE).
    pub ante: f64,
    /// √Cτ given to a station that just became turbulent when its surface has no turbulent
    /// station yet ([`super::march::MarchParams::ctau_sqrt_initial`]).
    pub ctau_sqrt_initial: f64,
    /// The regimes stored in the state were just decided by the mixed-mode march on the same
    /// state, so only the interval ending at the first turbulent station is checked for
    /// transition (the others are known not to transition).
    pub regimes_known: bool,
    /// Include the stagnation-point terms of ξ (see `StagnationSensitivity`). The solver
    /// leaves them out for one iteration after a step that blew up.
    pub stagnation_terms: bool,
    /// Equations of each station left by the mixed-mode march, linearly corrected to the final
    /// state of the march (None: evaluate here).
    pub cached: Option<&'a [Option<CachedEquations>]>,
}

/// Station equations computed by the mixed-mode march and reused by the assembly.
#[derive(Clone, Copy, Debug)]
pub enum CachedEquations {
    /// Similarity or interval equations (d1: upstream station, d2: this station), with the
    /// transition point (ξ, forced) if the interval transitions.
    Interval(IntervalEquations, Option<(f64, bool)>),
    /// Trailing-edge junction of the first wake station.
    Junction(TeJunction),
}

impl Coupling<'_> {
    /// Edge speed implied by the mass defects, Ue_inv + D·m.
    pub fn ue_from_mass(&self, mass: &[f64]) -> Vec<f64> {
        let mut ue = mat_vec(self.dv, mass);
        for (u, inv) in ue.iter_mut().zip(self.ue_inv) {
            *u += inv;
        }
        ue
    }
}

/// The assembled system and what was learnt while assembling it.
pub struct Assembly<'a> {
    /// The linear system for (δs, δθ, δm).
    pub system: BlockSystem<'a>,
    /// Edge-speed mismatch e = (Ue_inv + D·m) − Ue per station.
    pub mismatch: Vec<f64>,
    /// Transition on the upper and lower surface.
    pub transition: [Option<TransitionPoint>; 2],
}

/// Sensitivity of every station's ξ to the edge speeds of the two stations next to the
/// stagnation point (XFOIL SETBL: SST_GO, SST_GP, XI_ULE1, XI_ULE2).
///
/// The stagnation point is the zero of the surface speed interpolated linearly between the
/// first upper station (q = U₁) and the first lower station (q = −U₂) a distance Δs apart:
/// s_st = s_i + Δs·U₁/(U₁ + U₂), so ∂s_st/∂U₁ = Δs·U₂/(U₁ + U₂)² and
/// ∂s_st/∂U₂ = −Δs·U₁/(U₁ + U₂)². Upper-surface ξ = s_st − s moves with +δs_st; lower-surface
/// and wake ξ = s − s_st with −δs_st. Without these terms a Newton step changes the edge
/// speeds next to the stagnation point as if ξ stayed put, and the first stations (ξ → 0)
/// ask for large relative changes that throttle the whole update.
#[derive(Clone, Copy, Debug)]
struct StagnationSensitivity {
    /// System indices of the first upper and first lower station.
    stations: [usize; 2],
    /// ∂s_st/∂U₁ and ∂s_st/∂U₂.
    dsst_du: [f64; 2],
}

impl StagnationSensitivity {
    fn new(layout: &StationLayout, state: &BlState) -> Option<Self> {
        let k1 = layout.range(Surface::Upper).next()?;
        let k2 = layout.range(Surface::Lower).next()?;
        // Arc length between the two stations' nodes: the stagnation point lies between them.
        let ds = layout.stations[k1].xi + layout.stations[k2].xi;
        let (u1, u2) = (state.ue[k1], state.ue[k2]);
        let sum = u1 + u2;
        if !(sum > 0.0 && ds.is_finite()) {
            return None;
        }
        let f = ds / (sum * sum);
        Some(Self {
            stations: [k1, k2],
            dsst_du: [f * u2, -f * u1],
        })
    }

    /// Adds the edge-speed columns of the ξ dependence `xi_coef` (∂R/∂s_st of the three
    /// equations of station `k`) to the system.
    fn add(&self, sys: &mut BlockSystem<'_>, k: usize, xi_coef: &[f64; 3], mismatch: &[f64]) {
        for (r, &c) in xi_coef.iter().enumerate() {
            if c == 0.0 {
                continue;
            }
            for (&j, &dsdu) in self.stations.iter().zip(&self.dsst_du) {
                let cu = c * dsdu;
                sys.mass_terms[3 * k + r].add(j, cu);
                sys.rhs[k][r] -= cu * mismatch[j];
            }
        }
    }
}

/// Sign of ∂ξ/∂s_st at a station: +1 on the upper surface, −1 on the lower surface and wake.
fn xi_sign(layout: &StationLayout, j: usize) -> f64 {
    if layout.stations[j].surface == Surface::Upper {
        1.0
    } else {
        -1.0
    }
}

/// Adds the linearisation of 3 equations of station `k` with respect to station `j`'s
/// variables (Jacobian columns (s, θ, δ*, u, ξ)) to the system; the ξ column, times the
/// station's [`xi_sign`], is accumulated in `xi_coef` for the stagnation-point terms.
fn add_terms(
    sys: &mut BlockSystem<'_>,
    (k, j): (usize, usize),
    d: &[[f64; 5]; 3],
    state: &BlState,
    mismatch: &[f64],
    xi_coef: &mut [f64; 3],
    sign: f64,
) {
    for (x, dr) in xi_coef.iter_mut().zip(d) {
        *x += sign * dr[4];
    }
    let uj = state.ue[j];
    let dsj = state.dstar(j);
    let mut block = [[0.0; 3]; 3];
    for r in 0..3 {
        block[r][0] = d[r][0];
        block[r][1] = d[r][1];
        block[r][2] = d[r][2] / uj;
        // ∂R/∂Ue_j at fixed m_j: its mass columns are cu times row j of Dv.
        let cu = d[r][3] - d[r][2] * dsj / uj;
        if cu != 0.0 {
            sys.mass_terms[3 * k + r].add(j, cu);
            sys.rhs[k][r] -= cu * mismatch[j];
        }
    }
    let add = |target: &mut [[f64; 3]; 3]| {
        for r in 0..3 {
            for c in 0..3 {
                target[r][c] += block[r][c];
            }
        }
    };
    if j == k {
        add(&mut sys.diag[k]);
    } else if sys.upstream[k].map(|(p, _)| p) == Some(j) {
        if let Some((_, b)) = sys.upstream[k].as_mut() {
            add(b);
        }
    } else if sys.upstream2[k].map(|(p, _)| p) == Some(j) {
        if let Some((_, b)) = sys.upstream2[k].as_mut() {
            add(b);
        }
    } else if sys.upstream[k].is_none() {
        let mut b = [[0.0; 3]; 3];
        add(&mut b);
        sys.upstream[k] = Some((j, b));
    } else {
        let mut b = [[0.0; 3]; 3];
        add(&mut b);
        sys.upstream2[k] = Some((j, b));
    }
}

/// The system being assembled and what every station's terms need.
struct Assembler<'a, 'l> {
    sys: BlockSystem<'a>,
    layout: &'l StationLayout,
    /// Edge-speed mismatch e = (Ue_inv + D·m) − Ue per station.
    mismatch: Vec<f64>,
    /// ξ sensitivity to the edge speeds next to the stagnation point (None: left out).
    stagnation: Option<StagnationSensitivity>,
}

impl Assembler<'_, '_> {
    /// Adds the three equations of station `k`: residuals `res` and their Jacobians with
    /// respect to the listed stations (upstream stations first, in the order the block solver
    /// keeps them). `xi_terms: false` leaves out the stagnation-point terms (forced-transition
    /// intervals).
    fn station(
        &mut self,
        state: &BlState,
        k: usize,
        jacobians: &[(usize, &[[f64; 5]; 3])],
        res: &[f64; 3],
        xi_terms: bool,
    ) {
        let mut xi_coef = [0.0; 3];
        for &(j, d) in jacobians {
            let sign = xi_sign(self.layout, j);
            add_terms(
                &mut self.sys,
                (k, j),
                d,
                state,
                &self.mismatch,
                &mut xi_coef,
                sign,
            );
        }
        for (rhs, r) in self.sys.rhs[k].iter_mut().zip(res) {
            *rhs -= r;
        }
        if xi_terms {
            if let Some(st) = &self.stagnation {
                st.add(&mut self.sys, k, &xi_coef, &self.mismatch);
            }
        }
    }

    /// Adds interval (or similarity) equations: similarity stations have one combined
    /// Jacobian, interval stations one per end.
    fn interval(&mut self, state: &BlState, k: usize, e: &IntervalEquations, forced: bool) {
        let st = self.layout.stations[k];
        if st.kind == StationKind::Similarity {
            self.station(state, k, &[(k, &e.combined_jacobian())], &e.res, !forced);
        } else {
            let p = st.upstream.unwrap_or(k - 1);
            self.station(state, k, &[(p, &e.d1), (k, &e.d2)], &e.res, !forced);
        }
    }

    /// Adds the trailing-edge junction equations of the first wake station.
    fn junction(&mut self, state: &BlState, k: usize, e: &TeJunction) {
        let (ku, kl) = (self.layout.upper_te(), self.layout.lower_te());
        self.station(
            state,
            k,
            &[(kl, &e.d_lower), (ku, &e.d_upper), (k, &e.d_wake)],
            &e.res,
            true,
        );
    }
}

/// Assembles the Newton system. Regimes are decided here, station by station downstream, by
/// the transition check of each laminar interval (XFOIL SETBL with TRCHEK); a station whose regime
/// changes gets its `s` variable re-initialised.
pub fn assemble<'a>(
    models: &SideModels,
    coupling: &Coupling<'a>,
    state: &mut BlState,
) -> Result<Assembly<'a>, ViscousError> {
    let layout = coupling.layout;
    let n = layout.len();
    let ue_calc = coupling.ue_from_mass(&state.mass);
    let mismatch: Vec<f64> = ue_calc.iter().zip(&state.ue).map(|(c, u)| c - u).collect();
    let stagnation = coupling
        .stagnation_terms
        .then(|| StagnationSensitivity::new(layout, state))
        .flatten();
    let mut asm = Assembler {
        sys: BlockSystem::zeros(n, coupling.dv),
        layout,
        mismatch,
        stagnation,
    };
    let mut transition = [None, None];
    let cached = |k: usize| coupling.cached.and_then(|c| c[k].as_ref());

    for (side, surface) in [Surface::Upper, Surface::Lower].into_iter().enumerate() {
        let model = &models[side];
        let range = layout.range(surface);
        // Shear-stress value to give stations that switch from laminar to turbulent.
        let s_turb_ref = range
            .clone()
            .find(|&k| state.turbulent[k])
            .map(|k| state.s[k].clamp(1e-4, 0.25))
            .unwrap_or(coupling.ctau_sqrt_initial);
        let mut turbulent = false;
        for k in range {
            let st = layout.stations[k];
            if let Some(CachedEquations::Interval(e, tr)) = cached(k) {
                if let Some((xi, forced)) = tr {
                    turbulent = true;
                    transition[side] = Some(TransitionPoint {
                        xi: *xi,
                        station: k,
                        forced: *forced,
                    });
                }
                let forced = matches!(tr, Some((_, true)));
                asm.interval(state, k, e, forced);
                continue;
            }
            if st.kind == StationKind::Similarity {
                state.turbulent[k] = false;
                let v = state.vars(layout, k);
                let e = model.similarity(&v).map_err(at(k))?;
                asm.interval(state, k, &e, false);
                continue;
            }
            let p = st.upstream.unwrap_or(k - 1);
            if turbulent {
                if !state.turbulent[k] {
                    state.turbulent[k] = true;
                    state.s[k] = state.s[p].clamp(1e-4, 0.25);
                }
                let v1 = state.vars(layout, p);
                let v2 = state.vars(layout, k);
                let e = model.interval(Regime::Turbulent, &v1, &v2).map_err(at(k))?;
                asm.interval(state, k, &e, false);
                continue;
            }
            let v1 = state.vars(layout, p);
            let mut v2 = state.vars(layout, k);
            if !state.turbulent[k] {
                v2.s = s_turb_ref;
            }
            let tr = if coupling.regimes_known && !state.turbulent[k] {
                None
            } else {
                model
                    .transition_interval(&v1, &v2, coupling.xi_forced[side])
                    .map_err(at(k))?
            };
            match tr {
                Some(t) => {
                    let forced = t.kind == TransitionKind::Forced;
                    if !state.turbulent[k] {
                        state.s[k] = s_turb_ref;
                        state.turbulent[k] = true;
                    }
                    turbulent = true;
                    transition[side] = Some(TransitionPoint {
                        xi: t.xi_tr,
                        station: k,
                        forced,
                    });
                    asm.interval(state, k, &t.eqs, forced);
                }
                None => {
                    if state.turbulent[k] {
                        state.turbulent[k] = false;
                        state.s[k] = state.s[p].max(0.0);
                    }
                    let v2 = state.vars(layout, k);
                    let e = model.interval(Regime::Laminar, &v1, &v2).map_err(at(k))?;
                    asm.interval(state, k, &e, false);
                }
            }
        }
    }

    // Wake: junction of both trailing-edge layers, then wake intervals (side 2 in XFOIL).
    let model = &models[1];
    for k in layout.range(Surface::Wake) {
        state.turbulent[k] = true;
        match cached(k) {
            Some(CachedEquations::Junction(e)) => asm.junction(state, k, e),
            Some(CachedEquations::Interval(e, _)) => asm.interval(state, k, e, false),
            None if layout.stations[k].kind == StationKind::WakeStart => {
                let vu = state.vars(layout, layout.upper_te());
                let vl = state.vars(layout, layout.lower_te());
                let vw = state.vars(layout, k);
                let e = model
                    .te_junction(&vu, &vl, &vw, coupling.ante)
                    .map_err(at(k))?;
                asm.junction(state, k, &e);
            }
            None => {
                let p = layout.stations[k].upstream.unwrap_or(k - 1);
                let v1: StationVars = state.vars(layout, p);
                let v2 = state.vars(layout, k);
                let e = model.interval(Regime::Wake, &v1, &v2).map_err(at(k))?;
                asm.interval(state, k, &e, false);
            }
        }
    }

    Ok(Assembly {
        system: asm.sys,
        mismatch: asm.mismatch,
        transition,
    })
}

/// A boundary-layer error at system station `station`.
pub fn at(station: usize) -> impl Fn(BlError) -> ViscousError {
    move |source| ViscousError::BoundaryLayer { station, source }
}

#[cfg(test)]
mod tests;
