//! Math backends: where `sqrt`, `1/sqrt`, `atan2` and `ln` come from.
//!
//! The backend is a type parameter of the contact law, so two backends can be compared in one
//! program. [`Libm`] is the default: portable, deterministic across targets, `sqrt` correctly
//! rounded. `Std` (the optional `std` feature) takes its square roots from `std`, the same
//! correctly rounded bits, in a form the compiler can vectorise. [`Micromath`] is micromath's fast bit-level approximations, `f32` only; its error is
//! large (see [`Micromath`]) and is measured by the host-tests (`tests/backends.rs`), not
//! assumed.

/// The transcendental functions the kernel needs, for one precision `F`.
///
/// Implementations must be pure functions of their arguments so the kernel stays deterministic.
pub trait MathBackend<F>: Copy + Default + core::fmt::Debug + 'static {
    /// Square root of a non-negative number.
    fn sqrt(x: F) -> F;
    /// `1 / sqrt(x)` for a positive number.
    fn inv_sqrt(x: F) -> F;
    /// Four-quadrant arctangent of `y / x`, in `[-pi, pi]`.
    fn atan2(y: F, x: F) -> F;
    /// Natural logarithm of a positive number.
    fn ln(x: F) -> F;
}

/// The `libm` crate: pure-Rust ports of musl's math, identical on every target.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Libm;

macro_rules! impl_libm {
    ($t:ty, $sqrt:ident, $atan2:ident, $ln:ident) => {
        impl MathBackend<$t> for Libm {
            #[inline(always)]
            fn sqrt(x: $t) -> $t {
                libm::$sqrt(x)
            }
            /// `sqrt(x) * (1 / x)`: the root and the reciprocal run side by side instead of one
            /// after the other (within 1.5 ulp, against 1 ulp for `1 / sqrt(x)`).
            #[inline(always)]
            fn inv_sqrt(x: $t) -> $t {
                libm::$sqrt(x) * (1.0 / x)
            }
            #[inline(always)]
            fn atan2(y: $t, x: $t) -> $t {
                libm::$atan2(y, x)
            }
            #[inline(always)]
            fn ln(x: $t) -> $t {
                libm::$ln(x)
            }
        }
    };
}

impl_libm!(f32, sqrtf, atan2f, logf);
impl_libm!(f64, sqrt, atan2, log);

/// `std`'s square root (the `sqrt` instruction LLVM knows, so the list seam's loops over a
/// chunk's roots widen into vector registers), with [`Libm`]'s `atan2` and `ln`.
///
/// A square root is correctly rounded in IEEE 754 whoever computes it, so `Std` gives the same bits
/// as [`Libm`] on every target; `atan2` and `ln` are not, and `std`'s come from the platform's C
/// library, so they stay libm's. `libm`'s own square root is written so that LLVM does not see a
/// square root it can widen (on x86-64 an inline `sqrtsd`), which keeps such loops scalar. Needs the
/// `std` feature; the kernel stays `no_std` without it.
#[cfg(feature = "std")]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Std;

macro_rules! impl_std {
    ($t:ty) => {
        #[cfg(feature = "std")]
        impl MathBackend<$t> for Std {
            #[inline(always)]
            #[allow(
                clippy::disallowed_methods,
                reason = "this backend is std's square root"
            )]
            fn sqrt(x: $t) -> $t {
                <$t>::sqrt(x)
            }
            /// As [`Libm`]'s: `sqrt(x) * (1 / x)`, the same bits.
            #[inline(always)]
            fn inv_sqrt(x: $t) -> $t {
                <Self as MathBackend<$t>>::sqrt(x) * (1.0 / x)
            }
            #[inline(always)]
            fn atan2(y: $t, x: $t) -> $t {
                <Libm as MathBackend<$t>>::atan2(y, x)
            }
            #[inline(always)]
            fn ln(x: $t) -> $t {
                <Libm as MathBackend<$t>>::ln(x)
            }
        }
    };
}

impl_std!(f32);
impl_std!(f64);

/// The `micromath` crate's approximations, used as they are (no refinement step), `f32` only.
///
/// `sqrt` and `1/sqrt` are single bit-manipulation guesses (relative error below 6.5 % and
/// 3.5 %); `atan2` is a rational approximation (below 0.003 rad); `ln` is off by up to 0.12
/// (the laws take logarithms only when they are built, always through [`Libm`]). The kernel's
/// overlap formula keeps its relative accuracy with an approximate square root; force magnitudes
/// inherit the `1/sqrt` error through the contact normal.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Micromath;

impl MathBackend<f32> for Micromath {
    #[inline(always)]
    fn sqrt(x: f32) -> f32 {
        micromath::F32(x).sqrt().0
    }
    #[inline(always)]
    fn inv_sqrt(x: f32) -> f32 {
        micromath::F32(x).invsqrt().0
    }
    #[inline(always)]
    fn atan2(y: f32, x: f32) -> f32 {
        micromath::F32(y).atan2(micromath::F32(x)).0
    }
    #[inline(always)]
    fn ln(x: f32) -> f32 {
        micromath::F32(x).ln().0
    }
}
