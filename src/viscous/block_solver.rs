//! Structured linear solve of the global Newton system (the role of XFOIL's BLSOLV,
//! Drela 1989 §4), done as a block forward substitution plus a dense Schur complement on the
//! mass-defect unknowns.
//!
//! Each boundary-layer station k carries three unknowns w_k = (δs_k, δθ_k, δm_k) (shear/amplification
//! variable, momentum thickness, mass defect m = Ue·δ*) and three equations:
//!
//! ```text
//! A_k w_k + B_k w_p(k) + C_k w_q(k) + Σ_j V_k,j δm_j = r_k
//! ```
//!
//! with p(k) < k the upstream station along the same surface and q(k) < k an optional second
//! upstream station (the upper trailing-edge station for the first wake station, XFOIL TESYS).
//! The 3n×n block V carries the dense edge-velocity coupling Ue = Ue_inv + G·m: an equation
//! depends on the edge speeds of at most three of its own stations and, through ξ, of the two
//! stations next to the stagnation point, so each row of V is a combination of at most five
//! rows of G and is kept as those coefficients; V itself is never stored.
//! Writing the block part as the lower block-triangular operator L, the solution is
//! `w = L⁻¹(r − V m)` and `m = P w`, hence the n×n Schur system `(I + P L⁻¹ V) m = P L⁻¹ r`.
//! The cost is O(n²) for the substitutions plus one n×n LU, instead of a 3n×3n dense LU. Only
//! the mass rows P L⁻¹ V are stored; once m is known, w follows from a second block
//! substitution with V m = (rows of) G m.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::lu::partial_pivoting::{factor, solve};
use faer::perm::PermRef;
use faer::{Mat, MatMut, MatRef, Par};

use super::error::ViscousError;
use crate::numerics::dense::dot4;
use crate::numerics::simd::{with_avx2, Kernel};
use crate::numerics::small_dense::{invert3, mul3, mul33, Block3};

/// Most rows of G one row of V combines: the edge speeds of the equation's own stations (at
/// most three, at the trailing-edge junction) and of the two stations next to the stagnation
/// point (through ξ, see the assembly).
pub const MAX_MASS_TERMS: usize = 5;

/// Columns per block of the forward substitution's row operations.
const LANES: usize = 8;

/// Row of the mass columns V as a combination of at most [`MAX_MASS_TERMS`] rows of the mass
/// influence matrix G: V_row = Σ c·G\[j\].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MassTerms {
    rows: [usize; MAX_MASS_TERMS],
    coefs: [f64; MAX_MASS_TERMS],
    len: usize,
}

impl MassTerms {
    /// Adds c·G\[j\] (merged with an earlier term on the same row of G).
    ///
    /// # Panics
    /// If more than [`MAX_MASS_TERMS`] distinct rows of G are added.
    pub fn add(&mut self, j: usize, c: f64) {
        if let Some(i) = self.rows[..self.len].iter().position(|&r| r == j) {
            self.coefs[i] += c;
        } else {
            assert!(
                self.len < MAX_MASS_TERMS,
                "an equation depends on at most {MAX_MASS_TERMS} edge speeds"
            );
            self.rows[self.len] = j;
            self.coefs[self.len] = c;
            self.len += 1;
        }
    }

    /// The terms (row of G, coefficient).
    pub fn terms(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.rows[..self.len]
            .iter()
            .copied()
            .zip(self.coefs[..self.len].iter().copied())
    }
}

/// The structured Newton system of one viscous iteration.
#[derive(Clone, Debug)]
pub struct BlockSystem<'a> {
    /// Number of stations n (3n unknowns).
    pub n: usize,
    /// Diagonal blocks A_k (coefficients of the station's own unknowns).
    pub diag: Vec<Block3>,
    /// Upstream station p(k) (must be < k) with its block B_k.
    pub upstream: Vec<Option<(usize, Block3)>>,
    /// Second upstream station q(k) (< k) with its block C_k (trailing-edge junction).
    pub upstream2: Vec<Option<(usize, Block3)>>,
    /// Mass influence matrix G, n × n row-major: `g[j·n + i]` = ∂Ue_j/∂m_i.
    pub mass_influence: &'a [f64],
    /// The mass columns V (3n × n) by rows: row 3k+r, ∂(equation r of station k)/∂m, is
    /// Σ c·G\[j\] over the terms of `mass_terms[3k + r]`.
    pub mass_terms: Vec<MassTerms>,
    /// Right-hand sides r_k.
    pub rhs: Vec<[f64; 3]>,
}

