//! Convergence of warm-started sweeps at conditions that are hard for the Newton iteration,
//! through the same `polar::sweep` as the command line, with the NACA 8-H-12 paneled as
//! `polargen --airfoil naca8h12` does it (160 nodes). Guards that
//!
//! * a transition point just upstream of a station, or inside the onset ramp of the
//!   amplification rate (both cycle in XFOIL 6.99 too), converges in a few iterations
//!   instead of cycling to the iteration cap;
//! * the paper's sweep needs few Newton iterations in total (the warm start takes the
//!   stagnation point from the previous viscous solution, as XFOIL's VISCAL does);
//! * the default Newton tolerance and the re-march's carried corrections change the path of
//!   the iterations, not the polar;
//! * sweeps from 0° down stay on the branch XFOIL 6.99 finds (in negative stall too), through a
//!   near-singular first step and a chain of re-march fallbacks, within about three times the
//!   deviation from XFOIL measured when the limits were set (references in tests/data/xfoil).

use polargen::geometry::{airfoil_by_name_or_path, Airfoil, PanelingParams};
use polargen::polar::{sweep, SweepParams};
use polargen::section::PolarPoint;
use polargen::viscous::{ViscousParams, ViscousSolver};

mod xfoil_support;
use xfoil_support::{at_alpha, polar};

fn naca8h12() -> Airfoil {
    paneled("naca8h12")
}

fn paneled(name: &str) -> Airfoil {
    airfoil_by_name_or_path(name)
        .unwrap()
        .repanel(160, &PanelingParams::default())
        .unwrap()
}

/// A sweep at (Re, M); `recover` turns the sweep's retries of failed points on (half and quarter
/// steps, fresh start) — off, every point is the first warm-started attempt.
fn run(re: f64, mach: f64, alphas: &[f64], recover: bool) -> Vec<PolarPoint> {
    run_foil(&naca8h12(), re, mach, 1.0, alphas, recover)
}

fn run_foil(
    foil: &Airfoil,
    re: f64,
    mach: f64,
    xtr: f64,
    alphas: &[f64],
    recover: bool,
) -> Vec<PolarPoint> {
    let sweep_params = if recover {
        SweepParams::default()
    } else {
        SweepParams {
            substep_levels: 0,
            fresh_retry: false,
            recover_limit: 0,
            ..SweepParams::default()
        }
    };
    run_params(
        foil,
        ViscousParams::at(re, mach, xtr),
        alphas,
        &sweep_params,
    )
}

/// A sweep with the given solver parameters.
fn run_params(
    foil: &Airfoil,
    params: ViscousParams,
    alphas: &[f64],
    sweep_params: &SweepParams,
) -> Vec<PolarPoint> {
    let mut solver = ViscousSolver::new(foil, params).unwrap();
    sweep(&mut solver, alphas, sweep_params)
}

/// Newton iterations of a sweep's points (their final attempts).
fn total_iterations(points: &[PolarPoint]) -> u32 {
    points.iter().map(|p| p.iterations).sum()
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
    let total = total_iterations(&points);
    // 181 on the development machine; the bound leaves room for last-bit differences of the
    // math library on other machines and fails with XFOIL's Newton tolerance of 1e-4 (275) and
    // with the old warm start (315).
    assert!(total <= 200, "{total} Newton iterations");
}

/// The default Newton tolerance (1e-3 on the RMS relative change, XFOIL uses 1e-4) stops one
/// iteration earlier than a tight one but gives the same polar: the paper's free and tripped
/// sweeps against a tolerance of 1e-8, every point converged in both, nearly every point and
/// the sweeps in total in fewer iterations.
#[test]
fn default_tolerance_gives_the_converged_polar() {
    let foil = naca8h12();
    let alphas = range(-4.0, 12.0, 0.5);
    for xtr in [1.0, 0.07] {
        let solve = |tolerance: f64| {
            let params = ViscousParams {
                tolerance,
                ..ViscousParams::at(1.9e6, 0.41, xtr)
            };
            run_params(&foil, params, &alphas, &SweepParams::default())
        };
        let (loose, tight) = (solve(ViscousParams::default().tolerance), solve(1e-8));
        let (mut dcl, mut dcd, mut dcm) = (0.0_f64, 0.0_f64, 0.0_f64);
        let mut fewer = 0;
        for (a, b) in loose.iter().zip(&tight) {
            assert!(a.converged && b.converged, "xtr {xtr} alpha {}", a.alpha);
            fewer += usize::from(a.iterations < b.iterations);
            dcl = dcl.max((a.cl - b.cl).abs());
            dcd = dcd.max((a.cd / b.cd - 1.0).abs());
            dcm = dcm.max((a.cm - b.cm).abs());
        }
        eprintln!(
            "xtr {xtr}: max |dCl| {dcl:.1e}, |dCd|/Cd {dcd:.1e}, |dCm| {dcm:.1e}, iterations \
             {} vs {}, fewer at {fewer} of {} points",
            total_iterations(&loose),
            total_iterations(&tight),
            loose.len()
        );
        assert!(dcl <= 1e-4 && dcd <= 2e-4 && dcm <= 1e-5, "xtr {xtr}");
        // Fewer iterations in all but the odd wandering point (the laminar-bucket corner at
        // α 1°, whose warm start differs between the two runs, can take one more).
        assert!(
            total_iterations(&loose) < total_iterations(&tight),
            "xtr {xtr}"
        );
        assert!(fewer * 10 >= loose.len() * 9, "xtr {xtr}: {fewer}");
    }
}

