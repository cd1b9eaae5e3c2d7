//! Hostile inputs to both binaries (special files, oversized files, odd line ends, absurd
//! magnitudes, stray points, contours listed several times, tables that cannot round-trip,
//! limits that mean minutes, outputs that cannot be written, numbers echoed back): every one
//! must end quickly with a clean one-line error and a non-zero exit, or with a correct result.

use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

mod cli_support;
use cli_support::scratch;

/// No case may take longer than this (every refusal is meant to come before any solve).
const TIME_LIMIT: Duration = Duration::from_secs(20);

fn run(tool: &str, args: &[&str]) -> (Output, Duration) {
    let exe = match tool {
        "polargen" => env!("CARGO_BIN_EXE_polargen"),
        _ => env!("CARGO_BIN_EXE_gyro"),
    };
    let start = Instant::now();
    let out = Command::new(exe)
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    (out, start.elapsed())
}

/// The run failed with one clean line on stderr that contains `expect`.
fn refused(tool: &str, args: &[&str], expect: &str) {
    let (out, took) = run(tool, args);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(!out.status.success(), "{args:?} succeeded: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: not one line: {err}");
    for bad in [
        "panicked",
        "Custom {",
        "Os {",
        "polargen-set",
        "line 0",
        ".tmp",
        "polargen-probe",
    ] {
        assert!(
            !err.contains(bad),
            "{args:?}: unclear message ({bad}): {err}"
        );
    }
    let placeholder = err
        .split('<')
        .skip(1)
        .any(|rest| rest.starts_with(|c: char| c.is_ascii_alphabetic()));
    assert!(!placeholder, "{args:?}: a <placeholder> in: {err}");
    assert!(err.len() < 400, "{args:?}: overlong message: {err}");
    assert!(
        err.contains(expect),
        "{args:?}: expected '{expect}' in: {err}"
    );
    assert!(took < TIME_LIMIT, "{args:?} took {took:?}");
}

