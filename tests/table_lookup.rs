//! Lookup: interpolation in α (PCHIP), ln Re and M, clamping, gap bridging and the 360°
//! extension.

mod table_support;

use polargen::section::FlowCondition;
use polargen::section::PolarPoint;
use polargen::section::SectionAero;
use polargen::table::{PolarTable, PostStallParams};
use table_support::*;

const EXACT: f64 = 1e-12;

#[test]
fn exact_on_grid_nodes() {
    let t = analytic_table();
    for (FlowCondition { reynolds: re, mach }, points) in t.polars() {
        for p in points {
            let l = t.lookup(p.alpha, re, mach);
            assert!((l.cl - p.cl).abs() < EXACT, "cl at {re} {mach} {}", p.alpha);
            assert!((l.cd - p.cd).abs() < EXACT);
            assert!((l.cm - p.cm).abs() < EXACT);
            assert!(!l.re_clamped && !l.mach_clamped && !l.post_stall && !l.bridged);
        }
    }
}

#[test]
fn exact_between_nodes_in_alpha_log_re_and_mach() {
    // The analytic model is linear in α and bilinear in (ln Re, M): PCHIP reproduces linear
    // data and the (ln Re, M) interpolation is bilinear, so every interior lookup is exact.
    let t = analytic_table();
    for &alpha in &[-9.3, -0.5, 0.25, 7.77, 14.9] {
        for &re in &[0.6e6, 1e6, 1.37e6, 1.9e6] {
            for &mach in &[0.05, 0.2, 0.31, 0.39] {
                let l = t.lookup(alpha, re, mach);
                assert!((l.cl - cl_model(alpha, re, mach)).abs() < 1e-12);
                assert!((l.cd - cd_model(alpha, re, mach)).abs() < 1e-12);
                assert!((l.cm - cm_model(alpha, re, mach)).abs() < 1e-12);
                assert!(!l.re_clamped && !l.mach_clamped && !l.post_stall && !l.bridged);
            }
        }
    }
}

#[test]
fn non_uniform_alpha_spacing_is_exact() {
    // Clustered and sparse nodes (spacings from 1e-6° to 7°) exercise the interval index.
    let alphas = [
        -12.0, -5.0, -4.9, 0.0, 1e-6, 0.5, 0.75, 3.0, 10.0, 10.001, 17.0,
    ];
    let t = PolarTable::new(
        meta("uneven"),
        vec![1e6],
        vec![0.0],
        vec![analytic_polar(1e6, 0.0, &alphas)],
    )
    .unwrap();
    for k in 0..=2900 {
        let a = -12.0 + k as f64 * 0.01;
        let l = t.lookup(a, 1e6, 0.0);
        assert!((l.cl - cl_model(a, 1e6, 0.0)).abs() < 1e-12, "cl at {a}");
        assert!(!l.post_stall);
    }
    for &a in &alphas {
        assert_eq!(t.lookup(a, 1e6, 0.0).cl, cl_model(a, 1e6, 0.0), "node {a}");
    }
}

#[test]
fn re_interpolation_is_linear_in_log_re() {
    // Two polars differing only by a constant cl offset: at the geometric mean of the two Re
    // values the offset is exactly halfway (linear in ln Re), not at the arithmetic mean.
    let alphas = alpha_range(-5.0, 10.0, 1.0);
    let mk = |off: f64| -> Vec<PolarPoint> {
        alphas
            .iter()
            .map(|&a| point(a, 0.1 * a + off, 0.01, 0.0))
            .collect()
    };
    let t = PolarTable::new(
        meta("two-re"),
        vec![1e5, 1e7],
        vec![0.0],
        vec![mk(0.0), mk(1.0)],
    )
    .unwrap();
    let l = t.lookup(2.0, 1e6, 0.0);
    assert!((l.cl - (0.2 + 0.5)).abs() < EXACT, "cl {}", l.cl);
    let l = t.lookup(2.0, 5.05e6, 0.0);
    let w = (5.05e6f64 / 1e5).ln() / 100f64.ln();
    assert!((l.cl - (0.2 + w)).abs() < EXACT);
}

