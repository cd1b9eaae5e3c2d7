//! `polargen convert`: shipped tables to JSON (round trip) and C81 (structure), and its errors.

use std::path::PathBuf;

use polargen::table::{read_table, write_table, TableFormat};

mod cli_support;
use cli_support::{polargen, polars, scratch};

fn shipped(name: &str) -> PathBuf {
    PathBuf::from(polars(name))
}

/// The long-form CSV text of the table in `path`.
fn csv_text(path: &std::path::Path) -> String {
    let out = scratch("csv-text").join("t.csv");
    write_table(&read_table(path).unwrap(), &out, Some(TableFormat::Csv)).unwrap();
    std::fs::read_to_string(out).unwrap()
}

#[test]
fn csv_to_json_round_trip_and_c81_per_re() {
    let src = shipped("naca8h12_xtr0.07.csv");
    let dir = scratch("ok");
    let json = dir.join("t.json");
    let o = polargen(&[
        "convert",
        src.to_str().unwrap(),
        "--out",
        json.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // Same table (compared through its CSV text: unconverged rows hold NaN, which `==` rejects).
    assert_eq!(csv_text(&json), csv_text(&src));

    let c81 = dir.join("sub").join("t.c81");
    let o = polargen(&[
        "convert",
        src.to_str().unwrap(),
        "--out",
        c81.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("wrote 8 files"));
    let text = std::fs::read_to_string(dir.join("sub").join("t_Re2e6.c81")).unwrap();
    let first = text.lines().next().unwrap();
    assert!(first.starts_with("NACA 8-H-12"), "{first}");
    // Eight Mach columns in the header row of the CL block.
    let machs: Vec<f64> = text
        .lines()
        .nth(1)
        .unwrap()
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(machs, vec![0.0, 0.2, 0.3, 0.4, 0.5, 0.55, 0.6, 0.65]);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn errors_are_one_line() {
    let dir = scratch("err");
    let src = shipped("naca8h12_free.csv");
    let cases: [(Vec<String>, &str); 3] = [
        (
            vec![
                "convert".into(),
                "no/such.csv".into(),
                "--out".into(),
                dir.join("a.json").display().to_string(),
            ],
            "no/such.csv",
        ),
        (
            vec![
                "convert".into(),
                src.display().to_string(),
                "--out".into(),
                dir.join("a.txt").display().to_string(),
            ],
            "cannot infer table format",
        ),
        (
            vec![
                "convert".into(),
                src.display().to_string(),
                "--out".into(),
                dir.join("a.csv").display().to_string(),
                "--format".into(),
                "xls".into(),
            ],
            "xls",
        ),
    ];
    for (args, needle) in cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = polargen(&args);
        assert!(!o.status.success(), "{args:?} succeeded");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{err} lacks {needle}");
        assert!(!err.contains("panicked"));
    }
    assert!(!dir.join("a.txt").exists() && !dir.join("a.csv").exists());
    std::fs::remove_dir_all(dir).unwrap();
}
