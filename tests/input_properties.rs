//! Property tests of the input readers: random mutations of real coordinate files and table
//! files (numbers replaced by extreme values, lines deleted, repeated or swapped, bytes
//! changed, text cut short) never panic, never run past a time bound, and what they accept
//! is sound — an accepted contour gives a finite inviscid Cl with |Cl| ≤ 5 or a clean error,
//! an accepted table holds finite, plausible coefficients and reads back after every write.
//! The cargo-fuzz targets in `fuzz/` drive the same readers with coverage guidance.

use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

use polargen::geometry::{parse_airfoil_bytes, PanelingParams};
use polargen::inviscid::PanelSystem;
use polargen::table::{read_table, write_table, COEFFICIENT_BOUNDS};
use proptest::prelude::*;

/// Longest one mutated input may take through reading, validation and (for contours) an
/// inviscid solve; far above the milliseconds an input takes, far below a hang.
const TIME_BOUND: Duration = Duration::from_secs(20);

/// Largest |Cl| of an accepted contour at the α tested (0° and 6°): no real section comes
/// near it below stall, and the review's broken contours gave up to 4e10.
const MAX_PLAUSIBLE_CL: f64 = 5.0;

/// One edit of a text file.
#[derive(Debug, Clone)]
enum Mutation {
    /// Replace the `n`-th number token (modulo the count) with `Replacement`.
    Number(usize, Replacement),
    /// Delete line `n` (modulo the line count).
    DeleteLine(usize),
    /// Insert a copy of line `n` before line `m`.
    RepeatLine(usize, usize),
    /// Swap lines `n` and `m`.
    SwapLines(usize, usize),
    /// Set the byte at `n` (modulo the length) to `b`.
    Byte(usize, u8),
    /// Cut the text at byte `n` (modulo the length).
    Truncate(usize),
}

/// What a number token becomes.
#[derive(Debug, Clone)]
enum Replacement {
    /// The value times a factor.
    Scaled(f64),
    /// A fixed token (NaN, infinities, extreme or malformed numbers).
    Token(&'static str),
}

const TOKENS: [&str; 12] = [
    "nan", "inf", "-inf", "1e300", "-1e-300", "0", "-0", "1e9", "4e-10", "1.0.0", "", "1e99999",
];

fn mutation() -> impl Strategy<Value = Mutation> {
    let replacement = prop_oneof![
        prop_oneof![
            Just(-1.0),
            Just(0.5),
            Just(1.011),
            Just(10.0),
            -3.0f64..3.0,
            Just(1e12)
        ]
        .prop_map(Replacement::Scaled),
        (0..TOKENS.len()).prop_map(|i| Replacement::Token(TOKENS[i])),
    ];
    prop_oneof![
        4 => (any::<usize>(), replacement).prop_map(|(n, r)| Mutation::Number(n, r)),
        2 => any::<usize>().prop_map(Mutation::DeleteLine),
        2 => (any::<usize>(), any::<usize>()).prop_map(|(n, m)| Mutation::RepeatLine(n, m)),
        2 => (any::<usize>(), any::<usize>()).prop_map(|(n, m)| Mutation::SwapLines(n, m)),
        1 => (any::<usize>(), any::<u8>()).prop_map(|(n, b)| Mutation::Byte(n, b)),
        1 => any::<usize>().prop_map(Mutation::Truncate),
    ]
}

/// `text` with every mutation applied in turn.
fn mutate(text: &str, mutations: &[Mutation]) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    for m in mutations {
        let s = String::from_utf8_lossy(&bytes).into_owned();
        let mut lines: Vec<String> = s.split('\n').map(str::to_string).collect();
        match m {
            Mutation::Number(n, r) => {
                let mut tokens: Vec<(usize, usize)> = Vec::new();
                for (i, l) in lines.iter().enumerate() {
                    for (k, t) in l.split(|c: char| c == ',' || c.is_whitespace()).enumerate() {
                        if t.parse::<f64>().is_ok() {
                            tokens.push((i, k));
                        }
                    }
                }
                if let Some(&(i, k)) = tokens.get(n % tokens.len().max(1)) {
                    let sep = if lines[i].contains(',') { ',' } else { ' ' };
                    let mut parts: Vec<String> = lines[i]
                        .split(|c: char| c == ',' || c.is_whitespace())
                        .map(str::to_string)
                        .collect();
                    let v: f64 = parts[k].parse().unwrap();
                    parts[k] = match r {
                        Replacement::Scaled(f) => format!("{}", v * f),
                        Replacement::Token(t) => t.to_string(),
                    };
                    lines[i] = parts.join(&sep.to_string());
                }
            }
            Mutation::DeleteLine(n) => {
                let len = lines.len();
                lines.remove(n % len);
            }
            Mutation::RepeatLine(n, m) => {
                let l = lines[n % lines.len()].clone();
                lines.insert(m % lines.len(), l);
            }
            Mutation::SwapLines(n, m) => {
                let len = lines.len();
                lines.swap(n % len, m % len);
            }
            Mutation::Byte(n, b) => {
                if !bytes.is_empty() {
                    let len = bytes.len();
                    bytes[n % len] = *b;
                }
                continue;
            }
            Mutation::Truncate(n) => {
                bytes.truncate(n % bytes.len().max(1));
                continue;
            }
        }
        bytes = lines.join("\n").into_bytes();
    }
    bytes
}

