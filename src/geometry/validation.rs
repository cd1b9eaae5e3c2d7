//! Contour validation: what a list of points must satisfy to be an airfoil the panel method
//! can solve. Every check is O(n) or O(n log n), so a file at the point limit is checked in
//! milliseconds:
//!
//! * size: at least [`MIN_POINTS`], at most [`MAX_CONTOUR_POINTS`]; coordinates finite and
//!   within ±[`MAX_COORDINATE`]; an extent of at least [`MIN_CONTOUR_EXTENT`];
//! * no point equal to the one before it, and no point repeated anywhere else on the contour
//!   (a contour listed twice, a surface folded back onto itself); the last point may repeat
//!   the first (a closed trailing edge);
//! * no two segments crossing (a plane sweep over the segments, Shamos & Hoey 1976);
//! * one pass around the section: the direction of the contour turns through about 180° from
//!   its first to its last segment (upper TE forward, around the LE, lower surface aft), at
//!   most [`MAX_TURNING_DEG`] (a contour listed twice turns 540°);
//! * no spike: no vertex but the leading edge turns by more than [`SPIKE_TURN_DEG`] (folds
//!   the contour back), none turns by more than [`MAX_REVERSE_TURN_DEG`] against the sense of
//!   the contour (a stray point turns its two neighbours back by about its own angle), and all
//!   together not more than [`MAX_REVERSE_TURNING_DEG`] (concave stretches of real sections
//!   add tens of degrees in small steps; a sawtooth adds its teeth). Each turn is judged
//!   beyond what the rounding of the coordinates to their printed precision can make of it
//!   ([`printed_precision`]): a contour exported with many points and few decimals is a
//!   staircase whose vertices turn back and forth by degrees;
//! * thickness: the enclosed area is at least [`MIN_AREA_RATIO`] of the chord squared.
//!
//! Errors name the file (or airfoil) and the line (or point number) concerned.

use super::error::{GeometryError, Place};
use crate::limits::{MAX_CONTOUR_POINTS, MAX_COORDINATE, MIN_CONTOUR_EXTENT};

/// Minimum number of contour points accepted from a file.
pub const MIN_POINTS: usize = 10;

/// Largest total turning (degrees) of the contour from its first to its last segment: one
/// pass around a section turns 180° plus the trailing-edge wedge angle (measured over every
/// NACA 4- and 5-digit section: at most 278°, the NACA 0099), a section with a round trailing
/// edge listed from a point on it about 360°; a contour listed twice turns 540° or more.
pub const MAX_TURNING_DEG: f64 = 450.0;

/// A vertex turning by more than this (degrees) folds the contour back on itself: allowed at
/// the leading edge (the point farthest from the trailing edge), a spike anywhere else.
pub const SPIKE_TURN_DEG: f64 = 150.0;

/// Largest turn (degrees) of one vertex against the sense of the contour: a stray point turns
/// its two neighbours back by about its own angle. Measured over every NACA 4- and 5-digit
/// section (as generated and repaneled to 160 and 1000 nodes) and the test airfoils: at most
/// 11° (the leading edge of the NACA 91002 at 1000 nodes).
pub const MAX_REVERSE_TURN_DEG: f64 = 45.0;

/// Largest total turning (degrees) against the sense of the contour (concave stretches,
/// round-off wiggles): measured at most 92° over the same sections (NACA 91002 at 1000 nodes),
/// typically below 30°.
pub const MAX_REVERSE_TURNING_DEG: f64 = 150.0;

/// Smallest enclosed area as a fraction of the chord squared: a NACA 00xx section encloses
/// 0.685·t/c, so this refuses sections thinner than about 0.015 % of the chord (a flat line
/// traced out and back).
pub const MIN_AREA_RATIO: f64 = 1e-4;

