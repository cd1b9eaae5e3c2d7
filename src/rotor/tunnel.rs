//! The isolated rotor in a wind tunnel: the autorotative rotor speed at a shaft angle and a
//! wind speed, and the rotor's coefficients in wind axes — the quantities of the NACA
//! full-scale tunnel tests of autogiro rotors (Wheatley & Hood, NACA Report 515, 1935).
//!
//! The rotor angle of attack α is the angle between the wind and the plane normal to the shaft
//! (positive with the disc tilted back, as the hub angle of [`autorotation`]); the tip-speed
//! ratio μ = V cos α/(ΩR); lift and drag are perpendicular and parallel to the wind and their
//! coefficients C_L, C_D are on q·πR², q = ½ρV². Coning and flapping are given in the NACA
//! convention β = a0 − a1 cos ψ − b1 sin ψ (ψ from downwind in the direction of rotation), so
//! a0 = β0, a1 = −β1c (the tip-path plane tilted back), b1 = −β1s (tilted towards the
//! retreating side, ψ = 270°).

use super::aircraft::RotorParams;
use super::atmosphere::Atmosphere;
use super::disc_loads::Rotor;
use super::lookup_shares::LookupShares;
use super::spanwise::BladeSection;
use super::trim::{autorotation, TrimError, TrimParams};
use super::{rad_s_to_rpm, rpm_to_rad_s};
use crate::arguments::ArgumentError;
use crate::input::{read_input_or_stdin, InputError};
use crate::limits::short_number;
use crate::progress::{Progress, Silent, Work};
use rayon::prelude::*;
use serde::Serialize;
use std::path::Path;

/// Shaft angles a tunnel case may have \[deg\]: the disc tilted back up to near broadside, and
/// forward a little (an autorotating rotor needs the air to come up through it).
pub const TUNNEL_ALPHA_RANGE_DEG: (f64, f64) = (-10.0, 85.0);

/// Highest wind speed of a tunnel case \[m/s\] (about 300 kt).
pub const MAX_TUNNEL_SPEED_M_S: f64 = 150.0;

pub use crate::limits::MAX_TUNNEL_CASES;

/// One tunnel condition: shaft angle and wind speed.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize)]
pub struct TunnelCase {
    /// Rotor angle of attack α \[deg\] (module documentation).
    pub alpha_deg: f64,
    /// Wind speed V \[m/s\].
    pub speed_m_s: f64,
}

impl TunnelCase {
    /// The case of tip-speed ratio `mu` at `reference_rpm`: V = μ Ω_ref R/cos α for a rotor of
    /// radius `radius_m` (the tunnel speed that gives μ if the rotor turns at the reference
    /// speed; the autorotative speed, and so the μ reached, is the model's).
    pub fn from_mu(alpha_deg: f64, mu: f64, reference_rpm: f64, radius_m: f64) -> Self {
        Self {
            alpha_deg,
            speed_m_s: mu * rpm_to_rad_s(reference_rpm) * radius_m / alpha_deg.to_radians().cos(),
        }
    }

    /// Checks the case; `alpha_name` and `speed_name` name the values in the error.
    pub fn check(&self, alpha_name: &str, speed_name: &str) -> Result<(), ArgumentError> {
        check_alpha_deg(alpha_name, self.alpha_deg)?;
        let v = self.speed_m_s;
        if !(v.is_finite() && v > 0.0 && v <= MAX_TUNNEL_SPEED_M_S) {
            return Err(ArgumentError::new(
                speed_name,
                v,
                format!("must be above 0 and at most {MAX_TUNNEL_SPEED_M_S} m/s"),
            ));
        }
        Ok(())
    }
}

/// The tunnel case of the arguments `alpha_deg` with either `speed_m_s` or `mu_at_rpm` (μ and
/// the reference rpm it refers to; [`TunnelCase::from_mu`] for a rotor of radius `radius_m`),
/// every value checked; `names` are the caller's names of α, the speed, μ and the reference
/// rpm.
pub fn tunnel_case(
    alpha_deg: f64,
    speed_m_s: Option<f64>,
    mu_at_rpm: Option<(f64, f64)>,
    radius_m: f64,
    names: [&str; 4],
) -> Result<TunnelCase, ArgumentError> {
    let case = match (speed_m_s, mu_at_rpm) {
        (Some(speed_m_s), None) => TunnelCase {
            alpha_deg,
            speed_m_s,
        },
        (None, Some((mu, rpm))) => {
            check_mu(names[2], mu)?;
            check_rpm(names[3], rpm)?;
            TunnelCase::from_mu(alpha_deg, mu, rpm, radius_m)
        }
        _ => {
            return Err(ArgumentError::with_text(
                names[1],
                "",
                format!("give it, or {} with {}, not both", names[2], names[3]),
            ))
        }
    };
    case.check(names[0], names[1])?;
    Ok(case)
}

