//! The wing study on the shipped 8-H-12 clean table: its records are the aircraft's own
//! trims with the wing scaled, area 0 is the wingless aircraft, the rotor unloads as the wing
//! grows, bad settings stop with one line before any work.

use polargen::rotor::{trim_aircraft, Aircraft, TrimParams};
use polargen::studies::records_json;
use polargen::studies::wing::{run_wing, WingOptions, WingStudy};
use polargen::studies::Transition;
use polargen::table::read_lookup_table;
use std::path::Path;

fn root(p: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(p)
}

fn options(areas: &[f64], speeds: &[f64]) -> WingOptions {
    WingOptions {
        airfoil: "naca8h12".into(),
        areas_m2: areas.to_vec(),
        speeds_kt: speeds.to_vec(),
        xtr: None,
    }
}

#[test]
fn wing_records_are_the_trims_of_the_scaled_aircraft() {
    let ac = Aircraft::from_toml_file(&root("aircraft/mtosport.toml")).unwrap();
    let clean = read_lookup_table(&root("polars/naca8h12_free.csv")).unwrap();
    let opts = options(&[0.0, 1.0, 1.7], &[60.0]);
    let records = run_wing(&ac, &clean, &opts, &|| {}).unwrap();
    assert_eq!(records.len(), 3);
    let trim = |area: f64| {
        let a = ac.with_wing_area(area).unwrap();
        trim_aircraft(&a, &clean, 60.0, a.mass_kg, 0.0, &TrimParams::default()).unwrap()
    };
    // Area 0 is the shipped (wingless) aircraft exactly.
    let none = trim(0.0);
    assert!(records[0].converged);
    assert_eq!(records[0].prop_thrust_n, Some(none.prop_thrust_n));
    assert_eq!(records[0].delta_prop_thrust_pct, Some(0.0));
    assert_eq!(records[0].rotor_lift_share, Some(1.0));
    assert_eq!(records[0].wing_drag_n, Some(0.0));
    let wing = trim(1.7);
    assert_eq!(records[2].prop_thrust_n, Some(wing.prop_thrust_n));
    assert_eq!(records[2].engine_rpm, wing.engine_rpm);
    assert_eq!(
        records[2].delta_prop_thrust_pct,
        Some(100.0 * (wing.prop_thrust_n / none.prop_thrust_n - 1.0))
    );
    // The rotor carries less as the wing grows.
    let share: Vec<f64> = records
        .iter()
        .map(|r| r.rotor_lift_share.unwrap())
        .collect();
    assert!(share[0] > share[1] && share[1] > share[2], "{share:?}");
    // The names scripts rely on, in the JSON and the CSV.
    let json = records_json(&records);
    for key in [
        "wing_area_m2",
        "speed_kt",
        "prop_thrust_n",
        "power_required_kw",
        "rotor_lift_share",
        "engine_rpm",
        "rotor_rpm",
        "converged",
    ] {
        assert!(json.contains(&format!("\"{key}\"")), "{key}");
    }
    let study = WingStudy {
        airfoil: "NACA 8-H-12".into(),
        rotor: Transition::CLEAN,
        records,
    };
    let files = study.files().unwrap();
    assert_eq!(files.csv.lines().count(), 4);
    assert_eq!(
        files.csv.lines().next().unwrap(),
        "wing_area_m2,speed_kt,converged,rotor_rpm,prop_thrust_n,delta_prop_thrust_pct,\
         power_required_kw,engine_rpm,rotor_lift_share,rotor_drag_n,wing_drag_n,\
         wing_lift_coefficient,note"
    );
    assert!(study.text().lines().count() == 5, "{}", study.text());
}

#[test]
fn a_trim_that_fails_is_a_record_not_a_result() {
    // A wing of 17 m² at 90 kt lifts about 3060 N; the rotor, left with 1360 N, lifts more
    // than that at every hub angle the trim searches (down to −6°): no trim, said so, no
    // numbers.
    let ac = Aircraft::from_toml_file(&root("aircraft/mtosport.toml")).unwrap();
    let clean = read_lookup_table(&root("polars/naca8h12_free.csv")).unwrap();
    let records = run_wing(&ac, &clean, &options(&[17.0], &[90.0]), &|| {}).unwrap();
    assert!(!records[0].converged);
    assert!(records[0].prop_thrust_n.is_none() && records[0].power_required_kw.is_none());
    assert!(records[0].note.contains("no trim"), "{}", records[0].note);
}

#[test]
fn bad_settings_are_one_line_errors() {
    for (areas, speeds, xtr, needle) in [
        (vec![], vec![60.0], None, "--areas"),
        (vec![-1.0], vec![60.0], None, "--areas -1"),
        (vec![f64::NAN], vec![60.0], None, "--areas NaN"),
        (vec![1.0], vec![0.0], None, "--speeds 0"),
        (vec![1.0], vec![60.0], Some(0.0), "xtr"),
        (vec![1.0; 20], vec![60.0; 20], None, "at most"),
    ] {
        let o = WingOptions {
            airfoil: "naca8h12".into(),
            areas_m2: areas,
            speeds_kt: speeds,
            xtr,
        };
        let msg = o.checked().unwrap_err().to_string();
        assert!(msg.contains(needle) && !msg.contains('\n'), "{msg}");
    }
    // An aircraft without a [wing] has nothing to scale.
    let text = std::fs::read_to_string(root("aircraft/mtosport.toml")).unwrap();
    let start = text.find("[wing]\n").unwrap();
    let end = text.find("[takeoff]\n").unwrap();
    let text = format!("{}{}", &text[..start], &text[end..]);
    let ac = Aircraft::from_toml_str(&text, &root("aircraft/mtosport.toml").display().to_string())
        .unwrap();
    let clean = read_lookup_table(&root("polars/naca8h12_free.csv")).unwrap();
    let err = run_wing(&ac, &clean, &options(&[1.0], &[60.0]), &|| {}).unwrap_err();
    assert!(err.to_string().contains("[wing]"), "{err}");
}
