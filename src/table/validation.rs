//! The checks every [`PolarTable`](super::PolarTable) passes when it is made (so on every read
//! and before every write): increasing axes, sound metadata, non-empty polars of distinct α
//! and plausible converged points, so that whatever is written can be read back.

use super::error::TableError;
use super::meta::TableMeta;
use crate::inviscid::MAX_SECTION_CL;
use crate::limits::{short_number, short_text, MAX_TABLE_POINTS};
use crate::section::{PolarPoint, TransitionField};

/// Non-empty and strictly increasing.
pub(super) fn check_axis(name: &'static str, axis: &[f64]) -> Result<(), TableError> {
    if axis.is_empty() {
        return Err(TableError::EmptyAxis(name));
    }
    for w in axis.windows(2) {
        if w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater) {
            return Err(TableError::AxisOrder {
                axis: name,
                previous: w[0],
                value: w[1],
            });
        }
    }
    Ok(())
}

/// Slack of a converged point's transition location beyond the chord, [0, 1]: the solver reports
/// x/c of the transition point along the surface, and the corner points of a blunt trailing edge
/// lie a little aft of the chord line's end (a Clark Y normalised on its chord line, 0.12 % c
/// thick at the trailing edge: x/c up to 1.00002).
pub const XTR_SLACK: f64 = 1e-3;

/// Plausibility bounds of the coefficients of a converged point: |Cl| ≤ 4π (the Joukowski
/// bound, [`MAX_SECTION_CL`]), Cd ≤ 4 (twice a flat plate normal to the flow, Cd ≈ 2,
/// Hoerner 1965 §3), |Cm| ≤ 4 (ten times the flat plate's quarter-chord moment at 90°).
/// A value beyond is not a section coefficient (`Cl 1e300` at a converged point).
pub const COEFFICIENT_BOUNDS: [(&str, f64); 3] = [("cl", MAX_SECTION_CL), ("cd", 4.0), ("cm", 4.0)];

/// Check the metadata: the transition setting by its rule ([`Transition::check_recorded`]:
/// N_crit positive, trips in [0, 1], each may be NaN, unknown), a thickness in (0, 1) or
/// unknown, names without control characters (they head text files).
///
/// [`Transition::check_recorded`]: crate::section::Transition::check_recorded
pub(super) fn check_meta(meta: &TableMeta) -> Result<(), TableError> {
    let bad = |field, value: f64, rule| TableError::BadMeta {
        field,
        value: short_number(value),
        rule,
    };
    if let Err(e) = meta.transition.check_recorded() {
        // The fields as the files name them: one `ncrit` when both surfaces share it.
        let field = match (e.field, meta.transition.common_ncrit()) {
            (TransitionField::NcritTop | TransitionField::NcritBot, Some(_)) => "ncrit",
            (TransitionField::NcritTop, None) => "ncrit_top",
            (TransitionField::NcritBot, None) => "ncrit_bot",
            (TransitionField::XtrTop, _) => "xtr_top_set",
            (TransitionField::XtrBot, _) => "xtr_bot_set",
        };
        return Err(bad(field, e.value, e.field.range()));
    }
    let t = meta.thickness;
    if !(t.is_nan() || (t > 0.0 && t < 1.0)) {
        return Err(bad("thickness", t, "in (0, 1)"));
    }
    for (field, text) in [("airfoil", &meta.airfoil), ("solver", &meta.solver)] {
        if text.chars().any(char::is_control) {
            return Err(TableError::BadMeta {
                field,
                value: format!("{:?}", short_text(text)),
                rule: "text without control characters or line breaks",
            });
        }
    }
    Ok(())
}

