//! Batch runs: one table per airfoil of a list of coordinate files, folders and names, on one
//! grid with one set of solver settings, with an index of what was written; a shard (every
//! N-th airfoil) per machine or job-array task, and a resumed run keeps what is finished.
//!
//! * Inputs: a folder gives its `*.dat` files (any case; other entries are skipped with a
//!   note, subfolders are not searched); anything else is taken as one airfoil, a coordinate
//!   file or a name ([`airfoil_by_name_or_path`](crate::geometry::airfoil_by_name_or_path)).
//!   An airfoil's name in the batch is its file stem (`naca0012` for `foils/naca0012.dat` and
//!   for the name `naca0012`); two inputs with one name are refused, as is a name that an
//!   index file carries. The list is sorted by name (byte order) and shard K of N takes the
//!   airfoils at positions K, K + N, K + 2N, … (1-based), so shards of one list never overlap
//!   and together cover it.
//! * Before any solve every airfoil of the shard is loaded and prepared; the first that
//!   cannot be is the error.
//! * Each table is written atomically as `<name>.csv` or `<name>.json` in the output folder.
//!   A table with no converged point is not written (and a table of that name left from an
//!   earlier run is removed); its index row says why.
//! * The index `index.csv` + `index.json` (`index-K-of-N.*` for a shard) lists every airfoil
//!   of the shard with [`IndexRow`]s; it is written before the first solve and rewritten after
//!   each table, the two files together ([`OutputSet`](crate::output::OutputSet)).
//! * Resuming keeps a table that reads back and was made for the same grid and settings: its
//!   metadata (airfoil name, N_crit, forced transition, panel count, solver name and version,
//!   geometry operations)
//!   equal those of the request, and its Re and Mach axes and every polar's α list equal the
//!   requested ones. A truncated, foreign or differently made table is solved again. The
//!   Newton threshold and the chord rotation are not recorded in a table and so not compared.
//! * Airfoils run `jobs` at a time, each table on `threads` workers; tables do not depend on
//!   either.

mod index;

pub use index::{IndexRow, TableStatus};

use super::build::table_meta;
use super::{
    build_table, read_table, write_table, GridSpec, PolarTable, TableError, TableFormat, TableMeta,
};
use crate::diagnostics::error_line;
use crate::geometry::{solver_airfoil, Airfoil, GeometryError, ShapeOp};
use crate::output::{check_output_path, names_a_file, OutputError};
use crate::progress::{Progress, Work};
use crate::viscous::ViscousParams;
use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};
use std::time::Instant;

/// Extension (any case) of the coordinate files a folder given as input contributes.
pub const AIRFOIL_EXTENSION: &str = "dat";

/// Shard `index` of `count` (1 ≤ index ≤ count): the airfoils at positions index, index +
/// count, … of the sorted list.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    /// Which shard, from 1.
    pub index: usize,
    /// How many shards.
    pub count: usize,
}

impl FromStr for Shard {
    type Err = BatchError;

    /// `K/N` with 1 ≤ K ≤ N.
    fn from_str(text: &str) -> Result<Self, BatchError> {
        let bad = |reason| BatchError::Shard {
            text: text.to_string(),
            reason,
        };
        let (k, n) = text.split_once('/').ok_or_else(|| bad("expected K/N"))?;
        let parse = |s: &str| s.trim().parse::<usize>().map_err(|_| bad("expected K/N"));
        let (index, count) = (parse(k)?, parse(n)?);
        if count == 0 {
            return Err(bad("N must be at least 1"));
        }
        if index == 0 {
            return Err(bad(
                "K counts from 1 (a Slurm array whose task ids start at 0: --array=1-N)",
            ));
        }
        if index > count {
            return Err(bad("K must be at most N"));
        }
        Ok(Self { index, count })
    }
}

