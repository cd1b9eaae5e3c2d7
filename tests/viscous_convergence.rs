//! Convergence of warm-started sweeps at points that used to converge slowly or not at all.
//! The NACA 8-H-12 is paneled as `polargen --airfoil naca8h12` does it (160 nodes), and the
//! sweeps run through the same `polar::sweep` as the CLI.
//!
//! * Fixed cycles near transition (both also cycle in XFOIL 6.99): Re 1.5e6, M 0.2, α −0.5°
//!   after −0.25° (the lower-surface transition point just upstream of a station, the re-march
//!   undid every Newton step: RMS change 6.9e-3 repeated to the iteration cap), and Re 2e6,
//!   M 0, α 7° after 6.5° (transition inside the onset ramp of the amplification rate, the
//!   station's local iteration flipped between two states).
//! * Warm-start stagnation point (XFOIL VISCAL: the stagnation point of a warm start comes from
//!   the previous viscous solution): the paper's free sweep needed 315 Newton iterations in its
//!   final attempts when the stagnation point was taken from the new inviscid speed, 278 now.

use polargen::geometry::{airfoil_by_name_or_path, Airfoil, PanelingParams};
use polargen::polar::{sweep, PolarPoint, SweepParams, ViscousSweep};
use polargen::viscous::ViscousParams;

fn naca8h12() -> Airfoil {
    airfoil_by_name_or_path("naca8h12")
        .unwrap()
        .repanel(160, &PanelingParams::default())
        .unwrap()
}

/// A sweep at (Re, M); `recover` turns the sweep's retries of failed points on (half and quarter
/// steps, fresh start) — off, every point is the first warm-started attempt.
fn run(re: f64, mach: f64, alphas: &[f64], recover: bool) -> Vec<PolarPoint> {
    let params = ViscousParams {
        reynolds: re,
        mach,
        ..ViscousParams::default()
    };
    let mut solver = ViscousSweep::new(&naca8h12(), params).unwrap();
    let sweep_params = if recover {
        SweepParams::default()
    } else {
        SweepParams {
            substep_levels: 0,
            fresh_retry: false,
            recover_limit: 0,
        }
    };
    sweep(&mut solver, alphas, &sweep_params)
}

fn range(a0: f64, a1: f64, da: f64) -> Vec<f64> {
    let n = ((a1 - a0) / da).round() as usize;
    (0..=n).map(|i| a0 + da * i as f64).collect()
}

#[test]
fn former_transition_cycles_converge_quickly() {
    for (re, mach, alphas) in [
        (1.5e6, 0.2, range(-2.0, 0.0, 0.25)),
        (2.0e6, 0.0, range(5.0, 8.0, 0.5)),
    ] {
        // No retries: a cycle ran the first attempt to the 100-iteration cap (the sweep's
        // sub-step retries then rescued it at several times the cost); now 4–10 iterations.
        for p in run(re, mach, &alphas, false) {
            assert!(
                p.converged && p.iterations <= 20,
                "Re {re} M {mach} alpha {}: converged {} in {} iterations",
                p.alpha,
                p.converged,
                p.iterations
            );
        }
    }
}

#[test]
fn paper_sweep_needs_few_newton_iterations() {
    let points = run(1.9e6, 0.41, &range(-4.0, 12.0, 0.5), true);
    assert!(points.iter().all(|p| p.converged));
    let total: u32 = points.iter().map(|p| p.iterations).sum();
    // 278 on the development machine; the bound leaves room for last-bit differences of the
    // math library on other machines and fails for the old warm start (315).
    assert!(total <= 295, "{total} Newton iterations");
}
