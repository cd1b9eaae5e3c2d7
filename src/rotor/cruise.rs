//! Cruise analyses built on the level-flight trim of [`trim`](super::trim): the power-required
//! curve of a speed sweep and the blade angle of attack around the azimuth in trimmed cruise
//! (the paper's Fig. 10). Both only call the trim and the rotor model; no new physics here.

use super::aircraft::Aircraft;
use super::atmosphere::Atmosphere;
use super::disc_loads::Rotor;
use super::lookup_shares::LookupShares;
use super::spanwise::BladeSection;
use super::trim::{trim_aircraft, trim_rotor, TrimError, TrimParams, TrimResult};
use super::{check_speed_kt, KT_TO_MS};
use crate::arguments::ArgumentError;
use crate::limits::{short_number, MAX_SWEEP_CELL_SPEEDS, MAX_SWEEP_SPEEDS};
use rayon::prelude::*;

/// One speed of a [`speed_sweep`]: the airspeed \[kt\] and its trim (or why there is none).
pub type SweepPoint = (f64, Result<TrimResult, TrimError>);

/// Airspeeds `from_kt`, `from_kt + step_kt`, … up to `to_kt` inclusive (a step landing within
/// 10⁻⁹ kt of `to_kt` counts as reaching it). Empty if the bounds or the step are not usable.
pub fn sweep_speeds(from_kt: f64, to_kt: f64, step_kt: f64) -> Vec<f64> {
    if !(from_kt.is_finite() && to_kt.is_finite() && step_kt.is_finite() && step_kt > 0.0)
        || to_kt < from_kt
    {
        return Vec::new();
    }
    let n = ((to_kt - from_kt) / step_kt + 1e-9).floor() as usize + 1;
    (0..n).map(|k| from_kt + k as f64 * step_kt).collect()
}

/// The airspeeds of a sweep from the flags `--from-kt`, `--to-kt`, `--step-kt` ([`sweep_speeds`]),
/// checked: each bound a valid airspeed, `to ≥ from`, a positive step, at most
/// [`MAX_SWEEP_SPEEDS`] speeds and, for a rotor of `cells` strip × azimuth cells, at most
/// [`MAX_SWEEP_CELL_SPEEDS`] speeds × cells.
pub fn checked_sweep_speeds(
    from_kt: f64,
    to_kt: f64,
    step_kt: f64,
    cells: usize,
) -> Result<Vec<f64>, ArgumentError> {
    check_speed_kt("--from-kt", from_kt)?;
    check_speed_kt("--to-kt", to_kt)?;
    if to_kt < from_kt {
        let rule = format!("below --from-kt {}", short_number(from_kt));
        return Err(ArgumentError::new("--to-kt", to_kt, rule));
    }
    if !(step_kt.is_finite() && step_kt > 0.0) {
        let rule = "must be a positive number of knots";
        return Err(ArgumentError::new("--step-kt", step_kt, rule));
    }
    let count = ((to_kt - from_kt) / step_kt).floor() + 1.0;
    if count > MAX_SWEEP_SPEEDS as f64 {
        let rule = format!(
            "gives {count:.0} speeds from {from_kt} to {to_kt} kt (at most {MAX_SWEEP_SPEEDS})"
        );
        return Err(ArgumentError::new("--step-kt", step_kt, rule));
    }
    let speeds = sweep_speeds(from_kt, to_kt, step_kt);
    if speeds.len().saturating_mul(cells) > MAX_SWEEP_CELL_SPEEDS {
        let rule = format!(
            "{} speeds of a rotor with {cells} cells exceed the limit of \
             {MAX_SWEEP_CELL_SPEEDS} speeds × cells; use a larger step",
            speeds.len()
        );
        return Err(ArgumentError::new("--step-kt", step_kt, rule));
    }
    Ok(speeds)
}

