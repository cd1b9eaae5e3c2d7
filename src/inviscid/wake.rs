//! Wake geometry: a line of nodes trailing from the trailing-edge midpoint along the inviscid
//! streamline, with geometrically growing spacing (XFOIL xpanel.f XYWAKE, spacing from
//! xutils.f SETEXP), and the inviscid wake speeds of the unit solutions (XFOIL QWCALC).

use super::error::InviscidError;
use super::influence::{
    airfoil_influence_and_gradient, airfoil_vortex_gradient, Influence, PanelLine, Probe,
    SourceLine,
};
use super::system::PanelSystem;
use crate::numerics::dense::dot;
use crate::numerics::simd::reset_simd_state;

/// Tunable constants of the wake geometry (XFOIL defaults).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WakeParams {
    /// Wake length in chords (XFOIL WAKLEN = 1).
    pub length: f64,
    /// Number of wake nodes; `None` uses XFOIL 6.99's `N/12 + 10·⌊length⌋` for N airfoil
    /// nodes (23 for N = 160; older XFOIL versions used N/8 + 2). The 6.99 rule was confirmed
    /// against XFOIL 6.99 dumps at N = 100, 120, 136 and 160.
    pub n_nodes: Option<usize>,
    /// Offset of the first wake node behind the TE midpoint along the TE bisector, in chord
    /// units (XFOIL XYWAKE: 0.0001).
    pub te_offset: f64,
}

impl Default for WakeParams {
    fn default() -> Self {
        Self {
            length: 1.0,
            n_nodes: None,
            te_offset: 1.0e-4,
        }
    }
}

/// Wake nodes traced downstream from the trailing edge for one angle of attack.
///
/// Node 0 sits `te_offset` behind the TE midpoint; node k+1 lies `s[k+1] − s[k]` from node k
/// along the local streamline direction. The unit normal `(nx, ny)` at each node is chosen so
/// that the downstream tangent is `(−ny, nx)` (XFOIL: n = −∇ψ/|∇ψ|), hence the tangential
/// speed `∂ψ/∂n` is negative for downstream flow: wake speeds continue the lower-surface sign
/// convention of the airfoil γ (XFOIL QINV on the wake).
#[derive(Clone, Debug)]
pub struct Wake {
    /// Node x.
    pub x: Vec<f64>,
    /// Node y.
    pub y: Vec<f64>,
    /// Unit normal x at each node.
    pub nx: Vec<f64>,
    /// Unit normal y at each node.
    pub ny: Vec<f64>,
    /// Panel angles `atan2(∂ψ/∂y, ∂ψ/∂x)` used as arctan branch reference by the wake source
    /// panels (XFOIL APANEL on the wake); the last entry repeats the previous one.
    pub apanel: Vec<f64>,
    /// Inviscid tangential speed at the wake nodes for the α = 0° and α = 90° unit solutions
    /// (XFOIL QINVU(:,1..2) on the wake; node 0 copies the airfoil's last node).
    pub qinv_unit: [Vec<f64>; 2],
    /// Tangents and source-stencil lengths of the wake panels.
    pub(crate) panels: PanelLine,
    /// Row-major NW × N: the normal speed d(∂ψ/∂n)/dγ_j at each wake node (with its normal)
    /// per airfoil vorticity (XFOIL DQDG on the wake; row 0 is not evaluated and stays zero).
    pub(crate) qn_gamma: Vec<f64>,
    /// Row-major NW × N: d(∂ψ/∂n)/dm_j at each wake node per airfoil mass defect (XFOIL
    /// DQDM on the wake; row 0 zero).
    pub(crate) qn_source: Vec<f64>,
}

impl Wake {
    /// Traces the wake of `system` at `alpha_deg` with default [`WakeParams`].
    pub fn new(system: &PanelSystem, alpha_deg: f64) -> Result<Self, InviscidError> {
        Self::with_params(system, alpha_deg, &WakeParams::default())
    }

