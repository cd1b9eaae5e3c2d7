//! `Airfoil`: a contour from the NACA generators, the name registry, a coordinate file or
//! arrays, and the nodes the solvers see.

use numpy::ndarray::Array2;
use numpy::{AllowTypeChange, IntoPyArray, PyArray1, PyArray2, PyArrayLike1};
use polargen::arguments;
use polargen::geometry::{
    airfoil_by_name_or_path, apply_shape_ops, naca, read_airfoil_file, shape_ops_text,
    to_selig_string, Airfoil as Contour, GeometryError, NacaOptions, ShapeOp,
};
use pyo3::exceptions::PyUserWarning;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

use crate::errors::{raise, shielded};

/// An airfoil contour in XFOIL order: upper trailing edge → leading edge → lower trailing edge.
#[pyclass(module = "polargen", name = "Airfoil", frozen)]
#[derive(Clone)]
pub struct Airfoil {
    /// The contour as given (not repaneled); after geometry operations, in chord units.
    pub contour: Contour,
    /// The geometry operations that made it, in order (recorded in its tables).
    pub ops: Vec<ShapeOp>,
    /// The name before the operations.
    base_name: String,
}

/// A geometry result as an `Airfoil`, or the exception with the CLI's message.
fn wrap(result: Result<Contour, GeometryError>) -> PyResult<Airfoil> {
    result.map(Airfoil::plain).map_err(|e| raise(None, e))
}

impl Airfoil {
    /// A contour without operations.
    pub fn plain(contour: Contour) -> Self {
        Self {
            base_name: contour.name.clone(),
            contour,
            ops: Vec::new(),
        }
    }

    /// This airfoil with operation `op` applied (its check named after the method's argument
    /// `name`): to the contour in chord units first (XFOIL GDES semantics, as the CLI).
    fn shaped(
        &self,
        py: Python<'_>,
        name: &str,
        op: Result<ShapeOp, arguments::ArgumentError>,
        partner: Option<&Airfoil>,
    ) -> PyResult<Self> {
        let op = op.map_err(|e| {
            let e = arguments::ArgumentError::with_text(name, e.value, e.rule);
            raise(None, e)
        })?;
        let base = if self.ops.is_empty() {
            self.in_chord_units(py)?
        } else {
            self.contour.clone()
        };
        let load = |_: &str| -> Result<Contour, GeometryError> {
            match partner {
                Some(p) if p.ops.is_empty() => p.contour.in_chord_units().map(|(c, _)| c),
                Some(p) => Ok(p.contour.clone()),
                None => Err(GeometryError::UnknownAirfoil {
                    name: String::new(),
                }),
            }
        };
        let mut contour = shielded(|| apply_shape_ops(&base, std::slice::from_ref(&op), &load))?
            .map_err(|e| raise(None, e))?;
        let mut ops = self.ops.clone();
        ops.push(op);
        contour.name = format!("{} ({})", self.base_name, shape_ops_text(&ops));
        Ok(Self {
            contour,
            ops,
            base_name: self.base_name.clone(),
        })
    }

    /// The contour in chord units, warning (`UserWarning`, the CLI's note) when it had to be
    /// normalised.
    fn in_chord_units(&self, py: Python<'_>) -> PyResult<Contour> {
        let (contour, normalisation) =
            shielded(|| self.contour.in_chord_units())?.map_err(|e| raise(None, e))?;
        if let Some(n) = normalisation {
            warn_normalised(py, &n.note(&self.contour.name))?;
        }
        Ok(contour)
    }

    /// The nodes the solvers work on (`Airfoil::solver_nodes`; after geometry operations the
    /// contour is already in chord units and only repaneled, as the CLI does), after checking
    /// `panels`; warns (`UserWarning`, the CLI's note) when the contour had to be normalised.
    pub fn solver_nodes(&self, py: Python<'_>, panels: usize) -> PyResult<Contour> {
        arguments::panels("panels", panels).map_err(|e| raise(None, e))?;
        if !self.ops.is_empty() {
            return shielded(|| self.contour.prepared_nodes(panels))?.map_err(|e| raise(None, e));
        }
        let (nodes, normalisation) =
            shielded(|| self.contour.solver_nodes(panels))?.map_err(|e| raise(None, e))?;
        if let Some(n) = normalisation {
            warn_normalised(py, &n.note(&self.contour.name))?;
        }
        Ok(nodes)
    }
}

