//! Aircraft preset: rotor, airframe, propeller, engine and takeoff data, loaded from TOML.
//! The propeller's section table is named in the preset (relative to the preset's folder) and
//! read with it.

use super::atmosphere::{Atmosphere, MAX_ISA_ALTITUDE_M};
use super::inflow::{InflowModel, TipLoss, YawedFlow};
use super::propeller::{PropellerSections, SharedSection};
use crate::arguments::ArgumentError;
use crate::input::{read_input, InputError};
use crate::section::SectionAero;
use crate::table::{read_lookup_table, PolarTable, TableError};
use checks::{in_range, non_negative, positive};
use serde::Deserialize;
use std::borrow::Cow;
use std::path::Path;
use std::sync::Arc;

mod checks;
mod powerplant;
mod wing;

pub use powerplant::{BladeGeometry, EngineParams, PropellerParams, SectionFile};
pub use wing::{WingError, WingLoads, WingParams};

/// Errors while loading or checking an aircraft preset.
#[derive(Debug, thiserror::Error)]
pub enum AircraftError {
    /// The file could not be read: missing, not a regular file, too large or unreadable.
    #[error("cannot read aircraft file {}: {}", .0.path.display(), .0.problem)]
    Input(#[source] InputError),
    /// The file is not UTF-8 text.
    #[error("bad aircraft file {path}: not UTF-8 text")]
    NotText {
        /// File path.
        path: String,
    },
    /// The TOML is malformed, has a missing field or an unknown one.
    #[error("bad aircraft file {path}: {message}")]
    Parse {
        /// File path.
        path: String,
        /// The parser's message, folded onto one line.
        message: String,
    },
    /// The propeller's section table cannot be read.
    #[error("aircraft file {path}: propeller.section_table")]
    PropellerSection {
        /// The aircraft file.
        path: String,
        /// Why.
        #[source]
        source: TableError,
    },
    /// The wing's section table cannot be read.
    #[error("aircraft file {path}: wing.section_table")]
    WingSection {
        /// The aircraft file.
        path: String,
        /// Why.
        #[source]
        source: TableError,
    },
    /// The `[wing]` table does not describe one section model.
    #[error("aircraft [wing]: {0}")]
    WingModel(&'static str),
    /// A value is outside its physical range.
    #[error("aircraft parameter {field} = {} is invalid: {reason}", short_number(*value))]
    Invalid {
        /// Dotted field name.
        field: &'static str,
        /// Offending value.
        value: f64,
        /// What is required.
        reason: Cow<'static, str>,
    },
}

use crate::limits::short_number;
use crate::limits::{
    AZIMUTH_STEPS, MAX_ROTOR_CELLS, MAX_TAKEOFF_CELL_STEPS, MAX_TAKEOFF_STEPS, RADIAL_STRIPS,
};
pub use crate::limits::{MAX_MASS_KG, MAX_SPEED_KT};

/// An airspeed argument \[kt\] (of `gyro` and the Python package): above 0 and below
/// [`MAX_SPEED_KT`].
pub fn check_speed_kt(name: &str, kt: f64) -> Result<(), ArgumentError> {
    if kt.is_finite() && kt > 0.0 && kt < MAX_SPEED_KT {
        return Ok(());
    }
    Err(ArgumentError::new(
        name,
        kt,
        format!("must be above 0 and below {MAX_SPEED_KT} kt"),
    ))
}

/// A mass argument that replaces the preset's \[kg\]: positive, at most [`MAX_MASS_KG`].
pub fn check_mass_kg(name: &str, kg: f64) -> Result<(), ArgumentError> {
    if kg.is_finite() && kg > 0.0 && kg <= MAX_MASS_KG {
        return Ok(());
    }
    Err(ArgumentError::new(
        name,
        kg,
        format!("must be a positive number of kg, at most {MAX_MASS_KG}"),
    ))
}

/// A blade radius argument as a fraction of R: on the blade, outboard of the root cut-out.
pub fn check_blade_radius(
    name: &str,
    radius: f64,
    aircraft: &Aircraft,
) -> Result<(), ArgumentError> {
    let root = aircraft.rotor.root_cutout_m / aircraft.rotor.radius_m;
    if radius > root && radius <= 1.0 {
        return Ok(());
    }
    let rule = format!(
        "must be a fraction of R on the blade, in ({root:.3}, 1] (outboard of the {} m root \
         cut-out)",
        aircraft.rotor.root_cutout_m
    );
    Err(ArgumentError::new(name, radius, rule))
}

/// An azimuth sample count per revolution, within [`AZIMUTH_SAMPLES`](crate::limits::AZIMUTH_SAMPLES).
pub fn check_azimuth_samples(name: &str, samples: usize) -> Result<(), ArgumentError> {
    let (lo, hi) = crate::limits::AZIMUTH_SAMPLES;
    if (lo..=hi).contains(&samples) {
        return Ok(());
    }
    let rule = format!("must be between {lo} and {hi}");
    Err(ArgumentError::with_text(name, samples.to_string(), rule))
}

/// An ISA altitude argument \[m\]: inside the troposphere of the atmosphere model.
pub fn check_altitude_m(name: &str, m: f64) -> Result<(), ArgumentError> {
    if (0.0..=MAX_ISA_ALTITUDE_M).contains(&m) {
        return Ok(());
    }
    Err(ArgumentError::new(
        name,
        m,
        format!("must be within the ISA troposphere, 0 to {MAX_ISA_ALTITUDE_M} m"),
    ))
}

/// Accepted takeoff integration time steps \[s\]: below, a run takes hundreds of thousands of
/// steps; above, the integration of the rotor speed and flapping is no longer resolved.
const TAKEOFF_TIME_STEP_RANGE_S: (f64, f64) = (1e-3, 0.1);

/// Longest accepted simulated takeoff time \[s\].
const TAKEOFF_MAX_TIME_S: f64 = 600.0;

/// Whole-aircraft data.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Aircraft {
    /// Aircraft name (for reports).
    pub name: String,
    /// Takeoff mass \[kg\].
    pub mass_kg: f64,
    /// Equivalent parasitic drag area S_P·C_DP of the airframe without rotor \[m²\].
    pub parasitic_drag_area_m2: f64,
    /// Rotor data.
    pub rotor: RotorParams,
    /// Propeller data.
    pub propeller: PropellerParams,
    /// Engine and reduction gear.
    pub engine: EngineParams,
    /// Takeoff procedure data.
    pub takeoff: TakeoffParams,
    /// Fixed wing (none, or zero area, = a pure gyroplane).
    #[serde(default)]
    pub wing: Option<WingParams>,
    /// The propeller's section tables with their thickness ratios (NaN for the one table of
    /// `section_table`), read with the preset.
    #[serde(skip)]
    propeller_sections: Vec<(f64, Arc<PolarTable>)>,
    /// The wing's section table, read with the preset when its `[wing]` names one.
    #[serde(skip)]
    wing_section: Option<Arc<PolarTable>>,
}

/// Rotor geometry, mass and discretisation.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RotorParams {
    /// Rotor radius R \[m\].
    pub radius_m: f64,
    /// Number of blades (a teetering rotor has 2).
    pub blades: u32,
    /// Blade chord c \[m\] (constant, untwisted blade).
    pub chord_m: f64,
    /// Blade incidence θ relative to the hub plane \[deg\] (fixed, no collective or cyclic).
    pub incidence_deg: f64,
    /// Root cut-out: radius where the aerodynamic blade starts \[m\].
    pub root_cutout_m: f64,
    /// Built-in coning of the hub bar β0 \[deg\] (a teetering rotor's coning is fixed by the hub).
    pub precone_deg: f64,
    /// Mass of one blade \[kg\] (uniform spanwise distribution assumed for the inertia).
    pub blade_mass_kg: f64,
    /// Polar moment of inertia of hub, teeter block and bolts about the shaft \[kg m²\].
    pub hub_inertia_kg_m2: f64,
    /// Teeter stops: largest teeter amplitude before the blades hit the stops \[deg\].
    pub flap_stop_deg: f64,
    /// Number of radial strips.
    pub radial_strips: usize,
    /// Number of azimuth steps per revolution (even, so both blades sit on the grid).
    pub azimuth_steps: usize,
    /// Tip-loss model: "prandtl", "gessow_myers", "chord" or "none" ([`TipLoss`]).
    pub tip_loss: TipLoss,
    /// Profile drag in yawed (radial) flow: "radial_drag" or "none" ([`YawedFlow`]).
    pub yawed_flow: YawedFlow,
    /// Induced-inflow model: "glauert" (uniform) or "drees" (linear).
    pub inflow: InflowModel,
    /// Induced-power factor κ (induced velocity = κ × Glauert's momentum value, see
    /// [`crate::rotor::Rotor::induced_power_factor`]); omitted → 1 (ideal momentum theory).
    #[serde(default = "ideal_induced_power_factor")]
    pub induced_power_factor: f64,
}

