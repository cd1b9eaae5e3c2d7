//! The aircraft model against the flight test (paper Table 2) and the paper's model (Tables 1,
//! 3 and 4): `gyro compare --json` and `gyro trim --json` (a) with the project's own shipped
//! NACA 8-H-12 tables (`polars/`, the default Re × M grid) and (b) with the XFOIL 6.99
//! reference polars at Re 1.9e6, M 0.41 (one polar each, free transition and transition fixed
//! at 7 % chord).
//!
//! The project's acceptance bands that the model meets are asserted as set: clean
//! rotor rpm 350 ± 15 (ours 359.7), static full-throttle thrust 2000 N ± 10 %
//! (paper Table 1; ours 2060 N with the propeller's own thickness-interpolated sections; at
//! rest 85 % of its annuli lie beyond their table's usable α range — past stall, where the
//! points are in massive separation and the 360° extension stands in — and 70 % lean on
//! supercritical points, so the static thrust is mostly the extension's; a two-dimensional polar without
//! rotational stall delay still under-predicts a propeller's static power: NACA Report 594
//! propeller D at 30°: −43 %, `tests/rotor_propeller.rs`). Those it does not meet are stated
//! here with their numbers and asserted as the measured values within a stated guard, not
//! tuned:
//! * Δ engine rpm clean → contaminated +200 ± 60 (the paper's model +195): ours +262 (4307 →
//!   4568), just outside; +255 (4308 → 4563) with one 11.7 % Clark Y table along the
//!   propeller blade. The thinner outboard sections of the blade's own family need a little
//!   more rpm for the contaminated rotor's extra thrust;
//! * at most 2 % of the 60 kt lookups clamped: ours 3.1 % (clean), all in the innermost strip
//!   at ψ 220…320°, where the blade meets the air at under 7 m/s (Re < 10⁵): the reverse-flow
//!   circle (1.9 %) and its edge;
//! * ΔF_prop (paper +14 %): ours +20.6 %; clean D_R 397 N (paper 478 N) and clean α_R 5.14°
//!   (paper 6.2°): our clean rotor is less draggy than the paper's while the contaminated one
//!   is close (D_R 598 N, paper 624 N), so the relative rise is larger;
//! * takeoff: s_15 313 m clean (paper 218 m) and the s_TO rise +30 % (paper +19 %): the
//!   propeller's thrust falls quickly from its static value with speed, because its power
//!   coefficient rises with J at low J where NACA 594 shows it flat or falling (the same stall
//!   modelling).

use polargen::rotor::{trim_aircraft, Aircraft, TrimParams};
use polargen::section::{Lookup, SectionAero};
use polargen::table::read_lookup_table;
use std::path::PathBuf;

mod cli_support;
mod xfoil_support;
use cli_support::{aircraft, gyro, ok, root};

/// The JSON `gyro` prints for `args` (the run must succeed).
fn run_gyro(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&ok(gyro(args))).unwrap()
}

