//! One rotor model, the hub as data: blades on flapping hinges against the classical coning of
//! an articulated rotor in hover, and against the teetering rotor with the same coning.

mod rotor_support;

use polargen::rotor::{
    rpm_to_rad_s, Atmosphere, FlapHinge, FlightCondition, Hub, InflowModel, Planform, Rotor,
    RotorPreset, TipLoss, YawedFlow,
};
use rotor_support::AnalyticSection;
use std::path::Path;

/// The PCA-2 rotor of the preset (four blades on flapping hinges at the shaft).
fn pca2() -> Rotor {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("aircraft/pca2.toml");
    Rotor::from_params(&RotorPreset::from_toml_file(&path).unwrap().rotor)
}

/// A linear section without drag below stall: c_l = 2π sin α.
fn linear() -> AnalyticSection {
    AnalyticSection {
        a0: std::f64::consts::TAU,
        alpha0_deg: 0.0,
        cd0: 0.0,
        k: 0.0,
        stall_deg: 30.0,
        blend_deg: 1.0,
    }
}

#[test]
fn hover_coning_is_the_lock_number_relation() {
    // Untwisted constant-chord blades hinged at the shaft, no tip loss, no weight, ideal
    // momentum theory: β0 = (γ/8)(θ − (4/3)λ_i), γ = ρ a c R⁴/I_β, λ_i = v0/(ΩR) (Leishman,
    // Principles of Helicopter Aerodynamics, 2nd ed., §4.8; Johnson, Helicopter Theory, §5.4).
    let base = pca2();
    let hinge = FlapHinge {
        offset: 0.0,
        inertia: 452.8,
        mass_moment: 0.0,
    };
    let rotor = Rotor {
        planform: Planform::default(),
        root_cutout: 0.001 * base.radius,
        hub: Hub::Articulated(hinge),
        tip_loss: TipLoss::NoLoss,
        yawed_flow: YawedFlow::Ignored,
        inflow: InflowModel::Glauert,
        induced_power_factor: 1.0,
        radial_strips: 100,
        ..base
    };
    let atm = Atmosphere::isa(0.0);
    let cond = FlightCondition {
        airspeed: 0.0,
        hub_aoa: 0.0,
        omega: rpm_to_rad_s(140.0),
        atmosphere: atm,
    };
    let s = rotor.solve(&linear(), &cond, &mut None).unwrap();
    let gamma =
        atm.density * std::f64::consts::TAU * rotor.chord * rotor.radius.powi(4) / hinge.inertia;
    let expected = gamma / 8.0 * (rotor.pitch + 4.0 / 3.0 * s.inflow_ratio);
    let beta0 = s.flapping.beta0;
    // Measured: 0.1 % (the strip sum and the small-angle terms of the relation).
    assert!(
        (beta0 / expected - 1.0).abs() < 3e-3,
        "β0 {beta0} vs {expected} (γ {gamma})"
    );
    // No first harmonics in hover.
    assert!(s.flapping.amplitude() < 1e-8, "{:?}", s.flapping);
}

#[test]
fn hinged_blades_at_the_shaft_flap_as_a_teetering_pair_with_their_coning() {
    // Blades hinged on the shaft flap at 1/rev like a teeter bolt: their first harmonics make
    // the first harmonics of the aerodynamic flap moment vanish, whatever the inertia. So the
    // teetering rotor with a hub-bar coning equal to the hinged blades' free coning has the
    // same state and loads.
    let hinged = Rotor {
        blades: 2,
        ..pca2()
    };
    let section = AnalyticSection::contaminated();
    let cond = FlightCondition {
        airspeed: 30.0,
        hub_aoa: 6f64.to_radians(),
        omega: rpm_to_rad_s(140.0),
        atmosphere: Atmosphere::isa(0.0),
    };
    let a = hinged.solve(&section, &cond, &mut None).unwrap();
    let teetering = Rotor {
        hub: Hub::Teetering {
            precone: a.flapping.beta0,
        },
        ..hinged
    };
    let b = teetering.solve(&section, &cond, &mut None).unwrap();
    let tip = cond.omega * hinged.radius;
    assert!((a.induced_velocity - b.induced_velocity).abs() / tip < 1e-8);
    for (x, y) in [
        (a.flapping.beta1c, b.flapping.beta1c),
        (a.flapping.beta1s, b.flapping.beta1s),
    ] {
        assert!((x - y).abs() < 1e-8, "{x} vs {y}");
    }
    for (x, y) in [(a.thrust, b.thrust), (a.drag, b.drag), (a.torque, b.torque)] {
        assert!((x - y).abs() < 1e-6 * (1.0 + y.abs()), "{x} vs {y}");
    }
    // The coning is free: several degrees here, not the preset's or zero.
    assert!(a.flapping.beta0.to_degrees() > 3.0, "{:?}", a.flapping);
}

