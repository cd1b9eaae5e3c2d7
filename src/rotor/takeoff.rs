//! Takeoff simulation (paper Table 4): point-mass longitudinal dynamics plus the rotor-speed
//! ODE, integrated with the classical fourth-order Runge–Kutta method.
//!
//! Procedure (paper §Takeoff): rotor prerotated to 200 rpm, brake released, full throttle,
//! stick full aft (rotor head pitch 15°, fuselage level, so the hub angle of attack is 15° on
//! the ground roll). Ground roll: m·u̇ = F_prop − D − μ_r·(G − L). Lift-off when the lift
//! exceeds the weight, placed inside its step where the lift excess, linear over the step,
//! crosses zero (distance, speed and rotor speed interpolated alike), so that s_TO does not
//! move with the step; the airborne equations take over at the end of that step, and the
//! pilot's airspeed schedule starts from the interpolated lift-off speed. Airborne: forces along and normal to the flight path,
//! m·a = (F_prop − D)·e_V + L·e_L − G·e_z. L is the rotor lift plus that of a fixed wing, D the
//! rotor, airframe and wing drag; the wing flies at its incidence (the fuselage level on the
//! ground and along the flight path in the air, as in the trim). Rotor speed throughout: I_R·Ω̇ = Q_aero (the
//! quasi-steady autorotative torque of the blade-element model). Thrust acts along the flight
//! path (small angles).
//!
//! Pilot model after lift-off (paper: "the pilot lowers the rotor head angle after lift-off to
//! control pitch; climb accelerating to ≈ 50 kt"; clean case 43 kt at lift-off, 51 kt at 15 m):
//! at full throttle the pilot flies *pitch for airspeed*, the usual technique of a
//! propeller aircraft climbing at full power. The airspeed target rises in proportion to the
//! height gained, V_t(h) = V_LO + (V_climb − V_LO)·min(h/h_screen, 1), so the excess power is
//! shared between climbing and accelerating along the straight line the paper's clean run
//! draws in the (height, speed) plane, and the climb speed is reached at the screen height.
//! The disc angle follows a PI law on the speed error with derivative lead:
//! α̇_H = K·[(V − V_t) + τ·(V̇ − V̇_t)], clamped to the head-angle range (too slow → lower the
//! disc to accelerate; too fast → raise it to climb).

use super::aircraft::{Aircraft, WingError, WingLoads};
use super::atmosphere::Atmosphere;
use super::disc_loads::{FlightCondition, Rotor};
use super::inflow_flapping::RotorError;
use super::lookup_shares::LookupShares;
use super::propeller::{FullThrottle, Powerplant, PropellerError};
use super::solution::{RotorSolution, RotorWarmStart};
use super::spanwise::BladeSection;
use super::{rad_s_to_rpm, rpm_to_rad_s, G0};
use crate::output::{write_output, OutputError};
use serde::Serialize;
use std::path::Path;

/// Errors of the takeoff simulation.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TakeoffError {
    /// The rotor solution failed during the run.
    #[error("rotor solution failed at t = {time_s:.2} s: {source}")]
    Rotor {
        /// Simulation time \[s\].
        time_s: f64,
        /// Underlying error.
        source: RotorError,
    },
    /// The propeller could not be calibrated or solved.
    #[error(transparent)]
    Propeller(#[from] PropellerError),
    /// The aircraft did not reach the screen height in time.
    #[error("takeoff did not reach {height_m:.0} m within {time_s:.0} s ({reason})")]
    NotReached {
        /// Screen height \[m\].
        height_m: f64,
        /// Time limit \[s\].
        time_s: f64,
        /// State at the end.
        reason: &'static str,
    },
    /// The wing's loads could not be computed.
    #[error(transparent)]
    Wing(#[from] WingError),
    /// The rotor stopped or the state became non-finite.
    #[error("takeoff simulation diverged at t = {time_s:.2} s: {reason}")]
    Diverged {
        /// Simulation time \[s\].
        time_s: f64,
        /// What went wrong.
        reason: &'static str,
    },
}

/// One row of the takeoff time history.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TakeoffSample {
    /// Time since brake release \[s\].
    pub t: f64,
    /// Distance from brake release \[m\].
    pub x: f64,
    /// Height \[m\].
    pub h: f64,
    /// Airspeed \[m/s\].
    pub v: f64,
    /// Rotor speed \[rpm\].
    pub rotor_rpm: f64,
    /// Tip-path-plane angle of attack α_R \[deg\].
    pub alpha_r_deg: f64,
    /// Teeter amplitude β \[deg\].
    pub beta_deg: f64,
}

