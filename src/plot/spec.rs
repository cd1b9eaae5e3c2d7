//! A figure as plain data for another renderer (the Python package's matplotlib helper): the
//! [`Figure`] with the decisions the SVG/PNG renderer makes already taken — the panel grid,
//! each panel's axis limits (padding included) and which series carry point symbols — so that
//! both draw the same panels, ranges and symbols.

use serde::Serialize;

use super::axes::{panel_limits, y_sign};
use super::figure::{Figure, Line, MarkerKind};
use super::layout::grid_shape;
use super::render::RenderParams;
use super::sparse::{figure_is_sparse, shows_points};

/// A figure to draw: title, grid (rows, columns) and panels, row by row.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FigureSpec {
    /// Title above all panels.
    pub title: String,
    /// Rows and columns of the panel grid.
    pub grid: (usize, usize),
    /// The panels.
    pub panels: Vec<PanelSpec>,
}

/// One panel: labels, axis limits as drawn, series and markers.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PanelSpec {
    /// Caption above the axes.
    pub title: String,
    /// x-axis label.
    pub x_label: String,
    /// y-axis label.
    pub y_label: String,
    /// x limits (data units).
    pub x_limits: (f64, f64),
    /// y limits (data units; the first is the lower end of the axis as drawn, which is the
    /// larger value on an inverted axis).
    pub y_limits: (f64, f64),
    /// The series, drawn in order.
    pub series: Vec<SeriesSpec>,
    /// Reference marks over the series.
    pub markers: Vec<MarkerSpec>,
    /// Mark points outside the limits by an arrowhead at the edge, pointing to them.
    pub mark_clipped: bool,
}

/// One series: legend label (empty: none), points, palette colour index, line and symbols.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SeriesSpec {
    /// Legend text.
    pub label: String,
    /// Abscissae (non-finite values break the line).
    pub x: Vec<f64>,
    /// Ordinates.
    pub y: Vec<f64>,
    /// Palette index (the "tab10" colours, wrapping).
    pub color: usize,
    /// `solid`, `dashed` or `none`.
    pub line: &'static str,
    /// A symbol on every point.
    pub symbols: bool,
}

/// A reference mark: `vline` at `x`, `hline` at `y`, or a `point` at (`x`, `y`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MarkerSpec {
    /// `vline`, `hline` or `point`.
    pub kind: &'static str,
    /// x of a vertical line or a point (NaN otherwise).
    pub x: f64,
    /// y of a horizontal line or a point (NaN otherwise).
    pub y: f64,
    /// Legend text.
    pub label: String,
    /// Palette index.
    pub color: usize,
}

/// The drawing decisions of the default renderer for `figure`.
pub fn figure_spec(figure: &Figure) -> FigureSpec {
    let padding = RenderParams::default().padding;
    let sparse = figure_is_sparse(figure, padding);
    let panels = figure
        .panels
        .iter()
        .map(|panel| {
            let (x_limits, (y0, y1)) = panel_limits(panel, padding);
            let sign = y_sign(panel);
            PanelSpec {
                title: panel.title.clone(),
                x_label: panel.x_label.clone(),
                y_label: panel.y_label.clone(),
                x_limits,
                y_limits: (sign * y0, sign * y1),
                series: panel
                    .series
                    .iter()
                    .map(|s| SeriesSpec {
                        label: s.label.clone(),
                        x: s.x.clone(),
                        y: s.y.clone(),
                        color: s.style.color,
                        line: match s.style.line {
                            Line::Solid => "solid",
                            Line::Dashed => "dashed",
                            Line::None => "none",
                        },
                        symbols: shows_points(s, sparse),
                    })
                    .collect(),
                markers: panel
                    .markers
                    .iter()
                    .map(|m| {
                        let (kind, x, y) = match m.kind {
                            MarkerKind::VLine(x) => ("vline", x, f64::NAN),
                            MarkerKind::HLine(y) => ("hline", f64::NAN, y),
                            MarkerKind::Point(x, y) => ("point", x, y),
                        };
                        MarkerSpec {
                            kind,
                            x,
                            y,
                            label: m.label.clone(),
                            color: m.color,
                        }
                    })
                    .collect(),
                mark_clipped: panel.mark_clipped,
            }
        })
        .collect();
    FigureSpec {
        title: figure.title.clone(),
        grid: grid_shape(figure.panels.len()),
        panels,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::{Marker, Panel, Series, Style};

    #[test]
    fn the_spec_carries_the_renderers_decisions() {
        let sparse = Series::new(
            "a",
            vec![0.0, 1.0, 2.0],
            vec![0.0, 1.0, 4.0],
            Style::solid(1),
        );
        let figure = Figure::new("t")
            .with_panel(
                Panel::new("p", "x", "y")
                    .with_series(sparse)
                    .with_marker(Marker::hline(1.0, "one", 7))
                    .with_y_inverted(),
            )
            .with_panel(Panel::new("q", "x", "y").with_x_range(0.0, 0.5));
        let spec = figure_spec(&figure);
        assert_eq!(spec.grid, (1, 2));
        let p = &spec.panels[0];
        // three points across the panel are sparse: symbols on
        assert!(p.series[0].symbols && p.series[0].line == "solid" && p.series[0].color == 1);
        // y from 0 to 4 padded by 5 %, inverted: drawn from 4.2 (bottom) to −0.2 (top)
        assert!((p.y_limits.0 - 4.2).abs() < 1e-12 && (p.y_limits.1 + 0.2).abs() < 1e-12);
        assert!((p.x_limits.0 + 0.1).abs() < 1e-12 && (p.x_limits.1 - 2.1).abs() < 1e-12);
        assert_eq!((p.markers[0].kind, p.markers[0].y), ("hline", 1.0));
        assert_eq!(spec.panels[1].x_limits, (0.0, 0.5));
    }
}