#[test]
fn pchip_is_monotone_and_c1_on_reference_polar() {
    // XFOIL 6.99 NACA 8-H-12, Re 1.9e6, M 0.41, free transition: lookups reproduce every node
    // exactly, stay within the neighbouring node values (no overshoot) and the slope is
    // continuous across a node.
    let pts = xfoil_reference("naca8h12_Re1.9e6_M0.41_free.csv");
    let t = PolarTable::new(meta("naca8h12"), vec![1.9e6], vec![0.41], vec![pts.clone()]).unwrap();
    for p in &pts {
        let l = t.lookup(p.alpha, 1.9e6, 0.41);
        assert!((l.cl - p.cl).abs() < EXACT && (l.cd - p.cd).abs() < EXACT);
        assert!((l.cm - p.cm).abs() < EXACT);
    }
    for w in pts.windows(2) {
        for k in 1..10 {
            let a = w[0].alpha + (w[1].alpha - w[0].alpha) * k as f64 / 10.0;
            let l = t.lookup(a, 1.9e6, 0.41);
            let (lo, hi) = (w[0].cl.min(w[1].cl), w[0].cl.max(w[1].cl));
            assert!(
                l.cl >= lo - EXACT && l.cl <= hi + EXACT,
                "cl overshoot at {a}"
            );
            let (lo, hi) = (w[0].cd.min(w[1].cd), w[0].cd.max(w[1].cd));
            assert!(
                l.cd >= lo - EXACT && l.cd <= hi + EXACT,
                "cd overshoot at {a}"
            );
        }
    }
    // C¹: one-sided difference quotients at an interior node agree to O(h).
    let h = 1e-6;
    for p in &pts[1..pts.len() - 1] {
        let left = (t.lookup(p.alpha, 1.9e6, 0.41).cl - t.lookup(p.alpha - h, 1.9e6, 0.41).cl) / h;
        let right = (t.lookup(p.alpha + h, 1.9e6, 0.41).cl - t.lookup(p.alpha, 1.9e6, 0.41).cl) / h;
        assert!((left - right).abs() < 1e-3, "slope jump at {}", p.alpha);
    }
}

#[test]
fn clamping_outside_re_and_mach() {
    let t = analytic_table();
    let edge = t.lookup(3.0, 0.5e6, 0.0);
    let low = t.lookup(3.0, 1e5, -0.1);
    assert!(low.re_clamped && low.mach_clamped);
    assert_eq!((low.cl, low.cd, low.cm), (edge.cl, edge.cd, edge.cm));
    let edge = t.lookup(3.0, 2e6, 0.4);
    let high = t.lookup(3.0, 9e6, 0.9);
    assert!(high.re_clamped && high.mach_clamped);
    assert_eq!((high.cl, high.cd, high.cm), (edge.cl, edge.cd, edge.cm));
    let only_re = t.lookup(3.0, 9e6, 0.2);
    assert!(only_re.re_clamped && !only_re.mach_clamped);
    let bad = t.lookup(3.0, -1.0, f64::NAN);
    assert!(bad.re_clamped && bad.mach_clamped && bad.cl.is_finite());
    // A single-Re table is exact only at its Re.
    let pts = analytic_polar(1e6, 0.3, &alpha_range(-5.0, 5.0, 1.0));
    let single = PolarTable::new(meta("one"), vec![1e6], vec![0.3], vec![pts]).unwrap();
    assert!(!single.lookup(1.0, 1e6, 0.3).re_clamped);
    assert!(single.lookup(1.0, 1.1e6, 0.3).re_clamped);
    assert!(single.lookup(1.0, 1e6, 0.31).mach_clamped);
}

