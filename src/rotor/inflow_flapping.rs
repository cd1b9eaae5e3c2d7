//! The coupled solution of the rotor disc: mean induced inflow and blade flapping such that
//! momentum theory and the blade-element thrust agree and the blade's flap equation holds
//! harmonic by harmonic (`flapping`: for a teetering hub the first harmonics of the flap moment
//! vanish; on flapping hinges they, and the coning, balance the blade's inertia), with the
//! azimuth-averaged loads of `disc_loads` at that state.
//!
//! The scaled unknowns z = (v0/ΩR, β1c, β1s), and the coning β0 for hinged blades, are found
//! by Newton's method with a
//! finite-difference Jacobian, which each iterate between evaluations updates by Broyden's
//! rank-one formula (Broyden, "A class of methods for solving nonlinear simultaneous
//! equations", Math. Comp. 19, 1965; Dennis & Schnabel, *Numerical Methods for Unconstrained
//! Optimization and Nonlinear Equations*, 1983, §8.1). A solve hands back, beside its result,
//! its Jacobian in a [`RotorWarmStart`], so a warm start from a neighbouring operating point (the
//! next takeoff stage, the next rpm of a trim search) needs about one blade-element sum per
//! iteration instead of four. The Jacobian is taken afresh by finite differences whenever an
//! iteration fails to contract the residual
//! ([`RotorSolverParams::broyden_contraction`](super::RotorSolverParams::broyden_contraction));
//! the converged state is the same root to the step tolerance, only the path to it differs.
//!
//! A blade that twists under load ([`ElasticTorsion`](super::ElasticTorsion)) makes the
//! momentum balance feed back on itself: more inflow, more momentum thrust, more torsion, more
//! blade thrust. Solved from rest, the iteration can then cycle across the torsion's load limit
//! ([`MAX_LOAD_RATIO`](super::torsion::MAX_LOAD_RATIO); PCA-2 in the tunnel at 200–450 rpm),
//! so such a solve without a warm start begins at the rigid blade's solution, from which it
//! converges to the same root.

use super::disc_loads::{FlightCondition, Loads, Rotor};
use super::flapping::{FlapHinge, Flapping, Hub};
use super::inflow::glauert_induced_velocity;
use super::solution::{RotorSolution, RotorWarmStart, WarmJacobian};
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

impl Rotor {
    /// Induced-velocity residual (v0 − κ·v_Glauert(T))/ΩR, the loads at (`z0` = v0/ΩR,
    /// `flapping`) and the scale ½ρ(ΩR)²cR² of the flap-moment residuals.
    fn momentum_residual<S: BladeSection + ?Sized>(
        &self,
        section: &S,
        cond: &FlightCondition,
        z0: f64,
        flapping: &Flapping,
    ) -> (f64, Loads, f64) {
        let tip = cond.omega * self.radius;
        let rho = cond.atmosphere.density;
        let loads = self.evaluate(section, cond, z0 * tip, flapping);
        let v_mt = self.induced_power_factor
            * glauert_induced_velocity(
                loads.thrust,
                rho,
                self.disc_area(),
                cond.airspeed,
                cond.hub_aoa,
            );
        let mscale = 0.5 * rho * tip * tip * self.chord * self.radius * self.radius;
        (z0 - v_mt / tip, loads, mscale)
    }

    /// Scaled residuals of the teetering rotor for z = (v0/ΩR, β1c, β1s): the momentum
    /// balance and the first-harmonic moments about the teeter bolt divided by ½ρ(ΩR)²cR².
    fn teeter_residuals<S: BladeSection + ?Sized>(
        &self,
        section: &S,
        cond: &FlightCondition,
        precone: f64,
        z: [f64; 3],
    ) -> ([f64; 3], Loads) {
        let flapping = Flapping {
            beta0: precone,
            beta1c: z[1],
            beta1s: z[2],
        };
        let (f0, loads, mscale) = self.momentum_residual(section, cond, z[0], &flapping);
        (
            [f0, loads.moment_1c / mscale, loads.moment_1s / mscale],
            loads,
        )
    }

    /// Scaled residuals of blades on flapping hinges for z = (v0/ΩR, β1c, β1s, β0): the
    /// momentum balance and the harmonic balance of the flap equation (module documentation of
    /// `flapping`), (M_1c,1s − (ν²−1) I_β Ω² β1c,1s) and (M_0 − M_W − ν² I_β Ω² β0), divided by
    /// ½ρ(ΩR)²cR².
    fn hinged_residuals<S: BladeSection + ?Sized>(
        &self,
        section: &S,
        cond: &FlightCondition,
        hinge: &FlapHinge,
        z: [f64; 4],
    ) -> ([f64; 4], Loads) {
        let flapping = Flapping {
            beta0: z[3],
            beta1c: z[1],
            beta1s: z[2],
        };
        let (f0, loads, mscale) = self.momentum_residual(section, cond, z[0], &flapping);
        let nu2 = hinge.frequency_squared();
        let stiffness = hinge.inertia * cond.omega * cond.omega;
        let harmonic = (nu2 - 1.0) * stiffness;
        (
            [
                f0,
                (loads.moment_1c - harmonic * z[1]) / mscale,
                (loads.moment_1s - harmonic * z[2]) / mscale,
                (loads.moment_0 - hinge.weight_moment(cond.hub_aoa) - nu2 * stiffness * z[3])
                    / mscale,
            ],
            loads,
        )
    }

