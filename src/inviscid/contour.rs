//! An airfoil contour prepared for the panel method (XFOIL xpanel.f/xgeom.f SCALC, SEGSPL,
//! NCALC, LEFIND, TECALC, APCALC): arc length, spline tangents, normals, panel angles, the
//! leading edge and chord, and the trailing-edge gap with the strengths of its panel.

use std::f64::consts::PI;

use super::error::InviscidError;
use super::forces::MOMENT_REFERENCE;
use super::influence::PanelLine;
use crate::geometry::ContourSpline;

/// Tunable constants of the panel geometry (XFOIL defaults).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PanelParams {
    /// A trailing-edge gap smaller than this fraction of the chord is treated as sharp
    /// (XFOIL TECALC: `SHARP = DSTE < 0.0001*CHORD`).
    pub sharp_te_gap: f64,
    /// Distance of the sharp-TE control point ahead of the TE along the bisector, as a fraction
    /// of the shorter TE-adjacent panel (XFOIL GGCALC `BWT = 0.1`).
    pub sharp_te_bisector_fraction: f64,
    /// End nodes closer than this fraction of the perimeter count as coincident and the TE
    /// panel is dropped (XFOIL PSILIN `SEPS = (S(N) − S(1))·1e-5`).
    pub coincident_te_fraction: f64,
    /// Moment reference point x (chord units); XFOIL uses the quarter chord.
    pub moment_ref_x: f64,
    /// Moment reference point y (chord units).
    pub moment_ref_y: f64,
}

impl Default for PanelParams {
    fn default() -> Self {
        Self {
            sharp_te_gap: 1.0e-4,
            sharp_te_bisector_fraction: 0.1,
            coincident_te_fraction: 1.0e-5,
            moment_ref_x: MOMENT_REFERENCE.0,
            moment_ref_y: MOMENT_REFERENCE.1,
        }
    }
}

/// Trailing-edge gap geometry and TE-panel strength factors (XFOIL TECALC).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrailingEdge {
    /// TE midpoint x, `(x₀ + x_{N−1})/2`.
    pub x: f64,
    /// TE midpoint y.
    pub y: f64,
    /// Total TE gap |r₀ − r_{N−1}| (XFOIL DSTE).
    pub gap: f64,
    /// Gap projected normal to the TE bisector (XFOIL ANTE, signed).
    pub gap_normal: f64,
    /// Gap projected along the TE bisector (XFOIL ASTE, signed).
    pub gap_streamwise: f64,
    /// `true` if the gap is below `PanelParams::sharp_te_gap`·chord.
    pub sharp: bool,
    /// TE-panel source factor: σ_TE = ½·scs·(γ₀ − γ_{N−1}) (XFOIL SCS = ANTE/DSTE, 1 if sharp).
    pub scs: f64,
    /// TE-panel vortex factor: γ_TE = −½·sds·(γ₀ − γ_{N−1}) (XFOIL SDS = ASTE/DSTE, 0 if sharp).
    pub sds: f64,
    /// `true` when first and last node coincide, so the TE panel is dropped (PSILIN SEPS test).
    pub closed: bool,
    /// Slope of the wake-gap closure at the TE: the tangent of the angle between the contour
    /// tangents at the two TE nodes (XFOIL XICALC DWDXTE, before its limits).
    pub wake_gap_slope: f64,
}

/// An airfoil contour prepared for the panel method: nodes, arc length, spline tangents,
/// outward normals, panel angles and the trailing-edge description.
#[derive(Clone, Debug)]
pub struct PanelGeometry {
    /// Node x (XFOIL order).
    pub x: Vec<f64>,
    /// Node y.
    pub y: Vec<f64>,
    /// Cumulative chord-length arc length, s₀ = 0 (XFOIL SCALC).
    pub s: Vec<f64>,
    /// Spline derivative dx/ds at each node (XFOIL SPLIND with zero-third-derivative ends).
    pub xp: Vec<f64>,
    /// Spline derivative dy/ds at each node.
    pub yp: Vec<f64>,
    /// Outward unit normal x, `(dy/ds, −dx/ds)/|·|` (XFOIL NCALC).
    pub nx: Vec<f64>,
    /// Outward unit normal y.
    pub ny: Vec<f64>,
    /// Panel angles (XFOIL APCALC): `atan2(Δx, −Δy)` for panel j → j+1, last entry the TE panel.
    pub apanel: Vec<f64>,
    /// Tangents and source-stencil lengths of the panels j → j+1 (all but the TE panel).
    pub(crate) panels: PanelLine,
    /// Arc length of the leading edge, where the contour tangent is normal to the line to the
    /// TE midpoint (XFOIL LEFIND, [`ContourSpline::leading_edge`]).
    pub s_le: f64,
    /// Chord: distance from the TE midpoint to the leading edge (XFOIL CHORD).
    pub chord: f64,
    /// Trailing-edge data.
    pub te: TrailingEdge,
    /// The contour spline x(s), y(s) through the nodes (XFOIL SEGSPL).
    pub spline: ContourSpline,
}

