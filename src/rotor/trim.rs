//! Autorotation (rotor speed at zero shaft torque) and level-cruise trim of the gyroplane.
//!
//! Trim (paper eq. 5 and Table 3): at airspeed V, mass m and ISA altitude find the hub angle
//! of attack α_H and rotor speed Ω such that the rotor is in autorotation (torque = 0) and its
//! lift equals the weight G less the lift L_W of a fixed wing, if the preset has one (the wing
//! flies at its incidence with the fuselage level, see [`crate::rotor::WingParams`]). Then D_R
//! is the rotor drag, D_P = ½ρV²·S_P·C_DP the airframe drag, D_W the wing's profile and
//! induced drag, F_prop = D_R + D_P + D_W the propeller thrust and L/D = G/F_prop.
//!
//! Both unknowns are found by nested one-dimensional root finding with brackets: for each α_H
//! the autorotation rpm (scan down from high rpm until the torque changes sign, then the
//! crate's bracketed root finder, an Illinois-safeguarded secant), and α_H from the lift
//! balance the same way. Brackets make the solve robust; the secant makes it fast.

use super::aircraft::{Aircraft, WingError, WingLoads};
use super::atmosphere::{Atmosphere, MAX_ISA_ALTITUDE_M};
use super::disc_loads::{FlightCondition, Rotor};
use super::inflow_flapping::RotorError;
use super::lookup_shares::LookupShares;
use super::propeller::{Powerplant, PropellerError};
use super::solution::RotorSolution;
use super::spanwise::BladeSection;
use super::{rad_s_to_rpm, rpm_to_rad_s, KT_TO_MS};
use crate::numerics::roots::bracketed_root;
use serde::Serialize;

/// Errors of autorotation and trim.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TrimError {
    /// The rotor solution failed.
    #[error(transparent)]
    Rotor(#[from] RotorError),
    /// The propeller model could not be calibrated.
    #[error(transparent)]
    Propeller(#[from] PropellerError),
    /// No rotor speed in the search range gives zero torque.
    #[error("no autorotation at V = {airspeed_ms:.1} m/s, α_H = {aoa_deg:.2}°: {reason}")]
    NoAutorotation {
        /// Airspeed \[m/s\].
        airspeed_ms: f64,
        /// Hub angle of attack \[deg\].
        aoa_deg: f64,
        /// What the scan found.
        reason: &'static str,
    },
    /// No rotor angle of attack in the search range balances the weight.
    #[error("no trim at V = {airspeed_ms:.1} m/s for a rotor lift of {weight_n:.0} N: {reason}")]
    NoTrim {
        /// Airspeed \[m/s\].
        airspeed_ms: f64,
        /// Rotor lift sought: the weight less any wing lift \[N\].
        weight_n: f64,
        /// What the scan found.
        reason: &'static str,
    },
    /// The wing's loads could not be computed.
    #[error(transparent)]
    Wing(#[from] WingError),
    /// The wing alone lifts the weight: no rotor lift is left to trim for.
    #[error(
        "no trim at V = {airspeed_ms:.1} m/s: the wing lifts {wing_lift_n:.0} N, at least the \
         weight {weight_n:.0} N (the rotor would have to push down)"
    )]
    WingCarriesWeight {
        /// Airspeed \[m/s\].
        airspeed_ms: f64,
        /// Wing lift \[N\].
        wing_lift_n: f64,
        /// Weight \[N\].
        weight_n: f64,
    },
    /// Invalid input (speed, mass).
    #[error("invalid trim input: {0}")]
    Input(&'static str),
    /// The altitude is outside the atmosphere model.
    #[error(
        "invalid trim input: altitude must be within the ISA troposphere, 0 to {} m",
        MAX_ISA_ALTITUDE_M
    )]
    Altitude,
}

