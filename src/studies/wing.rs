//! What a fixed wing buys: the aircraft of `--aircraft` with its `[wing]` scaled to each of
//! several areas (span, incidence and section kept, the chord scales) and trimmed at each of
//! several airspeeds. The wing lifts part of the weight, the rotor unloads and turns slower, and
//! the propeller thrust, power and engine rpm follow (the paper's §6 argument for a wing).

use super::files::records_csv;
use super::{
    cell, check_speeds, load_study_airfoil, sections, study_tables, Progress, StudiesError,
};
use super::{StudyFiles, TableCache, Transition};
use crate::plot::{Figure, Panel, Series, Style};
use crate::rotor::{speed_sweep, Aircraft, BladeSection, TrimError, TrimParams, TrimResult};
use serde::Serialize;

/// Most areas × speeds of one study: each case is one trim of about a second, so 200 cases
/// take a few minutes on two cores.
pub const MAX_WING_CASES: usize = 200;

/// Largest wing area accepted \[m²\]: ten times the paper's 1.7 m², beyond any gyroplane wing.
pub const MAX_WING_AREA_M2: f64 = 17.0;

/// One wing area at one airspeed. Every quantity is `null` when the trim did not converge.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WingRecord {
    /// Wing area \[m²\] (0 = no wing).
    pub wing_area_m2: f64,
    /// Airspeed \[kt\].
    pub speed_kt: f64,
    /// The trim converged.
    pub converged: bool,
    /// Rotor speed \[rpm\].
    pub rotor_rpm: Option<f64>,
    /// Propeller thrust F_prop \[N\]: in level flight the total drag D_R + D_P + D_W.
    pub prop_thrust_n: Option<f64>,
    /// F_prop against the aircraft without a wing at the same speed \[%\].
    pub delta_prop_thrust_pct: Option<f64>,
    /// Power required F_prop·V \[kW\].
    pub power_required_kw: Option<f64>,
    /// Engine speed \[rpm\]; `null` also above the engine's maximum.
    pub engine_rpm: Option<f64>,
    /// Share of the weight the rotor carries, L_R/(L_R + L_W).
    pub rotor_lift_share: Option<f64>,
    /// Rotor drag D_R \[N\].
    pub rotor_drag_n: Option<f64>,
    /// Wing drag D_W (profile and induced) \[N\].
    pub wing_drag_n: Option<f64>,
    /// Wing lift coefficient C_L.
    pub wing_lift_coefficient: Option<f64>,
    /// Why the trim failed, or the trim's notes (engine above its maximum, table edges, wing
    /// stall), joined by `; `; empty if none.
    pub note: String,
}

/// The settings of a wing study (also `gyro study wing`'s flags), checked before any work.
/// The default areas are none and about 0.6, 1 and 1.5 times the 1.7 m² wing of the paper's
/// §6.
#[derive(Clone, Debug, clap::Args)]
pub struct WingOptions {
    /// Rotor airfoil name or coordinate file.
    #[arg(long, default_value = "naca8h12")]
    pub airfoil: String,
    /// Wing areas in m² (0 = no wing): the aircraft's [wing] at its span, incidence and section.
    #[arg(
        long = "areas",
        value_name = "AREAS",
        value_delimiter = ',',
        default_value = "0,1,1.7,2.5"
    )]
    pub areas_m2: Vec<f64>,
    /// Airspeeds in knots.
    #[arg(
        long = "speeds",
        value_name = "SPEEDS",
        value_delimiter = ',',
        default_value = "30,45,60,75,90"
    )]
    pub speeds_kt: Vec<f64>,
    /// Trip location x/c on both surfaces of a contaminated rotor [default: the clean rotor].
    #[arg(long)]
    pub xtr: Option<f64>,
}

