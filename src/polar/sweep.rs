//! α sweeps with warm starts and recovery of failed points.
//!
//! A sweep starts at the α nearest 0°, marches up, then restarts from the saved state at the
//! start point and marches down — the way XFOIL users run polars. A point that fails is retried
//! by sub-stepping from the last converged neighbour (half, then quarter steps), then from a fresh
//! start; if it still fails it is kept with `converged = false` and the march continues from the
//! last converged state, so one bad point does not poison its neighbours. A start point that
//! fails (it has no converged neighbour yet) is retried the same way from the first point above
//! it that converges, and the march down then starts from it. After a few failures
//! in a row (deep stall) the remaining points of the branch are solved once each, without the
//! costly recovery, and the recovery of one point stops once the point has used its budget of
//! Newton iterations, so a sweep's cost stays bounded. A solve that repeats one already done from
//! the same converged state along the same α path is not redone: its outcome is replayed.

use super::range::march_order;
use super::recovery::{recover, AnchorMemo};
use super::series::SeriesStates;
use crate::section::PolarPoint;

/// A point solver that can be marched along α with warm starts.
pub trait WarmStartSolver {
    /// Everything needed to resume from a solved point.
    type State: Clone;
    /// Solve at `alpha_deg`, warm-starting from the current state. The result and the state
    /// after it must depend on the current state and `alpha_deg` alone (a sweep replays the
    /// outcome of a solve it would repeat exactly).
    fn solve(&mut self, alpha_deg: f64) -> PolarPoint;
    /// Forget the warm-start state: the next solve starts from the inviscid solution.
    fn reset(&mut self);
    /// Snapshot of the current state.
    fn save(&self) -> Self::State;
    /// Return to a snapshot taken with [`save`](Self::save).
    fn restore(&mut self, state: &Self::State);
    /// Snapshot of the current state for a start at the same α under another condition (a
    /// grid's series, [`run_grid`](super::run_grid)); what only the march along α needs may
    /// be left out.
    fn series_state(&self) -> Self::State {
        self.save()
    }
}

/// Settings of the sweep's recovery of failed points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepParams {
    /// How many times the step from the last converged neighbour is halved when retrying a
    /// failed point (1 → a half step, 2 → also quarter steps).
    pub substep_levels: u32,
    /// Retry a failed point once more from a fresh (inviscid) start, after the sub-steps. The
    /// one place a fresh retry is decided: point solvers make one attempt per solve.
    pub fresh_retry: bool,
    /// After this many failures in a row along one branch (typically past stall), further
    /// points of that branch are still solved once each, but without the costly recovery.
    pub recover_limit: u32,
    /// Newton iterations one point may use, its first solve and its recovery together, as the
    /// solves report them ([`PolarPoint::iterations`]; a solve replayed from the anchor's
    /// memory costs nothing). The recovery makes no further solve once the point has used
    /// them, so a point costs at most this plus one solve.
    pub point_budget: u32,
    /// In a grid, a point its polar leaves unconverged is solved once more from the state its
    /// α converged to at the next lower Reynolds number of its series (the same Mach number
    /// and trips; [`run_grid`](super::run_grid)). The marches along α
    /// are not changed by it: every point they converge is the same with it or without.
    pub series_retry: bool,
}

impl Default for SweepParams {
    fn default() -> Self {
        Self {
            substep_levels: 2,
            fresh_retry: true,
            recover_limit: 3,
            point_budget: 500,
            series_retry: true,
        }
    }
}

/// Solve every α in `alphas` and return the points in the order of `alphas`.
pub fn sweep<S>(solver: &mut S, alphas: &[f64], params: &SweepParams) -> Vec<PolarPoint>
where
    S: WarmStartSolver + Send,
    S::State: Send,
{
    sweep_split(solver, None, alphas, params, false).0
}

/// What a march reads: the polar's α values and the recovery's settings, and whether it keeps
/// the states it converged to ([`SeriesStates`]).
struct Polar<'a> {
    alphas: &'a [f64],
    params: &'a SweepParams,
    keep_states: bool,
}

