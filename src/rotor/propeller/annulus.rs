//! One annulus of the blade-element–momentum propeller: Drela's one-unknown formulation
//! (M. Drela, "QPROP Formulation", MIT Aero & Astro, 2006), solved for the velocity-triangle
//! angle ψ by Newton's method with its analytic derivative, and by a bracketed root when
//! Newton does not settle.
//!
//! The imposed velocities at radius r are U_a = V (axial) and U_t = Ωr (tangential),
//! U = √(U_a² + U_t²). Momentum theory puts the total velocity at the blade on a circle of
//! diameter U through the ends of the imposed vector (the actuator-disc velocity triangle),
//! parametrised by ψ:
//!
//! * W_a = ½(U_a + U sin ψ), W_t = ½(U_t + U cos ψ); induced v_a = W_a − U_a, v_t = U_t − W_t;
//! * W = √(W_a² + W_t²), inflow angle φ = atan2(W_a, W_t), section α = β − φ;
//! * Prandtl's tip factor from the wake advance ratio λ_w = (r/R)·W_a/W_t:
//!   f = (B/2)(1 − r/R)/λ_w, F = (2/π) acos(e^(−f)) (Prandtl 1919; Glauert in Durand,
//!   *Aerodynamic Theory* IV, div. L, 1935; F = 1 when W_a ≤ 0, the windmilling branch);
//! * the blade circulation the swirl implies, Γ = v_t (4πr/B) F √(1 + (4λ_w R/(πBr))²);
//! * residual R(ψ) = Γ − ½ W c c_l(α, Re, M) = 0: that circulation is the one the section
//!   carries (Kutta–Joukowski).
//!
//! The ψ = atan2(U_a, U_t) end of the circle has no induced velocity (W = U, Γ = 0): a thrusting
//! blade element (c_l > 0 there) has R < 0 there and its root at larger ψ, a windmilling one at
//! smaller ψ; this is the bracket of the fallback. The formulation holds from the static
//! propeller (U_a = 0) to windmilling without special cases.

use crate::numerics::roots::bracketed_root;
use std::f64::consts::{FRAC_PI_2, PI};

/// Section data at one angle of attack: what the residual needs of the section.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct SectionSample {
    /// Lift coefficient.
    pub(crate) cl: f64,
    /// ∂c_l/∂α \[1/rad\].
    pub(crate) cl_alpha: f64,
    /// Drag coefficient.
    pub(crate) cd: f64,
}

/// Imposed flow and geometry of one annulus.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct AnnulusFlow {
    /// Axial velocity U_a = V \[m/s\].
    pub(crate) axial: f64,
    /// Tangential velocity U_t = Ωr \[m/s\].
    pub(crate) tangential: f64,
    /// Radius fraction r/R.
    pub(crate) x: f64,
    /// Radius r \[m\].
    pub(crate) radius: f64,
    /// Chord c \[m\].
    pub(crate) chord: f64,
    /// Blade angle β of the section's chord line from the plane of rotation \[rad\].
    pub(crate) blade_angle: f64,
    /// Number of blades B.
    pub(crate) blades: f64,
}

/// The velocity triangle at one ψ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Triangle {
    /// Axial and tangential velocity at the blade, W_a, W_t \[m/s\].
    pub(crate) wa: f64,
    /// W_t.
    pub(crate) wt: f64,
    /// Resultant W \[m/s\].
    pub(crate) w: f64,
    /// Inflow angle φ \[rad\].
    pub(crate) phi: f64,
    /// Section angle of attack α = β − φ \[rad\].
    pub(crate) alpha: f64,
}

/// Largest Prandtl exponent evaluated: e^(−20) makes F = 1 to 1e-9.
const PRANDTL_EXPONENT_CAP: f64 = 20.0;

/// Largest Newton step in ψ \[rad\] (QPROP gvcalc.f limits it the same way).
const MAX_NEWTON_STEP: f64 = 0.1;

/// Newton converged when the step in ψ is below this \[rad\].
const PSI_TOLERANCE: f64 = 1e-9;

/// Most Newton iterations before the bracketed fallback.
const MAX_NEWTON_ITERATIONS: usize = 20;

/// Scan step of the bracketed fallback in ψ \[rad\].
const SCAN_STEP: f64 = 0.05;

/// Most evaluations of the bracketed refinement.
const MAX_BRACKET_ITERATIONS: usize = 100;

/// Largest |R|/(½ W c) accepted at a converged ψ (a lift-coefficient equivalent).
const RESIDUAL_TOLERANCE: f64 = 1e-6;

impl AnnulusFlow {
    /// |U|.
    fn speed(&self) -> f64 {
        self.axial.hypot(self.tangential)
    }

    /// ψ without induced velocity: the imposed flow direction.
    pub(crate) fn psi_undisturbed(&self) -> f64 {
        self.axial.atan2(self.tangential)
    }

