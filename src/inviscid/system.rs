//! The stream-function panel system: influence matrix with Kutta condition, its LU
//! factorisation, and the α = 0° / 90° unit solutions (XFOIL xpanel.f GGCALC; Drela 1989 §2).
//!
//! Unknowns are the nodal vorticities γ₀ … γ_{N−1} and the body stream function ψ₀. Rows:
//! * node i: Σ_j (dψ_i/dγ_j) γ_j − ψ₀ = −(y_i cos α − x_i sin α) − Σ_j (dψ_i/dm_j) m_j;
//! * Kutta: γ₀ + γ_{N−1} = 0;
//! * sharp trailing edge: the row of the last node is replaced by zero velocity along the TE
//!   bisector at a control point just inside the TE (GGCALC "SHARP" block).
//!
//! The matrix depends only on the geometry; the right-hand sides for cos α and sin α give the
//! unit solutions, superposed as γ(α) = cos α·γ⁰ + sin α·γ⁹⁰.

use faer::linalg::solvers::{PartialPivLu, Solve};
use faer::Mat;
use std::sync::{Arc, OnceLock};

use super::contour::{PanelGeometry, PanelParams};
use super::error::InviscidError;
use super::forces::{integrate_pressure, SectionForces};
use super::influence::{airfoil_influence, FieldPoint, Influence, Probe};
use crate::compressibility::{KarmanTsien, MinimumPressure};
use crate::geometry::Airfoil;
use crate::numerics::simd::reset_simd_state;

/// Largest surface speed q/V∞ of a unit solution (α = 0° or 90°) accepted. Measured on NACA
/// 4- and 5-digit sections repaneled to 20…1000 nodes: 3.8 (NACA 0099) to 267 (NACA 91001,
/// 1 % thick with 9 % camber, at 1000 nodes); a contour listed twice or with a stray point
/// gave 10⁵–10¹⁰. Past it the factorised system is near-singular and its numbers are noise.
pub const MAX_UNIT_SPEED: f64 = 1e4;

/// Largest |Cl| of an inviscid solution accepted: 4π. The Kutta–Joukowski lift of a Joukowski
/// section is Cl = 8π(a/c)·sin(α + β) with a the circle radius and c the chord; a/c grows with
/// thickness to 1/2 for the circle itself, so no section exceeds 4π (the NACA 9999 at 20°:
/// 6.4). A larger value at a subcritical point is a numerical artefact of an irregular
/// contour.
pub const MAX_SECTION_CL: f64 = 4.0 * std::f64::consts::PI;

/// A factorised panel system for one paneled airfoil, holding the unit solutions.
#[derive(Debug)]
pub struct PanelSystem {
    geom: PanelGeometry,
    params: PanelParams,
    lu: PartialPivLu<f64>,
    /// dψ_i/dm_j of the airfoil sources on each system row (XFOIL BIJ = −DZDM), row-major
    /// (N+1)×N, right-hand-side sign already applied; the Kutta row is zero.
    source_rhs: Mat<f64>,
    /// Unit vorticity solutions γ⁰ (α = 0°) and γ⁹⁰ (α = 90°).
    gamma_unit: [Vec<f64>; 2],
    /// Body stream function ψ₀ of the unit solutions.
    psi0_unit: [f64; 2],
    /// Sharp-TE bisector control point (x, y, cos, sin of the bisector angle), if sharp.
    bisector: Option<(f64, f64, f64, f64)>,
    /// dγ_i/dσ_j for the airfoil sources, N × N, computed on first use (XFOIL DIJ airfoil
    /// block, cached like XFOIL's LADIJ flag), row-major.
    airfoil_dij: OnceLock<Arc<[f64]>>,
}

/// Inviscid solution at one angle of attack and Mach number.
#[derive(Clone, Debug)]
pub struct InviscidSolution {
    /// Angle of attack, degrees.
    pub alpha_deg: f64,
    /// Freestream Mach number.
    pub mach: f64,
    /// Nodal vorticity γ = signed incompressible surface speed q/V∞ (positive on the upper
    /// surface, XFOIL GAM/QINV).
    pub gamma: Vec<f64>,
    /// Karman–Tsien corrected pressure coefficient at each node (XFOIL CPCALC).
    pub cp: Vec<f64>,
    /// Lift coefficient from the corrected Cp (XFOIL CLCALC).
    pub cl: f64,
    /// Pitching-moment coefficient about the moment reference point (default (0.25, 0)).
    pub cm: f64,
    /// Pressure drag coefficient from surface-Cp integration (≈ 0 inviscid; XFOIL CDP).
    pub cdp: f64,
    /// Smallest corrected Cp on the surface.
    pub cp_min: f64,
    /// `true` if the minimum corrected Cp is below the critical (sonic) Cp*: the freestream is
    /// above the critical Mach number and the Karman–Tsien result is only indicative.
    pub supercritical: bool,
}

