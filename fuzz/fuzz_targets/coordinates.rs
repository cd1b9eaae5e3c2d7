//! Any bytes given as a coordinate file: the reader and validation never panic, and a contour
//! they accept gives, as `polargen --inviscid` does, a finite inviscid solution with
//! |Cl| ≤ 5 at 4° (or a clean error).
#![no_main]

use libfuzzer_sys::fuzz_target;
use polargen::geometry::{parse_airfoil_bytes, PanelingParams};
use polargen::inviscid::PanelSystem;

fuzz_target!(|data: &[u8]| {
    let Ok((foil, _)) = parse_airfoil_bytes(data, "fuzz.dat", "fuzz") else {
        return;
    };
    let Ok((foil, _)) = foil.in_chord_units() else {
        return;
    };
    let Ok(foil) = foil.repanel(160, &PanelingParams::default()) else {
        return;
    };
    let Ok(system) = PanelSystem::new(&foil) else {
        return;
    };
    if let Ok(sol) = system.solve(4.0, 0.0) {
        assert!(sol.cl.is_finite() && sol.cl.abs() <= 5.0, "Cl {}", sol.cl);
        assert!(sol.cm.is_finite(), "Cm {}", sol.cm);
    }
});