/// The run succeeded; its standard output and standard error.
fn accepted(tool: &str, args: &[&str]) -> (String, String) {
    let (out, took) = run(tool, args);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{args:?} failed: {err}");
    assert!(took < TIME_LIMIT, "{args:?} took {took:?}");
    (String::from_utf8_lossy(&out.stdout).into_owned(), err)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// NACA 4412 points (x, y) in XFOIL order.
fn points() -> Vec<(f64, f64)> {
    let a = polargen::geometry::naca("4412", &Default::default()).unwrap();
    a.x.into_iter().zip(a.y).collect()
}

fn write_points(path: &Path, name: &str, pts: &[(f64, f64)], end: &str) {
    let mut t = format!("{name}{end}");
    for (x, y) in pts {
        t.push_str(&format!("{x:.9} {y:.9}{end}"));
    }
    std::fs::write(path, t).unwrap();
}

fn mkfifo(path: &Path) -> bool {
    Command::new("mkfifo")
        .arg(path)
        .status()
        .is_ok_and(|s| s.success())
}

const AIRCRAFT: &str = "aircraft/mtosport.toml";
const TABLE: &str = "tests/data/xfoil/naca8h12_Re1.9e6_M0.41_free.csv";

#[test]
fn special_and_oversized_files_are_refused_at_once() {
    let d = scratch("special");
    refused(
        "polargen",
        &["--airfoil", "/dev/zero", "--inviscid"],
        "not a regular file (a character device)",
    );
    let link = d.join("random.json");
    std::os::unix::fs::symlink("/dev/urandom", &link).unwrap();
    refused(
        "polargen",
        &["convert", s(&link), "--out", s(&d.join("o.csv"))],
        "not a regular file",
    );
    let fifo = d.join("preset.toml");
    if mkfifo(&fifo) {
        refused(
            "gyro",
            &["trim", "--aircraft", s(&fifo), "--table", TABLE],
            "not a regular file (a FIFO)",
        );
        refused(
            "polargen",
            &["--airfoil", s(&fifo), "--inviscid"],
            "not a regular file (a FIFO)",
        );
    }
    let big = d.join("big.csv");
    std::fs::File::create(&big)
        .unwrap()
        .set_len(65 << 20)
        .unwrap();
    refused(
        "gyro",
        &["trim", "--aircraft", AIRCRAFT, "--table", s(&big)],
        "larger than the input limit of 64 MiB",
    );
}

#[test]
fn contours_of_every_bad_kind_are_refused_and_odd_but_valid_files_work() {
    let d = scratch("contours");
    // Old-Mac line ends: a correct result, the same as with Unix line ends.
    let (mac, unix) = (d.join("mac.dat"), d.join("unix.dat"));
    write_points(&mac, "NACA 4412 mac", &points(), "\r");
    write_points(&unix, "NACA 4412 unix", &points(), "\n");
    let a = accepted(
        "polargen",
        &["--airfoil", s(&mac), "--inviscid", "--alpha", "3"],
    )
    .0;
    let b = accepted(
        "polargen",
        &["--airfoil", s(&unix), "--inviscid", "--alpha", "3"],
    )
    .0;
    assert_eq!(a, b);
    // Micrometres: normalised, said so, same lift.
    let um = d.join("um.dat");
    let scaled: Vec<(f64, f64)> = points().iter().map(|(x, y)| (1e6 * x, 1e6 * y)).collect();
    write_points(&um, "NACA 4412 um", &scaled, "\n");
    let (c, note) = accepted(
        "polargen",
        &["--airfoil", s(&um), "--inviscid", "--alpha", "3"],
    );
    assert!(note.contains("normalised"), "{note}");
    let cl = |t: &str| {
        t.lines()
            .nth(1)
            .unwrap()
            .split(',')
            .nth(1)
            .unwrap()
            .parse::<f64>()
            .unwrap()
    };
    assert!((cl(&c) - cl(&b)).abs() < 1e-4, "{c} {b}");
    // A chord of 10¹² and one of 10⁻¹²: beyond the coordinate limits.
    let km = d.join("huge.dat");
    let huge: Vec<(f64, f64)> = points().iter().map(|(x, y)| (1e12 * x, 1e12 * y)).collect();
    write_points(&km, "huge", &huge, "\n");
    refused(
        "polargen",
        &["--airfoil", s(&km), "--inviscid"],
        "beyond the limit",
    );
    // A stray point below the lower surface, reported as such (not "clockwise").
    let stray = d.join("stray.dat");
    let mut p = points();
    let k = 2 * p.len() / 3;
    p[k].1 -= 0.4;
    write_points(&stray, "stray", &p, "\n");
    refused(
        "polargen",
        &["--airfoil", s(&stray), "--inviscid"],
        "folds back at point",
    );
    // The file cut short after the upper surface: an open arc, not a section.
    let cut = d.join("cut.dat");
    let p = points();
    write_points(&cut, "cut", &p[..p.len() / 2 - 10], "\n");
    refused(
        "polargen",
        &["--airfoil", s(&cut), "--inviscid"],
        "the contour is open",
    );
    // The contour listed three times.
    let thrice = d.join("thrice.dat");
    let p = points();
    let all: Vec<(f64, f64)> = p.iter().chain(&p[1..]).chain(&p[1..]).copied().collect();
    write_points(&thrice, "thrice", &all, "\n");
    refused(
        "polargen",
        &["--airfoil", s(&thrice), "--inviscid"],
        "repeats the point",
    );
    // A flat plate traced out and back.
    let flat = d.join("flat.dat");
    let p: Vec<(f64, f64)> = points().iter().map(|(x, y)| (*x, 1e-4 * y)).collect();
    write_points(&flat, "flat", &p, "\n");
    refused(
        "polargen",
        &["--airfoil", s(&flat), "--inviscid"],
        "almost no area",
    );
    // 30 000 points: over the limit, refused at once.
    let dense = d.join("dense.dat");
    let n = 30_000;
    let p: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            let t = 2.0 * std::f64::consts::PI * i as f64 / (n - 1) as f64;
            (0.5 + 0.5 * t.cos(), 0.05 * t.sin())
        })
        .collect();
    write_points(&dense, "dense", &p, "\n");
    refused(
        "polargen",
        &["--airfoil", s(&dense), "--inviscid"],
        "30000 points, more than the limit of 20000",
    );
}

