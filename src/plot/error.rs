//! Errors of the plotting layer: one-line messages naming the problem.

use crate::output::OutputError;
use std::path::{Path, PathBuf};

/// Why a figure could not be drawn or written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// The output file name does not end in `.svg` or `.png`.
    #[error("cannot plot to {path}: unknown file extension (use .svg or .png)")]
    UnknownExtension {
        /// The requested output path.
        path: PathBuf,
    },
    /// The output file could not be created, written or renamed.
    #[error("cannot write plot {}: {}", path.display(), source.detail_for(path))]
    Output {
        /// The requested output path.
        path: PathBuf,
        /// What went wrong, and where.
        source: OutputError,
    },
    /// The figure has no panels.
    #[error("figure \"{title}\" has no panels to draw")]
    EmptyFigure {
        /// Figure title.
        title: String,
    },
    /// A series has different numbers of x and y values.
    #[error("series \"{label}\" has {nx} x values but {ny} y values")]
    LengthMismatch {
        /// Series label.
        label: String,
        /// Number of x values.
        nx: usize,
        /// Number of y values.
        ny: usize,
    },
    /// A fixed axis range is empty, reversed or not finite.
    #[error("panel \"{panel}\": invalid {axis} range [{min}, {max}]")]
    InvalidRange {
        /// Panel title.
        panel: String,
        /// `"x"` or `"y"`.
        axis: &'static str,
        /// Requested lower limit.
        min: f64,
        /// Requested upper limit.
        max: f64,
    },
    /// A tick step is zero, negative or not finite.
    #[error("panel \"{panel}\": invalid {axis} tick step {step}")]
    InvalidTickStep {
        /// Panel title.
        panel: String,
        /// `"x"` or `"y"`.
        axis: &'static str,
        /// Requested step.
        step: f64,
    },
    /// The shipped font could not be parsed.
    #[error("the shipped font could not be loaded")]
    Font,
    /// The plotting backend failed while drawing.
    #[error("drawing failed: {0}")]
    Draw(String),
}

impl PlotError {
    /// An output error of the image file `path`.
    pub fn output(path: &Path, source: OutputError) -> Self {
        Self::Output {
            path: path.to_path_buf(),
            source,
        }
    }
}

impl From<OutputError> for PlotError {
    fn from(source: OutputError) -> Self {
        Self::Output {
            path: source.path().to_path_buf(),
            source,
        }
    }
}
