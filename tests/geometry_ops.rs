//! Geometry operations (thickness and camber, trailing-edge gap, flap, blend) against XFOIL
//! 6.99's GDES `TSET`, `TGAP`, `FLAP` and top-level `INTX` on the same input ordinates: the
//! resulting ordinates point for point, and the inviscid CL and CM of the result repaneled
//! to 160 nodes (data and how they were made: tests/data/geometry_ops/README.md).

use polargen::geometry::{
    apply_shape_ops, parse_shape_ops, read_airfoil_file, Airfoil, GeometryError, PanelingParams,
    ShapeOp,
};
use polargen::inviscid::PanelSystem;
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/geometry_ops")
        .join(name)
}

fn foil(name: &str) -> Airfoil {
    read_airfoil_file(&data(&format!("{name}.dat"))).unwrap()
}

/// The case's operation as a polargen operation (XFOIL's command words → our text form).
fn operation(xfoil: &str) -> Vec<ShapeOp> {
    let w: Vec<&str> = xfoil.split_whitespace().collect();
    let text = match w[0] {
        "tset" if w[2] == "-" => format!("thickness {}", w[1]),
        "tset" => format!("thickness {}; camber {}", w[1], w[2]),
        "tgap" => format!("te-gap {}:{}", w[1], w[2]),
        "flap" => format!("flap {}:{}:{}", w[1], w[2], w[3]),
        "intx" => format!("blend {}:{}", w[1], w[2]),
        other => panic!("unknown operation {other}"),
    };
    parse_shape_ops(&text).unwrap()
}

struct Case {
    name: String,
    input: String,
    ops: Vec<ShapeOp>,
}

fn cases() -> Vec<Case> {
    std::fs::read_to_string(data("cases.csv"))
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            Case {
                name: f[0].to_string(),
                input: f[1].to_string(),
                ops: operation(f[2]),
            }
        })
        .collect()
}

fn ours(case: &Case) -> Airfoil {
    let load = |name: &str| -> Result<Airfoil, GeometryError> { Ok(foil(name)) };
    apply_shape_ops(&foil(&case.input), &case.ops, &load).unwrap()
}

/// Largest distance between corresponding points (the counts must agree).
fn max_point_distance(a: &Airfoil, b: &Airfoil) -> f64 {
    assert_eq!(a.len(), b.len(), "point counts differ");
    a.x.iter()
        .zip(&a.y)
        .zip(b.x.iter().zip(&b.y))
        .map(|((xa, ya), (xb, yb))| (xa - xb).hypot(ya - yb))
        .fold(0.0, f64::max)
}

/// Max |ΔCl|, |ΔCm| of our result (repaneled to 160 nodes, not normalised, as XFOIL's PANE)
/// against XFOIL's inviscid polar of its result.
fn inviscid_errors(case: &Case, result: &Airfoil) -> (f64, f64) {
    let nodes = result.repanel(160, &PanelingParams::default()).unwrap();
    let system = PanelSystem::new(&nodes).unwrap();
    let text = std::fs::read_to_string(data(&format!("{}_inviscid.csv", case.name))).unwrap();
    let (mut ecl, mut ecm) = (0.0_f64, 0.0_f64);
    for line in text.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|t| t.parse().unwrap()).collect();
        let sol = system.solve(v[0], 0.0).unwrap();
        ecl = ecl.max((sol.cl - v[1]).abs());
        ecm = ecm.max((sol.cm - v[2]).abs());
    }
    (ecl, ecm)
}

/// Each case: the ordinates within `points` of XFOIL's (distance, chord units), the inviscid
/// CL within `cl` and CM within `cm`.
fn check(prefix: &str, points: f64, cl: f64, cm: f64) {
    let all = cases();
    let selected: Vec<&Case> = all.iter().filter(|c| c.name.contains(prefix)).collect();
    assert!(!selected.is_empty());
    for case in selected {
        let result = ours(case);
        let xfoil = foil(&case.name);
        let d = max_point_distance(&result, &xfoil);
        let (ecl, ecm) = inviscid_errors(case, &result);
        eprintln!(
            "{}: {} points, max distance {d:.2e}, |dCl| {ecl:.1e}, |dCm| {ecm:.1e}",
            case.name,
            result.len()
        );
        assert!(d <= points, "{}: ordinates differ by {d}", case.name);
        assert!(ecl <= cl, "{}: |dCl| = {ecl}", case.name);
        assert!(ecm <= cm, "{}: |dCm| = {ecm}", case.name);
    }
}

