//! Interpolation in a polar table.
//!
//! **Along α** each polar is a monotone piecewise-cubic Hermite interpolant (PCHIP) through its
//! *converged* points only (Fritsch & Carlson 1980, "Monotone piecewise cubic interpolation",
//! SIAM J. Numer. Anal. 17(2); slopes by the weighted harmonic mean of Fritsch & Butland 1984
//! with the shape-preserving three-point end slopes of Moler, *Numerical Computing with
//! MATLAB*, §3.4). Chosen over linear interpolation because it is C¹ — the rotor's trim
//! Newton iteration and lift-curve slopes see no kinks at every table node — and over a
//! natural cubic spline because it never overshoots the data near c_l,max or the edges of the
//! drag bucket, is local (a point only influences its two neighbouring intervals) and still
//! reproduces the table exactly at its nodes and linear data exactly between them.
//! Only usable points ([`PolarPoint::usable`]: converged, not in massive separation) are
//! interpolated; an interval that spans one or more other points is *bridged* and lookups
//! inside it are flagged. Outside the usable α range the 360° extension of
//! [`post_stall`](super::post_stall) takes over, from the last point the method can be trusted
//! at: converged points in massive separation beyond it are replaced by the extension, and
//! lookups there say so ([`Lookup::massive_separation`]).
//!
//! **Between polars** the four (Re, M) neighbours are combined bilinearly, linear in ln Re and
//! linear in M; each neighbour is evaluated at the same α with its own converged range and
//! extension. Outside the Re or Mach axis the value is clamped to the edge and flagged.

use super::post_stall::{Extension360, Junction, PostStallParams};
use super::PolarTable;
use crate::section::PolarPoint;
use crate::section::{wrap_deg, Lookup, SectionAero};

/// One polar prepared for fast lookups: usable points sorted by α, each interval's PCHIP cubic
/// and flags ([`Segment`]) and the 360° extension.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct AlphaCurve {
    /// α of the usable points (deg), strictly increasing.
    alpha: Vec<f64>,
    /// Interval k, between usable points k and k+1: its cubic and its flags.
    segments: Vec<Segment>,
    /// (cl, cd, cm) at the last usable point (the interpolant's value there, exactly).
    last_value: [f64; 3],
    /// Supercritical flag of the first and the last usable point ([`Criticality`]).
    end_criticality: [Criticality; 2],
    /// The first and the last usable point's table does not say whether it is in massive
    /// separation.
    end_separation_unknown: [bool; 2],
    /// The α span of the converged points in massive separation beyond the first and the last
    /// usable point (deg): lookups in it are flagged. Empty spans are (α₀, α₀) and (αₙ, αₙ).
    separated_beyond: (f64, f64),
    /// This curve stands in for a neighbouring polar that has too few converged points.
    pub(crate) substitute: bool,
    /// Extension beyond the first and last converged α.
    ext: Extension360,
    /// Buckets per degree of the interval index.
    bucket_scale: f64,
    /// Interval index: `bucket[b]` is the interval holding α₀ + b/bucket_scale, so that a
    /// lookup starts at most a few intervals from its target (no binary search).
    bucket: Vec<u32>,
}

/// Whether a table point is supercritical, as far as its table says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Criticality {
    /// Subcritical everywhere on the surface.
    Subcritical,
    /// Locally supersonic somewhere (Cp_min < Cp*).
    Supercritical,
    /// The table does not say.
    Unknown,
}

impl Criticality {
    fn of(p: &PolarPoint) -> Self {
        match p.supercritical {
            Some(false) => Self::Subcritical,
            Some(true) => Self::Supercritical,
            None => Self::Unknown,
        }
    }

    /// The flags of a value that leans on points of criticality `a` and `b`: (supercritical,
    /// unknown).
    fn flags(a: Self, b: Self) -> (bool, bool) {
        (
            a == Self::Supercritical || b == Self::Supercritical,
            a == Self::Unknown || b == Self::Unknown,
        )
    }
}

/// Largest number of buckets of one curve's interval index.
const MAX_BUCKETS: usize = 4096;

