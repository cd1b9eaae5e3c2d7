//! Source (mass-defect) influence matrix of the viscous–inviscid coupling (XFOIL xpanel.f
//! QDCALC, Drela 1989 §4): the tangential speed at every airfoil and wake node is
//! `q = q_inv(α) + D·σ`.
//!
//! # Conventions and units
//! * Node order: the N airfoil nodes (XFOIL order) followed by the NW wake nodes.
//! * `q` is the tangential speed per V∞ with XFOIL's sign: on the airfoil it is γ (positive
//!   on the upper surface, negative on the lower), on the wake it continues the lower-surface
//!   sign (negative for downstream flow), see [`Wake`].
//! * `σ_j` is XFOIL's nodal source variable (per V∞·c): the panels carry the source density
//!   dσ/ds, linear over half panels. With the boundary-layer mass defect `m = Ue·δ*` (Ue > 0)
//!   it is `σ = −m` on the upper surface and `σ = +m` on the lower surface and the wake, i.e.
//!   `σ = −VTI·m` with XFOIL's VTI = ±1. Hence `dUe_i/dm_j = −VTI_i·VTI_j·D_ij` (XFOIL UESET).
//! * `D_ij = ∂q_i/∂σ_j` (units 1/c). Airfoil rows come from back-substituting −dψ/dσ through
//!   the factorised panel system (the vorticity adjusts to keep the body a streamline and to
//!   satisfy the Kutta condition); wake rows are the direct source-panel speeds plus the
//!   effect of those vorticity changes. The first wake row copies the last airfoil row (XFOIL).
//! * As in XFOIL, wake sources do not enter the Kutta row nor, for a sharp TE, the bisector
//!   row of the panel system.

use std::sync::Arc;

use faer::linalg::matmul::matmul;
use faer::{Accum, Mat, MatRef, Par};

use super::influence::{wake_source_influence, wake_source_psi, LineFrames};
use super::system::PanelSystem;
use super::wake::Wake;
use crate::numerics::simd::reset_simd_state;

/// The source influence matrix D for one airfoil and wake, (N+NW) × (N+NW), in three blocks:
/// the airfoil rows' airfoil columns, which do not depend on α and are shared by the models of
/// every α ([`PanelSystem::airfoil_source_sensitivity`]); the airfoil rows' wake columns; and
/// the wake rows. Only the last two are built per α.
#[derive(Clone, Debug)]
pub struct SourceInfluence {
    /// Airfoil nodes N.
    n: usize,
    /// Wake nodes NW.
    nw: usize,
    /// Airfoil rows, airfoil columns: N × N row-major, `airfoil[i·N + j] = ∂q_i/∂σ_j`.
    airfoil: Arc<[f64]>,
    /// Airfoil rows, wake columns: N × NW row-major.
    airfoil_wake: Vec<f64>,
    /// Wake rows: NW × (N+NW) row-major.
    wake: Vec<f64>,
}

impl SourceInfluence {
    /// Builds D for `system` and `wake` (XFOIL QDCALC), O(NW·(N+NW)) kernel evaluations plus
    /// one back-substitution per wake node and an (NW−1)×N by N×(N+NW) product (in two column
    /// blocks).
    pub(crate) fn new(system: &PanelSystem, wake: &Wake) -> Self {
        let g = system.geometry();
        let n = g.len();
        let nw = wake.len();
        let nt = n + nw;
        reset_simd_state();
        let airfoil = system.airfoil_source_sensitivity();

        // Airfoil rows, wake sources: −dψ/dσ_w on each node row, back-substituted.
        let last_row = if g.te.sharp { n - 1 } else { n };
        let mut psi = vec![0.0; last_row * nw];
        wake_source_psi(
            wake.source_line(),
            &g.x[..last_row],
            &g.y[..last_row],
            &mut psi,
        );
        let mut bw = Mat::<f64>::from_fn(n + 1, nw, |i, j| {
            if i < last_row {
                -psi[j * last_row + i]
            } else {
                0.0
            }
        });
        // Wake rows: direct source speeds, and (below) dq/dγ for the chain through the airfoil
        // (the airfoil panels' rows were evaluated with the wake, `Wake::qn_gamma`). Row 0 is
        // filled last.
        let mut wake_rows = vec![0.0; nw * nt];
        let mut psi_w = vec![0.0; nw];
        let mut qn_w = vec![0.0; nw];
        let mut frames = LineFrames::default();
        for iw in 1..nw {
            let probe = wake.probe(iw);
            let line = wake.source_line();
            wake_source_influence(line, &probe, &mut frames, &mut psi_w, &mut qn_w);
            let row = &mut wake_rows[iw * nt..(iw + 1) * nt];
            row[..n].copy_from_slice(&wake.qn_source[iw * n..(iw + 1) * n]);
            row[n..].copy_from_slice(&qn_w);
        }
        // Dense linear algebra last: airfoil rows' wake columns from the factorised system,
        // then the wake rows' chain through the airfoil vorticity.
        system.back_substitute(bw.as_mut());
        let mut airfoil_wake = Vec::with_capacity(n * nw);
        for i in 0..n {
            airfoil_wake.extend((0..nw).map(|j| bw[(i, j)]));
        }
        let c = MatRef::from_row_major_slice(&wake.qn_gamma[n..], nw - 1, n);
        let mut bottom = faer::MatMut::from_row_major_slice_mut(&mut wake_rows[nt..], nw - 1, nt);
        let (mut left, mut right) = bottom.as_mut().split_at_col_mut(n);
        let a = MatRef::from_row_major_slice(&airfoil, n, n);
        matmul(left.as_mut(), Accum::Add, c, a, 1.0, Par::Seq);
        let aw = MatRef::from_row_major_slice(&airfoil_wake, n, nw);
        matmul(right.as_mut(), Accum::Add, c, aw, 1.0, Par::Seq);
        reset_simd_state();
        // First wake node carries the TE speed: D's last airfoil row.
        wake_rows[..n].copy_from_slice(&airfoil[(n - 1) * n..]);
        wake_rows[n..nt].copy_from_slice(&airfoil_wake[(n - 1) * nw..]);
        Self {
            n,
            nw,
            airfoil,
            airfoil_wake,
            wake: wake_rows,
        }
    }

