//! Section data along the blade: what a strip at radius fraction r/R reads.
//!
//! * [`BladeSection`] — coefficients at (r/R, α, Re, M), the interface the rotor's strips
//!   consume. Every [`SectionAero`] is a blade section that is the same along the whole span.
//! * [`SpanwiseSection`] — a blade whose section changes along the span: a base section, and
//!   other sections over given r/R bands (a blade contaminated over part of its span reads
//!   the tripped table there and the clean one elsewhere).

use crate::section::{Lookup, SectionAero};

/// Section coefficients along a blade: at radius fraction `r_over_r` (strip centre / R),
/// angle of attack `alpha_deg` (any value), Reynolds number `re` and Mach number `mach`.
pub trait BladeSection {
    /// Coefficients of the strip at `r_over_r`.
    fn lookup_at(&self, r_over_r: f64, alpha_deg: f64, re: f64, mach: f64) -> Lookup;
}

/// A section table or analytic section is the same at every radius.
impl<T: SectionAero + ?Sized> BladeSection for T {
    fn lookup_at(&self, _r_over_r: f64, alpha_deg: f64, re: f64, mach: f64) -> Lookup {
        self.lookup(alpha_deg, re, mach)
    }
}

/// One band of a [`SpanwiseSection`]: `section` over `inner ≤ r/R < outer` (`outer` = 1
/// includes the tip; `inner ≥ outer` is an empty band).
#[derive(Clone, Copy, Debug)]
pub struct SpanBand<'a, S: ?Sized> {
    /// Inner edge r/R of the band.
    pub inner: f64,
    /// Outer edge r/R of the band.
    pub outer: f64,
    /// The section inside the band.
    pub section: &'a S,
}

impl<S: ?Sized> SpanBand<'_, S> {
    /// Whether a strip centred at `r_over_r` lies in the band.
    pub fn contains(&self, r_over_r: f64) -> bool {
        self.inner < self.outer
            && r_over_r >= self.inner
            && (r_over_r < self.outer || (self.outer >= 1.0 && r_over_r <= 1.0))
    }
}

/// A blade whose section depends on the radius: `base` everywhere except inside `bands`,
/// where the first band containing the strip centre gives the section.
#[derive(Clone, Debug)]
pub struct SpanwiseSection<'a, S: ?Sized> {
    /// The section outside every band.
    pub base: &'a S,
    /// Bands with another section, searched in order.
    pub bands: Vec<SpanBand<'a, S>>,
}

impl<'a, S: ?Sized> SpanwiseSection<'a, S> {
    /// `base` everywhere, `band` over `inner ≤ r/R < outer`. An empty band (`inner ≥ outer`)
    /// leaves the blade all `base`.
    pub fn banded(base: &'a S, band: &'a S, inner: f64, outer: f64) -> Self {
        Self {
            base,
            bands: vec![SpanBand {
                inner,
                outer,
                section: band,
            }],
        }
    }

    /// The section of a strip centred at `r_over_r`.
    pub fn section_at(&self, r_over_r: f64) -> &'a S {
        self.bands
            .iter()
            .find(|b| b.contains(r_over_r))
            .map_or(self.base, |b| b.section)
    }
}

impl<S: SectionAero + ?Sized> BladeSection for SpanwiseSection<'_, S> {
    fn lookup_at(&self, r_over_r: f64, alpha_deg: f64, re: f64, mach: f64) -> Lookup {
        self.section_at(r_over_r).lookup(alpha_deg, re, mach)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A section whose lift coefficient is its label.
    struct Labelled(f64);

    impl SectionAero for Labelled {
        fn lookup(&self, _alpha: f64, _re: f64, _mach: f64) -> Lookup {
            Lookup::new(self.0, 0.0, 0.0)
        }
    }

    #[test]
    fn strips_read_the_band_they_lie_in() {
        let (clean, dirty) = (Labelled(1.0), Labelled(2.0));
        let outboard = SpanwiseSection::banded(&clean, &dirty, 0.5, 1.0);
        let cl = |s: &SpanwiseSection<Labelled>, r: f64| s.lookup_at(r, 0.0, 1e6, 0.3).cl;
        assert_eq!(cl(&outboard, 0.3), 1.0);
        assert_eq!(cl(&outboard, 0.5), 2.0);
        assert_eq!(cl(&outboard, 1.0), 2.0);
        let inboard = SpanwiseSection::banded(&clean, &dirty, 0.0, 0.5);
        assert_eq!(cl(&inboard, 0.49), 2.0);
        assert_eq!(cl(&inboard, 0.5), 1.0);
        let none = SpanwiseSection::banded(&clean, &dirty, 1.0, 1.0);
        assert_eq!(cl(&none, 0.999), 1.0);
        // A uniform section ignores the radius.
        assert_eq!(dirty.lookup_at(0.1, 0.0, 1e6, 0.3).cl, 2.0);
    }
}
