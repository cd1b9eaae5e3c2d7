//! NACA generators vs tabulated ordinates, vs an independent implementation (PDAS naca456)
//! and vs XFOIL 6.99's own `NACA` buffer geometry; mean-line properties by thin-airfoil
//! theory.

use polargen::geometry::{
    naca, CubicSpline, EndCondition, GeometryError, NacaOptions, NacaSection, TrailingEdge,
};
use std::f64::consts::PI;

mod xfoil_support;

/// Upper and lower surface y(x) splines of a generated contour, using only points with
/// x > x_min where both surfaces are single-valued in x.
fn surfaces(x: &[f64], y: &[f64], x_min: f64) -> (CubicSpline, CubicSpline) {
    let ile = (0..x.len()).min_by(|&a, &b| x[a].total_cmp(&x[b])).unwrap();
    let mut up: Vec<(f64, f64)> = (0..ile).rev().map(|i| (x[i], y[i])).collect();
    let mut lo: Vec<(f64, f64)> = (ile + 1..x.len()).map(|i| (x[i], y[i])).collect();
    up.retain(|p| p.0 > x_min);
    lo.retain(|p| p.0 > x_min);
    let mk = |v: &[(f64, f64)]| {
        let xs: Vec<f64> = v.iter().map(|p| p.0).collect();
        let ys: Vec<f64> = v.iter().map(|p| p.1).collect();
        CubicSpline::new(
            &xs,
            &ys,
            EndCondition::ZeroSecondDerivative,
            EndCondition::ZeroSecondDerivative,
        )
        .unwrap()
    };
    (mk(&up), mk(&lo))
}

/// NACA 0012 half thickness y_t in % chord, Abbott & von Doenhoff, *Theory of Wing
/// Sections*, Appendix I ("NACA 0012 basic thickness form"; same numbers as NACA Report 824).
const NACA0012_TABLE: [(f64, f64); 17] = [
    (1.25, 1.894),
    (2.5, 2.615),
    (5.0, 3.555),
    (7.5, 4.200),
    (10.0, 4.683),
    (15.0, 5.345),
    (20.0, 5.737),
    (25.0, 5.941),
    (30.0, 6.002),
    (40.0, 5.803),
    (50.0, 5.294),
    (60.0, 4.563),
    (70.0, 3.664),
    (80.0, 2.623),
    (90.0, 1.448),
    (95.0, 0.807),
    (100.0, 0.126),
];

#[test]
fn naca0012_thickness_matches_abbott_table() {
    // Table printed to 0.001 % c: tolerance 0.6e-5 c (rounding).
    let s = NacaSection::parse("0012").unwrap();
    for (xp, yt) in NACA0012_TABLE {
        let v = s.half_thickness(xp / 100.0, TrailingEdge::Blunt);
        assert!(
            (v - yt / 100.0).abs() < 0.6e-5,
            "x = {xp} %: {v} vs {}",
            yt / 100.0
        );
    }
}

#[test]
fn naca0012_generated_contour_matches_abbott_table() {
    // The default (XFOIL) point set, interpolated at the table stations.
    let a = naca("0012", &NacaOptions::default()).unwrap();
    let (u, l) = surfaces(&a.x, &a.y, 0.005);
    for (xp, yt) in NACA0012_TABLE {
        let x = xp / 100.0;
        assert!((u.eval(x) - yt / 100.0).abs() < 2e-5, "upper at {xp} %");
        assert!((l.eval(x) + yt / 100.0).abs() < 2e-5, "lower at {xp} %");
    }
}

/// NACA 23012 interpolated coordinates (x, y_upper, y_lower) from PDAS naca456
/// (R. Carmichael, Public Domain Aeronautical Software, an implementation of NASA TM 4741
/// which recomputes the tables of Abbott & von Doenhoff Appendix III; output file
/// `naca23012.txt`, "INTERPOLATED COORDINATES"). naca456 derives the mean-line constants
/// from the design equations with more digits than the 4-figure (r, k1) table used here and
/// by XFOIL; that alone changes the camber by up to 0.07 % (≤ 1.1e-5 c), hence the
/// tolerance of 2e-5 c.
const NACA23012_NACA456: [(f64, f64, f64); 12] = [
    (0.025, 0.036180, -0.017278),
    (0.050, 0.049166, -0.022609),
    (0.100, 0.064384, -0.029371),
    (0.200, 0.074994, -0.039784),
    (0.300, 0.075500, -0.044563),
    (0.400, 0.071350, -0.044738),
    (0.500, 0.064076, -0.041830),
    (0.600, 0.054567, -0.036723),
    (0.700, 0.043356, -0.029940),
    (0.800, 0.030721, -0.021754),
    (0.900, 0.016730, -0.012231),
    (0.950, 0.009196, -0.006939),
];

