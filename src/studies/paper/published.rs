//! The published numbers the study is compared with: Duda, Sachs, Seewald, Rohardt (DLR),
//! "Effects of rotor contamination on gyroplane flight performance" — Tables 3, 4 and 5 and the
//! values quoted with Figs. 10 and 11 — plus the XFOIL 6.99 reference values of Table 5
//! measured for this project. Each paper value sits beside the accessor of our result it is
//! compared with, so values are paired by name, never by position.

use crate::rotor::{TakeoffResult, TrimResult};

/// A value for each blade-section case of the study.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaseValues {
    /// Clean blades (free transition).
    pub clean: f64,
    /// Contaminated blades (transition fixed at 7 % chord).
    pub contaminated: f64,
}

impl CaseValues {
    /// The values in case order: clean, contaminated.
    pub fn both(&self) -> [f64; 2] {
        [self.clean, self.contaminated]
    }
}

/// One quantity of a paper table: its name as printed, the paper's values, the decimals ours is
/// printed with, and the accessor of ours in a result of type `R`.
#[derive(Clone, Copy, Debug)]
pub struct PaperQuantity<R> {
    /// Name as printed, with its symbol and unit.
    pub name: &'static str,
    /// The paper's values.
    pub paper: CaseValues,
    /// Decimals of ours in the report.
    pub decimals: usize,
    /// Ours, read from a result.
    pub ours: fn(&R) -> f64,
}

/// Paper Table 3: trim at 60 kt, 450 kg, ISA sea level.
pub const TABLE3_TRIM: [PaperQuantity<TrimResult>; 7] = [
    PaperQuantity {
        name: "rotor rpm n_R",
        paper: CaseValues {
            clean: 347.0,
            contaminated: 348.0,
        },
        decimals: 1,
        ours: |t| t.rotor_rpm,
    },
    // The paper's α_R is the drag-equivalent angle (eq. 5: D_R = G·α_R; Table 3:
    // atan(478/4414) = 6.2°), so ours is atan(D_R/L_R), not the tip-path-plane angle.
    PaperQuantity {
        name: "rotor AoA alpha_R [deg]",
        paper: CaseValues {
            clean: 6.2,
            contaminated: 8.1,
        },
        decimals: 2,
        ours: |t| t.rotor_aoa_drag_equivalent_deg,
    },
    PaperQuantity {
        name: "engine rpm",
        paper: CaseValues {
            clean: 4401.0,
            contaminated: 4596.0,
        },
        decimals: 0,
        ours: |t| t.engine_rpm.unwrap_or(f64::NAN),
    },
    PaperQuantity {
        name: "rotor drag D_R [N]",
        paper: CaseValues {
            clean: 478.0,
            contaminated: 624.0,
        },
        decimals: 1,
        ours: |t| t.rotor_drag_n,
    },
    PaperQuantity {
        name: "parasitic drag D_P [N]",
        paper: CaseValues {
            clean: 573.0,
            contaminated: 573.0,
        },
        decimals: 1,
        ours: |t| t.parasitic_drag_n,
    },
    PaperQuantity {
        name: "prop thrust F_prop [N]",
        paper: CaseValues {
            clean: 1051.0,
            contaminated: 1197.0,
        },
        decimals: 1,
        ours: |t| t.prop_thrust_n,
    },
    PaperQuantity {
        name: "L/D",
        paper: CaseValues {
            clean: 4.2,
            contaminated: 3.7,
        },
        decimals: 2,
        ours: |t| t.lift_to_drag,
    },
];

/// Paper Table 4: takeoff, ISA sea level, no wind, 450 kg.
pub const TABLE4_TAKEOFF: [PaperQuantity<TakeoffResult>; 3] = [
    PaperQuantity {
        name: "takeoff roll s_TO [m]",
        paper: CaseValues {
            clean: 121.0,
            contaminated: 144.0,
        },
        decimals: 1,
        ours: |t| t.takeoff_roll_m,
    },
    PaperQuantity {
        name: "distance to 15 m s_15 [m]",
        paper: CaseValues {
            clean: 218.0,
            contaminated: 253.0,
        },
        decimals: 1,
        ours: |t| t.distance_15m_m,
    },
    PaperQuantity {
        name: "max flapping beta_max [deg]",
        paper: CaseValues {
            clean: 3.5,
            contaminated: 4.2,
        },
        decimals: 2,
        ours: |t| t.max_flapping_deg,
    },
];

/// One quantity of a paper table beside ours, both cases.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// Name as printed.
    pub name: &'static str,
    /// The paper's values.
    pub paper: CaseValues,
    /// Ours.
    pub ours: CaseValues,
    /// Decimals of ours in the report.
    pub decimals: usize,
}

/// Relative change from `a` to `b` [%]: (b − a)/a, e.g. ours against the paper's value or the
/// contaminated case against the clean one.
pub fn change_percent(a: f64, b: f64) -> f64 {
    100.0 * (b - a) / a
}

