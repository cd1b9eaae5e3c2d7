//! Propeller and engine: a blade-element–momentum (BEMT) propeller built from its blade
//! geometry and a section polar table, driven through a reduction gear by an engine with a
//! full-throttle torque curve.
//!
//! * `annulus` — one annulus: Drela's QPROP velocity-triangle formulation with Prandtl's tip
//!   factor and swirl, solved for its one unknown.
//! * [`Propeller`] — the blade (diameter, blades, chord and twist against radius, the section)
//!   summed over annuli: thrust and torque at airspeed V and speed n, with J = V/(nD),
//!   C_T = T/(ρn²D⁴), C_P = P/(ρn³D⁵), η = J·C_T/C_P (McCormick, *Aerodynamics, Aeronautics
//!   and Flight Mechanics*, 2nd ed., ch. 6).
//! * [`Powerplant`] — propeller and [`Engine`]: the pitch that the one calibration point needs,
//!   the engine rpm for a thrust (trim), and the full-throttle equilibrium (takeoff, static
//!   thrust), where the propeller absorbs the shaft torque the engine delivers:
//!   Q_prop(V, n) = η·Q_e(n/i)/i.
//!
//! What the propeller is told and what it predicts: the geometry (shape of the chord and twist
//! distributions, diameter, blades) and the section come from the preset; the blade angle at
//! 0.75 R is the one calibrated value, set so that the propeller gives the calibration thrust
//! at the calibration airspeed and engine rpm. Everything else — thrust at other rpm and
//! speeds, the full-throttle rpm, the static thrust — is predicted.

mod annulus;
mod sections;

use super::aircraft::{Aircraft, BladeGeometry};
use super::atmosphere::Atmosphere;
use super::engine::Engine;
use super::KT_TO_MS;
use crate::numerics::roots::bracketed_root;
use annulus::{AnnulusFlow, SectionSample};
use sections::StationSection;
pub use sections::{PropellerSections, SectionsError, SharedSection};

/// Errors of the propeller and powerplant models.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PropellerError {
    /// No blade angle gives the calibration thrust.
    #[error("propeller calibration impossible: {0}")]
    Calibration(&'static str),
    /// The momentum and blade-element relations of an annulus have no common solution.
    #[error(
        "propeller annulus at r/R = {r_over_r:.3} not converged (V = {airspeed_ms:.1} m/s, \
         {rev_per_s:.1} rev/s)"
    )]
    NotConverged {
        /// Radius fraction of the annulus.
        r_over_r: f64,
        /// Airspeed \[m/s\].
        airspeed_ms: f64,
        /// Propeller speed \[rev/s\].
        rev_per_s: f64,
    },
    /// The requested thrust needs more than the engine's maximum rpm.
    #[error(
        "propeller thrust {thrust_n:.0} N needs more than the maximum {max_rpm:.0} engine rpm"
    )]
    Unavailable {
        /// Thrust requested \[N\].
        thrust_n: f64,
        /// Maximum engine rpm.
        max_rpm: f64,
    },
    /// The preset holds no propeller section (it was not loaded from a file).
    #[error("the aircraft has no propeller section table")]
    NoSection,
}

/// Step of the forward difference that gives ∂c_l/∂α from the table \[deg\] (the table's
/// monotone cubic is C¹, so the difference is smooth in α).
const LIFT_SLOPE_STEP_DEG: f64 = 0.01;

/// Blade-angle range searched by the calibration \[deg\].
const CALIBRATION_PITCH_RANGE_DEG: (f64, f64) = (0.0, 60.0);

/// Scan step of the calibration's blade angle \[deg\].
const CALIBRATION_PITCH_STEP_DEG: f64 = 2.0;

/// Tolerance of the calibrated blade angle \[rad\].
const PITCH_TOLERANCE: f64 = 1e-9;

/// Tolerance of the engine rpm solves \[rpm\] (a thrust change of about 10⁻⁵).
const RPM_TOLERANCE: f64 = 1e-2;

/// Lowest engine rpm searched by the rpm solves.
const MIN_ENGINE_RPM: f64 = 500.0;

/// Most secant steps from a previous full-throttle equilibrium before the bracketed solve.
const SECANT_ITERATIONS: usize = 8;

/// Most evaluations of each bracketed solve.
const MAX_SOLVE_ITERATIONS: usize = 100;

