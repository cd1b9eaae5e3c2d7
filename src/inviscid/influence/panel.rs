//! One straight panel seen from a field point (XFOIL PSILIN/PSWLIN): its local frame and the
//! integrals of a linear vortex, of the trailing-edge panel's constant source and vortex, and
//! of a linear source over each half panel, with their normal derivatives.

use std::f64::consts::PI;

use super::frames::{dist, source_neighbours, LineFrames};
use super::Probe;
use crate::numerics::elementary::{atan2, ln};

/// 1/(4π): normalisation of a linear panel's ψ integral (XFOIL QOPI).
pub(super) const QOPI: f64 = 0.25 / PI;
/// 1/(2π): normalisation of the trailing-edge panel's ψ integral (XFOIL HOPI).
pub(super) const HOPI: f64 = 0.5 / PI;

/// Local frame of one straight panel seen from a field point (PSILIN/PSWLIN geometry block):
/// panel-aligned coordinates of both ends, log r² and arctan terms with XFOIL's reflection
/// rule, and the derivatives of the coordinates with respect to the field normal direction.
#[derive(Clone, Copy, Debug)]
pub(super) struct PanelFrame {
    x1: f64,
    x2: f64,
    yy: f64,
    rs1: f64,
    rs2: f64,
    g1: f64,
    g2: f64,
    t1: f64,
    t2: f64,
    /// Panel unit tangent x.
    pub(super) sx: f64,
    /// Panel unit tangent y.
    pub(super) sy: f64,
    /// d(x1)/dn = d(x2)/dn at the field point.
    xi: f64,
    /// d(yy)/dn at the field point.
    yyi: f64,
    /// ln r² of the panel midpoint (source panels; XFOIL G0).
    g0: f64,
    /// Arctangent at the panel midpoint (source panels; XFOIL T0).
    t0: f64,
}

impl PanelFrame {
    /// Builds the frame of panel (xa,ya)→(xb,yb). `on_line` is true when the field point lies
    /// on the same panel line family (SGN = 1), `self_a`/`self_b` when it is that end node.
    /// `branch_sign` is +1 for airfoil panels (PSILIN) and −1 for wake panels (PSWLIN).
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub(super) fn new(
        p: &Probe,
        xa: f64,
        ya: f64,
        xb: f64,
        yb: f64,
        on_line: bool,
        self_a: bool,
        self_b: bool,
        branch_sign: f64,
    ) -> Self {
        let dso = dist(xa, ya, xb, yb);
        let sx = (xb - xa) / dso;
        let sy = (yb - ya) / dso;
        let rx1 = p.x - xa;
        let ry1 = p.y - ya;
        let rx2 = p.x - xb;
        let ry2 = p.y - yb;
        let x1 = sx * rx1 + sy * ry1;
        let x2 = sx * rx2 + sy * ry2;
        let yy = sx * ry1 - sy * rx1;
        let rs1 = rx1 * rx1 + ry1 * ry1;
        let rs2 = rx2 * rx2 + ry2 * ry2;
        let sgn = if on_line || yy >= 0.0 { 1.0 } else { -1.0 };
        let branch = branch_sign * (0.5 - 0.5 * sgn) * PI;
        let (g1, t1) = if !self_a && rs1 > 0.0 {
            (ln(rs1), atan2(sgn * x1, sgn * yy) + branch)
        } else {
            (0.0, 0.0)
        };
        let (g2, t2) = if !self_b && rs2 > 0.0 {
            (ln(rs2), atan2(sgn * x2, sgn * yy) + branch)
        } else {
            (0.0, 0.0)
        };
        let x0 = 0.5 * (x1 + x2);
        Self {
            x1,
            x2,
            yy,
            rs1,
            rs2,
            g1,
            g2,
            t1,
            t2,
            sx,
            sy,
            xi: sx * p.nx + sy * p.ny,
            yyi: sx * p.ny - sy * p.nx,
            g0: ln(x0 * x0 + yy * yy),
            t0: atan2(sgn * x0, sgn * yy) + branch,
        }
    }

    /// The frame of panel `jo` of a line from the terms evaluated in bulk ([`LineFrames`]),
    /// with unit tangent (`sx`, `sy`). An end at the field point itself (r = 0) has no log
    /// and arctangent terms, as in [`PanelFrame::new`].
    #[inline(always)]
    pub(super) fn from_frames(f: &LineFrames, jo: usize, p: &Probe, (sx, sy): (f64, f64)) -> Self {
        let (rs1, rs2) = (f.rs[jo], f.rs[jo + 1]);
        let (g1, t1) = if rs1 > 0.0 {
            (f.g[jo], f.t1[jo])
        } else {
            (0.0, 0.0)
        };
        let (g2, t2) = if rs2 > 0.0 {
            (f.g[jo + 1], f.t2[jo])
        } else {
            (0.0, 0.0)
        };
        Self {
            x1: f.x1[jo],
            x2: f.x2[jo],
            yy: f.yy[jo],
            rs1,
            rs2,
            g1,
            g2,
            t1,
            t2,
            sx,
            sy,
            xi: sx * p.nx + sy * p.ny,
            yyi: sx * p.ny - sy * p.nx,
            g0: f.g0[jo],
            t0: f.t0[jo],
        }
    }

