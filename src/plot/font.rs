//! The font shipped with the crate (DejaVu Sans, `assets/fonts/`), embedded in the binary and
//! registered with plotters' `ab_glyph` font support so that PNG text renders on machines
//! without system fonts or fontconfig.

use super::error::PlotError;

/// Font family name under which the shipped font is registered and which all plots use.
pub(crate) const FONT_FAMILY: &str = "sans-serif";

/// DejaVu Sans 2.37 (Bitstream Vera licence, see `assets/fonts/LICENSE`).
static DEJAVU_SANS: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// Registers the shipped font as [`FONT_FAMILY`] (normal style; plotters falls back to it for
/// bold/italic). Idempotent: calling it again replaces the entry with the same font.
pub(crate) fn register_shipped_font() -> Result<(), PlotError> {
    plotters::style::register_font(FONT_FAMILY, plotters::style::FontStyle::Normal, DEJAVU_SANS)
        .map_err(|_| PlotError::Font)
}
