//! Unix plumbing of both binaries: standard input and output as files, closed pipes, the one
//! error/exit-code convention, `--quiet`, completions and man pages, bare commands, the
//! `--re`-alone rule (`gyro report` outside the repository: tests/gyro_report.rs).

use std::path::{Path, PathBuf};

mod cli_support;
use cli_support::{closed_pipe_is_quiet, run, run_with_stdin, scratch, text};

const POLARGEN: &str = "polargen";
const GYRO: &str = "gyro";

fn data(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(rel)
}

#[test]
fn airfoil_from_stdin_equals_the_file() {
    let file = data("geometry/selig_clockwise_naca8h12.dat");
    let args = ["--inviscid", "--alpha", "0:4:2", "--airfoil"];
    let from_file = run(POLARGEN, &[&args[..], &[file.to_str().unwrap()]].concat());
    let bytes = std::fs::read(&file).unwrap();
    let from_stdin = run_with_stdin(POLARGEN, &[&args[..], &["-"]].concat(), &bytes);
    assert!(from_stdin.status.success(), "{}", text(&from_stdin.stderr));
    assert_eq!(from_file.stdout, from_stdin.stdout);
    assert_eq!(text(&from_stdin.stdout).lines().count(), 4);
}

#[test]
fn out_dash_is_standard_output_for_tables_only() {
    let o = run(
        POLARGEN,
        &[
            "--airfoil",
            "naca0012",
            "--inviscid",
            "--alpha",
            "2",
            "--out",
            "-",
        ],
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert!(text(&o.stdout).starts_with("alpha,cl,cd,cm,converged\n"));
    let table = data("xfoil/naca8h12_Re1.9e6_M0.41_free.csv");
    let json = run(
        POLARGEN,
        &[
            "convert",
            table.to_str().unwrap(),
            "--out",
            "-",
            "--format",
            "json",
        ],
    );
    assert!(json.status.success(), "{}", text(&json.stderr));
    assert!(text(&json.stdout).trim_start().starts_with('{'));
    let pol = run(
        POLARGEN,
        &[
            "convert",
            table.to_str().unwrap(),
            "--out",
            "-",
            "--format",
            "xfoil",
        ],
    );
    // A per-polar format to standard output: contradicting flags, a usage error.
    assert_eq!(pol.status.code(), Some(2));
    assert!(
        text(&pol.stderr).starts_with("polargen: error: ")
            && text(&pol.stderr).contains("give a file name"),
        "{}",
        text(&pol.stderr)
    );
}

#[test]
fn a_closed_pipe_exits_quietly_with_status_0() {
    // Large enough outputs that the pipe buffer (64 KiB) fills before the reader leaves.
    closed_pipe_is_quiet(
        POLARGEN,
        &[
            "--airfoil",
            "naca0012",
            "--inviscid",
            "--alpha",
            "-90:90:0.01",
        ],
    );
    closed_pipe_is_quiet(GYRO, &["completions", "zsh"]);
    closed_pipe_is_quiet(GYRO, &["man"]);
}

#[test]
fn one_error_prefix_and_exit_code_convention() {
    // Usage errors: exit 2, one line `<tool>: error: …`.
    for (bin, name) in [(POLARGEN, "polargen"), (GYRO, "gyro")] {
        let o = run(bin, &["--no-such-flag"]);
        assert_eq!(o.status.code(), Some(2));
        let err = text(&o.stderr);
        assert!(err.starts_with(&format!("{name}: error: ")), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    // Run errors: exit 1, one line with the same prefix.
    let o = run(POLARGEN, &["--airfoil", "/no/such/file.dat", "--inviscid"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o.stderr).starts_with("polargen: error: "));
    let o = run(
        GYRO,
        &[
            "trim",
            "--aircraft",
            "/no/such.toml",
            "--table",
            "/no/such.csv",
        ],
    );
    assert_eq!(o.status.code(), Some(1));
    let err = text(&o.stderr);
    assert!(
        err.starts_with("gyro: error: ") && err.lines().count() == 1,
        "{err}"
    );
}

#[test]
fn bare_gyro_and_gyro_plot_list_their_subcommands() {
    for args in [&[][..], &["plot"][..]] {
        let o = run(GYRO, args);
        assert_eq!(o.status.code(), Some(2));
        let help = text(&o.stderr);
        assert!(help.contains("Commands:"), "{help}");
    }
    assert!(text(&run(GYRO, &[]).stderr).contains("report"));
    let plot = text(&run(GYRO, &["plot"]).stderr);
    assert!(["alpha", "takeoff", "power"]
        .iter()
        .all(|k| plot.contains(k)));
}

#[test]
fn quiet_silences_notes_but_not_errors() {
    // A contour off chord units: normalised with a note.
    let dir = scratch("quiet");
    let foil = dir.join("scaled.dat");
    let src = std::fs::read_to_string(data("geometry/selig_clockwise_naca8h12.dat")).unwrap();
    let scaled: String = src
        .lines()
        .enumerate()
        .map(|(i, l)| {
            if i == 0 {
                return format!("{l}\n");
            }
            let v: Vec<f64> = l
                .split(|c: char| c == ',' || c.is_whitespace())
                .filter(|t| !t.is_empty())
                .map(|t| t.parse().unwrap())
                .collect();
            format!("{} {}\n", 2.0 * v[0], 2.0 * v[1])
        })
        .collect();
    std::fs::write(&foil, scaled).unwrap();
    let args = [
        "--inviscid",
        "--alpha",
        "2",
        "--airfoil",
        foil.to_str().unwrap(),
    ];
    let loud = run(POLARGEN, &args);
    assert!(
        text(&loud.stderr).contains("note:"),
        "{}",
        text(&loud.stderr)
    );
    let quiet = run(POLARGEN, &[&args[..], &["--quiet"]].concat());
    assert!(quiet.status.success() && quiet.stderr.is_empty());
    assert_eq!(loud.stdout, quiet.stdout);
    let failed = run(POLARGEN, &["-q", "--airfoil", "nacaXYZ", "--inviscid"]);
    assert!(text(&failed.stderr).starts_with("polargen: error: "));
}

#[test]
fn completions_and_man_pages() {
    for (bin, name) in [(POLARGEN, "polargen"), (GYRO, "gyro")] {
        for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
            let o = run(bin, &["completions", shell]);
            assert!(o.status.success(), "{name} {shell}: {}", text(&o.stderr));
            assert!(text(&o.stdout).contains(name), "{name} {shell}");
        }
        let man = run(bin, &["man"]);
        assert!(man.status.success());
        let page = text(&man.stdout);
        assert!(page.contains(&format!(".TH {name} 1")), "{page}");
        let bad = run(bin, &["completions", "cmd.exe"]);
        assert_eq!(bad.status.code(), Some(2));
    }
    assert!(text(&run(POLARGEN, &["completions", "bash"]).stdout).contains("--ncrit"));
}

#[test]
fn re_alone_is_one_polar_at_mach_0_and_mach_alone_is_refused() {
    let o = run(
        POLARGEN,
        &[
            "--airfoil",
            "naca0012",
            "--re",
            "1e6",
            "--alpha",
            "0:2:2",
            "-q",
        ],
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    let rows: Vec<&str> = out.lines().skip(1).collect();
    assert_eq!(rows.len(), 2, "{out}");
    assert!(
        rows.iter().all(|r| r.starts_with("NACA 0012,1000000,0,")),
        "{out}"
    );
    let m = run(POLARGEN, &["--airfoil", "naca0012", "--mach", "0.3"]);
    assert_eq!(m.status.code(), Some(2));
    assert!(text(&m.stderr).contains("--re"), "{}", text(&m.stderr));
}

#[test]
fn takeoff_history_times_carry_no_round_off() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = scratch("history");
    let hist = dir.join("h.csv");
    let o = run(
        GYRO,
        &[
            "takeoff",
            "--aircraft",
            root.join("aircraft/mtosport.toml").to_str().unwrap(),
            "--table",
            root.join("polars/naca8h12_free.csv").to_str().unwrap(),
            "--history",
            hist.to_str().unwrap(),
        ],
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    let h = std::fs::read_to_string(&hist).unwrap();
    for line in h.lines().skip(1) {
        let t = line.split(',').next().unwrap();
        let decimals = t.split('.').nth(1).map_or(0, str::len);
        assert!(decimals <= 6, "time {t} shows round-off");
    }
}