impl<'a> BlockSystem<'a> {
    /// An all-zero system of `n` stations coupled through the n × n mass influence matrix
    /// `mass_influence` (row-major).
    ///
    /// # Panics
    /// If `mass_influence` does not hold n² values.
    pub fn zeros(n: usize, mass_influence: &'a [f64]) -> Self {
        assert_eq!(
            mass_influence.len(),
            n * n,
            "mass influence matrix must be n × n"
        );
        Self {
            n,
            diag: vec![[[0.0; 3]; 3]; n],
            upstream: vec![None; n],
            upstream2: vec![None; n],
            mass_influence,
            mass_terms: vec![MassTerms::default(); 3 * n],
            rhs: vec![[0.0; 3]; n],
        }
    }

    /// The upstream stations of station k with their blocks: p(k) and, at the trailing-edge
    /// junction, q(k).
    fn upstreams(&self, k: usize) -> impl Iterator<Item = &(usize, Block3)> {
        [&self.upstream[k], &self.upstream2[k]]
            .into_iter()
            .flatten()
    }

    /// r_k − Σ_p B_p y_p: station k's right-hand side with its upstream stations' part of
    /// y = L⁻¹r eliminated (then y_k = A_k⁻¹ times it).
    #[inline(always)]
    fn upstream_eliminated(&self, k: usize, r_k: [f64; 3], y: &[[f64; 3]]) -> [f64; 3] {
        let mut t = r_k;
        for (p, b) in self.upstreams(k) {
            let yp = y[*p];
            for (r, tr) in t.iter_mut().enumerate() {
                *tr -= b[r][0] * yp[0] + b[r][1] * yp[1] + b[r][2] * yp[2];
            }
        }
        t
    }

    /// Expands the system into a dense 3n×3n matrix (for tests).
    #[cfg(test)]
    pub fn to_dense(&self) -> Mat<f64> {
        let n = self.n;
        let mut a = Mat::<f64>::zeros(3 * n, 3 * n);
        for k in 0..n {
            for r in 0..3 {
                for c in 0..3 {
                    a[(3 * k + r, 3 * k + c)] += self.diag[k][r][c];
                    for (p, b) in self.upstreams(k) {
                        a[(3 * k + r, 3 * p + c)] += b[r][c];
                    }
                }
                for (j, c) in self.mass_terms[3 * k + r].terms() {
                    for i in 0..n {
                        a[(3 * k + r, 3 * i + 2)] += c * self.mass_influence[j * n + i];
                    }
                }
            }
        }
        a
    }

    /// Solves the system; returns w_k = (δs_k, δθ_k, δm_k) for every station.
    #[cfg(test)]
    pub fn solve(&self) -> Result<Vec<[f64; 3]>, ViscousError> {
        let mut schur = Vec::new();
        self.clone().factor_and_solve(&mut schur).map(|(_, w)| w)
    }

    /// Forward substitution y = L⁻¹ r, returned, and the mass rows of Y = L⁻¹ V, written into
    /// `mass_rows` (n × n, row k the mass row of station k, row-major; any contents on entry).
    /// Station k's three rows of Y are
    /// Σ_j (A_k⁻¹W_k)_j G_j − Σ_p (A_k⁻¹B_p) Y_p, with W_k the coefficients of its rows of V;
    /// they are formed block of columns by block, so that every input row is read and every
    /// output row written once. The first two rows are kept only while a later station needs
    /// them (the next station, or a trailing-edge station for the wake junction): the back
    /// substitution does not use them (see [`solve_with`](Self::solve_with)).
    /// Compiled with AVX2 where the CPU has it ([`with_avx2`]).
    fn forward_substitute(&self, inv: &[Block3], mass_rows: &mut Vec<f64>) -> Vec<[f64; 3]> {
        with_avx2(ForwardSubstitution {
            system: self,
            inv,
            mass_rows,
        })
    }

