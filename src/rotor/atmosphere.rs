//! International Standard Atmosphere (ISO 2533 / ICAO Doc 7488) in the troposphere.

/// Sea-level temperature \[K\] (ISA).
const T0: f64 = 288.15;
/// Sea-level pressure \[Pa\] (ISA).
const P0: f64 = 101_325.0;
/// Tropospheric temperature lapse rate [K/m] (ISA).
const LAPSE: f64 = 0.0065;
/// Specific gas constant of dry air [J/(kg K)] (ISA).
const R_AIR: f64 = 287.052_87;
/// Ratio of specific heats of air.
const GAMMA: f64 = crate::compressibility::GAMMA;
/// Sutherland's law reference viscosity [Pa s] at `SUTH_T0` (ISA, ISO 2533).
const SUTH_MU0: f64 = 1.716e-5;
/// Sutherland reference temperature \[K\].
const SUTH_T0: f64 = 273.15;
/// Sutherland constant \[K\].
const SUTH_S: f64 = 110.4;

/// Highest altitude of the model: the top of the ISA troposphere (the tropopause) \[m\].
pub const MAX_ISA_ALTITUDE_M: f64 = 11_000.0;

/// Air state at one altitude.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Atmosphere {
    /// Geopotential altitude \[m\].
    pub altitude_m: f64,
    /// Temperature \[K\].
    pub temperature: f64,
    /// Static pressure \[Pa\].
    pub pressure: f64,
    /// Density [kg/m³].
    pub density: f64,
    /// Speed of sound \[m/s\].
    pub speed_of_sound: f64,
    /// Dynamic viscosity [Pa s].
    pub viscosity: f64,
}

impl Atmosphere {
    /// ISA troposphere at `altitude_m` (clamped to 0 … [`MAX_ISA_ALTITUDE_M`]):
    /// T = T0 − L·h, p = p0 (T/T0)^(g/(R L)), ρ = p/(R T), a = √(γ R T),
    /// μ from Sutherland's law μ = μ0 (T/T0s)^1.5 (T0s + S)/(T + S).
    pub fn isa(altitude_m: f64) -> Self {
        let h = altitude_m.clamp(0.0, MAX_ISA_ALTITUDE_M);
        let temperature = T0 - LAPSE * h;
        let pressure = P0 * (temperature / T0).powf(super::G0 / (R_AIR * LAPSE));
        let density = pressure / (R_AIR * temperature);
        let speed_of_sound = (GAMMA * R_AIR * temperature).sqrt();
        let viscosity = SUTH_MU0 * (temperature / SUTH_T0).powf(1.5) * (SUTH_T0 + SUTH_S)
            / (temperature + SUTH_S);
        Self {
            altitude_m: h,
            temperature,
            pressure,
            density,
            speed_of_sound,
            viscosity,
        }
    }

    /// Dynamic pressure ½ρV² \[Pa\] at airspeed `v` \[m/s\].
    pub fn dynamic_pressure(&self, v: f64) -> f64 {
        0.5 * self.density * v * v
    }
}
