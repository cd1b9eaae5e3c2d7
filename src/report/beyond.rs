//! The report's section "Beyond the paper": the contamination, airfoil and speed studies of
//! [`studies`](crate::studies) on the 8-H-12 rotor, their figures, and the findings in numbers
//! with what each depends on. Every number is read from the study records.

use crate::plot::Figure;
use crate::rotor::Aircraft;
use crate::studies::airfoil::{self, AirfoilStudy};
use crate::studies::contamination::{
    self, ContaminationOptions, ContaminationRecord, ContaminationStudy, Group,
    FLIGHT_TEST_DELTA_ENGINE_RPM,
};
use crate::studies::speed::{self, default_speeds, SpeedStudy};
use crate::studies::{command_line_cache, Progress, StudiesError, PAPER_TRIP_XTR};
use std::path::Path;

/// Rotor rpm change still read as "unchanged" \[rpm\]: an assumed reading resolution of the
/// flight test's rotor tachometer (the paper reports the rotor speed only as unchanged, ≈ 350).
const ROTOR_RPM_UNCHANGED: f64 = 5.0;

/// Airfoil of the studied rotor and the alternative the paper argues for.
const AIRFOILS: [&str; 2] = ["naca8h12", "naca23012"];

/// File stems of the section's figures.
pub(super) fn figure_stems() -> Vec<&'static str> {
    let mut v = contamination::FIGURE_STEMS.to_vec();
    v.extend(speed::FIGURE_STEMS);
    v.extend(airfoil::FIGURE_STEMS);
    v
}

/// A signed whole number of rpm, or `-`.
fn signed(v: Option<f64>) -> String {
    v.map_or_else(|| "-".to_string(), |d| format!("{d:+.0}"))
}

/// The three studies.
pub(super) struct Beyond {
    contamination: ContaminationStudy,
    airfoils: AirfoilStudy,
    speed: SpeedStudy,
}

/// Run the studies with tables from the cache folder `cache`.
pub(super) fn run(ac: &Aircraft, cache: &Path) -> Result<Beyond, StudiesError> {
    let cache = command_line_cache(Some(cache.to_path_buf()))?;
    let progress = Progress::on_terminal();
    let options = ContaminationOptions::default();
    let contamination = ContaminationStudy::run(ac, AIRFOILS[0], &options, &cache, &progress)?;
    let names: Vec<String> = AIRFOILS.iter().map(|s| s.to_string()).collect();
    let airfoils = AirfoilStudy::run(ac, &names, &cache, &progress)?;
    let speed = SpeedStudy::run(
        ac,
        AIRFOILS[0],
        PAPER_TRIP_XTR,
        &default_speeds(),
        &cache,
        &progress,
    )?;
    Ok(Beyond {
        contamination,
        airfoils,
        speed,
    })
}

impl Beyond {
    /// The figures by file stem.
    pub(super) fn figures(&self) -> Result<Vec<(String, Figure)>, StudiesError> {
        let mut v = contamination::figures(&self.contamination.records);
        v.push((speed::FIGURE_STEMS[0].to_string(), self.speed.figure()));
        v.extend(self.airfoils.files()?.figures);
        Ok(v)
    }

