//! Draws a [`Figure`] with plotters: SVG or PNG chosen by the output file extension.
//!
//! Layout: the figure title on top, panels in a grid (1–3 in one row, 4 as 2 × 2, more in a
//! near-square grid), and one legend shared by all panels in a strip below them, so the legend
//! never covers data. Each panel has a grid, tick labels, axis labels and an optional caption.
//! Lines are clipped to the axes (plotters does not clip). Files are written to a temporary
//! sibling first and renamed into place, so a failed render never leaves a truncated plot.

use std::fs;
use std::path::{Path, PathBuf};

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::error::PlotError;
use super::figure::{AxisRange, Figure, Line, MarkerKind, Panel, Style};
use super::font::{register_shipped_font, FONT_FAMILY};

/// Colour palette indexed by [`Style::color`] (wraps around): the "tab10" qualitative colours
/// of matplotlib (Tableau 10), chosen to stay distinguishable when printed in grey.
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// Colour of palette index `i` (wrapping).
fn palette(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

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
/// `.png` file name that is not a folder and whose nearest existing parent is a folder
/// ([`check_output_path`](crate::table::io::check_output_path)). Missing folders are fine;
/// `render` creates them.
pub fn check_image_path(path: &Path) -> Result<(), PlotError> {
    crate::table::io::check_output_path(path).map_err(|e| PlotError::Unwritable {
        path: path.to_path_buf(),
        reason: io_reason(e, path),
    })?;
    format_of(path).map(|_| ())
}

/// The reason of an output-path error for [`PlotError::Unwritable`], which names `requested`
/// itself (so the path is repeated only when the error concerns a folder above it).
fn io_reason(e: crate::table::TableError, requested: &Path) -> String {
    match e {
        crate::table::TableError::Io { path, source } if path == requested => source.to_string(),
        crate::table::TableError::Io { path, source } => format!("{}: {source}", path.display()),
        other => other.to_string(),
    }
}

/// Renders `figure` to `path` (SVG or PNG by extension) with default [`RenderParams`].
pub fn render(figure: &Figure, path: impl AsRef<Path>) -> Result<(), PlotError> {
    render_with(figure, path, &RenderParams::default())
}

/// Renders `figure` to `path` (SVG or PNG by extension) with the given parameters.
///
/// The image is written to a temporary file next to `path` and renamed into place; missing
/// folders are created, a symbolic link is written through, and a folder, device or pipe at
/// `path` is refused.
pub fn render_with(
    figure: &Figure,
    path: impl AsRef<Path>,
    params: &RenderParams,
) -> Result<(), PlotError> {
    let path = path.as_ref();
    let format = format_of(path)?;
    validate(figure)?;
    // The file to replace: `path`, or the file a symbolic link `path` points to.
    let target =
        crate::table::io::prepare_output_path(path).map_err(|e| PlotError::Unwritable {
            path: path.to_path_buf(),
            reason: io_reason(e, path),
        })?;
    register_shipped_font()?;
    let layout = Layout::new(figure, params)?;
    let tmp = temp_path(&target, format);
    let unwritable = |reason: String| PlotError::Unwritable {
        path: path.to_path_buf(),
        reason,
    };
    let result = match format {
        Format::Svg => {
            let svg = svg_string_of(figure, params, &layout)?;
            fs::write(&tmp, svg).map_err(|e| unwritable(e.to_string()))
        }
        Format::Png => write_png(figure, params, &layout, &tmp).map_err(|e| match e {
            PlotError::Unwritable { reason, .. } => unwritable(reason),
            other => other,
        }),
    }
    .and_then(|()| fs::rename(&tmp, &target).map_err(|e| unwritable(e.to_string())));
    if result.is_err() {
        // The temporary file may not exist; there is nothing else to clean up.
        let _ = fs::remove_file(&tmp);
    }
    result
}

/// Renders `figure` to an SVG document in memory (default parameters).
pub fn render_svg_string(figure: &Figure) -> Result<String, PlotError> {
    let params = RenderParams::default();
    validate(figure)?;
    register_shipped_font()?;
    let layout = Layout::new(figure, &params)?;
    svg_string_of(figure, &params, &layout)
}

/// Temporary sibling of `path` (same directory, hidden, unique per process and thread, keeping
/// the real extension because the PNG encoder picks its format from it).
fn temp_path(path: &Path, format: Format) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = match format {
        Format::Svg => "svg",
        Format::Png => "png",
    };
    let thread: String = format!("{:?}", std::thread::current().id())
        .chars()
        .filter(char::is_ascii_digit)
        .collect();
    path.with_file_name(format!(".{name}.{}-{thread}.tmp.{ext}", std::process::id()))
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

/// Draws the figure into a PNG file at `tmp`.
fn write_png(
    figure: &Figure,
    params: &RenderParams,
    layout: &Layout,
    tmp: &Path,
) -> Result<(), PlotError> {
    let unwritable = |reason: String| PlotError::Unwritable {
        path: tmp.to_path_buf(),
        reason,
    };
    // Fail early (with the OS message) when the directory is missing or read-only.
    fs::File::create(tmp).map_err(|e| unwritable(e.to_string()))?;
    let root = BitMapBackend::new(tmp, layout.size).into_drawing_area();
    draw_figure(&root, figure, params, layout)?;
    root.present().map_err(|e| unwritable(e.to_string()))
}

/// Converts a plotters drawing error into a [`PlotError`].
fn draw_err<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> PlotError {
    PlotError::Draw(e.to_string())
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

/// Grid shape (rows, columns) for `n` panels: one row up to 3, else a near-square grid.
pub fn grid_shape(n: usize) -> (usize, usize) {
    if n <= 3 {
        (1, n.max(1))
    } else {
        let cols = (n as f64).sqrt().ceil() as usize;
        (n.div_ceil(cols), cols)
    }
}

/// One entry of the shared legend.
#[derive(Clone, Debug, PartialEq)]
enum LegendEntry {
    /// A data series: its label and style.
    Series(String, Style),
    /// A labelled marker: its label, kind (position ignored) and colour.
    Marker(String, MarkerKind, usize),
}

impl LegendEntry {
    fn label(&self) -> &str {
        match self {
            Self::Series(l, _) | Self::Marker(l, _, _) => l,
        }
    }

    /// True when both entries would draw the same legend item.
    fn same_as(&self, other: &Self) -> bool {
        match (self, other) {
            (Self::Series(a, sa), Self::Series(b, sb)) => a == b && sa == sb,
            (Self::Marker(a, ka, ca), Self::Marker(b, kb, cb)) => {
                a == b && ca == cb && std::mem::discriminant(ka) == std::mem::discriminant(kb)
            }
            _ => false,
        }
    }
}

/// Pixel layout of a figure: canvas size, grid and legend rows.
#[derive(Clone, Debug)]
struct Layout {
    /// Canvas size (px).
    size: (u32, u32),
    /// Panel grid (rows, columns).
    grid: (usize, usize),
    /// Height of the title strip (px) (0 without a title).
    title_height: u32,
    /// Title font size (px): [`RenderParams::title_font`], reduced so a long title fits the
    /// canvas width.
    title_font: f64,
    /// Legend entries, by row.
    legend_rows: Vec<Vec<(LegendEntry, u32)>>,
}

impl Layout {
    /// Measures legend text with the shipped font and sizes the canvas.
    fn new(figure: &Figure, p: &RenderParams) -> Result<Self, PlotError> {
        let grid = grid_shape(figure.panels.len());
        let width = p.panel_width * grid.1 as u32;
        let title_height = if figure.title.is_empty() {
            0
        } else {
            p.title_height
        };
        let usable = width.saturating_sub(2 * p.margin);
        let title_font = fitted_font_size(&figure.title, p.title_font, usable)?;
        let font = FontDesc::new(
            FontFamily::Name(FONT_FAMILY),
            p.legend_font,
            FontStyle::Normal,
        );
        let mut rows: Vec<Vec<(LegendEntry, u32)>> = Vec::new();
        let mut row_width = 0;
        for entry in legend_entries(figure) {
            let (text_w, _) = font
                .box_size(entry.label())
                .map_err(|e| PlotError::Draw(e.to_string()))?;
            let w = p.legend_sample_length + 8 + text_w + p.legend_gap;
            match rows.last_mut() {
                Some(row) if row_width + w <= usable => row.push((entry, w)),
                _ => {
                    rows.push(vec![(entry, w)]);
                    row_width = 0;
                }
            }
            row_width += w;
        }
        let legend_height = if rows.is_empty() {
            0
        } else {
            rows.len() as u32 * p.legend_row_height + p.margin
        };
        let height = title_height + p.panel_height * grid.0 as u32 + legend_height;
        Ok(Self {
            size: (width, height),
            grid,
            title_height,
            title_font,
            legend_rows: rows,
        })
    }
}

/// The font size, at most `size`, at which `text` in the shipped font is no wider than `width`
/// pixels (text width scales linearly with the font size).
fn fitted_font_size(text: &str, size: f64, width: u32) -> Result<f64, PlotError> {
    if text.is_empty() {
        return Ok(size);
    }
    let font = FontDesc::new(FontFamily::Name(FONT_FAMILY), size, FontStyle::Normal);
    let (text_w, _) = font
        .box_size(text)
        .map_err(|e| PlotError::Draw(e.to_string()))?;
    Ok(if text_w > width && text_w > 0 {
        size * f64::from(width) / f64::from(text_w)
    } else {
        size
    })
}

/// Distinct labelled series and markers of all panels, in order of first appearance.
fn legend_entries(figure: &Figure) -> Vec<LegendEntry> {
    let mut entries: Vec<LegendEntry> = Vec::new();
    let mut add = |e: LegendEntry| {
        if !e.label().is_empty() && !entries.iter().any(|o| o.same_as(&e)) {
            entries.push(e);
        }
    };
    for panel in &figure.panels {
        for s in &panel.series {
            add(LegendEntry::Series(s.label.clone(), s.style));
        }
        for m in &panel.markers {
            add(LegendEntry::Marker(m.label.clone(), m.kind, m.color));
        }
    }
    entries
}

/// Draws title, panels and legend onto `root`.
fn draw_figure<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    figure: &Figure,
    p: &RenderParams,
    layout: &Layout,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_err)?;
    let (title_area, rest) = root.split_vertically(layout.title_height);
    if layout.title_height > 0 {
        let style = TextStyle::from((FONT_FAMILY, layout.title_font).into_font())
            .pos(Pos::new(HPos::Center, VPos::Center));
        title_area
            .draw_text(
                &figure.title,
                &style,
                (layout.size.0 as i32 / 2, layout.title_height as i32 / 2),
            )
            .map_err(draw_err)?;
    }
    let grid_height = p.panel_height * layout.grid.0 as u32;
    let (grid_area, legend_area) = rest.split_vertically(grid_height);
    let cells = grid_area.split_evenly(layout.grid);
    for (panel, cell) in figure.panels.iter().zip(cells.iter()) {
        draw_panel(cell, panel, p)?;
    }
    draw_legend(&legend_area, layout, p)
}