/// Result of a takeoff run. Its serde form (what `gyro takeoff --json` prints) holds the paper's
/// Table 4 quantities, the lift-off and screen speeds, the lift-off rotor speed, the time to
/// the screen height and the largest shares of section lookups outside the table or the
/// method's validity; the other fields are left out of it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TakeoffResult {
    /// Ground roll to lift-off s_TO \[m\].
    pub takeoff_roll_m: f64,
    /// Distance to the screen height s_15 \[m\].
    pub distance_15m_m: f64,
    /// Largest teeter amplitude during the run β_max \[deg\].
    pub max_flapping_deg: f64,
    /// Whether β_max reached the teeter stops.
    #[serde(skip)]
    pub flap_stops_reached: bool,
    /// Airspeed at lift-off \[kt\].
    pub liftoff_speed_kt: f64,
    /// Airspeed at the screen height \[kt\].
    pub screen_speed_kt: f64,
    /// Rotor speed at lift-off \[rpm\].
    pub liftoff_rotor_rpm: f64,
    /// Time from brake release to lift-off \[s\].
    #[serde(skip)]
    pub liftoff_time_s: f64,
    /// Time from brake release to the screen height \[s\].
    pub screen_time_s: f64,
    /// Time history (every integration step).
    #[serde(skip)]
    pub history: Vec<TakeoffSample>,
    /// Largest share, over the run's rotor solutions, of blade-element lookups whose Reynolds
    /// or Mach number lay outside the section table and were clamped to its edge.
    pub max_table_clamped_fraction: f64,
    /// Largest share over the run of lookups that lean on supercritical table points
    /// (locally supersonic flow, outside the section method's validity).
    pub max_table_supercritical_fraction: f64,
    /// Largest share over the run of lookups at whose α the table's points are in massive
    /// separation (outside the method's validity; the 360° extension stands in).
    pub max_table_separated_fraction: f64,
    /// Time from brake release of the rotor solution with that largest separated share \[s\]
    /// (the first, where several share it).
    pub max_table_separated_time_s: f64,
    /// Airspeed of that rotor solution \[kt\].
    pub max_table_separated_speed_kt: f64,
}

impl TakeoffResult {
    /// What a user should read beside the run: the rotor's section data outside the table or
    /// the method's validity at some point of it (the largest share of the run's lookups).
    /// One line each, starting `note: `.
    pub fn notes(&self) -> Vec<String> {
        self.lookup_shares()
            .notes("during the takeoff (the largest share of one rotor solution)")
    }

    /// The run's largest lookup shares ([`LookupShares`]).
    pub fn lookup_shares(&self) -> LookupShares {
        LookupShares {
            clamped: self.max_table_clamped_fraction,
            supercritical: self.max_table_supercritical_fraction,
            separated: self.max_table_separated_fraction,
        }
    }

    /// Writes the history as CSV with header `t,x,h,v,rotor_rpm,alpha_r_deg,beta_deg`.
    pub fn write_history_csv<W: std::io::Write>(&self, out: W) -> Result<(), csv::Error> {
        let mut w = csv::Writer::from_writer(out);
        for s in &self.history {
            w.serialize(s)?;
        }
        w.flush()?;
        Ok(())
    }

    /// Writes the history CSV ([`write_history_csv`](Self::write_history_csv)) to `path`
    /// (`-`: standard output), whole or not at all ([`write_output`]).
    pub fn write_history_file(&self, path: &Path) -> Result<(), OutputError> {
        write_output(path, |w| {
            self.write_history_csv(w)
                .map_err(|e| OutputError::io(path, e.into()))
        })
    }
}

