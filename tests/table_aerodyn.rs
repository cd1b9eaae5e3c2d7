//! OpenFAST AeroDyn airfoil files: the line order OpenFAST's `ReadAFfile` expects, one table
//! per Re (in millions) with its unsteady-aero block, α from −180° to 180° with equal ends,
//! values in shortest round-trip form equal to the table's lookups, one file per Mach number,
//! read back as the table. (The Python tests `python/tests/test_aerodyn_openfast_io.py` and
//! `test_openfast.py` read the files with OpenFAST's `openfast_io` and with weio.)

mod table_support;

use polargen::section::SectionAero;
use polargen::table::{parse_table, ua_parameters, write_table, PolarTable, TableFormat};
use table_support::*;

/// The non-comment lines of an AeroDyn file, split into words (trailing comments dropped).
fn data_lines(text: &str) -> Vec<Vec<String>> {
    text.lines()
        .filter(|l| !l.trim_start().starts_with('!') && !l.trim().is_empty())
        .map(|l| {
            l.split('!')
                .next()
                .unwrap()
                .split_whitespace()
                .map(String::from)
                .collect()
        })
        .collect()
}

#[test]
fn layout_follows_openfast_and_values_are_exact_lookups() {
    let alphas = alpha_range(-6.0, 12.0, 0.5);
    let res = [5e5, 1e6, 2e6];
    let polars = res
        .iter()
        .map(|&r| analytic_polar(r, 0.2, &alphas))
        .collect();
    let t = PolarTable::new(meta("NACA 8-H-12"), res.to_vec(), vec![0.2], polars).unwrap();
    let dir = scratch("aerodyn");
    let path = dir.join("foil.dat");
    let files = write_table(&t, &path, Some(TableFormat::AeroDyn)).unwrap();
    assert_eq!(files, vec![path.clone()]);
    let text = std::fs::read_to_string(&path).unwrap();
    let lines = data_lines(&text);
    let names: Vec<&str> = lines[..6].iter().map(|l| l[1].as_str()).collect();
    assert_eq!(
        names,
        [
            "InterpOrd",
            "RelThickness",
            "NonDimArea",
            "NumCoords",
            "BL_file",
            "NumTabs"
        ]
    );
    assert_eq!((lines[1][0].as_str(), lines[5][0].as_str()), ("0.12", "3"));
    let mut k = 6;
    for (i_re, &re) in res.iter().enumerate() {
        let field = |k: usize, name: &str| {
            assert_eq!(lines[k][1], name, "line {k}");
            lines[k][0].clone()
        };
        assert_eq!(field(k, "Re").parse::<f64>().unwrap() * 1e6, re);
        assert_eq!(field(k + 1, "UserProp"), "0");
        assert_eq!(field(k + 2, "InclUAdata"), "True");
        // The 32 UA lines in the order openfast_io reads them by position, with our values.
        let ua = ua_parameters(&t, i_re, 0).unwrap();
        for (j, (name, value, _)) in ua.lines().iter().enumerate() {
            assert_eq!(field(k + 3 + j, name).parse::<f64>().unwrap(), *value);
        }
        k += 32;
        let n: usize = field(k + 3, "NumAlf").parse().unwrap();
        let rows: Vec<[f64; 4]> = lines[k + 4..k + 4 + n]
            .iter()
            .map(|l| {
                assert_eq!(l.len(), 4);
                [0, 1, 2, 3].map(|i| l[i].parse().unwrap())
            })
            .collect();
        assert_eq!((rows[0][0], rows[n - 1][0]), (-180.0, 180.0));
        assert_eq!(rows[0][1..], rows[n - 1][1..]);
        assert!(rows.windows(2).all(|w| w[1][0] > w[0][0]));
        for a in &alphas {
            assert!(rows.iter().any(|r| r[0] == *a), "computed α {a} missing");
        }
        for r in &rows[..n - 1] {
            let l = t.lookup(r[0], re, 0.2);
            assert_eq!([r[1], r[2], r[3]], [l.cl, l.cd, l.cm], "α {}", r[0]);
        }
        // The extension rows are at most 5° apart.
        assert!(rows.windows(2).all(|w| w[1][0] - w[0][0] <= 5.0));
        k += 4 + n;
    }
    assert_eq!(k, lines.len());
    // Two column-header comment lines follow each NumAlf (weio takes them as the header).
    let raw: Vec<&str> = text.lines().collect();
    for (i, _) in raw.iter().enumerate().filter(|(_, l)| l.contains("NumAlf")) {
        assert!(raw[i + 1].starts_with("!    Alpha") && raw[i + 2].starts_with("!    (deg)"));
    }
    // Read back: the same table (metadata, Mach, extension, every converged point's
    // coefficients; the extension rows are left to the table's own extension).
    let back = parse_table(text.as_bytes(), TableFormat::AeroDyn).unwrap();
    assert_eq!(
        (back.meta(), back.re(), back.mach()),
        (t.meta(), t.re(), t.mach())
    );
    assert_eq!(back.post_stall_params(), t.post_stall_params());
    for ((_, a), (_, b)) in back.polars().zip(t.polars()) {
        let coefficients = |p: &[polargen::section::PolarPoint]| -> Vec<[f64; 4]> {
            p.iter().map(|q| [q.alpha, q.cl, q.cd, q.cm]).collect()
        };
        assert_eq!(coefficients(a), coefficients(b));
    }
    std::fs::remove_dir_all(dir).unwrap();
}

