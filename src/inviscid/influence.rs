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

#[cfg(test)]
pub(super) mod direct;
mod frames;
mod panel;
mod wake_psi;

use super::contour::PanelGeometry;
use crate::numerics::simd::{with_avx2, Kernel};
use frames::View;
pub(crate) use frames::{LineFrames, PanelLine};
use panel::{add_source_panel, source_coefficients, PanelFrame, HOPI, QOPI};
pub(crate) use wake_psi::wake_source_psi;

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
    /// Memory of the panel terms.
    frames: LineFrames,
    /// Memory of the per-panel contributions.
    contributions: Contributions,
}

impl Influence {
    /// Zeroed buffers for `n` nodes.
    pub fn new(n: usize) -> Self {
        Self {
            psi_gamma: vec![0.0; n],
            qn_gamma: vec![0.0; n],
            psi_source: vec![0.0; n],
            qn_source: vec![0.0; n],
            frames: LineFrames::default(),
            contributions: Contributions::default(),
        }
    }
}

/// Builds the frame of airfoil panel jo (jo = N−1 is the TE panel) seen from `p` (PSILIN),
/// evaluating its terms on its own.
#[inline]
fn airfoil_frame(g: &PanelGeometry, p: &Probe, jo: usize) -> PanelFrame {
    let n = g.len();
    let jp = if jo + 1 == n { 0 } else { jo + 1 };
    let (on, sa, sb) = airfoil_self(p, jo, jp);
    PanelFrame::new(p, g.x[jo], g.y[jo], g.x[jp], g.y[jp], on, sa, sb, 1.0)
}

/// Whether `p` lies on the airfoil line and whether it is the first or second node of panel
/// jo → jp (PSILIN's IO tests).
#[inline]
fn airfoil_self(p: &Probe, jo: usize, jp: usize) -> (bool, bool, bool) {
    match p.kind {
        FieldPoint::Airfoil(i) => (true, i == jo, i == jp),
        _ => (false, false, false),
    }
}

/// Evaluates the terms of the airfoil's panels 0…N−2 seen from `p` into `frames` (the TE
/// panel is evaluated on its own).
fn airfoil_frames(g: &PanelGeometry, p: &Probe, midpoints: bool, frames: &mut LineFrames) {
    let view = View {
        x: p.x,
        y: p.y,
        on_line: matches!(p.kind, FieldPoint::Airfoil(_)),
        branch_sign: 1.0,
        midpoints,
    };
    frames.evaluate(&g.x, &g.y, &g.panels, view);
}

/// XFOIL PSILIN: sensitivities of ψ and ∂ψ/∂n at probe `p` to the nodal vorticity of all
/// airfoil panels (incl. the TE panel's source/vortex, which are tied to γ₀ − γ_{N−1}) and,
/// if `with_sources`, to the nodal mass defect of the airfoil source panels. Freestream terms
/// are excluded (ψ∞ = y·cos α − x·sin α).
pub fn airfoil_influence(g: &PanelGeometry, p: &Probe, with_sources: bool, out: &mut Influence) {
    airfoil_frames(g, p, with_sources, &mut out.frames);
    influence_from_frames(g, p, with_sources, out);
}

/// Gradient of the airfoil-vorticity stream function at probe `p`: `gx[j] = d(∂ψ/∂x)/dγ_j`,
/// `gy[j] = d(∂ψ/∂y)/dγ_j` (PSILIN's dQ/dγ for the normals (1, 0) and (0, 1), evaluated in one
/// pass; ∂ψ/∂n for any normal n is `n_x·gx + n_y·gy`). Freestream excluded. `scratch`
/// lends its memory (its sensitivities are left unspecified).
pub fn airfoil_vortex_gradient(
    g: &PanelGeometry,
    p: &Probe,
    scratch: &mut Influence,
    gx: &mut [f64],
    gy: &mut [f64],
) {
    airfoil_frames(g, p, false, &mut scratch.frames);
    gradient_from_frames(g, p, &scratch.frames, &mut scratch.contributions, gx, gy);
}

/// [`airfoil_influence`] with sources and [`airfoil_vortex_gradient`] at the same probe (a
/// wake node: its influence rows and the streamline direction), from one evaluation of the
/// panel terms.
pub fn airfoil_influence_and_gradient(
    g: &PanelGeometry,
    p: &Probe,
    out: &mut Influence,
    gx: &mut [f64],
    gy: &mut [f64],
) {
    airfoil_frames(g, p, true, &mut out.frames);
    influence_from_frames(g, p, true, out);
    gradient_from_frames(g, p, &out.frames, &mut out.contributions, gx, gy);
}

