//! The geometry block of XFOIL's PSILIN/PSWLIN for every panel of a line at once: the
//! panel-frame coordinates of the field point, ln r² of every node and the arctangents of
//! both panel ends (and of the midpoints, for source panels). These logarithms and arctangents
//! are most of a panel evaluation's cost; evaluated in bulk with the branch-free
//! [`crate::numerics::elementary`] functions they run four at a time in AVX2 registers.

use std::f64::consts::PI;

use crate::numerics::elementary::{atan2, ln};
use crate::numerics::simd::{with_avx2, Kernel};

/// Geometry of a line of straight panels, panel j from node j to node j+1, that does not
/// depend on the field point: unit tangents and the inverse lengths of the source-slope
/// stencil (PSILIN/PSWLIN DSIO, DSIM, DSIP).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PanelLine {
    /// Unit tangent x of each panel, (x_{j+1} − x_j)/|·| (XFOIL SX).
    pub sx: Vec<f64>,
    /// Unit tangent y of each panel (XFOIL SY).
    pub sy: Vec<f64>,
    /// Per panel jo: 1/|r_jp − r_jo|, 1/|r_jp − r_jm|, 1/|r_jq − r_jo| with jm, jq its outer
    /// neighbours (the panel's own end at the ends of the line).
    pub inv_ds: Vec<[f64; 3]>,
}

/// Distance between two points (plain square root, as XFOIL; faster than `hypot`).
#[inline]
pub(super) fn dist(ax: f64, ay: f64, bx: f64, by: f64) -> f64 {
    ((bx - ax) * (bx - ax) + (by - ay) * (by - ay)).sqrt()
}

/// Neighbour indices (jm, jq) of panel jo→jo+1 on an open line of `n` nodes, used for the
/// source slopes (PSILIN/PSWLIN: JM = JO at the first panel, JQ = JP at the last).
#[inline]
pub(super) fn source_neighbours(jo: usize, n: usize) -> (usize, usize) {
    let jm = if jo == 0 { jo } else { jo - 1 };
    let jq = if jo + 2 >= n { jo + 1 } else { jo + 2 };
    (jm, jq)
}

impl PanelLine {
    /// The panels between consecutive nodes of the line `x`, `y`.
    pub fn new(x: &[f64], y: &[f64]) -> Self {
        let n = x.len().min(y.len());
        let np = n.saturating_sub(1);
        let mut line = Self {
            sx: Vec::with_capacity(np),
            sy: Vec::with_capacity(np),
            inv_ds: Vec::with_capacity(np),
        };
        for jo in 0..np {
            let jp = jo + 1;
            let (jm, jq) = source_neighbours(jo, n);
            let dso = dist(x[jo], y[jo], x[jp], y[jp]);
            line.sx.push((x[jp] - x[jo]) / dso);
            line.sy.push((y[jp] - y[jo]) / dso);
            line.inv_ds.push([
                1.0 / dso,
                1.0 / dist(x[jm], y[jm], x[jp], y[jp]),
                1.0 / dist(x[jo], y[jo], x[jq], y[jq]),
            ]);
        }
        line
    }

    /// Number of panels.
    pub fn len(&self) -> usize {
        self.sx.len()
    }
}

/// The terms of every panel of a line seen from one field point (XFOIL X1, X2, YY, RS1, RS2,
/// G1, G2, T1, T2 and, for source panels, G0, T0), before the field point's own panels are
/// singled out.
#[derive(Clone, Debug, Default)]
pub struct LineFrames {
    /// r² from each node to the field point.
    pub rs: Vec<f64>,
    /// ln r² of each node (0 where r = 0).
    pub g: Vec<f64>,
    /// Panel-frame coordinate of each panel's first end.
    pub x1: Vec<f64>,
    /// Panel-frame coordinate of each panel's second end.
    pub x2: Vec<f64>,
    /// Distance of the field point from each panel's line, positive on its left.
    pub yy: Vec<f64>,
    /// Arctangent at each panel's first end, with XFOIL's reflection and branch offset.
    pub t1: Vec<f64>,
    /// Arctangent at each panel's second end.
    pub t2: Vec<f64>,
    /// ln r² of each panel's midpoint (evaluated for source panels only).
    pub g0: Vec<f64>,
    /// Arctangent at each panel's midpoint (evaluated for source panels only).
    pub t0: Vec<f64>,
}