/// A rotor angle of attack argument \[deg\], within [`TUNNEL_ALPHA_RANGE_DEG`].
pub fn check_alpha_deg(name: &str, deg: f64) -> Result<(), ArgumentError> {
    let (lo, hi) = TUNNEL_ALPHA_RANGE_DEG;
    if (lo..=hi).contains(&deg) {
        return Ok(());
    }
    Err(ArgumentError::new(
        name,
        deg,
        format!("must be between {lo} and {hi} degrees"),
    ))
}

/// A tip-speed ratio argument: above 0 and at most 1.5.
pub fn check_mu(name: &str, mu: f64) -> Result<(), ArgumentError> {
    if mu.is_finite() && mu > 0.0 && mu <= 1.5 {
        return Ok(());
    }
    Err(ArgumentError::new(
        name,
        mu,
        "must be above 0 and at most 1.5",
    ))
}

/// A reference rotor speed argument \[rpm\]: above 0 and at most 5000.
pub fn check_rpm(name: &str, rpm: f64) -> Result<(), ArgumentError> {
    if rpm.is_finite() && rpm > 0.0 && rpm <= 5000.0 {
        return Ok(());
    }
    Err(ArgumentError::new(
        name,
        rpm,
        "must be above 0 and at most 5000 rpm",
    ))
}

/// The autorotating rotor of one tunnel case. Its serde form is what `gyro autorotate --json`
/// prints and the columns of `gyro autorotate --cases`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Autorotation {
    /// Rotor angle of attack α \[deg\] (the case).
    pub alpha_deg: f64,
    /// Wind speed V \[m/s\] (the case).
    pub speed_m_s: f64,
    /// Autorotative rotor speed \[rpm\].
    pub rotor_rpm: f64,
    /// Tip-speed ratio μ = V cos α/(ΩR) at that speed.
    pub mu: f64,
    /// Lift coefficient C_L = L/(q πR²), lift perpendicular to the wind.
    pub cl: f64,
    /// Drag coefficient C_D = D/(q πR²), drag along the wind.
    pub cd: f64,
    /// Lift-to-drag ratio L/D.
    pub lift_to_drag: f64,
    /// Coning a0 = β0 \[deg\].
    pub coning_deg: f64,
    /// Longitudinal flapping a1 = −β1c \[deg\] (positive: tip-path plane tilted back).
    pub a1_deg: f64,
    /// Lateral flapping b1 = −β1s \[deg\] (positive: the blade highest over the retreating
    /// side, ψ = 270°).
    pub b1_deg: f64,
    /// Thrust coefficient C_T = T/(ρπR²(ΩR)²), thrust along the shaft.
    pub thrust_coefficient: f64,
    /// Net inflow ratio λ = (V sin α − v0)/(ΩR), up through the disc positive.
    pub inflow_ratio: f64,
    /// Share of the blade-element samples in reverse flow.
    pub reverse_flow_fraction: f64,
    /// Share of the blade-element lookups outside the table's Reynolds/Mach range (edge
    /// values used).
    pub table_clamped_fraction: f64,
    /// Share of the blade-element lookups leaning on supercritical table points.
    pub table_supercritical_fraction: f64,
    /// Share of the blade-element lookups at whose α the table's points are in massive
    /// separation (the 360° extension stands in).
    pub table_separated_fraction: f64,
}

impl Autorotation {
    /// The row of a case that found no autorotation: the case and NaN elsewhere.
    fn failed(case: &TunnelCase) -> Self {
        Self {
            alpha_deg: case.alpha_deg,
            speed_m_s: case.speed_m_s,
            rotor_rpm: f64::NAN,
            mu: f64::NAN,
            cl: f64::NAN,
            cd: f64::NAN,
            lift_to_drag: f64::NAN,
            coning_deg: f64::NAN,
            a1_deg: f64::NAN,
            b1_deg: f64::NAN,
            thrust_coefficient: f64::NAN,
            inflow_ratio: f64::NAN,
            reverse_flow_fraction: f64::NAN,
            table_clamped_fraction: f64::NAN,
            table_supercritical_fraction: f64::NAN,
            table_separated_fraction: f64::NAN,
        }
    }

