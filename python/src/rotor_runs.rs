//! The rotor runs beyond one trim, as `gyro` runs them: a trim over a list of airspeeds
//! (`gyro sweep`), the clean-versus-contaminated comparison with the paper (`gyro compare`)
//! and the studies (`gyro study …`), each returning the JSON its `--json` prints.

use std::path::PathBuf;

use polargen::progress::Silent;
use polargen::report::console::compare_rows;
use polargen::report::ShippedInputs;
use polargen::rotor::check_sweep_speeds;
use polargen::studies::contamination::ContaminationOptions;
use polargen::studies::paper::{paper_runs, paper_runs_notes, SpeedSweep};
use polargen::studies::wing::WingOptions;
use polargen::studies::{StudyKind, StudyRequest};
use pyo3::prelude::*;

use crate::errors::{raise, shielded};
use crate::rotor::{json, section, PyAircraft};
use crate::table::Table;

/// Trims at each airspeed of `speeds_kt` (checked) as `gyro sweep` does: (JSON of the trims
/// that converged, in increasing speed; notes, one per skipped speed and on clamped lookups).
#[pyfunction]
#[pyo3(signature = (aircraft, table, speeds_kt, mass_kg))]
pub fn rotor_sweep(
    py: Python<'_>,
    aircraft: &PyAircraft,
    table: &Table,
    speeds_kt: Vec<f64>,
    mass_kg: Option<f64>,
) -> PyResult<(String, Vec<String>)> {
    let ac = aircraft.with_mass(mass_kg)?;
    check_sweep_speeds("speeds_kt", &speeds_kt, ac.rotor.cells()).map_err(|e| raise(None, e))?;
    let section = section(table)?;
    let sweep = py.detach(|| shielded(|| SpeedSweep::run(&ac, section, &speeds_kt, None)))?;
    Ok((json(&sweep.trims)?, sweep.notes()))
}

/// Clean versus contaminated as `gyro compare --json` prints it: JSON
/// `{"trim": [rows], "takeoff": [rows]}`, each row the paper's and our value of a quantity;
/// and the notes `gyro compare` prints (the trims' and takeoffs' lookup shares).
#[pyfunction]
pub fn rotor_compare(
    py: Python<'_>,
    aircraft: &PyAircraft,
    clean: &Table,
    contaminated: &Table,
) -> PyResult<(String, Vec<String>)> {
    let (c, d) = (section(clean)?, section(contaminated)?);
    let ac = &aircraft.inner;
    let runs = py.detach(|| shielded(|| paper_runs(ac, c, d)))?;
    let runs = runs.map_err(|e| raise(None, e))?;
    Ok((json(&compare_rows(&runs))?, paper_runs_notes(&runs)))
}

/// A study as `gyro study KIND --json` runs it: (JSON records, notes, files written). The
/// settings not given (None) are the command line's defaults.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (kind, aircraft, airfoil, airfoils, trips, ncrits, outboard, inboard, xtr, speeds_kt, areas_m2, out, cache))]
pub fn rotor_study(
    py: Python<'_>,
    kind: &str,
    aircraft: PathBuf,
    airfoil: Option<String>,
    airfoils: Option<Vec<String>>,
    trips: Option<Vec<f64>>,
    ncrits: Option<Vec<f64>>,
    outboard: Option<Vec<f64>>,
    inboard: Option<Vec<f64>>,
    xtr: Option<f64>,
    speeds_kt: Option<Vec<f64>>,
    areas_m2: Option<Vec<f64>>,
    out: Option<PathBuf>,
    cache: Option<PathBuf>,
) -> PyResult<(String, Vec<String>, Vec<PathBuf>)> {
    let airfoil = || airfoil.clone().unwrap_or_else(|| "naca8h12".to_string());
    let kind = match kind {
        "contamination" => {
            let d = ContaminationOptions::default();
            StudyKind::Contamination {
                airfoil: airfoil(),
                options: ContaminationOptions {
                    trips: trips.unwrap_or(d.trips),
                    ncrits: ncrits.unwrap_or(d.ncrits),
                    outboard: outboard.unwrap_or(d.outboard),
                    inboard: inboard.unwrap_or(d.inboard),
                },
            }
        }
        "airfoil" => StudyKind::Airfoil {
            airfoils: airfoils.unwrap_or_else(|| vec!["naca8h12".into(), "naca23012".into()]),
        },
        "speed" => StudyKind::Speed {
            airfoil: airfoil(),
            xtr: xtr.unwrap_or(0.07),
            speeds_kt: speeds_kt
                .unwrap_or_else(|| (0..13).map(|i| 30.0 + 5.0 * f64::from(i)).collect()),
        },
        "wing" => StudyKind::Wing(WingOptions {
            airfoil: airfoil(),
            areas_m2: areas_m2.unwrap_or_else(|| vec![0.0, 1.0, 1.7, 2.5]),
            speeds_kt: speeds_kt.unwrap_or_else(|| vec![30.0, 45.0, 60.0, 75.0, 90.0]),
            xtr,
        }),
        other => {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "study: unknown study '{other}' (contamination, airfoil, speed, wing)"
            )))
        }
    };
    // The aircraft preset at the path, or the built-in MTOsport for the shipped path.
    let aircraft = ShippedInputs::default()
        .aircraft(&Some(aircraft))
        .map_err(|e| raise(None, e))?;
    let request = StudyRequest {
        kind,
        aircraft,
        out,
        cache,
        json: true,
    };
    let outcome = py.detach(|| shielded(|| request.run(&Silent)))?;
    let outcome = outcome.map_err(|e| raise(None, e))?;
    Ok((outcome.stdout, outcome.notes, outcome.written))
}
