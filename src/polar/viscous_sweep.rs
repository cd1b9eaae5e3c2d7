//! The viscous solver as a [`WarmStartSolver`] for sweeps and grids.

use super::sweep::WarmStartSolver;
use crate::section::PolarPoint;
use std::sync::Arc;

use crate::geometry::Airfoil;
use crate::viscous::{SharedPanels, ViscousError, ViscousParams, ViscousSolver, WarmStart};

/// A [`ViscousSolver`] driven point by point by [`sweep`](super::sweep()).
#[derive(Debug)]
pub struct ViscousSweep {
    /// The solver of one (Re, M, Ncrit, trip) condition.
    pub solver: ViscousSolver,
}

impl ViscousSweep {
    /// Solver for an already paneled airfoil at the given condition. The solver's own
    /// fresh-start retry is turned off: the sweep retries from a fresh start itself, after
    /// sub-stepping from the converged neighbour (`SweepParams::fresh_retry`).
    pub fn new(airfoil: &Airfoil, params: ViscousParams) -> Result<Self, ViscousError> {
        Self::with_panels(Arc::new(SharedPanels::new(airfoil)?), params)
    }

    /// Like [`new`](Self::new), on a panel store shared with the sweeps of other flow
    /// conditions of the same airfoil (a grid builds each per-α inviscid model once).
    pub fn with_panels(
        panels: Arc<SharedPanels>,
        params: ViscousParams,
    ) -> Result<Self, ViscousError> {
        let params = ViscousParams {
            fresh_retry: false,
            ..params
        };
        Ok(Self {
            solver: ViscousSolver::with_panels(panels, params)?,
        })
    }
}

impl WarmStartSolver for ViscousSweep {
    type State = WarmStart;

    fn solve(&mut self, alpha_deg: f64) -> PolarPoint {
        self.solver.solve(alpha_deg).point
    }

    fn reset(&mut self) {
        self.solver.reset();
    }

    fn save(&self) -> WarmStart {
        self.solver.warm_start()
    }

    fn restore(&mut self, state: &WarmStart) {
        self.solver.set_warm_start(state);
    }
}
