//! The engine at full throttle: crankshaft torque against engine rpm, through a reduction
//! gear to the propeller shaft.
//!
//! The torque curve is a table of (rpm, N m) points from the aircraft preset (for the Rotax
//! 912 ULS: the operator's manual's performance points and the data sheet's maximum, the
//! estimated points marked as such in `aircraft/mtosport.toml`), interpolated linearly and held
//! constant beyond its ends. The propeller shaft receives Q_p = η·Q_e/i, with i the propeller
//! rpm per engine rpm and η the gear efficiency (power P_p = η·P_e).

use super::aircraft::EngineParams;

/// Full-throttle engine with its reduction gear.
#[derive(Clone, Debug, PartialEq)]
pub struct Engine {
    /// Propeller rpm per engine rpm, i.
    pub gear_ratio: f64,
    /// Gear efficiency η (propeller-shaft power / crankshaft power).
    pub gear_efficiency: f64,
    /// Highest engine rpm allowed \[rpm\].
    pub max_rpm: f64,
    /// Torque curve: engine rpm, strictly increasing.
    rpm: Vec<f64>,
    /// Torque curve: crankshaft torque at full throttle \[N m\].
    torque: Vec<f64>,
}

impl Engine {
    /// The engine of a preset (the preset's validation guarantees a usable curve).
    pub fn from_params(p: &EngineParams) -> Self {
        Self {
            gear_ratio: p.gear_ratio,
            gear_efficiency: p.gear_efficiency,
            max_rpm: p.max_rpm,
            rpm: p.torque_rpm.clone(),
            torque: p.torque_nm.clone(),
        }
    }

    /// Crankshaft torque at full throttle \[N m\] at `engine_rpm`: linear between the table's
    /// points, the end values beyond them.
    pub fn full_throttle_torque(&self, engine_rpm: f64) -> f64 {
        let (x, y) = (&self.rpm, &self.torque);
        let n = x.len();
        if n == 0 {
            return 0.0;
        }
        if engine_rpm <= x[0] {
            return y[0];
        }
        if engine_rpm >= x[n - 1] {
            return y[n - 1];
        }
        let k = x.partition_point(|&v| v <= engine_rpm).clamp(1, n - 1);
        let t = (engine_rpm - x[k - 1]) / (x[k] - x[k - 1]);
        y[k - 1] + t * (y[k] - y[k - 1])
    }

    /// Propeller-shaft torque at full throttle \[N m\] at `engine_rpm`: η·Q_e/i.
    pub fn shaft_torque(&self, engine_rpm: f64) -> f64 {
        self.gear_efficiency * self.full_throttle_torque(engine_rpm) / self.gear_ratio
    }

    /// Propeller revolutions per second at `engine_rpm`.
    pub fn propeller_rev_per_s(&self, engine_rpm: f64) -> f64 {
        self.gear_ratio * engine_rpm / 60.0
    }

    /// Engine rpm at propeller speed `rev_per_s`.
    pub fn engine_rpm(&self, rev_per_s: f64) -> f64 {
        rev_per_s * 60.0 / self.gear_ratio
    }
}
