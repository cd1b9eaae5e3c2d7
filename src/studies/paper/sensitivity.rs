//! How much the study's conclusions depend on the values the aircraft preset estimates: each
//! estimate of `aircraft/mtosport.toml` (and the trim mass, unknown for the flight test) is set
//! to the ends of its plausible range, one at a time, and the clean rotor rpm, the engine-rpm
//! and propeller-thrust changes of contamination at 60 kt and the clean takeoff distances are
//! computed again. Each range is argued or cited beside the value ([`ESTIMATES`]).

use super::{StudyError, PAPER_TRIM_SPEED_KT};
use crate::rotor::{
    simulate_takeoff, trim_aircraft, Aircraft, HubParams, InflowModel, TipLoss, TrimParams,
    YawedFlow,
};
use crate::section::SectionAero;
use rayon::prelude::*;

/// One change of the preset.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Change {
    /// Mass of the 60 kt trims \[kg\] (the takeoff stays at the preset's mass, the paper's).
    TrimMass(f64),
    /// Hub-bar coning \[deg\].
    Precone(f64),
    /// Mass of one blade \[kg\].
    BladeMass(f64),
    /// Root cut-out \[m\].
    RootCutout(f64),
    /// Hub polar moment of inertia \[kg m²\].
    HubInertia(f64),
    /// Rolling-friction coefficient.
    RollingFriction(f64),
    /// Induced-power factor κ.
    InducedPowerFactor(f64),
    /// Rotor tip-loss model.
    TipLoss(TipLoss),
    /// Yawed-flow profile drag.
    YawedFlow(YawedFlow),
    /// Induced-inflow model of the rotor.
    Inflow(InflowModel),
    /// Propeller chord scaled at every station.
    PropellerChord(f64),
    /// Propeller twist (blade angle relative to 0.75 R) scaled at every station.
    PropellerTwist(f64),
    /// Full-throttle engine torque scaled at every rpm.
    EngineTorque(f64),
}

impl Change {
    /// Whether the change enters (the 60 kt trims, the takeoff): the trim mass only the trims,
    /// the hub inertia (the rotor-speed equation) and the rolling friction only the takeoff,
    /// every other value both.
    fn moves(&self) -> (bool, bool) {
        match self {
            Self::TrimMass(_) => (true, false),
            Self::HubInertia(_) | Self::RollingFriction(_) => (false, true),
            _ => (true, true),
        }
    }

    /// Applies the change to `aircraft`.
    fn apply(&self, ac: &mut Aircraft) {
        match *self {
            Self::TrimMass(_) => {}
            Self::Precone(v) => {
                if let HubParams::Teetering { precone_deg } = &mut ac.rotor.hub {
                    *precone_deg = v;
                }
            }
            Self::BladeMass(v) => ac.rotor.blade_mass_kg = v,
            Self::RootCutout(v) => ac.rotor.root_cutout_m = v,
            Self::HubInertia(v) => ac.rotor.hub_inertia_kg_m2 = Some(v),
            Self::RollingFriction(v) => ac.takeoff.rolling_friction = v,
            Self::InducedPowerFactor(v) => ac.rotor.induced_power_factor = v,
            Self::TipLoss(t) => ac.rotor.tip_loss = t,
            Self::YawedFlow(y) => ac.rotor.yawed_flow = y,
            Self::Inflow(i) => ac.rotor.inflow = i,
            Self::PropellerChord(k) => ac
                .propeller
                .blade
                .chord_over_diameter
                .iter_mut()
                .for_each(|c| *c *= k),
            Self::PropellerTwist(k) => ac
                .propeller
                .blade
                .twist_deg
                .iter_mut()
                .for_each(|t| *t *= k),
            Self::EngineTorque(k) => ac.engine.torque_nm.iter_mut().for_each(|q| *q *= k),
        }
    }

