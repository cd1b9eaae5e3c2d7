//! Re × Mach × α polar tables: grid, interpolating lookup with a 360° extension, file formats.
//!
//! The facade: [`PolarTable`] and its [`TableMeta`]; [`build_table`] (and
//! [`build_table_cancellable`]) on a [`GridSpec`]; [`Batch`] runs of many airfoils; [`PolarTable::lookup_many`] for columns of
//! lookups;
//! [`read_table`] / [`read_lookup_table`] / [`parse_table`] and [`write_table`] /
//! [`write_c81`] in the [`TableFormat`]s; [`sample_polar`] and [`alpha_at_cl`] at one (Re, M);
//! [`PostStallParams`]; [`TableError`] and [`BuildError`]. Inside (private):
//!
//! * `batch` — [`Batch`]: one table per airfoil of a list of files, folders and names, with
//!   an index; shards and resumed runs.
//! * `build` — solving a table: the viscous polars of one airfoil on a Re × M × α grid.
//! * `points` — [`solve_points`]: scattered (α, Re, M, trip) points, one warm-started polar per
//!   distinct condition, in the order asked.
//! * `census` — [`TableCensus`]: points, converged, supercritical.
//! * `flap_sweep` — [`FlapSweep`]: one table, or one per flap deflection, and their outputs.
//! * `job` — [`TableJob`]: the tables of a flap sweep solved and written (`polargen`'s job).
//! * `grid` — [`PolarTable`]: one polar per (Re, M) node, metadata, validation, accessors.
//! * `lookup` — the α curve of one polar (monotone cubic, gaps bridged) and the
//!   [`SectionAero`](crate::section::SectionAero) implementation (linear in ln Re and in M
//!   between polars).
//! * `fixed_condition` — queries at one (Re, M) between nodes: the polar sampled by lookups,
//!   α and Cd where Cl reaches a target (paper Table 5).
//! * `post_stall` — the 360° extension beyond the computed α range (Viterna–Corrigan and a
//!   flat plate).
//! * `lift_slope` — the points the method trusts, the attached range and lift slope of a
//!   polar (one fit for the summary and the unsteady-aerodynamics block).
//! * `summary` — [`PolarSummary`]: α0, lift slope, Cl_max, Cd_min, best L/D, Cm0 per polar.
//! * `unsteady_aero` — [`UaParameters`]: the Beddoes–Leishman parameters AeroDyn reads.
//! * `io` — CSV, JSON, XFOIL polar, C81 and single-polar CSV files; one reader that
//!   recognises the layout, writers through [`output`](crate::output).
//! * `error` — [`TableError`].
//!
//! ```
//! use polargen::section::{FlowCondition, PolarPoint, SectionAero, Transition};
//! use polargen::table::{PolarTable, TableMeta};
//!
//! let meta = TableMeta {
//!     airfoil: "flat".into(),
//!     transition: Transition::default(),
//!     thickness: 0.12,
//!     panels: 160,
//!     solver: "example".into(),
//!     geometry: Vec::new(),
//! };
//! let polar = |re: f64| -> Vec<PolarPoint> {
//!     (-5..=10)
//!         .map(|a| PolarPoint {
//!             alpha: a as f64,
//!             cl: 0.1 * a as f64 + 0.01 * (re / 1e6),
//!             cd: 0.01,
//!             cdp: 0.004,
//!             cdf: 0.006,
//!             cm: -0.02,
//!             xtr_top: 0.5,
//!             xtr_bot: 0.8,
//!             converged: true,
//!             iterations: 5,
//!             residual: 1e-10,
//!             cpmin: -0.9,
//!             supercritical: Some(false),
//!             xsep_top: 1.0,
//!             xsep_bot: 1.0,
//!             massive_separation: Some(false),
//!         })
//!         .collect()
//! };
//! let table = PolarTable::from_polars(
//!     meta,
//!     vec![
//!         (FlowCondition::new(1e6, 0.0), polar(1e6)),
//!         (FlowCondition::new(4e6, 0.0), polar(4e6)),
//!     ],
//! )
//! .unwrap();
//! let l = table.lookup(2.5, 2e6, 0.0); // halfway in ln Re: 0.25 + 0.025
//! assert!((l.cl - 0.275).abs() < 1e-12 && !l.re_clamped);
//! let rev = table.lookup(170.0, 2e6, 0.3); // reverse flow, Mach clamped to 0
//! assert!(rev.post_stall && rev.mach_clamped && rev.cl < 0.0);
//! ```

mod batch;
mod build;
mod census;
mod error;
mod fixed_condition;
mod flap_sweep;
mod grid;
mod io;
mod job;
mod lift_slope;
mod lookup;
mod meta;
mod points;
mod post_stall;
mod summary;
mod unsteady_aero;
mod validation;

pub use crate::limits::MAX_RE;
pub use batch::{
    Batch, BatchError, BatchSettings, BatchSummary, IndexRow, Shard, TableStatus, AIRFOIL_EXTENSION,
};
pub use build::{
    build_table, build_table_cancellable, estimated_build_seconds, BuildError, GridSpec,
    DEFAULT_ALPHA, DEFAULT_MACH, DEFAULT_RE, SECONDS_PER_POINT_CORE, SERIES_STATES_BYTES,
};
pub use census::TableCensus;
pub use error::TableError;
pub use fixed_condition::{alpha_at_cl, sample_polar, LiftMatch};
pub use flap_sweep::{FlapMember, FlapSweep};
pub use grid::PolarTable;
pub use io::{
    check_flap_sweep_output, check_lookup_table, check_table_output, flap_sweep_files, parse_c81,
    parse_table, read_lookup_table, read_lookup_table_with, read_table, read_table_with,
    table_files, with_cd_max, write_aerodyn, write_aerodyn_flap_sweep, write_c81, write_table,
    write_table_into, C81Options, ReadOptions, TableFormat, TableRead, LOOKUP_ALPHA_COVER_DEG,
};
pub use job::{TableJob, TableJobError};
pub use lift_slope::{trusted, STALL_SLOPE_FRACTION};
pub use meta::TableMeta;
pub use points::{solve_points, PointPlan, PointQuery};
pub use post_stall::PostStallParams;
pub use summary::{
    summarize, summary_csv, summary_json, summary_text, PolarSummary, SummaryRow, SUMMARY_COLUMNS,
};
pub use unsteady_aero::{ua_parameters, UaParameters};
pub use validation::COEFFICIENT_BOUNDS;