    /// D = 0 for `n` airfoil and `nw` wake nodes: no coupling between the mass defect and the
    /// edge speed (a boundary layer on a fixed edge speed).
    pub fn zeros(n: usize, nw: usize) -> Self {
        Self {
            n,
            nw,
            airfoil: vec![0.0; n * n].into(),
            airfoil_wake: vec![0.0; n * nw],
            wake: vec![0.0; nw * (n + nw)],
        }
    }

    /// Number of nodes N + NW (D is square of that size).
    pub fn n_nodes(&self) -> usize {
        self.n + self.nw
    }

    /// Number of airfoil nodes N (where [`row`](Self::row) splits each row).
    pub fn n_airfoil(&self) -> usize {
        self.n
    }

    /// Row `i` of D in two parts: its airfoil columns (N) and its wake columns (NW).
    #[inline]
    pub fn row(&self, i: usize) -> (&[f64], &[f64]) {
        let (n, nw) = (self.n, self.nw);
        if i < n {
            (
                &self.airfoil[i * n..(i + 1) * n],
                &self.airfoil_wake[i * nw..(i + 1) * nw],
            )
        } else {
            self.wake[(i - n) * (n + nw)..(i - n + 1) * (n + nw)].split_at(n)
        }
    }

    /// D as a dense matrix.
    #[cfg(test)]
    pub fn d(&self) -> Mat<f64> {
        let nt = self.n_nodes();
        Mat::from_fn(nt, nt, |i, j| {
            let (air, wake) = self.row(i);
            if j < self.n {
                air[j]
            } else {
                wake[j - self.n]
            }
        })
    }

    /// D·σ: speed change at every node for sources `sigma` (length N + NW).
    #[cfg(test)]
    pub fn apply(&self, sigma: &[f64]) -> Vec<f64> {
        let d = self.d();
        let nt = d.nrows();
        assert_eq!(sigma.len(), nt, "one source per airfoil and wake node");
        (0..nt)
            .map(|i| (0..nt).map(|j| d[(i, j)] * sigma[j]).sum())
            .collect()
    }
}

/// The speeds re-solved with the sources summed directly, which verify D (tests only).
#[cfg(test)]
pub(crate) mod direct {
    use super::*;
    use crate::inviscid::influence::direct::{airfoil_source_value, wake_source_value};
    use crate::inviscid::influence::{airfoil_influence, Influence, Probe};
    use crate::numerics::dense::dot;

    /// Tangential speeds at all airfoil and wake nodes for `alpha_deg` with nodal sources
    /// `sigma` (length N + NW, conventions as in the module docs), by summing the source panels
    /// directly and re-solving the panel system — the non-linearised counterpart of
    /// `q_inv + D·σ`, used to verify D.
    pub(crate) fn speeds_with_sources(
        system: &PanelSystem,
        wake: &Wake,
        alpha_deg: f64,
        sigma: &[f64],
    ) -> Vec<f64> {
        let g = system.geometry();
        let n = g.len();
        let nw = wake.len();
        assert_eq!(sigma.len(), n + nw, "one source per airfoil and wake node");
        reset_simd_state();
        let (sig_a, sig_w) = sigma.split_at(n);
        let mut extra = vec![0.0; n];
        let last_row = if g.te.sharp { n - 1 } else { n };
        for (i, e) in extra.iter_mut().enumerate().take(last_row) {
            let probe = Probe::airfoil_node(g, i);
            *e = wake_source_value(&wake.x, &wake.y, &wake.apanel, &probe, sig_w).0;
        }
        let gamma = system.gamma_with_sources(alpha_deg, sig_a, &extra);
        let (sa, ca) = alpha_deg.to_radians().sin_cos();
        let mut q = gamma.clone();
        q.push(gamma[n - 1]);
        let mut inf = Influence::new(n);
        for iw in 1..nw {
            let probe = wake.probe(iw);
            airfoil_influence(g, &probe, false, &mut inf);
            let q_vortex = dot(&inf.qn_gamma, &gamma);
            let q_free = ca * wake.ny[iw] - sa * wake.nx[iw];
            let q_air = airfoil_source_value(g, &probe, sig_a).1;
            let q_wake = wake_source_value(&wake.x, &wake.y, &wake.apanel, &probe, sig_w).1;
            q.push(q_vortex + q_free + q_air + q_wake);
        }
        q
    }
}
