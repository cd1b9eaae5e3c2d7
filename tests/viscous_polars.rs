//! Viscous polars against XFOIL 6.99 on XFOIL's own 160 nodes (so that paneling does not
//! enter), −4° ≤ α ≤ 8° in 0.5° steps, each sweep run like the reference: from α = 0 upward
//! with warm starts, then reset and from −0.5° downward. Guards the agreement README.md states:
//! each case must stay within about three times the deviations measured when its limits were
//! set, and the README's accuracy table is this file's output (`readme_accuracy_table_is_current`
//! fails with the command that rewrites it when the table is stale).

mod xfoil_support;

use polargen::section::PolarPoint;
use polargen::viscous::{ViscousParams, ViscousSolver};
use std::sync::OnceLock;
use xfoil_support::{at_alpha, paneled, polar, PolarRow};

/// Largest deviations accepted for a case: median and largest |ΔCd|/Cd, largest |ΔCl| and
/// |ΔCm|, median |Δx_tr| of the upper surface, and |ΔCd|/Cd at Cl = 0.8.
#[derive(Clone, Copy, Debug)]
struct Limits {
    median_dcd: f64,
    max_dcd: f64,
    max_dcl: f64,
    max_dcm: f64,
    median_dxtr_top: f64,
    dcd_at_cl08: f64,
}

/// One sweep compared with XFOIL.
struct Case {
    /// Row label of the README's table.
    label: &'static str,
    foil: &'static str,
    /// Reference polar in tests/data/xfoil.
    file: &'static str,
    re: f64,
    mach: f64,
    xtr_top: f64,
    xtr_bot: f64,
    /// Cd at Cl = 0.8 of the paper's Table 5 (its own XFOIL runs), shown beside ours.
    paper_cd_at_cl08: Option<f64>,
    limits: Limits,
}

