//! The inviscid data the viscous coupling needs at one angle of attack (XFOIL XYWAKE, QWCALC,
//! QDCALC), and a store of them shared by the solvers of one airfoil.
//!
//! The wake streamline and the source influence matrix depend on the geometry and α only: the
//! Mach number enters through the boundary layer's Karman–Tsien edge speed, and the Reynolds
//! number, Ncrit and trips through the boundary layer alone. So every (Re, M, Ncrit, trip)
//! condition of a table needs the same model at a given α, and [`SharedPanels`] builds it once
//! per α for all of them. A model is a pure function of (geometry, α), so which solver or
//! thread builds it first does not change any result.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use crate::geometry::Airfoil;
use crate::inviscid::{superpose, PanelGeometry, PanelSystem, SourceInfluence, Wake};

use super::error::ViscousError;
use super::stations::StationLayout;

/// Inviscid data the coupling needs (XFOIL QINVU, DIJ): the airfoil contour as the panel
/// method prepared it, the wake nodes, surface speeds of the α = 0° and 90° unit solutions, and
/// the source influence matrix. Nodes are numbered airfoil first (0..n, XFOIL order), then wake
/// (n..n+nw).
#[derive(Clone, Debug)]
pub struct PanelModel {
    /// The airfoil contour: nodes, arc length, spline tangents and the trailing edge, whose gap
    /// (XFOIL ANTE) both the wake-gap closure and the trailing-edge junction use.
    pub airfoil: PanelGeometry,
    /// Wake node x, from the trailing edge downstream (XFOIL XYWAKE).
    pub wake_x: Vec<f64>,
    /// Wake node y.
    pub wake_y: Vec<f64>,
    /// Surface speed at all nodes for α = 0° and α = 90° (XFOIL QINVU, positive on the upper
    /// surface in XFOIL's orientation).
    pub q_unit: [Vec<f64>; 2],
    /// The (n+nw)² influence matrix: change of the surface speed q_i per unit mass defect
    /// m_j = Ue_j·δ*_j at node j (XFOIL DIJ; the edge speed then changes by −vti_i·vti_j·DIJ_ij·m_j,
    /// XFOIL UESET).
    pub dij: SourceInfluence,
}

impl PanelModel {
    /// Model of a panel system at angle of attack `alpha_deg`: wake traced at α, unit speeds at
    /// airfoil and wake nodes, and the source influence matrix (XFOIL XYWAKE, QWCALC, QDCALC).
    pub fn at_alpha(system: &PanelSystem, alpha_deg: f64) -> Result<Self, ViscousError> {
        let wake = Wake::new(system, alpha_deg)?;
        let d = SourceInfluence::new(system, &wake);
        let q_unit = [0, 1].map(|k| {
            let mut q = system.gamma_unit(k).to_vec();
            q.extend_from_slice(&wake.qinv_unit[k]);
            q
        });
        Ok(Self {
            airfoil: system.geometry().clone(),
            wake_x: wake.x,
            wake_y: wake.y,
            q_unit,
            dij: d,
        })
    }

    /// Number of airfoil nodes n.
    pub fn n_airfoil(&self) -> usize {
        self.airfoil.len()
    }

    /// Number of nodes, airfoil and wake.
    pub fn n_nodes(&self) -> usize {
        self.airfoil.len() + self.wake_x.len()
    }

    /// Coordinates (x, y) of node `i` (airfoil nodes first, then wake nodes).
    pub fn node(&self, i: usize) -> (f64, f64) {
        let n = self.airfoil.len();
        if i < n {
            (self.airfoil.x[i], self.airfoil.y[i])
        } else {
            (self.wake_x[i - n], self.wake_y[i - n])
        }
    }

    /// Trailing-edge gap normal to the TE bisector (XFOIL TECALC ANTE, from the contour's
    /// spline tangents): the one gap of the wake-gap closure and of the trailing-edge junction.
    pub fn te_gap(&self) -> f64 {
        self.airfoil.te.gap_normal.abs()
    }

    /// Rejects a model whose arrays do not fit together: at least 5 airfoil and 2 wake nodes,
    /// unit speeds and the influence matrix for all of them, its rows split after the airfoil
    /// nodes.
    pub(crate) fn check(&self) -> Result<(), ViscousError> {
        let (n, nt) = (self.n_airfoil(), self.n_nodes());
        if n < 5
            || self.wake_y.len() != self.wake_x.len()
            || self.q_unit.iter().any(|q| q.len() != nt)
            || self.dij.n_nodes() != nt
            || self.dij.n_airfoil() != n
            || nt < n + 2
        {
            return Err(ViscousError::BadAirfoil { min: 5, got: n });
        }
        Ok(())
    }

    /// Inviscid surface speed at all nodes for angle of attack α (XFOIL QISET).
    pub fn speeds(&self, alpha_deg: f64) -> Vec<f64> {
        superpose(&self.q_unit[0], &self.q_unit[1], alpha_deg)
    }

