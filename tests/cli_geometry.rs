//! The geometry operations on the command line: `polargen geometry`, the operation flags of
//! the main job, `point` and `batch`, a flap sweep (`--flap-deg`), the operations recorded in
//! the tables, and the usage errors of bad values.

mod cli_support;

use cli_support::{assert_one_line_error, ok, polargen, scratch, stderr};

/// The value of column `name` in the first data row of a CSV table.
fn first_row_field(csv: &str, name: &str) -> String {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    header
        .iter()
        .position(|h| *h == name)
        .map_or(String::new(), |i| row[i].to_string())
}

#[test]
fn geometry_writes_the_shaped_contour_and_says_its_thickness() {
    let o = polargen(&[
        "geometry",
        "naca2412",
        "--thickness",
        "0.15",
        "--camber",
        "0.03",
        "--out",
        "-",
    ]);
    let said = stderr(&o);
    let text = ok(o);
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("NACA 2412 (thickness 0.15; camber 0.03)")
    );
    assert_eq!(lines.count(), 245);
    assert!(
        said.contains("thickness 0.15000") && said.contains("camber 0.03000"),
        "{said}"
    );
    // The file reads back as a coordinate file (here: from standard input).
    let dir = scratch("geometry-out");
    let file = dir.join("flapped.dat");
    ok(polargen(&[
        "geometry",
        "naca2412",
        "--flap",
        "0.75:0:10",
        "--out",
        file.to_str().unwrap(),
    ]));
    let back = polargen::geometry::read_airfoil_file(&file).unwrap();
    assert_eq!(back.len(), 249);
    // A contour that would not read back as a section (the blend of a 12 % and a 99 %
    // section: a nose the spline cannot locate) is refused, and nothing is written.
    let blend = dir.join("blend.dat");
    let o = polargen(&[
        "geometry",
        "naca2412",
        "--blend",
        "naca9999:0.5",
        "--out",
        blend.to_str().unwrap(),
    ]);
    assert_one_line_error("polargen", &o, "reading back the contour written for");
    assert!(!blend.exists());
}

#[test]
fn bad_values_are_usage_errors() {
    for args in [
        &["--thickness", "0"][..],
        &["--thickness", "-0.2"],
        &["--thickness", "abc"],
        &["--camber", "0.5"],
        &["--te-gap", "0.01:2"],
        &["--flap", "1.2:0:10"],
        &["--flap", "0.7:0:120"],
        &["--blend", "naca0012:1.5"],
        &["--blend", "naca0012:-0.1"],
    ] {
        let o = polargen(&[&["geometry", "naca2412", "--out", "-"], args].concat());
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        // `--flag value: rule`, the convention of every refused value.
        assert_one_line_error("polargen", &o, &format!("error: {}", args[0]));
    }
    // --flap-deg needs the hinge.
    let o = polargen(&["--airfoil", "naca0012", "--re", "1e6", "--flap-deg", "5"]);
    assert_eq!(o.status.code(), Some(2));
}

/// A flap sweep: one table per deflection, named after it, each recording its operations
/// and its flap angle; the flap moves the lift as it should (down: more lift).
#[test]
fn a_flap_sweep_writes_one_table_per_deflection() {
    let dir = scratch("flap-sweep");
    let out = dir.join("t.csv");
    ok(polargen(&[
        "-q",
        "--airfoil",
        "naca0012",
        "--re",
        "1e6",
        "--alpha",
        "0",
        "--flap",
        "0.75:0",
        "--flap-deg",
        "-5,0,5",
        "--out",
        out.to_str().unwrap(),
    ]));
    let cl = |deg: &str| {
        let text = std::fs::read_to_string(dir.join(format!("t_flap{deg}.csv"))).unwrap();
        assert_eq!(
            first_row_field(&text, "geometry"),
            format!("flap 0.75:0:{deg}")
        );
        assert_eq!(first_row_field(&text, "flap_deg"), deg);
        let table = polargen::table::read_table(&dir.join(format!("t_flap{deg}.csv"))).unwrap();
        assert_eq!(table.meta().flap_deg(), Some(deg.parse().unwrap()));
        first_row_field(&text, "cl").parse::<f64>().unwrap()
    };
    let (down, zero, up) = (cl("5"), cl("0"), cl("-5"));
    // The operations survive a conversion to JSON and back.
    let json = dir.join("t.json");
    ok(polargen(&[
        "convert",
        dir.join("t_flap-5.csv").to_str().unwrap(),
        "--out",
        json.to_str().unwrap(),
    ]));
    let back = polargen::table::read_table(&json).unwrap();
    assert_eq!(back.meta().flap_deg(), Some(-5.0));
    assert_eq!(back.meta().geometry.len(), 1);
    // NACA 0012 at α 0: no lift without the flap; ±5° give opposite lift (thin-airfoil
    // theory for a 25 % flap: ΔCl = 2π·τ·δ, τ = 1 − (θ_f − sin θ_f)/π = 0.61 with
    // θ_f = arccos(1 − 2·0.75), so 0.33 for 5°; measured 0.347).
    assert!(zero.abs() < 1e-3, "{zero}");
    assert!((0.28..0.40).contains(&down), "{down}");
    assert!((down + up).abs() < 0.01, "{down} {up}");
    // Several tables cannot go to standard output.
    let o = polargen(&[
        "--airfoil",
        "naca0012",
        "--re",
        "1e6",
        "--alpha",
        "0",
        "--flap",
        "0.75:0",
        "--flap-deg",
        "-5,5",
    ]);
    // Contradicting flags are a usage error.
    assert_eq!(o.status.code(), Some(2));
    assert_one_line_error("polargen", &o, "--out FILE");
}