/// What a march writes: the point of each α it visits, and the states it converged to.
struct Marched<T> {
    points: Vec<Option<PolarPoint>>,
    states: SeriesStates<T>,
}

impl<T> Marched<T> {
    fn new(n: usize) -> Self {
        Self {
            points: vec![None; n],
            states: SeriesStates::default(),
        }
    }

    /// Takes over the points and states of another branch of the same polar.
    fn absorb(&mut self, other: Self) {
        for (mine, theirs) in self.points.iter_mut().zip(other.points) {
            if theirs.is_some() {
                *mine = theirs;
            }
        }
        self.states.merge(other.states);
    }
}

/// [`sweep`] with an optional second solver of the same condition. Once the start point has
/// converged, the upward branch continues on `solver` while the downward branch runs on
/// `second` (restored to the start point's state) in parallel (`rayon::join`). The points are
/// the same as [`sweep`]'s: each branch depends on the start point's state alone
/// ([`WarmStartSolver::solve`]). Without `second`, or when the start point failed (the
/// downward branch then depends on the upward one), the branches run one after the other.
///
/// With `keep_states`, the states the sweep converged to come back with its points (empty
/// otherwise).
pub(super) fn sweep_split<S>(
    solver: &mut S,
    second: Option<S>,
    alphas: &[f64],
    params: &SweepParams,
    keep_states: bool,
) -> (Vec<PolarPoint>, SeriesStates<S::State>)
where
    S: WarmStartSolver + Send,
    S::State: Send,
{
    let polar = Polar {
        alphas,
        params,
        keep_states,
    };
    let mut out = Marched::new(alphas.len());
    let (up, down) = march_order(alphas);
    if up.is_empty() {
        return (Vec::new(), out.states);
    }
    solver.reset();
    // The start point (the α nearest 0°) and the rest of the upward branch.
    let (start, rest) = (up[0], &up[1..]);
    let start_state = match march(solver, &polar, &up[..1], None, 0, &mut out) {
        Some((_, state)) => {
            let anchor = (alphas[start], state);
            match second {
                Some(mut other) if !down.is_empty() => {
                    let mut out_down = Marched::new(alphas.len());
                    let anchor_down = Some(anchor.clone());
                    rayon::join(
                        || march(solver, &polar, rest, Some(anchor), 0, &mut out),
                        || march_from(&mut other, &polar, &down, anchor_down, &mut out_down),
                    );
                    out.absorb(out_down);
                    return collect(out);
                }
                _ => {
                    let state = anchor.1.clone();
                    march(solver, &polar, rest, Some(anchor), 0, &mut out);
                    Some(state)
                }
            }
        }
        // The start point failed (it had no converged neighbour to start from): retry it warm
        // from the first converged point above it, with the usual recovery.
        None => match march(solver, &polar, rest, None, 1, &mut out) {
            Some((k, state)) => {
                let alpha = alphas[start];
                let from = (alphas[rest[k]], state);
                retry_start(solver, alpha, from, params).map(|(point, state)| {
                    out.points[start] = Some(point);
                    if keep_states {
                        out.states.insert(alpha, solver.series_state());
                    }
                    state
                })
            }
            None => None,
        },
    };
    if !down.is_empty() {
        // The downward branch starts from the start point's state (if it converged).
        let anchor = start_state.map(|s| (alphas[start], s));
        march_from(solver, &polar, &down, anchor, &mut out);
    }
    collect(out)
}

/// [`march`] from `anchor` with the solver set to its state first (reset without one).
fn march_from<S: WarmStartSolver>(
    solver: &mut S,
    polar: &Polar<'_>,
    order: &[usize],
    anchor: Option<(f64, S::State)>,
    out: &mut Marched<S::State>,
) {
    match &anchor {
        Some((_, s)) => solver.restore(s),
        None => solver.reset(),
    }
    march(solver, polar, order, anchor, 0, out);
}

