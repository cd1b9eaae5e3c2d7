//! Integrated forces of a viscous solution: Cl and Cm from the viscous surface speed with the
//! Karman–Tsien pressure correction (XFOIL xfoil.f CPCALC + CLCALC), Cd from Squire–Young at the
//! wake end (XFOIL CDCALC), the friction drag cdf by integrating the wall shear stress along both
//! surfaces (XFOIL CDCALC "CDF"), and cdp = cd − cdf.

use crate::compressibility::KarmanTsien;
use crate::inviscid::forces::{integrate_pressure, MOMENT_REFERENCE};
use crate::inviscid::PanelGeometry;

/// Lift and moment coefficients (about [`MOMENT_REFERENCE`]) of a closed contour with surface
/// speeds `q` (|q| = Ue/V∞ at the airfoil nodes): the Karman–Tsien Cp integrated as the
/// inviscid pressures are ([`integrate_pressure`], XFOIL CPCALC + CLCALC).
pub(crate) fn lift_and_moment(
    x: &[f64],
    y: &[f64],
    q: &[f64],
    alpha_deg: f64,
    karman_tsien: &KarmanTsien,
) -> (f64, f64) {
    let cp: Vec<f64> = q
        .iter()
        .map(|qi| karman_tsien.cp_unchecked(1.0 - qi * qi))
        .collect();
    let (xref, yref) = MOMENT_REFERENCE;
    let forces = integrate_pressure(x, y, &cp, alpha_deg, xref, yref);
    (forces.cl, forces.cm)
}

/// Friction drag of one surface at angle of attack `alpha_deg`: Σ ½(τ_i + τ_{i−1})·Δx_wind·2
/// with the wall shear τ = ½ ρe Ue,c² Cf normalised by ρ∞V∞² (XFOIL CDCALC). `x`, `y` are the
/// station coordinates from the stagnation point to the TE; the first (similarity) interval is
/// skipped as in XFOIL.
pub(crate) fn friction_drag(x: &[f64], y: &[f64], tau: &[f64], alpha_deg: f64) -> f64 {
    let (sa, ca) = alpha_deg.to_radians().sin_cos();
    let n = x.len().min(y.len()).min(tau.len());
    (1..n)
        .map(|i| {
            let dx = (x[i] - x[i - 1]) * ca + (y[i] - y[i - 1]) * sa;
            0.5 * (tau[i] + tau[i - 1]) * dx * 2.0
        })
        .sum()
}

/// x/c of the transition point at ξ_tr from the stagnation point (arc length `sst`) on the
/// upper surface (arc length sst − ξ_tr) or the lower one (sst + ξ_tr): the point's chord
/// fraction on the contour spline (XFOIL XOCTR), the measure a trip location is given in.
pub(crate) fn transition_x(contour: &PanelGeometry, sst: f64, upper: bool, xi_tr: f64) -> f64 {
    let s = if upper { sst - xi_tr } else { sst + xi_tr };
    contour.spline.chord_fraction(contour.s_le, s)
}

/// x of the start of the reversed flow (Cf < 0) that reaches the trailing edge, on one surface
/// given from the stagnation point to the trailing edge: the zero of Cf interpolated linearly
/// in x between the last station with Cf ≥ 0 and the first of the reversed run; the first
/// station's x when the whole surface is reversed, the trailing edge's x when the flow is
/// attached there. A bubble that reattaches before the trailing edge does not count.
pub(crate) fn separation_x(x: &[f64], cf: &[f64]) -> f64 {
    let n = x.len().min(cf.len());
    let Some(&x_te) = x[..n].last() else {
        return f64::NAN;
    };
    let Some(first) = (0..n).rev().take_while(|&k| cf[k] < 0.0).last() else {
        return x_te;
    };
    if first == 0 {
        return x[0];
    }
    let (c0, c1) = (cf[first - 1], cf[first]);
    let f = c0 / (c0 - c1);
    x[first - 1] + f.clamp(0.0, 1.0) * (x[first] - x[first - 1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transition_location_is_the_chord_fraction_of_the_point() {
        // A contour with its chord line tilted 30°: x/c runs along the chord line.
        let (sa, ca) = 30f64.to_radians().sin_cos();
        let foil = crate::geometry::naca("0012", &Default::default()).unwrap();
        let (x, y): (Vec<f64>, Vec<f64>) = foil
            .x
            .iter()
            .zip(&foil.y)
            .map(|(&x, &y)| (ca * x + sa * y, -sa * x + ca * y))
            .unzip();
        let contour = PanelGeometry::new(&x, &y, &Default::default()).unwrap();
        let s_le = contour.s_le;
        for xtr in [0.0, 0.07, 0.5, 0.999] {
            for upper in [true, false] {
                let s = contour
                    .spline
                    .arc_at_chord_fraction(s_le, xtr, upper)
                    .unwrap();
                let xi = if upper { s_le - s } else { s - s_le };
                let back = transition_x(&contour, s_le, upper, xi);
                assert!((back - xtr).abs() < 1e-12, "{xtr} {upper}: {back}");
            }
        }
    }

    #[test]
    fn separation_starts_where_the_reversed_flow_to_the_trailing_edge_does() {
        let x = [0.0, 0.2, 0.4, 0.6, 0.8, 1.0];
        // A bubble at 0.2 reattaches; the flow separates for good between 0.6 and 0.8.
        let cf = [0.01, -0.001, 0.002, 0.003, -0.001, -0.002];
        assert!((separation_x(&x, &cf) - 0.75).abs() < 1e-12);
        assert_eq!(
            separation_x(&x, &[0.01, -0.001, 0.002, 0.003, 0.001, 0.0]),
            1.0
        );
        assert_eq!(separation_x(&x, &[-1.0; 6]), 0.0);
        assert!(separation_x(&[], &[]).is_nan());
    }
}