fn run_compare(clean: PathBuf, contaminated: PathBuf) -> serde_json::Value {
    let (c, d) = (
        clean.display().to_string(),
        contaminated.display().to_string(),
    );
    run_gyro(&[
        "compare",
        "--aircraft",
        &aircraft(),
        "--clean",
        &c,
        "--contaminated",
        &d,
        "--json",
    ])
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

/// Relative change b/a − 1 in percent.
fn rise(a: f64, b: f64) -> f64 {
    100.0 * (b / a - 1.0)
}

fn shipped(kind: &str) -> PathBuf {
    root().join(format!("polars/naca8h12_{kind}.csv"))
}

#[test]
fn shipped_tables_against_the_flight_test_and_the_paper() {
    let v = run_compare(shipped("free"), shipped("xtr0.07"));
    // Bands met: clean rotor rpm 350 ± 15, Δ engine rpm +200 ± 60 (the flight test).
    let (rc, rd) = row(&v, "trim", "rotor rpm");
    assert!((rc - 350.0).abs() <= 15.0, "clean rotor rpm {rc}");
    assert!(
        (rd - 348.0).abs() <= 20.0 && (rd / rc - 1.0).abs() < 0.02,
        "{rc} {rd}"
    );
    let (ec, ed) = row(&v, "trim", "engine rpm");
    // Band +200 ± 60 narrowly not met: +262 (module doc). Guard: +230 … +290.
    assert!(
        (230.0..=290.0).contains(&(ed - ec)),
        "Δ engine rpm {}",
        ed - ec
    );
    // The drag-equivalent rotor angle (the paper's α_R): contaminated 8.1 ± 1.2°; clean ~5.2°
    // against 6.2° (module doc).
    let (ac, ad) = row(&v, "trim", "rotor AoA");
    assert!((ad - 8.1).abs() <= 1.2, "contaminated alpha_R {ad}");
    assert!(
        ac > 4.5 && ac < 6.2 && ad - ac > 1.5 && ad - ac < 3.5,
        "{ac} {ad}"
    );
    let (dc, dd) = row(&v, "trim", "rotor drag");
    assert!((dd / 624.0 - 1.0).abs() <= 0.15, "contaminated D_R {dd}");
    assert!(dc > 0.8 * 478.0 && dc < 478.0, "clean D_R {dc}");
    // ΔF_prop ~ +21 % against +14 % (module doc): guard 10…24 %.
    let (fc, fd) = row(&v, "trim", "prop thrust");
    let df = rise(fc, fd);
    assert!(df > 10.0 && df < 24.0, "F_prop rise {df} %");
    // Static thrust and table coverage from `gyro trim --json`.
    let trim = |kind: &str| {
        let t = shipped(kind).display().to_string();
        run_gyro(&["trim", "--aircraft", &aircraft(), "--table", &t, "--json"])
    };
    let (tc, td) = (trim("free"), trim("xtr0.07"));
    let static_thrust = tc["static_thrust_n"].as_f64().unwrap();
    // Band 2000 N ± 10 % (module doc): ~2060 N.
    assert!(
        (1800.0..=2200.0).contains(&static_thrust),
        "static thrust {static_thrust}"
    );
    // The static point's validity shares (module doc): ~85 % beyond the usable α range,
    // ~70 % supercritical.
    let share = |k: &str| 100.0 * tc[k].as_f64().unwrap();
    let (beyond, supercritical) = (
        share("static_thrust_post_stall_fraction"),
        share("static_thrust_supercritical_fraction"),
    );
    assert!((75.0..=95.0).contains(&beyond), "{beyond} %");
    assert!((55.0..=85.0).contains(&supercritical), "{supercritical} %");
    assert_eq!(static_thrust, td["static_thrust_n"].as_f64().unwrap());
    // The README states these numbers as computed here.
    xfoil_support::check_readme_block(
        "flight test",
        "UPDATE_README=1 cargo test --test gyro_paper shipped_tables",
        &format!(
            "The aircraft against the flight test at 60 kt (paper Table 2) with the shipped \
             tables: clean rotor {rc:.1} rpm (≈ 350), contamination {:+.0} engine rpm (≈ +200; \
             the paper's model +195); predicted static thrust {static_thrust:.0} N (paper Table \
             1 ≈ 2000 N). The rest in [the report](report/README.md); `tests/gyro_paper.rs` \
             asserts the bands that are met and states the others with their numbers.\n",
            ed - ec
        ),
    );
    for t in [&tc, &td] {
        let clamped = t["table_clamped_fraction"].as_f64().unwrap();
        // Band ≤ 2 % not met: ~3 % (module doc), all near the reverse-flow circle.
        assert!(clamped > 0.0 && clamped <= 0.035, "clamped {clamped}");
        assert_eq!(t["table_supercritical_fraction"].as_f64().unwrap(), 0.0);
    }
    // Table 4: s_TO within 25 % of 121 m and 144 m; β_max below the 7° stops and larger when
    // contaminated. Clean s_15 ~305 m against 218 m and the rises (module doc): guarded.
    let (sc, sd) = row(&v, "takeoff", "takeoff roll");
    assert!((sc / 121.0 - 1.0).abs() <= 0.25, "clean s_TO {sc}");
    assert!((sd / 144.0 - 1.0).abs() <= 0.25, "contaminated s_TO {sd}");
    assert!((10.0..45.0).contains(&rise(sc, sd)), "s_TO rise");
    let (s15c, s15d) = row(&v, "takeoff", "distance to 15 m");
    assert!(s15c > 218.0 && s15c < 1.5 * 218.0, "clean s_15 {s15c}");
    assert!(
        s15d > s15c * 1.1 && s15d < 1.7 * 253.0,
        "contaminated s_15 {s15d}"
    );
    let (bc, bd) = row(&v, "takeoff", "max flapping");
    assert!(bc < 7.0 && bd < 7.0 && bd > bc, "beta_max {bc} {bd}");
    assert!(
        (bc - 3.5).abs() < 1.0 && (bd - 4.2).abs() < 1.0,
        "beta_max {bc} {bd}"
    );
}

#[test]
fn xfoil_polars_against_the_flight_test_and_the_paper() {
    let t = |k: &str| root().join(format!("tests/data/xfoil/naca8h12_Re1.9e6_M0.41_{k}.csv"));
    let v = run_compare(t("free"), t("xtr0.07"));
    // One polar each (every strip at Re 1.9e6, M 0.41): clean rotor rpm 357, Δ engine rpm +246.
    let (rc, rd) = row(&v, "trim", "rotor rpm");
    assert!(
        (rc - 350.0).abs() <= 15.0 && (rd / rc - 1.0).abs() < 0.03,
        "{rc} {rd}"
    );
    let (ec, ed) = row(&v, "trim", "engine rpm");
    assert!((ed - ec - 200.0).abs() <= 60.0, "Δ engine rpm {}", ed - ec);
    let (ac, ad) = row(&v, "trim", "rotor AoA");
    assert!(
        (ad - 8.1).abs() <= 1.2 && ad - ac > 1.0,
        "alpha_R {ac} {ad}"
    );
    let (dc, dd) = row(&v, "trim", "rotor drag");
    assert!(
        (dd / 624.0 - 1.0).abs() <= 0.15 && dd > 1.3 * dc,
        "D_R {dc} {dd}"
    );
    let (fc, fd) = row(&v, "trim", "prop thrust");
    assert!((8.0..24.0).contains(&rise(fc, fd)), "F_prop rise");
    let (sc, sd) = row(&v, "takeoff", "takeoff roll");
    let (s15c, s15d) = row(&v, "takeoff", "distance to 15 m");
    for (ours, paper) in [(sc, 121.0), (sd, 144.0)] {
        assert!((ours / paper - 1.0).abs() <= 0.25, "{ours} vs {paper}");
    }
    assert!(
        s15c > 218.0 && s15d > 1.1 * s15c && s15d < 1.7 * 253.0,
        "{s15c} {s15d}"
    );
    let (bc, bd) = row(&v, "takeoff", "max flapping");
    assert!(bc < 7.0 && bd < 7.0 && bd > bc, "beta_max {bc} {bd}");
}

/// The contaminated section's drag with the clean section's lift and moment: contamination
/// without the loss of lift slope.
struct DragOnly<'a> {
    clean: &'a dyn SectionAero,
    contaminated: &'a dyn SectionAero,
}

