//! The Cd axis of the drag polar: wide enough for the attached-flow polar, not for the stalled
//! tail, so that the laminar bucket fills the panel instead of its first tenth.
//!
//! Rule ([`CdAxis::Attached`], the default): in each polar take the points of its attached
//! branch — α between the α of its smallest and of its largest Cl — whose Cl lies in the
//! central [`ATTACHED_LIFT_FRACTION`] of the polar's Cl range (clear of positive and negative
//! stall, and of a post-stall tail whose Cl falls back into the range); the axis runs from 0
//! to [`CD_AXIS_HEADROOM`] × the largest Cd among them over all polars. Points beyond are drawn as arrowheads at the right edge and counted
//! in the axis label. When nothing would be cut off, or fewer than
//! [`MIN_ATTACHED_POINTS`] points qualify, the axis spans all data as the other axes do.

use std::str::FromStr;

use crate::section::PolarPoint;

/// Fraction of a polar's Cl range, centred in it, whose points set the Cd axis (5 % trimmed
/// at each end: the stall plateau and the negative-stall tail).
pub const ATTACHED_LIFT_FRACTION: f64 = 0.9;

/// Upper end of the Cd axis as a multiple of the largest attached-flow Cd: room for the
/// curves to bend towards stall before they leave the panel.
pub const CD_AXIS_HEADROOM: f64 = 1.5;

/// Fewest attached-flow points (all polars together) for the rule to apply.
pub const MIN_ATTACHED_POINTS: usize = 3;

/// How the upper end of the drag polar's Cd axis is chosen (`--cd-axis`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CdAxis {
    /// From the attached-flow drag (the module's rule); text `auto`.
    Attached,
    /// All data, padded like the other axes; text `all`.
    AllData,
    /// From 0 to this Cd; text: the number.
    UpTo(f64),
}

impl FromStr for CdAxis {
    type Err = String;

    /// `auto`, `all`, or a positive finite number.
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        match text.trim() {
            "auto" => Ok(Self::Attached),
            "all" => Ok(Self::AllData),
            t => match t.parse::<f64>() {
                Ok(cd) if cd.is_finite() && cd > 0.0 => Ok(Self::UpTo(cd)),
                _ => Err("expected auto, all or a positive drag coefficient".to_string()),
            },
        }
    }
}

impl CdAxis {
    /// The upper Cd limit for the drag polar of `polars` (usable points: converged, finite),
    /// `None` for an axis over all data.
    pub fn upper_limit(self, polars: &[&[PolarPoint]]) -> Option<f64> {
        match self {
            Self::AllData => None,
            Self::UpTo(cd) => Some(cd),
            Self::Attached => attached_cd_limit(polars),
        }
    }
}

