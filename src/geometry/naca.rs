//! NACA 4-digit and 5-digit airfoil generators (analytic thickness and camber lines).
//!
//! Equations: Abbott & von Doenhoff, *Theory of Wing Sections* (1959), §6.4 (eq. 6.2 thickness,
//! 6.4 four-digit camber, 6.6 five-digit camber) and NACA Report 824; reflexed 5-digit mean
//! lines and constants from Ladson et al., NASA TM 4741 (1996). The default point distribution,
//! the blunt trailing edge (a4 = −0.1015) and the vertical addition of thickness to camber
//! follow XFOIL's `naca.f` (Drela) so that `NACA dddd` geometry matches XFOIL's buffer airfoil.

use super::error::GeometryError;
use super::Airfoil;

/// Trailing-edge form of the NACA thickness polynomial.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrailingEdge {
    /// Original NACA polynomial, a4 = −0.1015: finite TE thickness, gap 2·0.0021·t/0.2
    /// (0.00252 c for 12 % thickness). XFOIL's default.
    Blunt,
    /// Modified polynomial, a4 = −0.1036: the thickness vanishes at x = 1.
    Closed,
}

impl TrailingEdge {
    /// Coefficient a4 of x⁴ in the thickness polynomial (Abbott & von Doenhoff eq. 6.2).
    pub fn a4(self) -> f64 {
        match self {
            TrailingEdge::Blunt => -0.1015,
            TrailingEdge::Closed => -0.1036,
        }
    }
}

/// Options of the NACA generators. `Default` reproduces XFOIL 6.99's `NACA` command.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NacaOptions {
    /// Points per surface including LE and TE (XFOIL: `NSIDE = IQX/3` = 123 in XFOIL 6.99,
    /// giving 245 contour points).
    pub points_per_side: usize,
    /// TE bunching exponent `a` of the x distribution
    /// `x = 1 − (a+1)·f·(1−f)^a − (1−f)^(a+1)`, f ∈ [0, 1] (XFOIL `naca.f` AN = 1.5).
    pub te_bunching: f64,
    /// Trailing-edge form (blunt: XFOIL default).
    pub trailing_edge: TrailingEdge,
    /// If true, lay the thickness off normal to the mean line (classic NACA construction,
    /// the one behind the tabulated ordinates); if false, add it vertically as XFOIL does.
    pub thickness_normal_to_camber: bool,
}

impl Default for NacaOptions {
    fn default() -> Self {
        Self {
            points_per_side: 123,
            te_bunching: 1.5,
            trailing_edge: TrailingEdge::Blunt,
            thickness_normal_to_camber: false,
        }
    }
}

/// A parsed NACA designation: the thickness ratio and the mean line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NacaSection {
    /// 4-digit `MPTT`: max camber `m` (chord fraction) at `p`, thickness `t`.
    FourDigit {
        /// Maximum camber / chord.
        m: f64,
        /// Chordwise position of maximum camber / chord.
        p: f64,
        /// Thickness / chord.
        t: f64,
    },
    /// 5-digit `LPQTT`: design CL = 0.15·L, max camber near 0.05·P, Q = 1 for a reflexed
    /// mean line, thickness TT %.
    FiveDigit {
        /// Design lift digit L (design CL = 0.15 L).
        l: u8,
        /// Camber position digit P (1..5).
        p: u8,
        /// Reflexed mean line (third digit 1).
        reflexed: bool,
        /// Thickness / chord.
        t: f64,
    },
}

/// Why a 6-series designation is refused.
const SIX_SERIES: &str =
    "6-series sections (NACA 6X-XXX, 6XA-XXX) are not supported, only 4- and 5-digit \
     ones: give their ordinates as a coordinate file";

/// Whether `body` (lower case, without the `naca` prefix) names a 6-series section: a `6`, a
/// digit, then `-`, `a` or `(` (`64-212`, `65a010`, `63(420)-422`, `64_1-212`).
fn is_six_series(body: &str) -> bool {
    let b = body.as_bytes();
    b.len() > 2
        && b[0] == b'6'
        && b[1].is_ascii_digit()
        && matches!(b[2], b'-' | b'a' | b'(' | b'_')
}

