//! Envelope e^n amplification rate (Drela & Giles 1987, AIAA J. 25(10), eqs. 20–23, with the
//! March 1991 m(H) refit and the smooth onset ramp of XFOIL 6.99 DAMPL) and its interval
//! average (XFOIL AXSET, rms-average version).
//!
//! XFOIL 6.99 selects DAMPL when IDAMPV = 0, which is its default; DAMPL2 (the modified
//! correlation for separated profiles) is not implemented here.

use super::closures::Partials;
use super::Dual;

/// Half-width of the cubic onset ramp in log10(Re_θ) around the critical Re_θ (XFOIL DGR).
const DGR: f64 = 0.08;

/// Spatial envelope amplification rate dN/dξ (XFOIL DAMPL):
/// dN/dξ = m(Hk)·(dN/dRe_θ)(Hk)/θ · ramp, where
/// log10 Re_θcrit = 2.492/(Hk−1)^0.43 + 0.7(tanh(14/(Hk−1) − 9.24) + 1) (eq. 23),
/// dN/dRe_θ = 0.028(Hk−1) − 0.0345 exp(−(3.87/(Hk−1) − 2.52)²) (eq. 21),
/// m = −0.05 + 2.7/(Hk−1) − 5.5/(Hk−1)² + 3/(Hk−1)³ (1991 refit), and the ramp is the cubic
/// 3r² − 2r³ over log10(Re_θ/Re_θcrit) ∈ [−DGR, DGR]. Zero below the ramp.
/// Arguments: `(hk, theta, rt)`.
pub fn amplification_rate(hk: f64, theta: f64, rt: f64) -> Partials<3> {
    let r = amplification_rate_d(
        Dual::<3>::variable(hk, 0),
        Dual::variable(theta, 1),
        Dual::variable(rt, 2),
    );
    Partials {
        value: r.v,
        d: [r.g[0], r.g[1], r.g[2]],
    }
}

pub(crate) fn amplification_rate_d<const N: usize>(
    hk: Dual<N>,
    theta: Dual<N>,
    rt: Dual<N>,
) -> Dual<N> {
    let hmi = 1.0 / (hk - 1.0);
    let aa = hmi.powf(0.43) * 2.492;
    let bb = (hmi * 14.0 - 9.24).tanh();
    let grcrit = aa + (bb + 1.0) * 0.7;
    let gr = rt.ln() / std::f64::consts::LN_10;
    if gr.v < grcrit.v - DGR {
        return Dual::constant(0.0);
    }
    let rnorm = (gr - (grcrit - DGR)) / (2.0 * DGR);
    let rfac = if rnorm.v >= 1.0 {
        Dual::constant(1.0)
    } else {
        rnorm.sq() * 3.0 - rnorm.powi(3) * 2.0
    };
    let arg = hmi * 3.87 - 2.52;
    let ex = (-arg.sq()).exp();
    let dadr = (hk - 1.0) * 0.028 - ex * 0.0345;
    let af = hmi * 2.7 - hmi.sq() * 5.5 + hmi.powi(3) * 3.0 - 0.05;
    af * dadr / theta * rfac
}

/// Average amplification rate over an interval (XFOIL AXSET, second-order rms version):
/// ā = √(½(a1² + a2²)) + 0.002/(θ1+θ2)·exp(−min(20(Ncrit − ½(N1+N2)), 20)) — the small
/// extra term keeps dN/dξ > 0 near N = Ncrit. Inputs are the stations' rates a = dN/dξ
/// ([`amplification_rate_d`], kept with each station), θ and N as [`Dual`]s.
pub(crate) fn average_amplification_rate_d<const N: usize>(
    ax1: Dual<N>,
    t1: Dual<N>,
    a1: Dual<N>,
    ax2: Dual<N>,
    t2: Dual<N>,
    a2: Dual<N>,
    ncrit: f64,
) -> Dual<N> {
    let axsq = (ax1.sq() + ax2.sq()) * 0.5;
    let axa = if axsq.v <= 0.0 {
        Dual::constant(0.0)
    } else {
        axsq.sqrt()
    };
    let arg = ((a1 + a2) * (-0.5) + ncrit) * 20.0;
    let exn = if arg.v <= 0.0 {
        Dual::constant(1.0)
    } else {
        (-arg.min_const(20.0)).exp()
    };
    let dax = exn * 0.002 / (t1 + t2);
    axa + dax
}
