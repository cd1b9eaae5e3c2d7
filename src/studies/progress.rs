//! The tables of a study with their progress: the points still to solve, reported to the
//! caller's [`Progress`] (a phase that states the tables to solve, their points and an
//! estimate).

use super::cache::TableCache;
use super::{Sections, StudiesError};
use crate::geometry::Airfoil;
use crate::progress::{Progress, Work};
use crate::section::Transition;
use crate::table::PolarTable;

/// The tables of `foil` for `transitions` from `cache`, solving the missing ones as one
/// phase of `progress` (none when every table is cached).
pub fn study_tables(
    cache: &TableCache,
    foil: &Airfoil,
    transitions: &[Transition],
    progress: &dyn Progress,
) -> Result<Vec<PolarTable>, StudiesError> {
    solving_phase(cache, &[foil], transitions, progress);
    let tables = cache.tables(foil, transitions, &|n| progress.advance(n));
    progress.finish();
    tables
}

/// Starts the phase of `progress` that solves the tables of `foils` × `transitions` missing
/// from `cache`, if any: its start line names the tables, their points and an estimate.
pub(crate) fn solving_phase(
    cache: &TableCache,
    foils: &[&Airfoil],
    transitions: &[Transition],
    progress: &dyn Progress,
) {
    let missing: usize = foils
        .iter()
        .map(|f| cache.missing_points(f, transitions) / cache.grid.point_count().max(1))
        .sum();
    if missing == 0 {
        return;
    }
    let names: Vec<&str> = foils.iter().map(|f| f.name.as_str()).collect();
    progress.start(&Work {
        total: missing * cache.grid.point_count(),
        unit: "table points",
        what: format!(
            "{missing} section table{} of {} to solve (cached in {} for the next run)",
            if missing == 1 { "" } else { "s" },
            names.join(", "),
            cache.dir.display()
        ),
        estimate_s: Some(cache.grid.estimated_seconds(missing, cache.threads)),
    });
}

/// `tables` by their `transitions` (same order).
pub fn sections<'a>(
    transitions: &[Transition],
    tables: &'a [PolarTable],
) -> Sections<'a, PolarTable> {
    Sections {
        entries: transitions.iter().copied().zip(tables.iter()).collect(),
    }
}
