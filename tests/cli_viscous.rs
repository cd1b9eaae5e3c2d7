//! The `polargen` binary in viscous mode: single polars, small grids, formats, thread-count
//! determinism and input errors.

mod cli_support;
mod xfoil_support;
use cli_support::{polargen, scratch, stderr};

/// Column index by name in a CSV header.
fn col(header: &str, name: &str) -> usize {
    header
        .split(',')
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no column {name} in {header}"))
}

#[test]
fn single_polar_matches_xfoil_and_has_required_columns() {
    let o = polargen(&[
        "--airfoil",
        "naca0012",
        "--re",
        "1e6",
        "--mach",
        "0",
        "--alpha",
        "0:4:2",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("3 of 3 points converged"),
        "{}",
        stderr(&o)
    );
    let text = String::from_utf8(o.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let h = lines[0];
    for c in [
        "airfoil",
        "re",
        "mach",
        "ncrit",
        "xtr_top_set",
        "xtr_bot_set",
        "alpha",
        "cl",
        "cd",
        "cdp",
        "cm",
        "xtr_top",
        "xtr_bot",
        "converged",
    ] {
        col(h, c);
    }
    assert_eq!(lines.len(), 4);
    // Against XFOIL 6.99 at α = 4° (its own paneling; ours differs by < 1e-6 c): measured
    // |ΔCl| 2.5e-5 and |ΔCd|/Cd 1.6e-4; limits about three times that, not below XFOIL's
    // rounding (5e-5 in Cl, 5e-6 in Cd: 6.9e-4 of it).
    let row: Vec<&str> = lines[3].split(',').collect();
    let cl: f64 = row[col(h, "cl")].parse().unwrap();
    let cd: f64 = row[col(h, "cd")].parse().unwrap();
    assert_eq!(row[col(h, "converged")], "true");
    let xfoil = xfoil_support::polar("naca0012_Re1e6_M0_free.csv");
    let r = xfoil_support::at_alpha(&xfoil, 4.0).unwrap();
    eprintln!("cl {cl} vs {}, cd {cd} vs {}", r.cl, r.cd);
    assert!((cl - r.cl).abs() <= 8e-5, "cl {cl} vs XFOIL {}", r.cl);
    assert!((cd / r.cd - 1.0).abs() <= 7e-4, "cd {cd} vs XFOIL {}", r.cd);
}

/// `--tolerance` sets the Newton threshold: every point's last RMS change (the `residual`
/// column) is below it, and a tighter threshold takes more iterations than the default.
#[test]
fn tolerance_flag_sets_the_newton_threshold() {
    let run = |extra: &[&str]| -> Vec<(f64, u32)> {
        let mut args = vec!["--airfoil", "naca0012", "--re", "1e6", "--alpha", "0:4:1"];
        args.extend_from_slice(extra);
        let o = polargen(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        let text = String::from_utf8(o.stdout).unwrap();
        let h = text.lines().next().unwrap().to_string();
        text.lines()
            .skip(1)
            .map(|l| {
                let row: Vec<&str> = l.split(',').collect();
                assert_eq!(row[col(&h, "converged")], "true", "{l}");
                (
                    row[col(&h, "residual")].parse().unwrap(),
                    row[col(&h, "iterations")].parse().unwrap(),
                )
            })
            .collect()
    };
    let default = run(&[]);
    let tight = run(&["--tolerance", "1e-8"]);
    assert!(default.iter().all(|&(r, _)| r < 1e-3), "{default:?}");
    assert!(tight.iter().all(|&(r, _)| r < 1e-8), "{tight:?}");
    let iterations = |v: &[(f64, u32)]| v.iter().map(|p| p.1).sum::<u32>();
    assert!(
        iterations(&tight) > iterations(&default),
        "{tight:?} {default:?}"
    );
}

#[test]
fn forced_transition_is_reported() {
    let o = polargen(&[
        "--airfoil",
        "naca8h12",
        "--re",
        "1.9e6",
        "--mach",
        "0.41",
        "--alpha",
        "2",
        "--xtr-top",
        "0.07",
        "--xtr-bot",
        "0.5",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let h = lines[0];
    let row: Vec<&str> = lines[1].split(',').collect();
    let xt: f64 = row[col(h, "xtr_top")].parse().unwrap();
    let xb: f64 = row[col(h, "xtr_bot")].parse().unwrap();
    assert_eq!(row[col(h, "xtr_top_set")], "0.07");
    assert_eq!(row[col(h, "xtr_bot_set")], "0.5");
    assert!(xt <= 0.0701, "xtr_top {xt}");
    assert!(xb <= 0.5001, "xtr_bot {xb}");
}

#[test]
fn grid_output_is_identical_for_any_thread_count() {
    let args = |threads: &'static str| {
        polargen(&[
            "--airfoil",
            "naca2412",
            "--re",
            "5e5,1e6",
            "--mach",
            "0,0.3",
            "--alpha",
            "-2:4:2",
            "--threads",
            threads,
        ])
    };
    let one = args("1");
    let two = args("2");
    assert!(one.status.success(), "{}", stderr(&one));
    assert_eq!(one.stdout, two.stdout);
    let text = String::from_utf8(one.stdout.clone()).unwrap();
    // 2 Re × 2 M × 4 α rows plus the header.
    assert_eq!(text.lines().count(), 17);
    // stderr is not a terminal here: no progress bar, the start line of the work and the
    // summary line (a job this short ends before the first progress line).
    for o in [&one, &two] {
        let err = stderr(o);
        let lines: Vec<&str> = err.lines().collect();
        assert_eq!(lines.len(), 2, "{err}");
        assert!(lines[0].starts_with("polargen: 4 polars of NACA 2412: 16 points"));
        assert!(lines[1].starts_with("polargen: ") && lines[1].contains("of 16 points converged"));
    }
}

#[test]
fn formats_by_extension_and_flag() {
    let dir = scratch("formats");
    let common = [
        "--airfoil",
        "naca0012",
        "--re",
        "1e6,2e6",
        "--mach",
        "0.2",
        "--alpha",
        "0:2:1",
    ];
    let run = |extra: &[&str]| {
        let mut a: Vec<&str> = common.to_vec();
        a.extend_from_slice(extra);
        let o = polargen(&a);
        assert!(o.status.success(), "{extra:?}: {}", stderr(&o));
        o
    };
    let json = dir.join("sub/t.json");
    run(&["--out", json.to_str().unwrap()]);
    let table = polargen::table::read_table(&json).unwrap();
    assert_eq!(table.re(), &[1e6, 2e6]);
    assert_eq!(table.point_count(), 6);

    let csv = dir.join("t.csv");
    run(&["--out", csv.to_str().unwrap()]);
    let back = polargen::table::read_table(&csv).unwrap();
    assert_eq!(back, table);

    run(&[
        "--format",
        "xfoil",
        "--out",
        dir.join("p.pol").to_str().unwrap(),
    ]);
    let pols: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
        .filter(|n| n.ends_with(".pol"))
        .collect();
    assert_eq!(pols.len(), 2, "{pols:?}");

    run(&["--out", dir.join("t.c81").to_str().unwrap()]);
    let c81: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
        .filter(|n| n.ends_with(".c81"))
        .collect();
    assert_eq!(c81.len(), 2, "one C81 per Re: {c81:?}");
    std::fs::remove_dir_all(dir).unwrap();
}

/// Each bad input gives exactly one line on stderr naming the flag and value, and a non-zero
/// exit, before any solving.
#[test]
fn errors_name_the_flag() {
    let dir = scratch("flag-errors");
    let file = dir.join("plain");
    std::fs::write(&file, "x").unwrap();
    let not_under_a_folder = file.join("t.csv").to_str().unwrap().to_string();
    let base = ["--airfoil", "naca0012"];
    let cases: &[(&[&str], &str)] = &[
        (&["--re", "0"], "--re 0"),
        (&["--re", "-1e6"], "--re -1000000"),
        (&["--re", "1e6,abc"], "--re abc: not a number"),
        (&["--re", "1e6,,2e6"], "--re"),
        (&["--re", "1e6", "--mach", "1"], "--mach 1"),
        (&["--re", "1e6", "--mach", "0,-0.2"], "--mach -0.2"),
        (
            &["--mach", "0.3"],
            "--mach: give the Reynolds numbers with --re too",
        ),
        (&["--xtr", "1.5"], "--xtr 1.5"),
        (&["--xtr-top", "-0.1"], "--xtr-top -0.1"),
        (&["--xtr-bot", "2"], "--xtr-bot 2"),
        (&["--re", "1e6,2e6,1e6"], "--re 1000000: given twice"),
        (&["--re", "1e6", "--mach", "0.3,0.3"], "given twice"),
        (&["--re", "nan"], "--re NaN"),
        (&["--alpha", "nan:1:1"], "--alpha"),
        (&["--alpha", "170:190:10"], "'190' is outside -180…180 deg"),
        (&["--threads", "-1"], "--threads"),
        (&["--panels", "-3"], "--panels"),
        (&["--airfoil", "/"], "--airfoil: airfoil '/' is a folder"),
        (&["--out", "/"], "--out: /: is a folder"),
        (&["--out", &not_under_a_folder], "is not a folder"),
        (&["--xtr", "0.1", "--xtr-top", "0.2"], "--xtr"),
        (&["--ncrit", "0"], "--ncrit 0"),
        (&["--ncrit", "-3"], "--ncrit -3"),
        (&["--tolerance", "0"], "--tolerance 0"),
        (&["--tolerance", "1"], "--tolerance 1"),
        (&["--tolerance", "nan"], "--tolerance NaN"),
        (&["--alpha", "0:4:0"], "step is 0"),
        (&["--alpha", "4:0:1"], "empty"),
        (&["--format", "xls"], "xls"),
        (
            &["--format", "c81"],
            "c81 writes one file per Re: give a file name",
        ),
        (&["--out", "/tmp/x.unknown"], "x.unknown"),
        (&["--threads", "x"], "--threads"),
    ];
    for (extra, needle) in cases {
        let mut a: Vec<&str> = if extra.contains(&"--airfoil") {
            Vec::new()
        } else {
            base.to_vec()
        };
        a.extend_from_slice(extra);
        let o = polargen(&a);
        let err = stderr(&o);
        assert!(!o.status.success(), "{extra:?} succeeded");
        assert_eq!(err.lines().count(), 1, "{extra:?}: {err}");
        assert!(err.contains(needle), "{extra:?}: {err}");
    }
    std::fs::remove_dir_all(dir).unwrap();
}

/// A run in which no point converges writes no table (not even a folder) and fails.
#[test]
fn no_converged_point_writes_nothing() {
    let dir = scratch("none-converged").join("out");
    let out = dir.join("t.csv");
    let o = polargen(&[
        "--airfoil",
        "naca0012",
        "--re",
        "1e6",
        "--mach",
        "0",
        "--alpha",
        "89:91:1",
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = stderr(&o);
    assert!(!o.status.success());
    // The start line of the work, then the error with the census.
    assert!(
        err.starts_with("polargen: 1 polar of NACA 0012: 3 points"),
        "{err}"
    );
    assert!(
        err.contains("\npolargen: error: 0 of 3 points converged")
            && err.ends_with(": no point converged; no table written\n"),
        "{err}"
    );
    assert!(!dir.exists(), "nothing is created");
}
