//! `gyro report` run once per test binary, as a user outside the repository runs it (no
//! arguments: the built-in shipped aircraft and tables): the same report as the shipped one, and
//! its tables hold the values `gyro trim/takeoff/alpha --json` compute for the same inputs.

mod cli_support;

use cli_support::{aircraft, assert_ok, exe, gyro, polars, root, scratch, text};
use polargen::table::alpha_at_cl;
use polargen::table::read_table;
use std::collections::BTreeMap;
use std::path::Path;
use std::process::{Command, Output};
use std::sync::LazyLock;

/// What one `gyro report --out r`, run in an empty folder, left: the process's output, the
/// report's README and the size of every file it wrote (the folder itself is removed).
struct Report {
    out: Output,
    readme: String,
    sizes: BTreeMap<String, u64>,
}

/// The one report run every test here reads (about a minute of CPU).
static REPORT: LazyLock<Report> = LazyLock::new(|| {
    let dir = scratch("report");
    let out = Command::new(exe("gyro"))
        .args(["report", "--out", "r"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", text(&out.stderr));
    let written = dir.join("r");
    let readme = std::fs::read_to_string(written.join("README.md")).unwrap();
    let sizes = std::fs::read_dir(&written)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            let name = e.file_name().to_string_lossy().into_owned();
            (name, e.metadata().unwrap().len())
        })
        .collect();
    std::fs::remove_dir_all(&dir).unwrap();
    Report { out, readme, sizes }
});

#[test]
fn report_outside_the_repository_is_the_shipped_report() {
    let shipped = std::fs::read_to_string(root().join("report/README.md")).unwrap();
    // The same report as the shipped one: after its first lines, which name the command, and
    // before the section the shipped one adds with `--studies`.
    let body = |s: &str| {
        let lines = s
            .lines()
            .skip(3)
            .take_while(|l| *l != "## Beyond the paper");
        lines.collect::<Vec<_>>().join("\n").trim_end().to_string()
    };
    assert_eq!(body(&REPORT.readme), body(&shipped));
}

/// The cells of the Markdown table row whose first cell is `name`.
fn row<'a>(md: &'a str, name: &str) -> Vec<&'a str> {
    let line = md
        .lines()
        .find(|l| l.starts_with(&format!("| {name} |")))
        .unwrap_or_else(|| panic!("README has no row '{name}'"));
    line.trim_matches('|').split('|').map(str::trim).collect()
}

/// Checks that a printed cell equals `value` to the precision it is printed with.
fn assert_printed(cell: &str, value: f64, what: &str) {
    let printed: f64 = cell
        .parse()
        .unwrap_or_else(|_| panic!("{what}: '{cell}' is no number"));
    let decimals = cell.split('.').nth(1).map_or(0, str::len);
    let half_unit = 0.5 * 10f64.powi(-(decimals as i32)) * (1.0 + 1e-9);
    assert!(
        (printed - value).abs() <= half_unit,
        "{what}: README {cell}, computed {value}"
    );
}

