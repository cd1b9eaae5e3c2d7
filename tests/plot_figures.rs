//! Section figures (polars, point distributions) rendered to SVG and PNG; the rotor figures
//! are in `plot_rotor_figures.rs`.
//!
//! Inputs: XFOIL 6.99 reference polars and BL/Cp dumps of the NACA 8-H-12 at Re 1.9e6,
//! M 0.41, free and fixed (x/c = 0.07) transition, α = 4° (tests/data/xfoil).
//! Each figure is checked as SVG (size, title, labels, series text, series colours) and as PNG
//! (signature, IHDR size, decoded pixels: series colours present, dark text in the title strip).

use polargen::geometry::airfoil_by_name_or_path;
use polargen::plot::drag_axis::CdAxis;
use polargen::plot::point_plots::{
    bl_figure, cp_figure, point_figure, with_airfoil_contour, PointCase,
};
use polargen::plot::polar_plots::{
    mark_lift_coefficient, polar_figure, polar_figure_styled, PolarCurve,
};
use polargen::plot::{AxisRange, Line, Style};
use polargen::section::PolarPoint;

mod plot_support;
mod table_support;
use plot_support::{attr, render_and_check, svg_color, svg_texts};
use table_support::xfoil_reference as read_polar;
use table_support::xfoil_support;

/// Upper-surface distributions from an XFOIL BL dump: (x, Cf, Hk), LE → TE.
fn read_bl_upper(name: &str) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let rows: Vec<Vec<f64>> = xfoil_support::dump(name)
        .into_iter()
        .filter(|r| r.len() == 12)
        .collect();
    // Upper surface runs TE → LE: up to the first minimum of x.
    let le = (1..rows.len())
        .find(|&i| rows[i][1] > rows[i - 1][1])
        .expect("leading edge")
        - 1;
    let upper: Vec<&Vec<f64>> = rows[..=le].iter().rev().collect();
    (
        upper.iter().map(|r| r[1]).collect(),
        upper.iter().map(|r| r[6]).collect(),
        upper.iter().map(|r| r[7]).collect(),
    )
}

/// Cp(x) from an XFOIL CPWR dump.
fn read_cp(name: &str) -> (Vec<f64>, Vec<f64>) {
    xfoil_support::cp(name).into_iter().unzip()
}

#[test]
fn polar_overlay_clean_vs_fixed_transition() {
    let free = read_polar("naca8h12_Re1.9e6_M0.41_free.csv");
    let mut fixed = read_polar("naca8h12_Re1.9e6_M0.41_xtr0.07.csv");
    // An unconverged point with absurd values must not be drawn.
    fixed.push(PolarPoint {
        alpha: 30.0,
        cl: 50.0,
        cd: 9.0,
        cm: 7.0,
        converged: false,
        ..fixed[0]
    });
    let fig = polar_figure(
        &[
            ("8-H-12 free transition", &free),
            ("8-H-12 xtr = 0.07", &fixed),
        ],
        "NACA 8-H-12, Re = 1.9e6, M = 0.41 (XFOIL 6.99)",
    );
    assert_eq!(fig.panels.len(), 5, "lift, drag, transition, Cl/Cd, Cm");
    let lift = &fig.panels[0];
    assert_eq!(lift.series[0].x.len(), free.len());
    assert_eq!(
        lift.series[1].x.len(),
        fixed.len() - 1,
        "unconverged point kept"
    );
    assert!(lift.series[1].y.iter().all(|&cl| cl < 2.0));
    // Transition panel: x_tr/c of both surfaces against Cl, the unconverged point left out of
    // the lines as everywhere (Cl 50 would be drawn at x_tr of fixed[0]).
    let transition = &fig.panels[2];
    assert_eq!(transition.series.len(), 4, "upper and lower per polar");
    let (upper, lower) = (&transition.series[2], &transition.series[3]);
    assert_eq!(upper.x.len(), fixed.len() - 1, "unconverged point kept");
    assert!(upper.y.iter().chain(&lower.y).all(|&cl| cl < 2.0));
    assert_eq!(
        (upper.style.line, lower.style.line),
        (Line::Solid, Line::Dashed)
    );
    assert_eq!(lower.label, "", "one legend entry per polar");
    // α = 4° (free): x_tr upper 0.3989 from the reference polar, at Cl 0.7402
    let i = transition.series[0]
        .y
        .iter()
        .position(|&cl| cl == 0.7402)
        .unwrap();
    assert_eq!(transition.series[0].x[i], 0.3989);
    // Drag polar: the attached-flow Cd axis cuts off the stalled tail (data to 0.116) and says so.
    let drag = &fig.panels[1];
    let AxisRange::Fixed { min, max } = drag.x_range else {
        panic!("drag polar Cd axis not limited: {:?}", drag.x_range)
    };
    assert_eq!(min, 0.0);
    assert!((0.012..0.03).contains(&max), "Cd axis to {max}");
    assert!(drag.mark_clipped);
    assert!(drag.x_label.contains("points beyond"), "{}", drag.x_label);
    // Cl/Cd at α = 4° (free): 0.7402 / 0.00597 from the reference polar.
    let ratio = &fig.panels[3].series[0];
    let i = ratio
        .x
        .iter()
        .position(|&a| a == 4.0)
        .expect("α = 4 present");
    approx::assert_relative_eq!(ratio.y[i], 0.7402 / 0.00597, max_relative = 1e-12);

    render_and_check(
        &fig,
        "polars",
        &[
            "8-H-12 free transition",
            "8-H-12 xtr = 0.07",
            "α [deg]",
            "Cl [-]",
            "Cd [-]",
            "Cl/Cd [-]",
            "Cm (c/4) [-]",
            "Drag polar",
            "Transition: upper solid, lower dashed",
            "x_tr/c [-]",
        ],
        &[0, 1],
    );
}

