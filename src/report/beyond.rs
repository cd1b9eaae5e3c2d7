//! The report's section "Beyond the paper": the contamination, airfoil, speed and wing studies of
//! [`studies`](crate::studies) on the 8-H-12 rotor, their figures, and the findings in numbers
//! with what each depends on. Every number is read from the study records.

use crate::plot::Figure;
use crate::progress::Progress;
use crate::rotor::Aircraft;
use crate::studies::airfoil::{self, AirfoilStudy};
use crate::studies::contamination::{
    self, ContaminationOptions, ContaminationRecord, ContaminationStudy, Group,
    FLIGHT_TEST_DELTA_ENGINE_RPM,
};
use crate::studies::speed::{self, default_speeds, SpeedStudy};
use crate::studies::wing::{self, WingOptions, WingRecord, WingStudy};
use crate::studies::{command_line_cache, StudiesError, TableCache, PAPER_TRIP_XTR};
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
    v.extend(wing::FIGURE_STEMS);
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
    /// The wing study of the clean rotor; `None` when the aircraft file has no `[wing]`.
    wing: Option<WingStudy>,
    /// The table cache's notes (entries solved again).
    pub(super) cache_notes: Vec<String>,
}

/// Run the studies with tables from the cache folder `cache`.
pub(super) fn run(
    ac: &Aircraft,
    cache: &Path,
    progress: &dyn Progress,
) -> Result<Beyond, StudiesError> {
    run_with(
        ac,
        &command_line_cache(Some(cache.to_path_buf()))?,
        progress,
    )
}

/// Run the studies with tables from `cache`.
fn run_with(
    ac: &Aircraft,
    cache: &TableCache,
    progress: &dyn Progress,
) -> Result<Beyond, StudiesError> {
    let options = ContaminationOptions::default();
    let contamination = ContaminationStudy::run(ac, AIRFOILS[0], &options, cache, progress)?;
    let names: Vec<String> = AIRFOILS.iter().map(|s| s.to_string()).collect();
    let airfoils = AirfoilStudy::run(ac, &names, cache, progress)?;
    let speed = SpeedStudy::run(
        ac,
        AIRFOILS[0],
        PAPER_TRIP_XTR,
        &default_speeds(),
        cache,
        progress,
    )?;
    let wing = match ac.wing {
        Some(_) => {
            let options = WingOptions {
                airfoil: AIRFOILS[0].to_string(),
                ..WingOptions::default()
            };
            Some(WingStudy::run(ac, &options, cache, progress)?)
        }
        None => None,
    };
    Ok(Beyond {
        contamination,
        airfoils,
        speed,
        wing,
        cache_notes: cache.notes(),
    })
}

/// How the report names `docs/studies.md`: a relative link when the report folder `out` sits
/// beside the repository's `docs/` (the shipped `report/`), else the path in words, so that a
/// report written elsewhere has no broken link.
pub(super) fn studies_doc_reference(out: &std::path::Path) -> String {
    if out.join("../docs/studies.md").is_file() {
        "[docs/studies.md](../docs/studies.md)".to_string()
    } else {
        "`docs/studies.md` of the polargen sources".to_string()
    }
}

impl Beyond {
    /// The figures by file stem.
    pub(super) fn figures(&self) -> Result<Vec<(String, Figure)>, StudiesError> {
        let mut v = contamination::figures(&self.contamination.records);
        v.push((speed::FIGURE_STEMS[0].to_string(), self.speed.figure()));
        v.extend(self.airfoils.files()?.figures);
        if let Some(w) = &self.wing {
            v.push((wing::FIGURE_STEMS[0].to_string(), w.figure()));
        }
        Ok(v)
    }

    /// The section's Markdown; `studies_doc` is how it names `docs/studies.md` (a link when
    /// the report lies in the repository, [`studies_doc_reference`]).
    pub(super) fn markdown(&self, studies_doc: &str) -> String {
        let mut o = String::new();
        let recs = &self.contamination.records;
        let rpm = |r: &ContaminationRecord| signed(r.penalty.delta_engine_rpm);
        let clean_rpm = recs.first().map_or(0.0, |r| r.trim.rotor_rpm);
        let (band, tol) = FLIGHT_TEST_DELTA_ENGINE_RPM;
        outln!(o, "## Beyond the paper");
        outln!(o);
        outln!(
            o,
            "The paper computes one contaminated case (transition fixed at 7 % chord on both \
             surfaces of the whole blade). `gyro study` asks how the aircraft-level answer \
             depends on that choice ({studies_doc}); every table below is \
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
                    let dn = r.trim.rotor_rpm - clean_rpm;
                    format!("{} ({} engine rpm, rotor {dn:+.1} rpm)", r.setting, rpm(r))
                })
                .collect::<Vec<_>>()
                .join("; ")
        };
        let steady: Vec<&ContaminationRecord> = in_band
            .iter()
            .copied()
            .filter(|r| (r.trim.rotor_rpm - clean_rpm).abs() <= ROTOR_RPM_UNCHANGED)
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
        if let Some(w) = &self.wing {
            wing_findings(&mut o, w, studies_doc);
        }
        outln!(o, "\n![Penalty vs airspeed](contamination_speed.png)");
        outln!(o, "![Airfoils](airfoils.png)");
        if self.wing.is_some() {
            outln!(o, "![Fixed wing](wing.png)");
        }
        outln!(o);
        outln!(
            o,
            "What these depend on: the propeller/engine map turns ΔF_prop into engine rpm, so \
             every Δ engine rpm inherits its slope; the trip is a forced transition (no \
             roughness height, no bypass transition), N_crit below 9 only a proxy for roughness \
             and turbulence; spanwise coverage is resolved by the rotor's strips (a strip \
             belongs to the band holding its centre); the section data are 2-D (no rotational \
             or yawed-flow effects on the boundary layer); at 60 kt {:.0} % of the clean trim's \
             blade-element lookups lie outside the table's Re/M range and use its edge. The \
             wing is a lifting line on its section table with the fuselage level at every \
             speed (the wing at its incidence), no rotor downwash on it and no fitting drag; \
             its span, incidence and section are the aircraft file's assumptions.",
            100.0
                * recs
                    .first()
                    .map_or(0.0, |r| r.takeoff.table_clamped_fraction)
        );
        outln!(o);
        o
    }
}

