//! Solvers of several flow conditions sharing one airfoil's per-α inviscid models
//! (`SharedPanels`): each model is built once per α, and every result is bit-identical to a
//! solver with its own panel store.

use std::sync::Arc;

use polargen::geometry::Airfoil;
use polargen::viscous::{SharedPanels, ViscousParams, ViscousSolver};

/// XFOIL's 160-panel NACA 23012 nodes.
fn paneled() -> Airfoil {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/xfoil/naca23012_paneled.dat"
    );
    polargen::geometry::read_airfoil_file(std::path::Path::new(path)).unwrap()
}

/// (cl, cd, cm, iterations, converged) of a warm-started sweep.
fn sweep(solver: &mut ViscousSolver, alphas: &[f64]) -> Vec<(f64, f64, f64, u32, bool)> {
    alphas
        .iter()
        .map(|&a| {
            let p = solver.solve(a).point;
            (p.cl, p.cd, p.cm, p.iterations, p.converged)
        })
        .collect()
}

#[test]
fn shared_models_give_identical_results_and_are_built_once_per_alpha() {
    let foil = paneled();
    let alphas = [0.0, 1.0, 2.0, 1.0, 3.0];
    let conditions = [
        ViscousParams::at(1.9e6, 0.41, 1.0),
        ViscousParams::at(5e5, 0.0, 0.07),
    ];
    let shared = Arc::new(SharedPanels::new(&foil).unwrap());
    for params in conditions {
        let mut own = ViscousSolver::new(&foil, params).unwrap();
        let mut on_shared = ViscousSolver::with_panels(Arc::clone(&shared), params).unwrap();
        let a = sweep(&mut own, &alphas);
        let b = sweep(&mut on_shared, &alphas);
        assert!(a.iter().all(|p| p.4), "all points converge: {a:?}");
        // Bit-identical: the shared model is the same function of (geometry, α).
        assert_eq!(a, b);
    }
    // α = 0, 1, 2, 3: one model each for both conditions.
    assert_eq!(shared.len(), 4);
    let m1 = shared.model(1.0).unwrap();
    let m2 = shared.model(1.0).unwrap();
    assert!(Arc::ptr_eq(&m1, &m2));
    assert_eq!(shared.len(), 4);
}

#[test]
fn threads_sharing_a_store_agree_with_one_thread() {
    let foil = paneled();
    let alphas = [0.0, 0.5, 1.0, 1.5];
    let params = [
        ViscousParams::at(1e6, 0.2, 1.0),
        ViscousParams::at(2e6, 0.4, 1.0),
    ];
    let sequential: Vec<_> = params
        .iter()
        .map(|&p| sweep(&mut ViscousSolver::new(&foil, p).unwrap(), &alphas))
        .collect();
    let shared = Arc::new(SharedPanels::new(&foil).unwrap());
    let parallel: Vec<_> = std::thread::scope(|s| {
        let handles: Vec<_> = params
            .iter()
            .map(|&p| {
                let store = Arc::clone(&shared);
                s.spawn(move || sweep(&mut ViscousSolver::with_panels(store, p).unwrap(), &alphas))
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert_eq!(sequential, parallel);
    assert_eq!(shared.len(), alphas.len());
}
