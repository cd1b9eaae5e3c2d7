//! The propeller and engine sections of a preset: blade geometry, the calibration point, the
//! gear and the full-throttle torque curve, with their range checks.

use super::checks::{each, in_range, increasing, positive, same_length};
use super::{AircraftError, MAX_SPEED_KT};
use serde::Deserialize;
use std::path::PathBuf;

/// Propeller data: the blade and the one calibration point that sets its pitch (the model:
/// [`crate::rotor::Powerplant`]).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PropellerParams {
    /// Polar table of the blade section along the whole blade, a path relative to the
    /// preset's folder (or `sections`, not both).
    #[serde(default)]
    pub section_table: Option<PathBuf>,
    /// The blade's sections by thickness ratio, interpolated along the blade in
    /// `blade.thickness_ratio` (or `section_table`, not both).
    #[serde(default)]
    pub sections: Option<Vec<SectionFile>>,
    /// Calibration point: airspeed \[kt\] …
    pub calib_speed_kt: f64,
    /// … thrust there \[N\] …
    pub calib_thrust_n: f64,
    /// … and the engine rpm there \[rpm\].
    pub calib_engine_rpm: f64,
    /// Blade geometry.
    pub blade: BladeGeometry,
}

/// One member of a family of propeller sections: its thickness ratio and polar table.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SectionFile {
    /// Thickness ratio t/c of the section.
    pub thickness_ratio: f64,
    /// Its polar table, a path relative to the preset's folder.
    pub table: PathBuf,
}

/// Blade geometry of a propeller: the chord and twist distributions along the radius.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BladeGeometry {
    /// Diameter D \[m\].
    pub diameter_m: f64,
    /// Number of blades B.
    pub blades: u32,
    /// Stations r/R, increasing; the aerodynamic blade starts at the first.
    pub r_over_r: Vec<f64>,
    /// Chord over diameter c/D at each station.
    pub chord_over_diameter: Vec<f64>,
    /// Blade angle at each station relative to the one at 0.75 R \[deg\] (the twist).
    pub twist_deg: Vec<f64>,
    /// Thickness ratio t/c at each station: which sections of the family each annulus reads
    /// (needed with `propeller.sections`).
    #[serde(default)]
    pub thickness_ratio: Option<Vec<f64>>,
    /// Number of equal annuli from the first station to the tip.
    pub annuli: usize,
}

/// Engine and reduction gear (the model: [`crate::rotor::Engine`]).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EngineParams {
    /// Propeller rpm / engine rpm (reduction gear).
    pub gear_ratio: f64,
    /// Gear efficiency: propeller-shaft power / crankshaft power.
    pub gear_efficiency: f64,
    /// Highest engine rpm allowed (full-throttle rpm never exceeds it) \[rpm\].
    pub max_rpm: f64,
    /// Full-throttle torque curve: engine rpm, increasing …
    pub torque_rpm: Vec<f64>,
    /// … and crankshaft torque there \[N m\].
    pub torque_nm: Vec<f64>,
}

