//! `aero`: the section coefficients at scattered operating points (any α, Re, M and trips per
//! point), solved by the library's [`solve_points`]: one warm-started polar per distinct
//! condition, in parallel, with the GIL released; the points come back in the order asked.

use polargen::arguments;
use polargen::polar::check_alphas;
use polargen::table::{solve_points, PointPlan, PointQuery};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::airfoil::Airfoil;
use crate::errors::raise;
use crate::solve::{polar_columns, run_detached, NcritArgs, Settings};

/// The points (α, Re, M, xtr_top, xtr_bot), five equally long lists, solved as
/// `polargen --alpha …` solves the polar of each distinct condition over its distinct α values:
/// a dict of columns (those of a polar), one value per point in the order given.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (airfoil, alpha, re, mach, xtr_top, xtr_bot, ncrit, panels, tolerance, threads, progress))]
pub fn aero<'py>(
    py: Python<'py>,
    airfoil: &Airfoil,
    alpha: Vec<f64>,
    re: Vec<f64>,
    mach: Vec<f64>,
    xtr_top: Vec<f64>,
    xtr_bot: Vec<f64>,
    ncrit: NcritArgs,
    panels: usize,
    tolerance: f64,
    threads: usize,
    progress: Option<Py<PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let n = alpha.len();
    if [re.len(), mach.len(), xtr_top.len(), xtr_bot.len()] != [n; 4] {
        return Err(pyo3::exceptions::PyValueError::new_err(format!(
            "alpha, re, mach, xtr_top and xtr_bot must have one length (got {n}, {}, {}, {}, {})",
            re.len(),
            mach.len(),
            xtr_top.len(),
            xtr_bot.len()
        )));
    }
    let queries: Vec<PointQuery> = (0..n)
        .map(|i| PointQuery {
            alpha_deg: alpha[i],
            reynolds: re[i],
            mach: mach[i],
            xtr_top: xtr_top[i],
            xtr_bot: xtr_bot[i],
        })
        .collect();
    let plan = PointPlan::new(&queries);
    // Each distinct value checked as the CLI checks its flag, before any solve.
    let input = |r: Result<(), arguments::ArgumentError>| r.map_err(|e| raise(None, e));
    for (q, alphas) in plan.polars() {
        input(arguments::solver_reynolds("re", q.reynolds))?;
        input(arguments::mach("mach", q.mach))?;
        // The transition rule of the CLI, on this polar's trips.
        Settings::checked(q.xtr_top, q.xtr_bot, ncrit, tolerance)?;
        input(check_alphas("alpha", alphas))?;
    }
    plan.check_size().map_err(|e| raise(None, e))?;
    let settings = Settings::checked(1.0, 1.0, ncrit, tolerance)?;
    let nodes = airfoil.solver_nodes(py, panels)?;
    let base = settings.params(1.0, 0.0);
    let points = run_detached(py, plan.point_count(), progress, |on_points, cancel| {
        solve_points(&nodes, &plan, &base, threads, on_points, cancel)
    })?;
    polar_columns(py, &points)
}
