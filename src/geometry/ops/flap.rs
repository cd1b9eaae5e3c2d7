//! Plain trailing-edge flap (XFOIL GDES `FLAP`, with `SSS`, `INSIDE` and `SCHECK`).
//!
//! The contour aft of the hinge turns about the hinge point by the deflection (positive
//! trailing edge down). On each surface the break is where the fixed part and the flap meet:
//! * on the side where the surface opens (upper surface for a downward flap with the hinge
//!   inside the section) the break is the foot of the perpendicular from the hinge to the
//!   surface; the gap that opens is closed by points on the circular arc the break point
//!   sweeps, spaced like the contour's mean point spacing (1.5 × the arc over the mean
//!   spacing, plus one);
//! * on the side where it closes, the stretch of surface that the flap swings into is removed:
//!   its ends are the two points whose lines to the hinge include the deflection angle and
//!   are equally long, so that they meet after the rotation. A corner point is put there, and
//!   the nearest point on either side is moved to (or a point added at) a third of the way to
//!   its neighbour, so that the corner is resolved.
//! * A hinge outside the contour opens or closes both surfaces alike: it is above the section
//!   (a downward flap opens both) or below (an upward flap opens both), judged against the
//!   chord between the two surface points at the hinge x.
//!
//! Finally segments shorter than 0.2 × a neighbouring one are merged (`SCHECK`).

use super::super::spline::ContourSpline;
use super::super::{Airfoil, GeometryError};
use super::{invert_x, op_error};

/// Convergence tolerance of the break-point Newton iteration, a fraction of the contour length
/// (XFOIL `SSS`: 10⁻⁵).
const BREAK_TOLERANCE: f64 = 1e-5;

/// Newton iterations for the break points.
const BREAK_ITERATIONS: usize = 50;

/// Fraction of the way from a break to the next point where the nearest point is put.
const CORNER_FRACTION: f64 = 0.33333;

/// Segments shorter than this fraction of a neighbouring segment are merged (XFOIL's
/// `FLAP` calls `SCHECK` with 0.2).
const SHORT_SEGMENT: f64 = 0.2;

/// Whether `(xf, yf)` lies inside the closed polygon (XFOIL `INSIDE`: the summed sines of the
/// angles each segment subtends, ≈ ±2π inside and ≈ 0 outside).
fn inside(x: &[f64], y: &[f64], xf: f64, yf: f64) -> bool {
    let n = x.len();
    let angle: f64 = (0..n)
        .map(|i| {
            let j = (i + 1) % n;
            let (ax, ay) = (x[i] - xf, y[i] - yf);
            let (bx, by) = (x[j] - xf, y[j] - yf);
            (ax * by - ay * bx) / ((ax * ax + ay * ay) * (bx * bx + by * by)).sqrt()
        })
        .sum();
    angle.abs() > 1.0
}

/// Rotation of `(x, y)` about `(xf, yf)` by `angle` clockwise (trailing edge down for a
/// positive angle).
fn rotate(x: f64, y: f64, xf: f64, yf: f64, angle: f64) -> (f64, f64) {
    let (sa, ca) = angle.sin_cos();
    let (dx, dy) = (x - xf, y - yf);
    (xf + dx * ca + dy * sa, yf - dx * sa + dy * ca)
}

