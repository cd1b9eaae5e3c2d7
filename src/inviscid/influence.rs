//! Influence coefficients of XFOIL's linear-vorticity / linear-source panels on the stream
//! function ψ and on its normal derivative ∂ψ/∂n (Drela 1989, "XFOIL: An analysis and design
//! system for low Reynolds number airfoils", §2; XFOIL xpanel.f PSILIN and PSWLIN, the TE
//! panel's strengths from TECALC).
//!
//! Conventions (identical to XFOIL):
//! * nodes in XFOIL order (upper TE → LE → lower TE), panel `j` runs from node `j` to `j+1`,
//!   the trailing-edge panel runs from the last node back to node 0;
//! * vorticity γ is linear over each panel; on the body γ equals the surface speed with the sign
//!   of `−u·ŝ` (ŝ = panel direction), i.e. positive on the upper surface, negative below;
//! * the source strength of the viscous coupling is `dm/ds`, where `m = Ue·δ*` is the nodal
//!   mass defect; it is linear over each half panel, with slopes taken from the nodal `m`
//!   values (PSILIN "SIG" terms);
//! * ψ of a panel is normalised by 1/(4π) (QOPI) and the TE panel by 1/(2π) (HOPI), so that
//!   γ, σ are in units of V∞ and ψ in V∞·c.

use std::f64::consts::PI;

use super::contour::PanelGeometry;

/// 1/(4π): normalisation of a linear panel's ψ integral (XFOIL QOPI).
const QOPI: f64 = 0.25 / PI;
/// 1/(2π): normalisation of the trailing-edge panel's ψ integral (XFOIL HOPI).
const HOPI: f64 = 0.5 / PI;

/// Distance between two points (plain square root, as XFOIL; faster than `hypot`).
#[inline]
fn dist(ax: f64, ay: f64, bx: f64, by: f64) -> f64 {
    ((bx - ax) * (bx - ax) + (by - ay) * (by - ay)).sqrt()
}

/// Local frame of one straight panel seen from a field point (PSILIN/PSWLIN geometry block):
/// panel-aligned coordinates of both ends, log r² and arctan terms with XFOIL's reflection
/// rule, and the derivatives of the coordinates with respect to the field normal direction.
#[derive(Clone, Copy, Debug)]
struct PanelFrame {
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
    sx: f64,
    /// Panel unit tangent y.
    sy: f64,
    /// d(x1)/dn = d(x2)/dn at the field point.
    xi: f64,
    /// d(yy)/dn at the field point.
    yyi: f64,
    /// Reflection flag SGN.
    sgn: f64,
    /// Branch offset added to every arctan (±(½ − ½·SGN)π).
    branch: f64,
}

/// Field point of an influence evaluation: decides the arctan branch and which singular
/// panel-end terms are dropped (XFOIL's node index IO in PSILIN/PSWLIN).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldPoint {
    /// Airfoil node with this 0-based index.
    Airfoil(usize),
    /// Wake node with this 0-based index (0 = first wake node behind the TE).
    Wake(usize),
    /// Any other point (e.g. the sharp-TE bisector control point).
    Free,
}

/// Field point location and normal used by the influence routines.
#[derive(Clone, Copy, Debug)]
pub struct Probe {
    /// Which kind of point this is.
    pub kind: FieldPoint,
    /// x coordinate.
    pub x: f64,
    /// y coordinate.
    pub y: f64,
    /// Normal x component for ∂ψ/∂n.
    pub nx: f64,
    /// Normal y component for ∂ψ/∂n.
    pub ny: f64,
}

impl Probe {
    /// Airfoil node `i` of `g`, with its outward normal.
    pub fn airfoil_node(g: &PanelGeometry, i: usize) -> Self {
        Self {
            kind: FieldPoint::Airfoil(i),
            x: g.x[i],
            y: g.y[i],
            nx: g.nx[i],
            ny: g.ny[i],
        }
    }

