//! Thickness and camber lines: measured, scaled and recombined (XFOIL GDES `TSET`).
//!
//! * Measuring (XFOIL `GETCAM`, `GETMAX`): each contour point is paired with the point on the
//!   other surface at the same position along the chord line from the leftmost point to the
//!   trailing-edge midpoint (`SOPPS`); the pair's midpoint is a camber-line point, half its
//!   y distance a half-thickness point. The lines are sorted in x, the camber line is shifted
//!   so that it starts at y = 0, and each maximum is the stationary point of a cubic spline
//!   y(x) through the line (Newton on y′ = 0).
//! * Scaling (XFOIL `THKCAM`): in axes along and across the chord line from the leading-edge
//!   point (`LEFIND`) to the trailing-edge midpoint, each point and its opposite point are
//!   split into their mean (camber) and half difference (thickness); the cross-chord parts
//!   are multiplied by the camber and thickness factors and the two recombined.
//!
//! The new maximum thickness and camber are set by the factors t_new / t and c_new / c of the
//!   measured maxima (XFOIL `TCSET`).

use super::super::spline::{ContourSpline, CubicSpline};
use super::super::{Airfoil, GeometryError};
use super::op_error;

/// Newton iterations of the point searches.
const MAX_NEWTON: usize = 50;

/// Relative tolerance of the point searches (fraction of the contour length).
const NEWTON_TOLERANCE: f64 = 1e-12;

/// Tolerance, as a fraction of the contour length, within which two points of a thickness or
/// camber line count as one (XFOIL `GETCAM`: 10⁻⁵).
const DUPLICATE_TOLERANCE: f64 = 1e-5;

/// Camber below which a section counts as symmetric (no camber line to scale).
pub(crate) const MIN_CAMBER: f64 = 1e-6;

/// The maximum of a thickness or camber line and where it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineMaximum {
    /// The maximum (thickness: the full thickness; camber: signed, the largest |camber|).
    pub value: f64,
    /// Its chordwise position x.
    pub x: f64,
}

/// Maximum thickness and camber of a section as XFOIL's GDES measures them (`TCBUF`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThicknessCamber {
    /// Maximum thickness, measured in y between points at the same chordwise position.
    pub thickness: LineMaximum,
    /// Maximum camber (signed) of the mean line, measured from its leading end.
    pub camber: LineMaximum,
}

impl std::fmt::Display for ThicknessCamber {
    /// `thickness 0.12000 at x 0.2997, camber 0.02000 at x 0.4000`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (t, c) = (self.thickness, self.camber);
        write!(
            f,
            "thickness {:.5} at x {:.4}, camber {:.5} at x {:.4}",
            t.value, t.x, c.value, c.x
        )
    }
}

/// Arc parameter of the leftmost point, where dx/ds = 0 (XFOIL `XLFIND`): Newton from the
/// first node after which x grows, the step limited to 1 % of the contour length.
fn leftmost(sp: &ContourSpline) -> f64 {
    let s = sp.s();
    let x = sp.x.values();
    let n = s.len();
    let mut i = 2;
    while i < n - 2 && x[i + 1] - x[i] <= 0.0 {
        i += 1;
    }
    let guess = s[i];
    let limit = 0.01 * sp.length();
    let mut sl = guess;
    for _ in 0..MAX_NEWTON {
        let d2 = sp.x.deriv2(sl);
        if d2 == 0.0 || !d2.is_finite() {
            return guess;
        }
        let step = (-sp.x.deriv(sl) / d2).clamp(-limit, limit);
        sl += step;
        if step.abs() < NEWTON_TOLERANCE * sp.length() {
            return sl;
        }
    }
    guess
}

/// Unit vector from `(x0, y0)` to `(x1, y1)`.
fn unit(x0: f64, y0: f64, x1: f64, y1: f64) -> (f64, f64) {
    let l = (x1 - x0).hypot(y1 - y0);
    ((x1 - x0) / l, (y1 - y0) / l)
}