/// The break points `(s1, s2)` near `ss` on one surface (XFOIL `SSS`): `s1` on the fixed
/// part, `s2` on the flap. For `angle` > 0 the lines from the hinge to both include `angle`
/// and are equally long (the surface between them disappears); for `angle` = 0 they coincide
/// where the line from the hinge is normal to the surface (where the surface opens).
fn break_points(
    sp: &ContourSpline,
    ss: f64,
    angle: f64,
    hinge: (f64, f64),
    upper: bool,
) -> Option<(f64, f64)> {
    let (xf, yf) = hinge;
    let total = sp.length();
    let eps = BREAK_TOLERANCE * total;
    let half = (0.5 * angle.abs()).sin();
    let sign = if upper { -1.0 } else { 1.0 };
    let (x0, y0) = sp.point(ss);
    let r0 = (x0 - xf).hypot(y0 - yf);
    let mut s1 = ss - (half * r0 + eps) * sign;
    let mut s2 = ss + (half * r0 + eps) * sign;
    for _ in 0..BREAK_ITERATIONS {
        let (x1, y1) = sp.point(s1);
        let (x1p, y1p) = sp.tangent(s1);
        let (x2, y2) = sp.point(s2);
        let (x2p, y2p) = sp.tangent(s2);
        let r1 = (x1 - xf).hypot(y1 - yf);
        let r2 = (x2 - xf).hypot(y2 - yf);
        if r1 <= eps || r2 <= eps {
            return Some((ss, ss));
        }
        let r1_s1 = (x1p * (x1 - xf) + y1p * (y1 - yf)) / r1;
        let r2_s2 = (x2p * (x2 - xf) + y2p * (y2 - yf)) / r2;
        let (res1, a11, a12, res2, a21, a22);
        if half > 0.01 {
            let rr_sq = (x1 - x2).powi(2) + (y1 - y2).powi(2);
            let rr = rr_sq.sqrt();
            if rr == 0.0 {
                return Some((s1, s2));
            }
            let rr_s1 = (x1p * (x1 - x2) + y1p * (y1 - y2)) / rr;
            let rr_s2 = -(x2p * (x1 - x2) + y2p * (y1 - y2)) / rr;
            // The included angle through the projection of the hinge line on the chord
            // between the points, and equal lengths.
            let dot = (xf - x1) * (x2 - x1) + (yf - y1) * (y2 - y1);
            res1 = dot / rr - half * r1;
            a11 = ((xf - x1) * -x1p + (yf - y1) * -y1p) / rr
                + (-x1p * (x2 - x1) - y1p * (y2 - y1)) / rr
                - dot * rr_s1 / rr_sq
                - half * r1_s1;
            a12 = ((xf - x1) * x2p + (yf - y1) * y2p) / rr - dot * rr_s2 / rr_sq;
            res2 = r1 - r2;
            a21 = r1_s1;
            a22 = -r2_s2;
        } else {
            // Small angle: the arc between the points, and their hinge lines' sum normal to
            // the surface.
            res1 = (r1 + r2) * half + (s1 - s2) * sign;
            a11 = r1_s1 * half + sign;
            a12 = r2_s2 * half - sign;
            let (x1pp, y1pp) = (sp.x.deriv2(s1), sp.y.deriv2(s1));
            let (x2pp, y2pp) = (sp.x.deriv2(s2), sp.y.deriv2(s2));
            let (xt, yt) = (x1 + x2 - 2.0 * xf, y1 + y2 - 2.0 * yf);
            res2 = xt * (x1p + x2p) + yt * (y1p + y2p);
            a21 = x1p * (x1p + x2p) + y1p * (y1p + y2p) + xt * x1pp + yt * y1pp;
            a22 = x2p * (x1p + x2p) + y2p * (y1p + y2p) + xt * x2pp + yt * y2pp;
        }
        let det = a11 * a22 - a12 * a21;
        let limit = 0.01 * total;
        let ds1 = (-(res1 * a22 - a12 * res2) / det).clamp(-limit, limit);
        let ds2 = (-(a11 * res2 - res1 * a21) / det).clamp(-limit, limit);
        if !(ds1.is_finite() && ds2.is_finite()) {
            return None;
        }
        s1 += ds1;
        s2 += ds2;
        if ds1.abs() + ds2.abs() < eps {
            if angle == 0.0 {
                let mid = 0.5 * (s1 + s2);
                return Some((mid, mid));
            }
            return Some((s1, s2));
        }
    }
    None
}

/// Merge segments shorter than `ratio` × a neighbouring segment into their midpoint (XFOIL
/// `SCHECK`), from the start again after each merge.
fn merge_short_segments(x: &mut Vec<f64>, y: &mut Vec<f64>, ratio: f64) {
    let len = |x: &[f64], y: &[f64], i: usize| (x[i + 1] - x[i]).hypot(y[i + 1] - y[i]);
    'restart: loop {
        let n = x.len();
        for i in 1..n.saturating_sub(2) {
            let (dm, dp, dp2) = (len(x, y, i - 1), len(x, y, i), len(x, y, i + 1));
            if dp == 0.0 {
                continue;
            }
            if dp < ratio * dm || dp < ratio * dp2 {
                x[i] = 0.5 * (x[i] + x[i + 1]);
                y[i] = 0.5 * (y[i] + y[i + 1]);
                x.remove(i + 1);
                y.remove(i + 1);
                continue 'restart;
            }
        }
        return;
    }
}

/// Indices of the contour nodes next to the breaks (1-based positions as XFOIL, stored
/// 0-based): the first fixed node past each break and the last flap node before it.
struct BreakNodes {
    top_fixed: usize,
    top_flap: usize,
    bottom_fixed: usize,
    bottom_flap: usize,
}