/// κ = 1: ideal momentum theory (the default when a preset omits the factor).
fn ideal_induced_power_factor() -> f64 {
    1.0
}

/// Takeoff procedure and ground data.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TakeoffParams {
    /// Rotor speed when the brake is released \[rpm\].
    pub prerotation_rpm: f64,
    /// Rotor head pitch with the stick full aft \[deg\] (fuselage level on the ground).
    pub head_angle_max_deg: f64,
    /// Smallest rotor-disc angle the pilot model commands in the climb \[deg\].
    pub head_angle_min_deg: f64,
    /// Rolling-friction coefficient of the wheels.
    pub rolling_friction: f64,
    /// Airspeed the pilot accelerates to during the climb, reached at the screen height \[kt\]
    /// (see [`crate::rotor::simulate_takeoff`] for the pilot model).
    pub climb_speed_kt: f64,
    /// Pilot gain: rate of change of the rotor-disc angle per airspeed error [deg/s per m/s].
    pub pilot_gain_deg_per_ms: f64,
    /// Pilot (and control-system) time constant \[s\].
    pub pilot_time_constant_s: f64,
    /// Screen height \[m\].
    pub screen_height_m: f64,
    /// Airfield altitude \[m\] (ISA).
    pub field_altitude_m: f64,
    /// Integration time step \[s\].
    pub time_step_s: f64,
    /// Give up after this time \[s\].
    pub max_time_s: f64,
}

