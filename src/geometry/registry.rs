//! Airfoil name registry: resolves a user-supplied string to an airfoil — a built-in name,
//! any NACA 4/5-digit designation, or a path to a coordinate file.

use std::path::Path;

use super::coordinates::{parse_airfoil_text, read_airfoil_file, to_selig_string};
use super::error::GeometryError;
use super::naca::{naca, NacaOptions};
use super::ops::{apply_shape_ops, ShapeOp};
use super::paneling::DEFAULT_PANEL_NODES;
use super::Airfoil;
use crate::input;

/// NACA 8-H-12 ordinates (NACA TN 1998, Table I), embedded so they are found from any
/// working directory. Provenance: `geometry/README.md`.
const NACA8H12_DAT: &str = include_str!("../../geometry/naca8h12.dat");

/// The embedded NACA 8-H-12 rotor section (Selig file, 51 points, sparse LE).
pub fn naca8h12() -> Result<Airfoil, GeometryError> {
    parse_airfoil_text(NACA8H12_DAT, "naca8h12 (embedded)", "NACA 8-H-12").map(|(a, _)| a)
}

/// The lookup key of an airfoil name: lower case without white space, `-` and `_`, so that
/// `NACA 8-H-12`, `naca8h12` and `NACA_8H12` are the same airfoil.
pub fn airfoil_key(name: &str) -> String {
    name.to_ascii_lowercase()
        .chars()
        .filter(|c| !c.is_whitespace() && *c != '-' && *c != '_')
        .collect()
}

/// Resolves `s` to an airfoil:
/// * `naca8h12` (also `NACA 8-H-12`, any case) → embedded 8-H-12 ordinates;
/// * `nacaDDDD` / `nacaDDDDD` / `NACA 2412` (any case, spaces allowed) → NACA generator with
///   XFOIL's conventions ([`NacaOptions::default`]), e.g. `naca23012`;
/// * `-` → coordinates read from standard input (the same capped reader);
/// * otherwise an existing path → coordinate-file reader ([`crate::input`]: a device, FIFO or
///   broken link is named as such).
///
/// A NACA-looking name with an invalid designation reports why, a folder gives
/// [`GeometryError::AirfoilIsFolder`], and a path where nothing exists gives
/// [`GeometryError::UnknownAirfoil`] listing what is accepted.
pub fn airfoil_by_name_or_path(s: &str) -> Result<Airfoil, GeometryError> {
    let trimmed = s.trim();
    let key = airfoil_key(trimmed);
    if key == "naca8h12" {
        return naca8h12();
    }
    let path = Path::new(trimmed);
    if trimmed == crate::input::STDIN_PATH {
        return read_airfoil_file(path);
    }
    if let Some(rest) = key.strip_prefix("naca") {
        // A designation (digits, or a 6-series one such as 64-212 or 65A010, refused by name)
        // unless a file of that name exists or the name looks like a path.
        let designation =
            rest.starts_with(|c: char| c.is_ascii_digit()) && !trimmed.contains(['.', '/', '\\']);
        if designation && !path.is_file() {
            return naca(trimmed, &NacaOptions::default()).map_err(|e| match e {
                GeometryError::NacaDesignation { reason, .. } => GeometryError::NacaDesignation {
                    designation: trimmed.to_string(),
                    reason,
                },
                other => other,
            });
        }
    }
    if !trimmed.is_empty() && path.is_dir() {
        return Err(GeometryError::AirfoilIsFolder {
            name: trimmed.to_string(),
        });
    }
    if !trimmed.is_empty() && input::exists(path) {
        // A file, or a device, FIFO or broken link that the reader names as such.
        return read_airfoil_file(path);
    }
    Err(GeometryError::UnknownAirfoil {
        name: trimmed.to_string(),
    })
}

/// The section a user's `spec` (as [`airfoil_by_name_or_path`]) and operations describe:
/// rotated so that the chord line lies along x when `derotate` is set, in chord units
/// ([`Airfoil::in_chord_units`]), then shaped by `ops` ([`apply_shape_ops`]; the partner of a
/// blend is loaded and prepared the same way); with the notes a user should read about what
/// was changed (rotation, an inclined chord kept, normalisation), each starting with `spec`.
pub fn shaped_airfoil(
    spec: &str,
    derotate: bool,
    ops: &[ShapeOp],
) -> Result<(Airfoil, Vec<String>), GeometryError> {
    let mut given = airfoil_by_name_or_path(spec)?;
    let locating = |airfoil: &Airfoil| {
        let name = airfoil.name.clone();
        move |source| GeometryError::Preparing {
            step: "locating the chord of",
            airfoil: name,
            source: Box::new(source),
        }
    };
    let angle = given.chord_angle_deg().map_err(locating(&given))?;
    let mut notes = Vec::new();
    if derotate {
        given = given.derotated()?;
        notes.push(format!(
            "{spec}: rotated by {:.3} deg so that the chord line lies along x; alpha is \
             measured from the chord line",
            -angle
        ));
    } else if angle.to_radians().abs() > super::CHORD_UNITS_TOLERANCE {
        notes.push(format!(
            "{spec}: the chord line is inclined by {angle:.3} deg to the x axis; alpha is \
             measured from the x axis of the coordinates (--derotate measures it from the \
             chord line)"
        ));
    }
    let (base, normalisation) = given.in_chord_units().map_err(locating(&given))?;
    if let Some(n) = normalisation {
        notes.push(n.note(spec));
    }
    let partner = |other: &str| {
        let foil = airfoil_by_name_or_path(other)?;
        let foil = if derotate { foil.derotated()? } else { foil };
        Ok(foil.in_chord_units()?.0)
    };
    Ok((apply_shape_ops(&base, ops, &partner)?, notes))
}

/// The Selig coordinate file of `airfoil` (as [`to_selig_string`]), checked to read back as a
/// section the solvers take: parsed, its chord located and paneled to
/// [`DEFAULT_PANEL_NODES`] as a coordinate file given to `--airfoil` would be. A shaped
/// contour that would be refused when read (a blend of unlike noses, an extreme flap) is
/// refused here, before anything is written.
pub fn selig_file_text(airfoil: &Airfoil) -> Result<String, GeometryError> {
    let text = to_selig_string(airfoil);
    let read_back = || -> Result<(), GeometryError> {
        let (foil, _) = parse_airfoil_text(&text, &airfoil.name, &airfoil.name)?;
        foil.chord_angle_deg()?;
        foil.in_chord_units()?
            .0
            .prepared_nodes(DEFAULT_PANEL_NODES)?;
        Ok(())
    };
    read_back().map_err(|e| GeometryError::Preparing {
        step: "reading back the contour written for",
        airfoil: airfoil.name.clone(),
        source: Box::new(e),
    })?;
    Ok(text)
}

/// The airfoil the solvers get from a user's `spec` and operations: the
/// [`shaped_airfoil`] repaneled to `panels` nodes ([`Airfoil::prepared_nodes`]; it is not
/// normalised again after the operations: a deflected flap moves the trailing edge, and α and
/// the moment reference stay those of the section before the operations), with its notes.
pub fn solver_airfoil(
    spec: &str,
    panels: usize,
    derotate: bool,
    ops: &[ShapeOp],
) -> Result<(Airfoil, Vec<String>), GeometryError> {
    let (foil, notes) = shaped_airfoil(spec, derotate, ops)?;
    Ok((foil.prepared_nodes(panels)?, notes))
}
