//! Building a table: the viscous polars of one airfoil on a Reynolds × Mach × α grid, solved
//! in parallel (one panel store for the whole grid, [`run_grid`]), collected into a
//! [`PolarTable`] with the settings that made it.

use super::{PolarTable, TableError, TableMeta};
use crate::arguments::{distinct, ArgumentError};
use crate::geometry::Airfoil;
use crate::limits::MAX_GRID_POINTS;
use crate::polar::{parse_alpha_range, run_grid, GridNode, GridPolar, SweepParams};
use crate::progress::Work;
use crate::section::FlowCondition;
use crate::viscous::{
    SharedPanels, ViscousError, ViscousParams, ViscousSolver, SETTLED_STATE_BYTES_PER_NODE,
};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// Reynolds numbers of the default rotor grid, about a factor 1.5–2 apart (lookups are linear
/// in ln Re): the blade sections of a light gyroplane rotor (chord 0.2 m) from the inboard
/// strips near the reverse-flow circle (Re ≈ 10⁵) to the advancing tip at 90 kt (≈ 2.8·10⁶),
/// and those of its propeller (chord ≈ 0.1 m: ≈ 2·10⁵ at the root to ≈ 1.5·10⁶).
pub const DEFAULT_RE: [f64; 8] = [1e5, 2e5, 4e5, 7e5, 1.0e6, 1.5e6, 2.0e6, 3.0e6];

/// Mach numbers of the default rotor grid: up to the advancing rotor tip at 90 kt (M ≈ 0.61)
/// and the propeller tip at full throttle (≈ 0.64), closer spaced above 0.5 where the
/// compressibility factor 1/√(1 − M²) curves (linear interpolation errs by at most 0.3 % in it
/// between 0.4 and 0.5, 0.15 % between 0.6 and 0.65).
pub const DEFAULT_MACH: [f64; 8] = [0.0, 0.2, 0.3, 0.4, 0.5, 0.55, 0.6, 0.65];

/// α range of the default rotor grid, `A0:A1:DA` in degrees ([`parse_alpha_range`]).
pub const DEFAULT_ALPHA: &str = "-10:20:0.5";

/// Measured cost of one table point on one core \[s\], for the estimate of a progress start
/// line: the shipped default-grid tables rebuilt with `--threads 1` on a loaded two-core
/// machine took 6.3 ms per point (NACA 8-H-12, free transition), 2.4–5.0 ms (8-H-12 tripped,
/// 23012, Clark Y, GOE 429) and 8–22 ms (the thick Clark Y sections of the propeller, t/c
/// 0.18–0.44, where up to a fifth of the points fail their march and its recovery). An estimate, not a
/// promise: the machine's load moves it by 2×, the airfoil by up to 3×.
pub const SECONDS_PER_POINT_CORE: f64 = 0.007;

/// Estimated time to solve `points` points in `polars` polars with `threads` workers (0 = all
/// cores) \[s\]: [`SECONDS_PER_POINT_CORE`] per point, the workers busy as far as the polars
/// allow (each polar's two α branches run in parallel).
pub fn estimated_build_seconds(points: usize, polars: usize, threads: usize) -> f64 {
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    let threads = if threads == 0 {
        cores
    } else {
        threads.min(cores)
    };
    let workers = threads.min(2 * polars).max(1);
    points as f64 * SECONDS_PER_POINT_CORE / workers as f64
}

/// The axes of a table to build.
#[derive(Clone, Debug, PartialEq)]
pub struct GridSpec {
    /// Chord Reynolds numbers.
    pub reynolds: Vec<f64>,
    /// Mach numbers.
    pub mach: Vec<f64>,
    /// Angles of attack \[deg\].
    pub alpha_deg: Vec<f64>,
}

