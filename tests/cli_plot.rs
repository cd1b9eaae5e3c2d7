//! `polargen plot`: polars from the shipped tables overlaid in SVG and PNG, and its errors.

mod cli_support;
use cli_support::{polargen, polars, scratch};

#[test]
fn overlay_svg_and_png() {
    let dir = scratch("overlay");
    let (free_table, trip_table) = (polars("naca8h12_free.csv"), polars("naca8h12_xtr0.07.csv"));
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
        "Transition: upper solid, lower dashed",
        "points beyond",
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
    // --label names the legend entries (and the title) in the order of the tables;
    // --cd-axis 0.03 fixes the drag polar's Cd axis, and --cd-axis all shows all drag
    let labelled = dir.join("labelled.svg");
    let run = |extra: &[&str]| {
        let mut args = vec![
            "plot",
            &free_table,
            &trip_table,
            "--re",
            "1.9e6",
            "--mach",
            "0.41",
            "--out",
            labelled.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let o = polargen(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read_to_string(&labelled).unwrap()
    };
    let tick = |svg: &str, t: &str| svg.lines().any(|l| l.trim() == t);
    let text = run(&[
        "--label",
        "clean, 2 m/s",
        "--label",
        "tripped",
        "--cd-axis",
        "0.03",
    ]);
    assert!(text.contains("clean, 2 m/s vs tripped — Re 2e6, M 0.4"));
    assert!(!text.contains("NACA 8-H-12 free"));
    assert!(tick(&text, "0.030"), "Cd axis to 0.03");
    assert!(text.contains("points beyond 0.0300"));
    let tick = |svg: &str, t: &str| svg.lines().any(|l| l.trim() == t);
    let text = run(&["--cd-axis", "all"]);
    assert!(!text.contains("points beyond"));
    assert!(tick(&text, "0.20"), "Cd axis over all drag (to 0.24)");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn point_distributions_clean_vs_trip() {
    let dir = scratch("point");
    let svg = dir.join("p.svg");
    let csv = dir.join("p.csv");
    let args = [
        "plot-point",
        "--airfoil",
        "naca8h12",
        "--re",
        "1.9e6",
        "--mach",
        "0.41",
        "--cl",
        "0.8",
        "--xtr",
        "1,0.07",
        "--csv",
        csv.to_str().unwrap(),
        "--out",
    ];
    for out in [&svg, &dir.join("p.png")] {
        let mut a = args.to_vec();
        a.push(out.to_str().unwrap());
        let o = polargen(&a);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.len() > 20_000);
    for needle in [
        "NACA 8-H-12 — Re 1.9e6, M 0.41, Cl 0.8",
        "Pressure distribution",
        "Shape factor",
        "Skin friction",
        "Amplification",
        "free upper",
        "xtr 0.07 lower",
        "transition x/c = 0.070 (xtr 0.07 upper)",
        "Ncrit = 9",
    ] {
        assert!(text.contains(needle), "SVG lacks '{needle}'");
    }
    let png = std::fs::read(dir.join("p.png")).unwrap();
    assert!(png.len() > 50_000 && png.starts_with(b"\x89PNG"));
    // The CSV holds both cases; the tripped case is turbulent from x/c = 0.07 on the upper
    // surface, and the free case transitions well behind it (XFOIL: x/c ≈ 0.39 at Cl 0.8).
    let table = std::fs::read_to_string(&csv).unwrap();
    let first_turbulent = |case: &str| {
        table
            .lines()
            .skip(1)
            .map(|l| l.split(',').collect::<Vec<_>>())
            .filter(|f| f[0] == case && f[2] == "upper" && f[14] == "true")
            .map(|f| f[4].parse::<f64>().unwrap())
            .next()
            .unwrap()
    };
    let (free, trip) = (first_turbulent("free"), first_turbulent("xtr 0.07"));
    assert!(
        (0.07..0.09).contains(&trip),
        "tripped: turbulent from x/c {trip}"
    );
    assert!(
        (0.36..0.43).contains(&free),
        "free: turbulent from x/c {free}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn errors_are_one_line() {
    let dir = scratch("errors");
    let out = dir.join("e.svg");
    let out = out.to_str().unwrap();
    let free = polars("naca8h12_free.csv");
    let bad_path = dir.join("bad.csv");
    std::fs::write(&bad_path, "alpha,cl\n1,garbage\n").unwrap();
    let bad = bad_path.to_str().unwrap().to_string();
    let empty_path = dir.join("empty.csv");
    std::fs::write(&empty_path, "").unwrap();
    let empty = empty_path.to_str().unwrap().to_string();
    // a regular file where a folder should be; a CSV that must not appear when the image fails
    let not_under_a_folder = format!("{bad}/x.svg");
    let csv = dir.join("point.csv").to_str().unwrap().to_string();
    let txt = dir.join("point.txt").to_str().unwrap().to_string();
    /// plot-point of NACA 0012 at Re 1e6, alpha 2 with the given extra arguments
    fn point<'a>(extra: &[&'a str]) -> Vec<&'a str> {
        let mut args = vec![
            "plot-point",
            "--airfoil",
            "naca0012",
            "--re",
            "1e6",
            "--alpha",
            "2",
        ];
        args.extend_from_slice(extra);
        args
    }
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
        (vec!["plot", &bad, "--out", out], "lacks column 'airfoil'"),
        (
            vec![
                "plot",
                &free,
                "--re",
                "1e6",
                "--mach",
                "0",
                "--out",
                "/proc/no/x.svg",
            ],
            "cannot write plot /proc/no/x.svg",
        ),
        (
            vec![
                "plot-point",
                "--airfoil",
                "naca0012",
                "--re",
                "-1",
                "--alpha",
                "2",
                "--out",
                out,
            ],
            "--re -1: the Reynolds number must be positive",
        ),
        (
            vec![
                "plot-point",
                "--airfoil",
                "naca0012",
                "--re",
                "1e6",
                "--alpha",
                "2",
                "--xtr",
                "1,x",
                "--out",
                out,
            ],
            "--xtr x: not a number",
        ),
        (
            vec![
                "plot-point",
                "--airfoil",
                "naca0012",
                "--re",
                "1e6",
                "--out",
                out,
            ],
            "--alpha",
        ),
        (
            vec![
                "plot-point",
                "--airfoil",
                "naca0012",
                "--re",
                "1e6",
                "--cl",
                "4",
                "--out",
                out,
            ],
            "on the way to Cl 4",
        ),
        (
            point(&["--out", "/proc/no/x.png"]),
            "cannot write plot /proc/no/x.png",
        ),
        (
            point(&["--out", &not_under_a_folder, "--csv", &csv]),
            "is not a folder",
        ),
        (
            point(&["--out", &txt, "--csv", &csv]),
            "unknown file extension",
        ),
        (vec!["plot", &empty, "--out", out], "CSV line 1: empty file"),
        (
            vec!["plot", &free, "--re", "-1", "--mach", "0", "--out", out],
            "--re -1",
        ),
        (
            vec!["plot", &free, "--label", "a", "--label", "b", "--out", out],
            "--label: 2 label(s) for 1 table(s): give one per table, in order",
        ),
        (
            vec!["plot", &free, "--cd-axis", "wide", "--out", out],
            "expected auto, all or a positive drag coefficient",
        ),
        (
            vec!["plot", &free, "--cd-axis", "-0.1", "--out", out],
            "--cd-axis",
        ),
    ];
    for (args, needle) in cases {
        let o = polargen(&args);
        let err = String::from_utf8_lossy(&o.stderr).to_string();
        assert!(!o.status.success(), "{args:?} succeeded");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
    assert!(!dir.join("e.svg").exists());
    assert!(!dir.join("point.csv").exists());
    std::fs::remove_dir_all(dir).unwrap();
}