    /// The value as printed.
    pub fn value(&self) -> String {
        match *self {
            Self::TrimMass(v) => format!("{v} kg"),
            Self::Precone(v) => format!("{v}°"),
            Self::BladeMass(v) => format!("{v} kg"),
            Self::RootCutout(v) => format!("{v} m"),
            Self::HubInertia(v) => format!("{v} kg m²"),
            Self::RollingFriction(v) | Self::InducedPowerFactor(v) => format!("{v}"),
            Self::TipLoss(t) => match t {
                TipLoss::Prandtl => "prandtl",
                TipLoss::GessowMyers => "gessow_myers",
                TipLoss::Chord => "chord",
                TipLoss::NoLoss => "none",
            }
            .to_string(),
            Self::YawedFlow(y) => match y {
                YawedFlow::RadialDrag => "radial_drag",
                YawedFlow::Ignored => "none",
            }
            .to_string(),
            Self::Inflow(i) => match i {
                InflowModel::Glauert => "glauert",
                InflowModel::Drees => "drees",
            }
            .to_string(),
            Self::PropellerChord(k) | Self::PropellerTwist(k) | Self::EngineTorque(k) => {
                format!("×{k}")
            }
        }
    }
}

/// An estimated value of the preset: its name, why its range is what it is, and the two (or
/// more) values tried.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// The quantity, as printed.
    pub name: &'static str,
    /// The preset's value, as printed.
    pub preset: &'static str,
    /// Where the range comes from.
    pub range: &'static str,
    /// The values tried.
    pub changes: &'static [Change],
}

/// The estimates of the MTOsport preset and their ranges.
pub const ESTIMATES: [Estimate; 13] = [
    Estimate {
        name: "trim mass",
        preset: "450 kg",
        range: "flight-test mass not published: between a light crew with little fuel and MTOW",
        changes: &[Change::TrimMass(400.0)],
    },
    Estimate {
        name: "precone",
        preset: "3°",
        range: "equilibrium coning at 1 g (lift at 0.7 R, blades 12–16 kg, 330–380 rpm): \
                2.5–4.5°",
        changes: &[Change::Precone(2.5), Change::Precone(4.5)],
    },
    Estimate {
        name: "blade mass",
        preset: "14 kg",
        range: "extruded aluminium blades of 4.2 m, 1.1 mm walls: 12–16 kg",
        changes: &[Change::BladeMass(12.0), Change::BladeMass(16.0)],
    },
    Estimate {
        name: "root cut-out",
        preset: "0.5 m",
        range: "10–15 % R typical (Leishman ch. 3): 0.4–0.6 m",
        changes: &[Change::RootCutout(0.4), Change::RootCutout(0.6)],
    },
    Estimate {
        name: "hub inertia",
        preset: "3 kg m²",
        range: "hub bar, teeter block, bolts of 5–8 kg within 0.3 m: 2–4 kg m²",
        changes: &[Change::HubInertia(2.0), Change::HubInertia(4.0)],
    },
    Estimate {
        name: "rolling friction",
        preset: "0.04",
        range: "small tyres on a hard runway: 0.03–0.05",
        changes: &[Change::RollingFriction(0.03), Change::RollingFriction(0.05)],
    },
    Estimate {
        name: "induced-power factor κ",
        preset: "1.15",
        range: "empirical κ ≈ 1.15 (Leishman ch. 2, 5): ±0.1",
        changes: &[
            Change::InducedPowerFactor(1.05),
            Change::InducedPowerFactor(1.25),
        ],
    },
    Estimate {
        name: "rotor tip loss",
        preset: "prandtl",
        range: "the other models of the preset (Gessow–Myers hover relation, chord rule, none)",
        changes: &[
            Change::TipLoss(TipLoss::GessowMyers),
            Change::TipLoss(TipLoss::Chord),
            Change::TipLoss(TipLoss::NoLoss),
        ],
    },
    Estimate {
        name: "yawed-flow profile drag",
        preset: "radial_drag",
        range: "K = 4.6 (radial drag) or 3 (none) in the profile power (1 + Kμ²)",
        changes: &[Change::YawedFlow(YawedFlow::Ignored)],
    },
    Estimate {
        name: "rotor inflow model",
        preset: "drees",
        range: "uniform momentum inflow (Glauert) instead of Drees' linear gradients (Leishman \
                ch. 10); the PCA-2 flight test (NACA Report 487) favours Drees for the lateral \
                flapping",
        changes: &[Change::Inflow(InflowModel::Glauert)],
    },
    Estimate {
        name: "propeller chord",
        preset: "NACA 594 D",
        range: "HTC blade unknown; activity factor of light-aircraft propellers ±15 %",
        changes: &[Change::PropellerChord(0.85), Change::PropellerChord(1.15)],
    },
    Estimate {
        name: "propeller twist",
        preset: "NACA 594 D",
        range: "HTC blade unknown; blade angle change root to tip ±20 %",
        changes: &[Change::PropellerTwist(0.8), Change::PropellerTwist(1.2)],
    },
    Estimate {
        name: "engine torque",
        preset: "Rotax 912 ULS",
        range: "estimated points below 5100 rpm, gear and installation losses: ±5 %",
        changes: &[Change::EngineTorque(0.95), Change::EngineTorque(1.05)],
    },
];

