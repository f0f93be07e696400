//! A plain three-component vector, laid out like `[F; 3]` so C and Fortran hosts can share it.

use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

use crate::value::float::Float;

/// A 3-vector of positions, velocities, forces or torques.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct Vec3<F> {
    /// x component.
    pub x: F,
    /// y component.
    pub y: F,
    /// z component.
    pub z: F,
}

impl<F: Float> Vec3<F> {
    /// The zero vector.
    pub const ZERO: Self = Self {
        x: F::ZERO,
        y: F::ZERO,
        z: F::ZERO,
    };

    /// A vector from its components.
    #[inline(always)]
    pub const fn new(x: F, y: F, z: F) -> Self {
        Self { x, y, z }
    }

    /// Dot product.
    #[inline(always)]
    pub fn dot(self, other: Self) -> F {
        self.x * other.x + self.y * other.y + self.z * other.z
    }

    /// Cross product `self x other`.
    #[inline(always)]
    pub fn cross(self, other: Self) -> Self {
        Self {
            x: self.y * other.z - self.z * other.y,
            y: self.z * other.x - self.x * other.z,
            z: self.x * other.y - self.y * other.x,
        }
    }

    /// Squared length (no square root, so no backend needed).
    #[inline(always)]
    pub fn norm_squared(self) -> F {
        self.dot(self)
    }

    /// True when all three components are finite.
    #[inline(always)]
    pub fn is_finite(self) -> bool {
        crate::value::float::all_finite([self.x, self.y, self.z])
    }

    /// The components as an array.
    #[inline(always)]
    pub const fn to_array(self) -> [F; 3] {
        [self.x, self.y, self.z]
    }

    /// True when every component has the same bits as `other`'s.
    pub fn same_bits(self, other: Self) -> bool {
        self.x.to_bits_u64() == other.x.to_bits_u64()
            && self.y.to_bits_u64() == other.y.to_bits_u64()
            && self.z.to_bits_u64() == other.z.to_bits_u64()
    }
}

impl<F: Float> From<[F; 3]> for Vec3<F> {
    #[inline(always)]
    fn from([x, y, z]: [F; 3]) -> Self {
        Self { x, y, z }
    }
}

impl<F: Float> Add for Vec3<F> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<F: Float> Sub for Vec3<F> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<F: Float> AddAssign for Vec3<F> {
    #[inline(always)]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}

impl<F: Float> SubAssign for Vec3<F> {
    #[inline(always)]
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}

impl<F: Float> Neg for Vec3<F> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl<F: Float> Mul<F> for Vec3<F> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, s: F) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
}

/// True when every component of `vectors` is finite: each component's `x * 0` probe summed (see
/// [`crate::value::float::all_finite`]), in four sums side by side so that no addition waits on the one
/// before it.
pub(crate) fn all_finite<F: Float>(vectors: &[Vec3<F>]) -> bool {
    let mut probes = [Vec3::ZERO; 4];
    let mut quads = vectors.chunks_exact(4);
    for quad in &mut quads {
        for (probe, v) in probes.iter_mut().zip(quad) {
            *probe += *v * F::ZERO;
        }
    }
    for v in quads.remainder() {
        probes[0] += *v * F::ZERO;
    }
    let probe = (probes[0] + probes[1]) + (probes[2] + probes[3]);
    probe.x + probe.y + probe.z == F::ZERO
}
