//! The fixed wing of the aircraft model: a zero-area wing and a wing without lift or drag are
//! no wing, the rotor unloads as the wing grows, the loads against a hand calculation, the
//! lifting line on a section table, and the `[wing]` checks.

mod rotor_support;

use polargen::rotor::{
    simulate_takeoff, trim_aircraft, Aircraft, AircraftError, Atmosphere, TrimError, TrimParams,
    TrimResult, KT_TO_MS,
};
use polargen::section::SectionAero;
use polargen::table::read_lookup_table;
use rotor_support::AnalyticSection;
use std::path::Path;

fn preset_path() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("aircraft/mtosport.toml")
        .display()
        .to_string()
}

/// The shipped preset with its `[wing]` table replaced by `wing` (empty: no `[wing]`).
fn with_wing(wing: &str) -> Result<Aircraft, AircraftError> {
    let text = std::fs::read_to_string(preset_path()).unwrap();
    let start = text.find("[wing]\n").expect("the preset has a [wing]");
    let end = text.find("[takeoff]\n").unwrap();
    let text = format!("{}{wing}\n{}", &text[..start], &text[end..]);
    Aircraft::from_toml_str(&text, &preset_path())
}

/// A wing with a linear section: a0 = 2π/rad, α0 = −2°, incidence 4°, b = 4 m, e = 0.8,
/// c_d0 = 0.01, of `area` m².
fn linear_wing(area: f64) -> String {
    format!(
        "[wing]\narea_m2 = {area:?}\nspan_m = 4.0\nincidence_deg = 4.0\noswald_e = 0.8\n\
         lift_slope_per_rad = 6.283185307179586\nalpha_zero_lift_deg = -2.0\ncd0 = 0.01\n"
    )
}

fn trim(ac: &Aircraft, speed_kt: f64) -> Result<TrimResult, TrimError> {
    trim_aircraft(
        ac,
        &AnalyticSection::clean(),
        speed_kt,
        ac.mass_kg,
        0.0,
        &TrimParams::default(),
    )
}

#[test]
fn zero_area_is_no_wing_exactly() {
    let none = with_wing("").unwrap();
    assert!(none.wing.is_none() && !none.has_wing());
    // The shipped preset carries a wing of zero area (the shape the wing study scales), with
    // a section table; a linear wing of zero area is no wing either.
    let zero = Aircraft::from_toml_file(Path::new(&preset_path())).unwrap();
    assert_eq!(zero.wing.as_ref().unwrap().area_m2, 0.0);
    assert!(!zero.has_wing());
    for speed in [45.0, 60.0] {
        let t = trim(&none, speed).unwrap();
        assert!(t.wing.is_none());
        assert_eq!(trim(&zero, speed).unwrap(), t, "{speed} kt");
        let linear_zero = with_wing(&linear_wing(0.0)).unwrap();
        assert_eq!(trim(&linear_zero, speed).unwrap(), t, "{speed} kt");
        assert_eq!(t.rotor_lift_share(), 1.0);
    }
}

#[test]
fn wing_without_lift_or_drag_is_no_wing() {
    let none = trim(&with_wing("").unwrap(), 60.0).unwrap();
    let wing = linear_wing(1.7)
        .replace("6.283185307179586", "0.0")
        .replace("cd0 = 0.01", "cd0 = 0.0");
    let mut t = trim(&with_wing(&wing).unwrap(), 60.0).unwrap();
    let loads = t.wing.take().expect("a wing of non-zero area is reported");
    assert_eq!((loads.lift_n, loads.drag_n), (0.0, 0.0));
    assert_eq!(t, none);
}

