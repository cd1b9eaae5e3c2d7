//! Arc-length cubic splines: a scalar spline `v(s)` with selectable end conditions and a
//! parametric contour spline `x(s), y(s)` with curvature and the leading-edge finder.
//!
//! The formulation follows XFOIL's `spline.f` (Drela): the spline is stored as node values
//! plus node first derivatives (Hermite form) and the derivatives come from the usual
//! C2-continuity tridiagonal system (SPLIND). Evaluation uses the same cubic Hermite
//! polynomial as SEVAL/DEVAL/D2VAL, and the curvature is CURV's `(x'y'' − y'x'')/|r'|³`.

use super::error::GeometryError;

/// End condition of a cubic spline at one end (XFOIL `SPLIND` end-condition codes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EndCondition {
    /// Zero second derivative (natural spline; XFOIL code 999).
    ZeroSecondDerivative,
    /// Zero third derivative (XFOIL code −999; the default of XFOIL's `SEGSPL`).
    ZeroThirdDerivative,
    /// Prescribed first derivative dv/ds.
    Slope(f64),
}

/// Solves a tridiagonal system in place (Thomas algorithm, as XFOIL `TRISOL`).
///
/// `lower[k]·d[k−1] + diag[k]·d[k] + upper[k]·d[k+1] = rhs[k]`; the solution replaces `rhs`.
/// `diag` and `upper` are overwritten. Returns `false` if a zero pivot is met.
pub(crate) fn solve_tridiagonal(
    diag: &mut [f64],
    lower: &[f64],
    upper: &mut [f64],
    rhs: &mut [f64],
) -> bool {
    let n = rhs.len();
    if n == 0 {
        return true;
    }
    for k in 1..n {
        if diag[k - 1] == 0.0 || !diag[k - 1].is_finite() {
            return false;
        }
        upper[k - 1] /= diag[k - 1];
        rhs[k - 1] /= diag[k - 1];
        diag[k] -= lower[k] * upper[k - 1];
        rhs[k] -= lower[k] * rhs[k - 1];
    }
    if diag[n - 1] == 0.0 || !diag[n - 1].is_finite() {
        return false;
    }
    rhs[n - 1] /= diag[n - 1];
    for k in (0..n - 1).rev() {
        rhs[k] -= upper[k] * rhs[k + 1];
    }
    true
}

/// A cubic spline `v(s)` through points `(s_i, v_i)` with strictly increasing `s`, stored as
/// values and first derivatives at the nodes (XFOIL `SPLIND` + `SEVAL`/`DEVAL`/`D2VAL`).
#[derive(Clone, Debug, PartialEq)]
pub struct CubicSpline {
    s: Vec<f64>,
    v: Vec<f64>,
    dv: Vec<f64>,
}

impl CubicSpline {
    /// Builds the C2 cubic spline through `(s, v)` with the given end conditions
    /// (XFOIL `SPLIND`: interior rows `Δs₊·v'ᵢ₋₁ + 2(Δs₋+Δs₊)·v'ᵢ + Δs₋·v'ᵢ₊₁ =
    /// 3[(vᵢ₊₁−vᵢ)Δs₋/Δs₊ + (vᵢ−vᵢ₋₁)Δs₊/Δs₋]`).
    pub fn new(
        s: &[f64],
        v: &[f64],
        start: EndCondition,
        end: EndCondition,
    ) -> Result<Self, GeometryError> {
        let n = s.len();
        if n < 2 || v.len() != n {
            return Err(GeometryError::Spline(format!(
                "need at least 2 points with matching lengths (got {} s, {} values)",
                n,
                v.len()
            )));
        }
        if s.iter().chain(v.iter()).any(|t| !t.is_finite()) {
            return Err(GeometryError::Spline("non-finite input value".into()));
        }
        if let Some(i) = (1..n).find(|&i| s[i] <= s[i - 1]) {
            return Err(GeometryError::Spline(format!(
                "spline parameter not strictly increasing at point {}",
                i + 1
            )));
        }
        let mut a = vec![0.0; n];
        let mut b = vec![0.0; n];
        let mut c = vec![0.0; n];
        let mut d = vec![0.0; n];
        for i in 1..n - 1 {
            let dsm = s[i] - s[i - 1];
            let dsp = s[i + 1] - s[i];
            b[i] = dsp;
            a[i] = 2.0 * (dsm + dsp);
            c[i] = dsm;
            d[i] = 3.0 * ((v[i + 1] - v[i]) * dsm / dsp + (v[i] - v[i - 1]) * dsp / dsm);
        }
        let slope_first = (v[1] - v[0]) / (s[1] - s[0]);
        let slope_last = (v[n - 1] - v[n - 2]) / (s[n - 1] - s[n - 2]);
        let both_third =
            start == EndCondition::ZeroThirdDerivative && end == EndCondition::ZeroThirdDerivative;
        match start {
            EndCondition::ZeroSecondDerivative => {
                a[0] = 2.0;
                c[0] = 1.0;
                d[0] = 3.0 * slope_first;
            }
            EndCondition::ZeroThirdDerivative => {
                a[0] = 1.0;
                c[0] = 1.0;
                d[0] = 2.0 * slope_first;
            }
            EndCondition::Slope(m) => {
                a[0] = 1.0;
                c[0] = 0.0;
                d[0] = m;
            }
        }
        match end {
            _ if n == 2 && both_third => {
                // Two points with zero third derivative at both ends is singular; XFOIL
                // falls back to a zero second derivative at the far end.
                b[n - 1] = 1.0;
                a[n - 1] = 2.0;
                d[n - 1] = 3.0 * slope_last;
            }
            EndCondition::ZeroSecondDerivative => {
                b[n - 1] = 1.0;
                a[n - 1] = 2.0;
                d[n - 1] = 3.0 * slope_last;
            }
            EndCondition::ZeroThirdDerivative => {
                b[n - 1] = 1.0;
                a[n - 1] = 1.0;
                d[n - 1] = 2.0 * slope_last;
            }
            EndCondition::Slope(m) => {
                a[n - 1] = 1.0;
                b[n - 1] = 0.0;
                d[n - 1] = m;
            }
        }
        if !solve_tridiagonal(&mut a, &b, &mut c, &mut d) || d.iter().any(|t| !t.is_finite()) {
            return Err(GeometryError::Spline("singular spline system".into()));
        }
        Ok(Self {
            s: s.to_vec(),
            v: v.to_vec(),
            dv: d,
        })
    }