/// The operation flags on the main job, `point` and `batch` give the same section: the
/// thickened NACA 0012 has the same table as the NACA 0015 it nearly is (XFOIL's TSET of the
/// 0012 to 15 %: within a few 10⁻³ in Cl), and an unshaped table has no geometry column.
#[test]
fn the_flags_reach_every_solver_command() {
    let base = ["-q", "--airfoil", "naca0012", "--re", "1e6", "--alpha", "4"];
    let plain = ok(polargen(&base));
    assert!(!plain.lines().next().unwrap().contains("geometry"));
    let thick = ok(polargen(&[&base[..], &["--thickness", "0.15"]].concat()));
    assert_eq!(first_row_field(&thick, "geometry"), "thickness 0.15");
    assert_eq!(first_row_field(&thick, "flap_deg"), "");
    let naca0015 = ok(polargen(&[
        "-q",
        "--airfoil",
        "naca0015",
        "--re",
        "1e6",
        "--alpha",
        "4",
    ]));
    let cl = |t: &str| first_row_field(t, "cl").parse::<f64>().unwrap();
    assert!(
        (cl(&thick) - cl(&naca0015)).abs() < 0.01,
        "{thick}\n{naca0015}"
    );
    assert!((cl(&thick) - cl(&plain)).abs() > 1e-4);
    let dir = scratch("geometry-flags");
    let point = dir.join("p.csv");
    ok(polargen(&[
        "point",
        "-q",
        "--airfoil",
        "naca0012",
        "--re",
        "1e6",
        "--alpha",
        "4",
        "--flap",
        "0.75:0:5",
        "--csv",
        point.to_str().unwrap(),
    ]));
    assert!(std::fs::read_to_string(&point).unwrap().lines().count() > 100);
    let tables = dir.join("tables");
    ok(polargen(&[
        "batch",
        "-q",
        "--airfoils",
        "naca0012",
        "--out",
        tables.to_str().unwrap(),
        "--re",
        "1e6",
        "--alpha",
        "4",
        "--thickness",
        "0.15",
    ]));
    let batch = std::fs::read_to_string(tables.join("naca0012.csv")).unwrap();
    assert_eq!(first_row_field(&batch, "geometry"), "thickness 0.15");
    assert_eq!(first_row_field(&batch, "cl"), first_row_field(&thick, "cl"));
}

/// A tiny value is written so that it reads back exactly and stays short: `1e-300`, not a
/// 300-digit decimal, in the section's name and in a flap sweep's file name.
#[test]
fn tiny_values_keep_short_names() {
    let o = polargen(&[
        "geometry",
        "naca2412",
        "--flap",
        "0.75:0:1e-300",
        "--out",
        "-",
    ]);
    let text = ok(o);
    assert_eq!(text.lines().next(), Some("NACA 2412 (flap 0.75:0:1e-300)"));
    let dir = scratch("tiny-flap");
    let out = dir.join("t.csv");
    ok(polargen(&[
        "-q",
        "--airfoil",
        "naca2412",
        "--re",
        "1e6",
        "--alpha",
        "0:2:2",
        "--flap",
        "0.75:0",
        "--flap-deg",
        "1e-300,5",
        "--out",
        out.to_str().unwrap(),
    ]));
    let table = std::fs::read_to_string(dir.join("t_flap1e-300.csv")).unwrap();
    assert!(table.contains("(flap 0.75:0:1e-300)"), "{table}");
    assert_eq!(first_row_field(&table, "flap_deg"), "1e-300");
}

/// An operation whose contour is refused names the point of the shaped contour, not a line
/// of a file the user never saw.
#[test]
fn a_refused_shaped_contour_names_its_point() {
    let o = polargen(&["geometry", "naca2412", "--flap", "0.75:0:85", "--out", "-"]);
    assert_one_line_error(
        "polargen",
        &o,
        "NACA 2412 (flap 0.75:0:85), point 228: the contour folds back",
    );
}