/// What the sensitivity table shows for one set of values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    /// Clean rotor rpm at 60 kt.
    pub clean_rotor_rpm: f64,
    /// Engine rpm contaminated − clean at 60 kt (NaN if the engine cannot reach one).
    pub delta_engine_rpm: f64,
    /// Propeller thrust contaminated / clean − 1 at 60 kt \[%\].
    pub delta_prop_thrust_percent: f64,
    /// Clean takeoff roll \[m\].
    pub takeoff_roll_m: f64,
    /// Clean distance to 15 m \[m\].
    pub distance_15m_m: f64,
}

/// One row: an estimate at one value, and what follows.
#[derive(Debug)]
pub struct SensitivityRow {
    /// The estimate.
    pub estimate: &'static Estimate,
    /// The value tried.
    pub change: Change,
    /// The outcome, or why there is none.
    pub outcome: Result<Outcome, StudyError>,
}

/// The preset's outcome and every row.
#[derive(Debug)]
pub struct Sensitivity {
    /// With the preset's values.
    pub baseline: Outcome,
    /// One per value of each estimate, in the order of [`ESTIMATES`].
    pub rows: Vec<SensitivityRow>,
}

/// The trims' part of an outcome of `aircraft` (trims at `trim_mass` kg) with the two sections:
/// clean rotor rpm, Δ engine rpm, ΔF_prop \[%\].
fn trim_outcome<S: SectionAero + Sync + ?Sized>(
    aircraft: &Aircraft,
    trim_mass: f64,
    clean: &S,
    contaminated: &S,
) -> Result<[f64; 3], StudyError> {
    let trim = |section: &S, case: &str| {
        trim_aircraft(
            aircraft,
            section,
            PAPER_TRIM_SPEED_KT,
            trim_mass,
            0.0,
            &TrimParams::default(),
        )
        .map_err(|source| StudyError::Trim {
            case: case.to_string(),
            source,
        })
    };
    let (c, d) = rayon::join(
        || trim(clean, "clean"),
        || trim(contaminated, "contaminated"),
    );
    let (c, d) = (c?, d?);
    let rpm = |e: Option<f64>| e.unwrap_or(f64::NAN);
    Ok([
        c.rotor_rpm,
        rpm(d.engine_rpm) - rpm(c.engine_rpm),
        100.0 * (d.prop_thrust_n / c.prop_thrust_n - 1.0),
    ])
}

/// The takeoff's part of an outcome of `aircraft` with the clean section: s_TO, s_15 \[m\].
fn takeoff_outcome<S: SectionAero + Sync + ?Sized>(
    aircraft: &Aircraft,
    clean: &S,
) -> Result<[f64; 2], StudyError> {
    let t = simulate_takeoff(aircraft, clean).map_err(|source| StudyError::Takeoff {
        case: "clean".to_string(),
        source,
    })?;
    Ok([t.takeoff_roll_m, t.distance_15m_m])
}