/// One annulus of the discretised blade.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Station {
    /// Radius fraction at the annulus centre.
    x: f64,
    /// Width \[m\].
    dr: f64,
    /// Chord \[m\].
    chord: f64,
    /// Blade angle relative to the one at 0.75 R \[rad\].
    twist: f64,
    /// The annulus's section (its place in a family by thickness ratio).
    section: StationSection,
}

/// A fixed-pitch propeller: blade geometry, section and blade angle.
#[derive(Clone)]
pub struct Propeller {
    /// Diameter D \[m\].
    pub diameter: f64,
    /// Number of blades B.
    pub blades: u32,
    /// Blade angle of the section chord line at 0.75 R from the plane of rotation \[rad\].
    pub pitch_075: f64,
    stations: Vec<Station>,
    sections: PropellerSections,
}

impl std::fmt::Debug for Propeller {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Propeller")
            .field("diameter", &self.diameter)
            .field("blades", &self.blades)
            .field("pitch_075", &self.pitch_075)
            .field("stations", &self.stations)
            .finish_non_exhaustive()
    }
}

/// A propeller operating point.
#[derive(Clone, Debug, PartialEq)]
pub struct PropellerPoint {
    /// Airspeed V \[m/s\].
    pub airspeed: f64,
    /// Speed n \[rev/s\].
    pub rev_per_s: f64,
    /// Thrust T \[N\].
    pub thrust: f64,
    /// Shaft torque Q \[N m\].
    pub torque: f64,
    /// Advance ratio J = V/(nD).
    pub advance_ratio: f64,
    /// Thrust coefficient C_T = T/(ρn²D⁴).
    pub thrust_coefficient: f64,
    /// Power coefficient C_P = 2πQ/(ρn²D⁵).
    pub power_coefficient: f64,
    /// Share of the annuli whose section lookup was clamped to the table's Re or Mach range.
    pub clamped_fraction: f64,
    /// Share of the annuli beyond the table's computed α range (360° extension: stalled).
    pub post_stall_fraction: f64,
    /// Share of the annuli whose section data lean on supercritical table points.
    pub supercritical_fraction: f64,
    /// Share of the annuli at whose α the table's points are in massive separation (the 360°
    /// extension stands in for them; counted in `post_stall_fraction` too).
    pub separated_fraction: f64,
    /// Share of the annuli whose section lookup bridged unconverged table points.
    pub bridged_fraction: f64,
    /// ψ of each annulus (the warm start of a neighbouring point).
    psi: Vec<f64>,
}

impl PropellerPoint {
    /// Propulsive efficiency η = J·C_T/C_P (0 at rest).
    pub fn efficiency(&self) -> f64 {
        self.advance_ratio * self.thrust_coefficient / self.power_coefficient
    }

    /// Shaft power P = 2πnQ \[W\].
    pub fn power(&self) -> f64 {
        2.0 * std::f64::consts::PI * self.rev_per_s * self.torque
    }
}

/// Linear interpolation in `(xs, ys)`, extrapolating the end intervals.
fn interpolate(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    let n = xs.len();
    if n == 1 {
        return ys[0];
    }
    let k = xs.partition_point(|&v| v <= x).clamp(1, n - 1);
    let t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
    ys[k - 1] + t * (ys[k] - ys[k - 1])
}

impl Propeller {
    /// The propeller of blade `geometry` with `sections` at blade angle `pitch_075` \[rad\] at
    /// 0.75 R. The blade runs from the first station to the tip in `geometry.annuli` equal
    /// annuli; chord, twist and thickness ratio are linear between stations, the last
    /// interval continued to the tip; each annulus reads the sections at its thickness ratio
    /// ([`PropellerSections`]; a blade without thickness ratios, or one section, reads the
    /// thinnest everywhere).
    pub fn new(geometry: &BladeGeometry, sections: PropellerSections, pitch_075: f64) -> Self {
        let (x, c, tw) = (
            &geometry.r_over_r,
            &geometry.chord_over_diameter,
            &geometry.twist_deg,
        );
        let root = x[0];
        let n = geometry.annuli.max(1);
        let dx = (1.0 - root) / n as f64;
        let radius = 0.5 * geometry.diameter_m;
        let twist_075 = interpolate(x, tw, 0.75);
        let stations = (0..n)
            .map(|k| {
                let xc = root + (k as f64 + 0.5) * dx;
                let thickness = geometry
                    .thickness_ratio
                    .as_ref()
                    .map_or(f64::NAN, |t| interpolate(x, t, xc));
                Station {
                    x: xc,
                    dr: dx * radius,
                    chord: interpolate(x, c, xc).max(0.0) * geometry.diameter_m,
                    twist: (interpolate(x, tw, xc) - twist_075).to_radians(),
                    section: sections.at(thickness),
                }
            })
            .collect();
        Self {
            diameter: geometry.diameter_m,
            blades: geometry.blades,
            pitch_075,
            stations,
            sections,
        }
    }

