//! Readers of the XFOIL 6.99 reference files in `tests/data/xfoil` (the command that made each
//! file: that folder's README), shared by every test that compares with XFOIL.
#![allow(dead_code)]

use polargen::geometry::{read_airfoil_file, Airfoil};
use std::path::PathBuf;

/// The folder of the reference files.
pub const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/xfoil");

/// Path of the reference file `file`.
pub fn path(file: &str) -> PathBuf {
    PathBuf::from(DIR).join(file)
}

/// The text of the reference file `file`.
pub fn text(file: &str) -> String {
    std::fs::read_to_string(path(file)).unwrap_or_else(|e| panic!("{file}: {e}"))
}

/// One row of a polar file (`alpha,cl,cd,cdp,cm,xtr_top,xtr_bot`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolarRow {
    pub alpha: f64,
    pub cl: f64,
    pub cd: f64,
    /// Pressure drag (XFOIL's CDp).
    pub cdp: f64,
    pub cm: f64,
    pub xtr_top: f64,
    pub xtr_bot: f64,
}

/// The rows of a polar file, in the file's order (ascending α); α values where XFOIL did not
/// converge are absent.
pub fn polar(file: &str) -> Vec<PolarRow> {
    text(file)
        .lines()
        .skip(1)
        .map(|line| {
            let v: Vec<f64> = line
                .split(',')
                .map(|t| t.parse().unwrap_or_else(|e| panic!("{file}: {line}: {e}")))
                .collect();
            assert_eq!(v.len(), 7, "{file}: {line}");
            PolarRow {
                alpha: v[0],
                cl: v[1],
                cd: v[2],
                cdp: v[3],
                cm: v[4],
                xtr_top: v[5],
                xtr_bot: v[6],
            }
        })
        .collect()
}

/// The row of `rows` at `alpha`, if XFOIL converged there.
pub fn at_alpha(rows: &[PolarRow], alpha: f64) -> Option<&PolarRow> {
    rows.iter().find(|r| (r.alpha - alpha).abs() < 1e-9)
}

/// A node file of this folder (`<foil>_paneled.dat`, `<foil>_buffer.dat`, …) as an airfoil.
pub fn nodes(file: &str) -> Airfoil {
    read_airfoil_file(&path(file)).unwrap_or_else(|e| panic!("{file}: {e}"))
}

/// XFOIL's 160 paneled nodes of `foil` (`<foil>_paneled.dat`).
pub fn paneled(foil: &str) -> Airfoil {
    nodes(&format!("{foil}_paneled.dat"))
}

/// The numeric rows of a `DUMP` file: 12 columns on the airfoil surface (s, x, y, Ue, δ*, θ,
/// Cf, Hk, H*, P, m, K), 8 in the wake (s, x, y, Ue, δ*, θ, Cf, Hk).
pub fn dump(file: &str) -> Vec<Vec<f64>> {
    numeric_rows(file)
}

/// The (x, Cp) rows of a `CPWR` file.
pub fn cp(file: &str) -> Vec<(f64, f64)> {
    numeric_rows(file)
        .into_iter()
        .map(|v| (v[0], v[v.len() - 1]))
        .collect()
}

/// Whitespace-separated numbers of each line that is not a `#` comment.
fn numeric_rows(file: &str) -> Vec<Vec<f64>> {
    text(file)
        .lines()
        .filter(|l| !l.trim_start().starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            l.split_whitespace()
                .map(|t| t.parse().unwrap_or_else(|e| panic!("{file}: {l}: {e}")))
                .collect()
        })
        .collect()
}

/// Checks that README.md's block `name` — the lines between `<!-- generated: <name> (...) -->`
/// and `<!-- end generated: <name> -->` — is `generated`; with the environment variable
/// `UPDATE_README` set, rewrites the block first. Panics with `command` (which rewrites it) and
/// the current text when the block is stale.
pub fn check_readme_block(name: &str, command: &str, generated: &str) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("README.md");
    let readme = std::fs::read_to_string(&path).unwrap();
    let start_tag = format!("<!-- generated: {name} (");
    let end_tag = format!("<!-- end generated: {name} -->");
    let start = readme
        .find(&start_tag)
        .unwrap_or_else(|| panic!("README.md has no block starting `{start_tag}`"));
    let body = start + readme[start..].find('\n').unwrap() + 1;
    let end = body
        + readme[body..]
            .find(&end_tag)
            .unwrap_or_else(|| panic!("README.md has no `{end_tag}`"));
    if std::env::var_os("UPDATE_README").is_some() {
        let updated = format!("{}{generated}{}", &readme[..body], &readme[end..]);
        std::fs::write(&path, updated).unwrap();
        return;
    }
    assert!(
        readme[body..end] == *generated,
        "README.md's block `{name}` is stale: run `{command}`; it should read\n{generated}"
    );
}
