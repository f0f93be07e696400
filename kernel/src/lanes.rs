//! Lanes: `L` independent contacts evaluated side by side, as structure-of-arrays numbers and
//! vectors.
//!
//! Every operation is the one-contact operation applied lane by lane, in the same order, so each
//! lane gives the same bits as the one-contact path. The operations are plain loops over small
//! arrays with choices instead of jumps. The compiler turns them into vector instructions, and
//! the processor overlaps the lanes' roots and divisions. A scene evaluates its touching pairs this
//! way; an engine that batches its own contacts can too, through
//! [`TangentialModel::force_lanes`](crate::TangentialModel::force_lanes).

use core::ops::{Add, Div, Mul, Neg, Sub};

use crate::float::Float;
use crate::vector::Vec3;

/// `L` numbers, one per lane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lanes<F, const L: usize>(pub [F; L]);

/// A choice per lane.
pub type Mask<const L: usize> = [bool; L];

/// `[f(0), f(1), ..., f(L - 1)]`. `core::array::from_fn` is not reliably inlined in a hot loop
/// (its closure goes through a fallible-map adapter); this loop is.
#[inline(always)]
pub(crate) fn lanes<T: Copy + Default, const L: usize>(mut f: impl FnMut(usize) -> T) -> [T; L] {
    let mut out = [T::default(); L];
    for (l, slot) in out.iter_mut().enumerate() {
        *slot = f(l);
    }
    out
}

impl<F: Float, const L: usize> Default for Lanes<F, L> {
    fn default() -> Self {
        Self([F::ZERO; L])
    }
}

impl<F: Float, const L: usize> Lanes<F, L> {
    /// The same number in every lane.
    #[inline(always)]
    pub fn splat(value: F) -> Self {
        Self([value; L])
    }

    /// Lane `l` is `f(l)`.
    #[inline(always)]
    pub fn from_fn(f: impl FnMut(usize) -> F) -> Self {
        Self(lanes(f))
    }

    /// `f` applied to every lane.
    #[inline(always)]
    pub fn map(self, mut f: impl FnMut(F) -> F) -> Self {
        Self::from_fn(|l| f(self.0[l]))
    }

    /// Lane by lane `a` where `mask`, else `b`.
    #[inline(always)]
    pub fn select(mask: Mask<L>, a: Self, b: Self) -> Self {
        Self::from_fn(|l| if mask[l] { a.0[l] } else { b.0[l] })
    }

    /// Lane by lane `self < other`.
    #[inline(always)]
    pub fn less(self, other: Self) -> Mask<L> {
        lanes(|l| self.0[l] < other.0[l])
    }

    /// Lane by lane `self <= other`.
    #[inline(always)]
    pub fn less_or_equal(self, other: Self) -> Mask<L> {
        lanes(|l| self.0[l] <= other.0[l])
    }

    /// Lane by lane [`Float::abs`].
    #[inline(always)]
    pub fn abs(self) -> Self {
        self.map(F::abs)
    }

    /// Lane by lane [`Float::max_of`].
    #[inline(always)]
    pub fn max_of(self, other: Self) -> Self {
        Self::from_fn(|l| self.0[l].max_of(other.0[l]))
    }

    /// `value * 0` summed over the lanes: zero when every lane is finite, NaN otherwise (see
    /// [`all_finite`](crate::float)).
    #[inline(always)]
    pub(crate) fn finite_probe(self) -> Self {
        self * Self::splat(F::ZERO)
    }
}

macro_rules! lane_operator {
    ($trait:ident, $method:ident) => {
        impl<F: Float, const L: usize> $trait for Lanes<F, L> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, other: Self) -> Self {
                Self::from_fn(|l| $trait::$method(self.0[l], other.0[l]))
            }
        }
    };
}

lane_operator!(Add, add);
lane_operator!(Sub, sub);
lane_operator!(Mul, mul);
lane_operator!(Div, div);

impl<F: Float, const L: usize> Neg for Lanes<F, L> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|x| -x)
    }
}

/// `L` 3-vectors, one per lane, stored component by component.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LaneVec<F: Float, const L: usize> {
    /// The x components.
    pub x: Lanes<F, L>,
    /// The y components.
    pub y: Lanes<F, L>,
    /// The z components.
    pub z: Lanes<F, L>,
}