/// Why a batch cannot start or could not finish.
#[derive(Debug, thiserror::Error)]
pub enum BatchError {
    /// Airfoils (comma-separated) without a table at the end of the run.
    #[error("no table for {0} (see the index)")]
    Failed(String),
    /// A shard that is not `K/N` with 1 ≤ K ≤ N.
    #[error("shard '{text}': {reason}")]
    Shard {
        /// The shard as given.
        text: String,
        /// What is wrong.
        reason: &'static str,
    },
    /// A folder given as input holds no coordinate file.
    #[error("{0}: no *.dat coordinate files in this folder")]
    EmptyFolder(PathBuf),
    /// A folder given as input cannot be listed.
    #[error("{path}: {source}")]
    Folder {
        /// The folder.
        path: PathBuf,
        /// The operating-system error.
        #[source]
        source: std::io::Error,
    },
    /// Two inputs would write the same table.
    #[error("two airfoils named '{name}' ({first}, {second}): each table is named after its input's file stem")]
    SameName {
        /// The shared name.
        name: String,
        /// The first input.
        first: String,
        /// The second input.
        second: String,
    },
    /// An input whose table would be written over an index file.
    #[error("{spec}: an airfoil named '{name}' would be written over a batch index")]
    IndexName {
        /// Its name.
        name: String,
        /// The input.
        spec: String,
    },
    /// Standard input given as an airfoil.
    #[error("-: a batch takes coordinate files, folders or airfoil names, not standard input")]
    Stdin,
    /// An airfoil that cannot be loaded or prepared for the solver, and an error that does
    /// not name the input.
    #[error("{spec}")]
    Airfoil {
        /// The input.
        spec: String,
        /// Why.
        #[source]
        source: GeometryError,
    },
    /// An airfoil that cannot be loaded, by an error that names the input.
    #[error(transparent)]
    Geometry(GeometryError),
    /// A table format that a resumed batch could not read back with its settings.
    #[error(
        "format {0}: a batch writes csv or json tables (they read back with the settings a \
         resumed run compares; polargen convert writes the other formats)"
    )]
    Format(&'static str),
    /// The output folder or an index file.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// A table could not be written.
    #[error("{0}")]
    Table(PathBuf, #[source] TableError),
}

/// What a batch is asked to do besides its inputs and output folder.
#[derive(Clone, Debug)]
pub struct BatchSettings {
    /// The grid of every table.
    pub grid: GridSpec,
    /// Solver settings (Re and M are each node's).
    pub base: ViscousParams,
    /// Panel nodes of every airfoil.
    pub panels: usize,
    /// Rotate each contour so that its chord lies along x.
    pub derotate: bool,
    /// Geometry operations applied to every airfoil (recorded in its table).
    pub geometry: Vec<ShapeOp>,
    /// Table format: [`TableFormat::Csv`] or [`TableFormat::Json`].
    pub format: TableFormat,
    /// This run's shard, or all airfoils.
    pub shard: Option<Shard>,
    /// Keep finished tables (see the module documentation).
    pub resume: bool,
    /// Airfoils solved at the same time (0 = one per core).
    pub jobs: usize,
    /// Worker threads per table (0 = all cores).
    pub threads: usize,
}

/// A batch ready to run: its shard's airfoils loaded and the output folder checked.
pub struct Batch {
    settings: BatchSettings,
    out: PathBuf,
    /// This shard's airfoils: (name, input, solver nodes), sorted by name.
    airfoils: Vec<(String, String, Airfoil)>,
    notes: Vec<String>,
}

/// How a batch ended.
#[derive(Clone, Debug, PartialEq)]
pub struct BatchSummary {
    /// Tables solved and written.
    pub solved: usize,
    /// Tables kept from an earlier run.
    pub kept: usize,
    /// Airfoils without a table.
    pub failed: Vec<String>,
    /// Points in the tables written or kept.
    pub points: usize,
    /// Converged points among them.
    pub converged: usize,
    /// The index (CSV; the JSON beside it).
    pub index: PathBuf,
}

impl BatchSummary {
    /// An error naming the airfoils without a table, if any.
    pub fn require_all(&self) -> Result<(), BatchError> {
        match self.failed.as_slice() {
            [] => Ok(()),
            names => Err(BatchError::Failed(names.join(", "))),
        }
    }
}

impl std::fmt::Display for BatchSummary {
    /// `tables: 3 solved, 1 kept, 0 failed; 120 of 124 points converged; index out/index.csv`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "tables: {} solved, {} kept, {} failed; {} of {} points converged; index {}",
            self.solved,
            self.kept,
            self.failed.len(),
            self.converged,
            self.points,
            self.index.display()
        )
    }
}

