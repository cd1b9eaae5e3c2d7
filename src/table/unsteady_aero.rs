//! [`UaParameters`]: the unsteady-aerodynamics (Beddoes–Leishman type) parameters of one
//! polar, as OpenFAST's AeroDyn reads them from an airfoil file (`InclUAdata True`).
//!
//! Names and meanings follow OpenFAST's `AirfoilInfo` (`modules/aerodyn/src/AirfoilInfo.f90`,
//! `ReadAFfile` and `CalculateUACoeffs`; the AeroDyn user guide's example airfoil file
//! `docs/source/user/aerodyn/examples/ad_polar_example.dat`). From the polar:
//!
//! * `alpha0`, `C_nalpha`: the zero-lift angle and the slope of the normal-force coefficient
//!   Cn = Cl·cos α + (Cd − Cd0)·sin α over the attached range of
//!   [`lift_slope`](super::lift_slope) (the same range and fit as the summary's lift slope,
//!   applied to Cn; a laminar drag bucket does not inflate it). When the trusted points give
//!   no attached range (at high Mach numbers the supercritical points can leave too few), the
//!   fit takes the converged points, supercritical ones included — the rows the file holds
//!   and OpenFAST interpolates — and says so ([`UaParameters::supercritical_fit`]).
//! * `alpha1`, `alpha2`: where the Kirchhoff separation point f, from
//!   Cn = C_nα·(α − α0)·((1 + √f)/2)², falls to 0.7 above and below α0 (AeroDyn's definition:
//!   "angle of attack at f = 0.7, approximately the stall angle"); searched on the table's
//!   lookup curve (the rows the file holds) outwards from the point of the attached range
//!   where Cn is closest to (or above) the attached line, in [`SEARCH_STEP_DEG`] steps, linear
//!   between steps.
//! * `Cn1`, `Cn2`: Cn at `alpha1` and `alpha2` (AeroDyn derives them the same way).
//! * `Cd0`, `Cm0`: Cd and Cm at `alpha0` ("2D drag coefficient value at 0-lift", "pitching
//!   moment coefficient … at 0-lift").
//! * `k0`: x̂_AC − 0.25 = −dCm/dCn over the attached range (the Cm slope by the same fit).
//!
//! Not derivable from a steady polar, at OpenFAST's defaults (`CalculateUACoeffs` and the
//! defaults of `ReadAFfile`'s `ParseVarWDefault` calls, which are the Beddoes–Leishman
//! constants of Leishman & Beddoes 1989 for the NACA 0012): `eta_e` 1, `T_f0` 3, `T_V0` 6,
//! `T_p` 1.7, `T_VL` 11, `b1` 0.14, `b2` 0.53, `b5` 5, `A1` 0.3, `A2` 0.7, `A5` 1, `St_sh` 0.19,
//! `x_cp_bar` 0.2, `UACutout` 45°, `filtCutOff` 0.5; `S1`–`S4`, `k1`–`k3`, `k1_hat` 0 (the
//! curve fits of the original model, `UAMod` 1, which current OpenFAST no longer offers).

use super::lift_slope::{attached_fit, median_slope, run_around_zero_lift, trusted, AttachedFit};
use super::PolarTable;
use crate::section::PolarPoint;
use crate::section::SectionAero;

/// Step of the search for `alpha1` and `alpha2` \[deg\].
pub const SEARCH_STEP_DEG: f64 = 0.05;

/// f at `alpha1` and `alpha2` (AeroDyn: "angle of attack at f = 0.7").
const F_AT_STALL: f64 = 0.7;

