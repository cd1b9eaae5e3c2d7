//! Hand-tuned numerical kernels shared by the solver layers, private to the crate: nothing
//! here is physics, and nothing here is API.
//!
//! * [`dual`] — forward-mode derivative numbers: the closures and the boundary-layer
//!   equations are written once on them and their Jacobians follow exactly.
//! * [`dense`] — matrix–vector and dot products with a fixed summation order.
//! * [`small_dense`] — direct solves and inverses of 3×3 and 4×4 systems kept in registers.
//! * [`cycle`] — detection of an iteration caught in a cycle.
//! * [`roots`] — one-dimensional root finding on a bracket.
//! * [`elementary`] — branch-free ln and atan2 that vectorise inside a kernel loop.
//! * [`simd`] — AVX2 dispatch of a kernel and the vector-register hygiene around faer calls.

pub(crate) mod cycle;
pub(crate) mod dense;
pub(crate) mod dual;
pub(crate) mod elementary;
pub(crate) mod roots;
pub(crate) mod simd;
pub(crate) mod small_dense;
#[cfg(test)]
pub(crate) mod test_random;
