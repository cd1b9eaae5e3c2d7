//! `polargen point --csv` (distributions without an image) and the per-side N_crit flags
//! `--ncrit-top`, `--ncrit-bot` of the command line.

mod cli_support;
use cli_support::{ok, polargen, scratch};

const POLAR: [&str; 6] = ["--airfoil", "naca0012", "--re", "1e6", "--alpha", "0:2:1"];

/// `--ncrit N` and `--ncrit-top N --ncrit-bot N` give the same table, byte for byte, with
/// the one `ncrit` column.
#[test]
fn equal_sides_are_the_ncrit_flag_bit_for_bit() {
    let run = |extra: &[&str]| ok(polargen(&[&POLAR[..], &["-q"], extra].concat()));
    let both = run(&["--ncrit", "5"]);
    assert!(both.starts_with("airfoil,re,mach,ncrit,xtr_top_set"));
    assert_eq!(run(&["--ncrit-top", "5", "--ncrit-bot", "5"]), both);
    assert_eq!(run(&["--ncrit", "5", "--ncrit-bot", "5"]), both);
    assert_ne!(run(&["--ncrit", "5", "--ncrit-bot", "3"]), both);
}

/// Unequal sides: the table records both, and they survive conversion to JSON, XFOIL .pol
/// and back; N_crit 3 on the lower surface of the symmetric NACA 0012 moves its transition
/// ahead of the upper one's and gives lift at α = 0 (XFOIL 6.99: Cl 0.0107,
/// tests/data/xfoil/naca0012_Re1e6_M0_nt9_nb3.csv; printed to 1e-4).
#[test]
fn unequal_sides_are_recorded_and_read_back() {
    let dir = scratch("ncrit-sides");
    let table = dir.join("t.csv");
    let t = table.to_str().unwrap();
    ok(polargen(
        &[
            &POLAR[..],
            &["-q", "--ncrit-top", "9", "--ncrit-bot", "3", "--out", t],
        ]
        .concat(),
    ));
    let text = std::fs::read_to_string(&table).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    let field = |name: &str| row[header.iter().position(|h| *h == name).unwrap()];
    assert!(!header.contains(&"ncrit"));
    assert_eq!((field("ncrit_top"), field("ncrit_bot")), ("9", "3"));
    let cl: f64 = field("cl").parse().unwrap();
    assert!((cl - 0.0107).abs() < 1e-4, "Cl {cl}");
    let (xt, xb): (f64, f64) = (
        field("xtr_top").parse().unwrap(),
        field("xtr_bot").parse().unwrap(),
    );
    assert!(xb < xt, "xtr {xt} {xb}");
    for (name, written) in [
        ("t.json", "\"ncrit_top\": 9.0"),
        ("t.pol", "Ncrit =   9.000  3.000"),
    ] {
        let out = dir.join(name);
        ok(polargen(&["convert", t, "--out", out.to_str().unwrap()]));
        assert!(
            std::fs::read_to_string(&out).unwrap().contains(written),
            "{name}"
        );
        let back = dir.join(format!("{name}.csv"));
        ok(polargen(&[
            "convert",
            out.to_str().unwrap(),
            "--out",
            back.to_str().unwrap(),
        ]));
        let back = std::fs::read_to_string(&back).unwrap();
        assert!(
            back.starts_with("airfoil,re,mach,ncrit_top,ncrit_bot,"),
            "{name}"
        );
        assert!(
            back.lines()
                .nth(1)
                .unwrap()
                .starts_with("NACA 0012,1000000,0,9,3,"),
            "{name}"
        );
    }
    let aerodyn = dir.join("t.dat");
    ok(polargen(&[
        "convert",
        t,
        "--out",
        aerodyn.to_str().unwrap(),
        "--format",
        "aerodyn",
    ]));
    let header = std::fs::read_to_string(&aerodyn).unwrap();
    assert!(header
        .lines()
        .nth(1)
        .unwrap()
        .contains("Ncrit 9 (top) 3 (bottom)"));
    std::fs::remove_dir_all(dir).unwrap();
}

