//! Many polars at once: one warm-started sweep per (Re, M) node, run in parallel.
//!
//! Each node gets its own two solvers (no shared mutable state): one for the upward α branch
//! and one for the downward branch, which run in parallel once the start point has converged
//! ([`sweep_split`]). The points of a node do not depend on which thread ran them or in which
//! order: the output is identical for any thread count.

use rayon::prelude::*;

use super::sweep::{sweep_split, SweepParams, WarmStartSolver};
use crate::section::PolarPoint;

/// One polar a grid asks for: its condition and its angles of attack.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridNode<'a> {
    /// Reynolds number.
    pub re: f64,
    /// Mach number.
    pub mach: f64,
    /// Angles of attack \[deg\].
    pub alphas: &'a [f64],
}

/// One computed polar of a grid.
#[derive(Clone, Debug, PartialEq)]
pub struct GridPolar {
    /// Reynolds number of the node.
    pub re: f64,
    /// Mach number of the node.
    pub mach: f64,
    /// Points in the order of the requested α values.
    pub points: Vec<PolarPoint>,
}

/// Run one sweep over its α values for every node on a pool of `threads` threads
/// (0 = all cores). A node runs at most two tasks at once (its two α branches), so the pool
/// never gets more than two threads per node: more could not be used, and thousands of idle
/// threads cost seconds to start. `make_solver(i)` builds the solver of `nodes[i]`; a node whose
/// solver cannot be built fails the whole grid with that error. `on_polar_done` is called after each node
/// (from worker threads; for progress display). Polars come back in the order of `nodes`.
pub fn run_grid<S, E, F, P>(
    nodes: &[GridNode<'_>],
    threads: usize,
    params: &SweepParams,
    make_solver: F,
    on_polar_done: P,
) -> Result<Vec<GridPolar>, E>
where
    S: WarmStartSolver + Send,
    S::State: Send,
    E: Send,
    F: Fn(usize) -> Result<S, E> + Sync,
    P: Fn(&GridPolar) + Sync,
{
    let work = || {
        nodes
            .par_iter()
            .with_max_len(1)
            .enumerate()
            .map(|(i, node)| {
                // A second solver lets the node's two α branches run in parallel too, so that
                // the last polars of a grid do not leave a core idle.
                let mut solver = make_solver(i)?;
                let second = make_solver(i)?;
                let polar = GridPolar {
                    re: node.re,
                    mach: node.mach,
                    points: sweep_split(&mut solver, Some(second), node.alphas, params),
                };
                on_polar_done(&polar);
                Ok(polar)
            })
            .collect::<Result<Vec<_>, E>>()
    };
    let threads = if threads == 0 {
        0
    } else {
        threads.min(2 * nodes.len().max(1))
    };
    match rayon::ThreadPoolBuilder::new().num_threads(threads).build() {
        Ok(pool) => pool.install(work),
        // A pool that cannot be built (resource limits) falls back to rayon's global pool
        // (one thread per core); the output does not depend on the thread count.
        Err(_) => work(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Deterministic stand-in: cl depends on (Re, M, α), converges everywhere.
    struct Analytic {
        re: f64,
        mach: f64,
    }

    impl WarmStartSolver for Analytic {
        type State = ();
        fn solve(&mut self, alpha: f64) -> PolarPoint {
            let cl = 0.11 * alpha / (1.0 - self.mach * self.mach).sqrt();
            PolarPoint {
                alpha,
                cl,
                cd: 0.074 / self.re.powf(0.2),
                cdp: 0.0,
                cdf: 0.0,
                cm: 0.0,
                xtr_top: 1.0,
                xtr_bot: 1.0,
                converged: true,
                iterations: 1,
                residual: 0.0,
                cpmin: -1.0,
                supercritical: Some(false),
                xsep_top: 1.0,
                xsep_bot: 1.0,
                massive_separation: Some(false),
            }
        }
        fn reset(&mut self) {}
        fn save(&self) {}
        fn restore(&mut self, _: &()) {}
    }

    fn grid_nodes<'a>(nodes: &[(f64, f64)], alphas: &'a [f64]) -> Vec<GridNode<'a>> {
        nodes
            .iter()
            .map(|&(re, mach)| GridNode { re, mach, alphas })
            .collect()
    }

    fn analytic(nodes: &[GridNode<'_>], i: usize) -> Analytic {
        Analytic {
            re: nodes[i].re,
            mach: nodes[i].mach,
        }
    }

    #[test]
    fn same_result_for_any_thread_count() {
        let nodes: Vec<(f64, f64)> = [1e6, 2e6, 3e6]
            .iter()
            .flat_map(|&r| [0.0, 0.3].map(move |m| (r, m)))
            .collect();
        let alphas = [-2.0, 0.0, 2.0, 4.0];
        let nodes = grid_nodes(&nodes, &alphas);
        let run = |t| {
            run_grid(
                &nodes,
                t,
                &SweepParams::default(),
                |i| Ok::<_, ()>(analytic(&nodes, i)),
                |_| {},
            )
            .unwrap()
        };
        let one = run(1);
        assert_eq!(one.len(), 6);
        assert_eq!((one[3].re, one[3].mach), (2e6, 0.3));
        assert_eq!(one, run(2));
        assert_eq!(one, run(0));
    }

    #[test]
    fn at_most_two_threads_per_polar() {
        let pool_size = |nodes: &[(f64, f64)], threads| {
            let seen = std::sync::Mutex::new(Vec::new());
            let nodes = grid_nodes(nodes, &[0.0, 1.0]);
            run_grid(
                &nodes,
                threads,
                &SweepParams::default(),
                |i| {
                    seen.lock().unwrap().push(rayon::current_num_threads());
                    Ok::<_, ()>(analytic(&nodes, i))
                },
                |_| {},
            )
            .unwrap();
            let seen = seen.into_inner().unwrap();
            assert!(seen.windows(2).all(|w| w[0] == w[1]));
            seen[0]
        };
        assert_eq!(pool_size(&[(1e6, 0.0)], 100_000), 2);
        assert_eq!(pool_size(&[(1e6, 0.0), (2e6, 0.0)], 100_000), 4);
        assert_eq!(pool_size(&[(1e6, 0.0), (2e6, 0.0)], 3), 3);
    }

    #[test]
    fn solver_error_fails_the_grid() {
        let nodes = grid_nodes(&[(1e6, 0.0), (2e6, 0.0)], &[0.0]);
        let r = run_grid(
            &nodes,
            1,
            &SweepParams::default(),
            |i| {
                if nodes[i].re > 1.5e6 {
                    Err("too fast")
                } else {
                    Ok(analytic(&nodes, i))
                }
            },
            |_| {},
        );
        assert_eq!(r, Err("too fast"));
    }
}
