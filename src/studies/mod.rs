//! Studies at aircraft level, on top of the rotor model: the paper's clean-versus-contaminated
//! study, and its contamination question carried beyond its single point.
//!
//! * [`paper`] — the paper's two computations (60 kt trim, takeoff) for the clean and the
//!   contaminated blade, the paper's published values beside them, and the sensitivity of the
//!   results to every estimated value of the aircraft preset;
//! * [`contamination`] — trip location on both or one surface, free transition at several
//!   N_crit, and spanwise coverage (the blade reads the tripped table over part of its span):
//!   the 60 kt trim and the takeoff of each setting against the clean rotor;
//! * [`pca2`] — the rotor model on a second rotor: the PCA-2 autogiro rotor against its
//!   full-scale tunnel and flight tests (NACA Reports 515 and 487);
//! * [`airfoil`] — the same rotor with each of several airfoils, clean and tripped;
//! * [`speed`] — the contamination penalty over the airspeed range;
//! * [`wing`] — a fixed wing of several areas over the airspeed range: the rotor unloads;
//! * `cache` — the section tables each study needs, built with polargen's own solver
//!   ([`build_table`](crate::table::build_table)) and kept in a cache folder ([`TableCache`]);
//! * `files` — the CSV and figures of a study, written as one set.
//!
//! The study runs are generic over section data ([`SectionAero`](crate::section::SectionAero)):
//! the tables are looked up by their [`Transition`] setting, so tests may pass small tables.

pub mod airfoil;
mod cache;
pub mod contamination;
mod files;
pub mod paper;
pub mod pca2;
mod progress;
mod request;
pub mod speed;
pub mod wing;

pub use cache::{check_cache_dir, default_cache_dir, load_study_airfoil, TableCache, CACHE_FORMAT};
pub use files::{check_study_out, StudyFiles};
pub use progress::{sections, study_tables, Progress};
pub use request::{records_json, StudyKind, StudyOutcome, StudyRequest};

use crate::geometry::GeometryError;
use crate::output::OutputError;
use crate::plot::PlotError;
use crate::rotor::{TakeoffResult, TrimResult};
use crate::table::{BuildError, TableError};
use paper::StudyError;
use serde::Serialize;

/// Trip location x/c of the paper's contaminated blade (transition fixed at 7 % chord on both
/// surfaces, paper §4).
pub const PAPER_TRIP_XTR: f64 = 0.07;

/// N_crit of the clean blade: the e^n method's standard value for a low-turbulence free stream
/// (XFOIL default; Drela, *XFOIL 6.9 User Primer*).
pub const CLEAN_NCRIT: f64 = 9.0;

/// Why a study failed.
#[derive(Debug, thiserror::Error)]
pub enum StudiesError {
    /// A setting of the study is out of range (named in the message).
    #[error("{0}")]
    BadSetting(String),
    /// An airfoil could not be loaded or paneled.
    #[error("airfoil {name}")]
    Airfoil {
        /// The airfoil as given.
        name: String,
        /// Why.
        #[source]
        source: GeometryError,
    },
    /// A table could not be built.
    #[error("building the {name} table")]
    Build {
        /// Airfoil and transition setting.
        name: String,
        /// Why.
        #[source]
        source: BuildError,
    },
    /// A table could not be written to the cache.
    #[error("table cache")]
    Cache(#[source] TableError),
    /// The aircraft file could not be loaded.
    #[error(transparent)]
    Aircraft(#[from] crate::rotor::AircraftError),
    /// A rotor computation failed.
    #[error(transparent)]
    Rotor(#[from] StudyError),
    /// An output file could not be written.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// A figure could not be drawn.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// A CSV file could not be written.
    #[error("CSV")]
    Csv(#[source] csv::Error),
}

/// The boundary-layer transition setting a section table is built with.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Transition {
    /// Critical amplification ratio N_crit of the e^n method.
    pub ncrit: f64,
    /// Forced transition x/c on the upper surface (1 = free).
    pub xtr_top: f64,
    /// Forced transition x/c on the lower surface (1 = free).
    pub xtr_bot: f64,
}

impl Transition {
    /// Free transition with N_crit [`CLEAN_NCRIT`]: the clean blade.
    pub const CLEAN: Self = Self::free(CLEAN_NCRIT);

    /// Free transition on both surfaces with `ncrit`.
    pub const fn free(ncrit: f64) -> Self {
        Self {
            ncrit,
            xtr_top: 1.0,
            xtr_bot: 1.0,
        }
    }

    /// Transition fixed at `xtr` on both surfaces (N_crit [`CLEAN_NCRIT`] ahead of the trip).
    pub const fn tripped(xtr: f64) -> Self {
        Self {
            ncrit: CLEAN_NCRIT,
            xtr_top: xtr,
            xtr_bot: xtr,
        }
    }

    /// Checked: N_crit positive, trip locations in (0, 1].
    pub fn checked(self) -> Result<Self, StudiesError> {
        for (name, x) in [("xtr_top", self.xtr_top), ("xtr_bot", self.xtr_bot)] {
            if !(x > 0.0 && x <= 1.0) {
                return Err(StudiesError::BadSetting(format!(
                    "{name} {x}: a trip location must be a chord fraction in (0, 1]"
                )));
            }
        }
        if !(self.ncrit.is_finite() && self.ncrit > 0.0 && self.ncrit <= 20.0) {
            return Err(StudiesError::BadSetting(format!(
                "ncrit {}: must be in (0, 20]",
                self.ncrit
            )));
        }
        Ok(self)
    }

    /// Short label, e.g. `free Ncrit 9`, `xtr 0.07`, `xtr 0.07/1`.
    pub fn label(&self) -> String {
        if self.xtr_top >= 1.0 && self.xtr_bot >= 1.0 {
            format!("free Ncrit {}", self.ncrit)
        } else if self.xtr_top == self.xtr_bot {
            format!("xtr {}", self.xtr_top)
        } else {
            format!("xtr {}/{}", self.xtr_top, self.xtr_bot)
        }
    }
}

/// Section data by transition setting: what a study run reads.
#[derive(Debug)]
pub struct Sections<'a, S: ?Sized> {
    /// Each setting with its section.
    pub entries: Vec<(Transition, &'a S)>,
}

impl<'a, S: ?Sized> Sections<'a, S> {
    /// The section of setting `t`.
    pub fn get(&self, t: &Transition) -> Result<&'a S, StudiesError> {
        self.entries
            .iter()
            .find(|(k, _)| k == t)
            .map(|(_, s)| *s)
            .ok_or_else(|| StudiesError::BadSetting(format!("no section table for {}", t.label())))
    }
}

/// The trim quantities every study record carries (flattened into its JSON and CSV, ahead of
/// the record's deltas).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TrimFigures {
    /// Rotor speed at the trim \[rpm\].
    pub rotor_rpm: f64,
    /// Tip-path-plane angle of attack \[deg\].
    pub rotor_aoa_deg: f64,
    /// Drag-equivalent rotor angle atan(D_R/L_R) \[deg\] (the paper's D_R = G·α_R).
    pub rotor_aoa_drag_equivalent_deg: f64,
    /// Rotor drag D_R \[N\].
    pub rotor_drag_n: f64,
    /// Propeller thrust F_prop \[N\].
    pub prop_thrust_n: f64,
    /// Engine speed \[rpm\]; `null` above the engine's maximum.
    pub engine_rpm: Option<f64>,
}

/// The takeoff quantities every study record carries and the trim's use of the table
/// (flattened into its JSON and CSV, after the record's deltas).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TakeoffFigures {
    /// Takeoff roll s_TO \[m\].
    pub takeoff_roll_m: f64,
    /// Distance to 15 m s_15 \[m\].
    pub distance_15m_m: f64,
    /// Largest teeter flapping during the takeoff β_max \[deg\].
    pub max_flapping_deg: f64,
    /// Share of the trim's blade-element lookups clamped to the table's Re/M edge.
    pub table_clamped_fraction: f64,
}