impl Default for GridSpec {
    /// The default rotor grid: [`DEFAULT_RE`] × [`DEFAULT_MACH`] × [`DEFAULT_ALPHA`].
    fn default() -> Self {
        Self {
            reynolds: DEFAULT_RE.to_vec(),
            mach: DEFAULT_MACH.to_vec(),
            alpha_deg: parse_alpha_range(DEFAULT_ALPHA).unwrap_or_default(),
        }
    }
}

impl GridSpec {
    /// Every (Re, M) node, Re-major.
    pub fn conditions(&self) -> Vec<FlowCondition> {
        self.reynolds
            .iter()
            .flat_map(|&r| self.mach.iter().map(move |&m| FlowCondition::new(r, m)))
            .collect()
    }

    /// Number of points the grid asks for.
    pub fn point_count(&self) -> usize {
        self.reynolds.len() * self.mach.len() * self.alpha_deg.len()
    }

    /// Estimated time to solve `tables` tables on this grid with `threads` workers (0 = all
    /// cores) \[s\]: [`SECONDS_PER_POINT_CORE`] per point, the workers busy as far as the
    /// polars allow (each polar's two α branches run in parallel).
    pub fn estimated_seconds(&self, tables: usize, threads: usize) -> f64 {
        let polars = tables * self.reynolds.len() * self.mach.len();
        estimated_build_seconds(tables * self.point_count(), polars, threads)
    }

    /// The work of building `airfoil`'s table on this grid with `threads` workers, for a
    /// progress display.
    pub fn work(&self, airfoil: &str, threads: usize) -> Work {
        let polars = self.reynolds.len() * self.mach.len();
        Work {
            total: self.point_count(),
            unit: "points",
            what: format!(
                "{polars} polar{} of {airfoil}",
                if polars == 1 { "" } else { "s" }
            ),
            estimate_s: Some(self.estimated_seconds(1, threads)),
        }
    }

    /// Refuses a grid of more than [`MAX_GRID_POINTS`] points (a check before any solve).
    pub fn check_size(&self) -> Result<(), BuildError> {
        if self.point_count() <= MAX_GRID_POINTS {
            return Ok(());
        }
        Err(BuildError::TooLarge {
            re: self.reynolds.len(),
            mach: self.mach.len(),
            alpha: self.alpha_deg.len(),
            points: self.point_count(),
        })
    }

    /// The grid of the flags `--re`, `--mach` and `--alpha` (each value checked by its
    /// parser): the default grid when neither Re nor Mach is given, Re alone at M 0 (as
    /// XFOIL), Mach alone refused; no axis repeats a value, and the grid holds at most
    /// [`MAX_GRID_POINTS`] points.
    pub fn from_flags(
        re: Option<&[f64]>,
        mach: Option<&[f64]>,
        alpha_deg: Option<&[f64]>,
    ) -> Result<Self, ArgumentError> {
        let default = Self::default();
        let (reynolds, mach) = match (re, mach) {
            (Some(re), mach) => (re.to_vec(), mach.map_or(vec![0.0], <[f64]>::to_vec)),
            (None, None) => (default.reynolds, default.mach),
            (None, Some(_)) => Err(ArgumentError::with_text(
                "--mach",
                "",
                "give the Reynolds numbers with --re too",
            ))?,
        };
        distinct("--re", &reynolds)?;
        distinct("--mach", &mach)?;
        let grid = Self {
            reynolds,
            mach,
            alpha_deg: alpha_deg.map_or(default.alpha_deg, <[f64]>::to_vec),
        };
        grid.check_size()
            .map_err(|e| ArgumentError::with_text("--re, --mach, --alpha", "", e.to_string()))?;
        Ok(grid)
    }
}