/// The precision the coordinates were printed with: the largest power of ten 10⁻ᵈ of which at
/// least nine in ten coordinates are whole multiples (1e-4 for a file with 4 decimals, 1 for
/// whole millimetres); the round-off of a double for coordinates printed in full. Each point
/// then lies within half of it of the point meant, in x and in y.
pub(crate) fn printed_precision(x: &[f64], y: &[f64]) -> f64 {
    // Decimals of each coordinate: the fewest with which it is a whole number of 10⁻ᵈ, up to
    // the 17 significant digits a double holds.
    let decimals = |v: f64| -> i32 {
        (0..=MAX_DECIMALS)
            .find(|&d| {
                let scaled = v * 10f64.powi(d);
                (scaled - scaled.round()).abs() <= 8.0 * f64::EPSILON * scaled.abs().max(1.0)
            })
            .unwrap_or(MAX_DECIMALS)
    };
    let mut d: Vec<i32> = x.iter().chain(y).map(|&v| decimals(v)).collect();
    d.sort_unstable();
    let k = (d.len() * 9).div_ceil(10).saturating_sub(1);
    d.get(k).map_or(0.0, |&d| 10f64.powi(-d))
}

/// Most decimals [`printed_precision`] looks for: a double's 17 significant digits of a
/// coordinate near 1.
const MAX_DECIMALS: i32 = 17;

/// Checks a contour (see the module documentation). `line_of[i]` is the number reported for
/// point i, a file line or a point number as `place` says; `file` names the source.
pub(crate) fn validate_contour(
    x: &[f64],
    y: &[f64],
    line_of: &[usize],
    place: Place,
    file: &str,
) -> Result<(), GeometryError> {
    let n = x.len();
    if n < MIN_POINTS {
        return Err(GeometryError::TooFewPoints {
            file: file.to_string(),
            found: n,
            min: MIN_POINTS,
        });
    }
    if n > MAX_CONTOUR_POINTS {
        return Err(GeometryError::TooManyPoints {
            file: file.to_string(),
            found: n,
            max: MAX_CONTOUR_POINTS,
        });
    }
    for i in 0..n {
        if !(x[i].is_finite() && y[i].is_finite()) {
            return Err(GeometryError::NonFinite {
                file: file.to_string(),
                line: line_of[i],
                place,
                token: format!("({}, {})", x[i], y[i]),
            });
        }
        if x[i].abs().max(y[i].abs()) > MAX_COORDINATE {
            return Err(GeometryError::CoordinateTooLarge {
                file: file.to_string(),
                line: line_of[i],
                place,
                value: if x[i].abs() > y[i].abs() { x[i] } else { y[i] },
                limit: MAX_COORDINATE,
            });
        }
    }
    let span = |v: &[f64]| {
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &c| {
                (a.min(c), b.max(c))
            });
        hi - lo
    };
    let extent = span(x).max(span(y));
    if extent == 0.0 {
        return Err(GeometryError::SinglePoint {
            file: file.to_string(),
            count: n,
            x: x[0],
            y: y[0],
        });
    }
    if extent < MIN_CONTOUR_EXTENT {
        return Err(GeometryError::TooSmall {
            file: file.to_string(),
            extent,
            limit: MIN_CONTOUR_EXTENT,
        });
    }
    let scale = x
        .iter()
        .chain(y.iter())
        .fold(0.0f64, |m, v| m.max(v.abs()))
        .max(f64::MIN_POSITIVE);
    for i in 1..n {
        if (x[i] - x[i - 1]).hypot(y[i] - y[i - 1]) <= 1e-12 * scale {
            return Err(GeometryError::DuplicatePoint {
                file: file.to_string(),
                line: line_of[i],
                place,
                x: x[i],
                y: y[i],
            });
        }
    }
    // A closed TE (end points equal up to round-off) makes the first and last segments
    // neighbours, which must not count as a crossing, and lets the last point repeat the first.
    let closed = (x[0] - x[n - 1]).hypot(y[0] - y[n - 1]) <= 1e-9 * scale;
    if let Some((first, again)) = repeated_point(x, y, closed) {
        return Err(GeometryError::RepeatedPoint {
            file: file.to_string(),
            line: line_of[again],
            first_line: line_of[first],
            place,
            x: x[again],
            y: y[again],
        });
    }
    if let Some((i, j, px, py)) = first_crossing(x, y, closed) {
        return Err(GeometryError::SelfIntersecting {
            file: file.to_string(),
            line_a: line_of[i],
            line_b: line_of[j],
            place,
            x: px,
            y: py,
        });
    }
    check_turning(x, y, line_of, place, file)?;
    let gap = (x[0] - x[n - 1]).hypot(y[0] - y[n - 1]);
    if gap > MAX_TE_GAP_RATIO * extent {
        return Err(GeometryError::OpenContour {
            file: file.to_string(),
            ratio: gap / extent,
        });
    }
    let chord = span(x);
    let area = signed_area(x, y).abs();
    if area < MIN_AREA_RATIO * chord * chord {
        return Err(GeometryError::ZeroThickness {
            file: file.to_string(),
            ratio: area / (chord * chord),
        });
    }
    Ok(())
}