/// Superposition of the α = 0° and α = 90° unit solutions at angle of attack α:
/// cos α·u⁰ + sin α·u⁹⁰ (the panel method is linear in the free stream; XFOIL QISET/GAMQV).
pub fn superpose(unit0: &[f64], unit90: &[f64], alpha_deg: f64) -> Vec<f64> {
    let (sa, ca) = alpha_deg.to_radians().sin_cos();
    unit0
        .iter()
        .zip(unit90)
        .map(|(a, b)| ca * a + sa * b)
        .collect()
}

impl PanelSystem {
    /// Builds, factorises and solves the panel system for `airfoil` (nodes used as given,
    /// XFOIL order; checked by [`Airfoil::validate`]) with the default [`PanelParams`]. A
    /// near-singular system (a unit solution faster than [`MAX_UNIT_SPEED`]) is an error.
    pub fn new(airfoil: &Airfoil) -> Result<Self, InviscidError> {
        Self::with_params(airfoil, PanelParams::default())
    }

    /// As [`PanelSystem::new`] with explicit parameters.
    pub fn with_params(airfoil: &Airfoil, params: PanelParams) -> Result<Self, InviscidError> {
        let geom = PanelGeometry::new(&airfoil.x, &airfoil.y, &params)?;
        // The contour checks of the geometry layer (no repeated points, crossings, spikes, a
        // thickness), so that no contour they refuse reaches the solution.
        airfoil.validate()?;
        reset_simd_state();
        let n = geom.len();
        let mut a = Mat::<f64>::zeros(n + 1, n + 1);
        let mut source_rhs = Mat::<f64>::zeros(n + 1, n);
        let mut rhs = Mat::<f64>::zeros(n + 1, 2);
        let mut inf = Influence::new(n);
        for i in 0..n {
            let probe = Probe::airfoil_node(&geom, i);
            airfoil_influence(&geom, &probe, true, &mut inf);
            for j in 0..n {
                a[(i, j)] = inf.psi_gamma[j];
                source_rhs[(i, j)] = -inf.psi_source[j];
            }
            a[(i, n)] = -1.0;
            rhs[(i, 0)] = -geom.y[i];
            rhs[(i, 1)] = geom.x[i];
        }
        a[(n, 0)] = 1.0;
        a[(n, n - 1)] = 1.0;

        let mut bisector = None;
        if geom.te.sharp {
            // GGCALC: zero velocity along the TE bisector at a point just ahead of the TE.
            let ag1 = (-geom.yp[0]).atan2(-geom.xp[0]);
            let ag2 = continuous_atan2(geom.yp[n - 1], geom.xp[n - 1], ag1);
            let abis = 0.5 * (ag1 + ag2);
            let (sbis, cbis) = abis.sin_cos();
            let ds1 = (geom.x[0] - geom.x[1]).hypot(geom.y[0] - geom.y[1]);
            let ds2 = (geom.x[n - 1] - geom.x[n - 2]).hypot(geom.y[n - 1] - geom.y[n - 2]);
            let bwt = params.sharp_te_bisector_fraction * ds1.min(ds2);
            let xbis = geom.te.x - bwt * cbis;
            let ybis = geom.te.y - bwt * sbis;
            let probe = Probe {
                kind: FieldPoint::Free,
                x: xbis,
                y: ybis,
                nx: -sbis,
                ny: cbis,
            };
            airfoil_influence(&geom, &probe, true, &mut inf);
            for j in 0..n {
                a[(n - 1, j)] = inf.qn_gamma[j];
                source_rhs[(n - 1, j)] = -inf.qn_source[j];
            }
            a[(n - 1, n)] = 0.0;
            rhs[(n - 1, 0)] = -cbis;
            rhs[(n - 1, 1)] = -sbis;
            bisector = Some((xbis, ybis, cbis, sbis));
        }

        let lu = PartialPivLu::new(a.as_ref());
        lu.solve_in_place(rhs.as_mut());
        let mut gamma_unit = [vec![0.0; n], vec![0.0; n]];
        for (k, g) in gamma_unit.iter_mut().enumerate() {
            for (i, gi) in g.iter_mut().enumerate() {
                *gi = rhs[(i, k)];
            }
        }
        reset_simd_state();
        let psi0_unit = [rhs[(n, 0)], rhs[(n, 1)]];
        let finite = gamma_unit.iter().flatten().all(|v| v.is_finite())
            && psi0_unit.iter().all(|v| v.is_finite());
        if !finite {
            return Err(InviscidError::SingularSystem);
        }
        let fastest = gamma_unit
            .iter()
            .flatten()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        if fastest > MAX_UNIT_SPEED {
            return Err(InviscidError::Implausible {
                what: "surface speed",
                value: fastest,
            });
        }
        Ok(Self {
            geom,
            params,
            lu,
            source_rhs,
            gamma_unit,
            psi0_unit,
            bisector,
            airfoil_dij: OnceLock::new(),
        })
    }

