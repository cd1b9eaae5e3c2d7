//! Azimuth-averaged loads of the rotor: the blade-element sum over radial strips and azimuth
//! steps at given induced inflow and blade flapping (solved for in `inflow_flapping`).
//!
//! Hub frame: x along the hub plane pointing downstream (ψ = 0, the rear), y towards the
//! advancing side (ψ = 90°), z along the shaft, up. The disc is tilted back by the hub angle
//! of attack α_H, so the free stream has the in-plane component V cos α_H (towards +x) and the
//! upflow V sin α_H. Blade 1 sits at azimuth ψ, radius r; every other blade repeats its motion
//! and loads at its own azimuth, so the disc's forces are N_b times blade 1's azimuth mean.

use super::atmosphere::Atmosphere;
use super::blade_element::{strip_load, AirState, StripFlow};
use super::flapping::{first_harmonics, Flapping, Hub};
use super::inflow::{
    drees_coefficients, gessow_myers_tip_loss, glauert_thrust, prandtl_strip_mean, InflowModel,
    TipLoss, YawedFlow,
};
use super::planform::Planform;
use super::spanwise::BladeSection;
use super::torsion::ElasticTorsion;
use std::f64::consts::TAU;

/// Rotor geometry and discretisation.
#[derive(Clone, Debug, PartialEq)]
pub struct Rotor {
    /// Radius R \[m\].
    pub radius: f64,
    /// Reference chord c \[m\]: the blade's chord where the planform's ratio is 1 (solidity
    /// N_b c/(πR), the scale of the flap-moment residuals).
    pub chord: f64,
    /// Chord and twist along the blade (relative to `chord` and `pitch`).
    pub planform: Planform,
    /// Number of blades (2 for a teetering hub).
    pub blades: u32,
    /// Blade pitch setting relative to the hub plane θ \[rad\]: the pitch where the planform's
    /// twist is 0.
    pub pitch: f64,
    /// Root cut-out radius \[m\].
    pub root_cutout: f64,
    /// Elastic torsion of the blade under its load (the planform's twist is then the one
    /// measured at the torsion's reference thrust); `None`: a rigid blade.
    pub torsion: Option<ElasticTorsion>,
    /// How the blades are attached: teetering (fixed coning) or on flapping hinges.
    pub hub: Hub,
    /// Number of radial strips.
    pub radial_strips: usize,
    /// Number of azimuth steps per revolution.
    pub azimuth_steps: usize,
    /// Tip-loss model.
    pub tip_loss: TipLoss,
    /// Profile drag in yawed flow.
    pub yawed_flow: YawedFlow,
    /// Inflow model.
    pub inflow: InflowModel,
    /// Induced-power factor κ ≥ 1: the uniform induced velocity is κ times Glauert's
    /// momentum value, so the induced power is κ·T·v_Glauert. κ carries the losses of the
    /// real, non-uniform inflow of a finite-bladed rotor (tip vortices, root losses, the
    /// skewed wake) that ideal momentum theory leaves out; the usual empirical values are
    /// κ ≈ 1.15 in hover and about the same at moderate advance ratios (Leishman, *Principles
    /// of Helicopter Aerodynamics*, 2nd ed., ch. 2 "induced power factor" and ch. 5 forward-flight
    /// performance; Johnson, *Helicopter Theory*, ch. 5). κ = 1 is ideal momentum theory.
    pub induced_power_factor: f64,
    /// Numerics.
    pub solver: RotorSolverParams,
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

/// Operating point of the rotor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlightCondition {
    /// True airspeed V \[m/s\].
    pub airspeed: f64,
    /// Hub (shaft-normal plane) angle of attack α_H \[rad\], positive = disc tilted back.
    pub hub_aoa: f64,
    /// Rotor angular speed Ω \[rad/s\].
    pub omega: f64,
    /// Air state.
    pub atmosphere: Atmosphere,
}

/// The parts of the velocity triangle shared by every strip of one evaluation.
struct DiscStream {
    /// Edgewise free stream V cos α_H \[m/s\].
    edge: f64,
    /// Axial free stream V sin α_H (up through the disc) \[m/s\].
    axial: f64,
    /// Rotor speed Ω \[rad/s\].
    omega: f64,
    /// Mean induced velocity v0 \[m/s\].
    v0: f64,
    /// Drees' gradients (k_x, k_y) of the inflow; `None` for uniform inflow.
    drees: Option<(f64, f64)>,
    /// Air state.
    air: AirState,
}

/// One radial strip of the blade: centre radius, edges as radius fractions, chord and pitch.
#[derive(Clone, Copy, Debug)]
struct Strip {
    /// Centre radius r \[m\].
    r: f64,
    /// Inner and outer edge r/R.
    edges: (f64, f64),
    /// Chord \[m\].
    chord: f64,
    /// Pitch relative to the hub plane \[rad\].
    pitch: f64,
}