/// Largest trailing-edge gap (distance of the end points) as a fraction of the contour's
/// extent: 0.3. Flatback wind-turbine sections reach 0.175 (Sandia FB-3500-1750, Berg &
/// Zayas 2008); a larger gap is a contour cut short (a surface missing), whose panel
/// solution is meaningless (a truncated NACA 2412 gave Cl 12 at 6°).
pub const MAX_TE_GAP_RATIO: f64 = 0.3;

/// Signed area enclosed by the contour closed through its end points (positive for
/// counter-clockwise, i.e. XFOIL order), as in XFOIL `LOAD`.
pub(crate) fn signed_area(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len();
    let mut area = 0.0;
    for i in 0..n {
        let j = (i + 1) % n;
        area += 0.5 * (y[i] + y[j]) * (x[i] - x[j]);
    }
    area
}

/// The turning angle (radians, counter-clockwise positive) at each interior vertex 1..n−1.
fn vertex_turns<'a>(x: &'a [f64], y: &'a [f64]) -> impl Iterator<Item = f64> + 'a {
    (1..x.len() - 1).map(move |i| {
        let (ax, ay) = (x[i] - x[i - 1], y[i] - y[i - 1]);
        let (bx, by) = (x[i + 1] - x[i], y[i + 1] - y[i]);
        (ax * by - ay * bx).atan2(ax * bx + ay * by)
    })
}

/// One turn around the section, no spike, no sawtooth (see the module documentation).
fn check_turning(
    x: &[f64],
    y: &[f64],
    line_of: &[usize],
    place: Place,
    file: &str,
) -> Result<(), GeometryError> {
    let net: f64 = vertex_turns(x, y).sum::<f64>().to_degrees();
    if net.abs() > MAX_TURNING_DEG {
        return Err(GeometryError::Turning {
            file: file.to_string(),
            degrees: net,
        });
    }
    let sense = net.signum();
    let n = x.len();
    let (xt, yt) = (0.5 * (x[0] + x[n - 1]), 0.5 * (y[0] + y[n - 1]));
    let le = (0..n)
        .max_by(|&a, &b| {
            (x[a] - xt)
                .hypot(y[a] - yt)
                .total_cmp(&(x[b] - xt).hypot(y[b] - yt))
        })
        .unwrap_or(0);
    // A segment whose end points each lie within `position_error` of where they were meant
    // points within asin(2e/length) of its meant direction.
    let position_error = printed_precision(x, y) / std::f64::consts::SQRT_2;
    let segment_slack = |i: usize| {
        let length = (x[i + 1] - x[i]).hypot(y[i + 1] - y[i]);
        (2.0 * position_error / length).min(1.0).asin().to_degrees()
    };
    // turns[k] is the turn at vertex k + 1, and slack[k] what rounding can add to it.
    let turns: Vec<f64> = vertex_turns(x, y).map(f64::to_degrees).collect();
    let slack: Vec<f64> = (1..n - 1)
        .map(|i| segment_slack(i - 1) + segment_slack(i))
        .collect();
    let turn_at = |i: usize| {
        if i >= 1 && i < n - 1 {
            turns[i - 1]
        } else {
            0.0
        }
    };
    let spike = |i: usize| {
        // The stray point is the sharpest of the vertex and its neighbours.
        let tip = (i.saturating_sub(1)..=i + 1)
            .max_by(|&a, &b| turn_at(a).abs().total_cmp(&turn_at(b).abs()))
            .unwrap_or(i);
        GeometryError::Spike {
            file: file.to_string(),
            line: line_of[tip],
            place,
            x: x[tip],
            y: y[tip],
            degrees: turn_at(tip).abs(),
        }
    };
    let mut reverse_total = 0.0;
    let mut reversals = 0;
    let mut first_reversal = None;
    for (k, (&deg, &slack)) in turns.iter().zip(&slack).enumerate() {
        let i = k + 1;
        let reverse = (-sense * deg - slack).max(0.0);
        if (deg.abs() - slack > SPIKE_TURN_DEG && i != le) || reverse > MAX_REVERSE_TURN_DEG {
            return Err(spike(i));
        }
        if reverse > 0.0 {
            reverse_total += reverse;
            reversals += 1;
            first_reversal.get_or_insert(i);
        }
        if reverse_total > MAX_REVERSE_TURNING_DEG {
            let from = first_reversal.unwrap_or(i);
            return Err(GeometryError::Zigzag {
                file: file.to_string(),
                line: line_of[from],
                last_line: line_of[i],
                place,
                reversals,
                degrees: reverse_total,
                limit: MAX_REVERSE_TURNING_DEG,
            });
        }
    }
    Ok(())
}

