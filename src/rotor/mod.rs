//! Blade-element (strip) model of a gyroplane rotor driven by a polar table — two blades on a
//! teeter bolt or N blades on flapping hinges, the hub as data ([`Hub`]) — : autorotation,
//! cruise trim, takeoff, and the isolated rotor in a wind tunnel.
//!
//! The rotor sees the airfoil only through [`BladeSection`]: every strip turns its local
//! velocity into (α, Re, M) and asks the section at its radius for (c_l, c_d, c_m); every
//! [`SectionAero`](crate::section::SectionAero) is a blade section uniform along the span. The facade is re-exported here (the aircraft, the rotor and its solution,
//! trim, takeoff, cruise sweeps, the blade element); the files inside:
//!
//! * `atmosphere` — ISA standard atmosphere (density, speed of sound, viscosity).
//! * `aircraft` — the aircraft preset (rotor, airframe, propeller, engine, takeoff data and an
//!   optional fixed wing with its lifting-line lift and drag) from TOML, and a preset read for
//!   its rotor alone ([`RotorPreset`]).
//! * `blade_element` — velocity triangle and loads of one strip (reverse flow included).
//! * `inflow` — induced velocity: Glauert momentum theory, Drees linear inflow; the tip-loss
//!   models and the yawed-flow switch.
//! * `flapping` — first-harmonic blade flapping and the hub: teetering (fixed coning) or
//!   articulated (free coning from the blade's flapping inertia, hinge offset).
//! * `planform` — chord and twist along the blade.
//! * `torsion` — the blade's elastic torsion under its lift.
//! * `disc_loads` — the rotor disc: azimuth-averaged forces and torque of the blade-element
//!   sum.
//! * `inflow_flapping` — the disc's induced inflow and blade flapping solved together with
//!   those loads (Newton–Broyden).
//! * `solution` — what a solve returns: the converged state and its loads, and apart from it
//!   the solver's memory for a warm start.
//! * `trim` — autorotation rpm and level-cruise trim.
//! * `tunnel` — the isolated rotor in a wind tunnel: autorotative rpm and wind-axis
//!   coefficients at a shaft angle and wind speed (`gyro autorotate`).
//! * `cruise` — power-required speed sweep and blade α(ψ) in trimmed cruise.
//! * `engine` — full-throttle torque curve and reduction gear (Rotax 912 ULS in the preset).
//! * `propeller` — blade-element–momentum propeller from its geometry and section table, and
//!   the powerplant: calibrated pitch, engine rpm for a thrust, full-throttle equilibrium.
//! * `takeoff` — time-domain takeoff simulation to 15 m.
//! * `spanwise` — section data along the blade: [`BladeSection`] and [`SpanwiseSection`], a
//!   blade that reads another section over part of its span.

mod aircraft;
mod atmosphere;
mod blade_element;
mod cruise;
mod disc_loads;
mod engine;
mod flapping;
mod inflow;
mod inflow_flapping;
mod lookup_shares;
mod planform;
mod propeller;
mod solution;
mod spanwise;
mod takeoff;
mod torsion;
mod trim;
mod tunnel;

pub use aircraft::{
    check_altitude_m, check_azimuth_samples, check_blade_radius, check_mass_kg, check_speed_kt,
    Aircraft, AircraftError, BladeGeometry, BladeParams, EngineParams, HubParams, PropellerParams,
    RotorParams, RotorPreset, SectionFile, TakeoffParams, TorsionParams, WingError, WingLoads,
    WingParams, MAX_BLADES, MAX_MASS_KG, MAX_SPEED_KT,
};
pub use atmosphere::{Atmosphere, MAX_ISA_ALTITUDE_M};
pub use blade_element::{strip_load, AirState, StripFlow, StripLoad};
pub use cruise::{
    check_sweep_speeds, checked_sweep_speeds, cruise_blade_alpha, speed_sweep, sweep_speeds,
    BladeAlpha, SweepPoint,
};
pub use disc_loads::{FlightCondition, Rotor, RotorSolverParams};
pub use engine::Engine;
pub use flapping::{FlapHinge, Flapping, Hub};
pub use inflow::{InflowModel, TipLoss, YawedFlow};
pub use inflow_flapping::RotorError;
pub use lookup_shares::LookupShares;
pub use planform::{Planform, PlanformStation};
pub use propeller::{
    FullThrottle, Powerplant, Propeller, PropellerError, PropellerPoint, PropellerSections,
    SectionsError, SharedSection,
};
pub use solution::{RotorSolution, RotorWarmStart};
pub use spanwise::{BladeSection, SpanBand, SpanwiseSection};
pub use takeoff::{simulate_takeoff, TakeoffError, TakeoffResult, TakeoffSample};
pub use torsion::ElasticTorsion;
pub use trim::{autorotation, trim_aircraft, trim_rotor, TrimError, TrimParams, TrimResult};
pub use tunnel::{
    autorotate, autorotate_cases, autorotate_outcomes, cases_csv, check_alpha_deg, check_mu,
    check_rpm, read_tunnel_cases, tunnel_case, tunnel_run, Autorotation, CaseOutcome,
    NoAutorotation, TunnelCase, TunnelCasesError, MAX_TUNNEL_CASES, MAX_TUNNEL_SPEED_M_S,
    TUNNEL_ALPHA_RANGE_DEG,
};

/// Knots to metres per second (1 kt = 1852 m / 3600 s, exact by definition).
pub const KT_TO_MS: f64 = 1852.0 / 3600.0;

/// Standard gravity [m/s²] (ISO 80000-3, also the ISA value).
pub const G0: f64 = 9.80665;

/// Revolutions per minute to radians per second.
pub fn rpm_to_rad_s(rpm: f64) -> f64 {
    rpm * std::f64::consts::PI / 30.0
}

/// Radians per second to revolutions per minute.
pub fn rad_s_to_rpm(omega: f64) -> f64 {
    omega * 30.0 / std::f64::consts::PI
}
