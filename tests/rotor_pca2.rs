//! The rotor model on a second rotor: the PCA-2 autogiro rotor (`aircraft/pca2.toml`) against
//! NACA Report 515's tunnel data (Table III, pitch setting 1.9°; Table II, 0.8°) and NACA
//! Report 487's flight data (Figs. 7 and 8), through `polargen::studies::pca2`. Nothing in the preset is fitted to
//! these data; the tests guard the agreement and the disagreement the report states.
//!
//! Measured (Drees inflow, the presets' default; polargen's Göttingen 429 tables, polars/):
//! * tunnel, α ≥ 4° (40 rows, μ 0.13–0.32): 7 % trip rotor rpm +7.6 %, C_L +24.3 %, L/D
//!   −5.8 %; free transition +14.2 %, +34.4 %, −1.8 %. α < 4° (41 rows, μ 0.30–0.72): trip
//!   +43.1 %, +135 %, +8.7 % — the model's rotor reaches μ ≈ 0.33 where the tunnel's reaches
//!   0.72 (a stated limitation).
//! * the same rotor with NACA Report 487's own section constants for this blade (lift slope
//!   5.85 per rad, profile drag 0.0120): α ≥ 4° rpm −1.0 %, C_L −1.1 %, L/D −11 %: the rotor
//!   model holds ±5 % on rpm and ±8 % on C_L with them; polargen's smooth
//!   section (slope 6.9 per rad, c_d 0.009–0.011 tripped) has about a third less drag per lift
//!   slope than the fabric-covered blade of 1934. At Table II's 0.8°: rpm +2.0 %, C_L +18.5 %,
//!   L/D −10.8 % with the constants, rpm +17.2 %, C_L +61 %, L/D −0.7 % with the tripped table.
//! * the blade's torsion under load (Report 487's 2.4°, proportional to the thrust; not in the
//!   preset): α ≥ 4° rpm +8.8 %, C_L +36.7 %, L/D −7.8 %.
//! * flight, μ 0.11–0.40, trimmed to the measured thrust at the flight's speed: rotor rpm
//!   −1.5 % on average (largest 3.8 %); coning a0 2.0° high (Report 487's own theory is high
//!   too); with the model's coning error taken out (μ 0.15–0.41), lateral flapping b1 with
//!   Drees inflow is within 0.3° on average where uniform inflow is 1.1° (36 %) low; a1 is
//!   within 0.5° (Drees) and 0.2° (uniform).

mod rotor_support;
mod xfoil_support;

use polargen::rotor::{InflowModel, Rotor, RotorPreset};
use polargen::studies::pca2::{
    flapping_errors, flight_comparison, report_487_section, tunnel_comparison, BandErrors,
    FlightPoint, PresetChange, TunnelComparison, TunnelTable, ALPHA_BAND_DEG, FLIGHT_PITCH_DEG,
    REPORT_487_TORSION,
};
use polargen::table::{read_lookup_table, PolarTable};
use std::path::Path;
use std::sync::OnceLock;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn preset() -> RotorPreset {
    RotorPreset::from_toml_file(&root().join("aircraft/pca2.toml")).unwrap()
}

fn table(name: &str) -> PolarTable {
    read_lookup_table(&root().join("polars").join(name)).unwrap()
}

/// The tunnel rotor: the preset as it is (pitch setting 1.9°).
fn tunnel_rotor() -> Rotor {
    Rotor::from_params(&preset().rotor)
}

/// Tunnel table `tunnel` with `rotor` and the tripped table, computed once (in `cell`) for the
/// tests.
fn tripped_once(
    cell: &'static OnceLock<TunnelComparison>,
    tunnel: TunnelTable,
    rotor: impl FnOnce() -> Rotor,
) -> &'static TunnelComparison {
    cell.get_or_init(|| tunnel_comparison(tunnel, &rotor(), &table("goe429_xtr0.07.csv")))
}