    /// Linear-vorticity panel (PSILIN vortex block): returns (ψ_sum, ψ_dif, ∂ψ_sum/∂n,
    /// ∂ψ_dif/∂n); the panel contributes QOPI·(ψ_sum·(γa+γb) + ψ_dif·(γb−γa)).
    #[inline]
    pub(super) fn vortex(&self) -> (f64, f64, f64, f64) {
        let v = self.vortex_terms();
        (
            v[0],
            v[1],
            v[2] * self.xi + v[3] * self.yyi,
            v[4] * self.xi + v[5] * self.yyi,
        )
    }

    /// Vortex-panel integrals and their partial derivatives with respect to the panel-frame
    /// coordinates of the field point: [ψ_sum, ψ_dif, ∂ψ_sum/∂x, ∂ψ_sum/∂y, ∂ψ_dif/∂x,
    /// ∂ψ_dif/∂y] (PSILIN PSIS, PSID, PSX1+PSX2, PSYY, PDX1+PDX2, PDYY).
    #[inline]
    pub(super) fn vortex_terms(&self) -> [f64; 6] {
        let (x1, x2, yy) = (self.x1, self.x2, self.yy);
        let (g1, g2, t1, t2) = (self.g1, self.g2, self.t1, self.t2);
        let dxinv = 1.0 / (x1 - x2);
        let psis = 0.5 * x1 * g1 - 0.5 * x2 * g2 + x2 - x1 + yy * (t1 - t2);
        let psid =
            ((x1 + x2) * psis + 0.5 * (self.rs2 * g2 - self.rs1 * g1 + x1 * x1 - x2 * x2)) * dxinv;
        let psx1 = 0.5 * g1;
        let psx2 = -0.5 * g2;
        let psyy = t1 - t2;
        let pdx1 = ((x1 + x2) * psx1 + psis - x1 * g1 - psid) * dxinv;
        let pdx2 = ((x1 + x2) * psx2 + psis + x2 * g2 + psid) * dxinv;
        let pdyy = ((x1 + x2) * psyy - yy * (g1 - g2)) * dxinv;
        [psis, psid, psx1 + psx2, psyy, pdx1 + pdx2, pdyy]
    }

    /// Constant-strength source and vortex integrals of the TE panel (PSILIN label 11):
    /// returns (ψ_σ, ψ_γ, ∂ψ_σ/∂n, ∂ψ_γ/∂n), to be weighted by HOPI·σ_TE and HOPI·γ_TE.
    #[inline]
    pub(super) fn te_panel(&self, apan: f64) -> (f64, f64, f64, f64) {
        let v = self.te_terms(apan);
        (
            v[0],
            v[1],
            v[2] * self.xi + v[3] * self.yyi,
            v[4] * self.xi + v[5] * self.yyi,
        )
    }

    /// TE-panel integrals and partial derivatives in the panel frame: [ψ_σ, ψ_γ, ∂ψ_σ/∂x,
    /// ∂ψ_σ/∂y, ∂ψ_γ/∂x, ∂ψ_γ/∂y] (PSILIN PSIG, PGAM, PSIGX1+PSIGX2, PSIGYY, PGAMX1+PGAMX2,
    /// PGAMYY).
    #[inline]
    pub(super) fn te_terms(&self, apan: f64) -> [f64; 6] {
        let (x1, x2, yy) = (self.x1, self.x2, self.yy);
        let (g1, g2, t1, t2) = (self.g1, self.g2, self.t1, self.t2);
        let psig = 0.5 * yy * (g1 - g2) + x2 * (t2 - apan) - x1 * (t1 - apan);
        let pgam = 0.5 * x1 * g1 - 0.5 * x2 * g2 + x2 - x1 + yy * (t1 - t2);
        [
            psig,
            pgam,
            -(t1 - apan) + (t2 - apan),
            0.5 * (g1 - g2),
            0.5 * g1 - 0.5 * g2,
            t1 - t2,
        ]
    }

    /// Linear-source panel split at its midpoint (PSILIN/PSWLIN "SIGLIN" block), with the
    /// midpoint terms of the frame. Returns the
    /// (ψ_sum, ψ_dif, ∂ψ_sum/∂n, ∂ψ_dif/∂n) of the first half (node a → midpoint) and of the
    /// second half (midpoint → node b).
    #[inline]
    pub(super) fn source_halves(&self, apan: f64) -> ([f64; 4], [f64; 4]) {
        let x0 = 0.5 * (self.x1 + self.x2);
        let rs0 = x0 * x0 + self.yy * self.yy;
        let (g0, t0) = (self.g0, self.t0);
        let first = half_source(
            self.x1, x0, self.yy, self.t1, t0, self.g1, g0, self.rs1, rs0, apan, self.xi, self.yyi,
        );
        let second = half_source(
            x0, self.x2, self.yy, t0, self.t2, g0, self.g2, rs0, self.rs2, apan, self.xi, self.yyi,
        );
        (first, second)
    }
}

