//! What a viscous solution reports: the integrated coefficients (Cl, Cm, Cd, its friction and
//! pressure parts, transition, the minimum pressure and whether it is supercritical, where the
//! flow separates and whether that is massive separation) and the boundary-layer distributions
//! of both surfaces and the wake.

use super::forces::{friction_drag, lift_and_moment, separation_x, transition_x};
use super::panel_model::PanelModel;
use super::state::BlState;
use super::stations::{StationLayout, Surface};
use super::tangent::Tangent;
use crate::boundary_layer::{BlModel, Regime};
use crate::section::{massive_separation, PolarPoint};

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

/// Outcome of one Newton attempt.
pub(super) struct Attempt {
    pub layout: StationLayout,
    pub state: BlState,
    pub converged: bool,
    pub iterations: u32,
    pub residual: f64,
    /// ξ of transition on the upper and lower surface.
    pub transition: [Option<f64>; 2],
    /// Per surface, the turbulent fraction of the last transition interval.
    pub turbulent_fraction: [Option<f64>; 2],
    /// Derivative of the converged state along α (None if not converged).
    pub tangent: Option<Tangent>,
}

/// Integrated coefficients and distributions of an attempt on `panels` with the boundary layer
/// `bl` (XFOIL CLCALC, CDCALC, BLDUMP quantities).
pub(super) fn solution(
    panels: &PanelModel,
    bl: &BlModel,
    alpha_deg: f64,
    a: &Attempt,
) -> ViscousSolution {
    let g = &panels.airfoil;
    let n_af = g.len();
    let mut q = vec![0.0; n_af];
    for (k, st) in a.layout.stations.iter().enumerate() {
        if st.node < n_af {
            q[st.node] = st.vti * a.state.ue[k];
        }
    }
    let kt = &bl.flow.karman_tsien;
    let (cl, cm) = lift_and_moment(&g.x, &g.y, &q, alpha_deg, kt);
    // The closures of every station, once for the distributions and the friction drag.
    let props: Vec<_> = (0..a.layout.len())
        .map(|k| {
            let v = a.state.vars(&a.layout, k);
            bl.properties(&v, a.state.regime(&a.layout, k))
                .unwrap_or_default()
        })
        .collect();
    let minimum = kt.minimum_pressure(q.iter().copied());
    let dist = |surface: Surface| -> Vec<BlStation> {
        a.layout
            .range(surface)
            .map(|k| {
                let st = a.layout.stations[k];
                let v = a.state.vars(&a.layout, k);
                let regime = a.state.regime(&a.layout, k);
                let p = props[k];
                let s = a.state.s[k];
                let (x, y) = panels.node(st.node);
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
    let [xsep_top, xsep_bot] = [&upper, &lower].map(|stations| {
        let x: Vec<f64> = stations.iter().map(|s| s.x).collect();
        let cf: Vec<f64> = stations.iter().map(|s| s.cf).collect();
        separation_x(&x, &cf)
    });
    // Friction drag from the wall shear τ = ½ρe·Ue,c²·Cf (XFOIL CDCALC).
    let mut cdf = 0.0;
    let mut xtr = [1.0, 1.0];
    for (side, surface) in [Surface::Upper, Surface::Lower].into_iter().enumerate() {
        let range = a.layout.range(surface);
        let mut xs = Vec::with_capacity(range.len());
        let mut ys = Vec::with_capacity(range.len());
        let mut tau = Vec::with_capacity(range.len());
        let mut xi_te = 0.0;
        for k in range {
            let st = a.layout.stations[k];
            xs.push(g.x[st.node]);
            ys.push(g.y[st.node]);
            xi_te = st.xi;
            tau.push(props[k].tau_wall);
        }
        cdf += friction_drag(&xs, &ys, &tau, alpha_deg);
        // Without transition, the trailing edge's x/c.
        let xi_tr = a.transition[side].unwrap_or(xi_te);
        let sst = a.layout.stagnation.sst;
        xtr[side] = transition_x(g, sst, surface == Surface::Upper, xi_tr);
    }
    let last = a.layout.len() - 1;
    let cd = bl
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
            cpmin: minimum.cp,
            supercritical: Some(minimum.supercritical),
            xsep_top,
            xsep_bot,
            massive_separation: massive_separation(xsep_top, xsep_bot),
        },
        upper,
        lower,
        wake,
    }
}

/// The result reported for a point that could not be solved at all.
pub(super) fn failed_solution(alpha_deg: f64, iterations: u32) -> ViscousSolution {
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
            cpmin: f64::NAN,
            supercritical: None,
            xsep_top: f64::NAN,
            xsep_bot: f64::NAN,
            massive_separation: None,
        },
        upper: Vec::new(),
        lower: Vec::new(),
        wake: Vec::new(),
    }
}
