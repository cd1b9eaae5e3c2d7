//! The section tables of the studies: built with polargen's own solver and kept in a cache
//! folder, one JSON table per (airfoil geometry, transition setting, grid, solver settings),
//! so that a rerun reads them instead of solving them again.
//!
//! The file name carries a 64-bit FNV-1a hash of everything the table depends on: the
//! paneled coordinates (bit patterns), the panel count, the transition setting, the grid
//! axes, the solver's parameters (their full debug form, so any change of a default gives a
//! new key), the crate version and [`CACHE_FORMAT`]. An entry is used only when it parses
//! and describes exactly the requested table (airfoil, setting, panels, axes, point count);
//! anything else — a corrupt or cut-short file, a stale entry, an entry that is not a regular
//! file (a FIFO, a link to a device) or is larger than the input limit — is solved again and
//! replaced, with a note ([`TableCache::notes`]). Entries are read through the one capped,
//! regular-file-only reader ([`read_input`]) and written atomically
//! ([`write_output`](crate::output::write_output)).

use super::StudiesError;
use crate::geometry::{airfoil_by_name_or_path, Airfoil};
use crate::input::{read_input, InputProblem};
use crate::polar::SweepParams;
use crate::section::Transition;
use crate::table::{build_table, parse_table, write_table, GridSpec, PolarTable, TableFormat};
use crate::viscous::ViscousParams;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// Version of the cache's key and file layout; raise it when either changes.
pub const CACHE_FORMAT: u32 = 1;

/// The cache folder used without `--cache`: `$XDG_CACHE_HOME/polargen/tables`, else
/// `$HOME/.cache/polargen/tables`, else `.polargen-cache` in the working folder.
pub fn default_cache_dir() -> PathBuf {
    let from = |var: &str| {
        std::env::var_os(var)
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    };
    if let Some(dir) = from("XDG_CACHE_HOME") {
        dir.join("polargen").join("tables")
    } else if let Some(home) = from("HOME") {
        home.join(".cache").join("polargen").join("tables")
    } else {
        PathBuf::from(".polargen-cache")
    }
}

/// An airfoil by name (`naca8h12`, `naca23012`, …) or coordinate file, in chord units and
/// paneled with `panels` nodes (as `polargen --airfoil` does).
pub fn load_study_airfoil(spec: &str, panels: usize) -> Result<Airfoil, StudiesError> {
    let err = |source| StudiesError::Airfoil {
        name: spec.to_string(),
        source,
    };
    let given = airfoil_by_name_or_path(spec).map_err(err)?;
    given
        .solver_nodes(panels)
        .map(|(foil, _)| foil)
        .map_err(err)
}

/// 64-bit FNV-1a (Fowler–Noll–Vo; offset basis and prime of the 64-bit variant).
struct Fnv(u64);

