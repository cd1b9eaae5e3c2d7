//! "Ping" of the assembled global Newton system (XFOIL SETBL) against finite differences of the
//! residuals, with the edge speed tied to the mass defects (Ue = Ue_inv + D·m) and the
//! stagnation point — hence every station's ξ — moving with the edge speeds of the two stations
//! next to it, as between Newton iterations (XFOIL STMOVE). The mass columns of the stations
//! next to the stagnation point are only right with the ξ sensitivities (XFOIL XI_ULE1/2).

use super::{assemble, Coupling};
use crate::geometry::Airfoil;
use crate::inviscid::PanelSystem;
use crate::viscous::march::march;
use crate::viscous::params::SideModels;
use crate::viscous::state::BlState;
use crate::viscous::stations::{StationLayout, Surface};
use crate::viscous::{PanelModel, ViscousParams, ViscousSolver};

const RE: f64 = 3e6;
const ALPHA: f64 = 2.0;

fn paneled() -> Airfoil {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/xfoil/naca0012_paneled.dat"
    );
    crate::geometry::read_airfoil_file(std::path::Path::new(path)).unwrap()
}

/// Everything the assembly needs at one mass distribution.
struct Setup {
    model: PanelModel,
    q_inv: Vec<f64>,
    bl: SideModels,
    ante: f64,
}

impl Setup {
    fn new() -> Self {
        let foil = paneled();
        let system = PanelSystem::new(&foil).unwrap();
        let model = PanelModel::at_alpha(&system, ALPHA).unwrap();
        let q_inv = model.speeds(ALPHA);
        let ante = model.te_gap();
        Self {
            model,
            q_inv,
            // Different N_crit on the two sides, so that each side's equations are pinged
            // with its own.
            bl: ViscousParams {
                ncrit_top: 9.0,
                ncrit_bot: 7.0,
                ..ViscousParams::at(RE, 0.0, 1.0)
            }
            .boundary_layer()
            .unwrap(),
            ante,
        }
    }

    /// Station layout for the node speeds `q` (stagnation point where q changes sign).
    fn layout(&self, q: &[f64]) -> StationLayout {
        StationLayout::new(&self.model, &q[..self.model.n_airfoil()]).unwrap()
    }

    /// Free transition: the latest transition point is the trailing edge of each surface.
    fn xi_forced(layout: &StationLayout) -> [Option<f64>; 2] {
        [Surface::Upper, Surface::Lower]
            .map(|s| layout.range(s).last().map(|k| layout.stations[k].xi))
    }

    /// Residuals and dense Jacobian (3n × 3n, unknowns (s, θ, m) per station) at `state`, whose
    /// edge speeds are first made consistent with its mass defects and whose layout follows
    /// the stagnation point of those edge speeds.
    fn system(&self, base: &StationLayout, state: &BlState) -> (Vec<f64>, Vec<Vec<f64>>) {
        let dv = self.model.edge_speed_influence(base);
        let ue_inv = base.edge_speed(&self.q_inv);
        let n = base.len();
        let mut st = state.clone();
        // Stagnation point (and so ξ) from the consistent edge speeds.
        let (ue, layout) = self.consistent(base, state);
        st.ue = ue;
        assert_eq!(layout.stagnation.ist, base.stagnation.ist);
        let coupling = Coupling {
            layout: &layout,
            ue_inv: &ue_inv,
            dv: &dv,
            xi_forced: Self::xi_forced(&layout),
            ante: self.ante,
            ctau_sqrt_initial: ViscousParams::default().march.ctau_sqrt_initial,
            regimes_known: false,
            stagnation_terms: true,
            cached: None,
        };
        let asm = assemble(&self.bl, &coupling, &mut st).unwrap();
        assert!(asm.mismatch.iter().all(|e| e.abs() < 1e-12));
        let dense = asm.system.to_dense();
        let res: Vec<f64> = asm.system.rhs.iter().flatten().map(|r| -r).collect();
        let jac = (0..3 * n)
            .map(|i| (0..3 * n).map(|j| dense[(i, j)]).collect())
            .collect();
        (res, jac)
    }
}

impl Setup {
    /// Edge speeds Ue_inv + D·m of `state` on `layout`, and the layout their stagnation point
    /// gives.
    fn consistent(&self, layout: &StationLayout, state: &BlState) -> (Vec<f64>, StationLayout) {
        let dv = self.model.edge_speed_influence(layout);
        let ue_inv = layout.edge_speed(&self.q_inv);
        let n = layout.len();
        let ue: Vec<f64> = (0..n)
            .map(|k| ue_inv[k] + (0..n).map(|j| dv[k * n + j] * state.mass[j]).sum::<f64>())
            .collect();
        let mut q = self.q_inv.clone();
        for (k, s) in layout.stations.iter().enumerate() {
            q[s.node] = s.vti * ue[k];
        }
        (ue, self.layout(&q))
    }
}

#[test]
fn mass_columns_include_the_stagnation_point_motion() {
    let setup = Setup::new();
    let mut layout = setup.layout(&setup.q_inv);
    let ue_inv = layout.edge_speed(&setup.q_inv);
    let params = ViscousParams::at(RE, 0.0, 1.0);
    let mut state = march(
        &setup.bl,
        &layout,
        &ue_inv,
        Setup::xi_forced(&layout),
        setup.ante,
        &params.march,
    );
    // Move the layout to the stagnation point of the consistent edge speeds.
    for _ in 0..5 {
        let (_, next) = setup.consistent(&layout, &state);
        if next.stagnation.ist == layout.stagnation.ist {
            break;
        }
        let map = next.map_from(&layout);
        state = state.remap(&map, &layout, &next);
        layout = next;
    }
    let (_, jac) = setup.system(&layout, &state);
    let n = layout.len();
    let k1 = layout.range(Surface::Upper).start;
    let k2 = layout.range(Surface::Lower).start;
    // Mass columns of the two stations next to the stagnation point and of two others. With
    // the ξ terms the columns agree to ≈ 1e-7 of their largest entry; without them the
    // similarity-station rows are off by 3e-4 here.
    for j in [k1, k2, k1 + 5, k2 + 20] {
        let h = 1e-6 * state.mass[j].abs().max(1e-6);
        let mut plus = state.clone();
        plus.mass[j] += h;
        let mut minus = state.clone();
        minus.mass[j] -= h;
        let (rp, _) = setup.system(&layout, &plus);
        let (rm, _) = setup.system(&layout, &minus);
        let col = 3 * j + 2;
        let scale = (0..3 * n).map(|i| jac[i][col].abs()).fold(0.0, f64::max);
        for i in 0..3 * n {
            let fd = (rp[i] - rm[i]) / (2.0 * h);
            let an = jac[i][col];
            assert!(
                (fd - an).abs() <= 1e-5 * scale,
                "∂R[{i}]/∂m[{j}]: analytic {an:e}, finite difference {fd:e} (column scale {scale:e})"
            );
        }
    }
    // The case is a real one: the solver converges there.
    let foil = paneled();
    let mut solver = ViscousSolver::new(&foil, params).unwrap();
    assert!(solver.solve(ALPHA).point.converged);
}
