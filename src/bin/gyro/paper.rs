//! The published numbers `gyro` is compared with: Duda, Sachs, Seewald, Rohardt (DLR),
//! "Effects of rotor contamination on gyroplane flight performance" — Tables 3, 4 and 5 and the
//! values quoted with Figs. 10 and 11 — plus the XFOIL 6.99 reference values of Table 5 measured
//! for this project.

/// Paper Table 3 (quantity, clean, contaminated): trim at 60 kt, 450 kg, ISA sea level.
pub const PAPER_TRIM: [(&str, f64, f64); 7] = [
    ("rotor rpm n_R", 347.0, 348.0),
    ("rotor AoA alpha_R [deg]", 6.2, 8.1),
    ("engine rpm", 4401.0, 4596.0),
    ("rotor drag D_R [N]", 478.0, 624.0),
    ("parasitic drag D_P [N]", 573.0, 573.0),
    ("prop thrust F_prop [N]", 1051.0, 1197.0),
    ("L/D", 4.2, 3.7),
];

/// Paper Table 4 (quantity, clean, contaminated): takeoff, ISA sea level, no wind, 450 kg.
pub const PAPER_TAKEOFF: [(&str, f64, f64); 3] = [
    ("takeoff roll s_TO [m]", 121.0, 144.0),
    ("distance to 15 m s_15 [m]", 218.0, 253.0),
    ("max flapping beta_max [deg]", 3.5, 4.2),
];

/// Paper text on the clean takeoff (Fig. 11): lift-off speed \[kt\], speed at 15 m \[kt\] and rotor
/// speed at lift-off \[rpm\] (200 rpm prerotation → ≈ 300 rpm at lift-off).
pub const PAPER_CLEAN_TAKEOFF_TEXT: (f64, f64, f64) = (43.0, 51.0, 300.0);

/// Paper Fig. 10: maximum blade angle of attack at ≈ 90 % R in 60 kt cruise \[deg\] (clean,
/// contaminated), reached on the retreating side at ψ = 270° (ψ = 0 at the rear).
pub const PAPER_FIG10_MAX_ALPHA: (f64, f64) = (5.9, 6.7);

/// Azimuth of the paper's Fig. 10 maxima \[deg\].
pub const PAPER_FIG10_PSI: f64 = 270.0;

/// Reynolds and Mach number of the paper's airfoil analysis (blade section at ≈ 90 % R).
pub const PAPER_RE: f64 = 1.9e6;

/// Mach number of the paper's airfoil analysis.
pub const PAPER_MACH: f64 = 0.41;

/// Lift coefficient at which the paper's Table 5 compares the drag.
pub const PAPER_TABLE5_CL: f64 = 0.8;

/// One airfoil row of Table 5.
pub struct Table5Row {
    /// File stem of the shipped tables (`polars/<stem>_free.csv`, `polars/<stem>_xtr0.07.csv`).
    pub stem: &'static str,
    /// Airfoil name as printed.
    pub name: &'static str,
    /// Paper Table 5 (XFOIL 6.94), Cd at Cl = 0.8: free transition, fixed at 7 % chord. The paper
    /// prints three decimals.
    pub paper: (f64, f64),
    /// XFOIL 6.99 at Re 1.9e6, M 0.41 (160 panels, Ncrit 9; the reference polars of
    /// `tests/data/viscous/`), Cd at Cl = 0.8 by linear interpolation between its converged
    /// points: free, fixed at 7 %.
    pub xfoil: (f64, f64),
    /// α \[deg\] at Cl = 0.8 in the same XFOIL 6.99 polars: free, fixed at 7 %.
    pub xfoil_alpha: (f64, f64),
}

/// Paper Table 5, blade drag coefficient at Cl = 0.8, Re 1.9e6, M 0.41.
pub const PAPER_TABLE5: [Table5Row; 2] = [
    Table5Row {
        stem: "naca8h12",
        name: "NACA 8-H-12",
        paper: (0.006, 0.012),
        xfoil: (0.00607, 0.01165),
        xfoil_alpha: (4.40, 5.26),
    },
    Table5Row {
        stem: "naca23012",
        name: "NACA 23012",
        paper: (0.008, 0.012),
        xfoil: (0.00802, 0.01118),
        xfoil_alpha: (5.23, 5.21),
    },
];