impl Aircraft {
    /// Reads and checks a TOML preset.
    pub fn from_toml_file(path: &Path) -> Result<Self, AircraftError> {
        let bytes = read_input(path).map_err(AircraftError::Input)?;
        let origin = path.display().to_string();
        let text = String::from_utf8(bytes).map_err(|_| AircraftError::NotText {
            path: origin.clone(),
        })?;
        Self::from_toml_str(&text, &origin)
    }

    /// Parses and checks a TOML preset held in memory and reads its propeller (and wing)
    /// section table; `origin` names it in errors, and the tables' paths are relative to
    /// `origin`'s folder (the current folder when `origin` has none).
    pub fn from_toml_str(text: &str, origin: &str) -> Result<Self, AircraftError> {
        let mut aircraft = Self::parse_toml(text, origin)?;
        let folder = Path::new(origin).parent().unwrap_or(Path::new(""));
        let read = |file: &Path| {
            read_lookup_table(&folder.join(file)).map_err(|source| {
                AircraftError::PropellerSection {
                    path: origin.to_string(),
                    source,
                }
            })
        };
        let p = &aircraft.propeller;
        let sections = match (&p.section_table, &p.sections) {
            (Some(file), _) => vec![(f64::NAN, Arc::new(read(file)?))],
            (None, Some(list)) => list
                .iter()
                .map(|s| Ok((s.thickness_ratio, Arc::new(read(&s.table)?))))
                .collect::<Result<_, AircraftError>>()?,
            (None, None) => Vec::new(),
        };
        if let Some(path) = aircraft
            .wing
            .as_ref()
            .and_then(|w| w.section_table.as_ref())
        {
            let wing = read_lookup_table(&folder.join(path)).map_err(|source| {
                AircraftError::WingSection {
                    path: origin.to_string(),
                    source,
                }
            })?;
            aircraft.wing_section = Some(Arc::new(wing));
        }
        aircraft.propeller_sections = sections;
        Ok(aircraft)
    }