#[test]
fn naca23012_normal_thickness_matches_naca456() {
    // Classic construction (thickness normal to the mean line), dense points, interpolated.
    let opts = NacaOptions {
        points_per_side: 401,
        thickness_normal_to_camber: true,
        ..Default::default()
    };
    let a = naca("NACA 23012", &opts).unwrap();
    let (u, l) = surfaces(&a.x, &a.y, 0.005);
    for (x, yu, yl) in NACA23012_NACA456 {
        assert!((u.eval(x) - yu).abs() < 2e-5, "upper at {x}: {}", u.eval(x));
        assert!((l.eval(x) - yl).abs() < 2e-5, "lower at {x}: {}", l.eval(x));
    }
}

#[test]
fn naca23012_mean_line_matches_naca456() {
    // (x, yc, dyc/dx) from the naca456 "MEAN LINE" columns.
    let s = NacaSection::parse("23012").unwrap();
    for (x, yc, dyc) in [
        (0.01, 0.002894, 0.273741),
        (0.05, 0.011555, 0.163569),
        (0.10, 0.017022, 0.061779),
        (0.20, 0.017678, -0.022048),
        (0.50, 0.011049, -0.022098),
        (0.90, 0.002210, -0.022098),
    ] {
        let (c, d) = s.camber(x);
        assert!((c - yc).abs() < 1.5e-5, "yc at {x}: {c}");
        assert!((d - dyc).abs() < 2.5e-4, "dyc at {x}: {d}");
    }
}

#[test]
fn default_generator_reproduces_xfoil_buffer_airfoil() {
    // XFOIL 6.99: `NACA dddd`, `PCOP`, `PSAV` (245 points, written with 7 digits); measured
    // 5.0e-8 for each (XFOIL's rounding), limit about three times that.
    for f in ["0012", "2412", "23012"] {
        let g = naca(f, &NacaOptions::default()).unwrap();
        let r = xfoil_support::nodes(&format!("naca{f}_buffer.dat"));
        assert_eq!(g.x.len(), 245);
        assert_eq!(r.x.len(), 245);
        let dmax = (0..245)
            .map(|i| (g.x[i] - r.x[i]).hypot(g.y[i] - r.y[i]))
            .fold(0.0, f64::max);
        eprintln!("NACA {f}: max point distance {dmax:.2e}");
        assert!(dmax < 1.5e-7, "NACA {f}: max point distance {dmax:e}");
    }
}

#[test]
fn trailing_edge_gap_blunt_and_closed() {
    // XFOIL reports "Blunt trailing edge. Gap = 0.00252" for 12 % sections.
    for f in ["0012", "2412", "23012"] {
        let blunt = naca(f, &NacaOptions::default()).unwrap();
        assert!(
            (blunt.te_gap() - 0.00252).abs() < 1e-6,
            "{f}: {}",
            blunt.te_gap()
        );
        let closed = naca(
            f,
            &NacaOptions {
                trailing_edge: TrailingEdge::Closed,
                ..Default::default()
            },
        )
        .unwrap();
        assert!(closed.te_gap() < 1e-6, "{f} closed: {}", closed.te_gap());
    }
    let t15 = naca("23015", &NacaOptions::default()).unwrap();
    assert!((t15.te_gap() - 0.00315).abs() < 1e-6);
}

#[test]
fn contour_is_in_xfoil_order() {
    let a = naca("2412", &NacaOptions::default()).unwrap();
    let n = a.x.len();
    assert_eq!(a.name, "NACA 2412");
    assert_eq!((a.x[0], a.x[n - 1]), (1.0, 1.0));
    assert!(a.y[0] > a.y[n - 1]);
    assert_eq!((a.x[n / 2], a.y[n / 2]), (0.0, 0.0));
    assert!(a.y[n / 4] > 0.05 && a.y[3 * n / 4] < 0.0);
}

