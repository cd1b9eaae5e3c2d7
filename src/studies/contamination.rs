//! Contamination as a study: how the 60 kt trim and the takeoff change with the severity and
//! the extent of the blade's contamination, against the clean rotor.
//!
//! Settings ([`ContaminationOptions::settings`]): transition fixed on both surfaces at several
//! chord fractions; on the upper or the lower surface only; free transition at several N_crit
//! (a proxy for surface roughness and free-stream turbulence, Drela's e^n method); and spanwise
//! coverage — the blade tripped only outboard or inboard of a radius, read through a
//! [`SpanwiseSection`] (the clean table elsewhere). Each setting runs the paper's trim and
//! takeoff ([`paper_run`]), all settings in parallel.

use super::files::{band_markers, records_csv};
use super::{
    cell, load_study_airfoil, sections, study_tables, Penalty, Performance, Progress, Sections,
    StudiesError, StudyFiles, TableCache, TakeoffFigures, Transition, TrimFigures, PAPER_TRIP_XTR,
};
use crate::plot::{Figure, Marker, Panel, Series, Style};
use crate::rotor::{Aircraft, SpanwiseSection};
use crate::section::SectionAero;
use crate::studies::paper::{paper_run, PAPER_TRIM_SPEED_KT};
use rayon::prelude::*;
use serde::Serialize;

/// Flight test of the paper (Table 2): the contaminated rotor needed about +200 engine rpm at
/// ≈ 60 kt, read off the tachometer (≈ 4400 → 4600 rpm); ± 50 rpm is the reading band drawn.
pub const FLIGHT_TEST_DELTA_ENGINE_RPM: (f64, f64) = (200.0, 50.0);

/// Kind of a contamination setting.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Group {
    /// Free transition, N_crit 9 over the whole blade (the reference).
    Clean,
    /// Free transition at another N_crit.
    Ncrit,
    /// Transition fixed on both surfaces over the whole blade.
    Trip,
    /// Transition fixed on the upper surface only.
    UpperOnly,
    /// Transition fixed on the lower surface only.
    LowerOnly,
    /// The paper's trip outboard of a radius, clean inboard.
    Outboard,
    /// The paper's trip inboard of a radius, clean outboard.
    Inboard,
}

/// One setting: `transition` over `inner ≤ r/R < outer`, the clean section elsewhere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setting {
    /// Kind.
    pub group: Group,
    /// Transition inside the band.
    pub transition: Transition,
    /// Inner edge r/R of the contaminated band.
    pub inner: f64,
    /// Outer edge r/R.
    pub outer: f64,
}

impl Setting {
    /// Label, e.g. `xtr 0.07`, `upper 0.07`, `xtr 0.07 r/R 0.5-1`.
    pub fn label(&self) -> String {
        let t = &self.transition;
        match self.group {
            Group::Clean => "clean".to_string(),
            Group::UpperOnly => format!("upper {}", t.xtr_top),
            Group::LowerOnly => format!("lower {}", t.xtr_bot),
            Group::Outboard | Group::Inboard => {
                format!("{} r/R {}-{}", t.label(), self.inner, self.outer)
            }
            Group::Ncrit | Group::Trip => t.label(),
        }
    }
}

/// What to compute; [`Default`] is the set listed in `docs/studies.md`.
#[derive(Clone, Debug, PartialEq)]
pub struct ContaminationOptions {
    /// Trip locations x/c on both surfaces.
    pub trips: Vec<f64>,
    /// N_crit values of free transition (besides the clean [`CLEAN_NCRIT`](super::CLEAN_NCRIT)).
    pub ncrits: Vec<f64>,
    /// Radii r/R outboard of which the blade is tripped at [`PAPER_TRIP_XTR`].
    pub outboard: Vec<f64>,
    /// Radii r/R inboard of which the blade is tripped at [`PAPER_TRIP_XTR`].
    pub inboard: Vec<f64>,
}

impl Default for ContaminationOptions {
    fn default() -> Self {
        Self {
            trips: vec![0.02, 0.05, 0.07, 0.1, 0.2, 0.3, 0.5],
            ncrits: vec![6.0, 3.0, 1.0],
            outboard: vec![0.25, 0.5, 0.75],
            inboard: vec![0.5],
        }
    }
}