/// The wing bullet: F_prop change and the rotor's share of the lift for each wing area at 60
/// and 90 kt, and the paper's §6 claim beside them.
fn wing_findings(o: &mut String, w: &WingStudy, studies_doc: &str) {
    let at = |area: f64, v: f64| -> Option<&WingRecord> {
        w.records
            .iter()
            .find(|r| r.wing_area_m2 == area && r.speed_kt == v && r.converged)
    };
    let areas = WingOptions::default().areas_m2;
    let cells: Vec<String> = areas[1..]
        .iter()
        .map(|&area| {
            let one = |v: f64| {
                at(area, v).map_or("no trim".to_string(), |r| {
                    format!(
                        "{v} kt {:+.1} % (rotor lift share {:.2})",
                        r.delta_prop_thrust_pct.unwrap_or(f64::NAN),
                        r.rotor_lift_share.unwrap_or(f64::NAN)
                    )
                })
            };
            format!("{area} m²: {}, {}", one(60.0), one(90.0))
        })
        .collect();
    let best = w
        .records
        .iter()
        .filter(|r| r.wing_area_m2 == 1.7)
        .filter_map(|r| r.delta_prop_thrust_pct.map(|d| (r.speed_kt, d)))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    outln!(
        o,
        "- **Fixed wing** (clean rotor, the aircraft file's `[wing]` scaled in area). ΔF_prop \
         (= total drag in level flight) against no wing: {}. The 1.7 m² wing gains most at {}; \
         the paper's §6 cites about −12 % total drag at cruise for 1.7 m², which this model \
         reaches only with a much higher wing C_L or more rotor drag shed per newton of lift \
         ({studies_doc}).",
        cells.join("; "),
        best.map_or("no speed".to_string(), |(v, d)| format!(
            "{v} kt ({d:+.1} %)"
        ))
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::GridSpec;

    /// The section on small tables (2 Re × 2 M × α −6…14°, solved into a temporary cache):
    /// every study present, the bullets read from their records, the wing's figure listed.
    #[test]
    fn section_states_each_study_from_its_records() {
        let dir = tempfile::tempdir().unwrap();
        let cache = TableCache::new(
            dir.path().to_path_buf(),
            GridSpec {
                reynolds: vec![0.7e6, 1.5e6],
                mach: vec![0.2, 0.4],
                alpha_deg: (-6..=14).map(f64::from).collect(),
            },
            crate::geometry::DEFAULT_PANEL_NODES,
            0,
        );
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let ac = Aircraft::from_toml_file(&root.join("aircraft/mtosport.toml")).unwrap();
        let b = run_with(&ac, &cache, &crate::progress::Silent).unwrap();
        let text = b.markdown(&studies_doc_reference(&root.join("report")));
        assert!(text.starts_with("## Beyond the paper"));
        // In the repository the study notes are a link; elsewhere named in words.
        assert!(text.contains("[docs/studies.md](../docs/studies.md)"));
        let elsewhere = studies_doc_reference(dir.path());
        assert!(!elsewhere.contains("](") && elsewhere.contains("docs/studies.md"));
        // One entry per trip location, each with the Δ engine rpm of its record.
        let trip_line = text
            .lines()
            .find(|l| l.contains("**Trip location.**"))
            .unwrap();
        for r in b
            .contamination
            .records
            .iter()
            .filter(|r| r.group == Group::Trip)
        {
            let entry = format!(
                "{:.0} % {}",
                100.0 * r.xtr_top,
                signed(r.penalty.delta_engine_rpm)
            );
            assert!(trip_line.contains(&entry), "{entry} missing: {trip_line}");
        }
        // The airfoil bullet carries both airfoils' penalties.
        let a = &b.airfoils.records;
        assert_eq!(a.len(), 4);
        let airfoil_line = text.lines().find(|l| l.contains("**Airfoil.**")).unwrap();
        let pct = format!("{:+.1} %", a[3].penalty.delta_prop_thrust_pct);
        assert!(airfoil_line.contains(&pct), "{pct}: {airfoil_line}");
        // The wing: the shipped aircraft has a [wing] of area 0, scaled to each area.
        let w = b.wing.as_ref().expect("the shipped aircraft has a [wing]");
        let o = WingOptions::default();
        assert_eq!(w.records.len(), o.areas_m2.len() * o.speeds_kt.len());
        let wing_line = text.lines().find(|l| l.contains("**Fixed wing**")).unwrap();
        let r = w
            .records
            .iter()
            .find(|r| r.wing_area_m2 == 1.7 && r.speed_kt == 60.0)
            .unwrap();
        let entry = format!("60 kt {:+.1} %", r.delta_prop_thrust_pct.unwrap());
        assert!(wing_line.contains(&entry), "{entry}: {wing_line}");
        assert!(
            r.delta_prop_thrust_pct.unwrap() < 0.0,
            "a lifting wing unloads the rotor"
        );
        assert!(text.contains("![Fixed wing](wing.png)"));
        let stems: Vec<String> = b.figures().unwrap().into_iter().map(|f| f.0).collect();
        assert_eq!(stems.len(), figure_stems().len());
    }
}
