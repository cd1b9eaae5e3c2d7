//! `polargen batch`: one table per airfoil and an index; two shards together give the
//! unsharded run's tables byte for byte; `--resume` keeps valid tables and solves truncated
//! or foreign ones again; bad input is one line before any solve.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod cli_support;
use cli_support::stderr;

/// A tiny grid: one Re, one Mach number, three α.
const GRID: [&str; 4] = ["--re", "1e6", "--alpha", "0:4:2"];

/// Run `polargen batch` with `args` after the grid flags.
fn batch(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_polargen"))
        .arg("batch")
        .args(GRID)
        .args(args)
        .output()
        .expect("run polargen")
}

/// A folder of three coordinate files from tests/data and a file that is not `*.dat`.
fn airfoil_folder(root: &Path) -> PathBuf {
    let dir = root.join("foils");
    fs::create_dir_all(&dir).unwrap();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    for (from, to) in [
        ("xfoil/naca2412_buffer.dat", "n2412.dat"),
        ("xfoil/naca23012_buffer.dat", "n23012.dat"),
        ("geometry/lednicer_naca8h12.dat", "n8h12.DAT"),
    ] {
        fs::copy(data.join(from), dir.join(to)).unwrap();
    }
    fs::write(dir.join("README.txt"), "not an airfoil\n").unwrap();
    dir
}

/// Every file of `dir` except the index, by name.
fn tables(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            !p.file_name()
                .unwrap()
                .to_string_lossy()
                .starts_with("index")
        })
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, fs::read(&p).unwrap())
        })
        .collect()
}

/// The index rows of `path` (CSV) without the seconds column.
fn index_rows(path: &Path) -> Vec<Vec<String>> {
    let text = fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("airfoil,file,points,converged,seconds,status")
    );
    lines
        .map(|l| {
            let mut f: Vec<String> = l.split(',').map(str::to_string).collect();
            f.remove(4);
            f
        })
        .collect()
}

