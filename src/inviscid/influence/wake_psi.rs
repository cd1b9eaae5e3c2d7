//! The stream function of the wake's source panels at many field points at once (XFOIL
//! PSWLIN's dψ/dm at the airfoil nodes, the right-hand sides of the airfoil rows of QDCALC):
//! panel by panel, with the field points side by side in vector registers.

use std::f64::consts::PI;

use super::panel::{half_source_psi, QOPI};
use super::SourceLine;
use crate::numerics::elementary::{atan2, ln};
use crate::numerics::simd::{with_avx2, Kernel};

/// dψ/dm_j at the field points (`px`, `py`) — none of them on the wake line — per nodal mass
/// defect m_j of the wake sources of `line`, written column by column into `out` (column j at
/// `out[j·m..(j+1)·m]` for m field points; overwritten).
pub(crate) fn wake_source_psi(line: SourceLine<'_>, px: &[f64], py: &[f64], out: &mut [f64]) {
    let m = px.len().min(py.len());
    let nw = line.x.len();
    assert_eq!(out.len(), m * nw, "one column per wake node");
    out.fill(0.0);
    let mut terms = [vec![0.0; m], vec![0.0; m], vec![0.0; m], vec![0.0; m]];
    for jo in 0..line.panels.len() {
        with_avx2(PanelTerms {
            line,
            jo,
            px: &px[..m],
            py: &py[..m],
            terms: &mut terms,
        });
        // Columns jm, jo, jp, jq of the panel's source-slope stencil (jm = jo on the first
        // panel, jq = jp on the last, as in PSWLIN).
        let jm = jo.saturating_sub(1);
        let jq = (jo + 2).min(nw - 1);
        for (col, t) in [jm, jo, jo + 1, jq].into_iter().zip(&terms) {
            for (o, v) in out[col * m..(col + 1) * m].iter_mut().zip(t) {
                *o += v;
            }
        }
    }
}

/// The contributions of wake panel `jo` to the columns jm, jo, jp, jq at every field point.
struct PanelTerms<'a> {
    line: SourceLine<'a>,
    jo: usize,
    px: &'a [f64],
    py: &'a [f64],
    terms: &'a mut [Vec<f64>; 4],
}

impl Kernel for PanelTerms<'_> {
    type Output = ();

    #[inline(always)]
    fn run(self) {
        let Self {
            line,
            jo,
            px,
            py,
            terms,
        } = self;
        let m = px.len();
        let (xa, ya, xb, yb) = (line.x[jo], line.y[jo], line.x[jo + 1], line.y[jo + 1]);
        let (sx, sy) = (line.panels.sx[jo], line.panels.sy[jo]);
        let apan = line.apanel[jo];
        let [dsio, dsim, dsip] = line.panels.inv_ds[jo];
        let [cm, co, cp, cq] = terms;
        let (cm, co, cp, cq) = (&mut cm[..m], &mut co[..m], &mut cp[..m], &mut cq[..m]);
        for i in 0..m {
            let (rx1, ry1) = (px[i] - xa, py[i] - ya);
            let (rx2, ry2) = (px[i] - xb, py[i] - yb);
            let x1 = sx * rx1 + sy * ry1;
            let x2 = sx * rx2 + sy * ry2;
            let yy = sx * ry1 - sy * rx1;
            let rs1 = rx1 * rx1 + ry1 * ry1;
            let rs2 = rx2 * rx2 + ry2 * ry2;
            // Off the line: reflected below it, branch offset −π there (PSWLIN).
            let sgn = if yy >= 0.0 { 1.0 } else { -1.0 };
            let branch = -(0.5 - 0.5 * sgn) * PI;
            let (g1, t1) = if rs1 > 0.0 {
                (ln(rs1), atan2(sgn * x1, sgn * yy) + branch)
            } else {
                (0.0, 0.0)
            };
            let (g2, t2) = if rs2 > 0.0 {
                (ln(rs2), atan2(sgn * x2, sgn * yy) + branch)
            } else {
                (0.0, 0.0)
            };
            let x0 = 0.5 * (x1 + x2);
            let rs0 = x0 * x0 + yy * yy;
            let g0 = ln(rs0);
            let t0 = atan2(sgn * x0, sgn * yy) + branch;
            let (t1, t0, t2) = (t1 - apan, t0 - apan, t2 - apan);
            let [psum, pdif] = half_source_psi([x1, x0], yy, [t1, t0], [g1, g0], [rs1, rs0]);
            let [psum2, pdif2] = half_source_psi([x0, x2], yy, [t0, t2], [g0, g2], [rs0, rs2]);
            cm[i] = QOPI * (-psum + pdif) * dsim;
            co[i] = QOPI * (-psum - pdif) * dsio
                + QOPI * (-psum2 * (dsip + dsio) - pdif2 * (dsip - dsio));
            cp[i] = QOPI * (psum * (dsio + dsim) + pdif * (dsio - dsim))
                + QOPI * (psum2 - pdif2) * dsio;
            cq[i] = QOPI * (psum2 + pdif2) * dsip;
        }
    }
}