/// The nodes next to the breaks `st1`, `st2` (upper surface), `sb1`, `sb2` (lower surface).
fn break_nodes(s: &[f64], st1: f64, st2: f64, sb1: f64, sb2: f64) -> Option<BreakNodes> {
    let (mut t1, mut t2, mut b1, mut b2) = (None, None, None, None);
    for i in 0..s.len() - 1 {
        if s[i] <= st1 && s[i + 1] > st1 {
            t1 = Some(i + 1);
        }
        if s[i] < st2 && s[i + 1] >= st2 {
            t2 = Some(i);
        }
        if s[i] <= sb1 && s[i + 1] > sb1 {
            b1 = Some(i);
        }
        if s[i] < sb2 && s[i + 1] >= sb2 {
            b2 = Some(i + 1);
        }
    }
    Some(BreakNodes {
        top_fixed: t1?,
        top_flap: t2?,
        bottom_fixed: b1?,
        bottom_flap: b2?,
    })
}

/// Where the node next to a break goes when that surface closes: the point a third of the
/// way from the break `sb` to the node `s_near` (a new point), unless the node is nearer the
/// break than a third of the way to the node beyond it, `s_far`, where it is moved to
/// instead. Returns the point and whether it is new.
fn corner_neighbour(sp: &ContourSpline, sb: f64, s_near: f64, s_far: f64) -> ((f64, f64), bool) {
    let to_far = sb + CORNER_FRACTION * (s_far - sb);
    if (s_near - sb).abs() < (to_far - sb).abs() {
        (sp.point(to_far), false)
    } else {
        (sp.point(sb + CORNER_FRACTION * (s_near - sb)), true)
    }
}

