//! Blade-element (strip) model of a two-bladed teetering gyroplane rotor driven by a polar
//! table: autorotation, cruise trim and takeoff.
//!
//! The rotor sees the airfoil only through [`BladeSection`]: every strip turns its local
//! velocity into (α, Re, M) and asks the section at its radius for (c_l, c_d, c_m); every
//! [`SectionAero`](crate::section::SectionAero) is a blade section uniform along the span. The facade is re-exported here (the aircraft, the rotor and its solution,
//! trim, takeoff, cruise sweeps, the blade element) and [`study`]; the files inside:
//!
//! * `atmosphere` — ISA standard atmosphere (density, speed of sound, viscosity).
//! * `aircraft` — the aircraft preset (rotor, airframe, propeller, engine, takeoff data and an
//!   optional fixed wing with its lifting-line lift and drag) from TOML.
//! * `blade_element` — velocity triangle and loads of one strip (reverse flow included).
//! * `inflow` — induced velocity: Glauert momentum theory, Drees linear inflow; the tip-loss
//!   models and the yawed-flow switch.
//! * `flapping` — first-harmonic teeter motion of the blade pair.
//! * `disc_loads` — the rotor disc: azimuth-averaged forces and torque of the blade-element
//!   sum.
//! * `inflow_flapping` — the disc's induced inflow and teeter flapping solved together with
//!   those loads (Newton–Broyden).
//! * `trim` — autorotation rpm and level-cruise trim.
//! * `cruise` — power-required speed sweep and blade α(ψ) in trimmed cruise.
//! * `engine` — full-throttle torque curve and reduction gear (Rotax 912 ULS in the preset).
//! * `propeller` — blade-element–momentum propeller from its geometry and section table, and
//!   the powerplant: calibrated pitch, engine rpm for a thrust, full-throttle equilibrium.
//! * `takeoff` — time-domain takeoff simulation to 15 m.
//! * `spanwise` — section data along the blade: [`BladeSection`] and [`SpanwiseSection`], a
//!   blade that reads another section over part of its span.
//! * [`study`] — the paper's clean-versus-contaminated study and its published values.

mod aircraft;
mod atmosphere;
mod blade_element;
mod cruise;
mod disc_loads;
mod engine;
mod flapping;
mod inflow;
mod inflow_flapping;
mod propeller;
mod spanwise;
pub mod study;
mod takeoff;
mod trim;

pub use aircraft::{
    check_altitude_m, check_azimuth_samples, check_blade_radius, check_mass_kg, check_speed_kt,
    Aircraft, AircraftError, BladeGeometry, EngineParams, PropellerParams, RotorParams,
    TakeoffParams, WingError, WingLoads, WingParams, MAX_MASS_KG, MAX_SPEED_KT,
};
pub use atmosphere::{Atmosphere, MAX_ISA_ALTITUDE_M};
pub use blade_element::{strip_load, AirState, StripFlow, StripLoad};
pub use cruise::{
    check_sweep_speeds, checked_sweep_speeds, cruise_blade_alpha, speed_sweep, sweep_speeds,
    SweepPoint,
};
pub use disc_loads::{FlightCondition, Rotor};
pub use engine::Engine;
pub use flapping::Teeter;
pub use inflow::{InflowModel, TipLoss, YawedFlow};
pub use inflow_flapping::{RotorError, RotorSolution, RotorSolverParams};
pub use propeller::{FullThrottle, Powerplant, Propeller, PropellerError, PropellerPoint};
pub use spanwise::{BladeSection, SpanBand, SpanwiseSection};
pub use takeoff::{simulate_takeoff, TakeoffError, TakeoffResult, TakeoffSample};
pub use trim::{autorotation, trim_aircraft, trim_rotor, TrimError, TrimParams, TrimResult};

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
