//! Draws a [`Figure`] to SVG or PNG, chosen by the output file extension.
//!
//! Layout ([`layout`](super::layout)): the figure title on top, panels in a grid (1–3 in one
//! row, 4 as 2 × 2, more in a near-square grid), and one legend shared by all panels in a strip
//! below them, so the legend never covers data. Each panel has a grid, tick labels
//! ([`axes`](super::axes)), axis labels and an optional caption; lines are clipped to the axes
//! ([`clip`](super::clip)). Files go through [`write_output_via_file`], so a failed render never
//! leaves a truncated plot.

use std::path::Path;

use plotters::prelude::*;

use super::draw::{draw_err, draw_figure};
use super::error::PlotError;
use super::figure::{AxisRange, Figure};
use super::font::register_shipped_font;
use super::layout::Layout;
use crate::output::{check_output_path, write_output_via_file, OutputError, OutputSet};

/// Sizes (pixels), fonts (pixel heights) and spacing of rendered figures.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderParams {
    /// Width of one panel cell (px).
    pub panel_width: u32,
    /// Height of one panel cell (px).
    pub panel_height: u32,
    /// Height of the strip holding the figure title (px).
    pub title_height: u32,
    /// Figure title font size (px); a title wider than the canvas is drawn smaller to fit.
    pub title_font: f64,
    /// Panel caption font size (px).
    pub panel_title_font: f64,
    /// Axis label font size (px).
    pub axis_label_font: f64,
    /// Tick label font size (px).
    pub tick_font: f64,
    /// Legend text font size (px).
    pub legend_font: f64,
    /// Height of one legend row (px).
    pub legend_row_height: u32,
    /// Length of the line sample in front of a legend entry (px).
    pub legend_sample_length: u32,
    /// Horizontal gap between legend entries (px).
    pub legend_gap: u32,
    /// Stroke width of series lines (px).
    pub line_width: u32,
    /// Radius of series point symbols (px); highlighted marker points use twice this.
    pub point_radius: u32,
    /// Dash length of dashed lines (px).
    pub dash_length: u32,
    /// Gap between dashes (px).
    pub dash_gap: u32,
    /// Fraction of the data span added on each side of automatic axis ranges.
    pub padding: f64,
    /// Margin around each panel (px).
    pub margin: u32,
    /// Height reserved below each panel for x tick labels and the x-axis label (px).
    pub x_label_area: u32,
    /// Width reserved left of each panel for y tick labels and the y-axis label (px).
    pub y_label_area: u32,
    /// Maximum number of tick labels per axis.
    pub max_ticks: usize,
    /// Draw thin lines at x = 0 and y = 0 when they fall inside the axes.
    pub zero_lines: bool,
    /// Height of the strip below a panel that holds its [`Panel::contour`] and x tick labels
    /// (px), taken from the panel's cell.
    ///
    /// [`Panel::contour`]: super::Panel::contour
    pub contour_strip_height: u32,
}

impl Default for RenderParams {
    fn default() -> Self {
        Self {
            panel_width: 720,
            panel_height: 520,
            title_height: 50,
            title_font: 28.0,
            panel_title_font: 22.0,
            axis_label_font: 20.0,
            tick_font: 17.0,
            legend_font: 19.0,
            legend_row_height: 30,
            legend_sample_length: 44,
            legend_gap: 30,
            line_width: 2,
            point_radius: 4,
            dash_length: 10,
            dash_gap: 6,
            padding: 0.05,
            margin: 14,
            x_label_area: 60,
            y_label_area: 86,
            max_ticks: 9,
            zero_lines: true,
            contour_strip_height: 150,
        }
    }
}

/// Output format, chosen by the file extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    Svg,
    Png,
}

/// Format for `path` from its extension (case-insensitive `svg` or `png`).
fn format_of(path: &Path) -> Result<Format, PlotError> {
    match path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("svg") => Ok(Format::Svg),
        Some("png") => Ok(Format::Png),
        _ => Err(PlotError::UnknownExtension {
            path: path.to_path_buf(),
        }),
    }
}

/// Checks, before any drawing, that `path` names an image [`render`] can write: a `.svg` or
/// `.png` file name that [`check_output_path`] accepts. Missing folders are fine; `render`
/// creates them.
pub fn check_image_path(path: &Path) -> Result<(), PlotError> {
    check_output_path(path).map_err(|e| PlotError::output(path, e))?;
    format_of(path).map(|_| ())
}

/// Renders `figure` to `path` (SVG or PNG by extension) with default [`RenderParams`].
pub fn render(figure: &Figure, path: impl AsRef<Path>) -> Result<(), PlotError> {
    render_with(figure, path, &RenderParams::default())
}

