//! The computations: one polar, one operating point with its distributions, a Re × M × α
//! table. Every argument is checked before the first solve (the CLI's checks, naming the
//! argument as Python calls it), and the solver runs with the GIL released.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::Duration;

use numpy::{IntoPyArray, PyArray1};
use polargen::arguments::{self, TransitionArgs};
use polargen::polar::{
    check_alphas, parse_alpha_range, solve_operating_point, OperatingPoint, TargetClParams,
};
use polargen::section::{PolarPoint, Transition};
use polargen::table::{
    build_table_cancellable, summarize, BuildError, GridSpec, PolarSummary, PolarTable,
};
use polargen::viscous::distributions::pressure_coefficient;
use polargen::viscous::{BlStation, ViscousParams, ViscousSolver};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::airfoil::Airfoil;
use crate::errors::{raise, shielded};
use crate::table::Table;

/// The solver settings shared by `polar`, `point`, `table` and `aero`, checked.
pub struct Settings {
    transition: Transition,
    tolerance: f64,
}

/// The arguments `ncrit`, `ncrit_top`, `ncrit_bot` (a side not given takes `ncrit`).
pub type NcritArgs = (f64, Option<f64>, Option<f64>);

impl Settings {
    /// Checks each setting as the CLI checks its flag.
    pub fn checked(xtr_top: f64, xtr_bot: f64, ncrit: NcritArgs, tolerance: f64) -> PyResult<Self> {
        // One value for both surfaces (bit for bit: NaN too) is the argument `xtr` (the CLI's
        // `--xtr`).
        let names = if xtr_top.to_bits() == xtr_bot.to_bits() {
            ["xtr", "xtr"]
        } else {
            ["xtr_top", "xtr_bot"]
        };
        let transition = arguments::transition(&TransitionArgs {
            ncrit: ("ncrit", ncrit.0),
            ncrit_top: ("ncrit_top", ncrit.1),
            ncrit_bot: ("ncrit_bot", ncrit.2),
            xtr_top: (names[0], xtr_top),
            xtr_bot: (names[1], xtr_bot),
        })
        .map_err(|e| raise(None, e))?;
        arguments::tolerance("tolerance", tolerance).map_err(|e| raise(None, e))?;
        Ok(Self {
            transition,
            tolerance,
        })
    }

    /// The solver parameters at (Re, M) with these settings (the CLI's `ViscousParams`).
    pub fn params(&self, reynolds: f64, mach: f64) -> ViscousParams {
        ViscousParams {
            reynolds,
            mach,
            transition: self.transition,
            tolerance: self.tolerance,
            ..ViscousParams::default()
        }
    }
}

/// The points of a polar as columns: a dict of NumPy arrays, every per-point column of the
/// CSV table (`alpha`, `cl`, `cd`, `cdp`, `cdf`, `cm`, `xtr_top`, `xtr_bot`, `converged`,
/// `iterations`, `residual`, `cpmin`, `supercritical`, `xsep_top`, `xsep_bot`,
/// `massive_separation`); the two flags as int8 (1 yes, 0 no, −1 unknown, an empty CSV field).
pub fn polar_columns<'py>(py: Python<'py>, points: &[PolarPoint]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let column = |f: fn(&PolarPoint) -> f64| -> Bound<'py, PyArray1<f64>> {
        points.iter().map(f).collect::<Vec<f64>>().into_pyarray(py)
    };
    d.set_item("alpha", column(|p| p.alpha))?;
    d.set_item("cl", column(|p| p.cl))?;
    d.set_item("cd", column(|p| p.cd))?;
    d.set_item("cdp", column(|p| p.cdp))?;
    d.set_item("cdf", column(|p| p.cdf))?;
    d.set_item("cm", column(|p| p.cm))?;
    d.set_item("xtr_top", column(|p| p.xtr_top))?;
    d.set_item("xtr_bot", column(|p| p.xtr_bot))?;
    let converged: Vec<bool> = points.iter().map(|p| p.converged).collect();
    d.set_item("converged", converged.into_pyarray(py))?;
    let iterations: Vec<i64> = points.iter().map(|p| i64::from(p.iterations)).collect();
    d.set_item("iterations", iterations.into_pyarray(py))?;
    d.set_item("residual", column(|p| p.residual))?;
    d.set_item("cpmin", column(|p| p.cpmin))?;
    let flag = |f: fn(&PolarPoint) -> Option<bool>| -> Bound<'py, PyArray1<i8>> {
        points
            .iter()
            .map(|p| f(p).map_or(-1, i8::from))
            .collect::<Vec<i8>>()
            .into_pyarray(py)
    };
    d.set_item("supercritical", flag(|p| p.supercritical))?;
    d.set_item("xsep_top", column(|p| p.xsep_top))?;
    d.set_item("xsep_bot", column(|p| p.xsep_bot))?;
    d.set_item("massive_separation", flag(|p| p.massive_separation))?;
    Ok(d)
}

