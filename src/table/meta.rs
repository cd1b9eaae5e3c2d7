//! [`TableMeta`]: how a table was made, and its serde form.

use crate::geometry::{flap_deg, ShapeOp};
use serde::{Deserialize, Serialize};

/// How a table was made: the airfoil and the solver settings shared by all its polars.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
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
    /// Number of panel nodes on the airfoil.
    pub panels: usize,
    /// Solver name and version that produced the polars.
    pub solver: String,
    /// Geometry operations applied to the airfoil before it was solved, in order (empty: the
    /// section as given; tables written before operations existed read as empty).
    pub geometry: Vec<ShapeOp>,
}

impl TableMeta {
    /// The N_crit of both surfaces when they are equal (bit for bit), as the files write it:
    /// one `ncrit` value, else one per side.
    pub fn common_ncrit(&self) -> Option<f64> {
        (self.ncrit_top.to_bits() == self.ncrit_bot.to_bits()).then_some(self.ncrit_top)
    }

    /// N_crit for a comment line: `9`, or `9 (top) 3 (bottom)` when the surfaces differ.
    pub fn ncrit_text(&self) -> String {
        match self.common_ncrit() {
            Some(n) => n.to_string(),
            None => format!("{} (top) {} (bottom)", self.ncrit_top, self.ncrit_bot),
        }
    }

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
        let common = m.common_ncrit();
        let per_side = |n: f64| common.is_none().then_some(n);
        Self {
            ncrit: common,
            ncrit_top: per_side(m.ncrit_top),
            ncrit_bot: per_side(m.ncrit_bot),
            airfoil: m.airfoil,
            xtr_top_set: m.xtr_top_set,
            xtr_bot_set: m.xtr_bot_set,
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
            ncrit_top,
            ncrit_bot,
            xtr_top_set: r.xtr_top_set,
            xtr_bot_set: r.xtr_bot_set,
            panels: r.panels,
            solver: r.solver,
            geometry: r.geometry,
        })
    }
}