#[test]
fn polar_overlay_with_reference_points_and_dashes() {
    let free = read_polar("naca8h12_Re1.9e6_M0.41_free.csv");
    let fixed = read_polar("naca8h12_Re1.9e6_M0.41_xtr0.07.csv");
    let curves = [
        PolarCurve {
            label: "free",
            points: &free,
            style: Style::solid(0),
        },
        PolarCurve {
            label: "fixed 7 %",
            points: &fixed,
            style: Style::dashed(1),
        },
        PolarCurve {
            label: "XFOIL free (points)",
            points: &free,
            style: Style::points(2),
        },
    ];
    let fig = mark_lift_coefficient(
        polar_figure_styled(&curves, "Styles: solid, dashed, points", CdAxis::AllData),
        0.8,
    );
    assert_eq!(fig.panels[1].x_range, AxisRange::Auto, "--cd-axis all");
    let marked: Vec<usize> = fig.panels.iter().map(|p| p.markers.len()).collect();
    assert_eq!(
        marked,
        vec![1, 1, 1, 0, 0],
        "Cl = 0.8 line only on the Cl panels"
    );
    let svg = render_and_check(
        &fig,
        "polars_styled",
        &["fixed 7 %", "XFOIL free (points)", "Cl = 0.8"],
        &[0, 1],
    );
    // Points are drawn as circles: 47 per panel for the reference-point series (Cl/Cd all > 0).
    let circles = svg.matches(&format!("fill=\"{}\"", svg_color(2))).count();
    assert!(
        circles >= 5 * free.len(),
        "only {circles} reference circles"
    );
}

/// Circles filled in palette colour `i` in an SVG document.
fn circles(svg: &str, i: usize) -> usize {
    svg.split("<circle")
        .skip(1)
        .filter(|c| c.contains(&format!("fill=\"{}\"", svg_color(i))))
        .count()
}

#[test]
fn sparse_polars_get_point_symbols() {
    let free = read_polar("naca8h12_Re1.9e6_M0.41_free.csv");
    // 0.5° steps: the Cl/Cd peak is steeper than 1/40 of the axes per step → symbols on every
    // point of every line, 47 per panel (Cl/Cd: all Cd > 0)
    let fig = polar_figure(&[("free", &free)], "XFOIL, 0.5° steps");
    let svg = render_and_check(&fig, "polars_sparse", &["free"], &[0]);
    let visible: usize = fig
        .panels
        .iter()
        .flat_map(|p| p.series.iter().map(move |s| (p, s)))
        .map(|(p, s)| match p.x_range {
            AxisRange::Fixed { max, .. } => s.x.iter().filter(|&&x| x <= max).count(),
            AxisRange::Auto => s.x.len(),
        })
        .sum();
    // + 1: the legend sample
    assert_eq!(
        circles(&svg, 0),
        visible + 1,
        "one symbol per visible point"
    );
    // the same sweep interpolated to 0.1° steps is dense: no symbols at all
    let dense: Vec<PolarPoint> = free
        .windows(2)
        .filter(|w| w[1].alpha - w[0].alpha == 0.5)
        .flat_map(|w| {
            (0..5).map(move |k| {
                let t = f64::from(k) / 5.0;
                let mix = |a: f64, b: f64| a + t * (b - a);
                PolarPoint {
                    alpha: mix(w[0].alpha, w[1].alpha),
                    cl: mix(w[0].cl, w[1].cl),
                    cd: mix(w[0].cd, w[1].cd),
                    cm: mix(w[0].cm, w[1].cm),
                    xtr_top: mix(w[0].xtr_top, w[1].xtr_top),
                    xtr_bot: mix(w[0].xtr_bot, w[1].xtr_bot),
                    ..w[0]
                }
            })
        })
        .collect();
    let fig = polar_figure(&[("free", &dense)], "XFOIL, interpolated to 0.1° steps");
    let svg = render_and_check(&fig, "polars_dense", &["free"], &[0]);
    assert_eq!(circles(&svg, 0), 0, "no symbols on a dense polar");
}

