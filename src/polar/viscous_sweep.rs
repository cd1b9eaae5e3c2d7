//! The viscous solver as a [`WarmStartSolver`] for sweeps, grids and the target-Cl search.

use super::sweep::WarmStartSolver;
use crate::section::PolarPoint;
use crate::viscous::{ViscousSolver, WarmStart};

// A failed point is retried by the sweep's recovery ([`super::SweepParams`]), never by the
// solver.
impl WarmStartSolver for ViscousSolver {
    type State = WarmStart;

    fn solve(&mut self, alpha_deg: f64) -> PolarPoint {
        ViscousSolver::solve(self, alpha_deg).point
    }

    fn reset(&mut self) {
        ViscousSolver::reset(self);
    }

    fn save(&self) -> WarmStart {
        self.warm_start()
    }

    fn restore(&mut self, state: &WarmStart) {
        self.set_warm_start(state);
    }

    fn series_state(&self) -> WarmStart {
        self.settled_state()
    }
}