#[test]
fn linear_wing_loads_match_a_hand_calculation() {
    // Hand calculation (sea-level ISA, ρ = 1.225 kg/m³, 60 kt = 30.8667 m/s):
    //   AR = b²/S = 16/1.7 = 9.41176; π e AR = π·0.8·9.41176 = 23.6543
    //   wing slope a = 2π/(1 + 2π/23.6543) = 4.96449 /rad
    //   C_L = a·(4° + 2°) = 4.96449·0.104720 = 0.519880
    //   C_Di = C_L²/(π e AR) = 0.270275/23.6543 = 0.0114260; C_D = 0.0214260
    //   q = ½ρV² = 583.560 Pa; L_W = q S C_L = 515.75 N; D_W = q S C_D = 21.256 N
    //   G = 450·9.80665 = 4412.99 N; the rotor lifts 1 − 515.75/4412.99 = 88.313 %.
    let ac = with_wing(&linear_wing(1.7)).unwrap();
    let w = ac
        .wing_loads(&Atmosphere::isa(0.0), 60.0 * KT_TO_MS)
        .unwrap();
    assert!((w.lift_coefficient - 0.519880).abs() < 1e-6, "{w:?}");
    assert!(
        (w.induced_drag_coefficient - 0.0114260).abs() < 1e-7,
        "{w:?}"
    );
    assert!((w.lift_n - 515.75).abs() < 0.01, "{w:?}");
    assert!((w.drag_n - 21.256).abs() < 0.001, "{w:?}");
    assert!(!w.stalled && !w.table_clamped);
    let t = trim(&ac, 60.0).unwrap();
    assert!(
        (t.rotor_lift_share() - 0.88313).abs() < 1e-4,
        "{}",
        t.rotor_lift_share()
    );
    // Rotor lift + wing lift = weight (the rotor's to the trim tolerance); F_prop adds D_W.
    let weight = ac.weight_n();
    assert!((t.rotor_lift_n + w.lift_n - weight).abs() < 1e-3 * weight);
    assert!((t.prop_thrust_n - (t.rotor_drag_n + t.parasitic_drag_n + w.drag_n)).abs() < 1e-9);
    // A cl_max below the unlimited C_L caps it and says so.
    let capped = with_wing(&(linear_wing(1.7) + "cl_max = 0.4\n")).unwrap();
    let c = capped
        .wing_loads(&Atmosphere::isa(0.0), 60.0 * KT_TO_MS)
        .unwrap();
    assert!(c.stalled && c.lift_coefficient == 0.4, "{c:?}");
    let t = trim(&capped, 60.0).unwrap();
    assert!(t.notes().iter().any(|n| n.contains("linear range")));
}

#[test]
fn rotor_unloads_as_the_wing_grows() {
    let mut last: Option<TrimResult> = None;
    for area in [0.0, 1.0, 1.7, 2.5] {
        let t = trim(&with_wing(&linear_wing(area)).unwrap(), 60.0).unwrap();
        if let Some(p) = &last {
            assert!(
                t.rotor_lift_share() < p.rotor_lift_share() - 0.02,
                "{area} m²: share {} after {}",
                t.rotor_lift_share(),
                p.rotor_lift_share()
            );
            // The unloaded rotor turns slower and makes less drag.
            assert!(t.rotor_rpm < p.rotor_rpm, "{area} m²");
            assert!(t.rotor_drag_n < p.rotor_drag_n, "{area} m²");
        }
        last = Some(t);
    }
}

#[test]
fn table_wing_solves_the_lifting_line() {
    // The shipped wing (polargen's NACA 23012 table) at 1.7 m² and 60 kt: the C_L found
    // satisfies C_L = c_l(α − C_L/(π e AR)) at the wing's Re and M, and C_D is the section's
    // profile drag there plus C_L²/(π e AR).
    let ac = Aircraft::from_toml_file(Path::new(&preset_path()))
        .unwrap()
        .with_wing_area(1.7)
        .unwrap();
    let wing = ac.wing.clone().unwrap();
    let atm = Atmosphere::isa(0.0);
    let v = 60.0 * KT_TO_MS;
    let w = ac.wing_loads(&atm, v).unwrap();
    let table_path = Path::new(&preset_path())
        .parent()
        .unwrap()
        .join(wing.section_table.as_ref().unwrap());
    let table = read_lookup_table(&table_path).unwrap();
    let k = std::f64::consts::PI * wing.oswald_e * wing.aspect_ratio();
    let chord = wing.area_m2 / wing.span_m;
    let re = atm.density * v * chord / atm.viscosity;
    let alpha_eff = wing.incidence_deg - (w.lift_coefficient / k).to_degrees();
    let l = table.lookup(alpha_eff, re, v / atm.speed_of_sound);
    assert!((l.cl - w.lift_coefficient).abs() < 1e-8, "{w:?} vs {l:?}");
    let q_s = atm.dynamic_pressure(v) * wing.area_m2;
    let cd = l.cd + w.lift_coefficient.powi(2) / k;
    assert!((w.drag_n - q_s * cd).abs() < 1e-9 * w.drag_n);
    // The section's lift at 2-3° (c_l 0.33-0.45 in the table near Re 1e6) and an induced
    // angle of about 1°: C_L between 0.3 and 0.5 at the 3.5° incidence.
    assert!((0.3..0.5).contains(&w.lift_coefficient), "{w:?}");
}