/// Azimuth ψ of blade 1 with the trigonometry and flap motion its strips share.
struct AzimuthStation {
    /// sin ψ.
    sin_psi: f64,
    /// cos ψ.
    cos_psi: f64,
    /// Flap angle β(ψ) \[rad\].
    beta: f64,
    /// Flap rate dβ/dψ.
    beta_rate: f64,
}

impl AzimuthStation {
    fn new(flapping: &Flapping, psi: f64) -> Self {
        let (sin_psi, cos_psi) = psi.sin_cos();
        Self {
            sin_psi,
            cos_psi,
            beta: flapping.beta_at(sin_psi, cos_psi),
            beta_rate: flapping.beta_rate_at(sin_psi, cos_psi),
        }
    }
}

/// Loads of one evaluation at given inflow and flapping.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Loads {
    /// Thrust along the shaft \[N\].
    pub(super) thrust: f64,
    /// In-plane force towards the rear \[N\].
    pub(super) h_force: f64,
    /// In-plane force towards the advancing side \[N\].
    pub(super) side_force: f64,
    /// Aerodynamic driving torque \[N m\].
    pub(super) torque: f64,
    /// Mean of blade 1's aerodynamic flap moment about its flapping axis \[N m\].
    pub(super) moment_0: f64,
    /// Cosine harmonic of blade 1's flap moment about its flapping axis \[N m\].
    pub(super) moment_1c: f64,
    /// Sine harmonic of blade 1's flap moment about its flapping axis \[N m\].
    pub(super) moment_1s: f64,
    /// Fraction of strip-azimuth samples in reverse flow.
    pub(super) reverse_fraction: f64,
    /// Fraction of samples clamped to the table's Re/Mach edge.
    pub(super) clamped_fraction: f64,
    /// Fraction of samples leaning on supercritical table points.
    pub(super) supercritical_fraction: f64,
    /// Fraction of samples where the table's points are in massive separation (the 360°
    /// extension stands in for them).
    pub(super) separated_fraction: f64,
    /// Equivalent tip-loss factor B.
    pub(super) tip_loss_b: f64,
}

impl Rotor {
    /// Disc area πR² \[m²\].
    pub fn disc_area(&self) -> f64 {
        std::f64::consts::PI * self.radius * self.radius
    }

    /// Radii of the strip centres and the strip width \[m\].
    pub fn strips(&self) -> (Vec<f64>, f64) {
        let dr = (self.radius - self.root_cutout) / self.strip_count();
        let r = (0..self.radial_strips)
            .map(|i| self.root_cutout + (i as f64 + 0.5) * dr)
            .collect();
        (r, dr)
    }

    fn strip_count(&self) -> f64 {
        self.radial_strips.max(1) as f64
    }

    /// Chord \[m\] and pitch \[rad\] of the blade at radius `r` \[m\].
    pub fn chord_and_pitch(&self, r: f64) -> (f64, f64) {
        let (ratio, twist) = self.planform.at(r / self.radius);
        (self.chord * ratio, self.pitch + twist)
    }

    /// The rotor thrust momentum theory gives for the mean inflow `v0` \[N\]: Glauert's
    /// T = 2ρA·v_i·V′ with v_i = v0/κ (the induced-power factor taken out).
    fn momentum_thrust(&self, cond: &FlightCondition, v0: f64) -> f64 {
        glauert_thrust(
            v0 / self.induced_power_factor,
            cond.atmosphere.density,
            self.disc_area(),
            cond.airspeed,
            cond.hub_aoa,
        )
    }

