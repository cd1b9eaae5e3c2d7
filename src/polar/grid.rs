//! Many polars at once: one warm-started sweep per (Re, M) node, run in parallel, and the
//! holes of each series filled from the polar below.
//!
//! Each node's march gets its own two solvers (no shared mutable state): one for the upward α
//! branch and one for the downward branch, which run in parallel once the start point has
//! converged ([`sweep_split`]). Once every node's march is done, the points a march left
//! unconverged are solved once more, on a solver of their own, from the state the same α
//! converged to at the next lower Reynolds number of the node's series ([`GridNode::series`],
//! [`fill_from_below`]): each series from its lowest Reynolds number up, the series in
//! parallel. The points of a node do not depend on which thread ran them or in which order:
//! the output is identical for any thread count.

use std::collections::HashMap;

use rayon::prelude::*;

use super::series::{fill_from_below, SeriesStates};
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
    /// Nodes with the same series and Mach number differ in their Reynolds number alone (the
    /// same trips and N_crit): a point one of them leaves unconverged is solved once more from
    /// the state its α converged to at the next lower Reynolds number of the series (the node
    /// just below it: one with the same Reynolds number or without that α breaks the chain).
    pub series: usize,
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
/// (0 = all cores), then fill the holes of each series ([`SweepParams::series_retry`]; the
/// converged states of every node with a node above it are kept until then). A node runs at
/// most two tasks at once (its two α branches), so the pool never gets more than two threads
/// per node: more could not be used, and thousands of idle threads cost seconds to start.
/// `make_solver(i)` builds the solver of `nodes[i]`; a node whose solver cannot be built fails
/// the whole grid with that error. `on_polar_done` is called after each node's march (from
/// worker threads; for progress display), so it has reported every point before the filling,
/// which solves only the holes, starts. Polars come back in the order of `nodes`.
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
    let chains = if params.series_retry {
        series_chains(nodes)
    } else {
        Vec::new()
    };
    // Whose states a node above will start from: every node of a series but its top one.
    let mut below_another = vec![false; nodes.len()];
    for chain in &chains {
        for &i in &chain[..chain.len() - 1] {
            below_another[i] = true;
        }
    }
    let fill = below_another.contains(&true);
    let work = || {
        let marched = nodes
            .par_iter()
            .with_max_len(1)
            .enumerate()
            .map(|(i, node)| {
                // A second solver lets the node's two α branches run in parallel too, so that
                // the last polars of a grid do not leave a core idle.
                let mut solver = make_solver(i)?;
                let second = make_solver(i)?;
                let keep = below_another[i];
                let (points, states) =
                    sweep_split(&mut solver, Some(second), node.alphas, params, keep);
                let polar = GridPolar {
                    re: node.re,
                    mach: node.mach,
                    points,
                };
                on_polar_done(&polar);
                Ok((polar, states))
            })
            .collect::<Result<Vec<_>, E>>()?;
        if !fill {
            return Ok(marched.into_iter().map(|(p, _)| p).collect());
        }
        fill_series(nodes, &chains, marched, &make_solver)
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

/// A node's polar after its march, with the states it converged to.
type MarchedPolar<T> = (GridPolar, SeriesStates<T>);

/// The marched polars of `nodes` with each series' holes filled from the polar below
/// ([`fill_from_below`]), the series in parallel, each from its lowest Reynolds number up.
fn fill_series<S, E, F>(
    nodes: &[GridNode<'_>],
    chains: &[Vec<usize>],
    marched: Vec<MarchedPolar<S::State>>,
    make_solver: &F,
) -> Result<Vec<GridPolar>, E>
where
    S: WarmStartSolver + Send,
    S::State: Send,
    E: Send,
    F: Fn(usize) -> Result<S, E> + Sync,
{
    let mut marched: Vec<Option<MarchedPolar<S::State>>> = marched.into_iter().map(Some).collect();
    let taken: Vec<Vec<(usize, MarchedPolar<S::State>)>> = chains
        .iter()
        .map(|chain| {
            chain
                .iter()
                .map(|&i| (i, marched[i].take().expect("every node is in one series")))
                .collect()
        })
        .collect();
    let filled = taken
        .into_par_iter()
        .with_max_len(1)
        .map(|mut chain| {
            for k in 1..chain.len() {
                let (lower, upper) = chain.split_at_mut(k);
                let below = &lower[k - 1].1 .1;
                let (i, (polar, states)) = &mut upper[0];
                let holes = polar
                    .points
                    .iter()
                    .zip(nodes[*i].alphas)
                    .any(|(p, &a)| !p.converged && below.get(a).is_some());
                if holes {
                    let mut solver = make_solver(*i)?;
                    fill_from_below(
                        &mut solver,
                        nodes[*i].alphas,
                        &mut polar.points,
                        states,
                        below,
                    );
                }
                // The states below are not needed any more.
                drop(std::mem::take(&mut lower[k - 1].1 .1));
            }
            Ok(chain)
        })
        .collect::<Result<Vec<_>, E>>()?;
    let mut polars: Vec<Option<GridPolar>> = vec![None; nodes.len()];
    for (i, (polar, _)) in filled.into_iter().flatten() {
        polars[i] = Some(polar);
    }
    Ok(polars
        .into_iter()
        .map(|p| p.expect("every node is in one series"))
        .collect())
}

/// The nodes of each series ([`GridNode::series`] and the Mach number's bits), in order of
/// Reynolds number (equal ones in the order of `nodes`); series in the order of their first
/// node.
fn series_chains(nodes: &[GridNode<'_>]) -> Vec<Vec<usize>> {
    let mut index: HashMap<(usize, u64), usize> = HashMap::new();
    let mut chains: Vec<Vec<usize>> = Vec::new();
    for (i, node) in nodes.iter().enumerate() {
        let key = (node.series, (node.mach + 0.0).to_bits());
        let c = *index.entry(key).or_insert_with(|| {
            chains.push(Vec::new());
            chains.len() - 1
        });
        chains[c].push(i);
    }
    for chain in &mut chains {
        chain.sort_by(|&a, &b| nodes[a].re.total_cmp(&nodes[b].re));
    }
    chains
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
            .map(|&(re, mach)| GridNode {
                re,
                mach,
                alphas,
                series: 0,
            })
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

    /// A solver whose march fails at α in `bad`: it converges from a state within 1° at its
    /// own Reynolds number (a fresh start within 1° of 0°, but not at α in `bad_fresh`), or
    /// from the state another Reynolds number converged to at the same α, but at α in `bad`
    /// only from such a state.
    struct Series {
        re: f64,
        bad: Vec<f64>,
        bad_fresh: Vec<f64>,
        state: Option<(f64, f64)>,
    }

    impl WarmStartSolver for Series {
        type State = Option<(f64, f64)>;
        fn solve(&mut self, alpha: f64) -> PolarPoint {
            let from_series = matches!(self.state, Some((a, re)) if a == alpha && re != self.re);
            let near =
                matches!(self.state, Some((a, re)) if (a - alpha).abs() <= 1.0 && re == self.re);
            let fresh =
                self.state.is_none() && alpha.abs() <= 1.0 && !self.bad_fresh.contains(&alpha);
            let ok = from_series || (near || fresh) && !self.bad.contains(&alpha);
            self.state = ok.then_some((alpha, self.re));
            let mut p = Analytic {
                re: self.re,
                mach: 0.0,
            }
            .solve(alpha);
            p.converged = ok;
            p
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

    #[test]
    fn holes_are_filled_from_the_reynolds_number_below() {
        let alphas = [-2.0, -1.0, 0.0, 1.0, 2.0, 3.0];
        // (Re, M, series, α where the march fails), given out of Reynolds order. Series 0 at
        // M 0 is 1e6 → 2e6 → 3e6: 2e6 fails at −2° (the downward branch) and 2° (and so at 3°,
        // 2° away from 1°), 3e6 at 2° and 3°, which only 2e6's filled points can start. The
        // same 2e6 in series 1, and at M 0.3, has nothing below it.
        let spec = [
            (3e6, 0.0, 0, vec![2.0, 3.0]),
            (1e6, 0.0, 0, vec![]),
            (2e6, 0.0, 0, vec![-2.0, 2.0]),
            (2e6, 0.0, 1, vec![2.0]),
            (2e6, 0.3, 0, vec![2.0]),
        ];
        let nodes: Vec<GridNode<'_>> = spec
            .iter()
            .map(|&(re, mach, series, _)| GridNode {
                re,
                mach,
                alphas: &alphas,
                series,
            })
            .collect();
        let run = |series_retry, threads| {
            let params = SweepParams {
                series_retry,
                ..SweepParams::default()
            };
            let make = |i: usize| {
                Ok::<_, ()>(Series {
                    re: nodes[i].re,
                    bad: spec[i].3.clone(),
                    bad_fresh: vec![],
                    state: None,
                })
            };
            run_grid(&nodes, threads, &params, make, |_| {}).unwrap()
        };
        let holes = |g: &[GridPolar]| -> Vec<Vec<f64>> {
            g.iter()
                .map(|p| {
                    let holes = p.points.iter().filter(|q| !q.converged);
                    holes.map(|q| q.alpha).collect()
                })
                .collect()
        };
        let alone = run(false, 1);
        assert_eq!(
            holes(&alone),
            [
                vec![2.0, 3.0],
                vec![],
                vec![-2.0, 2.0, 3.0],
                vec![2.0, 3.0],
                vec![2.0, 3.0]
            ]
        );
        let filled = run(true, 1);
        assert_eq!(
            holes(&filled),
            [vec![], vec![], vec![], vec![2.0, 3.0], vec![2.0, 3.0]]
        );
        // The marches are the same: only the holes changed.
        for (a, f) in alone.iter().zip(&filled) {
            for (p, q) in a.points.iter().zip(&f.points) {
                assert!(!p.converged || p == q);
            }
        }
        assert_eq!(filled, run(true, 2));
        assert_eq!(filled, run(true, 0));
    }

    /// A start point that converges only on its retry from the point above it
    /// (`sweep_split`'s `retry_start`) keeps its state for the polar above it too.
    #[test]
    fn a_start_point_rescued_by_its_retry_fills_the_polar_above() {
        let alphas = [0.0, 1.0];
        let nodes = grid_nodes(&[(1e6, 0.0), (2e6, 0.0)], &alphas);
        let make = |i: usize| {
            Ok::<_, ()>(Series {
                re: nodes[i].re,
                // 1e6: no fresh start at 0°, so 0° converges warm from 1°; 2e6 fails at 0°.
                bad: if i == 1 { vec![0.0] } else { vec![] },
                bad_fresh: vec![0.0],
                state: None,
            })
        };
        let grid = run_grid(&nodes, 1, &SweepParams::default(), make, |_| {}).unwrap();
        assert!(grid.iter().all(|p| p.points.iter().all(|q| q.converged)));
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
