//! The same rotor with each of several airfoils, clean and with the paper's trip: the paper's
//! section-level robustness argument (§5, NACA 23012 vs 8-H-12) carried to the aircraft —
//! F_prop, engine rpm, takeoff, and the penalty of contamination for each airfoil.

use super::files::records_csv;
use super::progress::solving_phase;
use super::{
    cell, load_study_airfoil, Penalty, Performance, StudiesError, StudyFiles, TableCache,
    TakeoffFigures, TrimFigures, CLEAN, PAPER_TRIP_XTR,
};
use crate::geometry::Airfoil;
use crate::plot::{Figure, Panel, Series, Style};
use crate::progress::{Progress, Work};
use crate::rotor::Aircraft;
use crate::section::{SectionAero, Transition};
use crate::studies::paper::{paper_run, PAPER_TRIM_SPEED_KT};
use rayon::prelude::*;
use serde::Serialize;

/// One airfoil in one state.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AirfoilRecord {
    /// Airfoil name.
    pub airfoil: String,
    /// Transition fixed at the paper's 7 % chord on both surfaces (else free, N_crit 9).
    pub contaminated: bool,
    /// Trim.
    #[serde(flatten)]
    pub trim: TrimFigures,
    /// Against the same airfoil clean (zero for the clean record).
    #[serde(flatten)]
    pub penalty: Penalty,
    /// F_prop against the first airfoil in the same state \[%\].
    pub prop_thrust_vs_first_pct: f64,
    /// Takeoff.
    #[serde(flatten)]
    pub takeoff: TakeoffFigures,
}

/// Trim at the paper's speed and takeoff of each `(name, clean, contaminated)` airfoil, all
/// runs in parallel; clean and contaminated record of each airfoil in turn.
pub fn run_airfoils<S: SectionAero + Sync + ?Sized>(
    aircraft: &Aircraft,
    cases: &[(&str, &S, &S)],
    on_done: &(dyn Fn() + Sync),
) -> Result<Vec<AirfoilRecord>, StudiesError> {
    let jobs: Vec<(&str, bool, &S)> = cases
        .iter()
        .flat_map(|&(name, clean, dirty)| [(name, false, clean), (name, true, dirty)])
        .collect();
    let runs: Vec<Performance> = jobs
        .par_iter()
        .map(|&(name, dirty, section)| {
            let label = format!("{name} {}", if dirty { "contaminated" } else { "clean" });
            let run = paper_run(aircraft, section, &label)?;
            on_done();
            Ok(Performance::new(&run.trim, &run.takeoff))
        })
        .collect::<Result<_, StudiesError>>()?;
    Ok(jobs
        .iter()
        .enumerate()
        .map(|(k, &(name, dirty, _))| {
            let own_clean = &runs[k - usize::from(dirty)];
            let first = &runs[usize::from(dirty)];
            AirfoilRecord {
                airfoil: name.to_string(),
                contaminated: dirty,
                trim: runs[k].trim.clone(),
                penalty: Penalty::between(&own_clean.trim, &runs[k].trim),
                prop_thrust_vs_first_pct: 100.0
                    * (runs[k].trim.prop_thrust_n / first.trim.prop_thrust_n - 1.0),
                takeoff: runs[k].takeoff.clone(),
            }
        })
        .collect())
}

/// Stem of the study's CSV file under `--out`.
pub const CSV_STEM: &str = "airfoils";

/// Stems of the study's figures under `--out`.
pub const FIGURE_STEMS: [&str; 1] = ["airfoils"];

/// A finished airfoil study.
#[derive(Clone, Debug)]
pub struct AirfoilStudy {
    /// Two records per airfoil: clean, contaminated.
    pub records: Vec<AirfoilRecord>,
}

