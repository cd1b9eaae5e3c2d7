//! The rotor model on a second rotor: the Pitcairn PCA-2 autogiro rotor against its
//! full-scale tunnel tests (Wheatley & Hood, NACA Report 515, 1935, Tables III and II: pitch
//! settings 1.9° and 0.8°, protuberances faired) and its flight tests (Wheatley, NACA Report
//! 487, 1934, Figs. 7 and 8: thrust coefficient, rotor speed, coning and flapping against μ).
//!
//! * [`tunnel_comparison`] — every row of a table as a tunnel case (α and the wind speed
//!   V = μ·Ω·R/cos α of the row), the autorotating rotor beside the measurement, and the mean
//!   errors by α band ([`TunnelComparison::band`]).
//! * [`flight_comparison`] — every flight point of Fig. 7 as a trim: the rotor at the flight's
//!   speed V = μ·Ω·R and density carries the measured thrust C_T·ρπR²(ΩR)²; its rotor speed,
//!   coning and flapping beside the measured ones ([`flapping_errors`]).
//!
//! The measured data are the project's copies in `tests/data/pca2/` (their README says how
//! each was made); nothing here is fitted to them.

mod preset_change;

pub use preset_change::PresetChange;

use crate::rotor::{
    autorotate_outcomes, trim_rotor, Atmosphere, BladeSection, CaseOutcome, ElasticTorsion, Rotor,
    TrimError, TrimParams, TunnelCase,
};
use crate::section::{PolarPoint, Transition};
use crate::table::{PolarTable, TableError, TableMeta};
use serde::Deserialize;

/// NACA Report 515, Table III (μ, α, C_L, C_D, L/D, rpm) with the wind speed of each row.
const TABLE3_CSV: &str = include_str!("../../../tests/data/pca2/tr515_table3_pitch1.9_faired.csv");

/// NACA Report 515, Table II (pitch setting 0.8°), the same columns.
const TABLE2_CSV: &str = include_str!("../../../tests/data/pca2/tr515_table2_pitch0.8_faired.csv");

/// NACA Report 487, Fig. 7: measured thrust coefficient and rotor speed against μ.
const FLIGHT_ROTOR_CSV: &str = include_str!("../../../tests/data/pca2/tr487_flight_rotor.csv");

/// NACA Report 487, Fig. 8: measured coning and flapping (a0, a1, b1) against μ.
const FLIGHT_FLAPPING_CSV: &str =
    include_str!("../../../tests/data/pca2/tr487_flight_flapping.csv");

/// Blade pitch of the flight tests at the inboard blade \[deg\]: NACA Report 487 p. 12,
/// 0.0384 rad measured in flight (the preset's twist is relative to it).
pub const FLIGHT_PITCH_DEG: f64 = 2.2;

/// Air density of the flight tests [kg/m³]: NACA Report 487 p. 13, 0.00210 slug/ft³, "the
/// average density encountered during the tests".
pub const FLIGHT_DENSITY: f64 = 1.0823;

/// α band limit of the tunnel comparison \[deg\]: at and above it the μ range of the MTOsport's
/// flight (μ up to about 0.3).
pub const ALPHA_BAND_DEG: f64 = 4.0;

/// NACA Report 487's section constants for this blade (p. 13): lift slope a = 5.85 per rad
/// ("corresponding to infinite aspect ratio ... a good average") and profile drag δ = 0.0120
/// (one and a half times the section's minimum, Report 487 section 10).
pub const REPORT_487_SECTION: (f64, f64) = (5.85, 0.012);

/// The PCA-2 blade's elastic torsion as NACA Report 487 describes it (p. 13: the lift,
/// offset from the blade's centre of gravity, twists the blade "approximately 2.4° (0.0419
/// radian) at the tip" in flight; nose-up, as the measured pitch rises outboard, Fig. 5) for
/// the preset's flight-measured twist: on the outer blade, where the measured pitch is linear
/// (from 39.4 % R), at the mean rotor thrust of the report's flight points (Fig. 7: C_T ρπR²
/// (ΩR)² at the tests' average density, 10.64 kN; the points span 6.3–12.4 kN, and the report
/// does not say under which the pitch was measured). The preset leaves it out: with it the
/// model's rotor turns faster still against Table III (`tests/rotor_pca2.rs`).
pub const REPORT_487_TORSION: ElasticTorsion = ElasticTorsion {
    tip: 0.0419,
    reference_thrust: 10_640.0,
    from_r_over_r: 0.394,
};

