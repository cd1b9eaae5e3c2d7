//! Vector-register concerns of the kernels: running a kernel compiled for AVX2 where the CPU has
//! it, and clearing the vector-register state that faer's dense kernels leave behind.
//!
//! faer's AVX-512 matrix kernels can return with the upper halves of the vector registers
//! still marked in use. On x86-64 the scalar (SSE-encoded) code that follows — the
//! log/arctan-heavy panel influence kernels, but equally any other scalar numerics in the same
//! thread — then runs several times slower until a `vzeroupper` executes (the source influence
//! of 160 panels: about six times slower). [`reset_simd_state`] issues it.

/// A kernel run by [`with_avx2`]. Its `run` must be `#[inline(always)]`, so that it is
/// compiled inside the AVX2 function and not called from it (a closure would not be).
pub(crate) trait Kernel {
    /// What the kernel returns.
    type Output;
    /// Runs the kernel.
    fn run(self) -> Self::Output;
}

/// Runs `kernel` compiled with AVX2 enabled where the CPU has it, and as compiled for the
/// baseline target elsewhere. The kernel's operations are the same in both builds (Rust does
/// not fuse multiply–adds on its own), so the results are bit-identical; the AVX2 build only
/// uses wider vector registers.
#[inline(always)]
pub(crate) fn with_avx2<K: Kernel>(kernel: K) -> K::Output {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU supports AVX2, checked just above.
        return unsafe { avx2(kernel) };
    }
    kernel.run()
}

/// The AVX2 build of a kernel (see [`with_avx2`]).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn avx2<K: Kernel>(kernel: K) -> K::Output {
    kernel.run()
}

/// Clears the upper halves of the AVX registers (`vzeroupper`) when the CPU supports AVX; a
/// no-op elsewhere. Cheap (one instruction plus a cached feature test); the panel routines call
/// it before their kernels and after their dense linear algebra.
#[inline]
pub(crate) fn reset_simd_state() {
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