impl<F: Float, const L: usize> LaneVec<F, L> {
    /// Lane `l` is `f(l)`.
    #[inline(always)]
    pub fn from_fn(mut f: impl FnMut(usize) -> Vec3<F>) -> Self {
        let mut out = Self::default();
        for l in 0..L {
            let v = f(l);
            (out.x.0[l], out.y.0[l], out.z.0[l]) = (v.x, v.y, v.z);
        }
        out
    }

    /// The same vector in every lane.
    #[inline(always)]
    pub fn splat(v: Vec3<F>) -> Self {
        Self {
            x: Lanes::splat(v.x),
            y: Lanes::splat(v.y),
            z: Lanes::splat(v.z),
        }
    }

    /// Lane `l`'s vector.
    #[inline(always)]
    pub fn lane(&self, l: usize) -> Vec3<F> {
        Vec3::new(self.x.0[l], self.y.0[l], self.z.0[l])
    }

    /// Lane by lane [`Vec3::dot`].
    #[inline(always)]
    pub fn dot(self, other: Self) -> Lanes<F, L> {
        self.x * other.x + self.y * other.y + self.z * other.z
    }

    /// Lane by lane [`Vec3::cross`].
    #[inline(always)]
    pub fn cross(self, other: Self) -> Self {
        Self {
            x: self.y * other.z - self.z * other.y,
            y: self.z * other.x - self.x * other.z,
            z: self.x * other.y - self.y * other.x,
        }
    }

    /// Lane by lane [`Vec3::norm_squared`].
    #[inline(always)]
    pub fn norm_squared(self) -> Lanes<F, L> {
        self.dot(self)
    }

    /// Lane by lane `a` where `mask`, else `b`.
    #[inline(always)]
    pub fn select(mask: Mask<L>, a: Self, b: Self) -> Self {
        Self {
            x: Lanes::select(mask, a.x, b.x),
            y: Lanes::select(mask, a.y, b.y),
            z: Lanes::select(mask, a.z, b.z),
        }
    }

    /// The components' [`Lanes::finite_probe`], summed.
    #[inline(always)]
    pub(crate) fn finite_probe(self) -> Lanes<F, L> {
        self.x.finite_probe() + self.y.finite_probe() + self.z.finite_probe()
    }
}

impl<F: Float, const L: usize> Add for LaneVec<F, L> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }
}

impl<F: Float, const L: usize> Sub for LaneVec<F, L> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

impl<F: Float, const L: usize> Neg for LaneVec<F, L> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self {
            x: -self.x,
            y: -self.y,
            z: -self.z,
        }
    }
}

impl<F: Float, const L: usize> Mul<Lanes<F, L>> for LaneVec<F, L> {
    type Output = Self;
    /// Each lane's vector times that lane's number.
    #[inline(always)]
    fn mul(self, s: Lanes<F, L>) -> Self {
        Self {
            x: self.x * s,
            y: self.y * s,
            z: self.z * s,
        }
    }
}

/// `L` spheres, one per lane (the fields of [`Sphere`](crate::Sphere)).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct SphereLanes<F: Float, const L: usize> {
    pub position: LaneVec<F, L>,
    pub velocity: LaneVec<F, L>,
    pub angular_velocity: LaneVec<F, L>,
    pub radius: Lanes<F, L>,
    pub mass: Lanes<F, L>,
}

impl<F: Float, const L: usize> SphereLanes<F, L> {
    /// Lane `l` is sphere `f(l)`.
    #[inline(always)]
    pub fn from_fn(mut f: impl FnMut(usize) -> crate::Sphere<F>) -> Self {
        let mut out = Self::default();
        for l in 0..L {
            let s = f(l);
            for (lanes, v) in [
                (&mut out.position, s.position),
                (&mut out.velocity, s.velocity),
                (&mut out.angular_velocity, s.angular_velocity),
            ] {
                (lanes.x.0[l], lanes.y.0[l], lanes.z.0[l]) = (v.x, v.y, v.z);
            }
            (out.radius.0[l], out.mass.0[l]) = (s.radius, s.mass);
        }
        out
    }
}
