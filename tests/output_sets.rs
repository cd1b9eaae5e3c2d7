//! File sets are all-or-none (`polargen::output::OutputSet`): a target that cannot be replaced
//! at the last step puts back every file already renamed; any legal file name can be written
//! (the staging names are short) and an overlong one is refused before any work; staging
//! folders of a killed process are removed by the next run that writes into their folder; an
//! interrupted run leaves no staging folder behind.

mod cli_support;

use cli_support::scratch;
use polargen::output::{check_output_path, write_output, OutputError, OutputSet};
use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn write_text(set: &mut OutputSet, path: &Path, text: &str) {
    set.write(path, |w| {
        w.write_all(text.as_bytes())
            .map_err(|e| OutputError::io(path, e))
    })
    .unwrap();
}

#[test]
fn a_target_that_cannot_be_replaced_leaves_every_target_as_it_was() {
    let dir = scratch("rollback");
    let (a, b) = (dir.join("one/a.pol"), dir.join("two/b.pol"));
    let (new, c) = (dir.join("one/new.pol"), dir.join("two/c.pol"));
    let reset = || {
        for p in [&a, &b, &c] {
            let _ = std::fs::remove_dir_all(p);
            std::fs::create_dir_all(p.parent().unwrap()).unwrap();
            std::fs::write(p, "old").unwrap();
        }
    };
    let unchanged = |why: &str| {
        for p in [&a, &b, &c] {
            assert!(p.is_file(), "{why}: {}", p.display());
            assert_eq!(
                std::fs::read_to_string(p).unwrap(),
                "old",
                "{why}: {}",
                p.display()
            );
        }
        assert!(
            !new.exists(),
            "{why}: a file new to the set stayed after the failure"
        );
        assert_eq!(names(&dir.join("one")), ["a.pol"], "{why}");
        assert_eq!(names(&dir.join("two")), ["b.pol", "c.pol"], "{why}");
    };
    // The last rename fails after three succeeded (the staged file cannot replace its
    // target: it became a folder): the three are put back.
    reset();
    let mut set = OutputSet::new();
    for p in [&a, &new, &b] {
        write_text(&mut set, p, "new");
    }
    let staged = set.stage(&c).unwrap();
    std::fs::create_dir_all(staged.join("inside")).unwrap();
    let e = set.commit().unwrap_err();
    assert!(e.to_string().contains("c.pol"), "{e}");
    assert!(!e.to_string().contains("polargen-set"), "{e}");
    unchanged("failed rename");
    // A target replaced by a folder after staging: refused before any rename.
    let mut set = OutputSet::new();
    for p in [&a, &new, &b, &c] {
        write_text(&mut set, p, "new");
    }
    std::fs::remove_file(&c).unwrap();
    std::fs::create_dir_all(c.join("inside")).unwrap();
    let e = set.commit().unwrap_err();
    assert!(e.to_string().contains("c.pol"), "{e}");
    std::fs::remove_dir_all(&c).unwrap();
    std::fs::write(&c, "old").unwrap();
    unchanged("target became a folder");
    // Writing over hard-linked targets keeps the other links' content (a rename, not an
    // overwrite in place).
    let link = dir.join("link.pol");
    std::fs::hard_link(&a, &link).unwrap();
    let mut set = OutputSet::new();
    write_text(&mut set, &a, "newer");
    set.commit().unwrap();
    assert_eq!(std::fs::read_to_string(&a).unwrap(), "newer");
    assert_eq!(std::fs::read_to_string(&link).unwrap(), "old");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn any_legal_file_name_is_written_and_an_overlong_one_refused_before_the_work() {
    let dir = scratch("names");
    let legal = dir.join(format!("{}.csv", "n".repeat(246)));
    assert_eq!(legal.file_name().unwrap().len(), 250);
    check_output_path(&legal).unwrap();
    write_output(&legal, |w| {
        w.write_all(b"x").map_err(|e| OutputError::io(&legal, e))
    })
    .unwrap();
    assert_eq!(std::fs::read_to_string(&legal).unwrap(), "x");
    let too_long = dir.join(format!("{}.csv", "n".repeat(252)));
    let e = check_output_path(&too_long).unwrap_err();
    assert!(e.to_string().contains("longer than 255 bytes"), "{e}");
    // On the command line: refused before the solve, naming the path, not a temporary name.
    let start = Instant::now();
    let o = Command::new(env!("CARGO_BIN_EXE_polargen"))
        .args(["--airfoil", "naca0012", "--out", too_long.to_str().unwrap()])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("longer than 255 bytes") && err.contains("nnnn.csv"),
        "{err}"
    );
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "not refused before the solve"
    );
    // A 250-byte name through the tool, as a one-polar table.
    let o = Command::new(env!("CARGO_BIN_EXE_polargen"))
        .args(["--airfoil", "naca0012", "--re", "1e6", "--alpha", "0", "-q"])
        .args(["--out", legal.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::read_to_string(&legal)
        .unwrap()
        .starts_with("airfoil,"));
    // An XFOIL set whose member names would exceed the limit: refused before the solve.
    let stem = dir.join(format!("{}.pol", "p".repeat(246)));
    let o = Command::new(env!("CARGO_BIN_EXE_polargen"))
        .args([
            "--airfoil",
            "naca0012",
            "--re",
            "1e6,2e6",
            "--alpha",
            "0",
            "--out",
        ])
        .arg(&stem)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("_Re1e6_M0.pol") && err.contains("longer than 255"),
        "{err}"
    );
    assert_eq!(names(&dir), [legal.file_name().unwrap().to_str().unwrap()]);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn staging_folders_of_a_process_that_is_gone_are_removed_by_the_next_run() {
    let dir = scratch("stale");
    // The id of a process that has ended.
    let mut child = Command::new("true").spawn().unwrap();
    let dead = child.id();
    child.wait().unwrap();
    let stale = dir.join(format!(".polargen-set-{dead}.abcdef"));
    std::fs::create_dir_all(stale.join("n")).unwrap();
    std::fs::write(stale.join("n/t.csv"), "half").unwrap();
    // A live process's folder (process 1 always runs) is left alone.
    let live = dir.join(".polargen-set-1.ghijkl");
    std::fs::create_dir_all(&live).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_polargen"))
        .args(["convert", "polars/naca8h12_free.csv", "--out"])
        .arg(dir.join("t.csv"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(names(&dir), [".polargen-set-1.ghijkl", "t.csv"]);
    std::fs::remove_dir_all(dir).unwrap();
}

/// Sends SIGINT to `child` after `delay`, then waits for it; its exit code (None: a signal).
fn interrupt_after(mut child: std::process::Child, delay: Duration) -> Option<i32> {
    std::thread::sleep(delay);
    let _ = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status();
    child.wait().unwrap().code()
}

#[test]
fn an_interrupted_run_leaves_no_staging_folder_behind() {
    // A set of 64 XFOIL polars: SIGINT at many moments of the staging, 1 ms to 0.4 s after the
    // start in geometric steps (the whole run takes about 40 ms on a quiet machine, several
    // times that under load).
    let dir = scratch("sigint");
    let mut interrupted = 0;
    for k in 0..24u64 {
        let out = dir.join(format!("run{k}"));
        let child = Command::new(env!("CARGO_BIN_EXE_polargen"))
            .args([
                "convert",
                "polars/naca8h12_free.csv",
                "--format",
                "xfoil",
                "--out",
            ])
            .arg(out.join("t.pol"))
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .spawn()
            .unwrap();
        let delay = Duration::from_secs_f64(1e-3 * 1.3f64.powi(k as i32));
        if interrupt_after(child, delay) == Some(130) {
            interrupted += 1;
        }
        if out.exists() {
            let left: Vec<String> = names(&out)
                .into_iter()
                .filter(|n| n.starts_with(".polargen"))
                .collect();
            assert!(left.is_empty(), "run {k} left {left:?}");
            let files = names(&out).len();
            assert!(files == 0 || files == 64, "run {k}: {files} of 64 files");
        }
    }
    assert!(
        interrupted > 0,
        "no run was interrupted: the test tells nothing"
    );
    std::fs::remove_dir_all(dir).unwrap();
}
