//! Shared helpers of the inviscid tests: reading the reference files in tests/data/inviscid.

#![allow(dead_code)]

use polargen::geometry::Airfoil;

/// Directory of the inviscid test data.
pub const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/inviscid");

/// Reads XFOIL's paneled nodes `<name>_xfoil_paneled.dat` (plain `x y`, E-notation allowed).
pub fn xfoil_nodes(name: &str) -> Airfoil {
    let path = format!("{DATA}/{name}_xfoil_paneled.dat");
    polargen::geometry::read_airfoil_file(std::path::Path::new(&path)).unwrap()
}