    /// The spline with XFOIL's default end conditions for airfoil contours (`SEGSPL`: zero
    /// third derivative at both ends).
    pub fn xfoil_default(s: &[f64], v: &[f64]) -> Result<Self, GeometryError> {
        Self::new(
            s,
            v,
            EndCondition::ZeroThirdDerivative,
            EndCondition::ZeroThirdDerivative,
        )
    }

    /// Node parameter values.
    pub fn knots(&self) -> &[f64] {
        &self.s
    }

    /// Node values.
    pub fn values(&self) -> &[f64] {
        &self.v
    }

    /// Node first derivatives dv/ds.
    pub fn node_derivatives(&self) -> &[f64] {
        &self.dv
    }

    /// Interval `i` (1-based upper node as in XFOIL's bisection) containing `ss`, and the
    /// Hermite coefficients `(Δs, t, cx1, cx2)` of SEVAL.
    fn interval(&self, ss: f64) -> (usize, f64, f64, f64, f64) {
        let n = self.s.len();
        let mut ilow = 0usize;
        let mut i = n - 1;
        while i - ilow > 1 {
            let imid = (i + ilow) / 2;
            if ss < self.s[imid] {
                i = imid;
            } else {
                ilow = imid;
            }
        }
        let ds = self.s[i] - self.s[i - 1];
        let t = (ss - self.s[i - 1]) / ds;
        let dv = self.v[i] - self.v[i - 1];
        let cx1 = ds * self.dv[i - 1] - dv;
        let cx2 = ds * self.dv[i] - dv;
        (i, ds, t, cx1, cx2)
    }

    /// Spline value v(ss) (XFOIL `SEVAL`); extrapolates the end cubic outside the range.
    pub fn eval(&self, ss: f64) -> f64 {
        let (i, _ds, t, cx1, cx2) = self.interval(ss);
        t * self.v[i] + (1.0 - t) * self.v[i - 1] + (t - t * t) * ((1.0 - t) * cx1 - t * cx2)
    }

    /// First derivative dv/ds at ss (XFOIL `DEVAL`).
    pub fn deriv(&self, ss: f64) -> f64 {
        let (i, ds, t, cx1, cx2) = self.interval(ss);
        (self.v[i] - self.v[i - 1]
            + (1.0 - 4.0 * t + 3.0 * t * t) * cx1
            + t * (3.0 * t - 2.0) * cx2)
            / ds
    }

    /// Second derivative d²v/ds² at ss (XFOIL `D2VAL`).
    pub fn deriv2(&self, ss: f64) -> f64 {
        let (_i, ds, t, cx1, cx2) = self.interval(ss);
        ((6.0 * t - 4.0) * cx1 + (6.0 * t - 2.0) * cx2) / (ds * ds)
    }
}