    /// Solves inflow and blade flapping at `cond` (Newton's method on the scaled unknowns,
    /// Broyden-updated Jacobian; module documentation), starting from the state and Jacobian in
    /// `warm` if it holds one (`&mut None` for a cold start). On success `warm` holds the
    /// converged state's, the start of the next solve; on failure it is unchanged.
    pub fn solve<S: BladeSection + ?Sized>(
        &self,
        section: &S,
        cond: &FlightCondition,
        warm: &mut Option<RotorWarmStart>,
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
        // A blade that twists under load, without a warm start, starts from the rigid blade's
        // solution: from rest its iteration can cycle across the torsion's load limit (module
        // documentation). From rest after all if that start leads nowhere.
        let (solution, next) = match (warm.as_ref(), self.torsion) {
            (None, Some(_)) => {
                let rigid = Rotor {
                    torsion: None,
                    ..self.clone()
                };
                let mut start = None;
                let rigid_iterations = rigid
                    .solve(section, cond, &mut start)
                    .map_or(0, |s| s.iterations);
                match start.map(|s| self.solve_from(section, cond, Some(&s))) {
                    Some(Ok((mut solution, next))) => {
                        solution.iterations += rigid_iterations;
                        (solution, next)
                    }
                    _ => self.solve_from(section, cond, None)?,
                }
            }
            _ => self.solve_from(section, cond, warm.as_ref())?,
        };
        *warm = Some(next);
        Ok(solution)
    }

    /// [`solve`](Self::solve) from the state and Jacobian of `start`, or from rest: the
    /// solution and the warm start it hands on.
    fn solve_from<S: BladeSection + ?Sized>(
        &self,
        section: &S,
        cond: &FlightCondition,
        start: Option<&RotorWarmStart>,
    ) -> Result<(RotorSolution, RotorWarmStart), RotorError> {
        let tip = cond.omega * self.radius;
        let v0 = start.map_or(0.0, |w| w.induced_velocity / tip);
        let (v0_scaled, flapping, loads, iterations, jacobian) = match self.hub {
            Hub::Teetering { precone } => {
                let z = start.map_or([0.0; 3], |w| [v0, w.flapping.beta1c, w.flapping.beta1s]);
                let jac = start.and_then(|w| match w.jacobian {
                    WarmJacobian::Teetering(j) => Some(j),
                    WarmJacobian::Articulated(_) => None,
                });
                let (z, loads, iterations, jac) =
                    self.newton(|z| self.teeter_residuals(section, cond, precone, z), z, jac)?;
                let flapping = Flapping {
                    beta0: precone,
                    beta1c: z[1],
                    beta1s: z[2],
                };
                (
                    z[0],
                    flapping,
                    loads,
                    iterations,
                    WarmJacobian::Teetering(jac),
                )
            }
            Hub::Articulated(hinge) => {
                let z = start.map_or([0.0; 4], |w| {
                    [v0, w.flapping.beta1c, w.flapping.beta1s, w.flapping.beta0]
                });
                let jac = start.and_then(|w| match w.jacobian {
                    WarmJacobian::Articulated(j) => Some(j),
                    WarmJacobian::Teetering(_) => None,
                });
                let (z, loads, iterations, jac) =
                    self.newton(|z| self.hinged_residuals(section, cond, &hinge, z), z, jac)?;
                let flapping = Flapping {
                    beta0: z[3],
                    beta1c: z[1],
                    beta1s: z[2],
                };
                (
                    z[0],
                    flapping,
                    loads,
                    iterations,
                    WarmJacobian::Articulated(jac),
                )
            }
        };
        let solution = self.package(cond, v0_scaled, flapping, loads, iterations);
        let next = RotorWarmStart {
            induced_velocity: solution.induced_velocity,
            flapping,
            jacobian,
        };
        Ok((solution, next))
    }

