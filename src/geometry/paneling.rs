//! Curvature-based repaneling of an airfoil contour (XFOIL `PANGEN`, Drela).
//!
//! The node distribution makes `(1 + C·κ̃)·Δs` equal on both sides of every node, where κ̃ is
//! the surface curvature normalised by its maximum after smoothing by a diffusion equation,
//! with an artificial curvature at the trailing edge to bunch nodes there. The node arc
//! positions are found by Newton iteration on a grid `ipfac` times finer than the output,
//! and every `ipfac`-th node is kept. All constants are XFOIL 6.99 defaults (`xfoil.f`
//! `INIT` and `PANGEN`).

use super::error::GeometryError;
use super::spline::{arc_lengths, solve_tridiagonal, ContourSpline, CubicSpline};
use super::Airfoil;

/// XFOIL's default number of panel nodes (`NPAN`).
pub const DEFAULT_PANEL_NODES: usize = 160;

/// Tunable constants of the repaneling (XFOIL `PPAR` menu and `PANGEN` internals).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PanelingParams {
    /// Panel bunching parameter `CVPAR`: weight of curvature in the spacing law; the
    /// attraction coefficient is `C = 6·CVPAR` (XFOIL default 1.0).
    pub cvpar: f64,
    /// TE/LE panel density ratio `CTERAT`: artificial TE curvature as a fraction of the
    /// averaged LE curvature (XFOIL default 0.15).
    pub cterat: f64,
    /// Refined-area/LE panel density ratio `CTRRAT` (XFOIL default 0.2), used only inside
    /// the refinement zones below.
    pub ctrrat: f64,
    /// Upper-side refinement zone x/c limits `XSREF1, XSREF2` (XFOIL default 1, 1 = none).
    pub top_refinement: (f64, f64),
    /// Lower-side refinement zone x/c limits `XPREF1, XPREF2` (XFOIL default 1, 1 = none).
    pub bottom_refinement: (f64, f64),
    /// Oversampling factor of the Newton node grid `IPFAC` (XFOIL 5).
    pub ipfac: usize,
    /// Ratio of the TE panel length to the next one `RDSTE` (XFOIL 0.667).
    pub te_panel_ratio: f64,
    /// Number of LE points `2·NK+1` over which the LE curvature is averaged, as NK
    /// (XFOIL 3).
    pub le_average_half_points: usize,
    /// Lower bound of the normalised LE curvature used for the averaging window and the
    /// smoothing length (XFOIL 20).
    pub min_le_curvature: f64,
    /// Maximum Newton iterations for the node positions (XFOIL 20).
    pub max_iterations: usize,
    /// Newton convergence: largest node move / chord (XFOIL 1e-3, absolute for unit chord).
    pub tolerance: f64,
}

impl Default for PanelingParams {
    fn default() -> Self {
        Self {
            cvpar: 1.0,
            cterat: 0.15,
            ctrrat: 0.2,
            top_refinement: (1.0, 1.0),
            bottom_refinement: (1.0, 1.0),
            ipfac: 5,
            te_panel_ratio: 0.667,
            le_average_half_points: 3,
            min_le_curvature: 20.0,
            max_iterations: 20,
            tolerance: 1.0e-3,
        }
    }
}

