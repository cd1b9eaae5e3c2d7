//! Numerical building blocks shared by the layers, private to the crate.
//!
//! * [`roots`] — one-dimensional root finding on a bracket.

pub(crate) mod roots;
