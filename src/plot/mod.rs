//! SVG/PNG plots of polars, point distributions and rotor results (plotters, shipped font).
//!
//! The facade: the figure model ([`Figure`], [`Panel`], [`Series`], [`Marker`], [`Style`]),
//! [`render`] and its variants, [`check_image_path`], [`PlotError`], and the domain figures:
//!
//! * `figure` — solver-independent description of a multi-panel line plot.
//! * `render`, `layout`, `axes`, `clip`, `draw` — drawing a [`Figure`] to SVG or PNG (chosen
//!   by the file extension): entry points, pixel layout, tick scales, clipping, plotters calls.
//! * `font` — the embedded DejaVu Sans font used for all text.
//! * `sparse` — the rule that puts a symbol on every point of a sparse series.
//! * `spec` — [`figure_spec`]: a figure with the renderer's decisions taken (grid, axis
//!   limits, symbols), as plain data for another renderer (the Python package's matplotlib).
//! * [`polar_plots`] — Cl–α, Cl–Cd, Cl–x_tr, Cl/Cd–α, Cm–α overlays of polars, with the drag
//!   polar's Cd axis of [`drag_axis`].
//! * [`table_plots`] — the polars of table files overlaid (`polargen plot`).
//! * [`point_plots`] — Cp(x) over the airfoil contour and boundary-layer distributions (H, Cf,
//!   N) at one α.
//! * [`rotor_plots`] — blade α vs azimuth, takeoff time histories, power required.
//!
//! ```
//! use polargen::plot::{render, Figure, Panel, Series, Style};
//!
//! // Thin-airfoil lift, Cl = 2π α, drawn to SVG (a `.png` path gives a PNG).
//! let alpha: Vec<f64> = (-4..=8).map(f64::from).collect();
//! let cl: Vec<f64> = alpha.iter().map(|a| 2.0 * std::f64::consts::PI * a.to_radians()).collect();
//! let figure = Figure::new("Thin airfoil").with_panel(
//!     Panel::new("Lift", "α [deg]", "Cl [-]")
//!         .with_series(Series::new("Cl = 2πα", alpha, cl, Style::solid(0))),
//! );
//! let path = std::env::temp_dir().join("polargen_doc_thin_airfoil.svg");
//! render(&figure, &path)?;
//! # std::fs::remove_file(&path).ok();
//! # Ok::<(), polargen::plot::PlotError>(())
//! ```

mod axes;
mod clip;
pub mod drag_axis;
mod draw;
mod error;
mod figure;
mod font;
mod layout;
pub mod point_plots;
pub mod polar_plots;
mod render;
pub mod rotor_plots;
mod sparse;
mod spec;
pub mod table_plots;

pub use error::PlotError;
pub use figure::{AxisRange, Figure, Line, Marker, MarkerKind, Panel, Series, Style};
pub use render::{
    check_image_path, render, render_into_set, render_svg_string, render_with,
    render_with_legend_room, RenderParams,
};
pub use spec::{figure_spec, FigureSpec, MarkerSpec, PanelSpec, SeriesSpec};
