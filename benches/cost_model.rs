//! Per-stage cost model of a viscous sweep: the time of one sweep (single thread, as the
//! `polargen` CLI runs it with `--threads 1`) fitted by least squares as
//!
//!   t ≈ a + b·(angles of attack) + c·(Newton iterations of all attempts),
//!
//! where `a` is the setup (paneling, panel system, solver; timed on its own), `b` and `c`
//! fitted to the sweeps' remaining time: `b` the per-α cost that does not
//! depend on the iteration count (the per-α panel model: wake, source influence; the
//! solution record) and `c` one global Newton iteration (re-march, assembly, structured
//! solve, update). The sweeps are the paper's two cases (NACA 8-H-12, Re 1.9e6, M 0.41, free
//! transition and xtr 0.07) over α ranges and steps chosen so that the α count and the
//! iterations per α vary independently. Each sweep is timed as the fastest of `ROUNDS`
//! (environment, default 3) runs, in CPU time of the running thread where Linux reports it
//! (`/proc/thread-self/schedstat`: a loaded, shared machine then stretches the wall time but
//! not the figure), else in wall time. Run with `cargo bench --bench cost_model`.

use std::time::Instant;

use polargen::geometry::{airfoil_by_name_or_path, PanelingParams};
use polargen::polar::{parse_alpha_range, sweep, SweepParams};
use polargen::viscous::{ViscousParams, ViscousSolver};

/// CPU time of the calling thread in seconds (Linux), or `None`.
fn thread_cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = stat.split_whitespace().next()?.parse().ok()?;
    Some(1e-9 * ns)
}

/// Seconds since `start` (wall) or of CPU since `cpu_start`, whichever clock is available.
fn elapsed(start: Instant, cpu_start: Option<f64>) -> f64 {
    match (cpu_start, thread_cpu_seconds()) {
        (Some(a), Some(b)) => b - a,
        _ => start.elapsed().as_secs_f64(),
    }
}

/// One timed sweep: α count, Newton iterations, converged points, seconds of the sweep
/// (setup excluded).
struct Sample {
    alphas: f64,
    iterations: f64,
    converged: usize,
    seconds: f64,
}

/// Least-squares fit of the sweep time (setup excluded) t = b·n_α + c·n_it: the 2×2
/// normal equations solved by Cramer's rule.
fn fit(samples: &[Sample]) -> [f64; 2] {
    let (mut saa, mut sai, mut sii, mut sat, mut sit) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for s in samples {
        saa += s.alphas * s.alphas;
        sai += s.alphas * s.iterations;
        sii += s.iterations * s.iterations;
        sat += s.alphas * s.seconds;
        sit += s.iterations * s.seconds;
    }
    let det = saa * sii - sai * sai;
    [(sat * sii - sai * sit) / det, (saa * sit - sai * sat) / det]
}

/// The setup of a sweep (paneling, panel system, solver), the fastest of `rounds` batches of
/// 20 (the thread clock advances in scheduler ticks, too coarse for one setup).
fn setup_seconds(rounds: usize) -> f64 {
    let params = ViscousParams::at(1.9e6, 0.41, 1.0);
    let mut best = f64::INFINITY;
    for _ in 0..rounds {
        let (t0, cpu0) = (Instant::now(), thread_cpu_seconds());
        for _ in 0..20 {
            let foil = airfoil_by_name_or_path("naca8h12")
                .and_then(|a| a.repanel(160, &PanelingParams::default()))
                .expect("8-H-12 geometry");
            std::hint::black_box(ViscousSolver::new(&foil, params).expect("solver"));
        }
        best = best.min(elapsed(t0, cpu0) / 20.0);
    }
    best
}

fn main() {
    let rounds: usize = std::env::var("ROUNDS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(3);
    let ranges = [
        "-4:12:0.5",
        "-4:12:0.25",
        "-4:12:1",
        "-4:12:2",
        "0:8:0.5",
        "0:8:0.1",
    ];
    let sweep_params = SweepParams::default();
    let mut samples = Vec::new();
    let setup = setup_seconds(rounds);
    let clock = if thread_cpu_seconds().is_some() {
        "thread CPU"
    } else {
        "wall"
    };
    println!("sweep                 alphas  iterations  converged   ms {clock} (best of {rounds})");
    for (name, xtr) in [("free", 1.0), ("xtr0.07", 0.07)] {
        for range in ranges {
            let alphas = parse_alpha_range(range).expect("range");
            let params = ViscousParams::at(1.9e6, 0.41, xtr);
            let mut best = f64::INFINITY;
            let mut iterations = 0;
            let mut converged = 0;
            for _ in 0..rounds {
                let foil = airfoil_by_name_or_path("naca8h12")
                    .and_then(|a| a.repanel(160, &PanelingParams::default()))
                    .expect("8-H-12 geometry");
                let (t0, cpu0) = (Instant::now(), thread_cpu_seconds());
                let mut solver = ViscousSolver::new(&foil, params).expect("solver");
                let points = sweep(&mut solver, &alphas, &sweep_params);
                best = best.min(elapsed(t0, cpu0));
                iterations = solver.work().newton_iterations;
                converged = points.iter().filter(|p| p.converged).count();
            }
            println!(
                "{name:8} {range:>12} {:>6} {iterations:>11} {converged:>10} {:>10.1}",
                alphas.len(),
                best * 1e3
            );
            samples.push(Sample {
                alphas: alphas.len() as f64,
                iterations: iterations as f64,
                converged,
                seconds: best,
            });
        }
    }
    let [b, c] = fit(&samples);
    println!(
        "\nfit: sweep ≈ {:.2} ms setup + {:.3} ms per α + {:.3} ms per Newton iteration",
        setup * 1e3,
        b * 1e3,
        c * 1e3
    );
    let worst = samples
        .iter()
        .map(|s| ((b * s.alphas + c * s.iterations) / s.seconds - 1.0).abs())
        .fold(0.0, f64::max);
    println!("largest relative misfit of a sweep: {:.1} %", 100.0 * worst);
    // The paper's sweeps (step 0.5, the first sample of each case) split by stage.
    for s in samples.iter().step_by(ranges.len()) {
        let total = setup + b * s.alphas + c * s.iterations;
        println!(
            "step 0.5: {:.2} Newton iterations per converged point; setup {:.0} %, per-α {:.0} %, \
             Newton {:.0} %",
            s.iterations / s.converged.max(1) as f64,
            100.0 * setup / total,
            100.0 * b * s.alphas / total,
            100.0 * c * s.iterations / total
        );
    }
}