/// Search ranges and tolerances of the trim solvers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrimParams {
    /// Highest rotor speed searched \[rpm\]; the scan starts here or where the advancing tip
    /// reaches [`max_tip_mach`](Self::max_tip_mach), whichever is lower.
    pub rpm_max: f64,
    /// Highest Mach number of the advancing blade tip, (ΩR + V)/a, searched: the section
    /// tables end below Mach 1 (lookups beyond are clamped to their edge), so the scan does not
    /// start where every tip lookup would be.
    pub max_tip_mach: f64,
    /// Lowest rotor speed searched \[rpm\].
    pub rpm_min: f64,
    /// Scan factor between successive rpm samples (< 1).
    pub rpm_scan_factor: f64,
    /// Rotor speed tolerance \[rpm\].
    pub rpm_tolerance: f64,
    /// Smallest hub angle of attack searched \[deg\].
    pub aoa_min_deg: f64,
    /// Largest hub angle of attack searched \[deg\].
    pub aoa_max_deg: f64,
    /// Hub angle scan step \[deg\].
    pub aoa_scan_step_deg: f64,
    /// Hub angle tolerance \[deg\].
    pub aoa_tolerance_deg: f64,
    /// Maximum secant iterations of each bracketed solve.
    pub max_iterations: usize,
}

impl Default for TrimParams {
    fn default() -> Self {
        Self {
            rpm_max: 900.0,
            max_tip_mach: 1.0,
            rpm_min: 60.0,
            rpm_scan_factor: 0.85,
            rpm_tolerance: 1e-3,
            aoa_min_deg: -6.0,
            aoa_max_deg: 30.0,
            aoa_scan_step_deg: 1.5,
            aoa_tolerance_deg: 1e-4,
            max_iterations: 60,
        }
    }
}

/// Trimmed level flight. Its serde form (what `gyro trim --json` and `gyro sweep --json`
/// print) holds the paper's Table 3 quantities, both rotor angles, the hub angle, the power,
/// the flapping, the speed in knots (as `speed_kt`), the propeller's predicted static thrust and
/// the shares of table lookups clamped, supercritical or in massive separation; the other
/// fields are left out of it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TrimResult {
    /// Rotor speed n_R \[rpm\].
    pub rotor_rpm: f64,
    /// Tip-path-plane angle of attack α_TPP = α_H − β1c \[deg\]: the disc's attitude to the
    /// flight path, what a vane or the rotor head's attitude shows in flight.
    pub rotor_aoa_deg: f64,
    /// Drag-equivalent rotor angle atan(D_R/L_R) \[deg\]: the tilt of the resultant rotor force
    /// behind the normal to the flight path. The paper's α_R is this angle (its eq. 5 takes
    /// D_R = G·α_R, and Table 3 has atan(478/4414) = 6.2°, atan(624/4414) = 8.1°); it exceeds
    /// the tip-path-plane angle by about H_TPP/T, the in-plane force the profile drag adds.
    pub rotor_aoa_drag_equivalent_deg: f64,
    /// Engine speed at which the propeller gives F_prop \[rpm\] (`None` if above the engine's
    /// maximum).
    pub engine_rpm: Option<f64>,
    /// Rotor drag D_R \[N\].
    pub rotor_drag_n: f64,
    /// Airframe drag D_P \[N\].
    pub parasitic_drag_n: f64,
    /// Propeller thrust F_prop = D_R + D_P + D_W \[N\].
    pub prop_thrust_n: f64,
    /// Lift-to-drag ratio G/F_prop.
    pub lift_to_drag: f64,
    /// Hub-plane angle of attack α_H \[deg\].
    pub hub_aoa_deg: f64,
    /// Power required F_prop·V \[kW\].
    pub power_required_kw: f64,
    /// Longitudinal flapping β1c \[deg\] (negative = tip-path plane tilted back).
    pub beta1c_deg: f64,
    /// Lateral flapping β1s \[deg\].
    pub beta1s_deg: f64,
    /// Airspeed \[kt\].
    #[serde(rename = "speed_kt")]
    pub airspeed_kt: f64,
    /// Airspeed \[m/s\].
    #[serde(skip)]
    pub airspeed_ms: f64,
    /// Rotor lift \[N\] (= weight less the wing's lift at trim).
    #[serde(skip)]
    pub rotor_lift_n: f64,
    /// The wing's lift and drag; absent (and left out of the serde form) without a wing of
    /// non-zero area.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wing: Option<WingLoads>,
    /// Advance ratio μ.
    #[serde(skip)]
    pub advance_ratio: f64,
    /// Thrust coefficient C_T.
    #[serde(skip)]
    pub thrust_coefficient: f64,
    /// Residual shaft torque at the trim point \[N m\] (≈ 0).
    #[serde(skip)]
    pub torque_nm: f64,
    /// Fraction of the blade-element lookups at the trim point whose Reynolds or Mach number
    /// lay outside the section table and were clamped to its edge (0 when the table covers
    /// the rotor).
    pub table_clamped_fraction: f64,
    /// Fraction of the blade-element lookups at the trim point whose section data lean on
    /// supercritical table points (locally supersonic flow, outside the method's validity).
    pub table_supercritical_fraction: f64,
    /// Fraction of the blade-element lookups at the trim point at whose α the table's points
    /// are in massive separation (outside the method's validity; the 360° extension stands in).
    pub table_separated_fraction: f64,
    /// The propeller's full-throttle static thrust at the trim's altitude \[N\], predicted by
    /// the calibrated blade-element propeller (the paper's Table 1 quotes ≈ 2000 N).
    pub static_thrust_n: f64,
    /// Share of the propeller's annuli at that static point beyond their section table's
    /// computed α range (their data from the 360° extension: stalled).
    pub static_thrust_post_stall_fraction: f64,
    /// Share of the propeller's annuli at that static point whose section data lean on
    /// supercritical table points (locally supersonic, outside the method's validity).
    pub static_thrust_supercritical_fraction: f64,
}