    /// What a user should read beside the result: lookups outside the table, on
    /// supercritical points or in massive separation. One line each, starting `note: `.
    pub fn notes(&self) -> Vec<String> {
        LookupShares {
            clamped: self.table_clamped_fraction,
            supercritical: self.table_supercritical_fraction,
            separated: self.table_separated_fraction,
        }
        .notes(&format!(
            "at α {} deg, V {} m/s",
            short_number(self.alpha_deg),
            short_number(self.speed_m_s)
        ))
    }
}

/// The autorotating `rotor` with blade section `section` at one tunnel `case` in `atmosphere`
/// (the rotor speed searched as [`autorotation`] does with `params`).
pub fn autorotate<S: BladeSection + ?Sized>(
    rotor: &Rotor,
    section: &S,
    case: &TunnelCase,
    atmosphere: &Atmosphere,
    params: &TrimParams,
) -> Result<Autorotation, TrimError> {
    let v = case.speed_m_s;
    let s = autorotation(
        rotor,
        section,
        v,
        case.alpha_deg.to_radians(),
        atmosphere,
        params,
    )?;
    let q_area = atmosphere.dynamic_pressure(v) * rotor.disc_area();
    Ok(Autorotation {
        alpha_deg: case.alpha_deg,
        speed_m_s: v,
        rotor_rpm: rad_s_to_rpm(s.condition.omega),
        mu: s.advance_ratio,
        cl: s.lift / q_area,
        cd: s.drag / q_area,
        lift_to_drag: s.lift / s.drag,
        coning_deg: s.flapping.beta0.to_degrees(),
        a1_deg: -s.flapping.beta1c.to_degrees(),
        b1_deg: -s.flapping.beta1s.to_degrees(),
        thrust_coefficient: s.thrust_coefficient,
        inflow_ratio: s.inflow_ratio,
        reverse_flow_fraction: s.reverse_flow_fraction,
        table_clamped_fraction: s.table_clamped_fraction,
        table_supercritical_fraction: s.table_supercritical_fraction,
        table_separated_fraction: s.table_separated_fraction,
    })
}

/// [`autorotate`] for every case, in parallel, in the order given; `progress` follows the
/// cases when there are several (no estimate at the start: a case takes 5–16 ms of CPU, by
/// rotor, and the progress lines estimate what is left from the cases done).
pub fn autorotate_cases<S: BladeSection + Sync + ?Sized>(
    rotor: &Rotor,
    section: &S,
    cases: &[TunnelCase],
    atmosphere: &Atmosphere,
    params: &TrimParams,
    progress: &dyn Progress,
) -> Vec<Result<Autorotation, TrimError>> {
    let progress: &dyn Progress = if cases.len() > 1 { progress } else { &Silent };
    progress.start(&Work::new(cases.len(), "cases", "the rotor in the tunnel"));
    let results = cases
        .par_iter()
        .map(|c| {
            let r = autorotate(rotor, section, c, atmosphere, params);
            progress.advance(1);
            r
        })
        .collect();
    progress.finish();
    results
}

/// Why a cases file cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum TunnelCasesError {
    /// The file cannot be read.
    #[error("cannot read cases file {}: {}", .0.path.display(), .0.problem)]
    Input(#[source] InputError),
    /// The file is not a CSV with the columns `alpha_deg` and `speed_m_s`.
    #[error("bad cases file {path}: {message}")]
    Format {
        /// The file.
        path: String,
        /// What is wrong, with the line.
        message: String,
    },
    /// A case is out of range: a bad input file (exit status 1), so the value's rule is kept
    /// as text, not as the [`ArgumentError`] of a bad command-line value.
    #[error("cases file {path}, line {line}: {rule}")]
    Case {
        /// The file.
        path: String,
        /// Line number (the header is line 1).
        line: u64,
        /// Which value and why.
        rule: String,
    },
}

/// Reads the tunnel cases of a CSV file (`-`: standard input) with columns `alpha_deg` and
/// `speed_m_s` (others are ignored), each case checked, at least one and at most
/// [`MAX_TUNNEL_CASES`].
pub fn read_tunnel_cases(path: &Path) -> Result<Vec<TunnelCase>, TunnelCasesError> {
    let bytes = read_input_or_stdin(path).map_err(TunnelCasesError::Input)?;
    let name = path.display().to_string();
    let format = |message: String| TunnelCasesError::Format {
        path: name.clone(),
        message: message.replace('\n', " "),
    };
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(bytes.as_slice());
    let mut cases = Vec::new();
    for (i, row) in reader.deserialize::<TunnelCase>().enumerate() {
        let line = i as u64 + 2;
        let case = row.map_err(|e| format(format!("line {line}: {e}")))?;
        if cases.len() == MAX_TUNNEL_CASES {
            return Err(format(format!("more than {MAX_TUNNEL_CASES} cases")));
        }
        case.check("alpha_deg", "speed_m_s")
            .map_err(|e| TunnelCasesError::Case {
                path: name.clone(),
                line,
                rule: e.to_string(),
            })?;
        cases.push(case);
    }
    if cases.is_empty() {
        return Err(format(
            "no cases (a header alpha_deg,speed_m_s and rows)".into(),
        ));
    }
    Ok(cases)
}

