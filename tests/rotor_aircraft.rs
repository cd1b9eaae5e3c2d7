//! Aircraft preset, ISA atmosphere and propeller map.

mod rotor_support;

use polargen::rotor::{Aircraft, AircraftError, Atmosphere, PropellerMap, KT_TO_MS};
use rotor_support::mtosport;

#[test]
fn preset_holds_the_paper_table_1() {
    let ac = mtosport();
    assert_eq!(ac.mass_kg, 450.0);
    assert_eq!(ac.parasitic_drag_area_m2, 1.0);
    assert_eq!(ac.rotor.radius_m * 2.0, 8.4);
    assert_eq!(ac.rotor.blades, 2);
    assert_eq!(ac.rotor.chord_m, 0.2);
    assert_eq!(ac.rotor.incidence_deg, 2.5);
    assert_eq!(ac.rotor.flap_stop_deg, 7.0);
    assert_eq!(ac.rotor.radial_strips, 10);
    assert_eq!(ac.propeller.gear_ratio, 0.41);
    assert_eq!(ac.propeller.static_thrust_n, 2000.0);
    assert_eq!(ac.takeoff.prerotation_rpm, 200.0);
    assert_eq!(ac.takeoff.head_angle_max_deg, 15.0);
    // Uniform blades 0.5 … 4.2 m of 14 kg plus 3 kg m² hub: 2·14·(4.2³ − 0.5³)/(3·3.7) + 3.
    let expected = 2.0 * 14.0 * (4.2f64.powi(3) - 0.125) / 11.1 + 3.0;
    assert!((ac.rotor.polar_inertia() - expected).abs() < 1e-9);
}

fn preset_text() -> String {
    std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("aircraft/mtosport.toml"),
    )
    .unwrap()
}

#[test]
fn missing_field_is_a_one_line_error() {
    let text = preset_text().replace("chord_m = 0.2\n", "");
    let err = Aircraft::from_toml_str(&text, "test.toml").unwrap_err();
    let msg = err.to_string();
    assert!(matches!(err, AircraftError::Parse { .. }));
    assert!(
        msg.contains("chord_m") && msg.contains("test.toml") && !msg.contains('\n'),
        "{msg}"
    );
}

#[test]
fn unknown_field_and_bad_values_are_rejected() {
    let text = preset_text().replace("chord_m = 0.2\n", "chord_m = 0.2\ncord = 3\n");
    let msg = Aircraft::from_toml_str(&text, "t").unwrap_err().to_string();
    assert!(msg.contains("cord") && !msg.contains('\n'), "{msg}");
    let text = preset_text().replace("chord_m = 0.2\n", "chord_m = -0.2\n");
    let err = Aircraft::from_toml_str(&text, "t").unwrap_err();
    assert!(
        matches!(
            err,
            AircraftError::Invalid {
                field: "rotor.chord_m",
                ..
            }
        ),
        "{err}"
    );
    let text = preset_text().replace("blades = 2\n", "blades = 3\n");
    let err = Aircraft::from_toml_str(&text, "t").unwrap_err();
    assert!(
        matches!(
            err,
            AircraftError::Invalid {
                field: "rotor.blades",
                ..
            }
        ),
        "{err}"
    );
    let text = preset_text().replace("inflow = \"glauert\"", "inflow = \"vortex\"");
    assert_eq!(
        Aircraft::from_toml_str(&text, "t").unwrap_err().to_string(),
        "bad aircraft file t: unknown variant `vortex`, expected `glauert` or `drees`"
    );
    // Takeoff integration: a step that would take millions of steps, one too coarse to
    // resolve the rotor, a field above the ISA troposphere.
    for (from, to, field) in [
        (
            "time_step_s = 0.02",
            "time_step_s = 1e-9",
            "takeoff.time_step_s",
        ),
        (
            "time_step_s = 0.02",
            "time_step_s = 50",
            "takeoff.time_step_s",
        ),
        (
            "max_time_s = 120.0",
            "max_time_s = 1e6",
            "takeoff.max_time_s",
        ),
        (
            "max_time_s = 120.0",
            "max_time_s = 500",
            "takeoff.max_time_s",
        ),
        ("mass_kg = 450.0", "mass_kg = 1e300", "mass_kg"),
        (
            "max_engine_rpm = 5800.0",
            "max_engine_rpm = 1000.0",
            "propeller.max_engine_rpm",
        ),
        (
            "calib_speed_kt = ",
            "calib_speed_kt = 1e6 #",
            "propeller.calib_speed_kt",
        ),
        (
            "climb_speed_kt = ",
            "climb_speed_kt = 1e6 #",
            "takeoff.climb_speed_kt",
        ),
        (
            "field_altitude_m = 0.0",
            "field_altitude_m = 1e6",
            "takeoff.field_altitude_m",
        ),
    ] {
        assert!(preset_text().contains(from), "{from}");
        let err = Aircraft::from_toml_str(&preset_text().replace(from, to), "t").unwrap_err();
        assert!(
            matches!(err, AircraftError::Invalid { field: f, .. } if f == field),
            "{to}: {err}"
        );
    }
    let text = preset_text().replace("azimuth_steps = 36", "azimuth_steps = 35");
    assert!(Aircraft::from_toml_str(&text, "t").is_err());
    // κ below ideal momentum theory is rejected; omitting it means κ = 1.
    let text = preset_text().replace("induced_power_factor = 1.15", "induced_power_factor = 0.9");
    let err = Aircraft::from_toml_str(&text, "t").unwrap_err();
    assert!(
        matches!(
            err,
            AircraftError::Invalid {
                field: "rotor.induced_power_factor",
                ..
            }
        ),
        "{err}"
    );
    let text = preset_text().replace("induced_power_factor = 1.15\n", "");
    let ac = Aircraft::from_toml_str(&text, "t").unwrap();
    assert_eq!(ac.rotor.induced_power_factor, 1.0);
    let err = Aircraft::from_toml_file(std::path::Path::new("/nonexistent/x.toml")).unwrap_err();
    assert!(
        err.to_string().starts_with("cannot read aircraft file"),
        "{err}"
    );
}