impl ContaminationOptions {
    /// The settings, clean first, each checked (trip in (0, 1], N_crit in (0, 20], radii in
    /// [0, 1]).
    pub fn settings(&self) -> Result<Vec<Setting>, StudiesError> {
        let whole = |group, transition: Transition| -> Result<Setting, StudiesError> {
            Ok(Setting {
                group,
                transition: transition.checked()?,
                inner: 0.0,
                outer: 1.0,
            })
        };
        let paper = Transition::tripped(PAPER_TRIP_XTR);
        let mut out = vec![whole(Group::Clean, Transition::CLEAN)?];
        for &n in &self.ncrits {
            out.push(whole(Group::Ncrit, Transition::free(n))?);
        }
        for &x in &self.trips {
            out.push(whole(Group::Trip, Transition::tripped(x))?);
        }
        let single = |top: f64, bot: f64| Transition {
            xtr_top: top,
            xtr_bot: bot,
            ..paper
        };
        out.push(whole(Group::UpperOnly, single(PAPER_TRIP_XTR, 1.0))?);
        out.push(whole(Group::LowerOnly, single(1.0, PAPER_TRIP_XTR))?);
        for (group, radii) in [
            (Group::Outboard, &self.outboard),
            (Group::Inboard, &self.inboard),
        ] {
            for &r in radii {
                if !(0.0..=1.0).contains(&r) {
                    return Err(StudiesError::BadSetting(format!(
                        "coverage radius {r}: must be a fraction r/R in [0, 1]"
                    )));
                }
                let (inner, outer) = if group == Group::Outboard {
                    (r, 1.0)
                } else {
                    (0.0, r)
                };
                out.push(Setting {
                    group,
                    transition: paper,
                    inner,
                    outer,
                });
            }
        }
        Ok(out)
    }
}

/// The result of one setting; its field names are the `--json` keys of `gyro study contamination`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ContaminationRecord {
    /// Label of the setting.
    pub setting: String,
    /// Kind of the setting.
    pub group: Group,
    /// Upper-surface transition x/c inside the band (1 = free).
    pub xtr_top: f64,
    /// Lower-surface transition x/c inside the band (1 = free).
    pub xtr_bot: f64,
    /// N_crit inside the band.
    pub ncrit: f64,
    /// Inner edge r/R of the contaminated band.
    pub coverage_inner_r_over_r: f64,
    /// Outer edge r/R of the contaminated band.
    pub coverage_outer_r_over_r: f64,
    /// Trim.
    #[serde(flatten)]
    pub trim: TrimFigures,
    /// Against the clean rotor.
    #[serde(flatten)]
    pub penalty: Penalty,
    /// Takeoff.
    #[serde(flatten)]
    pub takeoff: TakeoffFigures,
}

/// The transition settings whose tables `settings` need (the clean one first).
pub fn transitions(settings: &[Setting]) -> Vec<Transition> {
    super::cache::unique(
        std::iter::once(Transition::CLEAN).chain(settings.iter().map(|s| s.transition)),
    )
}

/// Trim at the paper's speed and takeoff for every setting (in parallel), each against the
/// clean blade. `sections` holds a section for each of [`transitions`]; `on_done` is called
/// after each setting.
pub fn run_contamination<S: SectionAero + Sync + ?Sized>(
    aircraft: &Aircraft,
    settings: &[Setting],
    sections: &Sections<S>,
    on_done: &(dyn Fn() + Sync),
) -> Result<Vec<ContaminationRecord>, StudiesError> {
    let clean = sections.get(&Transition::CLEAN)?;
    let runs: Vec<Performance> = settings
        .par_iter()
        .map(|s| {
            let band = sections.get(&s.transition)?;
            let blade = SpanwiseSection::banded(clean, band, s.inner, s.outer);
            let run = paper_run(aircraft, &blade, &s.label())?;
            on_done();
            Ok(Performance::new(&run.trim, &run.takeoff))
        })
        .collect::<Result<_, StudiesError>>()?;
    let reference = match settings.iter().position(|s| s.group == Group::Clean) {
        Some(i) => runs[i].clone(),
        None => {
            let run = paper_run(aircraft, clean, "clean")?;
            Performance::new(&run.trim, &run.takeoff)
        }
    };
    Ok(settings
        .iter()
        .zip(runs)
        .map(|(s, performance)| ContaminationRecord {
            setting: s.label(),
            group: s.group,
            xtr_top: s.transition.xtr_top,
            xtr_bot: s.transition.xtr_bot,
            ncrit: s.transition.ncrit,
            coverage_inner_r_over_r: s.inner,
            coverage_outer_r_over_r: s.outer,
            penalty: Penalty::between(&reference.trim, &performance.trim),
            trim: performance.trim,
            takeoff: performance.takeoff,
        })
        .collect())
}