/// [`polar_columns`] of the points of one polar, with its summary (`polargen summary`) under
/// `summary`.
pub fn polar_columns_with_summary<'py>(
    py: Python<'py>,
    points: &[PolarPoint],
) -> PyResult<Bound<'py, PyDict>> {
    let d = polar_columns(py, points)?;
    d.set_item("summary", summary_dict(py, &summarize(points))?)?;
    Ok(d)
}

/// A polar's summary (`polargen summary`) as a dict: its JSON fields, absent values None.
pub fn summary_dict<'py>(py: Python<'py>, s: &PolarSummary) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let value = serde_json::to_value(s)
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    if let serde_json::Value::Object(fields) = value {
        for (name, v) in fields {
            match v {
                serde_json::Value::Bool(b) => d.set_item(name, b)?,
                serde_json::Value::Number(n) if n.is_u64() => d.set_item(name, n.as_u64())?,
                serde_json::Value::Number(n) => d.set_item(name, n.as_f64())?,
                _ => d.set_item(name, py.None())?,
            }
        }
    }
    Ok(d)
}

/// The stations of one surface or the wake as columns (those of the CLI's distributions CSV):
/// `s, x, y, ue, cp, dstar, theta, cf, h, hk, n_or_ctau, turbulent`, `cf` based on the
/// free-stream dynamic pressure.
fn station_columns<'py>(
    py: Python<'py>,
    stations: &[BlStation],
    mach: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let column = |f: &dyn Fn(&BlStation) -> f64| -> Bound<'py, PyArray1<f64>> {
        stations
            .iter()
            .map(f)
            .collect::<Vec<f64>>()
            .into_pyarray(py)
    };
    d.set_item("s", column(&|s| s.s))?;
    d.set_item("x", column(&|s| s.x))?;
    d.set_item("y", column(&|s| s.y))?;
    d.set_item("ue", column(&|s| s.ue))?;
    d.set_item("cp", column(&|s| pressure_coefficient(s.ue, mach)))?;
    d.set_item("dstar", column(&|s| s.dstar))?;
    d.set_item("theta", column(&|s| s.theta))?;
    d.set_item("cf", column(&|s| s.cf_inf))?;
    d.set_item("h", column(&|s| s.h))?;
    d.set_item("hk", column(&|s| s.hk))?;
    d.set_item("n_or_ctau", column(&|s| s.n_or_ctau))?;
    let turbulent: Vec<bool> = stations.iter().map(|s| s.turbulent).collect();
    d.set_item("turbulent", turbulent.into_pyarray(py))?;
    Ok(d)
}

/// The α values of the range text `A0:A1:DA` (or one value), as the CLI's `--alpha` reads it.
#[pyfunction]
pub fn alpha_range<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let alphas = parse_alpha_range(text).map_err(|e| raise(Some("alpha"), e))?;
    Ok(alphas.into_pyarray(py))
}

