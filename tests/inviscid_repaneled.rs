//! The whole inviscid chain as a user runs it — our NACA generator / file reader, our
//! curvature-based repaneling to 160 nodes, our panel method — against XFOIL 6.99's inviscid
//! CL/CM (XFOIL's own NACA geometry or LOAD + PANE). Tolerances from issue 2:
//! |ΔCl| ≤ 0.01 and |ΔCm| ≤ 0.004 over α −6…14 at M = 0 and 0.41.

use polargen::geometry::{airfoil_by_name_or_path, PanelingParams};
use polargen::inviscid::PanelSystem;

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/inviscid");

/// (alpha, cl, cm) rows of an XFOIL inviscid polar CSV (alpha,cl,cd,cdp,cm,…).
fn reference(name: &str, mach: &str) -> Vec<(f64, f64, f64)> {
    let text = std::fs::read_to_string(format!("{DATA}/{name}_inviscid_M{mach}.csv")).unwrap();
    text.lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|t| t.parse().unwrap()).collect();
            (v[0], v[1], v[4])
        })
        .collect()
}

fn check(name: &str) {
    let foil = airfoil_by_name_or_path(name)
        .unwrap()
        .repanel(160, &PanelingParams::default())
        .unwrap();
    let sys = PanelSystem::new(&foil).unwrap();
    for mach in ["0", "0.41"] {
        let m: f64 = mach.parse().unwrap();
        let rows = reference(name, mach);
        assert!(rows.len() >= 15, "{name} M{mach}: reference too short");
        let (mut ecl, mut ecm) = (0.0_f64, 0.0_f64);
        for (alpha, cl, cm) in rows {
            let sol = sys.solve(alpha, m).unwrap();
            ecl = ecl.max((sol.cl - cl).abs());
            ecm = ecm.max((sol.cm - cm).abs());
        }
        println!("{name} M{mach} repaneled: max |dCl| = {ecl:.2e}, max |dCm| = {ecm:.2e}");
        assert!(ecl <= 0.01, "{name} M{mach}: max |dCl| = {ecl}");
        assert!(ecm <= 0.004, "{name} M{mach}: max |dCm| = {ecm}");
    }
}

#[test]
fn naca0012_repaneled_matches_xfoil() {
    check("naca0012");
}

#[test]
fn naca2412_repaneled_matches_xfoil() {
    check("naca2412");
}

#[test]
fn naca23012_repaneled_matches_xfoil() {
    check("naca23012");
}

#[test]
fn naca8h12_repaneled_matches_xfoil() {
    check("naca8h12");
}
