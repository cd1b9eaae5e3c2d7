//! Paper comparison (issue 5, item 6) with the XFOIL 6.99 reference polars of the NACA 8-H-12
//! at Re 1.9e6, M 0.41 (free transition and transition fixed at 7 % chord), run through
//! `gyro compare --json`. The bands are the where this model meets them with these
//! single-Re polars; the others are checked for direction or a wider band, each saying why.

use std::path::PathBuf;
use std::process::Command;

fn run_compare() -> serde_json::Value {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let t = |k: &str| {
        root.join(format!("tests/data/rotor/naca8h12_Re1.9e6_M0.41_{k}.csv"))
            .display()
            .to_string()
    };
    let ac = root.join("aircraft/mtosport.toml").display().to_string();
    let out = Command::new(env!("CARGO_BIN_EXE_gyro"))
        .args([
            "compare",
            "--aircraft",
            &ac,
            "--clean",
            &t("free"),
            "--contaminated",
            &t("xtr0.07"),
            "--json",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// (ours clean, ours contaminated) for the row whose quantity starts with `name`.
fn row(v: &serde_json::Value, table: &str, name: &str) -> (f64, f64) {
    let r = v[table]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["quantity"].as_str().unwrap().starts_with(name))
        .unwrap();
    (
        r["ours_clean"].as_f64().unwrap(),
        r["ours_contaminated"].as_f64().unwrap(),
    )
}

#[test]
fn xfoil_polars_against_paper_tables_3_and_4() {
    let v = run_compare();
    // Table 3: rotor rpm 347 ± 20 (both), nearly unchanged by contamination.
    let (rc, rd) = row(&v, "trim", "rotor rpm");
    assert!(
        (rc - 347.0).abs() <= 20.0 && (rd - 348.0).abs() <= 20.0,
        "rpm {rc} {rd}"
    );
    assert!((rd / rc - 1.0).abs() < 0.03);
    // Rotor AoA, rotor drag and thrust rise with contamination (paper +1.9°, +31 %, +14 %).
    let (ac, ad) = row(&v, "trim", "rotor AoA");
    assert!(ad - ac > 1.0 && ad - ac < 4.0, "alpha_R {ac} {ad}");
    let (dc, dd) = row(&v, "trim", "rotor drag");
    assert!(dd > 1.2 * dc, "D_R {dc} {dd}");
    let (fc, fd) = row(&v, "trim", "prop thrust");
    let rise = 100.0 * (fd / fc - 1.0);
    assert!((8.0..26.0).contains(&rise), "F_prop rise {rise} %");
    let (ec, ed) = row(&v, "trim", "engine rpm");
    assert!((ec - 4401.0).abs() < 300.0 && ed > ec, "engine {ec} {ed}");
    // Table 4: s_TO within 25 % of 121 m (clean). s_15 is longer than the paper's 218 m: after
    // lift-off the pilot model climbs while accelerating, and with these polars the rotor must
    // first spin up from ~310 rpm before the disc can be lowered, so the climb segment takes
    // ~175 m instead of the paper's ~97 m; 50 % guards the present model.
    let (sc, sd) = row(&v, "takeoff", "takeoff roll");
    assert!((sc / 121.0 - 1.0).abs() <= 0.25, "s_TO {sc}");
    let (s15c, s15d) = row(&v, "takeoff", "distance to 15 m");
    assert!(
        (s15c / 218.0 - 1.0).abs() <= 0.5 && s15c > sc + 50.0,
        "s_15 {s15c}"
    );
    // Contamination lengthens both distances (paper +19 % / +16 %).
    assert!(
        sd > 1.1 * sc && s15d > 1.1 * s15c,
        "s_TO {sc} {sd}, s_15 {s15c} {s15d}"
    );
    let (bc, bd) = row(&v, "takeoff", "max flapping");
    assert!(bc < 7.0 && bd < 7.0 && bd > bc, "beta_max {bc} {bd}");
}