// Measured (all cases): CL and CM within 5·10⁻⁵ (the 4 decimals of XFOIL's polar file);
// ordinates within 5·10⁻⁸ (the 7 significant digits of XFOIL's SAVE) for TGAP, FLAP (the
// same point count, points inserted and removed alike) and INTX, within 2·10⁻⁵ for TSET
// (XFOIL stops its opposite-point Newton iteration at a residual of 10⁻⁵ of the contour
// length; ours converges fully). Bounds: 3× those.
const COEFFICIENTS: f64 = 1.5e-4;

#[test]
fn thickness_and_camber_match_xfoil_tset() {
    check("_tset_", 6e-5, COEFFICIENTS, COEFFICIENTS);
}

#[test]
fn trailing_edge_gap_matches_xfoil_tgap() {
    check("_tgap_", 1.5e-7, COEFFICIENTS, COEFFICIENTS);
}

#[test]
fn flap_matches_xfoil_flap() {
    check("_flap_", 2e-7, COEFFICIENTS, COEFFICIENTS);
}

#[test]
fn blend_matches_xfoil_intx() {
    check("_intx_", 1.5e-7, COEFFICIENTS, COEFFICIENTS);
}

#[test]
fn a_set_thickness_and_camber_are_measured_back() {
    // XFOIL's TCBUF of its own TSET result prints what was asked for; so does ours.
    let base = foil("naca2412");
    let before = base.thickness_camber().unwrap();
    assert!((before.thickness.value - 0.12).abs() < 2e-4, "{before}");
    assert!((before.camber.value - 0.02).abs() < 2e-4, "{before}");
    let set = base.with_thickness_camber(Some(0.24), None).unwrap();
    let after = set.thickness_camber().unwrap();
    assert!((after.thickness.value - 0.24).abs() < 1e-6, "{after}");
    assert!(
        (after.camber.value - before.camber.value).abs() < 1e-5,
        "{after}"
    );
    let cambered = base.with_thickness_camber(None, Some(0.05)).unwrap();
    let c = cambered.thickness_camber().unwrap();
    assert!((c.camber.value - 0.05).abs() < 1e-6, "{c}");
    assert!(
        (c.thickness.value - before.thickness.value).abs() < 1e-4,
        "{c}"
    );
    // A symmetric section has no camber line to scale.
    let e = foil("naca0012")
        .with_thickness_camber(None, Some(0.02))
        .unwrap_err();
    assert!(e.to_string().contains("no camber line"), "{e}");
}

#[test]
fn a_zero_flap_deflection_changes_nothing_and_a_gap_is_set_exactly() {
    let base = foil("naca2412");
    assert_eq!(base.with_flap(0.75, 0.0, 0.0).unwrap(), base);
    let closed = base.with_te_gap(0.0, 0.5).unwrap();
    assert!(closed.te_gap() < 1e-12, "{}", closed.te_gap());
    let open = base.with_te_gap(0.02, 0.5).unwrap();
    assert!((open.te_gap() - 0.02).abs() < 1e-12, "{}", open.te_gap());
}

#[test]
fn operations_read_back_from_their_text_and_bad_values_are_refused() {
    let text = "blend naca0012:0.5; thickness 0.15; camber -0.01; te-gap 0.002:0.8; \
                flap 0.75:0.01:-12.5";
    let ops = parse_shape_ops(text).unwrap();
    assert_eq!(ops.len(), 5);
    assert_eq!(polargen::geometry::shape_ops_text(&ops), text);
    assert_eq!(polargen::geometry::flap_deg(&ops), Some(-12.5));
    for (bad, why) in [
        ("thickness 0", "(0, 1)"),
        ("thickness -0.1", "(0, 1)"),
        ("thickness nan", "(0, 1)"),
        ("camber 0.3", "[-0.2, 0.2]"),
        ("te-gap -0.01", "[0, 0.2]"),
        ("te-gap 0.01:1.5", "blending distance"),
        ("flap 1.2:0:10", "inside the chord"),
        ("flap 0:0:10", "inside the chord"),
        ("flap 0.7:0:95", "(-90, 90)"),
        ("flap 0.7", "X:Y:DEG"),
        ("blend naca0012:1.5", "[0, 1]"),
        ("blend naca0012", "OTHER:F"),
        ("twist 3", "expected thickness"),
    ] {
        let e = parse_shape_ops(bad).unwrap_err().to_string();
        assert!(e.contains(why), "{bad}: {e}");
    }
}