#[test]
fn tables_that_cannot_round_trip_are_refused() {
    let d = scratch("tables");
    let good = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("polars/naca8h12_free.csv"),
    )
    .unwrap();
    let mut lines: Vec<String> = good.lines().take(40).map(str::to_string).collect();
    let edit = |lines: &mut Vec<String>, col: usize, value: &str| {
        for l in lines.iter_mut().skip(1) {
            let mut f: Vec<&str> = l.split(',').collect();
            f[col] = value;
            *l = f.join(",");
        }
    };
    let cases: [(usize, &str, &str, &str); 6] = [
        (3, "nan", "ncrit_top is unknown", "pol"),
        (5, "-0.5", "xtr_bot_set = -0.5 is invalid", "pol"),
        (4, "inf", "xtr_top_set = inf is invalid", "pol"),
        (7, "7e250", "cl = 7e250 at alpha", "pol"),
        (11, "3.5e9", "xtr_top = 3.5e9 at alpha -10", "csv"),
        (1, "3e-7", "Re = 3e-7 is below the resolution", "pol"),
    ];
    for (col, value, expect, ext) in cases {
        let mut l = lines.clone();
        edit(&mut l, col, value);
        let path = d.join(format!("t{col}.csv"));
        std::fs::write(&path, l.join("\n")).unwrap();
        let out = d.join(format!("out{col}.{ext}"));
        refused("polargen", &["convert", s(&path), "--out", s(&out)], expect);
        assert!(!out.exists());
    }
    // A JSON table with an empty polar.
    lines.truncate(3);
    let csv = d.join("small.csv");
    std::fs::write(&csv, lines.join("\n")).unwrap();
    let json = d.join("small.json");
    accepted("polargen", &["convert", s(&csv), "--out", s(&json)]);
    let text = std::fs::read_to_string(&json).unwrap();
    let start = text.find("\"polars\"").unwrap();
    let emptied = format!("{}\"polars\": [[]]\n}}\n", &text[..start]);
    std::fs::write(&json, emptied).unwrap();
    refused(
        "polargen",
        &["convert", s(&json), "--out", s(&d.join("x.csv"))],
        "has no points",
    );
}

#[test]
fn limits_and_late_checks_come_before_any_solve() {
    let d = scratch("limits");
    refused(
        "polargen",
        &[
            "--airfoil",
            "naca0012",
            "--re",
            "1e6",
            "--alpha",
            "2:2.0000000001:1e-11",
        ],
        "below the 1e-9 deg resolution",
    );
    refused(
        "polargen",
        &[
            "--airfoil",
            "naca0012",
            "--re",
            "1e6",
            "--alpha",
            "0",
            "--tolerance",
            "0.5",
        ],
        "--tolerance 0.5: must be above 0 and at most 0.01",
    );
    refused(
        "polargen",
        &[
            "--airfoil",
            "naca0012",
            "--re",
            "1e6,2e6,3e6,4e6,5e6,6e6,7e6,8e6",
            "--alpha",
            "-180:180:0.05",
        ],
        "more than the limit of 50000 points",
    );
    // An output folder that cannot take files (procfs), found before the default grid.
    refused(
        "polargen",
        &["--airfoil", "naca0012", "--out", "/proc/polargen-out.csv"],
        "cannot create files in this folder",
    );
    refused(
        "polargen",
        &[
            "plot-point",
            "--airfoil",
            "naca0012",
            "--re",
            "1e6",
            "--alpha",
            "2",
            "--out",
            "Cargo.toml/fig.png",
        ],
        "is not a folder",
    );
    // A preset whose strips × azimuth steps mean minutes per trim.
    let preset = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(AIRCRAFT))
        .unwrap()
        .replace("radial_strips = 10", "radial_strips = 100")
        .replace("azimuth_steps = 36", "azimuth_steps = 100");
    let heavy = d.join("heavy.toml");
    std::fs::write(&heavy, preset).unwrap();
    refused(
        "gyro",
        &["trim", "--aircraft", s(&heavy), "--table", TABLE],
        "10000 blade-element cells, more than the limit of 2880",
    );
    refused(
        "gyro",
        &[
            "sweep",
            "--aircraft",
            AIRCRAFT,
            "--table",
            TABLE,
            "--from-kt",
            "20",
            "--to-kt",
            "120",
            "--step-kt",
            "0.5",
        ],
        "exceed the limit of 36000 speeds × cells",
    );
}

