//! Shared helpers of the inviscid tests: reading the XFOIL 6.99 reference files in
//! tests/data/xfoil.

use crate::geometry::Airfoil;

/// Directory of the inviscid test data.
pub(super) const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/xfoil");

/// Reads XFOIL's paneled nodes `<name>_paneled.dat` (plain `x y`, E-notation allowed).
pub(super) fn xfoil_nodes(name: &str) -> Airfoil {
    let path = format!("{DATA}/{name}_paneled.dat");
    crate::geometry::read_airfoil_file(std::path::Path::new(&path)).unwrap()
}

/// Reads the wake rows (x, y) of an XFOIL `DUMP` file: the rows with 8 columns (airfoil rows
/// carry 12).
pub(super) fn xfoil_dump_wake(file: &str) -> Vec<(f64, f64)> {
    let text = std::fs::read_to_string(format!("{DATA}/{file}")).unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            l.split_whitespace()
                .map(|t| t.parse::<f64>().unwrap())
                .collect::<Vec<_>>()
        })
        .filter(|v| v.len() <= 9)
        .map(|v| (v[1], v[2]))
        .collect()
}
