//! Closure relations of the integral boundary layer (Drela & Giles 1987, AIAA J. 25(10);
//! Drela 1989, "XFOIL: an analysis and design system for low Reynolds number airfoils";
//! constants as in XFOIL 6.99 xblsys.f).
//!
//! Each closure is written once on derivative numbers (`*_d` functions, used by the station
//! and interval equations so the chain rule is exact) and exposed as a pure `f64` function
//! returning its value and partial derivatives in a [`Partials`] struct. The partials are the
//! exact derivatives of the implemented formula (forward-mode differentiation), including
//! the zero slope of any clamp that is active.

use super::Dual;
use crate::compressibility::GAMMA_MINUS_ONE;

/// Value of a closure and its partial derivatives with respect to its `N` arguments, in the
/// argument order of the function that returned it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Partials<const N: usize> {
    /// Closure value.
    pub value: f64,
    /// ∂value/∂argument, in argument order.
    pub d: [f64; N],
}

/// Evaluates a Dual closure at `args`, seeding one gradient slot per argument.
fn partials<const N: usize>(args: [f64; N], f: impl Fn(&[Dual<N>; N]) -> Dual<N>) -> Partials<N> {
    let duals: [Dual<N>; N] = std::array::from_fn(|i| Dual::variable(args[i], i));
    let r = f(&duals);
    Partials { value: r.v, d: r.g }
}

/// Kinematic shape parameter Hk(H, Me²) = (H − 0.29 Me²)/(1 + 0.113 Me²)
/// (Whitfield's correlation; XFOIL HKIN). Arguments: `(h, msq)`.
pub fn kinematic_shape_factor(h: f64, msq: f64) -> Partials<2> {
    partials([h, msq], |a| kinematic_shape_factor_d(a[0], a[1]))
}

pub(crate) fn kinematic_shape_factor_d<const N: usize>(h: Dual<N>, msq: Dual<N>) -> Dual<N> {
    (h - msq * 0.29) / (msq * 0.113 + 1.0)
}

/// Laminar kinetic-energy shape parameter H*(Hk) from Falkner–Skan profiles
/// (Drela & Giles 1987 eq. 17; XFOIL HSL). Arguments: `(hk, rt, msq)` (no Re_θ or Mach
/// dependence, the partials w.r.t. them are zero).
pub fn laminar_energy_shape_factor(hk: f64, rt: f64, msq: f64) -> Partials<3> {
    partials([hk, rt, msq], |a| laminar_energy_shape_factor_d(a[0]))
}

pub(crate) fn laminar_energy_shape_factor_d<const N: usize>(hk: Dual<N>) -> Dual<N> {
    if hk.v < 4.35 {
        let tmp = hk - 4.35;
        let hp1 = hk + 1.0;
        tmp.sq() * 0.0111 / hp1 - tmp.powi(3) * 0.0278 / hp1 + 1.528 - (tmp * hk).sq() * 0.0002
    } else {
        (hk - 4.35).sq() * 0.015 / hk + 1.528
    }
}

/// Turbulent kinetic-energy shape parameter H*(Hk, Re_θ, Me²) (Drela 1989 "arctan(y+) +
/// Schlichting" profile fit, attached and separated branches, with Whitfield's
/// compressibility correction; XFOIL HST). Arguments: `(hk, rt, msq)`.
pub fn turbulent_energy_shape_factor(hk: f64, rt: f64, msq: f64) -> Partials<3> {
    partials([hk, rt, msq], |a| {
        turbulent_energy_shape_factor_d(a[0], a[1], a[2])
    })
}