    /// The velocity triangle at `psi`.
    pub(crate) fn triangle(&self, psi: f64) -> Triangle {
        let u = self.speed();
        let (s, c) = psi.sin_cos();
        let wa = 0.5 * (self.axial + u * s);
        let wt = 0.5 * (self.tangential + u * c);
        let phi = wa.atan2(wt);
        Triangle {
            wa,
            wt,
            w: wa.hypot(wt),
            phi,
            alpha: self.blade_angle - phi,
        }
    }

    /// Prandtl's tip factor F and ∂F/∂ψ at `psi` (module documentation).
    fn tip_factor(&self, psi: f64) -> (f64, f64, f64, f64) {
        let t = self.triangle(psi);
        let u = self.speed();
        let (s, c) = psi.sin_cos();
        let (dwa, dwt) = (0.5 * u * c, -0.5 * u * s);
        if t.wa <= 0.0 || t.wt <= 0.0 {
            return (1.0, 0.0, 0.0, 0.0);
        }
        let lw = self.x * t.wa / t.wt;
        let dlw = self.x * (dwa * t.wt - t.wa * dwt) / (t.wt * t.wt);
        let f = 0.5 * self.blades * (1.0 - self.x) / lw;
        if f >= PRANDTL_EXPONENT_CAP {
            return (1.0, 0.0, lw, dlw);
        }
        let e = (-f).exp();
        let big_f = 2.0 / PI * e.acos();
        // dF/df = (2/π)·e^(−f)/√(1 − e^(−2f)); df/dψ = −f/λ_w · dλ_w/dψ.
        let d_f = 2.0 / PI * e / (1.0 - e * e).sqrt() * (-f / lw * dlw);
        (big_f, d_f, lw, dlw)
    }

    /// Residual R(ψ) = Γ − ½Wc·c_l and dR/dψ, for the section data `sample` at the α of `psi`.
    /// The derivative takes c_l through α only: its change with Re and M along W is left out
    /// (it slows Newton's method a little and never moves the root).
    pub(crate) fn residual(&self, psi: f64, sample: &SectionSample) -> (f64, f64) {
        let t = self.triangle(psi);
        let u = self.speed();
        let (s, c) = psi.sin_cos();
        let (dwa, dwt) = (0.5 * u * c, -0.5 * u * s);
        let dw = (t.wa * dwa + t.wt * dwt) / t.w;
        let dphi = (t.wt * dwa - t.wa * dwt) / (t.w * t.w);
        let (big_f, d_big_f, lw, dlw) = self.tip_factor(psi);
        let k = 4.0 / (PI * self.blades * self.x);
        let root = (1.0 + (k * lw).powi(2)).sqrt();
        let d_root = k * k * lw * dlw / root;
        let vt = self.tangential - t.wt;
        let ring = 4.0 * PI * self.radius / self.blades;
        let gamma = vt * ring * big_f * root;
        let d_gamma = ring * (-dwt * big_f * root + vt * d_big_f * root + vt * big_f * d_root);
        let half_c = 0.5 * self.chord;
        let res = gamma - half_c * t.w * sample.cl;
        let d_res = d_gamma - half_c * (dw * sample.cl - t.w * sample.cl_alpha * dphi);
        (res, d_res)
    }

    /// The converged ψ of this annulus, starting from `guess` (e.g. the previous solution) or
    /// QPROP's start max(atan2(U_a, U_t), β); `sample_at(α, W)` gives the section data at
    /// angle of attack α \[rad\] and resultant speed W \[m/s\]. `None` when no root is found.
    pub(crate) fn solve(
        &self,
        guess: Option<f64>,
        mut sample_at: impl FnMut(f64, f64) -> SectionSample,
    ) -> Option<f64> {
        let mut eval = |psi: f64| {
            let t = self.triangle(psi);
            let sample = sample_at(t.alpha, t.w);
            let (res, d_res) = self.residual(psi, &sample);
            (
                res / (0.5 * self.chord * t.w.max(f64::MIN_POSITIVE)),
                d_res,
                res,
            )
        };
        let psi0 = self.psi_undisturbed();
        let mut psi = guess.unwrap_or_else(|| psi0.max(self.blade_angle));
        for _ in 0..MAX_NEWTON_ITERATIONS {
            let (scaled, d_res, res) = eval(psi);
            if !(res.is_finite() && d_res.is_finite() && d_res != 0.0) {
                break;
            }
            let step = (-res / d_res).clamp(-MAX_NEWTON_STEP, MAX_NEWTON_STEP);
            psi += step;
            if step.abs() < PSI_TOLERANCE && scaled.abs() <= RESIDUAL_TOLERANCE {
                return Some(psi);
            }
        }
        self.bracketed(psi0, |p| eval(p).0)
    }