/// Table III with the tunnel rotor and the tripped table.
fn rigid_tripped() -> &'static TunnelComparison {
    static C: OnceLock<TunnelComparison> = OnceLock::new();
    tripped_once(&C, TunnelTable::III, tunnel_rotor)
}

/// Table II (pitch setting 0.8°) with the tunnel rotor at that pitch and the tripped table.
fn table_ii_tripped() -> &'static TunnelComparison {
    static C: OnceLock<TunnelComparison> = OnceLock::new();
    tripped_once(&C, TunnelTable::II, tunnel_rotor)
}

/// Table III with the tunnel rotor's blade twisting under load ([`REPORT_487_TORSION`]) and
/// the tripped table.
fn twisting_tripped() -> &'static TunnelComparison {
    static C: OnceLock<TunnelComparison> = OnceLock::new();
    tripped_once(&C, TunnelTable::III, || Rotor {
        torsion: Some(REPORT_487_TORSION),
        ..tunnel_rotor()
    })
}

/// The flight rotor: the preset at the pitch measured in flight, with `inflow`.
fn flight_rotor(inflow: InflowModel) -> Rotor {
    let mut p = preset().rotor;
    p.incidence_deg = FLIGHT_PITCH_DEG;
    Rotor {
        inflow,
        ..Rotor::from_params(&p)
    }
}

#[test]
fn preset_is_the_report_487_rotor() {
    let p = preset().rotor;
    let rotor = tunnel_rotor();
    // Solidity from the outer chord, as Report 487 computes it: 0.1038.
    let sigma = f64::from(p.blades) * p.chord_m / (std::f64::consts::PI * p.radius_m);
    assert!((sigma - 0.1038).abs() < 2e-4, "σ {sigma}");
    // Pitch at the tip: setting + 1.896° (Report 487's twist), chord steps at 0.394 R.
    let (c_in, _) = rotor.chord_and_pitch(0.3 * rotor.radius);
    let (c_out, tip) = rotor.chord_and_pitch(rotor.radius);
    assert!((c_in - 0.381).abs() < 1e-3 && (c_out - 0.5587).abs() < 1e-9);
    assert!(
        (tip.to_degrees() - 3.796).abs() < 1e-3,
        "{}",
        tip.to_degrees()
    );
}

