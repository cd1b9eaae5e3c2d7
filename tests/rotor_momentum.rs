//! The coupled rotor solution honours momentum theory in its limits.

mod rotor_support;

use polargen::rotor::{rpm_to_rad_s, Atmosphere, FlightCondition, InflowModel, Rotor};
use rotor_support::{mtosport, AnalyticSection};

#[test]
fn hover_inflow_matches_actuator_disc() {
    let r = Rotor::from_params(&mtosport().rotor);
    let atm = Atmosphere::isa(0.0);
    let cond = FlightCondition {
        airspeed: 0.0,
        hub_aoa: 0.0,
        omega: rpm_to_rad_s(350.0),
        atmosphere: atm,
    };
    let s = r
        .solve(&AnalyticSection::clean(), &cond, &mut None)
        .unwrap();
    assert!(s.thrust > 500.0, "thrust {}", s.thrust);
    // Actuator disc v_h = √(T/2ρA), scaled by the preset's induced-power factor κ.
    assert!(r.induced_power_factor > 1.0);
    let vh = r.induced_power_factor * (s.thrust / (2.0 * atm.density * r.disc_area())).sqrt();
    assert!(
        (s.induced_velocity / vh - 1.0).abs() < 1e-6,
        "{} vs {vh}",
        s.induced_velocity
    );
    // Axisymmetric hover: no flapping, no in-plane force, and the rotor needs driving torque.
    assert!(s.flapping.amplitude() < 1e-8, "{:?}", s.flapping);
    assert!(s.h_force.abs() < 1e-6 * s.thrust && s.side_force.abs() < 1e-6 * s.thrust);
    assert!(s.torque < 0.0);
}

#[test]
fn high_speed_inflow_tends_to_t_over_2_rho_a_v() {
    let mut r = Rotor::from_params(&mtosport().rotor);
    let atm = Atmosphere::isa(0.0);
    for model in [InflowModel::Glauert, InflowModel::Drees] {
        r.inflow = model;
        let v = 60.0;
        let cond = FlightCondition {
            airspeed: v,
            hub_aoa: 2f64.to_radians(),
            omega: rpm_to_rad_s(380.0),
            atmosphere: atm,
        };
        let s = r
            .solve(&AnalyticSection::clean(), &cond, &mut None)
            .unwrap();
        let expected = r.induced_power_factor * s.thrust / (2.0 * atm.density * r.disc_area() * v);
        assert!(
            (s.induced_velocity / expected - 1.0).abs() < 0.01,
            "{model:?}: {} vs {expected}",
            s.induced_velocity
        );
        // Wind-axis forces are the hub forces rotated by α_H.
        let a = cond.hub_aoa;
        assert!((s.lift - (s.thrust * a.cos() - s.h_force * a.sin())).abs() < 1e-9 * s.thrust);
        assert!((s.drag - (s.thrust * a.sin() + s.h_force * a.cos())).abs() < 1e-9 * s.thrust);
    }
}

