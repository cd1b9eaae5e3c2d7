//! `polargen plot`: polars from the shipped tables overlaid in SVG and PNG, and its errors.

use std::path::PathBuf;
use std::process::{Command, Output};

fn polargen(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_polargen"))
        .args(args)
        .output()
        .expect("run polargen")
}

fn polars(name: &str) -> String {
    format!("{}/polars/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// A scratch folder of its own for each test (tests run concurrently and each removes its folder).
fn out_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("polargen-plot-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn overlay_svg_and_png() {
    let dir = out_dir("overlay");
    let svg = dir.join("p.svg");
    let png = dir.join("p.png");
    for out in [&svg, &png] {
        let o = polargen(&[
            "plot",
            &polars("naca8h12_free.csv"),
            &polars("naca8h12_xtr0.07.csv"),
            "--re",
            "1.9e6",
            "--mach",
            "0.41",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.len() > 20_000);
    for needle in [
        "NACA 8-H-12 free",
        "NACA 8-H-12 xtr 0.07",
        "nearest to Re 1.9e6, M 0.41",
        "Re 2e6, M 0.4",
        "Drag polar",
        "Cd [-]",
        "Cm (c/4) [-]",
    ] {
        assert!(text.contains(needle), "SVG lacks '{needle}'");
    }
    let bytes = std::fs::read(&png).unwrap();
    assert!(bytes.len() > 50_000);
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn errors_are_one_line() {
    let dir = out_dir("errors");
    let out = dir.join("e.svg");
    let out = out.to_str().unwrap();
    let free = polars("naca8h12_free.csv");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["plot", &free, "--out", out], "give --re and --mach"),
        (
            vec!["plot", &free, "--re", "5e6", "--mach", "0.4", "--out", out],
            "--re 5000000: outside the table",
        ),
        (
            vec!["plot", &free, "--re", "1e6", "--mach", "0.7", "--out", out],
            "--mach 0.7: outside the table",
        ),
        (
            vec![
                "plot",
                "/no/table.csv",
                "--re",
                "1e6",
                "--mach",
                "0",
                "--out",
                out,
            ],
            "/no/table.csv",
        ),
        (
            vec![
                "plot",
                &free,
                "--re",
                "1e6",
                "--mach",
                "0",
                "--out",
                "/tmp/x.jpg",
            ],
            "unknown file extension",
        ),
        (vec!["plot", "--out", out], "TABLE"),
    ];
    for (args, needle) in cases {
        let o = polargen(&args);
        let err = String::from_utf8_lossy(&o.stderr).to_string();
        assert!(!o.status.success(), "{args:?} succeeded");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
    assert!(!dir.join("e.svg").exists());
    std::fs::remove_dir_all(dir).unwrap();
}