impl Fnv {
    fn new() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }

    fn bytes(&mut self, b: &[u8]) {
        for &x in b {
            self.0 ^= u64::from(x);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    fn floats(&mut self, v: &[f64]) {
        // The length first, so that two lists never hash as their concatenation.
        self.bytes(&(v.len() as u64).to_le_bytes());
        for x in v {
            self.bytes(&x.to_bits().to_le_bytes());
        }
    }
}

/// Where the studies' tables are built and kept.
#[derive(Clone, Debug)]
pub struct TableCache {
    /// Cache folder.
    pub dir: PathBuf,
    /// Table grid.
    pub grid: GridSpec,
    /// Panel nodes of the airfoils (recorded in the tables).
    pub panels: usize,
    /// Worker threads of a table build (0 = all cores).
    pub threads: usize,
    /// Why entries that exist were not used (shared by clones).
    notes: Arc<Mutex<Vec<String>>>,
}

impl TableCache {
    /// The cache in folder `dir` of tables on `grid` with `panels` nodes, built on `threads`
    /// workers (0 = all cores).
    pub fn new(dir: PathBuf, grid: GridSpec, panels: usize, threads: usize) -> Self {
        Self {
            dir,
            grid,
            panels,
            threads,
            notes: Arc::default(),
        }
    }

    /// Why entries that exist were not used (unreadable, not a regular file, too large,
    /// corrupt or stale) and were solved again, one note per entry.
    pub fn notes(&self) -> Vec<String> {
        self.notes.lock().map(|n| n.clone()).unwrap_or_default()
    }

    /// Records why the entry `path` was not used.
    fn note(&self, path: &Path, why: impl std::fmt::Display) {
        let note = format!(
            "note: table cache entry {}: {why}; solved again and replaced",
            path.display()
        );
        if let Ok(mut notes) = self.notes.lock() {
            if !notes.contains(&note) {
                notes.push(note);
            }
        }
    }

    /// The solver parameters of a table with `transition`.
    fn params(transition: &Transition) -> ViscousParams {
        ViscousParams {
            transition: *transition,
            ..ViscousParams::default()
        }
    }

    /// The cache file of `foil`'s table with `transition`.
    pub fn entry(&self, foil: &Airfoil, transition: &Transition) -> PathBuf {
        let mut h = Fnv::new();
        h.bytes(&CACHE_FORMAT.to_le_bytes());
        h.bytes(env!("CARGO_PKG_VERSION").as_bytes());
        h.bytes(foil.name.as_bytes());
        h.floats(&foil.x);
        h.floats(&foil.y);
        h.bytes(&(self.panels as u64).to_le_bytes());
        h.floats(&self.grid.reynolds);
        h.floats(&self.grid.mach);
        h.floats(&self.grid.alpha_deg);
        h.bytes(format!("{:?}", Self::params(transition)).as_bytes());
        h.bytes(format!("{:?}", SweepParams::default()).as_bytes());
        let stem: String = foil
            .name
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() {
                    c.to_ascii_lowercase()
                } else {
                    '_'
                }
            })
            .collect();
        self.dir.join(format!("{stem}_{:016x}.json", h.0))
    }

    /// The cached table, if its entry is a valid table of exactly this request; an entry
    /// that exists but is not used gets a note.
    pub fn cached(&self, foil: &Airfoil, transition: &Transition) -> Option<PolarTable> {
        let path = self.entry(foil, transition);
        let bytes = match read_input(&path) {
            Ok(bytes) => bytes,
            Err(e) if e.problem == InputProblem::NotFound => return None,
            Err(e) => {
                self.note(&path, e.problem);
                return None;
            }
        };
        let table = match parse_table(&bytes, TableFormat::Json) {
            Ok(t) => t,
            Err(e) => {
                self.note(&path, format!("not a readable table ({e})"));
                return None;
            }
        };
        let m = table.meta();
        let matches = m.airfoil == foil.name
            && m.transition == *transition
            && m.panels == self.panels
            && table.re() == self.grid.reynolds.as_slice()
            && table.mach() == self.grid.mach.as_slice()
            && table.point_count() == self.grid.point_count()
            && table.require_lookup().is_ok();
        if !matches {
            self.note(&path, "holds another table than its name promises");
        }
        matches.then_some(table)
    }

    /// Points still to solve for `foil` with each of `transitions` (cache misses).
    pub fn missing_points(&self, foil: &Airfoil, transitions: &[Transition]) -> usize {
        transitions
            .iter()
            .filter(|t| self.cached(foil, t).is_none())
            .count()
            * self.grid.point_count()
    }

    /// The tables of `foil` with each of `transitions`, in order: read from the cache, or
    /// built (one after the other, each on all [`threads`](Self::threads)) and stored.
    /// `on_points` is called with the number of points of each solved polar.
    pub fn tables(
        &self,
        foil: &Airfoil,
        transitions: &[Transition],
        on_points: &(dyn Fn(usize) + Sync),
    ) -> Result<Vec<PolarTable>, StudiesError> {
        std::fs::create_dir_all(&self.dir)
            .map_err(|e| StudiesError::Output(crate::output::OutputError::io(&self.dir, e)))?;
        transitions
            .iter()
            .map(|t| match self.cached(foil, t) {
                Some(table) => Ok(table),
                None => self.build(foil, t, on_points),
            })
            .collect()
    }

    /// Build and store one table.
    fn build(
        &self,
        foil: &Airfoil,
        transition: &Transition,
        on_points: &(dyn Fn(usize) + Sync),
    ) -> Result<PolarTable, StudiesError> {
        let params = Self::params(transition);
        let table = build_table(
            foil,
            self.panels,
            &self.grid,
            &params,
            self.threads,
            on_points,
        )
        .map_err(|source| StudiesError::Build {
            name: format!("{} {}", foil.name, transition.label()),
            source,
        })?;
        table.require_lookup().map_err(StudiesError::Cache)?;
        let entry = self.entry(foil, transition);
        // An entry that is not a regular file (a FIFO, a link to a device) would be written
        // in place: the cache's own name is replaced by a regular file instead.
        if std::fs::symlink_metadata(&entry).is_ok_and(|m| !m.is_file()) {
            std::fs::remove_file(&entry)
                .map_err(|e| StudiesError::Output(crate::output::OutputError::io(&entry, e)))?;
        }
        write_table(&table, &entry, Some(TableFormat::Json)).map_err(StudiesError::Cache)?;
        Ok(table)
    }
}

/// The unique transition settings of `list`, in first-seen order.
pub(crate) fn unique(list: impl IntoIterator<Item = Transition>) -> Vec<Transition> {
    let mut out: Vec<Transition> = Vec::new();
    for t in list {
        if !out.contains(&t) {
            out.push(t);
        }
    }
    out
}

/// Whether `dir` is a folder path the cache may use (not an existing file).
pub fn check_cache_dir(dir: &Path) -> Result<(), StudiesError> {
    if dir.exists() && !dir.is_dir() {
        return Err(StudiesError::BadSetting(format!(
            "--cache {}: exists and is not a folder",
            dir.display()
        )));
    }
    Ok(())
}
