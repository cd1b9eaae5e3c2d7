//! The airfoil and speed studies on the shipped 8-H-12 tables: each record's penalty is the
//! difference of its own runs, the speed study's 60 kt point is the contamination study's, and
//! the CSV columns are the records' JSON keys in the documented order (docs/studies.md).

use polargen::rotor::Aircraft;
use polargen::studies::airfoil::{run_airfoils, AirfoilStudy};
use polargen::studies::paper::paper_runs;
use polargen::studies::speed::{run_speeds, SpeedStudy};
use polargen::studies::Transition;
use polargen::table::read_lookup_table;
use std::path::Path;

fn root(p: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(p)
}

#[test]
fn airfoil_and_speed_studies_pair_their_runs() {
    let ac = Aircraft::from_toml_file(&root("aircraft/mtosport.toml")).unwrap();
    let clean = read_lookup_table(&root("polars/naca8h12_free.csv")).unwrap();
    let dirty = read_lookup_table(&root("polars/naca8h12_xtr0.07.csv")).unwrap();
    let compare = paper_runs(&ac, &clean, &dirty).unwrap();
    let thrust = [compare[0].trim.prop_thrust_n, compare[1].trim.prop_thrust_n];
    let delta_f = 100.0 * (thrust[1] / thrust[0] - 1.0);

    // "b" is an airfoil whose clean table is a's contaminated one.
    let records =
        run_airfoils(&ac, &[("a", &clean, &dirty), ("b", &dirty, &dirty)], &|| {}).unwrap();
    let names: Vec<(&str, bool)> = records
        .iter()
        .map(|r| (r.airfoil.as_str(), r.contaminated))
        .collect();
    assert_eq!(
        names,
        [("a", false), ("a", true), ("b", false), ("b", true)]
    );
    assert_eq!(records[0].trim.prop_thrust_n, thrust[0]);
    assert_eq!(records[1].trim.prop_thrust_n, thrust[1]);
    assert_eq!(records[1].penalty.delta_prop_thrust_pct, delta_f);
    assert_eq!(records[2].prop_thrust_vs_first_pct, delta_f);
    assert_eq!(records[3].penalty.delta_prop_thrust_pct, 0.0);
    assert_eq!(records[3].prop_thrust_vs_first_pct, 0.0);
    let json = serde_json::to_value(&records).unwrap();
    for key in [
        "airfoil",
        "contaminated",
        "prop_thrust_n",
        "engine_rpm",
        "takeoff_roll_m",
    ] {
        assert!(json[0].get(key).is_some(), "missing {key}");
    }
    let study = AirfoilStudy { records };
    assert_eq!(
        header(&study.files().unwrap().csv),
        "airfoil,contaminated,rotor_rpm,rotor_aoa_deg,rotor_aoa_drag_equivalent_deg,\
         rotor_drag_n,prop_thrust_n,engine_rpm,delta_prop_thrust_pct,delta_engine_rpm,\
         prop_thrust_vs_first_pct,takeoff_roll_m,distance_15m_m,max_flapping_deg,\
         table_clamped_fraction"
    );

    let (speeds, notes) = run_speeds(&ac, &clean, &dirty, &[45.0, 60.0, 75.0]);
    assert!(notes.is_empty(), "{notes:?}");
    assert_eq!(speeds[1].clean_prop_thrust_n, thrust[0]);
    assert_eq!(speeds[1].prop_thrust_n, thrust[1]);
    assert_eq!(speeds[1].delta_prop_thrust_pct, delta_f);
    // The relative penalty falls with airspeed (measured +28 % at 45 kt, +14 % at 75 kt).
    assert!(speeds[0].delta_prop_thrust_pct > speeds[1].delta_prop_thrust_pct);
    assert!(speeds[1].delta_prop_thrust_pct > speeds[2].delta_prop_thrust_pct);
    let json = serde_json::to_value(&speeds).unwrap();
    for key in [
        "speed_kt",
        "delta_prop_thrust_pct",
        "delta_engine_rpm",
        "power_required_kw",
    ] {
        assert!(json[0].get(key).is_some(), "missing {key}");
    }
    let study = SpeedStudy {
        airfoil: "NACA 8-H-12".into(),
        trip: Transition::tripped(0.07),
        records: speeds,
        notes,
    };
    assert_eq!(
        header(&study.files().unwrap().csv),
        "speed_kt,clean_rotor_rpm,rotor_rpm,clean_prop_thrust_n,prop_thrust_n,\
         clean_engine_rpm,engine_rpm,delta_prop_thrust_pct,delta_engine_rpm,power_required_kw"
    );
}

/// The first line of a CSV text.
fn header(csv: &str) -> &str {
    csv.lines().next().unwrap()
}