/// A table computed by polargen whose polars stop converging at different α (as every
/// shipped table does: the usable range grows with Re) reads back from its AeroDyn file: each
/// table gives back its own usable points, the α values only the other polars have as
/// unconverged points, so the table converts to CSV and reads back from it.
#[test]
fn polars_of_different_usable_ranges_read_back() {
    let alphas = alpha_range(-6.0, 12.0, 0.5);
    let res = [5e5, 1e6];
    let polars = res
        .iter()
        .map(|&re| {
            let last_usable = if re < 1e6 { 9.0 } else { 11.0 };
            analytic_polar(re, 0.2, &alphas)
                .into_iter()
                .map(|p| {
                    if p.alpha > last_usable {
                        failed(p.alpha)
                    } else {
                        p
                    }
                })
                .collect()
        })
        .collect();
    let t = PolarTable::new(meta("NACA 8-H-12"), res.to_vec(), vec![0.2], polars).unwrap();
    let dir = scratch("aerodyn-ranges");
    let path = dir.join("foil.dat");
    write_table(&t, &path, Some(TableFormat::AeroDyn)).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let back = parse_table(text.as_bytes(), TableFormat::AeroDyn).unwrap();
    assert_eq!(back.meta(), t.meta());
    for ((_, a), (_, b)) in back.polars().zip(t.polars()) {
        let usable: Vec<[f64; 4]> = b
            .iter()
            .filter(|q| q.converged)
            .map(|q| [q.alpha, q.cl, q.cd, q.cm])
            .collect();
        let read: Vec<[f64; 4]> = a
            .iter()
            .filter(|q| q.converged)
            .map(|q| [q.alpha, q.cl, q.cd, q.cm])
            .collect();
        assert_eq!(read, usable);
        // One α list: the last usable α of the other polar, unconverged here.
        assert_eq!(a.last().unwrap().alpha, 11.0);
    }
    // The table written as CSV reads back (the CSV reader requires one α list).
    let csv_path = dir.join("foil.csv");
    write_table(&back, &csv_path, Some(TableFormat::Csv)).unwrap();
    let text = std::fs::read_to_string(&csv_path).unwrap();
    let again = parse_table(text.as_bytes(), TableFormat::Csv).unwrap();
    assert_eq!(again.point_count(), back.point_count());
    // A table read so may be given other extension parameters (the table is rebuilt).
    let cd_max = polargen::table::PostStallParams {
        cd_max: 1.5,
        ..*back.post_stall_params()
    };
    assert!(back.with_post_stall(cd_max).is_ok());
    std::fs::remove_dir_all(dir).unwrap();
}

