//! The PCA-2 preset with one modelling choice changed: the rows of the report's table of what
//! NACA Report 515's tunnel errors depend on.

use crate::rotor::{InflowModel, Rotor, TipLoss, YawedFlow};

/// One modelling choice of the preset changed, for the report's table of what the tunnel
/// errors depend on. Each is an alternative a reader of the sources could take, or a bound;
/// none is fitted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PresetChange {
    /// Uniform inflow (Glauert's momentum value) instead of Drees' linear inflow.
    UniformInflow,
    /// NACA Report 487's tip loss: the blade lift-free over half the tip chord, B = 1 − c/(2R)
    /// (its B = 0.959), instead of Prandtl's factor.
    ChordTipLoss,
    /// Report 487's own modelling of this rotor together: uniform inflow and its tip-loss rule
    /// (the two changes above at once).
    Report487Modelling,
    /// No tip loss (a bound).
    NoTipLoss,
    /// Profile drag on the chord-normal speed only: no yawed-flow drag.
    NoYawedFlowDrag,
    /// Induced-power factor κ = 1 (ideal momentum theory) instead of 1.15.
    IdealInducedPower,
    /// The pitch setting read at 0.75 R (the helicopter convention) instead of at the inboard
    /// blade: every station's twist less the twist at 0.75 R.
    SettingAtThreeQuarterRadius,
    /// No root cut-out: the blade from the rotor axis.
    NoRootCutout,
    /// The blade untwisted, the whole blade at the setting: not what Report 487 measured (its
    /// blade was twisted in flight, Fig. 5), shown as the size of the blade pitch's share.
    Untwisted,
}

impl PresetChange {
    /// Every change, in the report's order.
    pub const ALL: [Self; 9] = [
        Self::UniformInflow,
        Self::ChordTipLoss,
        Self::Report487Modelling,
        Self::NoTipLoss,
        Self::NoYawedFlowDrag,
        Self::IdealInducedPower,
        Self::SettingAtThreeQuarterRadius,
        Self::NoRootCutout,
        Self::Untwisted,
    ];

    /// The change in words.
    pub fn label(self) -> &'static str {
        match self {
            Self::UniformInflow => "uniform inflow (Glauert)",
            Self::ChordTipLoss => "tip loss B = 1 − c/(2R) (Report 487's rule)",
            Self::Report487Modelling => "both: Report 487's modelling",
            Self::NoTipLoss => "no tip loss",
            Self::NoYawedFlowDrag => "no yawed-flow drag",
            Self::IdealInducedPower => "induced-power factor 1",
            Self::SettingAtThreeQuarterRadius => "pitch setting read at 0.75 R",
            Self::NoRootCutout => "no root cut-out",
            Self::Untwisted => "blade untwisted (all at the setting)",
        }
    }

    /// `rotor` with the change.
    pub fn apply(self, rotor: &Rotor) -> Rotor {
        let mut r = rotor.clone();
        match self {
            Self::UniformInflow => r.inflow = InflowModel::Glauert,
            Self::ChordTipLoss => r.tip_loss = TipLoss::Chord,
            Self::Report487Modelling => {
                r.inflow = InflowModel::Glauert;
                r.tip_loss = TipLoss::Chord;
            }
            Self::NoTipLoss => r.tip_loss = TipLoss::NoLoss,
            Self::NoYawedFlowDrag => r.yawed_flow = YawedFlow::Ignored,
            Self::IdealInducedPower => r.induced_power_factor = 1.0,
            Self::SettingAtThreeQuarterRadius => {
                let (_, at_three_quarters) = rotor.planform.at(0.75);
                for s in &mut r.planform.stations {
                    s.twist -= at_three_quarters;
                }
            }
            Self::NoRootCutout => r.root_cutout = 0.0,
            Self::Untwisted => {
                for s in &mut r.planform.stations {
                    s.twist = 0.0;
                }
            }
        }
        r
    }
}
