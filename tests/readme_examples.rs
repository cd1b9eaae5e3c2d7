//! The README's shell examples run as pasted: every command of every ```sh block, in a fresh
//! folder holding copies of the shipped inputs (`aircraft/`, `geometry/`, `polars/`) and
//! `target/release/` with the binaries this `cargo test` built (also on `PATH`, for examples
//! written after a `cargo install --path .`). The README is read when the test runs, so an
//! edited README is tested as it stands.
//!
//! Not run: a command line carrying the marker [`SKIP_MARKER`] (visible in the README, with
//! its reason: minutes of computing, a scheduler), and the setup commands of [`SETUP`] — the
//! harness has built the binaries itself, and `python/tests` covers the Python package. A
//! block's commands run in order in one `bash` with `set -eo pipefail`; a failure names the
//! README line.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// A command line holding this text is not run.
const SKIP_MARKER: &str = "[skip-test]";

/// Command prefixes that set up the tools rather than use them.
const SETUP: [&str; 2] = ["cargo ", "pip "];

/// The shipped folders the examples read, copied into the test's folder.
const INPUTS: [&str; 4] = ["aircraft", "geometry", "polars", "tests/data/pca2"];

/// One command of a shell block: its first README line and its text (continuations joined).
struct Example {
    line: usize,
    text: String,
}

/// Where a README line lies.
enum Fence {
    /// Prose.
    Outside,
    /// A shell block, with its commands so far.
    Shell(Vec<Example>),
    /// A block in another language.
    Other,
}

/// The commands of the README's shell blocks, block by block, and the lines skipped.
fn shell_blocks(readme: &str) -> (Vec<Vec<Example>>, Vec<String>) {
    let (mut blocks, mut skipped) = (Vec::new(), Vec::new());
    let mut fence = Fence::Outside;
    let mut continued: Option<Example> = None;
    for (k, raw) in readme.lines().enumerate() {
        let line = raw.trim();
        if let Some(info) = line.strip_prefix("```") {
            fence = match std::mem::replace(&mut fence, Fence::Outside) {
                Fence::Shell(b) => {
                    blocks.push(b);
                    Fence::Outside
                }
                Fence::Other => Fence::Outside,
                Fence::Outside if ["sh", "bash", "shell"].contains(&info.trim()) => {
                    Fence::Shell(Vec::new())
                }
                Fence::Outside => Fence::Other,
            };
            continue;
        }
        let Fence::Shell(block) = &mut fence else {
            continue;
        };
        let mut command = match continued.take() {
            Some(mut c) => {
                c.text = format!("{} {line}", c.text);
                c
            }
            None => Example {
                line: k + 1,
                text: line.to_string(),
            },
        };
        if let Some(head) = command.text.strip_suffix('\\') {
            command.text = head.trim_end().to_string();
            continued = Some(command);
            continue;
        }
        let text = command.text.as_str();
        if text.is_empty() || text.starts_with('#') {
            continue;
        }
        if text.contains(SKIP_MARKER) || SETUP.iter().any(|s| text.starts_with(s)) {
            skipped.push(format!("README.md:{}: {text}", command.line));
            continue;
        }
        block.push(command);
    }
    (blocks, skipped)
}

/// Copy the folder `from` into `to`, recursively.
fn copy_tree(from: &Path, to: &Path) {
    fs::create_dir_all(to).unwrap();
    for entry in fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        let target = to.join(path.file_name().unwrap());
        if path.is_dir() {
            copy_tree(&path, &target);
        } else {
            fs::copy(&path, &target).unwrap();
        }
    }
}

/// A folder laid out like a checkout after `cargo build --release`, for the examples.
fn checkout_like() -> (tempfile::TempDir, PathBuf) {
    let root = tempfile::tempdir().unwrap();
    let repo = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in INPUTS {
        copy_tree(&repo.join(dir), &root.path().join(dir));
    }
    let bin = root.path().join("target/release");
    fs::create_dir_all(&bin).unwrap();
    for (name, exe) in [
        ("polargen", env!("CARGO_BIN_EXE_polargen")),
        ("gyro", env!("CARGO_BIN_EXE_gyro")),
    ] {
        std::os::unix::fs::symlink(exe, bin.join(name)).unwrap();
    }
    (root, bin)
}

#[test]
fn the_readme_examples_run_as_pasted() {
    let readme = fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md"))
        .expect("read README.md");
    let (blocks, skipped) = shell_blocks(&readme);
    let count: usize = blocks.iter().map(Vec::len).sum();
    assert!(count >= 3, "only {count} runnable README commands found");
    for line in &skipped {
        eprintln!("not run: {line}");
    }
    let (root, bin) = checkout_like();
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    for block in blocks.iter().filter(|b| !b.is_empty()) {
        let script: String = std::iter::once("set -eo pipefail".to_string())
            .chain(block.iter().map(|c| c.text.clone()))
            .collect::<Vec<_>>()
            .join("\n");
        let start = Instant::now();
        let out = Command::new("bash")
            .args(["-c", &script])
            .current_dir(root.path())
            .env("PATH", &path)
            .output()
            .expect("run bash");
        eprintln!(
            "README.md:{}: {} commands in {:.1} s",
            block[0].line,
            block.len(),
            start.elapsed().as_secs_f64()
        );
        assert!(
            out.status.success(),
            "README.md:{}: the block failed ({}):\n{}",
            block[0].line,
            out.status,
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

#[test]
fn blocks_commands_and_markers_are_found() {
    let readme = "text\n```sh\ncargo build --release\n# a comment\n./a --x \\\n  --y\n\n\
                  ./b  # [skip-test] slow\n```\n```python\nprint(1)\n```\n```bash\n./c\n```\n";
    let (blocks, skipped) = shell_blocks(readme);
    let texts: Vec<Vec<&str>> = blocks
        .iter()
        .map(|b| b.iter().map(|c| c.text.as_str()).collect())
        .collect();
    assert_eq!(texts, [vec!["./a --x --y"], vec!["./c"]]);
    assert_eq!(blocks[0][0].line, 5);
    assert_eq!(skipped.len(), 2, "{skipped:?}");
}
