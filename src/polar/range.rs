//! Angle-of-attack ranges `A0:A1:DA` and the order in which a sweep visits them.

use crate::arguments::{self, ArgumentError};
use thiserror::Error;

/// Why an α range was rejected.
#[derive(Debug, Error, PartialEq)]
pub enum RangeError {
    /// The text is not `A0:A1:DA` or a single value.
    #[error("alpha range '{0}' is not A0:A1:DA or a single value")]
    Syntax(String),
    /// A field is not a finite number.
    #[error("alpha range '{text}': '{field}' is not a finite number")]
    Number {
        /// The whole range text.
        text: String,
        /// The offending field.
        field: String,
    },
    /// The step is zero.
    #[error("alpha range '{0}': step is 0")]
    ZeroStep(String),
    /// The step does not lead from A0 to A1 (wrong sign).
    #[error("alpha range '{0}' is empty: the step does not lead from A0 to A1")]
    Empty(String),
    /// An angle beyond ±180° (tables and their 360° extension cover one revolution).
    #[error("alpha range '{text}': '{field}' is outside -180…180 deg")]
    OutOfRange {
        /// The whole range text.
        text: String,
        /// The offending field.
        field: String,
    },
    /// The step is below the 10⁻⁹° resolution of the values, so two of them coincide.
    #[error(
        "alpha range '{text}': step {step} deg is below the 1e-9 deg resolution of the angles"
    )]
    StepTooSmall {
        /// The whole range text.
        text: String,
        /// The step.
        step: String,
    },
    /// Too many points (a typo such as a tiny step).
    #[error("alpha range '{text}' has {count} points (at most {max})")]
    TooMany {
        /// The whole range text.
        text: String,
        /// Number of points it would give.
        count: usize,
        /// The limit.
        max: usize,
    },
}

pub use crate::limits::MAX_ALPHA_POINTS;

/// Largest |α| (deg) a range may reach.
pub const MAX_ALPHA_DEG: f64 = 180.0;

/// Parse `A0:A1:DA` (degrees, inclusive of A1 within 1e-9 of a step) or a single value `A`;
/// every angle must lie within ±[`MAX_ALPHA_DEG`].
///
/// The values are `A0 + i·DA`, rounded to 1e-9 so that `-4:12:0.1` yields exactly `0.3` rather
/// than `0.30000000000000004`.
pub fn parse_alpha_range(text: &str) -> Result<Vec<f64>, RangeError> {
    let fields: Vec<&str> = text.split(':').map(str::trim).collect();
    let num = |f: &str| -> Result<f64, RangeError> {
        match f.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(RangeError::Number {
                text: crate::limits::short_text(text),
                field: crate::limits::short_text(f),
            }),
        }
    };
    let angle = |f: &str| -> Result<f64, RangeError> {
        let v = num(f)?;
        if v.abs() > MAX_ALPHA_DEG {
            return Err(RangeError::OutOfRange {
                text: crate::limits::short_text(text),
                field: crate::limits::short_text(f),
            });
        }
        Ok(v)
    };
    match fields.as_slice() {
        [a] => Ok(vec![angle(a)?]),
        [a0, a1, da] => {
            let (a0, a1, da) = (angle(a0)?, angle(a1)?, num(da)?);
            if da == 0.0 {
                return Err(RangeError::ZeroStep(crate::limits::short_text(text)));
            }
            let span = (a1 - a0) / da;
            if span < -1e-9 {
                return Err(RangeError::Empty(crate::limits::short_text(text)));
            }
            let n = (span + 1e-9).floor();
            if n + 1.0 > MAX_ALPHA_POINTS as f64 {
                return Err(RangeError::TooMany {
                    text: crate::limits::short_text(text),
                    count: (n + 1.0).min(usize::MAX as f64) as usize,
                    max: MAX_ALPHA_POINTS,
                });
            }
            let values: Vec<f64> = (0..=n as usize)
                .map(|i| round9(a0 + i as f64 * da))
                .collect();
            if values.windows(2).any(|w| w[0] == w[1]) {
                return Err(RangeError::StepTooSmall {
                    text: crate::limits::short_text(text),
                    step: crate::limits::short_number(da),
                });
            }
            Ok(values)
        }
        _ => Err(RangeError::Syntax(crate::limits::short_text(text))),
    }
}