/// Renders `figure` to `path` (SVG or PNG by extension) with the given parameters, through
/// [`write_output_via_file`](crate::output::write_output_via_file): missing folders are
/// created, a symbolic link is written through, a device or pipe is written in place.
pub fn render_with(
    figure: &Figure,
    path: impl AsRef<Path>,
    params: &RenderParams,
) -> Result<(), PlotError> {
    let path = path.as_ref();
    let format = format_of(path)?;
    validate(figure)?;
    check_output_path(path).map_err(|e| PlotError::output(path, e))?;
    register_shipped_font()?;
    let layout = Layout::new(figure, params)?;
    let extension = match format {
        Format::Svg => "svg",
        Format::Png => "png",
    };
    write_output_via_file(path, extension, |file| -> Result<(), PlotError> {
        match format {
            Format::Svg => {
                let svg = svg_string_of(figure, params, &layout)?;
                std::fs::write(file, svg).map_err(|e| OutputError::io(path, e).into())
            }
            Format::Png => {
                let root = BitMapBackend::new(file, layout.size).into_drawing_area();
                draw_figure(&root, figure, params, &layout)?;
                root.present()
                    .map_err(|e| OutputError::io(path, encoder_io_error(&e.to_string())).into())
            }
        }
    })
    .map_err(|e| match e {
        PlotError::Output { source, .. } => PlotError::output(path, source),
        other => other,
    })
}

/// The operating-system error inside the PNG encoder's error, whose text is the Rust debug form
/// of nested error values (`ImageError(IoError(Os { code: 28, … }))`, the bitmap backend's
/// error types are not exported to name them): the OS error when its code is there, else a
/// plain sentence.
fn encoder_io_error(debug: &str) -> std::io::Error {
    let code = debug.split("code: ").nth(1).and_then(|rest| {
        rest.split(|c: char| !c.is_ascii_digit())
            .next()
            .and_then(|d| d.parse::<i32>().ok())
    });
    match code {
        Some(code) => std::io::Error::from_raw_os_error(code),
        None => std::io::Error::other("the PNG encoder could not write the file"),
    }
}

/// Width of a one-panel figure drawn by [`render_with_legend_room`] (px): wider than a grid
/// cell, so that a long legend (curves, maxima, reference values) fits in two rows.
const SINGLE_PANEL_WIDTH: u32 = 960;

/// Renders `figure` to `path` with default [`RenderParams`], a one-panel figure wider
/// (960 px) so that its legend has room.
pub fn render_with_legend_room(figure: &Figure, path: &Path) -> Result<(), PlotError> {
    let mut params = RenderParams::default();
    if figure.panels.len() == 1 {
        params.panel_width = SINGLE_PANEL_WIDTH;
    }
    render_with(figure, path, &params)
}

/// Renders `figure` as the file `path` of the output `set` ([`render_with_legend_room`] into
/// the staged file); errors name `path`, never the staging folder.
pub fn render_into_set(figure: &Figure, path: &Path, set: &mut OutputSet) -> Result<(), PlotError> {
    let staged = set.stage(path).map_err(|e| PlotError::output(path, e))?;
    render_with_legend_room(figure, &staged).map_err(|e| match e {
        PlotError::Output { source, .. } => PlotError::output(
            path,
            OutputError::io(path, std::io::Error::other(source.detail_for(&staged))),
        ),
        other => other,
    })
}

/// Renders `figure` to an SVG document in memory (default parameters).
pub fn render_svg_string(figure: &Figure) -> Result<String, PlotError> {
    let params = RenderParams::default();
    validate(figure)?;
    register_shipped_font()?;
    let layout = Layout::new(figure, &params)?;
    svg_string_of(figure, &params, &layout)
}

/// Draws the figure into an SVG string.
fn svg_string_of(
    figure: &Figure,
    params: &RenderParams,
    layout: &Layout,
) -> Result<String, PlotError> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, layout.size).into_drawing_area();
        draw_figure(&root, figure, params, layout)?;
        root.present().map_err(draw_err)?;
    }
    Ok(svg)
}

/// Checks what the renderer cannot draw: no panels, x/y length mismatch, bad fixed ranges.
fn validate(figure: &Figure) -> Result<(), PlotError> {
    if figure.panels.is_empty() {
        return Err(PlotError::EmptyFigure {
            title: figure.title.clone(),
        });
    }
    for panel in &figure.panels {
        for s in &panel.series {
            if s.x.len() != s.y.len() {
                return Err(PlotError::LengthMismatch {
                    label: s.label.clone(),
                    nx: s.x.len(),
                    ny: s.y.len(),
                });
            }
        }
        for (axis, step) in [("x", panel.x_tick_step), ("y", panel.y_tick_step)] {
            if let Some(step) = step {
                if !(step.is_finite() && step > 0.0) {
                    return Err(PlotError::InvalidTickStep {
                        panel: panel.title.clone(),
                        axis,
                        step,
                    });
                }
            }
        }
        for (axis, range) in [("x", panel.x_range), ("y", panel.y_range)] {
            if let AxisRange::Fixed { min, max } = range {
                if !(min.is_finite() && max.is_finite() && min < max) {
                    return Err(PlotError::InvalidRange {
                        panel: panel.title.clone(),
                        axis,
                        min,
                        max,
                    });
                }
            }
        }
    }
    Ok(())
}
