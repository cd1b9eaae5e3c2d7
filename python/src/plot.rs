//! The polar figure of `polargen plot` for polars held in Python: the library builds the
//! figure ([`polar_figure_styled`]) and takes the renderer's decisions ([`figure_spec`]); the
//! Python module `polargen.plot` draws the result with matplotlib.

use polargen::plot::drag_axis::CdAxis;
use polargen::plot::figure_spec;
use polargen::plot::polar_plots::{overlay_figure, overlay_title};
use polargen::plot::table_plots::table_label;
use polargen::section::FlowCondition;
use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;

use crate::table::Table;

/// The figure of the polars at (re, mach) of each table, as `polargen plot` draws them: JSON
/// text of the figure with its panel grid, axis limits and point symbols decided. `labels`
/// names the curves (None: airfoil and transition setting), `title` the figure (None: the
/// names and the flow condition), `cd_axis` is `auto`, `all` or a drag coefficient.
#[pyfunction]
#[pyo3(signature = (curves, labels, title, cd_axis))]
pub fn polar_figure(
    curves: Vec<(Py<Table>, f64, f64)>,
    labels: Option<Vec<String>>,
    title: Option<String>,
    cd_axis: &str,
) -> PyResult<String> {
    let cd_axis: CdAxis = cd_axis
        .parse()
        .map_err(|e: String| PyValueError::new_err(format!("cd_axis: {e}")))?;
    if let Some(l) = &labels {
        if l.len() != curves.len() {
            return Err(PyValueError::new_err(format!(
                "labels: {} labels for {} polars",
                l.len(),
                curves.len()
            )));
        }
    }
    let mut names = Vec::new();
    let mut polars = Vec::new();
    let mut drawn = Vec::new();
    for (i, (table, re, mach)) in curves.iter().enumerate() {
        let table = &table.get().inner;
        let points = table.polar(*re, *mach).ok_or_else(|| {
            PyKeyError::new_err(format!("no polar at Re {re}, M {mach} in the table"))
        })?;
        names.push(match &labels {
            Some(l) => l[i].clone(),
            None => table_label(table.meta()),
        });
        polars.push(points);
        drawn.push(FlowCondition::new(*re, *mach));
    }
    let title = title.unwrap_or_else(|| {
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        overlay_title(&names, &drawn, None)
    });
    let spec = figure_spec(&overlay_figure(&names, &polars, &title, cd_axis));
    serde_json::to_string(&spec).map_err(|e| PyValueError::new_err(e.to_string()))
}