    /// Chord \[m\] and pitch \[rad\] at radius `r` \[m\] with the blade's elastic torsion at
    /// the thrust momentum theory gives for the inflow `v0` (the thrust the converged solution
    /// carries, so the torsion is part of the coupled solve).
    fn loaded_chord_and_pitch(
        &self,
        cond: &FlightCondition,
        v0: f64,
    ) -> impl Fn(f64) -> (f64, f64) + '_ {
        let torsion = self.torsion.map(|t| (t, self.momentum_thrust(cond, v0)));
        move |r| {
            let (chord, pitch) = self.chord_and_pitch(r);
            match torsion {
                None => (chord, pitch),
                Some((t, thrust)) => (chord, pitch + t.pitch_change(r / self.radius, thrust)),
            }
        }
    }

    /// The radial strips of one evaluation at inflow `v0`.
    fn strip_layout(&self, cond: &FlightCondition, v0: f64) -> (Vec<Strip>, f64) {
        let (radii, dr) = self.strips();
        let chord_and_pitch = self.loaded_chord_and_pitch(cond, v0);
        let strips = radii
            .into_iter()
            .map(|r| {
                let (chord, pitch) = chord_and_pitch(r);
                Strip {
                    r,
                    edges: ((r - 0.5 * dr) / self.radius, (r + 0.5 * dr) / self.radius),
                    chord,
                    pitch,
                }
            })
            .collect();
        (strips, dr)
    }

    fn air(cond: &FlightCondition) -> AirState {
        AirState {
            density: cond.atmosphere.density,
            viscosity: cond.atmosphere.viscosity,
            speed_of_sound: cond.atmosphere.speed_of_sound,
        }
    }

    /// The tip-loss factor B of the models that use one for the whole disc, for mean induced
    /// velocity `v0` (Gessow–Myers through the thrust momentum theory gives for it, so that B
    /// is a smooth function of the iterate); `None` for Prandtl's, which varies by strip.
    fn uniform_tip_loss(&self, cond: &FlightCondition, v0: f64) -> Option<f64> {
        match self.tip_loss {
            TipLoss::Prandtl => None,
            TipLoss::NoLoss => Some(1.0),
            TipLoss::Chord => Some(1.0 - 0.5 * self.chord_and_pitch(self.radius).0 / self.radius),
            TipLoss::GessowMyers => {
                let rho = cond.atmosphere.density;
                let t = self.momentum_thrust(cond, v0);
                let tip = cond.omega * self.radius;
                Some(gessow_myers_tip_loss(
                    t / (rho * self.disc_area() * tip * tip),
                    self.blades,
                ))
            }
        }
    }

    /// The parts of the velocity triangle shared by all strips at inflow `v0`.
    fn disc_stream(&self, cond: &FlightCondition, v0: f64) -> DiscStream {
        let edge = cond.airspeed * cond.hub_aoa.cos();
        let axial = cond.airspeed * cond.hub_aoa.sin();
        let drees = match self.inflow {
            InflowModel::Glauert => None,
            InflowModel::Drees => {
                let tip = cond.omega * self.radius;
                Some(drees_coefficients(edge / tip, (axial - v0) / tip))
            }
        };
        DiscStream {
            edge,
            axial,
            omega: cond.omega,
            v0,
            drees,
            air: Self::air(cond),
        }
    }

    /// Local induced velocity at radius `r` and azimuth `at` \[m/s\]: the mean value, with
    /// Drees' linear gradients when that model is chosen.
    fn induced_at(&self, stream: &DiscStream, r: f64, at: &AzimuthStation) -> f64 {
        match stream.drees {
            None => stream.v0,
            Some((kx, ky)) => {
                let x = r / self.radius;
                stream.v0 * (1.0 + kx * x * at.cos_psi + ky * x * at.sin_psi)
            }
        }
    }

    /// Velocity triangle of blade 1 at radius `r`, azimuth `psi`:
    /// U_T = Ωr + V cos α_H sin ψ,
    /// U_P = V sin α_H − v_i(r, ψ) − Ω(r − e) dβ/dψ − V cos α_H β cos ψ (e the hinge offset),
    /// U_R = V cos α_H cos ψ (radial, drag only, with [`YawedFlow::RadialDrag`]; see
    /// [`StripFlow`](super::StripFlow))
    /// (small flap angles; Leishman, *Principles of Helicopter Aerodynamics*, 2nd ed., §4.7,
    /// with the normal velocity counted upwards).
    pub fn strip_flow(
        &self,
        cond: &FlightCondition,
        v0: f64,
        flapping: &Flapping,
        r: f64,
        psi: f64,
    ) -> StripFlow {
        let stream = self.disc_stream(cond, v0);
        let (chord, pitch) = self.loaded_chord_and_pitch(cond, v0)(r);
        let strip = Strip {
            r,
            edges: (r / self.radius, r / self.radius),
            chord,
            pitch,
        };
        self.flow_at(&stream, &AzimuthStation::new(flapping, psi), &strip)
    }

    /// [`strip_flow`](Self::strip_flow) from the shared parts of one evaluation.
    fn flow_at(&self, stream: &DiscStream, at: &AzimuthStation, strip: &Strip) -> StripFlow {
        let r = strip.r;
        let ut = stream.omega * r + stream.edge * at.sin_psi;
        let up = stream.axial
            - self.induced_at(stream, r, at)
            - stream.omega * (r - self.hub.hinge_offset()) * at.beta_rate
            - stream.edge * at.beta * at.cos_psi;
        let flow = StripFlow::new(ut, up, strip.pitch, strip.chord, &stream.air);
        match self.yawed_flow {
            YawedFlow::RadialDrag => flow.with_radial(stream.edge * at.cos_psi),
            YawedFlow::Ignored => flow,
        }
    }

    /// Blade-element sum for inflow `v0` and flapping `flapping`.
    pub(super) fn evaluate<S: BladeSection + ?Sized>(
        &self,
        section: &S,
        cond: &FlightCondition,
        v0: f64,
        flapping: &Flapping,
    ) -> Loads {
        let (strips, dr) = self.strip_layout(cond, v0);
        let hinge = self.hub.hinge_offset();
        let uniform = self.uniform_tip_loss(cond, v0);
        let rho = cond.atmosphere.density;
        let n = self.azimuth_steps;
        let mut moments = vec![0.0; n];
        let mut loads = Loads::default();
        let mut reversed = 0usize;
        let mut clamped = 0usize;
        let mut supercritical = 0usize;
        let mut separated = 0usize;
        let mut lift_free = 0.0;
        let stream = self.disc_stream(cond, v0);
        for (k, moment) in moments.iter_mut().enumerate() {
            let at = AzimuthStation::new(flapping, TAU * k as f64 / n as f64);
            let (beta, sp, cp) = (at.beta, at.sin_psi, at.cos_psi);
            let (mut ft_sum, mut fn_sum, mut fr_sum, mut q, mut m) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for strip in &strips {
                let r = strip.r;
                let flow = self.flow_at(&stream, &at, strip);
                if flow.is_reversed() {
                    reversed += 1;
                }
                let (x1, x2) = strip.edges;
                let lift_factor = match uniform {
                    Some(b) => ((b - x1) / (x2 - x1)).clamp(0.0, 1.0),
                    // The tip-vortex helix angle: up-flow against the blade's rotational
                    // speed Ωr (TipLoss::Prandtl).
                    None => prandtl_strip_mean(
                        x1,
                        x2,
                        flow.up / flow.up.hypot(cond.omega * r),
                        self.blades,
                    ),
                };
                lift_free += (1.0 - lift_factor) * dr;
                let coeffs = flow.coefficients(section, r / self.radius);
                if coeffs.re_clamped || coeffs.mach_clamped {
                    clamped += 1;
                }
                if coeffs.supercritical {
                    supercritical += 1;
                }
                separated += usize::from(coeffs.massive_separation);
                let load = strip_load(&flow, &coeffs, rho, strip.chord, lift_factor);
                ft_sum += load.tangential * dr;
                fn_sum += load.normal * dr;
                fr_sum += load.radial * dr;
                q += load.tangential * r * dr;
                m += load.normal * (r - hinge) * dr;
            }
            *moment = m;
            // Force on the hub from blade 1:
            // F_t e_t + F_n (−sin β e_r + cos β e_z) + F_r (cos β e_r + sin β e_z),
            // e_r = (cos ψ, sin ψ), e_t = (−sin ψ, cos ψ).
            let (sb, cb) = beta.sin_cos();
            let inplane_r = fr_sum * cb - fn_sum * sb;
            loads.thrust += fn_sum * cb + fr_sum * sb;
            loads.h_force += -ft_sum * sp + inplane_r * cp;
            loads.side_force += ft_sum * cp + inplane_r * sp;
            loads.torque += q;
        }
        // Every blade reproduces blade 1's loads at its own azimuth.
        let scale = f64::from(self.blades) / n as f64;
        loads.thrust *= scale;
        loads.h_force *= scale;
        loads.side_force *= scale;
        loads.torque *= scale;
        let (m1c, m1s) = first_harmonics(&moments);
        loads.moment_0 = moments.iter().sum::<f64>() / n as f64;
        loads.moment_1c = m1c;
        loads.moment_1s = m1s;
        let cells = (n * strips.len()) as f64;
        loads.reverse_fraction = reversed as f64 / cells;
        loads.clamped_fraction = clamped as f64 / cells;
        loads.supercritical_fraction = supercritical as f64 / cells;
        loads.separated_fraction = separated as f64 / cells;
        loads.tip_loss_b = 1.0 - lift_free / (n as f64 * self.radius);
        loads
    }
}

impl Rotor {
    /// Builds the rotor model from the preset's rotor section.
    pub fn from_params(p: &super::aircraft::RotorParams) -> Self {
        Self {
            radius: p.radius_m,
            chord: p.chord_m,
            planform: p.planform(),
            blades: p.blades,
            pitch: p.incidence_deg.to_radians(),
            root_cutout: p.root_cutout_m,
            torsion: p.torsion(),
            hub: p.hub(),
            radial_strips: p.radial_strips,
            azimuth_steps: p.azimuth_steps,
            tip_loss: p.tip_loss,
            yawed_flow: p.yawed_flow,
            induced_power_factor: p.induced_power_factor,
            inflow: p.inflow,
            solver: RotorSolverParams::default(),
        }
    }
}