pub(crate) fn turbulent_energy_shape_factor_d<const N: usize>(
    hk: Dual<N>,
    rt: Dual<N>,
    msq: Dual<N>,
) -> Dual<N> {
    const HSMIN: f64 = 1.5;
    const DHSINF: f64 = 0.015;
    // Re_θ-dependent break point H0 (limited for Re_θ < 400) and Re_θ floor of 200.
    let ho = if rt.v > 400.0 {
        400.0 / rt + 3.0
    } else {
        Dual::constant(4.0)
    };
    let rtz = if rt.v > 200.0 {
        rt
    } else {
        Dual::constant(200.0)
    };
    let hs = if hk.v < ho.v {
        // attached branch
        let hr = (ho - hk) / (ho - 1.0);
        (2.0 - HSMIN - 4.0 / rtz) * hr.sq() * 1.5 / (hk + 0.5) + HSMIN + 4.0 / rtz
    } else {
        // separated branch
        let grt = rtz.ln();
        let hdif = hk - ho;
        let rtmp = hk - ho + 4.0 / grt;
        let htmp = grt * 0.007 / rtmp.sq() + DHSINF / hk;
        hdif.sq() * htmp + HSMIN + 4.0 / rtz
    };
    // Whitfield's compressibility correction
    (hs + msq * 0.028) / (msq * 0.014 + 1.0)
}

/// Laminar skin friction Cf(Hk, Re_θ) from Falkner–Skan profiles (Drela & Giles 1987
/// eq. 18; XFOIL CFL). Arguments: `(hk, rt, msq)` (no Mach dependence).
pub fn laminar_skin_friction(hk: f64, rt: f64, msq: f64) -> Partials<3> {
    partials([hk, rt, msq], |a| laminar_skin_friction_d(a[0], a[1]))
}

pub(crate) fn laminar_skin_friction_d<const N: usize>(hk: Dual<N>, rt: Dual<N>) -> Dual<N> {
    if hk.v < 5.5 {
        let tmp = (5.5 - hk).powi(3) / (hk + 1.0);
        (tmp * 0.0727 - 0.07) / rt
    } else {
        let tmp = 1.0 - 1.0 / (hk - 4.5);
        (tmp.sq() * 0.015 - 0.07) / rt
    }
}

/// Turbulent skin friction Cf(Hk, Re_θ, Me²), Swafford/Coles form with the Whitfield
/// compressibility factor Fc = √(1 + (γ−1)/2 Me²) (Drela 1989; XFOIL CFT, γ of air). Arguments: `(hk, rt, msq)`.
pub fn turbulent_skin_friction(hk: f64, rt: f64, msq: f64) -> Partials<3> {
    partials([hk, rt, msq], |a| {
        turbulent_skin_friction_d(a[0], a[1], a[2])
    })
}

/// ln 10 rounded as in XFOIL CFT (kept for fidelity to the reference implementation).
#[allow(clippy::approx_constant)]
const XFOIL_LN10: f64 = 2.3026;

pub(crate) fn turbulent_skin_friction_d<const N: usize>(
    hk: Dual<N>,
    rt: Dual<N>,
    msq: Dual<N>,
) -> Dual<N> {
    let fc = (msq * (0.5 * GAMMA_MINUS_ONE) + 1.0).sqrt();
    let grt = (rt / fc).ln().max_const(3.0);
    let gex = hk * (-0.31) - 1.74;
    let arg = (hk * (-1.33)).max_const(-20.0);
    let thk = (4.0 - hk / 0.875).tanh();
    // (GRT/ln 10)^GEX written as exp(GEX·ln(GRT/ln 10)) so both exponent and base vary
    let cfo = 0.3 * arg.exp() * (gex * (grt / XFOIL_LN10).ln()).exp();
    (cfo + (thk - 1.0) * 1.1e-4) / fc
}

/// Laminar dissipation function 2CD/H*(Hk, Re_θ) from Falkner–Skan profiles (Drela & Giles
/// 1987 eq. 19; XFOIL DIL). Arguments: `(hk, rt)`.
pub fn laminar_dissipation(hk: f64, rt: f64) -> Partials<2> {
    partials([hk, rt], |a| laminar_dissipation_d(a[0], a[1]))
}

pub(crate) fn laminar_dissipation_d<const N: usize>(hk: Dual<N>, rt: Dual<N>) -> Dual<N> {
    if hk.v < 4.0 {
        ((4.0 - hk).powf(5.5) * 0.00205 + 0.207) / rt
    } else {
        let hkb = hk - 4.0;
        let den = hkb.sq() * 0.02 + 1.0;
        (hkb.sq() * (-0.0016) / den + 0.207) / rt
    }
}