/// Each quantity of `table` beside ours from the `clean` and `contaminated` results.
pub fn compare<R>(table: &[PaperQuantity<R>], clean: &R, contaminated: &R) -> Vec<Comparison> {
    table
        .iter()
        .map(|q| Comparison {
            name: q.name,
            paper: q.paper,
            ours: CaseValues {
                clean: (q.ours)(clean),
                contaminated: (q.ours)(contaminated),
            },
            decimals: q.decimals,
        })
        .collect()
}

/// Paper Table 1: maximum takeoff thrust ≈ 2000 N (what our propeller's full-throttle static
/// thrust is compared with).
pub const TABLE1_STATIC_THRUST_N: f64 = 2000.0;

/// The flight test (paper Table 2) at 60 kt: engine rpm clean ≈ 4400, contaminated ≈ 4600 —
/// the one measurement of the study; the rotor rpm stays ≈ 350.
pub const TABLE2_ENGINE_RPM: CaseValues = CaseValues {
    clean: 4400.0,
    contaminated: 4600.0,
};

/// The flight test's rotor rpm at 60 kt, both cases (paper Table 2).
pub const TABLE2_ROTOR_RPM: f64 = 350.0;

/// The paper's text on the clean takeoff (Fig. 11): 200 rpm prerotation → ≈ 300 rpm at
/// lift-off.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CleanTakeoffText {
    /// Lift-off speed \[kt\].
    pub liftoff_speed_kt: f64,
    /// Speed at 15 m \[kt\].
    pub screen_speed_kt: f64,
    /// Rotor speed at lift-off \[rpm\].
    pub liftoff_rotor_rpm: f64,
}

/// The paper's text on the clean takeoff.
pub const CLEAN_TAKEOFF_TEXT: CleanTakeoffText = CleanTakeoffText {
    liftoff_speed_kt: 43.0,
    screen_speed_kt: 51.0,
    liftoff_rotor_rpm: 300.0,
};

/// Paper Fig. 10: maximum blade angle of attack at ≈ 90 % R in 60 kt cruise \[deg\], reached on
/// the retreating side at [`FIG10_PSI_DEG`] (ψ = 0 at the rear).
pub const FIG10_MAX_ALPHA_DEG: CaseValues = CaseValues {
    clean: 5.9,
    contaminated: 6.7,
};

/// Azimuth of the paper's Fig. 10 maxima \[deg\].
pub const FIG10_PSI_DEG: f64 = 270.0;

/// Reynolds number of the paper's airfoil analysis (blade section at ≈ 90 % R).
pub const SECTION_RE: f64 = 1.9e6;

/// Mach number of the paper's airfoil analysis.
pub const SECTION_MACH: f64 = 0.41;

/// Lift coefficient at which the paper's Table 5 compares the drag.
pub const TABLE5_CL: f64 = 0.8;

/// A value for each transition setting of Table 5.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TransitionValues {
    /// Free transition (e^N).
    pub free: f64,
    /// Transition fixed at 7 % chord on both surfaces.
    pub fixed: f64,
}

impl TransitionValues {
    /// The values in the order free, fixed.
    pub fn both(&self) -> [f64; 2] {
        [self.free, self.fixed]
    }
}

/// One airfoil row of Table 5.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Table5Row {
    /// File stem of the shipped tables (`polars/<stem>_free.csv`, `polars/<stem>_xtr0.07.csv`).
    pub stem: &'static str,
    /// Airfoil name as printed.
    pub name: &'static str,
    /// Paper Table 5 (XFOIL 6.94), Cd at Cl = 0.8; the paper prints three decimals.
    pub paper_cd: TransitionValues,
    /// XFOIL 6.99 at Re 1.9e6, M 0.41 (160 panels, Ncrit 9; the reference polars of
    /// `tests/data/xfoil/`), Cd at Cl = 0.8 by linear interpolation between its converged
    /// points.
    pub xfoil_cd: TransitionValues,
    /// α \[deg\] at Cl = 0.8 in the same XFOIL 6.99 polars.
    pub xfoil_alpha_deg: TransitionValues,
}

/// Paper Table 5, blade drag coefficient at Cl = 0.8, Re 1.9e6, M 0.41.
pub const TABLE5: [Table5Row; 2] = [
    Table5Row {
        stem: "naca8h12",
        name: "NACA 8-H-12",
        paper_cd: TransitionValues {
            free: 0.006,
            fixed: 0.012,
        },
        xfoil_cd: TransitionValues {
            free: 0.00607,
            fixed: 0.01165,
        },
        xfoil_alpha_deg: TransitionValues {
            free: 4.40,
            fixed: 5.26,
        },
    },
    Table5Row {
        stem: "naca23012",
        name: "NACA 23012",
        paper_cd: TransitionValues {
            free: 0.008,
            fixed: 0.012,
        },
        xfoil_cd: TransitionValues {
            free: 0.00802,
            fixed: 0.01118,
        },
        xfoil_alpha_deg: TransitionValues {
            free: 5.23,
            fixed: 5.21,
        },
    },
];