    #[inline(always)]
    fn forward_substitute_kernel(&self, inv: &[Block3], mass_rows: &mut Vec<f64>) -> Vec<[f64; 3]> {
        let n = self.n;
        let g = self.mass_influence;
        // Stations whose first two rows of Y a later station other than the next one needs
        // (the mass rows are all kept anyway).
        let mut kept_slot: Vec<Option<usize>> = vec![None; n];
        let mut n_kept = 0;
        for k in 0..n {
            for (p, _) in self.upstreams(k) {
                if *p + 1 != k && kept_slot[*p].is_none() {
                    kept_slot[*p] = Some(n_kept);
                    n_kept += 1;
                }
            }
        }
        let mut kept = vec![0.0; 2 * n * n_kept];
        let mut y = vec![[0.0; 3]; n];
        // Every entry is written below, so a buffer of the right size is used as it is.
        if mass_rows.len() != n * n {
            mass_rows.clear();
            mass_rows.resize(n * n, 0.0);
        }
        // Rows 0 and 1 of Y for the previous station and the current one.
        let mut prev = vec![0.0; 2 * n];
        let mut cur = vec![0.0; 2 * n];
        for k in 0..n {
            let a = &inv[k];
            // Y_k = Σ_j (A⁻¹W_k)_j G_j − Σ_p (A⁻¹B_p) Y_p: every input row read once and every
            // output row written once, in blocks of LANES columns.
            let t = self.upstream_eliminated(k, self.rhs[k], &y);
            let (done, rest) = mass_rows.split_at_mut(k * n);
            let out2 = &mut rest[..n];
            let mut ups: [UpstreamRows<'_>; 2] = [(&[], &[], &[], [[0.0; 3]; 3]); 2];
            let mut n_ups = 0;
            for (p, b) in self.upstreams(k) {
                let rows01 = match kept_slot[*p] {
                    Some(slot) if *p + 1 != k => &kept[2 * n * slot..2 * n * (slot + 1)],
                    _ => &prev[..],
                };
                let (p0, p1) = rows01.split_at(n);
                let p2 = &done[*p * n..(*p + 1) * n];
                ups[n_ups] = (p0, p1, p2, mul33(a, b));
                n_ups += 1;
            }
            y[k] = mul3(a, &t);
            // The distinct rows of G in the station's three equations, with their coefficients
            // per equation, multiplied by A⁻¹.
            let mut rows: [&[f64]; 3 * MAX_MASS_TERMS] = [&[]; 3 * MAX_MASS_TERMS];
            let mut row_index = [usize::MAX; 3 * MAX_MASS_TERMS];
            let mut coef = [[0.0; 3]; 3 * MAX_MASS_TERMS];
            let mut n_rows = 0;
            for (r, terms) in self.mass_terms[3 * k..3 * k + 3].iter().enumerate() {
                for (j, c) in terms.terms() {
                    let u = match row_index[..n_rows].iter().position(|&x| x == j) {
                        Some(u) => u,
                        None => {
                            row_index[n_rows] = j;
                            rows[n_rows] = &g[j * n..(j + 1) * n];
                            n_rows += 1;
                            n_rows - 1
                        }
                    };
                    coef[u][r] += c;
                }
            }
            for c in coef[..n_rows].iter_mut() {
                *c = mul3(a, c);
            }
            let (ups, rows, coef) = (&ups[..n_ups], &rows[..n_rows], &coef[..n_rows]);
            let (out0, out1) = cur.split_at_mut(n);
            let full = n - n % LANES;
            for i0 in (0..full).step_by(LANES) {
                let acc = station_columns::<LANES>(ups, rows, coef, i0);
                out0[i0..i0 + LANES].copy_from_slice(&acc[0]);
                out1[i0..i0 + LANES].copy_from_slice(&acc[1]);
                out2[i0..i0 + LANES].copy_from_slice(&acc[2]);
            }
            for i in full..n {
                let acc = station_columns::<1>(ups, rows, coef, i);
                out0[i] = acc[0][0];
                out1[i] = acc[1][0];
                out2[i] = acc[2][0];
            }
            if let Some(slot) = kept_slot[k] {
                kept[2 * n * slot..2 * n * (slot + 1)].copy_from_slice(&cur);
            }
            std::mem::swap(&mut prev, &mut cur);
        }
        y
    }

    /// Factors the system (block inverses, LU of the Schur complement) and solves it for its
    /// own right-hand side; the factored system then solves further right-hand sides at O(n²)
    /// each ([`FactoredSystem::solve`]). `schur` is the memory of the n × n Schur complement
    /// (any contents on entry, overwritten): a Newton loop passes the same buffer every
    /// iteration, which is then still in cache and needs no zero-filling.
    pub fn factor_and_solve(
        self,
        schur: &mut Vec<f64>,
    ) -> Result<(FactoredSystem<'_, 'a>, Vec<[f64; 3]>), ViscousError> {
        let n = self.n;
        let inv: Vec<Block3> = self
            .diag
            .iter()
            .enumerate()
            .map(|(k, a)| invert3(a).ok_or(ViscousError::SingularSystem { station: k }))
            .collect::<Result<_, _>>()?;

        let y = self.forward_substitute(&inv, schur);

        // Schur complement on the mass unknowns: (I + P Y) m = P y. The mass rows of Y, read
        // as columns, are Sᵀ in column-major order: Sᵀ is factored in place (no copy) and the
        // transposed system solved.
        let mut perm = vec![0usize; n];
        let mut perm_inv = vec![0usize; n];
        {
            let mut buf = MemBuffer::new(factor::lu_in_place_scratch::<usize, f64>(
                n,
                n,
                Par::Seq,
                Default::default(),
            ));
            let mut st = MatMut::from_column_major_slice_mut(schur, n, n);
            for i in 0..n {
                st[(i, i)] += 1.0;
            }
            // Sequential LU: the solver runs inside parallel sweeps, so no nested parallelism.
            factor::lu_in_place(
                st.as_mut(),
                &mut perm,
                &mut perm_inv,
                Par::Seq,
                MemStack::new(&mut buf),
                Default::default(),
            );
        }
        let factored = FactoredSystem {
            system: self,
            inv,
            schur_lu: schur,
            perm,
            perm_inv,
        };
        let w = factored.back_substitute(&factored.system.rhs, &y)?;
        Ok((factored, w))
    }
}

/// A factored [`BlockSystem`]: its block inverses and the LU factors of its Schur complement,
/// which solve further right-hand sides without a new factorisation.
pub struct FactoredSystem<'s, 'a> {
    system: BlockSystem<'a>,
    /// Inverses of the diagonal blocks A_k.
    inv: Vec<Block3>,
    /// LU factors of Sᵀ (n × n, column-major) and the row permutation.
    schur_lu: &'s [f64],
    perm: Vec<usize>,
    perm_inv: Vec<usize>,
}

impl FactoredSystem<'_, '_> {
    /// The residual change Σ_j (∂R/∂Ue_j)·due_j of every equation for an edge-speed change
    /// `due` at fixed mass defects (the coefficients of the mass columns V, before G): the
    /// right-hand side a change of the inviscid edge speed adds (XFOIL's DUE terms).
    pub fn edge_speed_terms(&self, due: &[f64]) -> Vec<[f64; 3]> {
        (0..self.system.n)
            .map(|k| {
                std::array::from_fn(|r| {
                    self.system.mass_terms[3 * k + r]
                        .terms()
                        .map(|(j, c)| c * due[j])
                        .sum()
                })
            })
            .collect()
    }