impl Batch {
    /// Collect the airfoils of `inputs` (see the module documentation), take the shard's,
    /// load and prepare each, and check that `out` can be the output folder.
    pub fn plan(
        inputs: &[String],
        out: &Path,
        settings: BatchSettings,
    ) -> Result<Self, BatchError> {
        if !matches!(settings.format, TableFormat::Csv | TableFormat::Json) {
            return Err(BatchError::Format(settings.format.name()));
        }
        let (list, mut notes) = collect_inputs(inputs)?;
        let total = list.len();
        let chosen: Vec<(String, String)> = match settings.shard {
            Some(s) => list
                .into_iter()
                .skip(s.index - 1)
                .step_by(s.count)
                .collect(),
            None => list,
        };
        check_output_path(&out.join(format!("{}.csv", index::index_stem(shard_pair(&settings)))))?;
        let mut airfoils = Vec::with_capacity(chosen.len());
        for (name, spec) in chosen {
            let (foil, more) = solver_airfoil(
                &spec,
                settings.panels,
                settings.derotate,
                &settings.geometry,
            )
            .map_err(|source| BatchError::Airfoil {
                spec: spec.clone(),
                source,
            })?;
            notes.extend(more);
            let table = out.join(format!("{name}.{}", settings.format.name()));
            check_output_path(&table)?;
            if !names_a_file(&table) {
                return Err(BatchError::Output(OutputError::bad(
                    &table,
                    "is not a regular file (a device, FIFO or descriptor): a batch writes its \
                     tables as files",
                )));
            }
            airfoils.push((name, spec, foil));
        }
        if let (Some(s), true) = (settings.shard, airfoils.is_empty()) {
            notes.push(format!(
                "shard {}/{}: no airfoil of the {total} given falls in this shard",
                s.index, s.count
            ));
        }
        Ok(Self {
            settings,
            out: out.to_path_buf(),
            airfoils,
            notes,
        })
    }

    /// What a user should read before the run: skipped folder entries, changed contours.
    pub fn notes(&self) -> &[String] {
        &self.notes
    }

    /// Points this run asks for (all tables of the shard, kept ones included).
    pub fn point_count(&self) -> usize {
        self.airfoils.len() * self.settings.grid.point_count()
    }

    /// The work of [`run`](Self::run) for a progress display: the tables, their points
    /// (kept ones included) and an estimate of solving them all.
    pub fn work(&self) -> Work {
        let s = &self.settings;
        let tables = self.airfoils.len();
        let threads = match s.threads {
            0 => 0,
            t => t * s.jobs.max(1),
        };
        Work {
            total: self.point_count(),
            unit: "points",
            what: format!(
                "{tables} airfoil table{} into {}",
                if tables == 1 { "" } else { "s" },
                self.out.display()
            ),
            estimate_s: Some(s.grid.estimated_seconds(tables, threads)),
        }
    }

    /// [`run`](Self::run) reported to `progress`: one phase of [`work`](Self::work).
    pub fn run_with_progress(&self, progress: &dyn Progress) -> Result<BatchSummary, BatchError> {
        progress.start(&self.work());
        let summary = self.run(|n| progress.advance(n))?;
        progress.finish();
        Ok(summary)
    }

