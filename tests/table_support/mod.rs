//! Shared builders for the table tests: analytic polars and the XFOIL reference polars.
#![allow(dead_code)]

#[path = "../xfoil_support/mod.rs"]
pub mod xfoil_support;

#[path = "../cli_support/mod.rs"]
pub mod cli_support;
/// A fresh, empty scratch folder (the CLI tests' one; not every table test uses it).
#[allow(unused_imports)]
pub use cli_support::scratch;

use polargen::section::{PolarPoint, Transition};
use polargen::table::{PolarTable, TableMeta};

/// Metadata of the synthetic test tables.
pub fn meta(name: &str) -> TableMeta {
    TableMeta {
        airfoil: name.to_string(),
        transition: Transition::default(),
        thickness: 0.12,
        panels: 160,
        solver: "polargen 0.1.0".to_string(),
        geometry: Vec::new(),
    }
}

/// A converged point with the given coefficients (cdp = 0.4·cd, cdf = cd − cdp).
pub fn point(alpha: f64, cl: f64, cd: f64, cm: f64) -> PolarPoint {
    PolarPoint {
        alpha,
        cl,
        cd,
        cdp: 0.4 * cd,
        cdf: 0.6 * cd,
        cm,
        xtr_top: 0.5,
        xtr_bot: 0.9,
        converged: true,
        iterations: 7,
        residual: 1e-9,
        cpmin: -0.8,
        supercritical: Some(false),
        xsep_top: 1.0,
        xsep_bot: 1.0,
        massive_separation: Some(false),
    }
}

/// An unconverged point holding garbage coefficients (they must never be used).
pub fn failed(alpha: f64) -> PolarPoint {
    PolarPoint {
        converged: false,
        iterations: 200,
        residual: 0.3,
        ..point(alpha, 99.0, -5.0, 42.0)
    }
}

/// Analytic lift: linear in α, ln Re and M plus a ln Re·M term, so that PCHIP in α and
/// bilinear (ln Re, M) interpolation reproduce it exactly.
pub fn cl_model(alpha: f64, re: f64, mach: f64) -> f64 {
    let l = (re / 1e6).ln();
    0.11 * alpha + 0.2 * l + 0.5 * mach + 0.03 * l * mach
}

/// Analytic moment, linear in α, ln Re and M.
pub fn cm_model(alpha: f64, re: f64, mach: f64) -> f64 {
    -0.05 + 0.002 * alpha + 0.01 * (re / 1e6).ln() - 0.02 * mach
}

/// Analytic drag, linear in α (so that interpolation is exact): 0.02 + 0.0005·α + terms.
pub fn cd_model(alpha: f64, re: f64, mach: f64) -> f64 {
    0.02 + 0.0005 * alpha - 0.002 * (re / 1e6).ln() + 0.01 * mach
}

/// Analytic polar at (Re, M) over `alphas`.
pub fn analytic_polar(re: f64, mach: f64, alphas: &[f64]) -> Vec<PolarPoint> {
    alphas
        .iter()
        .map(|&a| {
            point(
                a,
                cl_model(a, re, mach),
                cd_model(a, re, mach),
                cm_model(a, re, mach),
            )
        })
        .collect()
}

/// α = a0, a0 + da, …, a1.
pub fn alpha_range(a0: f64, a1: f64, da: f64) -> Vec<f64> {
    let n = ((a1 - a0) / da).round() as usize;
    (0..=n).map(|i| a0 + i as f64 * da).collect()
}

/// Analytic table on Re {0.5, 1, 2}·10⁶ × M {0, 0.2, 0.4} × α −10…15 step 1.
pub fn analytic_table() -> PolarTable {
    let re = vec![0.5e6, 1e6, 2e6];
    let mach = vec![0.0, 0.2, 0.4];
    let alphas = alpha_range(-10.0, 15.0, 1.0);
    let mut polars = Vec::new();
    for &r in &re {
        for &m in &mach {
            polars.push(analytic_polar(r, m, &alphas));
        }
    }
    PolarTable::new(meta("analytic"), re, mach, polars).expect("valid analytic table")
}

/// The XFOIL 6.99 reference polar `file` of tests/data/xfoil as converged points (α values XFOIL
/// did not converge at are absent from the file).
pub fn xfoil_reference(file: &str) -> Vec<PolarPoint> {
    xfoil_support::polar(file)
        .into_iter()
        .map(|r| PolarPoint {
            cdp: r.cdp,
            cdf: r.cd - r.cdp,
            xtr_top: r.xtr_top,
            xtr_bot: r.xtr_bot,
            ..PolarPoint::from_coefficients(r.alpha, r.cl, r.cd, r.cm)
        })
        .collect()
}

/// Compare two tables field by field, treating NaN as equal to NaN (bitwise comparison).
pub fn same_bits(a: &PolarTable, b: &PolarTable) -> bool {
    let pa: Vec<_> = a.polars().collect();
    let pb: Vec<_> = b.polars().collect();
    a.meta() == b.meta()
        && a.re() == b.re()
        && a.mach() == b.mach()
        && pa.len() == pb.len()
        && pa.iter().zip(&pb).all(|(x, y)| {
            x.0.reynolds.to_bits() == y.0.reynolds.to_bits()
                && x.0.mach.to_bits() == y.0.mach.to_bits()
                && x.1.len() == y.1.len()
                && x.1.iter().zip(y.1).all(|(p, q)| {
                    let f = |p: &PolarPoint| {
                        [
                            p.alpha, p.cl, p.cd, p.cdp, p.cdf, p.cm, p.xtr_top, p.xtr_bot,
                            p.residual, p.cpmin,
                        ]
                        .map(f64::to_bits)
                    };
                    f(p) == f(q)
                        && p.converged == q.converged
                        && p.iterations == q.iterations
                        && p.supercritical == q.supercritical
                })
        })
}

/// The names of the entries of `dir`, sorted.
pub fn files_in(dir: &std::path::Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}
