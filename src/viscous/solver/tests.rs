//! The tangent predictor against the converged solution: moving a converged state along its
//! tangent must land much closer to the next point's converged state than the state itself
//! is (the error of an Euler step is second order in Δα; the wake's re-tracing, which the
//! tangent neglects, adds a small first-order part).

use super::*;
use crate::geometry::read_airfoil_file;

fn solver(xtr: f64) -> ViscousSolver {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/xfoil/naca0012_paneled.dat"
    );
    let foil = read_airfoil_file(std::path::Path::new(path)).unwrap();
    ViscousSolver::new(&foil, ViscousParams::at(3e6, 0.3, xtr)).unwrap()
}

/// RMS of the relative differences of θ, m and Ue between state `a` on layout `la` and state
/// `b` on layout `lb`, over the stations of `lb` whose node has a station of `la` on the same
/// surface (all but the nodes the stagnation point crossed).
fn rms_difference(la: &StationLayout, a: &BlState, lb: &StationLayout, b: &BlState) -> f64 {
    let map = lb.map_from(la);
    let (mut sum, mut count) = (0.0, 0);
    for (k, &o) in map.iter().enumerate() {
        if la.stations[o].node != lb.stations[k].node {
            continue;
        }
        for (x, y) in [
            (a.theta[o], b.theta[k]),
            (a.mass[o], b.mass[k]),
            (a.ue[o], b.ue[k]),
        ] {
            sum += ((x - y) / y).powi(2);
            count += 1;
        }
    }
    (sum / count as f64).sqrt()
}

#[test]
fn tangent_predicts_the_next_converged_state() {
    // (trip, α, Δα, largest ratio of the predicted to the unpredicted distance). Measured
    // ratios: 0.04 and 0.03 with transition tripped, 0.33 and 0.45 free, where the stations
    // around the moving transition point change regime, which no tangent predicts.
    for (xtr, alpha0, step, ratio) in [
        (0.07, 2.0, 0.5, 0.1),
        (0.07, -3.0, -0.5, 0.1),
        (1.0, 1.0, 0.25, 0.6),
        (1.0, 6.0, 0.5, 0.6),
    ] {
        let mut s = solver(xtr);
        assert!(s.solve(alpha0).point.converged);
        let converged = s.warm.clone().unwrap();
        let tangent = converged
            .tangent
            .as_ref()
            .expect("tangent of a converged point");
        let alpha1 = alpha0 + step;
        let mut predicted = converged.state.clone();
        let limits = UpdateLimits::default();
        let bl = s.closures();
        tangent
            .predict(bl, &converged.layout, &mut predicted, alpha1, &limits)
            .unwrap();
        assert!(s.solve(alpha1).point.converged);
        let next = s.warm.clone().unwrap();
        let (la, lb) = (&converged.layout, &next.layout);
        let before = rms_difference(la, &converged.state, lb, &next.state);
        let after = rms_difference(la, &predicted, lb, &next.state);
        println!("xtr {xtr}, α {alpha0} → {alpha1}: {before:.3e} → {after:.3e}");
        assert!(after < ratio * before, "{after:e} vs {before:e}");
    }
}