#[test]
fn tunnel_table_iii_with_polargen_tables() {
    let tripped = rigid_tripped();
    let free = tunnel_comparison(TunnelTable::III, &tunnel_rotor(), &table("goe429_free.csv"));
    assert_eq!(tripped.rows.len(), 81);
    let (t_hi, t_lo) = (
        tripped.band(ALPHA_BAND_DEG, 90.0),
        tripped.band(-90.0, ALPHA_BAND_DEG),
    );
    let f_hi = free.band(ALPHA_BAND_DEG, 90.0);
    assert_eq!((t_hi.rows, t_lo.rows), (40, 41));
    assert_eq!(t_hi.failed + t_lo.failed + f_hi.failed, 0);
    // α ≥ 4°, 7 % trip: rpm +7.6 %, C_L +24 %, L/D −5.8 % (module documentation).
    assert!((0.045..0.105).contains(&t_hi.rotor_rpm), "{t_hi:?}");
    assert!((0.16..0.32).contains(&t_hi.cl), "{t_hi:?}");
    assert!(t_hi.lift_to_drag.abs() < 0.09, "{t_hi:?}");
    // Free transition turns the rotor faster still (+14 %).
    assert!(f_hi.rotor_rpm > t_hi.rotor_rpm + 0.04, "{f_hi:?}");
    // α < 4°: the stated limitation, the rotor far too fast (+43 %).
    assert!(t_lo.rotor_rpm > 0.25, "{t_lo:?}");
    // The README's sentence states these numbers and those of Report 487's constants.
    let (hi, hi_ii) = report_487_constants_bands();
    let tw = twisting_tripped().band(ALPHA_BAND_DEG, 90.0);
    let ii = table_ii_tripped().band(ALPHA_BAND_DEG, 90.0);
    let pct = |x: f64| format!("{:+.1} %", 100.0 * x).replace('-', "−");
    let sentence = format!(
        "At α ≥ 4° (40 of Table III's 81 rows) with our tripped Göttingen 429 table: rotor rpm \
         {}, C_L {}, L/D {}; with Report 487's own section constants: rpm {}, C_L {}, L/D {} \
         (at Table II's 0.8°: rpm {}, C_L {}, L/D {}); \
         with the blade's torsion following the load (Report 487's 2.4° at the tip, not in the \
         preset): rpm {}, C_L {}, L/D {}. At the lower pitch setting of Table II (0.8°, 90 of \
         108 rows at α ≥ 4°): rpm {}, C_L {}, L/D {} (`tests/rotor_pca2.rs`; α < 4° and the \
         flight tests in the report's section \"The rotor model on a second rotor\").\n",
        pct(t_hi.rotor_rpm),
        pct(t_hi.cl),
        pct(t_hi.lift_to_drag),
        pct(hi.rotor_rpm),
        pct(hi.cl),
        pct(hi.lift_to_drag),
        pct(hi_ii.rotor_rpm),
        pct(hi_ii.cl),
        pct(hi_ii.lift_to_drag),
        pct(tw.rotor_rpm),
        pct(tw.cl),
        pct(tw.lift_to_drag),
        pct(ii.rotor_rpm),
        pct(ii.cl),
        pct(ii.lift_to_drag),
    );
    xfoil_support::check_readme_block(
        "second rotor",
        "UPDATE_README=1 cargo test --test rotor_pca2 tunnel",
        &sentence,
    );
}

/// Measure with `cargo test --test rotor_pca2 preset_changes -- --nocapture`.
/// What the α ≥ 4° errors depend on (the report's table; tripped table, Table III), one
/// choice of the preset changed at a time (`studies::pca2::PresetChange`), measured rotor rpm /
/// C_L / L/D: uniform inflow +5.6 / +20.0 / −3.8 %, Report 487's chord tip loss +6.5 / +12.5 /
/// −5.5 %, no tip loss +7.3 / +26.4 / −5.3 %, no yawed-flow drag +8.4 / +25.7 / −0.8 %, κ = 1
/// +12.4 / +36.8 / −4.2 %, setting read at 0.75 R +5.6 / +5.7 / −4.2 %, no root cut-out
/// +7.5 / +24.4 / −8.0 %; Report 487's own modelling (uniform inflow and its chord tip loss
/// together) +4.7 / +8.9 / −3.7 %; the blade untwisted +4.6 / +2.8 / −3.0 %. No single change
/// but the untwisted blade brings the rotor speed within 5 %; the test pins that and the two
/// named rows to ±1 point.
#[test]
fn tunnel_table_iii_preset_changes() {
    let rotor = tunnel_rotor();
    let table = table("goe429_xtr0.07.csv");
    for change in PresetChange::ALL {
        let b = tunnel_comparison(TunnelTable::III, &change.apply(&rotor), &table)
            .band(ALPHA_BAND_DEG, 90.0);
        eprintln!("{change:?}: {b:?}");
        assert_eq!(b.failed, 0, "{change:?}");
        let pinned = match change {
            PresetChange::Untwisted => Some([0.046, 0.028, -0.030]),
            PresetChange::Report487Modelling => Some([0.047, 0.089, -0.037]),
            _ => None,
        };
        match pinned {
            Some(m) => {
                let got = [b.rotor_rpm, b.cl, b.lift_to_drag];
                assert!(
                    got.iter().zip(m).all(|(g, m)| (g - m).abs() < 0.01),
                    "{b:?}"
                );
            }
            None => assert!(b.rotor_rpm > 0.05, "{change:?}: {b:?}"),
        }
    }
    // The 0.75 R reading lowers the pitch by the twist there (0.647°), the untwisted blade
    // has the setting everywhere.
    let shifted = PresetChange::SettingAtThreeQuarterRadius.apply(&rotor);
    let (_, at) = shifted.planform.at(0.75);
    assert!(at.abs() < 1e-12, "{at}");
    let (_, tip) = shifted.planform.at(1.0);
    assert!(
        (tip.to_degrees() - (1.896 - 0.6468)).abs() < 1e-3,
        "{}",
        tip.to_degrees()
    );
    let flat = PresetChange::Untwisted.apply(&rotor);
    assert!(flat.planform.stations.iter().all(|s| s.twist == 0.0));
}