impl WingOptions {
    /// The rotor's transition setting, after checking every setting: areas in
    /// [0, [`MAX_WING_AREA_M2`]], speeds valid airspeeds, lists not empty, at most
    /// [`MAX_WING_CASES`] areas × speeds.
    pub fn checked(&self) -> Result<Transition, StudiesError> {
        let bad = |s: String| Err(StudiesError::BadSetting(s));
        if self.areas_m2.is_empty() || self.speeds_kt.is_empty() {
            return bad("--areas and --speeds: each needs at least one value".into());
        }
        if let Some(a) = self
            .areas_m2
            .iter()
            .find(|a| !(**a >= 0.0 && **a <= MAX_WING_AREA_M2))
        {
            return bad(format!(
                "--areas {a}: a wing area must be in [0, {MAX_WING_AREA_M2}] m²"
            ));
        }
        check_speeds("--speeds", &self.speeds_kt)?;
        let cases = self.areas_m2.len() * self.speeds_kt.len();
        if cases > MAX_WING_CASES {
            return bad(format!(
                "{cases} areas × speeds: at most {MAX_WING_CASES} trims per study"
            ));
        }
        self.xtr
            .map_or(Ok(Transition::CLEAN), |x| Transition::tripped(x).checked())
    }
}

/// Trim `aircraft` with its wing scaled to each area of `options` at each speed (speeds in
/// parallel), ISA sea level, the preset's mass; `on_area` is called after each area. One
/// record per area and speed, in that order, trimmed or not.
pub fn run_wing<S: BladeSection + Sync + ?Sized>(
    aircraft: &Aircraft,
    section: &S,
    options: &WingOptions,
    on_area: &dyn Fn(),
) -> Result<Vec<WingRecord>, StudiesError> {
    let params = TrimParams::default();
    let sweep = |area: f64| -> Result<Vec<Result<TrimResult, TrimError>>, StudiesError> {
        let ac = aircraft.with_wing_area(area)?;
        let points = speed_sweep(&ac, section, &options.speeds_kt, ac.mass_kg, 0.0, &params);
        Ok(points.into_iter().map(|(_, t)| t).collect())
    };
    let reference = sweep(0.0)?;
    let mut records = Vec::new();
    for &area in &options.areas_m2 {
        let trims = if area == 0.0 {
            reference.clone()
        } else {
            sweep(area)?
        };
        on_area();
        for ((&v, trim), none) in options.speeds_kt.iter().zip(&trims).zip(&reference) {
            records.push(record(area, v, trim, none.as_ref().ok()));
        }
    }
    Ok(records)
}

fn record(
    area: f64,
    speed_kt: f64,
    trim: &Result<TrimResult, TrimError>,
    none: Option<&TrimResult>,
) -> WingRecord {
    let t = match trim {
        Ok(t) => t,
        Err(e) => {
            return WingRecord {
                wing_area_m2: area,
                speed_kt,
                converged: false,
                rotor_rpm: None,
                prop_thrust_n: None,
                delta_prop_thrust_pct: None,
                power_required_kw: None,
                engine_rpm: None,
                rotor_lift_share: None,
                rotor_drag_n: None,
                wing_drag_n: None,
                wing_lift_coefficient: None,
                note: e.to_string(),
            }
        }
    };
    let notes: Vec<String> = t
        .notes()
        .iter()
        .map(|n| n.trim_start_matches("note: ").to_string())
        .collect();
    WingRecord {
        wing_area_m2: area,
        speed_kt,
        converged: true,
        rotor_rpm: Some(t.rotor_rpm),
        prop_thrust_n: Some(t.prop_thrust_n),
        delta_prop_thrust_pct: none.map(|n| 100.0 * (t.prop_thrust_n / n.prop_thrust_n - 1.0)),
        power_required_kw: Some(t.power_required_kw),
        engine_rpm: t.engine_rpm,
        rotor_lift_share: Some(t.rotor_lift_share()),
        rotor_drag_n: Some(t.rotor_drag_n),
        wing_drag_n: Some(t.wing.map_or(0.0, |w| w.drag_n)),
        wing_lift_coefficient: Some(t.wing.map_or(0.0, |w| w.lift_coefficient)),
        note: notes.join("; "),
    }
}

/// Stem of the study's CSV file under `--out`.
pub const CSV_STEM: &str = "wing";

/// Stems of the study's figures under `--out`.
pub const FIGURE_STEMS: [&str; 1] = ["wing"];