    /// Edge-speed influence matrix of a station layout, row-major in system order:
    /// Dv_kj = −vti_k·vti_j·DIJ(node_k, node_j) (XFOIL UESET), so Ue = Ue_inv + Dv·m.
    pub fn edge_speed_influence(&self, layout: &StationLayout) -> Vec<f64> {
        let mut dv = Vec::new();
        self.edge_speed_influence_into(layout, &mut dv);
        dv
    }

    /// [`edge_speed_influence`](Self::edge_speed_influence) written into `dv` (resized to n²),
    /// so that a solver rebuilding it when the stagnation point moves reuses the memory, which
    /// is then still in cache.
    pub fn edge_speed_influence_into(&self, layout: &StationLayout, dv: &mut Vec<f64>) {
        let n_af = self.n_airfoil();
        let n = layout.len();
        dv.resize(n * n, 0.0);
        for (out, sk) in dv.chunks_exact_mut(n).zip(&layout.stations) {
            let (airfoil, wake) = self.dij.row(sk.node);
            for (o, sj) in out.iter_mut().zip(&layout.stations) {
                let d = match sj.node.checked_sub(n_af) {
                    None => airfoil[sj.node],
                    Some(w) => wake[w],
                };
                *o = -sk.vti * sj.vti * d;
            }
        }
    }
}

/// Memory the per-α models of one [`SharedPanels`] may take (their blocks of the influence
/// matrix and node arrays); beyond it, further models are built for the asking solver only and
/// not kept.
pub const SHARED_MODEL_BYTES: usize = 256 << 20;

/// Nodes of a model of `n` airfoil nodes with the default wake (N/12 + 10 wake nodes,
/// `WakeParams`).
fn default_node_count(n: usize) -> usize {
    n + n / 12 + 10
}

/// One airfoil's panel system and its per-α [`PanelModel`]s, built on first request and then
/// shared by every solver holding this store (any thread). Keys are the exact α values, so a
/// model is reused only for the identical angle.
#[derive(Debug)]
pub struct SharedPanels {
    /// The factorised panel system of the airfoil.
    system: PanelSystem,
    /// Models by the bit pattern of α; each cell is filled once, by the first solver asking.
    models: Mutex<HashMap<u64, Arc<ModelCell>>>,
    /// Number of models kept at most ([`SHARED_MODEL_BYTES`] over one model's size).
    capacity: usize,
}

/// A model slot, filled once with the model or the reason it could not be built at that α.
type ModelCell = OnceLock<Result<Arc<PanelModel>, ViscousError>>;

impl SharedPanels {
    /// Panel system of an already paneled airfoil (XFOIL order).
    pub fn new(airfoil: &Airfoil) -> Result<Self, ViscousError> {
        if airfoil.x.len() != airfoil.y.len() || airfoil.x.len() < 5 {
            return Err(ViscousError::BadAirfoil {
                min: 5,
                got: airfoil.x.len().min(airfoil.y.len()),
            });
        }
        let system = PanelSystem::new(airfoil)?;
        // A model holds the per-α blocks of D (NW × (2N + NW), the airfoil block is shared) and
        // a dozen node arrays (contour, wake, unit speeds).
        let n = system.geometry().len();
        let nt = default_node_count(n);
        let nw = nt - n;
        let capacity = (SHARED_MODEL_BYTES / (8 * (nw * (n + nt) + 12 * nt))).max(1);
        Ok(Self {
            system,
            models: Mutex::new(HashMap::new()),
            capacity,
        })
    }

    /// Number of nodes of a model, airfoil and wake (with the default wake length).
    pub fn node_count(&self) -> usize {
        default_node_count(self.system.geometry().len())
    }

    /// The model at `alpha_deg`, built now if no solver asked for this α before.
    pub fn model(&self, alpha_deg: f64) -> Result<Arc<PanelModel>, ViscousError> {
        let build = || PanelModel::at_alpha(&self.system, alpha_deg).map(Arc::new);
        let cell = {
            // A poisoned lock only means another thread panicked while holding it; the map
            // itself is still consistent (cells are inserted whole).
            let mut map = self.models.lock().unwrap_or_else(|e| e.into_inner());
            let key = alpha_deg.to_bits();
            match map.get(&key) {
                Some(c) => Arc::clone(c),
                None if map.len() < self.capacity => Arc::clone(map.entry(key).or_default()),
                None => return build(),
            }
        };
        // Other solvers asking for the same α meanwhile wait here for this one build.
        cell.get_or_init(build).clone()
    }

    /// Number of models kept so far.
    pub fn len(&self) -> usize {
        self.models.lock().map(|m| m.len()).unwrap_or(0)
    }

    /// True when no model was built yet.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}
