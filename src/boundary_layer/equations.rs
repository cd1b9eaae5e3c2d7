//! Discrete integral boundary-layer equations of one interval (Drela & Giles 1987 eqs. 9–11;
//! Drela 1989 shear-lag equation; discretisation of XFOIL 6.99 xblsys.f BLMID + BLDIF):
//! amplification or shear-lag, von Kármán momentum, and kinetic-energy shape-parameter
//! equations, log-differenced between stations 1 and 2 with Hk-triggered upwinding.

use super::amplification::average_amplification_rate_d;
use super::closures::{laminar_skin_friction_d, turbulent_skin_friction_d};
use super::params::{BlParams, FlowConstants, Regime};
use super::station::Station;
use super::{Dual, NVARS};

/// Residuals of the three equations of one interval and their Jacobians.
///
/// Sign convention: `res` is the residual R itself (R = 0 at the solution); XFOIL's VSREZ is
/// −R. Newton: d1·Δv1 + d2·Δv2 = −res. Rows: 0 = amplification (laminar) or shear-lag
/// (turbulent, wake), 1 = momentum, 2 = shape parameter. Columns of `d1`/`d2`:
/// (s, θ, δ*, u, ξ) of station 1 / station 2, with u the incompressible edge speed and δ*
/// the total displacement thickness (XFOIL VS1/VS2 after BLSYS's Uec → Uei conversion).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct IntervalEquations {
    /// Residuals R of the three equations.
    pub res: [f64; 3],
    /// ∂R/∂(s, θ, δ*, u, ξ) of station 1.
    pub d1: [[f64; 5]; 3],
    /// ∂R/∂(s, θ, δ*, u, ξ) of station 2.
    pub d2: [[f64; 5]; 3],
}

impl IntervalEquations {
    /// d1 + d2: the Jacobian with respect to one station when station 1 and station 2
    /// coincide (similarity station).
    pub fn combined_jacobian(&self) -> [[f64; 5]; 3] {
        let mut d = self.d2;
        for (row, row1) in d.iter_mut().zip(&self.d1) {
            for (v, v1) in row.iter_mut().zip(row1) {
                *v += v1;
            }
        }
        d
    }

    /// Splits three residual derivative numbers into values and station Jacobians.
    pub(crate) fn from_duals(r: &[Dual; 3]) -> Self {
        debug_assert_eq!(NVARS, 10);
        Self {
            res: [r[0].v, r[1].v, r[2].v],
            d1: [r[0].slots(0), r[1].slots(0), r[2].slots(0)],
            d2: [r[0].slots(5), r[1].slots(5), r[2].slots(5)],
        }
    }
}

/// Residuals of an interval with their Jacobian with respect to station 2 only: what the
/// local iterations of a march need, since they vary station 2 alone. The Jacobian with respect
/// to station 1 is added later, for the last iteration only
/// ([`BlModel::complete_interval`](super::BlModel::complete_interval)). The residuals and both
/// Jacobians are bit-identical to those of one evaluation on 10-slot numbers
/// ([`BlModel::interval_from`](super::BlModel::interval_from)): every slot of a derivative
/// number is computed on its own, so the 4-slot evaluation with station 2's (s, θ, δ*, u)
/// seeded and station 1 held fixed computes exactly those slots, and the 6-slot one with
/// station 1's five variables and station 2's ξ seeded exactly the others, at about half the
/// cost each.
#[derive(Clone, Debug)]
pub struct DownstreamEquations {
    /// Residuals R of the three equations (as [`IntervalEquations::res`]).
    pub res: [f64; 3],
    /// ∂R/∂(s, θ, δ*, u) of station 2 (the first four columns of [`IntervalEquations::d2`];
    /// ξ, fixed in a local iteration, gets its column with station 1's Jacobian).
    pub d2: [[f64; 4]; 3],
    /// Regime of the interval.
    pub(crate) regime: Regime,
    /// Station 2's values (held fixed when station 1's Jacobian is added).
    pub(crate) station: Station<0>,
}

/// Which finite-difference system BLDIF sets up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum DiffKind {
    /// Similarity (stagnation) station: prescribed log-differences, N = 0.
    Similarity,
    /// Laminar interval: amplification equation.
    Laminar,
    /// Turbulent wall interval: shear-lag equation.
    Turbulent,
    /// Wake interval: shear-lag equation with wake constants.
    Wake,
}

