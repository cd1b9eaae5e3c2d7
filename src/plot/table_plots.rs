//! Polars read from table files and overlaid (`polargen plot`): one polar per file, at the
//! flow condition asked for (nearest table node), with legend labels given or made from the
//! airfoil and transition setting.

use std::path::{Path, PathBuf};

use super::drag_axis::CdAxis;
use super::figure::Figure;
use super::polar_plots::{compact_number, overlay_figure, overlay_title};
use crate::limits::short_number;
use crate::section::{FlowCondition, PolarPoint};
use crate::table::{read_table_with, ReadOptions, TableError, TableMeta};

/// Why the polars of an overlay could not be taken from their tables. One line each, naming
/// the flag (`--re`, `--label`) or file at fault.
#[derive(Debug, thiserror::Error)]
pub enum OverlayError {
    /// The number of legend labels differs from the number of tables.
    #[error("--label: {labels} label(s) for {tables} table(s): give one per table, in order")]
    LabelCount {
        /// Labels given.
        labels: usize,
        /// Tables given.
        tables: usize,
    },
    /// A table file could not be read.
    #[error(transparent)]
    Table(#[from] TableError),
    /// A table with several Re or Mach nodes, and no condition to pick one polar.
    #[error("{}: a grid table ({re} Re x {mach} M): give --re and --mach", path.display())]
    GridWithoutCondition {
        /// The table file.
        path: PathBuf,
        /// Its Reynolds-number count.
        re: usize,
        /// Its Mach-number count.
        mach: usize,
    },
    /// The requested Re or Mach lies outside a table's axis.
    #[error("--{flag} {}: outside the table {} ({} … {})", short_number(*value), path.display(), short_number(*lo), short_number(*hi))]
    Outside {
        /// `re` or `mach`.
        flag: &'static str,
        /// The value asked for.
        value: f64,
        /// The table file.
        path: PathBuf,
        /// Smallest axis value.
        lo: f64,
        /// Largest axis value.
        hi: f64,
    },
    /// The polar drawn from a table has no converged point.
    #[error("{}: the polar at Re {}, M {} has no converged point to draw", path.display(), compact_number(condition.reynolds), condition.mach)]
    NothingConverged {
        /// The table file.
        path: PathBuf,
        /// The node drawn.
        condition: FlowCondition,
    },
}

/// What to overlay: table files, their legend labels and the condition to draw.
#[derive(Clone, Copy, Debug)]
pub struct TableOverlay<'a> {
    /// Table files (any format `read_table` reads), one polar each.
    pub tables: &'a [PathBuf],
    /// Legend labels, one per table in order; empty for `<airfoil> <transition setting>`.
    pub labels: &'a [String],
    /// Reynolds number of the polar to draw (nearest node); needed for a grid table.
    pub re: Option<f64>,
    /// Mach number of the polar to draw (nearest node); needed for a grid table.
    pub mach: Option<f64>,
    /// Figure title; `None` for [`overlay_title`].
    pub title: Option<&'a str>,
    /// Upper end of the drag polar's Cd axis.
    pub cd_axis: CdAxis,
    /// What to assume where a file does not say.
    pub read: ReadOptions,
}

/// The polar figure of [`polar_figure_styled`](super::polar_plots::polar_figure_styled) with
/// one polar from each table (palette colour `i` for table `i`, solid). The label count is
/// checked before any file is read.
pub fn table_overlay_figure(overlay: &TableOverlay) -> Result<Figure, OverlayError> {
    let (tables, labels) = (overlay.tables, overlay.labels);
    if !labels.is_empty() && labels.len() != tables.len() {
        return Err(OverlayError::LabelCount {
            labels: labels.len(),
            tables: tables.len(),
        });
    }
    let mut names: Vec<String> = Vec::new();
    let mut polars: Vec<Vec<PolarPoint>> = Vec::new();
    let mut conditions: Vec<FlowCondition> = Vec::new();
    for (i, path) in tables.iter().enumerate() {
        let table = read_table_with(path, &overlay.read)?.table;
        let (re_axis, mach_axis) = (table.re(), table.mach());
        let (re, mach) = match (overlay.re, overlay.mach) {
            (Some(re), Some(mach)) => (re, mach),
            _ if re_axis.len() * mach_axis.len() > 1 => {
                return Err(OverlayError::GridWithoutCondition {
                    path: path.clone(),
                    re: re_axis.len(),
                    mach: mach_axis.len(),
                })
            }
            (re, mach) => (re.unwrap_or(re_axis[0]), mach.unwrap_or(mach_axis[0])),
        };
        check_inside("re", re, re_axis, path)?;
        check_inside("mach", mach, mach_axis, path)?;
        let (at, points) = table.nearest_polar(re, mach);
        if !points.iter().any(|p| p.converged) {
            return Err(OverlayError::NothingConverged {
                path: path.clone(),
                condition: at,
            });
        }
        names.push(match labels.get(i) {
            Some(label) => label.clone(),
            None => table_label(table.meta()),
        });
        polars.push(points.to_vec());
        conditions.push(at);
    }
    let title = overlay.title.map(str::to_string).unwrap_or_else(|| {
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        let asked = overlay
            .re
            .zip(overlay.mach)
            .map(|(r, m)| FlowCondition::new(r, m));
        overlay_title(&names, &conditions, asked)
    });
    Ok(overlay_figure(&names, &polars, &title, overlay.cd_axis))
}

/// The default legend label of a table's polars: airfoil and transition setting
/// (`naca8h12 xtr 0.07`).
pub fn table_label(meta: &TableMeta) -> String {
    format!("{} {}", meta.airfoil, meta.transition.trip_label())
}

/// Error when `value` lies outside a table axis (beyond 0.1 % of the span).
fn check_inside(
    flag: &'static str,
    value: f64,
    axis: &[f64],
    path: &Path,
) -> Result<(), OverlayError> {
    let (lo, hi) = (axis[0], axis[axis.len() - 1]);
    let slack = 1e-3 * (hi - lo).abs().max(hi.abs() * 1e-3);
    if !value.is_finite() || value < lo - slack || value > hi + slack {
        return Err(OverlayError::Outside {
            flag,
            value,
            path: path.to_path_buf(),
            lo,
            hi,
        });
    }
    Ok(())
}
