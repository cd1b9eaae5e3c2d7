//! OpenFAST AeroDyn airfoil files ("AirfoilInfo v1.01"): one file per airfoil and Mach number,
//! one table per Reynolds number; written, and read back (ours and other tools').
//!
//! Layout (OpenFAST `modules/aerodyn/src/AirfoilInfo.f90`, `ReadAFfile`; the AeroDyn user
//! guide's example `docs/source/user/aerodyn/examples/ad_polar_example.dat`): comment lines
//! start with `!`; every other line is `value name [! comment]`, read in this order:
//! `InterpOrd`, the optional `RelThickness`, `NonDimArea`, `NumCoords` (and that many
//! coordinate rows, or `@file`), `BL_file`, `NumTabs`, then per table `Re` (in millions),
//! `UserProp` (formerly `Ctrl`), `InclUAdata`, when it is true the unsteady-aerodynamics lines
//! (`alpha0` … `filtCutOff`, each optional for OpenFAST), `NumAlf` and `NumAlf` rows
//! `alpha cl cd cm` (α in degrees from −180° to 180° with equal coefficients at both ends).
//! OpenFAST finds a line by its name and skips a missing optional one.
//!
//! What the writer chooses:
//! * A comment header of five lines (what, the airfoil and settings, the extension, where the
//!   UA coefficients come from, and a `polargen-table` line holding the metadata, Mach number,
//!   extension parameters and each table's computed α range as JSON), and two column-header
//!   comment lines after `NumAlf`: the shape of OpenFAST's own example files, which
//!   weio/pyDatView (`FASTInputFile`) needs — it takes the two lines after `NumAlf` as column
//!   headers and the lines before the first value as the file's comment.
//! * `RelThickness` (UA_Mod 7 needs it) when the table knows its airfoil's thickness, else
//!   left out (OpenFAST then takes 0.2).
//! * One table per Re of the grid, Re strictly increasing, `UserProp` the table's flap
//!   deflection in degrees, 0 without a flap (AeroDyn interpolates between tables in ln Re
//!   with `AFTabMod = 2`). A table with several Mach numbers gives one file per Mach number
//!   (`<stem>_M<mach>.dat`), all together or none ([`OutputSet`]).
//! * A flap sweep ([`write_aerodyn_flap_sweep`]) gives one file per (Re, M) with one table per
//!   deflection, `UserProp` increasing (`AFTabMod = 3`; see the `flap` module for OpenFAST's
//!   rule); a sixth comment line lists the deflections, and the `polargen-table` line also
//!   holds each table's metadata.
//! * `InclUAdata True` with the 32 lines `alpha0` … `filtCutOff` of [`UaParameters`], in the
//!   order and number the `openfast_io` reader (5.0) reads them by position. OpenFAST itself
//!   then computes only the four lines this set leaves out (`alphaUpper`, `alphaLower`,
//!   `C_lalpha`, `UACutout_delta`, used by UA_Mod 4–6). `InclUAdata False` (OpenFAST derives
//!   everything) only for a polar without an attached range.
//! * α rows: every usable α (converged, not in massive separation) of the polar at that
//!   (Re, M), and outside that range rows every `OUTER_STEP_DEG` (5°) from −180° and up to
//!   180°, kept at least half a step away from it. Values come from [`SectionAero::lookup`], so
//!   they include the 360° extension (Viterna–Corrigan, then a flat plate, with the table's
//!   `cd_max`) and never use unconverged points or points in massive separation (the
//!   extension replaces them from the last usable point; a comment line says so); the +180°
//!   row repeats the −180° row.
//! * Numbers in shortest round-trip form (reading the file gives back the same doubles).
//!
//! What the reader does ([`parse_aerodyn`]): it takes the lines by name as OpenFAST does
//! (skipping comment lines `!`, `#`, blank lines, coordinate rows and the UA lines, which it
//! does not keep), one polar per table. Tables must differ in Re only, or in UserProp only —
//! then [`ReadOptions::user_prop`](crate::table::ReadOptions) picks the ones to read. A file
//! with a `polargen-table` line gives back its metadata, Mach number and extension, and only
//! the rows of each table's computed α range (the rows beyond are the extension, which the
//! table regenerates); any other file is read whole, every row a converged point, at the Mach
//! number of the options (else 0, said in a note), N_crit and transition unknown.
//!
//! [`OutputSet`]: crate::output::OutputSet
//! [`UaParameters`]: crate::table::UaParameters
//! [`SectionAero::lookup`]: crate::section::SectionAero::lookup

mod flap;
mod read;
mod write;

pub(crate) use flap::flap_sweep_files;
pub use flap::write_aerodyn_flap_sweep;
pub(crate) use read::looks_like_aerodyn;
pub use read::parse_aerodyn;
pub use write::write_aerodyn;
pub(crate) use write::{mach_path, stage_aerodyn};

use crate::table::{PolarTable, PostStallParams, TableMeta};
use serde::{Deserialize, Serialize};

/// Width of the value column of `value name` lines.
const LABEL_WIDTH: usize = 22;

/// The word that marks the comment line holding the [`Header`].
const HEADER_MARK: &str = "polargen-table";

/// What a file written here says about itself beyond the AeroDyn fields: enough to give the
/// tables back.
#[derive(Serialize, Deserialize)]
struct Header {
    /// Mach number of the file.
    mach: f64,
    /// The metadata of the file's tables (of its first table when they differ).
    meta: TableMeta,
    /// The 360°-extension parameters.
    post_stall: PostStallParams,
    /// Per table, in the file's order: the converged α range, `[first, last]`.
    computed_alpha: Vec<[f64; 2]>,
    /// Per table, in the file's order, when the tables are of different sections (a flap
    /// sweep): each one's metadata; empty otherwise.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    table_meta: Vec<TableMeta>,
}

/// One table of a file: grid row `i_re` of `table`.
type Entry<'a> = (&'a PolarTable, usize);

impl Header {
    /// The header of the file at Mach column `i_mach` holding `entries` in this order
    /// (not empty).
    fn new(entries: &[Entry], i_mach: usize) -> Self {
        let first = entries[0].0;
        let same = entries.iter().all(|(t, _)| t.meta() == first.meta());
        Self {
            mach: first.mach()[i_mach],
            meta: first.meta().clone(),
            post_stall: *first.post_stall_params(),
            computed_alpha: entries
                .iter()
                .map(|&(table, i_re)| {
                    let (lo, hi) = table.alpha_range(i_re, i_mach).unwrap_or((0.0, 0.0));
                    [lo, hi]
                })
                .collect(),
            table_meta: if same {
                Vec::new()
            } else {
                entries.iter().map(|(t, _)| t.meta().clone()).collect()
            },
        }
    }

    /// The metadata of the file's table `k` (in the file's order).
    fn meta_of(&self, k: usize) -> &TableMeta {
        self.table_meta.get(k).unwrap_or(&self.meta)
    }

    /// The comment text: the mark and the JSON on one line.
    fn to_line(&self) -> String {
        let json = serde_json::to_string(self).unwrap_or_default();
        format!("{HEADER_MARK} {json}")
    }

    /// The header of a comment line's text (after `!`), if it is one.
    fn from_comment(text: &str) -> Option<Result<Self, serde_json::Error>> {
        let json = text.trim().strip_prefix(HEADER_MARK)?;
        Some(serde_json::from_str(json.trim()))
    }
}