impl PropellerParams {
    /// Checks the calibration point and the blade.
    pub(super) fn validate(&self) -> Result<(), AircraftError> {
        in_range(
            "propeller.calib_speed_kt",
            self.calib_speed_kt,
            (f64::MIN_POSITIVE, MAX_SPEED_KT),
            "must be above 0 and at most 300 kt",
        )?;
        positive("propeller.calib_thrust_n", self.calib_thrust_n)?;
        match (
            &self.section_table,
            &self.sections,
            &self.blade.thickness_ratio,
        ) {
            (Some(_), None, _) => {}
            (None, Some(list), Some(t)) if !list.is_empty() => {
                let field = "propeller.sections.thickness_ratio";
                let ratios: Vec<f64> = list.iter().map(|s| s.thickness_ratio).collect();
                each(field, &ratios, |v| v > 0.0 && v < 1.0, "must be in (0, 1)")?;
                increasing(field, &ratios)?;
                same_length(
                    "propeller.blade.thickness_ratio",
                    t,
                    self.blade.r_over_r.len(),
                    "r_over_r",
                )?;
                each(
                    "propeller.blade.thickness_ratio",
                    t,
                    |v| v > 0.0 && v < 1.0,
                    "must be in (0, 1)",
                )?;
            }
            (None, Some(list), _) if !list.is_empty() => {
                return Err(AircraftError::Invalid {
                    field: "propeller.blade.thickness_ratio",
                    value: 0.0,
                    reason: "entries: needed with propeller.sections".into(),
                })
            }
            _ => {
                return Err(AircraftError::Invalid {
                    field: "propeller.section_table",
                    value: 0.0,
                    reason: "entries: give either section_table or sections (one or more)".into(),
                })
            }
        }
        positive("propeller.calib_engine_rpm", self.calib_engine_rpm)?;
        let b = &self.blade;
        positive("propeller.blade.diameter_m", b.diameter_m)?;
        in_range(
            "propeller.blade.blades",
            f64::from(b.blades),
            (1.0, 12.0),
            "must be between 1 and 12",
        )?;
        let x = &b.r_over_r;
        if x.len() < 2 {
            return Err(AircraftError::Invalid {
                field: "propeller.blade.r_over_r",
                value: x.len() as f64,
                reason: "entries: needs at least two stations".into(),
            });
        }
        each(
            "propeller.blade.r_over_r",
            x,
            |v| v > 0.0 && v <= 1.0,
            "must be in (0, 1]",
        )?;
        increasing("propeller.blade.r_over_r", x)?;
        if x[0] > 0.75 {
            return Err(AircraftError::Invalid {
                field: "propeller.blade.r_over_r",
                value: x[0],
                reason: "the blade must start inboard of 0.75 R (its reference station)".into(),
            });
        }
        same_length(
            "propeller.blade.chord_over_diameter",
            &b.chord_over_diameter,
            x.len(),
            "r_over_r",
        )?;
        same_length(
            "propeller.blade.twist_deg",
            &b.twist_deg,
            x.len(),
            "r_over_r",
        )?;
        each(
            "propeller.blade.chord_over_diameter",
            &b.chord_over_diameter,
            |v| v > 0.0 && v < 1.0,
            "must be in (0, 1)",
        )?;
        each(
            "propeller.blade.twist_deg",
            &b.twist_deg,
            |v| v.abs() <= 90.0,
            "must be within ±90°",
        )?;
        in_range(
            "propeller.blade.annuli",
            b.annuli as f64,
            (4.0, 200.0),
            "must be between 4 and 200",
        )
    }
}

impl EngineParams {
    /// Checks the gear and the torque curve; the maximum rpm must reach `calib_engine_rpm`.
    pub(super) fn validate(&self, calib_engine_rpm: f64) -> Result<(), AircraftError> {
        in_range(
            "engine.gear_ratio",
            self.gear_ratio,
            (f64::MIN_POSITIVE, 10.0),
            "must be above 0 and at most 10",
        )?;
        in_range(
            "engine.gear_efficiency",
            self.gear_efficiency,
            (0.5, 1.0),
            "must be between 0.5 and 1",
        )?;
        positive("engine.max_rpm", self.max_rpm)?;
        if self.max_rpm < calib_engine_rpm {
            return Err(AircraftError::Invalid {
                field: "engine.max_rpm",
                value: self.max_rpm,
                reason: "must be at least the calibration engine rpm".into(),
            });
        }
        if self.torque_rpm.is_empty() {
            return Err(AircraftError::Invalid {
                field: "engine.torque_rpm",
                value: 0.0,
                reason: "entries: needs at least one point".into(),
            });
        }
        each(
            "engine.torque_rpm",
            &self.torque_rpm,
            |v| v.is_finite() && v > 0.0,
            "must be positive",
        )?;
        increasing("engine.torque_rpm", &self.torque_rpm)?;
        same_length(
            "engine.torque_nm",
            &self.torque_nm,
            self.torque_rpm.len(),
            "torque_rpm",
        )?;
        each(
            "engine.torque_nm",
            &self.torque_nm,
            |v| v.is_finite() && v > 0.0,
            "must be positive",
        )
    }
}