/// Angles of the [`report_487_section`] polar \[deg\]: the attached range of the rotor's blades.
const REPORT_487_ALPHA_DEG: (i32, i32) = (-10, 14);

/// [`REPORT_487_SECTION`] as a one-polar table, c_l = a·α and c_d = δ from −10° to 14° (a
/// point per degree), continued to ±180° by the tables' 360° extension: the rotor model with
/// the section data of the blade's own analysis, to tell the section's share of a disagreement
/// from the rotor model's.
pub fn report_487_section() -> Result<PolarTable, TableError> {
    let (a, delta) = REPORT_487_SECTION;
    let points = (REPORT_487_ALPHA_DEG.0..=REPORT_487_ALPHA_DEG.1)
        .map(|deg| {
            let alpha = f64::from(deg);
            PolarPoint::from_coefficients(alpha, a * alpha.to_radians(), delta, 0.0)
        })
        .collect();
    let meta = TableMeta {
        airfoil: "NACA Report 487 section constants".to_string(),
        transition: Transition::default(),
        thickness: f64::NAN,
        panels: 0,
        solver: "analytic".to_string(),
        geometry: Vec::new(),
    };
    PolarTable::new(meta, vec![3e6], vec![0.0], vec![points])
}

/// One row of a table of NACA Report 515.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
pub struct TunnelMeasurement {
    /// Tip-speed ratio μ.
    pub mu: f64,
    /// Rotor angle of attack α \[deg\].
    pub alpha_deg: f64,
    /// Lift coefficient on q·πR².
    pub cl: f64,
    /// Drag coefficient on q·πR².
    pub cd: f64,
    /// L/D as printed.
    pub lift_to_drag: f64,
    /// Rotor speed \[rpm\].
    pub rotor_rpm: f64,
    /// Wind speed V = μ·Ω·R/cos α \[m/s\].
    pub speed_m_s: f64,
}

/// The tables of NACA Report 515 in the repository, both with the protuberances faired. Table
/// IV (pitch setting 2.7°) is kept out on purpose: an independent check held by the project's
/// owners.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TunnelTable {
    /// Table II: pitch setting 0.8° (108 rows).
    II,
    /// Table III: pitch setting 1.9° (81 rows), the preset's.
    III,
}

impl TunnelTable {
    /// The table's blade pitch setting \[deg\].
    pub fn pitch_deg(self) -> f64 {
        match self {
            Self::II => 0.8,
            Self::III => 1.9,
        }
    }

    /// The table's rows, in the report's order.
    pub fn rows(self) -> Vec<TunnelMeasurement> {
        parse_rows(match self {
            Self::II => TABLE2_CSV,
            Self::III => TABLE3_CSV,
        })
    }
}

/// Rows of one of the embedded CSV files (checked by the tests that they parse).
fn parse_rows<T: for<'de> Deserialize<'de>>(text: &str) -> Vec<T> {
    csv::Reader::from_reader(text.as_bytes())
        .deserialize()
        .filter_map(Result::ok)
        .collect()
}

/// A row of a tunnel table and the model's rotor at it.
#[derive(Clone, Debug, PartialEq)]
pub struct TunnelRow {
    /// The measurement.
    pub measured: TunnelMeasurement,
    /// The model (NaN results and the reason when it found no autorotation).
    pub predicted: CaseOutcome,
}

impl TunnelRow {
    /// Relative errors (predicted/measured − 1) of rotor speed, C_L and L/D; `None` when the
    /// case found no autorotation.
    pub fn errors(&self) -> Option<[f64; 3]> {
        let (m, p) = (&self.measured, &self.predicted);
        p.found().then(|| {
            [
                p.result.rotor_rpm / m.rotor_rpm - 1.0,
                p.result.cl / m.cl - 1.0,
                p.result.lift_to_drag / m.lift_to_drag - 1.0,
            ]
        })
    }
}

/// Largest difference of shaft angle of a [`TunnelComparison::speed_trend`] pair \[deg\].
pub const SPEED_PAIR_ALPHA_DEG: f64 = 0.15;

/// Smallest ratio of the measured rotor speeds of a [`TunnelComparison::speed_trend`] pair.
pub const SPEED_PAIR_RPM_RATIO: f64 = 1.25;

