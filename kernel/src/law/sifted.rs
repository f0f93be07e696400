//! A chunk of the list seam's candidate pairs, sifted for contact: the places of the pairs the
//! one-contact path evaluates, their separations, and the long-latency part of their evaluation
//! taken for the whole chunk before any of them is evaluated.
//!
//! One contact is a serial chain: a root and two divisions for its frame, a division and a root
//! to turn its stored spring into the tangent plane, then the force. Evaluated one after
//! another the processor waits on each chain. Taken ahead, place by place in plain arrays, the
//! roots of a chunk are independent: the processor overlaps them and the compiler widens the
//! loops. Each is the one-contact path's own formula on the same inputs, so the bits agree by
//! construction.

use crate::law::geometry::{Roots, Separation};
use crate::seam::spheres::Spheres;
use crate::value::float::Float;
use crate::value::vector::Vec3;

/// Candidate pairs sifted for contact at a time.
pub(crate) const SIFT: usize = 256;

/// One sifted pair: its separation and the roots of its evaluation. Only the kernel makes one.
#[derive(Clone, Copy, Debug)]
pub struct Sifted<F> {
    pub(crate) separation: Separation<F>,
    pub(crate) roots: Roots<F>,
    /// The tangential slot's stored vector turned into the pair's tangent plane.
    pub(crate) turned: Vec3<F>,
}

/// A sifted chunk, place by place: one array per number. Only the kernel makes one.
#[derive(Debug)]
pub struct Sifts<F> {
    /// Each place's pair, as its index in the chunk (in list order).
    pub(crate) places: [u16; SIFT],
    pub(crate) offset: [Vec3<F>; SIFT],
    pub(crate) distance_squared: [F; SIFT],
    pub(crate) reach: [F; SIFT],
    pub(crate) inverse_distance: [F; SIFT],
    pub(crate) overlap: [F; SIFT],
    /// The tangential slot's stored vector turned into the tangent plane (for a slot that
    /// [turns](crate::TangentialModel::TURNS) one).
    pub(crate) turned: [Vec3<F>; SIFT],
}

impl<F: Float> Sifts<F> {
    pub(crate) fn new() -> Self {
        Self {
            places: [0; SIFT],
            offset: [Vec3::ZERO; SIFT],
            distance_squared: [F::ZERO; SIFT],
            reach: [F::ZERO; SIFT],
            inverse_distance: [F::ZERO; SIFT],
            overlap: [F::ZERO; SIFT],
            turned: [Vec3::ZERO; SIFT],
        }
    }

    /// Sifts `chunk` (at most [`SIFT`] pairs, with their shifts or none): keeps, in list
    /// order, the pairs the one-contact path evaluates (overlapping or coincident) with their
    /// separations. Returns how many. Sifting first keeps the coin toss of touching or not out
    /// of the contact evaluation's branches.
    #[inline(always)]
    pub(crate) fn sift(
        &mut self,
        spheres: &impl Spheres<F>,
        (chunk, shifts): (&[[u32; 2]], &[Vec3<F>]),
    ) -> usize {
        // A loop for each case, so that neither tests for a shift at every pair (no shifts
        // add zero, as `shift` gives).
        if shifts.is_empty() {
            self.sift_shifted(spheres, chunk, core::iter::repeat(Vec3::ZERO))
        } else {
            self.sift_shifted(spheres, chunk, shifts.iter().copied())
        }
    }

    /// [`Sifts::sift`] with each pair's shift from `shifts`.
    #[inline(always)]
    fn sift_shifted(
        &mut self,
        spheres: &impl Spheres<F>,
        chunk: &[[u32; 2]],
        shifts: impl Iterator<Item = Vec3<F>>,
    ) -> usize {
        let mut found = 0;
        for (k, (&[i, j], shift)) in chunk.iter().zip(shifts).enumerate() {
            let (i, j) = (i as usize, j as usize);
            let separation = Separation::between(
                (spheres.position(i), spheres.radius(i)),
                (spheres.position(j) + shift, spheres.radius(j)),
            );
            let evaluate = separation.needs_evaluation();
            // Written at every pair, kept by counting only those that are evaluated.
            self.places[found] = k as u16;
            self.offset[found] = separation.offset;
            self.distance_squared[found] = separation.distance_squared;
            self.reach[found] = separation.reach;
            found += usize::from(evaluate);
        }
        found
    }

    /// Place `place`'s pair, once [`Law::sifted_roots`](crate::Law::sifted_roots) has taken
    /// its roots.
    #[inline(always)]
    pub(crate) fn pair(&self, place: usize) -> Sifted<F> {
        Sifted {
            separation: Separation {
                offset: self.offset[place],
                distance_squared: self.distance_squared[place],
                reach: self.reach[place],
            },
            roots: Roots {
                inverse_distance: self.inverse_distance[place],
                overlap: self.overlap[place],
            },
            turned: self.turned[place],
        }
    }
}

/// Pair `k`'s shift of its sphere `j` (none when the list has no shifts).
#[inline(always)]
pub(crate) fn shift<F: Float>(shifts: &[Vec3<F>], k: usize) -> Vec3<F> {
    shifts.get(k).copied().unwrap_or(Vec3::ZERO)
}
