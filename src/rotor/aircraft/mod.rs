//! Aircraft preset: rotor, airframe, propeller, engine and takeoff data, loaded from TOML.
//! The propeller's section table is named in the preset (relative to the preset's folder) and
//! read with it.

use super::atmosphere::{Atmosphere, MAX_ISA_ALTITUDE_M};
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
mod rotor_params;
mod wing;

pub use powerplant::{BladeGeometry, EngineParams, PropellerParams, SectionFile};
pub use rotor_params::{
    BladeParams, HubParams, RotorParams, RotorPreset, TorsionParams, MAX_BLADES,
};
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
    #[error("aircraft file {path}: {field}")]
    PropellerSection {
        /// The aircraft file.
        path: String,
        /// The field that names the table: `propeller.section_table`, or
        /// `propeller.sections[K].table` (K from 0).
        field: String,
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
    /// A value a whole aircraft needs is not given.
    #[error("aircraft parameter {field} is missing: {reason}")]
    Missing {
        /// Dotted field name.
        field: &'static str,
        /// What needs it.
        reason: &'static str,
    },
    /// The file describes a rotor alone, where a whole aircraft is needed.
    #[error(
        "aircraft file {path} describes a rotor alone (no [propeller], [engine], [takeoff]): \
         this needs a whole aircraft"
    )]
    RotorOnly {
        /// The file.
        path: String,
    },
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
pub use crate::limits::{MAX_MASS_KG, MAX_SPEED_KT};
use crate::limits::{MAX_TAKEOFF_CELL_STEPS, MAX_TAKEOFF_STEPS};

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

/// The text of the preset file at `path` (a regular file within the input limits, UTF-8)
/// and the name errors give it.
pub(super) fn read_preset_text(path: &Path) -> Result<(String, String), AircraftError> {
    let bytes = read_input(path).map_err(AircraftError::Input)?;
    let origin = path.display().to_string();
    let text = String::from_utf8(bytes).map_err(|_| AircraftError::NotText {
        path: origin.clone(),
    })?;
    Ok((text, origin))
}

/// Largest parasitic drag area accepted \[m²\] (a gyroplane's is below 1 m²; 100 m² bounds a
/// typo).
const MAX_DRAG_AREA_M2: f64 = 100.0;

/// Largest takeoff screen height accepted \[m\] (the certification screens are 15 m and
/// 50 ft).
const MAX_SCREEN_HEIGHT_M: f64 = 100.0;
impl Aircraft {
    /// Reads and checks a TOML preset.
    pub fn from_toml_file(path: &Path) -> Result<Self, AircraftError> {
        let (text, origin) = read_preset_text(path)?;
        Self::from_toml_str(&text, &origin)
    }

    /// Parses and checks a TOML preset held in memory and reads its propeller (and wing)
    /// section table; `origin` names it in errors, and the tables' paths are relative to
    /// `origin`'s folder (the current folder when `origin` has none).
    pub fn from_toml_str(text: &str, origin: &str) -> Result<Self, AircraftError> {
        let mut aircraft = Self::parse_toml(text, origin)?;
        let folder = Path::new(origin).parent().unwrap_or(Path::new(""));
        let read = |file: &Path, field: String| {
            read_lookup_table(&folder.join(file)).map_err(|source| {
                AircraftError::PropellerSection {
                    path: origin.to_string(),
                    field,
                    source,
                }
            })
        };
        let p = &aircraft.propeller;
        let sections = match (&p.section_table, &p.sections) {
            (Some(file), _) => vec![(
                f64::NAN,
                Arc::new(read(file, "propeller.section_table".into())?),
            )],
            (None, Some(list)) => list
                .iter()
                .enumerate()
                .map(|(k, s)| {
                    let field = format!("propeller.sections[{k}].table");
                    Ok((s.thickness_ratio, Arc::new(read(&s.table, field)?)))
                })
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
        let aircraft: Aircraft = toml::from_str(text).map_err(|e| {
            let rotor_only = toml::from_str::<toml::Table>(text).is_ok_and(|t| {
                t.contains_key("rotor")
                    && ["propeller", "engine", "takeoff"]
                        .iter()
                        .all(|k| !t.contains_key(*k))
            });
            if rotor_only {
                return AircraftError::RotorOnly {
                    path: origin.to_string(),
                };
            }
            AircraftError::Parse {
                path: origin.to_string(),
                message: toml_error_line(&e, text),
            }
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
        in_range(
            "parasitic_drag_area_m2",
            self.parasitic_drag_area_m2,
            (0.0, MAX_DRAG_AREA_M2),
            "must be 0 to 100 m² (a gyroplane's is below 1 m²)",
        )?;
        self.rotor.validate()?;
        let whole_aircraft = |field: &'static str, value: Option<f64>| {
            value.map(|_| ()).ok_or(AircraftError::Missing {
                field,
                reason: "a whole aircraft needs it (the takeoff)",
            })
        };
        whole_aircraft("rotor.hub_inertia_kg_m2", r.hub_inertia_kg_m2)?;
        whole_aircraft("rotor.flap_stop_deg", r.flap_stop_deg)?;
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
        in_range(
            "takeoff.rolling_friction",
            t.rolling_friction,
            (0.0, 1.0),
            "must be 0 to 1 (tyres on grass are about 0.05 to 0.1)",
        )?;
        in_range(
            "takeoff.climb_speed_kt",
            t.climb_speed_kt,
            (f64::MIN_POSITIVE, MAX_SPEED_KT),
            "must be above 0 and at most 300 kt",
        )?;
        non_negative("takeoff.pilot_gain_deg_per_ms", t.pilot_gain_deg_per_ms)?;
        positive("takeoff.pilot_time_constant_s", t.pilot_time_constant_s)?;
        in_range(
            "takeoff.screen_height_m",
            t.screen_height_m,
            (f64::MIN_POSITIVE, MAX_SCREEN_HEIGHT_M),
            "must be positive and at most 100 m (the certification screens are 15 m and 50 ft)",
        )?;
        in_range(
            "takeoff.field_altitude_m",
            t.field_altitude_m,
            (0.0, MAX_ISA_ALTITUDE_M),
            format!("must be within the ISA troposphere, 0 to {MAX_ISA_ALTITUDE_M} m"),
        )?;
        // A prerotation whose blade tip reaches the speed of sound at the field is beyond the
        // subsonic section tables and the blade-element model (and any real prerotator).
        let sound = super::atmosphere::Atmosphere::isa(t.field_altitude_m).speed_of_sound;
        let max_prerotation_rpm = sound / r.radius_m * 60.0 / std::f64::consts::TAU;
        in_range(
            "takeoff.prerotation_rpm",
            t.prerotation_rpm,
            (0.0, max_prerotation_rpm),
            format!(
                "must keep the blade tip below the speed of sound: at most \
                 {max_prerotation_rpm:.0} rpm for the {} m rotor",
                r.radius_m
            ),
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

/// A TOML error as one line: where it is (line and column of its span in `text`, the key or
/// value at fault) and what.
pub(crate) fn toml_error_line(e: &toml::de::Error, text: &str) -> String {
    let what = e.message().replace('\n', " ");
    let Some(before) = e.span().and_then(|span| text.get(..span.start)) else {
        return what;
    };
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    format!("line {line}, column {column}: {what}")
}
