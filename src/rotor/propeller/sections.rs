//! The sections of a propeller blade: one section along the whole blade, or a family of
//! sections by thickness ratio t/c, each annulus reading the two tables that bracket its own
//! t/c and interpolating their coefficients linearly in t/c.

use crate::section::{Lookup, SectionAero};
use std::sync::Arc;

/// Section data of one member of a family.
pub type SharedSection = Arc<dyn SectionAero + Send + Sync>;

/// The blade's sections: one, or several by thickness ratio.
#[derive(Clone)]
pub struct PropellerSections {
    /// Thickness ratio of each member, strictly increasing (empty for one section).
    thickness: Vec<f64>,
    /// The members' section data, in the order of `thickness`.
    sections: Vec<SharedSection>,
}

/// Why a family of sections cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("propeller sections: {0}")]
pub struct SectionsError(&'static str);

impl PropellerSections {
    /// One section along the whole blade.
    pub fn single(section: SharedSection) -> Self {
        Self {
            thickness: Vec::new(),
            sections: vec![section],
        }
    }

    /// A family of sections by thickness ratio: `(t/c, section)` pairs, in any order; the
    /// thickness ratios must be positive and distinct.
    pub fn by_thickness(mut members: Vec<(f64, SharedSection)>) -> Result<Self, SectionsError> {
        if members.is_empty() {
            return Err(SectionsError("no section"));
        }
        if members.iter().any(|m| !(m.0.is_finite() && m.0 > 0.0)) {
            return Err(SectionsError("thickness ratios must be positive"));
        }
        members.sort_by(|a, b| a.0.total_cmp(&b.0));
        if members.windows(2).any(|w| w[0].0 == w[1].0) {
            return Err(SectionsError("two sections with one thickness ratio"));
        }
        let (thickness, sections) = members.into_iter().unzip();
        Ok(Self {
            thickness,
            sections,
        })
    }

    /// The thickness ratios of the family (empty for one section).
    pub fn thickness_ratios(&self) -> &[f64] {
        &self.thickness
    }

    /// The section of an annulus of thickness ratio `t` (ignored for one section): the
    /// bracketing members and the weight of the thicker one; `t` outside the family's range
    /// takes the nearest member.
    pub(crate) fn at(&self, t: f64) -> StationSection {
        let n = self.sections.len();
        if n == 1 || t.is_nan() {
            return StationSection::one(0);
        }
        let k = self.thickness.partition_point(|&v| v <= t);
        match k {
            0 => StationSection::one(0),
            k if k >= n => StationSection::one(n - 1),
            k => {
                let (t0, t1) = (self.thickness[k - 1], self.thickness[k]);
                StationSection {
                    thinner: k - 1,
                    thicker: k,
                    weight: (t - t0) / (t1 - t0),
                }
            }
        }
    }

    /// Coefficients of `station`'s section: the bracketing members' lookups interpolated
    /// linearly in t/c, every validity flag of either carried.
    pub(crate) fn lookup(
        &self,
        station: &StationSection,
        alpha_deg: f64,
        re: f64,
        mach: f64,
    ) -> Lookup {
        let a = self.sections[station.thinner].lookup(alpha_deg, re, mach);
        if station.weight == 0.0 {
            return a;
        }
        let b = self.sections[station.thicker].lookup(alpha_deg, re, mach);
        let w = station.weight;
        let mix = |x: f64, y: f64| x + w * (y - x);
        Lookup {
            cl: mix(a.cl, b.cl),
            cd: mix(a.cd, b.cd),
            cm: mix(a.cm, b.cm),
            re_clamped: a.re_clamped || b.re_clamped,
            mach_clamped: a.mach_clamped || b.mach_clamped,
            post_stall: a.post_stall || b.post_stall,
            bridged: a.bridged || b.bridged,
            supercritical: a.supercritical || b.supercritical,
            supercritical_unknown: a.supercritical_unknown || b.supercritical_unknown,
            massive_separation: a.massive_separation || b.massive_separation,
            separation_unknown: a.separation_unknown || b.separation_unknown,
        }
    }
}

/// Where one annulus sits in the family: the two members and the weight of the thicker.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct StationSection {
    thinner: usize,
    thicker: usize,
    weight: f64,
}

impl StationSection {
    /// Member `k` alone.
    fn one(k: usize) -> Self {
        Self {
            thinner: k,
            thicker: k,
            weight: 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A section whose coefficients are `k` times (α, 1, −1) and which flags `post_stall`
    /// beyond 10°.
    struct Linear(f64);

    impl SectionAero for Linear {
        fn lookup(&self, alpha_deg: f64, _re: f64, _mach: f64) -> Lookup {
            Lookup {
                post_stall: alpha_deg > 10.0,
                ..Lookup::new(self.0 * alpha_deg, self.0, -self.0)
            }
        }
    }

    fn family() -> PropellerSections {
        let member = |t: f64, k: f64| (t, Arc::new(Linear(k)) as SharedSection);
        PropellerSections::by_thickness(vec![member(0.3, 3.0), member(0.1, 1.0), member(0.2, 2.0)])
            .unwrap()
    }

    #[test]
    fn annuli_interpolate_between_the_bracketing_thicknesses() {
        let f = family();
        assert_eq!(f.thickness_ratios(), &[0.1, 0.2, 0.3]);
        let at = |t: f64, alpha: f64| f.lookup(&f.at(t), alpha, 1e6, 0.1);
        assert!((at(0.15, 4.0).cl - 6.0).abs() < 1e-12);
        assert!((at(0.25, 4.0).cd - 2.5).abs() < 1e-12);
        assert_eq!(at(0.2, 4.0).cm, -2.0);
        // Outside the family: the nearest member; without a thickness: the thinnest.
        assert_eq!(at(0.05, 1.0).cl, 1.0);
        assert_eq!(at(0.5, 1.0).cl, 3.0);
        assert_eq!(at(f64::NAN, 1.0).cl, 1.0);
        assert!(at(0.15, 12.0).post_stall && !at(0.15, 8.0).post_stall);
    }

    #[test]
    fn a_family_needs_distinct_positive_thicknesses() {
        let member = |t: f64| (t, Arc::new(Linear(1.0)) as SharedSection);
        assert!(PropellerSections::by_thickness(vec![]).is_err());
        assert!(PropellerSections::by_thickness(vec![member(0.1), member(0.1)]).is_err());
        assert!(PropellerSections::by_thickness(vec![member(0.0)]).is_err());
        assert!(PropellerSections::by_thickness(vec![member(f64::NAN)]).is_err());
    }
}
