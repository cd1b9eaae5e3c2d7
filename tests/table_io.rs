//! Table files: CSV/JSON round trips, XFOIL polar and C81 structure, format inference and error
//! messages.

mod table_support;

use polargen::section::SectionAero;
use polargen::section::{FlowCondition, PolarPoint};
use polargen::table::{
    parse_table, read_table, write_c81, write_table, C81Options, PolarTable, TableError,
    TableFormat,
};
use std::path::Path;
use table_support::*;

/// A table with awkward values: non-terminating binary fractions, tiny and large magnitudes,
/// unconverged points holding NaN and ±∞, a name with a comma.
fn awkward_table() -> PolarTable {
    let alphas = alpha_range(-4.0, 8.0, 0.5);
    let mut list = Vec::new();
    for &re in &[2.5e5, 1.9e6] {
        for &m in &[0.0, 0.41] {
            let mut pts = analytic_polar(re, m, &alphas);
            for (k, p) in pts.iter_mut().enumerate() {
                p.cl += 0.1 / 3.0 + 1e-17 * k as f64;
                p.cd *= 1.0 + std::f64::consts::PI * 1e-7;
                p.residual = 1.234e-300 * (k + 1) as f64;
                p.iterations = k as u32;
            }
            pts[3].converged = false;
            pts[3].cl = f64::NAN;
            pts[4].converged = false;
            pts[4].cd = f64::INFINITY;
            pts[4].cm = f64::NEG_INFINITY;
            // Minimum pressure: a supercritical point, a broken-down correction, an unknown.
            pts[5].cpmin = -1.0 / 3.0 - 2.0;
            pts[5].supercritical = Some(m > 0.0);
            pts[6].cpmin = f64::NEG_INFINITY;
            pts[6].supercritical = Some(m > 0.0);
            pts[7].cpmin = f64::NAN;
            pts[7].supercritical = None;
            list.push((FlowCondition::new(re, m), pts));
        }
    }
    let mut m = meta("NACA 8-H-12, \"reflexed\"");
    m.transition.xtr_top = 0.07;
    m.transition.xtr_bot = 0.07;
    PolarTable::from_polars(m, list).unwrap()
}

