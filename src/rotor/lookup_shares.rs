//! The shares of a rotor run's blade-element lookups that fall outside the section table or
//! outside the section method's validity, and the one way the notes say them.

/// Shares (0 … 1) of the blade-element lookups of a rotor solution, or the largest over a
/// run, that the section data cannot vouch for.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LookupShares {
    /// Reynolds or Mach number outside the table: clamped to its edge.
    pub clamped: f64,
    /// Leaning on supercritical table points (locally supersonic flow).
    pub supercritical: f64,
    /// At an α where the table's points are in massive separation (the 360° extension
    /// stands in).
    pub separated: f64,
}

impl LookupShares {
    /// What each share means, in the order of [`values`](Self::values), as the notes say it.
    pub const MEANINGS: [&'static str; 3] = [
        "lie outside the table's Reynolds/Mach range and use its edge values",
        "lean on supercritical table points (locally supersonic, outside the section method's \
         validity)",
        "fall where the table's points are in massive separation (outside the section method's \
         validity): the 360-degree extension stands in for them",
    ];

    /// The shares in the order of [`MEANINGS`](Self::MEANINGS).
    pub fn values(&self) -> [f64; 3] {
        [self.clamped, self.supercritical, self.separated]
    }

    /// The larger of each share of `self` and `other`.
    pub fn max(self, other: Self) -> Self {
        Self {
            clamped: self.clamped.max(other.clamped),
            supercritical: self.supercritical.max(other.supercritical),
            separated: self.separated.max(other.separated),
        }
    }

    /// One note per share above zero: `note: {at}, {p} % of the blade-element lookups …`
    /// (`at` says where: `at 60.0 kt`, `during the takeoff up to`).
    pub fn notes(&self, at: &str) -> Vec<String> {
        self.values()
            .into_iter()
            .zip(Self::MEANINGS)
            .filter(|(share, _)| *share > 0.0)
            .map(|(share, meaning)| {
                format!(
                    "note: {at}, {:.1} % of the blade-element lookups {meaning}",
                    100.0 * share
                )
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn notes_name_each_share_above_zero() {
        let s = LookupShares {
            clamped: 0.25,
            supercritical: 0.0,
            separated: 0.031,
        };
        let notes = s.notes("at 60.0 kt");
        assert_eq!(notes.len(), 2);
        assert!(notes[0].starts_with("note: at 60.0 kt, 25.0 % of the blade-element lookups lie"));
        assert!(notes[1].contains("3.1 % of the blade-element lookups fall where"));
        let peak = s.max(LookupShares {
            clamped: 0.1,
            supercritical: 0.2,
            separated: 0.0,
        });
        assert_eq!(peak.values(), [0.25, 0.2, 0.031]);
    }
}