/// Axis limits in plot coordinates for one axis: fixed, or the padded extent of `values`.
pub fn axis_limits(range: AxisRange, values: &[f64], padding: f64) -> (f64, f64) {
    if let AxisRange::Fixed { min, max } = range {
        return (min, max);
    }
    let (lo, hi) = values
        .iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        return (0.0, 1.0);
    }
    if hi - lo <= 1e-12 * (1.0 + lo.abs().max(hi.abs())) {
        let half = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        return (lo - half, hi + half);
    }
    let pad = padding * (hi - lo);
    (lo - pad, hi + pad)
}

/// Tick positions of one axis: labelled (major) and grid-only (minor) values and the number
/// of decimals that prints every major tick exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct Ticks {
    /// Labelled tick values, ascending.
    pub major: Vec<f64>,
    /// Minor grid values, ascending.
    pub minor: Vec<f64>,
    /// Decimals for the tick labels; `None` (steps below 1e-8) prints in scientific notation.
    pub decimals: Option<usize>,
}

/// Ticks for the axis `[lo, hi]`: multiples of `step` if given (and not absurdly fine), else
/// of the smallest "nice" step {1, 2, 2.5, 5} × 10^k giving at most `max_ticks` labels.
pub fn ticks(lo: f64, hi: f64, max_ticks: usize, step: Option<f64>) -> Ticks {
    let span = hi - lo;
    // A given step that would put more than this many ticks on the axis is ignored.
    const MAX_GIVEN_TICKS: f64 = 1000.0;
    let step = step.filter(|s| span / s <= MAX_GIVEN_TICKS);
    let (step, minor_div) = match step {
        // Given steps get minor lines at thirds (e.g. 15° for 45°) when that divides evenly,
        // else at fifths.
        Some(s) => {
            let thirds = (s / 3.0) * 1e6;
            (
                s,
                if (thirds - thirds.round()).abs() < 1e-6 {
                    3.0
                } else {
                    5.0
                },
            )
        }
        None => {
            let raw = span / max_ticks.max(1) as f64;
            let mag = 10f64.powf(raw.log10().floor());
            [(1.0, 5.0), (2.0, 4.0), (2.5, 5.0), (5.0, 5.0), (10.0, 5.0)]
                .into_iter()
                .map(|(m, d)| (m * mag, d))
                .find(|(s, _)| *s >= raw * (1.0 - 1e-9))
                .unwrap_or((10.0 * mag, 5.0))
        }
    };
    let decimals = (0..=8).find(|&d| {
        let scaled = step * 10f64.powi(d as i32);
        scaled.round() >= 1.0 && (scaled - scaled.round()).abs() < 1e-6 * scaled
    });
    // Multiples of h in [lo, hi], rounded to `d` decimals (if any) so that 3 × 0.2 is 0.6.
    let multiples = |h: f64, d: Option<usize>| -> Vec<f64> {
        let k0 = (lo / h - 1e-9).ceil() as i64;
        let k1 = (hi / h + 1e-9).floor() as i64;
        (k0..=k1)
            .map(|k| {
                let v = k as f64 * h;
                let v = match d {
                    Some(d) => {
                        let scale = 10f64.powi(d as i32);
                        (v * scale).round() / scale
                    }
                    None => v,
                };
                v + 0.0
            })
            .collect()
    };
    Ticks {
        major: multiples(step, decimals),
        minor: multiples(step / minor_div, decimals.map(|d| d + 2)),
        decimals,
    }
}

