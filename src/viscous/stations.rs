//! Boundary-layer station topology: stagnation point, panel-node ↔ station mapping, the
//! boundary-layer coordinate ξ, the wake gap and the inviscid edge speed per station
//! (XFOIL xpanel.f/xbl.f STFIND, IBLPAN, XICALC, UICALC; Drela 1989 §3).
//!
//! Stations are numbered in one system order (XFOIL ISYS): the upper surface from the station
//! next to the stagnation point to the trailing edge, then the lower surface likewise, then the
//! wake. XFOIL's virtual station at the stagnation point itself (IBL = 1) is not stored: the first
//! station of each surface is the similarity station.

use super::error::ViscousError;
use super::panel_model::PanelModel;

/// Which layer a station belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    /// Upper surface (edge speed = +q of the panel solution).
    Upper,
    /// Lower surface (edge speed = −q).
    Lower,
    /// Wake behind the trailing edge (continues the lower-surface orientation, edge speed −q).
    Wake,
}

/// How a station's three equations are formed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StationKind {
    /// First station after the stagnation point: similarity form (XFOIL SIMI).
    Similarity,
    /// Interior station: interval equations with the upstream station.
    Interval,
    /// First wake station: trailing-edge junction of both surfaces (XFOIL TESYS).
    WakeStart,
}

/// One boundary-layer station.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Station {
    /// Node index in the panel arrays (airfoil nodes 0..n, wake nodes n..n+nw).
    pub node: usize,
    /// Surface the station lies on.
    pub surface: Surface,
    /// Sign relating the panel surface speed q to the edge speed: Ue = vti·q (XFOIL VTI).
    pub vti: f64,
    /// Boundary-layer coordinate ξ: arc length from the stagnation point (XFOIL XSSI).
    pub xi: f64,
    /// Wake gap thickness added to δ* behind a blunt trailing edge (XFOIL WGAP; 0 on the airfoil).
    pub wake_gap: f64,
    /// Upstream station in system order (None for similarity stations and the first wake station).
    pub upstream: Option<usize>,
    /// Equation form.
    pub kind: StationKind,
}

/// Location of the stagnation point on the airfoil surface (XFOIL STFIND).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stagnation {
    /// Node index i with `q[i] ≥ 0 > q[i+1]` (XFOIL IST, 0-based).
    pub ist: usize,
    /// Arc length of the stagnation point (XFOIL SST), linearly interpolated in q.
    pub sst: f64,
}

/// Finds the stagnation point as the sign change of the surface speed from + (upper) to −
/// (lower), linearly interpolated between nodes (XFOIL STFIND).
pub fn find_stagnation(q: &[f64], s: &[f64]) -> Result<Stagnation, ViscousError> {
    let n = q.len().min(s.len());
    let i = (0..n.saturating_sub(1))
        .find(|&i| q[i] >= 0.0 && q[i + 1] < 0.0)
        .ok_or(ViscousError::NoStagnationPoint)?;
    let dq = q[i + 1] - q[i];
    let ds = s[i + 1] - s[i];
    // Interpolate from the node with the smaller |q| to limit round-off (as XFOIL does).
    let mut sst = if q[i] < -q[i + 1] {
        s[i] - ds * (q[i] / dq)
    } else {
        s[i + 1] - ds * (q[i + 1] / dq)
    };
    let eps = 1e-7 * ds.abs().max(1e-12);
    sst = sst.clamp(s[i] + eps, s[i + 1] - eps);
    Ok(Stagnation { ist: i, sst })
}

/// Ratio of the length of the cubic wake-gap closure to the TE gap (XFOIL XICALC TELRAT).
pub const WAKE_GAP_LENGTH_RATIO: f64 = 2.5;

/// The complete station layout for one stagnation-point position.
#[derive(Clone, Debug)]
pub struct StationLayout {
    /// Stagnation point.
    pub stagnation: Stagnation,
    /// All stations in system order.
    pub stations: Vec<Station>,
    /// Number of upper-surface stations (system indices 0..n_upper).
    pub n_upper: usize,
    /// Number of lower-surface airfoil stations (system indices n_upper..n_upper+n_lower).
    pub n_lower: usize,
    /// Number of wake stations (the rest).
    pub n_wake: usize,
}