/// Arc parameter of the point opposite to `si` on the other surface: the point at the same
/// position along the chord line from the point at `sle` to the trailing-edge midpoint (XFOIL
/// `SOPPS`), from the guess at the same fraction of the other surface's arc length.
pub(crate) fn opposite(sp: &ContourSpline, si: f64, sle: f64) -> f64 {
    let s = sp.s();
    let n = s.len();
    let (xle, yle) = sp.point(sle);
    let (xte, yte) = sp.te_midpoint();
    let (dxc, dyc) = unit(xle, yle, xte, yte);
    let (own_end, other_end) = if si < sle {
        (s[0], s[n - 1])
    } else {
        (s[n - 1], s[0])
    };
    let frac = (si - sle) / (own_end - sle);
    let guess = sle + frac * (other_end - sle);
    if frac.abs() <= 1e-5 {
        return sle;
    }
    let along = |ss: f64| {
        let (x, y) = sp.point(ss);
        (x - xle) * dxc + (y - yle) * dyc
    };
    let target = along(si);
    let mut so = guess;
    for _ in 0..MAX_NEWTON {
        let (dx, dy) = sp.tangent(so);
        let slope = dx * dxc + dy * dyc;
        if slope == 0.0 || !slope.is_finite() {
            return guess;
        }
        let step = -(along(so) - target) / slope;
        so += step;
        if step.abs() < NEWTON_TOLERANCE * sp.length() {
            return so;
        }
    }
    guess
}

/// Points `(x, w)` sorted in x, with any point within `tol` of its predecessor dropped (XFOIL
/// `SORTOL`), and exact x repeats dropped so that the line can be splined in x.
fn sorted_line(mut pts: Vec<(f64, f64)>, tol: f64) -> Vec<(f64, f64)> {
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(pts.len());
    for p in pts {
        match out.last() {
            Some(q) if (p.0 - q.0).hypot(p.1 - q.1) < tol || p.0 == q.0 => {}
            _ => out.push(p),
        }
    }
    out
}

/// The maximum of |w| along a line `(x, w)` (XFOIL `GETMAX`): the stationary point of the
/// cubic spline w(x) near the largest |w| of the points, by Newton, each step limited to half
/// the neighbouring interval; the largest point itself when Newton does not settle.
fn line_maximum(line: &[(f64, f64)]) -> Result<LineMaximum, GeometryError> {
    let xs: Vec<f64> = line.iter().map(|p| p.0).collect();
    let ws: Vec<f64> = line.iter().map(|p| p.1).collect();
    let n = xs.len();
    let spline = CubicSpline::xfoil_default(&xs, &ws)?;
    let xlen = xs[n - 1] - xs[0];
    let (mut best, mut start, mut half_step) = (0usize, xs[0], 0.0);
    for i in 1..n {
        if ws[i].abs() > ws[best].abs() {
            best = i;
            start = 0.5 * (xs[i - 1] + xs[i]);
            half_step = 0.25 * (xs[(i + 1).min(n - 1)] - xs[i - 1]).abs();
        }
    }
    let fallback = LineMaximum {
        value: ws[best],
        x: start,
    };
    let mut x = start;
    for _ in 0..MAX_NEWTON {
        let curvature = spline.deriv2(x);
        if (xlen * curvature).abs() < 1e-6 {
            return Ok(LineMaximum {
                value: spline.eval(x),
                x,
            });
        }
        let step = (-spline.deriv(x) / curvature).clamp(-half_step, half_step);
        x += step;
        if step.abs() < NEWTON_TOLERANCE * xlen {
            return Ok(LineMaximum {
                value: spline.eval(x),
                x,
            });
        }
    }
    Ok(fallback)
}

