//! The shipped report inputs, built into the program so that `gyro report` runs from any
//! folder: the MTOsport preset with its propeller's Clark Y family tables, the four default-grid
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
use crate::table::{
    check_lookup_table, parse_table, read_lookup_table_with, PolarTable, ReadOptions, TableError,
    TableFormat, TableRead,
};
use std::path::{Path, PathBuf};

/// Default aircraft preset path of `gyro report`.
pub const SHIPPED_AIRCRAFT: &str = "aircraft/mtosport.toml";

/// Default table folder of `gyro report`.
pub const SHIPPED_POLARS: &str = "polars";

/// Default section table of the `gyro` commands of one section: the clean 8-H-12.
pub const SHIPPED_TABLE: &str = "polars/naca8h12_free.csv";

/// Default contaminated section table of `gyro compare`: the 8-H-12 tripped at 7 % chord.
pub const SHIPPED_CONTAMINATED_TABLE: &str = "polars/naca8h12_xtr0.07.csv";

/// The MTOsport preset as shipped.
const AIRCRAFT_TOML: &str = include_str!("../../aircraft/mtosport.toml");

/// The preset's propeller section tables (its `propeller.sections`) as shipped: file name,
/// content.
const PROPELLER_TABLES: [(&str, &str); 6] = [
    (
        "clarky_t0.08_free.csv",
        include_str!("../../polars/clarky_t0.08_free.csv"),
    ),
    (
        "clarky_free.csv",
        include_str!("../../polars/clarky_free.csv"),
    ),
    (
        "clarky_t0.18_free.csv",
        include_str!("../../polars/clarky_t0.18_free.csv"),
    ),
    (
        "clarky_t0.24_free.csv",
        include_str!("../../polars/clarky_t0.24_free.csv"),
    ),
    (
        "clarky_t0.36_free.csv",
        include_str!("../../polars/clarky_t0.36_free.csv"),
    ),
    (
        "clarky_t0.44_free.csv",
        include_str!("../../polars/clarky_t0.44_free.csv"),
    ),
];

/// The PCA-2 rotor preset beside the default aircraft preset.
pub const SHIPPED_PCA2: &str = "aircraft/pca2.toml";

/// The PCA-2 rotor preset as shipped.
const PCA2_TOML: &str = include_str!("../../aircraft/pca2.toml");

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
        let aircraft = Aircraft::parse_toml(AIRCRAFT_TOML, SHIPPED_AIRCRAFT)?;
        let embedded = |k: usize, file: &Path| {
            let fail = |source| AircraftError::PropellerSection {
                path: SHIPPED_AIRCRAFT.to_string(),
                field: format!("propeller.sections[{k}].table"),
                source,
            };
            let name = file.file_name().and_then(|n| n.to_str()).unwrap_or("");
            let (_, text) = PROPELLER_TABLES
                .iter()
                .find(|(n, _)| *n == name)
                .ok_or_else(|| AircraftError::Invalid {
                    field: "propeller.sections.table",
                    value: f64::NAN,
                    reason: format!("{name}: not a table built into the program").into(),
                })?;
            parse_table(text.as_bytes(), TableFormat::Csv)
                .and_then(|t| check_lookup_table(&t).map(|()| t))
                .map_err(fail)
        };
        let sections = aircraft.propeller.sections.clone().unwrap_or_default();
        let tables = sections
            .iter()
            .enumerate()
            .map(|(k, s)| Ok((s.thickness_ratio, embedded(k, &s.table)?)))
            .collect::<Result<Vec<_>, AircraftError>>()?;
        return Ok(aircraft.with_propeller_sections(tables));
    }
    Aircraft::from_toml_file(path)
}

/// The rotor preset at `path`, or the built-in PCA-2 or MTOsport preset (its rotor) when
/// `path` is the default path of either and absent.
pub(super) fn rotor_preset(path: &Path) -> Result<RotorPreset, AircraftError> {
    for (shipped, toml) in [(SHIPPED_PCA2, PCA2_TOML), (SHIPPED_AIRCRAFT, AIRCRAFT_TOML)] {
        if path == Path::new(shipped) && !exists(path) {
            return RotorPreset::from_toml_str(toml, shipped);
        }
    }
    RotorPreset::from_toml_file(path)
}

