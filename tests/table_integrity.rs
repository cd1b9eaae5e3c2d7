//! Tables that are all-or-none: what polargen writes it reads back (a table too large for the
//! read limit is refused on read by its row count, or before writing by its size), and a table
//! computed by polargen that was cut inside its last polar is refused instead of passing for a
//! shorter table.

mod table_support;

use polargen::table::{parse_table, write_table, PolarTable, TableFormat};
use std::io::Write;
use table_support::cli_support::{polargen, stderr};
use table_support::{analytic_polar, meta, scratch};

#[test]
fn a_table_of_more_rows_than_a_table_may_hold_is_refused_on_read() {
    // One polar of 10⁶ rows (≈ 52 MB of CSV, under the 64 MiB file limit): its JSON would be
    // ≈ 540 MB, which polargen could not read back. Refused on read, nothing written.
    let dir = scratch("rows");
    let src = dir.join("big.csv");
    let mut f = std::io::BufWriter::new(std::fs::File::create(&src).unwrap());
    writeln!(
        f,
        "airfoil,re,mach,ncrit,xtr_top_set,xtr_bot_set,alpha,cl,cd,cdp,cm,xtr_top,xtr_bot,converged"
    )
    .unwrap();
    for k in 0..1_000_000 {
        let alpha = -90.0 + 1.8e-4 * f64::from(k);
        writeln!(f, "x,1e6,0,9,1,1,{alpha},0.1,0.01,0.004,0,1,1,true").unwrap();
    }
    f.flush().unwrap();
    drop(f);
    let out = dir.join("big.json");
    let o = polargen(&[
        "convert",
        src.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("table of 1000000 points: more than the 100000 a table may hold"),
        "{}",
        stderr(&o)
    );
    assert!(!out.exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_file_larger_than_polargen_reads_is_refused_before_writing() {
    // 20 000 points with a 4 000-character airfoil name: the name repeats on every CSV row
    // (≈ 85 MB, beyond the 64 MiB read limit) but once in JSON (≈ 11 MB).
    let name = "N".repeat(4000);
    let alphas: Vec<f64> = (0..2000).map(|k| -20.0 + 0.02 * f64::from(k)).collect();
    let re: Vec<f64> = (1..=10).map(|k| 1e5 * f64::from(k)).collect();
    let polars = re
        .iter()
        .map(|&r| analytic_polar(r, 0.0, &alphas))
        .collect();
    let table = PolarTable::new(meta(&name), re, vec![0.0], polars).unwrap();
    let dir = scratch("size");
    let csv = dir.join("t.csv");
    let err = write_table(&table, &csv, None).unwrap_err();
    assert_eq!(
        err.to_string(),
        "the csv file would be larger than 64 MiB, the most polargen reads back \
         (docs/limits.md); nothing written: write fewer points or another format"
    );
    assert!(!csv.exists());
    let json = dir.join("t.json");
    write_table(&table, &json, None).unwrap();
    assert!(std::fs::metadata(&json).unwrap().len() < 64 << 20);
    assert_eq!(
        polargen::table::read_table(&json).unwrap().point_count(),
        20_000
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A polargen CSV table of two polars (Re 10⁶ and 2·10⁶, M 0) over α 0…4°.
fn two_polars_csv() -> String {
    let alphas = [0.0, 1.0, 2.0, 3.0, 4.0];
    let table = PolarTable::new(
        meta("foil"),
        vec![1e6, 2e6],
        vec![0.0],
        vec![
            analytic_polar(1e6, 0.0, &alphas),
            analytic_polar(2e6, 0.0, &alphas),
        ],
    )
    .unwrap();
    let dir = scratch("cut");
    let path = dir.join("t.csv");
    write_table(&table, &path, None).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    text
}

#[test]
fn a_polargen_table_cut_inside_its_last_polar_is_refused() {
    let whole = two_polars_csv();
    assert!(parse_table(whole.as_bytes(), TableFormat::Csv).is_ok());
    // Cut at a row boundary two rows before the end: the last polar ends at α 2°.
    let lines: Vec<&str> = whole.lines().collect();
    let cut = lines[..lines.len() - 2].join("\n") + "\n";
    let err = parse_table(cut.as_bytes(), TableFormat::Csv).unwrap_err();
    assert_eq!(
        err.to_string(),
        "polar Re 2000000, M 0 has 3 alpha values where the table's first polar has 5 and \
         ends at alpha 2: a table computed by polargen keeps every alpha in every polar, so \
         the file is cut short or was edited"
    );
    // Through `convert`: the error, and nothing written.
    let dir = scratch("cut-cli");
    let src = dir.join("cut.csv");
    std::fs::write(&src, &cut).unwrap();
    let out = dir.join("out.json");
    let o = polargen(&[
        "convert",
        src.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("cut short"), "{}", stderr(&o));
    assert!(!out.exists());
    // A table of another code may drop points per polar (XFOIL keeps only converged ones):
    // the same rows under another solver name are a valid table.
    let foreign = cut.replace("polargen 0.1.0", "XFOIL 6.99");
    let t = parse_table(foreign.as_bytes(), TableFormat::Csv).unwrap();
    assert_eq!(t.point_count(), 8);
    let _ = std::fs::remove_dir_all(&dir);
}