/// Why a table could not be built.
#[derive(Debug, thiserror::Error)]
pub enum BuildError {
    /// The viscous solver could not be set up for the airfoil.
    #[error("viscous solver")]
    Solver(#[source] ViscousError),
    /// The solved polars do not form a table.
    #[error("building the table")]
    Table(#[source] TableError),
    /// More points than [`MAX_GRID_POINTS`] ([`GridSpec::check_size`]).
    #[error(
        "{re} Re x {mach} M x {alpha} alpha = {points} points: more than the limit of \
         {MAX_GRID_POINTS} points per run"
    )]
    TooLarge {
        /// Reynolds numbers.
        re: usize,
        /// Mach numbers.
        mach: usize,
        /// Angles of attack.
        alpha: usize,
        /// Their product.
        points: usize,
    },
    /// More points to solve than [`MAX_GRID_POINTS`] ([`super::PointPlan::check_size`]).
    #[error(
        "{points} points in {polars} polars: more than the limit of {MAX_GRID_POINTS} points \
         per run"
    )]
    TooManyPoints {
        /// Distinct conditions.
        polars: usize,
        /// Distinct points to solve.
        points: usize,
    },
    /// The caller cancelled the build ([`build_table_cancellable`]).
    #[error("cancelled")]
    Cancelled,
}

/// Solve the viscous polars of `foil` (already paneled with `panels` nodes) on `grid` with
/// the settings of `base` (its Re and M are replaced by each node's) on at most `threads`
/// worker threads (0 = all cores), calling `on_points` with the number of points of each
/// finished polar. Unconverged points are kept, flagged, in the table.
pub fn build_table(
    foil: &Airfoil,
    panels: usize,
    grid: &GridSpec,
    base: &ViscousParams,
    threads: usize,
    on_points: impl Fn(usize) + Sync,
) -> Result<PolarTable, BuildError> {
    let never = AtomicBool::new(false);
    build_table_cancellable(foil, panels, grid, base, threads, on_points, &never)
}

/// [`build_table`] that stops when `cancel` is set (by another thread, or by `on_points`):
/// polars already being solved finish, no further polar starts, and the result is
/// [`BuildError::Cancelled`]. For callers that must stay interruptible (the Python package).
pub fn build_table_cancellable(
    foil: &Airfoil,
    panels: usize,
    grid: &GridSpec,
    base: &ViscousParams,
    threads: usize,
    on_points: impl Fn(usize) + Sync,
    cancel: &AtomicBool,
) -> Result<PolarTable, BuildError> {
    let nodes: Vec<GridNode<'_>> = grid
        .conditions()
        .iter()
        .map(|c| GridNode {
            re: c.reynolds,
            mach: c.mach,
            alphas: &grid.alpha_deg,
            series: 0,
        })
        .collect();
    let params = |i: usize| ViscousParams {
        reynolds: nodes[i].re,
        mach: nodes[i].mach,
        ..*base
    };
    let polars = solve_nodes(foil, &nodes, params, threads, on_points, cancel)?;
    PolarTable::from_polars(
        table_meta(foil, panels, base),
        polars
            .into_iter()
            .map(|p| (FlowCondition::new(p.re, p.mach), p.points))
            .collect(),
    )
    .map_err(BuildError::Table)
}

/// Memory the converged states of a grid may take while its series' holes wait to be filled
/// ([`run_grid`], [`SETTLED_STATE_BYTES_PER_NODE`]): a grid whose states would take more is
/// solved without the filling. The default 3 904-point grid at 160 panels needs ≈ 70 MB; at
/// 1 000 panels grids up to ≈ 2 500 points are filled.
pub const SERIES_STATES_BYTES: usize = 256 << 20;