/// A linear f64 axis whose grid and labels sit at precomputed [`Ticks`] (plotters' own f64
/// axis chooses its ticks itself and cannot take a given spacing).
#[derive(Clone, Debug)]
struct TickedAxis {
    /// Axis limits.
    lo: f64,
    hi: f64,
    /// Tick positions.
    ticks: Ticks,
}

impl TickedAxis {
    fn new((lo, hi): (f64, f64), ticks: Ticks) -> Self {
        Self { lo, hi, ticks }
    }
}

impl Ranged for TickedAxis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    /// Linear map of `value` onto the pixel interval `limit`.
    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let f = (value - self.lo) / (self.hi - self.lo);
        let px = limit.0 as f64 + f * (limit.1 - limit.0) as f64;
        px.round().clamp(-1e6, 1e6) as i32
    }

    /// Major ticks for labels and bold grid lines, minor ticks for light grid lines.
    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.ticks.minor.clone()
        } else {
            self.ticks.major.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

/// Formats a tick value with `decimals` decimals, or in scientific notation for `None`
/// (no "-0").
fn format_tick(v: f64, decimals: Option<usize>) -> String {
    let s = match decimals {
        Some(d) => format!("{v:.d$}"),
        None => format!("{v:.3e}"),
    };
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

/// Liang–Barsky clipping of the segment a→b to the rectangle `[x0, x1] × [y0, y1]`
/// (Liang & Barsky 1984, parametric line clipping). `None` when it lies outside.
fn clip_segment(
    a: (f64, f64),
    b: (f64, f64),
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let mut t0: f64 = 0.0;
    let mut t1: f64 = 1.0;
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            (a.0 + t * dx, a.1 + t * dy)
        }
    };
    Some((at(t0), at(t1)))
}

