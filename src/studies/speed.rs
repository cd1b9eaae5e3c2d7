//! The contamination penalty against airspeed: clean and tripped rotor trimmed at each speed
//! (the flight test's speed is only "≈ 60 kt"), ΔF_prop and Δ engine rpm.

use super::files::{band_label, flight_test_label, records_csv};
use super::{
    cell, check_speeds, load_study_airfoil, sections, study_tables, StudiesError, StudyFiles,
    TableCache, CLEAN,
};
use crate::plot::{Figure, Panel, Series, Style};
use crate::progress::Progress;
use crate::rotor::{speed_sweep, Aircraft, TrimParams, TrimResult};
use crate::section::{SectionAero, Transition};
use crate::studies::paper::PAPER_TRIM_SPEED_KT;
use serde::Serialize;

use super::contamination::FLIGHT_TEST_DELTA_ENGINE_RPM;

/// Speeds of the study by default \[kt\]: 30 to 90 in steps of 5.
pub fn default_speeds() -> Vec<f64> {
    (0..=12).map(|k| 30.0 + 5.0 * f64::from(k)).collect()
}

/// Clean and contaminated trim at one speed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SpeedRecord {
    /// Airspeed \[kt\].
    pub speed_kt: f64,
    /// Rotor rpm, clean.
    pub clean_rotor_rpm: f64,
    /// Rotor rpm, contaminated.
    pub rotor_rpm: f64,
    /// F_prop clean \[N\].
    pub clean_prop_thrust_n: f64,
    /// F_prop contaminated \[N\].
    pub prop_thrust_n: f64,
    /// Engine rpm clean (`null` above the engine's maximum).
    pub clean_engine_rpm: Option<f64>,
    /// Engine rpm contaminated.
    pub engine_rpm: Option<f64>,
    /// ΔF_prop \[%\].
    pub delta_prop_thrust_pct: f64,
    /// Δ engine rpm.
    pub delta_engine_rpm: Option<f64>,
    /// Power required, contaminated \[kW\].
    pub power_required_kw: f64,
}

/// Trim with `clean` and `dirty` at each of `speeds_kt` (in parallel). Returns the records of
/// the speeds where both trimmed, and one note per speed where either did not.
pub fn run_speeds<S: SectionAero + Sync + ?Sized>(
    aircraft: &Aircraft,
    clean: &S,
    dirty: &S,
    speeds_kt: &[f64],
) -> (Vec<SpeedRecord>, Vec<String>) {
    let params = TrimParams::default();
    let sweep = |s: &S| speed_sweep(aircraft, s, speeds_kt, aircraft.mass_kg, 0.0, &params);
    let (c, d) = rayon::join(|| sweep(clean), || sweep(dirty));
    let mut records = Vec::new();
    let mut notes = Vec::new();
    for ((v, c), (_, d)) in c.into_iter().zip(d) {
        match (c, d) {
            (Ok(c), Ok(d)) => records.push(record(&c, &d)),
            (Err(e), _) | (_, Err(e)) => notes.push(format!("no trim at {v} kt: {e}")),
        }
    }
    (records, notes)
}

fn record(c: &TrimResult, d: &TrimResult) -> SpeedRecord {
    SpeedRecord {
        speed_kt: c.airspeed_kt,
        clean_rotor_rpm: c.rotor_rpm,
        rotor_rpm: d.rotor_rpm,
        clean_prop_thrust_n: c.prop_thrust_n,
        prop_thrust_n: d.prop_thrust_n,
        clean_engine_rpm: c.engine_rpm,
        engine_rpm: d.engine_rpm,
        delta_prop_thrust_pct: 100.0 * (d.prop_thrust_n / c.prop_thrust_n - 1.0),
        delta_engine_rpm: d.engine_rpm.zip(c.engine_rpm).map(|(d, c)| d - c),
        power_required_kw: d.power_required_kw,
    }
}

/// Stem of the study's CSV file under `--out`.
pub const CSV_STEM: &str = "contamination_speed";

/// Stems of the study's figures under `--out`.
pub const FIGURE_STEMS: [&str; 1] = ["contamination_speed"];

/// A finished speed study.
#[derive(Clone, Debug)]
pub struct SpeedStudy {
    /// Airfoil name.
    pub airfoil: String,
    /// Transition of the contaminated blade.
    pub trip: Transition,
    /// One record per speed that trimmed clean and contaminated.
    pub records: Vec<SpeedRecord>,
    /// Speeds without a trim, and why.
    pub notes: Vec<String>,
}

