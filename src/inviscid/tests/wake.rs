//! Wake geometry (XFOIL XYWAKE/SETEXP) against the wake nodes of XFOIL 6.99 dumps.

use super::support::{xfoil_dump_wake, xfoil_nodes};
use crate::inviscid::wake::geometric_spacing;
use crate::inviscid::wake::{Wake, WakeParams};
use crate::inviscid::PanelSystem;

/// The wake traced at α = 4° and 8° on XFOIL's NACA 0012 nodes reproduces XFOIL's wake node
/// positions to 1e-5 chord (measured 4.8e-6 and 5.4e-6: the dump is printed to 5 decimals, the
/// input nodes to 7 digits).
#[test]
fn naca0012_wake_matches_xfoil_dump() {
    let sys = PanelSystem::new(&xfoil_nodes("naca0012")).unwrap();
    for alpha in [4.0, 8.0] {
        let reference = xfoil_dump_wake(&format!("naca0012_Re1e6_M0_free_bl_a{alpha}.txt"));
        let wake = Wake::new(&sys, alpha).unwrap();
        assert_eq!(
            wake.len(),
            reference.len(),
            "XFOIL 6.99 uses N/12 + 10 = 23 nodes"
        );
        let mut err = 0.0_f64;
        for (i, (xr, yr)) in reference.iter().enumerate() {
            err = err.max((wake.x[i] - xr).abs()).max((wake.y[i] - yr).abs());
        }
        println!("alpha {alpha}: max wake node error {err:.2e}");
        assert!(err < 1.0e-5, "alpha {alpha}: wake node error {err}");
    }
}

/// The wake starts behind the TE, is one chord long, and its panels follow the local flow:
/// the inviscid tangential speed is negative (downstream, lower-surface sign) and tends to
/// −1 far behind the airfoil.
#[test]
fn wake_length_and_speeds() {
    let sys = PanelSystem::new(&xfoil_nodes("naca2412")).unwrap();
    let wake = Wake::new(&sys, 3.0).unwrap();
    let n = wake.len();
    let length: f64 = (1..n)
        .map(|i| (wake.x[i] - wake.x[i - 1]).hypot(wake.y[i] - wake.y[i - 1]))
        .sum();
    assert!((length - 1.0).abs() < 2.0e-3, "wake length {length}");
    assert!(wake.x[0] > 1.0 && wake.x[0] < 1.001);
    let q = wake.qinv(3.0);
    assert!(q.iter().all(|&v| v < 0.0));
    assert!((q[n - 1] + 1.0).abs() < 0.03, "far-wake speed {}", q[n - 1]);
    // Speed recovers monotonically towards freestream after the TE region.
    for i in 3..n {
        assert!(q[i] <= q[i - 1] + 1e-12, "wake speed not recovering at {i}");
    }
}

/// Geometric spacing: first step, total length and constant ratio as requested.
#[test]
fn geometric_spacing_properties() {
    let s = geometric_spacing(0.008, 1.0, 22).unwrap();
    assert!((s[1] - 0.008).abs() < 1e-15);
    assert!((s[21] - 1.0).abs() < 1e-9, "end {}", s[21]);
    let r = (s[2] - s[1]) / s[1];
    for i in 2..21 {
        let ri = (s[i + 1] - s[i]) / (s[i] - s[i - 1]);
        assert!((ri - r).abs() < 1e-12);
    }
    assert!(geometric_spacing(0.5, 0.2, 10).is_err());
    assert!(geometric_spacing(0.01, 1.0, 2).is_err());
}

/// Invalid wake parameters are reported, not panicking.
#[test]
fn invalid_wake_parameters() {
    let sys = PanelSystem::new(&xfoil_nodes("naca0012")).unwrap();
    let bad = WakeParams {
        length: -1.0,
        ..WakeParams::default()
    };
    assert!(Wake::with_params(&sys, 0.0, &bad).is_err());
    assert!(Wake::new(&sys, f64::NAN).is_err());
}
