//! A small, solver-independent description of a multi-panel line plot.
//!
//! A [`Figure`] is a title and a list of [`Panel`]s (laid out in a grid by the renderer); each
//! panel holds [`Series`] (polylines and/or point sets) and [`Marker`]s (vertical/horizontal
//! reference lines, single highlighted points). Nothing here knows about plotters: the
//! description is plain data that [`render`](fn@super::render) turns into SVG or PNG.

/// How a series' line is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Line {
    /// Continuous line.
    Solid,
    /// Dashed line.
    Dashed,
    /// No line (points only; combine with [`Style::points`]).
    None,
}

/// Visual style of a series: a palette colour index, a line kind and optional point symbols.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Style {
    /// Index into the renderer's colour palette (wraps around).
    pub color: usize,
    /// Line kind.
    pub line: Line,
    /// Draw a filled circle at every data point. Without it a line still gets them where its
    /// data are sparse (the rule of `sparse`).
    pub points: bool,
}

impl Default for Style {
    /// Solid line in the first palette colour.
    fn default() -> Self {
        Self::solid(0)
    }
}

impl Style {
    /// Solid line in palette colour `color`.
    pub fn solid(color: usize) -> Self {
        Self {
            color,
            line: Line::Solid,
            points: false,
        }
    }

    /// Dashed line in palette colour `color`.
    pub fn dashed(color: usize) -> Self {
        Self {
            color,
            line: Line::Dashed,
            points: false,
        }
    }

    /// Points only (no line) in palette colour `color`, e.g. for reference data.
    pub fn points(color: usize) -> Self {
        Self {
            color,
            line: Line::None,
            points: true,
        }
    }

    /// The same style with point symbols added.
    pub fn with_points(mut self) -> Self {
        self.points = true;
        self
    }
}

/// One data series: a labelled polyline through (`x[i]`, `y[i]`).
///
/// Non-finite values (NaN, ±∞) break the line into separate pieces, so gaps in the data show
/// as gaps in the plot. `x` and `y` must have the same length (checked when rendering).
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend text; an empty label keeps the series out of the legend.
    pub label: String,
    /// Abscissae.
    pub x: Vec<f64>,
    /// Ordinates.
    pub y: Vec<f64>,
    /// Colour, line kind and point symbols.
    pub style: Style,
}

impl Series {
    /// A series from owned coordinate vectors.
    pub fn new(label: impl Into<String>, x: Vec<f64>, y: Vec<f64>, style: Style) -> Self {
        Self {
            label: label.into(),
            x,
            y,
            style,
        }
    }

    /// A series copied from coordinate slices.
    pub fn from_slices(label: impl Into<String>, x: &[f64], y: &[f64], style: Style) -> Self {
        Self::new(label, x.to_vec(), y.to_vec(), style)
    }

    /// A series from (x, y) pairs.
    pub fn from_pairs(
        label: impl Into<String>,
        pairs: impl IntoIterator<Item = (f64, f64)>,
        style: Style,
    ) -> Self {
        let (x, y) = pairs.into_iter().unzip();
        Self::new(label, x, y, style)
    }
}

/// Geometry of a [`Marker`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MarkerKind {
    /// Vertical line across the panel at this x (e.g. a transition location).
    VLine(f64),
    /// Horizontal line across the panel at this y (e.g. a critical amplification factor).
    HLine(f64),
    /// A highlighted point (x, y) (e.g. the maximum of a curve).
    Point(f64, f64),
}

/// A reference mark drawn on top of the series of a panel.
#[derive(Clone, Debug, PartialEq)]
pub struct Marker {
    /// What is marked, and where.
    pub kind: MarkerKind,
    /// Legend text; an empty label keeps the marker out of the legend.
    pub label: String,
    /// Palette colour index.
    pub color: usize,
}

impl Marker {
    /// A vertical reference line at `x`.
    pub fn vline(x: f64, label: impl Into<String>, color: usize) -> Self {
        Self {
            kind: MarkerKind::VLine(x),
            label: label.into(),
            color,
        }
    }

    /// A horizontal reference line at `y`.
    pub fn hline(y: f64, label: impl Into<String>, color: usize) -> Self {
        Self {
            kind: MarkerKind::HLine(y),
            label: label.into(),
            color,
        }
    }