impl DiffKind {
    /// The system of an interval whose stations are in `regime`.
    pub(crate) fn of(regime: Regime) -> Self {
        match regime {
            Regime::Laminar => DiffKind::Laminar,
            Regime::Turbulent => DiffKind::Turbulent,
            Regime::Wake => DiffKind::Wake,
        }
    }
}

/// Midpoint skin friction Cf(Hk_a, Re_θa, M²_a) at the interval averages (XFOIL BLMID):
/// laminar CFL, turbulent max(CFT, CFL), zero in the wake.
fn midpoint_cf<const N: usize>(kind: DiffKind, s1: &Station<N>, s2: &Station<N>) -> Dual<N> {
    let hka = (s1.hk + s2.hk) * 0.5;
    let rta = (s1.rt + s2.rt) * 0.5;
    let ma = (s1.msq + s2.msq) * 0.5;
    match kind {
        DiffKind::Wake => Dual::constant(0.0),
        DiffKind::Laminar | DiffKind::Similarity => laminar_skin_friction_d(hka, rta),
        DiffKind::Turbulent => {
            let ct = turbulent_skin_friction_d(hka, rta, ma);
            let cl = laminar_skin_friction_d(hka, rta);
            if cl.v > ct.v {
                cl
            } else {
                ct
            }
        }
    }
}

/// Local upwinding weight UPW ∈ [0.5, 1) from the change of ln(Hk − 1) over the interval
/// (XFOIL BLDIF): UPW = 1 − ½exp(−min(ln²|(Hk2−1)/(Hk1−1)|, 15)·HDCON), HDCON = 5·HUPWT/Hk2²
/// on the wall and HUPWT/Hk2² in the wake. 0.5 is trapezoidal, 1 backward Euler.
fn upwinding<const N: usize>(
    kind: DiffKind,
    s1: &Station<N>,
    s2: &Station<N>,
    p: &BlParams,
) -> Dual<N> {
    let hdcon = if kind == DiffKind::Wake {
        p.upwinding_constant / s2.hk.sq()
    } else {
        5.0 * p.upwinding_constant / s2.hk.sq()
    };
    let hl = ((s2.hk - 1.0) / (s1.hk - 1.0)).abs().ln();
    let hlsq = hl.sq().min_const(15.0);
    1.0 - (-(hlsq * hdcon)).exp() * 0.5
}