/// The lookup table at `path` with what its reader assumed (the Reynolds number of a C81
/// deck, the Mach number of an AeroDyn file: [`read_lookup_table_with`]), or the built-in copy
/// when `path` lies in the default folder, is one of the shipped tables and is absent.
pub(super) fn table(path: &Path) -> Result<TableRead, TableError> {
    let builtin = TABLES
        .iter()
        .find(|(name, _)| path == Path::new(SHIPPED_POLARS).join(name) && !exists(path));
    let Some((_, text)) = builtin else {
        return read_lookup_table_with(path, &ReadOptions::default());
    };
    let in_file = |source| TableError::File {
        path: path.to_path_buf(),
        source: Box::new(source),
    };
    let table = parse_table(text.as_bytes(), TableFormat::Csv).map_err(in_file)?;
    check_lookup_table(&table).map_err(in_file)?;
    Ok(TableRead {
        table,
        notes: Vec::new(),
    })
}

/// The inputs of a command that reads an aircraft and section tables: each file given, else
/// the shipped one (the file in a checkout, else the built-in copy: `aircraft`, `table`),
/// the rule of `gyro report` for every command; [`notes`](Self::notes) names the shipped
/// inputs used, in one line, after what the table readers assumed.
#[derive(Debug, Default)]
pub struct ShippedInputs {
    /// The shipped inputs used.
    shipped: Vec<&'static str>,
    /// What the table readers assumed, one line each.
    reader_notes: Vec<String>,
}

impl ShippedInputs {
    /// `given`, else the shipped path `shipped` (recorded for the note).
    fn path(&mut self, given: &Option<PathBuf>, shipped: &'static str) -> PathBuf {
        given.clone().unwrap_or_else(|| {
            self.shipped.push(shipped);
            PathBuf::from(shipped)
        })
    }

    /// The aircraft at `given`, else the shipped MTOsport ([`SHIPPED_AIRCRAFT`]).
    pub fn aircraft(&mut self, given: &Option<PathBuf>) -> Result<Aircraft, AircraftError> {
        aircraft(&self.path(given, SHIPPED_AIRCRAFT))
    }

    /// The aircraft at `aircraft` at `mass` \[kg\] (its own mass when `None`), what `check`
    /// makes of it (flags checked against the aircraft before the table is read) and the
    /// section table at `table`, else [`SHIPPED_TABLE`]: the inputs of a single-section command.
    pub fn aircraft_and_table<T, E>(
        &mut self,
        (aircraft, table): (&Option<PathBuf>, &Option<PathBuf>),
        mass: Option<f64>,
        check: impl FnOnce(&Aircraft) -> Result<T, E>,
    ) -> Result<(Aircraft, T, PolarTable), E>
    where
        E: From<AircraftError> + From<TableError>,
    {
        let mut ac = self.aircraft(aircraft)?;
        ac.mass_kg = mass.unwrap_or(ac.mass_kg);
        let checked = check(&ac)?;
        let table = self.table(table, SHIPPED_TABLE)?;
        Ok((ac, checked, table))
    }

    /// The rotor of the aircraft or rotor preset at `given`, else the shipped MTOsport's.
    pub fn rotor_preset(&mut self, given: &Option<PathBuf>) -> Result<RotorPreset, AircraftError> {
        rotor_preset(&self.path(given, SHIPPED_AIRCRAFT))
    }

    /// The lookup table at `given`, else the shipped table `shipped` (a path below
    /// [`SHIPPED_POLARS`], e.g. [`SHIPPED_TABLE`]).
    pub fn table(
        &mut self,
        given: &Option<PathBuf>,
        shipped: &'static str,
    ) -> Result<PolarTable, TableError> {
        let read = table(&self.path(given, shipped))?;
        self.reader_notes.extend(read.notes);
        Ok(read.table)
    }

    /// What a user should read about the inputs, one line each starting `note: `: what the
    /// table readers assumed, then the shipped inputs used.
    pub fn notes(&self) -> Vec<String> {
        let mut notes: Vec<String> = self
            .reader_notes
            .iter()
            .map(|n| format!("note: {n}"))
            .collect();
        notes.extend(self.shipped_note());
        notes
    }

    /// The note naming the shipped inputs used (`None` when every input was given).
    fn shipped_note(&self) -> Option<String> {
        (!self.shipped.is_empty()).then(|| {
            format!(
                "note: the shipped {} (the copy built in where the file is absent); \
                 --aircraft, --table, --clean, --contaminated choose others",
                self.shipped.join(" and ")
            )
        })
    }
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
            let f = crate::table::read_lookup_table(&root.join(SHIPPED_POLARS).join(name)).unwrap();
            assert_eq!(t.re(), f.re(), "{name}");
            assert_eq!(t.converged_count(), f.converged_count(), "{name}");
        }
    }
}