impl Airfoil {
    /// The section with a plain flap deflected by `deflection_deg` (positive trailing edge
    /// down) about the hinge `(hinge_x, hinge_y)` in the section's coordinates (XFOIL GDES
    /// `FLAP`; see the module documentation). A zero deflection returns the section as it is.
    pub fn with_flap(
        &self,
        hinge_x: f64,
        hinge_y: f64,
        deflection_deg: f64,
    ) -> Result<Airfoil, GeometryError> {
        let deflection = deflection_deg.to_radians();
        if deflection == 0.0 {
            return Ok(self.clone());
        }
        let sp = self.spline()?;
        let s = sp.s();
        let n = s.len();
        let sle = sp.leading_edge()?;
        let fail = |reason: &str| op_error(self, "flap", reason);
        let no_surface = || fail("the hinge x is not over both surfaces of the section");
        let tops = invert_x(&sp, hinge_x, s[0], sle).ok_or_else(no_surface)?;
        let bots = invert_x(&sp, hinge_x, sle, s[n - 1]).ok_or_else(no_surface)?;
        let hinge = (hinge_x, hinge_y);
        let (a_top, a_bot) = if inside(&self.x, &self.y, hinge_x, hinge_y) {
            ((-deflection).max(0.0), deflection.max(0.0))
        } else {
            let (tx, ty) = sp.tangent(tops);
            let (bx, by) = sp.tangent(bots);
            let (chx, chy) = (bx - tx, by - ty);
            let (p_t, p_b) = (sp.point(tops), sp.point(bots));
            let (fvx, fvy) = (p_t.0 + p_b.0, p_t.1 + p_b.1);
            let above = chx * (hinge_y - 0.5 * fvy) - chy * (hinge_x - 0.5 * fvx) > 0.0;
            let a = if above { deflection } else { -deflection }.max(0.0);
            (a, a)
        };
        let no_break = || fail("the surface break points were not found (hinge too far out?)");
        let (st1, st2) = break_points(&sp, tops, a_top, hinge, true).ok_or_else(no_break)?;
        let (sb1, sb2) = break_points(&sp, bots, a_bot, hinge, false).ok_or_else(no_break)?;
        let nodes = break_nodes(s, st1, st2, sb1, sb2)
            .filter(|b| {
                b.top_flap < b.top_fixed
                    && b.top_fixed <= b.bottom_fixed
                    && b.bottom_fixed < b.bottom_flap
            })
            .ok_or_else(|| fail("the hinge is too close to the trailing edge"))?;
        let (mut it1, it2, mut ib1, mut ib2) = (
            nodes.top_fixed,
            nodes.top_flap,
            nodes.bottom_fixed,
            nodes.bottom_flap,
        );
        let mean_spacing = sp.length() / (n - 1) as f64;
        let top_corner = (a_top != 0.0).then(|| {
            (
                corner_neighbour(&sp, st1, s[it1], s[(it1 + 1).min(n - 1)]),
                corner_neighbour(&sp, st2, s[it2], s[it2.saturating_sub(1)]),
            )
        });
        let bottom_corner = (a_bot != 0.0).then(|| {
            (
                corner_neighbour(&sp, sb1, s[ib1], s[ib1.saturating_sub(1)]),
                corner_neighbour(&sp, sb2, s[ib2], s[(ib2 + 1).min(n - 1)]),
            )
        });
        let (t1, b1) = (sp.point(st1), sp.point(sb1));
        let turn = |(x, y): (f64, f64)| rotate(x, y, hinge_x, hinge_y, deflection);
        let (mut x, mut y): (Vec<f64>, Vec<f64>) = (0..n)
            .map(|i| {
                if (it1..=ib1).contains(&i) {
                    (self.x[i], self.y[i])
                } else {
                    turn((self.x[i], self.y[i]))
                }
            })
            .unzip();
        // The surface the flap swings into disappears.
        let gone = it1 - it2 - 1;
        x.drain(it2 + 1..it1);
        y.drain(it2 + 1..it1);
        (it1, ib1, ib2) = (it1 - gone, ib1 - gone, ib2 - gone);
        let gone = ib2 - ib1 - 1;
        x.drain(ib1 + 1..ib2);
        y.drain(ib1 + 1..ib2);
        ib2 -= gone;
        // Upper surface: the arc of a gap that opens, or the corner where it closes. The new
        // points go between the flap's last node (it1 − 1) and the first fixed node (it1),
        // listed from the trailing edge forward.
        let top_points: Vec<(f64, f64)> = match top_corner {
            None => arc(t1, hinge, deflection, mean_spacing)
                .into_iter()
                .rev()
                .collect(),
            Some(((fixed, fixed_new), (flap, flap_new))) => {
                let mut pts = Vec::new();
                if flap_new {
                    pts.push(turn(flap));
                } else {
                    let k = it1 - 1;
                    (x[k], y[k]) = turn(flap);
                }
                pts.push(t1);
                if fixed_new {
                    pts.push(fixed);
                } else {
                    (x[it1], y[it1]) = fixed;
                }
                pts
            }
        };
        let added = top_points.len();
        splice(&mut x, &mut y, it1, &top_points);
        (ib1, ib2) = (ib1 + added, ib2 + added);
        // Lower surface, listed from the leading edge back.
        let bottom_points: Vec<(f64, f64)> = match bottom_corner {
            None => arc(b1, hinge, deflection, mean_spacing),
            Some(((fixed, fixed_new), (flap, flap_new))) => {
                let mut pts = Vec::new();
                if fixed_new {
                    pts.push(fixed);
                } else {
                    (x[ib1], y[ib1]) = fixed;
                }
                pts.push(b1);
                if flap_new {
                    pts.push(turn(flap));
                } else {
                    (x[ib2], y[ib2]) = turn(flap);
                }
                pts
            }
        };
        splice(&mut x, &mut y, ib2, &bottom_points);
        merge_short_segments(&mut x, &mut y, SHORT_SEGMENT);
        drop_repeated_points(&mut x, &mut y);
        Ok(Airfoil {
            name: self.name.clone(),
            x,
            y,
        })
    }
}

/// Points on the arc that `from` sweeps about `hinge` while turning by `angle`, spaced about
/// `spacing` apart: ⌊1.5 · |angle| · r / spacing + 1⌋ points at the mid-angles of equal steps,
/// in the order of increasing turn.
fn arc(from: (f64, f64), hinge: (f64, f64), angle: f64, spacing: f64) -> Vec<(f64, f64)> {
    let r = (from.0 - hinge.0).hypot(from.1 - hinge.1);
    let count = (1.5 * angle.abs() * r / spacing + 1.0) as usize;
    let step = angle / count as f64;
    (1..=count)
        .map(|k| rotate(from.0, from.1, hinge.0, hinge.1, step * (k as f64 - 0.5)))
        .collect()
}

/// Insert `pts` before index `at`.
fn splice(x: &mut Vec<f64>, y: &mut Vec<f64>, at: usize, pts: &[(f64, f64)]) {
    x.splice(at..at, pts.iter().map(|p| p.0));
    y.splice(at..at, pts.iter().map(|p| p.1));
}

/// Remove points equal to their predecessor (XFOIL strips doubled points when the buffer
/// becomes the current airfoil, `ABCOPY`).
fn drop_repeated_points(x: &mut Vec<f64>, y: &mut Vec<f64>) {
    let mut k = 1;
    while k < x.len() {
        if x[k] == x[k - 1] && y[k] == y[k - 1] {
            x.remove(k);
            y.remove(k);
        } else {
            k += 1;
        }
    }
}
