//! OpenFAST AeroDyn airfoil files: the line order OpenFAST's `ReadAFfile` expects, one table
//! per Re (in millions), α from −180° to 180° with equal ends, values in shortest round-trip
//! form equal to the table's lookups, one file per Mach number. (The Python test
//! `python/tests/test_aerodyn_openfast_io.py` reads the files with OpenFAST's `openfast_io`.)

mod table_support;

use polargen::section::SectionAero;
use polargen::table::{parse_table, write_table, PolarTable, TableFormat};
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
    let names: Vec<&str> = lines[..5].iter().map(|l| l[1].as_str()).collect();
    assert_eq!(
        names,
        ["InterpOrd", "NonDimArea", "NumCoords", "BL_file", "NumTabs"]
    );
    assert_eq!(lines[4][0], "3");
    let mut k = 5;
    for &re in &res {
        let field = |k: usize, name: &str| {
            assert_eq!(lines[k][1], name, "line {k}");
            lines[k][0].clone()
        };
        assert_eq!(field(k, "Re").parse::<f64>().unwrap() * 1e6, re);
        assert_eq!(field(k + 1, "UserProp"), "0");
        assert_eq!(field(k + 2, "InclUAdata"), "False");
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
    // Written only: reading it back as a table is refused with a one-line reason.
    assert_eq!(
        parse_table(text.as_bytes(), TableFormat::AeroDyn)
            .unwrap_err()
            .to_string(),
        "AeroDyn files are written only, not read back as tables"
    );
    std::fs::remove_dir_all(dir).unwrap();
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