/// A paneled airfoil with the spline data a panel method needs (XFOIL's "current airfoil":
/// `X, Y, S, XP, YP, SLE, NX, NY`).
#[derive(Clone, Debug, PartialEq)]
pub struct PaneledAirfoil {
    /// Panel nodes in XFOIL order.
    pub airfoil: Airfoil,
    /// Spline through the nodes; its knots are the node arc lengths (XFOIL `SCALC`).
    pub spline: ContourSpline,
    /// Arc length of each node from the upper TE node.
    pub s: Vec<f64>,
    /// dx/ds at each node (XFOIL `XP`).
    pub xp: Vec<f64>,
    /// dy/ds at each node (XFOIL `YP`).
    pub yp: Vec<f64>,
    /// Outward unit normal x component at each node (XFOIL `NCALC`: (yp, −xp)/|·|).
    pub nx: Vec<f64>,
    /// Outward unit normal y component at each node.
    pub ny: Vec<f64>,
    /// Arc length of the leading-edge point (XFOIL `LEFIND` on the nodes).
    pub sle: f64,
    /// Leading-edge point.
    pub le: (f64, f64),
    /// Trailing-edge midpoint.
    pub te: (f64, f64),
    /// Chord: distance from LE point to TE midpoint.
    pub chord: f64,
    /// Whether the Newton iteration on node positions met its tolerance (XFOIL continues
    /// anyway when it does not, and so does this code).
    pub converged: bool,
}

impl PaneledAirfoil {
    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.airfoil.x.len()
    }

    /// True if there are no nodes (never for a successfully paneled airfoil).
    pub fn is_empty(&self) -> bool {
        self.airfoil.x.is_empty()
    }

    /// Trailing-edge gap: distance between the first and last node.
    pub fn te_gap(&self) -> f64 {
        self.airfoil.te_gap()
    }

    /// Index of the node closest (in arc length) to the leading-edge point.
    pub fn le_index(&self) -> usize {
        nearest_index(&self.s, self.sle)
    }

    /// Builds the helper data (arc length, derivatives, normals, LE) for given nodes
    /// without moving them (XFOIL `PCOP`: use the points directly as panel nodes).
    pub fn from_nodes(airfoil: Airfoil, converged: bool) -> Result<Self, GeometryError> {
        let spline = ContourSpline::new(&airfoil.x, &airfoil.y)?;
        let s = spline.s().to_vec();
        let xp = spline.x.node_derivatives().to_vec();
        let yp = spline.y.node_derivatives().to_vec();
        let mut nx = Vec::with_capacity(s.len());
        let mut ny = Vec::with_capacity(s.len());
        for i in 0..s.len() {
            let m = xp[i].hypot(yp[i]);
            if m == 0.0 || !m.is_finite() {
                return Err(GeometryError::Paneling(format!(
                    "zero tangent at node {}",
                    i + 1
                )));
            }
            nx.push(yp[i] / m);
            ny.push(-xp[i] / m);
        }
        let sle = spline.leading_edge()?;
        let le = spline.point(sle);
        let te = spline.te_midpoint();
        let chord = (te.0 - le.0).hypot(te.1 - le.1);
        Ok(Self {
            airfoil,
            spline,
            s,
            xp,
            yp,
            nx,
            ny,
            sle,
            le,
            te,
            chord,
            converged,
        })
    }
}

/// Index of the value in sorted `s` closest to `target`.
pub(crate) fn nearest_index(s: &[f64], target: f64) -> usize {
    let mut best = 0;
    for (i, v) in s.iter().enumerate() {
        if (v - target).abs() < (s[best] - target).abs() {
            best = i;
        }
    }
    best
}