/// Starting a station's re-march iterations from its upstream station's relative corrections
/// (`MarchParams::carried_correction_limit`) changes the path of the Newton iterations, not
/// their result: the paper's free and tripped sweeps converged to 1e-8 give the same polar as
/// with the start left where the Newton step put it (limit 0), in no more Newton iterations
/// (398 against 402 on the development machine; the re-march's local iterations, where the
/// saving is, are not visible here).
#[test]
fn carried_correction_moves_only_the_start() {
    let foil = naca8h12();
    let alphas = range(-4.0, 12.0, 0.5);
    let limit = ViscousParams::default().march.carried_correction_limit;
    let mut iterations = [0, 0];
    for xtr in [1.0, 0.07] {
        let solve = |limit: f64| {
            let mut params = ViscousParams {
                tolerance: 1e-8,
                ..ViscousParams::at(1.9e6, 0.41, xtr)
            };
            params.march.carried_correction_limit = limit;
            run_params(&foil, params, &alphas, &SweepParams::default())
        };
        let (carried, plain) = (solve(limit), solve(0.0));
        let (mut dcl, mut dcd) = (0.0_f64, 0.0_f64);
        for (a, b) in carried.iter().zip(&plain) {
            assert!(a.converged && b.converged, "xtr {xtr} alpha {}", a.alpha);
            dcl = dcl.max((a.cl - b.cl).abs());
            dcd = dcd.max((a.cd / b.cd - 1.0).abs());
        }
        eprintln!(
            "xtr {xtr}: max |dCl| {dcl:.1e}, |dCd|/Cd {dcd:.1e}, iterations {} vs {}",
            total_iterations(&carried),
            total_iterations(&plain)
        );
        assert!(dcl <= 1e-10 && dcd <= 1e-9, "xtr {xtr}");
        iterations[0] += total_iterations(&carried);
        iterations[1] += total_iterations(&plain);
    }
    assert!(iterations[0] <= iterations[1], "{iterations:?}");
}

/// Largest |ΔCl| and |ΔCd|/Cd of the converged `points` against XFOIL's polar `file`, and the
/// number of points compared.
fn deviation_from_xfoil(points: &[PolarPoint], file: &str) -> (f64, f64, usize) {
    let reference = polar(file);
    let (mut dcl, mut dcd, mut compared) = (0.0_f64, 0.0_f64, 0);
    for p in points.iter().filter(|p| p.converged) {
        if let Some(r) = at_alpha(&reference, p.alpha) {
            dcl = dcl.max((p.cl - r.cl).abs());
            dcd = dcd.max((p.cd / r.cd - 1.0).abs());
            compared += 1;
        }
    }
    eprintln!("{file}: max |dCl| {dcl:.1e}, |dCd|/Cd {dcd:.1e} over {compared} points");
    (dcl, dcd, compared)
}

/// Sweeps from 0° to −10°: no converged point with negative form drag beyond round-off, and
/// every converged point on XFOIL's branch (the other branches a damped re-march of separated
/// stations or a negative-form-drag state led to differ by 0.01–0.05 in Cl and 10–50 % in Cd).
/// Limits (|ΔCl|, |ΔCd|/Cd): about three times the measured (in the comments).
#[test]
fn negative_stall_follows_xfoils_branch() {
    for (name, re, mach, xtr, file, limits) in [
        (
            "naca23012",
            5e5,
            0.4,
            0.07,
            "naca23012_Re5e5_M0.4_xtr0.07_negative.csv",
            [1.5e-4, 1.1e-3], // measured 4.9e-5, 3.7e-4
        ),
        (
            "naca8h12",
            2.5e6,
            0.4,
            1.0,
            "naca8h12_Re2.5e6_M0.4_free_negative.csv",
            [1.5e-4, 2.1e-3], // measured 4.9e-5, 6.9e-4
        ),
    ] {
        let points = run_foil(&paneled(name), re, mach, xtr, &range(-10.0, 0.0, 0.5), true);
        for p in points.iter().filter(|p| p.converged) {
            assert!(
                p.cd - p.cdf >= -2e-4,
                "{name} alpha {}: cd {} cdf {}",
                p.alpha,
                p.cd,
                p.cdf
            );
        }
        let (dcl, dcd, compared) = deviation_from_xfoil(&points, file);
        assert!(compared >= 10, "{name}: only {compared} points compared");
        assert!(
            dcl <= limits[0] && dcd <= limits[1],
            "{name}: {dcl:.2e} {dcd:.2e}"
        );
    }
}