/// The camber and half-thickness lines of a contour (XFOIL `GETCAM`), each sorted in x.
#[allow(clippy::type_complexity)]
fn lines(sp: &ContourSpline) -> (Vec<(f64, f64)>, Vec<(f64, f64)>) {
    let sl = leftmost(sp);
    let (xl, yl) = sp.point(sl);
    let mut camber = Vec::with_capacity(sp.s().len() + 1);
    let mut half = Vec::with_capacity(sp.s().len() + 1);
    for &si in sp.s() {
        let (x, y) = sp.point(si);
        let (xo, yo) = sp.point(opposite(sp, si, sl));
        camber.push((0.5 * (x + xo), 0.5 * (y + yo)));
        half.push((0.5 * (x + xo), 0.5 * (y - yo).abs()));
    }
    camber.push((xl, yl));
    half.push((xl, 0.0));
    let tol = DUPLICATE_TOLERANCE * sp.length();
    let mut camber = sorted_line(camber, tol);
    let y0 = camber[0].1;
    camber.iter_mut().for_each(|p| p.1 -= y0);
    (camber, sorted_line(half, tol))
}

impl Airfoil {
    /// Maximum thickness and camber and their chordwise positions, measured as XFOIL's GDES
    /// does (`TCBUF`; see the module documentation).
    pub fn thickness_camber(&self) -> Result<ThicknessCamber, GeometryError> {
        let sp = self.spline()?;
        let (camber, half) = lines(&sp);
        let t = line_maximum(&half)?;
        Ok(ThicknessCamber {
            thickness: LineMaximum {
                value: 2.0 * t.value,
                x: t.x,
            },
            camber: line_maximum(&camber)?,
        })
    }

    /// The section with maximum thickness `thickness` and maximum camber `camber` (each kept
    /// when `None`), as XFOIL's GDES `TSET`: the thickness and camber lines are scaled by the
    /// ratios of the new to the measured maxima and recombined (a negative camber factor
    /// mirrors the camber line). A camber is only scaled, never created: setting a non-zero
    /// camber on a symmetric section is an error.
    pub fn with_thickness_camber(
        &self,
        thickness: Option<f64>,
        camber: Option<f64>,
    ) -> Result<Airfoil, GeometryError> {
        let measured = self.thickness_camber()?;
        let t_factor = thickness.map_or(1.0, |t| t / measured.thickness.value);
        let c_factor = match camber {
            None => 1.0,
            Some(0.0) => 0.0,
            Some(c) => {
                if measured.camber.value.abs() < MIN_CAMBER {
                    return Err(op_error(
                        self,
                        "camber",
                        "the section has no camber line to scale (TSET scales camber, it \
                         cannot create it)",
                    ));
                }
                c / measured.camber.value
            }
        };
        self.scaled_thickness_camber(t_factor, c_factor)
    }

    /// The section with its thickness line scaled by `t_factor` and its camber line by
    /// `c_factor` about the chord line (XFOIL `THKCAM`).
    fn scaled_thickness_camber(
        &self,
        t_factor: f64,
        c_factor: f64,
    ) -> Result<Airfoil, GeometryError> {
        let sp = self.spline()?;
        let sle = sp.leading_edge()?;
        let (xle, yle) = sp.point(sle);
        let (xte, yte) = sp.te_midpoint();
        let (dxc, dyc) = unit(xle, yle, xte, yte);
        let (x, y) = sp
            .s()
            .iter()
            .map(|&si| {
                let (xi, yi) = sp.point(si);
                let (xo, yo) = sp.point(opposite(&sp, si, sle));
                let (mx, my) = (0.5 * (xi + xo), 0.5 * (yi + yo));
                let (hx, hy) = (0.5 * (xi - xo), 0.5 * (yi - yo));
                // Along and across the chord direction (about the origin, as XFOIL).
                let along = (mx * dxc + my * dyc) + (hx * dxc + hy * dyc);
                let across = c_factor * (my * dxc - mx * dyc) + t_factor * (hy * dxc - hx * dyc);
                (along * dxc - across * dyc, across * dxc + along * dyc)
            })
            .unzip();
        Ok(Airfoil {
            name: self.name.clone(),
            x,
            y,
        })
    }
}
