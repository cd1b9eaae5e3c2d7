//! Domain figures (polars, point distributions, rotor results) rendered to SVG and PNG.
//!
//! Inputs: XFOIL 6.99 reference polars and BL/Cp dumps of the NACA 8-H-12 at Re 1.9e6,
//! M 0.41, free and fixed (x/c = 0.07) transition, α = 4° (tests/data/xfoil); rotor inputs
//! are synthetic but shaped like the study's results (no rotor model is needed to test plots).
//! Each figure is checked as SVG (size, title, labels, series text, series colours) and as PNG
//! (signature, IHDR size, decoded pixels: series colours present, dark text in the title strip).

use std::f64::consts::PI;
use std::path::PathBuf;

use polargen::geometry::airfoil_by_name_or_path;
use polargen::plot::drag_axis::CdAxis;
use polargen::plot::point_plots::{
    bl_figure, cp_figure, point_figure, with_airfoil_contour, PointCase,
};
use polargen::plot::polar_plots::{
    mark_lift_coefficient, polar_figure, polar_figure_styled, PolarCurve,
};
use polargen::plot::rotor_plots::{
    alpha_azimuth_figure, power_required_figure, takeoff_figure, AzimuthCase, PowerCase,
    TakeoffCase,
};
use polargen::plot::{render, AxisRange, Figure, Line, Style};
use polargen::section::PolarPoint;

mod table_support;
use table_support::xfoil_reference as read_polar;
use table_support::xfoil_support;

/// Directory for this test run's images (kept, so they can be inspected).
fn out_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("polargen-plot-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

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

/// (opening tag, trimmed content) of every `<text>` element of an SVG document.
fn svg_texts(svg: &str) -> Vec<(String, String)> {
    svg.split("<text")
        .skip(1)
        .filter_map(|part| {
            let (tag, rest) = part.split_once('>')?;
            let content = rest.split("</text>").next()?.trim().to_string();
            Some((tag.to_string(), content))
        })
        .collect()
}

/// Numeric attribute `name` of an SVG tag.
fn attr(tag: &str, name: &str) -> Option<f64> {
    tag.split(&format!(" {name}=\""))
        .nth(1)?
        .split('"')
        .next()?
        .parse()
        .ok()
}

/// SVG colour string of palette index `i` as plotters writes it.
fn svg_color(i: usize) -> &'static str {
    ["#1F77B4", "#D62728", "#2CA02C", "#FF7F0E"][i]
}

/// RGB of palette index `i`.
fn rgb(i: usize) -> [u8; 3] {
    [[31, 119, 180], [214, 39, 40], [44, 160, 44], [255, 127, 14]][i]
}

