//! Parameters of a viscous solution: the flow condition, the trips and the controls of the
//! Newton iteration and of the marches.

use super::error::ViscousError;
use super::march::MarchParams;
use super::update::UpdateLimits;
use crate::boundary_layer::{BlConditions, BlModel, BlParams};

/// Parameters of a viscous solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViscousParams {
    /// Chord Reynolds number V∞c/ν.
    pub reynolds: f64,
    /// Free-stream Mach number (Karman–Tsien compressibility).
    pub mach: f64,
    /// Critical amplification ratio of the e^n method (XFOIL default 9).
    pub ncrit: f64,
    /// Forced transition x/c on the upper surface (≥ 1 = free transition).
    pub xtr_top: f64,
    /// Forced transition x/c on the lower surface (≥ 1 = free transition).
    pub xtr_bot: f64,
    /// Newton iteration cap per attempt.
    pub max_iterations: u32,
    /// Convergence threshold on the RMS relative Newton change. XFOIL's EPS1 is 1e-4; the
    /// default here is 1e-3. Newton converges quadratically at this stage, so the change a
    /// further iteration would make is far smaller: logged over the four default rotor grids,
    /// its median was 8e-7 and its 99th percentile 5e-5 (largest 9e-4, a slowly converging
    /// stall point). Against 1e-4, the points of those grids moved by a median |ΔCl| of 1e-8
    /// (99th percentile 1.5e-5) and |ΔCd|/Cd of 1e-7 (4e-5), except stall points that changed
    /// branch; the agreement with XFOIL's printed polars moved by ≤ 0.001 % in the median
    /// |ΔCd|/Cd and ≤ 4e-7 in the largest |ΔCl| (`tests/viscous_polars.rs`). The paper's free
    /// sweep needs 179 Newton iterations instead of 275.
    pub tolerance: f64,
    /// Relaxation and clipping limits of the update (XFOIL UPDATE).
    pub limits: UpdateLimits,
    /// Controls of the initial march (XFOIL MRCHUE).
    pub march: MarchParams,
    /// The mixed-mode re-march before each Newton iteration (XFOIL MRCHDU) is skipped once the
    /// RMS relative Newton change is below this value (0 = always re-march, as XFOIL).
    pub remarch_below: f64,
    /// In warm-started attempts, the re-march starts turbulent and wake stations from their
    /// upstream station's corrections ([`MarchParams::carried_correction_limit`]) after a Newton
    /// step whose RMS relative change was below this value. After larger steps (the first
    /// iteration of an attempt, and the wandering iterations of hard points) and in fresh
    /// starts, XFOIL's plain start is kept: with the carried start there too, hard points at
    /// Re 2.5e5 (NACA 8-H-12 xtr 0.07, M 0.2, α 12–18°; NACA 23012 free, M 0.3, α 11–16°)
    /// wandered onto a branch with 6–8 % less lift than XFOIL's, which they had followed, and
    /// the fresh start of the 8-H-12 at Re 5e5, M 0.3, α 0° no longer converged.
    pub carry_corrections_below: f64,
    /// Lowest accepted pressure (form) drag cd − cdf. A Newton-converged state whose
    /// Squire–Young drag lies further below its skin-friction drag has negative form drag: a
    /// spurious solution branch (seen in negative stall), reported as not converged so that a
    /// sweep retries the point. −2e-4 leaves room for the round-off of attached flow, where the
    /// form drag is near zero.
    pub min_pressure_drag: f64,
    /// Largest relative change of a Newton step (XFOIL RMXBL) above which the step is taken to
    /// come from a near-singular system (stagnation point almost on a node); the next
    /// iteration then goes without the stagnation-point terms of ξ.
    pub exploded_step: f64,
}

impl Default for ViscousParams {
    fn default() -> Self {
        Self {
            reynolds: 1.0e6,
            mach: 0.0,
            ncrit: 9.0,
            xtr_top: 1.0,
            xtr_bot: 1.0,
            max_iterations: 100,
            tolerance: 1e-3,
            limits: UpdateLimits::default(),
            march: MarchParams::default(),
            remarch_below: 0.0,
            carry_corrections_below: 1.0,
            min_pressure_drag: -2e-4,
            exploded_step: 1e6,
        }
    }
}

impl ViscousParams {
    /// The defaults at one flow condition: Reynolds number, Mach number, and transition forced
    /// at x/c = `xtr` on both surfaces (1 = free transition).
    pub fn at(reynolds: f64, mach: f64, xtr: f64) -> Self {
        Self {
            reynolds,
            mach,
            xtr_top: xtr,
            xtr_bot: xtr,
            ..Self::default()
        }
    }

    /// Rejects non-physical parameters.
    pub(crate) fn check(&self) -> Result<(), ViscousError> {
        let params = self;
        for (name, value, ok) in [
            ("reynolds", params.reynolds, params.reynolds > 0.0),
            ("mach", params.mach, (0.0..1.0).contains(&params.mach)),
            ("ncrit", params.ncrit, params.ncrit > 0.0),
            ("xtr_top", params.xtr_top, params.xtr_top >= 0.0),
            ("xtr_bot", params.xtr_bot, params.xtr_bot >= 0.0),
            ("tolerance", params.tolerance, params.tolerance > 0.0),
        ] {
            if !(value.is_finite() && ok) {
                return Err(ViscousError::BadParameter { name, value });
            }
        }
        Ok(())
    }

    /// The boundary-layer model of the flow condition, with XFOIL's closure constants.
    pub(crate) fn boundary_layer(&self) -> Result<BlModel, ViscousError> {
        let conditions = BlConditions {
            reynolds: self.reynolds,
            mach: self.mach,
            ncrit: self.ncrit,
        };
        BlModel::new(&conditions, BlParams::default()).map_err(ViscousError::FlowConditions)
    }
}
