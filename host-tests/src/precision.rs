//! What the tests need to know of a precision that the kernel's `Float` does not carry.

use soft_sphere::prelude::Float;

/// Machine epsilon of `F`: the gap between 1 and the next larger number.
pub fn epsilon<F: Float>() -> f64 {
    let mut gap = 1.0_f64;
    while F::from_f64(1.0 + gap / 2.0) != F::ONE {
        gap /= 2.0;
    }
    gap
}

/// A value's bit pattern, for bit-exact comparisons: widening `f32` to `f64` is exact, so two
/// values of `F` have the same bits exactly when these do.
pub fn bits<F: Float>(value: F) -> u64 {
    value.to_f64().to_bits()
}

#[cfg(test)]
mod tests {
    #[test]
    fn epsilon_is_the_standard_one() {
        assert_eq!(super::epsilon::<f32>(), f64::from(f32::EPSILON));
        assert_eq!(super::epsilon::<f64>(), f64::EPSILON);
    }
}
