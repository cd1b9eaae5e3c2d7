//! Input validation of the viscous solver: bad airfoils, parameters and angles give errors or
//! unconverged points, never panics.

use polargen::geometry::Airfoil;
use polargen::viscous::{ViscousError, ViscousParams, ViscousSolver};

#[test]
fn invalid_inputs_are_errors_not_panics() {
    let foil = Airfoil {
        name: "bad".into(),
        x: vec![1.0, 0.0, 1.0],
        y: vec![0.0, 0.0],
    };
    assert!(matches!(
        ViscousSolver::new(&foil, ViscousParams::default()),
        Err(ViscousError::BadAirfoil { .. })
    ));
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/xfoil/naca0012_paneled.dat"
    ))
    .unwrap();
    let (mut x, mut y) = (Vec::new(), Vec::new());
    for line in text.lines() {
        let v: Vec<f64> = line
            .split_whitespace()
            .filter_map(|t| t.parse().ok())
            .collect();
        if v.len() == 2 {
            x.push(v[0]);
            y.push(v[1]);
        }
    }
    let foil = Airfoil {
        name: "0012".into(),
        x,
        y,
    };
    for params in [
        ViscousParams {
            reynolds: -1.0,
            ..ViscousParams::default()
        },
        ViscousParams {
            mach: 1.2,
            ..ViscousParams::default()
        },
        ViscousParams {
            ncrit_top: f64::NAN,
            ..ViscousParams::default()
        },
        ViscousParams {
            ncrit_bot: 0.0,
            ..ViscousParams::default()
        },
    ] {
        assert!(matches!(
            ViscousSolver::new(&foil, params),
            Err(ViscousError::BadParameter { .. })
        ));
    }
    let mut solver = ViscousSolver::new(&foil, ViscousParams::default()).unwrap();
    let bad = solver.solve(f64::NAN);
    assert!(!bad.point.converged);
    // Far beyond stall: must return (converged or not) within the iteration cap, no panic.
    let params = ViscousParams {
        max_iterations: 30,
        ..ViscousParams::default()
    };
    let mut solver = ViscousSolver::new(&foil, params).unwrap();
    let p = solver.solve(25.0).point;
    assert!(p.iterations <= 30);
    // A good point after a failure still converges (state was reset).
    let p = solver.solve(2.0).point;
    assert!(p.converged, "{p:?}");
    assert!((p.cl - 0.2142).abs() < 0.002, "{p:?}");
}

/// Parallel sweeps move one solver per thread: it must be `Send`.
#[test]
fn solver_is_send() {
    fn assert_send<T: Send>() {}
    assert_send::<ViscousSolver>();
}

/// A fresh start depends on α alone: after it failed at some α it is not run again there, and
/// a failed solve is never retried inside `solve`.
#[test]
fn failed_fresh_start_is_not_repeated() {
    let foil = polargen::geometry::airfoil_by_name_or_path("naca0012")
        .and_then(|a| a.repanel(160, &polargen::geometry::PanelingParams::default()))
        .unwrap();
    // One Newton iteration cannot converge a fresh march.
    let params = ViscousParams {
        max_iterations: 1,
        ..ViscousParams::default()
    };
    let mut solver = ViscousSolver::new(&foil, params).unwrap();
    let first = solver.solve(4.0).point;
    assert!(!first.converged);
    assert_eq!(first.iterations, 1);
    solver.reset();
    let again = solver.solve(4.0).point;
    assert!(!again.converged);
    assert_eq!(again.iterations, 0, "the failed fresh start was run again");
    // Another α is tried normally.
    solver.reset();
    assert_eq!(solver.solve(3.0).point.iterations, 1);
}
