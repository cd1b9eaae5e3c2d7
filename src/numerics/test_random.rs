//! Deterministic pseudo-random numbers for the unit tests (a 64-bit linear congruential
//! generator with Knuth's MMIX constants), so that the tests need no extra crate.

/// The generator's state.
pub(crate) struct Lcg(u64);

impl Lcg {
    /// A generator started at `seed`.
    pub(crate) fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next number, uniform in [0, 1) (53 random bits).
    pub(crate) fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// The next number, uniform in [−1, 1).
    pub(crate) fn symmetric(&mut self) -> f64 {
        self.unit() * 2.0 - 1.0
    }
}
