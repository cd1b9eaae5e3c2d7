//! The recovery of a point a sweep's march failed: sub-steps from the last converged neighbour,
//! then a fresh start, within the point's budget of Newton iterations, with the solves a
//! recovery would repeat from the same converged state replayed.

use super::sweep::{SweepParams, WarmStartSolver};
use crate::section::PolarPoint;

/// Outcomes of the solves done from the current anchor (the last converged state), keyed by
/// the α path taken from it. A recovery often repeats such a solve exactly: the half step towards
/// the point after a failed one is that failed point again, from the same converged neighbour.
/// Solves are deterministic ([`WarmStartSolver::solve`]), so the stored point and end state are
/// exactly what the repeat would give. Cleared whenever the anchor changes.
pub(super) struct AnchorMemo<T> {
    /// (α path from the anchor as bit patterns, its last point, the state after it).
    entries: Vec<(Vec<u64>, PolarPoint, T)>,
}

impl<T> Default for AnchorMemo<T> {
    fn default() -> Self {
        Self {
            entries: Vec::new(),
        }
    }
}

impl<T: Clone> AnchorMemo<T> {
    /// Forgets every outcome (the anchor changed).
    pub(super) fn clear(&mut self) {
        self.entries.clear();
    }

    /// Solves `alpha` after the solves of `path` from the anchor (the solver holds the state
    /// they left), or replays the outcome if this path was solved before; `path` then ends with
    /// `alpha`. The iterations of a new solve are added to `spent`.
    pub(super) fn solve<S: WarmStartSolver<State = T>>(
        &mut self,
        solver: &mut S,
        path: &mut Vec<u64>,
        alpha: f64,
        spent: &mut u32,
    ) -> PolarPoint {
        path.push(alpha.to_bits());
        if let Some((_, point, state)) = self.entries.iter().find(|(p, _, _)| p == path) {
            solver.restore(state);
            return *point;
        }
        let point = solver.solve(alpha);
        *spent = spent.saturating_add(point.iterations);
        self.entries.push((path.clone(), point, solver.save()));
        point
    }
}

/// Retry a failed point: sub-steps from the last converged neighbour, then a fresh start, while
/// the point has not used its budget ([`SweepParams::point_budget`]; `spent` iterations so far).
pub(super) fn recover<S: WarmStartSolver>(
    solver: &mut S,
    alpha: f64,
    anchor: Option<&(f64, S::State)>,
    params: &SweepParams,
    memo: &mut AnchorMemo<S::State>,
    mut spent: u32,
) -> Option<PolarPoint> {
    let budget = params.point_budget;
    if let Some((a0, state)) = anchor {
        for level in 1..=params.substep_levels {
            let n = 1u32 << level;
            solver.restore(state);
            let mut path = Vec::new();
            let mut ok = true;
            for j in 1..n {
                let a = a0 + (alpha - a0) * f64::from(j) / f64::from(n);
                if spent >= budget || !memo.solve(solver, &mut path, a, &mut spent).converged {
                    ok = false;
                    break;
                }
            }
            if ok && spent < budget {
                let p = memo.solve(solver, &mut path, alpha, &mut spent);
                if p.converged {
                    return Some(p);
                }
            }
        }
    }
    if params.fresh_retry && spent < budget {
        solver.reset();
        let p = solver.solve(alpha);
        if p.converged {
            return Some(p);
        }
    }
    None
}
