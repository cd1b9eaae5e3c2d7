//! One-dimensional root finding on a bracket: the one root finder of the crate.
//!
//! A root is first bracketed by the caller (a scan of its own physics, or
//! [`first_rising_bracket`] on a grid), then refined by [`bracketed_root`]: secant steps with
//! the Illinois modification of regula falsi (Dowell & Jarratt 1971, "A modified regula falsi
//! method for computing the root of an equation", BIT 11), which keeps the bracket — so the
//! iteration cannot leave the interval the physics chose — and converges superlinearly where
//! plain regula falsi stalls on one side.

use std::convert::Infallible;

/// Root of `f` in the bracket [a, b] given with its end values (f(a)·f(b) ≤ 0): Illinois
/// steps until the bracket is narrower than `xtol` or an end value is exactly zero, at most
/// `max_iterations` evaluations of `f`. Returns the newest iterate; an error of `f` stops the
/// search and is returned.
pub(crate) fn bracketed_root<E>(
    mut f: impl FnMut(f64) -> Result<f64, E>,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
    xtol: f64,
    max_iterations: usize,
) -> Result<f64, E> {
    // Whether the last step kept `a` (a repeat then halves its value: the Illinois
    // modification).
    let mut kept_a = false;
    for _ in 0..max_iterations {
        if fa == 0.0 {
            return Ok(a);
        }
        if fb == 0.0 || (b - a).abs() < xtol {
            return Ok(b);
        }
        let mut c = (a * fb - b * fa) / (fb - fa);
        if !c.is_finite() || c <= a.min(b) || c >= a.max(b) {
            c = 0.5 * (a + b);
        }
        let fc = f(c)?;
        if fc * fb < 0.0 {
            a = b;
            fa = fb;
            kept_a = false;
        } else {
            if kept_a {
                fa *= 0.5;
            }
            kept_a = true;
        }
        b = c;
        fb = fc;
    }
    Ok(b)
}

/// [`bracketed_root`] of a function that cannot fail.
pub(crate) fn bracketed_root_of(
    mut f: impl FnMut(f64) -> f64,
    a: (f64, f64),
    b: (f64, f64),
    xtol: f64,
    max_iterations: usize,
) -> f64 {
    match bracketed_root(|x| Ok::<f64, Infallible>(f(x)), a, b, xtol, max_iterations) {
        Ok(x) => x,
        Err(never) => match never {},
    }
}

/// The first interval of the grid `xs` (in the order given) over which `f` rises through
/// zero, f(x_k) < 0 ≤ f(x_{k+1}), as the two ends with their values; `None` if there is none.
pub(crate) fn first_rising_bracket(
    xs: impl IntoIterator<Item = f64>,
    mut f: impl FnMut(f64) -> f64,
) -> Option<((f64, f64), (f64, f64))> {
    let mut previous: Option<(f64, f64)> = None;
    for x in xs {
        let fx = f(x);
        if let Some((xp, fp)) = previous {
            if fp < 0.0 && fx >= 0.0 {
                return Some(((xp, fp), (x, fx)));
            }
        }
        previous = Some((x, fx));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_a_cube_root_within_the_tolerance() {
        let f = |x: f64| x * x * x - 2.0;
        let x = bracketed_root_of(f, (0.0, f(0.0)), (2.0, f(2.0)), 1e-13, 100);
        assert!((x - 2f64.cbrt()).abs() < 1e-12, "{x}");
    }

    #[test]
    fn stays_in_the_bracket_and_stops_on_errors() {
        // Two roots (±1); the bracket [0, 3] holds only +1.
        let f = |x: f64| x * x - 1.0;
        let x = bracketed_root_of(f, (0.0, f(0.0)), (3.0, f(3.0)), 1e-12, 100);
        assert!((x - 1.0).abs() < 1e-11, "{x}");
        let mut calls = 0;
        let r: Result<f64, &str> = bracketed_root(
            |_| {
                calls += 1;
                Err("no value")
            },
            (0.0, -1.0),
            (1.0, 1.0),
            1e-12,
            100,
        );
        assert_eq!((r, calls), (Err("no value"), 1));
    }

    #[test]
    fn the_first_rising_interval_is_found() {
        let xs = (0..=20).map(|k| f64::from(k) * 0.5);
        // Falls through zero at 1, rises through it at 3 and again at 7.
        let f = |x: f64| -((x - 1.0) * (x - 3.0) * (x - 7.0));
        let ((a, fa), (b, fb)) = first_rising_bracket(xs, f).unwrap();
        assert_eq!((a, b), (2.5, 3.0));
        assert!(fa < 0.0 && fb >= 0.0);
        assert!(first_rising_bracket([0.0, 1.0], |_| 1.0).is_none());
    }
}