    /// Traces the wake with explicit parameters (XFOIL XYWAKE + QWCALC).
    pub fn with_params(
        system: &PanelSystem,
        alpha_deg: f64,
        params: &WakeParams,
    ) -> Result<Self, InviscidError> {
        if !alpha_deg.is_finite() {
            return Err(InviscidError::InvalidAlpha(alpha_deg));
        }
        if !(params.length.is_finite() && params.length > 0.0) {
            return Err(InviscidError::InvalidWake("length must be positive"));
        }
        if !(params.te_offset.is_finite() && params.te_offset >= 0.0) {
            return Err(InviscidError::InvalidWake("TE offset must be non-negative"));
        }
        let g = system.geometry();
        let n = g.len();
        let nw = params
            .n_nodes
            .unwrap_or(n / 12 + 10 * params.length.floor() as usize);
        if nw < 3 {
            return Err(InviscidError::InvalidWake(
                "at least 3 wake nodes are needed",
            ));
        }
        let ds1 = 0.5 * (g.s[1] - g.s[0] + g.s[n - 1] - g.s[n - 2]);
        let spacing = geometric_spacing(ds1, params.length * g.chord, nw)?;

        reset_simd_state();
        let gamma = system.gamma(alpha_deg);
        let (sa, ca) = alpha_deg.to_radians().sin_cos();
        let mut x = vec![0.0; nw];
        let mut y = vec![0.0; nw];
        let mut nx = vec![0.0; nw];
        let mut ny = vec![0.0; nw];
        let mut apanel = vec![0.0; nw];

        // First node: just behind the TE midpoint, along the bisector of the spline tangents.
        let sx = 0.5 * (g.yp[n - 1] - g.yp[0]);
        let sy = 0.5 * (g.xp[0] - g.xp[n - 1]);
        let smod = sx.hypot(sy);
        nx[0] = sx / smod;
        ny[0] = sy / smod;
        x[0] = g.te.x - params.te_offset * ny[0];
        y[0] = g.te.y + params.te_offset * nx[0];

        // One evaluation of the airfoil panels per node gives the streamline direction for
        // the next node, the unit-solution tangential speeds (QWCALC) at this node and, from
        // node 1 on, the node's influence rows (the wake rows of QDCALC).
        let mut qinv_unit = [vec![0.0; nw], vec![0.0; nw]];
        qinv_unit[0][0] = system.gamma_unit(0)[n - 1];
        qinv_unit[1][0] = system.gamma_unit(1)[n - 1];
        let mut qn_gamma = vec![0.0; nw * n];
        let mut qn_source = vec![0.0; nw * n];
        let mut gx = vec![0.0; n];
        let mut gy = vec![0.0; n];
        let mut inf = Influence::new(n);
        for i in 0..nw {
            if i > 0 {
                let ds = spacing[i] - spacing[i - 1];
                x[i] = x[i - 1] - ds * ny[i];
                y[i] = y[i - 1] + ds * nx[i];
            }
            let probe = Probe::wake_node(i, (x[i], y[i]), (nx[i], ny[i]));
            if i == 0 {
                airfoil_vortex_gradient(g, &probe, &mut inf, &mut gx, &mut gy);
            } else {
                airfoil_influence_and_gradient(g, &probe, &mut inf, &mut gx, &mut gy);
                qn_gamma[i * n..(i + 1) * n].copy_from_slice(&inf.qn_gamma);
                qn_source[i * n..(i + 1) * n].copy_from_slice(&inf.qn_source);
            }
            if i > 0 {
                for (k, q) in qinv_unit.iter_mut().enumerate() {
                    let gu = system.gamma_unit(k);
                    let free = if k == 0 { ny[i] } else { -nx[i] };
                    q[i] = nx[i] * dot(&gx, gu) + ny[i] * dot(&gy, gu) + free;
                }
            }
            if i + 1 == nw {
                apanel[i] = apanel[i - 1];
                break;
            }
            // ∇ψ from the airfoil vorticity and the freestream ψ∞ = y cos α − x sin α.
            let grad = [dot(&gx, &gamma) - sa, dot(&gy, &gamma) + ca];
            let gmod = grad[0].hypot(grad[1]);
            if !(gmod > 0.0 && gmod.is_finite()) {
                return Err(InviscidError::WakeStagnation(i));
            }
            nx[i + 1] = -grad[0] / gmod;
            ny[i + 1] = -grad[1] / gmod;
            apanel[i] = grad[1].atan2(grad[0]);
        }

        let panels = PanelLine::new(&x, &y);
        Ok(Self {
            x,
            y,
            nx,
            ny,
            apanel,
            qinv_unit,
            panels,
            qn_gamma,
            qn_source,
        })
    }

