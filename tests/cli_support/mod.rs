//! Shared by the tests that run the binaries: paths of the repository's inputs, running
//! `polargen` and `gyro`, the checks every CLI test makes (success, one-line errors) and scratch
//! folders.
#![allow(dead_code)]

use std::path::PathBuf;
use std::process::{Command, Output};

/// The repository root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The path of the repository file `relative` as a string (for an argument list).
pub fn repo(relative: &str) -> String {
    root().join(relative).display().to_string()
}

/// The shipped table `polars/<name>`.
pub fn polars(name: &str) -> String {
    repo(&format!("polars/{name}"))
}

/// The MTOsport preset.
pub fn aircraft() -> String {
    repo("aircraft/mtosport.toml")
}

/// Runs `polargen` with `args`.
pub fn polargen(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_polargen"))
        .args(args)
        .output()
        .expect("polargen runs")
}

/// Runs `gyro` with `args`.
pub fn gyro(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gyro"))
        .args(args)
        .output()
        .expect("gyro runs")
}

/// The path of the binary `name` (`polargen` or `gyro`).
pub fn exe(name: &str) -> &'static str {
    match name {
        "polargen" => env!("CARGO_BIN_EXE_polargen"),
        "gyro" => env!("CARGO_BIN_EXE_gyro"),
        other => panic!("no binary {other}"),
    }
}

/// Runs the binary `name` with `args`, `input` on its standard input.
pub fn run_with_stdin(name: &str, args: &[&str], input: &[u8]) -> Output {
    use std::io::Write;
    let mut child = Command::new(exe(name))
        .args(args)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("spawn");
    child.stdin.take().unwrap().write_all(input).unwrap();
    child.wait_with_output().unwrap()
}

/// `name` run with `args` in the repository, its standard output read by a reader that goes
/// away after the first byte (`| head -1`): exit 0 and nothing on stderr.
pub fn closed_pipe_is_quiet(name: &str, args: &[&str]) {
    use std::io::Read;
    let mut child = Command::new(exe(name))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("spawn");
    let mut first = [0u8; 1];
    child
        .stdout
        .as_mut()
        .unwrap()
        .read_exact(&mut first)
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stderr.is_empty(), "{}", text(&out.stderr));
}

/// Runs the binary `name` (`polargen` or `gyro`) with `args`.
pub fn run(name: &str, args: &[&str]) -> Output {
    match name {
        "polargen" => polargen(args),
        "gyro" => gyro(args),
        other => panic!("no binary {other}"),
    }
}

/// Bytes of a run's output as text.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The run's standard error as text.
pub fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// The run succeeded (stderr shown otherwise).
pub fn assert_ok(out: &Output) {
    assert!(out.status.success(), "stderr: {}", stderr(out));
}

/// The standard output of a run that must succeed.
pub fn ok(out: Output) -> String {
    assert_ok(&out);
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

/// The run of `tool` (the binary's name) failed with one line on stderr that starts with
/// `<tool>: ` and contains `needle`, and did not panic.
pub fn assert_one_line_error(tool: &str, out: &Output, needle: &str) {
    let err = stderr(out);
    assert!(!out.status.success(), "succeeded: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.starts_with(&format!("{tool}: ")), "{err}");
    assert!(err.contains(needle), "no '{needle}' in: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

/// A fresh, empty folder `polargen-test-<tag>-<process id>` in the system's temporary directory
/// (each test binary is its own process; tags keep the tests of one binary apart).
pub fn scratch(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("polargen-test-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
