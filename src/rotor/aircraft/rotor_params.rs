//! The `[rotor]` table of a preset: geometry, hub, blade planform, masses and discretisation,
//! with the checks of each value; and a preset that describes a rotor alone ([`RotorPreset`]).

use super::checks::{in_range, non_negative, positive};
use super::AircraftError;
use crate::arguments::ArgumentError;
use crate::limits::{AZIMUTH_STEPS, MAX_MASS_KG, MAX_ROTOR_CELLS, RADIAL_STRIPS};
use crate::rotor::flapping::{FlapHinge, Hub};
use crate::rotor::inflow::{InflowModel, TipLoss, YawedFlow};
use crate::rotor::planform::{Planform, PlanformStation};
use crate::rotor::torsion::ElasticTorsion;
use serde::Deserialize;
use std::path::Path;

/// Most blades of an articulated rotor.
pub const MAX_BLADES: u32 = 12;

/// Largest |pitch| and |twist| accepted \[deg\] (an autorotating rotor flies a few degrees).
const MAX_PITCH_DEG: f64 = 20.0;

/// Largest |precone| accepted \[deg\].
const MAX_PRECONE_DEG: f64 = 10.0;

/// Rotor geometry, hub, mass and discretisation.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RotorParams {
    /// Rotor radius R \[m\].
    pub radius_m: f64,
    /// Number of blades (a teetering hub has 2).
    pub blades: u32,
    /// Reference chord c \[m\]: the blade's chord, or with a `[rotor.blade]` table the chord
    /// its `chord_ratio` is relative to (solidity N_b c/(πR)).
    pub chord_m: f64,
    /// Blade pitch setting θ relative to the hub plane \[deg\] (fixed, no collective or
    /// cyclic): the pitch where the `[rotor.blade]` twist is 0, the pitch of the whole blade
    /// without one.
    pub incidence_deg: f64,
    /// Root cut-out: radius where the aerodynamic blade starts \[m\].
    pub root_cutout_m: f64,
    /// The hub: `type = "teetering"` with its `precone_deg`, or `type = "articulated"` with
    /// `hinge_offset_m` and `flap_inertia_kg_m2` ([`HubParams`]).
    pub hub: HubParams,
    /// Chord and twist along the blade; omitted: constant chord, untwisted.
    #[serde(default)]
    pub blade: Option<BladeParams>,
    /// Mass of one blade \[kg\], spread uniformly from the root cut-out to the tip (the polar
    /// inertia of the takeoff; the weight moment about a flapping hinge).
    pub blade_mass_kg: f64,
    /// Polar moment of inertia of hub, teeter block and bolts about the shaft \[kg m²\] (the
    /// takeoff's rotor spin-up; a whole aircraft needs it).
    #[serde(default)]
    pub hub_inertia_kg_m2: Option<f64>,
    /// Flapping stops: largest flapping amplitude before the blades hit the stops \[deg\] (the
    /// takeoff's β_max check; a whole aircraft needs it).
    #[serde(default)]
    pub flap_stop_deg: Option<f64>,
    /// Number of radial strips.
    pub radial_strips: usize,
    /// Number of azimuth steps per revolution (even, so both blades of a teetering rotor sit
    /// on the grid).
    pub azimuth_steps: usize,
    /// Tip-loss model: "prandtl", "gessow_myers", "chord" or "none" ([`TipLoss`]).
    pub tip_loss: TipLoss,
    /// Profile drag in yawed (radial) flow: "radial_drag" or "none" ([`YawedFlow`]).
    pub yawed_flow: YawedFlow,
    /// Induced-inflow model: "glauert" (uniform) or "drees" (linear).
    pub inflow: InflowModel,
    /// Induced-power factor κ (induced velocity = κ × Glauert's momentum value, see
    /// [`crate::rotor::Rotor::induced_power_factor`]); omitted → 1 (ideal momentum theory).
    #[serde(default = "ideal_induced_power_factor")]
    pub induced_power_factor: f64,
}

/// κ = 1: ideal momentum theory (the default when a preset omits the factor).
fn ideal_induced_power_factor() -> f64 {
    1.0
}

/// The hub of a preset (`[rotor.hub]`).
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(tag = "type", deny_unknown_fields)]
pub enum HubParams {
    /// Two blades on one teeter bolt at the shaft.
    #[serde(rename = "teetering")]
    Teetering {
        /// Built-in coning of the hub bar β0 \[deg\].
        precone_deg: f64,
    },
    /// Blades on flapping hinges.
    #[serde(rename = "articulated")]
    Articulated {
        /// Distance of the flapping hinges from the shaft \[m\].
        hinge_offset_m: f64,
        /// Flapping moment of inertia of one blade about its hinge \[kg m²\].
        flap_inertia_kg_m2: f64,
    },
}