impl TrimResult {
    /// The trim point's lookup shares ([`LookupShares`]).
    pub fn lookup_shares(&self) -> LookupShares {
        LookupShares {
            clamped: self.table_clamped_fraction,
            supercritical: self.table_supercritical_fraction,
            separated: self.table_separated_fraction,
        }
    }

    /// Share of the weight the rotor carries, L_R/(L_R + L_W) (1 without a wing).
    pub fn rotor_lift_share(&self) -> f64 {
        let wing = self.wing.map_or(0.0, |w| w.lift_n);
        self.rotor_lift_n / (self.rotor_lift_n + wing)
    }

    /// What a user should read beside a trim that is a valid rotor solution but not one the
    /// aircraft can fly as computed: the engine cannot reach the thrust, or the table did not
    /// cover the rotor. One line each, starting `note: `.
    pub fn notes(&self) -> Vec<String> {
        let mut notes = Vec::new();
        if self.engine_rpm.is_none() {
            notes.push(format!(
                "note: at {:.1} kt the propeller needs more than the engine's maximum rpm for \
                 {:.0} N of thrust: the aircraft cannot fly this speed level",
                self.airspeed_kt, self.prop_thrust_n
            ));
        }
        notes.extend(
            self.lookup_shares()
                .notes(&format!("at {:.1} kt", self.airspeed_kt)),
        );
        if let Some(w) = self.wing.filter(|w| w.stalled) {
            notes.push(format!(
                "note: at {:.1} kt the wing works beyond its linear range (C_L {:.3}: capped at \
                 its cl_max, or from the table's post-stall model)",
                self.airspeed_kt, w.lift_coefficient
            ));
        }
        if self.wing.is_some_and(|w| w.table_clamped) {
            notes.push(format!(
                "note: at {:.1} kt the wing's Reynolds or Mach number lies outside its section \
                 table's range and uses its edge values",
                self.airspeed_kt
            ));
        }
        notes
    }
}