impl NacaSection {
    /// Parses `2412`, `23012`, `NACA 23012`, `naca-0012` (case-insensitive).
    pub fn parse(designation: &str) -> Result<Self, GeometryError> {
        let err = |reason: &str| GeometryError::NacaDesignation {
            designation: designation.to_string(),
            reason: reason.to_string(),
        };
        let lower = designation.trim().to_ascii_lowercase();
        let body = lower.strip_prefix("naca").unwrap_or(&lower).trim_start();
        if is_six_series(body) {
            return Err(err(SIX_SERIES));
        }
        let digits: String = body
            .chars()
            .filter(|c| !c.is_whitespace() && *c != '-' && *c != '_')
            .collect();
        if digits.is_empty() || !digits.chars().all(|c| c.is_ascii_digit()) {
            return Err(err("expected 4 or 5 digits"));
        }
        let d: Vec<u8> = digits.bytes().map(|b| b - b'0').collect();
        match d.len() {
            4 => {
                let m = f64::from(d[0]) / 100.0;
                let p = f64::from(d[1]) / 10.0;
                let t = f64::from(d[2] * 10 + d[3]) / 100.0;
                if t <= 0.0 {
                    return Err(err("thickness must be positive"));
                }
                if m > 0.0 && p == 0.0 {
                    return Err(err("cambered section needs a camber position digit 1..9"));
                }
                Ok(NacaSection::FourDigit { m, p, t })
            }
            5 => {
                let t = f64::from(d[3] * 10 + d[4]) / 100.0;
                if t <= 0.0 {
                    return Err(err("thickness must be positive"));
                }
                if d[0] == 0 {
                    return Err(err("design-lift digit must be 1..9"));
                }
                if d[2] > 1 {
                    return Err(err("third digit must be 0 (normal) or 1 (reflexed)"));
                }
                let reflexed = d[2] == 1;
                let p_ok = if reflexed {
                    (2..=5).contains(&d[1])
                } else {
                    (1..=5).contains(&d[1])
                };
                if !p_ok {
                    return Err(err(if reflexed {
                        "reflexed camber position digit must be 2..5"
                    } else {
                        "camber position digit must be 1..5"
                    }));
                }
                Ok(NacaSection::FiveDigit {
                    l: d[0],
                    p: d[1],
                    reflexed,
                    t,
                })
            }
            _ => Err(err("expected 4 or 5 digits")),
        }
    }

    /// Thickness / chord.
    pub fn thickness(&self) -> f64 {
        match *self {
            NacaSection::FourDigit { t, .. } | NacaSection::FiveDigit { t, .. } => t,
        }
    }

    /// Mean-line ordinate yc(x) and slope dyc/dx.
    ///
    /// 4-digit: Abbott & von Doenhoff eq. 6.4. 5-digit normal (xx0): eq. 6.6 with the
    /// (r, k1) constants of Abbott & von Doenhoff Table (also XFOIL `naca.f`), reflexed (xx1):
    /// NASA TM 4741 with (r, k1, k2/k1). Both scaled by L/2 for design CL ≠ 0.3.
    pub fn camber(&self, x: f64) -> (f64, f64) {
        match *self {
            NacaSection::FourDigit { m, p, .. } => {
                if m == 0.0 {
                    (0.0, 0.0)
                } else if x < p {
                    let k = m / (p * p);
                    (k * (2.0 * p * x - x * x), 2.0 * k * (p - x))
                } else {
                    let k = m / ((1.0 - p) * (1.0 - p));
                    (
                        k * ((1.0 - 2.0 * p) + 2.0 * p * x - x * x),
                        2.0 * k * (p - x),
                    )
                }
            }
            NacaSection::FiveDigit { l, p, reflexed, .. } => {
                let scale = f64::from(l) / 2.0;
                let (yc, dyc) = if reflexed {
                    let (r, k1, k21) = REFLEXED_MEAN_LINES[usize::from(p) - 2];
                    let c = k1 / 6.0;
                    let r3 = r * r * r;
                    let tail = k21 * (1.0 - r).powi(3) + r3;
                    let xr = x - r;
                    if x < r {
                        (c * (xr.powi(3) - tail * x + r3), c * (3.0 * xr * xr - tail))
                    } else {
                        (
                            c * (k21 * xr.powi(3) - tail * x + r3),
                            c * (3.0 * k21 * xr * xr - tail),
                        )
                    }
                } else {
                    let (r, k1) = NORMAL_MEAN_LINES[usize::from(p) - 1];
                    let c = k1 / 6.0;
                    if x < r {
                        (
                            c * (x.powi(3) - 3.0 * r * x * x + r * r * (3.0 - r) * x),
                            c * (3.0 * x * x - 6.0 * r * x + r * r * (3.0 - r)),
                        )
                    } else {
                        (c * r.powi(3) * (1.0 - x), -c * r.powi(3))
                    }
                };
                (scale * yc, scale * dyc)
            }
        }
    }