/// Result of evaluating one curve.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CurveValue {
    /// (cl, cd, cm).
    pub(crate) v: [f64; 3],
    /// From the 360° extension.
    pub(crate) post_stall: bool,
    /// Inside a bridged interval, or from a substitute curve.
    pub(crate) bridged: bool,
    /// A point it leans on (the interval's ends, or the junction of the extension) is
    /// supercritical.
    pub(crate) supercritical: bool,
    /// A point it leans on does not say whether it is supercritical.
    pub(crate) supercritical_unknown: bool,
    /// The table's points at this α are in massive separation (replaced or bridged).
    pub(crate) massive_separation: bool,
    /// A point it leans on does not say whether it is in massive separation.
    pub(crate) separation_unknown: bool,
}

/// One interval of an [`AlphaCurve`]: the PCHIP cubic of each coefficient in the interval's
/// own variable t = (α − α_k)/(α_{k+1} − α_k), and what a value inside it leans on.
#[derive(Clone, Debug, PartialEq)]
struct Segment {
    /// α at the interval's start (deg).
    alpha0: f64,
    /// 1/(α_{k+1} − α_k) (1/deg).
    inv_width: f64,
    /// (cl, cd, cm) = Σ c_j t^j, j = 0…3: the Hermite cubic through both ends' values and
    /// slopes (Fritsch & Carlson 1980, eq. 2) in power form.
    cubic: [[f64; 4]; 3],
    /// The interval spans other points (bridged).
    bridged: bool,
    /// The interval spans converged points in massive separation.
    separated_gap: bool,
    /// Either end is supercritical; either end does not say ([`Criticality::flags`]).
    supercritical: (bool, bool),
    /// Either end's table does not say whether it is in massive separation.
    separation_unknown: bool,
}

impl AlphaCurve {
    /// Prepare a polar (points sorted by α). `None` if it has fewer than two usable points.
    pub(crate) fn new(points: &[PolarPoint], params: PostStallParams) -> Option<Self> {
        let mut alpha = Vec::new();
        let mut value = Vec::new();
        let mut criticality = Vec::new();
        let mut separation_unknown = Vec::new();
        let mut bridged = Vec::new();
        let mut separated_gap = Vec::new();
        let (mut skipped, mut separated) = (false, false);
        let mut separated_below = None;
        for p in points {
            if !p.usable() {
                skipped = true;
                if p.converged {
                    separated = true;
                    if alpha.is_empty() {
                        separated_below.get_or_insert(p.alpha);
                    }
                }
                continue;
            }
            if !alpha.is_empty() {
                bridged.push(skipped);
                separated_gap.push(separated);
            }
            (skipped, separated) = (false, false);
            alpha.push(p.alpha);
            value.push([p.cl, p.cd, p.cm]);
            criticality.push(Criticality::of(p));
            separation_unknown.push(p.massive_separation.is_none());
        }
        if alpha.len() < 2 {
            return None;
        }
        let last = alpha[alpha.len() - 1];
        let separated_above = points
            .iter()
            .rev()
            .find(|p| p.converged && !p.usable() && p.alpha > last)
            .map_or(last, |p| p.alpha);
        let separated_beyond = (separated_below.unwrap_or(alpha[0]), separated_above);
        let slope = pchip_slopes(&alpha, &value);
        let n = alpha.len();
        let junction = |k: usize| Junction {
            alpha_deg: alpha[k],
            cl: value[k][0],
            cd: value[k][1],
            cm: value[k][2],
        };
        let ext = Extension360::new(params, junction(0), junction(n - 1));
        let (bucket_scale, bucket) = interval_index(&alpha);
        // Interval k: the Hermite cubic of its ends' values and slopes in power form.
        let segment = |k: usize| {
            let h = alpha[k + 1] - alpha[k];
            let cubic = std::array::from_fn(|i| {
                let (y0, y1) = (value[k][i], value[k + 1][i]);
                let (d0, d1) = (h * slope[k][i], h * slope[k + 1][i]);
                [
                    y0,
                    d0,
                    3.0 * (y1 - y0) - 2.0 * d0 - d1,
                    2.0 * (y0 - y1) + d0 + d1,
                ]
            });
            Segment {
                alpha0: alpha[k],
                inv_width: 1.0 / h,
                cubic,
                bridged: bridged[k],
                separated_gap: separated_gap[k],
                supercritical: Criticality::flags(criticality[k], criticality[k + 1]),
                separation_unknown: separation_unknown[k] || separation_unknown[k + 1],
            }
        };
        let segments = (0..n - 1).map(segment).collect();
        Some(Self {
            alpha,
            segments,
            last_value: value[n - 1],
            end_criticality: [criticality[0], criticality[n - 1]],
            end_separation_unknown: [separation_unknown[0], separation_unknown[n - 1]],
            separated_beyond,
            substitute: false,
            ext,
            bucket_scale,
            bucket,
        })
    }

