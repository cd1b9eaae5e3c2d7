//! What a table holds, counted: points, converged points, and how many of the converged ones
//! are supercritical, in massive separation or do not say — the line `polargen` prints on
//! stderr after a grid.

use super::PolarTable;
use std::fmt;

/// Point counts of a [`PolarTable`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TableCensus {
    /// Points, converged or not.
    pub points: usize,
    /// Converged points.
    pub converged: usize,
    /// Converged points flagged supercritical (Cp_min < Cp*, outside the method's validity;
    /// lookups use them, flagged).
    pub supercritical: usize,
    /// Converged points without the supercritical flag (a table written before it existed).
    pub unknown: usize,
    /// Converged points in massive separation (outside the method's validity; lookups do
    /// not use them).
    pub massive_separation: usize,
    /// Converged points without the massive-separation flag (a table written before it
    /// existed, or read from a format without it).
    pub separation_unknown: usize,
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
                    match p.massive_separation {
                        Some(true) => c.massive_separation += 1,
                        Some(false) => {}
                        None => c.separation_unknown += 1,
                    }
                }
            }
        }
        c
    }

    /// Number of usable points (converged and not in massive separation: the points lookups
    /// use, [`PolarPoint::usable`](crate::section::PolarPoint::usable)).
    pub fn usable_count(&self) -> usize {
        self.polars()
            .flat_map(|(_, polar)| polar)
            .filter(|p| p.usable())
            .count()
    }
}

impl fmt::Display for TableCensus {
    /// `1825 of 1830 points converged (99.7 %); 12 of them supercritical (Cp_min < Cp*), 40
    /// in massive separation (not used)`, with the unknown ones named when there are any.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} of {} points converged ({:.1} %); {} of them supercritical (Cp_min < Cp*), {} \
             in massive separation (not used)",
            self.converged,
            self.points,
            100.0 * self.converged as f64 / self.points.max(1) as f64,
            self.supercritical,
            self.massive_separation,
        )?;
        match (self.unknown, self.separation_unknown) {
            (0, 0) => {}
            (u, 0) => write!(f, ", {u} without the supercritical flag (unknown)")?,
            (0, s) => write!(f, ", {s} without the separation flag (unknown)")?,
            (u, s) => write!(
                f,
                ", {u} without the supercritical and {s} without the separation flag (unknown)"
            )?,
        }
        Ok(())
    }
}
