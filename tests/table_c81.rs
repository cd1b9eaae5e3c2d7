//! C81 both ways: the writer's layout (header counts, continuation lines, one file per Re or
//! one at a chosen Re, α lists thinned to 99 rows), the reader (round trip of the writer,
//! shipped files, MBDyn-style fields without blanks, errors), one decimal count per block
//! with negatives as `-.0100`, one-Mach tables as two identical columns, and the post-stall
//! Cd_max of the written extension.

mod table_support;

use polargen::section::SectionAero;
use polargen::table::{
    parse_c81, read_lookup_table, read_table, with_cd_max, write_c81, write_table, C81Options,
    PolarTable, TableFormat,
};
use std::path::Path;
use table_support::*;

/// The data fields (after the first 7 columns) of a C81 line.
fn value_fields(line: &str) -> Vec<&str> {
    (1..line.len() / 7)
        .map(|k| &line[7 * k..7 * k + 7])
        .collect()
}

fn write_read(t: &PolarTable, name: &str) -> (String, PolarTable) {
    let dir = scratch(name);
    let files = write_table(t, &dir.join("foil.c81"), Some(TableFormat::C81)).unwrap();
    let path = &files[0];
    let text = std::fs::read_to_string(path).unwrap();
    let back = read_table(path).unwrap();
    std::fs::remove_dir_all(dir).unwrap();
    (text, back)
}

#[test]
fn round_trip_keeps_values_to_the_field_precision() {
    let alphas = alpha_range(-8.0, 14.0, 0.5);
    let mach = [0.0, 0.3, 0.5];
    let polars = mach
        .iter()
        .map(|&m| analytic_polar(2e6, m, &alphas))
        .collect();
    let t = PolarTable::new(meta("NACA 8-H-12"), vec![2e6], mach.to_vec(), polars).unwrap();
    let (_, back) = write_read(&t, "c81-round-trip");
    assert_eq!(back.re(), [2e6]);
    assert_eq!(back.mach(), mach);
    assert_eq!(back.meta().airfoil, "NACA 8-H-12");
    for &m in &mach {
        for a in [-180.0, -90.0, -8.0, -2.0, 0.0, 3.5, 14.0, 45.0, 170.0] {
            let (w, r) = (t.lookup(a, 2e6, m), back.lookup(a, 2e6, m));
            // Cl block: 3 decimals (it spans -1.x); Cd, Cm: 4.
            assert!((w.cl - r.cl).abs() <= 5e-4 + 1e-12, "cl α {a} M {m}");
            assert!((w.cd - r.cd).abs() <= 5e-5 + 1e-12, "cd α {a} M {m}");
            assert!((w.cm - r.cm).abs() <= 5e-5 + 1e-12, "cm α {a} M {m}");
        }
    }
}

#[test]
fn every_block_has_one_decimal_count_and_negatives_drop_the_zero() {
    let (text, _) = write_read(&analytic_table(), "c81-decimals");
    let lines: Vec<&str> = text.lines().collect();
    let na: usize = lines[0][32..34].trim().parse().unwrap();
    let nm: usize = lines[0][30..32].trim().parse().unwrap();
    assert!(nm <= 9);
    let mut saw_negative = false;
    for block in 0..3 {
        let start = 1 + block * (1 + na) + 1;
        let decimals: Vec<usize> = lines[start..start + na]
            .iter()
            .flat_map(|l| value_fields(l))
            .map(|f| {
                assert!(f.starts_with(' '), "{f:?} has no leading blank");
                let f = f.trim();
                saw_negative |= f.starts_with("-.");
                assert!(!f.starts_with("-0."), "{f} keeps the zero");
                f.split('.').nth(1).map_or(0, str::len)
            })
            .collect();
        assert!(decimals.windows(2).all(|w| w[0] == w[1]), "block {block}");
        assert!(decimals[0] >= 3, "block {block}: {} decimals", decimals[0]);
    }
    assert!(saw_negative);
}

#[test]
fn a_one_mach_table_has_two_identical_columns_and_reads_back_as_one() {
    let alphas = alpha_range(-6.0, 12.0, 1.0);
    let t = PolarTable::new(
        meta("one"),
        vec![1e6],
        vec![0.41],
        vec![analytic_polar(1e6, 0.41, &alphas)],
    )
    .unwrap();
    let (text, back) = write_read(&t, "c81-one-mach");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(&lines[0][30..32], " 2");
    assert_eq!(value_fields(lines[1]), ["  0.410", "  0.510"]);
    for l in &lines[2..10] {
        let f = value_fields(l);
        assert_eq!(f[0], f[1], "{l}");
    }
    assert_eq!(back.mach(), [0.41]);
    assert_eq!(back.re(), [1e6]);
}