/// Chord and twist along the blade (`[rotor.blade]`): stations in r/R, linear in between, a
/// repeated r/R a step.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BladeParams {
    /// Radius fractions r/R of the stations, non-decreasing, from at most the root cut-out to 1.
    pub r_over_r: Vec<f64>,
    /// Chord at each station relative to `rotor.chord_m`.
    pub chord_ratio: Vec<f64>,
    /// Pitch at each station relative to `rotor.incidence_deg` \[deg\]; with `torsion`, as
    /// measured under the torsion's reference thrust.
    pub twist_deg: Vec<f64>,
    /// Elastic torsion of the blade under its lift (`[rotor.blade.torsion]`); absent: a rigid
    /// blade.
    #[serde(default)]
    pub torsion: Option<TorsionParams>,
}

/// The blade's elastic torsion (`[rotor.blade.torsion]`, [`ElasticTorsion`]).
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TorsionParams {
    /// Torsion at the tip under the reference thrust, positive nose-up \[deg\].
    pub tip_deg: f64,
    /// Rotor thrust under which `twist_deg` was measured \[N\].
    pub reference_thrust_n: f64,
    /// Radius fraction inboard of which the blade does not twist (linear from there to the tip).
    pub from_r_over_r: f64,
}

/// Largest rotor radius accepted \[m\]: the largest rotors flown (Mil V-12, Mi-26) have 16 to
/// 17.5 m; 50 m bounds a typo, not a design.
const MAX_ROTOR_RADIUS_M: f64 = 50.0;

/// Smallest and largest reference chord as a fraction of the radius (blade aspect ratios
/// R/c from 200 to 2; the MTOsport's is 21, the PCA-2's 12).
const MIN_CHORD_RATIO: f64 = 0.005;
const MAX_CHORD_RATIO: f64 = 0.5;

impl RotorParams {
    /// Blade-element cells of one rotor evaluation: radial strips × azimuth steps.
    pub fn cells(&self) -> usize {
        self.radial_strips.saturating_mul(self.azimuth_steps)
    }

    /// Polar moment of inertia of the rotor about the shaft \[kg m²\]: the hub (0 when not
    /// given) plus N_b uniform blades spanning root cut-out r0 … R,
    /// I_b = m_b (R³ − r0³) / (3 (R − r0)).
    pub fn polar_inertia(&self) -> f64 {
        let (r0, r1) = (self.root_cutout_m, self.radius_m);
        let blade = self.blade_mass_kg * (r1.powi(3) - r0.powi(3)) / (3.0 * (r1 - r0));
        self.hub_inertia_kg_m2.unwrap_or(0.0) + f64::from(self.blades) * blade
    }

    /// Rotor disc area A = πR² \[m²\].
    pub fn disc_area(&self) -> f64 {
        std::f64::consts::PI * self.radius_m * self.radius_m
    }

    /// The hub of the rotor model: a flapping hinge carries the blade's measured flapping
    /// inertia and the first mass moment of its uniform mass about the hinge,
    /// S_β = m_b ((r0 + R)/2 − e).
    pub fn hub(&self) -> Hub {
        match self.hub {
            HubParams::Teetering { precone_deg } => Hub::Teetering {
                precone: precone_deg.to_radians(),
            },
            HubParams::Articulated {
                hinge_offset_m,
                flap_inertia_kg_m2,
            } => Hub::Articulated(FlapHinge {
                offset: hinge_offset_m,
                inertia: flap_inertia_kg_m2,
                mass_moment: self.blade_mass_kg
                    * (0.5 * (self.root_cutout_m + self.radius_m) - hinge_offset_m),
            }),
        }
    }

    /// The planform of the rotor model (twist in radians).
    pub fn planform(&self) -> Planform {
        let stations = self.blade.as_ref().map_or_else(Vec::new, |b| {
            b.r_over_r
                .iter()
                .zip(&b.chord_ratio)
                .zip(&b.twist_deg)
                .map(|((&r_over_r, &chord_ratio), &twist)| PlanformStation {
                    r_over_r,
                    chord_ratio,
                    twist: twist.to_radians(),
                })
                .collect()
        });
        Planform { stations }
    }

    /// The blade's elastic torsion of the rotor model, if the preset gives one.
    pub fn torsion(&self) -> Option<ElasticTorsion> {
        let t = self.blade.as_ref()?.torsion?;
        Some(ElasticTorsion {
            tip: t.tip_deg.to_radians(),
            reference_thrust: t.reference_thrust_n,
            from_r_over_r: t.from_r_over_r,
        })
    }