/// A list of sweep airspeeds given directly (the Python package's `sweep`), checked as
/// [`checked_sweep_speeds`] checks a range: each a valid airspeed, at most
/// [`MAX_SWEEP_SPEEDS`] of them and at most [`MAX_SWEEP_CELL_SPEEDS`] speeds × `cells`.
pub fn check_sweep_speeds(
    name: &str,
    speeds_kt: &[f64],
    cells: usize,
) -> Result<(), ArgumentError> {
    for &v in speeds_kt {
        check_speed_kt(name, v)?;
    }
    let n = speeds_kt.len();
    if n == 0 || n > MAX_SWEEP_SPEEDS || n.saturating_mul(cells) > MAX_SWEEP_CELL_SPEEDS {
        let rule = format!(
            "{n} speeds: give 1 to {} for a rotor with {cells} cells",
            MAX_SWEEP_SPEEDS.min(MAX_SWEEP_CELL_SPEEDS / cells.max(1))
        );
        return Err(ArgumentError::with_text(name, "", rule));
    }
    Ok(())
}

/// Power-required sweep: [`trim_aircraft`] at each airspeed of `speeds_kt` (in parallel), at
/// `mass_kg` and ISA `altitude_m`. Each point keeps its own result, so one speed without a trim
/// (e.g. too slow to carry the weight) does not lose the others.
pub fn speed_sweep<S: BladeSection + Sync + ?Sized>(
    aircraft: &Aircraft,
    section: &S,
    speeds_kt: &[f64],
    mass_kg: f64,
    altitude_m: f64,
    params: &TrimParams,
) -> Vec<SweepPoint> {
    speeds_kt
        .par_iter()
        .map(|&v| {
            (
                v,
                trim_aircraft(aircraft, section, v, mass_kg, altitude_m, params),
            )
        })
        .collect()
}

/// Blade section angle of attack α(ψ) at radius fraction `r_over_r` in trimmed level flight at
/// `speed_kt` (ISA `altitude_m`, the preset's mass): the rotor is trimmed with [`trim_rotor`]
/// and its converged inflow and flapping give α at `samples` azimuths ψ_k = 360°·k/samples,
/// ψ = 0 with the blade pointing to the rear (paper Fig. 10). Returns the (ψ \[deg\],
/// α \[deg\]) pairs and the trim's lookup shares.
pub fn cruise_blade_alpha<S: BladeSection + ?Sized>(
    aircraft: &Aircraft,
    section: &S,
    speed_kt: f64,
    altitude_m: f64,
    r_over_r: f64,
    samples: usize,
    params: &TrimParams,
) -> Result<BladeAlpha, TrimError> {
    let rotor = Rotor::from_params(&aircraft.rotor);
    let solution = trim_rotor(
        &rotor,
        section,
        speed_kt * KT_TO_MS,
        aircraft.weight_n(),
        &Atmosphere::isa(altitude_m),
        params,
    )?;
    Ok(BladeAlpha {
        points: rotor.alpha_at_radius(&solution, r_over_r, samples),
        speed_kt,
        lookup_shares: solution.lookup_shares(),
    })
}

/// Blade α(ψ) at one radius in trimmed cruise ([`cruise_blade_alpha`]).
#[derive(Clone, Debug, PartialEq)]
pub struct BladeAlpha {
    /// (ψ \[deg\], α \[deg\]) pairs.
    pub points: Vec<(f64, f64)>,
    /// Airspeed of the trim \[kt\].
    pub speed_kt: f64,
    /// The trim's blade-element lookups outside the table or the method's validity.
    pub lookup_shares: LookupShares,
}

impl BladeAlpha {
    /// What a user should read beside the curve: the trim's lookups outside the table or the
    /// method's validity (`note: at 60.0 kt, …`, as a trim's notes say them).
    pub fn notes(&self) -> Vec<String> {
        self.lookup_shares
            .notes(&format!("at {:.1} kt", self.speed_kt))
    }
}