/// Residuals of the three interval equations as derivative numbers (XFOIL BLDIF; residual
/// R, not XFOIL's −R). For [`DiffKind::Similarity`] pass the same station twice.
pub(crate) fn bldif<const N: usize>(
    kind: DiffKind,
    s1: &Station<N>,
    s2: &Station<N>,
    fc: &FlowConstants,
    p: &BlParams,
) -> [Dual<N>; 3] {
    let (xlog, ulog, tlog, hlog) = if kind == DiffKind::Similarity {
        (
            Dual::constant(1.0),
            Dual::constant(p.similarity_ue_exponent),
            Dual::constant(0.5 * (1.0 - p.similarity_ue_exponent)),
            Dual::constant(0.0),
        )
    } else {
        (
            (s2.x / s1.x).ln(),
            (s2.u / s1.u).ln(),
            (s2.t / s1.t).ln(),
            (s2.hs / s1.hs).ln(),
        )
    };
    let upw = upwinding(kind, s1, s2, p);
    let upw1 = 1.0 - upw;

    // ---- row 0: amplification or shear-lag equation
    let r0 = match kind {
        // stagnation point: N = 0
        DiffKind::Similarity => s2.s,
        // dN/dξ = average envelope rate (XFOIL AXSET, Drela & Giles 1987 eq. 20)
        DiffKind::Laminar => {
            let ax = average_amplification_rate_d(s1.ax, s1.t, s1.s, s2.ax, s2.t, s2.s, fc.ncrit);
            s2.s - s1.s - ax * (s2.x - s1.x)
        }
        // shear-lag (Drela 1989 eq. for d ln Cτ/dξ; Green's lag-entrainment form)
        DiffKind::Turbulent | DiffKind::Wake => shear_lag(kind, s1, s2, upw, upw1, ulog, p),
    };

    // ---- row 1: momentum equation dlnθ/dlnξ + (H + 2 − Me² + Hw) dlnUe/dlnξ = ξ/θ·Cf/2
    let ha = (s1.h + s2.h) * 0.5;
    let ma = (s1.msq + s2.msq) * 0.5;
    let xa = (s1.x + s2.x) * 0.5;
    let ta = (s1.t + s2.t) * 0.5;
    let hwa = (s1.dw / s1.t + s2.dw / s2.t) * 0.5;
    let cfm = midpoint_cf(kind, s1, s2);
    let cfx_m = cfm * xa / ta * 0.5 + (s1.cf * s1.x / s1.t + s2.cf * s2.x / s2.t) * 0.25;
    let btmp = ha + 2.0 - ma + hwa;
    let r1 = tlog + btmp * ulog - xlog * cfx_m * 0.5;

    // ---- row 2: kinetic-energy shape-parameter equation
    // dlnH*/dlnξ + (2H**/H* + 1 − H − Hw) dlnUe/dlnξ = ξ/θ (Cf/2 − 2CD/H*)
    let hsa = (s1.hs + s2.hs) * 0.5;
    let hca = (s1.hc + s2.hc) * 0.5;
    let xot1 = s1.x / s1.t;
    let xot2 = s2.x / s2.t;
    let dix = upw1 * s1.di * xot1 + upw * s2.di * xot2;
    let cfx = upw1 * s1.cf * xot1 + upw * s2.cf * xot2;
    let btmp = hca * 2.0 / hsa + 1.0 - ha - hwa;
    let r2 = hlog + btmp * ulog + xlog * (cfx * 0.5 - dix);

    [r0, r1, r2]
}

/// Shear-lag equation residual (Drela 1989; XFOIL BLDIF ITYP = 2, 3):
/// K_C/(1+Us)·(√Cτ_eq − λ√Cτ)Δξ − 2δ·Δln√Cτ + 2δ·(Q·Δξ − Δln Ue)·DUXCON = 0, with
/// K_C = SCCON·1.333, λ = DLCON in the wake, and the equilibrium 1/Ue dUe/dξ
/// Q = (CFFAC·Cf/2 − ((Hk − 1 − GCCON/Re_θ)/(GACON·λ·Hk))²)/(GBCON·δ*) (the XFOIL names of
/// the [`BlParams`] fields).
fn shear_lag<const N: usize>(
    kind: DiffKind,
    s1: &Station<N>,
    s2: &Station<N>,
    upw: Dual<N>,
    upw1: Dual<N>,
    ulog: Dual<N>,
    p: &BlParams,
) -> Dual<N> {
    let sa = upw1 * s1.s + upw * s2.s;
    let cqa = upw1 * s1.cq + upw * s2.cq;
    let cfa = upw1 * s1.cf + upw * s2.cf;
    let hka = upw1 * s1.hk + upw * s2.hk;
    let usa = (s1.us + s2.us) * 0.5;
    let rta = (s1.rt + s2.rt) * 0.5;
    let dea = (s1.de + s2.de) * 0.5;
    let da = (s1.d + s2.d) * 0.5;
    let ald = if kind == DiffKind::Wake {
        p.wake_dissipation_length_ratio
    } else {
        1.0
    };
    let hkc = if kind == DiffKind::Turbulent {
        (hka - 1.0 - p.equilibrium_low_re_offset / rta).max_const(0.01)
    } else {
        hka - 1.0
    };
    let hr = hkc / (hka * (p.equilibrium_locus_a * ald));
    let uq = (cfa * (0.5 * p.equilibrium_cf_factor) - hr.sq()) / (da * p.equilibrium_locus_b);
    let scc = p.shear_lag_constant * 1.333 / (usa + 1.0);
    let slog = (s2.s / s1.s).ln();
    let dxi = s2.x - s1.x;
    scc * (cqa - sa * ald) * dxi - dea * 2.0 * slog
        + dea * 2.0 * (uq * dxi - ulog) * p.shear_lag_pressure_gradient_factor
}
