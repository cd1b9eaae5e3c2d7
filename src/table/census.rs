//! What a table holds, counted: points, converged points, and how many of the converged ones
//! are supercritical or do not say — the line `polargen` prints on stderr after a grid.

use super::PolarTable;
use std::fmt;

/// Point counts of a [`PolarTable`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TableCensus {
    /// Points, converged or not.
    pub points: usize,
    /// Converged points (the only ones lookups use).
    pub converged: usize,
    /// Converged points flagged supercritical (Cp_min < Cp*, outside the method's validity).
    pub supercritical: usize,
    /// Converged points without the flag (a table written before it existed).
    pub unknown: usize,
}

impl PolarTable {
    /// The point counts of this table.
    pub fn census(&self) -> TableCensus {
        let mut c = TableCensus::default();
        for (_, polar) in self.polars() {
            for p in polar {
                c.points += 1;
                if p.converged {
                    c.converged += 1;
                    match p.supercritical {
                        Some(true) => c.supercritical += 1,
                        Some(false) => {}
                        None => c.unknown += 1,
                    }
                }
            }
        }
        c
    }
}

impl fmt::Display for TableCensus {
    /// `1825 of 1830 points converged (99.7 %); 12 of them supercritical (Cp_min < Cp*)`, with
    /// the unknown ones named when there are any.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} of {} points converged ({:.1} %); {} of them supercritical (Cp_min < Cp*)",
            self.converged,
            self.points,
            100.0 * self.converged as f64 / self.points.max(1) as f64,
            self.supercritical
        )?;
        if self.unknown > 0 {
            write!(f, ", {} without the flag (unknown)", self.unknown)?;
        }
        Ok(())
    }
}