    /// Newton–Broyden iteration on the scaled unknowns `z` (v0/ΩR first, the flap coefficients
    /// after it) from `z` and, if given and finite, the Jacobian `warm_jacobian`. Returns the
    /// converged unknowns with the loads there, the iterations used and the Jacobian.
    #[allow(clippy::type_complexity)]
    fn newton<const N: usize>(
        &self,
        residuals: impl Fn([f64; N]) -> ([f64; N], Loads),
        mut z: [f64; N],
        warm_jacobian: Option<[[f64; N]; N]>,
    ) -> Result<([f64; N], Loads, usize, [[f64; N]; N]), RotorError> {
        let p = self.solver;
        let (mut f, _) = residuals(z);
        let warm_jacobian = warm_jacobian.filter(|j| j.iter().flatten().all(|v| v.is_finite()));
        let mut jac = match warm_jacobian {
            Some(j) => j,
            None => fd_jacobian(&residuals, z, f, p.fd_step),
        };
        let newton_step = |jac: [[f64; N]; N], f: [f64; N]| {
            small_dense::solve(jac, std::array::from_fn(|i| -f[i]))
        };
        let mut dz = newton_step(jac, f);
        let mut last_step = f64::INFINITY;
        for iter in 1..=p.max_iterations {
            let Some(step) = dz else {
                return Err(RotorError::NoConvergence {
                    iterations: iter,
                    step: f64::NAN,
                });
            };
            let flap_step = step[1..].iter().fold(0.0_f64, |a, s| a.max(s.abs()));
            let damp = if flap_step > p.max_flap_step {
                p.max_flap_step / flap_step
            } else {
                1.0
            };
            let mut z_next = z;
            for i in 0..N {
                z_next[i] += damp * step[i];
            }
            last_step = max_abs(&step);
            if !last_step.is_finite() {
                break;
            }
            let (f_next, loads) = residuals(z_next);
            broyden_update(&mut jac, z, z_next, f, f_next);
            dz = newton_step(jac, f_next);
            // Converged when the step taken or the next one is below the tolerance.
            let next_step = dz.as_ref().map_or(f64::INFINITY, max_abs);
            if last_step < p.tolerance || next_step < p.tolerance {
                return Ok((z_next, loads, iter, jac));
            }
            if max_abs(&f_next) > p.broyden_contraction * max_abs(&f) {
                jac = fd_jacobian(&residuals, z_next, f_next, p.fd_step);
                dz = newton_step(jac, f_next);
            }
            (z, f) = (z_next, f_next);
        }
        Err(RotorError::NoConvergence {
            iterations: p.max_iterations,
            step: last_step,
        })
    }

    /// The result at the converged state (`v0_scaled` = v0/ΩR).
    fn package(
        &self,
        cond: &FlightCondition,
        v0_scaled: f64,
        flapping: Flapping,
        loads: Loads,
        iterations: usize,
    ) -> RotorSolution {
        let tip = cond.omega * self.radius;
        let rho = cond.atmosphere.density;
        let (sa, ca) = cond.hub_aoa.sin_cos();
        let v0 = v0_scaled * tip;
        RotorSolution {
            condition: *cond,
            induced_velocity: v0,
            flapping,
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
        }
    }
}

/// Largest absolute component.
fn max_abs<const N: usize>(v: &[f64; N]) -> f64 {
    v.iter().fold(0.0_f64, |a, x| a.max(x.abs()))
}

/// Forward-difference Jacobian of `residuals` at `z`, where they are `f`, with step `h`.
fn fd_jacobian<const N: usize>(
    residuals: &impl Fn([f64; N]) -> ([f64; N], Loads),
    z: [f64; N],
    f: [f64; N],
    h: f64,
) -> [[f64; N]; N] {
    let mut jac = [[0.0; N]; N];
    for j in 0..N {
        let mut zp = z;
        zp[j] += h;
        let (fp, _) = residuals(zp);
        for i in 0..N {
            jac[i][j] = (fp[i] - f[i]) / h;
        }
    }
    jac
}

/// Broyden's rank-one update J ← J + (Δf − J·Δz)·Δzᵀ/(Δzᵀ·Δz) for the step `z` → `z_next`,
/// whose residuals are `f` → `f_next` (the secant condition J·Δz = Δf); no update for a zero
/// step.
fn broyden_update<const N: usize>(
    jac: &mut [[f64; N]; N],
    z: [f64; N],
    z_next: [f64; N],
    f: [f64; N],
    f_next: [f64; N],
) {
    let dz: [f64; N] = std::array::from_fn(|i| z_next[i] - z[i]);
    let norm2: f64 = dz.iter().map(|d| d * d).sum();
    if norm2.is_nan() || norm2 <= 0.0 {
        return;
    }
    for i in 0..N {
        let predicted: f64 = (0..N).map(|j| jac[i][j] * dz[j]).sum();
        let k = (f_next[i] - f[i] - predicted) / norm2;
        for j in 0..N {
            jac[i][j] += k * dz[j];
        }
    }
}