/// The first pair (earlier, later) of non-consecutive points with identical coordinates, the
/// last point repeating the first of a `closed` contour excepted (sort, O(n log n)).
fn repeated_point(x: &[f64], y: &[f64], closed: bool) -> Option<(usize, usize)> {
    let n = x.len();
    let count = if closed { n - 1 } else { n };
    let mut order: Vec<usize> = (0..count).collect();
    order.sort_by(|&a, &b| x[a].total_cmp(&x[b]).then(y[a].total_cmp(&y[b])));
    order
        .windows(2)
        .filter(|w| x[w[0]] == x[w[1]] && y[w[0]] == y[w[1]])
        .map(|w| (w[0].min(w[1]), w[0].max(w[1])))
        .min_by_key(|p| p.1)
}

/// Whether segments (i, i+1) and (j, j+1) cross properly (each one's end points strictly on
/// opposite sides of the other), with the crossing point.
fn proper_crossing(x: &[f64], y: &[f64], i: usize, j: usize) -> Option<(f64, f64)> {
    let orient = |a: usize, b: usize, c: usize| -> f64 {
        (x[b] - x[a]) * (y[c] - y[a]) - (y[b] - y[a]) * (x[c] - x[a])
    };
    let d1 = orient(i, i + 1, j);
    let d2 = orient(i, i + 1, j + 1);
    let d3 = orient(j, j + 1, i);
    let d4 = orient(j, j + 1, i + 1);
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        let t = d1 / (d1 - d2);
        Some((x[j] + t * (x[j + 1] - x[j]), y[j] + t * (y[j + 1] - y[j])))
    } else {
        None
    }
}

