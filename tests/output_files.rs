//! Output files (`polargen::output`): path checks, atomic replacement of regular files (no
//! temporary file left behind, old content kept on failure), symbolic links written through,
//! and streams (`-`, `/dev/stdout`, devices) written in place, never renamed over.

mod table_support;

use polargen::output::{check_output_path, write_output, OutputError};
use std::path::{Path, PathBuf};
use std::process::Command;
use table_support::{files_in, scratch};

/// A writer body failing after half its output, with an error of the caller's own type.
#[derive(Debug)]
enum BodyError {
    Output(#[allow(dead_code)] OutputError),
    Half,
}

impl From<OutputError> for BodyError {
    fn from(e: OutputError) -> Self {
        Self::Output(e)
    }
}

fn write_text(path: &Path, text: &str) -> Result<(), OutputError> {
    write_output(path, |w| {
        w.write_all(text.as_bytes())
            .map_err(|e| OutputError::io(path, e))
    })
}

#[test]
fn atomic_write_creates_folders_and_leaves_no_temp_files() {
    let dir = scratch("atomic");
    let path = dir.join("a/b/c.txt");
    write_text(&path, "hello").unwrap();
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "hello");
    assert_eq!(files_in(&dir.join("a/b")), vec!["c.txt"]);
    // A failing writer leaves the old content and no temporary file.
    let e = write_output(&path, |w| {
        w.write_all(b"half a fi").unwrap();
        Err(BodyError::Half)
    })
    .unwrap_err();
    assert!(matches!(e, BodyError::Half));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "hello");
    assert_eq!(files_in(&dir.join("a/b")), vec!["c.txt"]);
    // …and no target at all when there was none.
    let fresh = dir.join("a/b/new.csv");
    assert!(write_output(&fresh, |_| Err(BodyError::Half)).is_err());
    assert!(!fresh.exists());
    assert_eq!(files_in(&dir.join("a/b")), vec!["c.txt"]);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn output_paths_are_checked_before_writing() {
    let dir = scratch("outpath");
    std::fs::create_dir_all(dir.join("folder.csv")).unwrap();
    std::fs::write(dir.join("plain"), "x").unwrap();
    let msg = |p: PathBuf| check_output_path(&p).unwrap_err().to_string();
    let d = dir.display();
    assert_eq!(
        msg(dir.join("folder.csv")),
        format!("{d}/folder.csv: is a folder, not a file name")
    );
    assert_eq!(
        msg(PathBuf::from(format!("{d}/new/"))),
        format!("{d}/new/: is a folder, not a file name")
    );
    assert_eq!(
        msg(dir.join("plain/sub/t.csv")),
        format!("{d}/plain: is not a folder")
    );
    // Missing folders are fine (the writers create them); nothing was created by the checks.
    check_output_path(&dir.join("a/b/t.csv")).unwrap();
    check_output_path(Path::new("t.csv")).unwrap();
    check_output_path(Path::new("-")).unwrap();
    assert_eq!(files_in(&dir), vec!["folder.csv", "plain"]);
    // The writer makes the same checks.
    let e = write_text(&dir.join("folder.csv"), "x").unwrap_err();
    assert_eq!(
        e.to_string(),
        format!("{d}/folder.csv: is a folder, not a file name")
    );
    std::fs::remove_dir_all(dir).unwrap();
}

/// A device is written in place: it stays a device (never replaced by a regular file).
#[cfg(unix)]
#[test]
fn devices_are_written_in_place() {
    let null = Path::new("/dev/null");
    if !null.exists() {
        return;
    }
    check_output_path(null).unwrap();
    write_text(null, "into the void").unwrap();
    assert!(!std::fs::metadata(null).unwrap().is_file());
}

/// A symbolic link is written through: the linked file gets the new content, the link stays.
#[cfg(unix)]
#[test]
fn writers_follow_symbolic_links() {
    let dir = scratch("symlink");
    std::fs::create_dir_all(dir.join("real")).unwrap();
    std::fs::write(dir.join("real/t.csv"), "old").unwrap();
    std::os::unix::fs::symlink(dir.join("real/t.csv"), dir.join("link.csv")).unwrap();
    write_text(&dir.join("link.csv"), "new").unwrap();
    let link = std::fs::symlink_metadata(dir.join("link.csv")).unwrap();
    assert!(link.file_type().is_symlink());
    assert_eq!(
        std::fs::read_to_string(dir.join("real/t.csv")).unwrap(),
        "new"
    );
    assert_eq!(files_in(&dir.join("real")), vec!["t.csv"]);
    // A broken link is an error, and nothing is created.
    std::os::unix::fs::symlink(dir.join("gone/x.csv"), dir.join("broken.csv")).unwrap();
    let e = check_output_path(&dir.join("broken.csv")).unwrap_err();
    assert!(
        e.to_string()
            .ends_with("broken.csv: is a broken symbolic link"),
        "{e}"
    );
    assert!(!dir.join("gone").exists());
    std::fs::remove_dir_all(dir).unwrap();
}

/// `--out /dev/stdout` and `--out -` write into the shell's stream in order with what others
/// write into it; the file the shell redirected into is not replaced.
#[cfg(unix)]
#[test]
fn standard_output_is_written_in_order() {
    if !Path::new("/dev/stdout").exists() || !Path::new("/bin/sh").exists() {
        return;
    }
    let dir = scratch("stdout");
    let exe = env!("CARGO_BIN_EXE_polargen");
    for out in ["/dev/stdout", "-"] {
        let file = dir.join("f.txt");
        let script = format!(
            "( echo a; '{exe}' --airfoil naca0012 --inviscid --alpha 2 --out {out}; echo b ) > '{}'",
            file.display()
        );
        let status = Command::new("/bin/sh")
            .arg("-c")
            .arg(&script)
            .status()
            .unwrap();
        assert!(status.success(), "{out}");
        let text = std::fs::read_to_string(&file).unwrap();
        assert!(
            text.starts_with("a\nalpha,cl,cd,cm,converged\n2,") && text.ends_with("\nb\n"),
            "{out}: {text}"
        );
        assert_eq!(files_in(&dir), vec!["f.txt"]);
    }
    std::fs::remove_dir_all(dir).unwrap();
}
