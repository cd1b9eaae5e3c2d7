//! Shared by the boundary-layer tests: the BL model at given conditions, XFOIL 6.99 DUMP files
//! (tests/data/xfoil) split into surfaces at the stagnation point, and the inverse Karman–Tsien
//! relation that turns XFOIL's dumped (compressible) edge speeds back into panel speeds.
#![allow(dead_code)]

#[path = "../xfoil_support/mod.rs"]
pub mod xfoil_support;

use polargen::boundary_layer::{BlConditions, BlModel, BlParams};

/// The BL model with XFOIL's default parameters and Ncrit 9.
pub fn model(re: f64, mach: f64) -> BlModel {
    BlModel::new(
        &BlConditions {
            reynolds: re,
            mach,
            ncrit: 9.0,
        },
        BlParams::default(),
    )
    .expect("valid conditions")
}

/// Incompressible edge speed from XFOIL's dumped (compressible) Ue by inverting the
/// Karman–Tsien relation Ue = Ui(1−λ)/(1−λUi²): the positive root of λ·Ue·Ui² + (1−λ)Ui − Ue = 0.
pub fn incompressible(m: &BlModel, ue: f64) -> f64 {
    let l = m.flow.karman_tsien.lambda;
    let ue = ue.abs();
    if l == 0.0 {
        return ue;
    }
    let (a, b, c) = (l * ue, 1.0 - l, -ue);
    (-b + (b * b - 4.0 * a * c).sqrt()) / (2.0 * a)
}

/// One row of an XFOIL DUMP file.
#[derive(Clone, Copy, Debug)]
pub struct Row {
    /// Arc length along the contour (XFOIL's s, from the upper TE).
    pub s: f64,
    /// x/c.
    pub x: f64,
    /// Signed compressible edge speed (negative on the lower surface).
    pub ue: f64,
    /// Displacement thickness δ*.
    pub dstar: f64,
    /// Momentum thickness θ.
    pub theta: f64,
    /// Skin friction (free-stream based).
    pub cf: f64,
    /// Kinematic shape factor Hk (BLDUMP prints HKIN).
    pub h: f64,
    /// H* where the dump has it.
    pub hs: Option<f64>,
}

/// Surfaces of a dump, each station with ξ, its arc length from the interpolated stagnation
/// point: upper (stagnation → TE), lower (stagnation → TE), wake (TE → end).
pub struct Dump {
    pub upper: Vec<(f64, Row)>,
    pub lower: Vec<(f64, Row)>,
    pub wake: Vec<(f64, Row)>,
}

/// The dump `name` of tests/data/xfoil: airfoil rows have 12 columns, wake rows 8.
pub fn load_dump(name: &str) -> Dump {
    let mut airfoil = Vec::new();
    let mut wake = Vec::new();
    for v in xfoil_support::dump(name) {
        let row = Row {
            s: v[0],
            x: v[1],
            ue: v[3],
            dstar: v[4],
            theta: v[5],
            cf: v[6],
            h: v[7],
            hs: v.get(8).copied(),
        };
        if v.len() >= 12 {
            airfoil.push(row);
        } else {
            wake.push(row);
        }
    }
    // Stagnation point: sign change of the signed surface speed, interpolated linearly.
    let k = airfoil
        .windows(2)
        .position(|w| w[0].ue > 0.0 && w[1].ue <= 0.0)
        .expect("stagnation point");
    let (a, b) = (airfoil[k], airfoil[k + 1]);
    let s_stag = a.s + (b.s - a.s) * a.ue / (a.ue - b.ue);
    Dump {
        upper: airfoil[..=k]
            .iter()
            .rev()
            .map(|r| (s_stag - r.s, *r))
            .collect(),
        lower: airfoil[k + 1..]
            .iter()
            .map(|r| (r.s - s_stag, *r))
            .collect(),
        wake: wake.iter().map(|r| (r.s - s_stag, *r)).collect(),
    }
}
