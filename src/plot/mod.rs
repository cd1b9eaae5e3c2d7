//! SVG/PNG plots of polars, point distributions and rotor results (plotters, shipped font).
