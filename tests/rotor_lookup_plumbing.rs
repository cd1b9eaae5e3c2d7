//! The rotor asks the section for (α, Re, M) computed from each strip's velocity triangle.

mod rotor_support;

use polargen::rotor::{rpm_to_rad_s, Atmosphere, FlightCondition, Rotor};
use polargen::section::{Lookup, SectionAero};
use rotor_support::{mtosport, AnalyticSection};
use std::cell::RefCell;

/// Wraps a section and records every query.
struct Recording {
    inner: AnalyticSection,
    queries: RefCell<Vec<(f64, f64, f64)>>,
}

impl SectionAero for Recording {
    fn lookup(&self, alpha_deg: f64, re: f64, mach: f64) -> Lookup {
        self.queries.borrow_mut().push((alpha_deg, re, mach));
        self.inner.lookup(alpha_deg, re, mach)
    }
}

#[test]
fn strips_query_reynolds_and_mach_of_their_local_speed() {
    let rotor = Rotor::from_params(&mtosport().rotor);
    let atm = Atmosphere::isa(0.0);
    let cond = FlightCondition {
        airspeed: 30.0,
        hub_aoa: 6f64.to_radians(),
        omega: rpm_to_rad_s(350.0),
        atmosphere: atm,
    };
    let section = Recording {
        inner: AnalyticSection::clean(),
        queries: RefCell::new(Vec::new()),
    };
    let s = rotor.solve(&section, &cond, &mut None).unwrap();
    let q = section.queries.borrow();
    // One query per strip and azimuth step for each residual evaluation.
    assert_eq!(q.len() % (rotor.radial_strips * rotor.azimuth_steps), 0);
    // Fastest strip: outermost centre r = R − Δr/2 on the advancing side (ψ = 90°).
    let (radii, _) = rotor.strips();
    let r_out = *radii.last().unwrap();
    let w_max = cond.omega * r_out + cond.airspeed * cond.hub_aoa.cos();
    let m_max = q.iter().map(|x| x.2).fold(0.0, f64::max);
    let re_max = q.iter().map(|x| x.1).fold(0.0, f64::max);
    // U_P adds a little to W: allow 0.5 %.
    assert!(
        (m_max / (w_max / atm.speed_of_sound) - 1.0).abs() < 5e-3,
        "M {m_max}"
    );
    let re_expected = atm.density * w_max * rotor.chord / atm.viscosity;
    assert!(
        (re_max / re_expected - 1.0).abs() < 5e-3,
        "Re {re_max} vs {re_expected}"
    );
    // Paper: Re ≈ 1.9e6, M ≈ 0.41 at 90 % R from rotation alone (0.9·ΩR ≈ 139 m/s); the
    // advancing tip adds the flight speed: M ≈ 0.52, Re ≈ 2.4e6.
    assert!(
        (2.2e6..2.6e6).contains(&re_max) && (0.48..0.56).contains(&m_max),
        "{re_max} {m_max}"
    );
    // Re/M ratio is the same for every query (same chord, air): Re/M = ρ a c/μ.
    let k = atm.density * atm.speed_of_sound * rotor.chord / atm.viscosity;
    assert!(q.iter().all(|x| (x.1 / x.2 / k - 1.0).abs() < 1e-9));
    // The last evaluation's α range: all blade angles within ±180°, stall-free in cruise
    // outside the reverse-flow region.
    assert!(q.iter().all(|x| x.0 > -180.0 && x.0 <= 180.0));
    assert!(s.reverse_flow_fraction < 0.05);
}
