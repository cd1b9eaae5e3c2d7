//! Natural logarithm and two-argument arctangent written without branches, so that a loop
//! calling them over many values compiles to vector instructions (four values per instruction
//! under [`super::simd::with_avx2`]); the standard library's versions are function calls that
//! keep such a loop scalar. They serve the panel influence kernels (XFOIL PSILIN/PSWLIN: one
//! log r² and one arctangent per panel end), whose cost per angle of attack they dominate.
//!
//! Both reduce the argument and sum a truncated Taylor series whose first omitted term is below
//! half an ulp; the error is at most 2 ulp over the tested ranges (see the tests), against the
//! correctly rounded results of the standard library.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, SQRT_2};

/// ln 2 split so that e·LN2_HI is exact for any binary exponent e (LN2_HI has 32 significant
/// bits); LN2_LO = ln 2 − LN2_HI.
const LN2_HI: f64 = 0.693_147_180_369_123_8;
const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;

/// 1/(2k+1), k = 1…9: the series 2·atanh z = 2z·Σ z^{2k}/(2k+1) of ln((1+z)/(1−z)); with
/// |z| ≤ (√2−1)/(√2+1) the first omitted term is below 2.3e-17 relative.
const ATANH_SERIES: [f64; 9] = [
    1.0 / 3.0,
    1.0 / 5.0,
    1.0 / 7.0,
    1.0 / 9.0,
    1.0 / 11.0,
    1.0 / 13.0,
    1.0 / 15.0,
    1.0 / 17.0,
    1.0 / 19.0,
];

/// (−1)^k/(2k+1), k = 1…11: the series atan u = u·Σ (−u²)^k/(2k+1); with |u| ≤ tan(π/16) the
/// first omitted term is below 1e-18 relative.
const ATAN_SERIES: [f64; 11] = [
    -1.0 / 3.0,
    1.0 / 5.0,
    -1.0 / 7.0,
    1.0 / 9.0,
    -1.0 / 11.0,
    1.0 / 13.0,
    -1.0 / 15.0,
    1.0 / 17.0,
    -1.0 / 19.0,
    1.0 / 21.0,
    -1.0 / 23.0,
];

/// tan(π/16) and tan(3π/16): the bounds of the three reduction intervals of [`atan2`].
const TAN_PI_16: f64 = 0.198_912_367_379_658;
const TAN_3PI_16: f64 = 0.668_178_637_919_298_9;
/// tan(π/8) = √2 − 1 as a double, the centre of the middle interval, and atan of that double.
const TAN_PI_8: f64 = 0.414_213_562_373_095_15;
const ATAN_TAN_PI_8: f64 = 0.392_699_081_698_724_25;
/// The parts of π/4, π/2 and π below their doubles.
const FRAC_PI_4_LO: f64 = 3.061_616_997_868_383e-17;
const FRAC_PI_2_LO: f64 = 6.123_233_995_736_766e-17;
const PI_LO: f64 = 1.224_646_799_147_353_2e-16;

/// Σ c_k w^k by Horner's rule.
#[inline(always)]
fn series<const N: usize>(w: f64, c: &[f64; N]) -> f64 {
    let mut p = c[N - 1];
    for &ck in c[..N - 1].iter().rev() {
        p = ck + w * p;
    }
    p
}

/// Natural logarithm of a positive, finite, normal `x` (other arguments give unspecified
/// values). x = m·2^e with m ∈ [√½, √2), ln m = 2·atanh((m−1)/(m+1)).
#[inline(always)]
pub(crate) fn ln(x: f64) -> f64 {
    let bits = x.to_bits();
    // 2^52 + biased exponent, exactly, then minus 2^52 + 1023: the exponent as a float
    // (no integer-to-float conversion, which has no AVX2 instruction for 64-bit lanes).
    let biased = f64::from_bits(0x4330_0000_0000_0000 | (bits >> 52));
    let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    let big = m > SQRT_2;
    let m = if big { 0.5 * m } else { m };
    let e = biased - 4_503_599_627_371_519.0 + if big { 1.0 } else { 0.0 };
    let z2 = 2.0 * (m - 1.0) / (m + 1.0);
    let w = 0.25 * z2 * z2;
    let ln_m = z2 + z2 * (w * series(w, &ATANH_SERIES));
    e * LN2_HI + (e * LN2_LO + ln_m)
}

