//! `Aircraft`: the gyroplane preset, its cruise trim and its takeoff, with the results in the
//! fields `gyro trim --json` and `gyro takeoff --json` print (their serde form); `Rotor`: the
//! rotor of a preset alone, autorotating in a tunnel as `gyro autorotate` computes it.

use std::path::PathBuf;

use numpy::IntoPyArray;
use polargen::progress::Silent;
use polargen::rotor::{
    autorotate, autorotate_outcomes, check_altitude_m, check_mass_kg, check_speed_kt,
    simulate_takeoff, trim_aircraft, tunnel_case, Aircraft, Atmosphere, Rotor, RotorParams,
    RotorPreset, TakeoffSample, TrimParams,
};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::{raise, shielded};
use crate::table::Table;

/// A gyroplane preset (rotor, airframe, propeller, takeoff data).
#[pyclass(module = "polargen._polargen", name = "Aircraft", frozen)]
pub struct PyAircraft {
    /// The preset.
    pub inner: Aircraft,
}

impl PyAircraft {
    /// The preset with its mass replaced by `mass_kg` (checked as `gyro --mass`) when given.
    pub fn with_mass(&self, mass_kg: Option<f64>) -> PyResult<Aircraft> {
        let mut aircraft = self.inner.clone();
        if let Some(m) = mass_kg {
            check_mass_kg("mass_kg", m).map_err(|e| raise(None, e))?;
            aircraft.mass_kg = m;
        }
        Ok(aircraft)
    }
}

/// The table as a rotor section: it must allow lookups, as `gyro` requires of its `--table`.
pub fn section(table: &Table) -> PyResult<&polargen::table::PolarTable> {
    table
        .inner
        .require_lookup()
        .map_err(|e| raise(Some("table"), e))?;
    Ok(&table.inner)
}

/// The serde form of a result (what `gyro … --json` prints) as JSON text.
pub fn json<T: serde::Serialize>(value: &T) -> PyResult<String> {
    serde_json::to_string(value).map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))
}

#[pymethods]
impl PyAircraft {
    /// Reads and checks a TOML preset (e.g. `aircraft/mtosport.toml`).
    #[staticmethod]
    fn read(path: PathBuf) -> PyResult<Self> {
        Aircraft::from_toml_file(&path)
            .map(|inner| Self { inner })
            .map_err(|e| raise(None, e))
    }

    /// Parses and checks a TOML preset held in a string; `origin` names it in errors.
    #[staticmethod]
    #[pyo3(signature = (text, origin = "<string>"))]
    fn from_toml(text: &str, origin: &str) -> PyResult<Self> {
        Aircraft::from_toml_str(text, origin)
            .map(|inner| Self { inner })
            .map_err(|e| raise(None, e))
    }

    /// The aircraft's name.
    #[getter]
    fn name(&self) -> &str {
        &self.inner.name
    }

    /// The preset's takeoff mass [kg].
    #[getter]
    fn mass_kg(&self) -> f64 {
        self.inner.mass_kg
    }

    /// Level-cruise trim as `gyro trim --json` computes it: (JSON text, notes).
    fn trim(
        &self,
        py: Python<'_>,
        table: &Table,
        speed_kt: f64,
        mass_kg: Option<f64>,
        altitude_m: f64,
    ) -> PyResult<(String, Vec<String>)> {
        check_speed_kt("speed_kt", speed_kt).map_err(|e| raise(None, e))?;
        check_altitude_m("altitude_m", altitude_m).map_err(|e| raise(None, e))?;
        let aircraft = self.with_mass(mass_kg)?;
        let section = section(table)?;
        let trimmed = py.detach(|| {
            shielded(|| {
                trim_aircraft(
                    &aircraft,
                    section,
                    speed_kt,
                    aircraft.mass_kg,
                    altitude_m,
                    &TrimParams::default(),
                )
            })
        })?;
        let t = trimmed.map_err(|e| raise(None, e))?;
        Ok((json(&t)?, t.notes()))
    }

    /// The takeoff as `gyro takeoff --json` computes it: (JSON text, time history columns,
    /// notes).
    fn takeoff<'py>(
        &self,
        py: Python<'py>,
        table: &Table,
        mass_kg: Option<f64>,
    ) -> PyResult<(String, Bound<'py, PyDict>, Vec<String>)> {
        let aircraft = self.with_mass(mass_kg)?;
        let section = section(table)?;
        let run = py.detach(|| shielded(|| simulate_takeoff(&aircraft, section)))?;
        let t = run.map_err(|e| raise(None, e))?;
        let history = PyDict::new(py);
        let column = |f: fn(&TakeoffSample) -> f64| {
            t.history
                .iter()
                .map(f)
                .collect::<Vec<f64>>()
                .into_pyarray(py)
        };
        history.set_item("t", column(|s| s.t))?;
        history.set_item("x", column(|s| s.x))?;
        history.set_item("h", column(|s| s.h))?;
        history.set_item("v", column(|s| s.v))?;
        history.set_item("rotor_rpm", column(|s| s.rotor_rpm))?;
        history.set_item("alpha_r_deg", column(|s| s.alpha_r_deg))?;
        history.set_item("beta_deg", column(|s| s.beta_deg))?;
        Ok((json(&t)?, history, t.notes()))
    }

    fn __repr__(&self) -> String {
        format!("Aircraft({:?}, {} kg)", self.inner.name, self.inner.mass_kg)
    }
}

