//! Drawing with plotters: the figure title, each panel (grid, ticks, series, markers) and the
//! shared legend, onto any plotters backend.

use plotters::chart::MeshStyle;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{format_tick, panel_limits, ticks, y_sign, TickedAxis, Ticks};
use super::clip::{inside, visible_pieces};
use super::error::PlotError;
use super::figure::{Figure, Line, MarkerKind, Panel};
use super::font::FONT_FAMILY;
use super::layout::{Layout, LegendEntry};
use super::render::RenderParams;
use super::sparse::{figure_is_sparse, shows_points};

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
    let sparse = figure_is_sparse(figure, p.padding);
    for (panel, cell) in figure.panels.iter().zip(cells.iter()) {
        draw_panel(cell, panel, p, sparse)?;
    }
    match cells.get(figure.panels.len()) {
        Some(cell) if layout.legend_in_cell => draw_legend(cell, layout, p),
        _ => draw_legend(&legend_area, layout, p),
    }
}

/// Draws one panel: axes, grid, series (with symbols on every point in a `sparse` figure),
/// markers, clipped-data arrowheads and the contour strip.
fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    p: &RenderParams,
    sparse: bool,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let sign = y_sign(panel);
    let (xlim, ylim) = panel_limits(panel, p.padding);
    let (area, strip) = if panel.contour.is_empty() {
        (area.clone(), None)
    } else {
        let height = area.dim_in_pixel().1;
        let (a, s) = area.split_vertically(height.saturating_sub(p.contour_strip_height));
        (a, Some(s))
    };
    let area = &area;
    // With a contour strip below, the strip carries the x tick labels and axis label.
    let x_label_area = if strip.is_some() { 0 } else { p.x_label_area };

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
        .margin_bottom(if strip.is_some() { 0 } else { p.margin })
        .x_label_area_size(x_label_area)
        .y_label_area_size(p.y_label_area)
        .build_cartesian_2d(x_coord, y_coord)
        .map_err(draw_err)?;

    let x_fmt = |v: &f64| {
        if strip.is_some() {
            String::new()
        } else {
            format_tick(*v, x_dec)
        }
    };
    let y_fmt = |v: &f64| format_tick(sign * *v, y_dec);
    let x_desc = if strip.is_some() { "" } else { &panel.x_label };
    let mut mesh = chart.configure_mesh();
    mesh_style(&mut mesh, p)
        .x_desc(x_desc)
        .y_desc(panel.y_label.as_str())
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
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
        if shows_points(s, sparse) {
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
    if panel.mark_clipped {
        draw_clipped_marks(&mut chart, panel, xlim, ylim)?;
    }
    if let Some(strip) = strip {
        draw_contour_strip(&strip, panel, xlim, p)?;
    }
    Ok(())
}

/// Tick-label count, fonts and grid-line colours of every panel's mesh (and contour strip).
fn mesh_style<'m, 'a, 'b, DB: DrawingBackend>(
    mesh: &'m mut MeshStyle<'a, 'b, TickedAxis, TickedAxis, DB>,
    p: &RenderParams,
) -> &'m mut MeshStyle<'a, 'b, TickedAxis, TickedAxis, DB> {
    mesh.x_labels(p.max_ticks)
        .y_labels(p.max_ticks)
        .label_style((FONT_FAMILY, p.tick_font))
        .axis_desc_style((FONT_FAMILY, p.axis_label_font))
        .bold_line_style(RGBColor(205, 205, 205))
        .light_line_style(RGBColor(238, 238, 238))
}

/// Length and half width (px) of the arrowheads that mark data outside the axes.
const CLIP_ARROW: (i32, i32) = (11, 5);

/// Top margin (px) of a contour strip: it sits close under the panel it belongs to.
const STRIP_TOP_MARGIN: u32 = 4;

/// An arrowhead in the series colour at the edge of the axes for every finite point outside
/// them, pointing towards the point (right for x beyond the axis, up for y above it, …).
fn draw_clipped_marks<DB: DrawingBackend>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<TickedAxis, TickedAxis>>,
    panel: &Panel,
    xlim: (f64, f64),
    ylim: (f64, f64),
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let sign = y_sign(panel);
    let side = |v: f64, (lo, hi): (f64, f64)| -> f64 {
        if v < lo {
            -1.0
        } else if v > hi {
            1.0
        } else {
            0.0
        }
    };
    let (length, half) = CLIP_ARROW;
    for s in &panel.series {
        let color = palette(s.style.color);
        let mut arrows = Vec::new();
        for (&x, &y) in s.x.iter().zip(&s.y) {
            let (x, y) = (x, sign * y);
            if !(x.is_finite() && y.is_finite()) || inside((x, y), xlim, ylim) {
                continue;
            }
            // Direction in pixels (y down), unit length.
            let (ux, uy) = (side(x, xlim), -side(y, ylim));
            let norm = ux.hypot(uy);
            let (ux, uy) = (ux / norm, uy / norm);
            let at = |l: i32, w: i32| {
                let (l, w) = (f64::from(l), f64::from(w));
                (
                    (-l * ux - w * uy).round() as i32,
                    (-l * uy + w * ux).round() as i32,
                )
            };
            let edge = (x.clamp(xlim.0, xlim.1), y.clamp(ylim.0, ylim.1));
            arrows.push(
                EmptyElement::at(edge)
                    + Polygon::new(
                        vec![(0, 0), at(length, half), at(length, -half)],
                        color.filled(),
                    ),
            );
        }
        chart.draw_series(arrows).map_err(draw_err)?;
    }
    Ok(())
}