#[test]
fn isa_values() {
    // ISO 2533: ρ0 = 1.225 kg/m³, a0 = 340.294 m/s, μ0 = 1.7894e-5 Pa s; ρ(1000 m) = 1.1117.
    let sl = Atmosphere::isa(0.0);
    assert!((sl.density - 1.225).abs() < 5e-4, "{}", sl.density);
    assert!(
        (sl.speed_of_sound - 340.294).abs() < 0.01,
        "{}",
        sl.speed_of_sound
    );
    assert!((sl.viscosity - 1.7894e-5).abs() < 2e-8, "{}", sl.viscosity);
    let h = Atmosphere::isa(1000.0);
    assert!((h.density - 1.1117).abs() < 5e-4, "{}", h.density);
    assert!((h.temperature - 281.65).abs() < 1e-9);
}

#[test]
fn propeller_map_reproduces_its_calibration_points() {
    let ac = mtosport();
    let map = PropellerMap::calibrate(&ac.propeller).unwrap();
    let rho = Atmosphere::isa(0.0).density;
    assert!((map.thrust(rho, 0.0, 5200.0) - 2000.0).abs() < 1e-6);
    let v = 60.0 * KT_TO_MS;
    assert!((map.thrust(rho, v, 4400.0) - 1051.0).abs() < 1e-6);
    let rpm = map.engine_rpm_for_thrust(rho, v, 1051.0).unwrap();
    assert!((rpm - 4400.0).abs() < 1e-6, "{rpm}");
    // Full throttle: the engine speeds up as the propeller unloads (static rpm standing still,
    // capped at the maximum), and the thrust falls slowly with speed (k = 1.15 > 1).
    assert!((map.full_throttle_engine_rpm(0.0) - 5200.0).abs() < 1e-9);
    let rpm_45 = map.full_throttle_engine_rpm(45.0 * KT_TO_MS);
    assert!(rpm_45 > 5400.0 && rpm_45 < 5800.0, "{rpm_45}");
    assert_eq!(map.full_throttle_engine_rpm(100.0), 5800.0);
    let t45 = map.full_throttle_thrust(rho, 45.0 * KT_TO_MS);
    assert!(t45 < 2000.0 && t45 > 1850.0, "{t45}");
    assert!(map.full_throttle_thrust(rho, 20.0) < map.full_throttle_thrust(rho, 0.0));
    // With k = 1 (torque and thrust vanishing at the same J) the torque balance keeps the
    // thrust exactly at its static value until the rpm limit.
    let ideal = PropellerMap {
        zero_torque_j: map.j0,
        ..map
    };
    for v in [5.0, 15.0, 25.0] {
        assert!(
            (ideal.full_throttle_thrust(rho, v) - 2000.0).abs() < 1e-6,
            "{v}"
        );
    }
    assert!(map.engine_rpm_for_thrust(rho, v, 5000.0).is_err());
}