/// [`airfoil_influence`] from the panel terms already in `out`: every panel's contributions
/// side by side ([`Contributions`]), then their sums at the nodes.
fn influence_from_frames(g: &PanelGeometry, p: &Probe, with_sources: bool, out: &mut Influence) {
    let n = g.len();
    let kind = if with_sources {
        Terms::VortexAndSources
    } else {
        Terms::Vortex
    };
    with_avx2(Contribute {
        g,
        p,
        kind,
        frames: &out.frames,
        out: &mut out.contributions,
    });
    let c = &out.contributions.0;
    // Vortex: panel jo adds to its nodes jo and jo + 1; sources to their stencils.
    node_sums_vortex(&c[0], &c[1], &mut out.psi_gamma);
    node_sums_vortex(&c[2], &c[3], &mut out.qn_gamma);
    if with_sources {
        node_sums_source(&c[4..8], &mut out.psi_source);
        node_sums_source(&c[8..12], &mut out.qn_source);
    } else {
        out.psi_source.fill(0.0);
        out.qn_source.fill(0.0);
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

/// [`airfoil_vortex_gradient`] from the panel terms in `frames` (`contributions` is memory
/// for the per-panel terms).
fn gradient_from_frames(
    g: &PanelGeometry,
    p: &Probe,
    frames: &LineFrames,
    contributions: &mut Contributions,
    gx: &mut [f64],
    gy: &mut [f64],
) {
    let n = g.len();
    with_avx2(Contribute {
        g,
        p,
        kind: Terms::Gradient,
        frames,
        out: contributions,
    });
    let c = &contributions.0;
    node_sums_vortex(&c[0], &c[1], gx);
    node_sums_vortex(&c[2], &c[3], gy);
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

/// Node sums of per-panel vortex contributions: node i gets `a[i]` of its own panel and `b`
/// of the panel before (panels j → j+1, one node more than panels).
fn node_sums_vortex(a: &[f64], b: &[f64], out: &mut [f64]) {
    let np = a.len();
    out[0] = a[0];
    for i in 1..np {
        out[i] = a[i] + b[i - 1];
    }
    out[np] = b[np - 1];
}

/// Node sums of per-panel source contributions `c` = [m, o, p, q], to the nodes jm, jo, jp, jq
/// of each panel's stencil ([`frames::source_neighbours`]: jm = jo − 1 and jq = jo + 2 inside
/// the line, the panel's own end at its ends).
fn node_sums_source(c: &[Vec<f64>], out: &mut [f64]) {
    let [m, o, p, q] = [&c[0], &c[1], &c[2], &c[3]];
    let np = o.len();
    for (i, v) in out.iter_mut().enumerate().take(np + 1) {
        let mut s = 0.0;
        if i < np {
            s += o[i];
        }
        if i >= 1 {
            s += p[i - 1];
        }
        if i + 1 < np {
            s += m[i + 1];
        }
        if i >= 2 && i - 2 < np - 1 {
            s += q[i - 2];
        }
        *v = s;
    }
    out[0] += m[0];
    out[np] += q[np - 1];
}

/// Per-panel contributions of one field point, before their sums at the nodes: vortex ψ and
/// ∂ψ/∂n to the panel's first and second node (4), source ψ and ∂ψ/∂n to the four nodes of
/// its stencil (8).
#[derive(Clone, Debug, Default)]
struct Contributions([Vec<f64>; 12]);

/// Which per-panel terms [`Contribute`] forms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Terms {
    /// Vortex ψ and ∂ψ/∂n (along the probe's normal).
    Vortex,
    /// Vortex and source ψ and ∂ψ/∂n.
    VortexAndSources,
    /// Vortex ∂ψ/∂x and ∂ψ/∂y, in place of the vortex ψ and ∂ψ/∂n.
    Gradient,
}

/// The [`Contributions`] kernel.
struct Contribute<'a> {
    g: &'a PanelGeometry,
    p: &'a Probe,
    kind: Terms,
    frames: &'a LineFrames,
    out: &'a mut Contributions,
}

impl Kernel for Contribute<'_> {
    type Output = ();

    #[inline(always)]
    fn run(self) {
        let Self {
            g,
            p,
            kind,
            frames,
            out,
        } = self;
        let np = g.len() - 1;
        for v in out.0.iter_mut() {
            v.resize(np, 0.0);
        }
        let [va, vb, qa, qb, sm, so, sp, sq, rm, ro, rp, rq] = &mut out.0;
        let (va, vb, qa, qb) = (&mut va[..np], &mut vb[..np], &mut qa[..np], &mut qb[..np]);
        let (sx, sy) = (&g.panels.sx[..np], &g.panels.sy[..np]);
        if kind == Terms::Gradient {
            // Normals (1, 0): xi = sx, yyi = −sy; (0, 1): xi = sy, yyi = sx.
            for jo in 0..np {
                let f = PanelFrame::from_frames(frames, jo, p, (sx[jo], sy[jo]));
                let v = f.vortex_terms();
                let (psx, pdx) = (v[2] * f.sx - v[3] * f.sy, v[4] * f.sx - v[5] * f.sy);
                let (psy, pdy) = (v[2] * f.sy + v[3] * f.sx, v[4] * f.sy + v[5] * f.sx);
                va[jo] = QOPI * (psx - pdx);
                vb[jo] = QOPI * (psx + pdx);
                qa[jo] = QOPI * (psy - pdy);
                qb[jo] = QOPI * (psy + pdy);
            }
            return;
        }
        for jo in 0..np {
            let f = PanelFrame::from_frames(frames, jo, p, (sx[jo], sy[jo]));
            let (psis, psid, psni, pdni) = f.vortex();
            va[jo] = QOPI * (psis - psid);
            vb[jo] = QOPI * (psis + psid);
            qa[jo] = QOPI * (psni - pdni);
            qb[jo] = QOPI * (psni + pdni);
        }
        if kind == Terms::VortexAndSources {
            let (sm, so, sp, sq) = (&mut sm[..np], &mut so[..np], &mut sp[..np], &mut sq[..np]);
            let (rm, ro, rp, rq) = (&mut rm[..np], &mut ro[..np], &mut rp[..np], &mut rq[..np]);
            let (apanel, inv_ds) = (&g.apanel[..np], &g.panels.inv_ds[..np]);
            for jo in 0..np {
                let f = PanelFrame::from_frames(frames, jo, p, (sx[jo], sy[jo]));
                let [psi, qn] = source_coefficients(&f, apanel[jo], inv_ds[jo]);
                [sm[jo], so[jo], sp[jo], sq[jo]] = psi;
                [rm[jo], ro[jo], rp[jo], rq[jo]] = qn;
            }
        }
    }
}