    /// Sets the blade pitch setting `incidence_deg` to `pitch_deg` (flag `--pitch-deg`) and
    /// checks the rotor again ([`validate`](Self::validate)).
    pub fn set_pitch(&mut self, pitch_deg: f64) -> Result<(), ArgumentError> {
        self.incidence_deg = pitch_deg;
        let bad_pitch = |e| ArgumentError::new("--pitch-deg", pitch_deg, format!("{e}"));
        self.validate().map_err(bad_pitch)
    }

    /// Checks every value of the `[rotor]` table for its physical range.
    pub fn validate(&self) -> Result<(), AircraftError> {
        in_range(
            "rotor.radius_m",
            self.radius_m,
            (f64::MIN_POSITIVE, MAX_ROTOR_RADIUS_M),
            "must be positive and at most 50 m (the largest rotors flown have 17.5 m)",
        )?;
        in_range(
            "rotor.chord_m",
            self.chord_m,
            (
                MIN_CHORD_RATIO * self.radius_m,
                MAX_CHORD_RATIO * self.radius_m,
            ),
            "must be 0.5 % to 50 % of the radius (a blade aspect ratio R/c of 2 to 200)",
        )?;
        non_negative("rotor.root_cutout_m", self.root_cutout_m)?;
        if self.root_cutout_m >= self.radius_m {
            return Err(invalid(
                "rotor.root_cutout_m",
                self.root_cutout_m,
                "must be smaller than the radius",
            ));
        }
        let pitch = (-MAX_PITCH_DEG, MAX_PITCH_DEG);
        in_range(
            "rotor.incidence_deg",
            self.incidence_deg,
            pitch,
            "must be within ±20°",
        )?;
        self.validate_hub()?;
        if let Some(b) = &self.blade {
            b.validate(self.root_cutout_m / self.radius_m)?;
        }
        in_range(
            "rotor.blade_mass_kg",
            self.blade_mass_kg,
            (f64::MIN_POSITIVE, MAX_MASS_KG),
            "must be positive and at most 100000 kg",
        )?;
        if let Some(i) = self.hub_inertia_kg_m2 {
            non_negative("rotor.hub_inertia_kg_m2", i)?;
        }
        if let Some(stop) = self.flap_stop_deg {
            positive("rotor.flap_stop_deg", stop)?;
        }
        let count = |field, n: usize, (lo, hi): (usize, usize), even: bool| {
            if (lo..=hi).contains(&n) && (!even || n % 2 == 0) {
                return Ok(());
            }
            let parity = if even { "even and " } else { "" };
            Err(invalid(
                field,
                n as f64,
                format!("must be {parity}between {lo} and {hi}"),
            ))
        };
        count(
            "rotor.radial_strips",
            self.radial_strips,
            RADIAL_STRIPS,
            false,
        )?;
        count(
            "rotor.azimuth_steps",
            self.azimuth_steps,
            AZIMUTH_STEPS,
            true,
        )?;
        if self.cells() > MAX_ROTOR_CELLS {
            return Err(invalid(
                "rotor.azimuth_steps",
                self.azimuth_steps as f64,
                format!(
                    "with {} radial strips gives {} blade-element cells, more than the limit \
                     of {MAX_ROTOR_CELLS} (radial_strips × azimuth_steps; every rotor \
                     evaluation costs in proportion)",
                    self.radial_strips,
                    self.cells()
                ),
            ));
        }
        if !(self.induced_power_factor >= 1.0 && self.induced_power_factor <= 2.0) {
            return Err(invalid(
                "rotor.induced_power_factor",
                self.induced_power_factor,
                "must be between 1 and 2",
            ));
        }
        Ok(())
    }

    /// The hub's values and the blade count it allows.
    fn validate_hub(&self) -> Result<(), AircraftError> {
        let blades = f64::from(self.blades);
        match self.hub {
            HubParams::Teetering { precone_deg } => {
                if self.blades != 2 {
                    return Err(invalid(
                        "rotor.blades",
                        blades,
                        "a teetering hub carries exactly 2 blades",
                    ));
                }
                in_range(
                    "rotor.hub.precone_deg",
                    precone_deg,
                    (-MAX_PRECONE_DEG, MAX_PRECONE_DEG),
                    "must be within ±10°",
                )
            }
            HubParams::Articulated {
                hinge_offset_m,
                flap_inertia_kg_m2,
            } => {
                if !(2..=MAX_BLADES).contains(&self.blades) {
                    return Err(invalid(
                        "rotor.blades",
                        blades,
                        format!("an articulated hub carries 2 to {MAX_BLADES} blades"),
                    ));
                }
                non_negative("rotor.hub.hinge_offset_m", hinge_offset_m)?;
                if hinge_offset_m > self.root_cutout_m {
                    return Err(invalid(
                        "rotor.hub.hinge_offset_m",
                        hinge_offset_m,
                        "must not lie outboard of the root cut-out",
                    ));
                }
                positive("rotor.hub.flap_inertia_kg_m2", flap_inertia_kg_m2)
            }
        }
    }
}

