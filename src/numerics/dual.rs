//! Forward-mode derivative numbers: a value with its gradient with respect to `N` independent
//! variables. A formula written once on [`Dual`] numbers gives its value and its exact partial
//! derivatives (the chain rule applied operation by operation), so the closures and the
//! discrete boundary-layer equations need no hand-expanded sensitivity bookkeeping. Every
//! operation acts on the value and on each gradient slot separately: the number of slots never
//! changes a value.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// A value together with its gradient with respect to `N` independent variables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Dual<const N: usize> {
    /// Function value.
    pub v: f64,
    /// Partial derivatives with respect to the `N` independent variables.
    pub g: [f64; N],
}

impl<const N: usize> Dual<N> {
    /// A constant (zero gradient).
    pub fn constant(v: f64) -> Self {
        Self { v, g: [0.0; N] }
    }

    /// An independent variable occupying gradient slot `slot`.
    pub fn variable(v: f64, slot: usize) -> Self {
        let mut g = [0.0; N];
        g[slot] = 1.0;
        Self { v, g }
    }

    /// The same number with its gradient placed at slots `offset..offset+N` of a longer
    /// gradient (a station's derivatives placed among the interval's variables).
    pub fn embed<const M: usize>(self, offset: usize) -> Dual<M> {
        let mut g = [0.0; M];
        g[offset..offset + N].copy_from_slice(&self.g);
        Dual { v: self.v, g }
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

    /// Real power with a constant exponent (one `powf`: the derivative is p·f/v, except at
    /// v = 0).
    pub fn powf(self, p: f64) -> Self {
        let f = self.v.powf(p);
        let df = if self.v != 0.0 {
            p * f / self.v
        } else {
            p * self.v.powf(p - 1.0)
        };
        self.map(f, df)
    }

    /// Integer power.
    pub fn powi(self, n: i32) -> Self {
        let f = self.v.powi(n);
        self.map(f, f64::from(n) * self.v.powi(n - 1))
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

    /// Gradient slots `offset..offset+M` (e.g. one station's columns); `offset + M ≤ N`.
    pub fn slots<const M: usize>(&self, offset: usize) -> [f64; M] {
        let mut out = [0.0; M];
        out.copy_from_slice(&self.g[offset..offset + M]);
        out
    }
}

impl<const N: usize> Add for Dual<N> {
    type Output = Dual<N>;
    fn add(self, o: Dual<N>) -> Dual<N> {
        let mut g = self.g;
        for (gi, oi) in g.iter_mut().zip(o.g.iter()) {
            *gi += oi;
        }
        Dual { v: self.v + o.v, g }
    }
}

impl<const N: usize> Sub for Dual<N> {
    type Output = Dual<N>;
    fn sub(self, o: Dual<N>) -> Dual<N> {
        let mut g = self.g;
        for (gi, oi) in g.iter_mut().zip(o.g.iter()) {
            *gi -= oi;
        }
        Dual { v: self.v - o.v, g }
    }
}

impl<const N: usize> Mul for Dual<N> {
    type Output = Dual<N>;
    fn mul(self, o: Dual<N>) -> Dual<N> {
        let mut g = [0.0; N];
        for (i, gi) in g.iter_mut().enumerate() {
            *gi = self.g[i] * o.v + self.v * o.g[i];
        }
        Dual { v: self.v * o.v, g }
    }
}

impl<const N: usize> Div for Dual<N> {
    type Output = Dual<N>;
    fn div(self, o: Dual<N>) -> Dual<N> {
        // One division: the gradient is scaled by the reciprocal.
        let r = 1.0 / o.v;
        let q = self.v * r;
        let mut g = [0.0; N];
        for (i, gi) in g.iter_mut().enumerate() {
            *gi = (self.g[i] - q * o.g[i]) * r;
        }
        Dual { v: q, g }
    }
}

impl<const N: usize> Neg for Dual<N> {
    type Output = Dual<N>;
    fn neg(self) -> Dual<N> {
        self.map(-self.v, -1.0)
    }
}

impl<const N: usize> Add<f64> for Dual<N> {
    type Output = Dual<N>;
    fn add(self, c: f64) -> Dual<N> {
        Dual {
            v: self.v + c,
            g: self.g,
        }
    }
}

impl<const N: usize> Sub<f64> for Dual<N> {
    type Output = Dual<N>;
    fn sub(self, c: f64) -> Dual<N> {
        Dual {
            v: self.v - c,
            g: self.g,
        }
    }
}

impl<const N: usize> Mul<f64> for Dual<N> {
    type Output = Dual<N>;
    fn mul(self, c: f64) -> Dual<N> {
        self.map(self.v * c, c)
    }
}

impl<const N: usize> Div<f64> for Dual<N> {
    type Output = Dual<N>;
    fn div(self, c: f64) -> Dual<N> {
        self.map(self.v / c, 1.0 / c)
    }
}

impl<const N: usize> Add<Dual<N>> for f64 {
    type Output = Dual<N>;
    fn add(self, d: Dual<N>) -> Dual<N> {
        d + self
    }
}

impl<const N: usize> Sub<Dual<N>> for f64 {
    type Output = Dual<N>;
    fn sub(self, d: Dual<N>) -> Dual<N> {
        d.map(self - d.v, -1.0)
    }
}

impl<const N: usize> Mul<Dual<N>> for f64 {
    type Output = Dual<N>;
    fn mul(self, d: Dual<N>) -> Dual<N> {
        d * self
    }
}

impl<const N: usize> Div<Dual<N>> for f64 {
    type Output = Dual<N>;
    fn div(self, d: Dual<N>) -> Dual<N> {
        let q = self / d.v;
        d.map(q, -q / d.v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quotient_and_log_rules() {
        let a: Dual<2> = Dual::variable(2.0, 0);
        let b: Dual<2> = Dual::variable(3.0, 1);
        let f = (a * b).ln() / b + a.powf(1.5);
        // d/da = 1/(a b) * b / b + 1.5 a^0.5 = 1/(a b) + 1.5 sqrt(a)
        let dfa = 1.0 / 3.0 / 2.0 + 1.5 * 2f64.sqrt();
        // d/db = (1/b * b - ln(ab)) / b^2
        let dfb = (1.0 - 6f64.ln()) / 9.0;
        assert!((f.g[0] - dfa).abs() < 1e-14);
        assert!((f.g[1] - dfb).abs() < 1e-14);
    }
}