#[test]
fn airfoil_contour_under_the_pressure_distribution() {
    let (x_cp, cp) = read_cp("naca8h12_Re1.9e6_M0.41_free_cp_a4.txt");
    let case = PointCase {
        label: "free transition",
        style: Style::solid(0),
        cp: (&x_cp, &cp),
        ..PointCase::default()
    };
    let foil = airfoil_by_name_or_path("naca8h12").unwrap();
    let fig = with_airfoil_contour(point_figure(&[case], "NACA 8-H-12, α = 4°", None), &foil);
    assert_eq!(fig.panels[0].contour.len(), foil.x.len(), "Cp panel");
    assert!(fig.panels[1..].iter().all(|p| p.contour.is_empty()));
    let svg = render_and_check(&fig, "point_contour", &["x/c [-]"], &[0]);
    // the contour is filled light grey; the x label is drawn once per panel, still four times
    assert!(svg.contains("#D7D7D7"), "no filled contour");
    let x_labels = svg_texts(&svg)
        .iter()
        .filter(|(_, t)| t == "x/c [-]")
        .count();
    assert_eq!(x_labels, 4);
}

#[test]
fn pressure_and_boundary_layer_distributions() {
    let (x_cp_free, cp_free) = read_cp("naca8h12_Re1.9e6_M0.41_free_cp_a4.txt");
    let (x_cp_fixed, cp_fixed) = read_cp("naca8h12_Re1.9e6_M0.41_xtr0.07_cp_a4.txt");
    let (x_free, cf_free, h_free) = read_bl_upper("naca8h12_Re1.9e6_M0.41_free_bl_a4.txt");
    let (x_fixed, cf_fixed, h_fixed) = read_bl_upper("naca8h12_Re1.9e6_M0.41_xtr0.07_bl_a4.txt");
    // The reference polar gives xtr_top = 0.3989 at α = 4° (free); the trip is at 0.07.
    let xtr_free = read_polar("naca8h12_Re1.9e6_M0.41_free.csv")
        .iter()
        .find(|p| p.alpha == 4.0)
        .map(|p| p.xtr_top);
    assert_eq!(xtr_free, Some(0.3989));
    // Synthetic amplification curves (only the plotting is under test): growing to Ncrit = 9 at
    // transition, N plotted over the laminar part only.
    let laminar = |x: &[f64], xtr: f64| -> (Vec<f64>, Vec<f64>) {
        x.iter()
            .filter(|&&x| x <= xtr)
            .map(|&x| (x, 9.0 * (x / xtr).powi(3)))
            .unzip()
    };
    let (xn_free, n_free) = laminar(&x_free, 0.3989);
    let (xn_fixed, n_fixed) = laminar(&x_fixed, 0.07);
    let cases = [
        PointCase {
            label: "free transition",
            style: Style::solid(0),
            cp: (&x_cp_free, &cp_free),
            h: (&x_free, &h_free),
            cf: (&x_free, &cf_free),
            n: (&xn_free, &n_free),
            x_transition: xtr_free,
        },
        PointCase {
            label: "xtr = 0.07",
            style: Style::dashed(1),
            cp: (&x_cp_fixed, &cp_fixed),
            h: (&x_fixed, &h_fixed),
            cf: (&x_fixed, &cf_fixed),
            n: (&xn_fixed, &n_fixed),
            x_transition: Some(0.07),
        },
    ];
    let title = "NACA 8-H-12, α = 4°, Re = 1.9e6, M = 0.41 (BL: upper surface)";
    let cp = cp_figure(&cases, title);
    assert!(cp.panels[0].y_inverted, "Cp axis must be inverted");
    let svg = render_and_check(
        &cp,
        "cp",
        &["Cp [-]", "x/c [-]", "free transition"],
        &[0, 1],
    );
    // Inverted axis: y tick labels (right-aligned text) sorted by value run down the page.
    let mut y_ticks: Vec<(f64, f64)> = svg_texts(&svg)
        .into_iter()
        .filter(|(tag, _)| tag.contains("text-anchor=\"end\""))
        .filter_map(|(tag, text)| Some((text.parse::<f64>().ok()?, attr(&tag, "y")?)))
        .collect();
    assert!(y_ticks.len() >= 4, "too few Cp tick labels: {y_ticks:?}");
    y_ticks.sort_by(|a, b| a.0.total_cmp(&b.0));
    assert!(
        y_ticks.windows(2).all(|w| w[1].1 > w[0].1),
        "Cp axis is not inverted in the SVG: {y_ticks:?}"
    );

    render_and_check(
        &bl_figure(&cases, title, Some(9.0)),
        "bl",
        &[
            "H [-]",
            "Cf [-]",
            "N [-]",
            "transition x/c = 0.399 (free transition)",
            "Ncrit = 9",
        ],
        &[0, 1],
    );
    render_and_check(
        &point_figure(&cases, title, Some(9.0)),
        "point",
        &[
            "Pressure distribution",
            "Shape factor",
            "Skin friction",
            "Amplification",
        ],
        &[0, 1],
    );
}