/// Renders `fig` as SVG and PNG under `name`, checks both, returns the SVG text.
fn render_and_check(fig: &Figure, name: &str, texts: &[&str], colors: &[usize]) -> String {
    let dir = out_dir();
    let svg_path = dir.join(format!("{name}.svg"));
    let png_path = dir.join(format!("{name}.png"));
    render(fig, &svg_path).expect("svg render");
    render(fig, &png_path).expect("png render");

    let svg = std::fs::read_to_string(&svg_path).expect("svg written");
    assert!(svg.len() > 10_000, "{name}.svg only {} bytes", svg.len());
    assert!(svg.starts_with("<svg"), "{name}.svg is not an SVG document");
    assert!(
        svg.trim_end().ends_with("</svg>"),
        "{name}.svg is truncated"
    );
    assert!(svg.contains(&fig.title), "{name}.svg lacks its title");
    for t in texts {
        assert!(svg.contains(t), "{name}.svg lacks text {t:?}");
    }
    for &c in colors {
        assert!(
            svg.contains(&format!("stroke=\"{}\"", svg_color(c))),
            "{name}.svg has no line in palette colour {c}"
        );
    }

    let png = std::fs::read(&png_path).expect("png written");
    assert!(png.len() > 20_000, "{name}.png only {} bytes", png.len());
    let img = png_decode::decode(&png).expect("png decodes");
    // grid: one row up to 3 panels, 4 as 2 × 2, 5 and 6 as 2 × 3
    let n = fig.panels.len() as u32;
    let cols = if n <= 3 {
        n
    } else {
        (f64::from(n)).sqrt().ceil() as u32
    };
    assert_eq!(img.width, 720 * cols, "{name}.png width");
    let rows = n.div_ceil(cols);
    assert!(
        img.height >= 50 + 520 * rows,
        "{name}.png height {}",
        img.height
    );
    let non_white = img.pixels.iter().filter(|p| **p != [255, 255, 255]).count();
    let fraction = non_white as f64 / img.pixels.len() as f64;
    assert!(
        fraction > 0.02,
        "{name}.png is nearly blank ({fraction:.4})"
    );
    for &c in colors {
        let n = img.pixels.iter().filter(|p| **p == rgb(c)).count();
        assert!(
            n > 200,
            "{name}.png has only {n} pixels of palette colour {c}"
        );
    }
    // Title text: dark anti-aliased glyph pixels in the title strip (font rendered).
    let dark_title = img.pixels[..(img.width * 50) as usize]
        .iter()
        .filter(|p| p.iter().all(|&v| v < 80))
        .count();
    assert!(
        dark_title > 300,
        "{name}.png title strip has {dark_title} dark pixels"
    );
    svg
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

/// Synthetic blade local α at r/R = 0.9 (test input only): pitch θ plus the inflow angle
/// atan(λ / (r + μ sin ψ)) of a blade element in forward flight, ψ = 0 at the
/// rear, so the tangential speed is lowest and α highest on the retreating side (ψ = 270°).
fn synthetic_alpha(theta_deg: f64, lambda: f64, mu: f64) -> (Vec<f64>, Vec<f64>) {
    let r = 0.9;
    (0..=72)
        .map(|k| {
            let psi = 5.0 * k as f64;
            let s = (psi * PI / 180.0).sin();
            let phi = lambda / (r + mu * s);
            (psi, theta_deg + phi.atan().to_degrees())
        })
        .unzip()
}

#[test]
fn rotor_alpha_vs_azimuth() {
    let (psi, a_clean) = synthetic_alpha(2.5, 0.03, 0.22);
    let (_, a_cont) = synthetic_alpha(2.5, 0.045, 0.22);
    let cases = [
        AzimuthCase {
            label: "clean",
            style: Style::solid(0),
            psi_deg: &psi,
            alpha_deg: &a_clean,
        },
        AzimuthCase {
            label: "contaminated",
            style: Style::dashed(1),
            psi_deg: &psi,
            alpha_deg: &a_cont,
        },
    ];
    let fig = alpha_azimuth_figure(&cases, "Blade local α at r = 0.9 R, 60 kt");
    // The maximum must be on the retreating side (ψ = 270°) for μ > 0.
    let max_label = &fig.panels[0].markers[0].label;
    assert!(max_label.contains("ψ = 270°"), "{max_label}");
    let svg = render_and_check(
        &fig,
        "alpha_azimuth",
        &["azimuth ψ [deg] (0 = rear)", "local α [deg]", "max clean"],
        &[0, 1],
    );
    // Azimuth ticks every 45°.
    let texts: Vec<String> = svg_texts(&svg).into_iter().map(|(_, t)| t).collect();
    for tick in ["0", "90", "180", "270", "360"] {
        assert!(
            texts.iter().any(|t| t == tick),
            "azimuth tick {tick} missing"
        );
    }
}

#[test]
fn rotor_takeoff_and_power_required() {
    let t: Vec<f64> = (0..=150).map(|k| 0.1 * k as f64).collect();
    let history = |liftoff: f64, scale: f64| {
        let speed: Vec<f64> = t
            .iter()
            .map(|&t| 50.0 * (1.0 - (-t / (6.0 * scale)).exp()))
            .collect();
        let height: Vec<f64> = t
            .iter()
            .map(|&t| (2.0 * (t - liftoff) / scale).max(0.0).powf(1.5))
            .collect();
        let rpm: Vec<f64> = t
            .iter()
            .map(|&t| 350.0 - 150.0 * (-t / (4.0 * scale)).exp())
            .collect();
        let flap: Vec<f64> = t
            .iter()
            .map(|&t| 4.0 * scale * (t / 3.0).min(1.0) * (-t / 12.0).exp())
            .collect();
        (speed, height, rpm, flap)
    };
    let (s1, h1, r1, f1) = history(8.0, 1.0);
    let (s2, h2, r2, f2) = history(9.5, 1.15);
    let cases = [
        TakeoffCase {
            label: "clean",
            style: Style::solid(0),
            t: &t,
            speed_kt: &s1,
            height_m: &h1,
            rotor_rpm: &r1,
            flapping_deg: &f1,
            liftoff_t: Some(8.0),
        },
        TakeoffCase {
            label: "contaminated",
            style: Style::dashed(1),
            t: &t,
            speed_kt: &s2,
            height_m: &h2,
            rotor_rpm: &r2,
            flapping_deg: &f2,
            liftoff_t: Some(9.5),
        },
    ];
    render_and_check(
        &takeoff_figure(&cases, "Takeoff, m = 450 kg, standard atmosphere"),
        "takeoff",
        &[
            "speed [kt]",
            "height [m]",
            "rotor speed [rpm]",
            "flapping β [deg]",
            "15 m obstacle",
            "lift-off, clean (t = 8.0 s)",
        ],
        &[0, 1],
    );

    let v: Vec<f64> = (0..=12).map(|k| 30.0 + 5.0 * k as f64).collect();
    let curve = |k: f64| -> (Vec<f64>, Vec<f64>) {
        v.iter()
            .map(|&v| {
                let ms = v * 0.514444;
                let thrust = k
                    * (0.5 * 1.225 * ms * ms
                        + 4414.0 * 4414.0 / (0.5 * 1.225 * ms * ms * 55.4 * 4.0));
                (thrust * ms / 1000.0, thrust)
            })
            .unzip()
    };
    let (p1, t1) = curve(1.0);
    let (p2, t2) = curve(1.14);
    let power = [
        PowerCase {
            label: "clean",
            style: Style::solid(0),
            speed_kt: &v,
            power_kw: &p1,
            thrust_n: &t1,
        },
        PowerCase {
            label: "contaminated",
            style: Style::dashed(1),
            speed_kt: &v,
            power_kw: &p2,
            thrust_n: &t2,
        },
    ];
    render_and_check(
        &power_required_figure(&power, "Power required in level flight"),
        "power",
        &["airspeed [kt]", "power [kW]", "propeller thrust [N]"],
        &[0, 1],
    );
}

/// Minimal PNG reader for the tests: zlib/DEFLATE (RFC 1950/1951) and PNG scanline filters
/// (PNG spec §9), 8-bit RGB or RGBA, non-interlaced — what plotters' encoder writes.
mod png_decode {
    /// Decoded image: RGB pixels row by row.
    pub struct Image {
        pub width: u32,
        pub height: u32,
        pub pixels: Vec<[u8; 3]>,
    }

    fn be32(b: &[u8]) -> u32 {
        u32::from_be_bytes([b[0], b[1], b[2], b[3]])
    }

    /// Decodes a PNG file.
    pub fn decode(png: &[u8]) -> Result<Image, String> {
        if png.len() < 8 || png[..8] != [0x89, b'P', b'N', b'G', 0x0D, 0x0A, 0x1A, 0x0A] {
            return Err("bad PNG signature".into());
        }
        let mut pos = 8;
        let (mut width, mut height, mut channels) = (0, 0, 0);
        let mut idat = Vec::new();
        while pos + 8 <= png.len() {
            let len = be32(&png[pos..]) as usize;
            let kind = &png[pos + 4..pos + 8];
            let data = png.get(pos + 8..pos + 8 + len).ok_or("truncated chunk")?;
            match kind {
                b"IHDR" => {
                    width = be32(data);
                    height = be32(&data[4..]);
                    if data[8] != 8 || data[12] != 0 {
                        return Err("only 8-bit non-interlaced PNGs".into());
                    }
                    channels = match data[9] {
                        2 => 3,
                        6 => 4,
                        c => return Err(format!("colour type {c} unsupported")),
                    };
                }
                b"IDAT" => idat.extend_from_slice(data),
                b"IEND" => break,
                _ => {}
            }
            pos += 12 + len;
        }
        if width == 0 || height == 0 {
            return Err("missing IHDR".into());
        }
        let raw = inflate(idat.get(2..).ok_or("empty IDAT")?)?;
        let stride = width as usize * channels;
        if raw.len() < (stride + 1) * height as usize {
            return Err("not enough image data".into());
        }
        let mut prev = vec![0u8; stride];
        let mut pixels = Vec::with_capacity((width * height) as usize);
        for row in 0..height as usize {
            let line = &raw[row * (stride + 1)..(row + 1) * (stride + 1)];
            let mut cur = line[1..].to_vec();
            for i in 0..stride {
                let a = if i >= channels {
                    cur[i - channels] as i16
                } else {
                    0
                };
                let b = prev[i] as i16;
                let c = if i >= channels {
                    prev[i - channels] as i16
                } else {
                    0
                };
                let pred = match line[0] {
                    0 => 0,
                    1 => a,
                    2 => b,
                    3 => (a + b) / 2,
                    4 => {
                        let p = a + b - c;
                        let (pa, pb, pc) = ((p - a).abs(), (p - b).abs(), (p - c).abs());
                        if pa <= pb && pa <= pc {
                            a
                        } else if pb <= pc {
                            b
                        } else {
                            c
                        }
                    }
                    f => return Err(format!("bad filter {f}")),
                };
                cur[i] = cur[i].wrapping_add(pred as u8);
            }
            pixels.extend(cur.chunks(channels).map(|p| [p[0], p[1], p[2]]));
            prev = cur;
        }
        Ok(Image {
            width,
            height,
            pixels,
        })
    }

    /// LSB-first bit reader over a DEFLATE stream.
    struct Bits<'a> {
        data: &'a [u8],
        pos: usize,
        bit: u32,
    }

    impl Bits<'_> {
        fn get(&mut self, n: u32) -> Result<u32, String> {
            let mut v = 0;
            for k in 0..n {
                let byte = *self.data.get(self.pos).ok_or("deflate stream ended")?;
                v |= (((byte >> self.bit) & 1) as u32) << k;
                self.bit += 1;
                if self.bit == 8 {
                    self.bit = 0;
                    self.pos += 1;
                }
            }
            Ok(v)
        }
    }

    /// Canonical Huffman code: number of codes per length and symbols in code order.
    struct Huffman {
        counts: [u16; 16],
        symbols: Vec<u16>,
    }

    impl Huffman {
        fn new(lengths: &[u8]) -> Self {
            let mut counts = [0u16; 16];
            for &l in lengths {
                counts[l as usize] += 1;
            }
            counts[0] = 0;
            let mut offsets = [0u16; 16];
            for l in 1..16 {
                offsets[l] = offsets[l - 1] + counts[l - 1];
            }
            let mut symbols = vec![0; lengths.len()];
            for (s, &l) in lengths.iter().enumerate() {
                if l != 0 {
                    symbols[offsets[l as usize] as usize] = s as u16;
                    offsets[l as usize] += 1;
                }
            }
            Self { counts, symbols }
        }

        fn decode(&self, bits: &mut Bits) -> Result<u16, String> {
            let (mut code, mut first, mut index) = (0i32, 0i32, 0i32);
            for len in 1..16 {
                code |= bits.get(1)? as i32;
                let count = self.counts[len] as i32;
                if code - first < count {
                    return Ok(self.symbols[(index + code - first) as usize]);
                }
                index += count;
                first = (first + count) << 1;
                code <<= 1;
            }
            Err("bad Huffman code".into())
        }
    }

    const LEN_BASE: [u16; 29] = [
        3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115,
        131, 163, 195, 227, 258,
    ];
    const LEN_EXTRA: [u8; 29] = [
        0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0,
    ];
    const DIST_BASE: [u16; 30] = [
        1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537,
        2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577,
    ];
    const DIST_EXTRA: [u8; 30] = [
        0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12,
        13, 13,
    ];

    /// Inflates a raw DEFLATE stream (RFC 1951).
    pub fn inflate(data: &[u8]) -> Result<Vec<u8>, String> {
        let mut bits = Bits {
            data,
            pos: 0,
            bit: 0,
        };
        let mut out: Vec<u8> = Vec::new();
        loop {
            let last = bits.get(1)?;
            match bits.get(2)? {
                0 => {
                    if bits.bit != 0 {
                        bits.bit = 0;
                        bits.pos += 1;
                    }
                    let p = bits.pos;
                    let len = u16::from_le_bytes([data[p], data[p + 1]]) as usize;
                    out.extend_from_slice(data.get(p + 4..p + 4 + len).ok_or("stored block")?);
                    bits.pos = p + 4 + len;
                }
                1 => {
                    let mut l = [8u8; 288];
                    l[144..256].fill(9);
                    l[256..280].fill(7);
                    block(
                        &mut bits,
                        &mut out,
                        &Huffman::new(&l),
                        &Huffman::new(&[5; 30]),
                    )?;
                }
                2 => {
                    let hlit = bits.get(5)? as usize + 257;
                    let hdist = bits.get(5)? as usize + 1;
                    let hclen = bits.get(4)? as usize + 4;
                    const ORDER: [usize; 19] = [
                        16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15,
                    ];
                    let mut cl = [0u8; 19];
                    for &o in &ORDER[..hclen] {
                        cl[o] = bits.get(3)? as u8;
                    }
                    let code_lengths = Huffman::new(&cl);
                    let mut lengths = Vec::with_capacity(hlit + hdist);
                    while lengths.len() < hlit + hdist {
                        match code_lengths.decode(&mut bits)? {
                            s @ 0..=15 => lengths.push(s as u8),
                            16 => {
                                let prev = *lengths.last().ok_or("repeat without length")?;
                                let n = 3 + bits.get(2)?;
                                lengths.extend(std::iter::repeat(prev).take(n as usize));
                            }
                            17 => {
                                let n = 3 + bits.get(3)?;
                                lengths.extend(std::iter::repeat(0).take(n as usize));
                            }
                            _ => {
                                let n = 11 + bits.get(7)?;
                                lengths.extend(std::iter::repeat(0).take(n as usize));
                            }
                        }
                    }
                    let lit = Huffman::new(&lengths[..hlit]);
                    let dist = Huffman::new(&lengths[hlit..]);
                    block(&mut bits, &mut out, &lit, &dist)?;
                }
                _ => return Err("bad block type".into()),
            }
            if last == 1 {
                return Ok(out);
            }
        }
    }

    /// Decodes one Huffman-coded block.
    fn block(
        bits: &mut Bits,
        out: &mut Vec<u8>,
        lit: &Huffman,
        dist: &Huffman,
    ) -> Result<(), String> {
        loop {
            let sym = lit.decode(bits)? as usize;
            if sym < 256 {
                out.push(sym as u8);
            } else if sym == 256 {
                return Ok(());
            } else {
                let i = sym - 257;
                let len = *LEN_BASE.get(i).ok_or("bad length")? as usize
                    + bits.get(LEN_EXTRA[i] as u32)? as usize;
                let d = dist.decode(bits)? as usize;
                let back = *DIST_BASE.get(d).ok_or("bad distance")? as usize
                    + bits.get(DIST_EXTRA[d] as u32)? as usize;
                let start = out.len().checked_sub(back).ok_or("distance too far")?;
                for k in 0..len {
                    out.push(out[start + k]);
                }
            }
        }
    }
}
