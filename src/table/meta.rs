//! [`TableMeta`]: how a table was made, and its serde form.

use crate::geometry::{flap_deg, ShapeOp};
use crate::section::Transition;
use serde::{Deserialize, Serialize};

/// How a table was made: the airfoil and the solver settings shared by all its polars.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "MetaRecord", into = "MetaRecord")]
pub struct TableMeta {
    /// Airfoil display name.
    pub airfoil: String,
    /// The transition setting of every polar: N_crit and trip x/c per surface (the files'
    /// `ncrit` or `ncrit_top`/`ncrit_bot`, and `xtr_top_set`, `xtr_bot_set`).
    pub transition: Transition,
    /// Number of panel nodes on the airfoil.
    pub panels: usize,
    /// Solver name and version that produced the polars.
    pub solver: String,
    /// Geometry operations applied to the airfoil before it was solved, in order (empty: the
    /// section as given; tables written before operations existed read as empty).
    pub geometry: Vec<ShapeOp>,
}

impl TableMeta {
    /// The flap deflection \[deg\, positive trailing edge down\] of the section when a flap
    /// operation made it: the parameter of a flap sweep, one table per deflection (OpenFAST
    /// AeroDyn's `UserProp`).
    pub fn flap_deg(&self) -> Option<f64> {
        flap_deg(&self.geometry)
    }
}

/// The serde form of [`TableMeta`] (the JSON table format): `ncrit` when both surfaces have the
/// same N_crit, `ncrit_top` and `ncrit_bot` when they differ. Reading accepts either form.
#[derive(Serialize, Deserialize)]
struct MetaRecord {
    airfoil: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    ncrit: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    ncrit_top: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    ncrit_bot: Option<f64>,
    xtr_top_set: f64,
    xtr_bot_set: f64,
    panels: usize,
    solver: String,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    geometry: Vec<ShapeOp>,
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
            panels: r.panels,
            solver: r.solver,
            geometry: r.geometry,
        })
    }
}