/// How a field point sees a line.
#[derive(Clone, Copy, Debug)]
pub struct View {
    /// Field point.
    pub x: f64,
    /// Field point.
    pub y: f64,
    /// The field point lies on the line (one of its nodes): no reflection (XFOIL SGN = 1).
    pub on_line: bool,
    /// +1 for airfoil panels (PSILIN), −1 for wake panels (PSWLIN): the sign of the branch
    /// offset of reflected arctangents.
    pub branch_sign: f64,
    /// Also the midpoint terms (source panels).
    pub midpoints: bool,
}

impl LineFrames {
    /// Evaluates the terms of the first `line.len()` panels of the nodes `x`, `y` seen from
    /// `view`.
    pub fn evaluate(&mut self, x: &[f64], y: &[f64], line: &PanelLine, view: View) {
        let np = line.len();
        assert!(x.len() > np && y.len() > np, "one node more than panels");
        self.rs.resize(np + 1, 0.0);
        self.g.resize(np + 1, 0.0);
        for v in [
            &mut self.x1,
            &mut self.x2,
            &mut self.yy,
            &mut self.t1,
            &mut self.t2,
        ] {
            v.resize(np, 0.0);
        }
        // The midpoint terms keep older values when not evaluated (unused then).
        self.g0.resize(np, 0.0);
        self.t0.resize(np, 0.0);
        with_avx2(Evaluate {
            frames: self,
            x: &x[..=np],
            y: &y[..=np],
            line,
            view,
        });
    }
}

/// The [`LineFrames::evaluate`] kernel.
struct Evaluate<'a> {
    frames: &'a mut LineFrames,
    x: &'a [f64],
    y: &'a [f64],
    line: &'a PanelLine,
    view: View,
}

impl Kernel for Evaluate<'_> {
    type Output = ();

    #[inline(always)]
    fn run(self) {
        let Self {
            frames: f,
            x,
            y,
            line,
            view,
        } = self;
        let (px, py) = (view.x, view.y);
        for (((rs, g), &xj), &yj) in f.rs.iter_mut().zip(f.g.iter_mut()).zip(x).zip(y) {
            let (rx, ry) = (px - xj, py - yj);
            *rs = rx * rx + ry * ry;
            *g = if *rs > 0.0 { ln(*rs) } else { 0.0 };
        }
        let np = line.len();
        let (sx, sy) = (&line.sx[..np], &line.sy[..np]);
        let (x1o, x2o, yyo) = (&mut f.x1[..np], &mut f.x2[..np], &mut f.yy[..np]);
        let (t1o, t2o) = (&mut f.t1[..np], &mut f.t2[..np]);
        for j in 0..np {
            let (rx1, ry1) = (px - x[j], py - y[j]);
            let (rx2, ry2) = (px - x[j + 1], py - y[j + 1]);
            let x1 = sx[j] * rx1 + sy[j] * ry1;
            let x2 = sx[j] * rx2 + sy[j] * ry2;
            let yy = sx[j] * ry1 - sy[j] * rx1;
            let sgn = if view.on_line || yy >= 0.0 { 1.0 } else { -1.0 };
            let branch = view.branch_sign * (0.5 - 0.5 * sgn) * PI;
            x1o[j] = x1;
            x2o[j] = x2;
            yyo[j] = yy;
            t1o[j] = atan2(sgn * x1, sgn * yy) + branch;
            t2o[j] = atan2(sgn * x2, sgn * yy) + branch;
        }
        if view.midpoints {
            let (x1, x2, yy) = (&f.x1[..np], &f.x2[..np], &f.yy[..np]);
            let (g0o, t0o) = (&mut f.g0[..np], &mut f.t0[..np]);
            for j in 0..np {
                let sgn = if view.on_line || yy[j] >= 0.0 {
                    1.0
                } else {
                    -1.0
                };
                let branch = view.branch_sign * (0.5 - 0.5 * sgn) * PI;
                let x0 = 0.5 * (x1[j] + x2[j]);
                g0o[j] = ln(x0 * x0 + yy[j] * yy[j]);
                t0o[j] = atan2(sgn * x0, sgn * yy[j]) + branch;
            }
        }
    }
}