#[test]
fn wing_that_lifts_the_weight_is_no_trim() {
    // 8 m², AR 2, 10° incidence: C_L = 2.79·0.209 = 0.58, L_W = 1313 Pa·8 m²·0.58 ≈ 6100 N > G.
    let wing = linear_wing(8.0).replace("incidence_deg = 4.0", "incidence_deg = 10.0");
    let ac = with_wing(&wing).unwrap();
    let err = trim(&ac, 90.0).unwrap_err();
    assert!(matches!(err, TrimError::WingCarriesWeight { .. }), "{err}");
    assert!(err.to_string().contains("wing lifts"), "{err}");
}

#[test]
fn bad_wings_get_one_line_errors() {
    let field = |wing: String, field: &str| {
        let err = with_wing(&wing).unwrap_err();
        let msg = err.to_string();
        assert!(
            matches!(&err, AircraftError::Invalid { field: f, .. } if *f == field),
            "{wing}: {msg}"
        );
        assert!(msg.contains(field) && !msg.contains('\n'), "{msg}");
    };
    let base = linear_wing(1.7);
    field(base.replace("span_m = 4.0", "span_m = 0.0"), "wing.span_m");
    field(base.replace("span_m = 4.0", "span_m = -4.0"), "wing.span_m");
    field(base.replace("span_m = 4.0", "span_m = nan"), "wing.span_m");
    field(
        base.replace("area_m2 = 1.7", "area_m2 = -1.0"),
        "wing.area_m2",
    );
    field(
        base.replace("area_m2 = 1.7", "area_m2 = nan"),
        "wing.area_m2",
    );
    field(
        base.replace("oswald_e = 0.8", "oswald_e = 0.0"),
        "wing.oswald_e",
    );
    field(
        base.replace("oswald_e = 0.8", "oswald_e = 1.2"),
        "wing.oswald_e",
    );
    field(
        base.replace("oswald_e = 0.8", "oswald_e = nan"),
        "wing.oswald_e",
    );
    field(base.replace("cd0 = 0.01", "cd0 = -0.01"), "wing.cd0");
    field(
        base.replace("incidence_deg = 4.0", "incidence_deg = inf"),
        "wing.incidence_deg",
    );
    field(
        base.replace("6.283185307179586", "nan"),
        "wing.lift_slope_per_rad",
    );
    field(base.clone() + "cl_max = 0.0\n", "wing.cl_max");
    // One section model, complete.
    for wing in [
        base.clone() + "section_table = \"../polars/naca23012_free.csv\"\n",
        base.replace("cd0 = 0.01\n", ""),
        base.replace("alpha_zero_lift_deg = -2.0\n", ""),
    ] {
        let err = with_wing(&wing).unwrap_err();
        assert!(matches!(err, AircraftError::WingModel(_)), "{wing}: {err}");
        assert!(!err.to_string().contains('\n'));
    }
    // A missing wing table is named.
    let wing = "[wing]\narea_m2 = 1.0\nspan_m = 4.0\nincidence_deg = 3.0\noswald_e = 0.8\n\
                section_table = \"missing.csv\"\n";
    let err = with_wing(wing).unwrap_err();
    assert!(
        matches!(err, AircraftError::WingSection { .. }) && err.to_string().contains("wing"),
        "{err}"
    );
    // Scaling needs a [wing] and a non-negative area.
    let none = with_wing("").unwrap();
    assert!(matches!(
        none.with_wing_area(1.0),
        Err(AircraftError::WingModel(_))
    ));
    let ac = with_wing(&base).unwrap();
    assert!(ac.with_wing_area(-1.0).is_err());
    assert!(ac.with_wing_area(0.0).is_ok_and(|a| !a.has_wing()));
}

#[test]
fn takeoff_with_a_zero_area_wing_is_unchanged_and_a_wing_lifts_off_sooner() {
    let section = AnalyticSection::clean();
    let none = simulate_takeoff(&with_wing("").unwrap(), &section).unwrap();
    let zero = simulate_takeoff(&with_wing(&linear_wing(0.0)).unwrap(), &section).unwrap();
    assert_eq!(zero, none);
    // 1.7 m² at its 4° incidence (fuselage level on the ground roll) lifts ≈ 230 N at 40 kt
    // (q = 259 Pa, C_L 0.52: the same hand calculation as above), which the rotor need not.
    let wing = simulate_takeoff(&with_wing(&linear_wing(1.7)).unwrap(), &section).unwrap();
    assert!(
        wing.takeoff_roll_m < none.takeoff_roll_m && wing.liftoff_speed_kt < none.liftoff_speed_kt,
        "wing: {} m at {} kt; none: {} m at {} kt",
        wing.takeoff_roll_m,
        wing.liftoff_speed_kt,
        none.takeoff_roll_m,
        none.liftoff_speed_kt
    );
}
