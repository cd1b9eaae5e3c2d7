//! Contour validation: what it refuses (stray points, contours listed twice, zero thickness,
//! absurd magnitudes, oversized files) with one-line errors, quickly, and what it must keep
//! accepting (every NACA 4- and 5-digit section, every test airfoil).

use polargen::geometry::{
    naca, parse_airfoil_text, read_airfoil_file, Airfoil, GeometryError, NacaOptions,
    PanelingParams,
};
use polargen::limits::MAX_CONTOUR_POINTS;
use std::path::Path;
use std::time::Instant;

/// The NACA 0012 ordinates of XFOIL's buffer as (x, y) pairs.
fn naca0012_points() -> Vec<(f64, f64)> {
    let a = naca("0012", &NacaOptions::default()).unwrap();
    a.x.into_iter().zip(a.y).collect()
}

fn selig(points: &[(f64, f64)]) -> String {
    let mut s = String::from("test section\n");
    for (x, y) in points {
        s.push_str(&format!("{x:.10e} {y:.10e}\n"));
    }
    s
}

fn parse_err(points: &[(f64, f64)]) -> String {
    let e = parse_airfoil_text(&selig(points), "t.dat", "t").unwrap_err();
    let text = e.to_string();
    assert!(!text.contains('\n') && text.len() < 300, "{text}");
    text
}

#[test]
fn a_stray_point_is_a_spike() {
    let mut p = naca0012_points();
    // One lower-surface point 0.2 chord below the surface, another case 2 chords above.
    let k = 3 * p.len() / 4;
    p[k].1 -= 0.2;
    let e = parse_err(&p);
    assert!(
        e.contains("folds back at point") && e.contains("stray point"),
        "{e}"
    );
    assert!(e.starts_with(&format!("t.dat:{}:", k + 2)), "{e}");
    let mut p = naca0012_points();
    p[20].1 += 2.0;
    assert!(parse_err(&p).contains("folds back"));
}

#[test]
fn a_contour_listed_twice_is_refused() {
    let p = naca0012_points();
    // Exactly twice: a repeated point.
    let twice: Vec<(f64, f64)> = p.iter().chain(&p[1..]).copied().collect();
    assert!(parse_err(&twice).contains("repeats the point at line 3"));
    // Twice, the second pass slightly smaller (no point repeated, no crossing): the turning.
    let inner: Vec<(f64, f64)> = p.iter().map(|(x, y)| (0.02 + 0.96 * x, 0.96 * y)).collect();
    let both: Vec<(f64, f64)> = p.iter().chain(&inner).copied().collect();
    let e = parse_err(&both);
    assert!(e.contains("is it listed twice"), "{e}");
}

#[test]
fn zero_thickness_and_absurd_magnitudes_are_refused() {
    let flat: Vec<(f64, f64)> = naca0012_points()
        .into_iter()
        .map(|(x, y)| (x, 1e-6 * y))
        .collect();
    assert!(parse_err(&flat).contains("encloses almost no area"));
    let huge: Vec<(f64, f64)> = naca0012_points()
        .into_iter()
        .map(|(x, y)| (1e200 * x, 1e200 * y))
        .collect();
    let e = parse_err(&huge);
    assert!(
        e.contains("beyond the limit of ±1e9") && e.contains("1e200"),
        "{e}"
    );
    let tiny: Vec<(f64, f64)> = naca0012_points()
        .into_iter()
        .map(|(x, y)| (1e-200 * x, 1e-200 * y))
        .collect();
    assert!(parse_err(&tiny).contains("too small to be resolved"));
}

#[test]
fn a_million_points_are_refused_at_once() {
    let n = 1_000_000;
    let mut text = String::with_capacity(30 * n);
    text.push_str("dense ellipse\n");
    for i in 0..n {
        let t = 2.0 * std::f64::consts::PI * i as f64 / n as f64;
        text.push_str(&format!("{} {}\n", 0.5 + 0.5 * t.cos(), 0.06 * t.sin()));
    }
    let start = Instant::now();
    let e = parse_airfoil_text(&text, "dense.dat", "d").unwrap_err();
    assert!(matches!(e, GeometryError::TooManyPoints { .. }), "{e}");
    assert!(start.elapsed().as_secs_f64() < 2.0, "{:?}", start.elapsed());
    // At the limit the whole validation (with the crossing sweep) takes milliseconds, where
    // the pairwise test took a minute for 80 001 points.
    let m = MAX_CONTOUR_POINTS;
    let t = |i: usize| 2.0 * std::f64::consts::PI * i as f64 / (m - 1) as f64;
    let a = Airfoil {
        name: "limit".into(),
        x: (0..m).map(|i| 0.5 + 0.5 * t(i).cos()).collect(),
        y: (0..m).map(|i| -0.06 * t(i).sin()).collect(),
    };
    let start = Instant::now();
    a.validate().unwrap();
    assert!(start.elapsed().as_secs_f64() < 0.5, "{:?}", start.elapsed());
}

#[test]
fn cr_only_line_ends_are_lines() {
    let text = selig(&naca0012_points()).replace('\n', "\r");
    let (a, _) = parse_airfoil_text(&text, "mac.dat", "m").unwrap();
    assert_eq!(a.name, "test section");
    assert_eq!(a.len(), naca0012_points().len());
}

#[test]
fn every_naca_section_and_test_airfoil_passes() {
    let mut designations = Vec::new();
    for m in 0..10 {
        for p in 0..10 {
            if (m == 0) != (p == 0) {
                continue;
            }
            for t in 1..100 {
                designations.push(format!("{m}{p}{t:02}"));
            }
        }
    }
    for l in 1..10 {
        for p in 1..6 {
            for r in 0..2 {
                if r == 1 && p < 2 {
                    continue;
                }
                for t in 1..100 {
                    designations.push(format!("{l}{p}{r}{t:02}"));
                }
            }
        }
    }
    for (k, d) in designations.iter().enumerate() {
        let a = naca(d, &NacaOptions::default()).unwrap();
        a.validate().unwrap_or_else(|e| panic!("NACA {d}: {e}"));
        // A sample repaneled as the tools do (the paneled nodes are validated again).
        if k % 97 == 0 {
            if let Ok(p) = a.repanel(160, &PanelingParams::default()) {
                p.validate()
                    .unwrap_or_else(|e| panic!("NACA {d} paneled: {e}"));
            }
        }
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut files = 0;
    for sub in ["geometry", "xfoil"] {
        for entry in std::fs::read_dir(dir.join(sub)).unwrap() {
            let path = entry.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            if name.ends_with(".dat") && !name.starts_with("bad_") {
                read_airfoil_file(&path).unwrap_or_else(|e| panic!("{e}"));
                files += 1;
            }
        }
    }
    assert!(files >= 10, "{files}");
}
