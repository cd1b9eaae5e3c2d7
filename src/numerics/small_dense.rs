//! Small dense linear algebra kept in registers: Gaussian elimination with partial pivoting for
//! N ≤ 4 unknowns (the local Newton iterations of the boundary-layer marches, 4×4), and the 3×3
//! inverse and products of the structured Newton solve, whose diagonal blocks are each applied
//! to many right-hand sides.

/// A 3×3 block, row-major.
pub(crate) type Block3 = [[f64; 3]; 3];

/// Solves `a·x = b` (N ≤ 4) by Gaussian elimination with partial pivoting, the last of equally
/// large pivot candidates taken. `None` if a pivot is zero (below 1e-300), infinite or NaN, or
/// the solution is not finite.
#[inline]
pub(crate) fn solve<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> Option<[f64; N]> {
    const { assert!(N <= 4, "small_dense::solve handles up to 4 unknowns") };
    // One call per column with a literal index: inlined, every index is a constant and the
    // matrix stays in registers (a loop over the columns swapped rows through memory; same
    // operations, same results).
    eliminate_column(&mut a, &mut b, 0)?;
    if N > 1 {
        eliminate_column(&mut a, &mut b, 1)?;
    }
    if N > 2 {
        eliminate_column(&mut a, &mut b, 2)?;
    }
    if N > 3 {
        eliminate_column(&mut a, &mut b, 3)?;
    }
    let mut x = [0.0; N];
    for r in (0..N).rev() {
        let mut s = 0.0;
        for c in r + 1..N {
            s += a[r][c] * x[c];
        }
        x[r] = (b[r] - s) / a[r][r];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Step `col` of [`solve`]: moves the largest entry of column `col` at or below the diagonal
/// (the last of equal ones, or a NaN) onto the diagonal and eliminates the column below it.
/// `None` if that pivot is zero (below 1e-300), infinite or NaN.
#[inline(always)]
fn eliminate_column<const N: usize>(
    a: &mut [[f64; N]; N],
    b: &mut [f64; N],
    col: usize,
) -> Option<()> {
    let mut p = col;
    let mut best = a[col][col].abs();
    for (r, row) in a.iter().enumerate().skip(col + 1) {
        let v = row[col].abs();
        if v >= best || v.is_nan() {
            best = v;
            p = r;
        }
    }
    if best.is_nan() || best < 1e-300 || best.is_infinite() {
        return None;
    }
    // Row exchange by selects rather than a branch on the data-dependent pivot row (the
    // same values; a mispredicted branch per column cost more than the selects). Only columns
    // col.. are exchanged: the ones left of col in rows col.. are never read again (the
    // elimination and the back substitution use a[r][c] with c ≥ r only).
    for r in col + 1..N {
        let take = r == p;
        // Two rows of `a` in step: indices read plainer than zipped row iterators.
        #[allow(clippy::needless_range_loop)]
        for k in col..N {
            let (x, y) = (a[col][k], a[r][k]);
            a[col][k] = if take { y } else { x };
            a[r][k] = if take { x } else { y };
        }
        let (x, y) = (b[col], b[r]);
        b[col] = if take { y } else { x };
        b[r] = if take { x } else { y };
    }
    let pivot_row = a[col];
    let pivot_rhs = b[col];
    for r in col + 1..N {
        let f = a[r][col] / pivot_row[col];
        for k in col..N {
            a[r][k] -= f * pivot_row[k];
        }
        b[r] -= f * pivot_rhs;
    }
    Some(())
}

/// Inverse of a 3×3 matrix by cofactors; `None` if it is (numerically) singular: its
/// determinant is lost to cancellation, at most 1e-15 of the sum of the magnitudes of the six
/// products it is made of. That measure does not change when rows or columns are scaled, so a
/// block whose columns differ by orders of magnitude (the similarity station with the
/// stagnation point almost on a node: columns of 1, 1e5 and 1e9) is not mistaken for a singular
/// one.
pub(crate) fn invert3(a: &Block3) -> Option<Block3> {
    let c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    let c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    let c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    let det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    let terms = (a[0][0] * a[1][1] * a[2][2]).abs()
        + (a[0][0] * a[1][2] * a[2][1]).abs()
        + (a[0][1] * a[1][2] * a[2][0]).abs()
        + (a[0][1] * a[1][0] * a[2][2]).abs()
        + (a[0][2] * a[1][0] * a[2][1]).abs()
        + (a[0][2] * a[1][1] * a[2][0]).abs();
    if !det.is_finite() || det.abs() <= 1e-15 * terms {
        return None;
    }
    let d = 1.0 / det;
    Some([
        [
            c00 * d,
            (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * d,
            (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * d,
        ],
        [
            c01 * d,
            (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * d,
            (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * d,
        ],
        [
            c02 * d,
            (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * d,
            (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * d,
        ],
    ])
}

/// Product of two 3×3 blocks.
pub(crate) fn mul33(a: &Block3, b: &Block3) -> Block3 {
    std::array::from_fn(|r| {
        std::array::from_fn(|c| a[r][0] * b[0][c] + a[r][1] * b[1][c] + a[r][2] * b[2][c])
    })
}

/// Product of a 3×3 block with a 3-vector.
pub(crate) fn mul3(a: &Block3, v: &[f64; 3]) -> [f64; 3] {
    [
        a[0][0] * v[0] + a[0][1] * v[1] + a[0][2] * v[2],
        a[1][0] * v[0] + a[1][1] * v[1] + a[1][2] * v[2],
        a[2][0] * v[0] + a[2][1] * v[1] + a[2][2] * v[2],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A system that needs row exchanges (zero leading entries) is solved to round-off; a
    /// singular or NaN system gives `None`.
    #[test]
    fn solve_pivots_and_rejects_singular_systems() {
        let a = [
            [0.0, 2.0, 1.0, -1.0],
            [0.0, 0.0, 3.0, 2.0],
            [4.0, 1.0, 0.0, 1.0],
            [1.0, -1.0, 2.0, 0.0],
        ];
        let x = [1.0, -2.0, 0.5, 3.0];
        let b: [f64; 4] = std::array::from_fn(|r| (0..4).map(|c| a[r][c] * x[c]).sum());
        let got = solve(a, b).unwrap();
        for (g, e) in got.iter().zip(&x) {
            assert!((g - e).abs() < 1e-14, "{got:?}");
        }
        let mut singular = a;
        singular[3] = singular[2];
        assert!(solve(singular, b).is_none());
        let mut nan = a;
        nan[1][2] = f64::NAN;
        assert!(solve(nan, b).is_none());
        // Three unknowns: the 4×4 system's leading block with its own right-hand side.
        let a3 = [[0.0, 2.0, 1.0], [0.0, 1.0, 3.0], [4.0, 1.0, 0.0]];
        let b3: [f64; 3] = std::array::from_fn(|r| (0..3).map(|c| a3[r][c] * x[c]).sum());
        let got3 = solve(a3, b3).unwrap();
        for (g, e) in got3.iter().zip(&x) {
            assert!((g - e).abs() < 1e-14, "{got3:?}");
        }
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
}
