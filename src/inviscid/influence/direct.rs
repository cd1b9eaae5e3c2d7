//! Direct evaluation of the source panels for given nodal mass defects: an independent
//! summation path of the PSILIN/PSWLIN source terms, each panel evaluated on its own, that
//! verifies the sensitivities (tests only).

use super::frames::{dist, source_neighbours};
use super::panel::{PanelFrame, QOPI};
use super::{airfoil_frame, FieldPoint, PanelGeometry, Probe};

/// Direct evaluation of (ψ, ∂ψ/∂n) of one source panel jo→jo+1 of a line for given nodal mass
/// defects `m` (the SSUM/SDIF form of PSILIN, without forming sensitivities).
#[inline]
fn source_panel_value(
    frame: &PanelFrame,
    apan: f64,
    x: &[f64],
    y: &[f64],
    jo: usize,
    m: &[f64],
) -> (f64, f64) {
    let n = x.len();
    let jp = jo + 1;
    let (jm, jq) = source_neighbours(jo, n);
    let dso = dist(x[jo], y[jo], x[jp], y[jp]);
    let dsm = dist(x[jm], y[jm], x[jp], y[jp]);
    let dsp = dist(x[jo], y[jo], x[jq], y[jq]);
    let slope_o = (m[jp] - m[jo]) / dso;
    let slope_m = (m[jp] - m[jm]) / dsm;
    let slope_p = (m[jq] - m[jo]) / dsp;
    let ([psum, pdif, psni, pdni], [psum2, pdif2, psni2, pdni2]) = frame.source_halves(apan);
    let (ssum1, sdif1) = (slope_o + slope_m, slope_o - slope_m);
    let (ssum2, sdif2) = (slope_p + slope_o, slope_p - slope_o);
    let psi = QOPI * (psum * ssum1 + pdif * sdif1 + psum2 * ssum2 + pdif2 * sdif2);
    let qn = QOPI * (psni * ssum1 + pdni * sdif1 + psni2 * ssum2 + pdni2 * sdif2);
    (psi, qn)
}

/// Direct (ψ, ∂ψ/∂n) at probe `p` of the airfoil source panels for nodal mass defects `m`
/// (an independent summation path of the PSILIN source terms, used to verify sensitivities).
pub(crate) fn airfoil_source_value(g: &PanelGeometry, p: &Probe, m: &[f64]) -> (f64, f64) {
    let n = g.len();
    let mut psi = 0.0;
    let mut qn = 0.0;
    for jo in 0..n - 1 {
        let f = airfoil_frame(g, p, jo);
        let (a, b) = source_panel_value(&f, g.apanel[jo], &g.x, &g.y, jo, m);
        psi += a;
        qn += b;
    }
    (psi, qn)
}

/// Direct (ψ, ∂ψ/∂n) at probe `p` of the wake source panels for nodal mass defects `m`.
pub(crate) fn wake_source_value(
    x: &[f64],
    y: &[f64],
    apanel: &[f64],
    p: &Probe,
    m: &[f64],
) -> (f64, f64) {
    let mut psi = 0.0;
    let mut qn = 0.0;
    for (jo, &apan) in apanel.iter().enumerate().take(x.len() - 1) {
        let f = wake_frame(x, y, p, jo);
        let (a, b) = source_panel_value(&f, apan, x, y, jo, m);
        psi += a;
        qn += b;
    }
    (psi, qn)
}

/// Builds the frame of wake panel jo seen from `p` (PSWLIN), evaluating its terms on its own.
#[inline]
fn wake_frame(x: &[f64], y: &[f64], p: &Probe, jo: usize) -> PanelFrame {
    let (on, sa, sb) = wake_self(p, jo);
    PanelFrame::new(p, x[jo], y[jo], x[jo + 1], y[jo + 1], on, sa, sb, -1.0)
}

/// Whether `p` lies on the wake line and whether it is the first or second node of panel jo
/// (PSWLIN's IO tests).
#[inline]
fn wake_self(p: &Probe, jo: usize) -> (bool, bool, bool) {
    match p.kind {
        FieldPoint::Wake(i) => (true, i == jo, i == jo + 1),
        _ => (false, false, false),
    }
}
