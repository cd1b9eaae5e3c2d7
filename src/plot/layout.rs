//! Pixel layout of a figure: the panel grid, the title size and the rows of the shared
//! legend, measured with the shipped font.

use plotters::style::{FontDesc, FontFamily, FontStyle};

use super::error::PlotError;
use super::figure::{Figure, MarkerKind, Style};
use super::font::FONT_FAMILY;
use super::render::RenderParams;
use super::sparse::{figure_is_sparse, shows_points};

/// Grid shape (rows, columns) for `n` panels: one row up to 3, else a near-square grid.
pub(crate) fn grid_shape(n: usize) -> (usize, usize) {
    if n <= 3 {
        (1, n.max(1))
    } else {
        let cols = (n as f64).sqrt().ceil() as usize;
        (n.div_ceil(cols), cols)
    }
}

/// One entry of the shared legend.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum LegendEntry {
    /// A data series: its label and style.
    Series(String, Style),
    /// A labelled marker: its label, kind (position ignored) and colour.
    Marker(String, MarkerKind, usize),
}

impl LegendEntry {
    pub(super) fn label(&self) -> &str {
        match self {
            Self::Series(l, _) | Self::Marker(l, _, _) => l,
        }
    }

    /// True when both entries name the same item (series: label, colour and line kind; the
    /// point symbol is merged).
    fn same_as(&self, other: &Self) -> bool {
        match (self, other) {
            (Self::Series(a, sa), Self::Series(b, sb)) => {
                a == b && sa.color == sb.color && sa.line == sb.line
            }
            (Self::Marker(a, ka, ca), Self::Marker(b, kb, cb)) => {
                a == b && ca == cb && std::mem::discriminant(ka) == std::mem::discriminant(kb)
            }
            _ => false,
        }
    }
}

/// Pixel layout of a figure: canvas size, grid and legend rows.
#[derive(Clone, Debug)]
pub(super) struct Layout {
    /// Canvas size (px).
    pub(super) size: (u32, u32),
    /// Panel grid (rows, columns).
    pub(super) grid: (usize, usize),
    /// Height of the title strip (px) (0 without a title).
    pub(super) title_height: u32,
    /// Title font size (px): [`RenderParams::title_font`], reduced so a long title fits the
    /// canvas width.
    pub(super) title_font: f64,
    /// Legend entries, by row.
    pub(super) legend_rows: Vec<Vec<(LegendEntry, u32)>>,
    /// The legend sits in the grid cell after the last panel (one entry per row), not in a
    /// strip below the grid: when the grid has a free cell and the entries fit its height.
    pub(super) legend_in_cell: bool,
}

impl Layout {
    /// Measures legend text with the shipped font and sizes the canvas.
    pub(super) fn new(figure: &Figure, p: &RenderParams) -> Result<Self, PlotError> {
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
        let mut widths: Vec<(LegendEntry, u32)> = Vec::new();
        for entry in legend_entries(figure, p) {
            let (text_w, _) = font
                .box_size(entry.label())
                .map_err(|e| PlotError::Draw(e.to_string()))?;
            widths.push((entry, p.legend_sample_length + 8 + text_w + p.legend_gap));
        }
        let free_cell = grid.0 * grid.1 > figure.panels.len();
        let cell_fits = |rows: usize| {
            rows as u32 * p.legend_row_height <= p.panel_height.saturating_sub(2 * p.margin)
        };
        let in_cell_width = p.panel_width.saturating_sub(2 * p.margin);
        let legend_in_cell = free_cell
            && cell_fits(widths.len())
            && widths
                .iter()
                .all(|(_, w)| *w <= in_cell_width + p.legend_gap);
        let rows: Vec<Vec<(LegendEntry, u32)>> = if legend_in_cell {
            widths.into_iter().map(|e| vec![e]).collect()
        } else {
            let mut rows: Vec<Vec<(LegendEntry, u32)>> = Vec::new();
            let mut row_width = 0;
            for (entry, w) in widths {
                match rows.last_mut() {
                    Some(row) if row_width + w <= usable => row.push((entry, w)),
                    _ => {
                        rows.push(vec![(entry, w)]);
                        row_width = 0;
                    }
                }
                row_width += w;
            }
            rows
        };
        let legend_height = if rows.is_empty() || legend_in_cell {
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
            legend_in_cell,
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

/// Distinct labelled series and markers of all panels, in order of first appearance. A
/// series entry shows the point symbol when the series is drawn with symbols
/// ([`shows_points`]).
fn legend_entries(figure: &Figure, p: &RenderParams) -> Vec<LegendEntry> {
    let mut entries: Vec<LegendEntry> = Vec::new();
    let mut add = |e: LegendEntry| {
        if e.label().is_empty() {
            return;
        }
        match entries.iter_mut().find(|o| o.same_as(&e)) {
            Some(LegendEntry::Series(_, style)) => {
                if let LegendEntry::Series(_, s) = e {
                    style.points |= s.points;
                }
            }
            Some(_) => {}
            None => entries.push(e),
        }
    };
    let sparse = figure_is_sparse(figure, p.padding);
    for panel in &figure.panels {
        for s in &panel.series {
            let style = Style {
                points: shows_points(s, sparse),
                ..s.style
            };
            add(LegendEntry::Series(s.label.clone(), style));
        }
        for m in &panel.markers {
            add(LegendEntry::Marker(m.label.clone(), m.kind, m.color));
        }
    }
    entries
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
}