    /// Wake node `i` as a field point of the influence routines.
    pub fn probe(&self, i: usize) -> Probe {
        Probe::wake_node(i, (self.x[i], self.y[i]), (self.nx[i], self.ny[i]))
    }

    /// The wake as a line of source panels (XFOIL PSWLIN).
    pub fn source_line(&self) -> SourceLine<'_> {
        SourceLine {
            x: &self.x,
            y: &self.y,
            apanel: &self.apanel,
            panels: &self.panels,
        }
    }

    /// Number of wake nodes.
    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// Inviscid wake speeds at `alpha_deg`, `cos α·q⁰ + sin α·q⁹⁰` (signed as described on
    /// [`Wake`]; the geometry stays the one traced at its own α).
    #[cfg(test)]
    pub fn qinv(&self, alpha_deg: f64) -> Vec<f64> {
        super::system::superpose(&self.qinv_unit[0], &self.qinv_unit[1], alpha_deg)
    }
}

/// Geometrically stretched coordinates `0 = s₀ < s₁ < … < s_{n−1} = total` with first step
/// `ds1` and constant ratio of successive steps (XFOIL SETEXP: quadratic initial guess, then
/// Newton iteration on the ratio).
pub fn geometric_spacing(ds1: f64, total: f64, n: usize) -> Result<Vec<f64>, InviscidError> {
    if n < 3 || !(ds1 > 0.0 && total > ds1) {
        return Err(InviscidError::InvalidWake(
            "geometric spacing needs n >= 3 and 0 < first step < length",
        ));
    }
    let sigma = total / ds1;
    let nex = (n - 1) as f64;
    let rni = 1.0 / nex;
    let aaa = nex * (nex - 1.0) * (nex - 2.0) / 6.0;
    let bbb = nex * (nex - 1.0) / 2.0;
    let ccc = nex - sigma;
    let disc = (bbb * bbb - 4.0 * aaa * ccc).max(0.0);
    let mut ratio = if n == 3 {
        -ccc / bbb + 1.0
    } else {
        (-bbb + disc.sqrt()) / (2.0 * aaa) + 1.0
    };
    if ratio != 1.0 {
        let ne = (n - 1) as i32;
        for _ in 0..100 {
            let sigman = (ratio.powi(ne) - 1.0) / (ratio - 1.0);
            let res = sigman.powf(rni) - sigma.powf(rni);
            let dresdr = rni * sigman.powf(rni) * (nex * ratio.powi(ne - 1) - sigman)
                / (ratio.powi(ne) - 1.0);
            let dratio = -res / dresdr;
            ratio += dratio;
            if dratio.abs() < 1.0e-10 {
                break;
            }
        }
    }
    if !(ratio.is_finite() && ratio > 0.0) {
        return Err(InviscidError::InvalidWake(
            "no geometric stretching ratio found",
        ));
    }
    let mut out = vec![0.0; n];
    let mut ds = ds1;
    for i in 1..n {
        out[i] = out[i - 1] + ds;
        ds *= ratio;
    }
    Ok(out)
}