/// The `UserWarning` that the contour of `name` was normalised (the CLI's note).
fn warn_normalised(py: Python<'_>, note: &str) -> PyResult<()> {
    PyErr::warn(
        py,
        &py.get_type::<PyUserWarning>(),
        &std::ffi::CString::new(note).unwrap_or_default(),
        1,
    )
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
        Ok(Self::plain(contour))
    }

    /// The section with maximum thickness ``thickness`` (chord units; XFOIL GDES TSET: the
    /// thickness line scaled, the camber line kept), as ``--thickness``.
    fn with_thickness(&self, py: Python<'_>, thickness: f64) -> PyResult<Self> {
        self.shaped(
            py,
            "thickness",
            ShapeOp::thickness(&thickness.to_string()),
            None,
        )
    }

    /// The section with maximum camber ``camber`` (chord units, signed; TSET scales the camber
    /// line and cannot create one), as ``--camber``.
    fn with_camber(&self, py: Python<'_>, camber: f64) -> PyResult<Self> {
        self.shaped(py, "camber", ShapeOp::camber(&camber.to_string()), None)
    }

    /// The section with trailing-edge gap ``gap`` (chord units), the change blended over
    /// ``blend`` of the chord (0…1; XFOIL TGAP), as ``--te-gap``.
    #[pyo3(signature = (gap, blend = polargen::geometry::DEFAULT_TE_GAP_BLEND))]
    fn with_te_gap(&self, py: Python<'_>, gap: f64, blend: f64) -> PyResult<Self> {
        self.shaped(py, "gap", ShapeOp::te_gap(&format!("{gap}:{blend}")), None)
    }

    /// The section with a plain flap hinged at (``x``, ``y``) in chord units, deflected by
    /// ``deg`` degrees, positive trailing edge down (XFOIL FLAP), as ``--flap X:Y:DEG``.
    fn with_flap(&self, py: Python<'_>, x: f64, y: f64, deg: f64) -> PyResult<Self> {
        self.shaped(
            py,
            "x, y, deg",
            ShapeOp::flap(&format!("{x}:{y}:{deg}")),
            None,
        )
    }

    /// ``1 - fraction`` of this section and ``fraction`` of ``other``, points paired by
    /// chordwise station on each surface (XFOIL INTX, as XFLR5), as ``--blend``.
    fn blended(&self, py: Python<'_>, other: &Airfoil, fraction: f64) -> PyResult<Self> {
        let op = ShapeOp::blend(&format!("{}:{fraction}", other.contour.name));
        self.shaped(py, "fraction", op, Some(other))
    }

    /// Maximum thickness and camber and their chordwise positions, as XFOIL's GDES measures
    /// them: ``{"thickness", "x_thickness", "camber", "x_camber"}``.
    fn thickness_camber<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let m = shielded(|| self.contour.thickness_camber())?.map_err(|e| raise(None, e))?;
        let d = PyDict::new(py);
        d.set_item("thickness", m.thickness.value)?;
        d.set_item("x_thickness", m.thickness.x)?;
        d.set_item("camber", m.camber.value)?;
        d.set_item("x_camber", m.camber.x)?;
        Ok(d)
    }

    /// The geometry operations that made this section, in their text form
    /// (``["thickness 0.24", "flap 0.75:0:10"]``).
    #[getter]
    fn operations(&self) -> Vec<String> {
        self.ops.iter().map(ToString::to_string).collect()
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
        Ok(Self {
            ops: Vec::new(),
            base_name: contour.name.clone(),
            contour,
        })
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
