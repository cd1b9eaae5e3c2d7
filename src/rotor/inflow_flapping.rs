//! The coupled solution of the rotor disc: mean induced inflow and teeter flapping such that
//! momentum theory and the blade-element thrust agree and the first harmonics of the flap
//! moment vanish, with the azimuth-averaged loads of [`disc_loads`](super::disc_loads) at
//! that state.
//!
//! Three scaled unknowns z = (v0/ΩR, β1c, β1s) are found by Newton's method with a
//! finite-difference Jacobian, which each iterate between evaluations updates by Broyden's
//! rank-one formula (Broyden, "A class of methods for solving nonlinear simultaneous
//! equations", Math. Comp. 19, 1965; Dennis & Schnabel, *Numerical Methods for Unconstrained
//! Optimization and Nonlinear Equations*, 1983, §8.1). A solution keeps its Jacobian, so a warm
//! start from a neighbouring operating point (the next takeoff stage, the next rpm of a trim
//! search) needs about one blade-element sum per iteration instead of four. The Jacobian is
//! taken afresh by finite differences whenever an iteration fails to contract the residual
//! ([`RotorSolverParams::broyden_contraction`]); the converged state is the same root to the
//! step tolerance, only the path to it differs.

use super::disc_loads::{FlightCondition, Loads, Rotor};
use super::flapping::Teeter;
use super::inflow::glauert_induced_velocity;
use super::spanwise::BladeSection;
use crate::numerics::small_dense;

/// Errors of the rotor solution.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RotorError {
    /// The operating point is not physical (non-finite values, rotor not turning, …).
    #[error("invalid rotor operating point: {0}")]
    InvalidCondition(&'static str),
    /// The coupled inflow/flapping iteration did not converge.
    #[error("rotor inflow/flapping iteration did not converge after {iterations} iterations (step {step:.3e})")]
    NoConvergence {
        /// Iterations used.
        iterations: usize,
        /// Size of the last Newton step (scaled).
        step: f64,
    },
}

/// Tunable numerics of the coupled inflow/flapping Newton iteration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RotorSolverParams {
    /// Largest number of Newton iterations.
    pub max_iterations: usize,
    /// Convergence: scaled Newton step below this (v0 in units of ΩR, β in rad), the step
    /// taken to the returned state or the next one from it.
    pub tolerance: f64,
    /// Finite-difference step for the Jacobian (same scaling).
    pub fd_step: f64,
    /// Largest allowed change of a flap coefficient per iteration \[rad\].
    pub max_flap_step: f64,
    /// A Broyden-updated Jacobian is kept while each iteration shrinks the largest scaled
    /// residual by at least this factor; otherwise it is taken afresh by finite differences.
    pub broyden_contraction: f64,
}

impl Default for RotorSolverParams {
    fn default() -> Self {
        Self {
            max_iterations: 40,
            tolerance: 1e-9,
            fd_step: 1e-6,
            max_flap_step: 0.05,
            broyden_contraction: 0.5,
        }
    }
}

/// Converged rotor state and its azimuth-averaged loads.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RotorSolution {
    /// Operating point solved.
    pub condition: FlightCondition,
    /// Mean induced velocity v0 \[m/s\] (downwards positive).
    pub induced_velocity: f64,
    /// Teeter flapping.
    pub teeter: Teeter,
    /// Tip-loss factor B used: 1 − (lift-free length)/R, for Prandtl's factor the equivalent
    /// value ∫(1 − F)dr/R averaged over the azimuth.
    pub tip_loss_b: f64,
    /// Thrust along the shaft T \[N\].
    pub thrust: f64,
    /// In-plane force towards the rear (H-force) \[N\].
    pub h_force: f64,
    /// In-plane force towards the advancing side \[N\].
    pub side_force: f64,
    /// Rotor lift, perpendicular to the flight path \[N\].
    pub lift: f64,
    /// Rotor drag, along the flight path, rearwards \[N\].
    pub drag: f64,
    /// Aerodynamic driving torque about the shaft \[N m\]; positive accelerates the rotor,
    /// zero in autorotation (the shaft torque needed to drive the rotor is its negative).
    pub torque: f64,
    /// Advance ratio μ = V cos α_H/(ΩR).
    pub advance_ratio: f64,
    /// Net upflow ratio λ = (V sin α_H − v0)/(ΩR).
    pub inflow_ratio: f64,
    /// Thrust coefficient C_T = T/(ρA(ΩR)²).
    pub thrust_coefficient: f64,
    /// Fraction of the strip-azimuth samples in reverse flow.
    pub reverse_flow_fraction: f64,
    /// Fraction of the strip-azimuth samples whose Reynolds or Mach number lay outside the
    /// section table, so that the lookup used the table's edge (see [`Lookup`](crate::section::Lookup)).
    pub table_clamped_fraction: f64,
    /// Fraction of the strip-azimuth samples whose section data lean on supercritical table
    /// points (Cp_min < Cp*, outside the validity of the section method).
    pub table_supercritical_fraction: f64,
    /// Fraction of the strip-azimuth samples at whose α the table's points are in massive
    /// separation (outside the validity of the section method; the 360° extension stands in).
    pub table_separated_fraction: f64,
    /// Newton iterations used.
    pub iterations: usize,
    /// Jacobian of the scaled residuals with respect to z at the solution (finite differences,
    /// Broyden-updated): the start of a warm solve from this one.
    jacobian: [[f64; 3]; 3],
}

