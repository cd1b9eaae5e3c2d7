//! The report's section "The rotor model on a second rotor": the PCA-2 autogiro rotor
//! ([`studies::pca2`](crate::studies::pca2)) against NACA Report 515's tunnel data and NACA
//! Report 487's flight data, its two figures, and where the model holds and where not, in
//! numbers read from the comparisons.

use super::words::{num, pct};
use crate::plot::{Figure, Panel, Series, Style};
use crate::rotor::{InflowModel, Rotor, RotorPreset, TrimError};
use crate::studies::pca2::{
    flapping_errors, flight_comparison, flight_flapping, flight_points, report_487_section,
    tunnel_comparison, BandErrors, FlappingErrors, FlightPoint, PresetChange, TunnelComparison,
    TunnelMeasurement, TunnelRow, TunnelTable, ALPHA_BAND_DEG, FLIGHT_PITCH_DEG,
    REPORT_487_SECTION, REPORT_487_TORSION, SPEED_PAIR_ALPHA_DEG, SPEED_PAIR_RPM_RATIO,
};
use crate::table::{PolarTable, TableError};

/// File stems of the section's figures.
pub(super) const FIGURE_STEMS: [&str; 2] = ["pca2_tunnel", "pca2_flight"];

/// Upper μ of the flight comparison's averages: the range of the MTOsport's flight (and where
/// the PCA-2's rotor speed stays near 140 rpm).
const FLIGHT_MU_MAX: f64 = 0.41;

/// Lower μ of the flapping averages: the lowest flight points' coning is a climb's or a steep
/// glide's (α_H above 20°), far from the MTOsport's cruise.
const FLAPPING_MU_MIN: f64 = 0.15;

/// Everything computed for the section.
pub(super) struct SecondRotor {
    /// The preset's name.
    name: String,
    /// Table III with the free-transition and the tripped table.
    tunnel: [TunnelComparison; 2],
    /// Table III with NACA Report 487's section constants.
    tunnel_487: TunnelComparison,
    /// Table III with the tripped table and the blade's torsion under load
    /// ([`REPORT_487_TORSION`]).
    tunnel_torsion: TunnelComparison,
    /// Table II (pitch setting 0.8°) with the tripped table and with Report 487's constants.
    tunnel_table2: [TunnelComparison; 2],
    /// Table III with the tripped table and one choice of the preset changed, each of
    /// [`PresetChange::ALL`].
    variations: Vec<(PresetChange, TunnelComparison)>,
    /// The flight points with uniform and with Drees inflow (tripped table).
    flight: [Vec<Result<FlightPoint, TrimError>>; 2],
}

/// The inflow models compared in flight, in the order of [`SecondRotor::flight`].
const INFLOWS: [(InflowModel, &str); 2] = [
    (InflowModel::Glauert, "uniform (Glauert)"),
    (InflowModel::Drees, "Drees"),
];

/// Transition settings of the tables, in the order of [`SecondRotor::tunnel`].
const TRANSITIONS: [&str; 2] = ["free transition", "7 % trip"];

/// Runs the comparisons with the preset `preset` and the Göttingen 429 tables (free, tripped).
pub(super) fn run(
    preset: &RotorPreset,
    tables: &[PolarTable; 2],
) -> Result<SecondRotor, TableError> {
    let rotor = Rotor::from_params(&preset.rotor);
    let mut flight_params = preset.rotor.clone();
    flight_params.incidence_deg = FLIGHT_PITCH_DEG;
    let section_487 = report_487_section()?;
    let twisting = Rotor {
        torsion: Some(REPORT_487_TORSION),
        ..rotor.clone()
    };
    // Each comparison solves its rows (and flight points) in parallel itself.
    let tunnel = tables
        .each_ref()
        .map(|t| tunnel_comparison(TunnelTable::III, &rotor, t));
    let tunnel_487 = tunnel_comparison(TunnelTable::III, &rotor, &section_487);
    let tunnel_torsion = tunnel_comparison(TunnelTable::III, &twisting, &tables[1]);
    let tunnel_table2 =
        [&tables[1], &section_487].map(|t| tunnel_comparison(TunnelTable::II, &rotor, t));
    let variations = PresetChange::ALL
        .iter()
        .map(|&c| {
            let changed = c.apply(&rotor);
            (c, tunnel_comparison(TunnelTable::III, &changed, &tables[1]))
        })
        .collect();
    let flight = INFLOWS.map(|(inflow, _)| {
        let r = Rotor {
            inflow,
            ..Rotor::from_params(&flight_params)
        };
        flight_comparison(&r, &tables[1])
    });
    Ok(SecondRotor {
        name: preset.name.clone(),
        tunnel,
        tunnel_487,
        tunnel_torsion,
        tunnel_table2,
        variations,
        flight,
    })
}