/// The unsteady-aerodynamics parameters of one polar (angles in degrees, slopes per radian),
/// in the order of an AeroDyn airfoil file.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UaParameters {
    /// Zero-lift angle.
    pub alpha0: f64,
    /// f = 0.7 above α0.
    pub alpha1: f64,
    /// f = 0.7 below α0.
    pub alpha2: f64,
    /// Recovery factor (OpenFAST's default 1).
    pub eta_e: f64,
    /// Attached-flow slope of Cn.
    pub c_nalpha: f64,
    /// Time constants T_f0, T_V0, T_p, T_VL (OpenFAST's defaults).
    pub t_f0: f64,
    /// See `t_f0`.
    pub t_v0: f64,
    /// See `t_f0`.
    pub t_p: f64,
    /// See `t_f0`.
    pub t_vl: f64,
    /// Indicial-response constants b1, b2, b5, A1, A2, A5 (OpenFAST's defaults).
    pub b1: f64,
    /// See `b1`.
    pub b2: f64,
    /// See `b1`.
    pub b5: f64,
    /// See `b1`.
    pub a1: f64,
    /// See `b1`.
    pub a2: f64,
    /// See `b1`.
    pub a5: f64,
    /// Separation-curve constants S1–S4 (0: unused by current OpenFAST).
    pub s: [f64; 4],
    /// Cn at `alpha1`.
    pub cn1: f64,
    /// Cn at `alpha2`.
    pub cn2: f64,
    /// Strouhal number of vortex shedding (OpenFAST's default 0.19).
    pub st_sh: f64,
    /// Cd at `alpha0`.
    pub cd0: f64,
    /// Cm at `alpha0`.
    pub cm0: f64,
    /// x̂_AC − 0.25 = −dCm/dCn over the attached range.
    pub k0: f64,
    /// Centre-of-pressure constants k1, k2, k3, k1_hat (0: unused by current OpenFAST).
    pub k: [f64; 4],
    /// Vortex centre-of-pressure constant (OpenFAST's default 0.2).
    pub x_cp_bar: f64,
    /// α above which unsteady aerodynamics is switched off (OpenFAST's default 45°).
    pub ua_cutout: f64,
    /// Reduced-frequency cut-off of the input filter (OpenFAST's default 0.5).
    pub filt_cutoff: f64,
    /// The α range C_nα was fitted on.
    pub fit_alpha: (f64, f64),
    /// The fit took supercritical points (the trusted ones gave no attached range).
    pub supercritical_fit: bool,
}

impl UaParameters {
    /// Name, value and unit-or-note of every line of the AeroDyn block, in file order.
    pub fn lines(&self) -> [(&'static str, f64, &'static str); 32] {
        let [s1, s2, s3, s4] = self.s;
        let [k1, k2, k3, k1_hat] = self.k;
        let default = "OpenFAST default";
        [
            ("alpha0", self.alpha0, "deg, zero lift"),
            ("alpha1", self.alpha1, "deg, f = 0.7 above alpha0"),
            ("alpha2", self.alpha2, "deg, f = 0.7 below alpha0"),
            ("eta_e", self.eta_e, default),
            ("C_nalpha", self.c_nalpha, "1/rad, attached-flow Cn slope"),
            ("T_f0", self.t_f0, default),
            ("T_V0", self.t_v0, default),
            ("T_p", self.t_p, default),
            ("T_VL", self.t_vl, default),
            ("b1", self.b1, default),
            ("b2", self.b2, default),
            ("b5", self.b5, default),
            ("A1", self.a1, default),
            ("A2", self.a2, default),
            ("A5", self.a5, default),
            ("S1", s1, "unused by current OpenFAST"),
            ("S2", s2, "unused by current OpenFAST"),
            ("S3", s3, "unused by current OpenFAST"),
            ("S4", s4, "unused by current OpenFAST"),
            ("Cn1", self.cn1, "Cn at alpha1"),
            ("Cn2", self.cn2, "Cn at alpha2"),
            ("St_sh", self.st_sh, default),
            ("Cd0", self.cd0, "Cd at alpha0"),
            ("Cm0", self.cm0, "Cm at alpha0"),
            ("k0", self.k0, "x_ac - 0.25 = -dCm/dCn"),
            ("k1", k1, "unused by current OpenFAST"),
            ("k2", k2, "unused by current OpenFAST"),
            ("k3", k3, "unused by current OpenFAST"),
            ("k1_hat", k1_hat, "unused by current OpenFAST"),
            ("x_cp_bar", self.x_cp_bar, default),
            ("UACutout", self.ua_cutout, "deg, OpenFAST default"),
            ("filtCutOff", self.filt_cutoff, default),
        ]
    }
}

/// The parameters of the polar at grid row (`i_re`, `i_mach`), from its trusted points, else
/// from its converged points; `None` when neither gives an attached range
/// (`attached_fit`) in which f falls to 0.7 on both sides within 90° of α0.
pub fn ua_parameters(table: &PolarTable, i_re: usize, i_mach: usize) -> Option<UaParameters> {
    let points = table.polar_at(i_re, i_mach)?;
    let converged: fn(&PolarPoint) -> bool = |p| p.converged;
    [trusted, converged].into_iter().find_map(|keep| {
        let (run, fit, supercritical_fit) = fitted_run(points, keep)?;
        from_fit(table, i_re, i_mach, run, fit, supercritical_fit)
    })
}

