//! Provenance of the test data: every folder of tests/data has a README.md, and every XFOIL
//! reference file in tests/data/xfoil is made by exactly one command of that folder's README
//! (run by the repository's `tools/xfoil_reference.py`), each command's files present. With
//! XFOIL installed, the ignored test runs the README's commands into a temporary folder and
//! requires every file byte for byte: `cargo test --test xfoil_reference_data -- --ignored`.

mod xfoil_support;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The shell block of the README of tests/data/xfoil (the block after "## Commands").
fn command_block() -> String {
    let readme = xfoil_support::text("README.md");
    let section = &readme[readme.find("## Commands").expect("a Commands section")..];
    let start = section.find("```sh\n").expect("a sh block") + "```sh\n".len();
    let end = start + section[start..].find("```").expect("the block's end");
    section[start..end].to_string()
}

/// The files the block's commands write under `$D`: the arguments of `--out`, and the second
/// arguments of `--bl-dump` and `--cp-dump`.
fn outputs(block: &str) -> Vec<String> {
    let mut files = Vec::new();
    for line in block.lines().filter(|l| l.starts_with("$T ")) {
        let words: Vec<&str> = line.split_whitespace().collect();
        for (k, w) in words.iter().enumerate() {
            let file = match *w {
                "--out" => words.get(k + 1),
                "--bl-dump" | "--cp-dump" => words.get(k + 2),
                _ => None,
            };
            if let Some(f) = file {
                let name = f
                    .strip_prefix("$D/")
                    .unwrap_or_else(|| panic!("{f}: not written under $D in: {line}"));
                files.push(name.to_string());
            }
        }
    }
    files
}

#[test]
fn every_reference_file_has_its_command() {
    let named = outputs(&command_block());
    let unique: BTreeSet<&String> = named.iter().collect();
    assert_eq!(unique.len(), named.len(), "a file is made by two commands");
    let present: BTreeSet<String> = std::fs::read_dir(xfoil_support::DIR)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n != "README.md")
        .collect();
    let named: BTreeSet<String> = named.into_iter().collect();
    let missing: Vec<_> = named.difference(&present).collect();
    let unexplained: Vec<_> = present.difference(&named).collect();
    assert!(missing.is_empty(), "named but absent: {missing:?}");
    assert!(
        unexplained.is_empty(),
        "present without a command: {unexplained:?}"
    );
}

/// Every folder under tests/data, at any depth, has a README.md.
#[test]
fn every_data_folder_has_a_readme() {
    fn walk(dir: &Path, without: &mut Vec<PathBuf>) {
        if !dir.join("README.md").is_file() {
            without.push(dir.to_path_buf());
        }
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, without);
            }
        }
    }
    let mut without = Vec::new();
    walk(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data"),
        &mut without,
    );
    assert!(
        without.is_empty(),
        "folders without a README.md: {without:?}"
    );
}

/// Runs the README's commands (needs `xfoil`, `gcc` and `python3`) into a temporary folder and
/// compares every file with the repository's copy.
#[test]
#[ignore = "needs XFOIL 6.99 (apt-get install xfoil gcc); a few minutes"]
fn commands_rebuild_the_files_byte_for_byte() {
    let out = std::env::temp_dir().join(format!("polargen-xfoil-rebuild-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    std::fs::create_dir_all(&out).unwrap();
    let block = command_block().replace("D=tests/data/xfoil\n", &format!("D={}\n", out.display()));
    let status = Command::new("bash")
        .arg("-euc")
        .arg(&block)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .status()
        .expect("bash runs");
    assert!(status.success(), "the commands failed");
    let mut differ = Vec::new();
    for name in outputs(&command_block()) {
        let made = std::fs::read(out.join(&name)).unwrap_or_default();
        if made != std::fs::read(xfoil_support::path(&name)).unwrap() {
            differ.push(name);
        }
    }
    assert!(
        differ.is_empty(),
        "differ from the repository's copies: {differ:?}"
    );
    let _ = std::fs::remove_dir_all(&out);
}
