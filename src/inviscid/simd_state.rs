//! Vector-register state hygiene between faer's dense kernels and the scalar panel kernels.
//!
//! faer's AVX-512 matrix kernels can return with the upper halves of the vector registers
//! still marked in use. On x86-64 the scalar (SSE-encoded) code that follows — the
//! log/arctan-heavy influence kernels of this module, but equally any other scalar numerics in
//! the same thread — then runs several times slower until a `vzeroupper` executes. Measured on
//! the project machine: `SourceInfluence::new` for N = 160 took 15.5 ms of CPU with the dirty
//! state and 2.5 ms after clearing it.

/// Clears the upper halves of the AVX registers (`vzeroupper`) when the CPU supports AVX; a
/// no-op elsewhere. Cheap (one instruction plus a cached feature test); the panel routines call
/// it before their kernels and after their dense linear algebra, and other modules that mix
/// faer with scalar numerics can call it after their faer calls.
#[inline]
pub fn reset_simd_state() {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx") {
            // SAFETY: AVX support was detected at run time, so the instruction exists;
            // vzeroupper only clears bits 128 and up of the vector registers, which the SysV and
            // Windows x64 ABIs treat as clobbered across this call anyway.
            unsafe { std::arch::x86_64::_mm256_zeroupper() }
        }
    }
}
