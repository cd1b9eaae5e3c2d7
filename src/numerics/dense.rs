//! Dense products of the coupling: matrix–vector products with the n × n edge-speed influence
//! matrix (Ue = Ue_inv + D·m, and D·δm in the Newton update) and dot products.

use super::simd::{with_avx2, Kernel};

/// Rows of [`mat_vec`] summed side by side: independent chains that keep the adders busy
/// through their latency, where one row's strict left-to-right sum waits on every add.
const ROWS: usize = 8;

/// `a · v` for a row-major matrix `a` with `v.len()` columns. Each row's sum runs strictly left
/// to right from −0.0, as `Iterator::sum` does, so the result is bit-identical to
/// `row.iter().zip(v).map(|(d, x)| d * x).sum()`; speed comes from summing [`ROWS`] rows at once
/// (and from AVX2 registers where the CPU has them), not from reordering.
pub(crate) fn mat_vec(a: &[f64], v: &[f64]) -> Vec<f64> {
    with_avx2(MatVec { a, v })
}

/// The [`mat_vec`] kernel: matrix `a`, vector `v`.
struct MatVec<'a> {
    a: &'a [f64],
    v: &'a [f64],
}

impl Kernel for MatVec<'_> {
    type Output = Vec<f64>;

    #[inline(always)]
    fn run(self) -> Vec<f64> {
        mat_vec_kernel(self.a, self.v)
    }
}

#[inline(always)]
fn mat_vec_kernel(a: &[f64], v: &[f64]) -> Vec<f64> {
    let n = v.len();
    if n == 0 {
        return Vec::new();
    }
    let mut out = Vec::with_capacity(a.len() / n);
    let mut blocks = a.chunks_exact(ROWS * n);
    for block in &mut blocks {
        let rows: [&[f64]; ROWS] = std::array::from_fn(|l| &block[l * n..(l + 1) * n]);
        let mut acc = [-0.0; ROWS];
        for (j, x) in v.iter().enumerate() {
            for l in 0..ROWS {
                acc[l] += rows[l][j] * x;
            }
        }
        out.extend_from_slice(&acc);
    }
    for row in blocks.remainder().chunks_exact(n) {
        let mut acc = -0.0;
        for (d, x) in row.iter().zip(v) {
            acc += d * x;
        }
        out.push(acc);
    }
    out
}

/// Dot product summed strictly left to right (the order of `Iterator::sum`).
#[inline]
pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(p, q)| p * q).sum()
}

/// Dot product with four partial sums (vectorisable, unlike [`dot`]'s strict order).
pub(crate) fn dot4(a: &[f64], b: &[f64]) -> f64 {
    let mut acc = [0.0; 4];
    let (ac, bc) = (a.chunks_exact(4), b.chunks_exact(4));
    let tail: f64 = ac
        .remainder()
        .iter()
        .zip(bc.remainder())
        .map(|(x, y)| x * y)
        .sum();
    for (x, y) in ac.zip(bc) {
        for i in 0..4 {
            acc[i] += x[i] * y[i];
        }
    }
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::test_random::Lcg;

    /// Bit for bit the strict left-to-right sum, for row counts below, at and between multiples
    /// of the block size, with values whose products and sums round (and signed zeros).
    #[test]
    fn mat_vec_is_bit_identical_to_plain_sums() {
        let mut random = Lcg::new(7);
        let mut next = || random.unit() - 0.5;
        for (rows, n) in [(1, 1), (7, 5), (8, 13), (17, 31), (183, 183)] {
            let mut a: Vec<f64> = (0..rows * n).map(|_| next() * 1e3).collect();
            let v: Vec<f64> = (0..n).map(|_| next() / 7.0).collect();
            a[0] = -0.0;
            let out = mat_vec(&a, &v);
            assert_eq!(out.len(), rows);
            for (r, o) in out.iter().enumerate() {
                let plain: f64 = a[r * n..(r + 1) * n]
                    .iter()
                    .zip(&v)
                    .map(|(d, x)| d * x)
                    .sum();
                assert_eq!(o.to_bits(), plain.to_bits(), "rows {rows} n {n} row {r}");
            }
        }
        let zeros = mat_vec(&[-0.0, -0.0], &[1.0, 1.0]);
        assert!(zeros[0] == 0.0 && zeros[0].is_sign_negative());
    }
}