/// Distributes `n` panel nodes on the contour of `buffer` by XFOIL's `PANGEN` algorithm.
///
/// The buffer must be a valid contour in XFOIL order (checked). The result is not
/// normalised: like XFOIL's `PANE`, nodes lie on the spline of the input points.
pub(crate) fn panel(
    buffer: &Airfoil,
    n: usize,
    params: &PanelingParams,
) -> Result<PaneledAirfoil, GeometryError> {
    buffer.validate()?;
    if !(10..=20_000).contains(&n) {
        return Err(GeometryError::Paneling(format!(
            "number of panel nodes must be between 10 and 20000 (got {n})"
        )));
    }
    check_params(params)?;
    let (xb, yb) = (&buffer.x, &buffer.y);
    let nb = xb.len();
    let bsp = ContourSpline::new(xb, yb)?;
    let sb = bsp.s().to_vec();

    // Normalizing length (~ chord): half the perimeter.
    let sbref = 0.5 * (sb[nb - 1] - sb[0]);

    // Curvature at the buffer points and at the LE (XFOIL PANGEN, W5 and CVLE).
    let mut w5: Vec<f64> = sb.iter().map(|&s| bsp.curvature(s).abs() * sbref).collect();
    let sble = bsp.leading_edge()?;
    let cvle = bsp.curvature(sble).abs() * sbref;
    let (xble, yble) = bsp.point(sble);
    let (xbte, ybte) = bsp.te_midpoint();
    let chbsq = (xbte - xble).powi(2) + (ybte - yble).powi(2);
    if chbsq <= 0.0 {
        return Err(GeometryError::Paneling(
            "leading edge coincides with trailing edge".into(),
        ));
    }

    // Average curvature over 2·NK+1 points within one LE radius of the LE point.
    let nk = params.le_average_half_points.max(1);
    let mut cvsum = 0.0;
    for k in 0..=2 * nk {
        let frac = (k as f64 - nk as f64) / nk as f64;
        let sbk = sble + frac * sbref / cvle.max(params.min_le_curvature);
        cvsum += bsp.curvature(sbk).abs() * sbref;
    }
    let cvavg = cvsum / (2 * nk + 1) as f64;

    // Curvature attraction coefficient and artificial TE curvature.
    let cc = 6.0 * params.cvpar;
    let cvte = cvavg * params.cterat;
    w5[0] = cvte;
    w5[nb - 1] = cvte;

    // Smoothing length: 1/(averaged LE curvature), at least 1/4 of an average panel.
    let smool = (1.0 / cvavg.max(params.min_le_curvature)).max(0.25 / (n / 2) as f64);
    let smoosq = (smool * sbref).powi(2);

    // Tridiagonal diffusion system for the smoothed curvature:
    // κ̃ − L²·d²κ̃/ds² = κ (implicit smoothing, PANGEN).
    let mut lo = vec![0.0; nb];
    let mut di = vec![0.0; nb];
    let mut up = vec![0.0; nb];
    di[0] = 1.0;
    for i in 1..nb - 1 {
        let dsm = sb[i] - sb[i - 1];
        let dsp = sb[i + 1] - sb[i];
        let dso = 0.5 * (sb[i + 1] - sb[i - 1]);
        lo[i] = smoosq * (-1.0 / dsm) / dso;
        di[i] = smoosq * (1.0 / dsp + 1.0 / dsm) / dso + 1.0;
        up[i] = smoosq * (-1.0 / dsp) / dso;
    }
    di[nb - 1] = 1.0;

    // Pin the curvature at the LE point by modifying the equations next to it.
    for i in 1..nb - 1 {
        if sb[i] == sble {
            lo[i] = 0.0;
            di[i] = 1.0;
            up[i] = 0.0;
            w5[i] = cvle;
            break;
        } else if sb[i - 1] < sble && sb[i] > sble {
            if i >= 2 {
                let dsm = sb[i - 1] - sb[i - 2];
                let dsp = sble - sb[i - 1];
                let dso = 0.5 * (sble - sb[i - 2]);
                lo[i - 1] = smoosq * (-1.0 / dsm) / dso;
                di[i - 1] = smoosq * (1.0 / dsp + 1.0 / dsm) / dso + 1.0;
                up[i - 1] = 0.0;
                w5[i - 1] += smoosq * cvle / (dsp * dso);
            }
            let dsm = sb[i] - sble;
            let dsp = sb[i + 1] - sb[i];
            let dso = 0.5 * (sb[i + 1] - sble);
            lo[i] = 0.0;
            di[i] = smoosq * (1.0 / dsp + 1.0 / dsm) / dso + 1.0;
            up[i] = smoosq * (-1.0 / dsp) / dso;
            w5[i] += smoosq * cvle / (dsm * dso);
            break;
        }
    }

    // Artificial curvature CTRRAT·κ_LE inside the refinement zones.
    for i in 1..nb - 1 {
        let xoc = ((xb[i] - xble) * (xbte - xble) + (yb[i] - yble) * (ybte - yble)) / chbsq;
        let zone = if sb[i] < sble {
            params.top_refinement
        } else {
            params.bottom_refinement
        };
        if xoc > zone.0 && xoc < zone.1 {
            lo[i] = 0.0;
            di[i] = 1.0;
            up[i] = 0.0;
            w5[i] = cvle * params.ctrrat;
        }
    }

    if !solve_tridiagonal(&mut di, &lo, &mut up, &mut w5) {
        return Err(GeometryError::Paneling(
            "curvature smoothing system is singular".into(),
        ));
    }
    let cvmax = w5.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if !(cvmax > 0.0 && cvmax.is_finite()) {
        return Err(GeometryError::Paneling(
            "contour has no finite curvature".into(),
        ));
    }
    for v in w5.iter_mut() {
        *v /= cvmax;
    }
    let cspl = CubicSpline::xfoil_default(&sb, &w5)?;

    // Initial node positions uniform in s, on a grid IPFAC times finer, with the TE panel
    // shortened to the ratio RTF.
    let nn = params.ipfac * (n - 1) + 1;
    let rtf = (params.te_panel_ratio - 1.0) * 2.0 + 1.0;
    let dsavg = (sb[nb - 1] - sb[0]) / ((nn - 3) as f64 + 2.0 * rtf);
    let mut snew: Vec<f64> = (0..nn)
        .map(|i| {
            if i == 0 {
                sb[0]
            } else if i == nn - 1 {
                sb[nb - 1]
            } else {
                sb[0] + dsavg * ((i - 1) as f64 + rtf)
            }
        })
        .collect();

    // Newton iteration on the node positions: (1 + C·κ̃)·Δs equal on both sides of a node.
    let tol = params.tolerance * chbsq.sqrt();
    let mut converged = false;
    let mut a = vec![0.0; nn];
    let mut b = vec![0.0; nn];
    let mut c = vec![0.0; nn];
    let mut d = vec![0.0; nn];
    for _ in 0..params.max_iterations {
        let cv1 = cspl.eval(snew[0]);
        let mut cv2 = cspl.eval(snew[1]);
        let cvs1 = cspl.deriv(snew[0]);
        let mut cvs2 = cspl.deriv(snew[1]);
        let mut cavm = cv1.hypot(cv2);
        let (mut cavm_s1, mut cavm_s2) = if cavm == 0.0 {
            (0.0, 0.0)
        } else {
            (cvs1 * cv1 / cavm, cvs2 * cv2 / cavm)
        };
        for i in 1..nn - 1 {
            let dsm = snew[i] - snew[i - 1];
            let dsp = snew[i] - snew[i + 1];
            let cv3 = cspl.eval(snew[i + 1]);
            let cvs3 = cspl.deriv(snew[i + 1]);
            let cavp = cv3.hypot(cv2);
            let (cavp_s2, cavp_s3) = if cavp == 0.0 {
                (0.0, 0.0)
            } else {
                (cvs2 * cv2 / cavp, cvs3 * cv3 / cavp)
            };
            let fm = cc * cavm + 1.0;
            let fp = cc * cavp + 1.0;
            let rez = dsp * fp + dsm * fm;
            b[i] = -fm + cc * dsm * cavm_s1;
            a[i] = fp + fm + cc * (dsp * cavp_s2 + dsm * cavm_s2);
            c[i] = -fp + cc * dsp * cavp_s3;
            d[i] = -rez;
            cv2 = cv3;
            cvs2 = cvs3;
            cavm = cavp;
            cavm_s1 = cavp_s2;
            cavm_s2 = cavp_s3;
        }
        // Fixed end nodes (the TE points).
        a[0] = 1.0;
        c[0] = 0.0;
        d[0] = 0.0;
        b[nn - 1] = 0.0;
        a[nn - 1] = 1.0;
        d[nn - 1] = 0.0;
        if rtf != 1.0 {
            // Equations next to the TE replaced to impose the TE panel length ratio.
            let i = 1;
            d[i] = -((snew[i] - snew[i - 1]) + rtf * (snew[i] - snew[i + 1]));
            b[i] = -1.0;
            a[i] = 1.0 + rtf;
            c[i] = -rtf;
            let i = nn - 2;
            d[i] = -((snew[i] - snew[i + 1]) + rtf * (snew[i] - snew[i - 1]));
            c[i] = -1.0;
            a[i] = 1.0 + rtf;
            b[i] = -rtf;
        }
        if !solve_tridiagonal(&mut a, &b, &mut c, &mut d) {
            return Err(GeometryError::Paneling(
                "node-position Newton system is singular".into(),
            ));
        }
        // Under-relaxation keeping neighbouring panel-length ratios within [0.2, 4].
        let mut rlx = 1.0;
        let mut dmax = 0.0f64;
        for i in 0..nn - 1 {
            let ds = snew[i + 1] - snew[i];
            let dds = d[i + 1] - d[i];
            let dsrat = 1.0 + rlx * dds / ds;
            if dsrat > 4.0 {
                rlx = (4.0 - 1.0) * ds / dds;
            }
            if dsrat < 0.2 {
                rlx = (0.2 - 1.0) * ds / dds;
            }
            dmax = dmax.max(d[i].abs());
        }
        if !dmax.is_finite() {
            return Err(GeometryError::Paneling(
                "node-position Newton iteration diverged".into(),
            ));
        }
        for i in 1..nn - 1 {
            snew[i] += rlx * d[i];
        }
        if dmax < tol {
            converged = true;
            break;
        }
    }

    let mut x = Vec::with_capacity(n);
    let mut y = Vec::with_capacity(n);
    for i in 0..n {
        let (px, py) = bsp.point(snew[params.ipfac * i]);
        x.push(px);
        y.push(py);
    }
    let s_nodes = arc_lengths(&x, &y);
    if let Some(i) = (1..n).find(|&i| s_nodes[i] <= s_nodes[i - 1]) {
        return Err(GeometryError::Paneling(format!(
            "nodes {} and {} coincide",
            i,
            i + 1
        )));
    }
    let airfoil = Airfoil {
        name: buffer.name.clone(),
        x,
        y,
    };
    PaneledAirfoil::from_nodes(airfoil, converged)
}

/// Rejects parameter sets that would make the algorithm meaningless.
fn check_params(p: &PanelingParams) -> Result<(), GeometryError> {
    let bad = |what: &str| {
        Err(GeometryError::Paneling(format!(
            "invalid parameter: {what}"
        )))
    };
    if !(p.cvpar.is_finite() && p.cvpar >= 0.0) {
        return bad("cvpar must be finite and >= 0");
    }
    if !(p.cterat.is_finite() && p.cterat >= 0.0) {
        return bad("cterat must be finite and >= 0");
    }
    if !(p.ctrrat.is_finite() && p.ctrrat >= 0.0) {
        return bad("ctrrat must be finite and >= 0");
    }
    if !(1..=100).contains(&p.ipfac) {
        return bad("ipfac must be between 1 and 100");
    }
    if !(p.te_panel_ratio.is_finite() && p.te_panel_ratio > 0.5) {
        return bad("te_panel_ratio must be > 0.5");
    }
    if !(p.min_le_curvature.is_finite() && p.min_le_curvature > 0.0) {
        return bad("min_le_curvature must be > 0");
    }
    if !(p.tolerance.is_finite() && p.tolerance > 0.0) {
        return bad("tolerance must be > 0");
    }
    Ok(())
}