/// [`TunnelComparison::speed_trend`]: the mean μ(slower) − μ(faster) of its pairs of rows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedTrend {
    /// Pairs of rows.
    pub pairs: usize,
    /// Measured mean difference of μ.
    pub measured: f64,
    /// Predicted mean difference of μ.
    pub predicted: f64,
}

/// The mean relative errors over the rows of an α band.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BandErrors {
    /// Rows of the band.
    pub rows: usize,
    /// Rows without an autorotation (left out of the means).
    pub failed: usize,
    /// Mean relative error of the rotor speed.
    pub rotor_rpm: f64,
    /// Mean relative error of C_L.
    pub cl: f64,
    /// Mean relative error of L/D.
    pub lift_to_drag: f64,
    /// Largest |relative error| of the rotor speed.
    pub rotor_rpm_max: f64,
}

/// A tunnel table against the model.
#[derive(Clone, Debug, PartialEq)]
pub struct TunnelComparison {
    /// Every row, in the table's order.
    pub rows: Vec<TunnelRow>,
}

impl TunnelComparison {
    /// Mean errors over the rows with `lo ≤ α < hi` \[deg\].
    pub fn band(&self, lo: f64, hi: f64) -> BandErrors {
        let band: Vec<&TunnelRow> = self
            .rows
            .iter()
            .filter(|r| (lo..hi).contains(&r.measured.alpha_deg))
            .collect();
        let errors: Vec<[f64; 3]> = band.iter().filter_map(|r| r.errors()).collect();
        let n = errors.len().max(1) as f64;
        let mean = |i: usize| errors.iter().map(|e| e[i]).sum::<f64>() / n;
        BandErrors {
            rows: band.len(),
            failed: band.len() - errors.len(),
            rotor_rpm: mean(0),
            cl: mean(1),
            lift_to_drag: mean(2),
            rotor_rpm_max: errors.iter().fold(0.0, |a, e| a.max(e[0].abs())),
        }
    }

    /// How μ changes with the wind speed at one shaft angle, measured and predicted: over the
    /// pairs of rows with `lo ≤ α < hi` whose angles differ by at most
    /// [`SPEED_PAIR_ALPHA_DEG`] and whose measured rotor speeds differ by more than
    /// [`SPEED_PAIR_RPM_RATIO`], the mean of μ(slower row) − μ(faster row). The tunnel's rotor
    /// reaches a higher μ at the lower speed; a rigid blade with the same coefficients at every
    /// speed would not, apart from the Reynolds number. `None` without such pairs.
    pub fn speed_trend(&self, lo: f64, hi: f64) -> Option<SpeedTrend> {
        let rows: Vec<&TunnelRow> = self
            .rows
            .iter()
            .filter(|r| (lo..hi).contains(&r.measured.alpha_deg) && r.errors().is_some())
            .collect();
        let (mut measured, mut predicted, mut pairs) = (0.0, 0.0, 0usize);
        for slow in &rows {
            for fast in &rows {
                let (a, b) = (&slow.measured, &fast.measured);
                if (a.alpha_deg - b.alpha_deg).abs() <= SPEED_PAIR_ALPHA_DEG
                    && b.rotor_rpm > SPEED_PAIR_RPM_RATIO * a.rotor_rpm
                {
                    measured += a.mu - b.mu;
                    predicted += slow.predicted.result.mu - fast.predicted.result.mu;
                    pairs += 1;
                }
            }
        }
        (pairs > 0).then(|| SpeedTrend {
            pairs,
            measured: measured / pairs as f64,
            predicted: predicted / pairs as f64,
        })
    }
}

/// The tunnel's air: ISA sea level (NACA Report 515 gives coefficients; the tunnel ran near
/// sea level, and the air state sets only the Reynolds number, the Mach number and the Lock
/// number).
pub fn tunnel_atmosphere() -> Atmosphere {
    Atmosphere::isa(0.0)
}

/// Every row of `table` with the autorotating `rotor` at the table's pitch setting (blade
/// section `section`), in parallel.
pub fn tunnel_comparison<S: BladeSection + Sync + ?Sized>(
    table: TunnelTable,
    rotor: &Rotor,
    section: &S,
) -> TunnelComparison {
    let measured = table.rows();
    let rotor = &Rotor {
        pitch: table.pitch_deg().to_radians(),
        ..rotor.clone()
    };
    let cases: Vec<TunnelCase> = measured
        .iter()
        .map(|m| TunnelCase {
            alpha_deg: m.alpha_deg,
            speed_m_s: m.speed_m_s,
        })
        .collect();
    let outcomes = autorotate_outcomes(
        rotor,
        section,
        &cases,
        &tunnel_atmosphere(),
        &TrimParams::default(),
        &crate::progress::Silent,
    );
    TunnelComparison {
        rows: measured
            .into_iter()
            .zip(outcomes)
            .map(|(measured, predicted)| TunnelRow {
                measured,
                predicted,
            })
            .collect(),
    }
}