/// Sort a polar by α and check α and the converged coefficients.
pub(super) fn check_polar(re: f64, mach: f64, polar: &mut [PolarPoint]) -> Result<(), TableError> {
    if polar.is_empty() {
        return Err(TableError::EmptyPolar { re, mach });
    }
    for p in polar.iter() {
        if !p.alpha.is_finite() {
            return Err(TableError::NotFinite {
                field: "alpha",
                value: p.alpha,
                re,
                mach,
                alpha: p.alpha,
            });
        }
        if p.alpha.abs() > 180.0 {
            return Err(TableError::AlphaRange {
                re,
                mach,
                alpha: p.alpha,
            });
        }
        if p.converged {
            for (field, value) in [("cl", p.cl), ("cd", p.cd), ("cm", p.cm)] {
                if !value.is_finite() {
                    return Err(TableError::NotFinite {
                        field,
                        value,
                        re,
                        mach,
                        alpha: p.alpha,
                    });
                }
            }
            if p.cd < 0.0 {
                return Err(TableError::NegativeDrag {
                    re,
                    mach,
                    alpha: p.alpha,
                    cd: p.cd,
                });
            }
            // NaN: unknown (a C81 file carries no transition or separation locations).
            for (field, value) in [
                ("xtr_top", p.xtr_top),
                ("xtr_bot", p.xtr_bot),
                ("xsep_top", p.xsep_top),
                ("xsep_bot", p.xsep_bot),
            ] {
                if !(value.is_nan() || (-XTR_SLACK..=1.0 + XTR_SLACK).contains(&value)) {
                    return Err(TableError::TransitionRange {
                        field,
                        value,
                        re,
                        mach,
                        alpha: p.alpha,
                    });
                }
            }
            for ((field, bound), value) in COEFFICIENT_BOUNDS.into_iter().zip([p.cl, p.cd, p.cm]) {
                if value.abs() > bound {
                    return Err(TableError::Implausible {
                        field,
                        value,
                        bound,
                        re,
                        mach,
                        alpha: p.alpha,
                    });
                }
            }
        }
    }
    polar.sort_by(|a, b| a.alpha.total_cmp(&b.alpha));
    if let Some(w) = polar.windows(2).find(|w| w[0].alpha == w[1].alpha) {
        return Err(TableError::DuplicateAlpha {
            re,
            mach,
            alpha: w[0].alpha,
        });
    }
    Ok(())
}

/// At most [`MAX_TABLE_POINTS`] points in all.
pub(super) fn check_size(polars: &[Vec<PolarPoint>]) -> Result<(), TableError> {
    let points: usize = polars.iter().map(Vec::len).sum();
    if points > MAX_TABLE_POINTS {
        return Err(TableError::TooManyPoints {
            points,
            limit: MAX_TABLE_POINTS,
        });
    }
    Ok(())
}

/// A table computed by polargen (its solver name starts with `polargen`) keeps every α of its
/// grid in every polar, converged or not: a polar with other α values than the first one is
/// refused, so that a file cut at a row boundary inside its last polar (or edited) does not
/// pass for a table. Tables of other codes may differ from polar to polar (XFOIL drops the
/// points it cannot converge) and are not checked. `polars` are sorted by α, Re-major on the
/// axes `re` × `mach`.
pub(super) fn check_shared_alphas(
    meta: &TableMeta,
    re: &[f64],
    mach: &[f64],
    polars: &[Vec<PolarPoint>],
) -> Result<(), TableError> {
    if !meta.solver.starts_with("polargen") {
        return Ok(());
    }
    let Some(first) = polars.first() else {
        return Ok(());
    };
    let same = |p: &[PolarPoint]| {
        p.len() == first.len() && p.iter().zip(first).all(|(a, b)| a.alpha == b.alpha)
    };
    match polars.iter().position(|p| !same(p)) {
        None => Ok(()),
        Some(k) => Err(TableError::AlphaListDiffers {
            re: re[k / mach.len()],
            mach: mach[k % mach.len()],
            got: polars[k].len(),
            expected: first.len(),
            last_alpha: polars[k].last().map_or(f64::NAN, |p| p.alpha),
        }),
    }
}