#[test]
fn shipped_c81_files_read_and_agree_with_their_tables() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("polars");
    let csv = read_lookup_table(&root.join("naca8h12_free.csv")).unwrap();
    let mut n = 0;
    for entry in std::fs::read_dir(root.join("c81")).unwrap() {
        let path = entry.unwrap().path();
        let t = read_lookup_table(&path).unwrap();
        assert_eq!(t.mach().len(), csv.mach().len(), "{}", path.display());
        n += 1;
        if path.file_name().unwrap() == "naca8h12_free_Re2e6.c81" {
            assert_eq!(t.re(), [2e6]);
            for a in [-4.0, 0.0, 6.0] {
                let (r, c) = (t.lookup(a, 2e6, 0.2), csv.lookup(a, 2e6, 0.2));
                assert!(
                    (r.cl - c.cl).abs() < 1e-3 && (r.cd - c.cd).abs() < 1e-4,
                    "α {a}"
                );
            }
        }
    }
    assert_eq!(n, 4 * csv.re().len());
}

#[test]
fn fixed_fields_without_blanks_and_errors_name_the_line() {
    // MBDyn-style: full 7-character fields, no blank between them; CD and CM at other α.
    let text = "\
mbdyn sample                   2 3 2 2 2 2
         0.0    0.5
 -10.00-0.8000-0.7000
   0.00 0.0000 0.0000
  10.00 0.8000 0.9000
         0.0    0.5
 -10.00 0.0200 0.0300
  10.00 0.0200 0.0300
         0.0    0.5
 -10.00-0.0100-0.0200
  10.00 0.0100 0.0200
";
    let t = parse_c81(text, "sample_Re3e6").unwrap();
    assert_eq!(t.re(), [3e6]);
    assert_eq!(t.mach(), [0.0, 0.5]);
    let p = t.polar_at(0, 1).unwrap();
    assert_eq!(p.iter().map(|q| q.cl).collect::<Vec<_>>(), [-0.7, 0.0, 0.9]);
    assert!((p[1].cm - 0.0).abs() < 1e-12 && (p[0].cm + 0.02).abs() < 1e-12);
    let bad = |text: &str| parse_c81(text, "x").unwrap_err().to_string();
    assert_eq!(
        bad("name only\n"),
        "C81 line 1: columns 31-42 must hold six counts of two digits (NML NAL NMD NAD NMM NAM)"
    );
    assert_eq!(
        bad(&text.replace("  10.00 0.8000", "  -20.0 0.8000")),
        "C81 line 5: the CL alpha list is not strictly increasing"
    );
    assert_eq!(
        bad(&text[..text.len() - 22]),
        "C81 line 11: the CM block ends early"
    );
    assert_eq!(
        bad(&text.replace("0.0200 0.0300\n  10", "0.0x00 0.0300\n  10")),
        "C81 line 7: '0.0x00' is not a number"
    );
}

#[test]
fn cd_max_sets_the_broadside_drag_of_the_written_extension() {
    let t = with_cd_max(analytic_table(), Some(1.3)).unwrap();
    let (_, back) = write_read(&t, "c81-cd-max");
    let l = back.lookup(90.0, 1e6, 0.0);
    assert!((l.cd - 1.3).abs() < 1e-3, "cd(90°) = {}", l.cd);
    assert!(with_cd_max(analytic_table(), Some(0.0)).is_err());
}

/// Split a C81 line into 7-character fields, checking the layout.
fn fields(line: &str) -> Vec<&str> {
    assert_eq!(
        line.len() % 7,
        0,
        "line length {} not a multiple of 7: {line:?}",
        line.len()
    );
    (0..line.len() / 7)
        .map(|k| &line[7 * k..7 * k + 7])
        .collect()
}