    /// Solves the system with the right-hand side `rhs` (one [r₀, r₁, r₂] per station).
    pub fn solve(&self, rhs: &[[f64; 3]]) -> Result<Vec<[f64; 3]>, ViscousError> {
        let sys = &self.system;
        let mut y = vec![[0.0; 3]; sys.n];
        for k in 0..sys.n {
            y[k] = mul3(&self.inv[k], &sys.upstream_eliminated(k, rhs[k], &y));
        }
        self.back_substitute(rhs, &y)
    }

    /// From the right-hand side r and y = L⁻¹r: the mass unknowns m from the Schur system,
    /// then w = L⁻¹(r − V m).
    fn back_substitute(
        &self,
        rhs: &[[f64; 3]],
        y: &[[f64; 3]],
    ) -> Result<Vec<[f64; 3]>, ViscousError> {
        let sys = &self.system;
        let n = sys.n;
        let mut m = Mat::<f64>::from_fn(n, 1, |i, _| y[i][2]);
        let mut buf = MemBuffer::new(solve::solve_transpose_in_place_scratch::<usize, f64>(
            n,
            1,
            Par::Seq,
        ));
        let lu = MatRef::from_column_major_slice(self.schur_lu, n, n);
        let perm = PermRef::new_checked(&self.perm, &self.perm_inv, n);
        solve::solve_transpose_in_place(
            lu,
            lu,
            perm,
            m.as_mut(),
            Par::Seq,
            MemStack::new(&mut buf),
        );
        if let Some(i) = (0..n).find(|&i| !m[(i, 0)].is_finite()) {
            return Err(ViscousError::SingularSystem { station: i });
        }

        // Back substitution w = L⁻¹(r − V m), block by block, with V m formed from G m; the
        // mass unknowns are m itself.
        let mdense: Vec<f64> = (0..n).map(|j| m[(j, 0)]).collect();
        let gm: Vec<f64> = sys
            .mass_influence
            .chunks_exact(n)
            .map(|row| dot4(row, &mdense))
            .collect();
        let mut w = vec![[0.0; 3]; n];
        for k in 0..n {
            let mut t = rhs[k];
            for (r, tr) in t.iter_mut().enumerate() {
                *tr -= sys.mass_terms[3 * k + r]
                    .terms()
                    .map(|(j, c)| c * gm[j])
                    .sum::<f64>();
            }
            for (p, b) in sys.upstreams(k) {
                let t_p = mul3(b, &w[*p]);
                for (tr, d) in t.iter_mut().zip(t_p) {
                    *tr -= d;
                }
            }
            w[k] = mul3(&self.inv[k], &t);
            w[k][2] = mdense[k];
        }
        Ok(w)
    }
}

/// The forward-substitution kernel of a system (see [`BlockSystem::forward_substitute`]).
struct ForwardSubstitution<'s, 'a> {
    system: &'s BlockSystem<'a>,
    inv: &'s [Block3],
    mass_rows: &'s mut Vec<f64>,
}

impl Kernel for ForwardSubstitution<'_, '_> {
    type Output = Vec<[f64; 3]>;