/// The cases. Limits: about three times the deviations measured when they were set (in the
/// comment above each: median / max |ΔCd|/Cd, max |ΔCl|, max |ΔCm|, median |Δx_tr|, |ΔCd|/Cd at
/// Cl 0.8), never below half a unit of XFOIL's last printed digit where that is all there is
/// (Cl, Cm and x_tr printed to 1e-4: |ΔCl|, |ΔCm| ≈ 5e-5 is its rounding; Cd to 1e-5, a few
/// 0.01 % of Cd).
const CASES: [Case; 9] = [
    Case {
        label: "NACA 0012 Re 1e6 M 0",
        foil: "naca0012",
        file: "naca0012_Re1e6_M0_free.csv",
        re: 1e6,
        mach: 0.0,
        xtr_top: 1.0,
        xtr_bot: 1.0,
        paper_cd_at_cl08: None,
        // measured 0.038 % / 0.081 %, 4.9e-5, 5.0e-5, 3.6e-5, 1.0e-4
        limits: Limits {
            median_dcd: 1.2e-3,
            max_dcd: 2.5e-3,
            max_dcl: 1.5e-4,
            max_dcm: 1.5e-4,
            median_dxtr_top: 1.1e-4,
            dcd_at_cl08: 5e-4,
        },
    },
    Case {
        label: "NACA 2412 Re 1e6 M 0",
        foil: "naca2412",
        file: "naca2412_Re1e6_M0_free.csv",
        re: 1e6,
        mach: 0.0,
        xtr_top: 1.0,
        xtr_bot: 1.0,
        paper_cd_at_cl08: None,
        // measured 0.030 % / 0.087 %, 4.9e-5, 4.8e-5, 4.3e-5, 1.6e-4
        limits: Limits {
            median_dcd: 1e-3,
            max_dcd: 2.7e-3,
            max_dcl: 1.5e-4,
            max_dcm: 1.5e-4,
            median_dxtr_top: 1.3e-4,
            dcd_at_cl08: 6.5e-4,
        },
    },
    Case {
        label: "NACA 4412 Re 3e6 M 0.2",
        foil: "naca4412",
        file: "naca4412_Re3e6_M0.2_free.csv",
        re: 3e6,
        mach: 0.2,
        xtr_top: 1.0,
        xtr_bot: 1.0,
        paper_cd_at_cl08: None,
        // measured 0.038 % / 0.077 %, 4.9e-5, 4.9e-5, 3.9e-5, 4.7e-4
        limits: Limits {
            median_dcd: 1.2e-3,
            max_dcd: 2.4e-3,
            max_dcl: 1.5e-4,
            max_dcm: 1.5e-4,
            median_dxtr_top: 1.2e-4,
            dcd_at_cl08: 1.4e-3,
        },
    },
    Case {
        label: "NACA 23012 free, Re 1.9e6 M 0.41",
        foil: "naca23012",
        file: "naca23012_Re1.9e6_M0.41_free.csv",
        re: 1.9e6,
        mach: 0.41,
        xtr_top: 1.0,
        xtr_bot: 1.0,
        paper_cd_at_cl08: Some(0.00802),
        // measured 0.034 % / 0.065 %, 4.0e-5, 4.8e-5, 4.0e-5, 2.2e-4
        limits: Limits {
            median_dcd: 1.1e-3,
            max_dcd: 2e-3,
            max_dcl: 1.2e-4,
            max_dcm: 1.5e-4,
            median_dxtr_top: 1.2e-4,
            dcd_at_cl08: 7e-4,
        },
    },
    Case {
        label: "NACA 23012 xtr 0.07",
        foil: "naca23012",
        file: "naca23012_Re1.9e6_M0.41_xtr0.07.csv",
        re: 1.9e6,
        mach: 0.41,
        xtr_top: 0.07,
        xtr_bot: 0.07,
        paper_cd_at_cl08: Some(0.01118),
        // measured 0.027 % / 0.047 %, 4.9e-5, 5.0e-5, 3.1e-7, 1.7e-5
        limits: Limits {
            median_dcd: 8.5e-4,
            max_dcd: 1.5e-3,
            max_dcl: 1.5e-4,
            max_dcm: 1.5e-4,
            median_dxtr_top: 5e-5,
            dcd_at_cl08: 4.5e-4,
        },
    },
    Case {
        label: "NACA 8-H-12 free",
        foil: "naca8h12",
        file: "naca8h12_Re1.9e6_M0.41_free.csv",
        re: 1.9e6,
        mach: 0.41,
        xtr_top: 1.0,
        xtr_bot: 1.0,
        paper_cd_at_cl08: Some(0.00607),
        // measured 0.035 % / 0.088 %, 4.7e-5, 4.8e-5, 5.6e-5, 4.1e-4
        limits: Limits {
            median_dcd: 1.1e-3,
            max_dcd: 2.7e-3,
            max_dcl: 1.5e-4,
            max_dcm: 1.5e-4,
            median_dxtr_top: 1.7e-4,
            dcd_at_cl08: 1.3e-3,
        },
    },
    Case {
        label: "NACA 8-H-12 xtr 0.07",
        foil: "naca8h12",
        file: "naca8h12_Re1.9e6_M0.41_xtr0.07.csv",
        re: 1.9e6,
        mach: 0.41,
        xtr_top: 0.07,
        xtr_bot: 0.07,
        paper_cd_at_cl08: Some(0.01165),
        // measured 0.036 % / 0.13 %, 2.2e-4, 5.6e-5, 4.1e-7, 7.9e-4
        limits: Limits {
            median_dcd: 1.1e-3,
            max_dcd: 3.9e-3,
            max_dcl: 6.6e-4,
            max_dcm: 1.7e-4,
            median_dxtr_top: 5e-5,
            dcd_at_cl08: 2.4e-3,
        },
    },
    Case {
        label: "NACA 4415 Re 2e5 M 0 (laminar bubbles)",
        foil: "naca4415",
        file: "naca4415_Re2e5_M0_free.csv",
        re: 2e5,
        mach: 0.0,
        xtr_top: 1.0,
        xtr_bot: 1.0,
        paper_cd_at_cl08: None,
        // measured 0.016 % / 0.036 %, 4.5e-5, 5.0e-5, 2.6e-5, 2.3e-4
        limits: Limits {
            median_dcd: 5e-4,
            max_dcd: 1.1e-3,
            max_dcl: 1.4e-4,
            max_dcm: 1.5e-4,
            median_dxtr_top: 8e-5,
            dcd_at_cl08: 7e-4,
        },
    },
    Case {
        label: "NACA 0012 Re 3e6 M 0.3, xtr 0.1 / 0.2",
        foil: "naca0012",
        file: "naca0012_Re3e6_M0.3_xtr0.1_0.2.csv",
        re: 3e6,
        mach: 0.3,
        xtr_top: 0.1,
        xtr_bot: 0.2,
        paper_cd_at_cl08: None,
        // measured 0.039 % / 0.060 %, 5.0e-5, 5.0e-5, 9.6e-7, 3.0e-4
        limits: Limits {
            median_dcd: 1.2e-3,
            max_dcd: 1.8e-3,
            max_dcl: 1.5e-4,
            max_dcm: 1.5e-4,
            median_dxtr_top: 5e-5,
            dcd_at_cl08: 9e-4,
        },
    },
];

