//! The optional fixed wing of a preset: its planform, its section (a linear lift curve or a
//! polar table) and its lift and drag in level flight.
//!
//! Geometry: the wing is fixed to the fuselage at `incidence_deg`, so its angle of attack is
//! the fuselage's plus the incidence. The model has no pitching-moment balance, so nothing in
//! it sets the fuselage attitude; the fuselage is taken to fly level, along the flight path,
//! at every speed (the paper's takeoff has it level on the ground roll). The wing's angle of
//! attack is then its incidence, its lift acts normal to the flight path and its drag along
//! it. The rotor's downwash on the wing and the wing's upwash on the rotor are not modelled.
//!
//! Section to wing: Prandtl's lifting line with the span efficiency e (Anderson,
//! *Fundamentals of Aerodynamics*, 5th ed., §5.3): the section works at the effective angle
//! α_eff = α − C_L/(π e AR), so C_L = c_l(α_eff), and the induced drag is C_L²/(π e AR)
//! (e stands for both Glauert's slope factor 1/(1+τ) and the drag factor 1/(1+δ), the usual
//! approximation, e.g. Raymer, *Aircraft Design*, §12.6). A linear section
//! c_l = a0 (α − α_0) gives the closed form C_L = a0 (α − α_0)/(1 + a0/(π e AR)).

use super::checks::{non_negative, positive};
use super::AircraftError;
use crate::numerics::roots::bracketed_root_of;
use crate::rotor::atmosphere::Atmosphere;
use crate::section::SectionAero;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;
use std::path::PathBuf;

/// Bracket of the wing lift coefficient searched by the lifting-line solve: |C_L| ≤ 4 holds
/// every section table (the 360° post-stall model stays below 2.5).
const LIFT_COEFFICIENT_BRACKET: f64 = 4.0;

/// Tolerance of the lifting-line solve on C_L.
const LIFT_COEFFICIENT_TOLERANCE: f64 = 1e-10;

/// Iteration limit of the lifting-line solve.
const LIFTING_LINE_ITERATIONS: usize = 100;

/// The `[wing]` table of a preset. The section is either linear (`lift_slope_per_rad`,
/// `alpha_zero_lift_deg`, optional `cl_max`, `cd0`) or a polar table (`section_table`,
/// optional `cd0` added to its profile drag).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WingParams {
    /// Planform area S \[m²\]; 0 = no wing.
    pub area_m2: f64,
    /// Span b \[m\].
    pub span_m: f64,
    /// Incidence to the fuselage datum \[deg\]: the wing's angle of attack with the fuselage
    /// level (see the module documentation).
    pub incidence_deg: f64,
    /// Span (Oswald) efficiency e in (0, 1].
    pub oswald_e: f64,
    /// Linear section: lift-curve slope a0 = dc_l/dα of the airfoil section \[1/rad\] (the
    /// wing's follows from the lifting line).
    pub lift_slope_per_rad: Option<f64>,
    /// Linear section: zero-lift angle α_0 \[deg\].
    pub alpha_zero_lift_deg: Option<f64>,
    /// Linear section: largest wing lift coefficient (the wing stalls there; none = no
    /// limit).
    pub cl_max: Option<f64>,
    /// Zero-lift (profile) drag coefficient; with a section table the drag added to the
    /// table's profile drag (fittings, interference), 0 if omitted.
    pub cd0: Option<f64>,
    /// Polar table of the section, a path relative to the preset's folder (read through the
    /// crate's table reader with the preset).
    pub section_table: Option<PathBuf>,
}

/// Why the wing's loads could not be computed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("wing: {0}")]
pub struct WingError(pub &'static str);

/// Lift and drag of the wing at one flight condition.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct WingLoads {
    /// Lift L_W = q S C_L \[N\], normal to the flight path.
    pub lift_n: f64,
    /// Drag D_W = q S (C_D0 + C_L²/(π e AR)) \[N\], along the flight path.
    pub drag_n: f64,
    /// Wing lift coefficient C_L.
    pub lift_coefficient: f64,
    /// Induced drag coefficient C_L²/(π e AR).
    pub induced_drag_coefficient: f64,
    /// The wing works beyond its linear range: C_L capped at `cl_max`, or the section table
    /// answered from its post-stall model.
    pub stalled: bool,
    /// The section table's Reynolds or Mach range did not cover the wing (edge values used).
    pub table_clamped: bool,
}

/// Largest wing area accepted \[m²\] (a gyroplane's stub wing has a few; a sanity bound).
const MAX_WING_AREA_M2: f64 = 100.0;

/// Largest wing span accepted \[m\] (a sanity bound).
const MAX_WING_SPAN_M: f64 = 50.0;
impl WingLoads {
    /// No wing: zero lift and drag.
    pub const NONE: Self = Self {
        lift_n: 0.0,
        drag_n: 0.0,
        lift_coefficient: 0.0,
        induced_drag_coefficient: 0.0,
        stalled: false,
        table_clamped: false,
    };
}

impl WingParams {
    /// Aspect ratio AR = b²/S.
    pub fn aspect_ratio(&self) -> f64 {
        self.span_m * self.span_m / self.area_m2
    }