/// Laminar wake dissipation function 2CD/H*(Hk, Re_θ) = 2·1.10(1−1/Hk)²/Hk/(H*·Re_θ),
/// with the laminar H* (XFOIL DILW). Arguments: `(hk, rt)`.
pub fn laminar_wake_dissipation(hk: f64, rt: f64) -> Partials<2> {
    partials([hk, rt], |a| laminar_wake_dissipation_d(a[0], a[1]))
}

pub(crate) fn laminar_wake_dissipation_d<const N: usize>(hk: Dual<N>, rt: Dual<N>) -> Dual<N> {
    let hs = laminar_energy_shape_factor_d(hk);
    let rcd = (1.0 - 1.0 / hk).sq() * 1.10 / hk;
    rcd * 2.0 / (hs * rt)
}

/// Density-thickness shape parameter H** = Me²(0.064/(Hk − 0.8) + 0.251) (Whitfield;
/// XFOIL HCT). Arguments: `(hk, msq)`.
pub fn density_shape_factor(hk: f64, msq: f64) -> Partials<2> {
    partials([hk, msq], |a| density_shape_factor_d(a[0], a[1]))
}

pub(crate) fn density_shape_factor_d<const N: usize>(hk: Dual<N>, msq: Dual<N>) -> Dual<N> {
    msq * (0.064 / (hk - 0.8) + 0.251)
}

/// Normalised wall slip velocity Us = H*/2·(1 − (Hk − 1)/(B·H)) (Drela 1989 eq. for the
/// outer-layer velocity; XFOIL BLVAR US2). Arguments: `(hs, hk, h)`; `locus_b` is B.
/// No clamp is applied here (the station applies the regime's limits).
pub fn slip_velocity(hs: f64, hk: f64, h: f64, locus_b: f64) -> Partials<3> {
    partials([hs, hk, h], |a| slip_velocity_d(a[0], a[1], a[2], locus_b))
}

pub(crate) fn slip_velocity_d<const N: usize>(
    hs: Dual<N>,
    hk: Dual<N>,
    h: Dual<N>,
    locus_b: f64,
) -> Dual<N> {
    hs * 0.5 * (1.0 - (hk - 1.0) / (h * locus_b))
}

/// Square root of the equilibrium shear-stress coefficient,
/// √Cτ_eq = √(CTCON·H*·(Hk−1)·Hkc²/((1−Us)·H·Hk²)), with Hkc = Hk − 1 − GCCON/Re_θ (≥ 0.01)
/// on the turbulent wall and Hkc = Hk − 1 otherwise (Drela 1989 G–β equilibrium locus, XFOIL BLVAR
/// CQ2 "NEW 12 Oct 94"). `low_re_offset` selects the wall form (XFOIL applies it on
/// turbulent wall stations only); `ctau_constant` is CTCON, `low_re_c` GCCON
/// ([`super::BlParams`]). Arguments: `(hs, us, hk, h, rt)`.
#[allow(clippy::too_many_arguments)]
pub fn ctau_eq_sqrt(
    hs: f64,
    us: f64,
    hk: f64,
    h: f64,
    rt: f64,
    low_re_offset: bool,
    ctau_constant: f64,
    low_re_c: f64,
) -> Partials<5> {
    partials([hs, us, hk, h, rt], |a| {
        ctau_eq_sqrt_d(
            a[0],
            a[1],
            a[2],
            a[3],
            a[4],
            low_re_offset,
            ctau_constant,
            low_re_c,
        )
    })
}

#[allow(clippy::too_many_arguments)]
pub(crate) fn ctau_eq_sqrt_d<const N: usize>(
    hs: Dual<N>,
    us: Dual<N>,
    hk: Dual<N>,
    h: Dual<N>,
    rt: Dual<N>,
    low_re_offset: bool,
    ctau_constant: f64,
    low_re_c: f64,
) -> Dual<N> {
    let hkc = if low_re_offset {
        (hk - 1.0 - low_re_c / rt).max_const(0.01)
    } else {
        hk - 1.0
    };
    let hkb = hk - 1.0;
    let usb = 1.0 - us;
    (hs * hkb * hkc.sq() * ctau_constant / (usb * h * hk.sq())).sqrt()
}