#[test]
fn step_from_a_near_singular_system_is_not_repeated() {
    // 8-H-12, Re 2.5e6, M 0.3, sweep 0° → −3.5°: at −3° the stagnation point lands 3.5e-6 of
    // the node interval from a node, the first Newton step comes out of a near-singular system
    // (relative changes ≈ 1e23), and with the stagnation-point terms in every iteration the
    // point failed in all retries. The iteration after such a step goes without those terms.
    // Every point against XFOIL 6.99's sweep: measured |ΔCl| 4.0e-5, |ΔCd|/Cd 5.8e-4, limits
    // about three times that.
    let points = run(2.5e6, 0.3, &range(-3.5, 0.0, 0.5), true);
    assert!(points.iter().all(|p| p.converged), "{points:?}");
    let (dcl, dcd, compared) =
        deviation_from_xfoil(&points, "naca8h12_Re2.5e6_M0.3_free_negative.csv");
    assert_eq!(compared, 8);
    assert!(dcl <= 1.2e-4 && dcd <= 1.8e-3, "{dcl:.2e} {dcd:.2e}");
}

#[test]
fn fallback_chain_does_not_explode_the_newton_step() {
    // 8-H-12, Re 1e6, M 0.3, sweep 0° → −3.5°: at −2.5° (from −2°) the stagnation point moves
    // by one node in the first iteration, a laminar bubble near the leading edge on the lower
    // surface then transitions one station earlier in the re-march, the next station cannot
    // follow from H ≈ 9.6 and falls back, and with XFOIL's fallback (extrapolation from the
    // extrapolated neighbour) all 63 stations after it would too; the Newton step at that
    // state explodes (RMS change 1e47, 18–20 iterations). The stations of such a chain keep the
    // Newton step's state instead: 5 and 6 iterations. The converged points against XFOIL
    // 6.99's sweep: measured |ΔCl| 4.4e-5, |ΔCd|/Cd 4.2e-4, limits about three times that.
    let points = run(1e6, 0.3, &range(-3.5, 0.0, 0.5), false);
    for alpha in [-2.5, -3.5] {
        let p = points.iter().find(|p| p.alpha == alpha).unwrap();
        assert!(p.converged, "{alpha}: not converged");
        assert!(p.iterations <= 8, "{alpha}: {} iterations", p.iterations);
    }
    let (dcl, dcd, compared) =
        deviation_from_xfoil(&points, "naca8h12_Re1e6_M0.3_free_negative.csv");
    assert!(compared >= 6, "{compared}");
    assert!(dcl <= 1.3e-4 && dcd <= 1.3e-3, "{dcl:.2e} {dcd:.2e}");
}

/// A point the march cannot reach is filled in a grid from the Reynolds number below
/// (`SweepParams::series_retry`, `polar::run_grid`): NACA 8-H-12 at Re 2·10⁵, M 0.4, α −4.5°
/// fails on the sweep from 0° down, with every rung of its recovery; in a table with
/// Re 10⁵ below it, the state that α converged to there starts it, and it lands on XFOIL 6.99's
/// solution (`tools/xfoil_reference.py polar --airfoil geometry/naca8h12.dat --re 200000
/// --mach 0.4 --alpha -10 20 0.5 --iter 200`: C_l −0.3547, C_d 0.03668 at −4.5°). The points
/// the sweep converges are the table's, bit for bit.
#[test]
fn grid_fills_a_hole_from_the_reynolds_number_below() {
    use polargen::table::{build_table, GridSpec};
    let alphas: Vec<f64> = (-9..=0).map(|k| 0.5 * f64::from(k)).collect();
    let alone = run(2e5, 0.4, &alphas, true);
    let first = alone[0];
    assert_eq!(first.alpha, -4.5);
    assert!(
        !first.converged,
        "the sweep alone converged −4.5°: {first:?}"
    );

    let grid = GridSpec {
        reynolds: vec![1e5, 2e5],
        mach: vec![0.4],
        alpha_deg: alphas.clone(),
    };
    let table = build_table(
        &naca8h12(),
        160,
        &grid,
        &ViscousParams::at(1e5, 0.4, 1.0),
        2,
        |_| {},
    )
    .unwrap();
    let polar = table.polar(2e5, 0.4).unwrap();
    for (p, q) in alone.iter().zip(polar).filter(|(p, _)| p.converged) {
        assert_eq!(p, q);
    }
    let filled = polar.iter().find(|p| p.alpha == -4.5).unwrap();
    assert!(filled.converged, "{filled:?}");
    assert!((filled.cl - -0.3547).abs() < 1.5e-4, "cl {}", filled.cl);
    assert!((filled.cd / 0.03668 - 1.0).abs() < 3e-4, "cd {}", filled.cd);
}