/// A checked axis of Reynolds or Mach numbers.
fn checked_axis(
    name: &str,
    values: Vec<f64>,
    each: fn(&str, f64) -> Result<(), arguments::ArgumentError>,
) -> PyResult<Vec<f64>> {
    arguments::distinct(name, &values).map_err(|e| raise(None, e))?;
    for &v in &values {
        each(name, v).map_err(|e| raise(None, e))?;
    }
    Ok(values)
}

/// Solves the grid (checked) on the nodes of `airfoil` with the GIL released
/// ([`run_detached`]).
#[allow(clippy::too_many_arguments)]
fn build(
    py: Python<'_>,
    airfoil: &Airfoil,
    grid: GridSpec,
    settings: &Settings,
    panels: usize,
    threads: usize,
    progress: Option<Py<PyAny>>,
) -> PyResult<PolarTable> {
    check_alphas("alpha", &grid.alpha_deg).map_err(|e| raise(None, e))?;
    let nodes = airfoil.solver_nodes(py, panels)?;
    let base = settings.params(1.0, 0.0);
    let total = grid.point_count();
    // The work before any of it is done (a default progress prints its start line).
    if let Some(callback) = &progress {
        callback.call1(py, (0, total))?;
    }
    run_detached(py, total, progress, |on_points, cancel| {
        build_table_cancellable(&nodes, panels, &grid, &base, threads, on_points, cancel)
    })
}

/// Runs `work` with the GIL released: on a worker thread while this thread forwards its
/// progress (`work` reports finished points to the function it is given) to
/// `progress(done, total)` and checks for signals (Ctrl-C) every 0.1 s; an exception from
/// either sets the cancel flag `work` is given and is raised once the polars under way have
/// finished.
pub fn run_detached<T: Send>(
    py: Python<'_>,
    total: usize,
    progress: Option<Py<PyAny>>,
    work: impl FnOnce(&(dyn Fn(usize) + Sync), &AtomicBool) -> Result<T, BuildError> + Send,
) -> PyResult<T> {
    let cancel = AtomicBool::new(false);
    let (result, interrupted) = py.detach(|| {
        let (sender, receiver) = mpsc::channel::<usize>();
        std::thread::scope(|scope| {
            let cancel = &cancel;
            let worker = scope.spawn(move || {
                // The receiver is gone only once the work is over.
                let on_points = move |n: usize| {
                    let _ = sender.send(n);
                };
                shielded(|| work(&on_points, cancel))
            });
            let (mut done, mut reported) = (0, 0);
            let mut interrupted: Option<PyErr> = None;
            loop {
                let finished = match receiver.recv_timeout(Duration::from_millis(100)) {
                    Ok(n) => {
                        done += n;
                        false
                    }
                    Err(mpsc::RecvTimeoutError::Timeout) => false,
                    Err(mpsc::RecvTimeoutError::Disconnected) => true,
                };
                if interrupted.is_none() {
                    let outcome = Python::attach(|py| -> PyResult<()> {
                        py.check_signals()?;
                        match &progress {
                            Some(callback) if done != reported => {
                                reported = done;
                                callback.call1(py, (done, total)).map(drop)
                            }
                            _ => Ok(()),
                        }
                    });
                    if let Err(e) = outcome {
                        cancel.store(true, Ordering::Relaxed);
                        interrupted = Some(e);
                    }
                }
                if finished {
                    break;
                }
            }
            let result = worker.join().unwrap_or_else(|_| {
                Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "polargen internal error (please report): the worker thread failed",
                ))
            });
            (result, interrupted)
        })
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    match result? {
        Ok(value) => Ok(value),
        Err(BuildError::Cancelled) => Err(pyo3::exceptions::PyKeyboardInterrupt::new_err(
            "computation cancelled",
        )),
        Err(e) => Err(raise(None, e)),
    }
}

