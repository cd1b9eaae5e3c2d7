//! The study table cache reads its entries through the one capped, regular-file-only reader:
//! an entry that is a FIFO, a link to a device (`/dev/zero`) or larger than the input limit
//! does not hang or fill memory; it is a cache miss, solved again and replaced by a regular
//! file, with a note naming it.

use polargen::geometry::DEFAULT_PANEL_NODES;
use polargen::studies::{load_study_airfoil, TableCache, CLEAN};
use polargen::table::GridSpec;
use std::path::Path;
use std::time::{Duration, Instant};

/// A one-polar grid, solved in about a second.
fn tiny_cache(dir: &Path) -> TableCache {
    TableCache::new(
        dir.to_path_buf(),
        GridSpec {
            reynolds: vec![1e6],
            mach: vec![0.2],
            alpha_deg: (-2..=10).map(f64::from).collect(),
        },
        DEFAULT_PANEL_NODES,
        1,
    )
}

/// Puts a bad entry at a path.
type MakeEntry = Box<dyn Fn(&Path)>;

fn mkfifo(path: &Path) -> bool {
    std::process::Command::new("mkfifo")
        .arg(path)
        .status()
        .is_ok_and(|s| s.success())
}

#[test]
fn unreadable_entries_are_misses_solved_again_with_a_note() {
    let dir = tempfile::tempdir().unwrap();
    let foil = load_study_airfoil("naca0012", DEFAULT_PANEL_NODES).unwrap();
    let keys = [CLEAN];
    let mut cases: Vec<(&str, MakeEntry)> = vec![
        (
            "character device",
            Box::new(|p: &Path| std::os::unix::fs::symlink("/dev/zero", p).unwrap()),
        ),
        (
            "larger than the input limit",
            Box::new(|p: &Path| {
                let f = std::fs::File::create(p).unwrap();
                f.set_len(polargen::limits::MAX_INPUT_BYTES + 1).unwrap();
            }),
        ),
        (
            "not a readable table",
            Box::new(|p: &Path| std::fs::write(p, "{").unwrap()),
        ),
    ];
    if mkfifo(&dir.path().join("probe")) {
        cases.push(("FIFO", Box::new(|p: &Path| assert!(mkfifo(p)))));
    }
    for (why, make) in cases {
        let cache = tiny_cache(dir.path());
        let entry = cache.entry(&foil, &keys[0]);
        let _ = std::fs::remove_file(&entry);
        make(&entry);
        let start = Instant::now();
        assert_eq!(cache.missing_points(&foil, &keys), 13, "{why}");
        let tables = cache.tables(&foil, &keys, &|_| {}).unwrap();
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "{why}: {:?}",
            start.elapsed()
        );
        assert_eq!(tables[0].point_count(), 13);
        let notes = cache.notes();
        assert_eq!(notes.len(), 1, "{why}: {notes:?}");
        assert!(
            notes[0].contains(&entry.display().to_string())
                && notes[0].contains(why)
                && notes[0].contains("solved again"),
            "{why}: {notes:?}"
        );
        // Replaced by a regular file that the next run reads.
        let meta = std::fs::symlink_metadata(&entry).unwrap();
        assert!(meta.is_file() && meta.len() < 1 << 20, "{why}");
        assert_eq!(cache.missing_points(&foil, &keys), 0, "{why}");
    }
}