#[test]
fn csv_round_trip_is_exact() {
    let t = awkward_table();
    let dir = scratch("csv_rt");
    let path = dir.join("t.csv");
    assert_eq!(write_table(&t, &path, None).unwrap(), vec![path.clone()]);
    let back = read_table(&path).unwrap();
    assert!(same_bits(&t, &back));
    let text = std::fs::read_to_string(&path).unwrap();
    let header = text.lines().next().unwrap();
    assert!(header.starts_with(
        "airfoil,re,mach,ncrit,xtr_top_set,xtr_bot_set,alpha,cl,cd,cdp,cm,xtr_top,xtr_bot,converged"
    ));
    assert_eq!(text.lines().count(), 1 + t.point_count());
    // Lookups on the read-back table are identical.
    for a in [-3.3, 2.0, 40.0, -170.0] {
        assert_eq!(t.lookup(a, 1e6, 0.2), back.lookup(a, 1e6, 0.2));
    }
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn json_round_trip_is_exact() {
    let t = awkward_table();
    let dir = scratch("json_rt");
    let path = dir.join("sub/t.json");
    write_table(&t, &path, None).unwrap();
    let back = read_table(&path).unwrap();
    assert!(same_bits(&t, &back));
    assert_eq!(back.post_stall_params(), t.post_stall_params());
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains("\"NaN\"") && text.contains("\"-inf\""));
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn csv_reader_accepts_minimal_columns_in_any_order() {
    let text = "alpha,re,mach,airfoil,ncrit,xtr_top_set,xtr_bot_set,cl,cd,cdp,cm,xtr_top,xtr_bot,converged\n\
                1,1e6,0,foil,9,1,1,0.11,0.01,0.004,-0.01,0.5,0.9,true\n\
                0,1e6,0,foil,9,1,1,0,0.009,0.003,-0.012,0.6,0.8,1\n\
                2,1e6,0,foil,9,1,1,0.22,0.012,0.005,-0.008,0.4,1,false\n";
    let t = parse_table(text.as_bytes(), TableFormat::Csv).unwrap();
    assert_eq!(t.meta().airfoil, "foil");
    assert_eq!(t.meta().panels, 0);
    let p = t.polar(1e6, 0.0).unwrap();
    assert_eq!(p.len(), 3);
    assert_eq!(p[1].alpha, 1.0);
    assert!((p[1].cdf - 0.006).abs() < 1e-15);
    assert!(!p[2].converged);
    assert_eq!(t.converged_count(), 2);
}

fn csv_err(text: &str) -> String {
    parse_table(text.as_bytes(), TableFormat::Csv)
        .unwrap_err()
        .to_string()
}

const HEAD: &str =
    "airfoil,re,mach,ncrit,xtr_top_set,xtr_bot_set,alpha,cl,cd,cdp,cm,xtr_top,xtr_bot,converged\n";

#[test]
fn csv_errors_name_the_line_and_problem() {
    assert_eq!(
        csv_err("airfoil,re,mach,ncrit,xtr_top_set,xtr_bot_set,alpha,cl,cd,cdp,xtr_top,xtr_bot,converged\n"),
        "CSV header lacks column 'cm'"
    );
    let e = csv_err(&format!(
        "{HEAD}f,1e6,0,9,1,1,0,0,0.01,0,0,1,1,true\nf,1e6,0,9,1,1,1,abc,0.01,0,0,1,1,true\n"
    ));
    assert_eq!(e, "CSV line 3: cl 'abc' is not a number");
    let e = csv_err(&format!("{HEAD}f,1e6,0,9,1,1,0,0,NaN,0,0,1,1,true\n"));
    assert_eq!(e, "CSV line 2: cd is NaN in a converged point");
    let e = csv_err(&format!("{HEAD}f,1e6,0,9,1,1,0,0,0.01,0,0,1,1,maybe\n"));
    assert_eq!(e, "CSV line 2: converged 'maybe' is not true or false");
    let e = csv_err(&format!("{HEAD}f,1e6,0,9,1,1,0,0,0.01,0,0,1\n"));
    assert_eq!(e, "CSV line 2: 12 fields, expected 14");
    let e = csv_err(&format!(
        "{HEAD}f,1e6,0,9,1,1,0,0,0.01,0,0,1,1,true\ng,1e6,0,9,1,1,1,0,0.01,0,0,1,1,true\n"
    ));
    assert_eq!(e, "CSV line 3: airfoil differs from line 2");
    assert_eq!(csv_err(HEAD), "CSV line 2: no data rows (empty table)");
    assert_eq!(csv_err(""), "CSV line 1: empty file: no header line");
    assert_eq!(csv_err("\n\n"), "CSV line 1: empty file: no header line");
    // Ragged: Re 2e6 has only M 0, Re 1e6 only M 0.2.
    let e = csv_err(&format!(
        "{HEAD}f,1e6,0.2,9,1,1,0,0,0.01,0,0,1,1,true\nf,1e6,0.2,9,1,1,1,0,0.01,0,0,1,1,true\n\
         f,2e6,0,9,1,1,0,0,0.01,0,0,1,1,true\nf,2e6,0,9,1,1,1,0,0.01,0,0,1,1,true\n"
    ));
    assert_eq!(e, "ragged grid: no polar at Re 1000000, M 0");
    let e = csv_err(&format!("{HEAD}f,1e6,1.5,9,1,1,0,0,0.01,0,0,1,1,true\n"));
    assert_eq!(e, "Mach must be in [0, 1), got 1.5");
}

#[test]
fn json_errors_name_the_position_and_problem() {
    let e = parse_table("{\n  \"meta\": [1,\n".as_bytes(), TableFormat::Json).unwrap_err();
    assert!(matches!(e, TableError::Json { line: 2, .. }), "{e}");
    let t = awkward_table();
    let text = serde_json::to_string_pretty(&t)
        .unwrap()
        .replacen("0.41", "1.41", 1);
    let e = parse_table(text.as_bytes(), TableFormat::Json)
        .unwrap_err()
        .to_string();
    assert!(e == "JSON table: Mach must be in [0, 1), got 1.41", "{e}");
    assert!(!e.contains('\n'));
    let e = parse_table("{\"meta\": 3}".as_bytes(), TableFormat::Json)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("JSON line 1, column") && e.contains("invalid type"),
        "{e}"
    );
}