/// The polars of `nodes` on `foil`, node `i` solved with `params(i)` (one panel store for all:
/// the per-α inviscid model does not depend on Re, M or trips), on at most `threads` threads,
/// `on_points` called with each finished polar's point count (after its march; the filling
/// of the holes comes after all of them); no polar starts once `cancel` is set, and the result
/// is then [`BuildError::Cancelled`].
pub(crate) fn solve_nodes(
    foil: &Airfoil,
    nodes: &[GridNode<'_>],
    params: impl Fn(usize) -> ViscousParams + Sync,
    threads: usize,
    on_points: impl Fn(usize) + Sync,
    cancel: &AtomicBool,
) -> Result<Vec<GridPolar>, BuildError> {
    let store = Arc::new(SharedPanels::new(foil).map_err(BuildError::Solver)?);
    let points: usize = nodes.iter().map(|n| n.alphas.len()).sum();
    let state_bytes = store.node_count() * SETTLED_STATE_BYTES_PER_NODE;
    let sweep = SweepParams {
        series_retry: points.saturating_mul(state_bytes) <= SERIES_STATES_BYTES,
        ..SweepParams::default()
    };
    let polars = run_grid(
        nodes,
        threads,
        &sweep,
        |i| {
            if cancel.load(Ordering::Relaxed) {
                return Err(BuildError::Cancelled);
            }
            ViscousSolver::with_panels(Arc::clone(&store), params(i)).map_err(BuildError::Solver)
        },
        |p: &GridPolar| on_points(p.points.len()),
    )?;
    if cancel.load(Ordering::Relaxed) {
        return Err(BuildError::Cancelled);
    }
    Ok(polars)
}

/// The metadata of a table of `foil` (paneled with `panels` nodes) solved with `base`.
pub(crate) fn table_meta(foil: &Airfoil, panels: usize, base: &ViscousParams) -> TableMeta {
    TableMeta {
        airfoil: foil.name.clone(),
        transition: base.transition,
        // Unknown only for a contour the spline cannot take, which the solver refuses anyway.
        thickness: foil
            .max_thickness()
            .ok()
            .filter(|t| *t > 0.0 && *t < 1.0)
            .unwrap_or(f64::NAN),
        panels,
        solver: format!("polargen {}", env!("CARGO_PKG_VERSION")),
        geometry: Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::airfoil_by_name_or_path;

    /// A cancelled build stops after the polars already started; uncancelled it is the plain
    /// build.
    #[test]
    fn a_cancelled_build_stops() {
        let foil = airfoil_by_name_or_path("naca0012")
            .and_then(|f| f.solver_nodes(120))
            .unwrap()
            .0;
        let grid = GridSpec {
            reynolds: vec![1e6, 2e6, 3e6],
            mach: vec![0.0],
            alpha_deg: vec![0.0, 2.0],
        };
        let base = ViscousParams::default();
        let build = |cancel: &AtomicBool, stop_after: usize| {
            let done = std::sync::atomic::AtomicUsize::new(0);
            build_table_cancellable(
                &foil,
                120,
                &grid,
                &base,
                1,
                |_| {
                    if done.fetch_add(1, Ordering::Relaxed) + 1 >= stop_after {
                        cancel.store(true, Ordering::Relaxed);
                    }
                },
                cancel,
            )
            .map(|t| (t, done.into_inner()))
        };
        let plain = build_table(&foil, 120, &grid, &base, 1, |_| {}).unwrap();
        let (whole, polars) = build(&AtomicBool::new(false), usize::MAX).unwrap();
        assert_eq!((whole, polars), (plain, 3));
        let stopped = build(&AtomicBool::new(false), 1);
        assert!(matches!(stopped, Err(BuildError::Cancelled)), "{stopped:?}");
        let before = build(&AtomicBool::new(true), usize::MAX);
        assert!(matches!(before, Err(BuildError::Cancelled)), "{before:?}");
    }

    #[test]
    fn the_default_grid_is_the_rotor_grid() {
        let g = GridSpec::default();
        assert_eq!(g.alpha_deg.len(), 61);
        assert_eq!((g.alpha_deg[0], g.alpha_deg[60]), (-10.0, 20.0));
        assert_eq!(g.conditions().len(), 64);
        assert_eq!(g.conditions()[1], FlowCondition::new(1e5, 0.2));
        assert_eq!(g.point_count(), 64 * 61);
    }
}