impl BladeParams {
    /// The stations: equal lengths, r/R non-decreasing from at most `root` (the root cut-out as
    /// r/R) to 1, positive chords, twists within ±20°.
    fn validate(&self, root: f64) -> Result<(), AircraftError> {
        let n = self.r_over_r.len();
        if n < 2 || self.chord_ratio.len() != n || self.twist_deg.len() != n {
            return Err(invalid(
                "rotor.blade.r_over_r",
                n as f64,
                "needs at least 2 stations, with as many chord_ratio and twist_deg values",
            ));
        }
        let first = self.r_over_r[0];
        if !(0.0..=root).contains(&first) {
            return Err(invalid(
                "rotor.blade.r_over_r",
                first,
                format!("must start at or inboard of the root cut-out, r/R ≤ {root:.4}"),
            ));
        }
        if self
            .r_over_r
            .windows(2)
            .any(|w| w[1].is_nan() || w[1] < w[0])
            || self.r_over_r[n - 1] != 1.0
        {
            return Err(invalid(
                "rotor.blade.r_over_r",
                self.r_over_r[n - 1],
                "must not decrease and must end at the tip, 1",
            ));
        }
        for &c in &self.chord_ratio {
            positive("rotor.blade.chord_ratio", c)?;
        }
        for &t in &self.twist_deg {
            in_range(
                "rotor.blade.twist_deg",
                t,
                (-MAX_PITCH_DEG, MAX_PITCH_DEG),
                "must be within ±20°",
            )?;
        }
        if let Some(t) = &self.torsion {
            in_range(
                "rotor.blade.torsion.tip_deg",
                t.tip_deg,
                (-MAX_PITCH_DEG, MAX_PITCH_DEG),
                "must be within ±20°",
            )?;
            positive(
                "rotor.blade.torsion.reference_thrust_n",
                t.reference_thrust_n,
            )?;
            in_range(
                "rotor.blade.torsion.from_r_over_r",
                t.from_r_over_r,
                (0.0, 0.99),
                "must be between 0 and 0.99",
            )?;
        }
        Ok(())
    }
}

/// An [`AircraftError::Invalid`] for `field`.
fn invalid(
    field: &'static str,
    value: f64,
    reason: impl Into<std::borrow::Cow<'static, str>>,
) -> AircraftError {
    AircraftError::Invalid {
        field,
        value,
        reason: reason.into(),
    }
}

/// A preset read for its rotor alone: the name and the `[rotor]` table of an aircraft preset,
/// or of a file that describes only a rotor (such as a rotor tested isolated in a wind tunnel).
/// The other tables of a whole aircraft are allowed and not read.
#[derive(Clone, Debug, Deserialize)]
pub struct RotorPreset {
    /// The rotor's (or aircraft's) name.
    pub name: String,
    /// The rotor.
    pub rotor: RotorParams,
}

/// The top-level keys of an aircraft preset ([`super::Aircraft`]).
const PRESET_KEYS: [&str; 8] = [
    "name",
    "mass_kg",
    "parasitic_drag_area_m2",
    "rotor",
    "propeller",
    "engine",
    "takeoff",
    "wing",
];

impl RotorPreset {
    /// Reads and checks the rotor of a TOML preset.
    pub fn from_toml_file(path: &Path) -> Result<Self, AircraftError> {
        let (text, origin) = super::read_preset_text(path)?;
        Self::from_toml_str(&text, &origin)
    }

    /// Parses and checks the rotor of a TOML preset held in memory; `origin` names it in
    /// errors. Unknown top-level keys are refused as in an aircraft preset.
    pub fn from_toml_str(text: &str, origin: &str) -> Result<Self, AircraftError> {
        let parse = |message: String| AircraftError::Parse {
            path: origin.to_string(),
            message: message.replace('\n', " "),
        };
        let table: toml::Table =
            toml::from_str(text).map_err(|e| parse(super::toml_error_line(&e, text)))?;
        if let Some(key) = table.keys().find(|k| !PRESET_KEYS.contains(&k.as_str())) {
            return Err(parse(format!(
                "unknown field `{key}`, expected one of {}",
                PRESET_KEYS.map(|k| format!("`{k}`")).join(", ")
            )));
        }
        let preset: Self =
            toml::from_str(text).map_err(|e| parse(super::toml_error_line(&e, text)))?;
        preset.rotor.validate()?;
        Ok(preset)
    }
}
