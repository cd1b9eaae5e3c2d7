//! polargen — airfoil polar tables from an XFOIL-class viscous–inviscid solver, and a
//! gyroplane rotor strip model that consumes them.
//!
//! # Layers
//!
//! Data flows one way through the module tree; a lower layer never imports a higher one:
//!
//! ```text
//! geometry → inviscid → boundary_layer → viscous → polar → table → rotor → studies → report
//!                                                              ↘ plot ↗
//! leaf modules every layer may use: section, compressibility, input, output, limits,
//! diagnostics, arguments, cli
//! ```
//!
//! * [`geometry`] — airfoil shapes (NACA 4/5-digit, coordinate files, named registry), splines,
//!   curvature-based paneling.
//! * [`inviscid`] — linear-vorticity stream-function panel method (Drela 1989), unit solutions,
//!   source influence for the viscous coupling.
//! * [`boundary_layer`] — integral boundary-layer closures, amplification (e^n) and the
//!   discrete equations for one interval (Drela & Giles 1987).
//! * [`viscous`] — wake, viscous–inviscid coupling and the global Newton solve; the surface
//!   distributions of a solution.
//! * [`polar`] — α sweeps with warm starts and recovery of failed points.
//! * [`table`] — Re × Mach × α tables: building ([`table::build_table`]), lookups with a 360°
//!   extension, one reader that recognises every readable layout ([`table::read_table`]), and
//!   the writers.
//! * [`rotor`] — blade-element model of a gyroplane rotor (teetering, or N blades on flapping
//!   hinges) and a blade-element–momentum propeller with its engine: trim, takeoff, cruise
//!   sweeps, the isolated rotor in a wind tunnel.
//! * [`studies`] — studies on top of the rotor: [`studies::paper`], the paper's
//!   clean-versus-contaminated study and its sensitivity to the preset's estimates,
//!   [`studies::pca2`], the rotor model against the PCA-2 autogiro's tunnel and flight tests,
//!   and the what-if studies (contamination severity and spanwise coverage, airfoil choice, airspeed,
//!   a fixed wing), their section tables solved and cached.
//! * [`plot`] — SVG/PNG figures of polars, point distributions and rotor results.
//! * [`report`] — the paper report: Tables 3–5 beside the paper's values, figures, words.
//!
//! Leaf modules:
//!
//! * [`section`] — the shared vocabulary of section data: polar points, flow conditions and
//!   the lookup interface the rotor consumes.
//! * [`compressibility`] — γ and the Karman–Tsien relations (Cp, speed, critical Cp).
//! * [`output`] — every result file goes through it: path checks, atomic writes, `-` for
//!   standard output, streams written in place; [`output::OutputError`].
//! * [`input`] — every input file goes through it: regular files (or standard input where
//!   allowed) up to a size cap; devices, FIFOs and folders refused at once.
//! * [`limits`] — every bound on input sizes and on the work a request may ask for, in one
//!   place.
//! * [`diagnostics`] — an error and its causes on one line, for the command-line tools.
//! * [`arguments`] — checks of user-given values (flags, Python arguments) with one-line
//!   errors naming the argument.
//! * [`cli`] — the conventions both command-line tools share: the error line and exit codes,
//!   `--quiet`, completions, man pages and the generated command-line reference.
//!
//! # Public API
//!
//! Each layer exports a narrow facade from its root and keeps its files `pub(crate)` or
//! private. The main entry points:
//!
//! | task | API |
//! |---|---|
//! | load and panel an airfoil | [`geometry::airfoil_by_name_or_path`], [`geometry::Airfoil`] |
//! | solve one viscous point or a sweep | [`viscous::ViscousSolver`] (a [`polar::WarmStartSolver`] for [`polar::sweep`]) |
//! | build, read, write a table | [`table::build_table`], [`table::read_table`], [`table::write_table`] |
//! | one table per airfoil of many, sharded | [`table::Batch`] |
//! | look up section coefficients | [`section::SectionAero`] on [`table::PolarTable`] |
//! | trim, takeoff, sweeps | [`rotor::trim_aircraft`], [`rotor::simulate_takeoff`], [`studies::paper`] |
//! | a rotor in a wind tunnel | [`rotor::autorotate`], [`rotor::RotorPreset`] |
//! | propeller and engine | [`rotor::Powerplant`], [`rotor::Propeller`] |
//! | figures | [`plot::render`] with [`plot::polar_plots`], [`plot::point_plots`], [`plot::rotor_plots`] |
//! | the paper report | [`report::write_report`] |
//! | write any result file | [`output::write_output`] |
//! | check user-given values | [`arguments`], [`polar::check_alphas`], [`rotor::check_speed_kt`] |
//!
//! The Python package (`python/`, a workspace member built with PyO3 and maturin) is a thin
//! layer over this API: it calls the functions above and adds no computation of its own.

#![warn(missing_docs)]

pub mod arguments;
pub mod boundary_layer;
pub mod cli;
pub mod compressibility;
pub mod diagnostics;
pub mod geometry;
pub mod input;
pub mod inviscid;
pub mod limits;
mod numerics;
pub mod output;
pub mod plot;
pub mod polar;
pub mod report;
pub mod rotor;
pub mod section;
pub mod studies;
pub mod table;
pub mod viscous;
