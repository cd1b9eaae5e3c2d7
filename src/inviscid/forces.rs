//! Lift, moment and pressure-drag coefficients from surface Cp (XFOIL xfoil.f CLCALC):
//! trapezoidal integration over every panel including the trailing-edge panel, in wind axes,
//! with the linear-Cp moment correction term ΔCp·Δ²/12.

/// Moment reference point (x, y) in chord units: the quarter chord (XFOIL XCMREF, YCMREF).
pub const MOMENT_REFERENCE: (f64, f64) = (0.25, 0.0);

/// Section force coefficients (per unit span, chord 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SectionForces {
    /// Lift coefficient.
    pub cl: f64,
    /// Pitching-moment coefficient about the reference point (nose-up positive).
    pub cm: f64,
    /// Pressure drag coefficient.
    pub cdp: f64,
}

/// Integrates nodal `cp` over the closed contour `x`, `y` (XFOIL order; the panel from the last
/// node back to the first is included) at angle of attack `alpha_deg`, with moments about
/// (`xref`, `yref`). Implements XFOIL CLCALC: CL = Σ Δx_w·Cp̄, CDP = −Σ Δy_w·Cp̄,
/// CM = −Σ [Δx_w(Cp̄·a_x + ΔCp·Δx_w/12) + Δy_w(Cp̄·a_y + ΔCp·Δy_w/12)], where (Δx_w, Δy_w) is
/// the panel vector in wind axes and (a_x, a_y) the panel midpoint relative to the reference.
pub fn integrate_pressure(
    x: &[f64],
    y: &[f64],
    cp: &[f64],
    alpha_deg: f64,
    xref: f64,
    yref: f64,
) -> SectionForces {
    let (sa, ca) = alpha_deg.to_radians().sin_cos();
    let n = x.len().min(y.len()).min(cp.len());
    let mut cl = 0.0;
    let mut cm = 0.0;
    let mut cdp = 0.0;
    for i in 0..n {
        let ip = if i + 1 == n { 0 } else { i + 1 };
        let (ddx, ddy) = (x[ip] - x[i], y[ip] - y[i]);
        let dx = ddx * ca + ddy * sa;
        let dy = ddy * ca - ddx * sa;
        let dg = cp[ip] - cp[i];
        let mx = 0.5 * (x[ip] + x[i]) - xref;
        let my = 0.5 * (y[ip] + y[i]) - yref;
        let ax = mx * ca + my * sa;
        let ay = my * ca - mx * sa;
        let ag = 0.5 * (cp[ip] + cp[i]);
        cl += dx * ag;
        cdp -= dy * ag;
        cm -= dx * (ag * ax + dg * dx / 12.0) + dy * (ag * ay + dg * dy / 12.0);
    }
    SectionForces { cl, cm, cdp }
}