/// State vector: x, h, u (horizontal speed), w (climb rate), Ω, α_H.
type State = [f64; 6];

/// Everything the right-hand side needs.
struct Model<'a, S: BladeSection + ?Sized> {
    aircraft: &'a Aircraft,
    rotor: Rotor,
    section: &'a S,
    prop: Powerplant,
    /// Last full-throttle equilibrium, the start of the next solve (local to this run).
    warm_prop: Option<FullThrottle>,
    inertia: f64,
    /// The last rotor solve's state, the warm start of the next solve (local to this run).
    warm: Option<RotorWarmStart>,
    /// Airspeed at lift-off \[m/s\] (start of the pilot's airspeed schedule).
    liftoff_speed: f64,
    /// The largest lookup shares of the solutions so far.
    validity_peaks: LookupShares,
    /// Time \[s\] and airspeed \[m/s\] of the first solution with the largest separated share.
    separated_peak_at: (f64, f64),
}

impl<S: BladeSection + ?Sized> Model<'_, S> {
    fn rotor_at(&mut self, t: f64, y: &State) -> Result<RotorSolution, TakeoffError> {
        let atm = Atmosphere::isa(self.aircraft.takeoff.field_altitude_m + y[1].max(0.0));
        let cond = FlightCondition {
            airspeed: y[2].hypot(y[3]),
            hub_aoa: y[5],
            omega: y[4],
            atmosphere: atm,
        };
        if !(y.iter().all(|v| v.is_finite())) {
            return Err(TakeoffError::Diverged {
                time_s: t,
                reason: "non-finite state",
            });
        }
        if y[4] <= 0.0 {
            return Err(TakeoffError::Diverged {
                time_s: t,
                reason: "the rotor stopped",
            });
        }
        let solution = self
            .rotor
            .solve(self.section, &cond, &mut self.warm)
            .map_err(|source| TakeoffError::Rotor { time_s: t, source })?;
        let shares = solution.lookup_shares();
        if shares.separated > self.validity_peaks.separated {
            self.separated_peak_at = (t, cond.airspeed);
        }
        self.validity_peaks = self.validity_peaks.max(shares);
        Ok(solution)
    }

    /// The wing's lift and drag in state `y`.
    fn wing_at(&self, y: &State) -> Result<WingLoads, TakeoffError> {
        let atm = Atmosphere::isa(self.aircraft.takeoff.field_altitude_m + y[1].max(0.0));
        Ok(self.aircraft.wing_loads(&atm, y[2].hypot(y[3]))?)
    }

    /// Time derivative of the state; `airborne` selects the equations of motion.
    fn derivative(
        &mut self,
        t: f64,
        y: &State,
        airborne: bool,
    ) -> Result<(State, RotorSolution), TakeoffError> {
        let s = self.rotor_at(t, y)?;
        let ac = self.aircraft;
        let m = ac.mass_kg;
        let weight = ac.weight_n();
        let v = y[2].hypot(y[3]);
        let rho = s.condition.atmosphere.density;
        let full = self
            .prop
            .full_throttle(&s.condition.atmosphere, v, self.warm_prop.as_ref())?;
        let thrust = full.propeller.thrust;
        self.warm_prop = Some(full);
        let wing = self.wing_at(y)?;
        let drag = s.drag + 0.5 * rho * v * v * ac.parasitic_drag_area_m2 + wing.drag_n;
        let lift = s.lift + wing.lift_n;
        let omega_dot = s.torque / self.inertia;
        let mut dy = [0.0; 6];
        if !airborne {
            let friction = ac.takeoff.rolling_friction * (weight - lift).max(0.0);
            let ax = (thrust - drag - friction) / m;
            dy[0] = y[2];
            // Standing still, the brakes-off aircraft cannot roll backwards.
            dy[2] = if y[2] <= 0.0 { ax.max(0.0) } else { ax };
            dy[4] = omega_dot;
            return Ok((dy, s));
        }
        let gamma = if v > 1e-6 { y[3].atan2(y[2]) } else { 0.0 };
        let (sg, cg) = gamma.sin_cos();
        let along = thrust - drag;
        let ax = (along * cg - lift * sg) / m;
        let az = (along * sg + lift * cg) / m - G0;
        let to = &ac.takeoff;
        // Pilot: airspeed schedule V_t(h) and the PI law of the module documentation.
        let v_climb = to.climb_speed_kt * super::KT_TO_MS;
        let h_frac = (y[1] / to.screen_height_m).clamp(0.0, 1.0);
        let v_target = self.liftoff_speed + (v_climb - self.liftoff_speed) * h_frac;
        let v_target_rate = if h_frac < 1.0 {
            (v_climb - self.liftoff_speed) / to.screen_height_m * y[3]
        } else {
            0.0
        };
        let v_rate = if v > 1e-6 {
            (y[2] * ax + y[3] * az) / v
        } else {
            0.0
        };
        let mut rate = (to.pilot_gain_deg_per_ms
            * ((v - v_target) + to.pilot_time_constant_s * (v_rate - v_target_rate)))
            .to_radians();
        let (lo, hi) = (
            to.head_angle_min_deg.to_radians(),
            to.head_angle_max_deg.to_radians(),
        );
        if (y[5] >= hi && rate > 0.0) || (y[5] <= lo && rate < 0.0) {
            rate = 0.0;
        }
        dy[0] = y[2];
        dy[1] = y[3];
        dy[2] = ax;
        dy[3] = az;
        dy[4] = omega_dot;
        dy[5] = rate;
        Ok((dy, s))
    }

    fn rk4_step(
        &mut self,
        t: f64,
        y: &State,
        dt: f64,
        airborne: bool,
    ) -> Result<(State, RotorSolution), TakeoffError> {
        let add = |a: &State, k: &State, h: f64| -> State {
            let mut r = *a;
            for i in 0..6 {
                r[i] += h * k[i];
            }
            r
        };
        let (k1, s1) = self.derivative(t, y, airborne)?;
        let (k2, _) = self.derivative(t + 0.5 * dt, &add(y, &k1, 0.5 * dt), airborne)?;
        let (k3, _) = self.derivative(t + 0.5 * dt, &add(y, &k2, 0.5 * dt), airborne)?;
        let (k4, _) = self.derivative(t + dt, &add(y, &k3, dt), airborne)?;
        let mut next = *y;
        for i in 0..6 {
            next[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        let hi = self.aircraft.takeoff.head_angle_max_deg.to_radians();
        let lo = self.aircraft.takeoff.head_angle_min_deg.to_radians();
        next[5] = next[5].clamp(lo, hi);
        if next[1] < 0.0 {
            next[1] = 0.0;
            next[3] = next[3].max(0.0);
        }
        Ok((next, s1))
    }
}

fn sample(t: f64, y: &State, s: &RotorSolution) -> TakeoffSample {
    TakeoffSample {
        t,
        x: y[0],
        h: y[1],
        v: y[2].hypot(y[3]),
        rotor_rpm: rad_s_to_rpm(y[4]),
        alpha_r_deg: s.disc_aoa().to_degrees(),
        beta_deg: s.flapping.amplitude().to_degrees(),
    }
}

/// Simulates the takeoff of `aircraft` with rotor section `section` from brake release to the
/// screen height (see the module documentation for the equations).
pub fn simulate_takeoff<S: BladeSection + ?Sized>(
    aircraft: &Aircraft,
    section: &S,
) -> Result<TakeoffResult, TakeoffError> {
    let to = &aircraft.takeoff;
    let mut model = Model {
        aircraft,
        rotor: Rotor::from_params(&aircraft.rotor),
        section,
        prop: Powerplant::from_aircraft(aircraft)?,
        warm_prop: None,
        inertia: aircraft.rotor.polar_inertia(),
        warm: None,
        liftoff_speed: 0.0,
        validity_peaks: LookupShares::default(),
        separated_peak_at: (0.0, 0.0),
    };
    let dt = to.time_step_s;
    let kt = super::KT_TO_MS;
    let mut y: State = [
        0.0,
        0.0,
        0.0,
        0.0,
        rpm_to_rad_s(to.prerotation_rpm),
        to.head_angle_max_deg.to_radians(),
    ];
    // Time as step × dt rounded to 1e-9 s (not a running sum, whose round-off would show in
    // the history file as 15.559999999999757).
    let time_at = |step: u32| (f64::from(step) * dt * 1e9).round() / 1e9;
    let mut step: u32 = 0;
    let mut t = 0.0;
    let mut airborne = false;
    let mut history = Vec::new();
    let mut beta_max: f64 = 0.0;
    let mut liftoff: Option<(f64, f64, f64, f64)> = None;
    // The ground roll's last state and its lift excess L − W (< 0), to place the lift-off
    // inside the step in which the excess turned positive.
    let mut rolling: Option<(State, f64)> = None;
    let weight = aircraft.weight_n();
    while t < to.max_time_s {
        let (next, s) = model.rk4_step(t, &y, dt, airborne)?;
        history.push(sample(t, &y, &s));
        beta_max = beta_max.max(s.flapping.amplitude().to_degrees());
        if !airborne {
            let excess = s.lift + model.wing_at(&y)?.lift_n - weight;
            if excess >= 0.0 {
                airborne = true;
                // Lift-off where the lift excess, linear over the step, crosses zero.
                let (before, frac) = match rolling {
                    Some((before, e0)) if e0.is_finite() && excess.is_finite() => {
                        (before, e0 / (e0 - excess))
                    }
                    _ => (y, 1.0),
                };
                let at = |i: usize| before[i] + frac * (y[i] - before[i]);
                liftoff = Some((at(0), t - (1.0 - frac) * dt, at(2), at(4)));
                model.liftoff_speed = at(2);
            } else {
                rolling = Some((y, excess));
            }
        }
        if airborne && next[1] >= to.screen_height_m {
            let frac = (to.screen_height_m - y[1]) / (next[1] - y[1]);
            let x15 = y[0] + frac * (next[0] - y[0]);
            let t15 = t + frac * dt;
            let v15 = y[2].hypot(y[3]) + frac * (next[2].hypot(next[3]) - y[2].hypot(y[3]));
            let t_next = time_at(step + 1);
            let s_end = model.rotor_at(t_next, &next)?;
            history.push(sample(t_next, &next, &s_end));
            beta_max = beta_max.max(s_end.flapping.amplitude().to_degrees());
            let (x_to, t_to, v_to, omega_to) = liftoff.unwrap_or((x15, t15, v15, next[4]));
            return Ok(TakeoffResult {
                takeoff_roll_m: x_to,
                distance_15m_m: x15,
                max_flapping_deg: beta_max,
                flap_stops_reached: aircraft
                    .rotor
                    .flap_stop_deg
                    .is_some_and(|stop| beta_max >= stop),
                liftoff_speed_kt: v_to / kt,
                screen_speed_kt: v15 / kt,
                liftoff_rotor_rpm: rad_s_to_rpm(omega_to),
                liftoff_time_s: t_to,
                screen_time_s: t15,
                history,
                max_table_clamped_fraction: model.validity_peaks.clamped,
                max_table_supercritical_fraction: model.validity_peaks.supercritical,
                max_table_separated_fraction: model.validity_peaks.separated,
                max_table_separated_time_s: model.separated_peak_at.0,
                max_table_separated_speed_kt: model.separated_peak_at.1 / kt,
            });
        }
        y = next;
        step += 1;
        t = time_at(step);
    }
    Err(TakeoffError::NotReached {
        height_m: to.screen_height_m,
        time_s: to.max_time_s,
        reason: if airborne {
            "airborne but not climbing enough"
        } else {
            "still on the ground"
        },
    })
}