/// Measure with `cargo test --test rotor_pca2 torsion -- --nocapture`.
/// The blade's torsion under load as Report 487 describes it (2.4° nose-up at the tip at the
/// flights' mean thrust, proportional to the thrust; `studies::pca2::REPORT_487_TORSION`)
/// against Table III, tripped table. Nothing here sets the torsion: its size is Report 487's.
/// * α ≥ 4°: rpm +8.8 %, C_L +36.7 %, L/D −7.8 % (rigid blade: +7.6 %, +24.3 %, −5.8 %): the
///   model's rotor carries more thrust than the tunnel's, so the blade twists further nose-up
///   and the rotor turns faster still;
/// * α < 4°: rpm +57 % (rigid +43 %); the model's thrust there exceeds twice the flights',
///   where the torsion is held (`rotor::torsion::MAX_LOAD_RATIO`);
/// * how μ changes with the wind speed at one shaft angle (pairs of rows within 0.15° whose
///   rotor speeds differ by more than 25 %, `TunnelComparison::speed_trend`): measured at
///   α < 4° μ(slower) − μ(faster) = 0.039 (25 pairs), rigid blade 0.008 (the Reynolds number
///   alone), with torsion 0.019; at α ≥ 4° 0.016 measured (4 pairs), rigid 0.006, torsion
///   0.027. A load-dependent pitch is in the data; this torsion gives it the right order.
#[test]
fn tunnel_table_iii_with_blade_torsion() {
    let (rigid, twisted) = (rigid_tripped(), twisting_tripped());
    let (hi, lo) = (
        twisted.band(ALPHA_BAND_DEG, 90.0),
        twisted.band(-90.0, ALPHA_BAND_DEG),
    );
    eprintln!("torsion: α ≥ 4° {hi:?}\nα < 4° {lo:?}");
    assert_eq!(hi.failed + lo.failed, 0);
    assert!((0.06..0.12).contains(&hi.rotor_rpm), "{hi:?}");
    assert!((0.25..0.50).contains(&hi.cl), "{hi:?}");
    assert!((-0.12..-0.04).contains(&hi.lift_to_drag), "{hi:?}");
    assert!(lo.rotor_rpm > 0.45, "{lo:?}");
    let rigid_hi = rigid.band(ALPHA_BAND_DEG, 90.0);
    assert!(hi.rotor_rpm > rigid_hi.rotor_rpm && hi.cl > rigid_hi.cl);
    let trends = |c: &TunnelComparison| {
        (
            c.speed_trend(-90.0, ALPHA_BAND_DEG).unwrap(),
            c.speed_trend(ALPHA_BAND_DEG, 90.0).unwrap(),
        )
    };
    let ((r_lo, r_hi), (t_lo, t_hi)) = (trends(rigid), trends(twisted));
    eprintln!("speed trend α < 4°: rigid {r_lo:?}, torsion {t_lo:?}");
    eprintln!("speed trend α ≥ 4°: rigid {r_hi:?}, torsion {t_hi:?}");
    assert_eq!((r_lo.pairs, r_hi.pairs), (25, 4));
    assert!((0.03..0.05).contains(&r_lo.measured), "{r_lo:?}");
    assert!((0.01..0.02).contains(&r_hi.measured), "{r_hi:?}");
    // The rigid blade shows a fifth of the measured trend, the twisting blade about half of it
    // at α < 4° and 1.7 times it at α ≥ 4°.
    assert!(r_lo.predicted < 0.3 * r_lo.measured, "{r_lo:?}");
    assert!(r_hi.predicted < 0.5 * r_hi.measured, "{r_hi:?}");
    assert!(
        (0.3..0.8).contains(&(t_lo.predicted / t_lo.measured)),
        "{t_lo:?}"
    );
    assert!(
        (1.2..2.4).contains(&(t_hi.predicted / t_hi.measured)),
        "{t_hi:?}"
    );
}