/// The UA block of a linear polar: C_nalpha is the slope of Cn = Cl·cos α + (Cd − Cd0)·sin α
/// over the polar, α0 its zero, Cd0 and Cm0 the values there, OpenFAST's defaults elsewhere.
#[test]
fn unsteady_aero_block_of_an_analytic_polar() {
    let t = analytic_table();
    let (i_re, i_mach) = (1, 0);
    let (re, mach) = (t.re()[i_re], t.mach()[i_mach]);
    let ua = ua_parameters(&t, i_re, i_mach).unwrap();
    // Cl = 0.11·(α − α0): α0 where cl_model is zero.
    let alpha0 = -(cl_model(0.0, re, mach)) / 0.11;
    assert!((ua.alpha0 - alpha0).abs() < 1e-9, "{ua:?}");
    assert!((ua.cd0 - cd_model(alpha0, re, mach)).abs() < 1e-12);
    assert!((ua.cm0 - cm_model(alpha0, re, mach)).abs() < 1e-12);
    // Cn's slope: d(Cl·cos α)/dα = 0.11/deg·(cos α − α·sin α), 1.8 % below 0.11/deg at the
    // median |α| (6°) of the range −10°…15° (measured 6.1873 against 6.3025 per rad).
    let lift_slope = 0.11f64.to_degrees();
    let expected = lift_slope * (1.0 - 1.5 * 6.25f64.to_radians().powi(2));
    assert!((ua.c_nalpha / expected - 1.0).abs() < 0.005, "{ua:?}");
    // k0 = −dCm/dCn: Cm rises 0.002/deg against Cn's ≈ 0.11/deg.
    assert!((ua.k0 + 0.002 / 0.11).abs() < 5e-4, "{ua:?}");
    // OpenFAST's documented defaults.
    let defaults = [
        ua.eta_e, ua.t_f0, ua.t_v0, ua.t_p, ua.t_vl, ua.b1, ua.b2, ua.b5,
    ];
    assert_eq!(defaults, [1.0, 3.0, 6.0, 1.7, 11.0, 0.14, 0.53, 5.0]);
    assert_eq!([ua.a1, ua.a2, ua.a5, ua.st_sh], [0.3, 0.7, 1.0, 0.19]);
    assert_eq!(
        [ua.x_cp_bar, ua.ua_cutout, ua.filt_cutoff],
        [0.2, 45.0, 0.5]
    );
    // Stall angles where f = 0.7 on the 360° extension beyond the computed range, Cn there.
    assert!(ua.alpha1 > 12.0 && ua.alpha2 < -6.0, "{ua:?}");
    let cn = |a: f64| {
        let l = t.lookup(a, re, mach);
        let r = a.to_radians();
        l.cl * r.cos() + (l.cd - ua.cd0) * r.sin()
    };
    assert!((ua.cn1 - cn(ua.alpha1)).abs() < 1e-12 && (ua.cn2 - cn(ua.alpha2)).abs() < 1e-12);
    let f = |a: f64| {
        let ratio = cn(a) / (ua.c_nalpha * (a - ua.alpha0).to_radians());
        (2.0 * ratio.sqrt() - 1.0).powi(2)
    };
    assert!((f(ua.alpha1) - 0.7).abs() < 0.01 && (f(ua.alpha2) - 0.7).abs() < 0.01);
}

#[test]
fn one_file_per_mach_number() {
    let dir = scratch("aerodyn-mach");
    let files = write_table(
        &analytic_table(),
        &dir.join("foil.dat"),
        Some(TableFormat::AeroDyn),
    )
    .unwrap();
    let names = files_in(&dir);
    assert_eq!(files.len(), analytic_table().mach().len());
    assert!(
        names
            .iter()
            .all(|n| n.starts_with("foil_M") && n.ends_with(".dat")),
        "{names:?}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}
