//! The blade-element–momentum propeller against a published fixed-pitch propeller chart:
//! NACA Report 594, propeller D (10 ft, two blades, Clark Y sections), at blade angles 15°,
//! 30° and 45° at 0.75 R, with polargen's own Clark Y table as the section
//! (`polars/clarky_free.csv`; data and provenance in `tests/data/rotor/naca594/`).

use polargen::geometry::read_airfoil_file;
use polargen::rotor::{Atmosphere, BladeGeometry, Propeller};
use polargen::table::read_lookup_table;
use std::path::Path;
use std::sync::Arc;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn csv_rows(file: &str) -> Vec<Vec<f64>> {
    let text = std::fs::read_to_string(root().join("tests/data/rotor/naca594").join(file)).unwrap();
    text.lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

/// Angle of the Clark Y chord line (leading-edge point of the spline to the trailing edge, the
/// α datum of the table, made with `--derotate`) above the flat lower face the report measures
/// blade angles from [rad]: the face is the x axis of the ordinates, so it is minus the chord
/// line's inclination to that axis.
fn face_to_chord_angle() -> f64 {
    let raw = read_airfoil_file(&root().join("geometry/clarky.dat")).unwrap();
    assert!(raw
        .x
        .iter()
        .zip(&raw.y)
        .any(|(&x, &y)| x >= 0.3 && y == 0.0));
    -raw.chord_angle_deg().unwrap().to_radians()
}

/// Propeller D at blade angle `beta075_deg` (flat face) at 0.75 R.
fn propeller_d(beta075_deg: f64) -> Propeller {
    let g = csv_rows("propeller_d_geometry.csv");
    let geometry = BladeGeometry {
        diameter_m: 10.0 * 0.3048,
        blades: 2,
        r_over_r: g.iter().map(|r| r[0]).collect(),
        chord_over_diameter: g.iter().map(|r| r[1]).collect(),
        twist_deg: g.iter().map(|r| r[2] - 15.0).collect(),
        annuli: 20,
    };
    let table = read_lookup_table(&root().join("polars/clarky_free.csv")).unwrap();
    Propeller::new(
        &geometry,
        Arc::new(table),
        beta075_deg.to_radians() + face_to_chord_angle(),
    )
}

/// (J, C_T, C_P) measured and computed at `beta`, at the test rpm (1000 rpm, tip Mach 0.47).
fn chart(beta: f64) -> Vec<(f64, [f64; 2], [f64; 2])> {
    let prop = propeller_d(beta);
    let air = Atmosphere::isa(0.0);
    let n = 1000.0 / 60.0;
    csv_rows("propeller_d_performance.csv")
        .into_iter()
        .filter(|r| r[0] == beta)
        .map(|r| {
            let p = prop.operate(&air, r[1] * n * prop.diameter, n).unwrap();
            (
                r[1],
                [r[2], r[3]],
                [p.thrust_coefficient, p.power_coefficient],
            )
        })
        .collect()
}

#[test]
fn the_clark_y_face_is_two_degrees_below_its_chord_line() {
    // The ordinates put the nose 3.5 % c above the face, the trailing edge on it; the
    // spline's leading-edge point (XFOIL's, used for the table's chord line) sits a little
    // lower: 2.03° (the "+2°" of the propeller literature, e.g. Morgado et al. 2015).
    let d = face_to_chord_angle().to_degrees();
    assert!((d - 2.0).abs() < 0.1, "{d}");
}

/// Relative error ours/measured − 1.
fn err(ours: f64, measured: f64) -> f64 {
    ours / measured - 1.0
}

/// Advance ratio of zero thrust, interpolated between the chart's points (the measured chart
/// ends at C_T = 2·10⁻⁵, counted as zero).
fn zero_thrust_j(points: &[(f64, f64)]) -> f64 {
    let w = points
        .windows(2)
        .find(|w| w[0].1 > 0.0 && w[1].1 <= 1e-4)
        .expect("thrust reaches zero");
    w[0].0 + (w[1].0 - w[0].0) * w[0].1 / (w[0].1 - w[1].1)
}

/// The chart of NACA Report 594 propeller D against ours. Measured agreement and why it is
/// not closer (the bands below are the stated tolerances of this model, not of BEMT in
/// general):
/// * 15°, attached flow (J 0…0.75, the branch the calibrated MTOsport propeller cruises on at
///   J ≈ 0.6): C_T +6 … +19 %, C_P −3 … +14 %. The section is the 11.7 % Clark Y everywhere,
///   while this blade is 8–10 % thick outboard of 0.6 R: its thinner sections have less
///   camber (α_L0 about 0.8° smaller); taking 0.85° off the blade angle, a diagnostic only,
///   brings C_T to −4 … +12 %.
/// * zero-thrust advance ratio at 15°: 0.837 against 0.850.
/// * static (J = 0): 15°: C_T +10 %, C_P −3 %; 30°: C_T −6 %, C_P −41 %; 45°: C_T −17 %,
///   C_P −30 %. Inboard, the high blade angles stall, and a two-dimensional post-stall polar
///   (Viterna–Corrigan) lacks the rotational stall delay of a real propeller, which raises both
///   lift and drag there: the static power is under-predicted, more so the larger the blade
///   angle.
/// * 30°, J 0.9…1.5: C_T +18 … +27 %, C_P +15 … +22 % (the same section camber).
/// * 45° above J ≈ 1.2 the measured thrust falls far below ours: not compared (the blade angle
///   is far from the MTOsport's, and the tip speed of those curves is not known here).
#[test]
fn naca_report_594_propeller_d() {
    let show = |beta: f64, j: f64, m: [f64; 2], o: [f64; 2]| {
        eprintln!(
            "β {beta} J {j:.2}: C_T {:.4} vs {:.4} ({:+.1} %), C_P {:.4} vs {:.4} ({:+.1} %)",
            o[0],
            m[0],
            100.0 * err(o[0], m[0]),
            o[1],
            m[1],
            100.0 * err(o[1], m[1])
        );
    };
    let c15 = chart(15.0);
    for &(j, m, o) in &c15 {
        show(15.0, j, m, o);
        if j <= 0.75 {
            assert!((-0.10..=0.20).contains(&err(o[0], m[0])), "15° J {j}: C_T");
            assert!(err(o[1], m[1]).abs() <= 0.15, "15° J {j}: C_P");
        }
    }
    let j0 = |c: &[(f64, [f64; 2], [f64; 2])], k: usize| {
        let pts: Vec<(f64, f64)> = c
            .iter()
            .map(|p| (p.0, if k == 0 { p.1[0] } else { p.2[0] }))
            .collect();
        zero_thrust_j(&pts)
    };
    let (measured, ours) = (j0(&c15, 0), j0(&c15, 1));
    eprintln!("15°: zero thrust at J {ours:.3} (measured {measured:.3})");
    assert!((ours - measured).abs() <= 0.05);
    let c30 = chart(30.0);
    for &(j, m, o) in &c30 {
        show(30.0, j, m, o);
        if (0.9..=1.5).contains(&j) {
            assert!(err(o[0], m[0]).abs() <= 0.30, "30° J {j}: C_T");
            assert!(err(o[1], m[1]).abs() <= 0.25, "30° J {j}: C_P");
        }
    }
    // Static: the thrust within 20 % at every blade angle; the power under-predicted at the
    // high blade angles (no rotational stall delay), by less than half.
    for (beta, c) in [(15.0, &c15), (30.0, &c30), (45.0, &chart(45.0))] {
        let (_, m, o) = c[0];
        show(beta, 0.0, m, o);
        assert!(err(o[0], m[0]).abs() <= 0.20, "{beta}° static C_T");
        assert!(
            (-0.5..=0.05).contains(&err(o[1], m[1])),
            "{beta}° static C_P"
        );
    }
}
