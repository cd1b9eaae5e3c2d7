//! Shared helpers of the `gyro` binary tests: paths of the repository's inputs, running the
//! binary, and the checks every CLI test makes (success, one-line errors).
#![allow(dead_code)]

use std::path::PathBuf;
use std::process::{Command, Output};

/// The repository root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The MTOsport preset.
pub fn aircraft() -> String {
    root().join("aircraft/mtosport.toml").display().to_string()
}

/// Runs `gyro` with `args`.
pub fn gyro(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gyro"))
        .args(args)
        .output()
        .expect("gyro runs")
}

/// The run succeeded (stderr shown otherwise).
pub fn assert_ok(out: &Output) {
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The run failed with one line on stderr that starts with `gyro: ` and contains `needle`.
pub fn assert_one_line_error(out: &Output, needle: &str) {
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.starts_with("gyro: ") && err.contains(needle), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}
