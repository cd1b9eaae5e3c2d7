//! Pixel layout of a figure: the panel grid, the title size and the rows of the shared
//! legend, measured with the shipped font.

use plotters::style::{FontDesc, FontFamily, FontStyle};

use super::error::PlotError;
use super::figure::{Figure, MarkerKind, Style};
use super::font::FONT_FAMILY;
use super::render::RenderParams;

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
