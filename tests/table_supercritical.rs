//! The minimum pressure and the supercritical flag of table points: the columns of every
//! format, files written without them (unknown, not "subcritical"), the flags lookups carry
//! and the census `polargen` prints.

mod table_support;

use polargen::section::{FlowCondition, SectionAero};
use polargen::table::{parse_table, write_table, PolarTable, TableCensus, TableFormat};
use table_support::*;

/// One polar at (1e6, `mach`) over α 0…6°, the point at 4° supercritical.
fn flagged_polar(mach: f64) -> (FlowCondition, Vec<polargen::section::PolarPoint>) {
    let mut pts = analytic_polar(1e6, mach, &alpha_range(0.0, 6.0, 1.0));
    for p in &mut pts {
        p.cpmin = -0.5 - 0.2 * p.alpha;
        p.supercritical = Some(p.alpha == 4.0);
    }
    (FlowCondition::new(1e6, mach), pts)
}

#[test]
fn lookups_flag_the_intervals_of_supercritical_points() {
    let t = PolarTable::from_polars(meta("f"), vec![flagged_polar(0.5)]).unwrap();
    let flag = |a: f64| t.lookup(a, 1e6, 0.5).supercritical;
    // The point at 4° taints the intervals 3…4° and 4…5°, nothing else.
    assert!(!flag(1.5) && !flag(2.9) && flag(3.2) && flag(4.0) && flag(4.8) && !flag(5.5));
    assert!(!t.lookup(3.5, 1e6, 0.5).supercritical_unknown);
    // The 360° extension leans on the junction point: flagged when the last point is.
    let mut last = flagged_polar(0.5);
    last.1[6].supercritical = Some(true);
    let t = PolarTable::from_polars(meta("f"), vec![last]).unwrap();
    assert!(t.lookup(40.0, 1e6, 0.5).supercritical && !t.lookup(-40.0, 1e6, 0.5).supercritical);
    assert_eq!(
        t.census(),
        TableCensus {
            points: 7,
            converged: 7,
            supercritical: 2,
            unknown: 0,
            massive_separation: 0,
            separation_unknown: 0,
        }
    );
}

#[test]
fn files_without_the_columns_read_as_unknown() {
    let text = "airfoil,re,mach,ncrit,xtr_top_set,xtr_bot_set,alpha,cl,cd,cdp,cm,xtr_top,xtr_bot,converged\n\
                foil,1e6,0.6,9,1,1,0,0.1,0.01,0.004,-0.01,0.5,0.9,true\n\
                foil,1e6,0.6,9,1,1,2,0.3,0.01,0.004,-0.01,0.5,0.9,true\n";
    let t = parse_table(text.as_bytes(), TableFormat::Csv).unwrap();
    let p = t.polar(1e6, 0.6).unwrap();
    assert!(p[0].cpmin.is_nan() && p[0].supercritical.is_none());
    let l = t.lookup(1.0, 1e6, 0.6);
    assert!(l.supercritical_unknown && !l.supercritical);
    assert_eq!(
        t.census().to_string(),
        "2 of 2 points converged (100.0 %); 0 of them supercritical (Cp_min < Cp*), 0 in \
         massive separation (not used), 2 without the supercritical and 2 without the \
         separation flag (unknown)"
    );
    // With `cpmin` but without `supercritical` the flag follows from Cp* at the row's Mach
    // number: Cp*(0.6) = −1.2948, so −1.30 is supercritical and −1.29 is not.
    let text = text
        .replace("converged\n", "converged,cpmin\n")
        .replacen("true\n", "true,-1.29\n", 1)
        .replacen("0.9,true\n", "0.9,true,-1.30\n", 1);
    let t = parse_table(text.as_bytes(), TableFormat::Csv).unwrap();
    let p = t.polar(1e6, 0.6).unwrap();
    assert_eq!(
        (p[0].supercritical, p[1].supercritical),
        (Some(false), Some(true))
    );
    // JSON written before the fields existed: the same unknowns.
    let mut json = serde_json::to_value(&t).unwrap();
    for point in json["polars"][0].as_array_mut().unwrap() {
        let point = point.as_object_mut().unwrap();
        point.remove("cpmin");
        point.remove("supercritical");
    }
    let t = parse_table(json.to_string().as_bytes(), TableFormat::Json).unwrap();
    let p = t.polar(1e6, 0.6).unwrap();
    assert!(p[1].cpmin.is_nan() && p[1].supercritical.is_none());
}

#[test]
fn every_readable_format_carries_the_flag() {
    let t = PolarTable::from_polars(meta("f"), vec![flagged_polar(0.6)]).unwrap();
    let dir = scratch("supercritical_formats");
    for name in ["t.csv", "t.json", "t.pol"] {
        let path = dir.join(name);
        write_table(&t, &path, None).unwrap();
        let back = polargen::table::read_table(&path).unwrap();
        let flags: Vec<Option<bool>> = back
            .polar(1e6, 0.6)
            .unwrap()
            .iter()
            .map(|p| p.supercritical)
            .collect();
        // The XFOIL polar holds Cpmin (4 decimals) and derives the flag from Cp*(0.6) =
        // −1.2948: the points at 4°, 5°, 6° (Cp_min −1.3, −1.5, −1.7) are supercritical there.
        let expected: Vec<Option<bool>> = match name {
            "t.pol" => (0..7)
                .map(|a| Some(-0.5 - 0.2 * f64::from(a) < -1.2948))
                .collect(),
            _ => (0..7).map(|a| Some(a == 4)).collect(),
        };
        assert_eq!(flags, expected, "{name}");
    }
    let text = std::fs::read_to_string(dir.join("t.csv")).unwrap();
    assert!(text
        .lines()
        .next()
        .unwrap()
        .contains(",cpmin,supercritical,xsep_top,xsep_bot,massive_separation"));
    std::fs::remove_dir_all(dir).unwrap();
}