impl SpeedStudy {
    /// Load `airfoil`, get its clean and tripped (`xtr` on both surfaces) tables from `cache`
    /// and trim both at each of `speeds_kt` (each in (0, 200) kt).
    pub fn run(
        aircraft: &Aircraft,
        airfoil: &str,
        xtr: f64,
        speeds_kt: &[f64],
        cache: &TableCache,
        progress: &dyn Progress,
    ) -> Result<Self, StudiesError> {
        let trip = super::checked_transition(Transition::tripped(xtr))?;
        check_speeds("--speeds", speeds_kt)?;
        let foil = load_study_airfoil(airfoil, cache.panels)?;
        let keys = [CLEAN, trip];
        let tables = study_tables(cache, &foil, &keys, progress)?;
        let s = sections(&keys, &tables);
        let (records, notes) = run_speeds(aircraft, s.get(&keys[0])?, s.get(&keys[1])?, speeds_kt);
        if records.is_empty() {
            return Err(StudiesError::BadSetting("no speed trimmed".into()));
        }
        Ok(Self {
            airfoil: foil.name,
            trip,
            records,
            notes,
        })
    }

    /// The text table.
    pub fn text(&self) -> String {
        let mut s = format!(
            "Contamination vs airspeed, {} ({}): clean → contaminated\n{:>5} {:>6} {:>6} {:>7} {:>7} {:>6} {:>6} {:>7} {:>6}\n",
            self.airfoil,
            self.trip.label(),
            "V_kt", "nR_cl", "nR_co", "F_cl", "F_co", "ne_cl", "ne_co", "dF_%", "dn_eng"
        );
        for r in &self.records {
            s.push_str(&format!(
                "{:>5.1} {:>6.1} {:>6.1} {:>7.1} {:>7.1} {:>6} {:>6} {:>+7.1} {:>6}\n",
                r.speed_kt,
                r.clean_rotor_rpm,
                r.rotor_rpm,
                r.clean_prop_thrust_n,
                r.prop_thrust_n,
                cell(r.clean_engine_rpm, 0),
                cell(r.engine_rpm, 0),
                r.delta_prop_thrust_pct,
                cell(r.delta_engine_rpm.map(f64::round), 0)
            ));
        }
        s
    }

    /// The figure: Δ engine rpm (with the flight test at 60 kt) and ΔF_prop against airspeed.
    pub fn figure(&self) -> Figure {
        let series = |v: &dyn Fn(&SpeedRecord) -> Option<f64>| {
            let pts: Vec<(f64, f64)> = self
                .records
                .iter()
                .filter_map(|r| v(r).map(|y| (r.speed_kt, y)))
                .collect();
            Series::from_pairs("computed", pts, Style::solid(0).with_points())
        };
        // The flight test is one point, at the paper's 60 kt: drawn there only, its band as
        // an error bar.
        let (centre, half) = FLIGHT_TEST_DELTA_ENGINE_RPM;
        let v = PAPER_TRIM_SPEED_KT;
        let rpm = Panel::new("", "airspeed [kt]", "Δ engine rpm")
            .with_series(series(&|r| r.delta_engine_rpm))
            .with_series(Series::new(
                band_label(half),
                vec![v, v],
                vec![centre - half, centre + half],
                Style::solid(7),
            ))
            .with_series(Series::new(
                flight_test_label(centre),
                vec![v],
                vec![centre],
                Style::points(1),
            ));
        let thrust = Panel::new("", "airspeed [kt]", "ΔF_prop [%]")
            .with_series(series(&|r| Some(r.delta_prop_thrust_pct)));
        Figure::new(format!(
            "Contamination penalty vs airspeed, {} ({})",
            self.airfoil,
            self.trip.label()
        ))
        .with_panel(rpm)
        .with_panel(thrust)
    }

    /// The files under `--out`.
    pub fn files(&self) -> Result<StudyFiles, StudiesError> {
        Ok(StudyFiles {
            csv_stem: CSV_STEM.to_string(),
            csv: records_csv(&self.records)?,
            figures: vec![(FIGURE_STEMS[0].to_string(), self.figure())],
        })
    }
}