impl RotorSolution {
    /// Angle of attack of the tip-path plane α_R = α_H − β1c \[rad\] (the "rotor AoA").
    pub fn disc_aoa(&self) -> f64 {
        self.condition.hub_aoa + self.teeter.tilt_back()
    }

    /// Resultant rotor force √(L² + D²) \[N\].
    pub fn resultant(&self) -> f64 {
        self.lift.hypot(self.drag)
    }
}

impl Rotor {
    /// Scaled residuals of the coupled problem for unknowns z = (v0/ΩR, β1c, β1s):
    /// momentum balance (v0 − κ·v_Glauert(T))/ΩR and the first-harmonic teeter moments divided
    /// by ½ρ(ΩR)²cR².
    fn residuals<S: BladeSection + ?Sized>(
        &self,
        section: &S,
        cond: &FlightCondition,
        z: [f64; 3],
    ) -> ([f64; 3], Loads) {
        let tip = cond.omega * self.radius;
        let rho = cond.atmosphere.density;
        let teeter = Teeter {
            beta0: self.precone,
            beta1c: z[1],
            beta1s: z[2],
        };
        let loads = self.evaluate(section, cond, z[0] * tip, &teeter);
        let v_mt = self.induced_power_factor
            * glauert_induced_velocity(
                loads.thrust,
                rho,
                self.disc_area(),
                cond.airspeed,
                cond.hub_aoa,
            );
        let mscale = 0.5 * rho * tip * tip * self.chord * self.radius * self.radius;
        (
            [
                z[0] - v_mt / tip,
                loads.moment_1c / mscale,
                loads.moment_1s / mscale,
            ],
            loads,
        )
    }

    /// Solves inflow and teeter flapping at `cond` (Newton's method on the three scaled
    /// unknowns, Broyden-updated Jacobian; module documentation), starting from `warm` and its
    /// Jacobian if given.
    pub fn solve<S: BladeSection + ?Sized>(
        &self,
        section: &S,
        cond: &FlightCondition,
        warm: Option<&RotorSolution>,
    ) -> Result<RotorSolution, RotorError> {
        if !(cond.airspeed.is_finite() && cond.hub_aoa.is_finite() && cond.omega.is_finite()) {
            return Err(RotorError::InvalidCondition(
                "non-finite airspeed, angle or rotor speed",
            ));
        }
        if cond.omega <= 0.0 {
            return Err(RotorError::InvalidCondition("rotor speed must be positive"));
        }
        if cond.airspeed < 0.0 {
            return Err(RotorError::InvalidCondition(
                "airspeed must not be negative",
            ));
        }
        if cond.atmosphere.density.is_nan() || cond.atmosphere.density <= 0.0 {
            return Err(RotorError::InvalidCondition("air density must be positive"));
        }
        let tip = cond.omega * self.radius;
        let mut z = match warm {
            Some(w) => [w.induced_velocity / tip, w.teeter.beta1c, w.teeter.beta1s],
            None => [0.0, 0.0, 0.0],
        };
        let p = self.solver;
        let (mut f, _) = self.residuals(section, cond, z);
        let warm_jacobian = warm
            .map(|w| w.jacobian)
            .filter(|j| j.iter().flatten().all(|v| v.is_finite()));
        let mut jac = match warm_jacobian {
            Some(j) => j,
            None => self.fd_jacobian(section, cond, z, f),
        };
        let newton_step =
            |jac: [[f64; 3]; 3], f: [f64; 3]| small_dense::solve(jac, [-f[0], -f[1], -f[2]]);
        let mut dz = newton_step(jac, f);
        let mut last_step = f64::INFINITY;
        for iter in 1..=p.max_iterations {
            let Some(step) = dz else {
                return Err(RotorError::NoConvergence {
                    iterations: iter,
                    step: f64::NAN,
                });
            };
            let flap_step = step[1].abs().max(step[2].abs());
            let damp = if flap_step > p.max_flap_step {
                p.max_flap_step / flap_step
            } else {
                1.0
            };
            let mut z_next = z;
            for i in 0..3 {
                z_next[i] += damp * step[i];
            }
            last_step = max_abs(step);
            if !last_step.is_finite() {
                break;
            }
            let (f_next, loads) = self.residuals(section, cond, z_next);
            broyden_update(&mut jac, z, z_next, f, f_next);
            dz = newton_step(jac, f_next);
            // Converged when the step taken or the next one is below the tolerance.
            let next_step = dz.map_or(f64::INFINITY, max_abs);
            if last_step < p.tolerance || next_step < p.tolerance {
                return Ok(self.package(cond, z_next, loads, iter, jac));
            }
            if max_abs(f_next) > p.broyden_contraction * max_abs(f) {
                jac = self.fd_jacobian(section, cond, z_next, f_next);
                dz = newton_step(jac, f_next);
            }
            (z, f) = (z_next, f_next);
        }
        Err(RotorError::NoConvergence {
            iterations: p.max_iterations,
            step: last_step,
        })
    }

