//! C81: the airfoil-table format of rotorcraft comprehensive codes (C81, CAMRAD, RCAS,
//! MBDyn, DUST).
//!
//! Layout, as documented in the header comment of MBDyn's `c81data.cc` (Politecnico di
//! Milano):
//!
//! ```text
//! name, NML, NAL, NMD, NAD, NMM, NAM               A30, 6I2
//! ML(1..NML)                                        7X, 9F7.0   (continuation lines 7X, 9F7.0)
//! AL(i), CL(i, 1..NML)        for i = 1..NAL        10F7.0 / (7X, 9F7.0)
//! MD(1..NMD); AD(i), CD(i, 1..NMD)                  the same for drag
//! MM(1..NMM); AM(i), CM(i, 1..NMM)                  the same for moment
//! ```
//!
//! i.e. a block per coefficient: a row of Mach numbers, then one row per α with the value at
//! each Mach number, in 7-character fields, at most 9 values per line (the α field counts as
//! the tenth on the first line), continuation lines starting with 7 blanks.
//!
//! What this writer chooses:
//! * One table per Reynolds number (file `<stem>_Re<re>.c81`, or `path` itself when the table
//!   has one Re), or a single table at a chosen Re (interpolated in ln Re).
//! * The three blocks share the Mach list (the table's Mach axis) and the α list.
//! * α rows: every usable α (converged, not in massive separation) of the polars used (the
//!   nearest Re row of the grid), thinned uniformly if needed to fit the 99-row limit of the
//!   I2 counts, plus rows every
//!   `outer_step_deg` from −180° and up to +180° outside that range, kept at least half a
//!   step away from it; any rows left of the 99 then split the widest gaps outside the
//!   computed range, weighted towards it (the extension changes fastest after stall), while
//!   gaps wider than 2° remain. Values come from
//!   [`SectionAero::lookup`](crate::section::SectionAero::lookup), so they include the
//!   360° extension and never use unconverged points or points in massive separation (the
//!   extension starts from the last usable point and replaces them).
//! * Fields: Mach F7.3, α F7.2; each coefficient block with one decimal count for all its
//!   values, the largest (≤ 4) that leaves every field a leading blank, so that free-format
//!   (whitespace-splitting) readers work too. A negative value drops the zero before the
//!   point (`-.0100`, which Fortran F7.0, C `strtod` and Python `float` all read), so it keeps
//!   the digits of a positive one (`0.0089`).
//! * A one-Mach table is written as two identical Mach columns, at its Mach number M and at
//!   M + 0.1 (or halfway to 1 when that reaches 1), because some readers (c81utils) need two
//!   Mach values; the values do not depend on Mach. [`parse_c81`] reads such a table back as
//!   one Mach column.
//! * The format has no comment line and no field for the minimum pressure, the supercritical
//!   or the massive-separation flag, so a deck cannot carry them: supercritical points enter it
//!   like any other, points in massive separation not at all (the extension stands in for
//!   them). The CSV, JSON and XFOIL-polar forms of the same table hold them.
//!
//! The reader ([`parse_c81`], [`parse_c81_with`]) takes the fixed 7-column fields of the
//! format's definition (MBDyn files need not leave blanks between fields) and the counts from
//! columns 31–42 of the first line. Each block is read on its own Mach and α lists, as decks
//! from other tools have them (MBDyn's `naca0012.c81`: CL at 11 Mach numbers and 39 angles,
//! CD at 11 and 65, CM at 9 and 47). The table's Mach axis is the union of the three Mach
//! lists below 1 (a column at M ≥ 1 is dropped, and said: a table holds subsonic polars), each
//! polar's α rows the union of the three α lists; each coefficient is interpolated on its
//! own block, linearly in α and M, held at the block's edges. Every row is a converged point.
//! A deck carries no Reynolds number and no N_crit or transition setting: the Reynolds number
//! comes from a `Re<number>` word of the name (as written here), else from the file name
//! (`…_Re1e6…`), else [`ReadOptions::re`](crate::table::ReadOptions), else 10⁶ — the last two
//! said in a note; N_crit and the transition settings are unknown (NaN).

mod read;
mod write;

pub(crate) use read::looks_like_c81;
pub use read::{parse_c81, parse_c81_with};
pub(in crate::table::io) use write::re_path;
pub(crate) use write::stage_c81;
pub use write::{write_c81, C81Options};

/// Width of every C81 field.
pub const FIELD: usize = 7;
/// Largest α or Mach count the 2-digit header allows.
pub const MAX_COUNT: usize = 99;