/// The angle of the point (x, y) in (−π, π], as `f64::atan2(y, x)` (signed zeros included) for
/// finite arguments. |y/x| or |x/y| ∈ [0, 1] is reduced about 0, tan(π/8) or 1 to
/// |u| ≤ tan(π/16) (atan t = atan c + atan((t − c)/(1 + t·c))).
#[inline(always)]
pub(crate) fn atan2(y: f64, x: f64) -> f64 {
    let (ax, ay) = (x.abs(), y.abs());
    let swap = ay > ax;
    let (num, den) = if swap { (ax, ay) } else { (ay, ax) };
    let high = num > TAN_3PI_16 * den;
    let mid = num > TAN_PI_16 * den;
    let c = if high {
        1.0
    } else if mid {
        TAN_PI_8
    } else {
        0.0
    };
    let (base, base_lo) = if high {
        (FRAC_PI_4, FRAC_PI_4_LO)
    } else if mid {
        (ATAN_TAN_PI_8, 0.0)
    } else {
        (0.0, 0.0)
    };
    let u = (num - c * den) / (den + c * num);
    // x = y = 0: angle 0 before the quadrant corrections.
    let u = if den > 0.0 { u } else { 0.0 };
    let w = u * u;
    let a = base + (base_lo + (u + u * (w * series(w, &ATAN_SERIES))));
    let a = if swap {
        FRAC_PI_2 - a + FRAC_PI_2_LO
    } else {
        a
    };
    let a = if x.is_sign_negative() {
        PI - a + PI_LO
    } else {
        a
    };
    a.copysign(y)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::test_random::Lcg;

    /// Distance of `a` from the correctly rounded `b` in units of the last place of `b`.
    fn ulps(a: f64, b: f64) -> f64 {
        if a == b {
            return 0.0;
        }
        let ulp = f64::from_bits(b.abs().to_bits() + 1) - b.abs();
        (a - b).abs() / ulp
    }

    #[test]
    fn ln_within_two_ulp() {
        let mut g = Lcg::new(7);
        let mut worst: f64 = 0.0;
        for i in 0..200_000 {
            // log-uniform over 1e-300…1e300, and densely around 1 where ln is small.
            let x = if i % 2 == 0 {
                10f64.powf(600.0 * g.unit() - 300.0)
            } else {
                1.0 + 0.1 * g.symmetric()
            };
            worst = worst.max(ulps(ln(x), x.ln()));
        }
        for x in [
            1.0,
            2.0,
            0.5,
            SQRT_2,
            f64::MIN_POSITIVE,
            f64::MAX,
            1.0 + f64::EPSILON,
        ] {
            worst = worst.max(ulps(ln(x), x.ln()));
        }
        assert!(worst <= 2.0, "worst {worst} ulp");
        assert_eq!(ln(1.0), 0.0);
    }

    #[test]
    fn atan2_within_two_ulp_and_quadrants_of_std() {
        let mut g = Lcg::new(11);
        let mut worst: f64 = 0.0;
        for i in 0..200_000 {
            let (y, x) = if i % 3 == 0 {
                // Near the axes and diagonals, where the reductions switch.
                let a = std::f64::consts::FRAC_PI_8 * (g.unit() * 16.0).floor();
                let a = a + 1e-6 * g.symmetric();
                (a.sin(), a.cos())
            } else {
                let r = 10f64.powf(20.0 * g.unit() - 10.0);
                (
                    r * g.symmetric(),
                    r * 10f64.powf(6.0 * g.symmetric()) * g.symmetric(),
                )
            };
            worst = worst.max(ulps(atan2(y, x), y.atan2(x)));
        }
        assert!(worst <= 2.0, "worst {worst} ulp");
        for (y, x) in [
            (0.0, 0.0),
            (-0.0, 0.0),
            (0.0, -0.0),
            (-0.0, -0.0),
            (1.0, 0.0),
            (1.0, -0.0),
            (-1.0, 0.0),
            (0.0, -1.0),
            (-0.0, -1.0),
            (1e-300, 1.0),
            (1.0, 1e-300),
            (-1.0, -1.0),
        ] {
            let (a, b) = (atan2(y, x), y.atan2(x));
            assert!(
                ulps(a, b) <= 2.0 && a.is_sign_negative() == b.is_sign_negative(),
                "{y} {x}: {a} {b}"
            );
        }
    }
}
