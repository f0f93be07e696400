//! `[f64; 3]` vector arithmetic for test inputs and checks, kept apart from the kernel's `Vec3` so
//! that test arithmetic is always f64 whatever precision the kernel runs in.

use soft_sphere::prelude::{Float, Vec3};

/// A kernel vector of precision `F` (rounded to nearest).
pub fn to_vec3<F: Float>(a: [f64; 3]) -> Vec3<F> {
    Vec3::new(F::from_f64(a[0]), F::from_f64(a[1]), F::from_f64(a[2]))
}

/// A kernel vector's components, exactly.
pub fn from_vec3<F: Float>(v: Vec3<F>) -> [f64; 3] {
    v.to_array().map(Float::to_f64)
}

/// `a + scale b`.
pub fn add_scaled(a: [f64; 3], b: [f64; 3], scale: f64) -> [f64; 3] {
    [
        a[0] + scale * b[0],
        a[1] + scale * b[1],
        a[2] + scale * b[2],
    ]
}

/// `a . b`.
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `|a|`.
pub fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// `a x b`.
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
