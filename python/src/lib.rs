//! `polargen._polargen`: the compiled core of the Python package `polargen`, a thin layer over
//! the Rust library. Nothing is computed here that the library does not compute for the
//! command-line tools: this crate checks arguments with the library's checks, converts between
//! NumPy arrays and the library's types, releases the GIL while the library works, and turns
//! the library's errors into Python exceptions with the CLI's messages. The Python modules in
//! `python/polargen/` give the results their classes (columns, `to_pandas`).

mod aero;
mod airfoil;
mod errors;
mod plot;
mod rotor;
mod rotor_runs;
mod solve;
mod table;

use pyo3::prelude::*;

/// The compiled core of `polargen` (see the package `polargen` for the documented API).
#[pymodule]
mod _polargen {
    use pyo3::prelude::*;

    #[pymodule_export]
    use crate::aero::aero;
    #[pymodule_export]
    use crate::airfoil::Airfoil;
    #[pymodule_export]
    use crate::errors::NotConvergedError;
    #[pymodule_export]
    use crate::plot::polar_figure;
    #[pymodule_export]
    use crate::rotor::{PyAircraft, PyRotor};
    #[pymodule_export]
    use crate::rotor_runs::{rotor_compare, rotor_study, rotor_sweep};
    #[pymodule_export]
    use crate::solve::{alpha_range, estimate_seconds, point, table};
    #[pymodule_export]
    use crate::table::Table;

    #[pymodule_init]
    fn init(m: &Bound<'_, PyModule>) -> PyResult<()> {
        use polargen::table::{DEFAULT_ALPHA, DEFAULT_MACH, DEFAULT_RE};
        m.add("DEFAULT_RE", DEFAULT_RE.to_vec())?;
        m.add("DEFAULT_MACH", DEFAULT_MACH.to_vec())?;
        m.add("DEFAULT_ALPHA", DEFAULT_ALPHA)?;
        m.add(
            "DEFAULT_TOLERANCE",
            polargen::viscous::ViscousParams::default().tolerance,
        )?;
        m.add("DEFAULT_PANELS", polargen::geometry::DEFAULT_PANEL_NODES)?;
        m.add("VERSION", env!("CARGO_PKG_VERSION"))?;
        Ok(())
    }
}