    /// Solve (or keep) every table, writing each and the index after it; `on_points` is
    /// called with the number of points of each finished polar (a kept table's all at once).
    /// An airfoil without a converged point is a failed row, not an error; errors are those
    /// of writing.
    pub fn run(&self, on_points: impl Fn(usize) + Sync) -> Result<BatchSummary, BatchError> {
        let stem = index::index_stem(shard_pair(&self.settings));
        let rows: Vec<IndexRow> = self
            .airfoils
            .iter()
            .map(|(name, spec, _)| IndexRow {
                airfoil: name.clone(),
                file: spec.clone(),
                points: 0,
                converged: 0,
                seconds: 0.0,
                status: TableStatus::Pending,
                summary: Vec::new(),
            })
            .collect();
        let index = index::write_index(&self.out, &stem, &rows)?;
        let rows = Mutex::new(rows);
        // Plain threads, not a rayon pool: a rayon worker waiting for a table's own pool would
        // start further airfoils meanwhile, so `jobs` would not bound the tables in progress.
        let (next, stop) = (AtomicUsize::new(0), AtomicBool::new(false));
        let worker = || -> Result<(), BatchError> {
            loop {
                let k = next.fetch_add(1, Ordering::Relaxed);
                if k >= self.airfoils.len() || stop.load(Ordering::Relaxed) {
                    return Ok(());
                }
                let written = self.table(&self.airfoils[k], &on_points).and_then(|row| {
                    let mut rows = rows.lock().unwrap_or_else(PoisonError::into_inner);
                    rows[k] = row;
                    Ok(index::write_index(&self.out, &stem, &rows)?)
                });
                if written.is_err() {
                    stop.store(true, Ordering::Relaxed);
                    return written.map(|_| ());
                }
            }
        };
        let jobs = match self.settings.jobs {
            0 => std::thread::available_parallelism().map_or(1, |n| n.get()),
            j => j,
        };
        std::thread::scope(|scope| {
            let workers: Vec<_> = (0..jobs.min(self.airfoils.len()))
                .map(|_| scope.spawn(worker))
                .collect();
            workers
                .into_iter()
                .try_for_each(|w| w.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
        })?;
        let rows = rows.into_inner().unwrap_or_else(PoisonError::into_inner);
        let count = |s: TableStatus| rows.iter().filter(|r| r.status == s).count();
        Ok(BatchSummary {
            solved: count(TableStatus::Solved),
            kept: count(TableStatus::Kept),
            failed: rows
                .iter()
                .filter(|r| matches!(r.status, TableStatus::Failed(_)))
                .map(|r| r.airfoil.clone())
                .collect(),
            points: rows.iter().map(|r| r.points).sum(),
            converged: rows.iter().map(|r| r.converged).sum(),
            index,
        })
    }

    /// The table of one airfoil: kept, or solved and written; its index row.
    fn table(
        &self,
        (name, spec, foil): &(String, String, Airfoil),
        on_points: &(impl Fn(usize) + Sync),
    ) -> Result<IndexRow, BatchError> {
        let s = &self.settings;
        let path = self.out.join(format!("{name}.{}", s.format.name()));
        let row = |table: Option<&PolarTable>, seconds, status| {
            let c = table.map(PolarTable::census).unwrap_or_default();
            let summary = table.map_or_else(Vec::new, |t| {
                let mut rows = t.summaries();
                rows.iter_mut().for_each(|r| r.airfoil.clone_from(name));
                rows
            });
            IndexRow {
                airfoil: name.clone(),
                file: spec.clone(),
                points: c.points,
                converged: c.converged,
                seconds,
                status,
                summary,
            }
        };
        let meta = TableMeta {
            geometry: s.geometry.clone(),
            ..table_meta(foil, s.panels, &s.base)
        };
        if let Some(table) = s.resume.then(|| finished(&path, &meta, &s.grid)).flatten() {
            on_points(s.grid.point_count());
            return Ok(row(Some(&table), 0.0, TableStatus::Kept));
        }
        let start = Instant::now();
        let built = build_table(foil, s.panels, &s.grid, &s.base, s.threads, on_points)
            .map(|t| t.with_geometry(&s.geometry));
        let seconds = (start.elapsed().as_secs_f64() * 100.0).round() / 100.0;
        let why = match built {
            Ok(table) if table.census().converged > 0 => {
                write_table(&table, &path, Some(s.format))
                    .map_err(|e| BatchError::Table(path, e))?;
                return Ok(row(Some(&table), seconds, TableStatus::Solved));
            }
            Ok(_) => "no point converged".to_string(),
            Err(e) => error_line(&e),
        };
        match std::fs::remove_file(&path) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                return Err(OutputError::io(&path, e).into())
            }
            _ => {}
        }
        Ok(row(None, seconds, TableStatus::Failed(why)))
    }
}

