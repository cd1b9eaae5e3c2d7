//! Propeller/engine map: thrust of a fixed-pitch propeller driven through a reduction gear.
//!
//! Model: thrust coefficient falling linearly with advance ratio,
//! T = ρ n² D⁴ C_T0 (1 − J/J0), J = V/(nD), n = gear · engine rpm / 60
//! (the linear C_T(J) of a fixed-pitch propeller below stall; McCormick, *Aerodynamics,
//! Aeronautics and Flight Mechanics*, 2nd ed., §6.6, Fig. 6.22 shape).
//!
//! Calibration (two constants, two conditions):
//! * C_T0 from the static full-throttle point: T_static at the full-throttle static engine rpm
//!   at sea-level ISA density;
//! * J0 from the flight-test point: the thrust needed in cruise (paper Table 3: 1051 N at 60 kt,
//!   clean) at the engine rpm measured there (4400 rpm).
//!
//! Full throttle: a fixed-pitch propeller unloads as the airspeed grows and the engine speeds
//! up until its torque balances the propeller's again. The engine is taken to deliver constant
//! torque at full throttle (the Rotax 912 ULS torque curve is flat within about 5 % between
//! 5000 and 5800 rpm) and the propeller's torque coefficient to fall linearly with J, reaching
//! zero at J_Q = k·J0 (at zero thrust a propeller still absorbs the blades' profile torque, so
//! k > 1). The balance ρn²D⁵C_Q0(1 − J/J_Q) = Q_static, with J = V/(nD), gives
//! n² − n·V/(D·J_Q) = n_static², whose positive root is the full-throttle propeller speed
//! (capped at the engine's maximum rpm). Thrust then falls slowly with airspeed (exactly
//! constant for k = 1), which is the "full thrust decreasing with speed" of the takeoff model.

use super::aircraft::PropellerParams;
use super::atmosphere::Atmosphere;

/// Errors of the propeller map.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PropellerError {
    /// The calibration point is inconsistent with the static thrust.
    #[error("propeller calibration impossible: {0}")]
    Calibration(&'static str),
    /// The requested thrust needs more than the engine's maximum rpm.
    #[error("propeller thrust {thrust_n:.0} N needs {engine_rpm:.0} engine rpm, above the maximum {max_rpm:.0}")]
    Unavailable {
        /// Thrust requested \[N\].
        thrust_n: f64,
        /// Engine rpm it would need.
        engine_rpm: f64,
        /// Maximum engine rpm.
        max_rpm: f64,
    },
}

/// Calibrated propeller/engine map.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PropellerMap {
    /// Propeller diameter D \[m\].
    pub diameter: f64,
    /// Propeller rpm per engine rpm.
    pub gear_ratio: f64,
    /// Static thrust coefficient C_T0 = T/(ρn²D⁴) at J = 0.
    pub ct0: f64,
    /// Advance ratio of zero thrust J0.
    pub j0: f64,
    /// Engine rpm at full throttle, standing still.
    pub static_engine_rpm: f64,
    /// Advance ratio at which the propeller's torque vanishes, J_Q = k·J0.
    pub zero_torque_j: f64,
    /// Maximum engine rpm.
    pub max_engine_rpm: f64,
}

impl PropellerMap {
    /// Calibrates C_T0 and J0 from the preset (see the module documentation).
    pub fn calibrate(p: &PropellerParams) -> Result<Self, PropellerError> {
        let rho0 = Atmosphere::isa(0.0).density;
        let d4 = p.diameter_m.powi(4);
        let n_static = p.gear_ratio * p.static_engine_rpm / 60.0;
        let ct0 = p.static_thrust_n / (rho0 * n_static * n_static * d4);
        let n_cal = p.gear_ratio * p.calib_engine_rpm / 60.0;
        let ratio = 1.0 - p.calib_thrust_n / (rho0 * n_cal * n_cal * d4 * ct0);
        if !(ratio > 0.0 && ratio < 1.0) {
            return Err(PropellerError::Calibration(
                "the cruise point needs more thrust coefficient than the static point",
            ));
        }
        let j_cal = p.calib_speed_kt * super::KT_TO_MS / (n_cal * p.diameter_m);
        Ok(Self {
            diameter: p.diameter_m,
            gear_ratio: p.gear_ratio,
            ct0,
            j0: j_cal / ratio,
            static_engine_rpm: p.static_engine_rpm,
            zero_torque_j: p.zero_torque_j_factor * j_cal / ratio,
            max_engine_rpm: p.max_engine_rpm,
        })
    }

    /// Thrust \[N\] at density `rho`, airspeed `v` \[m/s\] and engine rpm (zero beyond J0).
    pub fn thrust(&self, rho: f64, v: f64, engine_rpm: f64) -> f64 {
        let n = self.gear_ratio * engine_rpm / 60.0;
        if n <= 0.0 {
            return 0.0;
        }
        let j = v / (n * self.diameter);
        (rho * n * n * self.diameter.powi(4) * self.ct0 * (1.0 - j / self.j0)).max(0.0)
    }

    /// Engine rpm at full throttle and airspeed `v` \[m/s\]: the torque balance of the module
    /// documentation, n = [a + √(a² + 4 n_static²)]/2 with a = V/(D·J_Q), capped at the
    /// maximum engine rpm.
    pub fn full_throttle_engine_rpm(&self, v: f64) -> f64 {
        let n_static = self.gear_ratio * self.static_engine_rpm / 60.0;
        let a = v.max(0.0) / (self.diameter * self.zero_torque_j);
        let n = 0.5 * (a + (a * a + 4.0 * n_static * n_static).sqrt());
        (n * 60.0 / self.gear_ratio).min(self.max_engine_rpm)
    }

    /// Full-throttle thrust \[N\] at density `rho` and airspeed `v` \[m/s\].
    pub fn full_throttle_thrust(&self, rho: f64, v: f64) -> f64 {
        self.thrust(rho, v, self.full_throttle_engine_rpm(v))
    }

    /// Engine rpm that gives `thrust` \[N\] at density `rho` and airspeed `v`: the positive root
    /// of a n² − b n − T = 0 with a = ρD⁴C_T0, b = ρD³C_T0 V/J0.
    pub fn engine_rpm_for_thrust(
        &self,
        rho: f64,
        v: f64,
        thrust: f64,
    ) -> Result<f64, PropellerError> {
        let a = rho * self.diameter.powi(4) * self.ct0;
        let b = rho * self.diameter.powi(3) * self.ct0 * v / self.j0;
        let t = thrust.max(0.0);
        let n = (b + (b * b + 4.0 * a * t).sqrt()) / (2.0 * a);
        let rpm = n * 60.0 / self.gear_ratio;
        if rpm > self.max_engine_rpm {
            return Err(PropellerError::Unavailable {
                thrust_n: thrust,
                engine_rpm: rpm,
                max_rpm: self.max_engine_rpm,
            });
        }
        Ok(rpm)
    }
}