/// The records as a text table.
pub fn text_table(records: &[ContaminationRecord], airfoil: &str, speed_kt: f64) -> String {
    let mut s =
        format!(
        "Contamination study, {airfoil}: trim at {speed_kt} kt and takeoff; deltas against clean\n\
         {:<22} {:>6} {:>6} {:>6} {:>6} {:>7} {:>6} {:>7} {:>6} {:>6} {:>6} {:>5}\n",
        "setting", "n_R", "aR_tpp", "aR_D/L", "D_R", "F_prop", "n_eng", "dF_%", "dn_eng",
        "s_TO", "s_15", "b_max"
    );
    for r in records {
        let (p, t) = (&r.trim, &r.takeoff);
        s.push_str(&format!(
            "{:<22} {:>6.1} {:>6.2} {:>6.2} {:>6.1} {:>7.1} {:>6} {:>+7.1} {:>6} {:>6.1} {:>6.1} {:>5.2}\n",
            r.setting,
            p.rotor_rpm,
            p.rotor_aoa_deg,
            p.rotor_aoa_drag_equivalent_deg,
            p.rotor_drag_n,
            p.prop_thrust_n,
            cell(p.engine_rpm, 0),
            r.penalty.delta_prop_thrust_pct,
            cell(r.penalty.delta_engine_rpm.map(|d| d.round()), 0),
            t.takeoff_roll_m,
            t.distance_15m_m,
            t.max_flapping_deg
        ));
    }
    let (band, tol) = FLIGHT_TEST_DELTA_ENGINE_RPM;
    let inside: Vec<&str> = records
        .iter()
        .filter(|r| {
            r.penalty
                .delta_engine_rpm
                .is_some_and(|d| (d - band).abs() <= tol)
        })
        .map(|r| r.setting.as_str())
        .collect();
    s.push_str(&format!(
        "flight test: +{band} ± {tol} engine rpm, rotor rpm unchanged; inside the band: {}\n",
        if inside.is_empty() {
            "none".to_string()
        } else {
            inside.join(", ")
        }
    ));
    s
}

/// The CSV file of the records.
pub fn csv(records: &[ContaminationRecord]) -> Result<String, StudiesError> {
    records_csv(records)
}

/// Δ engine rpm and ΔF_prop of `records` of the groups `line` (a curve over `x`) and `marks`
/// (single points), with the flight-test band on the rpm panel.
fn delta_figure(
    title: &str,
    x_label: &str,
    line: &[(f64, &ContaminationRecord)],
    marks: &[(f64, &ContaminationRecord)],
) -> Figure {
    let panel = |y_label: &str, value: &dyn Fn(&ContaminationRecord) -> Option<f64>| {
        let pts: Vec<(f64, f64)> = line
            .iter()
            .filter_map(|(x, r)| value(r).map(|v| (*x, v)))
            .collect();
        let mut p = Panel::new("", x_label, y_label).with_series(Series::from_pairs(
            "computed",
            pts,
            Style::solid(0).with_points(),
        ));
        for (i, (x, r)) in marks.iter().enumerate() {
            if let Some(v) = value(r) {
                p = p.with_marker(Marker::point(*x, v, r.setting.clone(), 2 + i));
            }
        }
        p
    };
    let rpm = band_markers(
        panel("Δ engine rpm", &|r| r.penalty.delta_engine_rpm),
        FLIGHT_TEST_DELTA_ENGINE_RPM,
    );
    let thrust = panel("ΔF_prop [%]", &|r| Some(r.penalty.delta_prop_thrust_pct));
    Figure::new(title).with_panel(rpm).with_panel(thrust)
}