/// Autorotation: the rotor speed at which the aerodynamic torque vanishes, for airspeed `v`
/// \[m/s\] and hub angle `hub_aoa` \[rad\]. The scan starts at the highest rpm searched
/// ([`TrimParams::rpm_max`], lower where the advancing tip would pass
/// [`TrimParams::max_tip_mach`]) and moves down, so the equilibrium found is the stable one
/// (torque falls with rpm there).
pub fn autorotation<S: BladeSection + ?Sized>(
    rotor: &Rotor,
    section: &S,
    v: f64,
    hub_aoa: f64,
    atmosphere: &Atmosphere,
    params: &TrimParams,
) -> Result<RotorSolution, TrimError> {
    let cond = |rpm: f64| FlightCondition {
        airspeed: v,
        hub_aoa,
        omega: rpm_to_rad_s(rpm),
        atmosphere: *atmosphere,
    };
    let no_auto = |reason| TrimError::NoAutorotation {
        airspeed_ms: v,
        aoa_deg: hub_aoa.to_degrees(),
        reason,
    };
    let tip_mach_rpm =
        rad_s_to_rpm((params.max_tip_mach * atmosphere.speed_of_sound - v) / rotor.radius);
    // The start, and whether the tip Mach number rather than rpm_max sets it.
    let (mut hi, tip_limited) = if tip_mach_rpm < params.rpm_max {
        (tip_mach_rpm, true)
    } else {
        (params.rpm_max, false)
    };
    if hi.is_nan() || hi <= params.rpm_min {
        return Err(no_auto(if tip_limited {
            "the advancing blade tip passes the highest Mach number searched at every rpm"
        } else {
            "the highest rpm searched is not above the lowest"
        }));
    }
    let mut warm = None;
    let first = rotor.solve(section, &cond(hi), &mut warm)?;
    if first.torque > 0.0 {
        return Err(no_auto(if tip_limited {
            "the rotor still accelerates where its advancing tip reaches the highest Mach number \
             searched"
        } else {
            "the rotor still accelerates at the highest rpm searched"
        }));
    }
    let mut f_hi = first.torque;
    let (lo, f_lo) = loop {
        let lo = hi * params.rpm_scan_factor;
        if lo < params.rpm_min {
            return Err(no_auto(
                "the rotor needs driving torque at every rpm searched",
            ));
        }
        let s = rotor.solve(section, &cond(lo), &mut warm)?;
        if s.torque >= 0.0 {
            break (lo, s.torque);
        }
        hi = lo;
        f_hi = s.torque;
    };
    let rpm = bracketed_root(
        |rpm| -> Result<f64, TrimError> { Ok(rotor.solve(section, &cond(rpm), &mut warm)?.torque) },
        (lo, f_lo),
        (hi, f_hi),
        params.rpm_tolerance,
        params.max_iterations,
    )?;
    Ok(rotor.solve(section, &cond(rpm), &mut warm)?)
}

/// Level-flight trim: hub angle and rotor speed such that the rotor autorotates and its lift
/// equals `weight` \[N\] at airspeed `v` \[m/s\]. Returns the rotor solution.
pub fn trim_rotor<S: BladeSection + ?Sized>(
    rotor: &Rotor,
    section: &S,
    v: f64,
    weight: f64,
    atmosphere: &Atmosphere,
    params: &TrimParams,
) -> Result<RotorSolution, TrimError> {
    if !(v.is_finite() && v > 0.0) {
        return Err(TrimError::Input("airspeed must be a positive number"));
    }
    if !(weight.is_finite() && weight > 0.0) {
        return Err(TrimError::Input("weight must be a positive number"));
    }
    let no_trim = |reason| TrimError::NoTrim {
        airspeed_ms: v,
        weight_n: weight,
        reason,
    };
    let excess = |aoa_deg: f64| -> Result<(f64, RotorSolution), TrimError> {
        let s = autorotation(rotor, section, v, aoa_deg.to_radians(), atmosphere, params)?;
        Ok((s.lift - weight, s))
    };
    // Scan α_H upwards until the lift exceeds the weight; the bracket must lie on one
    // continuous autorotation branch, so a gap without autorotation restarts it.
    let mut below: Option<(f64, f64)> = None;
    let mut overspeed = false;
    let mut aoa = params.aoa_min_deg;
    let (below, above) =
        loop {
            if aoa > params.aoa_max_deg {
                return Err(no_trim(if overspeed {
                    "the rotor leaves the rpm range searched before its lift reaches the weight"
                } else {
                    "the rotor lift stays below the weight at every angle searched"
                }));
            }
            match excess(aoa) {
                Ok((f, _)) if f >= 0.0 => match below {
                    Some(b) => break (b, (aoa, f)),
                    None => return Err(no_trim(
                        "the rotor lift exceeds the weight already at the smallest angle searched",
                    )),
                },
                Ok((f, _)) => below = Some((aoa, f)),
                Err(TrimError::NoAutorotation { .. }) => {
                    overspeed |= below.is_some();
                    below = None;
                }
                Err(e) => return Err(e),
            }
            aoa += params.aoa_scan_step_deg;
        };
    let aoa = bracketed_root(
        |a| excess(a).map(|(f, _)| f),
        below,
        above,
        params.aoa_tolerance_deg,
        params.max_iterations,
    )?;
    Ok(excess(aoa)?.1)
}