/// The measured flight points of Fig. 7: (μ, C_T, rotor rpm), C_T and rpm read at their own μ
/// and paired in order of μ.
pub fn flight_points() -> Vec<(f64, f64, f64)> {
    let series = |name| quantity_series(FLIGHT_ROTOR_CSV, name);
    series("ct")
        .into_iter()
        .zip(series("rotor_rpm"))
        .map(|((mu_c, ct), (mu_n, rpm))| (0.5 * (mu_c + mu_n), ct, rpm))
        .collect()
}

/// The measured coning and flapping of Fig. 8 (degrees, NACA signs) as (μ, value) series:
/// a0, a1, b1.
pub fn flight_flapping() -> [Vec<(f64, f64)>; 3] {
    ["a0_deg", "a1_deg", "b1_deg"].map(|name| quantity_series(FLIGHT_FLAPPING_CSV, name))
}

/// The (μ, value) pairs of quantity `name` in a long-form CSV of `quantity,mu,value` rows, in
/// order of μ.
fn quantity_series(csv_text: &str, name: &str) -> Vec<(f64, f64)> {
    let mut s: Vec<(f64, f64)> = csv::Reader::from_reader(csv_text.as_bytes())
        .deserialize::<(String, f64, f64)>()
        .filter_map(Result::ok)
        .filter(|d| d.0 == name)
        .map(|d| (d.1, d.2))
        .collect();
    s.sort_by(|a, b| a.0.total_cmp(&b.0));
    s
}

/// The model trimmed at one flight point of NACA Report 487.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlightPoint {
    /// Measured tip-speed ratio.
    pub mu_measured: f64,
    /// Measured thrust coefficient.
    pub ct_measured: f64,
    /// Measured rotor speed \[rpm\].
    pub rpm_measured: f64,
    /// The model's rotor speed \[rpm\].
    pub rotor_rpm: f64,
    /// The model's tip-speed ratio.
    pub mu: f64,
    /// The model's rotor angle of attack (hub plane) \[deg\].
    pub alpha_deg: f64,
    /// The model's coning a0 \[deg\].
    pub a0_deg: f64,
    /// The model's longitudinal flapping a1 \[deg\].
    pub a1_deg: f64,
    /// The model's lateral flapping b1 \[deg\].
    pub b1_deg: f64,
}

/// The flight tests' air: [`FLIGHT_DENSITY`] with the ISA sea-level temperature, viscosity
/// and speed of sound.
pub fn flight_atmosphere() -> Atmosphere {
    Atmosphere {
        density: FLIGHT_DENSITY,
        ..Atmosphere::isa(0.0)
    }
}

/// Every flight point of Fig. 7 trimmed with `rotor` (its pitch the flight's; see
/// [`FLIGHT_PITCH_DEG`]): at V = μ·Ω·R (Ω the measured rotor speed) the autorotating rotor
/// lifts the measured thrust C_T·ρπR²(ΩR)². A point that does not trim keeps its error.
pub fn flight_comparison<S: BladeSection + Sync + ?Sized>(
    rotor: &Rotor,
    section: &S,
) -> Vec<Result<FlightPoint, TrimError>> {
    use rayon::prelude::*;
    let atm = flight_atmosphere();
    flight_points()
        .par_iter()
        .map(|&(mu, ct, rpm)| {
            let tip = crate::rotor::rpm_to_rad_s(rpm) * rotor.radius;
            let v = mu * tip;
            let thrust = ct * atm.density * rotor.disc_area() * tip * tip;
            let s = trim_rotor(rotor, section, v, thrust, &atm, &TrimParams::default())?;
            Ok(FlightPoint {
                mu_measured: mu,
                ct_measured: ct,
                rpm_measured: rpm,
                rotor_rpm: crate::rotor::rad_s_to_rpm(s.condition.omega),
                mu: s.advance_ratio,
                alpha_deg: s.condition.hub_aoa.to_degrees(),
                a0_deg: s.flapping.beta0.to_degrees(),
                a1_deg: -s.flapping.beta1c.to_degrees(),
                b1_deg: -s.flapping.beta1s.to_degrees(),
            })
        })
        .collect()
}