impl StationLayout {
    /// Builds the layout from the surface speed q of the airfoil nodes (XFOIL IBLPAN + XICALC).
    pub fn new(model: &PanelModel, q_airfoil: &[f64]) -> Result<Self, ViscousError> {
        let geom = &model.airfoil;
        let n = geom.len();
        let stag = find_stagnation(&q_airfoil[..n], &geom.s)?;
        let ist = stag.ist;
        let mut stations = Vec::with_capacity(model.n_nodes());
        // Upper surface: nodes ist, ist−1, …, 0.
        for (k, i) in (0..=ist).rev().enumerate() {
            stations.push(Station {
                node: i,
                surface: Surface::Upper,
                vti: 1.0,
                xi: (stag.sst - geom.s[i]).max(0.0),
                wake_gap: 0.0,
                upstream: if k == 0 { None } else { Some(k - 1) },
                kind: if k == 0 {
                    StationKind::Similarity
                } else {
                    StationKind::Interval
                },
            });
        }
        let n_upper = stations.len();
        for (k, i) in (ist + 1..n).enumerate() {
            let sys = n_upper + k;
            stations.push(Station {
                node: i,
                surface: Surface::Lower,
                vti: -1.0,
                xi: (geom.s[i] - stag.sst).max(0.0),
                wake_gap: 0.0,
                upstream: if k == 0 { None } else { Some(sys - 1) },
                kind: if k == 0 {
                    StationKind::Similarity
                } else {
                    StationKind::Interval
                },
            });
        }
        let n_lower = stations.len() - n_upper;
        let nw = model.n_nodes() - n;
        // The wake gap closes behind a blunt TE as a cubic over WAKE_GAP_LENGTH_RATIO gaps,
        // leaving the TE at the angle between the two TE tangents (XFOIL XICALC).
        let te = &geom.te;
        let ante = model.te_gap();
        let limit = 3.0 / WAKE_GAP_LENGTH_RATIO;
        let dwdxte = te.wake_gap_slope.clamp(-limit, limit);
        let aa = 3.0 + WAKE_GAP_LENGTH_RATIO * dwdxte;
        let bb = -2.0 - WAKE_GAP_LENGTH_RATIO * dwdxte;
        let xi_te = stations.last().map(|s| s.xi).unwrap_or(0.0);
        let mut xi = xi_te;
        for iw in 0..nw {
            let node = n + iw;
            if iw > 0 {
                let ((x1, y1), (x2, y2)) = (model.node(node - 1), model.node(node));
                let (dx, dy) = (x2 - x1, y2 - y1);
                xi += (dx * dx + dy * dy).sqrt();
            }
            // Cubic closure of the dead-air region behind a blunt TE (XFOIL XICALC WGAP); none
            // behind a sharp one.
            let zn = 1.0 - (xi - xi_te) / (WAKE_GAP_LENGTH_RATIO * ante);
            let gap = if !te.sharp && zn >= 0.0 {
                ante * (aa + bb * zn) * zn * zn
            } else {
                0.0
            };
            let sys = stations.len();
            stations.push(Station {
                node,
                surface: Surface::Wake,
                vti: -1.0,
                xi,
                wake_gap: gap,
                upstream: if iw == 0 { None } else { Some(sys - 1) },
                kind: if iw == 0 {
                    StationKind::WakeStart
                } else {
                    StationKind::Interval
                },
            });
        }
        Ok(Self {
            stagnation: stag,
            stations,
            n_upper,
            n_lower,
            n_wake: nw,
        })
    }

    /// Number of stations in the system.
    pub fn len(&self) -> usize {
        self.stations.len()
    }

    /// True if there are no stations.
    pub fn is_empty(&self) -> bool {
        self.stations.is_empty()
    }

    /// System index of the upper trailing-edge station.
    pub fn upper_te(&self) -> usize {
        self.n_upper - 1
    }

    /// System index of the lower trailing-edge station.
    pub fn lower_te(&self) -> usize {
        self.n_upper + self.n_lower - 1
    }

    /// System index of the first wake station.
    pub fn wake_start(&self) -> usize {
        self.n_upper + self.n_lower
    }

    /// Range of system indices of one surface (the wake included with `Surface::Wake`).
    pub fn range(&self, surface: Surface) -> std::ops::Range<usize> {
        match surface {
            Surface::Upper => 0..self.n_upper,
            Surface::Lower => self.n_upper..self.n_upper + self.n_lower,
            Surface::Wake => self.n_upper + self.n_lower..self.len(),
        }
    }

    /// Inviscid edge speed per station, Ue_inv = vti·q_inv (XFOIL UICALC).
    pub fn edge_speed(&self, q_nodes: &[f64]) -> Vec<f64> {
        self.stations
            .iter()
            .map(|st| st.vti * q_nodes[st.node])
            .collect()
    }

    /// For every station of `self`, the station of `old` that carries the best initial state
    /// (XFOIL STMOVE): the same node on the same surface if it exists, otherwise the first station
    /// of the same surface in `old` (nodes that crossed the stagnation point).
    pub fn map_from(&self, old: &StationLayout) -> Vec<usize> {
        let mut by_node =
            vec![usize::MAX; old.stations.iter().map(|s| s.node + 1).max().unwrap_or(0)];
        for (k, st) in old.stations.iter().enumerate() {
            by_node[st.node] = k;
        }
        self.stations
            .iter()
            .map(|st| {
                let k = by_node.get(st.node).copied().unwrap_or(usize::MAX);
                if k != usize::MAX && old.stations[k].surface == st.surface {
                    k
                } else {
                    old.range(st.surface).start
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests;