    /// Forward-difference Jacobian of the scaled residuals at `z`, where they are `f`.
    fn fd_jacobian<S: BladeSection + ?Sized>(
        &self,
        section: &S,
        cond: &FlightCondition,
        z: [f64; 3],
        f: [f64; 3],
    ) -> [[f64; 3]; 3] {
        let h = self.solver.fd_step;
        let mut jac = [[0.0; 3]; 3];
        for j in 0..3 {
            let mut zp = z;
            zp[j] += h;
            let (fp, _) = self.residuals(section, cond, zp);
            for i in 0..3 {
                jac[i][j] = (fp[i] - f[i]) / h;
            }
        }
        jac
    }

    fn package(
        &self,
        cond: &FlightCondition,
        z: [f64; 3],
        loads: Loads,
        iterations: usize,
        jacobian: [[f64; 3]; 3],
    ) -> RotorSolution {
        let tip = cond.omega * self.radius;
        let rho = cond.atmosphere.density;
        let (sa, ca) = cond.hub_aoa.sin_cos();
        let v0 = z[0] * tip;
        RotorSolution {
            condition: *cond,
            induced_velocity: v0,
            teeter: Teeter {
                beta0: self.precone,
                beta1c: z[1],
                beta1s: z[2],
            },
            tip_loss_b: loads.tip_loss_b,
            thrust: loads.thrust,
            h_force: loads.h_force,
            side_force: loads.side_force,
            // Wind axes: lift ⟂ flight path, drag along it (disc tilted back by α_H).
            lift: loads.thrust * ca - loads.h_force * sa,
            drag: loads.thrust * sa + loads.h_force * ca,
            torque: loads.torque,
            advance_ratio: cond.airspeed * ca / tip,
            inflow_ratio: (cond.airspeed * sa - v0) / tip,
            thrust_coefficient: loads.thrust / (rho * self.disc_area() * tip * tip),
            reverse_flow_fraction: loads.reverse_fraction,
            table_clamped_fraction: loads.clamped_fraction,
            table_supercritical_fraction: loads.supercritical_fraction,
            table_separated_fraction: loads.separated_fraction,
            iterations,
            jacobian,
        }
    }
}

/// Largest absolute component.
fn max_abs(v: [f64; 3]) -> f64 {
    v.iter().fold(0.0_f64, |a, x| a.max(x.abs()))
}

/// Broyden's rank-one update J ← J + (Δf − J·Δz)·Δzᵀ/(Δzᵀ·Δz) for the step `z` → `z_next`,
/// whose residuals are `f` → `f_next` (the secant condition J·Δz = Δf); no update for a zero
/// step.
fn broyden_update(
    jac: &mut [[f64; 3]; 3],
    z: [f64; 3],
    z_next: [f64; 3],
    f: [f64; 3],
    f_next: [f64; 3],
) {
    let dz: [f64; 3] = std::array::from_fn(|i| z_next[i] - z[i]);
    let norm2: f64 = dz.iter().map(|d| d * d).sum();
    if norm2.is_nan() || norm2 <= 0.0 {
        return;
    }
    for i in 0..3 {
        let predicted: f64 = (0..3).map(|j| jac[i][j] * dz[j]).sum();
        let k = (f_next[i] - f[i] - predicted) / norm2;
        for j in 0..3 {
            jac[i][j] += k * dz[j];
        }
    }
}
