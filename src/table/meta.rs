//! [`TableMeta`]: how a table was made, and its serde form.

use super::grid::nonfinite;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// How a table was made: the airfoil and the solver settings shared by all its polars.
///
/// A number a table's file does not give (a C81 deck has no N_crit, no transition setting,
/// no thickness) is NaN: unknown, written as such, never a made-up default.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(try_from = "MetaRecord", into = "MetaRecord")]
pub struct TableMeta {
    /// Airfoil display name.
    pub airfoil: String,
    /// e^n transition criterion N_crit on the upper surface (XFOIL ACRIT(1), VPAR `NT`).
    pub ncrit_top: f64,
    /// e^n transition criterion N_crit on the lower surface (XFOIL ACRIT(2), VPAR `NB`).
    pub ncrit_bot: f64,
    /// Forced transition x/c on the upper surface (1 = free transition).
    pub xtr_top_set: f64,
    /// Forced transition x/c on the lower surface (1 = free transition).
    pub xtr_bot_set: f64,
    /// Largest thickness / chord of the airfoil (AeroDyn's `RelThickness`); NaN when unknown.
    pub thickness: f64,
    /// Number of panel nodes on the airfoil.
    pub panels: usize,
    /// Solver name and version that produced the polars.
    pub solver: String,
}

impl PartialEq for TableMeta {
    /// Field by field; two unknown (NaN) numbers are equal: the same metadata.
    fn eq(&self, other: &Self) -> bool {
        let same = |a: f64, b: f64| a == b || (a.is_nan() && b.is_nan());
        self.airfoil == other.airfoil
            && same(self.ncrit_top, other.ncrit_top)
            && same(self.ncrit_bot, other.ncrit_bot)
            && same(self.xtr_top_set, other.xtr_top_set)
            && same(self.xtr_bot_set, other.xtr_bot_set)
            && same(self.thickness, other.thickness)
            && self.panels == other.panels
            && self.solver == other.solver
    }
}

impl TableMeta {
    /// The N_crit of both surfaces when they are equal (bit for bit), as the files write it:
    /// one `ncrit` value, else one per side.
    pub fn common_ncrit(&self) -> Option<f64> {
        (self.ncrit_top.to_bits() == self.ncrit_bot.to_bits()).then_some(self.ncrit_top)
    }

    /// N_crit for a comment line: `9`, `9 (top) 3 (bottom)` when the surfaces differ,
    /// `unknown` when the table does not say.
    pub fn ncrit_text(&self) -> String {
        match self.common_ncrit() {
            Some(n) if n.is_nan() => "unknown".to_string(),
            Some(n) => n.to_string(),
            None => format!("{} (top) {} (bottom)", self.ncrit_top, self.ncrit_bot),
        }
    }

    /// The metadata of a table read from a file that gives only the airfoil's name (C81,
    /// AeroDyn from other tools): N_crit, transition settings and thickness unknown, no panel
    /// count, `solver` naming the file kind.
    pub fn unknown(airfoil: &str, solver: &str) -> Self {
        Self {
            airfoil: airfoil.to_string(),
            ncrit_top: f64::NAN,
            ncrit_bot: f64::NAN,
            xtr_top_set: f64::NAN,
            xtr_bot_set: f64::NAN,
            thickness: f64::NAN,
            panels: 0,
            solver: solver.to_string(),
        }
    }
}

/// The serde form of [`TableMeta`] (the JSON table format): `ncrit` when both surfaces have the
/// same N_crit, `ncrit_top` and `ncrit_bot` when they differ. Reading accepts either form.
/// Unknown numbers are the string `"NaN"`; a file without `thickness` reads as unknown.
#[derive(Serialize, Deserialize)]
struct MetaRecord {
    airfoil: String,
    #[serde(default, skip_serializing_if = "Option::is_none", with = "optional")]
    ncrit: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none", with = "optional")]
    ncrit_top: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none", with = "optional")]
    ncrit_bot: Option<f64>,
    #[serde(with = "nonfinite")]
    xtr_top_set: f64,
    #[serde(with = "nonfinite")]
    xtr_bot_set: f64,
    #[serde(with = "nonfinite", default = "unknown")]
    thickness: f64,
    panels: usize,
    solver: String,
}

/// NaN: the value of a field a file does not have.
fn unknown() -> f64 {
    f64::NAN
}

/// [`nonfinite`] for optional fields.
mod optional {
    use super::*;

    pub fn serialize<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
        match v {
            Some(v) => nonfinite::serialize(v, s),
            None => s.serialize_none(),
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
        nonfinite::deserialize(d).map(Some)
    }
}

impl From<TableMeta> for MetaRecord {
    fn from(m: TableMeta) -> Self {
        let common = m.common_ncrit();
        let per_side = |n: f64| common.is_none().then_some(n);
        Self {
            ncrit: common,
            ncrit_top: per_side(m.ncrit_top),
            ncrit_bot: per_side(m.ncrit_bot),
            airfoil: m.airfoil,
            xtr_top_set: m.xtr_top_set,
            xtr_bot_set: m.xtr_bot_set,
            thickness: m.thickness,
            panels: m.panels,
            solver: m.solver,
        }
    }
}

impl TryFrom<MetaRecord> for TableMeta {
    type Error = &'static str;

    fn try_from(r: MetaRecord) -> Result<Self, Self::Error> {
        let (ncrit_top, ncrit_bot) = match (r.ncrit, r.ncrit_top, r.ncrit_bot) {
            (Some(n), None, None) => (n, n),
            (None, Some(top), Some(bot)) => (top, bot),
            _ => return Err("metadata needs either ncrit or both ncrit_top and ncrit_bot"),
        };
        Ok(Self {
            airfoil: r.airfoil,
            ncrit_top,
            ncrit_bot,
            xtr_top_set: r.xtr_top_set,
            xtr_bot_set: r.xtr_bot_set,
            thickness: r.thickness,
            panels: r.panels,
            solver: r.solver,
        })
    }
}