/// Turbulent dissipation function 2CD/H* on the wall (XFOIL 6.99 BLVAR, ITYP = 2):
/// wall term Cf·Us/H* scaled by the low-Hk factor ½(1 + tanh((Hk−1)/(Hmin−1))),
/// Hmin = 1 + 2.1/ln Re_θ, plus the outer-layer term 2Cτ(0.995 − Us)/H* and the laminar
/// stress term 0.3(0.995 − Us)²/(Re_θ H*) (Drela 1989 eq. for CD). Arguments:
/// `(hs, us, cf_turb, s = √Cτ, hk, rt)`. The laminar floor (max with DIL) is applied by the
/// caller.
pub fn dissipation_turbulent(
    hs: f64,
    us: f64,
    cf_turb: f64,
    s: f64,
    hk: f64,
    rt: f64,
) -> Partials<6> {
    partials([hs, us, cf_turb, s, hk, rt], |a| {
        dissipation_turbulent_d(a[0], a[1], a[2], a[3], a[4], a[5])
    })
}

pub(crate) fn dissipation_turbulent_d<const N: usize>(
    hs: Dual<N>,
    us: Dual<N>,
    cf_turb: Dual<N>,
    s: Dual<N>,
    hk: Dual<N>,
    rt: Dual<N>,
) -> Dual<N> {
    let wall = cf_turb * us * 0.5 * 2.0 / hs;
    let hmin = 1.0 + 2.1 / rt.ln();
    let fl = (hk - 1.0) / (hmin - 1.0);
    let dfac = 0.5 + fl.tanh() * 0.5;
    wall * dfac + dissipation_outer_d(hs, us, s, rt)
}

/// Outer-layer (wake-like) part of 2CD/H*: 2Cτ(0.995 − Us)/H* + 0.3(0.995 − Us)²/(Re_θ H*)
/// (XFOIL BLVAR, ITYP ≠ 1). Arguments: `(hs, us, s = √Cτ, rt)`.
pub fn dissipation_outer(hs: f64, us: f64, s: f64, rt: f64) -> Partials<4> {
    partials([hs, us, s, rt], |a| {
        dissipation_outer_d(a[0], a[1], a[2], a[3])
    })
}

pub(crate) fn dissipation_outer_d<const N: usize>(
    hs: Dual<N>,
    us: Dual<N>,
    s: Dual<N>,
    rt: Dual<N>,
) -> Dual<N> {
    let dd = s.sq() * (0.995 - us) * 2.0 / hs;
    let dl = (0.995 - us).sq() * 0.15 / rt * 2.0 / hs;
    dd + dl
}

/// Initial shear stress at transition as a fraction of equilibrium,
/// Cτ_tr/Cτ_eq factor on √Cτ: factor·exp(−exponent/(Hk − 1)) (XFOIL TRDIF CTR; CTRCON, CTRCEX).
/// Arguments: `(hk,)`.
pub fn transition_ctau_factor(hk: f64, factor: f64, exponent: f64) -> Partials<1> {
    partials([hk], |a| transition_ctau_factor_d(a[0], factor, exponent))
}

pub(crate) fn transition_ctau_factor_d<const N: usize>(
    hk: Dual<N>,
    factor: f64,
    exponent: f64,
) -> Dual<N> {
    (-exponent / (hk - 1.0)).exp() * factor
}

/// Boundary-layer thickness δ from Green's simplified correlation,
/// δ = (3.15 + 1.72/(Hk − 1))θ + δ*, limited to 12θ (XFOIL BLVAR DE2). Arguments:
/// `(hk, theta, dstar)`.
pub fn bl_thickness(hk: f64, theta: f64, dstar: f64) -> Partials<3> {
    partials([hk, theta, dstar], |a| bl_thickness_d(a[0], a[1], a[2]))
}

pub(crate) fn bl_thickness_d<const N: usize>(
    hk: Dual<N>,
    theta: Dual<N>,
    dstar: Dual<N>,
) -> Dual<N> {
    const HDMAX: f64 = 12.0;
    let de = (3.15 + 1.72 / (hk - 1.0)) * theta + dstar;
    if de.v > HDMAX * theta.v {
        theta * HDMAX
    } else {
        de
    }
}
