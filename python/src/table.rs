//! `PolarTable`: a Re × M × α table — reading and writing every format of the CLI, the polars
//! it holds, vectorised lookups with their flags and the 360° extension.

use std::path::PathBuf;

use numpy::{AllowTypeChange, IntoPyArray, PyArray1, PyArrayLike1};
use polargen::section::Lookup;
use polargen::table::{
    alpha_at_cl, read_table_with, write_c81, write_table, C81Options, PolarTable, PostStallParams,
    ReadOptions, TableFormat,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::errors::{raise, shielded};
use crate::solve::polar_columns_with_summary;

/// A table of polars, one per (Re, M) node (the library's `PolarTable`).
#[pyclass(module = "polargen._polargen", name = "PolarTable", frozen)]
pub struct Table {
    /// The table.
    pub inner: PolarTable,
}

impl From<PolarTable> for Table {
    fn from(inner: PolarTable) -> Self {
        Self { inner }
    }
}

/// The fields of a lookup as a dict of scalars.
fn lookup_dict<'py>(py: Python<'py>, l: &Lookup) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("cl", l.cl)?;
    d.set_item("cd", l.cd)?;
    d.set_item("cm", l.cm)?;
    d.set_item("re_clamped", l.re_clamped)?;
    d.set_item("mach_clamped", l.mach_clamped)?;
    d.set_item("post_stall", l.post_stall)?;
    d.set_item("bridged", l.bridged)?;
    d.set_item("supercritical", l.supercritical)?;
    d.set_item("supercritical_unknown", l.supercritical_unknown)?;
    d.set_item("massive_separation", l.massive_separation)?;
    d.set_item("separation_unknown", l.separation_unknown)?;
    Ok(d)
}

#[pymethods]
impl Table {
    /// Reads a table file as the CLI does (every format `polargen convert` reads), assuming
    /// `re` (a C81 deck), `mach` (an AeroDyn file from another tool) where the file gives
    /// none and reading the tables at `user_prop` of an AeroDyn file with several: the table
    /// and the reader's notes (what it assumed).
    #[staticmethod]
    #[pyo3(signature = (path, re = None, mach = None, user_prop = None))]
    fn read(
        py: Python<'_>,
        path: PathBuf,
        re: Option<f64>,
        mach: Option<f64>,
        user_prop: Option<f64>,
    ) -> PyResult<(Self, Vec<String>)> {
        let input = |r: Result<(), polargen::arguments::ArgumentError>, name| {
            r.map_err(|e| raise(Some(name), e))
        };
        if let Some(re) = re {
            input(polargen::arguments::reynolds("re", re), "re")?;
        }
        if let Some(mach) = mach {
            input(polargen::arguments::mach("mach", mach), "mach")?;
        }
        let options = ReadOptions {
            re,
            mach,
            user_prop,
        };
        let read = py.detach(|| shielded(|| read_table_with(&path, &options)))?;
        read.map(|r| (Self::from(r.table), r.notes))
            .map_err(|e| raise(None, e))
    }