    #[inline(always)]
    fn run(self) -> Vec<[f64; 3]> {
        self.system
            .forward_substitute_kernel(self.inv, self.mass_rows)
    }
}

/// The upstream rows and their 3×3 factors (A⁻¹B) of one station in the forward substitution.
type UpstreamRows<'r> = (&'r [f64], &'r [f64], &'r [f64], Block3);

/// Columns i0..i0+L of a station's three rows of Y = L⁻¹V:
/// Σ_j (A⁻¹W)_j G_j − Σ_p (A⁻¹B_p) Y_p, with the rows of G and Y_p given as slices.
#[inline(always)]
fn station_columns<const L: usize>(
    ups: &[UpstreamRows<'_>],
    rows: &[&[f64]],
    coef: &[[f64; 3]],
    i0: usize,
) -> [[f64; L]; 3] {
    let mut acc = [[0.0; L]; 3];
    for (p0, p1, p2, mb) in ups {
        let a0: &[f64; L] = p0[i0..i0 + L].try_into().expect("L columns");
        let a1: &[f64; L] = p1[i0..i0 + L].try_into().expect("L columns");
        let a2: &[f64; L] = p2[i0..i0 + L].try_into().expect("L columns");
        for (accr, m) in acc.iter_mut().zip(mb) {
            for l in 0..L {
                accr[l] -= m[0] * a0[l] + m[1] * a1[l] + m[2] * a2[l];
            }
        }
    }
    for (gr, c) in rows.iter().zip(coef) {
        let gv: &[f64; L] = gr[i0..i0 + L].try_into().expect("L columns");
        for (accr, cr) in acc.iter_mut().zip(c) {
            for l in 0..L {
                accr[l] += cr * gv[l];
            }
        }
    }
    acc
}

#[cfg(test)]
mod tests;