/// Splits a polyline at non-finite points and clips it to the axes: the visible pieces.
pub fn visible_pieces(
    points: &[(f64, f64)],
    xlim: (f64, f64),
    ylim: (f64, f64),
) -> Vec<Vec<(f64, f64)>> {
    let mut pieces: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut current: Vec<(f64, f64)> = Vec::new();
    let finite = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite();
    for w in points.windows(2) {
        let clipped = if finite(&w[0]) && finite(&w[1]) {
            clip_segment(w[0], w[1], xlim, ylim)
        } else {
            None
        };
        match clipped {
            Some((a, b)) => {
                if current.last() != Some(&a) {
                    if current.len() > 1 {
                        pieces.push(std::mem::take(&mut current));
                    }
                    current.clear();
                    current.push(a);
                }
                current.push(b);
            }
            None => {
                if current.len() > 1 {
                    pieces.push(std::mem::take(&mut current));
                }
                current.clear();
            }
        }
    }
    if current.len() > 1 {
        pieces.push(current);
    }
    pieces
}

/// Whether (x, y) lies inside the axes.
fn inside(pt: (f64, f64), (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> bool {
    pt.0 >= x0 && pt.0 <= x1 && pt.1 >= y0 && pt.1 <= y1
}

/// Draws one panel: axes, grid, series, markers.
fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    p: &RenderParams,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let sign = if panel.y_inverted { -1.0 } else { 1.0 };
    let mut xs: Vec<f64> = Vec::new();
    let mut ys: Vec<f64> = Vec::new();
    for s in &panel.series {
        for (&x, &y) in s.x.iter().zip(&s.y) {
            if x.is_finite() && y.is_finite() {
                xs.push(x);
                ys.push(sign * y);
            }
        }
    }
    for m in &panel.markers {
        match m.kind {
            MarkerKind::VLine(x) => xs.push(x),
            MarkerKind::HLine(y) => ys.push(sign * y),
            MarkerKind::Point(x, y) => {
                xs.push(x);
                ys.push(sign * y);
            }
        }
    }
    let y_range = match panel.y_range {
        AxisRange::Fixed { min, max } if panel.y_inverted => AxisRange::Fixed {
            min: -max,
            max: -min,
        },
        r => r,
    };
    let xlim = axis_limits(panel.x_range, &xs, p.padding);
    let ylim = axis_limits(y_range, &ys, p.padding);

    let x_ticks = ticks(xlim.0, xlim.1, p.max_ticks, panel.x_tick_step);
    let y_ticks = ticks(ylim.0, ylim.1, p.max_ticks, panel.y_tick_step);
    let (x_dec, y_dec) = (x_ticks.decimals, y_ticks.decimals);
    let x_coord = TickedAxis::new(xlim, x_ticks);
    let y_coord = TickedAxis::new(ylim, y_ticks);

    let mut builder = ChartBuilder::on(area);
    if !panel.title.is_empty() {
        builder.caption(&panel.title, (FONT_FAMILY, p.panel_title_font));
    }
    // Twice the margin on the right: a tick label at the right end of the x axis is centred on
    // it and would otherwise be cut off by the cell edge.
    let mut chart = builder
        .margin(p.margin)
        .margin_right(2 * p.margin)
        .x_label_area_size(p.x_label_area)
        .y_label_area_size(p.y_label_area)
        .build_cartesian_2d(x_coord, y_coord)
        .map_err(draw_err)?;

    let x_fmt = |v: &f64| format_tick(*v, x_dec);
    let y_fmt = |v: &f64| format_tick(sign * *v, y_dec);
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_labels(p.max_ticks)
        .y_labels(p.max_ticks)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style((FONT_FAMILY, p.tick_font))
        .axis_desc_style((FONT_FAMILY, p.axis_label_font))
        .bold_line_style(RGBColor(205, 205, 205))
        .light_line_style(RGBColor(238, 238, 238))
        .draw()
        .map_err(draw_err)?;

    let axis_grey = RGBColor(90, 90, 90);
    if p.zero_lines {
        if xlim.0 < 0.0 && xlim.1 > 0.0 {
            chart
                .draw_series(LineSeries::new(
                    [(0.0, ylim.0), (0.0, ylim.1)],
                    axis_grey.stroke_width(1),
                ))
                .map_err(draw_err)?;
        }
        if ylim.0 < 0.0 && ylim.1 > 0.0 {
            chart
                .draw_series(LineSeries::new(
                    [(xlim.0, 0.0), (xlim.1, 0.0)],
                    axis_grey.stroke_width(1),
                ))
                .map_err(draw_err)?;
        }
    }

    for s in &panel.series {
        let color = palette(s.style.color);
        let pts: Vec<(f64, f64)> = s.x.iter().zip(&s.y).map(|(&x, &y)| (x, sign * y)).collect();
        let line_style = color.stroke_width(p.line_width);
        for piece in visible_pieces(&pts, xlim, ylim) {
            match s.style.line {
                Line::Solid => {
                    chart
                        .draw_series(LineSeries::new(piece, line_style))
                        .map_err(draw_err)?;
                }
                Line::Dashed => {
                    chart
                        .draw_series(DashedLineSeries::new(
                            piece,
                            p.dash_length,
                            p.dash_gap,
                            line_style,
                        ))
                        .map_err(draw_err)?;
                }
                Line::None => {}
            }
        }
        if s.style.points {
            chart
                .draw_series(
                    pts.iter()
                        .filter(|pt| pt.0.is_finite() && pt.1.is_finite())
                        .filter(|&&pt| inside(pt, xlim, ylim))
                        .map(|&pt| Circle::new(pt, p.point_radius, color.filled())),
                )
                .map_err(draw_err)?;
        }
    }

    for m in &panel.markers {
        let color = palette(m.color);
        let style = color.stroke_width(p.line_width);
        let line = match m.kind {
            MarkerKind::VLine(x) => Some([(x, ylim.0), (x, ylim.1)]),
            MarkerKind::HLine(y) => Some([(xlim.0, sign * y), (xlim.1, sign * y)]),
            MarkerKind::Point(..) => None,
        };
        if let Some(line) = line {
            for piece in visible_pieces(&line, xlim, ylim) {
                chart
                    .draw_series(DashedLineSeries::new(
                        piece,
                        p.dash_length / 2,
                        p.dash_gap,
                        style,
                    ))
                    .map_err(draw_err)?;
            }
        }
        if let MarkerKind::Point(x, y) = m.kind {
            let pt = (x, sign * y);
            if pt.0.is_finite() && pt.1.is_finite() && inside(pt, xlim, ylim) {
                let r = 2 * p.point_radius;
                chart
                    .draw_series([
                        Circle::new(pt, r, color.filled()),
                        Circle::new(pt, r, BLACK.stroke_width(1)),
                    ])
                    .map_err(draw_err)?;
            }
        }
    }
    Ok(())
}

/// Draws the shared legend rows into `area`.
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    layout: &Layout,
    p: &RenderParams,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let text_style = TextStyle::from((FONT_FAMILY, p.legend_font).into_font())
        .pos(Pos::new(HPos::Left, VPos::Center));
    let width = layout.size.0 as i32;
    let sample = p.legend_sample_length as i32;
    let lw = p.line_width;
    for (row_index, row) in layout.legend_rows.iter().enumerate() {
        let row_width: i32 = row.iter().map(|(_, w)| *w as i32).sum::<i32>() - p.legend_gap as i32;
        let mut x = ((width - row_width) / 2).max(p.margin as i32);
        let yc = (row_index as u32 * p.legend_row_height + p.legend_row_height / 2) as i32;
        for (entry, w) in row {
            let (color, line, points, vertical) = match entry {
                LegendEntry::Series(_, s) => (palette(s.color), s.line, s.points, false),
                LegendEntry::Marker(_, kind, c) => match kind {
                    MarkerKind::VLine(_) => (palette(*c), Line::Dashed, false, true),
                    MarkerKind::HLine(_) => (palette(*c), Line::Dashed, false, false),
                    MarkerKind::Point(..) => (palette(*c), Line::None, true, false),
                },
            };
            let style = color.stroke_width(lw);
            if vertical {
                let h = p.legend_row_height as i32 / 2 - 2;
                let xm = x + sample / 2;
                area.draw(&PathElement::new([(xm, yc - h), (xm, yc - h / 3)], style))
                    .map_err(draw_err)?;
                area.draw(&PathElement::new([(xm, yc + h / 3), (xm, yc + h)], style))
                    .map_err(draw_err)?;
            } else {
                match line {
                    Line::Solid => area
                        .draw(&PathElement::new([(x, yc), (x + sample, yc)], style))
                        .map_err(draw_err)?,
                    Line::Dashed => {
                        let dash = sample / 5;
                        for k in [0, 2 * dash, 4 * dash] {
                            area.draw(&PathElement::new([(x + k, yc), (x + k + dash, yc)], style))
                                .map_err(draw_err)?;
                        }
                    }
                    Line::None => {}
                }
            }
            if points {
                let r = match entry {
                    LegendEntry::Marker(..) => 2 * p.point_radius,
                    LegendEntry::Series(..) => p.point_radius,
                } as i32;
                area.draw(&Circle::new((x + sample / 2, yc), r, color.filled()))
                    .map_err(draw_err)?;
                if matches!(entry, LegendEntry::Marker(..)) {
                    area.draw(&Circle::new((x + sample / 2, yc), r, BLACK.stroke_width(1)))
                        .map_err(draw_err)?;
                }
            }
            area.draw_text(entry.label(), &text_style, (x + sample + 8, yc))
                .map_err(draw_err)?;
            x += *w as i32;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_shapes() {
        assert_eq!(grid_shape(1), (1, 1));
        assert_eq!(grid_shape(3), (1, 3));
        assert_eq!(grid_shape(4), (2, 2));
        assert_eq!(grid_shape(5), (2, 3));
        assert_eq!(grid_shape(9), (3, 3));
    }

    #[test]
    fn auto_limits_pad_and_handle_degenerate_data() {
        let (lo, hi) = axis_limits(AxisRange::Auto, &[0.0, 10.0, f64::NAN], 0.05);
        assert!((lo + 0.5).abs() < 1e-12 && (hi - 10.5).abs() < 1e-12);
        assert_eq!(axis_limits(AxisRange::Auto, &[], 0.05), (0.0, 1.0));
        assert_eq!(axis_limits(AxisRange::Auto, &[0.0, 0.0], 0.05), (-1.0, 1.0));
        let (lo, hi) = axis_limits(AxisRange::Auto, &[2.0], 0.05);
        assert!((lo - 1.8).abs() < 1e-12 && (hi - 2.2).abs() < 1e-12);
    }

    #[test]
    fn nice_ticks() {
        let t = ticks(-0.6, 1.3, 9, None);
        assert_eq!(t.major, vec![-0.5, -0.25, 0.0, 0.25, 0.5, 0.75, 1.0, 1.25]);
        assert_eq!(t.decimals, Some(2));
        assert_eq!(t.minor.len(), 39);
        let t = ticks(0.0, 360.0, 9, Some(45.0));
        assert_eq!(t.major.len(), 9);
        assert_eq!((t.major[2], t.decimals), (90.0, Some(0)));
        assert_eq!(t.minor[1], 15.0);
        let t = ticks(0.0, 1.0, 9, Some(1e-9));
        assert_eq!(
            t.major,
            vec![0.0, 0.2, 0.4, 0.6, 0.8, 1.0],
            "automatic ticks"
        );
        let t = ticks(0.0, 0.012, 9, None);
        assert_eq!((t.major[1], t.decimals), (0.002, Some(3)));
        assert_eq!(format_tick(-0.0001, Some(2)), "0.00");
        assert_eq!(format_tick(0.0125, Some(4)), "0.0125");
        let t = ticks(1e-10, 5e-10, 9, None);
        assert_eq!((t.major.len(), t.decimals), (9, None));
        assert_eq!(format_tick(t.major[0], t.decimals), "1.000e-10");
    }

    #[test]
    fn clipping_cuts_lines_at_the_axes() {
        let pts = [
            (-1.0, 0.5),
            (0.5, 0.5),
            (2.0, 0.5),
            (f64::NAN, 0.0),
            (0.2, 0.2),
            (0.4, 0.4),
        ];
        let pieces = visible_pieces(&pts, (0.0, 1.0), (0.0, 1.0));
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[0], vec![(0.0, 0.5), (0.5, 0.5), (1.0, 0.5)]);
        assert_eq!(pieces[1], vec![(0.2, 0.2), (0.4, 0.4)]);
        assert!(clip_segment((2.0, 2.0), (3.0, 3.0), (0.0, 1.0), (0.0, 1.0)).is_none());
    }
}