fn json_of(args: &[&str]) -> serde_json::Value {
    let out = gyro(args);
    assert_ok(&out);
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

/// The report's tables against the single commands on the repository's aircraft and tables
/// (those the report outside the repository uses built in).
#[test]
fn report_tables_match_the_single_commands() {
    let ac = aircraft();
    let out = &REPORT.out;
    for name in [
        "README.md",
        "blade_alpha.png",
        "blade_alpha.svg",
        "takeoff.png",
        "takeoff.svg",
        "power_required.png",
        "power_required.svg",
        "polar_naca8h12.png",
        "polar_naca8h12.svg",
        "polar_naca23012.png",
        "polar_naca23012.svg",
        "pca2_tunnel.png",
        "pca2_tunnel.svg",
        "pca2_flight.png",
        "pca2_flight.svg",
    ] {
        let len = REPORT.sizes.get(name).copied().unwrap_or(0);
        assert!(len > 5_000, "{name}: {len} bytes");
    }
    let md = &REPORT.readme;
    // The second rotor's section with its figures.
    for line in [
        "## The rotor model on a second rotor",
        "![PCA-2 in the tunnel](pca2_tunnel.png)",
        "![PCA-2 in flight](pca2_flight.png)",
    ] {
        assert!(md.contains(line), "no {line:?} in the report");
    }
    // The files written are notes on stderr, nothing on stdout.
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.stdout.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    assert!(
        stderr.contains("gyro: wrote ") && stderr.contains("README.md"),
        "{stderr}"
    );
    // The summary leads with the flight test: our Δ engine rpm beside the test's ≈ +200 and
    // our contamination changes as multiples of the paper's.
    let summary = md.split("## Summary").nth(1).expect("summary");
    let first = summary.lines().find(|l| l.starts_with("- ")).unwrap();
    assert!(first.starts_with("- **Flight test (Table 2)"), "{first}");
    // `gyro trim --json` on the 8-H-12 tables, clean and contaminated.
    let trims: Vec<serde_json::Value> = ["free", "xtr0.07"]
        .iter()
        .map(|kind| {
            let table = polars(&format!("naca8h12_{kind}.csv"));
            json_of(&["trim", "--aircraft", &ac, "--table", &table, "--json"])
        })
        .collect();
    let engine = |trim: &serde_json::Value| trim["engine_rpm"].as_f64().unwrap();
    let delta = format!(
        "costs {:+.0} engine rpm",
        engine(&trims[1]) - engine(&trims[0])
    );
    assert!(
        first.contains(&delta) && first.contains("× its Table 3 changes"),
        "{delta}: {first}"
    );
    // The share of lookups clamped to the tables' edges is stated under Table 3.
    let coverage = md
        .lines()
        .find(|l| l.starts_with("Table coverage: at these trims "))
        .expect("coverage line");
    // The default grid covers the rotor up to its advancing tip: only the inboard strips near
    // the reverse-flow circle lie below its lowest Reynolds number.
    assert!(
        coverage.contains("fall outside the tables' range (Re 100000…3000000, M 0…0.65)")
            && coverage.contains("the reverse-flow circle")
            && !coverage.contains("advancing tip"),
        "{coverage}"
    );
    // Both rotor angles, the flight test and the sensitivity table are shown.
    for heading in [
        "## Flight test (Table 2)",
        "### Rotor angle of attack: two angles",
        "## Sensitivity to the estimated values",
    ] {
        assert!(md.contains(heading), "{heading}");
    }

    // Tables 3 and 4: "ours clean" is cell 2, "ours contaminated" cell 5, same runs as
    // `gyro trim --json` and `gyro takeoff --json` on the 8-H-12 tables.
    let trim_keys = [
        ("rotor rpm n_R", "rotor_rpm"),
        ("rotor AoA alpha_R [deg]", "rotor_aoa_drag_equivalent_deg"),
        ("engine rpm", "engine_rpm"),
        ("rotor drag D_R [N]", "rotor_drag_n"),
        ("parasitic drag D_P [N]", "parasitic_drag_n"),
        ("prop thrust F_prop [N]", "prop_thrust_n"),
        ("L/D", "lift_to_drag"),
    ];
    let takeoff_keys = [
        ("takeoff roll s_TO [m]", "takeoff_roll_m"),
        ("distance to 15 m s_15 [m]", "distance_15m_m"),
        ("max flapping beta_max [deg]", "max_flapping_deg"),
    ];
    for ((cell, kind), trim) in [(2, "free"), (5, "xtr0.07")].into_iter().zip(&trims) {
        let table = polars(&format!("naca8h12_{kind}.csv"));
        for (name, key) in trim_keys {
            let v = trim[key].as_f64().unwrap_or(f64::NAN);
            let printed = row(md, name)[cell];
            if v.is_nan() {
                assert_eq!(printed, "—", "{name} {kind}");
            } else {
                assert_printed(printed, v, &format!("{name} {kind}"));
            }
        }
        let takeoff = json_of(&["takeoff", "--aircraft", &ac, "--table", &table, "--json"]);
        for (name, key) in takeoff_keys {
            assert_printed(
                row(md, name)[cell],
                takeoff[key].as_f64().unwrap(),
                &format!("{name} {kind}"),
            );
        }
        // Fig. 10 row: the maximum of `gyro alpha` at 0.9 R with 1° samples.
        let out = gyro(&[
            "alpha",
            "--aircraft",
            &ac,
            "--table",
            &table,
            "--radius",
            "0.9",
            "--samples",
            "360",
        ]);
        assert_ok(&out);
        let curve: Vec<(f64, f64)> = String::from_utf8(out.stdout)
            .unwrap()
            .lines()
            .skip(1)
            .map(|l| {
                let (p, a) = l.split_once(',').unwrap();
                (p.parse::<f64>().unwrap(), a.parse::<f64>().unwrap())
            })
            .collect();
        let alpha = curve.iter().fold(f64::MIN, |m, r| m.max(r.1));
        let fig10 = row(
            md,
            if kind == "free" {
                "clean"
            } else {
                "contaminated"
            },
        );
        // `gyro alpha` prints α to 3 decimals, so near the flat top several samples can tie:
        // allow that rounding on α, and check that the report's ψ is one of the tied maxima.
        let alpha_readme: f64 = fig10[2].parse().unwrap();
        assert!(
            (alpha_readme - alpha).abs() <= 0.0055,
            "{fig10:?} vs {alpha}"
        );
        let psi_readme: f64 = fig10[5].parse().unwrap();
        let at_psi = curve
            .iter()
            .find(|(p, _)| (p - psi_readme).abs() < 0.5)
            .map(|r| r.1);
        assert!(
            at_psi.is_some_and(|a| alpha - a <= 0.0015),
            "{fig10:?}: α {at_psi:?} at the report's ψ, maximum {alpha}"
        );
    }

    // Table 5: ours is the table lookup at Re 1.9e6, M 0.41, and within 3 % of XFOIL 6.99
    // (0.00607, 0.01165, 0.00802, 0.01118; the shipped tables were checked against it).
    let mut rows = md
        .lines()
        .filter(|l| l.starts_with("| NACA 8-H-12 |") || l.starts_with("| NACA 23012 |"));
    for (file, xfoil) in [
        ("naca8h12_free.csv", 0.00607),
        ("naca8h12_xtr0.07.csv", 0.01165),
        ("naca23012_free.csv", 0.00802),
        ("naca23012_xtr0.07.csv", 0.01118),
    ] {
        let cells: Vec<&str> = rows
            .next()
            .unwrap()
            .trim_matches('|')
            .split('|')
            .map(str::trim)
            .collect();
        let table = read_table(Path::new(&polars(file))).unwrap();
        let m = alpha_at_cl(&table, 0.8, 1.9e6, 0.41, -5.0, 15.0).unwrap();
        assert_printed(cells[3], xfoil, &format!("{file} XFOIL column"));
        assert_printed(cells[4], m.lookup.cd, &format!("{file} Cd"));
        assert_printed(cells[8], m.alpha_deg, &format!("{file} alpha"));
        assert!((m.lookup.cl - 0.8).abs() < 1e-6, "{file}: {m:?}");
        assert!(
            (m.lookup.cd / xfoil - 1.0).abs() < 0.03,
            "{file}: Cd {} vs XFOIL 6.99 {xfoil}",
            m.lookup.cd
        );
    }
    assert!(md.contains("![Blade angle of attack vs azimuth](blade_alpha.png)"));
}
