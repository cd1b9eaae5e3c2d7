//! The panel method against XFOIL 6.99's inviscid CL, CM and CDp on XFOIL's own 160 nodes,
//! α −6…14° at M 0 and 0.41. Guards that the inviscid solution is XFOIL's: the same method on
//! the same nodes leaves only the rounding of XFOIL's printed digits (Cl, Cm to 1e-4, CDp to
//! 1e-5), and each airfoil must stay within about three times the deviations measured when the
//! limits were set. The README's inviscid line is this file's output.

mod xfoil_support;

use polargen::inviscid::PanelSystem;
use std::fmt::Write;
use xfoil_support::{paneled, polar};

/// Largest |ΔCl|, |ΔCm|, |ΔCdp| over the sweep of `foil` at Mach `mach` (as in the file name).
fn max_errors(foil: &str, mach: &str) -> [f64; 3] {
    let sys = PanelSystem::new(&paneled(foil)).unwrap();
    let m: f64 = mach.parse().unwrap();
    let rows = polar(&format!("{foil}_inviscid_M{mach}.csv"));
    assert_eq!(rows.len(), 21, "{foil} M{mach}: reference sweep");
    let mut worst = [0.0_f64; 3];
    for r in &rows {
        let sol = sys.solve(r.alpha, m).unwrap();
        let d = [
            (sol.cl - r.cl).abs(),
            (sol.cm - r.cm).abs(),
            (sol.cdp - r.cdp).abs(),
        ];
        for (w, d) in worst.iter_mut().zip(d) {
            *w = w.max(d);
        }
    }
    println!(
        "{foil} M{mach}: max |dCl| = {:.2e}, |dCm| = {:.2e}, |dCdp| = {:.2e}",
        worst[0], worst[1], worst[2]
    );
    worst
}

/// `foil` at M 0 and 0.41 against `limits` (|ΔCl|, |ΔCm|, |ΔCdp|, both Mach numbers).
fn check(foil: &str, limits: [f64; 3]) {
    for mach in ["0", "0.41"] {
        let worst = max_errors(foil, mach);
        for (what, (w, l)) in ["Cl", "Cm", "Cdp"].iter().zip(worst.iter().zip(limits)) {
            assert!(*w <= l, "{foil} M{mach}: max |d{what}| = {w:.2e} > {l:.1e}");
        }
    }
}

// Limits: about three times the deviations measured when they were set (in the comments:
// |ΔCl|, |ΔCm|, |ΔCdp| over both Mach numbers, each XFOIL's rounding), but Cl and Cm not
// above 1e-4, one unit of XFOIL's last digit.

#[test]
fn naca0012_matches_xfoil() {
    // measured 5.0e-5, 4.5e-5, 5.0e-6
    check("naca0012", [1e-4, 1e-4, 1.5e-5]);
}

#[test]
fn naca2412_matches_xfoil() {
    // measured 4.9e-5, 4.9e-5, 4.9e-6
    check("naca2412", [1e-4, 1e-4, 1.5e-5]);
}

#[test]
fn naca23012_matches_xfoil() {
    // measured 4.9e-5, 5.0e-5, 5.0e-6
    check("naca23012", [1e-4, 1e-4, 1.5e-5]);
}

#[test]
fn naca8h12_matches_xfoil() {
    // measured 4.8e-5, 4.9e-5, 4.4e-6
    check("naca8h12", [1e-4, 1e-4, 1.5e-5]);
}

/// README.md's inviscid sentence, from the same comparison.
#[test]
fn readme_inviscid_line_is_current() {
    let mut worst = [0.0_f64; 2];
    for foil in ["naca0012", "naca2412", "naca23012", "naca8h12"] {
        for mach in ["0", "0.41"] {
            let e = max_errors(foil, mach);
            worst = [worst[0].max(e[0]), worst[1].max(e[1])];
        }
    }
    let mut line = String::new();
    writeln!(
        line,
        "Inviscid on XFOIL's nodes (test `inviscid_xfoil`): max |ΔCl| {:.1e}, max |ΔCm| {:.1e} for \
         NACA 0012, 2412, 23012 and 8-H-12 at M 0 and 0.41, α −6…14°.",
        worst[0], worst[1]
    )
    .unwrap();
    xfoil_support::check_readme_block(
        "inviscid accuracy",
        "UPDATE_README=1 cargo test --test inviscid_xfoil readme",
        &line,
    );
}
