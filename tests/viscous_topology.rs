//! Station topology (XFOIL STFIND/IBLPAN/XICALC), force helpers and input validation.

use polargen::geometry::Airfoil;
use polargen::viscous::forces::{karman_tsien_cp, transition_x};
use polargen::viscous::stations::{find_stagnation, PanelGeometry, StationLayout, Surface};
use polargen::viscous::{ViscousError, ViscousParams, ViscousSolver};

#[test]
fn stagnation_point_is_interpolated_sign_change() {
    let q = [1.0, 0.5, -0.5, -1.0];
    let s = [0.0, 1.0, 2.0, 3.0];
    let st = find_stagnation(&q, &s).unwrap();
    assert_eq!(st.ist, 1);
    assert!((st.sst - 1.5).abs() < 1e-12);
    // Asymmetric: zero crossing at 1/4 of the interval.
    let st = find_stagnation(&[1.0, 0.25, -0.75], &[0.0, 1.0, 3.0]).unwrap();
    assert!((st.sst - 1.5).abs() < 1e-12, "{}", st.sst);
    assert_eq!(
        find_stagnation(&[1.0, 1.0, 1.0], &[0.0, 1.0, 2.0]),
        Err(ViscousError::NoStagnationPoint)
    );
}

/// Diamond-like closed contour of 9 nodes with a 3-node wake.
fn geometry() -> PanelGeometry {
    let x = vec![1.0, 0.7, 0.4, 0.1, 0.0, 0.1, 0.4, 0.7, 1.0, 1.0, 1.3, 1.8];
    let y = vec![
        0.0, 0.03, 0.05, 0.03, 0.0, -0.03, -0.05, -0.03, 0.0, 0.0, 0.0, 0.0,
    ];
    let mut s = vec![0.0];
    for i in 1..9 {
        let d: f64 = (x[i] - x[i - 1]) * (x[i] - x[i - 1]) + (y[i] - y[i - 1]) * (y[i] - y[i - 1]);
        s.push(s[i - 1] + d.sqrt());
    }
    PanelGeometry {
        x,
        y,
        s,
        n_airfoil: 9,
    }
}

#[test]
fn layout_orders_stations_and_xi() {
    let g = geometry();
    // Stagnation between nodes 4 and 5 (slightly on the lower side).
    let q = [1.0, 1.1, 1.2, 0.8, 0.2, -0.6, -1.1, -1.0, -0.9];
    let layout = StationLayout::new(&g, &q).unwrap();
    assert_eq!(layout.n_upper, 5);
    assert_eq!(layout.n_lower, 4);
    assert_eq!(layout.n_wake, 3);
    let upper: Vec<usize> = layout
        .range(Surface::Upper)
        .map(|k| layout.stations[k].node)
        .collect();
    assert_eq!(upper, vec![4, 3, 2, 1, 0]);
    let lower: Vec<usize> = layout
        .range(Surface::Lower)
        .map(|k| layout.stations[k].node)
        .collect();
    assert_eq!(lower, vec![5, 6, 7, 8]);
    for surface in [Surface::Upper, Surface::Lower, Surface::Wake] {
        let xi: Vec<f64> = layout
            .range(surface)
            .map(|k| layout.stations[k].xi)
            .collect();
        assert!(xi.windows(2).all(|w| w[1] >= w[0]), "{surface:?}: {xi:?}");
        assert!(xi[0] >= 0.0);
    }
    // Wake ξ starts at the lower TE ξ and then adds the wake arc length.
    let w0 = layout.wake_start();
    assert_eq!(
        layout.stations[w0].xi,
        layout.stations[layout.lower_te()].xi
    );
    assert!((layout.stations[w0 + 2].xi - layout.stations[w0].xi - 0.8).abs() < 1e-12);
    // Sharp TE: no wake gap.
    assert!(layout.stations[w0..].iter().all(|s| s.wake_gap == 0.0));
    // Edge speed sign convention Ue = vti·q.
    let ue = layout.edge_speed(&[q.as_slice(), &[-1.0, -1.0, -1.0]].concat());
    assert!(ue.iter().all(|u| *u > 0.0));
    // Moving the stagnation point one node down: node 5 changes surface and maps to the first
    // old upper station; every other station maps to the same node.
    let q2 = [1.0, 1.1, 1.2, 0.8, 0.4, 0.1, -1.1, -1.0, -0.9];
    let layout2 = StationLayout::new(&g, &q2).unwrap();
    let map = layout2.map_from(&layout);
    for (k, &o) in map.iter().enumerate() {
        let (new, old) = (layout2.stations[k], layout.stations[o]);
        if new.node == 5 {
            assert_eq!(o, 0);
        } else {
            assert_eq!(new.node, old.node);
        }
    }
}

#[test]
fn karman_tsien_and_transition_location() {
    assert_eq!(karman_tsien_cp(-0.5, 0.0), -0.5);
    // M = 0.5: Cp = Cp0/(β + M²/(2(1+β))·Cp0), β = √0.75 (XFOIL CPCALC).
    let beta = 0.75_f64.sqrt();
    let expect = -0.5 / (beta + 0.125 / (1.0 + beta) * -0.5);
    assert!((karman_tsien_cp(-0.5, 0.5) - expect).abs() < 1e-14);
    let xi = [0.0, 0.1, 0.3];
    let x = [0.0, 0.08, 0.3];
    assert!((transition_x(&xi, &x, Some(0.2)) - 0.19).abs() < 1e-12);
    assert_eq!(transition_x(&xi, &x, None), 0.3);
}

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
        "/tests/data/viscous/naca0012_xfoil_paneled.dat"
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
            ncrit: f64::NAN,
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
/// with `fresh_retry` off a failed warm start is not retried inside `solve`.
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