#[test]
fn two_shards_give_the_tables_of_the_unsharded_run() {
    let root = tempfile::tempdir().unwrap();
    let foils = airfoil_folder(root.path());
    let foils = foils.to_str().unwrap();
    let whole = root.path().join("whole");
    let sharded = root.path().join("sharded");
    let o = batch(&[
        "--airfoils",
        foils,
        "naca0012",
        "--out",
        whole.to_str().unwrap(),
        "--jobs",
        "2",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("1 entries other than *.dat files skipped"),
        "{}",
        stderr(&o)
    );
    for shard in ["1/2", "2/2"] {
        let o = batch(&[
            "--airfoils",
            "naca0012",
            foils,
            "--out",
            sharded.to_str().unwrap(),
            "--shard",
            shard,
        ]);
        assert!(o.status.success(), "{shard}: {}", stderr(&o));
    }
    let all = tables(&whole);
    let names: Vec<&str> = all.keys().map(String::as_str).collect();
    assert_eq!(
        names,
        ["n23012.csv", "n2412.csv", "n8h12.csv", "naca0012.csv"]
    );
    assert_eq!(tables(&sharded), all, "the union of the shards differs");

    // The index: every airfoil once, sorted by name; shard 1 of 2 has the 1st and 3rd.
    let rows = index_rows(&whole.join("index.csv"));
    let first = index_rows(&sharded.join("index-1-of-2.csv"));
    let second = index_rows(&sharded.join("index-2-of-2.csv"));
    assert_eq!(first, [rows[0].clone(), rows[2].clone()]);
    assert_eq!(second, [rows[1].clone(), rows[3].clone()]);
    for row in &rows {
        assert_eq!(row[2], "3", "points: {row:?}");
        assert_eq!(row[4], "solved", "{row:?}");
        assert!(row[3].parse::<usize>().unwrap() <= 3);
        let table = fs::read_to_string(whole.join(format!("{}.csv", row[0]))).unwrap();
        let converged = table.lines().filter(|l| l.contains(",true,")).count();
        assert_eq!(row[3], converged.to_string(), "{row:?}");
    }
    assert_eq!(rows[0][1], format!("{foils}/n23012.dat"));
    assert_eq!(rows[3][..2], ["naca0012", "naca0012"]);

    // A shard beyond the list: a note and an index without rows.
    let o = batch(&[
        "--airfoils",
        foils,
        "naca0012",
        "--out",
        sharded.to_str().unwrap(),
        "--shard",
        "5/5",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("no airfoil of the 4 given"),
        "{}",
        stderr(&o)
    );
    assert!(index_rows(&sharded.join("index-5-of-5.csv")).is_empty());

    // The JSON index holds the same rows.
    let json: serde_json::Value =
        serde_json::from_str(&fs::read_to_string(whole.join("index.json")).unwrap()).unwrap();
    let json = json.as_array().unwrap();
    assert_eq!(json.len(), rows.len());
    for (j, row) in json.iter().zip(&rows) {
        assert_eq!(j["airfoil"], row[0].as_str());
        assert_eq!(j["points"].as_u64().unwrap().to_string(), row[2]);
        assert_eq!(j["status"], row[4].as_str());
        assert!(j["seconds"].as_f64().unwrap() >= 0.0);
    }

    // The summary files: one row per polar of each table (one polar each here), named as in
    // the index, with the numbers of `polargen summary` of that table.
    let text = fs::read_to_string(whole.join("index-summary.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        polargen::table::SUMMARY_COLUMNS.join(",")
    );
    let summary: Vec<Vec<String>> = lines
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    assert_eq!(summary.len(), rows.len());
    for (s, row) in summary.iter().zip(&rows) {
        assert_eq!(s[0], row[0]);
        let table = polargen::table::read_table(&whole.join(format!("{}.csv", row[0]))).unwrap();
        let mut expect = table.summaries().remove(0);
        expect.airfoil = row[0].clone();
        assert_eq!(s, &expect.fields(), "{}", row[0]);
    }
    let json: serde_json::Value =
        serde_json::from_str(&fs::read_to_string(whole.join("index-summary.json")).unwrap())
            .unwrap();
    assert_eq!(json.as_array().unwrap().len(), rows.len());
}

#[test]
fn resume_keeps_valid_tables_and_solves_truncated_and_foreign_ones() {
    let root = tempfile::tempdir().unwrap();
    let foils = airfoil_folder(root.path());
    let out = root.path().join("out");
    let args = [
        "--airfoils",
        foils.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    let o = batch(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let first = tables(&out);

    // Truncate one table, replace another with a table of other settings (N_crit 5).
    let truncated = out.join("n2412.csv");
    let bytes = fs::read(&truncated).unwrap();
    fs::write(&truncated, &bytes[..bytes.len() / 2]).unwrap();
    let foreign = root.path().join("foreign");
    let mut foreign_args = args.to_vec();
    foreign_args[3] = foreign.to_str().unwrap();
    let o = batch(&[&foreign_args[..], &["--ncrit", "5"]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    fs::copy(foreign.join("n8h12.csv"), out.join("n8h12.csv")).unwrap();
    assert_ne!(fs::read(out.join("n8h12.csv")).unwrap(), first["n8h12.csv"]);

    let o = batch(&[&args[..], &["--resume"]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("tables: 2 solved, 1 kept, 0 failed"),
        "{}",
        stderr(&o)
    );
    let status: BTreeMap<String, String> = index_rows(&out.join("index.csv"))
        .into_iter()
        .map(|r| (r[0].clone(), r[4].clone()))
        .collect();
    assert_eq!(status["n23012"], "kept");
    assert_eq!(status["n2412"], "solved");
    assert_eq!(status["n8h12"], "solved");
    assert_eq!(
        tables(&out),
        first,
        "resumed tables differ from the first run"
    );

    // Other grid settings: nothing is kept.
    let o = batch(&[&args[..], &["--resume", "--xtr", "0.5"]].concat());
    assert!(
        stderr(&o).contains("tables: 3 solved, 0 kept"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn bad_input_is_one_line_before_any_solve() {
    let root = tempfile::tempdir().unwrap();
    let foils = airfoil_folder(root.path());
    let empty = root.path().join("empty");
    fs::create_dir(&empty).unwrap();
    let twin = root.path().join("twin");
    fs::create_dir(&twin).unwrap();
    fs::copy(foils.join("n2412.dat"), twin.join("n2412.dat")).unwrap();
    let junk = root.path().join("junk");
    fs::create_dir(&junk).unwrap();
    fs::copy(foils.join("n2412.dat"), junk.join("a.dat")).unwrap();
    fs::write(junk.join("b.dat"), "just some text\nnot coordinates\n").unwrap();
    let out = root.path().join("out");
    let (f, e, t, j) = (
        foils.to_str().unwrap(),
        empty.to_str().unwrap(),
        twin.to_str().unwrap(),
        junk.to_str().unwrap(),
    );
    let cases: [(&[&str], &str); 7] = [
        (
            &["--airfoils", f, "--shard", "3/2"],
            "shard '3/2': K must be at most N",
        ),
        (
            &["--airfoils", f, "--shard", "0/0"],
            "shard '0/0': N must be at least 1",
        ),
        (&["--airfoils", f, "--shard", "0/2"], "K counts from 1"),
        (
            &["--airfoils", e],
            "no *.dat coordinate files in this folder",
        ),
        (&["--airfoils", f, t], "two airfoils named 'n2412'"),
        (&["--airfoils", j], "b.dat"),
        (
            &["--airfoils", f, "--format", "c81"],
            "--format c81: must be one of csv, json",
        ),
    ];
    for (args, expected) in cases {
        let o = batch(&[args, &["--out", out.to_str().unwrap()]].concat());
        let text = stderr(&o);
        assert!(!o.status.success(), "{args:?}");
        assert!(text.contains(expected), "{args:?}: {text}");
        assert_eq!(text.lines().count(), 1, "{args:?}: {text}");
        assert!(!out.exists(), "{args:?} wrote {}", out.display());
    }
}

/// A table whose name in the output folder is a folder, or a link to a device, is refused
/// before any solve, with no index written (it was found after the solves, leaving an index
/// of pending airfoils, or the table went into the device).
#[cfg(unix)]
#[test]
fn a_table_name_that_is_not_a_file_is_refused_before_any_solve() {
    let root = tempfile::tempdir().unwrap();
    let foils = airfoil_folder(root.path());
    for (tag, make) in [
        (
            "folder",
            (|p: &Path| fs::create_dir_all(p).unwrap()) as fn(&Path),
        ),
        ("device", |p: &Path| {
            std::os::unix::fs::symlink("/dev/null", p).unwrap()
        }),
    ] {
        let out = root.path().join(tag);
        fs::create_dir(&out).unwrap();
        make(&out.join("n2412.csv"));
        let o = batch(&[
            "--airfoils",
            foils.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let text = stderr(&o);
        assert!(!o.status.success(), "{tag}: {text}");
        assert!(
            text.contains("n2412.csv") && text.lines().count() == 1,
            "{tag}: {text}"
        );
        let names: Vec<String> = fs::read_dir(&out)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        assert_eq!(names, ["n2412.csv"], "{tag}");
    }
}