    /// Half thickness yt(x) (Abbott & von Doenhoff eq. 6.2):
    /// `yt = t/0.2·(0.2969√x − 0.1260x − 0.3516x² + 0.2843x³ + a4·x⁴)`.
    pub fn half_thickness(&self, x: f64, te: TrailingEdge) -> f64 {
        let t = self.thickness();
        let x = x.max(0.0);
        (0.29690 * x.sqrt() - 0.12600 * x - 0.35160 * x * x
            + 0.28430 * x.powi(3)
            + te.a4() * x.powi(4))
            * t
            / 0.20
    }

    /// Display name, e.g. `NACA 2412`.
    pub fn name(&self) -> String {
        match *self {
            NacaSection::FourDigit { m, p, t } => format!(
                "NACA {}{}{:02}",
                (m * 100.0).round() as u32,
                (p * 10.0).round() as u32,
                (t * 100.0).round() as u32
            ),
            NacaSection::FiveDigit { l, p, reflexed, t } => format!(
                "NACA {}{}{}{:02}",
                l,
                p,
                u8::from(reflexed),
                (t * 100.0).round() as u32
            ),
        }
    }

    /// Generates the contour in XFOIL order (upper TE → LE → lower TE) with
    /// `2·points_per_side − 1` points (XFOIL `NACA4`/`NACA5`).
    pub fn airfoil(&self, opts: &NacaOptions) -> Result<Airfoil, GeometryError> {
        if !(5..=100_000).contains(&opts.points_per_side) {
            return Err(GeometryError::NacaDesignation {
                designation: self.name(),
                reason: format!(
                    "points_per_side must be between 5 and 100000 (got {})",
                    opts.points_per_side
                ),
            });
        }
        if !(opts.te_bunching.is_finite() && opts.te_bunching > 0.0) {
            return Err(GeometryError::NacaDesignation {
                designation: self.name(),
                reason: "te_bunching must be positive".into(),
            });
        }
        let n = opts.points_per_side;
        let a = opts.te_bunching;
        let xs: Vec<f64> = (0..n)
            .map(|i| {
                if i == n - 1 {
                    1.0
                } else {
                    let f = i as f64 / (n - 1) as f64;
                    1.0 - (a + 1.0) * f * (1.0 - f).powf(a) - (1.0 - f).powf(a + 1.0)
                }
            })
            .collect();
        let mut upper = Vec::with_capacity(n);
        let mut lower = Vec::with_capacity(n);
        for &x in &xs {
            let yt = self.half_thickness(x, opts.trailing_edge);
            let (yc, dyc) = self.camber(x);
            if opts.thickness_normal_to_camber {
                let th = dyc.atan();
                let (s, c) = th.sin_cos();
                upper.push((x - yt * s, yc + yt * c));
                lower.push((x + yt * s, yc - yt * c));
            } else {
                upper.push((x, yc + yt));
                lower.push((x, yc - yt));
            }
        }
        let mut x = Vec::with_capacity(2 * n - 1);
        let mut y = Vec::with_capacity(2 * n - 1);
        for &(px, py) in upper.iter().rev() {
            x.push(px);
            y.push(py);
        }
        for &(px, py) in lower.iter().skip(1) {
            x.push(px);
            y.push(py);
        }
        Ok(Airfoil {
            name: self.name(),
            x,
            y,
        })
    }
}

/// Normal 5-digit mean lines LP0, P = 1..5: (r, k1). Abbott & von Doenhoff §6.4 table
/// (same values in XFOIL `naca.f`).
const NORMAL_MEAN_LINES: [(f64, f64); 5] = [
    (0.0580, 361.4),
    (0.1260, 51.64),
    (0.2025, 15.957),
    (0.2900, 6.643),
    (0.3910, 3.230),
];

/// Reflexed 5-digit mean lines LP1, P = 2..5: (r, k1, k2/k1). NASA TM 4741 (Ladson et al.
/// 1996), Table of 5-digit reflexed mean-line constants. (r = 0.3180 is a tabulated value,
/// not 1/π.)
#[allow(clippy::approx_constant)]
const REFLEXED_MEAN_LINES: [(f64, f64, f64); 4] = [
    (0.1300, 51.990, 0.000764),
    (0.2170, 15.793, 0.00677),
    (0.3180, 6.520, 0.0303),
    (0.4410, 3.191, 0.1355),
];

/// Generates a NACA 4- or 5-digit airfoil from its designation (`"2412"`, `"NACA 23012"`).
pub fn naca(designation: &str, opts: &NacaOptions) -> Result<Airfoil, GeometryError> {
    NacaSection::parse(designation)?.airfoil(opts)
}