/// `point --csv -` writes plot-point's CSV to standard output, and no image: the same bytes as
/// `plot-point --csv FILE`, one row per station of each case's upper and lower surface and wake.
#[test]
fn point_csv_is_plot_point_csv_without_an_image() {
    let dir = scratch("point-csv");
    let case = [
        "--airfoil",
        "naca0012",
        "--re",
        "1e6",
        "--alpha",
        "2",
        "--xtr",
        "1,0.1",
        "--ncrit-bot",
        "5",
    ];
    let stdout = ok(polargen(&[&["point"], &case[..], &["--csv", "-"]].concat()));
    let file = dir.join("p.csv");
    ok(polargen(
        &[&["point"], &case[..], &["--csv", file.to_str().unwrap()]].concat(),
    ));
    assert_eq!(std::fs::read_to_string(&file).unwrap(), stdout);
    let (image, plotted) = (dir.join("p.svg"), dir.join("pp.csv"));
    let plot = [
        &["plot-point"],
        &case[..],
        &["--out", image.to_str().unwrap()],
    ]
    .concat();
    ok(polargen(
        &[&plot[..], &["--csv", plotted.to_str().unwrap()]].concat(),
    ));
    assert_eq!(std::fs::read_to_string(&plotted).unwrap(), stdout);
    let files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(files.len(), 3, "{files:?}");

    let mut lines = stdout.lines();
    assert_eq!(
        lines.next().unwrap(),
        "case,alpha,surface,s,x,y,ue,cp,dstar,theta,cf,h,hk,n_or_ctau,turbulent"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    for case in ["free", "xtr 0.1"] {
        for surface in ["upper", "lower", "wake"] {
            let n = rows
                .iter()
                .filter(|r| r[0] == case && r[2] == surface)
                .count();
            assert!(n > 10, "{case} {surface}: {n} rows");
        }
    }
    assert!(rows.iter().all(|r| r.len() == 15 && r[1] == "2"));
    std::fs::remove_dir_all(dir).unwrap();
}

/// A bad per-side value is a one-line error naming its flag, before any computation.
#[test]
fn bad_per_side_ncrit_names_the_flag() {
    for (args, named) in [
        (&["--ncrit-bot", "0"][..], "--ncrit-bot 0"),
        (&["--ncrit-top", "nan"][..], "--ncrit-top NaN"),
    ] {
        for cmd in [
            &POLAR[..],
            &[
                "point",
                "--airfoil",
                "naca0012",
                "--re",
                "1e6",
                "--alpha",
                "0",
                "--csv",
                "-",
            ][..],
        ] {
            let o = polargen(&[cmd, args].concat());
            let err = String::from_utf8_lossy(&o.stderr).to_string();
            assert!(!o.status.success() && o.stdout.is_empty(), "{err}");
            assert!(
                err.contains(named) && err.trim_end().lines().count() == 1,
                "{err}"
            );
        }
    }
}

/// `point`'s α is within ±180° and its cases at most 20, checked before any solve.
#[test]
fn point_alpha_and_case_count_are_bounded() {
    let base = [
        "point",
        "--airfoil",
        "naca0012",
        "--re",
        "1e6",
        "--csv",
        "-",
    ];
    let many: Vec<String> = (1..=21)
        .map(|i| format!("{}", f64::from(i) / 100.0))
        .collect();
    for (extra, needle) in [
        (
            vec!["--alpha", "1e308"],
            "--alpha 1e308: outside -180…180 deg".to_string(),
        ),
        (
            vec!["--alpha", "2", "--xtr", &many.join(",")],
            "--xtr: 21 transition settings: at most 20".to_string(),
        ),
    ] {
        let o = polargen(&[&base[..], &extra[..]].concat());
        cli_support::assert_one_line_error("polargen", &o, &needle);
        assert_eq!(o.status.code(), Some(2));
    }
}
