//! The structured Newton solve (block forward substitution + mass Schur complement) must agree
//! with a dense LU of the same system expanded to 3n×3n.

use faer::prelude::*;
use faer::Mat;

use super::*;
use crate::numerics::test_random::Lcg;

/// A random 3×3 block with `diag` added on the diagonal.
fn random_block(g: &mut Lcg, diag: f64) -> [[f64; 3]; 3] {
    let mut b = [[0.0; 3]; 3];
    for (r, row) in b.iter_mut().enumerate() {
        for (c, v) in row.iter_mut().enumerate() {
            *v = g.symmetric() + if r == c { diag } else { 0.0 };
        }
    }
    b
}

/// A random mass influence matrix G (n × n row-major) with entries of size 0.3/n.
fn random_influence(n: usize, seed: u64) -> Vec<f64> {
    let mut g = Lcg::new(seed ^ 0x9e37_79b9);
    (0..n * n).map(|_| 0.3 * g.symmetric() / n as f64).collect()
}

/// Builds a system with XFOIL's topology: upper chain 0..nu, lower chain nu..nu+nl, wake chain
/// whose first station depends on both trailing-edge stations, and a dense mass coupling whose
/// rows combine the rows of G of the station and its upstream station(s), as the assembly does.
fn random_system(nu: usize, nl: usize, nw: usize, seed: u64, influence: &[f64]) -> BlockSystem<'_> {
    let n = nu + nl + nw;
    let mut g = Lcg::new(seed);
    let mut sys = BlockSystem::zeros(n, influence);
    for k in 0..n {
        sys.diag[k] = random_block(&mut g, 4.0);
        let first_lower = k == nu;
        if k != 0 && !first_lower {
            sys.upstream[k] = Some((k - 1, random_block(&mut g, 0.0)));
        }
        if k == nu + nl {
            sys.upstream2[k] = Some((nu - 1, random_block(&mut g, 0.0)));
        }
        let mut coupled = vec![k];
        coupled.extend(sys.upstream[k].map(|(p, _)| p));
        coupled.extend(sys.upstream2[k].map(|(q, _)| q));
        for r in 0..3 {
            for &j in &coupled {
                sys.mass_terms[3 * k + r].add(j, g.symmetric());
            }
        }
        sys.rhs[k] = [g.symmetric(), g.symmetric(), g.symmetric()];
    }
    sys
}

#[test]
fn structured_solve_matches_dense_lu() {
    for (nu, nl, nw, seed) in [(5, 6, 3, 1), (40, 45, 20, 7), (80, 85, 30, 42)] {
        let n = nu + nl + nw;
        let influence = random_influence(n, seed);
        let sys = random_system(nu, nl, nw, seed, &influence);
        let w = sys.solve().expect("solvable");
        let a = sys.to_dense();
        let mut b = Mat::<f64>::from_fn(3 * n, 1, |i, _| sys.rhs[i / 3][i % 3]);
        a.partial_piv_lu().solve_in_place(b.as_mut());
        let mut max_err: f64 = 0.0;
        let mut max_val: f64 = 0.0;
        for k in 0..n {
            for r in 0..3 {
                max_err = max_err.max((w[k][r] - b[(3 * k + r, 0)]).abs());
                max_val = max_val.max(b[(3 * k + r, 0)].abs());
            }
        }
        // Both are direct solves of a well-conditioned system: agreement to round-off.
        assert!(
            max_err <= 1e-10 * max_val.max(1.0),
            "n={n}: max error {max_err:e} (max |x| {max_val:e})"
        );
    }
}