    /// Parses and checks a TOML preset held in memory without reading its propeller section
    /// tables (give them with [`Aircraft::with_propeller_section`] or
    /// [`Aircraft::with_propeller_sections`]); `origin` names it in errors.
    pub fn parse_toml(text: &str, origin: &str) -> Result<Self, AircraftError> {
        let aircraft: Aircraft = toml::from_str(text).map_err(|e| AircraftError::Parse {
            path: origin.to_string(),
            message: e.message().replace('\n', " "),
        })?;
        aircraft.validate()?;
        Ok(aircraft)
    }

    /// The preset with `table` as its propeller section along the whole blade.
    pub fn with_propeller_section(mut self, table: PolarTable) -> Self {
        self.propeller_sections = vec![(f64::NAN, Arc::new(table))];
        self
    }

    /// The preset with `tables` as its propeller's sections by thickness ratio
    /// (`(t/c, table)`), in the order of the preset's `propeller.sections`.
    pub fn with_propeller_sections(mut self, tables: Vec<(f64, PolarTable)>) -> Self {
        self.propeller_sections = tables.into_iter().map(|(t, s)| (t, Arc::new(s))).collect();
        self
    }

    /// The propeller's sections, read with the preset (`None` before they are given).
    pub fn propeller_sections(&self) -> Option<PropellerSections> {
        let members = &self.propeller_sections;
        let shared = |t: &Arc<PolarTable>| Arc::clone(t) as SharedSection;
        match members.as_slice() {
            [] => None,
            [(t, table)] if t.is_nan() => Some(PropellerSections::single(shared(table))),
            _ => PropellerSections::by_thickness(
                members.iter().map(|(t, s)| (*t, shared(s))).collect(),
            )
            .ok(),
        }
    }

    /// The propeller's section tables with their thickness ratios (NaN for one table along
    /// the whole blade).
    pub fn propeller_tables(&self) -> &[(f64, Arc<PolarTable>)] {
        &self.propeller_sections
    }

    /// The preset with its wing's area set to `area_m2` at the same span, incidence and
    /// section (the chord scales); fails without a `[wing]` or for a negative area.
    pub fn with_wing_area(&self, area_m2: f64) -> Result<Self, AircraftError> {
        let mut aircraft = self.clone();
        let wing = aircraft.wing.as_mut().ok_or(AircraftError::WingModel(
            "the aircraft file has no [wing] to scale",
        ))?;
        wing.area_m2 = area_m2;
        wing.validate()?;
        Ok(aircraft)
    }

    /// Lift and drag of the wing at airspeed `v` \[m/s\] in `atmosphere`
    /// ([`WingLoads::NONE`] without a wing or with zero area).
    pub fn wing_loads(&self, atmosphere: &Atmosphere, v: f64) -> Result<WingLoads, WingError> {
        match &self.wing {
            None => Ok(WingLoads::NONE),
            Some(w) => w.loads(
                self.wing_section
                    .as_deref()
                    .map(|t| t as &(dyn SectionAero + Send + Sync)),
                atmosphere,
                v,
            ),
        }
    }