/// A finished wing study.
#[derive(Clone, Debug)]
pub struct WingStudy {
    /// Rotor airfoil name.
    pub airfoil: String,
    /// The rotor's transition setting.
    pub rotor: Transition,
    /// One record per area and speed.
    pub records: Vec<WingRecord>,
}

impl WingStudy {
    /// Load the rotor airfoil of `options`, get its table (clean or tripped) from `cache`, and
    /// trim the aircraft with each wing area at each speed. `aircraft` must have a `[wing]`
    /// (the shape that is scaled).
    pub fn run(
        aircraft: &Aircraft,
        options: &WingOptions,
        cache: &TableCache,
        progress: &Progress,
    ) -> Result<Self, StudiesError> {
        let rotor = options.checked()?;
        aircraft.with_wing_area(0.0)?;
        let foil = load_study_airfoil(&options.airfoil, cache.panels)?;
        let keys = [rotor];
        let tables = study_tables(cache, &foil, &keys, progress)?;
        let section = sections(&keys, &tables).get(&rotor)?;
        progress.start(options.areas_m2.len(), "wing areas");
        let records = run_wing(aircraft, section, options, &|| progress.advance(1))?;
        progress.finish();
        Ok(Self {
            airfoil: foil.name,
            rotor,
            records,
        })
    }

    /// The text table.
    pub fn text(&self) -> String {
        let mut s = format!(
            "Fixed wing, {} rotor ({}): each wing area at each airspeed\n{:>5} {:>5} {:>6} {:>7} {:>6} {:>6} {:>6} {:>6} {:>6} {:>5}\n",
            self.airfoil,
            self.rotor.label(),
            "S_m2", "V_kt", "nR", "F_prop", "dF_%", "P_kW", "n_eng", "LR/G", "D_W", "C_L"
        );
        for r in &self.records {
            if !r.converged {
                s.push_str(&format!(
                    "{:>5.2} {:>5.1} no trim: {}\n",
                    r.wing_area_m2, r.speed_kt, r.note
                ));
                continue;
            }
            s.push_str(&format!(
                "{:>5.2} {:>5.1} {:>6} {:>7} {:>6} {:>6} {:>6} {:>6} {:>6} {:>5}\n",
                r.wing_area_m2,
                r.speed_kt,
                cell(r.rotor_rpm, 1),
                cell(r.prop_thrust_n, 1),
                cell(r.delta_prop_thrust_pct, 1),
                cell(r.power_required_kw, 1),
                cell(r.engine_rpm, 0),
                cell(r.rotor_lift_share, 3),
                cell(r.wing_drag_n, 1),
                cell(r.wing_lift_coefficient, 2),
            ));
        }
        s
    }

    /// The figure: power required and ΔF_prop against airspeed, one line per wing area.
    pub fn figure(&self) -> Figure {
        let mut areas: Vec<f64> = self.records.iter().map(|r| r.wing_area_m2).collect();
        areas.dedup();
        let series = |value: &dyn Fn(&WingRecord) -> Option<f64>| -> Vec<Series> {
            areas
                .iter()
                .enumerate()
                .map(|(k, &area)| {
                    let pts: Vec<(f64, f64)> = self
                        .records
                        .iter()
                        .filter(|r| r.wing_area_m2 == area)
                        .filter_map(|r| value(r).map(|y| (r.speed_kt, y)))
                        .collect();
                    Series::from_pairs(format!("{area} m²"), pts, Style::solid(k).with_points())
                })
                .collect()
        };
        let mut power = Panel::new("", "airspeed [kt]", "power required [kW]");
        for s in series(&|r| r.power_required_kw) {
            power = power.with_series(s);
        }
        let mut thrust = Panel::new("", "airspeed [kt]", "ΔF_prop vs no wing [%]");
        for s in series(&|r| r.delta_prop_thrust_pct) {
            thrust = thrust.with_series(s);
        }
        Figure::new(format!(
            "Fixed wing: power and propeller thrust, {} rotor ({})",
            self.airfoil,
            self.rotor.label()
        ))
        .with_panel(power)
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