impl SectionAero for DragOnly<'_> {
    fn lookup(&self, alpha_deg: f64, re: f64, mach: f64) -> Lookup {
        let c = self.clean.lookup(alpha_deg, re, mach);
        Lookup {
            cd: self.contaminated.lookup(alpha_deg, re, mach).cd,
            ..c
        }
    }
}

/// What the trip's loss of lift slope is worth (the README's sentence is this test's output):
/// the contaminated table with the clean table's lift and moment (its drag alone) gives a
/// smaller ΔF_prop than the contaminated table.
#[test]
fn the_lift_slope_loss_is_worth_points_of_delta_f_prop() {
    let ac = Aircraft::from_toml_file(&root().join("aircraft/mtosport.toml")).unwrap();
    let clean = read_lookup_table(&shipped("free")).unwrap();
    let dirty = read_lookup_table(&shipped("xtr0.07")).unwrap();
    let f = |s: &dyn SectionAero| {
        trim_aircraft(&ac, s, 60.0, 450.0, 0.0, &TrimParams::default())
            .unwrap()
            .prop_thrust_n
    };
    let (fc, fd) = (f(&clean), f(&dirty));
    let fh = f(&DragOnly {
        clean: &clean,
        contaminated: &dirty,
    });
    let (full, drag_only) = (rise(fc, fd), rise(fc, fh));
    eprintln!("ΔF_prop {full:.1} %, drag alone {drag_only:.1} %");
    // Measured: +20.6 % with both, +15.5 % from the drag alone: the slope loss adds 5 points.
    assert!(
        full - drag_only > 3.0 && full - drag_only < 7.0,
        "{full} {drag_only}"
    );
    // The README states these numbers as computed here.
    xfoil_support::check_readme_block(
        "thrust rise",
        "UPDATE_README=1 cargo test --test gyro_paper lift_slope",
        &format!(
            "That loss of slope is worth {:.0} points of the propeller-thrust rise at 60 kt: \
             {full:+.1} % with the tripped table, {drag_only:+.1} % with its drag alone \
             (`tests/gyro_paper.rs`).\n",
            full - drag_only
        ),
    );
}