/// The factored system solves a further right-hand side like a dense LU, and the edge-speed
/// terms are the mass-term coefficients applied to an edge-speed change.
#[test]
fn factored_system_solves_further_right_hand_sides() {
    let (nu, nl, nw, seed) = (30, 35, 12, 3);
    let n = nu + nl + nw;
    let influence = random_influence(n, seed);
    let sys = random_system(nu, nl, nw, seed, &influence);
    let a = sys.to_dense();
    let mut schur = Vec::new();
    let (factored, _) = sys.clone().factor_and_solve(&mut schur).expect("solvable");
    let mut g = Lcg::new(99);
    let due: Vec<f64> = (0..n).map(|_| g.symmetric()).collect();
    let terms = factored.edge_speed_terms(&due);
    for (k, row) in terms.iter().enumerate() {
        for (r, &t) in row.iter().enumerate() {
            let direct: f64 = sys.mass_terms[3 * k + r]
                .terms()
                .map(|(j, c)| c * due[j])
                .sum();
            assert_eq!(t, direct);
        }
    }
    let w = factored.solve(&terms).expect("solvable");
    let mut b = Mat::<f64>::from_fn(3 * n, 1, |i, _| terms[i / 3][i % 3]);
    a.partial_piv_lu().solve_in_place(b.as_mut());
    let max_val = (0..3 * n).map(|i| b[(i, 0)].abs()).fold(1.0, f64::max);
    for k in 0..n {
        for r in 0..3 {
            let err = (w[k][r] - b[(3 * k + r, 0)]).abs();
            assert!(
                err <= 1e-10 * max_val,
                "station {k}, row {r}: error {err:e}"
            );
        }
    }
}

#[test]
fn mass_terms_merge_rows_and_expand_to_v() {
    let influence = [1.0, 2.0, 3.0, 4.0];
    let mut sys = BlockSystem::zeros(2, &influence);
    sys.mass_terms[4].add(0, 2.0);
    sys.mass_terms[4].add(1, -1.0);
    sys.mass_terms[4].add(0, 0.5);
    assert_eq!(
        sys.mass_terms[4].terms().collect::<Vec<_>>(),
        vec![(0, 2.5), (1, -1.0)]
    );
    // Row 4 of V (station 1, equation 1) = 2.5·G[0] − G[1] = (2.5 − 3, 5 − 4); it sits in the
    // mass columns (unknown 2 of each station) of the expanded matrix.
    let a = sys.to_dense();
    assert_eq!(a[(4, 2)], -0.5);
    assert_eq!(a[(4, 5)], 1.0);
    assert_eq!(a[(3, 2)], 0.0);
}

/// The vector-extension build of the forward substitution gives bit-identical results to
/// the baseline build (same operations, no fused multiply-add).
#[test]
fn dispatched_forward_substitution_is_bit_identical() {
    let n = 37;
    let mut random = Lcg::new(12345);
    let mut next = move || random.unit() - 0.5;
    let g: Vec<f64> = (0..n * n).map(|_| next() / n as f64).collect();
    let mut sys = BlockSystem::zeros(n, &g);
    for k in 0..n {
        sys.diag[k] = [
            [2.0 + next(), next(), next()],
            [next(), 2.0 + next(), next()],
            [next(), next(), 2.0 + next()],
        ];
        if k > 0 {
            sys.upstream[k] = Some((k - 1, [[next(); 3]; 3]));
            for r in 0..3 {
                sys.mass_terms[3 * k + r].add(k - 1, next());
            }
        }
        if k > 2 {
            sys.upstream2[k] = Some((k / 2, [[next(), next(), next()]; 3]));
        }
        for r in 0..3 {
            sys.mass_terms[3 * k + r].add(k, next());
        }
        sys.rhs[k] = [next(), next(), next()];
    }
    let inv: Vec<Block3> = sys.diag.iter().map(|a| invert3(a).unwrap()).collect();
    let (mut big1, mut big2) = (Vec::new(), vec![f64::NAN; n * n]);
    let y1 = sys.forward_substitute(&inv, &mut big1);
    let y2 = sys.forward_substitute_kernel(&inv, &mut big2);
    assert_eq!(y1, y2);
    assert!(big1
        .iter()
        .zip(&big2)
        .all(|(a, b)| a.to_bits() == b.to_bits()));
    assert_eq!(big1.len(), n * n);
}
