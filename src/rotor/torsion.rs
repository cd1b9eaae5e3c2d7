//! Elastic torsion of the blade under its lift: a blade whose lift acts off its centre of
//! gravity twists in proportion to the load (Wheatley, NACA Report 487, 1934, p. 13: on the
//! PCA-2 "the blade lift is offset from the center of gravity of the blade and causes a
//! torsional deflection in flight which in this case amounts to approximately 2.4°
//! (0.0419 radian) at the tip", which is why its pitch was measured in flight).
//!
//! The blade's twist given in the planform is the one measured under a reference load (the
//! rotor thrust of the flights the pitch was measured in). The torsion is taken as the
//! steady (azimuth-mean) part only, proportional to the rotor thrust with the spanwise shape
//! fixed: zero inboard of `from_r_over_r`, linear from there to `tip` at the tip at the
//! reference thrust. At thrust T the pitch is the planform's plus
//! `tip · (T / reference_thrust − 1) · shape(r/R)`: unchanged at the reference thrust, less
//! twisted below it. The once-per-revolution part of the torsion is not modelled, and the
//! linear law is not extrapolated beyond [`MAX_LOAD_RATIO`] times the reference thrust.

/// Largest thrust ratio T/T_ref the torsion follows: the torsion is held at this multiple of
/// the measured one above it. The rotor-speed searches start far above any autorotative speed,
/// where the thrust is many times the measured one and a linear torsion would turn the blade
/// by tens of degrees; twice the measured load is the guard.
pub const MAX_LOAD_RATIO: f64 = 2.0;

/// Elastic torsion of the blade: the torsion at the tip at a reference thrust and its shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElasticTorsion {
    /// Torsion at the tip at the reference thrust, positive nose-up \[rad\].
    pub tip: f64,
    /// Rotor thrust under which the planform's twist was measured \[N\].
    pub reference_thrust: f64,
    /// Radius fraction inboard of which the blade does not twist; the torsion grows linearly
    /// from there to the tip.
    pub from_r_over_r: f64,
}

impl ElasticTorsion {
    /// Change of the pitch at radius fraction `x` from the planform's (measured at the
    /// reference thrust) when the rotor carries `thrust` \[N\] (held within 0 …
    /// twice the reference, `MAX_LOAD_RATIO`) \[rad\].
    pub fn pitch_change(&self, x: f64, thrust: f64) -> f64 {
        let span = 1.0 - self.from_r_over_r;
        let shape = if span > 0.0 {
            ((x - self.from_r_over_r) / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        self.tip * ((thrust / self.reference_thrust).clamp(0.0, MAX_LOAD_RATIO) - 1.0) * shape
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_change_at_the_reference_thrust_and_linear_in_thrust_and_radius() {
        let t = ElasticTorsion {
            tip: 2.4_f64.to_radians(),
            reference_thrust: 10_000.0,
            from_r_over_r: 0.4,
        };
        assert_eq!(t.pitch_change(1.0, 10_000.0), 0.0);
        assert_eq!(t.pitch_change(0.3, 5_000.0), 0.0);
        // Half the reference thrust: half the tip torsion taken off at the tip, a quarter of
        // it halfway out along the twisting part.
        let tip = t.pitch_change(1.0, 5_000.0);
        assert!((tip + 1.2_f64.to_radians()).abs() < 1e-15, "{tip}");
        let mid = t.pitch_change(0.7, 5_000.0);
        assert!((mid + 0.6_f64.to_radians()).abs() < 1e-15, "{mid}");
        // No load: no torsion at all (the planform's twist less the reference torsion).
        assert!((t.pitch_change(1.0, 0.0) + 2.4_f64.to_radians()).abs() < 1e-15);
        // Beyond twice the reference load the torsion stays at twice the measured one.
        let held = t.pitch_change(1.0, 50_000.0);
        assert!((held - 2.4_f64.to_radians()).abs() < 1e-15, "{held}");
    }
}