    /// Whether the aircraft has a wing of non-zero area.
    pub fn has_wing(&self) -> bool {
        self.wing.as_ref().is_some_and(|w| w.area_m2 > 0.0)
    }

    /// Aircraft weight G = m·g0 \[N\].
    pub fn weight_n(&self) -> f64 {
        self.mass_kg * super::G0
    }

    /// Checks every value for its physical range.
    pub fn validate(&self) -> Result<(), AircraftError> {
        let r = &self.rotor;
        in_range(
            "mass_kg",
            self.mass_kg,
            (f64::MIN_POSITIVE, MAX_MASS_KG),
            "must be positive and at most 100000 kg",
        )?;
        non_negative("parasitic_drag_area_m2", self.parasitic_drag_area_m2)?;
        positive("rotor.radius_m", r.radius_m)?;
        positive("rotor.chord_m", r.chord_m)?;
        non_negative("rotor.root_cutout_m", r.root_cutout_m)?;
        if r.root_cutout_m >= r.radius_m {
            return Err(AircraftError::Invalid {
                field: "rotor.root_cutout_m",
                value: r.root_cutout_m,
                reason: "must be smaller than the radius".into(),
            });
        }
        if r.blades != 2 {
            return Err(AircraftError::Invalid {
                field: "rotor.blades",
                value: f64::from(r.blades),
                reason: "the teetering-rotor model needs exactly 2 blades".into(),
            });
        }
        if !r.incidence_deg.is_finite() || r.incidence_deg.abs() > 20.0 {
            return Err(AircraftError::Invalid {
                field: "rotor.incidence_deg",
                value: r.incidence_deg,
                reason: "must be within ±20°".into(),
            });
        }
        if !r.precone_deg.is_finite() || r.precone_deg.abs() > 10.0 {
            return Err(AircraftError::Invalid {
                field: "rotor.precone_deg",
                value: r.precone_deg,
                reason: "must be within ±10°".into(),
            });
        }
        positive("rotor.blade_mass_kg", r.blade_mass_kg)?;
        non_negative("rotor.hub_inertia_kg_m2", r.hub_inertia_kg_m2)?;
        positive("rotor.flap_stop_deg", r.flap_stop_deg)?;
        if !(RADIAL_STRIPS.0..=RADIAL_STRIPS.1).contains(&r.radial_strips) {
            return Err(AircraftError::Invalid {
                field: "rotor.radial_strips",
                value: r.radial_strips as f64,
                reason: format!(
                    "must be between {} and {}",
                    RADIAL_STRIPS.0, RADIAL_STRIPS.1
                )
                .into(),
            });
        }
        if !(AZIMUTH_STEPS.0..=AZIMUTH_STEPS.1).contains(&r.azimuth_steps)
            || r.azimuth_steps % 2 != 0
        {
            return Err(AircraftError::Invalid {
                field: "rotor.azimuth_steps",
                value: r.azimuth_steps as f64,
                reason: format!(
                    "must be even and between {} and {}",
                    AZIMUTH_STEPS.0, AZIMUTH_STEPS.1
                )
                .into(),
            });
        }
        if r.cells() > MAX_ROTOR_CELLS {
            return Err(AircraftError::Invalid {
                field: "rotor.azimuth_steps",
                value: r.azimuth_steps as f64,
                reason: format!(
                    "with {} radial strips gives {} blade-element cells, more than the limit \
                     of {MAX_ROTOR_CELLS} (radial_strips × azimuth_steps; every rotor \
                     evaluation costs in proportion)",
                    r.radial_strips,
                    r.cells()
                )
                .into(),
            });
        }
        if !(r.induced_power_factor >= 1.0 && r.induced_power_factor <= 2.0) {
            return Err(AircraftError::Invalid {
                field: "rotor.induced_power_factor",
                value: r.induced_power_factor,
                reason: "must be between 1 and 2".into(),
            });
        }
        self.propeller.validate()?;
        if let Some(w) = &self.wing {
            w.validate()?;
        }
        self.engine.validate(self.propeller.calib_engine_rpm)?;
        let t = &self.takeoff;
        positive("takeoff.prerotation_rpm", t.prerotation_rpm)?;
        positive("takeoff.head_angle_max_deg", t.head_angle_max_deg)?;
        if !t.head_angle_min_deg.is_finite() || t.head_angle_min_deg >= t.head_angle_max_deg {
            return Err(AircraftError::Invalid {
                field: "takeoff.head_angle_min_deg",
                value: t.head_angle_min_deg,
                reason: "must be below head_angle_max_deg".into(),
            });
        }
        non_negative("takeoff.rolling_friction", t.rolling_friction)?;
        in_range(
            "takeoff.climb_speed_kt",
            t.climb_speed_kt,
            (f64::MIN_POSITIVE, MAX_SPEED_KT),
            "must be above 0 and at most 300 kt",
        )?;
        non_negative("takeoff.pilot_gain_deg_per_ms", t.pilot_gain_deg_per_ms)?;
        positive("takeoff.pilot_time_constant_s", t.pilot_time_constant_s)?;
        positive("takeoff.screen_height_m", t.screen_height_m)?;
        in_range(
            "takeoff.field_altitude_m",
            t.field_altitude_m,
            (0.0, MAX_ISA_ALTITUDE_M),
            format!("must be within the ISA troposphere, 0 to {MAX_ISA_ALTITUDE_M} m"),
        )?;
        in_range(
            "takeoff.time_step_s",
            t.time_step_s,
            TAKEOFF_TIME_STEP_RANGE_S,
            "must be between 0.001 and 0.1 s",
        )?;
        in_range(
            "takeoff.max_time_s",
            t.max_time_s,
            (t.time_step_s, TAKEOFF_MAX_TIME_S),
            "must be between one time step and 600 s",
        )?;
        let steps = t.max_time_s / t.time_step_s;
        if steps > MAX_TAKEOFF_STEPS as f64 {
            return Err(AircraftError::Invalid {
                field: "takeoff.max_time_s",
                value: t.max_time_s,
                reason: format!(
                    "gives more than {MAX_TAKEOFF_STEPS} time steps (max_time_s / time_step_s)"
                )
                .into(),
            });
        }
        if steps * r.cells() as f64 > MAX_TAKEOFF_CELL_STEPS as f64 {
            return Err(AircraftError::Invalid {
                field: "takeoff.max_time_s",
                value: t.max_time_s,
                reason: format!(
                    "gives {steps:.0} time steps of {} rotor cells, more than the limit of \
                     {MAX_TAKEOFF_CELL_STEPS} steps × cells",
                    r.cells()
                )
                .into(),
            });
        }
        Ok(())
    }
}

impl RotorParams {
    /// Blade-element cells of one rotor evaluation: radial strips × azimuth steps.
    pub fn cells(&self) -> usize {
        self.radial_strips.saturating_mul(self.azimuth_steps)
    }

    /// Polar moment of inertia of the rotor about the shaft \[kg m²\]: hub plus N_b uniform
    /// blades spanning root cut-out r0 … R, I_b = m_b (R³ − r0³) / (3 (R − r0)).
    pub fn polar_inertia(&self) -> f64 {
        let (r0, r1) = (self.root_cutout_m, self.radius_m);
        let blade = self.blade_mass_kg * (r1.powi(3) - r0.powi(3)) / (3.0 * (r1 - r0));
        self.hub_inertia_kg_m2 + f64::from(self.blades) * blade
    }

    /// Rotor disc area A = πR² \[m²\].
    pub fn disc_area(&self) -> f64 {
        std::f64::consts::PI * self.radius_m * self.radius_m
    }
}