    /// The bracketed fallback: scan from the undisturbed ψ towards the side where the residual
    /// changes sign, then refine (Illinois).
    fn bracketed(&self, psi0: f64, mut scaled: impl FnMut(f64) -> f64) -> Option<f64> {
        let r0 = scaled(psi0);
        if r0 == 0.0 {
            return Some(psi0);
        }
        let (direction, limit) = if r0 < 0.0 {
            (1.0, PI)
        } else {
            (-1.0, -FRAC_PI_2)
        };
        let mut a = (psi0, r0);
        loop {
            let next = a.0 + direction * SCAN_STEP;
            if (next - limit) * direction > 0.0 {
                return None;
            }
            let b = (next, scaled(next));
            if !b.1.is_finite() {
                return None;
            }
            if b.1 * a.1 <= 0.0 {
                let psi = bracketed_root(
                    |p| Ok::<f64, ()>(scaled(p)),
                    a,
                    b,
                    PSI_TOLERANCE,
                    MAX_BRACKET_ITERATIONS,
                )
                .ok()?;
                return (scaled(psi).abs() <= RESIDUAL_TOLERANCE).then_some(psi);
            }
            a = b;
        }
    }
}

#[cfg(test)]
mod tests {
    //! The analytic derivative of the residual against central differences (the ping test),
    //! and the solution against the actuator-disc limit.

    use super::*;

    /// A thin-airfoil section: c_l = 2π sin(α − α0) up to stall-free, c_d constant.
    fn section(alpha: f64) -> SectionSample {
        let alpha0 = (-3.5f64).to_radians();
        SectionSample {
            cl: 2.0 * PI * (alpha - alpha0).sin(),
            cl_alpha: 2.0 * PI * (alpha - alpha0).cos(),
            cd: 0.01,
        }
    }

    fn flows() -> [AnnulusFlow; 3] {
        let base = AnnulusFlow {
            axial: 0.0,
            tangential: 150.0,
            x: 0.7,
            radius: 0.6,
            chord: 0.1,
            blade_angle: 20f64.to_radians(),
            blades: 3.0,
        };
        [
            base,
            // Cruise-like and windmilling (blade angle below the inflow angle).
            AnnulusFlow {
                axial: 31.0,
                ..base
            },
            AnnulusFlow {
                axial: 60.0,
                blade_angle: 5f64.to_radians(),
                x: 0.95,
                ..base
            },
        ]
    }

    #[test]
    fn residual_derivative_matches_central_differences() {
        let h = 1e-6;
        for flow in flows() {
            let psi0 = flow.psi_undisturbed();
            for dpsi in [-0.2, 0.05, 0.15, 0.3, 0.6] {
                let psi = psi0 + dpsi;
                let at = |p: f64| flow.residual(p, &section(flow.triangle(p).alpha));
                let (_, d) = at(psi);
                let fd = (at(psi + h).0 - at(psi - h).0) / (2.0 * h);
                let scale = d.abs().max(fd.abs()).max(1.0);
                assert!(
                    (d - fd).abs() <= 1e-6 * scale,
                    "V {} ψ {psi}: analytic {d} vs central {fd}",
                    flow.axial
                );
            }
        }
    }

    #[test]
    fn converged_annulus_satisfies_both_relations() {
        for flow in flows() {
            let psi = flow
                .solve(None, |alpha, _| section(alpha))
                .expect("converges");
            let t = flow.triangle(psi);
            let (res, _) = flow.residual(psi, &section(t.alpha));
            assert!(res.abs() < 1e-6 * 0.5 * flow.chord * t.w, "residual {res}");
            // The start from a neighbouring solution gives the same root.
            let again = flow
                .solve(Some(psi + 0.01), |alpha, _| section(alpha))
                .unwrap();
            assert!((again - psi).abs() < 1e-7, "{again} vs {psi}");
        }
    }

    #[test]
    fn static_annulus_obeys_momentum_theory_without_tip_loss() {
        // Far inboard (F = 1, swirl small) at rest the annulus momentum balance is
        // dT = 4πrρ·v_a²·dr per unit radius, with dT from the blade elements.
        let flow = AnnulusFlow {
            axial: 0.0,
            tangential: 100.0,
            x: 0.4,
            radius: 0.4,
            chord: 0.08,
            blade_angle: 12f64.to_radians(),
            blades: 2.0,
        };
        let psi = flow.solve(None, |alpha, _| section(alpha)).unwrap();
        let t = flow.triangle(psi);
        let s = section(t.alpha);
        let thrust_per_radius =
            0.5 * t.w * t.w * flow.blades * flow.chord * (s.cl * t.phi.cos() - s.cd * t.phi.sin());
        let momentum = 4.0 * PI * flow.radius * t.wa * t.wa;
        assert!(
            (thrust_per_radius / momentum - 1.0).abs() < 0.02,
            "{thrust_per_radius} vs {momentum}"
        );
    }
}
