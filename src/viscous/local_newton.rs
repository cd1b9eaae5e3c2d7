//! The local Newton iteration of one boundary-layer station, shared by the initial march
//! (XFOIL xbl.f MRCHUE, [`super::march`]) and the mixed-mode re-march (MRCHDU,
//! [`super::remarch`]).
//!
//! A march solves each station on its own, the upstream station held fixed: the three interval
//! (or similarity, or junction) equations in the station's four unknowns (√Cτ or N, θ, δ*, Ue)
//! together with a fourth, prescribed row — Ue itself (direct mode), Hk (inverse mode) or a
//! combination of both (mixed mode). Every iteration solves that 4×4 system and takes the step
//! relaxed so that its largest relative change stays below a limit (XFOIL's DMAX limiting).
//! The marches differ in the fourth row, in how they measure a step and in the limits they put
//! on the unknowns; those are the [`LocalProblem`] of a march.

use crate::numerics::small_dense::solve;

/// One evaluation of a station's local system.
pub(super) enum Evaluation {
    /// The rows of J·Δ = r in the unknowns (s, θ, δ*, Ue): the three boundary-layer equations
    /// and the march's prescribed fourth row.
    System([[f64; 4]; 4], [f64; 4]),
    /// The station changed regime while evaluating: evaluate again (counts as an iteration).
    Again,
    /// The equations cannot be evaluated at these unknowns: the iteration ends.
    Failed,
}

/// Whether the iteration goes on after a step.
pub(super) enum Next {
    /// Evaluate again.
    Continue,
    /// Converged, or the unknowns left the equations' range: the iteration ends.
    Stop,
}

/// A station's local problem as one march poses it; the station's unknowns live in the
/// implementing type.
pub(super) trait LocalProblem {
    /// The local system at the current unknowns in iteration `iteration` (0-based).
    fn evaluate(&mut self, iteration: usize) -> Evaluation;

    /// The largest relative change of the Newton step `dx`, which the relaxation limits.
    fn largest_change(&self, dx: &[f64; 4]) -> f64;

    /// A factor on the relaxation of step `dx`: 1 unless the march damps oscillations.
    fn damping(&mut self, _dx: &[f64; 4]) -> f64 {
        1.0
    }

    /// Takes the step `rlx·dx` with the march's limits on the unknowns; `largest` is the
    /// unrelaxed largest relative change of the step.
    fn step(&mut self, dx: &[f64; 4], rlx: f64, largest: f64) -> Next;
}

/// Runs the local Newton iteration of `problem`: at most `max_iterations` evaluations, each
/// step relaxed so that its largest relative change is at most `max_step`. It ends early when
/// the equations cannot be evaluated, the system is singular, or the problem says so.
pub(super) fn iterate(problem: &mut impl LocalProblem, max_iterations: usize, max_step: f64) {
    for iteration in 0..max_iterations {
        let (a, b) = match problem.evaluate(iteration) {
            Evaluation::System(a, b) => (a, b),
            Evaluation::Again => continue,
            Evaluation::Failed => break,
        };
        let Some(dx) = solve(a, b) else { break };
        let largest = problem.largest_change(&dx);
        let rlx = problem.damping(&dx)
            * if largest > max_step {
                max_step / largest
            } else {
                1.0
            };
        if let Next::Stop = problem.step(&dx, rlx, largest) {
            break;
        }
    }
}

/// The three equation rows of a local system: J·Δ = −R in (s, θ, δ*, Ue), the fourth row left
/// for the march to prescribe.
pub(super) fn equation_rows(res: &[f64; 3], jac: &[[f64; 4]; 3]) -> ([[f64; 4]; 4], [f64; 4]) {
    let mut a = [[0.0; 4]; 4];
    let mut b = [0.0; 4];
    for r in 0..3 {
        a[r] = jac[r];
        b[r] = -res[r];
    }
    (a, b)
}
