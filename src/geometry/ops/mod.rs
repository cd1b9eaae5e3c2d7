//! Geometry operations on a section, with XFOIL GDES semantics (Drela & Youngren, XFOIL 6.99
//! `xgdes.f`, `xtcam.f`, `xgeom.f`, read for the equations; written anew here):
//!
//! * thickness and camber set to given maxima (`TSET`: the thickness and camber lines are
//!   separated, scaled and recombined) — [`Airfoil::with_thickness_camber`], module `camber`;
//! * trailing-edge gap with a blending distance (`TGAP`) — [`Airfoil::with_te_gap`];
//! * plain flap about a hinge (`FLAP`, with the gap and overlap handling at the surface
//!   breaks) — [`Airfoil::with_flap`];
//! * blend of two sections by a fraction, points paired by chordwise station (XFOIL `INTX`,
//!   as XFLR5) — [`Airfoil::blended`].
//!
//! [`ShapeOp`] is one operation as a user gives it and a table records it; [`apply_shape_ops`]
//! applies a list in order. Operations work in the section's own coordinates: the callers
//! bring a contour to chord units first, so a hinge at x = 0.75 is at 75 % chord.

mod blend;
mod camber;
mod flap;
mod te_gap;

pub use camber::{LineMaximum, ThicknessCamber};

use super::spline::ContourSpline;
use super::{Airfoil, GeometryError};
use crate::arguments::ArgumentError;
use crate::limits::exact_number;
use serde::{Deserialize, Serialize};
use std::fmt;

/// Largest maximum thickness a section may be given \[chord\] (exclusive).
pub const MAX_THICKNESS: f64 = 1.0;

/// Largest |maximum camber| a section may be given \[chord\].
pub const MAX_CAMBER: f64 = 0.2;

/// Largest trailing-edge gap a section may be given \[chord\] (flatback wind-turbine sections
/// reach 0.175 of the chord, see [`MAX_TE_GAP_RATIO`](super::MAX_TE_GAP_RATIO)).
pub const MAX_TE_GAP: f64 = 0.2;

/// Largest |flap deflection| \[deg\] (exclusive).
pub const MAX_FLAP_DEG: f64 = 90.0;

/// Largest |hinge y| \[chord\].
pub const MAX_HINGE_Y: f64 = 0.5;

/// Blending distance of `te-gap` when none is given: XFOIL `TGAP`'s default, 1 (the change
/// spread linearly over the whole chord).
pub const DEFAULT_TE_GAP_BLEND: f64 = 1.0;

/// One geometry operation as given by a user and recorded in a table's metadata. Text form
/// (command-line flag, CSV column): `thickness T`, `camber C`, `te-gap G:BLEND`,
/// `flap X:Y:DEG`, `blend OTHER:F`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "op", rename_all = "kebab-case")]
pub enum ShapeOp {
    /// Maximum thickness set to `thickness` (chord units; XFOIL `TSET`).
    Thickness {
        /// New maximum thickness.
        thickness: f64,
    },
    /// Maximum camber set to `camber` (chord units, signed; XFOIL `TSET`).
    Camber {
        /// New maximum camber.
        camber: f64,
    },
    /// Trailing-edge gap set to `gap`, blended over `blend` of the chord (XFOIL `TGAP`).
    TeGap {
        /// New gap (chord units).
        gap: f64,
        /// Blending distance / chord, in [0, 1].
        blend: f64,
    },
    /// Plain flap about the hinge (x/c, y/c), deflected by `deflection_deg` (positive trailing
    /// edge down; XFOIL `FLAP`).
    Flap {
        /// Hinge x/c.
        hinge_x: f64,
        /// Hinge y/c.
        hinge_y: f64,
        /// Deflection \[deg\], positive trailing edge down.
        deflection_deg: f64,
    },
    /// Blend with the section `other` (a name or path as `--airfoil` takes it): `fraction` of
    /// it, 1 − `fraction` of this one.
    Blend {
        /// The other section as given.
        other: String,
        /// Fraction of the other section, in [0, 1].
        fraction: f64,
    },
}

impl fmt::Display for ShapeOp {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Numbers that read back exactly and stay short (`1e-300`, not 300 digits).
        let n = |v: &f64| exact_number(*v);
        match self {
            Self::Thickness { thickness } => write!(f, "thickness {}", n(thickness)),
            Self::Camber { camber } => write!(f, "camber {}", n(camber)),
            Self::TeGap { gap, blend } => write!(f, "te-gap {}:{}", n(gap), n(blend)),
            Self::Flap {
                hinge_x,
                hinge_y,
                deflection_deg,
            } => write!(
                f,
                "flap {}:{}:{}",
                n(hinge_x),
                n(hinge_y),
                n(deflection_deg)
            ),
            Self::Blend { other, fraction } => write!(f, "blend {other}:{}", n(fraction)),
        }
    }
}

/// The operations as one line, `; `-separated (the text form of each, [`ShapeOp`]).
pub fn shape_ops_text(ops: &[ShapeOp]) -> String {
    ops.iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join("; ")
}

