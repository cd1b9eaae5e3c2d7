//! [`TableMeta`]: how a table was made, and its serde form.

use super::grid::nonfinite;
use crate::geometry::{flap_deg, ShapeOp};
use crate::section::Transition;
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
    /// The transition setting of every polar: N_crit and trip x/c per surface (the files'
    /// `ncrit` or `ncrit_top`/`ncrit_bot`, and `xtr_top_set`, `xtr_bot_set`); NaN values when
    /// the file does not record them ([`Transition::UNKNOWN`]).
    pub transition: Transition,
    /// Largest thickness / chord of the airfoil (AeroDyn's `RelThickness`); NaN when unknown.
    pub thickness: f64,
    /// Number of panel nodes on the airfoil.
    pub panels: usize,
    /// Solver name and version that produced the polars.
    pub solver: String,
    /// Geometry operations applied to the airfoil before it was solved, in order (empty: the
    /// section as given; tables written before operations existed read as empty).
    pub geometry: Vec<ShapeOp>,
}

impl PartialEq for TableMeta {
    /// Field by field; two unknown (NaN) numbers are equal: the same metadata.
    fn eq(&self, other: &Self) -> bool {
        let same = |a: f64, b: f64| a == b || (a.is_nan() && b.is_nan());
        let (a, b) = (&self.transition, &other.transition);
        self.airfoil == other.airfoil
            && same(a.ncrit_top, b.ncrit_top)
            && same(a.ncrit_bot, b.ncrit_bot)
            && same(a.xtr_top, b.xtr_top)
            && same(a.xtr_bot, b.xtr_bot)
            && same(self.thickness, other.thickness)
            && self.panels == other.panels
            && self.solver == other.solver
            && self.geometry == other.geometry
    }
}

impl TableMeta {
    /// The flap deflection \[deg, positive trailing edge down\] of the section when a flap
    /// operation made it: the parameter of a flap sweep, one table per deflection (OpenFAST
    /// AeroDyn's `UserProp`).
    pub fn flap_deg(&self) -> Option<f64> {
        flap_deg(&self.geometry)
    }

    /// The metadata of a table read from a file that gives only the airfoil's name (C81,
    /// AeroDyn from other tools): N_crit, transition settings and thickness unknown, no panel
    /// count, `solver` naming the file kind.
    pub fn unknown(airfoil: &str, solver: &str) -> Self {
        Self {
            airfoil: airfoil.to_string(),
            transition: Transition::UNKNOWN,
            thickness: f64::NAN,
            panels: 0,
            solver: solver.to_string(),
            geometry: Vec::new(),
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
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    geometry: Vec<ShapeOp>,
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
        let t = m.transition;
        let common = t.common_ncrit();
        let per_side = |n: f64| common.is_none().then_some(n);
        Self {
            ncrit: common,
            ncrit_top: per_side(t.ncrit_top),
            ncrit_bot: per_side(t.ncrit_bot),
            airfoil: m.airfoil,
            xtr_top_set: t.xtr_top,
            xtr_bot_set: t.xtr_bot,
            thickness: m.thickness,
            panels: m.panels,
            solver: m.solver,
            geometry: m.geometry,
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
            transition: Transition::sides(ncrit_top, ncrit_bot, r.xtr_top_set, r.xtr_bot_set),
            thickness: r.thickness,
            panels: r.panels,
            solver: r.solver,
            geometry: r.geometry,
        })
    }
}