/// Measured agreement of one case.
#[derive(Debug)]
struct Stats {
    median_dcd: f64,
    max_dcd: f64,
    max_dcl: f64,
    max_dcm: f64,
    median_dxtr_top: f64,
    /// Converged points of ours (of 25) and of XFOIL's in the compared range.
    converged: usize,
    xfoil_converged: usize,
    /// Cd at Cl = 0.8, linear in Cl between converged points: ours and XFOIL's.
    cd_at_cl08: f64,
    xfoil_cd_at_cl08: f64,
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => v[n / 2],
        _ => 0.5 * (v[n / 2 - 1] + v[n / 2]),
    }
}

fn largest(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |m, x| m.max(*x))
}

/// Cd at Cl = 0.8 by linear interpolation in Cl between consecutive (α-sorted) points.
fn cd_at_cl08(points: &[(f64, f64, f64)]) -> f64 {
    points
        .windows(2)
        .find(|w| w[0].1 <= 0.8 && w[1].1 > 0.8)
        .map(|w| w[0].2 + (0.8 - w[0].1) / (w[1].1 - w[0].1) * (w[1].2 - w[0].2))
        .unwrap_or(f64::NAN)
}

/// Runs the sweep of `case` and compares it with XFOIL's polar.
fn run(case: &Case) -> Stats {
    let params = ViscousParams {
        reynolds: case.re,
        mach: case.mach,
        xtr_top: case.xtr_top,
        xtr_bot: case.xtr_bot,
        ..ViscousParams::default()
    };
    let mut solver = ViscousSolver::new(&paneled(case.foil), params).unwrap();
    let mut points: Vec<PolarPoint> = (0..=16)
        .map(|i| solver.solve(0.5 * f64::from(i)).point)
        .collect();
    solver.reset();
    points.extend((1..=8).map(|i| solver.solve(-0.5 * f64::from(i)).point));
    let refs: Vec<PolarRow> = polar(case.file)
        .into_iter()
        .filter(|r| (-4.0..=8.0).contains(&r.alpha))
        .collect();
    let (mut dcd, mut dcl, mut dcm, mut dxt) = (vec![], vec![], vec![], vec![]);
    for p in points.iter().filter(|p| p.converged) {
        let Some(r) = at_alpha(&refs, p.alpha) else {
            continue;
        };
        dcd.push((p.cd - r.cd).abs() / r.cd);
        dcl.push((p.cl - r.cl).abs());
        dcm.push((p.cm - r.cm).abs());
        dxt.push((p.xtr_top - r.xtr_top).abs());
    }
    points.sort_by(|a, b| a.alpha.total_cmp(&b.alpha));
    let ours: Vec<_> = points
        .iter()
        .filter(|p| p.converged)
        .map(|p| (p.alpha, p.cl, p.cd))
        .collect();
    let theirs: Vec<_> = polar(case.file)
        .iter()
        .map(|r| (r.alpha, r.cl, r.cd))
        .collect();
    let stats = Stats {
        median_dcd: median(dcd.clone()),
        max_dcd: largest(&dcd),
        max_dcl: largest(&dcl),
        max_dcm: largest(&dcm),
        median_dxtr_top: median(dxt),
        converged: points.iter().filter(|p| p.converged).count(),
        xfoil_converged: refs.len(),
        cd_at_cl08: cd_at_cl08(&ours),
        xfoil_cd_at_cl08: cd_at_cl08(&theirs),
    };
    eprintln!("{}: {stats:?}", case.label);
    stats
}