/// Cumulative chord-length arc parameter of a polyline (XFOIL `SCALC`): `s₀ = 0`,
/// `sᵢ = sᵢ₋₁ + |rᵢ − rᵢ₋₁|`.
pub(crate) fn arc_lengths(x: &[f64], y: &[f64]) -> Vec<f64> {
    let mut s = Vec::with_capacity(x.len());
    let mut acc = 0.0;
    for i in 0..x.len() {
        if i > 0 {
            acc += (x[i] - x[i - 1]).hypot(y[i] - y[i - 1]);
        }
        s.push(acc);
    }
    s
}

/// Steps of [`ContourSpline::mean_line_length`].
pub const MEAN_LINE_STEPS: usize = 200;

/// A closed-ish airfoil contour splined in arc length: `x(s)` and `y(s)` with XFOIL's
/// `SEGSPL` end conditions, in XFOIL point order (upper TE → LE → lower TE).
#[derive(Clone, Debug, PartialEq)]
pub struct ContourSpline {
    /// Spline of x(s).
    pub x: CubicSpline,
    /// Spline of y(s).
    pub y: CubicSpline,
}

impl ContourSpline {
    /// Splines the points `(x, y)` against their chord-length arc parameter (XFOIL `SCALC`
    /// followed by `SEGSPL` on x and y). Duplicate consecutive points are rejected.
    pub fn new(x: &[f64], y: &[f64]) -> Result<Self, GeometryError> {
        if x.len() != y.len() {
            return Err(GeometryError::Spline(format!(
                "x and y lengths differ ({} vs {})",
                x.len(),
                y.len()
            )));
        }
        let s = arc_lengths(x, y);
        Ok(Self {
            x: CubicSpline::xfoil_default(&s, x)?,
            y: CubicSpline::xfoil_default(&s, y)?,
        })
    }

    /// Arc parameter of the nodes.
    pub fn s(&self) -> &[f64] {
        self.x.knots()
    }

    /// Total arc length from the first to the last node.
    pub fn length(&self) -> f64 {
        let s = self.s();
        s[s.len() - 1] - s[0]
    }

    /// Point (x, y) at arc parameter `ss`.
    pub fn point(&self, ss: f64) -> (f64, f64) {
        (self.x.eval(ss), self.y.eval(ss))
    }

    /// Tangent (dx/ds, dy/ds) at `ss`.
    pub fn tangent(&self, ss: f64) -> (f64, f64) {
        (self.x.deriv(ss), self.y.deriv(ss))
    }

    /// Signed curvature at `ss` (XFOIL `CURV`): `κ = (x'y'' − y'x'')/|r'|³`, positive for a
    /// counter-clockwise turn (convex airfoil surface in XFOIL order). As in XFOIL the
    /// speed |r'| is limited below by 0.001·Δs of the interval to avoid division by zero.
    pub fn curvature(&self, ss: f64) -> f64 {
        let (_, dsx, tx, cx1, cx2) = self.x.interval(ss);
        let (i, _, _, cy1, cy2) = self.y.interval(ss);
        let t = tx;
        let xv = self.x.values();
        let yv = self.y.values();
        let xd =
            xv[i] - xv[i - 1] + (1.0 - 4.0 * t + 3.0 * t * t) * cx1 + t * (3.0 * t - 2.0) * cx2;
        let xdd = (6.0 * t - 4.0) * cx1 + (6.0 * t - 2.0) * cx2;
        let yd =
            yv[i] - yv[i - 1] + (1.0 - 4.0 * t + 3.0 * t * t) * cy1 + t * (3.0 * t - 2.0) * cy2;
        let ydd = (6.0 * t - 4.0) * cy1 + (6.0 * t - 2.0) * cy2;
        let sd = xd.hypot(yd).max(0.001 * dsx);
        (xd * ydd - yd * xdd) / (sd * sd * sd)
    }

    /// Trailing-edge midpoint: mean of the first and last node.
    pub fn te_midpoint(&self) -> (f64, f64) {
        let xv = self.x.values();
        let yv = self.y.values();
        let n = xv.len();
        (0.5 * (xv[0] + xv[n - 1]), 0.5 * (yv[0] + yv[n - 1]))
    }

    /// Chord fraction of the point at arc parameter `ss`: its projection on the chord line from
    /// the leading edge (at arc parameter `s_le`) to the TE midpoint, in chords (XFOIL XIFSET
    /// `W1`, the "chord-based x/c").
    pub fn chord_fraction(&self, s_le: f64, ss: f64) -> f64 {
        let (xle, yle) = self.point(s_le);
        let (xte, yte) = self.te_midpoint();
        let (chx, chy) = (xte - xle, yte - yle);
        let (x, y) = self.point(ss);
        ((x - xle) * chx + (y - yle) * chy) / (chx * chx + chy * chy)
    }

