//! Flap sweeps in the formats with a flap axis: AeroDyn files holding one table per
//! deflection (`UserProp`, OpenFAST's AFTabMod 3), read back with `--user-prop`, and C81
//! decks, one per deflection and Re.

mod cli_support;

use cli_support::{assert_one_line_error, ok, polargen, scratch};
use polargen::section::SectionAero;
use polargen::table::{read_table, read_table_with, PolarTable, ReadOptions};

/// The coarse sweep of these tests: NACA 0012, a 25 % flap, one Re, α −4…8°.
const SWEEP: [&str; 12] = [
    "-q",
    "--airfoil",
    "naca0012",
    "--re",
    "1e6",
    "--alpha",
    "-4:8:4",
    "--flap",
    "0.75:0",
    "--flap-deg",
    "-5,0,5",
    "--out",
];

/// (α, Cl, Cd, Cm) of the usable points of the table's only polar.
fn rows(table: &PolarTable) -> Vec<[f64; 4]> {
    table
        .polar_at(0, 0)
        .unwrap()
        .iter()
        .filter(|p| p.usable())
        .map(|p| [p.alpha, p.cl, p.cd, p.cm])
        .collect()
}

/// One AeroDyn file for the one (Re, M) with the three deflections in increasing order, each
/// with its UA block; `--user-prop 5` reads the 5° table back equal to the sweep's 5° CSV
/// table; without it a one-line error lists the deflections.
#[test]
fn an_aerodyn_flap_sweep_is_one_file_read_back_by_user_prop() {
    let dir = scratch("flap-aerodyn");
    let dat = dir.join("f.dat");
    let csv = dir.join("t.csv");
    let run = |out: &std::path::Path, extra: &[&str]| {
        let mut args = SWEEP.to_vec();
        args.push(out.to_str().unwrap());
        args.extend_from_slice(extra);
        ok(polargen(&args));
    };
    run(&dat, &["--format", "aerodyn"]);
    run(&csv, &[]);
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('f'))
        .collect();
    assert_eq!(names, ["f.dat"]);
    let text = std::fs::read_to_string(&dat).unwrap();
    let value = |name: &str| -> Vec<String> {
        text.lines()
            .filter(|l| l.split_whitespace().nth(1) == Some(name))
            .map(|l| l.split_whitespace().next().unwrap().to_string())
            .collect()
    };
    assert_eq!(value("NumTabs"), ["3"]);
    assert_eq!(value("UserProp"), ["-5", "0", "5"]);
    assert_eq!(value("Re"), ["1", "1", "1"]);
    assert_eq!(value("InclUAdata"), ["True", "True", "True"]);

    let options = ReadOptions {
        user_prop: Some(5.0),
        ..ReadOptions::default()
    };
    let back = read_table_with(&dat, &options).unwrap().table;
    let five = read_table(&dir.join("t_flap5.csv")).unwrap();
    assert_eq!(back.meta(), five.meta());
    assert_eq!(back.meta().flap_deg(), Some(5.0));
    assert_eq!((back.re(), back.mach()), (five.re(), five.mach()));
    assert_eq!(rows(&back), rows(&five));
    assert_eq!(rows(&five).len(), 4);

    // The CLI: convert with --user-prop gives the 5° table; without it, one line naming the
    // deflections.
    let out = dir.join("back.csv");
    let conv = |extra: &[&str]| {
        let mut args = vec!["convert", dat.to_str().unwrap(), "--out"];
        args.push(out.to_str().unwrap());
        args.extend_from_slice(extra);
        polargen(&args)
    };
    ok(conv(&["--user-prop", "5", "-q"]));
    assert_eq!(rows(&read_table(&out).unwrap()), rows(&five));
    let o = conv(&[]);
    assert_eq!(o.status.code(), Some(1));
    assert_one_line_error(
        "polargen",
        &o,
        "the tables are at UserProp -5, 0, 5: choose one with --user-prop",
    );
}

/// C81 has no flap axis: one deck per deflection and Re, named after both; a path that
/// cannot be written is found before the work, for the AeroDyn set as for the others.
#[test]
fn a_c81_flap_sweep_writes_one_deck_per_deflection_and_re() {
    let dir = scratch("flap-c81");
    let out = dir.join("d.c81");
    let mut args = SWEEP.to_vec();
    args[4] = "1e6,2e6";
    args[10] = "-5,5";
    args.push(out.to_str().unwrap());
    ok(polargen(&args));
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "d_flap-5_Re1e6.c81",
            "d_flap-5_Re2e6.c81",
            "d_flap5_Re1e6.c81",
            "d_flap5_Re2e6.c81"
        ]
    );
    let up = read_table(&dir.join("d_flap5_Re2e6.c81")).unwrap();
    let down = read_table(&dir.join("d_flap-5_Re2e6.c81")).unwrap();
    // At α 0 the symmetric section's lift is the flap's: opposite for ±5°.
    let cl0 = |t: &PolarTable| t.lookup(0.0, 2e6, 0.0).cl;
    assert!(
        cl0(&up) > 0.25 && cl0(&down) < -0.25,
        "{} {}",
        cl0(&up),
        cl0(&down)
    );

    // The AeroDyn set is checked before solving: a folder where a file must go.
    let blocked = dir.join("blocked.dat");
    std::fs::create_dir_all(dir.join("blocked_Re2e6_M0.dat")).unwrap();
    let mut args = SWEEP.to_vec();
    args[4] = "1e6,2e6";
    args.extend_from_slice(&[blocked.to_str().unwrap(), "--format", "aerodyn"]);
    let o = polargen(&args);
    assert!(!o.status.success());
    assert_one_line_error("polargen", &o, "blocked_Re2e6_M0.dat");
    assert!(!dir.join("blocked_Re1e6_M0.dat").exists());
}

