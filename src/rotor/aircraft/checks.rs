//! Range checks of preset values, each failing with [`AircraftError::Invalid`] naming the
//! field.

use super::AircraftError;
use std::borrow::Cow;

/// `value` must be finite and positive.
pub(super) fn positive(field: &'static str, value: f64) -> Result<(), AircraftError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(AircraftError::Invalid {
            field,
            value,
            reason: "must be a positive number".into(),
        })
    }
}
/// `value` must be finite and not negative.
pub(super) fn non_negative(field: &'static str, value: f64) -> Result<(), AircraftError> {
    if value.is_finite() && value >= 0.0 {
        Ok(())
    } else {
        Err(AircraftError::Invalid {
            field,
            value,
            reason: "must be zero or positive".into(),
        })
    }
}
/// `value` must lie in [lo, hi].
pub(super) fn in_range(
    field: &'static str,
    value: f64,
    (lo, hi): (f64, f64),
    reason: impl Into<Cow<'static, str>>,
) -> Result<(), AircraftError> {
    if value >= lo && value <= hi {
        Ok(())
    } else {
        Err(AircraftError::Invalid {
            field,
            value,
            reason: reason.into(),
        })
    }
}

/// Each entry of `values` satisfies `ok`; else the first that does not, with `reason`.
pub(super) fn each(
    field: &'static str,
    values: &[f64],
    ok: impl Fn(f64) -> bool,
    reason: &'static str,
) -> Result<(), AircraftError> {
    match values.iter().find(|&&v| !ok(v)) {
        Some(&value) => Err(AircraftError::Invalid {
            field,
            value,
            reason: reason.into(),
        }),
        None => Ok(()),
    }
}

/// `values` strictly increase.
pub(super) fn increasing(field: &'static str, values: &[f64]) -> Result<(), AircraftError> {
    match values
        .windows(2)
        .find(|w| w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater))
    {
        Some(w) => Err(AircraftError::Invalid {
            field,
            value: w[1],
            reason: "must increase strictly".into(),
        }),
        None => Ok(()),
    }
}

/// `values` has `len` entries (the length of `of`).
pub(super) fn same_length(
    field: &'static str,
    values: &[f64],
    len: usize,
    of: &'static str,
) -> Result<(), AircraftError> {
    if values.len() == len {
        Ok(())
    } else {
        Err(AircraftError::Invalid {
            field,
            value: values.len() as f64,
            reason: format!("entries: must be as many as {of} ({len})").into(),
        })
    }
}