/// The outcome of one tunnel case: the autorotating rotor, or the case with NaN results and
/// the reason it found none in `error` (empty when it did). Its serde form is a row of
/// `gyro autorotate --cases` (JSON: null for NaN).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CaseOutcome {
    /// The result (NaN but the case when there is none).
    #[serde(flatten)]
    pub result: Autorotation,
    /// Why the case found no autorotation (empty when it did).
    pub error: String,
}

impl CaseOutcome {
    /// Whether the case found an autorotating rotor speed.
    pub fn found(&self) -> bool {
        self.error.is_empty()
    }

    /// What a user should read beside the row (one line each, starting `note: `).
    pub fn notes(&self) -> Vec<String> {
        if self.found() {
            return self.result.notes();
        }
        let (alpha, v) = (self.result.alpha_deg, self.result.speed_m_s);
        vec![format!(
            "note: alpha {} deg, V {} m/s: {}",
            short_number(alpha),
            short_number(v),
            self.error
        )]
    }
}

/// [`autorotate_cases`] with every case kept as a [`CaseOutcome`].
pub fn autorotate_outcomes<S: BladeSection + Sync + ?Sized>(
    rotor: &Rotor,
    section: &S,
    cases: &[TunnelCase],
    atmosphere: &Atmosphere,
    params: &TrimParams,
    progress: &dyn Progress,
) -> Vec<CaseOutcome> {
    let results = autorotate_cases(rotor, section, cases, atmosphere, params, progress);
    cases
        .iter()
        .zip(results)
        .map(|(case, r)| match r {
            Ok(result) => CaseOutcome {
                result,
                error: String::new(),
            },
            Err(e) => CaseOutcome {
                result: Autorotation::failed(case),
                error: e.to_string(),
            },
        })
        .collect()
}

/// No case of a tunnel run found an autorotating rotor speed: the number of cases and the
/// reason the first gave (the reason of each is in its note).
#[derive(Debug, thiserror::Error)]
#[error(
    "{}",
    if *cases == 1 {
        format!("no autorotating rotor speed: {first}")
    } else {
        format!("none of the {cases} cases found an autorotating rotor speed (the first: {first})")
    }
)]
pub struct NoAutorotation {
    /// Cases run.
    pub cases: usize,
    /// Why the first case found none.
    pub first: String,
}

/// The rotor of `params` in the tunnel at ISA `altitude_m` \[m\]: every case of `cases` with
/// `section` ([`autorotate_outcomes`], default trim settings); `progress` follows the cases and
/// `say` gets each case's notes. An error when no case found an autorotating rotor speed.
pub fn tunnel_run<S: BladeSection + Sync + ?Sized>(
    params: &RotorParams,
    section: &S,
    cases: &[TunnelCase],
    altitude_m: f64,
    progress: &dyn Progress,
    say: &dyn Fn(String),
) -> Result<Vec<CaseOutcome>, NoAutorotation> {
    let rotor = Rotor::from_params(params);
    let atm = Atmosphere::isa(altitude_m);
    let params = TrimParams::default();
    let outcomes = autorotate_outcomes(&rotor, section, cases, &atm, &params, progress);
    outcomes.iter().flat_map(|o| o.notes()).for_each(say);
    match outcomes.iter().any(CaseOutcome::found) {
        true => Ok(outcomes),
        false => Err(NoAutorotation {
            cases: outcomes.len(),
            first: outcomes.first().map_or(String::new(), |o| o.error.clone()),
        }),
    }
}

/// The `error` column of a cases CSV.
#[derive(Serialize)]
struct CaseError<'a> {
    /// Why the case found no autorotation (empty when it did).
    error: &'a str,
}

/// `outcomes` as CSV text: the columns of [`Autorotation`] and `error`.
pub fn cases_csv(outcomes: &[CaseOutcome]) -> Result<String, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for o in outcomes {
        w.serialize((&o.result, CaseError { error: &o.error }))?;
    }
    let bytes = w
        .into_inner()
        .map_err(|e| csv::Error::from(e.into_error()))?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}