/// A line of linear-source panels (the wake, XFOIL PSWLIN): nodes, panel angles (XFOIL APANEL,
/// used as arctangent branch reference) and the panels' geometry.
#[derive(Clone, Copy, Debug)]
pub struct SourceLine<'a> {
    /// Node x.
    pub x: &'a [f64],
    /// Node y.
    pub y: &'a [f64],
    /// Panel angles.
    pub apanel: &'a [f64],
    /// Panel tangents and source-stencil lengths.
    pub panels: &'a PanelLine,
}

/// XFOIL PSWLIN: sensitivities of ψ and ∂ψ/∂n at probe `p` to the nodal mass defect of the
/// wake source panels of `line`, written into `psi_out`, `qn_out` (length = number of wake
/// nodes). `frames` is memory for the panel terms.
pub fn wake_source_influence(
    line: SourceLine<'_>,
    p: &Probe,
    frames: &mut LineFrames,
    psi_out: &mut [f64],
    qn_out: &mut [f64],
) {
    psi_out.fill(0.0);
    qn_out.fill(0.0);
    let view = View {
        x: p.x,
        y: p.y,
        on_line: matches!(p.kind, FieldPoint::Wake(_)),
        branch_sign: -1.0,
        midpoints: true,
    };
    frames.evaluate(line.x, line.y, line.panels, view);
    let n = line.x.len();
    for jo in 0..line.panels.len() {
        let tangent = (line.panels.sx[jo], line.panels.sy[jo]);
        let f = PanelFrame::from_frames(frames, jo, p, tangent);
        let stencil = line.panels.inv_ds[jo];
        add_source_panel(&f, line.apanel[jo], stencil, (jo, n), psi_out, qn_out);
    }
}