/// The parameters from the attached `fit` of `run`, points of the polar at (`i_re`,
/// `i_mach`).
fn from_fit(
    table: &PolarTable,
    i_re: usize,
    i_mach: usize,
    run: &[PolarPoint],
    fit: AttachedFit,
    supercritical_fit: bool,
) -> Option<UaParameters> {
    let (re, mach) = (table.re()[i_re], table.mach()[i_mach]);
    let alpha: Vec<f64> = run.iter().map(|p| p.alpha).collect();
    let alpha0 = fit.alpha_zero;
    let at0 = table.lookup(alpha0, re, mach);
    let cd0 = at0.cd;
    let normal = |a: f64, cl: f64, cd: f64| {
        let r = a.to_radians();
        cl * r.cos() + (cd - cd0) * r.sin()
    };
    let cn: Vec<f64> = run.iter().map(|p| normal(p.alpha, p.cl, p.cd)).collect();
    let cm: Vec<f64> = run.iter().map(|p| p.cm).collect();
    let c_nalpha = median_slope(&alpha, &cn, fit.first, fit.last);
    let cm_slope = median_slope(&alpha, &cm, fit.first, fit.last);
    let cn_at = |a: f64| {
        let l = table.lookup(a, re, mach);
        normal(a, l.cl, l.cd)
    };
    // Cn / Cn_attached at which f = 0.7: ((1 + √0.7) / 2)².
    let threshold = (0.5 * (1.0 + F_AT_STALL.sqrt())).powi(2);
    let ratio = |a: f64| cn_at(a) / (c_nalpha * (a - alpha0).to_radians());
    // Each search starts where the attached range holds Cn closest to (or above) the line:
    // the point of largest ratio at least 1° from α0 on that side (a laminar-bucket dip or
    // the first rounding of the curve inside the range does not count as stall).
    let start = |side: &mut dyn Iterator<Item = f64>, sign: f64| {
        side.filter(|a| (a - alpha0) * sign >= 1.0)
            .max_by(|a, b| ratio(*a).total_cmp(&ratio(*b)))
            .unwrap_or(alpha0 + sign)
    };
    let upper = start(&mut alpha[fit.first..=fit.last].iter().copied(), 1.0);
    let lower = start(&mut alpha[fit.first..=fit.last].iter().copied(), -1.0);
    let alpha1 = stall_crossing(upper, 1.0, alpha0, &ratio, threshold)?;
    let alpha2 = stall_crossing(lower, -1.0, alpha0, &ratio, threshold)?;
    Some(UaParameters {
        alpha0,
        alpha1,
        alpha2,
        eta_e: 1.0,
        c_nalpha,
        t_f0: 3.0,
        t_v0: 6.0,
        t_p: 1.7,
        t_vl: 11.0,
        b1: 0.14,
        b2: 0.53,
        b5: 5.0,
        a1: 0.3,
        a2: 0.7,
        a5: 1.0,
        s: [0.0; 4],
        cn1: cn_at(alpha1),
        cn2: cn_at(alpha2),
        st_sh: 0.19,
        cd0,
        cm0: at0.cm,
        k0: -cm_slope / c_nalpha,
        k: [0.0; 4],
        x_cp_bar: 0.2,
        ua_cutout: 45.0,
        filt_cutoff: 0.5,
        fit_alpha: (alpha[fit.first], alpha[fit.last]),
        supercritical_fit,
    })
}

/// The run around zero lift of the points that pass `keep`, and its attached fit; whether
/// the fit spans a supercritical point.
fn fitted_run(
    points: &[PolarPoint],
    keep: fn(&PolarPoint) -> bool,
) -> Option<(&[PolarPoint], AttachedFit, bool)> {
    let (first, last) = run_around_zero_lift(points, keep)?;
    let run = &points[first..=last];
    let alpha: Vec<f64> = run.iter().map(|p| p.alpha).collect();
    let cl: Vec<f64> = run.iter().map(|p| p.cl).collect();
    let fit = attached_fit(&alpha, &cl)?;
    let supercritical = run[fit.first..=fit.last]
        .iter()
        .any(|p| p.supercritical == Some(true));
    Some((run, fit, supercritical))
}

/// Where `ratio(α)` (Cn over the attached line) falls below `threshold` going away from α0 in
/// direction `sign` (+1 up, −1 down): from `start`, step outwards while the ratio stays at or
/// above the threshold, and interpolate linearly between the last two steps. `None` when the
/// ratio is below the threshold already at `start` or does not fall below it within 90° of
/// α0.
fn stall_crossing(
    start: f64,
    sign: f64,
    alpha0: f64,
    ratio: &dyn Fn(f64) -> f64,
    threshold: f64,
) -> Option<f64> {
    let above = |a: f64| ratio(a) >= threshold;
    if !above(start) {
        return None;
    }
    let step = sign * SEARCH_STEP_DEG;
    let mut a = start;
    loop {
        let next = a + step;
        if (next - alpha0) * sign > 90.0 {
            return None;
        }
        if !above(next) {
            let (ra, rn) = (ratio(a) - threshold, ratio(next) - threshold);
            return Some(a + step * ra / (ra - rn));
        }
        a = next;
    }
}