#[test]
fn gaps_are_bridged_and_unconverged_points_never_used() {
    let re = 1e6;
    let mut pts = analytic_polar(re, 0.0, &alpha_range(-4.0, 12.0, 1.0));
    // α = 5 and 6 failed: replace them by unconverged points with garbage coefficients.
    for p in pts.iter_mut().filter(|p| p.alpha == 5.0 || p.alpha == 6.0) {
        *p = failed(p.alpha);
    }
    let t = PolarTable::new(meta("gap"), vec![re], vec![0.0], vec![pts]).unwrap();
    assert_eq!(t.converged_count(), 15);
    for &a in &[4.5, 5.0, 5.5, 6.0, 6.9] {
        let l = t.lookup(a, re, 0.0);
        assert!(l.bridged, "α {a} should be bridged");
        assert!(
            (l.cl - cl_model(a, re, 0.0)).abs() < EXACT,
            "cl at {a}: {}",
            l.cl
        );
        assert!((l.cm - cm_model(a, re, 0.0)).abs() < EXACT);
    }
    for &a in &[3.9, 7.0, 7.5] {
        assert!(!t.lookup(a, re, 0.0).bridged, "α {a} is not in the gap");
    }
}

#[test]
fn unconverged_points_at_the_ends_start_the_extension_earlier() {
    let re = 1e6;
    let mut pts = analytic_polar(re, 0.0, &alpha_range(-4.0, 12.0, 1.0));
    for p in pts.iter_mut().filter(|p| p.alpha >= 11.0) {
        *p = failed(p.alpha);
    }
    let t = PolarTable::new(meta("tail"), vec![re], vec![0.0], vec![pts]).unwrap();
    assert_eq!(t.alpha_range(0, 0), Some((-4.0, 10.0)));
    let l = t.lookup(11.0, re, 0.0);
    assert!(l.post_stall && !l.bridged);
    assert!(l.cl < 5.0 && l.cl > 0.0, "garbage cl leaked: {}", l.cl);
}

#[test]
fn dead_polar_is_replaced_by_its_neighbour_and_flagged() {
    let alphas = alpha_range(-5.0, 10.0, 1.0);
    let dead: Vec<PolarPoint> = alphas.iter().map(|&a| failed(a)).collect();
    let t = PolarTable::new(
        meta("dead"),
        vec![1e6],
        vec![0.0, 0.2, 0.4],
        vec![
            analytic_polar(1e6, 0.0, &alphas),
            analytic_polar(1e6, 0.2, &alphas),
            dead,
        ],
    )
    .unwrap();
    let l = t.lookup(2.0, 1e6, 0.4);
    assert!(l.bridged);
    assert!((l.cl - cl_model(2.0, 1e6, 0.2)).abs() < EXACT);
    assert!(!t.lookup(2.0, 1e6, 0.2).bridged);
}

/// Maximum jump of (cl, cd, cm) across `a` (one-sided values at a ± 1e-9).
fn jump(t: &PolarTable, a: f64, re: f64, mach: f64) -> f64 {
    let (l, r) = (t.lookup(a - 1e-9, re, mach), t.lookup(a + 1e-9, re, mach));
    (l.cl - r.cl)
        .abs()
        .max((l.cd - r.cd).abs())
        .max((l.cm - r.cm).abs())
}