/// Linear source over a half panel from panel coordinate `xa` to `xb` (XFOIL PSILIN PSUM/PDIF
/// with their normal derivatives); returns [ψ_sum, ψ_dif, ∂ψ_sum/∂n, ∂ψ_dif/∂n].
#[allow(clippy::too_many_arguments)]
#[inline]
fn half_source(
    xa: f64,
    xb: f64,
    yy: f64,
    ta: f64,
    tb: f64,
    ga: f64,
    gb: f64,
    rsa: f64,
    rsb: f64,
    apan: f64,
    xi: f64,
    yyi: f64,
) -> [f64; 4] {
    let dxinv = 1.0 / (xa - xb);
    let ta = ta - apan;
    let tb = tb - apan;
    let [psum, pdif] = half_source_psi([xa, xb], yy, [ta, tb], [ga, gb], [rsa, rsb]);
    let psxa = -ta;
    let psxb = tb;
    let psyy = 0.5 * (ga - gb);
    let pdxa = ((xa + xb) * psxa + psum + 2.0 * xa * ta - pdif) * dxinv;
    let pdxb = ((xa + xb) * psxb + psum - 2.0 * xb * tb + pdif) * dxinv;
    let pdyy = ((xa + xb) * psyy + 2.0 * (xb - xa + yy * (ta - tb))) * dxinv;
    let psni = (psxa + psxb) * xi + psyy * yyi;
    let pdni = (pdxa + pdxb) * xi + pdyy * yyi;
    [psum, pdif, psni, pdni]
}

/// ψ of a linear source over a half panel from panel coordinate `xa` to `xb` at normal
/// distance `yy` (XFOIL PSILIN PSUM, PDIF): the arctangents `t` (panel angle already
/// subtracted), ln r² `g` and r² `rs` at both ends give [ψ_sum, ψ_dif].
#[inline(always)]
pub(super) fn half_source_psi(
    [xa, xb]: [f64; 2],
    yy: f64,
    [ta, tb]: [f64; 2],
    [ga, gb]: [f64; 2],
    [rsa, rsb]: [f64; 2],
) -> [f64; 2] {
    let psum = xb * tb - xa * ta + 0.5 * yy * (ga - gb);
    let pdif = ((xa + xb) * psum + rsa * ta - rsb * tb + (xb - xa) * yy) / (xa - xb);
    [psum, pdif]
}

/// The source sensitivities of one panel jo→jo+1 (XFOIL PSILIN/PSWLIN dPsi/dm and dQ/dm
/// updates): its contributions to ψ and to ∂ψ/∂n per mass defect at the nodes jm, jo, jp, jq
/// of its source-slope stencil ([`source_neighbours`]); `inv_ds` are the panel's inverse
/// stencil lengths ([`super::PanelLine::inv_ds`]).
#[inline(always)]
pub(super) fn source_coefficients(
    frame: &PanelFrame,
    apan: f64,
    [dsio, dsim, dsip]: [f64; 3],
) -> [[f64; 4]; 2] {
    let ([psum, pdif, psni, pdni], [psum2, pdif2, psni2, pdni2]) = frame.source_halves(apan);
    // First half: SSUM = (m_p − m_o)/dso + (m_p − m_m)/dsm, SDIF = (m_p − m_o)/dso − (m_p −
    // m_m)/dsm; second half: SSUM = (m_q − m_o)/dsp + (m_p − m_o)/dso, SDIF = (m_q − m_o)/dsp
    // − (m_p − m_o)/dso.
    let stencil = |sum: f64, dif: f64, sum2: f64, dif2: f64| {
        [
            QOPI * (-sum + dif) * dsim,
            QOPI * (-sum - dif) * dsio + QOPI * (-sum2 * (dsip + dsio) - dif2 * (dsip - dsio)),
            QOPI * (sum * (dsio + dsim) + dif * (dsio - dsim)) + QOPI * (sum2 - dif2) * dsio,
            QOPI * (sum2 + dif2) * dsip,
        ]
    };
    [
        stencil(psum, pdif, psum2, pdif2),
        stencil(psni, pdni, psni2, pdni2),
    ]
}

/// Adds the source sensitivities of panel jo of a line of `n` nodes
/// ([`source_coefficients`]) to `psi_out`/`qn_out`.
#[inline]
pub(super) fn add_source_panel(
    frame: &PanelFrame,
    apan: f64,
    inv_ds: [f64; 3],
    (jo, n): (usize, usize),
    psi_out: &mut [f64],
    qn_out: &mut [f64],
) {
    let (jm, jq) = source_neighbours(jo, n);
    let [psi, qn] = source_coefficients(frame, apan, inv_ds);
    for (k, j) in [jm, jo, jo + 1, jq].into_iter().enumerate() {
        psi_out[j] += psi[k];
        qn_out[j] += qn[k];
    }
}
