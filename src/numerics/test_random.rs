//! Deterministic pseudo-random numbers for the tests (a 64-bit linear congruential generator
//! with Knuth's MMIX constants), so that the tests need no extra crate. The integration tests
//! include this same file (`#[path]`), so some of its methods serve only them.
#![allow(dead_code)]

/// The generator's state.
pub(crate) struct Lcg(u64);

impl Lcg {
    /// A generator started at `seed`.
    pub(crate) fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next 53 random bits (the state's high bits), uniform in [0, 2⁵³).
    pub(crate) fn bits(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0 >> 11
    }

    /// The next number, uniform in [0, 1) (53 random bits).
    pub(crate) fn unit(&mut self) -> f64 {
        self.bits() as f64 / (1u64 << 53) as f64
    }

    /// The next number, uniform in [−1, 1).
    pub(crate) fn symmetric(&mut self) -> f64 {
        self.unit() * 2.0 - 1.0
    }

    /// The next number, uniform in [a, b).
    pub(crate) fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }
}
