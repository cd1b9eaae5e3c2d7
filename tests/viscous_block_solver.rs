//! The structured Newton solve (block forward substitution + mass Schur complement) must agree
//! with a dense LU of the same system expanded to 3n×3n.

use faer::prelude::*;
use faer::Mat;
use polargen::viscous::block_solver::{invert3, BlockSystem};

/// Small deterministic generator (64-bit LCG) so the test needs no extra crate.
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
    fn block(&mut self, diag: f64) -> [[f64; 3]; 3] {
        let mut b = [[0.0; 3]; 3];
        for (r, row) in b.iter_mut().enumerate() {
            for (c, v) in row.iter_mut().enumerate() {
                *v = self.next() + if r == c { diag } else { 0.0 };
            }
        }
        b
    }
}

/// A random mass influence matrix G (n × n row-major) with entries of size 0.3/n.
fn random_influence(n: usize, seed: u64) -> Vec<f64> {
    let mut g = Lcg(seed ^ 0x9e37_79b9);
    (0..n * n).map(|_| 0.3 * g.next() / n as f64).collect()
}

/// Builds a system with XFOIL's topology: upper chain 0..nu, lower chain nu..nu+nl, wake chain
/// whose first station depends on both trailing-edge stations, and a dense mass coupling whose
/// rows combine the rows of G of the station and its upstream station(s), as the assembly does.
fn random_system(nu: usize, nl: usize, nw: usize, seed: u64, influence: &[f64]) -> BlockSystem<'_> {
    let n = nu + nl + nw;
    let mut g = Lcg(seed);
    let mut sys = BlockSystem::zeros(n, influence);
    for k in 0..n {
        sys.diag[k] = g.block(4.0);
        let first_lower = k == nu;
        if k != 0 && !first_lower {
            sys.upstream[k] = Some((k - 1, g.block(0.0)));
        }
        if k == nu + nl {
            sys.upstream2[k] = Some((nu - 1, g.block(0.0)));
        }
        let mut coupled = vec![k];
        coupled.extend(sys.upstream[k].map(|(p, _)| p));
        coupled.extend(sys.upstream2[k].map(|(q, _)| q));
        for r in 0..3 {
            for &j in &coupled {
                sys.mass_terms[3 * k + r].add(j, g.next());
            }
        }
        sys.rhs[k] = [g.next(), g.next(), g.next()];
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

/// A·A⁻¹ is the identity to `tol`.
fn assert_inverse(a: &[[f64; 3]; 3], ai: &[[f64; 3]; 3], tol: f64) {
    for (r, row) in a.iter().enumerate() {
        for c in 0..3 {
            let s: f64 = row.iter().zip(ai).map(|(x, ai_row)| x * ai_row[c]).sum();
            let e = if r == c { 1.0 } else { 0.0 };
            assert!((s - e).abs() < tol, "A·A⁻¹[{r}][{c}] = {s}");
        }
    }
}

#[test]
fn invert3_inverts_and_rejects_singular() {
    let a = [[2.0, 1.0, 0.5], [0.3, 3.0, -1.0], [1.0, -0.5, 4.0]];
    assert_inverse(&a, &invert3(&a).expect("regular"), 1e-14);
    let singular = [[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 1.0, 1.0]];
    assert!(invert3(&singular).is_none());
}

/// A regular block whose columns differ by orders of magnitude is inverted, not rejected as
/// singular: the similarity station of the 8-H-12 at Re 2e6, M 0.2, α −3° with the stagnation
/// point 2e-7 from a node (columns of 1, 3e5 and 5e9). Rejecting it failed that point in every
/// retry, where XFOIL converges (Cl −0.2407). A nearly singular block with the same scales is
/// still rejected.
#[test]
fn invert3_accepts_badly_scaled_regular_blocks() {
    let a = [
        [1.0, 0.0, 0.0],
        [0.0, -697_036.283_242_453_6, 7_214_639_720.909_253],
        [0.0, 926_018.947_203_428_3, -5_341_905_754.138_013],
    ];
    assert_inverse(&a, &invert3(&a).expect("regular, only badly scaled"), 1e-12);
    // Column 2 made parallel to column 1 up to 1e-17 relative: singular to round-off.
    let mut nearly = a;
    let f = a[1][2] / a[1][1];
    nearly[2][2] = a[2][1] * f * (1.0 + 1e-17);
    assert!(invert3(&nearly).is_none());
}