/// Runs `f` on a thread and fails if it takes longer than [`TIME_BOUND`] or panics.
fn bounded<T: Send + 'static>(what: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    match rx.recv_timeout(TIME_BOUND) {
        Ok(v) => v,
        Err(mpsc::RecvTimeoutError::Timeout) => panic!("{what}: longer than {TIME_BOUND:?}"),
        Err(mpsc::RecvTimeoutError::Disconnected) => panic!("{what}: panicked"),
    }
}

fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

/// Real coordinate files in every layout (Selig, Lednicer, plain, clockwise).
const COORDINATE_SEEDS: [&str; 5] = [
    "geometry/naca8h12.dat",
    "tests/data/geometry/lednicer_naca8h12.dat",
    "tests/data/xfoil/naca2412_buffer.dat",
    "tests/data/xfoil/naca23012_buffer.dat",
    "tests/data/geometry/selig_clockwise_naca8h12.dat",
];

/// Reads a mutated coordinate file and, if it is accepted, solves the panel flow at 0° and 6°
/// as `polargen --inviscid` does; the Cl values of an accepted contour.
fn coordinates_to_cl(bytes: Vec<u8>) -> Option<Vec<f64>> {
    let (foil, _) = parse_airfoil_bytes(&bytes, "mutated.dat", "mutated").ok()?;
    let (foil, _) = foil.in_chord_units().ok()?;
    let foil = foil.repanel(160, &PanelingParams::default()).ok()?;
    let system = PanelSystem::new(&foil).ok()?;
    let mut cl = Vec::new();
    for alpha in [0.0, 6.0] {
        let sol = system.solve(alpha, 0.0).ok()?;
        assert!(sol.cm.is_finite(), "Cm {} at alpha {alpha}", sol.cm);
        cl.push(sol.cl);
    }
    Some(cl)
}

/// 96 cases each (about 3 s for both properties); `PROPTEST_CASES` asks for more.
fn config() -> ProptestConfig {
    ProptestConfig {
        cases: std::env::var("PROPTEST_CASES")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(96),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn mutated_coordinate_files_give_a_clean_error_or_a_sound_lift(
        seed in 0..COORDINATE_SEEDS.len(),
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let text = std::fs::read_to_string(repo(COORDINATE_SEEDS[seed])).unwrap();
        let bytes = mutate(&text, &mutations);
        if let Some(cl) = bounded("coordinates", move || coordinates_to_cl(bytes)) {
            for c in cl {
                prop_assert!(c.is_finite() && c.abs() <= MAX_PLAUSIBLE_CL, "Cl {c}");
            }
        }
    }
}

/// Seed tables: a slice of a shipped long-form table in CSV and, written by polargen, JSON and
/// XFOIL polar files; the reference single-polar CSV.
fn table_seeds(dir: &Path) -> Vec<(String, String)> {
    let csv = std::fs::read_to_string(repo("polars/naca8h12_free.csv")).unwrap();
    let slice: Vec<&str> = csv.lines().take(30).collect();
    let slice = slice.join("\n") + "\n";
    let csv_path = dir.join("seed.csv");
    std::fs::write(&csv_path, &slice).unwrap();
    let table = read_table(&csv_path).unwrap();
    let mut seeds = vec![("csv".to_string(), slice)];
    for ext in ["json", "pol"] {
        let path = dir.join(format!("seed.{ext}"));
        let written = write_table(&table, &path, None).unwrap();
        seeds.push((
            ext.to_string(),
            std::fs::read_to_string(&written[0]).unwrap(),
        ));
    }
    let polar = std::fs::read_to_string(repo("tests/data/xfoil/naca8h12_Re1.9e6_M0.41_free.csv"));
    seeds.push(("csv".to_string(), polar.unwrap()));
    seeds
}

/// Reads a mutated table file; if it is accepted, checks its values and writes it in every
/// format that can be read, reading each back.
fn check_table(dir: &Path, ext: &str, bytes: &[u8]) -> Result<(), String> {
    // A file name whose Re and M a single-polar CSV takes its flow condition from.
    let path = dir.join(format!("mutated_Re1.9e6_M0.41.{ext}"));
    std::fs::write(&path, bytes).unwrap();
    let Ok(table) = read_table(&path) else {
        return Ok(());
    };
    for (cond, polar) in table.polars() {
        if !(cond.reynolds.is_finite() && cond.mach.is_finite()) {
            return Err(format!("condition {cond:?}"));
        }
        for p in polar.iter().filter(|p| p.converged) {
            for ((name, bound), v) in COEFFICIENT_BOUNDS.iter().zip([p.cl, p.cd, p.cm]) {
                if !(v.is_finite() && v.abs() <= *bound) {
                    return Err(format!("{name} {v} accepted at alpha {}", p.alpha));
                }
            }
        }
    }
    for out in ["csv", "json", "pol"] {
        let target = dir.join(format!("back.{out}"));
        if let Ok(written) = write_table(&table, &target, None) {
            for file in written {
                read_table(&file).map_err(|e| format!("{out} written but unreadable: {e}"))?;
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn mutated_tables_are_refused_or_sound_and_read_back(
        seed in 0..4usize,
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let dir = std::env::temp_dir().join(format!("polargen-prop-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let seeds = table_seeds(&dir);
        let (ext, text) = seeds[seed].clone();
        let bytes = mutate(&text, &mutations);
        let scratch = dir.clone();
        let verdict = bounded("table", move || check_table(&dir, &ext, &bytes));
        let _ = std::fs::remove_dir_all(scratch);
        prop_assert!(verdict.is_ok(), "{}", verdict.unwrap_err());
    }
}
