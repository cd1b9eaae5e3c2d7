//! Flat plate at zero incidence with the edge speed fixed (no source influence): the coupled
//! Newton machinery (march, assembly, structured solve, update) must reproduce the Blasius
//! boundary layer, θ = 0.664·x/√Re_x, H = 2.59, Cf = 0.664/√Re_x.

use polargen::inviscid::{PanelGeometry, PanelParams, SourceInfluence};
use polargen::viscous::{PanelModel, ViscousParams, ViscousSolver};

/// Zero-thickness plate 0 ≤ x ≤ 1 with cosine-clustered nodes, XFOIL node order, and a wake
/// to x = 2; surface speed +1 on the upper side and −1 on the lower side and in the wake.
fn flat_plate(n_side: usize, n_wake: usize) -> PanelModel {
    let mut x = Vec::new();
    let mut y = Vec::new();
    for i in 0..n_side {
        let t = i as f64 / (n_side - 1) as f64;
        x.push(0.5 * (1.0 + (std::f64::consts::PI * t).cos()));
        y.push(1e-9 * (1.0 - t));
    }
    for i in 1..n_side {
        let t = i as f64 / (n_side - 1) as f64;
        x.push(0.5 * (1.0 - (std::f64::consts::PI * t).cos()));
        y.push(-1e-9 * t);
    }
    let airfoil = PanelGeometry::new(&x, &y, &PanelParams::default()).unwrap();
    let wake_x: Vec<f64> = (0..n_wake)
        .map(|i| {
            let t = i as f64 / (n_wake - 1) as f64;
            1.0 + t * t
        })
        .collect();
    let nn = x.len() + n_wake;
    let le = n_side - 1;
    let q0: Vec<f64> = (0..nn)
        .map(|i| {
            if i < le {
                1.0
            } else if i == le {
                1e-3
            } else {
                -1.0
            }
        })
        .collect();
    PanelModel {
        airfoil,
        wake_x,
        wake_y: vec![0.0; n_wake],
        q_unit: [q0, vec![0.0; nn]],
        dij: SourceInfluence::zeros(x.len(), n_wake),
    }
}

#[test]
fn blasius_flat_plate() {
    let re = 1.0e6;
    let params = ViscousParams {
        reynolds: re,
        ..ViscousParams::default()
    };
    let mut solver = ViscousSolver::from_panel_model(flat_plate(81, 30), params).unwrap();
    let sol = solver.solve(0.0);
    assert!(sol.point.converged, "not converged: {:?}", sol.point);
    // Tolerances: XFOIL's laminar closures fit Falkner–Skan profiles to ~1 % (H = 2.568 instead of
    // 2.591 for Blasius), and the log-difference discretisation adds < 0.5 % on this grid.
    let mut checked = 0;
    for st in sol
        .upper
        .iter()
        .chain(&sol.lower)
        .filter(|st| st.x > 0.2 && st.x < 0.95)
    {
        let rex = re * st.x;
        let theta = 0.664 * st.x / rex.sqrt();
        let cf = 0.664 / rex.sqrt();
        assert!(
            (st.theta / theta - 1.0).abs() < 0.01,
            "θ at x={}: {} vs {}",
            st.x,
            st.theta,
            theta
        );
        assert!(
            (st.cf / cf - 1.0).abs() < 0.015,
            "Cf at x={}: {} vs {}",
            st.x,
            st.cf,
            cf
        );
        assert!(
            (st.h / 2.591 - 1.0).abs() < 0.015,
            "H at x={}: {}",
            st.x,
            st.h
        );
        assert!(
            !st.turbulent,
            "flat plate at Re 1e6 must stay laminar (x={})",
            st.x
        );
        checked += 1;
    }
    assert!(checked > 50);
    // Both sides laminar: Cd = 2·1.328/√Re (Squire–Young of the wake, friction only).
    let cd = 2.0 * 1.328 / re.sqrt();
    assert!(
        (sol.point.cd / cd - 1.0).abs() < 0.01,
        "cd {} vs {}",
        sol.point.cd,
        cd
    );
    assert!(
        (sol.point.cdf / cd - 1.0).abs() < 0.04,
        "cdf {} vs {}",
        sol.point.cdf,
        cd
    );
    assert_eq!(sol.point.xtr_top, 1.0);
    assert!(sol.point.cl.abs() < 1e-9);
}

/// A model whose influence matrix splits its rows elsewhere than after the airfoil nodes is
/// refused (the rows would be read at the wrong columns).
#[test]
fn a_misshapen_influence_matrix_is_refused() {
    let good = flat_plate(81, 30);
    let nt = good.n_nodes();
    let bad = PanelModel {
        dij: SourceInfluence::zeros(nt, 0),
        ..good
    };
    assert!(ViscousSolver::from_panel_model(bad, ViscousParams::default()).is_err());
}
