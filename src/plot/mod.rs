//! SVG/PNG plots of polars, point distributions and rotor results (plotters, shipped font).
//!
//! * [`figure`] — solver-independent description of a multi-panel line plot.
//! * [`render`] — draws a [`Figure`] to SVG or PNG (chosen by the file extension).
//! * [`font`] — the embedded DejaVu Sans font used for all text.
//! * [`polar_plots`] — Cl–α, Cd–Cl, Cl/Cd–α, Cm–α overlays of polars.
//! * [`point_plots`] — Cp(x) and boundary-layer distributions (H, Cf, N) at one α.
//! * [`rotor_plots`] — blade α vs azimuth, takeoff time histories, power required.

pub mod error;
pub mod figure;
pub mod font;
pub mod point_plots;
pub mod polar_plots;
pub mod render;
pub mod rotor_plots;

pub use error::PlotError;
pub use figure::{AxisRange, Figure, Line, Marker, MarkerKind, Panel, Series, Style};
pub use render::{render, render_svg_string, render_with, RenderParams};
