//! Arc-length spline (XFOIL SPLIND/SEVAL/DEVAL/D2VAL/CURV/LEFIND equivalents): exactness on
//! cubics, end conditions, curvature of a circle, leading edge of an ellipse, errors.

use polargen::geometry::{ContourSpline, CubicSpline, EndCondition, GeometryError};

fn cubic(s: f64) -> (f64, f64, f64) {
    (
        1.0 - 2.0 * s + 0.5 * s * s + 0.3 * s * s * s,
        -2.0 + s + 0.9 * s * s,
        1.0 + 1.8 * s,
    )
}

#[test]
fn cubic_is_reproduced_exactly_with_slope_end_conditions() {
    // Non-uniform knots; a C2 cubic spline with exact end slopes reproduces any cubic.
    let s = [0.0, 0.3, 0.45, 1.1, 1.7, 2.0, 2.9];
    let v: Vec<f64> = s.iter().map(|&t| cubic(t).0).collect();
    let sp = CubicSpline::new(
        &s,
        &v,
        EndCondition::Slope(cubic(0.0).1),
        EndCondition::Slope(cubic(2.9).1),
    )
    .unwrap();
    for k in 0..=58 {
        let t = 0.05 * k as f64;
        let (f, df, d2f) = cubic(t);
        assert!((sp.eval(t) - f).abs() < 1e-12, "value at {t}");
        assert!((sp.deriv(t) - df).abs() < 1e-11, "slope at {t}");
        assert!((sp.deriv2(t) - d2f).abs() < 1e-10, "curvature at {t}");
    }
}

#[test]
fn end_conditions_hold() {
    let s = [0.0, 0.5, 1.2, 2.0, 2.4, 3.0];
    let v = [0.0, 0.8, 0.1, -0.7, 0.3, 1.0];
    let nat = CubicSpline::new(
        &s,
        &v,
        EndCondition::ZeroSecondDerivative,
        EndCondition::ZeroSecondDerivative,
    )
    .unwrap();
    assert!(nat.deriv2(0.0).abs() < 1e-12 && nat.deriv2(3.0).abs() < 1e-12);
    // Zero third derivative: the second derivative is constant over the end intervals.
    let z3 = CubicSpline::xfoil_default(&s, &v).unwrap();
    assert!((z3.deriv2(0.0) - z3.deriv2(0.5 - 1e-9)).abs() < 1e-6);
    assert!((z3.deriv2(3.0) - z3.deriv2(2.4 + 1e-9)).abs() < 1e-6);
    // Interpolation at the knots for both.
    for (i, &t) in s.iter().enumerate() {
        assert!((nat.eval(t) - v[i]).abs() < 1e-14 && (z3.eval(t) - v[i]).abs() < 1e-14);
    }
}

#[test]
fn circle_curvature_and_ellipse_leading_edge() {
    // Counter-clockwise circle of radius 0.5: curvature +2, up to the O(Δs²) error of the
    // chord-length parameter (Δs ≈ 0.015 → ~2e-4 relative).
    let n = 200;
    let (x, y): (Vec<f64>, Vec<f64>) = (0..n)
        .map(|i| {
            let t = 0.05 + 6.1 * i as f64 / (n - 1) as f64;
            (0.5 * t.cos(), 0.5 * t.sin())
        })
        .unzip();
    let c = ContourSpline::new(&x, &y).unwrap();
    let (s0, s1) = (c.s()[20], c.s()[180]);
    for k in 0..=10 {
        let ss = s0 + (s1 - s0) * k as f64 / 10.0;
        assert!((c.curvature(ss) - 2.0).abs() < 5e-4, "{}", c.curvature(ss));
    }
    // Ellipse from (1, 0) counter-clockwise with a small TE gap: LE point at (−1, 0), up to
    // the spline interpolation error between points (measured 1.7e-6).
    let (x, y): (Vec<f64>, Vec<f64>) = (0..n)
        .map(|i| {
            let t = 2.0 * std::f64::consts::PI * i as f64 / (n - 1) as f64;
            (
                t.cos(),
                0.1 * t.sin() + 0.001 * (1.0 - 2.0 * (i as f64) / (n - 1) as f64),
            )
        })
        .unzip();
    let e = ContourSpline::new(&x, &y).unwrap();
    let (xl, yl) = e.point(e.leading_edge().unwrap());
    assert!(
        (xl + 1.0).abs() < 5e-6 && yl.abs() < 1e-9,
        "LE ({xl}, {yl})"
    );
}

#[test]
fn bad_spline_input_is_an_error() {
    let e = CubicSpline::xfoil_default(&[0.0, 1.0, 1.0, 2.0], &[0.0; 4]).unwrap_err();
    assert_eq!(
        e,
        GeometryError::Spline("spline parameter not strictly increasing at point 3".into())
    );
    assert!(CubicSpline::xfoil_default(&[0.0, 1.0], &[0.0, f64::NAN]).is_err());
    assert!(CubicSpline::xfoil_default(&[0.0], &[0.0]).is_err());
    assert!(ContourSpline::new(&[0.0, 1.0, 1.0], &[0.0, 1.0, 1.0]).is_err());
}
