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

/// Builds a system with XFOIL's topology: upper chain 0..nu, lower chain nu..nu+nl, wake chain
/// whose first station depends on both trailing-edge stations, and a dense mass coupling.
fn random_system(nu: usize, nl: usize, nw: usize, seed: u64) -> BlockSystem {
    let n = nu + nl + nw;
    let mut g = Lcg(seed);
    let mut sys = BlockSystem::zeros(n);
    for k in 0..n {
        sys.diag[k] = g.block(4.0);
        let first_lower = k == nu;
        if k != 0 && !first_lower {
            sys.upstream[k] = Some((k - 1, g.block(0.0)));
        }
        if k == nu + nl {
            sys.upstream2[k] = Some((nu - 1, g.block(0.0)));
        }
        for r in 0..3 {
            for j in 0..n {
                sys.dense[(3 * k + r) * n + j] = 0.3 * g.next() / n as f64;
            }
        }
        sys.rhs[k] = [g.next(), g.next(), g.next()];
    }
    sys
}

#[test]
fn structured_solve_matches_dense_lu() {
    for (nu, nl, nw, seed) in [(5, 6, 3, 1), (40, 45, 20, 7), (80, 85, 30, 42)] {
        let sys = random_system(nu, nl, nw, seed);
        let n = sys.n;
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
fn invert3_inverts_and_rejects_singular() {
    let a = [[2.0, 1.0, 0.5], [0.3, 3.0, -1.0], [1.0, -0.5, 4.0]];
    let ai = invert3(&a).expect("regular");
    for (r, row) in a.iter().enumerate() {
        for c in 0..3 {
            let s: f64 = row.iter().zip(&ai).map(|(x, ai_row)| x * ai_row[c]).sum();
            let e = if r == c { 1.0 } else { 0.0 };
            assert!((s - e).abs() < 1e-14, "A·A⁻¹[{r}][{c}] = {s}");
        }
    }
    let singular = [[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 1.0, 1.0]];
    assert!(invert3(&singular).is_none());
}
