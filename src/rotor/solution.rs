//! What a solve of the rotor disc returns: the converged state and its azimuth-averaged loads
//! ([`RotorSolution`], a plain result that compares equal whenever the states are equal), and
//! apart from it the solver's memory for a warm start from that state ([`RotorWarmStart`]).

use super::disc_loads::{FlightCondition, Rotor};
use super::flapping::Flapping;
use super::lookup_shares::LookupShares;
use std::f64::consts::TAU;

/// Converged rotor state and its azimuth-averaged loads.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RotorSolution {
    /// Operating point solved.
    pub condition: FlightCondition,
    /// Mean induced velocity v0 \[m/s\] (downwards positive).
    pub induced_velocity: f64,
    /// Blade flapping.
    pub flapping: Flapping,
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
    /// Newton iterations used (for a twisting blade solved without a warm start, with those
    /// of the rigid blade's solution it starts from).
    pub iterations: usize,
}

impl RotorSolution {
    /// The solution's lookup shares ([`LookupShares`]).
    pub fn lookup_shares(&self) -> LookupShares {
        LookupShares {
            clamped: self.table_clamped_fraction,
            supercritical: self.table_supercritical_fraction,
            separated: self.table_separated_fraction,
        }
    }

    /// Angle of attack of the tip-path plane α_R = α_H − β1c \[rad\] (the "rotor AoA").
    pub fn disc_aoa(&self) -> f64 {
        self.condition.hub_aoa + self.flapping.tilt_back()
    }

    /// Resultant rotor force √(L² + D²) \[N\].
    pub fn resultant(&self) -> f64 {
        self.lift.hypot(self.drag)
    }
}

/// The solver's memory of a converged state, the start of a warm solve from it
/// ([`Rotor::solve`]): the unknowns there and the Jacobian of the scaled residuals
/// (finite differences, Broyden-updated). Opaque: two solves that reach the same state by
/// different paths hold different Jacobians, which is why it is kept apart from the result.
#[derive(Clone, Copy, Debug)]
pub struct RotorWarmStart {
    /// Mean induced velocity v0 \[m/s\].
    pub(super) induced_velocity: f64,
    /// Flapping.
    pub(super) flapping: Flapping,
    /// Jacobian of the scaled residuals with respect to the scaled unknowns.
    pub(super) jacobian: WarmJacobian,
}

/// The Jacobian of a warm start, sized by the hub's unknowns.
#[derive(Clone, Copy, Debug)]
pub(super) enum WarmJacobian {
    /// (v0/ΩR, β1c, β1s).
    Teetering([[f64; 3]; 3]),
    /// (v0/ΩR, β1c, β1s, β0).
    Articulated([[f64; 4]; 4]),
}

impl Rotor {
    /// Section angle of attack α(ψ) \[deg\] at radius fraction `r_over_r` for `samples` azimuths
    /// ψ_k = 360°·k/samples (ψ = 0 at the rear), using a converged `solution`'s inflow and
    /// flapping. Returns (ψ \[deg\], α \[deg\]) pairs.
    pub fn alpha_at_radius(
        &self,
        solution: &RotorSolution,
        r_over_r: f64,
        samples: usize,
    ) -> Vec<(f64, f64)> {
        let r = r_over_r * self.radius;
        (0..samples)
            .map(|k| {
                let psi = TAU * k as f64 / samples.max(1) as f64;
                let flow = self.strip_flow(
                    &solution.condition,
                    solution.induced_velocity,
                    &solution.flapping,
                    r,
                    psi,
                );
                (psi.to_degrees(), flow.alpha_deg)
            })
            .collect()
    }
}
