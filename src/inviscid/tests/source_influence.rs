//! Source influence matrix D (XFOIL QDCALC) against re-solving the panel system with the
//! perturbed sources, and a physical sign check of the displacement effect.

use super::support::xfoil_nodes;
use crate::inviscid::source_influence::direct::speeds_with_sources;
use crate::inviscid::source_influence::SourceInfluence;
use crate::inviscid::wake::Wake;
use crate::inviscid::PanelSystem;
use crate::numerics::test_random::Lcg;

/// Deterministic pseudo-random numbers in [−1, 1) (64-bit LCG, Knuth MMIX constants).
fn pseudo_random(n: usize, seed: u64) -> Vec<f64> {
    let mut random = Lcg::new(seed);
    (0..n).map(|_| random.symmetric()).collect()
}

/// Inviscid speeds at airfoil + wake nodes.
fn q_inviscid(sys: &PanelSystem, wake: &Wake, alpha: f64) -> Vec<f64> {
    let mut q = sys.gamma(alpha);
    q.extend(wake.qinv(alpha));
    q
}

/// Column j of D equals the central difference of the re-solved speeds when source j is
/// perturbed (relative error ≤ 1e-7), for airfoil and wake sources.
fn check_columns(name: &str, alpha: f64) {
    let sys = PanelSystem::new(&xfoil_nodes(name)).unwrap();
    let wake = Wake::new(&sys, alpha).unwrap();
    let dij = SourceInfluence::new(&sys, &wake);
    let d = dij.d();
    let (n, nw) = (sys.n_nodes(), wake.len());
    let nt = n + nw;
    let base = pseudo_random(nt, 7)
        .into_iter()
        .map(|v| 1.0e-3 * v)
        .collect::<Vec<_>>();
    let h = 1.0e-4;
    let mut worst = 0.0_f64;
    for j in [
        0,
        1,
        40,
        n / 2,
        120,
        n - 2,
        n - 1,
        n,
        n + 1,
        n + nw / 2,
        nt - 1,
    ] {
        let mut plus = base.clone();
        let mut minus = base.clone();
        plus[j] += h;
        minus[j] -= h;
        let qp = speeds_with_sources(&sys, &wake, alpha, &plus);
        let qm = speeds_with_sources(&sys, &wake, alpha, &minus);
        let scale = (0..nt).map(|i| d[(i, j)].abs()).fold(0.0, f64::max);
        assert!(scale > 0.0, "{name}: column {j} of D is zero");
        for i in 0..nt {
            let fd = (qp[i] - qm[i]) / (2.0 * h);
            let err = (fd - d[(i, j)]).abs() / scale;
            worst = worst.max(err);
            assert!(
                err < 1.0e-7,
                "{name}: D[{i},{j}] = {} but finite difference gives {fd}",
                d[(i, j)]
            );
        }
    }
    println!("{name}: worst relative column error {worst:.2e}");
}

#[test]
fn d_matches_finite_differences_blunt_te() {
    check_columns("naca0012", 4.0);
}

#[test]
fn d_matches_finite_differences_sharp_te() {
    check_columns("naca8h12", 6.0);
}

/// For arbitrary sources, q_inv + D·σ equals the re-solved speeds to round-off.
#[test]
fn linearisation_is_exact() {
    let sys = PanelSystem::new(&xfoil_nodes("naca2412")).unwrap();
    let wake = Wake::new(&sys, 2.0).unwrap();
    let dij = SourceInfluence::new(&sys, &wake);
    let sigma: Vec<f64> = pseudo_random(dij.d().nrows(), 11)
        .into_iter()
        .map(|v| 5.0e-3 * v)
        .collect();
    let q = speeds_with_sources(&sys, &wake, 2.0, &sigma);
    let dq = dij.apply(&sigma);
    let q0 = q_inviscid(&sys, &wake, 2.0);
    for i in 0..q.len() {
        assert!(
            (q0[i] + dq[i] - q[i]).abs() < 1.0e-10,
            "node {i}: {} vs {}",
            q0[i] + dq[i],
            q[i]
        );
    }
}

/// A boundary layer thickening downstream (m = Ue·δ* growing with x on both surfaces and
/// carried into the wake) displaces the flow outward, so the edge speed rises over the
/// rear half of the chord on both surfaces; XFOIL's σ = −VTI·m convention is used (σ = −m
/// upper, +m lower and wake). At α = 0 on the symmetric NACA 0012 the rise is the same on
/// both surfaces.
#[test]
fn displacement_accelerates_the_flow() {
    let alpha = 0.0;
    let sys = PanelSystem::new(&xfoil_nodes("naca0012")).unwrap();
    let wake = Wake::new(&sys, alpha).unwrap();
    let dij = SourceInfluence::new(&sys, &wake);
    let g = sys.geometry();
    let gamma = sys.gamma(alpha);
    let n = g.x.len();
    let ist = (0..n - 1)
        .find(|&i| gamma[i] >= 0.0 && gamma[i + 1] < 0.0)
        .unwrap();
    let mut sigma = vec![0.0; dij.d().nrows()];
    for i in 0..n {
        let dstar = 0.004 * g.x[i].max(0.0).powf(0.8);
        let m = gamma[i].abs() * dstar;
        sigma[i] = if i <= ist { -m } else { m };
    }
    let m_te = 0.5 * (sigma[n - 1] - sigma[0]);
    for s in sigma.iter_mut().skip(n) {
        *s = m_te;
    }
    let dq = dij.apply(&sigma);
    for i in 0..n {
        if (0.3..0.8).contains(&g.x[i]) {
            let vti = if i <= ist { 1.0 } else { -1.0 };
            let due = vti * dq[i];
            assert!(due > 0.0, "node {i} (x = {}): dUe = {due}", g.x[i]);
            let mirror = -dq[n - 1 - i] * vti;
            assert!(
                (due - mirror).abs() < 1e-6 * due.abs().max(1e-3),
                "asymmetric at {i}"
            );
        }
    }
}