/// The points of a sweep in the order of its α values, and the states it converged to.
fn collect<T>(out: Marched<T>) -> (Vec<PolarPoint>, SeriesStates<T>) {
    let points = out
        .points
        .into_iter()
        .map(|p| p.expect("every alpha visited once"))
        .collect();
    (points, out.states)
}

/// Retries a failed start point at `alpha` from the converged point `from` = (α, state): a warm
/// solve, then the sub-steps and fresh start of [`recover`]. The point and the state after it
/// if it converged.
fn retry_start<S: WarmStartSolver>(
    solver: &mut S,
    alpha: f64,
    from: (f64, S::State),
    params: &SweepParams,
) -> Option<(PolarPoint, S::State)> {
    let mut memo = AnchorMemo::default();
    solver.restore(&from.1);
    let mut spent = 0;
    let mut point = memo.solve(solver, &mut Vec::new(), alpha, &mut spent);
    if !point.converged {
        point = recover(solver, alpha, Some(&from), params, &mut memo, spent)?;
    }
    point.converged.then(|| (point, solver.save()))
}

/// March through `order`; `anchor` is the last converged (α, state) before the first point,
/// and `failures_in_a_row` the number of failed points just before it (for
/// [`SweepParams::recover_limit`]). Returns the position in `order` and the state of the first
/// point that converged.
fn march<S: WarmStartSolver>(
    solver: &mut S,
    polar: &Polar<'_>,
    order: &[usize],
    mut anchor: Option<(f64, S::State)>,
    mut failures_in_a_row: u32,
    out: &mut Marched<S::State>,
) -> Option<(usize, S::State)> {
    let params = polar.params;
    let mut first_state = None;
    let mut memo = AnchorMemo::default();
    for (k, &i) in order.iter().enumerate() {
        let alpha = polar.alphas[i];
        // The solver holds the anchor's state here (or none before the first converged point).
        let mut spent = 0;
        let mut point = match anchor {
            Some(_) => memo.solve(solver, &mut Vec::new(), alpha, &mut spent),
            None => {
                let p = solver.solve(alpha);
                spent = p.iterations;
                p
            }
        };
        if !point.converged && failures_in_a_row < params.recover_limit {
            point =
                recover(solver, alpha, anchor.as_ref(), params, &mut memo, spent).unwrap_or(point);
        }
        if point.converged {
            failures_in_a_row = 0;
            memo.clear();
            let state = solver.save();
            if first_state.is_none() {
                first_state = Some((k, state.clone()));
            }
            if polar.keep_states {
                out.states.insert(alpha, solver.series_state());
            }
            anchor = Some((alpha, state));
        } else {
            failures_in_a_row += 1;
            match &anchor {
                Some((_, s)) => solver.restore(s),
                None => solver.reset(),
            }
        }
        out.points[i] = Some(point);
    }
    first_state
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A mock solver that converges only when the step from its state is at most `max_step`
    /// (a fresh start counts as state 0°), and never at α in `bad`.
    struct Mock {
        state: Option<f64>,
        max_step: f64,
        bad: Vec<f64>,
        /// α where a fresh start (no state) fails.
        bad_fresh: Vec<f64>,
        calls: usize,
        /// Newton iterations a failed solve reports (a converged one reports 1).
        failed_iterations: u32,
    }

    impl WarmStartSolver for Mock {
        type State = Option<f64>;
        fn solve(&mut self, alpha: f64) -> PolarPoint {
            self.calls += 1;
            let from = self.state.unwrap_or(0.0);
            let fresh_fails = self.state.is_none() && self.bad_fresh.contains(&alpha);
            let ok = (alpha - from).abs() <= self.max_step + 1e-12
                && !self.bad.contains(&alpha)
                && !fresh_fails;
            self.state = if ok { Some(alpha) } else { Some(f64::NAN) };
            PolarPoint {
                alpha,
                // Depends on the state solved from, so that a sweep's path shows in its points.
                cl: 0.1 * alpha + if from.is_nan() { -1.0 } else { 0.01 * from },
                cd: 0.01,
                cdp: 0.005,
                cdf: 0.005,
                cm: 0.0,
                xtr_top: 1.0,
                xtr_bot: 1.0,
                converged: ok,
                iterations: if ok { 1 } else { self.failed_iterations },
                residual: 0.0,
                cpmin: -1.0,
                supercritical: Some(false),
                xsep_top: 1.0,
                xsep_bot: 1.0,
                massive_separation: Some(false),
            }
        }
        fn reset(&mut self) {
            self.state = None;
        }
        fn save(&self) -> Self::State {
            self.state
        }
        fn restore(&mut self, s: &Self::State) {
            self.state = *s;
        }
    }

    /// The split sweep (the downward branch on a second solver, in parallel) gives the points
    /// of the sequential sweep, with the start point converged or failed.
    #[test]
    fn split_sweep_gives_the_sequential_points() {
        // The start point (nearest 0°) is 0.25°, not the 0° a fresh mock starts from.
        let alphas: Vec<f64> = (-8..=10).map(|a| f64::from(a) * 0.5 + 0.25).collect();
        for (bad, bad_fresh) in [
            (vec![], vec![]),
            (vec![1.75, 2.25, -1.75, -2.25, -2.75, -3.25], vec![]),
            (vec![3.25], vec![0.25]),
        ] {
            let mock = || Mock {
                state: None,
                max_step: 0.6,
                bad: bad.clone(),
                bad_fresh: bad_fresh.clone(),
                calls: 0,
                failed_iterations: 1,
            };
            let params = SweepParams::default();
            let sequential = sweep(&mut mock(), &alphas, &params);
            let (split, _) = sweep_split(&mut mock(), Some(mock()), &alphas, &params, false);
            assert_eq!(split, sequential);
            assert_eq!(sequential.len(), alphas.len());
            assert_eq!(sequential.iter().any(|p| !p.converged), !bad.is_empty());
        }
    }

    #[test]
    fn marches_from_zero_and_recovers_with_substeps() {
        let alphas: Vec<f64> = (-4..=8).map(|a| a as f64 * 2.0).collect();
        // Steps of 2° are too big; 1° sub-steps work.
        let mut m = Mock {
            state: None,
            max_step: 1.0,
            bad: vec![],
            bad_fresh: vec![],
            calls: 0,
            failed_iterations: 1,
        };
        let pts = sweep(&mut m, &alphas, &SweepParams::default());
        assert!(pts.iter().all(|p| p.converged));
        assert_eq!(pts.iter().map(|p| p.alpha).collect::<Vec<_>>(), alphas);
    }

    #[test]
    fn failed_point_is_flagged_and_march_continues() {
        let alphas = [0.0, 1.0, 2.0, 3.0, -1.0, -2.0];
        let mut m = Mock {
            state: None,
            max_step: 2.0,
            bad: vec![2.0, -1.0],
            bad_fresh: vec![],
            calls: 0,
            failed_iterations: 1,
        };
        let pts = sweep(&mut m, &alphas, &SweepParams::default());
        let conv: Vec<bool> = pts.iter().map(|p| p.converged).collect();
        assert_eq!(conv, vec![true, true, false, true, false, true]);
    }

    #[test]
    fn recovery_stops_after_failures_in_a_row() {
        // Past 2° every point fails; with a limit of 2 only the first two failures get the
        // recovery. Solves: 0° and 1° one each; 2°: 1 + half step 1.5° + 2° + fresh = 4;
        // 3°: 1 + fresh = 2, its half step 2° from 1° being a repeat of 2°'s first solve
        // (replayed, and it fails, ending the sub-steps); 4°, 5°, 6°: one each.
        let alphas = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        let mut m = Mock {
            state: None,
            max_step: 1.0,
            bad: vec![2.0, 3.0, 4.0, 5.0, 6.0],
            bad_fresh: vec![],
            calls: 0,
            failed_iterations: 1,
        };
        let params = SweepParams {
            substep_levels: 1,
            fresh_retry: true,
            recover_limit: 2,
            ..SweepParams::default()
        };
        let pts = sweep(&mut m, &alphas, &params);
        assert_eq!(pts.iter().filter(|p| p.converged).count(), 2);
        assert!(pts.iter().all(|p| p.converged == (p.alpha < 2.0)));
        assert_eq!(m.calls, 11);
    }

    #[test]
    fn repeated_solves_from_the_anchor_are_replayed() {
        // 3° fails; so does 4°, whose recovery starts with a half step to 3° from 2° (a repeat
        // of 3°'s first solve, replayed) and then quarter steps 2.5° (new), 3° from 2.5° (new,
        // fails). The result equals that of a solver that repeats every solve.
        let alphas = [0.0, 1.0, 2.0, 3.0, 4.0];
        let params = SweepParams {
            substep_levels: 2,
            fresh_retry: false,
            recover_limit: 3,
            ..SweepParams::default()
        };
        let mut m = Mock {
            state: None,
            max_step: 1.0,
            bad: vec![3.0],
            bad_fresh: vec![],
            calls: 0,
            failed_iterations: 1,
        };
        let pts = sweep(&mut m, &alphas, &params);
        let conv: Vec<bool> = pts.iter().map(|p| p.converged).collect();
        assert_eq!(conv, vec![true, true, true, false, false]);
        // 0°, 1°, 2°: 3. 3°: 1 + half 2.5° + 3° + quarters 2.25°, 2.5° (from 2.25°), 2.75°, 3°
        // = 7. 4°: 1 + half step 3° replayed + quarters 2.5° (from 2°: replayed) and 3° (from
        // 2.5°: replayed) = 1.
        assert_eq!(m.calls, 11);
    }

    #[test]
    fn failed_start_point_is_retried_from_its_converged_neighbour() {
        // Fresh starts fail at 0° and −1°. 0° then converges warm from 1°, and the march down
        // starts from it; before, 0° stayed failed and −1° (fresh) failed too.
        let alphas = [-2.0, -1.0, 0.0, 1.0, 2.0];
        let mut m = Mock {
            state: None,
            max_step: 1.0,
            bad: vec![],
            bad_fresh: vec![0.0, -1.0],
            calls: 0,
            failed_iterations: 1,
        };
        let pts = sweep(&mut m, &alphas, &SweepParams::default());
        assert!(pts.iter().all(|p| p.converged), "{pts:?}");
        assert_eq!(pts.iter().map(|p| p.alpha).collect::<Vec<_>>(), alphas);
    }

    #[test]
    fn recovery_stops_when_the_point_has_used_its_budget() {
        // 2° fails from everywhere; each failed solve reports 100 iterations. Its first solve
        // and recovery: 2° (100), half step 1.5° (1), 2° (100), quarters 1.25°, 1.5°, 1.75°
        // (1 each), 2° (100), fresh 2° (100) = 8 solves and 403 iterations without a budget.
        let run = |point_budget| {
            let mut m = Mock {
                state: None,
                max_step: 1.0,
                bad: vec![2.0],
                bad_fresh: vec![],
                calls: 0,
                failed_iterations: 100,
            };
            let params = SweepParams {
                point_budget,
                ..SweepParams::default()
            };
            let pts = sweep(&mut m, &[0.0, 1.0, 2.0], &params);
            assert!(!pts[2].converged);
            m.calls - 2
        };
        assert_eq!(run(u32::MAX), 8);
        // With 250: 2° (100), 1.5° (1), 2° (100), 1.25°, 1.5°, 1.75° (1 each), 2° (100): 304
        // used, the fresh start is not tried.
        assert_eq!(run(250), 7);
        // With 100 the first solve has used it all: no recovery.
        assert_eq!(run(100), 1);
    }
}
