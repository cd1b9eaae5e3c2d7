//! Parameters of a viscous solution: the flow condition, the trips and the controls of the
//! Newton iteration and of the marches.

use super::error::ViscousError;
use super::march::MarchParams;
use super::update::UpdateLimits;
use crate::boundary_layer::{BlConditions, BlModel, BlParams};
use crate::section::Transition;

/// The boundary-layer models of the two sides, which differ in N_crit only: index 0 = upper
/// surface, 1 = lower surface and wake (XFOIL sets AMCRIT = ACRIT(IS) before it marches or
/// assembles side IS, and the wake is part of side 2).
pub(crate) type SideModels = [BlModel; 2];

/// Parameters of a viscous solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViscousParams {
    /// Chord Reynolds number V∞c/ν.
    pub reynolds: f64,
    /// Free-stream Mach number (Karman–Tsien compressibility).
    pub mach: f64,
    /// N_crit and trip location of each surface (XFOIL VPAR N, NT, NB, XTR).
    pub transition: Transition,
    /// Newton iteration cap per attempt.
    pub max_iterations: u32,
    /// Convergence threshold on the RMS relative Newton change (XFOIL EPS1 = 1e-4; 1e-3 here).
    /// Newton converges quadratically at this stage, so the change a further iteration would
    /// make is far below the threshold; what the looser threshold changes in the tables and
    /// in the agreement with XFOIL is measured in docs/performance.md.
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
    /// starts, XFOIL's plain start is kept: with the carried start there too, hard points
    /// past stall at low Reynolds numbers wandered onto another solution branch than the one
    /// XFOIL follows, and some fresh starts no longer converged.
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
    /// A warm start begins from the previous converged state moved along its tangent to the
    /// new α (an Euler predictor, see `viscous::tangent`; not in XFOIL) instead of from that
    /// state itself.
    pub tangent_predictor: bool,
    /// Newton iteration cap of an attempt from a predicted state; one that has not converged
    /// by then is repeated from the converged state itself (with `max_iterations`).
    pub predicted_iterations: u32,
    /// An attempt stops as failed once its RMS relative Newton changes repeat twice, to six
    /// digits, with a period of at most this many iterations: the iteration is caught in a
    /// cycle (or sits on a fixed point above the tolerance) and would run to its cap without
    /// converging. Not in XFOIL; 0 turns the check off. On the shipped tables no attempt that
    /// converges triggers it (docs/performance.md).
    pub cycle_period: u32,
}

impl Default for ViscousParams {
    fn default() -> Self {
        Self {
            reynolds: 1.0e6,
            mach: 0.0,
            transition: Transition::default(),
            max_iterations: 100,
            tolerance: 1e-3,
            limits: UpdateLimits::default(),
            march: MarchParams::default(),
            remarch_below: 0.0,
            carry_corrections_below: 1.0,
            min_pressure_drag: -2e-4,
            exploded_step: 1e6,
            tangent_predictor: true,
            predicted_iterations: 30,
            cycle_period: 16,
        }
    }
}

impl ViscousParams {
    /// The defaults at one flow condition: Reynolds number, Mach number, and transition forced
    /// at x/c = `xtr` on both surfaces (1 = free transition), N_crit 9.
    pub fn at(reynolds: f64, mach: f64, xtr: f64) -> Self {
        Self {
            reynolds,
            mach,
            transition: Transition::tripped(xtr),
            ..Self::default()
        }
    }

    /// Rejects non-physical parameters; the transition setting by its own rule
    /// ([`Transition::check`]).
    pub(crate) fn check(&self) -> Result<(), ViscousError> {
        let params = self;
        for (name, value, ok) in [
            ("reynolds", params.reynolds, params.reynolds > 0.0),
            ("mach", params.mach, (0.0..1.0).contains(&params.mach)),
            ("tolerance", params.tolerance, params.tolerance > 0.0),
        ] {
            if !(value.is_finite() && ok) {
                return Err(ViscousError::BadParameter { name, value });
            }
        }
        self.transition
            .check()
            .map_err(|e| ViscousError::BadParameter {
                name: e.field.name(),
                value: e.value,
            })
    }

    /// The boundary-layer models of the flow condition, with XFOIL's closure constants, one per
    /// side ([`SideModels`]).
    pub(crate) fn boundary_layer(&self) -> Result<SideModels, ViscousError> {
        let model = |ncrit: f64| {
            let conditions = BlConditions {
                reynolds: self.reynolds,
                mach: self.mach,
                ncrit,
            };
            BlModel::new(&conditions, BlParams::default()).map_err(ViscousError::FlowConditions)
        };
        Ok([
            model(self.transition.ncrit_top)?,
            model(self.transition.ncrit_bot)?,
        ])
    }
}