#[test]
fn extension_is_continuous_at_junctions_and_90_degrees() {
    let pts = xfoil_reference("naca8h12_Re1.9e6_M0.41_xtr0.07.csv");
    let (lo, hi) = (pts[0].alpha, pts[pts.len() - 1].alpha);
    let t = PolarTable::new(meta("naca8h12"), vec![1.9e6], vec![0.41], vec![pts]).unwrap();
    for a in [lo, hi, -90.0, 90.0] {
        let j = jump(&t, a, 1.9e6, 0.41);
        assert!(j < 1e-6, "jump {j} at α {a}");
    }
    assert!(!t.lookup(hi, 1.9e6, 0.41).post_stall);
    assert!(t.lookup(hi + 1e-6, 1.9e6, 0.41).post_stall);
    assert!(t.lookup(lo - 1e-6, 1.9e6, 0.41).post_stall);
    // Continuity over the whole circle: no step larger than a smooth function allows.
    let mut prev = t.lookup(-180.0, 1.9e6, 0.41);
    for k in 1..=36000 {
        let a = -180.0 + k as f64 * 0.01;
        let l = t.lookup(a, 1.9e6, 0.41);
        let d = (l.cl - prev.cl)
            .abs()
            .max((l.cd - prev.cd).abs())
            .max((l.cm - prev.cm).abs());
        assert!(d < 0.01, "step {d} at α {a}");
        assert!(l.cd > 0.0, "negative cd at {a}");
        prev = l;
    }
}

#[test]
fn extension_is_periodic() {
    let t = analytic_table();
    let (a, b) = (t.lookup(180.0, 1e6, 0.2), t.lookup(-180.0, 1e6, 0.2));
    assert!((a.cl - b.cl).abs() < 1e-12 && (a.cd - b.cd).abs() < 1e-12);
    assert!((a.cm - b.cm).abs() < 1e-12);
    assert!(jump(&t, 180.0, 1e6, 0.2) < 1e-6);
    for &alpha in &[-170.0, -33.0, 4.5, 95.0] {
        for turns in [-2.0, 1.0, 3.0] {
            let x = t.lookup(alpha + 360.0 * turns, 1e6, 0.2);
            let y = t.lookup(alpha, 1e6, 0.2);
            assert!((x.cl - y.cl).abs() < 1e-9 && (x.cd - y.cd).abs() < 1e-9);
        }
    }
}

#[test]
fn reverse_flow_is_sane() {
    let t = analytic_table();
    let p = PostStallParams::default();
    let at = |a: f64| t.lookup(a, 1e6, 0.2);
    // Broadside: flat-plate drag cd_max ≈ 2, no lift.
    for a in [90.0, -90.0] {
        assert!((at(a).cd - p.cd_max).abs() < 1e-9 && at(a).cl.abs() < 1e-9);
    }
    assert!((at(90.0).cd - 2.0).abs() < 1e-9);
    // Reverse flow: lift has the sign of sin 2α (trailing edge first), cd back to cd_reverse.
    for a in [100.0, 135.0, 170.0, 179.0] {
        assert!(at(a).cl < 0.0 && at(-a).cl > 0.0, "cl sign at ±{a}");
        assert!(at(a).cm < 0.0 && at(-a).cm > 0.0, "cm sign at ±{a}");
    }
    assert!((at(180.0).cd - p.cd_reverse).abs() < 1e-12);
    assert!(at(180.0).cl.abs() < 1e-12 && at(180.0).post_stall);
    // Deep stall between junction and 90°: positive lift on the positive side.
    for a in [20.0, 45.0, 70.0] {
        assert!(at(a).cl > 0.0 && at(-a).cl < 0.0);
    }
    assert!((at(45.0).cd - at(-45.0).cd).abs() < 0.2);
}

#[test]
fn viterna_corrigan_matches_its_equations() {
    // Independent evaluation of Viterna & Corrigan (1982) at α = 40° from the junction
    // (last converged point) of the reference polar.
    let pts = xfoil_reference("naca8h12_Re1.9e6_M0.41_free.csv");
    let s = pts[pts.len() - 1];
    let t = PolarTable::new(meta("naca8h12"), vec![1.9e6], vec![0.41], vec![pts]).unwrap();
    let cd_max = t.post_stall_params().cd_max;
    let (ss, cs) = s.alpha.to_radians().sin_cos();
    let a2 = (s.cl - cd_max * ss * cs) * ss / (cs * cs);
    let b2 = (s.cd - cd_max * ss * ss) / cs;
    let (sa, ca) = 40f64.to_radians().sin_cos();
    let cl = cd_max / 2.0 * (2.0 * sa * ca) + a2 * ca * ca / sa;
    let cd = cd_max * sa * sa + b2 * ca;
    let l = t.lookup(40.0, 1.9e6, 0.41);
    assert!((l.cl - cl).abs() < 1e-12 && (l.cd - cd).abs() < 1e-12);
    assert!(l.post_stall);
}