    /// The prepared geometry (nodes, arc length, normals, TE data).
    pub fn geometry(&self) -> &PanelGeometry {
        &self.geom
    }

    /// The parameters the system was built with.
    pub fn params(&self) -> &PanelParams {
        &self.params
    }

    /// Number of airfoil nodes N.
    pub fn n_nodes(&self) -> usize {
        self.geom.len()
    }

    /// Unit vorticity solution: `k = 0` for α = 0° (V∞ along +x), `k = 1` for α = 90°.
    /// Values are signed surface speeds per V∞ (XFOIL GAMU(:,1), GAMU(:,2)).
    pub fn gamma_unit(&self, k: usize) -> &[f64] {
        &self.gamma_unit[k.min(1)]
    }

    /// Body stream function ψ₀ of the unit solutions (per V∞·c).
    pub fn psi0_unit(&self) -> [f64; 2] {
        self.psi0_unit
    }

    /// Sharp-TE bisector control point `(x, y, cos θ, sin θ)` if the TE is sharp.
    pub fn bisector(&self) -> Option<(f64, f64, f64, f64)> {
        self.bisector
    }

    /// Incompressible surface speed distribution γ(α) = cos α·γ⁰ + sin α·γ⁹⁰ (signed, per V∞).
    pub fn gamma(&self, alpha_deg: f64) -> Vec<f64> {
        superpose(&self.gamma_unit[0], &self.gamma_unit[1], alpha_deg)
    }

    /// dγ/dα (per radian) at `alpha_deg`: −sin α·γ⁰ + cos α·γ⁹⁰ (XFOIL QINV_A).
    pub fn gamma_alpha_derivative(&self, alpha_deg: f64) -> Vec<f64> {
        let (sa, ca) = alpha_deg.to_radians().sin_cos();
        self.gamma_unit[0]
            .iter()
            .zip(&self.gamma_unit[1])
            .map(|(g0, g90)| -sa * g0 + ca * g90)
            .collect()
    }

    /// Solves the inviscid flow at `alpha_deg` and Mach `mach` (0 ≤ M < 1): γ, Karman–Tsien
    /// Cp, Cl, Cm and Cdp exactly as XFOIL's SPECAL → CPCALC → CLCALC.
    pub fn solve(&self, alpha_deg: f64, mach: f64) -> Result<InviscidSolution, InviscidError> {
        if !alpha_deg.is_finite() {
            return Err(InviscidError::InvalidAlpha(alpha_deg));
        }
        let kt = KarmanTsien::new(mach)?;
        let gamma = self.gamma(alpha_deg);
        let mut cp = Vec::with_capacity(gamma.len());
        for &q in &gamma {
            match kt.cp_from_speed(q) {
                Some(c) => cp.push(c),
                None => {
                    return Err(InviscidError::CompressibilityBreakdown { mach, alpha_deg });
                }
            }
        }
        let SectionForces { cl, cm, cdp } = integrate_pressure(
            &self.geom.x,
            &self.geom.y,
            &cp,
            alpha_deg,
            self.params.moment_ref_x,
            self.params.moment_ref_y,
        );
        let MinimumPressure {
            cp: cp_min,
            supercritical,
        } = kt.minimum_pressure(gamma.iter().copied());
        // A supercritical point is flagged instead: there the correction, not the contour,
        // inflates Cl.
        if !(cl.abs() <= MAX_SECTION_CL || supercritical && cl.is_finite()) {
            return Err(InviscidError::Implausible {
                what: "Cl",
                value: cl,
            });
        }
        Ok(InviscidSolution {
            alpha_deg,
            mach,
            gamma,
            cp,
            cl,
            cm,
            cdp,
            cp_min,
            supercritical,
        })
    }