/// One deflection to standard output is the table on standard output (no file named `-…`);
/// a sweep whose last deflection's contour is refused, a deflection given twice (−0 is 0) or
/// a sweep over the points limit is an error before any solve, with no file written.
#[test]
fn a_sweep_is_checked_whole_before_any_solve() {
    let dir = scratch("flap-whole");
    let run_in = |args: &[&str]| {
        std::process::Command::new(cli_support::exe("polargen"))
            .args(args)
            .current_dir(&dir)
            .output()
            .unwrap()
    };
    let base = [
        "-q",
        "--airfoil",
        "naca2412",
        "--re",
        "1e6",
        "--alpha",
        "0:2:2",
        "--flap",
        "0.75:0",
    ];
    for out in ["-", "/dev/stdout"] {
        let stdout = ok(run_in(
            &[&base[..], &["--flap-deg", "10", "--out", out]].concat(),
        ));
        assert!(stdout.starts_with("airfoil,re,mach"), "{out}: {stdout}");
        assert!(stdout.contains("flap 0.75:0:10"), "{out}: {stdout}");
    }
    let two = run_in(&[&base[..], &["--flap-deg", "5,10", "--out", "/dev/stdout"]].concat());
    assert_one_line_error(
        "polargen",
        &two,
        "one table per deflection needs --out FILE",
    );
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    let started = std::time::Instant::now();
    let folds = run_in(&[&base[..], &["--flap-deg", "-10,0,89", "--out", "f.csv"]].concat());
    assert_one_line_error("polargen", &folds, "(flap 0.75:0:89)");
    assert!(started.elapsed().as_secs_f64() < 5.0);
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    let twice = run_in(&[&base[..], &["--flap-deg", "0,-0", "--out", "f.csv"]].concat());
    assert_one_line_error("polargen", &twice, "--flap-deg 0: given twice");
    assert_eq!(twice.status.code(), Some(2));
    // The default grid (3 904 points) thirteen times is more than 50 000 points.
    let many = run_in(&[
        "-q",
        "--airfoil",
        "naca2412",
        "--flap",
        "0.75:0",
        "--flap-deg",
        "-30,-25,-20,-15,-10,-5,0,5,10,15,20,25,30",
        "--out",
        "f.csv",
    ]);
    assert_one_line_error("polargen", &many, "13 tables of 3904 points");
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Progress that puts a folder where the sweep's last table is to be written once that table
/// is solved: the checks before the solves passed, the write then fails.
struct BlockLastTable {
    tables: std::sync::atomic::AtomicUsize,
    count: usize,
    obstacle: std::path::PathBuf,
}

impl polargen::progress::Progress for BlockLastTable {
    fn start(&self, _: &polargen::progress::Work) {}
    fn advance(&self, _: usize) {}
    fn finish(&self) {
        let done = 1 + self
            .tables
            .fetch_add(1, std::sync::atomic::Ordering::SeqCst);
        if done == self.count {
            std::fs::create_dir_all(self.obstacle.join("inside")).unwrap();
        }
    }
}

/// The tables of a sweep are written together or not at all: when the last table's file
/// cannot be written, the tables already solved leave no file either (the folder in the way
/// is all the folder holds).
#[test]
fn a_sweep_whose_last_write_fails_leaves_no_table() {
    use polargen::geometry::ShapeOp;
    use polargen::table::{FlapSweep, GridSpec, TableFormat, TableJob};
    let dir = scratch("flap-set");
    let out = dir.join("t.csv");
    let ops = [ShapeOp::flap("0.75:0").unwrap()];
    let sweep = FlapSweep::new(&ops, Some("0,5"), &out, TableFormat::Csv).unwrap();
    let grid = GridSpec {
        reynolds: vec![1e6],
        mach: vec![0.0],
        alpha_deg: vec![0.0, 2.0],
    };
    sweep
        .check_output(TableFormat::Csv, &grid.reynolds, &grid.mach)
        .unwrap();
    let job = TableJob {
        airfoil: "naca2412",
        derotate: false,
        panels: 160,
        grid: &grid,
        base: &polargen::viscous::ViscousParams::default(),
        threads: 1,
        cd_max: None,
        format: TableFormat::Csv,
    };
    let progress = BlockLastTable {
        tables: 0.into(),
        count: 2,
        obstacle: dir.join("t_flap5.csv"),
    };
    let said = std::sync::Mutex::new(Vec::new());
    let err = job
        .run(&sweep, &progress, &|line| said.lock().unwrap().push(line))
        .unwrap_err();
    let chain: Vec<String> = anyhow::Error::from(err)
        .chain()
        .map(|e| e.to_string())
        .collect();
    assert!(chain.join(": ").contains("t_flap5.csv"), "{chain:?}");
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    assert_eq!(names, ["t_flap5.csv"]);
    assert!(said.lock().unwrap().iter().all(|l| !l.contains(" in ")));
}
