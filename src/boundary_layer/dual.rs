//! Forward-mode derivative numbers for the chain rule through the interval equations.
//!
//! A [`Dual`] carries a value and its gradient with respect to the [`NVARS`] = 10 primary
//! variables of one interval: station 1 `(s, θ, δ*, u, ξ)` in slots 0..5 and station 2 in
//! slots 5..10 (the column order of XFOIL's VS1/VS2 matrices, xblsys.f BLSYS). The closures
//! supply their own analytic partials; [`Dual::chain`] combines them with the gradients of
//! their arguments, so the Jacobians of the discrete equations follow exactly from the
//! residual expressions without hand-expanded sensitivity bookkeeping.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// Number of independent variables of one interval (5 per station, 2 stations).
pub const NVARS: usize = 10;

/// A value together with its gradient with respect to the interval's primary variables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dual {
    /// Function value.
    pub v: f64,
    /// Partial derivatives with respect to the [`NVARS`] primary variables.
    pub g: [f64; NVARS],
}

impl Dual {
    /// A constant (zero gradient).
    pub fn constant(v: f64) -> Self {
        Self { v, g: [0.0; NVARS] }
    }

    /// An independent variable occupying gradient slot `slot`.
    pub fn variable(v: f64, slot: usize) -> Self {
        let mut g = [0.0; NVARS];
        g[slot] = 1.0;
        Self { v, g }
    }

    /// Chain rule: the value `value` of a function whose partials with respect to the
    /// arguments `args` are `partials` (same order).
    pub fn chain(value: f64, partials: &[f64], args: &[Dual]) -> Self {
        let mut g = [0.0; NVARS];
        for (p, a) in partials.iter().zip(args) {
            if *p != 0.0 {
                for (gi, ai) in g.iter_mut().zip(a.g.iter()) {
                    *gi += p * ai;
                }
            }
        }
        Self { v: value, g }
    }

    /// Applies a scalar function with value `f` and derivative `df` at `self.v`.
    fn map(self, f: f64, df: f64) -> Self {
        let mut g = self.g;
        for gi in g.iter_mut() {
            *gi *= df;
        }
        Self { v: f, g }
    }

    /// Natural logarithm.
    pub fn ln(self) -> Self {
        self.map(self.v.ln(), 1.0 / self.v)
    }

    /// Exponential.
    pub fn exp(self) -> Self {
        let e = self.v.exp();
        self.map(e, e)
    }

    /// Square root.
    pub fn sqrt(self) -> Self {
        let r = self.v.sqrt();
        self.map(r, 0.5 / r)
    }

    /// Real power with a constant exponent.
    pub fn powf(self, p: f64) -> Self {
        let f = self.v.powf(p);
        self.map(f, p * self.v.powf(p - 1.0))
    }

    /// Square.
    pub fn sq(self) -> Self {
        self * self
    }

    /// Hyperbolic tangent.
    pub fn tanh(self) -> Self {
        let t = self.v.tanh();
        self.map(t, 1.0 - t * t)
    }

    /// Absolute value.
    pub fn abs(self) -> Self {
        if self.v < 0.0 {
            -self
        } else {
            self
        }
    }

    /// The larger of `self` and the constant `c` (a clamp kills the gradient).
    pub fn max_const(self, c: f64) -> Self {
        if self.v < c {
            Self::constant(c)
        } else {
            self
        }
    }

    /// The smaller of `self` and the constant `c` (a clamp kills the gradient).
    pub fn min_const(self, c: f64) -> Self {
        if self.v > c {
            Self::constant(c)
        } else {
            self
        }
    }

    /// Gradient slots `offset..offset+5` (one station's columns).
    pub fn station_grad(&self, offset: usize) -> [f64; 5] {
        let mut out = [0.0; 5];
        out.copy_from_slice(&self.g[offset..offset + 5]);
        out
    }
}

impl Add for Dual {
    type Output = Dual;
    fn add(self, o: Dual) -> Dual {
        let mut g = self.g;
        for (gi, oi) in g.iter_mut().zip(o.g.iter()) {
            *gi += oi;
        }
        Dual { v: self.v + o.v, g }
    }
}

impl Sub for Dual {
    type Output = Dual;
    fn sub(self, o: Dual) -> Dual {
        let mut g = self.g;
        for (gi, oi) in g.iter_mut().zip(o.g.iter()) {
            *gi -= oi;
        }
        Dual { v: self.v - o.v, g }
    }
}

impl Mul for Dual {
    type Output = Dual;
    fn mul(self, o: Dual) -> Dual {
        let mut g = [0.0; NVARS];
        for (i, gi) in g.iter_mut().enumerate() {
            *gi = self.g[i] * o.v + self.v * o.g[i];
        }
        Dual { v: self.v * o.v, g }
    }
}

impl Div for Dual {
    type Output = Dual;
    fn div(self, o: Dual) -> Dual {
        let q = self.v / o.v;
        let mut g = [0.0; NVARS];
        for (i, gi) in g.iter_mut().enumerate() {
            *gi = (self.g[i] - q * o.g[i]) / o.v;
        }
        Dual { v: q, g }
    }
}

impl Neg for Dual {
    type Output = Dual;
    fn neg(self) -> Dual {
        self.map(-self.v, -1.0)
    }
}

impl Add<f64> for Dual {
    type Output = Dual;
    fn add(self, c: f64) -> Dual {
        Dual {
            v: self.v + c,
            g: self.g,
        }
    }
}

impl Sub<f64> for Dual {
    type Output = Dual;
    fn sub(self, c: f64) -> Dual {
        Dual {
            v: self.v - c,
            g: self.g,
        }
    }
}

impl Mul<f64> for Dual {
    type Output = Dual;
    fn mul(self, c: f64) -> Dual {
        self.map(self.v * c, c)
    }
}

impl Div<f64> for Dual {
    type Output = Dual;
    fn div(self, c: f64) -> Dual {
        self.map(self.v / c, 1.0 / c)
    }
}

impl Add<Dual> for f64 {
    type Output = Dual;
    fn add(self, d: Dual) -> Dual {
        d + self
    }
}

impl Sub<Dual> for f64 {
    type Output = Dual;
    fn sub(self, d: Dual) -> Dual {
        d.map(self - d.v, -1.0)
    }
}

impl Mul<Dual> for f64 {
    type Output = Dual;
    fn mul(self, d: Dual) -> Dual {
        d * self
    }
}

impl Div<Dual> for f64 {
    type Output = Dual;
    fn div(self, d: Dual) -> Dual {
        let q = self / d.v;
        d.map(q, -q / d.v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quotient_and_log_rules() {
        let a = Dual::variable(2.0, 0);
        let b = Dual::variable(3.0, 1);
        let f = (a * b).ln() / b + a.powf(1.5);
        // d/da = 1/(a b) * b / b + 1.5 a^0.5 = 1/(a b) + 1.5 sqrt(a)
        let dfa = 1.0 / 3.0 / 2.0 + 1.5 * 2f64.sqrt();
        // d/db = (1/b * b - ln(ab)) / b^2
        let dfb = (1.0 - 6f64.ln()) / 9.0;
        assert!((f.g[0] - dfa).abs() < 1e-14);
        assert!((f.g[1] - dfb).abs() < 1e-14);
    }
}