    /// A highlighted point at (`x`, `y`).
    pub fn point(x: f64, y: f64, label: impl Into<String>, color: usize) -> Self {
        Self {
            kind: MarkerKind::Point(x, y),
            label: label.into(),
            color,
        }
    }
}

/// Range of one axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AxisRange {
    /// Data extent (series and markers) widened by the renderer's padding fraction.
    Auto,
    /// Exactly `[min, max]` in data units; data outside is clipped.
    Fixed {
        /// Lower limit.
        min: f64,
        /// Upper limit.
        max: f64,
    },
}

/// One panel (one set of axes) of a figure.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    /// Caption above the axes (may be empty).
    pub title: String,
    /// x-axis label, with units, e.g. `"α [deg]"`.
    pub x_label: String,
    /// y-axis label, with units.
    pub y_label: String,
    /// Data series, drawn in order.
    pub series: Vec<Series>,
    /// Reference marks, drawn over the series.
    pub markers: Vec<Marker>,
    /// x-axis range.
    pub x_range: AxisRange,
    /// y-axis range.
    pub y_range: AxisRange,
    /// Spacing of labelled x ticks (e.g. 90° for azimuth); `None` picks a 1-2-2.5-5 step.
    pub x_tick_step: Option<f64>,
    /// Spacing of labelled y ticks; `None` picks a 1-2-2.5-5 step.
    pub y_tick_step: Option<f64>,
    /// Draw the y axis increasing downwards (as for pressure coefficients, −Cp up).
    pub y_inverted: bool,
    /// Mark data outside a fixed range: an arrowhead in the series colour at the edge of the
    /// axes, pointing to where each point lies.
    pub mark_clipped: bool,
    /// An outline (e.g. the airfoil, x/c and y/c) drawn true to scale in a strip below the
    /// axes, on the same x axis (which then carries its tick labels); empty for none.
    pub contour: Vec<(f64, f64)>,
}

impl Panel {
    /// An empty panel with automatic ranges.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            markers: Vec::new(),
            x_range: AxisRange::Auto,
            y_range: AxisRange::Auto,
            x_tick_step: None,
            y_tick_step: None,
            y_inverted: false,
            mark_clipped: false,
            contour: Vec::new(),
        }
    }

    /// Adds a series.
    pub fn with_series(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// Adds a marker.
    pub fn with_marker(mut self, marker: Marker) -> Self {
        self.markers.push(marker);
        self
    }

    /// Fixes the x range to `[min, max]`.
    pub fn with_x_range(mut self, min: f64, max: f64) -> Self {
        self.x_range = AxisRange::Fixed { min, max };
        self
    }

    /// Fixes the y range to `[min, max]` (data units, also when inverted).
    pub fn with_y_range(mut self, min: f64, max: f64) -> Self {
        self.y_range = AxisRange::Fixed { min, max };
        self
    }

    /// Labels x ticks at multiples of `step`.
    pub fn with_x_tick_step(mut self, step: f64) -> Self {
        self.x_tick_step = Some(step);
        self
    }

    /// Labels y ticks at multiples of `step`.
    pub fn with_y_tick_step(mut self, step: f64) -> Self {
        self.y_tick_step = Some(step);
        self
    }

    /// Draws the y axis increasing downwards.
    pub fn with_y_inverted(mut self) -> Self {
        self.y_inverted = true;
        self
    }

    /// Marks data outside fixed ranges by arrowheads at the edges.
    pub fn with_clipped_marked(mut self) -> Self {
        self.mark_clipped = true;
        self
    }

    /// Draws the outline through `points` (closed back to the first) in a strip below the axes.
    pub fn with_contour(mut self, points: Vec<(f64, f64)>) -> Self {
        self.contour = points;
        self
    }
}

/// A figure: a title over a grid of panels, with one legend shared by all panels.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// Title printed above all panels.
    pub title: String,
    /// Panels, laid out row by row (1–3 in one row, 4 as 2 × 2, more in a near-square grid).
    pub panels: Vec<Panel>,
}

impl Figure {
    /// A figure with a title and no panels yet.
    pub fn new(title: impl Into<String>) -> Self {
        Self {
            title: title.into(),
            panels: Vec::new(),
        }
    }

    /// Adds a panel.
    pub fn with_panel(mut self, panel: Panel) -> Self {
        self.panels.push(panel);
        self
    }
}