/// The rotor of a preset (an aircraft's, or a rotor-only preset such as the PCA-2's).
#[pyclass(module = "polargen._polargen", name = "Rotor", frozen)]
pub struct PyRotor {
    inner: RotorPreset,
}

impl PyRotor {
    /// The preset's rotor with the blade pitch setting `pitch_deg` when given (checked as the
    /// preset is, the error naming `pitch_deg`).
    fn tunnel_params(&self, pitch_deg: Option<f64>) -> PyResult<RotorParams> {
        let mut params = self.inner.rotor.clone();
        if let Some(pitch) = pitch_deg {
            params.incidence_deg = pitch;
            params.validate().map_err(|e| raise(Some("pitch_deg"), e))?;
        }
        Ok(params)
    }
}

#[pymethods]
impl PyRotor {
    /// Reads and checks the rotor of a TOML preset (e.g. `aircraft/pca2.toml`).
    #[staticmethod]
    fn read(path: PathBuf) -> PyResult<Self> {
        RotorPreset::from_toml_file(&path)
            .map(|inner| Self { inner })
            .map_err(|e| raise(None, e))
    }

    /// Parses and checks the rotor of a TOML preset held in a string.
    #[staticmethod]
    #[pyo3(signature = (text, origin = "<string>"))]
    fn from_toml(text: &str, origin: &str) -> PyResult<Self> {
        RotorPreset::from_toml_str(text, origin)
            .map(|inner| Self { inner })
            .map_err(|e| raise(None, e))
    }

    /// The preset's name.
    #[getter]
    fn name(&self) -> &str {
        &self.inner.name
    }

    /// The autorotating rotor in a tunnel as `gyro autorotate --json` computes it: the wind
    /// speed `speed_m_s`, or `mu` at `reference_rpm`; (JSON text, notes).
    #[allow(clippy::too_many_arguments)]
    fn autorotate(
        &self,
        py: Python<'_>,
        table: &Table,
        alpha_deg: f64,
        speed_m_s: Option<f64>,
        mu: Option<f64>,
        reference_rpm: Option<f64>,
        pitch_deg: Option<f64>,
        altitude_m: f64,
    ) -> PyResult<(String, Vec<String>)> {
        check_altitude_m("altitude_m", altitude_m).map_err(|e| raise(None, e))?;
        let params = self.tunnel_params(pitch_deg)?;
        let names = ["alpha_deg", "speed_m_s", "mu", "reference_rpm"];
        let case = tunnel_case(
            alpha_deg,
            speed_m_s,
            mu.zip(reference_rpm),
            params.radius_m,
            names,
        )
        .map_err(|e| raise(None, e))?;
        let section = section(table)?;
        let rotor = Rotor::from_params(&params);
        let atm = Atmosphere::isa(altitude_m);
        let run = py.detach(|| {
            shielded(|| autorotate(&rotor, section, &case, &atm, &TrimParams::default()))
        })?;
        let a = run.map_err(|e| raise(None, e))?;
        Ok((json(&a)?, a.notes()))
    }

    /// Every tunnel case (`alpha_deg[i]`, `speed_m_s[i]`) as `gyro autorotate --cases
    /// --json` computes them: (JSON array of the rows, with `error` for a case without
    /// autorotation; notes). Each case is checked as the command checks a row, before any solve.
    fn autorotate_cases(
        &self,
        py: Python<'_>,
        table: &Table,
        alpha_deg: Vec<f64>,
        speed_m_s: Vec<f64>,
        pitch_deg: Option<f64>,
        altitude_m: f64,
    ) -> PyResult<(String, Vec<String>)> {
        check_altitude_m("altitude_m", altitude_m).map_err(|e| raise(None, e))?;
        if alpha_deg.len() != speed_m_s.len() || alpha_deg.is_empty() {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "autorotate_cases: alpha_deg and speed_m_s need the same number of cases, at \
                 least one (got {} and {})",
                alpha_deg.len(),
                speed_m_s.len()
            )));
        }
        let params = self.tunnel_params(pitch_deg)?;
        let names = ["alpha_deg", "speed_m_s", "mu", "reference_rpm"];
        let cases = alpha_deg
            .iter()
            .zip(&speed_m_s)
            .map(|(&a, &v)| tunnel_case(a, Some(v), None, params.radius_m, names))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| raise(None, e))?;
        let section = section(table)?;
        let rotor = Rotor::from_params(&params);
        let atm = Atmosphere::isa(altitude_m);
        let outcomes = py.detach(|| {
            shielded(|| {
                let params = TrimParams::default();
                autorotate_outcomes(&rotor, section, &cases, &atm, &params, &Silent)
            })
        })?;
        let notes = outcomes.iter().flat_map(|o| o.notes()).collect();
        Ok((json(&outcomes)?, notes))
    }

    fn __repr__(&self) -> String {
        format!("Rotor({:?})", self.inner.name)
    }
}