/// The operations of [`shape_ops_text`]'s form (empty text: none).
pub fn parse_shape_ops(text: &str) -> Result<Vec<ShapeOp>, ArgumentError> {
    text.split(';')
        .map(str::trim)
        .filter(|t| !t.is_empty())
        .map(|t| {
            let (kind, value) = t.split_once(' ').unwrap_or((t, ""));
            match kind {
                "thickness" => ShapeOp::thickness(value),
                "camber" => ShapeOp::camber(value),
                "te-gap" => ShapeOp::te_gap(value),
                "flap" => ShapeOp::flap(value),
                "blend" => ShapeOp::blend(value),
                _ => Err(ArgumentError::with_text(
                    "geometry",
                    t,
                    "expected thickness, camber, te-gap, flap or blend",
                )),
            }
        })
        .collect()
}

/// A number of flag `name` from `text`, checked by `ok`.
fn number(
    name: &str,
    text: &str,
    ok: impl Fn(f64) -> bool,
    rule: &'static str,
) -> Result<f64, ArgumentError> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| ArgumentError::with_text(name, text, "not a number"))?;
    if v.is_finite() && ok(v) {
        Ok(v)
    } else {
        Err(ArgumentError::with_text(name, text, rule))
    }
}

impl ShapeOp {
    /// `--thickness T`: 0 < T < [`MAX_THICKNESS`].
    pub fn thickness(text: &str) -> Result<Self, ArgumentError> {
        let rule = "the maximum thickness must be in (0, 1) chord";
        number("--thickness", text, |t| t > 0.0 && t < MAX_THICKNESS, rule)
            .map(|thickness| Self::Thickness { thickness })
    }

    /// `--camber C`: |C| ≤ [`MAX_CAMBER`].
    pub fn camber(text: &str) -> Result<Self, ArgumentError> {
        let rule = "the maximum camber must be in [-0.2, 0.2] chord";
        number("--camber", text, |c| c.abs() <= MAX_CAMBER, rule)
            .map(|camber| Self::Camber { camber })
    }

    /// `--te-gap G[:BLEND]`: 0 ≤ G ≤ [`MAX_TE_GAP`], BLEND in [0, 1] (default
    /// [`DEFAULT_TE_GAP_BLEND`]).
    pub fn te_gap(text: &str) -> Result<Self, ArgumentError> {
        let (g, b) = text.split_once(':').unwrap_or((text, ""));
        let rule = "the trailing-edge gap must be in [0, 0.2] chord";
        let gap = number("--te-gap", g, |g| (0.0..=MAX_TE_GAP).contains(&g), rule)?;
        let blend = if b.is_empty() {
            DEFAULT_TE_GAP_BLEND
        } else {
            let rule = "the blending distance must be in [0, 1] chord";
            number("--te-gap", b, |b| (0.0..=1.0).contains(&b), rule)?
        };
        Ok(Self::TeGap { gap, blend })
    }

    /// `--flap X:Y[:DEG]`: the hinge inside the chord (0 < X < 1), |Y| ≤ [`MAX_HINGE_Y`],
    /// |DEG| < [`MAX_FLAP_DEG`] (default 0, for a sweep set by `--flap-deg`).
    pub fn flap(text: &str) -> Result<Self, ArgumentError> {
        let parts: Vec<&str> = text.split(':').collect();
        if !(2..=3).contains(&parts.len()) {
            return Err(ArgumentError::with_text(
                "--flap",
                text,
                "expected X:Y:DEG (hinge x/c, y/c, deflection in degrees, + down)",
            ));
        }
        let rule = "the hinge must be inside the chord, 0 < x/c < 1";
        let hinge_x = number("--flap", parts[0], |x| x > 0.0 && x < 1.0, rule)?;
        let rule = "the hinge y/c must be in [-0.5, 0.5]";
        let hinge_y = number("--flap", parts[1], |y| y.abs() <= MAX_HINGE_Y, rule)?;
        let deflection_deg = match parts.get(2) {
            Some(d) => flap_deflection(d)?,
            None => 0.0,
        };
        Ok(Self::Flap {
            hinge_x,
            hinge_y,
            deflection_deg,
        })
    }

    /// `--blend OTHER:F`: F in [0, 1] (split at the last `:`, so OTHER may hold one).
    pub fn blend(text: &str) -> Result<Self, ArgumentError> {
        let (other, f) = text.rsplit_once(':').ok_or_else(|| {
            ArgumentError::with_text("--blend", text, "expected OTHER:F (airfoil, fraction)")
        })?;
        if other.trim().is_empty() {
            return Err(ArgumentError::with_text(
                "--blend",
                text,
                "no airfoil given",
            ));
        }
        let rule = "the blend fraction must be in [0, 1]";
        let fraction = number("--blend", f, |f| (0.0..=1.0).contains(&f), rule)?;
        Ok(Self::Blend {
            other: other.trim().to_string(),
            fraction,
        })
    }

    /// The flap deflection \[deg\] of a flap operation.
    pub fn flap_deg(&self) -> Option<f64> {
        match self {
            Self::Flap { deflection_deg, .. } => Some(*deflection_deg),
            _ => None,
        }
    }
}

