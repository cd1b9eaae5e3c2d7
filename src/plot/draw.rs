//! Drawing with plotters: the figure title, each panel (grid, ticks, series, markers) and the
//! shared legend, onto any plotters backend.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{axis_limits, format_tick, ticks, TickedAxis};
use super::clip::{inside, visible_pieces};
use super::error::PlotError;
use super::figure::{AxisRange, Figure, Line, MarkerKind, Panel};
use super::font::FONT_FAMILY;
use super::layout::{Layout, LegendEntry};
use super::render::RenderParams;

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

/// Converts a plotters drawing error into a [`PlotError`].
pub(super) fn draw_err<E: std::error::Error + Send + Sync>(
    e: DrawingAreaErrorKind<E>,
) -> PlotError {
    PlotError::Draw(e.to_string())
}

/// Draws title, panels and legend onto `root`.
pub(super) fn draw_figure<DB: DrawingBackend>(
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