impl Outcome {
    /// The outcome from its trims' and its takeoff's parts.
    fn of(
        [clean_rotor_rpm, delta_engine_rpm, delta_prop_thrust_percent]: [f64; 3],
        [takeoff_roll_m, distance_15m_m]: [f64; 2],
    ) -> Self {
        Self {
            clean_rotor_rpm,
            delta_engine_rpm,
            delta_prop_thrust_percent,
            takeoff_roll_m,
            distance_15m_m,
        }
    }
}

/// The sensitivity of the study to [`ESTIMATES`] for `aircraft` with the `clean` and
/// `contaminated` blade sections (every value in parallel).
pub fn sensitivity<S: SectionAero + Sync + ?Sized>(
    aircraft: &Aircraft,
    clean: &S,
    contaminated: &S,
) -> Result<Sensitivity, StudyError> {
    let cases: Vec<(&'static Estimate, Change)> = ESTIMATES
        .iter()
        .flat_map(|e| e.changes.iter().map(move |c| (e, *c)))
        .collect();
    let (trims, takeoff) = rayon::join(
        || trim_outcome(aircraft, aircraft.mass_kg, clean, contaminated),
        || takeoff_outcome(aircraft, clean),
    );
    let (trims, takeoff) = (trims?, takeoff?);
    // A change the trims or the takeoff do not see takes that part from the preset's run.
    let rows = cases
        .par_iter()
        .map(|&(estimate, change)| {
            let mut ac = aircraft.clone();
            change.apply(&mut ac);
            let mass = match change {
                Change::TrimMass(m) => m,
                _ => ac.mass_kg,
            };
            let (moves_trims, moves_takeoff) = change.moves();
            let (row_trims, row_takeoff) = rayon::join(
                || {
                    if moves_trims {
                        trim_outcome(&ac, mass, clean, contaminated)
                    } else {
                        Ok(trims)
                    }
                },
                || {
                    if moves_takeoff {
                        takeoff_outcome(&ac, clean)
                    } else {
                        Ok(takeoff)
                    }
                },
            );
            SensitivityRow {
                estimate,
                change,
                outcome: row_trims.and_then(|t| Ok(Outcome::of(t, row_takeoff?))),
            }
        })
        .collect();
    Ok(Sensitivity {
        baseline: Outcome::of(trims, takeoff),
        rows,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::read_table;
    use std::path::Path;

    /// What [`Change::moves`] leaves out is the preset's run: on the shipped 8-H-12 tables, a
    /// change that does not move the trims gives the preset's trims bit for bit; one that does
    /// not move the takeoff leaves the aircraft the takeoff reads unchanged.
    #[test]
    fn a_change_leaves_alone_what_it_does_not_move() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let ac = Aircraft::from_toml_file(&root.join("aircraft/mtosport.toml")).unwrap();
        let [clean, dirty] = ["naca8h12_free.csv", "naca8h12_xtr0.07.csv"]
            .map(|f| read_table(&root.join("polars").join(f)).unwrap());
        let trims = trim_outcome(&ac, ac.mass_kg, &clean, &dirty).unwrap();
        let changes: Vec<Change> = ESTIMATES.iter().flat_map(|e| e.changes).copied().collect();
        let mut checked = (0, 0);
        for change in changes {
            let mut changed = ac.clone();
            change.apply(&mut changed);
            match change.moves() {
                (false, true) => {
                    let t = trim_outcome(&changed, changed.mass_kg, &clean, &dirty).unwrap();
                    assert_eq!(t, trims, "{change:?}");
                    checked.0 += 1;
                }
                (true, false) => {
                    // The takeoff reads the aircraft alone: the change must leave it as it is
                    // (the trim mass enters the trims as an argument).
                    assert_eq!(format!("{changed:?}"), format!("{ac:?}"), "{change:?}");
                    checked.1 += 1;
                }
                _ => {}
            }
        }
        // Hub inertia and rolling friction at both ends; the trim mass.
        assert_eq!(checked, (4, 1));
    }
}