#[test]
fn a_hinge_offset_stiffens_the_flapping() {
    // ν² = 1 + e S_β/I_β > 1: the coning falls (ν² I_β Ω² β0 = M_0 − M_W) and the 1/rev
    // flapping no longer makes the moment's first harmonics vanish, so the tilt changes.
    let base = pca2();
    let Hub::Articulated(hinge) = base.hub else {
        panic!("the PCA-2 preset is articulated")
    };
    let section = AnalyticSection::contaminated();
    let cond = FlightCondition {
        airspeed: 30.0,
        hub_aoa: 6f64.to_radians(),
        omega: rpm_to_rad_s(140.0),
        atmosphere: Atmosphere::isa(0.0),
    };
    let central = base.solve(&section, &cond, &mut None).unwrap();
    let offset = Rotor {
        hub: Hub::Articulated(FlapHinge {
            offset: 0.3,
            mass_moment: hinge.mass_moment - 0.3 * 26.76,
            ..hinge
        }),
        ..base
    };
    let stiff = offset.solve(&section, &cond, &mut None).unwrap();
    assert!(stiff.flapping.beta0 < central.flapping.beta0);
    let tilt = |f: &polargen::rotor::Flapping| f.beta1s.atan2(f.beta1c);
    assert!(
        (tilt(&stiff.flapping) - tilt(&central.flapping)).abs() > 1e-3,
        "{:?} {:?}",
        stiff.flapping,
        central.flapping
    );
}

/// The result carries no solver memory: the same condition solved cold and warm-started from
/// two different neighbours gives the same rotor state, to the Newton tolerance, and the warm
/// state is the only thing a solve hands on (`RotorWarmStart`, opaque).
#[test]
fn a_solution_does_not_depend_on_the_path_that_reached_it() {
    let rotor = pca2();
    let cond = |kt: f64, aoa_deg: f64| FlightCondition {
        airspeed: kt * 0.514_444,
        hub_aoa: aoa_deg.to_radians(),
        omega: rpm_to_rad_s(120.0),
        atmosphere: Atmosphere::isa(0.0),
    };
    let section = linear();
    let target = cond(60.0, 8.0);
    let cold = rotor.solve(&section, &target, &mut None).unwrap();
    let mut paths = Vec::new();
    for (kt, aoa) in [(40.0, 12.0), (80.0, 4.0)] {
        let mut warm = None;
        rotor.solve(&section, &cond(kt, aoa), &mut warm).unwrap();
        assert!(warm.is_some());
        paths.push(rotor.solve(&section, &target, &mut warm).unwrap());
    }
    for s in &paths {
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-7 * (1.0 + a.abs().max(b.abs()));
        assert!(close(s.thrust, cold.thrust), "{} {}", s.thrust, cold.thrust);
        assert!(close(s.torque, cold.torque), "{} {}", s.torque, cold.torque);
        assert!(close(s.induced_velocity, cold.induced_velocity));
        assert!(close(s.flapping.beta0, cold.flapping.beta0));
        assert!(close(s.flapping.beta1c, cold.flapping.beta1c));
        assert!(close(s.flapping.beta1s, cold.flapping.beta1s));
        assert_eq!(s.condition, cold.condition);
    }
}