/// A band's mean errors as the report words them: "rotor rpm …, C_L …, L/D …".
fn errors_in_words(b: &BandErrors) -> String {
    format!(
        "rotor rpm {}, C_L {}, L/D {}",
        pct(100.0 * b.rotor_rpm),
        pct(100.0 * b.cl),
        pct(100.0 * b.lift_to_drag)
    )
}

/// The trimmed flight points of `runs`.
fn trimmed(runs: &[Result<FlightPoint, TrimError>]) -> Vec<FlightPoint> {
    runs.iter()
        .filter_map(|r| r.as_ref().ok().copied())
        .collect()
}

impl SecondRotor {
    /// The section's figures: Table III (L/D and rotor speed against μ, measured and
    /// predicted) and the flight (coning, flapping and rotor speed against μ).
    pub(super) fn figures(&self) -> [(&'static str, Figure); 2] {
        [
            (FIGURE_STEMS[0], self.tunnel_figure()),
            (FIGURE_STEMS[1], self.flight_figure()),
        ]
    }

    fn tunnel_figure(&self) -> Figure {
        let rows = &self.tunnel[0].rows;
        let measured = |y: fn(&TunnelMeasurement) -> f64| {
            Series::new(
                "NACA Report 515, Table III",
                rows.iter().map(|r| r.measured.mu).collect(),
                rows.iter().map(|r| y(&r.measured)).collect(),
                Style::points(0),
            )
        };
        let mut ratio = Panel::new("Lift-to-drag ratio", "tip-speed ratio μ", "L/D")
            .with_series(measured(|m| m.lift_to_drag));
        let mut rpm = Panel::new(
            "Autorotative rotor speed, each row at its measured μ",
            "tip-speed ratio μ (measured)",
            "rotor speed [rpm]",
        )
        .with_series(measured(|m| m.rotor_rpm));
        for (k, (c, label)) in self.tunnel.iter().zip(TRANSITIONS).enumerate() {
            let found: Vec<&TunnelRow> = c.rows.iter().filter(|r| r.predicted.found()).collect();
            ratio = ratio.with_series(Series::new(
                format!("model, {label} (at its own μ)"),
                found.iter().map(|r| r.predicted.result.mu).collect(),
                found
                    .iter()
                    .map(|r| r.predicted.result.lift_to_drag)
                    .collect(),
                Style::points(k + 1),
            ));
            rpm = rpm.with_series(Series::new(
                format!("model, {label}"),
                found.iter().map(|r| r.measured.mu).collect(),
                found.iter().map(|r| r.predicted.result.rotor_rpm).collect(),
                Style::points(k + 1),
            ));
        }
        Figure::new(format!(
            "{} in the NACA full-scale tunnel, pitch setting 1.9° — measured and predicted",
            self.name
        ))
        .with_panel(ratio)
        .with_panel(rpm)
    }

    fn flight_figure(&self) -> Figure {
        let names = ["a0 coning", "a1", "b1"];
        let measured = flight_flapping();
        let mut flapping = Panel::new(
            "Coning and flapping in flight (NACA signs)",
            "tip-speed ratio μ",
            "angle [deg]",
        );
        for (k, series) in measured.iter().enumerate() {
            let (x, y) = series.iter().copied().unzip();
            flapping = flapping.with_series(Series::new(
                format!("{} measured (Report 487 Fig. 8)", names[k]),
                x,
                y,
                Style::points(k),
            ));
        }
        let mut rpm = Panel::new(
            "Rotor speed in flight",
            "tip-speed ratio μ",
            "rotor speed [rpm]",
        );
        let flight = flight_points();
        rpm = rpm.with_series(Series::new(
            "measured (Report 487 Fig. 7)",
            flight.iter().map(|p| p.0).collect(),
            flight.iter().map(|p| p.2).collect(),
            Style::points(0),
        ));
        for (runs, (_, label)) in self.flight.iter().zip(INFLOWS) {
            let mut points = trimmed(runs);
            points.sort_by(|a, b| a.mu.total_cmp(&b.mu));
            let style = |k: usize| {
                if label == "Drees" {
                    Style::solid(k)
                } else {
                    Style::dashed(k)
                }
            };
            let mu: Vec<f64> = points.iter().map(|p| p.mu).collect();
            for (k, value) in [
                (|p: &FlightPoint| p.a0_deg) as fn(&FlightPoint) -> f64,
                |p| p.a1_deg,
                |p| p.b1_deg,
            ]
            .into_iter()
            .enumerate()
            {
                flapping = flapping.with_series(Series::new(
                    format!("{} model, {label} inflow", names[k]),
                    mu.clone(),
                    points.iter().map(value).collect(),
                    style(k),
                ));
            }
            rpm = rpm.with_series(Series::new(
                format!("model, {label} inflow"),
                mu,
                points.iter().map(|p| p.rotor_rpm).collect(),
                style(if label == "Drees" { 1 } else { 2 }),
            ));
        }
        Figure::new(format!(
            "{} in flight (NACA Report 487): trimmed to the measured thrust at the flight's speed",
            self.name
        ))
        .with_panel(flapping)
        .with_panel(rpm)
    }

    /// The section's Markdown.
    pub(super) fn markdown(&self) -> String {
        let mut out = String::new();
        let o = &mut out;
        outln!(o, "## The rotor model on a second rotor");
        outln!(o);
        outln!(
            o,
            "The same rotor model, set up for the Pitcairn PCA-2 autogiro (`aircraft/pca2.toml`: \
             four blades on flapping hinges, free coning from the blades' flapping inertia, the \
             stepped chord and the twist of NACA Report 487, every value with its source) and \
             given polargen's own Göttingen 429 tables (`polars/goe429_*.csv`), against the \
             rotor's full-scale tunnel tests (Wheatley & Hood, NACA Report 515, Table III: pitch \
             setting 1.9°, 81 rows; each row computed at its α and wind speed, ISA sea level) \
             and its flight tests (NACA Report 487, Figs. 7–8; each flight point trimmed so that \
             the rotor lifts the measured thrust at the flight's speed and density, pitch as \
             measured in flight). Its tip loss, yawed-flow drag and induced-power factor are the \
             MTOsport preset's; nothing is fitted to these data. The data are copied in \
             `tests/data/pca2/` (how each was made: its README); `tests/rotor_pca2.rs` guards \
             the numbers below."
        );
        outln!(o);
        self.tunnel_words(o);
        self.flight_words(o);
        outln!(o, "![PCA-2 in the tunnel](pca2_tunnel.png)");
        outln!(o);
        outln!(o, "![PCA-2 in flight](pca2_flight.png)");
        outln!(o);
        out
    }

    fn tunnel_words(&self, o: &mut String) {
        let band = |c: &TunnelComparison, high: bool| {
            if high {
                c.band(ALPHA_BAND_DEG, 90.0)
            } else {
                c.band(-90.0, ALPHA_BAND_DEG)
            }
        };
        outln!(
            o,
            "Table III, mean error of the model (predicted/measured − 1) by α band:"
        );
        outln!(o);
        outln!(
            o,
            "| section data | α band | rows | rotor rpm | C_L | L/D | largest rpm error |"
        );
        outln!(o, "|---|---|---|---|---|---|---|");
        let (a, d) = REPORT_487_SECTION;
        let label_487 = format!("Report 487's constants (a {a}/rad, δ {d})");
        let cases: Vec<(&TunnelComparison, &str)> = self
            .tunnel
            .iter()
            .zip(TRANSITIONS)
            .chain([
                (&self.tunnel_487, label_487.as_str()),
                (
                    &self.tunnel_torsion,
                    "7 % trip, blade torsion ∝ thrust (Report 487's 2.4°)",
                ),
                (
                    &self.tunnel_table2[0],
                    "7 % trip, Table II (pitch setting 0.8°, 108 rows)",
                ),
                (
                    &self.tunnel_table2[1],
                    "Report 487's constants, Table II (pitch setting 0.8°)",
                ),
            ])
            .collect();
        for (c, label) in &cases {
            for high in [true, false] {
                let b: BandErrors = band(c, high);
                outln!(
                    o,
                    "| {label} | {} | {}{} | {} | {} | {} | {} |",
                    if high { "α ≥ 4°" } else { "α < 4°" },
                    b.rows,
                    if b.failed > 0 {
                        format!(" ({} without autorotation)", b.failed)
                    } else {
                        String::new()
                    },
                    pct(100.0 * b.rotor_rpm),
                    pct(100.0 * b.cl),
                    pct(100.0 * b.lift_to_drag),
                    pct(100.0 * b.rotor_rpm_max)
                );
            }
        }
        outln!(o);
        let t = band(&self.tunnel[1], true);
        let f = band(&self.tunnel[0], true);
        let r = band(&self.tunnel_487, true);
        let max_mu = |c: &TunnelComparison| {
            c.rows
                .iter()
                .filter(|r| r.predicted.found())
                .fold(0.0_f64, |m, r| m.max(r.predicted.result.mu))
        };
        outln!(
            o,
            "Where it holds: at α ≥ 4° (μ up to 0.32, the MTOsport's range) the lift-to-drag \
             ratio is within {} % (tripped) and {} % (free). Where not: with polargen's tables \
             the rotor turns too fast ({} tripped, {} free) and lifts too much (C_L {} and {}) \
             at the tunnel's α. The same rotor model with the section constants Report 487 gives \
             for this blade (lift slope {a} per rad, profile drag {d}) is off by {} in rotor \
             speed and {} in C_L — within 5 % and 8 % — and {} in L/D (a constant drag \
             coefficient is too high at the rotor's low c_l): the disagreement is the section \
             data's, not the rotor model's. polargen's Göttingen 429 is a smooth two-dimensional \
             section (lift slope 6.9 per rad, c_d 0.009–0.011 with the trip at Re 2–3·10⁶), \
             about a third less drag per lift slope than Report 487's values for the \
             fabric-covered blade of 1934. Free transition is the further off, as a fabric blade \
             with ribs is not laminar.",
            num(100.0 * t.lift_to_drag.abs(), 1),
            num(100.0 * f.lift_to_drag.abs(), 1),
            pct(100.0 * t.rotor_rpm),
            pct(100.0 * f.rotor_rpm),
            pct(100.0 * t.cl),
            pct(100.0 * f.cl),
            pct(100.0 * r.rotor_rpm),
            pct(100.0 * r.cl),
            pct(100.0 * r.lift_to_drag),
        );
        outln!(o);
        outln!(
            o,
            "α < 4° (μ 0.30–0.72) is a limitation of the model: the tunnel's rotor kept turning \
             at about 100 rpm as the wind rose, reaching μ 0.72 at α 1.1°, while the model's \
             rotor speeds up with the wind and reaches μ {} at most (tripped; {} with Report \
             487's constants), so its rotor speed is far too high there. Report 487's own \
             theory shows the same, its errors \"becoming important above a tip-speed ratio \
             of about 0.40\" in flight. The cause is not found here: not the section data (the \
             constants above leave it), not the coning (free, modelled), not the blade's \
             torsion under load (below).",
            num(max_mu(&self.tunnel[1]), 2),
            num(max_mu(&self.tunnel_487), 2),
        );
        outln!(o);
        let low_pitch = band(&self.tunnel_table2[0], true);
        let low_pitch_487 = band(&self.tunnel_table2[1], true);
        outln!(
            o,
            "At the lower pitch setting of Table II (0.8°; the report's Table II, transcribed for \
             this project) the model with polargen's table is further off at α ≥ 4°: {} \
             (Table III: {}, {}, {}); the tunnel's rotor slowed more than the \
             model's when the pitch was lowered. With Report 487's constants the rotor speed \
             holds at both settings ({} at 0.8°, {} at 1.9°; C_L {} at 0.8°): with a constant \
             drag coefficient (and the lower lift slope) the rotor speed follows the pitch as \
             the tunnel's did; with polargen's smooth section it does not.",
            errors_in_words(&low_pitch),
            pct(100.0 * t.rotor_rpm),
            pct(100.0 * t.cl),
            pct(100.0 * t.lift_to_drag),
            pct(100.0 * low_pitch_487.rotor_rpm),
            pct(100.0 * r.rotor_rpm),
            pct(100.0 * low_pitch_487.cl),
        );
        outln!(o);
        self.torsion_words(o);
        self.variation_words(o);
    }

    /// What the α ≥ 4° errors depend on: the preset with one choice changed at a time.
    fn variation_words(&self, o: &mut String) {
        let high = |c: &TunnelComparison| c.band(ALPHA_BAND_DEG, 90.0);
        let preset = high(&self.tunnel[1]);
        outln!(
            o,
            "What the α ≥ 4° errors depend on: the preset with one choice changed at a time \
             (Table III, 7 % trip; `studies::pca2::PresetChange`):"
        );
        outln!(o);
        outln!(
            o,
            "| change | rotor rpm | C_L | L/D | rotor rpm at α < 4° |"
        );
        outln!(o, "|---|---|---|---|---|");
        let row = |o: &mut String, label: &str, c: &TunnelComparison| {
            let (h, l) = (high(c), c.band(-90.0, ALPHA_BAND_DEG));
            outln!(
                o,
                "| {label} | {} | {} | {} | {} |",
                pct(100.0 * h.rotor_rpm),
                pct(100.0 * h.cl),
                pct(100.0 * h.lift_to_drag),
                pct(100.0 * l.rotor_rpm)
            );
        };
        row(o, "none (the preset)", &self.tunnel[1]);
        for (change, c) in &self.variations {
            row(o, change.label(), c);
        }
        outln!(o);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        let (mut untwisted, mut report_487) = (preset, preset);
        for (change, c) in &self.variations {
            let b = high(c);
            match change {
                PresetChange::Untwisted => untwisted = b,
                PresetChange::Report487Modelling => report_487 = b,
                _ => {
                    lo = lo.min(b.rotor_rpm);
                    hi = hi.max(b.rotor_rpm);
                }
            }
        }
        outln!(
            o,
            "No single choice of the inflow, the tip loss, the yawed-flow drag, the induced \
             power, the root cut-out or where the setting is read brings the rotor speed within \
             5 %: they leave its error between {} and {} (preset {}). Report 487's own modelling \
             of this rotor, uniform inflow with its tip-loss rule together, gives {}. The \
             presets keep Drees' inflow, which the flight's lateral flapping \
             supports (below), and the MTOsport's Prandtl tip loss: choosing either on this \
             table would be fitting the model to it. The blade's pitch along the span moves C_L \
             most: taken untwisted, all at its 1.9° setting, the blade would give {}. \
             Report 487 measured the blade twisted in flight (the tip 1.9° above \
             the inboard pitch; the lift's torsion alone about 2.4° at the tip), and the tunnel \
             did not measure the pitch under load, so the preset keeps the measured twist; the \
             row shows how much the comparison hangs on the pitch the blades took in the tunnel.",
            pct(100.0 * lo),
            pct(100.0 * hi),
            pct(100.0 * preset.rotor_rpm),
            errors_in_words(&report_487),
            errors_in_words(&untwisted),
        );
        outln!(o);
    }

    /// The blade's torsion under load: what it does to the levels and to the trend with the
    /// wind speed at one α.
    fn torsion_words(&self, o: &mut String) {
        let twisted = self.tunnel_torsion.band(ALPHA_BAND_DEG, 90.0);
        let twisted_low = self.tunnel_torsion.band(-90.0, ALPHA_BAND_DEG);
        let trend = |c: &TunnelComparison| c.speed_trend(-90.0, ALPHA_BAND_DEG);
        let (Some(rigid), Some(torsion)) = (trend(&self.tunnel[1]), trend(&self.tunnel_torsion))
        else {
            return;
        };
        outln!(
            o,
            "The preset's pitch is the one Report 487 measured in flight, its blade twisted \
             nose-up by the lift (about 2.4° at the tip, its Fig. 5 and p. 13). Made \
             proportional to the rotor thrust (2.4° at the flights' mean thrust, \
             `studies::pca2::REPORT_487_TORSION`; nothing fitted), the torsion turns the rotor \
             faster still (rotor rpm {} at α ≥ 4°, {} at α < 4°; C_L {}): the model's rotor \
             carries more thrust than the tunnel's, so its blade twists further. It does give \
             the tunnel's trend with the wind speed at one α the right order: at α < 4°, over \
             {} pairs of rows within {SPEED_PAIR_ALPHA_DEG}° whose rotor speeds differ by more \
             than {} %, the slower rotor reached a μ higher by {} measured, {} with the rigid blade (the \
             Reynolds number alone) and {} with the twisting one. A load-dependent pitch is in \
             the data; the preset leaves the torsion out because it moves the levels further \
             from them.",
            pct(100.0 * twisted.rotor_rpm),
            pct(100.0 * twisted_low.rotor_rpm),
            pct(100.0 * twisted.cl),
            rigid.pairs,
            num(100.0 * (SPEED_PAIR_RPM_RATIO - 1.0), 0),
            num(rigid.measured, 3),
            num(rigid.predicted, 3),
            num(torsion.predicted, 3),
        );
        outln!(o);
    }

    fn flight_words(&self, o: &mut String) {
        let range = (FLAPPING_MU_MIN, FLIGHT_MU_MAX);
        let errors: Vec<FlappingErrors> = self
            .flight
            .iter()
            .map(|runs| flapping_errors(&trimmed(runs), range))
            .collect();
        let failed: Vec<String> = self.flight[1]
            .iter()
            .zip(flight_points())
            .filter(|(r, _)| r.is_err())
            .map(|(_, p)| format!("μ {}", num(p.0, 3)))
            .collect();
        let drees = trimmed(&self.flight[1]);
        let rpm_errors: Vec<f64> = drees
            .iter()
            .filter(|p| p.mu_measured <= FLIGHT_MU_MAX)
            .map(|p| p.rotor_rpm / p.rpm_measured - 1.0)
            .collect();
        let n = rpm_errors.len().max(1) as f64;
        let mean = rpm_errors.iter().sum::<f64>() / n;
        let worst = rpm_errors.iter().fold(0.0_f64, |a, e| a.max(e.abs()));
        outln!(
            o,
            "In flight (μ ≤ {FLIGHT_MU_MAX}): the rotor speed at the measured load and speed is \
             off by {} on average (largest {}){}. Coning and flapping at μ {FLAPPING_MU_MIN}–\
             {FLIGHT_MU_MAX}, model − measured (degrees; reading tolerance of the digitised \
             points ±0.05°):",
            pct(100.0 * mean),
            pct(100.0 * worst).trim_start_matches('+'),
            if failed.is_empty() {
                String::new()
            } else {
                format!(
                    "; the points at {} found no trim (left out)",
                    failed.join(", ")
                )
            }
        );
        outln!(o);
        outln!(
            o,
            "| inflow | a0 | a1 | b1 | b1 with the coning error taken out |"
        );
        outln!(o, "|---|---|---|---|---|");
        for (e, (_, label)) in errors.iter().zip(INFLOWS) {
            outln!(
                o,
                "| {label} | {} | {} | {} | {} ({}) |",
                num(e.a0.mean, 2),
                num(e.a1.mean, 2),
                num(e.b1.mean, 2),
                num(e.b1_coning_corrected.mean, 2),
                pct(100.0 * e.b1_coning_corrected.mean_relative)
            );
        }
        outln!(o);
        outln!(
            o,
            "The coning comes out about {}° too high with either inflow (Report 487's own \
             calculation is high too and puts it down to the tip losses and the radial \
             distribution of the induced velocity), and the lateral flapping b1 carries \
             (4/3)·μ·a0 of it (Report 487 eq. 9-11). With that share taken out, Drees' inflow \
             gives b1 within {}° on average, where uniform inflow is {} low; the longitudinal \
             flapping a1 favours uniform inflow by {}°. b1 is the quantity the inflow \
             distribution decides (Report 487 Fig. 10: \"the calculated value of b1 depends \
             critically upon the variation of the induced velocity\"), so both presets use Drees' \
             inflow.",
            num(errors[1].a0.mean, 1),
            num(errors[1].b1_coning_corrected.mean_abs, 1),
            pct(100.0 * errors[0].b1_coning_corrected.mean_relative).trim_start_matches('-'),
            num(errors[1].a1.mean_abs - errors[0].a1.mean_abs, 1),
        );
        outln!(o);
    }
}