    /// Wake node `i` at (`x`, `y`) with the normal (`nx`, `ny`).
    pub fn wake_node(i: usize, (x, y): (f64, f64), (nx, ny): (f64, f64)) -> Self {
        Self {
            kind: FieldPoint::Wake(i),
            x,
            y,
            nx,
            ny,
        }
    }
}

impl PanelFrame {
    /// Builds the frame of panel (xa,ya)→(xb,yb). `on_line` is true when the field point lies
    /// on the same panel line family (SGN = 1), `self_a`/`self_b` when it is that end node.
    /// `branch_sign` is +1 for airfoil panels (PSILIN) and −1 for wake panels (PSWLIN).
    #[allow(clippy::too_many_arguments)]
    #[inline]
    fn new(
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
            (rs1.ln(), (sgn * x1).atan2(sgn * yy) + branch)
        } else {
            (0.0, 0.0)
        };
        let (g2, t2) = if !self_b && rs2 > 0.0 {
            (rs2.ln(), (sgn * x2).atan2(sgn * yy) + branch)
        } else {
            (0.0, 0.0)
        };
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
            sgn,
            branch,
        }
    }

    /// Linear-vorticity panel (PSILIN vortex block): returns (ψ_sum, ψ_dif, ∂ψ_sum/∂n,
    /// ∂ψ_dif/∂n); the panel contributes QOPI·(ψ_sum·(γa+γb) + ψ_dif·(γb−γa)).
    #[inline]
    fn vortex(&self) -> (f64, f64, f64, f64) {
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
    fn vortex_terms(&self) -> [f64; 6] {
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
    fn te_panel(&self, apan: f64) -> (f64, f64, f64, f64) {
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
    fn te_terms(&self, apan: f64) -> [f64; 6] {
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

    /// Linear-source panel split at its midpoint (PSILIN/PSWLIN "SIGLIN" block). Returns the
    /// (ψ_sum, ψ_dif, ∂ψ_sum/∂n, ∂ψ_dif/∂n) of the first half (node a → midpoint) and of the
    /// second half (midpoint → node b).
    #[inline]
    fn source_halves(&self, apan: f64) -> ([f64; 4], [f64; 4]) {
        let x0 = 0.5 * (self.x1 + self.x2);
        let rs0 = x0 * x0 + self.yy * self.yy;
        let g0 = rs0.ln();
        let t0 = (self.sgn * x0).atan2(self.sgn * self.yy) + self.branch;
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
    let psum = xb * tb - xa * ta + 0.5 * yy * (ga - gb);
    let pdif = ((xa + xb) * psum + rsa * ta - rsb * tb + (xb - xa) * yy) * dxinv;
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

/// Sensitivities of ψ and ∂ψ/∂n at one field point to the airfoil's nodal vorticity and
/// nodal mass defect (XFOIL DZDG, DQDG, DZDM, DQDM). Freestream terms are not included.
#[derive(Clone, Debug)]
pub struct Influence {
    /// dψ/dγ_j.
    pub psi_gamma: Vec<f64>,
    /// d(∂ψ/∂n)/dγ_j.
    pub qn_gamma: Vec<f64>,
    /// dψ/dm_j (mass defect m_j = Ue·δ* at node j).
    pub psi_source: Vec<f64>,
    /// d(∂ψ/∂n)/dm_j.
    pub qn_source: Vec<f64>,
}

impl Influence {
    /// Zeroed buffers for `n` nodes.
    pub fn new(n: usize) -> Self {
        Self {
            psi_gamma: vec![0.0; n],
            qn_gamma: vec![0.0; n],
            psi_source: vec![0.0; n],
            qn_source: vec![0.0; n],
        }
    }

    fn clear(&mut self) {
        self.psi_gamma.fill(0.0);
        self.qn_gamma.fill(0.0);
        self.psi_source.fill(0.0);
        self.qn_source.fill(0.0);
    }
}

/// Neighbour indices (jm, jq) of panel jo→jo+1 on an open line of `n` nodes, used for the
/// source slopes (PSILIN/PSWLIN: JM = JO at the first panel, JQ = JP at the last).
#[inline]
fn source_neighbours(jo: usize, n: usize) -> (usize, usize) {
    let jm = if jo == 0 { jo } else { jo - 1 };
    let jq = if jo + 2 >= n { jo + 1 } else { jo + 2 };
    (jm, jq)
}

/// Accumulates the source sensitivities of one panel jo→jo+1 of a line (x, y) into
/// `psi_out`/`qn_out` (XFOIL PSILIN/PSWLIN dPsi/dm and dQ/dm updates).
#[allow(clippy::too_many_arguments)]
#[inline]
fn add_source_panel(
    frame: &PanelFrame,
    apan: f64,
    x: &[f64],
    y: &[f64],
    jo: usize,
    psi_out: &mut [f64],
    qn_out: &mut [f64],
) {
    let n = x.len();
    let jp = jo + 1;
    let (jm, jq) = source_neighbours(jo, n);
    let dsio = 1.0 / dist(x[jo], y[jo], x[jp], y[jp]);
    let dsim = 1.0 / dist(x[jm], y[jm], x[jp], y[jp]);
    let dsip = 1.0 / dist(x[jo], y[jo], x[jq], y[jq]);
    let ([psum, pdif, psni, pdni], [psum2, pdif2, psni2, pdni2]) = frame.source_halves(apan);
    // first half: SSUM = (m_p − m_o)/dso + (m_p − m_m)/dsm, SDIF = (m_p − m_o)/dso − (m_p − m_m)/dsm
    psi_out[jm] += QOPI * (-psum + pdif) * dsim;
    psi_out[jo] += QOPI * (-psum - pdif) * dsio;
    psi_out[jp] += QOPI * (psum * (dsio + dsim) + pdif * (dsio - dsim));
    qn_out[jm] += QOPI * (-psni + pdni) * dsim;
    qn_out[jo] += QOPI * (-psni - pdni) * dsio;
    qn_out[jp] += QOPI * (psni * (dsio + dsim) + pdni * (dsio - dsim));
    // second half: SSUM = (m_q − m_o)/dsp + (m_p − m_o)/dso, SDIF = (m_q − m_o)/dsp − (m_p − m_o)/dso
    psi_out[jo] += QOPI * (-psum2 * (dsip + dsio) - pdif2 * (dsip - dsio));
    psi_out[jp] += QOPI * (psum2 - pdif2) * dsio;
    psi_out[jq] += QOPI * (psum2 + pdif2) * dsip;
    qn_out[jo] += QOPI * (-psni2 * (dsip + dsio) - pdni2 * (dsip - dsio));
    qn_out[jp] += QOPI * (psni2 - pdni2) * dsio;
    qn_out[jq] += QOPI * (psni2 + pdni2) * dsip;
}

/// Builds the frame of airfoil panel jo (jo = N−1 is the TE panel) seen from `p` (PSILIN).
#[inline]
fn airfoil_frame(g: &PanelGeometry, p: &Probe, jo: usize) -> PanelFrame {
    let n = g.len();
    let jp = if jo + 1 == n { 0 } else { jo + 1 };
    let (on, sa, sb) = match p.kind {
        FieldPoint::Airfoil(i) => (true, i == jo, i == jp),
        _ => (false, false, false),
    };
    PanelFrame::new(p, g.x[jo], g.y[jo], g.x[jp], g.y[jp], on, sa, sb, 1.0)
}

/// XFOIL PSILIN: sensitivities of ψ and ∂ψ/∂n at probe `p` to the nodal vorticity of all
/// airfoil panels (incl. the TE panel's source/vortex, which are tied to γ₀ − γ_{N−1}) and,
/// if `with_sources`, to the nodal mass defect of the airfoil source panels. Freestream terms
/// are excluded (ψ∞ = y·cos α − x·sin α).
pub fn airfoil_influence(g: &PanelGeometry, p: &Probe, with_sources: bool, out: &mut Influence) {
    let n = g.len();
    out.clear();
    for jo in 0..n - 1 {
        let f = airfoil_frame(g, p, jo);
        if with_sources {
            add_source_panel(
                &f,
                g.apanel[jo],
                &g.x,
                &g.y,
                jo,
                &mut out.psi_source,
                &mut out.qn_source,
            );
        }
        let (psis, psid, psni, pdni) = f.vortex();
        out.psi_gamma[jo] += QOPI * (psis - psid);
        out.psi_gamma[jo + 1] += QOPI * (psis + psid);
        out.qn_gamma[jo] += QOPI * (psni - pdni);
        out.qn_gamma[jo + 1] += QOPI * (psni + pdni);
    }
    if !g.te.closed {
        let f = airfoil_frame(g, p, n - 1);
        let (psig, pgam, psigni, pgamni) = f.te_panel(g.apanel[n - 1]);
        let (scs, sds) = (g.te.scs, g.te.sds);
        let dpsi = HOPI * (psig * 0.5 * scs - pgam * 0.5 * sds);
        let dqn = HOPI * (psigni * 0.5 * scs - pgamni * 0.5 * sds);
        out.psi_gamma[n - 1] -= dpsi;
        out.psi_gamma[0] += dpsi;
        out.qn_gamma[n - 1] -= dqn;
        out.qn_gamma[0] += dqn;
    }
}

/// Gradient of the airfoil-vorticity stream function at probe `p`: `gx[j] = d(∂ψ/∂x)/dγ_j`,
/// `gy[j] = d(∂ψ/∂y)/dγ_j` (PSILIN's dQ/dγ for the normals (1, 0) and (0, 1), evaluated in one
/// pass; ∂ψ/∂n for any normal n is `n_x·gx + n_y·gy`). Freestream excluded.
pub fn airfoil_vortex_gradient(g: &PanelGeometry, p: &Probe, gx: &mut [f64], gy: &mut [f64]) {
    let n = g.len();
    gx.fill(0.0);
    gy.fill(0.0);
    for jo in 0..n - 1 {
        let f = airfoil_frame(g, p, jo);
        let v = f.vortex_terms();
        // (1, 0): xi = sx, yyi = −sy;  (0, 1): xi = sy, yyi = sx.
        for (out, xi, yyi) in [(&mut *gx, f.sx, -f.sy), (&mut *gy, f.sy, f.sx)] {
            let psni = v[2] * xi + v[3] * yyi;
            let pdni = v[4] * xi + v[5] * yyi;
            out[jo] += QOPI * (psni - pdni);
            out[jo + 1] += QOPI * (psni + pdni);
        }
    }
    if !g.te.closed {
        let f = airfoil_frame(g, p, n - 1);
        let v = f.te_terms(g.apanel[n - 1]);
        let (scs, sds) = (g.te.scs, g.te.sds);
        for (out, xi, yyi) in [(&mut *gx, f.sx, -f.sy), (&mut *gy, f.sy, f.sx)] {
            let psigni = v[2] * xi + v[3] * yyi;
            let pgamni = v[4] * xi + v[5] * yyi;
            let dqn = HOPI * (psigni * 0.5 * scs - pgamni * 0.5 * sds);
            out[n - 1] -= dqn;
            out[0] += dqn;
        }
    }
}

/// Builds the frame of wake panel jo seen from `p` (PSWLIN).
#[inline]
fn wake_frame(x: &[f64], y: &[f64], p: &Probe, jo: usize) -> PanelFrame {
    let (on, sa, sb) = match p.kind {
        FieldPoint::Wake(i) => (true, i == jo, i == jo + 1),
        _ => (false, false, false),
    };
    PanelFrame::new(p, x[jo], y[jo], x[jo + 1], y[jo + 1], on, sa, sb, -1.0)
}

/// XFOIL PSWLIN: sensitivities of ψ and ∂ψ/∂n at probe `p` to the nodal mass defect of the
/// wake source panels (line `x`, `y` with panel angles `apanel`), written into `psi_out`,
/// `qn_out` (length = number of wake nodes).
pub fn wake_source_influence(
    x: &[f64],
    y: &[f64],
    apanel: &[f64],
    p: &Probe,
    psi_out: &mut [f64],
    qn_out: &mut [f64],
) {
    psi_out.fill(0.0);
    qn_out.fill(0.0);
    for (jo, &apan) in apanel.iter().enumerate().take(x.len() - 1) {
        let f = wake_frame(x, y, p, jo);
        add_source_panel(&f, apan, x, y, jo, psi_out, qn_out);
    }
}

/// Direct evaluation of the source panels for given nodal mass defects: an independent
/// summation path of the PSILIN/PSWLIN source terms that verifies the sensitivities (tests
/// only).
#[cfg(test)]
pub(super) mod direct {
    use super::*;

    /// Direct evaluation of (ψ, ∂ψ/∂n) of one source panel jo→jo+1 of a line for given nodal mass
    /// defects `m` (the SSUM/SDIF form of PSILIN, without forming sensitivities).
    #[inline]
    fn source_panel_value(
        frame: &PanelFrame,
        apan: f64,
        x: &[f64],
        y: &[f64],
        jo: usize,
        m: &[f64],
    ) -> (f64, f64) {
        let n = x.len();
        let jp = jo + 1;
        let (jm, jq) = source_neighbours(jo, n);
        let dso = dist(x[jo], y[jo], x[jp], y[jp]);
        let dsm = dist(x[jm], y[jm], x[jp], y[jp]);
        let dsp = dist(x[jo], y[jo], x[jq], y[jq]);
        let slope_o = (m[jp] - m[jo]) / dso;
        let slope_m = (m[jp] - m[jm]) / dsm;
        let slope_p = (m[jq] - m[jo]) / dsp;
        let ([psum, pdif, psni, pdni], [psum2, pdif2, psni2, pdni2]) = frame.source_halves(apan);
        let (ssum1, sdif1) = (slope_o + slope_m, slope_o - slope_m);
        let (ssum2, sdif2) = (slope_p + slope_o, slope_p - slope_o);
        let psi = QOPI * (psum * ssum1 + pdif * sdif1 + psum2 * ssum2 + pdif2 * sdif2);
        let qn = QOPI * (psni * ssum1 + pdni * sdif1 + psni2 * ssum2 + pdni2 * sdif2);
        (psi, qn)
    }

    /// Direct (ψ, ∂ψ/∂n) at probe `p` of the airfoil source panels for nodal mass defects `m`
    /// (an independent summation path of the PSILIN source terms, used to verify sensitivities).
    pub(crate) fn airfoil_source_value(g: &PanelGeometry, p: &Probe, m: &[f64]) -> (f64, f64) {
        let n = g.len();
        let mut psi = 0.0;
        let mut qn = 0.0;
        for jo in 0..n - 1 {
            let f = airfoil_frame(g, p, jo);
            let (a, b) = source_panel_value(&f, g.apanel[jo], &g.x, &g.y, jo, m);
            psi += a;
            qn += b;
        }
        (psi, qn)
    }

    /// Direct (ψ, ∂ψ/∂n) at probe `p` of the wake source panels for nodal mass defects `m`.
    pub(crate) fn wake_source_value(
        x: &[f64],
        y: &[f64],
        apanel: &[f64],
        p: &Probe,
        m: &[f64],
    ) -> (f64, f64) {
        let mut psi = 0.0;
        let mut qn = 0.0;
        for (jo, &apan) in apanel.iter().enumerate().take(x.len() - 1) {
            let f = wake_frame(x, y, p, jo);
            let (a, b) = source_panel_value(&f, apan, x, y, jo, m);
            psi += a;
            qn += b;
        }
        (psi, qn)
    }
}