    /// First and last usable α (deg).
    pub(crate) fn alpha_range(&self) -> (f64, f64) {
        (self.alpha[0], self.alpha[self.alpha.len() - 1])
    }

    /// (cl, cd, cm) at `a` (deg, within ±180°): the interval's cubic Hermite inside the usable
    /// range ([`Segment`]), the 360° extension outside.
    /// `trig` caches (sin α, cos α) across the polars of one lookup.
    pub(crate) fn eval(&self, a: f64, trig: &mut Option<(f64, f64)>) -> CurveValue {
        let n = self.alpha.len();
        if !(a >= self.alpha[0] && a <= self.alpha[n - 1]) {
            let (s, c) = *trig.get_or_insert_with(|| super::post_stall::sin_cos_deg(a));
            let end = if a < self.alpha[0] { 0 } else { 1 };
            let at_end = self.end_criticality[end];
            let (supercritical, supercritical_unknown) = Criticality::flags(at_end, at_end);
            let (below, above) = self.separated_beyond;
            return CurveValue {
                v: self.ext.eval_sc(a, s, c),
                post_stall: true,
                bridged: self.substitute,
                supercritical,
                supercritical_unknown,
                massive_separation: a >= below && a <= above,
                separation_unknown: self.end_separation_unknown[end],
            };
        }
        let b = (((a - self.alpha[0]) * self.bucket_scale) as usize).min(self.bucket.len() - 1);
        let mut k = self.bucket[b] as usize;
        while k + 2 < n && self.alpha[k + 1] <= a {
            k += 1;
        }
        while k > 0 && self.alpha[k] > a {
            k -= 1;
        }
        let seg = &self.segments[k];
        let t = (a - seg.alpha0) * seg.inv_width;
        // The last node exactly (elsewhere t = 0 at a node, where the cubic is its value).
        let v = if a == self.alpha[n - 1] {
            self.last_value
        } else {
            seg.cubic
                .map(|[c0, c1, c2, c3]| c0 + t * (c1 + t * (c2 + t * c3)))
        };
        let (supercritical, supercritical_unknown) = seg.supercritical;
        CurveValue {
            v,
            post_stall: false,
            bridged: seg.bridged || self.substitute,
            supercritical,
            supercritical_unknown,
            massive_separation: seg.separated_gap,
            separation_unknown: seg.separation_unknown,
        }
    }
}

/// Uniform-bucket index of the intervals of a strictly increasing `alpha` (n ≥ 2): bucket
/// width at most the smallest spacing (capped at [`MAX_BUCKETS`] buckets), each holding the
/// interval that contains its left edge.
fn interval_index(alpha: &[f64]) -> (f64, Vec<u32>) {
    let n = alpha.len();
    let span = alpha[n - 1] - alpha[0];
    let h_min = alpha
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(f64::INFINITY, f64::min);
    let nb = ((span / h_min).ceil() as usize).clamp(1, MAX_BUCKETS);
    let scale = nb as f64 / span;
    let mut k = 0;
    let bucket = (0..nb)
        .map(|b| {
            let edge = alpha[0] + b as f64 / scale;
            while k + 2 < n && alpha[k + 1] <= edge {
                k += 1;
            }
            k as u32
        })
        .collect();
    (scale, bucket)
}

/// PCHIP node slopes for each of the three coefficient columns.
fn pchip_slopes(x: &[f64], y: &[[f64; 3]]) -> Vec<[f64; 3]> {
    let n = x.len();
    let mut d = vec![[0.0; 3]; n];
    for c in 0..3 {
        let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
        let del: Vec<f64> = (0..n - 1).map(|k| (y[k + 1][c] - y[k][c]) / h[k]).collect();
        if n == 2 {
            d[0][c] = del[0];
            d[1][c] = del[0];
            continue;
        }
        // Interior: weighted harmonic mean where the secants agree in sign, else 0
        // (Fritsch & Butland 1984; satisfies the Fritsch–Carlson monotonicity region).
        for k in 1..n - 1 {
            if del[k - 1] * del[k] > 0.0 {
                let w1 = 2.0 * h[k] + h[k - 1];
                let w2 = h[k] + 2.0 * h[k - 1];
                d[k][c] = (w1 + w2) / (w1 / del[k - 1] + w2 / del[k]);
            }
        }
        d[0][c] = end_slope(h[0], h[1], del[0], del[1]);
        d[n - 1][c] = end_slope(h[n - 2], h[n - 3], del[n - 2], del[n - 3]);
    }
    d
}

