//! Coordinate-file reader: Selig, Lednicer and plain (E-notation) files, orientation, and
//! one test per kind of malformed file asserting the one-line error message.

use polargen::geometry::{
    airfoil_by_name_or_path, parse_airfoil_bytes, parse_airfoil_text, read_airfoil_file,
    to_selig_string, Airfoil, CoordinateFormat, GeometryError, PanelingParams,
};
use std::path::{Path, PathBuf};

mod xfoil_support;

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/geometry")
        .join(name)
}

fn selig_8h12() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("geometry/naca8h12.dat")
}

fn read(path: &Path) -> (Airfoil, CoordinateFormat) {
    let bytes = std::fs::read(path).unwrap();
    parse_airfoil_bytes(&bytes, &path.display().to_string(), "fallback").unwrap()
}

fn err(name: &str) -> String {
    let p = data(name);
    let e = read_airfoil_file(&p).unwrap_err();
    let msg = e.to_string();
    assert!(!msg.contains('\n'), "multi-line message: {msg}");
    assert!(
        msg.starts_with(&p.display().to_string()),
        "file not named: {msg}"
    );
    msg
}

#[test]
fn selig_file_is_read_in_xfoil_order() {
    let (a, fmt) = read(&selig_8h12());
    assert_eq!(fmt, CoordinateFormat::Selig);
    assert_eq!(a.name, "NACA 8-H-12");
    assert_eq!(a.x.len(), 51);
    // Upper TE first, LE (0, 0) at index 25, lower TE last; upper surface point at x = 0.29969.
    assert_eq!((a.x[0], a.y[0]), (1.0, 0.0));
    assert_eq!((a.x[25], a.y[25]), (0.0, 0.0));
    assert_eq!((a.x[14], a.y[14]), (0.29969, 0.09533));
    assert_eq!((a.x[50], a.y[50]), (1.0, 0.0));
    assert_eq!((a.x[1], a.y[1]), (0.94995, -0.00119));
}

#[test]
fn lednicer_file_gives_the_same_contour_as_selig() {
    let (s, _) = read(&selig_8h12());
    let (l, fmt) = read(&data("lednicer_naca8h12.dat"));
    assert_eq!(fmt, CoordinateFormat::Lednicer);
    assert_eq!(l.name, "NACA 8-H-12");
    assert_eq!(l, s);
}

#[test]
fn clockwise_comma_separated_selig_is_reversed() {
    let (s, _) = read(&selig_8h12());
    let (c, fmt) = read(&data("selig_clockwise_naca8h12.dat"));
    assert_eq!(fmt, CoordinateFormat::Selig);
    assert_eq!(c.name, "NACA 8-H-12 (clockwise)");
    assert_eq!((c.x, c.y), (s.x, s.y));
}

#[test]
fn plain_file_with_fortran_e_notation() {
    // XFOIL PSAV output: no name line, values like 0.1260000E-02.
    let (a, fmt) = read(&xfoil_support::path("naca0012_paneled.dat"));
    assert_eq!(fmt, CoordinateFormat::Plain);
    assert_eq!(a.name, "fallback");
    assert_eq!(a.x.len(), 160);
    assert_eq!((a.x[0], a.y[0]), (1.0, 0.1260000E-02));
    assert_eq!((a.x[1], a.y[1]), (0.9916796, 0.2421450E-02));
    // Name from the file stem when read from disk.
    let b = read_airfoil_file(&xfoil_support::path("naca0012_paneled.dat")).unwrap();
    assert_eq!(b.name, "naca0012_paneled");
}

#[test]
fn fortran_d_exponent_and_blank_lines_are_accepted() {
    let mut text = String::from("My foil\n\n");
    let (s, _) = read(&selig_8h12());
    for (x, y) in s.x.iter().zip(&s.y) {
        text.push_str(&format!("  {:.6}D+00\t{:.6}d0\n", x, y));
    }
    let (a, fmt) = parse_airfoil_bytes(text.as_bytes(), "mem", "x").unwrap();
    assert_eq!(fmt, CoordinateFormat::Selig);
    assert_eq!(a.name, "My foil");
    assert_eq!(a.x, s.x);
}

#[test]
fn unparsable_number() {
    assert!(err("bad_number.dat").ends_with(":6: cannot parse '0.0l895' as a number"));
}

#[test]
fn nan_and_infinity() {
    assert!(err("bad_nan.dat").ends_with(":9: coordinate 'NaN' is not finite"));
    assert!(err("bad_inf.dat").ends_with(":11: coordinate 'inf' is not finite"));
}

#[test]
fn empty_file_and_name_only() {
    assert!(err("bad_empty.dat").ends_with(": empty file, no coordinates found"));
    assert!(err("bad_name_only.dat").ends_with(": empty file, no coordinates found"));
}

#[test]
fn too_few_points() {
    assert!(err("bad_few_points.dat").ends_with(": only 8 points, at least 10 are needed"));
}

#[test]
fn duplicate_consecutive_points() {
    assert!(err("bad_duplicate.dat")
        .ends_with(":13: point (0.5039, 0.07666) duplicates the previous point"));
}

#[test]
fn crossing_surfaces() {
    // Upper-surface point at line 12 moved to y = -0.05, below the lower surface: both upper
    // segments at it cross the lower surface; the leftmost crossing is reported, that of the
    // segment starting at line 12 with the lower segment starting at line 41.
    assert!(err("bad_crossing.dat").ends_with(
        ":12: surfaces cross: segment at line 12 intersects segment at line 41 near (0.4943, -0.02437)"
    ));
}

#[test]
fn wrong_column_count() {
    assert!(err("bad_columns.dat").ends_with(":5: expected 2 columns (x y), found 3"));
}

#[test]
fn binary_garbage_and_control_characters() {
    assert!(err("bad_binary.dat").ends_with(": not a text file (invalid UTF-8 at byte 0)"));
    assert!(err("bad_control.dat")
        .ends_with(":7: binary data (control character 0x00) in a coordinate file"));
}

#[test]
fn lednicer_count_mismatch() {
    assert!(err("bad_lednicer_count.dat")
        .ends_with(":2: Lednicer header announces 28 upper + 26 lower points but 52 were read"));
}

#[test]
fn missing_file() {
    let e = read_airfoil_file(&data("does_not_exist.dat")).unwrap_err();
    assert!(matches!(e, GeometryError::Input(_)));
    assert!(
        e.to_string().starts_with("cannot read airfoil file ")
            && e.to_string().ends_with("does_not_exist.dat: no such file")
    );
}

#[test]
fn selig_writer_round_trips_paneled_nodes() {
    let p = airfoil_by_name_or_path("naca23012")
        .unwrap()
        .repanel(160, &PanelingParams::default())
        .unwrap();
    let text = to_selig_string(&p);
    assert!(text.starts_with("NACA 23012\n"));
    let (back, fmt) = parse_airfoil_text(&text, "mem", "x").unwrap();
    assert_eq!(fmt, CoordinateFormat::Selig);
    assert_eq!(back.name, "NACA 23012");
    for i in 0..160 {
        assert!((back.x[i] - p.x[i]).abs() <= 5e-9 && (back.y[i] - p.y[i]).abs() <= 5e-9);
    }
}