/// One flap deflection \[deg\] of `--flap` or `--flap-deg`: |DEG| < [`MAX_FLAP_DEG`].
pub fn flap_deflection(text: &str) -> Result<f64, ArgumentError> {
    let rule = "the flap deflection must be in (-90, 90) degrees";
    number("--flap", text, |d| d.abs() < MAX_FLAP_DEG, rule)
}

/// The flap deflection of `ops` \[deg\] (of the last flap operation), if any: the
/// parameter of a flap sweep (OpenFAST AeroDyn's `UserProp`).
pub fn flap_deg(ops: &[ShapeOp]) -> Option<f64> {
    ops.iter().rev().find_map(ShapeOp::flap_deg)
}

/// `ops` with the deflection of every flap operation set to `deg` (one member of a flap
/// sweep).
pub fn with_flap_deflection(ops: &[ShapeOp], deg: f64) -> Vec<ShapeOp> {
    ops.iter()
        .map(|op| match op {
            ShapeOp::Flap {
                hinge_x, hinge_y, ..
            } => ShapeOp::Flap {
                hinge_x: *hinge_x,
                hinge_y: *hinge_y,
                deflection_deg: deg,
            },
            other => other.clone(),
        })
        .collect()
}

/// `foil` with `ops` applied in order (consecutive thickness and camber operations in one
/// `TSET`, as XFOIL does both at once), the partner of a blend loaded by `load`; the name
/// then says what was done (`NACA 2412 (thickness 0.15; flap 0.75:0:10)`). The result is
/// checked like a coordinate file.
pub fn apply_shape_ops(
    foil: &Airfoil,
    ops: &[ShapeOp],
    load: &dyn Fn(&str) -> Result<Airfoil, GeometryError>,
) -> Result<Airfoil, GeometryError> {
    if ops.is_empty() {
        return Ok(foil.clone());
    }
    let mut out = foil.clone();
    let mut k = 0;
    while k < ops.len() {
        out = match &ops[k] {
            ShapeOp::Thickness { thickness } => {
                let camber = match ops.get(k + 1) {
                    Some(ShapeOp::Camber { camber }) => {
                        k += 1;
                        Some(*camber)
                    }
                    _ => None,
                };
                out.with_thickness_camber(Some(*thickness), camber)?
            }
            ShapeOp::Camber { camber } => out.with_thickness_camber(None, Some(*camber))?,
            ShapeOp::TeGap { gap, blend } => out.with_te_gap(*gap, *blend)?,
            ShapeOp::Flap {
                hinge_x,
                hinge_y,
                deflection_deg,
            } => out.with_flap(*hinge_x, *hinge_y, *deflection_deg)?,
            ShapeOp::Blend { other, fraction } => out.blended(&load(other)?, *fraction)?,
        };
        k += 1;
    }
    out.name = format!("{} ({})", foil.name, shape_ops_text(ops));
    out.validate()?;
    Ok(out)
}

/// The error of operation `op` on `foil`.
pub(crate) fn op_error(foil: &Airfoil, op: &'static str, reason: &str) -> GeometryError {
    GeometryError::Operation {
        op,
        airfoil: foil.name.clone(),
        reason: reason.to_string(),
    }
}

/// Arc parameter in [`lo`, `hi`] where the contour's x equals `target`: the sign change of
/// x − target nearest `lo` among the nodes, refined by Newton steps kept inside the bracket
/// (bisection where a step leaves it); the node nearest in x when x never crosses `target`
/// there (a station just outside the surface's x range). `None` only for an empty range.
pub(crate) fn invert_x(sp: &ContourSpline, target: f64, lo: f64, hi: f64) -> Option<f64> {
    if hi <= lo || hi.is_nan() || lo.is_nan() {
        return None;
    }
    let f = |s: f64| sp.x.eval(s) - target;
    let mut knots: Vec<f64> = vec![lo];
    knots.extend(sp.s().iter().copied().filter(|&s| s > lo && s < hi));
    knots.push(hi);
    let Some(w) = knots.windows(2).find(|w| f(w[0]) * f(w[1]) <= 0.0) else {
        return knots
            .into_iter()
            .min_by(|a, b| f(*a).abs().total_cmp(&f(*b).abs()));
    };
    let (mut a, mut b) = (w[0], w[1]);
    let (fa, _) = (f(a), f(b));
    if fa == 0.0 {
        return Some(a);
    }
    let mut s = 0.5 * (a + b);
    for _ in 0..100 {
        let fs = f(s);
        if fs == 0.0 {
            return Some(s);
        }
        if (fs < 0.0) == (fa < 0.0) {
            a = s;
        } else {
            b = s;
        }
        let d = sp.x.deriv(s);
        let newton = s - fs / d;
        let next = if d != 0.0 && newton > a && newton < b {
            newton
        } else {
            0.5 * (a + b)
        };
        if (next - s).abs() < 1e-14 * sp.length() {
            return Some(next);
        }
        s = next;
    }
    Some(s)
}