/// The torsion's pitch change vanishes at its reference thrust: a rotor whose torsion is
/// referred to the thrust the rigid rotor carries gives the rigid rotor's solution.
#[test]
fn torsion_at_its_reference_thrust_changes_nothing() {
    use polargen::rotor::{Atmosphere, ElasticTorsion, FlightCondition};
    let section = table("goe429_xtr0.07.csv");
    let rigid = tunnel_rotor();
    let cond = FlightCondition {
        airspeed: 25.0,
        hub_aoa: 6f64.to_radians(),
        omega: 130f64.to_radians() * 6.0,
        atmosphere: Atmosphere::isa(0.0),
    };
    let a = rigid.solve(&section, &cond, &mut None).unwrap();
    let twisting = Rotor {
        torsion: Some(ElasticTorsion {
            reference_thrust: a.thrust,
            ..REPORT_487_TORSION
        }),
        ..rigid.clone()
    };
    let b = twisting.solve(&section, &cond, &mut None).unwrap();
    assert!(
        (b.thrust / a.thrust - 1.0).abs() < 1e-6,
        "{} {}",
        a.thrust,
        b.thrust
    );
    assert!((b.torque - a.torque).abs() < 1e-6 * a.thrust * rigid.radius);
    // Referred to half that thrust, the blade twists further nose-up: more thrust.
    let stiffer = Rotor {
        torsion: Some(ElasticTorsion {
            reference_thrust: 0.5 * a.thrust,
            ..REPORT_487_TORSION
        }),
        ..rigid
    };
    let c = stiffer.solve(&section, &cond, &mut None).unwrap();
    assert!(c.thrust > 1.05 * a.thrust, "{} {}", a.thrust, c.thrust);
}

/// A twisting blade solved from rest converges, to the root a solution carried down from a
/// faster rotor reaches: in the tunnel at α 8.3°, 15.8 m/s (a Table III row) the iteration
/// from rest alone cycled across the torsion's load limit between 300 and 452 rpm (step
/// 0.1–0.3 after 40 iterations); it now starts from the rigid blade's solution and meets the
/// carried-down root to 1e-8 in thrust, measured (3e-8 asserted; the Newton tolerance's reach).
#[test]
fn twisting_blade_solves_from_rest() {
    use polargen::rotor::{Atmosphere, FlightCondition};
    let section = table("goe429_xtr0.07.csv");
    let twisting = Rotor {
        torsion: Some(REPORT_487_TORSION),
        ..tunnel_rotor()
    };
    let cond = |rpm: f64| FlightCondition {
        airspeed: 15.755,
        hub_aoa: 8.3f64.to_radians(),
        omega: rpm.to_radians() * 6.0,
        atmosphere: Atmosphere::isa(0.0),
    };
    // Carried down from 900 rpm in steps of 50 rpm, each solve warm-started by the last.
    let mut warm = None;
    let mut carried = Vec::new();
    for rpm in (6..=18).rev().map(|k| 50.0 * f64::from(k)) {
        carried.push((
            rpm,
            twisting.solve(&section, &cond(rpm), &mut warm).unwrap(),
        ));
    }
    for (rpm, c) in carried
        .iter()
        .filter(|(rpm, _)| (300.0..=450.0).contains(rpm))
    {
        let cold = twisting.solve(&section, &cond(*rpm), &mut None).unwrap();
        assert!(
            (cold.thrust / c.thrust - 1.0).abs() < 3e-8
                && (cold.torque - c.torque).abs() < 4e-10 * c.thrust * twisting.radius,
            "{rpm} rpm: from rest {} N, carried down {} N",
            cold.thrust,
            c.thrust
        );
    }
}