#[test]
fn narrow_polar_uses_the_blend_and_stays_continuous() {
    // Converged only on −1…1°: the junction is too close to 0° for Viterna–Corrigan.
    let pts = analytic_polar(1e6, 0.0, &[-1.0, -0.5, 0.0, 0.5, 1.0]);
    let t = PolarTable::new(meta("narrow"), vec![1e6], vec![0.0], vec![pts]).unwrap();
    for a in [-90.0, -1.0, 1.0, 90.0, 180.0] {
        assert!(jump(&t, a, 1e6, 0.0) < 1e-6, "jump at {a}");
    }
    for k in -180..=180 {
        let l = t.lookup(k as f64, 1e6, 0.0);
        assert!(
            l.cl.is_finite() && l.cd >= 0.0 && l.cm.is_finite(),
            "at {k}"
        );
    }
}

#[test]
fn custom_post_stall_parameters_are_used() {
    let p = PostStallParams {
        cd_max: 1.8,
        cd_reverse: 0.05,
        vc_min_junction_deg: 3.0,
    };
    let t = analytic_table().with_post_stall(p).unwrap();
    assert!((t.lookup(90.0, 1e6, 0.0).cd - 1.8).abs() < 1e-12);
    assert!((t.lookup(-180.0, 1e6, 0.0).cd - 0.05).abs() < 1e-12);
    let bad = PostStallParams {
        cd_max: -1.0,
        ..PostStallParams::default()
    };
    assert_eq!(
        t.clone().with_post_stall(bad).unwrap_err().to_string(),
        "post-stall parameter cd_max = -1 is invalid (must be in (0, 3])"
    );
    let bad = PostStallParams {
        vc_min_junction_deg: f64::NAN,
        ..PostStallParams::default()
    };
    assert_eq!(
        t.with_post_stall(bad).unwrap_err().to_string(),
        "post-stall parameter vc_min_junction_deg = NaN is invalid (must be in [0, 90))"
    );
}

#[test]
fn non_finite_queries_do_not_panic() {
    let t = analytic_table();
    let l = t.lookup(f64::NAN, 1e6, 0.2);
    assert!(l.cl.is_nan() && l.post_stall);
    assert!(t.lookup(f64::INFINITY, 1e6, 0.2).cl.is_nan());
    let l = t.lookup(3.0, f64::INFINITY, f64::NEG_INFINITY);
    assert!(l.re_clamped && l.mach_clamped);
    assert!((l.cl - cl_model(3.0, 2e6, 0.0)).abs() < 1e-12);
    let l = t.lookup(1e300, 0.0, 0.2);
    assert!(l.re_clamped && l.cl.is_finite());
}

/// The column lookup is the point lookup at each (α, Re, M), flags included, over the
/// shortest column.
#[test]
fn lookup_many_is_the_lookup_of_each_row() {
    let t = analytic_table();
    let alpha = [-170.0, -9.3, 0.25, 14.9, 40.0, 400.0];
    let re = [1e5, 0.6e6, 1e6, 1.9e6, 3e7, 1e6];
    let mach = [0.0, 0.05, 0.2, 0.39, 0.9, 0.3];
    let many = t.lookup_many(&alpha, &re, &mach);
    assert_eq!(many.len(), alpha.len());
    for (k, l) in many.iter().enumerate() {
        assert_eq!(*l, t.lookup(alpha[k], re[k], mach[k]), "row {k}");
    }
    assert!(many[0].post_stall && many[4].re_clamped && many[4].mach_clamped);
    assert_eq!(t.lookup_many(&alpha, &re[..2], &mach).len(), 2);
}