    /// The section's Markdown.
    pub(super) fn markdown(&self) -> String {
        let mut o = String::new();
        let recs = &self.contamination.records;
        let rpm = |r: &ContaminationRecord| signed(r.penalty.delta_engine_rpm);
        let clean_rpm = recs.first().map_or(0.0, |r| r.performance.rotor_rpm);
        let (band, tol) = FLIGHT_TEST_DELTA_ENGINE_RPM;
        outln!(o, "## Beyond the paper");
        outln!(o);
        outln!(
            o,
            "The paper computes one contaminated case (transition fixed at 7 % chord on both \
             surfaces of the whole blade). `gyro study` asks how the aircraft-level answer \
             depends on that choice ([docs/studies.md](../docs/studies.md)); every table below is \
             solved by polargen on the default grid, the aircraft is the preset above at 60 kt."
        );
        outln!(o);
        outln!(o, "```text\n{}```", self.contamination.text());
        outln!(o);
        outln!(o, "![Penalty vs trip location](contamination_trip.png)");
        outln!(o, "![Penalty vs coverage](contamination_coverage.png)");
        outln!(o);
        let trips: Vec<String> = recs
            .iter()
            .filter(|r| r.group == Group::Trip)
            .map(|r| format!("{:.0} % {}", 100.0 * r.xtr_top, rpm(r)))
            .collect();
        outln!(
            o,
            "- **Trip location.** Δ engine rpm against the trip's chord position (both \
             surfaces): {}.",
            trips.join(", ")
        );
        let in_band: Vec<&ContaminationRecord> = recs
            .iter()
            .filter(|r| {
                r.penalty
                    .delta_engine_rpm
                    .is_some_and(|d| (d - band).abs() <= tol)
            })
            .collect();
        let listed = |v: &[&ContaminationRecord]| -> String {
            if v.is_empty() {
                return "no setting".to_string();
            }
            v.iter()
                .map(|r| {
                    let dn = r.performance.rotor_rpm - clean_rpm;
                    format!("{} ({} engine rpm, rotor {dn:+.1} rpm)", r.setting, rpm(r))
                })
                .collect::<Vec<_>>()
                .join("; ")
        };
        let steady: Vec<&ContaminationRecord> = in_band
            .iter()
            .copied()
            .filter(|r| (r.performance.rotor_rpm - clean_rpm).abs() <= ROTOR_RPM_UNCHANGED)
            .collect();
        let paper = recs
            .iter()
            .find(|r| r.group == Group::Trip && r.xtr_top == PAPER_TRIP_XTR)
            .map_or("-".to_string(), rpm);
        outln!(
            o,
            "- **Flight test** (+{band} ± {tol} engine rpm, rotor rpm unchanged). Inside the \
             engine-rpm band: {}. Of these, the rotor rpm stays within ± {ROTOR_RPM_UNCHANGED} \
             rpm of clean (an assumed reading resolution of the rotor tachometer) for: {}. The \
             paper's own setting (7 % trip, whole blade) gives {paper} engine rpm.",
            listed(&in_band),
            listed(&steady),
        );
        let a = &self.airfoils.records;
        if a.len() == 4 {
            outln!(
                o,
                "- **Airfoil.** Contamination raises F_prop by {:+.1} % on the {} rotor and by \
                 {:+.1} % on the {} rotor ({} vs {} engine rpm). The {} rotor's F_prop against \
                 the {}'s: clean {:+.1} %, contaminated {:+.1} %.",
                a[1].penalty.delta_prop_thrust_pct,
                a[0].airfoil,
                a[3].penalty.delta_prop_thrust_pct,
                a[2].airfoil,
                signed(a[1].penalty.delta_engine_rpm),
                signed(a[3].penalty.delta_engine_rpm),
                a[2].airfoil,
                a[0].airfoil,
                a[2].prop_thrust_vs_first_pct,
                a[3].prop_thrust_vs_first_pct
            );
        }
        let at = |v: f64| self.speed.records.iter().find(|r| r.speed_kt == v);
        let speeds: Vec<String> = [30.0, 45.0, 60.0, 75.0, 90.0]
            .iter()
            .filter_map(|&v| at(v))
            .map(|r| {
                format!(
                    "{} kt {:+.1} % ({} rpm)",
                    r.speed_kt,
                    r.delta_prop_thrust_pct,
                    signed(r.delta_engine_rpm)
                )
            })
            .collect();
        outln!(
            o,
            "- **Airspeed.** ΔF_prop (Δ engine rpm) of the 7 % trip: {}; `-` where the \
             contaminated rotor needs more than the engine's maximum rpm.",
            speeds.join(", ")
        );
        outln!(o, "\n![Penalty vs airspeed](contamination_speed.png)");
        outln!(o, "![Airfoils](airfoils.png)");
        outln!(o);
        outln!(
            o,
            "What these depend on: the propeller/engine map turns ΔF_prop into engine rpm, so \
             every Δ engine rpm inherits its slope; the trip is a forced transition (no \
             roughness height, no bypass transition), N_crit below 9 only a proxy for roughness \
             and turbulence; spanwise coverage is resolved by the rotor's strips (a strip \
             belongs to the band holding its centre); the section data are 2-D (no rotational \
             or yawed-flow effects on the boundary layer); at 60 kt {:.0} % of the clean trim's \
             blade-element lookups lie outside the table's Re/M range and use its edge. A fixed \
             wing (the paper's §6) is not modelled here.",
            100.0
                * recs
                    .first()
                    .map_or(0.0, |r| r.performance.table_clamped_fraction)
        );
        outln!(o);
        o
    }
}
