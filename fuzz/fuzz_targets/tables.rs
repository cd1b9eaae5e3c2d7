//! Any bytes given as a table (the first byte picks CSV, JSON or XFOIL polar): the readers
//! never panic, a table they accept holds finite, plausible converged coefficients, and every
//! format it is written in reads back.
#![no_main]

use libfuzzer_sys::fuzz_target;
use polargen::table::{parse_table, read_table, write_table, TableFormat, COEFFICIENT_BOUNDS};

fuzz_target!(|data: &[u8]| {
    let Some((&pick, bytes)) = data.split_first() else {
        return;
    };
    let format = match pick % 3 {
        0 => TableFormat::Csv,
        1 => TableFormat::Json,
        _ => TableFormat::XfoilPolar,
    };
    let Ok(table) = parse_table(bytes, format) else {
        return;
    };
    for (_, polar) in table.polars() {
        for p in polar.iter().filter(|p| p.converged) {
            for ((name, bound), v) in COEFFICIENT_BOUNDS.iter().zip([p.cl, p.cd, p.cm]) {
                assert!(v.is_finite() && v.abs() <= *bound, "{name} {v}");
            }
        }
    }
    let dir = std::env::temp_dir().join(format!("polargen-fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for ext in ["csv", "json", "pol"] {
        if let Ok(written) = write_table(&table, &dir.join(format!("t.{ext}")), None) {
            for file in written {
                if let Err(e) = read_table(&file) {
                    panic!("{ext} written but unreadable: {e}");
                }
                let _ = std::fs::remove_file(file);
            }
        }
    }
});
