//! The shipped report inputs, built into the program so that `gyro report` runs from any
//! folder: the MTOsport preset with its propeller's Clark Y table, the four default-grid
//! tables of `polars/`, and the PCA-2 rotor preset with its two Göttingen 429 tables. They are
//! used
//! when the default path is asked for and nothing exists there; a file that exists (in a
//! checkout, or given with `--aircraft`/`--polars`) is always read instead.
//!
//! The tables are embedded rather than computed: the four default grids take many minutes
//! of solver time, and the report documents exactly the tables the repository ships
//! (`polars/README.md`), so a report made outside the checkout shows the same numbers.

use crate::input::exists;
use crate::rotor::{Aircraft, AircraftError, RotorPreset};
use crate::table::{parse_table, read_lookup_table, PolarTable, TableError, TableFormat};
use std::path::Path;

/// Default aircraft preset path of `gyro report`.
pub const SHIPPED_AIRCRAFT: &str = "aircraft/mtosport.toml";

/// Default table folder of `gyro report`.
pub const SHIPPED_POLARS: &str = "polars";

/// The MTOsport preset as shipped.
const AIRCRAFT_TOML: &str = include_str!("../../aircraft/mtosport.toml");

/// The PCA-2 rotor preset beside the default aircraft preset.
pub const SHIPPED_PCA2: &str = "aircraft/pca2.toml";

/// The PCA-2 rotor preset as shipped.
const PCA2_TOML: &str = include_str!("../../aircraft/pca2.toml");

/// The preset's propeller section table (its `section_table`) as shipped.
const PROPELLER_TABLE: &str = include_str!("../../polars/clarky_free.csv");

/// The shipped tables: file name, content.
const TABLES: [(&str, &str); 6] = [
    (
        "naca8h12_free.csv",
        include_str!("../../polars/naca8h12_free.csv"),
    ),
    (
        "naca8h12_xtr0.07.csv",
        include_str!("../../polars/naca8h12_xtr0.07.csv"),
    ),
    (
        "naca23012_free.csv",
        include_str!("../../polars/naca23012_free.csv"),
    ),
    (
        "naca23012_xtr0.07.csv",
        include_str!("../../polars/naca23012_xtr0.07.csv"),
    ),
    (
        "goe429_free.csv",
        include_str!("../../polars/goe429_free.csv"),
    ),
    (
        "goe429_xtr0.07.csv",
        include_str!("../../polars/goe429_xtr0.07.csv"),
    ),
];

/// The aircraft at `path`, or the built-in preset when `path` is the default and absent.
pub(super) fn aircraft(path: &Path) -> Result<Aircraft, AircraftError> {
    if path == Path::new(SHIPPED_AIRCRAFT) && !exists(path) {
        let section = parse_table(PROPELLER_TABLE.as_bytes(), TableFormat::Csv)
            .and_then(|t| t.require_lookup().map(|()| t))
            .map_err(|source| AircraftError::PropellerSection {
                path: SHIPPED_AIRCRAFT.to_string(),
                source,
            })?;
        return Ok(
            Aircraft::parse_toml(AIRCRAFT_TOML, SHIPPED_AIRCRAFT)?.with_propeller_section(section)
        );
    }
    Aircraft::from_toml_file(path)
}

/// The rotor preset at `path`, or the built-in PCA-2 preset when `path` is the default and
/// absent.
pub(super) fn rotor_preset(path: &Path) -> Result<RotorPreset, AircraftError> {
    if path == Path::new(SHIPPED_PCA2) && !exists(path) {
        return RotorPreset::from_toml_str(PCA2_TOML, SHIPPED_PCA2);
    }
    RotorPreset::from_toml_file(path)
}

/// The lookup table at `path`, or the built-in copy when `path` lies in the default folder,
/// is one of the shipped tables and is absent.
pub(super) fn table(path: &Path) -> Result<PolarTable, TableError> {
    let builtin = TABLES
        .iter()
        .find(|(name, _)| path == Path::new(SHIPPED_POLARS).join(name) && !exists(path));
    let Some((_, text)) = builtin else {
        return read_lookup_table(path);
    };
    let in_file = |source| TableError::File {
        path: path.to_path_buf(),
        source: Box::new(source),
    };
    let table = parse_table(text.as_bytes(), TableFormat::Csv).map_err(in_file)?;
    table.require_lookup().map_err(in_file)?;
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_in_inputs_parse_and_match_the_files() {
        // The tests run in the checkout, where the files exist: compare both routes.
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let ac = Aircraft::from_toml_str(AIRCRAFT_TOML, SHIPPED_AIRCRAFT).unwrap();
        let file = Aircraft::from_toml_file(&root.join(SHIPPED_AIRCRAFT)).unwrap();
        assert_eq!(ac.mass_kg, file.mass_kg);
        let pca2 = RotorPreset::from_toml_str(PCA2_TOML, SHIPPED_PCA2).unwrap();
        let file = RotorPreset::from_toml_file(&root.join(SHIPPED_PCA2)).unwrap();
        assert_eq!(pca2.rotor.incidence_deg, file.rotor.incidence_deg);
        for (name, text) in TABLES {
            let t = parse_table(text.as_bytes(), TableFormat::Csv).unwrap();
            let f = read_lookup_table(&root.join(SHIPPED_POLARS).join(name)).unwrap();
            assert_eq!(t.re(), f.re(), "{name}");
            assert_eq!(t.converged_count(), f.converged_count(), "{name}");
        }
    }
}
