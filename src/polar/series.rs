//! The states a grid's series share: each polar's converged states by α, and the filling of
//! the points a march left unconverged from the polar at the next lower Reynolds number
//! ([`run_grid`](super::run_grid)).

use std::collections::HashMap;

use super::sweep::WarmStartSolver;
use crate::section::PolarPoint;

/// The converged states of one polar by α ([`WarmStartSolver::series_state`]): where a point
/// the next polar of its series (the same Mach number and trips at the next higher Reynolds
/// number of a grid) leaves unconverged is solved once more ([`fill_from_below`]). States of
/// points in massive separation are kept too: without them the filling of the 8-H-12 free
/// table converges 3 points that lookups use instead of 10.
#[derive(Clone, Debug)]
pub struct SeriesStates<T> {
    /// States by the bit pattern of α (+0.0 for −0.0).
    by_alpha: HashMap<u64, T>,
}

impl<T> Default for SeriesStates<T> {
    fn default() -> Self {
        Self {
            by_alpha: HashMap::new(),
        }
    }
}

impl<T> SeriesStates<T> {
    fn key(alpha: f64) -> u64 {
        (alpha + 0.0).to_bits()
    }

    /// Keeps the state converged at `alpha`.
    pub(super) fn insert(&mut self, alpha: f64, state: T) {
        self.by_alpha.insert(Self::key(alpha), state);
    }

    /// Takes over the states of another branch of the same polar (other α).
    pub(super) fn merge(&mut self, other: Self) {
        self.by_alpha.extend(other.by_alpha);
    }

    /// The state converged at exactly `alpha`, if any.
    pub(super) fn get(&self, alpha: f64) -> Option<&T> {
        self.by_alpha.get(&Self::key(alpha))
    }
}

/// Solves once more each point of a polar (`alphas`, `points`) that is not converged, from
/// the state its α converged to in the polar below it in its series (`below`), and keeps the
/// state of each point this converges in `states` (for the polar above). Across one step of a
/// grid's Reynolds numbers the boundary layer changes little, so that state is a close start
/// where the march along α found none. The march itself is not changed: every point it
/// converged stays as it was, so the polar follows the branch its α continuation gives
/// (XFOIL's).
pub(super) fn fill_from_below<S: WarmStartSolver>(
    solver: &mut S,
    alphas: &[f64],
    points: &mut [PolarPoint],
    states: &mut SeriesStates<S::State>,
    below: &SeriesStates<S::State>,
) {
    for (&alpha, point) in alphas.iter().zip(points.iter_mut()) {
        let Some(start) = below.get(alpha).filter(|_| !point.converged) else {
            continue;
        };
        solver.restore(start);
        let p = solver.solve(alpha);
        if p.converged {
            *point = p;
            states.insert(alpha, solver.series_state());
        }
    }
}
