//! `Airfoil`: a contour from the NACA generators, the name registry, a coordinate file or
//! arrays, and the nodes the solvers see.

use numpy::ndarray::Array2;
use numpy::{AllowTypeChange, IntoPyArray, PyArray1, PyArray2, PyArrayLike1};
use polargen::arguments;
use polargen::geometry::{
    airfoil_by_name_or_path, naca, read_airfoil_file, to_selig_string, Airfoil as Contour,
    GeometryError, NacaOptions,
};
use pyo3::exceptions::PyUserWarning;
use pyo3::prelude::*;
use std::path::PathBuf;

use crate::errors::{raise, shielded};

/// An airfoil contour in XFOIL order: upper trailing edge → leading edge → lower trailing edge.
#[pyclass(module = "polargen", name = "Airfoil", frozen)]
#[derive(Clone)]
pub struct Airfoil {
    /// The contour as given (not repaneled).
    pub contour: Contour,
}

/// A geometry result as an `Airfoil`, or the exception with the CLI's message.
fn wrap(result: Result<Contour, GeometryError>) -> PyResult<Airfoil> {
    result
        .map(|contour| Airfoil { contour })
        .map_err(|e| raise(None, e))
}

impl Airfoil {
    /// The nodes the solvers work on (`Airfoil::solver_nodes`), after checking `panels`; warns
    /// (`UserWarning`, the CLI's note) when the contour had to be normalised.
    pub fn solver_nodes(&self, py: Python<'_>, panels: usize) -> PyResult<Contour> {
        arguments::panels("panels", panels).map_err(|e| raise(None, e))?;
        let (nodes, normalised) =
            shielded(|| self.contour.solver_nodes(panels))?.map_err(|e| raise(None, e))?;
        if normalised {
            let note = Contour::normalisation_note(&self.contour.name);
            PyErr::warn(
                py,
                &py.get_type::<PyUserWarning>(),
                &std::ffi::CString::new(note).unwrap_or_default(),
                1,
            )?;
        }
        Ok(nodes)
    }
}

#[pymethods]
impl Airfoil {
    /// A NACA 4- or 5-digit section from XFOIL's generator conventions: ``"2412"``,
    /// ``"23012"``, ``"NACA 23012"``.
    #[staticmethod]
    fn naca(designation: &str) -> PyResult<Self> {
        wrap(
            naca(designation, &NacaOptions::default()).map_err(|e| match e {
                GeometryError::NacaDesignation { reason, .. } => GeometryError::NacaDesignation {
                    designation: designation.trim().to_string(),
                    reason,
                },
                other => other,
            }),
        )
    }

    /// What the command line's ``--airfoil`` accepts: ``naca8h12``, ``naca23012``, any NACA
    /// 4/5-digit name, or the path of a coordinate file.
    #[staticmethod]
    fn named(name: &str) -> PyResult<Self> {
        wrap(airfoil_by_name_or_path(name))
    }

    /// A Selig, Lednicer or plain x-y coordinate file.
    #[staticmethod]
    fn from_file(path: PathBuf) -> PyResult<Self> {
        wrap(read_airfoil_file(&path))
    }

    /// A contour from coordinate arrays in XFOIL order, checked like a file's points.
    #[staticmethod]
    #[pyo3(signature = (x, y, name = "airfoil"))]
    fn from_coordinates(
        x: PyArrayLike1<'_, f64, AllowTypeChange>,
        y: PyArrayLike1<'_, f64, AllowTypeChange>,
        name: &str,
    ) -> PyResult<Self> {
        let contour = Contour {
            name: name.to_string(),
            x: x.as_array().to_vec(),
            y: y.as_array().to_vec(),
        };
        contour.validate().map_err(|e| raise(None, e))?;
        Ok(Self { contour })
    }

    /// The airfoil's name.
    #[getter]
    fn name(&self) -> &str {
        &self.contour.name
    }

    /// x coordinates (XFOIL order).
    #[getter]
    fn x<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.contour.x.clone().into_pyarray(py)
    }

    /// y coordinates (XFOIL order).
    #[getter]
    fn y<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.contour.y.clone().into_pyarray(py)
    }

    /// The points as an (n, 2) array of x, y.
    #[getter]
    fn coordinates<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let c = &self.contour;
        let flat: Vec<f64> = c.x.iter().zip(&c.y).flat_map(|(&x, &y)| [x, y]).collect();
        let array = Array2::from_shape_vec((c.x.len(), 2), flat)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        Ok(array.into_pyarray(py))
    }

    /// The nodes the solvers work on: in chord units and repaneled to ``panels`` nodes
    /// (XFOIL PANE), as ``polar``, ``point`` and ``table`` prepare the airfoil.
    #[pyo3(signature = (panels = polargen::geometry::DEFAULT_PANEL_NODES))]
    fn paneled(&self, py: Python<'_>, panels: usize) -> PyResult<Self> {
        let contour = self.solver_nodes(py, panels)?;
        Ok(Self { contour })
    }

    /// The contour as Selig-format text (name line, then x y per line).
    fn to_selig(&self) -> String {
        to_selig_string(&self.contour)
    }

    fn __len__(&self) -> usize {
        self.contour.len()
    }

    fn __repr__(&self) -> String {
        format!(
            "Airfoil({:?}, {} points)",
            self.contour.name,
            self.contour.len()
        )
    }
}