    /// Critical Mach number at `alpha_deg`: the freestream Mach at which the smallest
    /// Karman–Tsien corrected Cp on the surface reaches the sonic value Cp*(M) (bisection
    /// to 1e-6). Returns `None` when no stagnation-free solution reaches Cp* below M = 1.
    pub fn critical_mach(&self, alpha_deg: f64) -> Option<f64> {
        let gamma = self.gamma(alpha_deg);
        let qmax = gamma.iter().map(|g| g.abs()).fold(0.0, f64::max);
        let crit = |m: f64| -> f64 {
            match KarmanTsien::new(m) {
                Ok(kt) => match kt.cp_from_speed(qmax) {
                    Some(cp) => cp - kt.cp_sonic(),
                    None => -1.0,
                },
                Err(_) => -1.0,
            }
        };
        let (mut lo, mut hi) = (1.0e-6, 1.0 - 1.0e-9);
        if crit(lo) < 0.0 || crit(hi) > 0.0 {
            return None;
        }
        while hi - lo > 1.0e-7 {
            let mid = 0.5 * (lo + hi);
            if crit(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Some(0.5 * (lo + hi))
    }

    /// Back-substitutes `rhs` ((N+1) × k, system-row order) through the factorised matrix in
    /// place; row N of the result is ψ₀.
    pub fn back_substitute(&self, rhs: faer::MatMut<'_, f64>) {
        self.lu.solve_in_place(rhs);
        reset_simd_state();
    }

    /// Sensitivity of the nodal vorticity (surface speed) to the airfoil nodal sources,
    /// dγ_i/dσ_j (N × N, row-major), from back-substituting the source right-hand sides
    /// through the factorised system (XFOIL QDCALC airfoil block). Computed once, then shared
    /// by every α's source influence ([`SourceInfluence`](super::SourceInfluence)).
    pub fn airfoil_source_sensitivity(&self) -> Arc<[f64]> {
        self.airfoil_dij
            .get_or_init(|| {
                let n = self.n_nodes();
                let mut b = self.source_rhs.clone();
                self.lu.solve_in_place(b.as_mut());
                reset_simd_state();
                // b(i, j) = dγ_i/dσ_j (column j: the response to source j), copied row-major.
                let mut rows = Vec::with_capacity(n * n);
                for i in 0..n {
                    rows.extend((0..n).map(|j| b[(i, j)]));
                }
                rows.into()
            })
            .clone()
    }

    /// System right-hand side of the airfoil sources: entry (i, j) is −dψ_i/dm_j (−d(q_bis)/dm_j
    /// on the sharp-TE row, 0 on the Kutta row), XFOIL BIJ.
    pub fn source_rhs(&self) -> faer::MatRef<'_, f64> {
        self.source_rhs.as_ref()
    }

    /// Nodal vorticity (surface speed) for `alpha_deg` with airfoil mass defects `m_airfoil`
    /// (length N) and an additional system right-hand side `extra_psi` per node (stream function
    /// induced by other sources, e.g. the wake, length N; on the sharp-TE row the bisector
    /// velocity). Evaluates the airfoil source ψ by direct summation and re-solves the system.
    #[cfg(test)]
    pub fn gamma_with_sources(
        &self,
        alpha_deg: f64,
        m_airfoil: &[f64],
        extra_psi: &[f64],
    ) -> Vec<f64> {
        let n = self.n_nodes();
        assert!(
            m_airfoil.len() == n && extra_psi.len() == n,
            "one value per airfoil node"
        );
        let (sa, ca) = alpha_deg.to_radians().sin_cos();
        let g = &self.geom;
        reset_simd_state();
        let mut rhs = Mat::<f64>::zeros(n + 1, 1);
        for i in 0..n {
            let probe = Probe::airfoil_node(g, i);
            let (psi_m, _) = super::influence::direct::airfoil_source_value(g, &probe, m_airfoil);
            rhs[(i, 0)] = -(ca * g.y[i] - sa * g.x[i]) - psi_m - extra_psi[i];
        }
        if let Some((xb, yb, cb, sb)) = self.bisector {
            let probe = Probe {
                kind: FieldPoint::Free,
                x: xb,
                y: yb,
                nx: -sb,
                ny: cb,
            };
            let (_, q_m) = super::influence::direct::airfoil_source_value(g, &probe, m_airfoil);
            rhs[(n - 1, 0)] = -(ca * cb + sa * sb) - q_m - extra_psi[n - 1];
        }
        self.lu.solve_in_place(rhs.as_mut());
        reset_simd_state();
        (0..n).map(|i| rhs[(i, 0)]).collect()
    }
}

/// atan2(y, x) shifted by multiples of 2π to lie within π of `reference` (XFOIL ATANC).
fn continuous_atan2(y: f64, x: f64, reference: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    let a = y.atan2(x);
    a + two_pi * ((reference - a) / two_pi).round()
}