impl PanelGeometry {
    /// Prepares the contour `x`, `y` (XFOIL order, used as given) for the panel method.
    pub fn new(x: &[f64], y: &[f64], params: &PanelParams) -> Result<Self, InviscidError> {
        const MIN_NODES: usize = 5;
        if x.len() != y.len() {
            return Err(InviscidError::LengthMismatch {
                x: x.len(),
                y: y.len(),
            });
        }
        let n = x.len();
        if n < MIN_NODES {
            return Err(InviscidError::TooFewNodes {
                got: n,
                min: MIN_NODES,
            });
        }
        if let Some(i) = (0..n).find(|&i| !x[i].is_finite() || !y[i].is_finite()) {
            return Err(InviscidError::NonFiniteNode(i));
        }
        if let Some(i) = (1..n).find(|&i| x[i] == x[i - 1] && y[i] == y[i - 1]) {
            return Err(InviscidError::DuplicateNode(i - 1));
        }
        // Shoelace area of the closed polygon: positive for XFOIL's counter-clockwise order.
        let area2: f64 = (0..n)
            .map(|i| {
                let j = (i + 1) % n;
                x[i] * y[j] - x[j] * y[i]
            })
            .sum();
        if area2 < 0.0 {
            return Err(InviscidError::ClockwiseContour);
        }
        // Arc length and dX/ds, dY/ds at the nodes: XFOIL's contour spline (SCALC, SEGSPL with
        // zero third derivative at both ends).
        let spline = ContourSpline::new(x, y)?;
        let s = spline.s().to_vec();
        let xp = spline.x.node_derivatives().to_vec();
        let yp = spline.y.node_derivatives().to_vec();
        let mut nx = vec![0.0; n];
        let mut ny = vec![0.0; n];
        for i in 0..n {
            let m = xp[i].hypot(yp[i]);
            nx[i] = yp[i] / m;
            ny[i] = -xp[i] / m;
        }

        let (xte, yte) = spline.te_midpoint();
        let s_le = spline.leading_edge()?;
        let (xle, yle) = spline.point(s_le);
        let chord = (xle - xte).hypot(yle - yte);

        // XFOIL TECALC: TE base vector, bisector from the spline tangents, gap projections.
        let dxte = x[0] - x[n - 1];
        let dyte = y[0] - y[n - 1];
        let dxs = 0.5 * (-xp[0] + xp[n - 1]);
        let dys = 0.5 * (-yp[0] + yp[n - 1]);
        let gap_normal = dxs * dyte - dys * dxte;
        let gap_streamwise = dxs * dxte + dys * dyte;
        let gap = dxte.hypot(dyte);
        let sharp = gap < params.sharp_te_gap * chord;
        let (scs, sds) = if sharp {
            (1.0, 0.0)
        } else {
            (gap_normal / gap, gap_streamwise / gap)
        };
        // XICALC: sine of the angle between the two TE tangents, then its tangent.
        let crosp = (xp[0] * yp[n - 1] - yp[0] * xp[n - 1])
            / ((xp[0] * xp[0] + yp[0] * yp[0]) * (xp[n - 1] * xp[n - 1] + yp[n - 1] * yp[n - 1]))
                .sqrt();
        let wake_gap_slope = crosp / (1.0 - crosp * crosp).sqrt();
        // PSILIN: TE panel skipped when the end nodes coincide within SEPS.
        let seps = s[n - 1] * params.coincident_te_fraction;
        let closed = gap * gap < seps * seps;

        // XFOIL APCALC panel angles.
        let mut apanel = vec![0.0; n];
        for i in 0..n - 1 {
            apanel[i] = (x[i + 1] - x[i]).atan2(-(y[i + 1] - y[i]));
        }
        apanel[n - 1] = if sharp {
            PI
        } else {
            (-(x[0] - x[n - 1])).atan2(y[0] - y[n - 1]) + PI
        };

        Ok(Self {
            x: x.to_vec(),
            y: y.to_vec(),
            s,
            xp,
            yp,
            nx,
            ny,
            apanel,
            panels: PanelLine::new(x, y),
            s_le,
            chord,
            te: TrailingEdge {
                x: xte,
                y: yte,
                gap,
                gap_normal,
                gap_streamwise,
                sharp,
                scs,
                sds,
                closed,
                wake_gap_slope,
            },
            spline,
        })
    }

    /// Number of nodes N.
    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// Always false (a geometry has at least 5 nodes); present for API symmetry with `len`.
    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }
}