/// Draws `panel.contour` (closed, filled light grey) true to scale into `strip`, on the
/// x axis `xlim` of the panel above it (same margins and label widths, so the x pixels line
/// up), with the panel's x tick labels and x label; the y scale equals the x scale unless the
/// outline is too thick for the strip.
fn draw_contour_strip<DB: DrawingBackend>(
    strip: &DrawingArea<DB, Shift>,
    panel: &Panel,
    xlim: (f64, f64),
    p: &RenderParams,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let x_ticks = ticks(xlim.0, xlim.1, p.max_ticks, panel.x_tick_step);
    let x_dec = x_ticks.decimals;
    let (w, h) = strip.dim_in_pixel();
    let plot_w = w.saturating_sub(3 * p.margin + p.y_label_area).max(1);
    let plot_h = h
        .saturating_sub(STRIP_TOP_MARGIN + p.margin + p.x_label_area)
        .max(1);
    let outline: Vec<(f64, f64)> = panel
        .contour
        .iter()
        .copied()
        .filter(|q| q.0.is_finite() && q.1.is_finite())
        .collect();
    let (lo, hi) = outline
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), q| {
            (lo.min(q.1), hi.max(q.1))
        });
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (0.0, 0.0) };
    let true_scale = (xlim.1 - xlim.0) * f64::from(plot_h) / f64::from(plot_w);
    let span = true_scale.max(1.1 * (hi - lo));
    let mid = 0.5 * (lo + hi);
    let ylim = (mid - 0.5 * span, mid + 0.5 * span);
    let no_ticks = Ticks {
        major: Vec::new(),
        minor: Vec::new(),
        decimals: None,
    };
    let mut chart = ChartBuilder::on(strip)
        .margin(p.margin)
        .margin_top(STRIP_TOP_MARGIN)
        .margin_right(2 * p.margin)
        .x_label_area_size(p.x_label_area)
        .y_label_area_size(p.y_label_area)
        .build_cartesian_2d(
            TickedAxis::new(xlim, x_ticks),
            TickedAxis::new(ylim, no_ticks),
        )
        .map_err(draw_err)?;
    let x_fmt = |v: &f64| format_tick(*v, x_dec);
    let mut mesh = chart.configure_mesh();
    mesh_style(&mut mesh, p)
        .x_desc(panel.x_label.as_str())
        .x_label_formatter(&x_fmt)
        .draw()
        .map_err(draw_err)?;
    let mut closed = outline;
    if let Some(&first) = closed.first() {
        closed.push(first);
    }
    if closed.iter().all(|&q| inside(q, xlim, ylim)) {
        chart
            .draw_series(std::iter::once(Polygon::new(
                closed.clone(),
                RGBColor(215, 215, 215).filled(),
            )))
            .map_err(draw_err)?;
    }
    for piece in visible_pieces(&closed, xlim, ylim) {
        chart
            .draw_series(LineSeries::new(piece, BLACK.stroke_width(1)))
            .map_err(draw_err)?;
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
    let (width, height) = area.dim_in_pixel();
    let (width, height) = (width as i32, height as i32);
    let sample = p.legend_sample_length as i32;
    let lw = p.line_width;
    let row_h = p.legend_row_height as i32;
    let row_width = |row: &[(LegendEntry, u32)]| {
        row.iter().map(|(_, w)| *w as i32).sum::<i32>() - p.legend_gap as i32
    };
    // In a grid cell: one left-aligned column, centred in the cell; in the strip: centred rows.
    let (column_width, top) = if layout.legend_in_cell {
        let widest = layout
            .legend_rows
            .iter()
            .map(|r| row_width(r))
            .max()
            .unwrap_or(0);
        (
            Some(widest),
            (height - row_h * layout.legend_rows.len() as i32) / 2,
        )
    } else {
        (None, 0)
    };
    for (row_index, row) in layout.legend_rows.iter().enumerate() {
        let mut x =
            ((width - column_width.unwrap_or_else(|| row_width(row))) / 2).max(p.margin as i32);
        let yc = top + row_index as i32 * row_h + row_h / 2;
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