/// An α list given as values (the Python package's arrays) rather than as a range: not empty,
/// finite, none twice ([`arguments::distinct`]), every angle within ±[`MAX_ALPHA_DEG`] and at most
/// [`MAX_ALPHA_POINTS`] of them. `name` is the argument as the caller calls it.
pub fn check_alphas(name: &str, alphas: &[f64]) -> Result<(), ArgumentError> {
    if alphas.len() > MAX_ALPHA_POINTS {
        return Err(ArgumentError::with_text(
            name,
            "",
            format!("{} values (at most {MAX_ALPHA_POINTS})", alphas.len()),
        ));
    }
    arguments::distinct(name, alphas)?;
    match alphas.iter().find(|a| a.abs() > MAX_ALPHA_DEG) {
        Some(a) => Err(ArgumentError::new(name, *a, "outside -180…180 deg")),
        None => Ok(()),
    }
}

/// Round to 9 decimals (removes binary noise from `A0 + i·DA`).
fn round9(v: f64) -> f64 {
    let r = (v * 1e9).round() / 1e9;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

/// The order in which a warm-started sweep visits `alphas`: start at the value nearest 0°,
/// march up to the largest, then return to the start and march down (as XFOIL users do).
///
/// Returns two index lists into `alphas` after sorting by value: `(upward, downward)`, where
/// `upward` begins with the start point and `downward` does not contain it.
pub fn march_order(alphas: &[f64]) -> (Vec<usize>, Vec<usize>) {
    let mut idx: Vec<usize> = (0..alphas.len()).collect();
    idx.sort_by(|&a, &b| alphas[a].total_cmp(&alphas[b]));
    let Some(start) = (0..idx.len()).min_by(|&a, &b| {
        alphas[idx[a]]
            .abs()
            .total_cmp(&alphas[idx[b]].abs())
            .then(a.cmp(&b))
    }) else {
        return (Vec::new(), Vec::new());
    };
    let up = idx[start..].to_vec();
    let down = idx[..start].iter().rev().copied().collect();
    (up, down)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges() {
        assert_eq!(parse_alpha_range("-4:12:2").unwrap().len(), 9);
        assert_eq!(parse_alpha_range("-4:12:0.1").unwrap()[43], 0.3);
        assert_eq!(
            parse_alpha_range("12:-4:-4").unwrap(),
            vec![12.0, 8.0, 4.0, 0.0, -4.0]
        );
        assert_eq!(parse_alpha_range("3").unwrap(), vec![3.0]);
        assert_eq!(
            parse_alpha_range("0:1:0.3").unwrap(),
            vec![0.0, 0.3, 0.6, 0.9]
        );
        assert!(matches!(
            parse_alpha_range("0:4:0"),
            Err(RangeError::ZeroStep(_))
        ));
        assert!(matches!(
            parse_alpha_range("4:0:1"),
            Err(RangeError::Empty(_))
        ));
        assert!(matches!(
            parse_alpha_range("a:1:1"),
            Err(RangeError::Number { .. })
        ));
        assert!(matches!(
            parse_alpha_range("nan:1:1"),
            Err(RangeError::Number { .. })
        ));
        assert!(matches!(
            parse_alpha_range("1:2"),
            Err(RangeError::Syntax(_))
        ));
        assert!(matches!(
            parse_alpha_range("0:180:1e-4"),
            Err(RangeError::TooMany { .. })
        ));
        assert_eq!(parse_alpha_range("-180:180:90").unwrap().len(), 5);
        // Values that coincide after rounding are refused before any solve.
        assert!(matches!(
            parse_alpha_range("0:1e-10:1e-10"),
            Err(RangeError::StepTooSmall { .. })
        ));
        assert!(matches!(
            parse_alpha_range("5:5.000000003:3e-10"),
            Err(RangeError::StepTooSmall { .. })
        ));
        for bad in ["170:190:10", "1e300", "-180.5:0:1"] {
            assert!(
                matches!(parse_alpha_range(bad), Err(RangeError::OutOfRange { .. })),
                "{bad}"
            );
        }
    }

    #[test]
    fn alpha_lists() {
        assert!(check_alphas("alpha", &[-180.0, 0.0, 180.0]).is_ok());
        let msg = |a: &[f64]| check_alphas("alpha", a).unwrap_err().to_string();
        assert_eq!(msg(&[0.0, 180.5]), "alpha 180.5: outside -180…180 deg");
        assert_eq!(msg(&[1.0, 1.0]), "alpha 1: given twice");
        assert_eq!(msg(&[]), "alpha: no values given");
        let many = vec![0.0; MAX_ALPHA_POINTS + 1];
        assert_eq!(msg(&many), "alpha: 100001 values (at most 100000)");
    }

    #[test]
    fn order_starts_near_zero() {
        let a = [-4.0, -2.0, 0.5, 2.0, 4.0];
        let (up, down) = march_order(&a);
        assert_eq!(up, vec![2, 3, 4]);
        assert_eq!(down, vec![1, 0]);
        let (up, down) = march_order(&[5.0, 3.0, 4.0]);
        assert_eq!(up, vec![1, 2, 0]);
        assert!(down.is_empty());
    }
}