/// The shard as (K, N), when there is one.
fn shard_pair(settings: &BatchSettings) -> Option<(usize, usize)> {
    settings.shard.map(|s| (s.index, s.count))
}

/// The table at `path` when it reads back and was made with `meta` on `grid` (see the module
/// documentation); `None` otherwise.
fn finished(path: &Path, meta: &TableMeta, grid: &GridSpec) -> Option<PolarTable> {
    let table = read_table(path).ok()?;
    let sorted = |v: &[f64]| {
        let mut v = v.to_vec();
        v.sort_by(f64::total_cmp);
        v
    };
    let alphas = sorted(&grid.alpha_deg);
    let same = table.meta() == meta
        && table.re() == sorted(&grid.reynolds)
        && table.mach() == sorted(&grid.mach)
        && table
            .polars()
            .all(|(_, polar)| polar.iter().map(|p| p.alpha).eq(alphas.iter().copied()));
    same.then_some(table)
}

/// (name, input) pairs.
type NamedInputs = Vec<(String, String)>;

/// The (name, input) pairs of `inputs` sorted by name, and notes on skipped folder entries.
fn collect_inputs(inputs: &[String]) -> Result<(NamedInputs, Vec<String>), BatchError> {
    let stem = |p: &Path, spec: &str| {
        p.file_stem()
            .map_or_else(|| spec.to_string(), |s| s.to_string_lossy().into_owned())
    };
    let mut list: Vec<(String, String)> = Vec::new();
    let mut notes = Vec::new();
    for spec in inputs {
        let path = Path::new(spec);
        if spec.trim() == crate::input::STDIN_PATH {
            return Err(BatchError::Stdin);
        }
        if !path.is_dir() {
            list.push((stem(path, spec), spec.clone()));
            continue;
        }
        let folder = |source| BatchError::Folder {
            path: path.to_path_buf(),
            source,
        };
        let (mut found, mut skipped) = (0, 0);
        for entry in std::fs::read_dir(path).map_err(folder)? {
            let file = entry.map_err(folder)?.path();
            let dat = file
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case(AIRFOIL_EXTENSION));
            if dat && file.is_file() {
                list.push((stem(&file, spec), file.display().to_string()));
                found += 1;
            } else {
                skipped += 1;
            }
        }
        if found == 0 {
            return Err(BatchError::EmptyFolder(path.to_path_buf()));
        }
        if skipped > 0 {
            notes.push(format!(
                "{spec}: {skipped} entries other than *.{AIRFOIL_EXTENSION} files skipped"
            ));
        }
    }
    list.sort();
    if let Some(w) = list.windows(2).find(|w| w[0].0 == w[1].0) {
        return Err(BatchError::SameName {
            name: w[0].0.clone(),
            first: w[0].1.clone(),
            second: w[1].1.clone(),
        });
    }
    if let Some((name, spec)) = list.iter().find(|(n, _)| index::is_index_name(n)) {
        return Err(BatchError::IndexName {
            name: name.clone(),
            spec: spec.clone(),
        });
    }
    Ok((list, notes))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_are_k_of_n_from_one() {
        assert_eq!(
            "2/3".parse::<Shard>().unwrap(),
            Shard { index: 2, count: 3 }
        );
        for (text, why) in [
            ("3/2", "K must be at most N"),
            ("0/0", "N must be at least 1"),
            ("0/4", "K counts from 1"),
            ("2", "expected K/N"),
            ("a/2", "expected K/N"),
        ] {
            let e = text.parse::<Shard>().unwrap_err().to_string();
            assert!(e.starts_with(&format!("shard '{text}': {why}")), "{e}");
        }
    }
}