    /// The same propeller at blade angle `pitch_075` \[rad\].
    pub fn with_pitch(&self, pitch_075: f64) -> Self {
        Self {
            pitch_075,
            ..self.clone()
        }
    }

    /// Thrust and torque at airspeed `v` \[m/s\] and `rev_per_s` in `air`.
    pub fn operate(
        &self,
        air: &Atmosphere,
        v: f64,
        rev_per_s: f64,
    ) -> Result<PropellerPoint, PropellerError> {
        self.operate_from(air, v, rev_per_s, None)
    }

    /// [`operate`](Self::operate) starting each annulus from a neighbouring point's solution.
    fn operate_from(
        &self,
        air: &Atmosphere,
        v: f64,
        rev_per_s: f64,
        warm: Option<&PropellerPoint>,
    ) -> Result<PropellerPoint, PropellerError> {
        let omega = 2.0 * std::f64::consts::PI * rev_per_s;
        let radius = 0.5 * self.diameter;
        let blades = f64::from(self.blades);
        let (mut thrust, mut torque) = (0.0, 0.0);
        let (mut clamped, mut stalled, mut supercritical) = (0usize, 0usize, 0usize);
        let mut separated = 0usize;
        let mut bridged = 0usize;
        let mut psis = Vec::with_capacity(self.stations.len());
        let sections = &self.sections;
        for (k, s) in self.stations.iter().enumerate() {
            let r = s.x * radius;
            let flow = AnnulusFlow {
                axial: v,
                tangential: omega * r,
                x: s.x,
                radius: r,
                chord: s.chord,
                blade_angle: self.pitch_075 + s.twist,
                blades,
            };
            let re_per_speed = air.density * s.chord / air.viscosity;
            let lookup = |alpha: f64, w: f64| {
                let (re, mach) = (re_per_speed * w, w / air.speed_of_sound);
                sections.lookup(&s.section, alpha.to_degrees(), re, mach)
            };
            let sample_at = |alpha: f64, w: f64| {
                let l = lookup(alpha, w);
                let l2 = lookup(alpha + LIFT_SLOPE_STEP_DEG.to_radians(), w);
                SectionSample {
                    cl: l.cl,
                    cl_alpha: (l2.cl - l.cl) / LIFT_SLOPE_STEP_DEG.to_radians(),
                    cd: l.cd,
                }
            };
            let guess = warm.and_then(|p| p.psi.get(k).copied());
            let psi = flow
                .solve(guess, sample_at)
                .ok_or(PropellerError::NotConverged {
                    r_over_r: s.x,
                    airspeed_ms: v,
                    rev_per_s,
                })?;
            let t = flow.triangle(psi);
            let l = lookup(t.alpha, t.w);
            clamped += usize::from(l.re_clamped || l.mach_clamped);
            stalled += usize::from(l.post_stall);
            supercritical += usize::from(l.supercritical);
            separated += usize::from(l.massive_separation);
            bridged += usize::from(l.bridged);
            // Blade-element loads per unit radius of all blades (Kutta–Joukowski with the
            // converged circulation): ½ρW²Bc(c_l cos φ − c_d sin φ) and ×r for the torque.
            let q = 0.5 * air.density * t.w * t.w * blades * s.chord * s.dr;
            let (sp, cp) = t.phi.sin_cos();
            thrust += q * (l.cl * cp - l.cd * sp);
            torque += q * (l.cl * sp + l.cd * cp) * r;
            psis.push(psi);
        }
        let count = self.stations.len().max(1) as f64;
        let n2d4 = air.density * rev_per_s * rev_per_s * self.diameter.powi(4);
        Ok(PropellerPoint {
            airspeed: v,
            rev_per_s,
            thrust,
            torque,
            advance_ratio: v / (rev_per_s * self.diameter),
            thrust_coefficient: thrust / n2d4,
            power_coefficient: 2.0 * std::f64::consts::PI * torque / (n2d4 * self.diameter),
            clamped_fraction: clamped as f64 / count,
            post_stall_fraction: stalled as f64 / count,
            supercritical_fraction: supercritical as f64 / count,
            separated_fraction: separated as f64 / count,
            bridged_fraction: bridged as f64 / count,
            psi: psis,
        })
    }