/// Every case, computed once (in parallel) for all tests of this file.
fn measured() -> &'static [Stats] {
    static STATS: OnceLock<Vec<Stats>> = OnceLock::new();
    STATS.get_or_init(|| {
        std::thread::scope(|s| {
            let runs: Vec<_> = CASES.iter().map(|c| s.spawn(move || run(c))).collect();
            runs.into_iter().map(|h| h.join().unwrap()).collect()
        })
    })
}

/// The case labelled `label` against its limits; XFOIL's converged points must all converge.
fn check(label: &str) {
    let k = CASES.iter().position(|c| c.label == label).unwrap();
    let (case, s, l) = (&CASES[k], &measured()[k], CASES[k].limits);
    let dcd08 = (s.cd_at_cl08 / s.xfoil_cd_at_cl08 - 1.0).abs();
    for (what, value, limit) in [
        ("median |dCd|/Cd", s.median_dcd, l.median_dcd),
        ("max |dCd|/Cd", s.max_dcd, l.max_dcd),
        ("max |dCl|", s.max_dcl, l.max_dcl),
        ("max |dCm|", s.max_dcm, l.max_dcm),
        ("median |dxtr_top|", s.median_dxtr_top, l.median_dxtr_top),
        ("|dCd|/Cd at Cl 0.8", dcd08, l.dcd_at_cl08),
    ] {
        // NaN (no Cl = 0.8 in the range) fails too.
        assert!(
            value <= limit,
            "{}: {what} {value:.3e} > {limit:.1e}: {s:?}",
            case.label
        );
    }
    assert!(s.converged >= s.xfoil_converged, "{}: {s:?}", case.label);
}

#[test]
fn naca0012_re1e6_m0_free() {
    check("NACA 0012 Re 1e6 M 0");
}

#[test]
fn naca2412_re1e6_m0_free() {
    check("NACA 2412 Re 1e6 M 0");
}

#[test]
fn naca4412_re3e6_m02_free() {
    check("NACA 4412 Re 3e6 M 0.2");
}

#[test]
fn naca23012_re19e5_m041_free() {
    check("NACA 23012 free, Re 1.9e6 M 0.41");
}

#[test]
fn naca23012_re19e5_m041_xtr007() {
    check("NACA 23012 xtr 0.07");
}

#[test]
fn naca8h12_re19e5_m041_free() {
    check("NACA 8-H-12 free");
}

#[test]
fn naca8h12_re19e5_m041_xtr007() {
    check("NACA 8-H-12 xtr 0.07");
}

/// Low Reynolds number with laminar separation bubbles.
#[test]
fn naca4415_re2e5_m0_free_bubble() {
    check("NACA 4415 Re 2e5 M 0 (laminar bubbles)");
}

/// Different trips on the two surfaces.
#[test]
fn naca0012_re3e6_m03_trip_top01_bot02() {
    check("NACA 0012 Re 3e6 M 0.3, xtr 0.1 / 0.2");
}

/// The README's accuracy table as this file measures it.
fn accuracy_table() -> String {
    let mut t = String::from(
        "| case | median / max \\|ΔCd\\|/Cd | max \\|ΔCl\\| | max \\|ΔCm\\| | median \\|Δx_tr\\| upper \
         | converged (ours / XFOIL) | Cd at Cl = 0.8: ours / XFOIL (paper) |\n|---|---|---|---|---|---|---|\n",
    );
    for (case, s) in CASES.iter().zip(measured()) {
        let cd08 = if s.cd_at_cl08.is_nan() {
            String::new()
        } else {
            let paper = case
                .paper_cd_at_cl08
                .map_or(String::new(), |p| format!(" ({p})"));
            format!("{:.6} / {:.6}{paper}", s.cd_at_cl08, s.xfoil_cd_at_cl08)
        };
        t.push_str(&format!(
            "| {} | {:.2} % / {:.2} % | {:.1e} | {:.1e} | {:.1e} | {} / {} | {cd08} |\n",
            case.label,
            100.0 * s.median_dcd,
            100.0 * s.max_dcd,
            s.max_dcl,
            s.max_dcm,
            s.median_dxtr_top,
            s.converged,
            s.xfoil_converged,
        ));
    }
    t
}

#[test]
fn readme_accuracy_table_is_current() {
    xfoil_support::check_readme_block(
        "viscous accuracy",
        "UPDATE_README=1 cargo test --test viscous_polars readme",
        &accuracy_table(),
    );
}