    /// The summary of every polar (`polargen summary`), Re-major: dicts with airfoil, re,
    /// mach and the summary's fields.
    fn summary<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
        self.inner
            .summaries()
            .iter()
            .map(|row| {
                let d = PyDict::new(py);
                d.set_item("airfoil", &row.airfoil)?;
                d.set_item("re", row.re)?;
                d.set_item("mach", row.mach)?;
                d.update(crate::solve::summary_dict(py, &row.summary)?.as_mapping())?;
                Ok(d)
            })
            .collect()
    }

    /// Writes the table to `path` in `format` (`csv`, `json`, `jsonl`, `xfoil`, `c81`,
    /// `aerodyn`; from the extension when None), as `polargen convert` does; C81 at `c81_re`
    /// only when given.
    /// Returns the files written.
    #[pyo3(signature = (path, format = None, c81_re = None))]
    fn write(
        &self,
        py: Python<'_>,
        path: PathBuf,
        format: Option<&str>,
        c81_re: Option<f64>,
    ) -> PyResult<Vec<PathBuf>> {
        let format = match format {
            Some(f) => f
                .parse::<TableFormat>()
                .map_err(|e| raise(Some("format"), e))?,
            None => TableFormat::from_path(&path).map_err(|e| raise(Some("path"), e))?,
        };
        let written = py.detach(|| {
            shielded(|| match (format, c81_re) {
                (TableFormat::C81, Some(re)) => write_c81(
                    &self.inner,
                    &path,
                    &C81Options {
                        re: Some(re),
                        ..C81Options::default()
                    },
                ),
                _ => write_table(&self.inner, &path, Some(format)),
            })
        })?;
        written.map_err(|e| raise(None, e))
    }

    /// The Reynolds-number axis.
    #[getter]
    fn re<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.inner.re().to_vec().into_pyarray(py)
    }

    /// The Mach-number axis.
    #[getter]
    fn mach<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.inner.mach().to_vec().into_pyarray(py)
    }

    /// How the table was made: airfoil, ncrit (None when the surfaces differ), ncrit_top,
    /// ncrit_bot, xtr_top_set, xtr_bot_set, thickness (t/c), panels, solver; NaN where the
    /// file did not say (a C81 deck has no N_crit).
    #[getter]
    fn meta<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let m = self.inner.meta();
        let d = PyDict::new(py);
        d.set_item("airfoil", &m.airfoil)?;
        let t = &m.transition;
        d.set_item("ncrit", t.common_ncrit())?;
        d.set_item("ncrit_top", t.ncrit_top)?;
        d.set_item("ncrit_bot", t.ncrit_bot)?;
        d.set_item("xtr_top_set", t.xtr_top)?;
        d.set_item("xtr_bot_set", t.xtr_bot)?;
        d.set_item("thickness", m.thickness)?;
        d.set_item("panels", m.panels)?;
        d.set_item("solver", &m.solver)?;
        let ops: Vec<String> = m.geometry.iter().map(ToString::to_string).collect();
        d.set_item("geometry", ops)?;
        d.set_item("flap_deg", m.flap_deg())?;
        Ok(d)
    }

    /// The parameters of the 360° extension: cd_max, cd_reverse, vc_min_junction_deg.
    #[getter]
    fn post_stall<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let p = self.inner.post_stall_params();
        let d = PyDict::new(py);
        d.set_item("cd_max", p.cd_max)?;
        d.set_item("cd_reverse", p.cd_reverse)?;
        d.set_item("vc_min_junction_deg", p.vc_min_junction_deg)?;
        Ok(d)
    }

    /// The same table with other 360°-extension parameters.
    fn with_post_stall(
        &self,
        cd_max: f64,
        cd_reverse: f64,
        vc_min_junction_deg: f64,
    ) -> PyResult<Self> {
        let params = PostStallParams {
            cd_max,
            cd_reverse,
            vc_min_junction_deg,
        };
        self.inner
            .clone()
            .with_post_stall(params)
            .map(Self::from)
            .map_err(|e| raise(None, e))
    }

    /// Every polar with its node: a list of (re, mach, columns), Re-major.
    fn polars<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let list = PyList::empty(py);
        for (condition, points) in self.inner.polars() {
            let columns = polar_columns_with_summary(py, points)?;
            list.append(PyTuple::new(
                py,
                [
                    condition.reynolds.into_pyobject(py)?.into_any(),
                    condition.mach.into_pyobject(py)?.into_any(),
                    columns.into_any(),
                ],
            )?)?;
        }
        Ok(list)
    }

    /// The polar at the node (re, mach) (relative tolerance 1e-9): (re, mach, columns) of the
    /// node, or None.
    fn polar<'py>(
        &self,
        py: Python<'py>,
        re: f64,
        mach: f64,
    ) -> PyResult<Option<(f64, f64, Bound<'py, PyDict>)>> {
        let Some(found) = self.inner.polar(re, mach) else {
            return Ok(None);
        };
        let node = self
            .inner
            .polars()
            .find(|(_, points)| std::ptr::eq(*points, found));
        node.map(|(c, points)| Ok((c.reynolds, c.mach, polar_columns_with_summary(py, points)?)))
            .transpose()
    }

    /// Section coefficients at every (alpha, re, mach) of three equally long 1-D arrays, with
    /// the flags: (cl, cd, cm, re_clamped, mach_clamped, post_stall, bridged, supercritical,
    /// supercritical_unknown, massive_separation, separation_unknown).
    fn lookup<'py>(
        &self,
        py: Python<'py>,
        alpha: PyArrayLike1<'py, f64, AllowTypeChange>,
        re: PyArrayLike1<'py, f64, AllowTypeChange>,
        mach: PyArrayLike1<'py, f64, AllowTypeChange>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let (a, r, m) = (
            alpha.as_array().to_vec(),
            re.as_array().to_vec(),
            mach.as_array().to_vec(),
        );
        if a.len() != r.len() || a.len() != m.len() {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "alpha, re and mach must have one length (got {}, {}, {})",
                a.len(),
                r.len(),
                m.len()
            )));
        }
        let looked = py.detach(|| shielded(|| self.inner.lookup_many(&a, &r, &m)))?;
        let value = |f: fn(&Lookup) -> f64| looked.iter().map(f).collect::<Vec<f64>>();
        let flag = |f: fn(&Lookup) -> bool| looked.iter().map(f).collect::<Vec<bool>>();
        PyTuple::new(
            py,
            [
                value(|l| l.cl).into_pyarray(py).into_any(),
                value(|l| l.cd).into_pyarray(py).into_any(),
                value(|l| l.cm).into_pyarray(py).into_any(),
                flag(|l| l.re_clamped).into_pyarray(py).into_any(),
                flag(|l| l.mach_clamped).into_pyarray(py).into_any(),
                flag(|l| l.post_stall).into_pyarray(py).into_any(),
                flag(|l| l.bridged).into_pyarray(py).into_any(),
                flag(|l| l.supercritical).into_pyarray(py).into_any(),
                flag(|l| l.supercritical_unknown)
                    .into_pyarray(py)
                    .into_any(),
                flag(|l| l.massive_separation).into_pyarray(py).into_any(),
                flag(|l| l.separation_unknown).into_pyarray(py).into_any(),
            ],
        )
    }

    /// The smallest α in [alpha_min, alpha_max] where the lift coefficient at (re, mach) rises
    /// through `cl` (the attached branch), with the lookup there; None if it does not.
    fn alpha_at_cl<'py>(
        &self,
        py: Python<'py>,
        cl: f64,
        re: f64,
        mach: f64,
        alpha_min: f64,
        alpha_max: f64,
    ) -> PyResult<Option<(f64, Bound<'py, PyDict>)>> {
        let found = shielded(|| alpha_at_cl(&self.inner, cl, re, mach, alpha_min, alpha_max))?;
        found
            .map(|m| Ok((m.alpha_deg, lookup_dict(py, &m.lookup)?)))
            .transpose()
    }

    /// Number of points, converged or not.
    #[getter]
    fn point_count(&self) -> usize {
        self.inner.point_count()
    }

    /// Number of converged points.
    #[getter]
    fn converged_count(&self) -> usize {
        self.inner.converged_count()
    }

    /// Number of usable points: converged and not in massive separation (those lookups use).
    #[getter]
    fn usable_count(&self) -> usize {
        self.inner.usable_count()
    }

    /// Whether lookups are possible (some polar has two usable points).
    #[getter]
    fn has_lookup(&self) -> bool {
        self.inner.has_lookup()
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.inner == other.inner
    }
}
