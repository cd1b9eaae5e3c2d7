//! Karman–Tsien correction (XFOIL CPCALC/CLCALC): formula values, the Prandtl–Glauert
//! limit, behaviour towards the critical Mach number and input errors.

mod xfoil_support;

use polargen::compressibility::{KarmanTsien, MachOutOfRange};
use polargen::inviscid::{InviscidError, PanelSystem};
use xfoil_support::paneled;

/// Cp_c = Cp/(β + λ(1+β)Cp/2) with λ = M²/(1+β)², checked at M = 0.5, Cp = −1 against the
/// hand-evaluated value −1.251505; small Cp tends to Prandtl–Glauert Cp/β.
#[test]
fn karman_tsien_values() {
    let kt = KarmanTsien::new(0.5).unwrap();
    assert!((kt.beta - 0.75_f64.sqrt()).abs() < 1e-15);
    let cp = kt.cp(-1.0).unwrap();
    assert!((cp - (-1.251505)).abs() < 1e-6, "Cp_c = {cp}");
    let small = 1.0e-7;
    assert!((kt.cp(small).unwrap() / small - 1.0 / kt.beta).abs() < 1e-6);
    // M = 0 leaves Cp unchanged; Cp* is -inf.
    let kt0 = KarmanTsien::new(0.0).unwrap();
    assert_eq!(kt0.cp(-2.5), Some(-2.5));
    assert_eq!(kt0.cp_sonic(), f64::NEG_INFINITY);
    // Sonic Cp of air at M = 0.7: -0.779 (isentropic relation).
    let cps = KarmanTsien::new(0.7).unwrap().cp_sonic();
    assert!((cps + 0.7794).abs() < 1e-3, "Cp* = {cps}");
    // Compressible speed: stagnation stays zero, freestream stays one; the relation without
    // the range check gives the same value inside the range.
    assert_eq!(kt.speed(0.0), 0.0);
    assert!((kt.speed(1.0) - 1.0).abs() < 1e-15);
    assert_eq!(kt.cp_unchecked(-1.0), kt.cp(-1.0).unwrap());
}

/// Lift grows with Mach roughly like 1/β: Karman–Tsien gives more than Prandtl–Glauert
/// because suction peaks are amplified more (measured +8 % at M = 0.6, α = 2°).
#[test]
fn lift_grows_with_mach() {
    let sys = PanelSystem::new(&paneled("naca0012")).unwrap();
    let cl0 = sys.solve(2.0, 0.0).unwrap().cl;
    let mut prev = cl0;
    for m in [0.2, 0.4, 0.6] {
        let cl = sys.solve(2.0, m).unwrap().cl;
        let pg = cl0 / (1.0 - m * m).sqrt();
        assert!(cl > prev, "Cl not increasing at M = {m}");
        assert!(
            cl >= pg * 0.999 && cl < pg * 1.10,
            "M = {m}: Cl {cl} vs PG {pg}"
        );
        prev = cl;
    }
}

/// Critical Mach of NACA 0012 at α = 0 is about 0.72–0.73 (Karman–Tsien; Abbott & von
/// Doenhoff Fig. 4.8 region); it drops with α, and the `supercritical` flag switches there.
#[test]
fn critical_mach_behaviour() {
    let sys = PanelSystem::new(&paneled("naca0012")).unwrap();
    let mcr0 = sys.critical_mach(0.0).unwrap();
    let mcr4 = sys.critical_mach(4.0).unwrap();
    println!("NACA 0012 critical Mach: {mcr0:.4} at 0 deg, {mcr4:.4} at 4 deg");
    assert!(mcr0 > 0.70 && mcr0 < 0.76, "Mcr(0) = {mcr0}");
    assert!(mcr4 < mcr0 - 0.1, "Mcr(4) = {mcr4}");
    assert!(!sys.solve(0.0, mcr0 - 0.01).unwrap().supercritical);
    assert!(sys.solve(0.0, mcr0 + 0.01).unwrap().supercritical);
    // At the critical Mach the minimum corrected Cp equals Cp*.
    let sol = sys.solve(0.0, mcr0).unwrap();
    let cps = KarmanTsien::new(mcr0).unwrap().cp_sonic();
    assert!((sol.cp_min - cps).abs() < 1e-4, "{} vs {cps}", sol.cp_min);
}

/// Mach outside [0, 1), non-finite α and a breakdown of the correction are errors.
#[test]
fn invalid_inputs_are_errors() {
    let sys = PanelSystem::new(&paneled("naca2412")).unwrap();
    assert_eq!(
        sys.solve(2.0, 1.0).unwrap_err(),
        InviscidError::InvalidMach(MachOutOfRange(1.0))
    );
    assert_eq!(
        sys.solve(2.0, 1.3).unwrap_err(),
        InviscidError::InvalidMach(MachOutOfRange(1.3))
    );
    assert_eq!(
        sys.solve(2.0, -0.1).unwrap_err(),
        InviscidError::InvalidMach(MachOutOfRange(-0.1))
    );
    assert!(matches!(
        sys.solve(2.0, f64::NAN),
        Err(InviscidError::InvalidMach(_))
    ));
    assert!(matches!(
        sys.solve(f64::INFINITY, 0.3),
        Err(InviscidError::InvalidAlpha(_))
    ));
    assert!(matches!(
        sys.solve(12.0, 0.99),
        Err(InviscidError::CompressibilityBreakdown { .. })
    ));
}