impl AirfoilStudy {
    /// Load each airfoil of `airfoils` (names or files; at least one), get its clean and
    /// tripped tables from `cache` and run them.
    pub fn run(
        aircraft: &Aircraft,
        airfoils: &[String],
        cache: &TableCache,
        progress: &dyn Progress,
    ) -> Result<Self, StudiesError> {
        if airfoils.is_empty() {
            let e = crate::arguments::ArgumentError::with_text("--airfoils", "", "empty list");
            return Err(e.into());
        }
        let foils = airfoils
            .iter()
            .map(|a| load_study_airfoil(a, cache.panels))
            .collect::<Result<Vec<_>, _>>()?;
        let keys = [CLEAN, Transition::tripped(PAPER_TRIP_XTR)];
        let refs: Vec<&Airfoil> = foils.iter().collect();
        solving_phase(cache, &refs, &keys, progress);
        let tables = foils
            .iter()
            .map(|f| cache.tables(f, &keys, &|n| progress.advance(n)))
            .collect::<Result<Vec<_>, _>>();
        progress.finish();
        let tables = tables?;
        let cases: Vec<(&str, _, _)> = foils
            .iter()
            .zip(&tables)
            .map(|(f, t)| (f.name.as_str(), &t[0], &t[1]))
            .collect();
        progress.start(&Work::new(
            2 * cases.len(),
            "cases",
            "airfoil study: trim and takeoff of each airfoil, clean and tripped",
        ));
        let records = run_airfoils(aircraft, &cases, &|| progress.advance(1));
        progress.finish();
        Ok(Self { records: records? })
    }

    /// The text table.
    pub fn text(&self) -> String {
        let mut s = format!(
            "Airfoil study: trim at {PAPER_TRIM_SPEED_KT} kt and takeoff, clean and with transition \
             fixed at {:.0} % chord\n{:<22} {:<5} {:>6} {:>7} {:>6} {:>7} {:>6} {:>7} {:>6} {:>6} {:>5}\n",
            100.0 * PAPER_TRIP_XTR,
            "airfoil", "trip", "n_R", "F_prop", "n_eng", "dF_%", "dn_eng", "F/1st%", "s_TO", "s_15",
            "b_max"
        );
        for r in &self.records {
            let (p, t) = (&r.trim, &r.takeoff);
            s.push_str(&format!(
                "{:<22} {:<5} {:>6.1} {:>7.1} {:>6} {:>+7.1} {:>6} {:>+7.1} {:>6.1} {:>6.1} {:>5.2}\n",
                r.airfoil,
                if r.contaminated { "7 %" } else { "free" },
                p.rotor_rpm,
                p.prop_thrust_n,
                cell(p.engine_rpm, 0),
                r.penalty.delta_prop_thrust_pct,
                cell(r.penalty.delta_engine_rpm.map(f64::round), 0),
                r.prop_thrust_vs_first_pct,
                t.takeoff_roll_m,
                t.distance_15m_m,
                t.max_flapping_deg
            ));
        }
        s
    }

    /// The files under `--out`: the CSV and a bar-like figure of F_prop and engine rpm per
    /// airfoil, clean and contaminated.
    pub fn files(&self) -> Result<StudyFiles, StudiesError> {
        let xs = |dirty: bool| -> Vec<(f64, &AirfoilRecord)> {
            self.records
                .iter()
                .filter(|r| r.contaminated == dirty)
                .enumerate()
                .map(|(i, r)| (i as f64 + 1.0, r))
                .collect()
        };
        let names: Vec<&str> = xs(false).iter().map(|(_, r)| r.airfoil.as_str()).collect();
        let numbered: Vec<String> = names
            .iter()
            .enumerate()
            .map(|(i, n)| format!("{} = {n}", i + 1))
            .collect();
        let x_label = format!("airfoil: {}", numbered.join(", "));
        let last = names.len() as f64;
        let panel = |y: &str, v: &dyn Fn(&AirfoilRecord) -> Option<f64>| {
            let mut p = Panel::new("", x_label.as_str(), y)
                .with_x_range(0.5, last + 0.5)
                .with_x_tick_step(1.0);
            for (c, dirty) in [false, true].into_iter().enumerate() {
                let pts: Vec<(f64, f64)> = xs(dirty)
                    .iter()
                    .filter_map(|(x, r)| v(r).map(|y| (*x, y)))
                    .collect();
                let label = if dirty {
                    "transition at 7 %"
                } else {
                    "free transition"
                };
                p = p.with_series(Series::from_pairs(label, pts, Style::points(c)));
            }
            p
        };
        let fig = Figure::new(format!(
            "Rotor with each airfoil at 60 kt: {}",
            names.join(", ")
        ))
        .with_panel(panel("F_prop [N]", &|r| Some(r.trim.prop_thrust_n)))
        .with_panel(panel("engine rpm", &|r| r.trim.engine_rpm));
        Ok(StudyFiles {
            csv_stem: CSV_STEM.to_string(),
            csv: records_csv(&self.records)?,
            figures: vec![(FIGURE_STEMS[0].to_string(), fig)],
        })
    }
}