/// Shape-preserving three-point end slope (Moler, Numerical Computing with MATLAB, §3.4).
fn end_slope(h0: f64, h1: f64, del0: f64, del1: f64) -> f64 {
    let d = ((2.0 * h0 + h1) * del0 - h0 * del1) / (h0 + h1);
    if d * del0 <= 0.0 {
        0.0
    } else if del0 * del1 < 0.0 && d.abs() > 3.0 * del0.abs() {
        3.0 * del0
    } else {
        d
    }
}

/// Bracketing index and weight of `x` on a strictly increasing axis; the flag says `x` was
/// outside the axis (or NaN) and was clamped to its edge. Edges match within a relative 1e-12.
#[inline]
pub(crate) fn bracket(axis: &[f64], x: f64) -> (usize, f64, bool) {
    let n = axis.len();
    let tol = 1e-12 * axis[0].abs().max(axis[n - 1].abs()).max(1.0);
    if x.is_nan() {
        return (0, 0.0, true);
    }
    if n == 1 {
        return (0, 0.0, (x - axis[0]).abs() > tol);
    }
    if x <= axis[0] {
        return (0, 0.0, x < axis[0] - tol);
    }
    if x >= axis[n - 1] {
        return (n - 2, 1.0, x > axis[n - 1] + tol);
    }
    let i = (axis.partition_point(|&v| v <= x).max(1) - 1).min(n - 2);
    (i, (x - axis[i]) / (axis[i + 1] - axis[i]), false)
}

impl PolarTable {
    /// [`lookup`](SectionAero::lookup) at every (α, Re, M) of three columns, in order: the
    /// vectorised lookup of the Python package. Columns of unequal length are read up to the
    /// shortest.
    pub fn lookup_many(&self, alpha_deg: &[f64], re: &[f64], mach: &[f64]) -> Vec<Lookup> {
        alpha_deg
            .iter()
            .zip(re)
            .zip(mach)
            .map(|((&a, &r), &m)| self.lookup(a, r, m))
            .collect()
    }
}

impl SectionAero for PolarTable {
    /// Table lookup: PCHIP in α over usable points, 360° extension outside their range,
    /// bilinear in (ln Re, M) between the four neighbouring polars, clamped (and flagged)
    /// outside the Re and Mach axes; flagged supercritical when a point it leans on (either end
    /// of an α interval of a polar with weight) is, and massive separation when a polar with
    /// weight has such points at this α. Allocation-free; O(1) per polar (interval
    /// index, no binary search in α).
    fn lookup(&self, alpha_deg: f64, re: f64, mach: f64) -> Lookup {
        if !self.has_lookup() {
            return Lookup {
                cl: f64::NAN,
                cd: f64::NAN,
                cm: f64::NAN,
                ..Lookup::default()
            };
        }
        let a = wrap_deg(alpha_deg);
        let ln_re = if re > 0.0 { re.ln() } else { f64::NEG_INFINITY };
        let (ir, wr, re_clamped) = bracket(self.ln_re(), ln_re);
        let (im, wm, mach_clamped) = bracket(self.mach(), mach);
        let mut out = Lookup {
            re_clamped,
            mach_clamped,
            ..Lookup::default()
        };
        let n_re = self.re().len();
        let n_m = self.mach().len();
        let mut trig = None;
        for (dr, fr) in [(0, 1.0 - wr), (1, wr)] {
            if fr == 0.0 || ir + dr >= n_re {
                continue;
            }
            for (dm, fm) in [(0, 1.0 - wm), (1, wm)] {
                let w = fr * fm;
                if w == 0.0 || im + dm >= n_m {
                    continue;
                }
                let c = self.curve(ir + dr, im + dm).eval(a, &mut trig);
                out.cl += w * c.v[0];
                out.cd += w * c.v[1];
                out.cm += w * c.v[2];
                out.post_stall |= c.post_stall;
                out.bridged |= c.bridged;
                out.supercritical |= c.supercritical;
                out.supercritical_unknown |= c.supercritical_unknown;
                out.massive_separation |= c.massive_separation;
                out.separation_unknown |= c.separation_unknown;
            }
        }
        out
    }
}
