//! The conventions both tools keep (docs/cli/README.md): every bad value is a usage error
//! (exit 2, one line naming the flag), a bare command points to its help, the `gyro` commands
//! read the shipped MTOsport and its tables when none are given, man pages exist for every
//! subcommand, `--format` is a value enum, and diagnostics never cost a result (a full stderr,
//! a closed stdout, data on stdout kept apart from the summary).

mod cli_support;

use cli_support::{closed_pipe_is_quiet, gyro, polargen, repo, run, scratch, stderr, text};
use std::process::{Command, Output};

const POLARGEN: &str = env!("CARGO_BIN_EXE_polargen");
const GYRO: &str = env!("CARGO_BIN_EXE_gyro");

/// The run is a usage error: exit 2 and one line `<tool>: error: …` holding `expect`.
fn usage_error(name: &str, args: &[&str], expect: &str) {
    let o = run(name, args);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{name} {args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{name} {args:?}: {err}");
    assert!(err.starts_with(&format!("{name}: error: ")), "{err}");
    assert!(
        err.contains(expect),
        "{name} {args:?}: expected '{expect}' in {err}"
    );
    assert!(o.stdout.is_empty(), "{name} {args:?}");
}

#[test]
fn every_bad_value_is_a_usage_error_naming_the_flag() {
    let base = ["--airfoil", "naca0012", "--alpha", "0"];
    let grid = |extra: &[&'static str]| -> Vec<&'static str> {
        let mut v: Vec<&str> = base.to_vec();
        v.extend_from_slice(extra);
        v
    };
    for (args, expect) in [
        (grid(&["--re", "abc"]), "--re abc: not a number"),
        (
            grid(&["--re", "0"]),
            "--re 0: the Reynolds number must be positive",
        ),
        (
            grid(&["--re", "1e6,500"]),
            "--re 500: the viscous solver takes Reynolds numbers from 1000",
        ),
        (
            grid(&["--re", "1e6", "--out", "x.c81"]),
            "--format c81 needs at least two angles of attack",
        ),
        (
            grid(&["--re", "1e6", "--panels", "5"]),
            "--panels 5: must be between",
        ),
        (grid(&["--re", "1e6", "--panels", "-1"]), "--panels -1"),
        (grid(&["--re", "1e6", "--ncrit", "abc"]), "--ncrit abc"),
        (grid(&["--re", "1e6", "--ncrit-top", "0"]), "--ncrit-top 0"),
        (
            grid(&["--re", "1e6", "--mach", "1"]),
            "--mach 1: the Mach number",
        ),
        (grid(&["--re", "1e6", "--xtr", "2"]), "--xtr 2"),
        (
            grid(&["--re", "1e6", "--xtr-bot", "-0.1"]),
            "--xtr-bot -0.1",
        ),
        (
            grid(&["--re", "1e6", "--tolerance", "0.5"]),
            "--tolerance 0.5",
        ),
        (grid(&["--re", "1e6", "--threads", "x"]), "--threads x"),
        (
            grid(&["--re", "1e6", "--format", "xls"]),
            "--format xls: must be one of",
        ),
        (grid(&["--re", "1e6,2e6,1e6"]), "--re 1000000: given twice"),
        (
            grid(&["--mach", "0.3"]),
            "--mach: give the Reynolds numbers with --re",
        ),
        (grid(&["--re", "1e6", "--cd-max", "-2"]), "--cd-max -2"),
        (
            grid(&["--re", "1e6", "--cd-max", "1e308"]),
            "--cd-max 1e308: must be in (0, 3]",
        ),
        (grid(&["--inviscid", "--mach", "0.1,0.2"]), "--mach"),
    ] {
        usage_error("polargen", &args, expect);
    }
    usage_error(
        "polargen",
        &[
            "--airfoil",
            "naca0012",
            "--re",
            "1e6",
            "--alpha",
            "0:1:1e-12",
        ],
        "--alpha",
    );
    usage_error(
        "polargen",
        &[
            "--airfoil",
            "naca0012",
            "--re",
            "1e4,2e4,3e4,4e4,5e4,6e4,7e4,8e4",
            "--alpha",
            "-180:180:0.05",
        ],
        "more than the limit of 50000 points",
    );
    let point = [
        "point",
        "--airfoil",
        "naca0012",
        "--alpha",
        "2",
        "--csv",
        "-",
    ];
    usage_error(
        "polargen",
        &[&point[..], &["--re", "-5"]].concat(),
        "--re -5",
    );
    usage_error(
        "polargen",
        &[&point[..], &["--re", "1e6", "--xtr", "1,1.5"]].concat(),
        "--xtr 1.5",
    );
    usage_error(
        "polargen",
        &[
            "convert",
            "polars/naca8h12_free.csv",
            "--out",
            "x.csv",
            "--format",
            "png",
        ],
        "--format png",
    );
    usage_error(
        "polargen",
        &[
            "plot",
            "polars/naca8h12_free.csv",
            "--out",
            "x.svg",
            "--re",
            "0",
        ],
        "--re 0",
    );
    usage_error(
        "polargen",
        &[
            "batch",
            "--airfoils",
            "naca0012",
            "--out",
            "t",
            "--format",
            "xfoil",
        ],
        "--format xfoil",
    );
    usage_error(
        "polargen",
        &[
            "batch",
            "--airfoils",
            "naca0012",
            "--out",
            "t",
            "--jobs",
            "-1",
        ],
        "--jobs -1",
    );
    for (args, expect) in [
        (&["trim", "--speed-kt", "0"][..], "--speed-kt 0"),
        (&["trim", "--speed-kt", "fast"][..], "--speed-kt fast"),
        (&["trim", "--mass", "0"][..], "--mass 0"),
        (&["trim", "--altitude-m", "-5"][..], "--altitude-m -5"),
        (&["alpha", "--radius", "2"][..], "--radius 2"),
        (&["alpha", "--radius", "0.05"][..], "--radius 0.05"),
        (&["alpha", "--samples", "1"][..], "--samples 1"),
        (&["sweep", "--step-kt", "0"][..], "--step-kt 0"),
        (
            &["sweep", "--from-kt", "90", "--to-kt", "30"][..],
            "--to-kt 30",
        ),
        (&["takeoff", "--mass", "1e9"][..], "--mass 1e9"),
        (&["study", "wing", "--areas", "50"][..], "--areas 50"),
        (&["study", "wing", "--speeds", "400"][..], "--speeds 400"),
        (&["study", "contamination", "--trips", "2"][..], "--trips 2"),
        (
            &["study", "contamination", "--outboard", "1.5"][..],
            "--outboard 1.5",
        ),
        (&["study", "speed", "--xtr", "x"][..], "--xtr x"),
        (
            &["plot", "alpha", "--out", "a.svg", "--samples", "0"][..],
            "--samples 0",
        ),
        (&["man", "nosuch"][..], "nosuch"),
    ] {
        usage_error("gyro", args, expect);
    }
}

#[test]
fn a_bare_command_prints_its_help() {
    for name in ["polargen", "gyro"] {
        let o = run(name, &[]);
        assert_eq!(o.status.code(), Some(2));
        let help = text(&o.stderr);
        assert!(help.contains("Usage:") && help.contains("--help"), "{help}");
    }
}

#[test]
fn format_is_a_value_enum_listed_in_help_and_completions() {
    let help = text(&polargen(&["convert", "-h"]).stdout);
    assert!(
        help.contains("[possible values: csv, json, jsonl, xfoil, c81, aerodyn]"),
        "{help}"
    );
    let long = text(&polargen(&["convert", "--help"]).stdout);
    assert!(
        long.contains("- aerodyn: OpenFAST AeroDyn airfoil file"),
        "{long}"
    );
    let bash = text(&polargen(&["completions", "bash"]).stdout);
    assert!(
        bash.contains("csv json jsonl xfoil c81 aerodyn"),
        "no format values offered"
    );
    // The aliases still parse.
    let o = run(
        "polargen",
        &[
            "convert",
            "polars/naca8h12_free.csv",
            "--format",
            "pol",
            "--out",
            "-",
        ],
    );
    // A per-polar format to standard output: flags that contradict each other, exit 2.
    assert_eq!(o.status.code(), Some(2), "{}", text(&o.stderr));
    assert!(
        text(&o.stderr).contains("give a file name"),
        "{}",
        text(&o.stderr)
    );
}

#[test]
fn every_subcommand_has_a_man_page_and_every_reference_resolves() {
    for name in ["polargen", "gyro"] {
        let dir = scratch(&format!("man-{name}"));
        let o = run(name, &["man", "--out", dir.to_str().unwrap()]);
        assert!(o.status.success(), "{}", text(&o.stderr));
        let pages: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        assert!(pages.contains(&format!("{name}.1")), "{pages:?}");
        for page in &pages {
            let roff = std::fs::read_to_string(dir.join(page)).unwrap();
            // Every `<tool>-<sub>(1)` a page names is a page of the set.
            for (k, _) in roff.match_indices(&format!("{name}\\-")) {
                let rest = &roff[k..];
                let Some(end) = rest.find("(1)") else {
                    continue;
                };
                let referred = rest[..end].replace("\\-", "-");
                if referred
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '-')
                {
                    assert!(
                        pages.contains(&format!("{referred}.1")),
                        "{page} refers to {referred}(1), which has no page: {pages:?}"
                    );
                }
            }
        }
        let _ = std::fs::remove_dir_all(dir);
    }
    let batch = text(&polargen(&["man", "batch"]).stdout);
    assert!(batch.contains(".TH polargen-batch 1"), "{batch}");
    let wing = text(&gyro(&["man", "study", "wing"]).stdout);
    assert!(
        wing.contains(".TH gyro-study-wing 1") && wing.contains("areas"),
        "{wing}"
    );
}

#[test]
fn gyro_commands_read_the_shipped_aircraft_and_tables_when_none_are_given() {
    // Outside the repository the built-in copies stand in; one note says so.
    let dir = scratch("defaults");
    let o = Command::new(GYRO)
        .arg("trim")
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = text(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(text(&o.stdout).contains("rotor rpm"), "{}", text(&o.stdout));
    let notes: Vec<&str> = err.lines().filter(|l| l.contains("shipped")).collect();
    assert_eq!(notes.len(), 1, "{err}");
    assert!(
        notes[0].contains("aircraft/mtosport.toml") && notes[0].contains("naca8h12_free.csv"),
        "{err}"
    );
    // Given inputs: no note, the same numbers.
    let (ac, table) = (
        repo("aircraft/mtosport.toml"),
        repo("polars/naca8h12_free.csv"),
    );
    let given = Command::new(GYRO)
        .args(["trim", "--aircraft", &ac, "--table", &table])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(given.status.success(), "{}", text(&given.stderr));
    assert!(
        !text(&given.stderr).contains("shipped"),
        "{}",
        text(&given.stderr)
    );
    assert_eq!(given.stdout, o.stdout);
    let _ = std::fs::remove_dir_all(dir);
}

/// Runs `script` in bash with `$0` set to the binary (for redirections Rust cannot express,
/// such as a closed descriptor).
fn shell(bin: &str, script: &str) -> Output {
    Command::new("bash")
        .args(["-c", script, bin])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("bash")
}

#[test]
fn a_full_stderr_costs_no_result_and_a_closed_stdout_is_an_error() {
    let grid = r#""$0" --airfoil naca0012 --re 1e6 --alpha 0:2:1"#;
    let full = shell(POLARGEN, &format!("{grid} 2>/dev/full"));
    assert_eq!(full.status.code(), Some(0));
    assert_eq!(
        text(&full.stdout).lines().count(),
        4,
        "{}",
        text(&full.stdout)
    );
    let full = shell(GYRO, r#""$0" trim 2>/dev/full"#);
    assert_eq!(full.status.code(), Some(0));
    assert!(text(&full.stdout).contains("rotor rpm"));
    for (bin, script) in [
        (POLARGEN, format!("{grid} >&-")),
        (GYRO, r#""$0" trim >&-"#.to_string()),
    ] {
        let closed = shell(bin, &script);
        let err = text(&closed.stderr);
        assert_eq!(closed.status.code(), Some(1), "{script}: {err}");
        assert!(err.contains("standard output is closed"), "{err}");
    }
    // Closed stdout and full stderr together: still exit 1, no panic (status 101).
    let both = shell(GYRO, r#""$0" trim >&- 2>/dev/full"#);
    assert_eq!(both.status.code(), Some(1));
}

#[test]
fn a_takeoff_history_on_stdout_is_data_only_and_stops_quietly_when_the_reader_goes() {
    let o = gyro(&["takeoff", "--history", "-"]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let csv = text(&o.stdout);
    assert!(csv.starts_with("t,x,h,v,rotor_rpm,alpha_r_deg,beta_deg\n"));
    assert!(
        csv.lines().all(|l| l.split(',').count() == 7),
        "a non-data line on stdout"
    );
    assert!(
        text(&o.stderr).contains("lift-off speed"),
        "{}",
        text(&o.stderr)
    );
    // `| head -1`: the reader leaves after one line.
    closed_pipe_is_quiet("gyro", &["takeoff", "--history", "-", "--quiet"]);
}