/// Model-minus-measured differences of one flapping quantity \[deg\].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FlappingError {
    /// Measured points compared.
    pub points: usize,
    /// Mean difference (model − measured).
    pub mean: f64,
    /// Mean |difference|.
    pub mean_abs: f64,
    /// Mean difference relative to the measured value.
    pub mean_relative: f64,
}

/// The model's flapping against Fig. 8 of NACA Report 487.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FlappingErrors {
    /// Coning a0.
    pub a0: FlappingError,
    /// Longitudinal flapping a1.
    pub a1: FlappingError,
    /// Lateral flapping b1.
    pub b1: FlappingError,
    /// Lateral flapping with the model's coning error taken out to first order:
    /// b1 − (4/3)·μ·(a0 − a0_measured)/(1 + μ²/2), the coning's share of b1 in uniform-inflow
    /// flapping theory (NACA Report 487, eq. 9-11 with B = 1). What is left is the part of b1
    /// that the inflow distribution decides.
    pub b1_coning_corrected: FlappingError,
}

/// The model's coning and flapping against the measured points of Fig. 8 with
/// `mu_range.0 ≤ μ ≤ mu_range.1`, the model interpolated linearly in μ between the trimmed
/// `points` (measured points outside their μ range are left out).
pub fn flapping_errors(points: &[FlightPoint], mu_range: (f64, f64)) -> FlappingErrors {
    let mut model: Vec<&FlightPoint> = points.iter().collect();
    model.sort_by(|a, b| a.mu.total_cmp(&b.mu));
    let at = |mu: f64, value: &dyn Fn(&FlightPoint) -> f64| -> Option<f64> {
        let i = model
            .windows(2)
            .position(|w| w[0].mu <= mu && mu <= w[1].mu)?;
        let (a, b) = (model[i], model[i + 1]);
        let t = if b.mu > a.mu {
            (mu - a.mu) / (b.mu - a.mu)
        } else {
            0.0
        };
        Some(value(a) + t * (value(b) - value(a)))
    };
    let [a0, a1, b1] = flight_flapping();
    let a0_measured = |mu: f64| interpolate(&a0, mu);
    let compare = |measured: &[(f64, f64)], value: &dyn Fn(&FlightPoint) -> f64| {
        let pairs: Vec<(f64, f64)> = measured
            .iter()
            .filter(|(mu, _)| (mu_range.0..=mu_range.1).contains(mu))
            .filter_map(|&(mu, v)| at(mu, value).map(|m| (m, v)))
            .collect();
        let n = pairs.len().max(1) as f64;
        FlappingError {
            points: pairs.len(),
            mean: pairs.iter().map(|(m, v)| m - v).sum::<f64>() / n,
            mean_abs: pairs.iter().map(|(m, v)| (m - v).abs()).sum::<f64>() / n,
            mean_relative: pairs.iter().map(|(m, v)| m / v - 1.0).sum::<f64>() / n,
        }
    };
    FlappingErrors {
        a0: compare(&a0, &|p| p.a0_deg),
        a1: compare(&a1, &|p| p.a1_deg),
        b1: compare(&b1, &|p| p.b1_deg),
        b1_coning_corrected: compare(&b1, &|p| {
            p.b1_deg - 4.0 / 3.0 * p.mu * (p.a0_deg - a0_measured(p.mu)) / (1.0 + 0.5 * p.mu * p.mu)
        }),
    }
}

/// Linear interpolation in a series of (μ, value) sorted by μ; the end values outside.
fn interpolate(series: &[(f64, f64)], mu: f64) -> f64 {
    let (Some(first), Some(last)) = (series.first(), series.last()) else {
        return f64::NAN;
    };
    if mu <= first.0 {
        return first.1;
    }
    if mu >= last.0 {
        return last.1;
    }
    let i = series
        .windows(2)
        .position(|w| w[0].0 <= mu && mu <= w[1].0)
        .unwrap_or(0);
    let (a, b) = (series[i], series[i + 1]);
    if b.0 > a.0 {
        a.1 + (mu - a.0) / (b.0 - a.0) * (b.1 - a.1)
    } else {
        a.1
    }
}