/// The [`CdAxis::Attached`] limit: `None` when it would cut nothing off or too few points
/// qualify.
pub fn attached_cd_limit(polars: &[&[PolarPoint]]) -> Option<f64> {
    let mut count = 0;
    let mut attached_max = f64::NEG_INFINITY;
    let mut data_max = f64::NEG_INFINITY;
    for points in polars {
        let by_cl = |a: &&PolarPoint, b: &&PolarPoint| a.cl.total_cmp(&b.cl);
        let (Some(low), Some(high)) = (points.iter().min_by(by_cl), points.iter().max_by(by_cl))
        else {
            continue;
        };
        let (lo, hi) = (low.cl, high.cl);
        let (alpha_lo, alpha_hi) = (low.alpha.min(high.alpha), low.alpha.max(high.alpha));
        let trim = 0.5 * (1.0 - ATTACHED_LIFT_FRACTION) * (hi - lo);
        for p in points.iter() {
            data_max = data_max.max(p.cd);
            let attached = p.alpha >= alpha_lo && p.alpha <= alpha_hi;
            if attached && p.cl >= lo + trim && p.cl <= hi - trim {
                count += 1;
                attached_max = attached_max.max(p.cd);
            }
        }
    }
    let limit = CD_AXIS_HEADROOM * attached_max;
    (count >= MIN_ATTACHED_POINTS && limit > 0.0 && limit < data_max).then_some(limit)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A polar point with the given α, Cl, Cd.
    fn point(alpha: f64, cl: f64, cd: f64) -> PolarPoint {
        PolarPoint::from_coefficients(alpha, cl, cd, 0.0)
    }

    /// A laminar-bucket polar, α −6…14° in 0.25° steps: Cl 0.11 + 0.11 α up to its
    /// maximum 1.2 near 10°, flat beyond; Cd 0.005 in the bucket (|Cl − 0.4| ≤ 0.3), rising
    /// parabolically outside it to 0.01345 at Cl −0.55, and to 0.08 at 14° on the stall
    /// plateau.
    fn bucket_polar() -> Vec<PolarPoint> {
        (0..=80)
            .map(|i| {
                let alpha = -6.0 + 0.25 * f64::from(i);
                let cl = (0.11 + 0.11 * alpha).min(1.2);
                let off = ((cl - 0.4).abs() - 0.3).max(0.0);
                let stall = ((alpha - 10.0) / 4.0).max(0.0);
                let cd = 0.005 + 0.02 * off * off + 0.07 * stall * stall;
                point(alpha, cl, cd)
            })
            .collect()
    }

    #[test]
    fn attached_limit_keeps_the_bucket_readable() {
        let polar = bucket_polar();
        let data_max = polar.iter().map(|p| p.cd).fold(0.0, f64::max);
        assert!((data_max - 0.08).abs() < 1e-12, "data run to {data_max}");
        // Cl −0.55…1.2; the central 90 % is −0.4625…1.1125: its lowest point is Cl −0.44
        // (α −5°) with the largest Cd, 0.005 + 0.02·0.54² = 0.010832; × 1.5 = 0.016248.
        let limit = attached_cd_limit(&[&polar]).unwrap();
        assert!((limit - 0.016_248).abs() < 1e-9, "limit {limit}");
        assert!(limit < 0.03);
        // the bucket (Cd 0.005) reaches 31 % of the axis, not 6 % as over all data
        assert!(0.005 / limit > 0.3);
        // two polars: the larger attached drag sets the axis
        let tripped: Vec<PolarPoint> = polar
            .iter()
            .map(|p| point(p.alpha, p.cl, 2.0 * p.cd))
            .collect();
        let both = attached_cd_limit(&[&polar, &tripped]).unwrap();
        assert!((both - 2.0 * limit).abs() < 1e-12);
        // a post-stall tail whose Cl falls back into the range (α 15…20°, Cl 1.1 → 0.6, Cd
        // to 0.3) is not attached flow and leaves the limit alone
        let mut tail = polar.clone();
        tail.extend((1..=20).map(|i| {
            let alpha = 14.0 + 0.25 * f64::from(i) + 1.0;
            point(
                alpha,
                1.2 - 0.03 * f64::from(i),
                0.08 + 0.011 * f64::from(i),
            )
        }));
        assert_eq!(attached_cd_limit(&[&tail]), Some(limit));
    }

    #[test]
    fn attached_limit_steps_aside_when_it_cuts_nothing() {
        // a polar without stall: the limit would lie above all data
        let mild: Vec<PolarPoint> = (0..20)
            .map(|i| {
                let cl = 0.1 * f64::from(i);
                point(f64::from(i), cl, 0.006 + 0.001 * cl)
            })
            .collect();
        assert_eq!(attached_cd_limit(&[&mild]), None);
        assert_eq!(attached_cd_limit(&[&mild[..2]]), None, "too few points");
        assert_eq!(attached_cd_limit(&[]), None);
    }

    #[test]
    fn parses_the_option() {
        assert_eq!("auto".parse::<CdAxis>(), Ok(CdAxis::Attached));
        assert_eq!("all".parse::<CdAxis>(), Ok(CdAxis::AllData));
        assert_eq!("0.02".parse::<CdAxis>(), Ok(CdAxis::UpTo(0.02)));
        for bad in ["0", "-0.1", "inf", "nan", "wide", ""] {
            assert!(bad.parse::<CdAxis>().is_err(), "{bad}");
        }
        let polar = bucket_polar();
        assert_eq!(CdAxis::UpTo(0.04).upper_limit(&[&polar]), Some(0.04));
        assert_eq!(CdAxis::AllData.upper_limit(&[&polar]), None);
    }
}