    /// The blade angle at 0.75 R \[rad\] at which the propeller gives `thrust` \[N\] at airspeed
    /// `v` and `rev_per_s` in `air`: the smallest one, found by a scan upwards in 2° steps and
    /// refined (thrust rises with the blade angle until the blade stalls, so the smallest
    /// solution is the attached-flow one). Blade angles at the bottom of the scan at which an
    /// annulus has no solution are passed over.
    pub fn pitch_for_thrust(
        &self,
        air: &Atmosphere,
        v: f64,
        rev_per_s: f64,
        thrust: f64,
    ) -> Result<f64, PropellerError> {
        let mut warm: Option<PropellerPoint> = None;
        let mut excess = |pitch: f64| -> Result<f64, PropellerError> {
            let p = self
                .with_pitch(pitch)
                .operate_from(air, v, rev_per_s, warm.as_ref())?;
            let e = p.thrust - thrust;
            warm = Some(p);
            Ok(e)
        };
        let (lo, hi) = CALIBRATION_PITCH_RANGE_DEG;
        let mut below: Option<(f64, f64)> = None;
        let mut deg = lo;
        while deg <= hi {
            let pitch = deg.to_radians();
            match excess(pitch) {
                Ok(e) if e < 0.0 => below = Some((pitch, e)),
                Ok(e) => {
                    let Some(below) = below else {
                        return Err(PropellerError::Calibration(
                            "the propeller gives the calibration thrust already at the \
                             smallest blade angle it can be solved at",
                        ));
                    };
                    return bracketed_root(
                        excess,
                        below,
                        (pitch, e),
                        PITCH_TOLERANCE,
                        MAX_SOLVE_ITERATIONS,
                    );
                }
                // The smallest blade angles put the outer annuli deep into negative α, where
                // an annulus may have no momentum solution (a windmilling, stalled tip): far
                // below the calibration thrust, so the scan goes on upwards.
                Err(PropellerError::NotConverged { .. }) if below.is_none() => {}
                Err(e) => return Err(e),
            }
            deg += CALIBRATION_PITCH_STEP_DEG;
        }
        Err(PropellerError::Calibration(
            "no blade angle between 0° and 60° gives the calibration thrust",
        ))
    }
}

/// The full-throttle equilibrium at one airspeed.
#[derive(Clone, Debug, PartialEq)]
pub struct FullThrottle {
    /// Engine rpm.
    pub engine_rpm: f64,
    /// The engine would run faster than its maximum rpm: it is held there (throttled back).
    pub rpm_limited: bool,
    /// d(Q_prop − η·Q_e/i)/d(rpm) at the equilibrium \[N m/rpm\] (0 when rpm-limited): the
    /// start of the next solve.
    pub slope: f64,
    /// The propeller at that rpm.
    pub propeller: PropellerPoint,
}

/// Propeller and engine of an aircraft, the propeller's blade angle calibrated.
#[derive(Clone, Debug)]
pub struct Powerplant {
    /// The propeller, at its calibrated blade angle.
    pub propeller: Propeller,
    /// The engine and gear.
    pub engine: Engine,
}

impl Powerplant {
    /// The powerplant of `aircraft`, its blade angle set by the preset's calibration point
    /// (thrust at airspeed and engine rpm, ISA sea level).
    pub fn from_aircraft(aircraft: &Aircraft) -> Result<Self, PropellerError> {
        let p = &aircraft.propeller;
        let sections = aircraft
            .propeller_sections()
            .ok_or(PropellerError::NoSection)?;
        let engine = Engine::from_params(&aircraft.engine);
        let propeller = Propeller::new(&p.blade, sections, 0.0);
        let pitch = propeller.pitch_for_thrust(
            &Atmosphere::isa(0.0),
            p.calib_speed_kt * KT_TO_MS,
            engine.propeller_rev_per_s(p.calib_engine_rpm),
            p.calib_thrust_n,
        )?;
        Ok(Self {
            propeller: propeller.with_pitch(pitch),
            engine,
        })
    }

