//! PolarTable construction, validation and accessors.

mod table_support;

use polargen::section::FlowCondition;
use polargen::section::PolarPoint;
use polargen::section::SectionAero;
use polargen::table::{PolarTable, TableError};
use table_support::*;

fn small(re: Vec<f64>, mach: Vec<f64>) -> Result<PolarTable, TableError> {
    let alphas = alpha_range(-2.0, 2.0, 1.0);
    let polars = re
        .iter()
        .flat_map(|&r| mach.iter().map(move |&m| (r, m)))
        .map(|(r, m)| analytic_polar(r.max(1.0), m, &alphas))
        .collect();
    PolarTable::new(meta("small"), re, mach, polars)
}

#[test]
fn grid_shape_and_accessors() {
    let t = analytic_table();
    assert_eq!(t.re(), &[0.5e6, 1e6, 2e6]);
    assert_eq!(t.mach(), &[0.0, 0.2, 0.4]);
    assert_eq!(t.polars().count(), 9);
    assert_eq!(t.point_count(), 9 * 26);
    assert_eq!(t.converged_count(), 9 * 26);
    let p = t.polar(1e6, 0.2).unwrap();
    assert_eq!(p.len(), 26);
    assert!((p[10].cl - cl_model(0.0, 1e6, 0.2)).abs() < 1e-15);
    assert!(t.polar(1.5e6, 0.2).is_none());
    assert!(t.polar_at(3, 0).is_none());
    let (at, pts) = t.nearest_polar(1.3e6, 0.29);
    assert_eq!((at, pts.len()), (FlowCondition::new(1e6, 0.2), 26));
    let (at, _) = t.nearest_polar(1.5e6, 0.31);
    assert_eq!(at, FlowCondition::new(2e6, 0.4)); // 1.5e6 is nearer 2e6 than 1e6 in ln Re
    let (at, _) = t.nearest_polar(1e9, -3.0);
    assert_eq!(at, FlowCondition::new(2e6, 0.0));
    assert_eq!(t.alpha_range(2, 2), Some((-10.0, 15.0)));
}

#[test]
fn from_polars_infers_axes_and_sorts_points() {
    let alphas = [3.0, -1.0, 0.0, 2.0, 1.0];
    let mut list = Vec::new();
    for &m in &[0.3, 0.0] {
        for &r in &[2e6, 5e5] {
            list.push((FlowCondition::new(r, m), analytic_polar(r, m, &alphas)));
        }
    }
    let t = PolarTable::from_polars(meta("x"), list).unwrap();
    assert_eq!(t.re(), &[5e5, 2e6]);
    assert_eq!(t.mach(), &[0.0, 0.3]);
    let a: Vec<f64> = t.polar(2e6, 0.3).unwrap().iter().map(|p| p.alpha).collect();
    assert_eq!(a, vec![-1.0, 0.0, 1.0, 2.0, 3.0]);
    assert_eq!(t.polar_at(1, 1).unwrap()[0].cl, cl_model(-1.0, 2e6, 0.3));
}

#[test]
fn unconverged_points_are_kept_and_counted() {
    let mut pts = analytic_polar(1e6, 0.0, &alpha_range(-2.0, 6.0, 1.0));
    pts[3] = failed(1.0);
    pts[4].converged = false;
    pts[4].cl = f64::NAN; // NaN is allowed in an unconverged point
    let t = PolarTable::new(meta("x"), vec![1e6], vec![0.0], vec![pts]).unwrap();
    assert_eq!(t.point_count(), 9);
    assert_eq!(t.converged_count(), 7);
    assert!(!t.polar(1e6, 0.0).unwrap()[3].converged);
}

#[test]
fn ragged_and_duplicate_grids_are_rejected() {
    let alphas = [0.0, 1.0];
    let list = vec![
        (
            FlowCondition::new(1e6, 0.0),
            analytic_polar(1e6, 0.0, &alphas),
        ),
        (
            FlowCondition::new(2e6, 0.0),
            analytic_polar(2e6, 0.0, &alphas),
        ),
        (
            FlowCondition::new(1e6, 0.2),
            analytic_polar(1e6, 0.2, &alphas),
        ),
    ];
    let e = PolarTable::from_polars(meta("x"), list.clone()).unwrap_err();
    assert_eq!(e.to_string(), "ragged grid: no polar at Re 2000000, M 0.2");
    let mut nan = list.clone();
    nan[2].0.mach = f64::NAN;
    let e = PolarTable::from_polars(meta("x"), nan).unwrap_err();
    assert_eq!(e.to_string(), "Mach must be in [0, 1), got NaN");
    let mut dup = list;
    dup.push(dup[0].clone());
    let e = PolarTable::from_polars(meta("x"), dup).unwrap_err();
    assert_eq!(e.to_string(), "duplicate polar at Re 1000000, M 0");
    let e = PolarTable::new(meta("x"), vec![1e6, 2e6], vec![0.0], vec![vec![]]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "ragged grid: 2 Re × 1 Mach needs 2 polars, got 1"
    );
}