#[test]
fn c81_structure() {
    // 11 Mach numbers: every block row needs a continuation line (9 values per line).
    let mach: Vec<f64> = (0..11).map(|k| 0.05 * k as f64).collect();
    let alphas = alpha_range(-8.0, 14.0, 0.5);
    let polars = mach
        .iter()
        .map(|&m| analytic_polar(1e6, m, &alphas))
        .collect();
    let t = PolarTable::new(meta("NACA 8-H-12"), vec![1e6], mach.clone(), polars).unwrap();
    let dir = scratch("c81");
    let path = dir.join("deep/er/t.c81");
    assert_eq!(write_table(&t, &path, None).unwrap(), vec![path.clone()]);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(!text.contains("-0.000"));
    let lines: Vec<&str> = text.lines().collect();
    let head = lines[0];
    assert_eq!(head.len(), 42);
    assert_eq!(&head[..30], "NACA 8-H-12 Re1e6             ");
    let counts: Vec<usize> = (0..6)
        .map(|k| head[30 + 2 * k..32 + 2 * k].trim().parse().unwrap())
        .collect();
    let (nm, na) = (counts[0], counts[1]);
    assert_eq!(counts, vec![nm, na, nm, na, nm, na]);
    assert_eq!(nm, 11);
    // α rows: −180…−20 every 10° (−10 is within half a step of −8), the 45 computed α,
    // 20…180 every 10°, and 20 more that split the widest extension gaps.
    assert_eq!(na, 99);
    assert_eq!(lines.len(), 1 + 3 * (2 + 2 * na));
    let mut k = 1;
    let mut alpha_seen = Vec::new();
    for block in 0..3 {
        // Mach row: 7 blanks + 9 Mach numbers, continuation 7 blanks + 2.
        let f1 = fields(lines[k]);
        let f2 = fields(lines[k + 1]);
        assert_eq!((f1.len(), f2.len()), (10, 3));
        assert!(f1[0].trim().is_empty() && f2[0].trim().is_empty());
        let m: Vec<f64> = f1[1..]
            .iter()
            .chain(&f2[1..])
            .map(|s| s.trim().parse().unwrap())
            .collect();
        assert_eq!(
            m,
            mach.iter()
                .map(|v| (v * 1000.0).round() / 1000.0)
                .collect::<Vec<_>>()
        );
        k += 2;
        for _ in 0..na {
            let f1 = fields(lines[k]);
            let f2 = fields(lines[k + 1]);
            assert_eq!((f1.len(), f2.len()), (10, 3));
            assert!(f2[0].trim().is_empty());
            let a: f64 = f1[0].trim().parse().unwrap();
            if block == 0 {
                alpha_seen.push(a);
            }
            let vals: Vec<f64> = f1[1..]
                .iter()
                .chain(&f2[1..])
                .map(|s| {
                    assert!(s.starts_with(' '), "field {s:?} has no leading blank");
                    s.trim().parse().unwrap()
                })
                .collect();
            for (j, v) in vals.iter().enumerate() {
                let l = t.lookup(a, 1e6, mach[j]);
                let expect = [l.cl, l.cd, l.cm][block];
                assert!(
                    (v - expect).abs() <= 5e-4,
                    "block {block} α {a} M {}",
                    mach[j]
                );
            }
            k += 2;
        }
    }
    assert_eq!(alpha_seen[0], -180.0);
    assert_eq!(*alpha_seen.last().unwrap(), 180.0);
    assert!(alpha_seen.windows(2).all(|w| w[1] > w[0]));
    for a in &alphas {
        assert!(alpha_seen.contains(a), "computed α {a} missing");
    }
    // The extension is sampled at most every 10°, and more finely next to the computed range.
    let gaps: Vec<f64> = alpha_seen.windows(2).map(|w| w[1] - w[0]).collect();
    assert!(gaps.iter().all(|&g| g <= 10.0 + 1e-9));
    let k = alpha_seen.iter().position(|&a| a == -8.0).unwrap();
    assert!(alpha_seen[k] - alpha_seen[k - 1] < 5.0);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn c81_one_file_per_re_or_at_a_chosen_re() {
    let t = analytic_table();
    let dir = scratch("c81re");
    let files = write_table(&t, &dir.join("foil.c81"), None).unwrap();
    assert_eq!(
        files_in(&dir),
        vec!["foil_Re1e6.c81", "foil_Re2e6.c81", "foil_Re5e5.c81"]
    );
    assert_eq!(files.len(), 3);
    let path = dir.join("at.c81");
    let opts = C81Options {
        re: Some(1.4e6),
        ..C81Options::default()
    };
    assert_eq!(write_c81(&t, &path, &opts).unwrap(), vec![path.clone()]);
    let text = std::fs::read_to_string(&path).unwrap();
    let first_row = text.lines().nth(2).unwrap();
    let f = fields(first_row);
    assert_eq!(f[0].trim(), "-180.00");
    let bad = C81Options {
        re: Some(-1.0),
        ..C81Options::default()
    };
    assert_eq!(
        write_c81(&t, &dir.join("bad.c81"), &bad)
            .unwrap_err()
            .to_string(),
        "Re must be positive and at most 1e10, got -1"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn c81_thins_long_alpha_lists_to_99_rows() {
    let alphas = alpha_range(-20.0, 25.0, 0.25);
    let t = PolarTable::new(
        meta("dense"),
        vec![1e6],
        vec![0.0, 0.3],
        vec![
            analytic_polar(1e6, 0.0, &alphas),
            analytic_polar(1e6, 0.3, &alphas),
        ],
    )
    .unwrap();
    let dir = scratch("thin");
    let path = dir.join("dense.c81");
    let one_re = C81Options {
        re: Some(1e6),
        outer_step_deg: 10.0,
    };
    write_c81(&t, &path, &one_re).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_dir_all(dir).unwrap();
    let head = text.lines().next().unwrap();
    let na: usize = head[32..34].trim().parse().unwrap();
    assert!(na <= 99 && na > 80, "na {na}");
    assert_eq!(text.lines().count(), 1 + 3 * (1 + na));
}