    /// Engine rpm at which the propeller gives `thrust` \[N\] at airspeed `v` in `air`.
    pub fn engine_rpm_for_thrust(
        &self,
        air: &Atmosphere,
        v: f64,
        thrust: f64,
    ) -> Result<f64, PropellerError> {
        let mut warm: Option<PropellerPoint> = None;
        let mut excess = |rpm: f64| -> Result<f64, PropellerError> {
            let p = self.propeller.operate_from(
                air,
                v,
                self.engine.propeller_rev_per_s(rpm),
                warm.as_ref(),
            )?;
            let e = p.thrust - thrust;
            warm = Some(p);
            Ok(e)
        };
        let max = self.engine.max_rpm;
        let f_hi = excess(max)?;
        if f_hi < 0.0 {
            return Err(PropellerError::Unavailable {
                thrust_n: thrust,
                max_rpm: max,
            });
        }
        let f_lo = excess(MIN_ENGINE_RPM)?;
        if f_lo >= 0.0 {
            return Ok(MIN_ENGINE_RPM);
        }
        bracketed_root(
            excess,
            (MIN_ENGINE_RPM, f_lo),
            (max, f_hi),
            RPM_TOLERANCE,
            MAX_SOLVE_ITERATIONS,
        )
    }

    /// The full-throttle equilibrium at airspeed `v` in `air`: the engine rpm at which the
    /// propeller absorbs the shaft torque, Q_prop = η·Q_e/i (the torque surplus
    /// Q_prop − η·Q_e/i rises with rpm), held at the maximum rpm if the engine would run
    /// faster. From a nearby equilibrium `previous` (a takeoff's last step) secant steps start
    /// at its rpm with its slope; without one, or if they do not settle, a bracketed root over
    /// the whole rpm range.
    pub fn full_throttle(
        &self,
        air: &Atmosphere,
        v: f64,
        previous: Option<&FullThrottle>,
    ) -> Result<FullThrottle, PropellerError> {
        let max = self.engine.max_rpm;
        let mut warm = previous.map(|p| p.propeller.clone());
        let mut surplus = |rpm: f64| -> Result<(f64, PropellerPoint), PropellerError> {
            let p = self.propeller.operate_from(
                air,
                v,
                self.engine.propeller_rev_per_s(rpm),
                warm.as_ref(),
            )?;
            warm = Some(p.clone());
            Ok((p.torque - self.engine.shaft_torque(rpm), p))
        };
        let equilibrium = |rpm: f64, slope: f64, propeller: PropellerPoint| FullThrottle {
            engine_rpm: rpm,
            rpm_limited: false,
            slope,
            propeller,
        };
        if let Some(p) = previous.filter(|p| !p.rpm_limited && p.slope > 0.0) {
            let (mut a, mut ga) = (p.engine_rpm, surplus(p.engine_rpm)?.0);
            let mut slope = p.slope;
            for _ in 0..SECANT_ITERATIONS {
                let b = (a - ga / slope).clamp(MIN_ENGINE_RPM, max);
                let (gb, point) = surplus(b)?;
                if b != a {
                    slope = (gb - ga) / (b - a);
                }
                if (b - a).abs() < RPM_TOLERANCE && slope > 0.0 {
                    return Ok(equilibrium(b, slope, point));
                }
                if slope.is_nan() || slope <= 0.0 || (b == max && gb < 0.0) {
                    break;
                }
                (a, ga) = (b, gb);
            }
        }
        let (lo, hi) = (MIN_ENGINE_RPM, max);
        let (f_hi, at_max) = surplus(hi)?;
        if f_hi < 0.0 {
            return Ok(FullThrottle {
                engine_rpm: max,
                rpm_limited: true,
                slope: 0.0,
                propeller: at_max,
            });
        }
        let f_lo = surplus(lo)?.0;
        let rpm = if f_lo >= 0.0 {
            lo
        } else {
            bracketed_root(
                |rpm| surplus(rpm).map(|s| s.0),
                (lo, f_lo),
                (hi, f_hi),
                RPM_TOLERANCE,
                MAX_SOLVE_ITERATIONS,
            )?
        };
        // The slope for the next start, over a small step.
        let (g, point) = surplus(rpm)?;
        let step = 1.0;
        let g2 = surplus(rpm + step)?.0;
        Ok(equilibrium(rpm, (g2 - g) / step, point))
    }
}