/// Estimated time to solve `points` points in `polars` polars on `threads` workers (0 = all
/// cores), in seconds (the estimate of the command-line tools' start line).
#[pyfunction]
pub fn estimate_seconds(points: usize, polars: usize, threads: usize) -> f64 {
    polargen::table::estimated_build_seconds(points, polars, threads)
}

/// A Re × M × α table, computed as the CLI computes it (one polar: one Re and one Mach
/// number); `progress(done, total)` is called (on this thread) as polars finish.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (airfoil, re, mach, alpha, xtr_top, xtr_bot, ncrit, panels, tolerance, threads, progress))]
pub fn table(
    py: Python<'_>,
    airfoil: &Airfoil,
    re: Vec<f64>,
    mach: Vec<f64>,
    alpha: Vec<f64>,
    xtr_top: f64,
    xtr_bot: f64,
    ncrit: NcritArgs,
    panels: usize,
    tolerance: f64,
    threads: usize,
    progress: Option<Py<PyAny>>,
) -> PyResult<Table> {
    let grid = GridSpec {
        reynolds: checked_axis("re", re, arguments::solver_reynolds)?,
        mach: checked_axis("mach", mach, arguments::mach)?,
        alpha_deg: alpha,
    };
    let settings = Settings::checked(xtr_top, xtr_bot, ncrit, tolerance)?;
    let table = build(py, airfoil, grid, &settings, panels, threads, progress)?;
    Ok(Table::from(table.with_geometry(&airfoil.ops)))
}

/// One operating point at `alpha` or at lift coefficient `cl` (as `polargen plot-point`
/// solves it): a dict with `point` (the coefficients) and `upper`, `lower`, `wake` (station
/// columns). A point that does not converge raises `NotConvergedError`.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (airfoil, re, mach, alpha, cl, xtr_top, xtr_bot, ncrit, panels, tolerance))]
pub fn point<'py>(
    py: Python<'py>,
    airfoil: &Airfoil,
    re: f64,
    mach: f64,
    alpha: Option<f64>,
    cl: Option<f64>,
    xtr_top: f64,
    xtr_bot: f64,
    ncrit: NcritArgs,
    panels: usize,
    tolerance: f64,
) -> PyResult<Bound<'py, PyDict>> {
    arguments::solver_reynolds("re", re).map_err(|e| raise(None, e))?;
    arguments::mach("mach", mach).map_err(|e| raise(None, e))?;
    // A finite α beyond ±180° (a non-finite one is named further on).
    if let Some(a) = alpha.filter(|a| a.is_finite()) {
        polargen::polar::check_alphas("alpha", &[a]).map_err(|e| raise(None, e))?;
    }
    let settings = Settings::checked(xtr_top, xtr_bot, ncrit, tolerance)?;
    let at = match (alpha, cl) {
        (Some(a), None) => OperatingPoint::Alpha(a),
        (None, Some(c)) => OperatingPoint::Cl(c),
        _ => {
            return Err(pyo3::exceptions::PyValueError::new_err(
                "give alpha or cl (one of them)",
            ))
        }
    };
    let nodes = airfoil.solver_nodes(py, panels)?;
    let params = settings.params(re, mach);
    let solution = py.detach(|| {
        shielded(|| {
            ViscousSolver::new(&nodes, params)
                .map_err(|e| raise(Some("viscous solver"), e))
                .and_then(|mut solver| {
                    solve_operating_point(&mut solver, at, &TargetClParams::default())
                        .map_err(|e| raise(None, e))
                })
        })
    })??;
    let d = PyDict::new(py);
    let columns = polar_columns(py, std::slice::from_ref(&solution.point))?;
    d.set_item("point", columns)?;
    d.set_item("upper", station_columns(py, &solution.upper, mach)?)?;
    d.set_item("lower", station_columns(py, &solution.lower, mach)?)?;
    d.set_item("wake", station_columns(py, &solution.wake, mach)?)?;
    Ok(d)
}