/// Thin-airfoil-theory Fourier coefficient A_k = (2/π)∫₀^π dyc/dx·cos kθ dθ,
/// x = (1 − cos θ)/2 (Abbott & von Doenhoff §4.3, eq. 4.26).
fn fourier(s: &NacaSection, k: i32) -> f64 {
    let n = 20_000;
    let h = PI / n as f64;
    (0..n)
        .map(|i| {
            let th = (i as f64 + 0.5) * h;
            s.camber(0.5 * (1.0 - th.cos())).1 * (k as f64 * th).cos() * h
        })
        .sum::<f64>()
        * 2.0
        / PI
}

#[test]
fn five_digit_mean_lines_have_design_lift_and_reflexed_moment() {
    // Design CL = 0.15·L = 0.3 for L = 2: cl_i = π·A1 (Abbott & von Doenhoff eq. 4.28);
    // reflexed lines are designed for cm_c/4 = (π/4)(A2 − A1) ≈ 0 (eq. 4.29).
    for p in 2..=5 {
        for q in [0, 1] {
            let s = NacaSection::parse(&format!("2{p}{q}12")).unwrap();
            let a1 = fourier(&s, 1);
            let a2 = fourier(&s, 2);
            let cl = PI * a1;
            let cm = PI / 4.0 * (a2 - a1);
            assert!((cl - 0.3).abs() < 0.01, "2{p}{q}: cl_i = {cl}");
            if q == 1 {
                assert!(cm.abs() < 2e-3, "2{p}1 reflexed: cm = {cm}");
                assert!(s.camber(1.0).0.abs() < 1e-12 && s.camber(0.0).0.abs() < 1e-12);
            } else {
                assert!(cm < -0.005, "2{p}0 normal: cm = {cm}");
            }
        }
    }
    // Design lift digit scales the mean line: L = 4 doubles it.
    let s2 = NacaSection::parse("23012").unwrap();
    let s4 = NacaSection::parse("43012").unwrap();
    assert!((s4.camber(0.3).0 - 2.0 * s2.camber(0.3).0).abs() < 1e-15);
}

#[test]
fn invalid_designations_are_rejected_with_reason() {
    let msg = |d: &str| match NacaSection::parse(d) {
        Err(e @ GeometryError::NacaDesignation { .. }) => e.to_string(),
        other => panic!("{d}: expected designation error, got {other:?}"),
    };
    assert!(msg("241").contains("expected 4 or 5 digits"));
    assert!(msg("2412x").contains("expected 4 or 5 digits"));
    assert!(msg("0000").contains("thickness must be positive"));
    assert!(msg("2012").contains("camber position"));
    assert!(msg("03012").contains("design-lift digit"));
    assert!(msg("23512").contains("third digit"));
    assert!(msg("21112").contains("reflexed camber position digit"));
    assert!(msg("26012").contains("camber position digit must be 1..5"));
    for six in ["64-212", "NACA 65A010", "naca63(420)-422", "64_1-212"] {
        assert!(msg(six).contains("6-series"), "{six}: {}", msg(six));
    }
    assert!(NacaSection::parse("6412").is_ok() && NacaSection::parse("64012").is_ok());
    assert!(NacaSection::parse("naca-23012").is_ok());
    assert!(NacaSection::parse(" NACA 2412 ").is_ok());
}

/// The largest thickness of the contour (AeroDyn's `RelThickness`): 12 % for the NACA 0012,
/// 23012 and 8-H-12 (their designations), measured normal to the chord line whatever the
/// contour's rotation. Measured: 0.120032 (0012, 23012; linear between contour points),
/// 0.119780 (8-H-12, its tabulated ordinates); tolerance 6e-4.
#[test]
fn max_thickness_is_the_designation() {
    use polargen::geometry::airfoil_by_name_or_path;
    for name in ["naca0012", "naca23012", "naca8h12"] {
        let foil = airfoil_by_name_or_path(name).unwrap();
        let t = foil.max_thickness().unwrap();
        assert!((t - 0.12).abs() < 6e-4, "{name}: {t}");
        // Rotated by 10° and scaled by 2: the same t/c.
        let (s, c) = 10f64.to_radians().sin_cos();
        let turned = polargen::geometry::Airfoil {
            name: foil.name.clone(),
            x: foil
                .x
                .iter()
                .zip(&foil.y)
                .map(|(x, y)| 2.0 * (x * c - y * s))
                .collect(),
            y: foil
                .x
                .iter()
                .zip(&foil.y)
                .map(|(x, y)| 2.0 * (x * s + y * c))
                .collect(),
        };
        assert!((turned.max_thickness().unwrap() - t).abs() < 1e-4, "{name}");
    }
}