/// Measure with `cargo test --test rotor_pca2 table_ii -- --nocapture`.
/// NACA Report 515's Table II (pitch setting 0.8°, 108 rows; data the model was not built
/// from) with the tripped table, the preset at that pitch:
/// * α ≥ 4° (90 rows): rotor rpm +17.2 %, C_L +61 %, L/D −0.7 %; α < 4° (18 rows): rpm +66 %;
/// * against Table III (pitch 1.9°, α ≥ 4°: +7.6 %, +24 %, −5.8 %) the rpm error grows by 10
///   points as the pitch falls: the tunnel's rotor slowed more than the model's when the pitch
///   was lowered.
#[test]
fn tunnel_table_ii_at_the_lower_pitch() {
    let c = tunnel_comparison(
        TunnelTable::II,
        &tunnel_rotor(),
        &table("goe429_xtr0.07.csv"),
    );
    assert_eq!(c.rows.len(), 108);
    let (hi, lo) = (c.band(ALPHA_BAND_DEG, 90.0), c.band(-90.0, ALPHA_BAND_DEG));
    eprintln!("Table II: α ≥ 4° {hi:?}\nα < 4° {lo:?}");
    assert_eq!((hi.rows, lo.rows, hi.failed + lo.failed), (90, 18, 0));
    assert!((0.12..0.22).contains(&hi.rotor_rpm), "{hi:?}");
    assert!((0.45..0.80).contains(&hi.cl), "{hi:?}");
    assert!(hi.lift_to_drag.abs() < 0.05, "{hi:?}");
    assert!(lo.rotor_rpm > 0.45, "{lo:?}");
    let iii = rigid_tripped().band(ALPHA_BAND_DEG, 90.0);
    assert!(hi.rotor_rpm > iii.rotor_rpm + 0.05, "{hi:?} {iii:?}");
}

/// A preset's `[rotor.blade.torsion]` table: read into the rotor model, its values checked.
#[test]
fn preset_torsion_table() {
    let text = std::fs::read_to_string(root().join("aircraft/pca2.toml")).unwrap();
    let with = |table: &str| format!("{text}\n[rotor.blade.torsion]\n{table}\n");
    let p = RotorPreset::from_toml_str(
        &with("tip_deg = 2.4\nreference_thrust_n = 10640.0\nfrom_r_over_r = 0.394"),
        "t",
    )
    .unwrap();
    let t = Rotor::from_params(&p.rotor).torsion.unwrap();
    assert!((t.tip - REPORT_487_TORSION.tip).abs() < 1e-4, "{t:?}");
    assert_eq!((t.reference_thrust, t.from_r_over_r), (10_640.0, 0.394));
    assert!(
        tunnel_rotor().torsion.is_none(),
        "the preset leaves the torsion out"
    );
    for (table, message) in [
        (
            "tip_deg = 2.4\nreference_thrust_n = 0.0\nfrom_r_over_r = 0.394",
            "rotor.blade.torsion.reference_thrust_n",
        ),
        (
            "tip_deg = 25.0\nreference_thrust_n = 1.0\nfrom_r_over_r = 0.394",
            "rotor.blade.torsion.tip_deg",
        ),
        (
            "tip_deg = 2.4\nreference_thrust_n = 1.0\nfrom_r_over_r = 1.0",
            "rotor.blade.torsion.from_r_over_r",
        ),
        ("tip_deg = 2.4\nreference_thrust_n = 1.0", "from_r_over_r"),
    ] {
        let e = RotorPreset::from_toml_str(&with(table), "t")
            .unwrap_err()
            .to_string();
        assert!(e.contains(message) && !e.contains('\n'), "{e}");
    }
}

