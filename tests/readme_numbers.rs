//! The README's numbers on the clean versus tripped NACA 8-H-12 at the paper's condition are
//! computed here from the polars its figure is drawn from (`docs/naca8h12_Re1.9e6_M0.41_*.csv`,
//! made by the README's commands): Cd at Cl = 0.8 (on the interpolated polar, as the report and
//! the Python example read it), the best Cl/Cd and the lift-curve slope (least squares over the
//! usable points (converged, not in massive separation) with α in [`SLOPE_WINDOW_DEG`]). The README's paragraph is this file's
//! output (`UPDATE_README=1 cargo test --test readme_numbers` rewrites it), so the README states
//! the numbers the code gives; `python/examples/clean_vs_contaminated.py` computes the same
//! polars and prints the same values.

mod xfoil_support;

use polargen::section::PolarPoint;
use polargen::table::{alpha_at_cl, read_table, PolarTable};
use std::path::Path;

/// The lift coefficient of the paper's Table 5.
const TABLE5_CL: f64 = 0.8;

/// α window of the lift-curve slope \[deg\] (the attached range of both polars).
const SLOPE_WINDOW_DEG: (f64, f64) = (-2.0, 6.0);

/// What the paragraph states of one polar.
struct Numbers {
    cd_at_cl08: f64,
    best_ld: f64,
    slope: f64,
}

fn polar(trip: &str) -> PolarTable {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("docs")
        .join(format!("naca8h12_Re1.9e6_M0.41_{trip}.csv"));
    read_table(&path).unwrap()
}

fn numbers(table: &PolarTable) -> Numbers {
    let (at, points) = table.polars().next().unwrap();
    let found = alpha_at_cl(table, TABLE5_CL, at.reynolds, at.mach, -10.0, 20.0).unwrap();
    let ok: Vec<&PolarPoint> = points.iter().filter(|p| p.usable()).collect();
    let best_ld = ok.iter().map(|p| p.cl / p.cd).fold(f64::MIN, f64::max);
    let window: Vec<&&PolarPoint> = ok
        .iter()
        .filter(|p| p.alpha >= SLOPE_WINDOW_DEG.0 && p.alpha <= SLOPE_WINDOW_DEG.1)
        .collect();
    let n = window.len() as f64;
    let (sx, sy) = window
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.alpha, b + p.cl));
    let (mx, my) = (sx / n, sy / n);
    let (sxy, sxx) = window.iter().fold((0.0, 0.0), |(a, b), p| {
        (a + (p.alpha - mx) * (p.cl - my), b + (p.alpha - mx).powi(2))
    });
    Numbers {
        cd_at_cl08: found.lookup.cd,
        best_ld,
        slope: sxy / sxx,
    }
}

/// The README's paragraph as the polars give it.
fn paragraph() -> String {
    let (c, d) = (numbers(&polar("free")), numbers(&polar("xtr0.07")));
    format!(
        "With the trip the laminar runs are gone: at Cl = {TABLE5_CL} the drag goes from {:.5} to \
         {:.5} ({:+.0} %) and the best Cl/Cd falls from {:.0} to {:.0}, and the lift-curve slope \
         falls by {:.1} % ({:.3} → {:.3} per degree, least squares over α {}…{}°), as the paper \
         says of its own polars.\n",
        c.cd_at_cl08,
        d.cd_at_cl08,
        100.0 * (d.cd_at_cl08 / c.cd_at_cl08 - 1.0),
        c.best_ld,
        d.best_ld,
        100.0 * (1.0 - d.slope / c.slope),
        c.slope,
        d.slope,
        minus(SLOPE_WINDOW_DEG.0),
        minus(SLOPE_WINDOW_DEG.1),
    )
}

/// A number as the README writes it, with a typographic minus.
fn minus(v: f64) -> String {
    format!("{v}").replace('-', "−")
}

#[test]
fn readme_contamination_numbers_are_current() {
    xfoil_support::check_readme_block(
        "contamination numbers",
        "UPDATE_README=1 cargo test --test readme_numbers",
        &paragraph(),
    );
}

/// The trip roughly doubles the drag at Cl = 0.8 and costs lift slope, as the paper says
/// (its Table 5: 0.006 → 0.012; "lift-curve slope about 15 % lower").
#[test]
fn the_trip_doubles_drag_and_costs_slope() {
    let (c, d) = (numbers(&polar("free")), numbers(&polar("xtr0.07")));
    let ratio = d.cd_at_cl08 / c.cd_at_cl08;
    assert!(ratio > 1.7 && ratio < 2.2, "Cd ratio {ratio}");
    let loss = 1.0 - d.slope / c.slope;
    assert!(loss > 0.08 && loss < 0.2, "slope loss {loss}");
}
