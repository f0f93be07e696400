//! The sealed floating-point trait that makes every law available in `f32` and `f64`.
//!
//! Precision is a type parameter, not a cargo feature: features unify across a build, and a host
//! that compares both precisions needs both in the same program.

use core::fmt::Debug;
use core::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

use crate::value::backend::{Libm, MathBackend};

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
}

/// A floating-point precision the kernel supports: `f32` or `f64`. Sealed.
///
/// Only arithmetic, comparisons and bit-level operations live here. Transcendental math
/// (`sqrt`, `atan2`, `ln`) goes through a [`MathBackend`], chosen by the caller, so that a benchmark
/// of a backend measures that backend and not whatever `std` happens to provide.
pub trait Float:
    sealed::Sealed
    + Copy
    + Debug
    + Default
    + PartialEq
    + PartialOrd
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
{
    /// The default backend ([`Libm`]): the per-contact backend of a law built with
    /// [`ContactLaw::new`](crate::ContactLaw::new), and the accurate one that one-off parameter
    /// derivation (damping from restitution, contact duration, stability limits) always uses,
    /// whichever backend the per-contact path uses.
    type DefaultBackend: MathBackend<Self>;
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// 2.
    const TWO: Self;
    /// 1/2.
    const HALF: Self;
    /// pi.
    const PI: Self;
    /// Positive infinity.
    const INFINITY: Self;
    /// The smallest positive normal number.
    const MIN_POSITIVE: Self;
    /// The largest finite number.
    const MAX: Self;
    /// The distance from 1 to the next larger number (the unit of rounding, twice its bound).
    const EPSILON: Self;

    /// Converts from `f64`, rounding to nearest.
    fn from_f64(value: f64) -> Self;
    /// Converts to `f64` exactly.
    fn to_f64(self) -> f64;
    /// True unless the value is NaN or infinite.
    fn is_finite(self) -> bool;
    /// Absolute value, by clearing the sign bit.
    fn abs(self) -> Self;
    /// The bit pattern, widened to 64 bits: equal exactly for the same number (NaNs with the same
    /// payload included, `0` and `-0` told apart).
    fn to_bits_u64(self) -> u64;
    /// The number whose bit pattern is `bits` (for `f32`, its low 32 bits): arbitrary bit
    /// patterns for fuzzing.
    fn from_bits_u64(bits: u64) -> Self;

    /// The larger of two numbers. With a NaN operand the comparison fails and `other` is returned;
    /// the kernel only calls it on validated numbers.
    #[inline(always)]
    fn max_of(self, other: Self) -> Self {
        if self >= other { self } else { other }
    }

    /// The smaller of two numbers; NaN handling as for [`Float::max_of`].
    #[inline(always)]
    fn min_of(self, other: Self) -> Self {
        if self <= other { self } else { other }
    }
}

macro_rules! impl_float {
    ($t:ident, $sign:expr) => {
        impl Float for $t {
            type DefaultBackend = Libm;
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;
            const HALF: Self = 0.5;
            const PI: Self = core::$t::consts::PI;
            const INFINITY: Self = $t::INFINITY;
            const MIN_POSITIVE: Self = $t::MIN_POSITIVE;
            const EPSILON: Self = $t::EPSILON;
            const MAX: Self = $t::MAX;

            #[inline(always)]
            fn from_f64(value: f64) -> Self {
                value as $t
            }
            #[inline(always)]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline(always)]
            fn is_finite(self) -> bool {
                $t::is_finite(self)
            }
            #[inline(always)]
            fn abs(self) -> Self {
                $t::from_bits(self.to_bits() & !$sign)
            }
            #[inline(always)]
            fn to_bits_u64(self) -> u64 {
                u64::from(self.to_bits())
            }
            #[inline(always)]
            fn from_bits_u64(bits: u64) -> Self {
                // f32: the low half (the cast truncates by design).
                $t::from_bits(bits as _)
            }
        }
    };
}

impl_float!(f32, 1u32 << 31);
impl_float!(f64, 1u64 << 63);

/// True when every value is finite. `x * 0` is `0` for finite `x` and NaN otherwise, so one sum
/// answers for all of them without overflow and without a branch per value.
#[inline(always)]
pub(crate) fn all_finite<F: Float, const N: usize>(values: [F; N]) -> bool {
    let mut probe = F::ZERO;
    for value in values {
        probe += value * F::ZERO;
    }
    probe == F::ZERO
}

/// `1 / sqrt(x)` for a positive `x`, subnormal ones included. Below `1 / F::MAX` (a length
/// under 5.4e-20 in f32, as at the creeping end of a small contact) a backend's
/// `sqrt(x) * (1 / x)` overflows to infinity, so `1 / sqrt(x)` is taken for every subnormal
/// `x`; a normal `x` keeps the backend's bits.
#[inline(always)]
pub(crate) fn inverse_root<F: Float, M: MathBackend<F>>(x: F) -> F {
    if x >= F::MIN_POSITIVE {
        M::inv_sqrt(x)
    } else {
        F::ONE / M::sqrt(x)
    }
}

#[cfg(test)]
mod tests {
    use super::inverse_root;
    use crate::value::backend::{Libm, MathBackend};

    /// A squared length below `1 / F::MAX` (subnormal): the backend's `sqrt(x) * (1 / x)`
    /// overflows; `inverse_root` is within 2 eps of `1 / sqrt(x)` taken in f64, and exact where that is a
    /// power of two.
    #[test]
    fn inverse_root_holds_for_subnormal_squares() {
        for x in [1e-45_f32, 1e-40, 2.9e-39] {
            assert!(
                <Libm as MathBackend<f32>>::inv_sqrt(x).is_infinite(),
                "{x:e}"
            );
            let root = inverse_root::<f32, Libm>(x);
            let exact = 1.0 / libm::sqrt(f64::from(x));
            assert!(((f64::from(root) - exact) / exact).abs() < 2.0 * f64::from(f32::EPSILON));
        }
        // Even powers of two, whose inverse roots are exact: 2^-148 and 2^-130 in f32, 2^-1074
        // and 2^-1030 in f64.
        for (x, root) in [(-148, 74), (-130, 65)].map(|(x, r)| {
            (
                f32::from_bits(1 << (149 + x)),
                f32::from_bits((127 + r) << 23),
            )
        }) {
            assert!(<Libm as MathBackend<f32>>::inv_sqrt(x).is_infinite());
            assert_eq!(inverse_root::<f32, Libm>(x), root, "{x:e}");
        }
        for (x, root) in [(-1074, 537), (-1030, 515)].map(|(x, r)| {
            (
                f64::from_bits(1 << (1074 + x)),
                f64::from_bits((1023 + r) << 52),
            )
        }) {
            assert!(<Libm as MathBackend<f64>>::inv_sqrt(x).is_infinite());
            assert_eq!(inverse_root::<f64, Libm>(x), root, "{x:e}");
        }
        // Normal numbers keep the backend's bits.
        for x in [f32::MIN_POSITIVE, 1e-20, 1.0, 3.0e38] {
            assert_eq!(
                inverse_root::<f32, Libm>(x).to_bits(),
                <Libm as MathBackend<f32>>::inv_sqrt(x).to_bits()
            );
        }
    }
}