/// Tables III and II at α ≥ 4° with the blade section of Report 487's own constants, checked;
/// the two bands (Table III, Table II).
fn report_487_constants_bands() -> (BandErrors, BandErrors) {
    // Report 487 p. 13: lift slope 5.85 per rad, profile drag 0.0120 for this blade, as the
    // report's table of them (`studies::pca2::report_487_section`).
    let section = report_487_section().unwrap();
    let [iii, ii] = [TunnelTable::III, TunnelTable::II].map(|t| {
        let hi = tunnel_comparison(t, &tunnel_rotor(), &section).band(ALPHA_BAND_DEG, 90.0);
        assert_eq!(hi.failed, 0);
        hi
    });
    // Within ±5 % and ±8 % with the blade's own constants at 1.9°: rpm −1.0 %, C_L −1.1 %.
    assert!(iii.rotor_rpm.abs() < 0.05, "{iii:?}");
    assert!(iii.cl.abs() < 0.08, "{iii:?}");
    // A constant drag coefficient is too high at the rotor's low c_l: L/D −11 %.
    assert!((-0.2..-0.04).contains(&iii.lift_to_drag), "{iii:?}");
    // At 0.8° the rotor speed still holds (+2.0 %), C_L +18.5 %, L/D −10.8 %: with a constant
    // drag coefficient the rotor speed follows the pitch as the tunnel's did.
    assert!(ii.rotor_rpm.abs() < 0.05, "{ii:?}");
    assert!((0.10..0.28).contains(&ii.cl), "{ii:?}");
    assert!((-0.2..-0.04).contains(&ii.lift_to_drag), "{ii:?}");
    (iii, ii)
}

#[test]
fn flight_report_487_rotor_speed_and_flapping() {
    let section = table("goe429_xtr0.07.csv");
    let trims = |inflow| -> Vec<FlightPoint> {
        flight_comparison(&flight_rotor(inflow), &section)
            .into_iter()
            .filter_map(Result::ok)
            .collect()
    };
    let (drees, uniform) = (trims(InflowModel::Drees), trims(InflowModel::Glauert));
    let low: Vec<&FlightPoint> = drees.iter().filter(|p| p.mu_measured <= 0.41).collect();
    assert!(low.len() >= 8, "{} trims at μ ≤ 0.4", low.len());
    // Rotor speed at the measured load and speed: −1.5 % on average, at most 3.8 % off.
    let errors: Vec<f64> = low
        .iter()
        .map(|p| p.rotor_rpm / p.rpm_measured - 1.0)
        .collect();
    let mean = errors.iter().sum::<f64>() / errors.len() as f64;
    let worst = errors.iter().fold(0.0_f64, |a, e| a.max(e.abs()));
    assert!(mean.abs() < 0.04 && worst < 0.07, "{errors:?}");
    let range = (0.15, 0.41);
    let (d, u) = (
        flapping_errors(&drees, range),
        flapping_errors(&uniform, range),
    );
    // Coning 2.0° too high with either inflow (Report 487's theory is high too).
    assert!((1.0..3.5).contains(&d.a0.mean), "{d:?}");
    // Lateral flapping, coning error taken out: Drees within 0.3° on average (measured 0.30),
    // uniform inflow 1.1° (36 %) low. The evidence for the presets' inflow.
    assert!(d.b1_coning_corrected.points >= 7, "{d:?}");
    assert!(d.b1_coning_corrected.mean_abs < 0.6, "{d:?}");
    assert!(u.b1_coning_corrected.mean < -0.8, "{u:?}");
    assert!(u.b1_coning_corrected.mean_relative < -0.25, "{u:?}");
    // Longitudinal flapping within 0.5° (Drees) and 0.2° (uniform).
    assert!(d.a1.mean_abs < 0.8 && u.a1.mean_abs < 0.8, "{d:?} {u:?}");
}