#[test]
fn axes_are_validated() {
    let msg = |r: Result<PolarTable, TableError>| r.unwrap_err().to_string();
    assert_eq!(msg(small(vec![], vec![0.0])), "table has no Re values");
    assert_eq!(
        msg(small(vec![2e6, 1e6], vec![0.0])),
        "Re axis is not strictly increasing: 1000000 follows 2000000"
    );
    assert_eq!(
        msg(small(vec![1e6], vec![0.2, 0.2])),
        "Mach axis is not strictly increasing: 0.2 follows 0.2"
    );
    assert_eq!(
        msg(small(vec![0.0, 1e6], vec![0.0])),
        "Re must be positive and at most 1e10, got 0"
    );
    assert_eq!(
        msg(small(vec![1e6], vec![0.5, 1.0])),
        "Mach must be in [0, 1), got 1"
    );
    assert_eq!(
        msg(small(vec![1e6], vec![-0.1, 0.5])),
        "Mach must be in [0, 1), got -0.1"
    );
    assert!(small(vec![1e6, 2e6], vec![0.0, 0.5]).is_ok());
}

#[test]
fn points_are_validated() {
    let one = |pts: Vec<PolarPoint>| {
        PolarTable::new(meta("x"), vec![1e6], vec![0.3], vec![pts])
            .unwrap_err()
            .to_string()
    };
    let mut pts = analytic_polar(1e6, 0.3, &[0.0, 1.0, 2.0]);
    pts[1].cd = f64::NAN;
    assert_eq!(
        one(pts),
        "cd is NaN at Re 1000000, M 0.3, alpha 1 (must be finite)"
    );
    let pts = analytic_polar(1e6, 0.3, &[0.0, 1.0, 1.0]);
    assert_eq!(one(pts), "duplicate alpha 1 in polar Re 1000000, M 0.3");
    let mut pts = analytic_polar(1e6, 0.3, &[0.0, 1.0, 2.0]);
    pts[2].cd = -0.01;
    assert_eq!(
        one(pts),
        "cd -0.01 < 0 at alpha 2 in polar Re 1000000, M 0.3"
    );
    // …but only converged points are held to it.
    let mut pts = analytic_polar(1e6, 0.3, &[0.0, 1.0, 2.0]);
    pts[2].cd = -0.01;
    pts[2].converged = false;
    PolarTable::new(meta("x"), vec![1e6], vec![0.3], vec![pts]).unwrap();
    let pts = analytic_polar(1e6, 0.3, &[0.0, 190.0]);
    assert_eq!(
        one(pts),
        "alpha 190 outside [-180, 180] in polar Re 1000000, M 0.3"
    );
    // Too few converged points for a lookup: the table is a valid record, but unusable for
    // lookups, which say so.
    let pts = vec![failed(0.0), failed(1.0), point(2.0, 0.1, 0.01, 0.0)];
    let t = PolarTable::new(meta("x"), vec![1e6], vec![0.3], vec![pts]).unwrap();
    assert!(!t.has_lookup());
    assert_eq!(
        t.require_lookup().unwrap_err().to_string(),
        "empty table: no polar has at least 2 converged points outside massive separation \
         (docs/limits.md)"
    );
    assert!(t.lookup(1.0, 1e6, 0.3).cl.is_nan());
}

#[test]
fn tables_can_be_shared_across_threads() {
    fn shareable<T: Send + Sync>(_: &T) -> bool {
        true
    }
    let t = analytic_table();
    assert!(shareable(&t));
    let cl: Vec<f64> = std::thread::scope(|s| {
        let h: Vec<_> = (0..2)
            .map(|k| {
                let t = &t;
                s.spawn(move || polargen::section::SectionAero::lookup(t, k as f64, 1e6, 0.2).cl)
            })
            .collect();
        h.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert!((cl[1] - cl[0] - 0.11).abs() < 1e-12);
}