/// A pair of non-adjacent polyline segments (i, i+1), (j, j+1), i < j, that cross properly,
/// with the crossing point; with `closed`, the first and last segments are adjacent.
///
/// A plane sweep (Shamos & Hoey 1976): segments enter at their left end and leave at their
/// right end; the segments under the sweep line are kept ordered by height, and only
/// neighbours in that order are tested. If any two segments cross, the two that cross
/// leftmost are neighbours just before the sweep reaches the crossing. O(n log n) for a
/// contour whose vertical lines cut it a bounded number of times (an airfoil: twice), at
/// worst O(n·k) for k segments cut by one vertical line.
pub(crate) fn first_crossing(
    x: &[f64],
    y: &[f64],
    closed: bool,
) -> Option<(usize, usize, f64, f64)> {
    let n = x.len();
    if n < 4 {
        return None;
    }
    let segments = n - 1;
    let adjacent = |a: usize, b: usize| {
        let (i, j) = (a.min(b), a.max(b));
        j == i + 1 || (closed && i == 0 && j == segments - 1)
    };
    let test = |a: usize, b: usize| -> Option<(usize, usize, f64, f64)> {
        if a == b || adjacent(a, b) {
            return None;
        }
        let (i, j) = (a.min(b), a.max(b));
        proper_crossing(x, y, i, j).map(|(px, py)| (i, j, px, py))
    };
    let before = |a: usize, b: usize| (x[a], y[a]) < (x[b], y[b]);
    // (left, right) end point of each segment, lexicographic by (x, y).
    let ends: Vec<(usize, usize)> = (0..segments)
        .map(|s| {
            if before(s + 1, s) {
                (s + 1, s)
            } else {
                (s, s + 1)
            }
        })
        .collect();
    // Events: (point, 0 = enter / 1 = leave, segment); at one x every entry comes first, so
    // that segments meeting at that x are under the sweep together.
    let mut events: Vec<(usize, u8, usize)> = Vec::with_capacity(2 * segments);
    for (s, &(l, r)) in ends.iter().enumerate() {
        events.push((l, 0, s));
        events.push((r, 1, s));
    }
    events.sort_by(|a, b| {
        x[a.0]
            .total_cmp(&x[b.0])
            .then(a.1.cmp(&b.1))
            .then(y[a.0].total_cmp(&y[b.0]))
    });
    // Height of segment s at the sweep position (sx, sy), and its slope for ties.
    let height = |s: usize, sx: f64, sy: f64| -> f64 {
        let (l, r) = ends[s];
        let dx = x[r] - x[l];
        if dx == 0.0 {
            sy.clamp(y[l], y[r])
        } else {
            let t = ((sx - x[l]) / dx).clamp(0.0, 1.0);
            y[l] + t * (y[r] - y[l])
        }
    };
    let slope = |s: usize| -> f64 {
        let (l, r) = ends[s];
        let dx = x[r] - x[l];
        if dx == 0.0 {
            f64::INFINITY
        } else {
            (y[r] - y[l]) / dx
        }
    };
    let mut active: Vec<usize> = Vec::new();
    for &(p, kind, s) in &events {
        let (sx, sy) = (x[p], y[p]);
        if kind == 0 {
            let (hs, ks) = (height(s, sx, sy), slope(s));
            let k = active.partition_point(|&a| {
                let ha = height(a, sx, sy);
                ha < hs || (ha == hs && slope(a) < ks)
            });
            active.insert(k, s);
            let below = k.checked_sub(1).map(|b| active[b]);
            let above = active.get(k + 1).copied();
            for other in below.into_iter().chain(above) {
                if let Some(hit) = test(s, other) {
                    return Some(hit);
                }
            }
        } else if let Some(k) = active.iter().position(|&a| a == s) {
            active.remove(k);
            if k > 0 && k < active.len() {
                if let Some(hit) = test(active[k - 1], active[k]) {
                    return Some(hit);
                }
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::test_random::Lcg;

    /// Every pair of segments tested (the reference the sweep must agree with).
    fn crossing_by_pairs(x: &[f64], y: &[f64], closed: bool) -> bool {
        let n = x.len();
        (0..n - 1).any(|i| {
            (i + 2..n - 1)
                .any(|j| !(closed && i == 0 && j == n - 2) && proper_crossing(x, y, i, j).is_some())
        })
    }

    #[test]
    fn the_sweep_finds_a_crossing_exactly_when_some_pair_crosses() {
        let mut r = Lcg::new(11);
        let mut crossing = 0;
        for k in 0..4000 {
            let n = 4 + (r.unit() * 14.0) as usize;
            // Points on a small lattice: many collinear, touching and vertical segments.
            let lattice = [3.0, 5.0, 9.0][k % 3];
            let (mut x, mut y) = (Vec::new(), Vec::new());
            for _ in 0..n {
                x.push((r.unit() * lattice).floor());
                y.push((r.unit() * lattice).floor());
            }
            if (1..n).any(|i| x[i] == x[i - 1] && y[i] == y[i - 1]) {
                continue; // refused before the sweep (zero-length segment)
            }
            let closed = x[0] == x[n - 1] && y[0] == y[n - 1];
            let expected = crossing_by_pairs(&x, &y, closed);
            let found = first_crossing(&x, &y, closed);
            assert_eq!(found.is_some(), expected, "contour {k}: {x:?} {y:?}");
            crossing += usize::from(expected);
        }
        assert!(crossing > 500 && crossing < 3900, "{crossing}");
    }

    #[test]
    fn a_large_contour_is_checked_quickly() {
        // An ellipse at the point limit; the pairwise test would need ~2·10⁸ segment pairs.
        let n = MAX_CONTOUR_POINTS;
        let t = |i: usize| 2.0 * std::f64::consts::PI * i as f64 / n as f64;
        let x: Vec<f64> = (0..n).map(|i| 0.5 + 0.5 * t(i).cos()).collect();
        let y: Vec<f64> = (0..n).map(|i| 0.06 * t(i).sin()).collect();
        let lines: Vec<usize> = (1..=n).collect();
        let start = std::time::Instant::now();
        validate_contour(&x, &y, &lines, Place::Line, "ellipse").unwrap();
        assert!(start.elapsed().as_secs_f64() < 0.5, "{:?}", start.elapsed());
    }
}