#[test]
fn format_inference_and_names() {
    let f = |p: &str| TableFormat::from_path(Path::new(p));
    assert_eq!(f("a/b.csv").unwrap(), TableFormat::Csv);
    assert_eq!(f("b.JSON").unwrap(), TableFormat::Json);
    assert_eq!(f("b.pol").unwrap(), TableFormat::XfoilPolar);
    assert_eq!(f("b.c81").unwrap(), TableFormat::C81);
    assert_eq!(
        f("out/b.txt").unwrap_err().to_string(),
        "cannot infer table format from 'out/b.txt' (use .csv, .json, .jsonl, .pol or .c81)"
    );
    assert_eq!(
        "xfoil".parse::<TableFormat>().unwrap(),
        TableFormat::XfoilPolar
    );
    assert_eq!("C81".parse::<TableFormat>().unwrap(), TableFormat::C81);
    assert_eq!(
        "xls".parse::<TableFormat>().unwrap_err().to_string(),
        "unknown table format 'xls' (expected csv, json, jsonl, xfoil, c81 or aerodyn)"
    );
    // An explicit format overrides the extension.
    let dir = scratch("explicit");
    let path = dir.join("table.txt");
    write_table(&analytic_table(), &path, Some(TableFormat::Json)).unwrap();
    assert!(parse_table(&std::fs::read(&path).unwrap(), TableFormat::Json).is_ok());
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn xfoil_polar_files_have_xfoil_layout() {
    let dir = scratch("pol");
    let t = awkward_table();
    let files = write_table(&t, &dir.join("foil.pol"), None).unwrap();
    let names: Vec<String> = files
        .iter()
        .map(|f| f.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        names,
        vec![
            "foil_Re2.5e5_M0.pol",
            "foil_Re2.5e5_M0.41.pol",
            "foil_Re1.9e6_M0.pol",
            "foil_Re1.9e6_M0.41.pol"
        ]
    );
    assert_eq!(files_in(&dir), {
        let mut n = names.clone();
        n.sort();
        n
    });
    let text = std::fs::read_to_string(&files[3]).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let pts = t.polar(1.9e6, 0.41).unwrap();
    let conv: Vec<&PolarPoint> = pts.iter().filter(|p| p.converged).collect();
    assert_eq!(lines.len(), 12 + conv.len());
    assert!(lines[3].starts_with(" Calculated polar for: NACA 8-H-12"));
    assert_eq!(lines[7], " xtrf =   0.070 (top)        0.070 (bottom)  ");
    assert_eq!(
        lines[8],
        " Mach =   0.410     Re =     1.900 e 6     Ncrit =   9.000"
    );
    assert_eq!(
        lines[10],
        "   alpha    CL        CD       CDp       CM     Top_Xtr  Bot_Xtr   Cpmin   Top_Xsep \
         Bot_Xsep"
    );
    for (line, p) in lines[12..].iter().zip(&conv) {
        assert_eq!(line.len(), 8 + 9 + 10 + 10 + 9 + 9 + 9 + 9 + 9 + 9);
        let v: Vec<f64> = line
            .split_whitespace()
            .map(|f| f.parse().unwrap())
            .collect();
        assert_eq!(v.len(), 10);
        assert!(v[7].to_bits() == p.cpmin.to_bits() || (v[7] - p.cpmin).abs() <= 5e-5);
        assert!((v[8] - p.xsep_top).abs() <= 5e-5 && (v[9] - p.xsep_bot).abs() <= 5e-5);
        assert!((v[0] - p.alpha).abs() <= 5e-4 && (v[1] - p.cl).abs() <= 5e-5);
        assert!((v[2] - p.cd).abs() <= 5e-6 && (v[4] - p.cm).abs() <= 5e-5);
    }
    // A single-polar table goes to the named file itself.
    let single = PolarTable::new(
        meta("one"),
        vec![1e6],
        vec![0.0],
        vec![analytic_polar(1e6, 0.0, &[0.0, 1.0])],
    )
    .unwrap();
    let path = dir.join("single.pol");
    assert_eq!(write_table(&single, &path, None).unwrap(), vec![path]);
    std::fs::remove_dir_all(dir).unwrap();
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

#[test]
fn failed_table_writes_leave_nothing_behind() {
    let dir = scratch("failed");
    std::fs::create_dir_all(dir.join("folder.csv")).unwrap();
    // A table that could not be written in every format (Cl 1e9, too wide for C81's 7
    // characters) cannot be made at all.
    let huge = PolarTable::new(
        meta("huge"),
        vec![1e6],
        vec![0.0],
        vec![vec![point(0.0, 1e9, 0.01, 0.0), point(1.0, 1e9, 0.01, 0.0)]],
    )
    .unwrap_err();
    assert!(
        matches!(huge, TableError::Implausible { field: "cl", .. }),
        "{huge}"
    );
    // The writers check the path like every output.
    let e = write_table(&awkward_table(), &dir.join("folder.csv"), None).unwrap_err();
    assert_eq!(
        e.to_string(),
        format!("{}/folder.csv: is a folder, not a file name", dir.display())
    );
    assert_eq!(files_in(&dir), vec!["folder.csv"]);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn xfoil_polar_reads_back_to_field_precision() {
    let pts = xfoil_reference("naca8h12_Re1.9e6_M0.41_xtr0.07.csv");
    let mut m = meta("NACA 8-H-12");
    m.transition.xtr_top = 0.07;
    m.transition.xtr_bot = 0.07;
    let t = PolarTable::new(m, vec![1.9e6], vec![0.41], vec![pts.clone()]).unwrap();
    let dir = scratch("polread");
    let path = dir.join("p.pol");
    write_table(&t, &path, None).unwrap();
    let back = read_table(&path).unwrap();
    assert_eq!(back.meta().airfoil, "NACA 8-H-12");
    assert_eq!(back.meta().solver, "polargen 0.1.0");
    assert_eq!(
        (
            back.meta().transition.common_ncrit(),
            back.meta().transition.xtr_top
        ),
        (Some(9.0), 0.07)
    );
    assert_eq!((back.re(), back.mach()), (&[1.9e6][..], &[0.41][..]));
    let q = back.polar(1.9e6, 0.41).unwrap();
    assert_eq!(q.len(), pts.len());
    // The reference has at most 4 decimals in cl/cm and 5 in cd: the text is exact for it.
    for (a, b) in pts.iter().zip(q) {
        assert_eq!(
            (a.alpha, a.cl, a.cd, a.cdp, a.cm),
            (b.alpha, b.cl, b.cd, b.cdp, b.cm)
        );
        assert_eq!((a.xtr_top, a.xtr_bot), (b.xtr_top, b.xtr_bot));
    }
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn xfoil_polar_reader_handles_extra_columns_and_repeats() {
    let text = "\n       XFOIL         Version 6.99\n\n Calculated polar for: NACA 2412\n\n\
 1 1 Reynolds number fixed          Mach number fixed\n\n\
 xtrf =   1.000 (top)        0.070 (bottom)\n\
 Mach =   0.200     Re =     3.000 e 6     Ncrit =   5.000\n\n\
   alpha    CL        CD       CDp       CM      Cpmin    Xcpmin   Chinge   Top_Xtr  Bot_Xtr\n\
  ------ -------- --------- --------- -------- -------- -------- -------- -------- --------\n\
   0.000   0.2500   0.00600   0.00100  -0.0500  -1.5000   0.0300  -0.0100   0.6000   0.0700\n\
   2.000   0.4700   0.00650   0.00120  -0.0510  -1.1000   0.0400  -0.0080   0.5000   0.0700\n\
   0.000   0.2500   0.00600   0.00100  -0.0500  -1.5000   0.0300  -0.0100   0.6000   0.0700\n\
  -2.000   0.0300   0.00640   0.00110  -0.0490  -1.0000   0.0300  -0.0100   0.7000   0.0700\n";
    let t = parse_table(text.as_bytes(), TableFormat::XfoilPolar).unwrap();
    assert_eq!(t.meta().solver, "XFOIL Version 6.99");
    assert_eq!(
        (
            t.meta().transition.common_ncrit(),
            t.meta().transition.xtr_bot
        ),
        (Some(5.0), 0.07)
    );
    assert_eq!((t.re()[0], t.mach()[0]), (3e6, 0.2));
    let p = t.polar(3e6, 0.2).unwrap();
    let alphas: Vec<f64> = p.iter().map(|p| p.alpha).collect();
    assert_eq!(alphas, vec![-2.0, 0.0, 2.0]);
    assert_eq!((p[2].cl, p[2].cm, p[2].xtr_top), (0.47, -0.051, 0.5));
    // XFOIL's CDp column is its pressure integral, not CD − CDf: CDf is unknown.
    assert_eq!(p[2].cdp, 0.0012);
    assert!(p[2].cdf.is_nan());
    let broken = text.replace("Ncrit =   5.000", "");
    assert_eq!(
        parse_table(broken.as_bytes(), TableFormat::XfoilPolar)
            .unwrap_err()
            .to_string(),
        "XFOIL polar line 9: Mach/Re/Ncrit line is incomplete"
    );
    let bad = text.replace("0.4700", "0.47x0");
    assert_eq!(
        parse_table(bad.as_bytes(), TableFormat::XfoilPolar)
            .unwrap_err()
            .to_string(),
        "XFOIL polar line 14: '0.47x0' is not a number"
    );
}

#[test]
fn output_does_not_depend_on_polar_order() {
    // Polars collected from parallel workers arrive in any order: the files are identical.
    let alphas = alpha_range(-3.0, 6.0, 1.0);
    let mut list = Vec::new();
    for &re in &[5e5, 1e6, 2e6] {
        for &m in &[0.0, 0.3] {
            list.push((FlowCondition::new(re, m), analytic_polar(re, m, &alphas)));
        }
    }
    let a = PolarTable::from_polars(meta("order"), list.clone()).unwrap();
    list.reverse();
    list.swap(1, 4);
    for (_, pts) in list.iter_mut() {
        pts.reverse();
    }
    let b = PolarTable::from_polars(meta("order"), list).unwrap();
    let dir = scratch("order");
    for ext in ["csv", "json", "c81"] {
        let (pa, pb) = (dir.join(format!("a.{ext}")), dir.join(format!("b.{ext}")));
        let fa = write_table(&a, &pa, None).unwrap();
        let fb = write_table(&b, &pb, None).unwrap();
        for (x, y) in fa.iter().zip(&fb) {
            assert_eq!(
                std::fs::read(x).unwrap(),
                std::fs::read(y).unwrap(),
                "{ext}"
            );
        }
    }
    std::fs::remove_dir_all(dir).unwrap();
}

/// polargen's `.pol` files carry XFOIL's `Version` word (so `PGET` shows the code's version)
/// and its printed CDp = CD − CDf, so reading one back restores cdf.
#[test]
fn own_xfoil_polars_carry_a_version_and_cd_minus_cdf() {
    let dir = scratch("pol-version");
    let mut m = meta("foil");
    m.solver = "polargen 0.1.0".to_string();
    let alphas = alpha_range(-2.0, 4.0, 1.0);
    let t = PolarTable::new(
        m,
        vec![1e6],
        vec![0.0],
        vec![analytic_polar(1e6, 0.0, &alphas)],
    )
    .unwrap();
    let path = dir.join("p.pol");
    write_table(&t, &path, None).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let version = text.lines().nth(1).unwrap();
    assert!(version.starts_with("       polargen 0.1.0") && version.ends_with("Version 0.1"));
    let back = read_table(&path).unwrap();
    assert_eq!(back.meta().solver, "polargen 0.1.0");
    let p = &back.polar(1e6, 0.0).unwrap()[0];
    assert!((p.cdf - (p.cd - p.cdp)).abs() < 1e-12);
    std::fs::remove_dir_all(dir).unwrap();
}

/// Per-side N_crit: the `ncrit_top,ncrit_bot` columns of CSV, the two fields of JSON and
/// XFOIL 6.99's two-value `Ncrit` header of a .pol all read back to the same metadata; a CSV
/// with only one of the per-side columns is refused.
#[test]
fn unequal_ncrit_round_trips() {
    let mut m = meta("foil");
    (m.transition.ncrit_top, m.transition.ncrit_bot) = (9.0, 3.5);
    let polar = analytic_polar(1e6, 0.0, &alpha_range(-4.0, 8.0, 1.0));
    let t = PolarTable::from_polars(m, vec![(FlowCondition::new(1e6, 0.0), polar)]).unwrap();
    let dir = scratch("ncrit_sides");
    for (name, written) in [
        ("t.csv", "airfoil,re,mach,ncrit_top,ncrit_bot,xtr_top_set"),
        ("t.json", "\"ncrit_bot\": 3.5"),
        ("t.pol", " Ncrit =   9.000  3.500\n"),
    ] {
        let files = write_table(&t, &dir.join(name), None).unwrap();
        let text = std::fs::read_to_string(&files[0]).unwrap();
        assert!(text.contains(written), "{name}: {text}");
        let back = read_table(&files[0]).unwrap();
        let m = back.meta();
        assert_eq!(
            (
                m.transition.ncrit_top,
                m.transition.ncrit_bot,
                m.transition.common_ncrit()
            ),
            (9.0, 3.5, None)
        );
    }
    std::fs::remove_dir_all(dir).unwrap();
    let head = "airfoil,re,mach,ncrit_top,xtr_top_set,xtr_bot_set,alpha,cl,cd,cdp,cm,xtr_top,xtr_bot,converged\n";
    assert_eq!(
        csv_err(&format!("{head}f,1e6,0,9,1,1,0,0,0.01,0,0,1,1,true\n")),
        "CSV header lacks column 'ncrit'"
    );
}
