//! The `polargen` binary in inviscid mode: output format, α parsing, errors.

mod cli_support;
mod xfoil_support;
use cli_support::{polargen, stderr};
use std::process::Output;

#[test]
fn inviscid_csv_to_stdout() {
    let o = polargen(&["--airfoil", "naca0012", "--inviscid", "--alpha", "-4:4:2"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "alpha,cl,cd,cm,converged");
    assert_eq!(lines.len(), 6);
    // Symmetric section: cl(α) = −cl(−α), cl(0) = 0 printed without a sign.
    let row = |i: usize| -> Vec<String> { lines[i].split(',').map(String::from).collect() };
    assert_eq!(row(3), ["0", "0.000000", "0", "0.000000", "true"]);
    let cl4: f64 = row(5)[1].parse().unwrap();
    let clm4: f64 = row(1)[1].parse().unwrap();
    assert!((cl4 + clm4).abs() < 1e-6);
    // Against XFOIL 6.99 (its geometry and paneling): measured 4.9e-5 (XFOIL prints 4
    // decimals), the limit about three times that.
    let xfoil = xfoil_support::at_alpha(&xfoil_support::polar("naca0012_inviscid_M0.csv"), 4.0)
        .unwrap()
        .cl;
    eprintln!("cl(4°) = {cl4}, XFOIL {xfoil}");
    assert!(
        (cl4 - xfoil).abs() <= 1.5e-4,
        "cl(4°) = {cl4}, XFOIL {xfoil}"
    );
}

#[test]
fn alpha_with_equals_and_negative_start() {
    let a = polargen(&["--airfoil=naca8h12", "--inviscid", "--alpha=-4:12:2"]);
    let b = polargen(&["--airfoil", "naca8h12", "--inviscid", "--alpha", "-4:12:2"]);
    assert!(a.status.success() && b.status.success());
    assert_eq!(a.stdout, b.stdout);
    assert_eq!(String::from_utf8_lossy(&a.stdout).lines().count(), 10);
}

#[test]
fn out_file_is_written_into_new_folder() {
    let dir = std::env::temp_dir().join(format!("polargen-cli-{}", std::process::id()));
    let path = dir.join("sub").join("p.csv");
    let o = polargen(&[
        "--airfoil",
        "naca2412",
        "--inviscid",
        "--mach",
        "0.3",
        "--alpha",
        "2",
        "--out",
        path.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.starts_with("alpha,cl,cd,cm,converged\n2,"));
    std::fs::remove_dir_all(dir).unwrap();
}

/// Each bad input gives exactly one line on stderr naming the problem and a non-zero exit.
#[test]
fn errors_are_one_line() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["--airfoil", "nope", "--inviscid"],
            "unknown airfoil 'nope'",
        ),
        (
            &["--airfoil", "naca0012", "--inviscid", "--mach", "1"],
            "--mach",
        ),
        (
            &["--airfoil", "naca0012", "--inviscid", "--mach", "-0.1"],
            "--mach",
        ),
        (
            &["--airfoil", "naca0012", "--inviscid", "--mach", "abc"],
            "--mach",
        ),
        (
            &["--airfoil", "naca0012", "--inviscid", "--alpha", "4:0:1"],
            "empty",
        ),
        (
            &["--airfoil", "naca0012", "--inviscid", "--alpha", "0:4:0"],
            "step is 0",
        ),
        (
            &["--airfoil", "naca0012", "--inviscid", "--alpha", "0:x:1"],
            "'x'",
        ),
        (
            &["--airfoil", "naca0012", "--inviscid", "--panels", "5"],
            "--panels",
        ),
        (
            &["--airfoil", "naca0012", "--inviscid", "--panels", "100000"],
            "--panels",
        ),
        (
            &["--airfoil", "/no/such/file.dat", "--inviscid"],
            "/no/such/file.dat",
        ),
        (&["--airfoil", "naca0012", "--bogus"], "--bogus"),
        (&["--inviscid"], "--airfoil"),
    ];
    for (args, needle) in cases {
        let o = polargen(args);
        let err = stderr(&o);
        assert!(!o.status.success(), "{args:?} succeeded");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

#[test]
fn failure_leaves_no_output_file() {
    let dir = std::env::temp_dir().join(format!("polargen-cli-fail-{}", std::process::id()));
    let path = dir.join("p.csv");
    // M = 0.95 exceeds the critical Mach: the error comes mid-sweep, after the file was opened.
    let o = polargen(&[
        "--airfoil",
        "naca0012",
        "--inviscid",
        "--mach",
        "0.95",
        "--out",
        path.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(!path.exists());
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn coordinates_in_other_units_are_normalised() {
    // The same contour in chord units and in percent (×100, shifted by 5 in x, tabs):
    // identical coefficients, and a note that the second one was normalised.
    let dir = std::env::temp_dir().join(format!("polargen-units-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let unit = polargen(&["--airfoil", "naca2412", "--inviscid", "--alpha", "3"]);
    let foil = polargen::geometry::airfoil_by_name_or_path("naca2412").unwrap();
    let text: String = foil
        .x
        .iter()
        .zip(&foil.y)
        .map(|(x, y)| format!("{}\t{}\n", 100.0 * x + 5.0, 100.0 * y))
        .collect();
    let path = dir.join("percent.dat");
    std::fs::write(&path, format!("NACA 2412 in percent\n{text}")).unwrap();
    let scaled = polargen(&[
        "--airfoil",
        path.to_str().unwrap(),
        "--inviscid",
        "--alpha",
        "3",
    ]);
    assert!(
        unit.status.success() && scaled.status.success(),
        "{}",
        stderr(&scaled)
    );
    assert!(stderr(&unit).is_empty());
    assert!(
        stderr(&scaled).contains("normalised to unit chord"),
        "{}",
        stderr(&scaled)
    );
    let coeffs = |o: &Output| -> Vec<f64> {
        let line = String::from_utf8_lossy(&o.stdout)
            .lines()
            .nth(1)
            .unwrap()
            .to_string();
        line.split(',')
            .take(4)
            .map(|v| v.parse().unwrap())
            .collect()
    };
    let (a, b) = (coeffs(&unit), coeffs(&scaled));
    assert!(
        (a[1] - b[1]).abs() <= 2e-6 && (a[3] - b[3]).abs() <= 2e-6,
        "{a:?} vs {b:?}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

/// The viscous table's flags that change nothing in the panel solution, and formats other
/// than CSV, are usage errors under `--inviscid` (they were ignored: a `.c81` file held CSV).
#[test]
fn viscous_flags_and_other_formats_are_refused() {
    let base = ["--airfoil", "naca2412", "--inviscid", "--alpha", "0"];
    for (extra, needle) in [
        (&["--re", "1e6"][..], "--re: does not apply to --inviscid"),
        (&["--xtr", "0.1"][..], "--xtr: does not apply"),
        (&["--cd-max", "1.5"][..], "--cd-max: does not apply"),
        (
            &["--flap", "0.75:0", "--flap-deg", "-5,5", "--out", "f.csv"][..],
            "--flap-deg: does not apply",
        ),
        (&["--ncrit-top", "5"][..], "--ncrit-top: does not apply"),
        (&["--format", "json"][..], "--inviscid writes CSV"),
        (
            &["--out", "p.dat"][..],
            "cannot infer table format from 'p.dat'",
        ),
        (&["--out", "x.c81"][..], "--inviscid writes CSV"),
    ] {
        let o = polargen(&[&base[..], extra].concat());
        cli_support::assert_one_line_error("polargen", &o, needle);
        assert_eq!(o.status.code(), Some(2), "{extra:?}");
    }
    assert!(!std::path::Path::new("x.c81").exists() && !std::path::Path::new("f.csv").exists());
}
