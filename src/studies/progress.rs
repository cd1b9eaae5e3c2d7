//! Progress of a study on the terminal: a bar for the table points still to solve, then one
//! for the trims. Shown only when standard error is a terminal; silent otherwise and in tests.

use super::cache::TableCache;
use super::{Sections, StudiesError};
use crate::geometry::Airfoil;
use crate::section::Transition;
use crate::table::PolarTable;
use indicatif::{ProgressBar, ProgressStyle};

/// Progress display of a study.
#[derive(Default)]
pub struct Progress {
    /// Shown at all.
    visible: bool,
    /// The bar of the current phase.
    bar: std::sync::Mutex<Option<ProgressBar>>,
}

impl Progress {
    /// Bars on standard error if it is a terminal, else silent.
    pub fn on_terminal() -> Self {
        use std::io::IsTerminal;
        Self {
            visible: std::io::stderr().is_terminal(),
            bar: Default::default(),
        }
    }

    /// Silent.
    pub fn hidden() -> Self {
        Self::default()
    }

    /// Start a phase of `total` steps named by `unit`.
    pub fn start(&self, total: usize, unit: &str) {
        if !self.visible || total == 0 {
            return;
        }
        let bar = ProgressBar::new(total as u64);
        if let Ok(style) =
            ProgressStyle::with_template(&format!("{{bar:40}} {{pos}}/{{len}} {unit}, eta {{eta}}"))
        {
            bar.set_style(style);
        }
        if let Ok(mut slot) = self.bar.lock() {
            if let Some(old) = slot.replace(bar) {
                old.finish_and_clear();
            }
        }
    }

    /// Advance the current phase by `n` steps.
    pub fn advance(&self, n: usize) {
        if let Ok(slot) = self.bar.lock() {
            if let Some(bar) = slot.as_ref() {
                bar.inc(n as u64);
            }
        }
    }

    /// End the current phase.
    pub fn finish(&self) {
        if let Ok(mut slot) = self.bar.lock() {
            if let Some(bar) = slot.take() {
                bar.finish_and_clear();
            }
        }
    }
}

/// The tables of `foil` for `transitions` from `cache` (solving the missing ones with a
/// progress bar of their points).
pub fn study_tables(
    cache: &TableCache,
    foil: &Airfoil,
    transitions: &[Transition],
    progress: &Progress,
) -> Result<Vec<PolarTable>, StudiesError> {
    progress.start(cache.missing_points(foil, transitions), "table points");
    let tables = cache.tables(foil, transitions, &|n| progress.advance(n));
    progress.finish();
    tables
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