/// The study's figures: the deltas against the trip location (both surfaces; one surface
/// and free transition as points) and against the tripped share of the span.
pub fn figures(records: &[ContaminationRecord]) -> Vec<(String, Figure)> {
    let of = |g: Group| records.iter().filter(move |r| r.group == g);
    let clean: Vec<&ContaminationRecord> = of(Group::Clean).collect();
    let mut trip: Vec<(f64, &ContaminationRecord)> =
        of(Group::Trip).map(|r| (r.xtr_top, r)).collect();
    trip.sort_by(|a, b| a.0.total_cmp(&b.0));
    let singles: Vec<(f64, &ContaminationRecord)> = of(Group::UpperOnly)
        .chain(of(Group::LowerOnly))
        .map(|r| (r.xtr_top.min(r.xtr_bot), r))
        .collect();
    // Coverage: tripped share of the span, from clean (0) to the paper's whole blade (1).
    let mut cover: Vec<(f64, &ContaminationRecord)> = clean.iter().map(|r| (0.0, *r)).collect();
    cover.extend(of(Group::Outboard).map(|r| (1.0 - r.coverage_inner_r_over_r, r)));
    cover.extend(
        of(Group::Trip)
            .filter(|r| r.xtr_top == PAPER_TRIP_XTR)
            .map(|r| (1.0, r)),
    );
    cover.sort_by(|a, b| a.0.total_cmp(&b.0));
    let inboard: Vec<(f64, &ContaminationRecord)> = of(Group::Inboard)
        .map(|r| (r.coverage_outer_r_over_r, r))
        .collect();
    vec![
        (
            "contamination_trip".to_string(),
            delta_figure(
                "Contamination penalty vs trip location (both surfaces), 60 kt",
                "trip location x/c",
                &trip,
                &singles,
            ),
        ),
        (
            "contamination_coverage".to_string(),
            delta_figure(
                "Contamination penalty vs tripped share of the span (trip at 7 % chord, outboard), 60 kt",
                "tripped share of the span, outboard part (1 − r/R)",
                &cover,
                &inboard,
            ),
        ),
    ]
}

/// Stem of the study's CSV file under `--out`.
pub const CSV_STEM: &str = "contamination";

/// Stems of the study's figures under `--out`.
pub const FIGURE_STEMS: [&str; 2] = ["contamination_trip", "contamination_coverage"];

/// A finished contamination study of one airfoil.
#[derive(Clone, Debug)]
pub struct ContaminationStudy {
    /// Airfoil name.
    pub airfoil: String,
    /// One record per setting, clean first.
    pub records: Vec<ContaminationRecord>,
}

impl ContaminationStudy {
    /// Check `options`, load `airfoil` (name or file), get its tables from `cache` (solving
    /// the missing ones) and run every setting.
    pub fn run(
        aircraft: &Aircraft,
        airfoil: &str,
        options: &ContaminationOptions,
        cache: &TableCache,
        progress: &Progress,
    ) -> Result<Self, StudiesError> {
        let settings = options.settings()?;
        let foil = load_study_airfoil(airfoil, cache.panels)?;
        let keys = transitions(&settings);
        let tables = study_tables(cache, &foil, &keys, progress)?;
        progress.start(settings.len(), "settings");
        let records = run_contamination(aircraft, &settings, &sections(&keys, &tables), &|| {
            progress.advance(1)
        });
        progress.finish();
        Ok(Self {
            airfoil: foil.name,
            records: records?,
        })
    }

    /// The text table.
    pub fn text(&self) -> String {
        text_table(&self.records, &self.airfoil, PAPER_TRIM_SPEED_KT)
    }

    /// The files under `--out`.
    pub fn files(&self) -> Result<StudyFiles, StudiesError> {
        Ok(StudyFiles {
            csv_stem: CSV_STEM.to_string(),
            csv: csv(&self.records)?,
            figures: figures(&self.records),
        })
    }
}