    /// Checks the planform, the efficiency and that exactly one section model is given.
    pub(super) fn validate(&self) -> Result<(), AircraftError> {
        super::checks::in_range(
            "wing.area_m2",
            self.area_m2,
            (0.0, MAX_WING_AREA_M2),
            "must be 0 to 100 m² (a gyroplane's stub wing has a few)",
        )?;
        super::checks::in_range(
            "wing.span_m",
            self.span_m,
            (f64::MIN_POSITIVE, MAX_WING_SPAN_M),
            "must be positive and at most 50 m",
        )?;
        if !(self.incidence_deg.is_finite() && self.incidence_deg.abs() <= 20.0) {
            return Err(AircraftError::Invalid {
                field: "wing.incidence_deg",
                value: self.incidence_deg,
                reason: "must be within ±20°".into(),
            });
        }
        if !(self.oswald_e > 0.0 && self.oswald_e <= 1.0) {
            return Err(AircraftError::Invalid {
                field: "wing.oswald_e",
                value: self.oswald_e,
                reason: "must be in (0, 1]".into(),
            });
        }
        if let Some(cd0) = self.cd0 {
            non_negative("wing.cd0", cd0)?;
        }
        let linear = [
            self.lift_slope_per_rad,
            self.alpha_zero_lift_deg,
            self.cl_max,
        ];
        match (
            &self.section_table,
            self.lift_slope_per_rad,
            self.alpha_zero_lift_deg,
        ) {
            (Some(_), ..) if linear.iter().any(Option::is_some) => Err(AircraftError::WingModel(
                "give either section_table or lift_slope_per_rad/alpha_zero_lift_deg/cl_max, \
                 not both",
            )),
            (Some(_), ..) => Ok(()),
            (None, Some(a0), Some(alpha0)) => {
                non_negative("wing.lift_slope_per_rad", a0)?;
                if !(alpha0.is_finite() && alpha0.abs() <= 20.0) {
                    return Err(AircraftError::Invalid {
                        field: "wing.alpha_zero_lift_deg",
                        value: alpha0,
                        reason: "must be within ±20°".into(),
                    });
                }
                if let Some(cl_max) = self.cl_max {
                    positive("wing.cl_max", cl_max)?;
                }
                match self.cd0 {
                    Some(_) => Ok(()),
                    None => Err(AircraftError::WingModel(
                        "a linear section needs cd0, its zero-lift drag coefficient",
                    )),
                }
            }
            (None, ..) => Err(AircraftError::WingModel(
                "needs either lift_slope_per_rad and alpha_zero_lift_deg or section_table",
            )),
        }
    }

    /// Lift and drag at airspeed `v` \[m/s\] in `atmosphere`, with `section` the preset's wing
    /// table (`None` for a linear section). Zero area gives [`WingLoads::NONE`].
    pub(super) fn loads(
        &self,
        section: Option<&(dyn SectionAero + Send + Sync)>,
        atmosphere: &Atmosphere,
        v: f64,
    ) -> Result<WingLoads, WingError> {
        if self.area_m2 == 0.0 {
            return Ok(WingLoads::NONE);
        }
        let k = PI * self.oswald_e * self.aspect_ratio();
        let alpha = self.incidence_deg.to_radians();
        let cd0 = self.cd0.unwrap_or(0.0);
        let (cl, cd_profile, stalled, table_clamped) = match (self.section_table.as_ref(), section)
        {
            (None, _) => {
                let a0 = self.lift_slope_per_rad.unwrap_or(0.0);
                let alpha0 = self.alpha_zero_lift_deg.unwrap_or(0.0).to_radians();
                let unlimited = a0 * (alpha - alpha0) / (1.0 + a0 / k);
                let cap = self.cl_max.unwrap_or(f64::INFINITY);
                (
                    unlimited.clamp(-cap, cap),
                    cd0,
                    unlimited.abs() > cap,
                    false,
                )
            }
            (Some(_), None) => {
                return Err(WingError("its section_table was not read with the preset"))
            }
            (Some(_), Some(section)) => {
                let chord = self.area_m2 / self.span_m;
                let re = atmosphere.density * v * chord / atmosphere.viscosity;
                let mach = v / atmosphere.speed_of_sound;
                let at = |cl: f64| section.lookup((alpha - cl / k).to_degrees(), re, mach);
                let excess = |cl: f64| cl - at(cl).cl;
                let b = LIFT_COEFFICIENT_BRACKET;
                let (lo, hi) = (excess(-b), excess(b));
                if !(lo < 0.0 && hi > 0.0) {
                    return Err(WingError(
                        "the section table's lift coefficient leaves ±4: no lifting-line solution",
                    ));
                }
                let cl = bracketed_root_of(
                    excess,
                    (-b, lo),
                    (b, hi),
                    LIFT_COEFFICIENT_TOLERANCE,
                    LIFTING_LINE_ITERATIONS,
                );
                let l = at(cl);
                (cl, l.cd + cd0, l.post_stall, l.re_clamped || l.mach_clamped)
            }
        };
        let induced = cl * cl / k;
        let q_s = atmosphere.dynamic_pressure(v) * self.area_m2;
        Ok(WingLoads {
            lift_n: q_s * cl,
            drag_n: q_s * (cd_profile + induced),
            lift_coefficient: cl,
            induced_drag_coefficient: induced,
            stalled,
            table_clamped,
        })
    }
}