#[test]
fn induced_power_factor_scales_the_induced_power() {
    // Same operating point with κ = 1 (ideal momentum theory) and κ = 1.15: the induced
    // velocity is κ times the ideal one (for the thrust each solution carries), so the induced
    // power T·v grows by about κ; the extra loss is taken from the autorotative (driving)
    // torque at fixed disc angle and rpm.
    let mut ideal = Rotor::from_params(&mtosport().rotor);
    ideal.induced_power_factor = 1.0;
    let mut real = ideal.clone();
    real.induced_power_factor = 1.15;
    let atm = Atmosphere::isa(0.0);
    let v = 30.9;
    let cond = FlightCondition {
        airspeed: v,
        hub_aoa: 5f64.to_radians(),
        omega: rpm_to_rad_s(360.0),
        atmosphere: atm,
    };
    let section = AnalyticSection::clean();
    let a = ideal.solve(&section, &cond, &mut None).unwrap();
    let b = real.solve(&section, &cond, &mut None).unwrap();
    // Glauert's momentum theory, T = 2ρA·v·V′ with V′ = √((V cos α)² + (V sin α − v)²), solved
    // for the induced velocity v by bisection (a reference independent of the library's).
    let ideal_of = |s: &polargen::rotor::RotorSolution| {
        let (edge, axial) = (v * cond.hub_aoa.cos(), v * cond.hub_aoa.sin());
        let g = |w: f64| {
            2.0 * atm.density * ideal.disc_area() * w * (edge * edge + (axial - w).powi(2)).sqrt()
                - s.thrust
        };
        let (mut lo, mut hi) = (0.0, 50.0);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if g(mid) < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    assert!((a.induced_velocity / ideal_of(&a) - 1.0).abs() < 1e-6);
    assert!((b.induced_velocity / ideal_of(&b) - 1.15).abs() < 1e-6);
    let ratio = (b.thrust * b.induced_velocity) / (a.thrust * a.induced_velocity);
    assert!((ratio - 1.15).abs() < 0.05, "induced power ratio {ratio}");
    assert!(b.torque < a.torque, "{} vs {}", b.torque, a.torque);
}

#[test]
fn discretisation_is_converged_to_a_few_percent() {
    let ac = mtosport();
    let coarse = Rotor::from_params(&ac.rotor);
    let mut fine = coarse.clone();
    fine.radial_strips = 40;
    fine.azimuth_steps = 144;
    let cond = FlightCondition {
        airspeed: 30.9,
        hub_aoa: 5f64.to_radians(),
        omega: rpm_to_rad_s(370.0),
        atmosphere: Atmosphere::isa(0.0),
    };
    let section = AnalyticSection::clean();
    let a = coarse.solve(&section, &cond, &mut None).unwrap();
    let b = fine.solve(&section, &cond, &mut None).unwrap();
    assert!(
        (a.thrust / b.thrust - 1.0).abs() < 0.02,
        "{} vs {}",
        a.thrust,
        b.thrust
    );
    assert!(
        (a.drag / b.drag - 1.0).abs() < 0.05,
        "{} vs {}",
        a.drag,
        b.drag
    );
}

#[test]
fn warm_start_reaches_the_cold_solution() {
    // A warm start carries the previous solve's Broyden-updated Jacobian; near (the next
    // takeoff stage) and far (hover from cruise: the Jacobian is refreshed) it must land on the
    // same root as a cold solve, to the step tolerance.
    let r = Rotor::from_params(&mtosport().rotor);
    let section = AnalyticSection::contaminated();
    let at = |v: f64, aoa_deg: f64, rpm: f64| FlightCondition {
        airspeed: v,
        hub_aoa: aoa_deg.to_radians(),
        omega: rpm_to_rad_s(rpm),
        atmosphere: Atmosphere::isa(0.0),
    };
    let mut start = None;
    r.solve(&section, &at(30.0, 10.0, 330.0), &mut start)
        .unwrap();
    for target in [
        at(30.2, 10.05, 331.0),
        at(0.0, 0.0, 350.0),
        at(40.0, 3.0, 380.0),
    ] {
        let mut from_start = start;
        let warm = r.solve(&section, &target, &mut from_start).unwrap();
        let cold = r.solve(&section, &target, &mut None).unwrap();
        let tip = target.omega * r.radius;
        let dv = (warm.induced_velocity - cold.induced_velocity).abs() / tip;
        let db = (warm.flapping.beta1c - cold.flapping.beta1c)
            .abs()
            .max((warm.flapping.beta1s - cold.flapping.beta1s).abs());
        assert!(
            dv < 1e-8 && db < 1e-8,
            "{target:?}: Δv0/ΩR {dv:e}, Δβ {db:e}"
        );
        for (a, b) in [
            (warm.thrust, cold.thrust),
            (warm.drag, cold.drag),
            (warm.torque, cold.torque),
        ] {
            assert!((a - b).abs() < 1e-6 * (1.0 + b.abs()), "{a} vs {b}");
        }
    }
}