#[test]
fn numbers_are_echoed_short_and_supercritical_points_are_flagged() {
    let long = format!("-{}", "9".repeat(300));
    refused(
        "polargen",
        &["--airfoil", "naca0012", "--re", &long, "--alpha", "0"],
        "--re -1e300: the Reynolds number must be positive",
    );
    refused(
        "gyro",
        &[
            "trim",
            "--aircraft",
            AIRCRAFT,
            "--table",
            TABLE,
            "--speed-kt",
            &long[1..],
        ],
        "--speed-kt 1e300: must be above 0",
    );
    let (csv, note) = accepted(
        "polargen",
        &[
            "--airfoil",
            "naca2412",
            "--inviscid",
            "--mach",
            "0.85",
            "--alpha",
            "0:4:2",
        ],
    );
    assert_eq!(csv.lines().count(), 4);
    assert!(
        note.contains("supercritical") && note.contains("only indicative"),
        "{note}"
    );
}

#[test]
fn a_file_set_appears_whole_or_not_at_all() {
    let d = scratch("set");
    // One of the six C81 names is taken by a folder: nothing of the set may appear.
    std::fs::create_dir_all(d.join("t_Re1e6.c81")).unwrap();
    refused(
        "polargen",
        &[
            "convert",
            "polars/naca8h12_free.csv",
            "--out",
            s(&d.join("t.c81")),
        ],
        "t_Re1e6.c81",
    );
    let names: Vec<String> = std::fs::read_dir(&d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["t_Re1e6.c81"], "{names:?}");
}

/// A single-polar table of `alphas` (a plausible attached-flow polar in the units given).
fn short_table(path: &Path, alphas: &[f64], per_degree: f64) {
    let mut text = String::from("alpha,cl,cd,cm\n");
    for a in alphas {
        let cl = 0.1 * a / per_degree + 0.2;
        text.push_str(&format!("{a},{cl},{},-0.02\n", 0.008 + 0.005 * cl * cl));
    }
    std::fs::write(path, text).unwrap();
}

#[test]
fn a_table_short_of_the_rotors_alpha_range_is_refused_before_the_trim() {
    let d = scratch("alpha-range");
    let narrow = d.join("narrow.csv");
    short_table(&narrow, &[-2.0, -1.0, 0.0, 1.0, 2.0], 1.0);
    let radians = d.join("radians.csv");
    let rad: Vec<f64> = (-3..=6).map(|k| f64::from(k) * 0.05).collect();
    short_table(&radians, &rad, std::f64::consts::PI / 180.0);
    refused(
        "gyro",
        &["trim", "--aircraft", AIRCRAFT, "--table", s(&narrow)],
        "α spans only -2…2°",
    );
    refused(
        "gyro",
        &["takeoff", "--table", s(&radians)],
        "α in radians?",
    );
    refused(
        "gyro",
        &["compare", "--clean", TABLE, "--contaminated", s(&narrow)],
        "narrow.csv",
    );
}

#[test]
fn a_prerotation_beyond_the_speed_of_sound_at_the_tip_is_refused() {
    let d = scratch("prerotation");
    let preset =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(AIRCRAFT)).unwrap();
    let line = preset
        .lines()
        .find(|l| l.trim_start().starts_with("prerotation_rpm"))
        .expect("the preset sets prerotation_rpm");
    let fast = d.join("fast.toml");
    std::fs::write(&fast, preset.replace(line, "prerotation_rpm = 1e9")).unwrap();
    refused(
        "gyro",
        &["takeoff", "--aircraft", s(&fast), "--table", TABLE],
        "takeoff.prerotation_rpm = 1e9 is invalid: must keep the blade tip below the speed of sound",
    );
}

#[test]
fn the_360_degree_rows_carry_no_round_off() {
    let d = scratch("rows360");
    let out = d.join("t.dat");
    accepted(
        "polargen",
        &["convert", TABLE, "--format", "aerodyn", "--out", s(&out)],
    );
    let text = std::fs::read_to_string(&out).unwrap();
    for a in ["-180", "-90", "90", "180"] {
        let row = text
            .lines()
            .find(|l| l.split_whitespace().next() == Some(a))
            .unwrap_or_else(|| panic!("no row at {a}°"));
        assert!(!row.contains("e-1"), "round-off in the {a}° row: {row}");
    }
    let row = |a: &str| {
        text.lines()
            .find(|l| l.starts_with(&format!("{a} ")))
            .unwrap()
    };
    assert_eq!(row("-90"), "-90 0 2 0.5");
    assert_eq!(row("180"), "180 0 0.03 0");
}