    /// Arc parameter of the point at chord fraction `fraction` ([`chord_fraction`]) on the
    /// upper surface (arc parameters below `s_le`) or the lower one: the first such point from
    /// the leading edge, found by bisection between the nodes that bracket it (XFOIL XIFSET
    /// inverts the same spline by Newton's method, SINVRT, from a guess on that surface). The
    /// leading edge itself for a fraction ≤ 0; `None` if the surface never reaches the fraction.
    ///
    /// [`chord_fraction`]: Self::chord_fraction
    pub fn arc_at_chord_fraction(&self, s_le: f64, fraction: f64, upper: bool) -> Option<f64> {
        if fraction <= 0.0 {
            return Some(s_le);
        }
        let s = self.s();
        let knots: Vec<f64> = if upper {
            s.iter().rev().copied().filter(|&k| k < s_le).collect()
        } else {
            s.iter().copied().filter(|&k| k > s_le).collect()
        };
        let w = |ss: f64| self.chord_fraction(s_le, ss) - fraction;
        let mut near = s_le;
        for far in knots {
            if w(far) >= 0.0 {
                // w(near) < 0 ≤ w(far): bisect to round-off.
                let (mut a, mut b) = (near, far);
                for _ in 0..200 {
                    let m = 0.5 * (a + b);
                    if m == a || m == b {
                        break;
                    }
                    if w(m) >= 0.0 {
                        b = m;
                    } else {
                        a = m;
                    }
                }
                return Some(b);
            }
            near = far;
        }
        None
    }

    /// Length of the mean line from the leading edge (at arc parameter `s_le`) to the TE
    /// midpoint: the polyline through the midpoints of the upper and the lower surface at equal
    /// fractions of their arc lengths, at [`MEAN_LINE_STEPS`] steps. The chord a section was
    /// drawn with, even where a deflected flap or a tilted chord line has moved its trailing
    /// edge closer to its leading edge (exact for a symmetric section, within 0.5 % for a
    /// section of 4 % camber, 2 % for 9 %).
    pub fn mean_line_length(&self, s_le: f64) -> f64 {
        let s = self.s();
        let (upper, lower) = (s_le - s[0], s[s.len() - 1] - s_le);
        let mid = |t: f64| {
            let (xu, yu) = self.point(s_le - t * upper);
            let (xl, yl) = self.point(s_le + t * lower);
            (0.5 * (xu + xl), 0.5 * (yu + yl))
        };
        let mut length = 0.0;
        let mut last = mid(0.0);
        for k in 1..=MEAN_LINE_STEPS {
            let next = mid(k as f64 / MEAN_LINE_STEPS as f64);
            length += (next.0 - last.0).hypot(next.1 - last.1);
            last = next;
        }
        length
    }

    /// Arc parameter of the leading edge (XFOIL `LEFIND`): the point where the surface
    /// tangent is perpendicular to the line from that point to the TE midpoint,
    /// `(r − r_TE)·r' = 0`, solved by a limited Newton iteration started at the first node
    /// where the contour turns back towards the TE.
    pub fn leading_edge(&self) -> Result<f64, GeometryError> {
        let s = self.s();
        let xv = self.x.values();
        let yv = self.y.values();
        let n = s.len();
        if n < 5 {
            return Err(GeometryError::Spline(
                "leading edge needs at least 5 points".into(),
            ));
        }
        let eps = self.length() * 1.0e-5;
        let (xte, yte) = self.te_midpoint();
        let mut i = 2;
        while i < n - 2 {
            let dot = (xv[i] - xte) * (xv[i + 1] - xv[i]) + (yv[i] - yte) * (yv[i + 1] - yv[i]);
            if dot < 0.0 {
                break;
            }
            i += 1;
        }
        let mut sle = s[i];
        for _ in 0..50 {
            let (xle, yle) = self.point(sle);
            let (dxds, dyds) = self.tangent(sle);
            let dxdd = self.x.deriv2(sle);
            let dydd = self.y.deriv2(sle);
            let xch = xle - xte;
            let ych = yle - yte;
            let res = xch * dxds + ych * dyds;
            let ress = dxds * dxds + dyds * dyds + xch * dxdd + ych * dydd;
            if ress == 0.0 || !ress.is_finite() {
                break;
            }
            let lim = 0.02 * (xch + ych).abs();
            let dsle = (-res / ress).max(-lim).min(lim);
            sle += dsle;
            if dsle.abs() < eps {
                return Ok(sle);
            }
        }
        Err(GeometryError::Spline(
            "leading-edge point not found (Newton iteration did not converge)".into(),
        ))
    }
}