/// The trim and takeoff of one study case.
#[derive(Clone, Debug, PartialEq)]
pub struct Performance {
    /// The trim.
    pub trim: TrimFigures,
    /// The takeoff (and the trim's clamped lookups).
    pub takeoff: TakeoffFigures,
}

impl Performance {
    /// The quantities of a trim and a takeoff.
    pub fn new(trim: &TrimResult, takeoff: &TakeoffResult) -> Self {
        Self {
            trim: TrimFigures {
                rotor_rpm: trim.rotor_rpm,
                rotor_aoa_deg: trim.rotor_aoa_deg,
                rotor_aoa_drag_equivalent_deg: trim.rotor_aoa_drag_equivalent_deg,
                rotor_drag_n: trim.rotor_drag_n,
                prop_thrust_n: trim.prop_thrust_n,
                engine_rpm: trim.engine_rpm,
            },
            takeoff: TakeoffFigures {
                takeoff_roll_m: takeoff.takeoff_roll_m,
                distance_15m_m: takeoff.distance_15m_m,
                max_flapping_deg: takeoff.max_flapping_deg,
                table_clamped_fraction: trim.table_clamped_fraction,
            },
        }
    }
}

/// The changes of a contaminated case against its clean reference.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Penalty {
    /// ΔF_prop / F_prop,clean \[%\].
    pub delta_prop_thrust_pct: f64,
    /// Δ engine rpm; `null` if either engine speed is above the engine's maximum.
    pub delta_engine_rpm: Option<f64>,
}

impl Penalty {
    /// `case` against `clean`.
    pub fn between(clean: &TrimFigures, case: &TrimFigures) -> Self {
        Self {
            delta_prop_thrust_pct: 100.0 * (case.prop_thrust_n / clean.prop_thrust_n - 1.0),
            delta_engine_rpm: case.engine_rpm.zip(clean.engine_rpm).map(|(c, r)| c - r),
        }
    }
}

/// The cache of the command-line studies: folder `dir` (else [`default_cache_dir`]), the
/// default rotor grid, the default panel count, all cores. Checks the folder.
pub fn command_line_cache(dir: Option<std::path::PathBuf>) -> Result<TableCache, StudiesError> {
    let dir = dir.unwrap_or_else(default_cache_dir);
    check_cache_dir(&dir)?;
    Ok(TableCache {
        dir,
        grid: crate::table::GridSpec::default(),
        panels: crate::geometry::DEFAULT_PANEL_NODES,
        threads: 0,
    })
}

/// Airspeeds of a study given with `flag`, checked with the rotor layer's
/// [`check_speed_kt`](crate::rotor::check_speed_kt): each above 0 and below the maximum.
pub(crate) fn check_speeds(flag: &str, speeds_kt: &[f64]) -> Result<(), StudiesError> {
    speeds_kt.iter().try_for_each(|&v| {
        crate::rotor::check_speed_kt(flag, v).map_err(|e| StudiesError::BadSetting(e.to_string()))
    })
}

/// A value with `decimals` decimals, or `-` for none.
pub(crate) fn cell(v: Option<f64>, decimals: usize) -> String {
    v.map_or_else(|| "-".to_string(), |v| format!("{v:.decimals$}"))
}