/// Full cruise trim of `aircraft` at `speed_kt` \[kt\], `mass_kg` and ISA `altitude_m`: rotor
/// trim for the weight the wing leaves, airframe and wing drag, propeller thrust and engine rpm
/// (paper Table 3).
pub fn trim_aircraft<S: BladeSection + ?Sized>(
    aircraft: &Aircraft,
    section: &S,
    speed_kt: f64,
    mass_kg: f64,
    altitude_m: f64,
    params: &TrimParams,
) -> Result<TrimResult, TrimError> {
    if !(mass_kg.is_finite() && mass_kg > 0.0) {
        return Err(TrimError::Input("mass must be a positive number"));
    }
    if !(0.0..=MAX_ISA_ALTITUDE_M).contains(&altitude_m) {
        return Err(TrimError::Altitude);
    }
    let rotor = Rotor::from_params(&aircraft.rotor);
    let powerplant = Powerplant::from_aircraft(aircraft)?;
    let atm = Atmosphere::isa(altitude_m);
    let v = speed_kt * KT_TO_MS;
    let weight = mass_kg * super::G0;
    let wing = aircraft.wing_loads(&atm, v)?;
    if wing.lift_n >= weight {
        return Err(TrimError::WingCarriesWeight {
            airspeed_ms: v,
            wing_lift_n: wing.lift_n,
            weight_n: weight,
        });
    }
    let s = trim_rotor(&rotor, section, v, weight - wing.lift_n, &atm, params)?;
    let d_p = atm.dynamic_pressure(v) * aircraft.parasitic_drag_area_m2;
    let f_prop = s.drag + d_p + wing.drag_n;
    let engine_rpm = match powerplant.engine_rpm_for_thrust(&atm, v, f_prop) {
        Ok(rpm) => Some(rpm),
        Err(PropellerError::Unavailable { .. }) => None,
        Err(e) => return Err(e.into()),
    };
    let at_rest = powerplant.full_throttle(&atm, 0.0, None)?.propeller;
    Ok(TrimResult {
        airspeed_ms: v,
        airspeed_kt: speed_kt,
        rotor_rpm: rad_s_to_rpm(s.condition.omega),
        rotor_aoa_deg: s.disc_aoa().to_degrees(),
        rotor_aoa_drag_equivalent_deg: s.drag.atan2(s.lift).to_degrees(),
        hub_aoa_deg: s.condition.hub_aoa.to_degrees(),
        engine_rpm,
        rotor_drag_n: s.drag,
        rotor_lift_n: s.lift,
        wing: aircraft.has_wing().then_some(wing),
        parasitic_drag_n: d_p,
        prop_thrust_n: f_prop,
        lift_to_drag: weight / f_prop,
        power_required_kw: f_prop * v / 1000.0,
        beta1c_deg: s.flapping.beta1c.to_degrees(),
        beta1s_deg: s.flapping.beta1s.to_degrees(),
        advance_ratio: s.advance_ratio,
        thrust_coefficient: s.thrust_coefficient,
        torque_nm: s.torque,
        table_clamped_fraction: s.table_clamped_fraction,
        table_supercritical_fraction: s.table_supercritical_fraction,
        table_separated_fraction: s.table_separated_fraction,
        static_thrust_n: at_rest.thrust,
        static_thrust_post_stall_fraction: at_rest.post_stall_fraction,
        static_thrust_supercritical_fraction: at_rest.supercritical_fraction,
    })
}
