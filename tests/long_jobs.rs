//! Long jobs talk when stderr is not a terminal (a log file, `nohup`, CI, a notebook cell):
//! `polargen` grids, `batch`, `gyro study` and `gyro report` print a start line with the work
//! (polars or tables to solve, points, an estimate) before solving; `--quiet` silences it. The
//! plain progress lines that follow at a steady interval are tested in `polargen::progress`.

mod cli_support;

use cli_support::scratch;
use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::Duration;

/// Starts `bin args` with stderr on a pipe and returns the first stderr line holding `needle`
/// within `within` (the process is then stopped), or every line read when none did.
fn first_line_with(
    bin: &str,
    args: &[&str],
    needle: &str,
    within: Duration,
) -> Result<String, Vec<String>> {
    let mut child = Command::new(bin)
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let stderr = child.stderr.take().unwrap();
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stderr).lines().map_while(Result::ok) {
            if send.send(line).is_err() {
                break;
            }
        }
    });
    let mut seen = Vec::new();
    let deadline = std::time::Instant::now() + within;
    let found = loop {
        let left = deadline.saturating_duration_since(std::time::Instant::now());
        match receive.recv_timeout(left) {
            Ok(line) if line.contains(needle) => break Some(line),
            Ok(line) => seen.push(line),
            Err(_) => break None,
        }
    };
    let _ = child.kill();
    let _ = child.wait();
    found.ok_or(seen)
}

#[test]
fn grids_and_batches_state_their_work_before_solving() {
    let polargen = env!("CARGO_BIN_EXE_polargen");
    let line = first_line_with(
        polargen,
        &[
            "--airfoil",
            "naca0012",
            "--re",
            "1e6,2e6",
            "--mach",
            "0,0.3",
            "--alpha",
            "-2:6:1",
        ],
        "points",
        Duration::from_secs(60),
    )
    .unwrap();
    assert!(
        line.starts_with("polargen: 4 polars of NACA 0012: 36 points, ")
            && (line.contains("about") || line.contains("under")),
        "{line}"
    );
    let dir = scratch("batch");
    let out = dir.join("tables");
    let line = first_line_with(
        polargen,
        &[
            "batch",
            "--airfoils",
            "naca0012",
            "naca2412",
            "--out",
            out.to_str().unwrap(),
        ],
        "points",
        Duration::from_secs(60),
    )
    .unwrap();
    assert!(
        line.contains("2 airfoil tables") && line.contains("7808 points"),
        "{line}"
    );
    // --quiet: nothing.
    let o = Command::new(polargen)
        .args(["--airfoil", "naca0012", "--re", "1e6", "--alpha", "0", "-q"])
        .output()
        .unwrap();
    assert!(o.status.success() && o.stderr.is_empty());
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_cold_study_and_the_report_state_their_work_before_solving() {
    let gyro = env!("CARGO_BIN_EXE_gyro");
    let cache = scratch("cold-cache");
    let line = first_line_with(
        gyro,
        &[
            "study",
            "wing",
            "--speeds",
            "60",
            "--areas",
            "0",
            "--cache",
            cache.to_str().unwrap(),
        ],
        "to solve",
        Duration::from_secs(60),
    )
    .unwrap();
    assert!(
        line.contains("1 section table of NACA 8-H-12 to solve")
            && line.contains("3904 table points, about"),
        "{line}"
    );
    let out = scratch("report");
    let line = first_line_with(
        gyro,
        &["report", "--out", out.to_str().unwrap()],
        "computations",
        Duration::from_secs(60),
    )
    .unwrap();
    assert!(line.starts_with("gyro: the paper report: "), "{line}");
    let _ = std::fs::remove_dir_all(cache);
    let _ = std::fs::remove_dir_all(out);
}
