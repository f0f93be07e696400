//! The spheres of a list evaluation, as the engine keeps them: one array per field
//! ([`SphereArrays`], as LAMMPS does) or one array of checked spheres ([`SphereSlice`], as an
//! engine with a struct per particle does), with a material id per sphere.

use crate::seam::list_error::{ListArray, ListError};
use crate::value::body::Sphere;
use crate::value::checked::{self, CheckedSphere};
use crate::value::float::Float;
use crate::value::vector::Vec3;

pub(crate) mod sealed {
    /// Only the kernel's two layouts are [`Spheres`](super::Spheres).
    pub trait Sealed: Sized {
        /// The same spheres with every array cut to the spheres' count (their lengths are
        /// checked equal first, so no cut fails): the compiler then tests an index once for
        /// all the arrays it reads.
        fn evened(&self) -> Self;
    }
}

/// The spheres a list evaluation reads, in either layout. Sealed: [`SphereArrays`] and
/// [`SphereSlice`].
pub trait Spheres<F: Float>: sealed::Sealed + Sync {
    /// How many spheres.
    fn len(&self) -> usize;

    /// Whether there are none.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Sphere `k`'s centre (below [`Spheres::len`], after [`Spheres::check`]).
    fn position(&self, k: usize) -> Vec3<F>;

    /// Sphere `k`'s radius.
    fn radius(&self, k: usize) -> F;

    /// Sphere `k`'s material id.
    fn material(&self, k: usize) -> u32;

    /// Sphere `k`, all of it.
    fn sphere(&self, k: usize) -> Sphere<F>;

    /// Checks that every array is as long as the first.
    ///
    /// # Errors
    /// [`ListError::Length`] for an array of another length.
    fn check_lengths(&self) -> Result<(), ListError>;

    /// Checks sphere `k`: finite fields, positive radius and mass. A [`SphereSlice`] holds
    /// spheres checked when they were made, and passes.
    ///
    /// # Errors
    /// [`ListError::Sphere`] when the sphere is not valid.
    fn check(&self, k: usize) -> Result<(), ListError>;
}

/// The engine's spheres, as its own arrays: sphere `k` is entry `k` of each. Every array must
/// be as long as `position`.
#[derive(Clone, Copy, Debug)]
pub struct SphereArrays<'a, F> {
    /// Centre positions (m).
    pub position: &'a [Vec3<F>],
    /// Centre velocities (m/s).
    pub velocity: &'a [Vec3<F>],
    /// Angular velocities (rad/s).
    pub angular_velocity: &'a [Vec3<F>],
    /// Radii (m).
    pub radius: &'a [F],
    /// Masses (kg).
    pub mass: &'a [F],
    /// Material ids, rows of the [`MaterialTable`](crate::MaterialTable).
    pub material: &'a [u32],
}

/// The engine's spheres as one array of [`CheckedSphere`]s (checked when they were made, so
/// an evaluation does not check them again) and one of material ids, as long as it.
#[derive(Clone, Copy, Debug)]
pub struct SphereSlice<'a, F> {
    /// The spheres.
    pub spheres: &'a [CheckedSphere<F>],
    /// Material ids, rows of the [`MaterialTable`](crate::MaterialTable).
    pub material: &'a [u32],
}

impl<F> sealed::Sealed for SphereArrays<'_, F> {
    #[inline(always)]
    fn evened(&self) -> Self {
        let n = self.position.len();
        Self {
            position: self.position,
            velocity: &self.velocity[..n],
            angular_velocity: &self.angular_velocity[..n],
            radius: &self.radius[..n],
            mass: &self.mass[..n],
            material: &self.material[..n],
        }
    }
}

impl<F> sealed::Sealed for SphereSlice<'_, F> {
    #[inline(always)]
    fn evened(&self) -> Self {
        let n = self.spheres.len();
        Self {
            spheres: self.spheres,
            material: &self.material[..n],
        }
    }
}

impl<F: Float> Spheres<F> for SphereArrays<'_, F> {
    #[inline(always)]
    fn len(&self) -> usize {
        self.position.len()
    }

    #[inline(always)]
    fn position(&self, k: usize) -> Vec3<F> {
        self.position[k]
    }

    #[inline(always)]
    fn radius(&self, k: usize) -> F {
        self.radius[k]
    }

    #[inline(always)]
    fn material(&self, k: usize) -> u32 {
        self.material[k]
    }

    #[inline(always)]
    fn sphere(&self, k: usize) -> Sphere<F> {
        Sphere {
            position: self.position[k],
            velocity: self.velocity[k],
            angular_velocity: self.angular_velocity[k],
            radius: self.radius[k],
            mass: self.mass[k],
        }
    }

    fn check_lengths(&self) -> Result<(), ListError> {
        let n = self.len();
        let lengths = [
            (self.velocity.len(), ListArray::Velocity),
            (self.angular_velocity.len(), ListArray::AngularVelocity),
            (self.radius.len(), ListArray::Radius),
            (self.mass.len(), ListArray::Mass),
            (self.material.len(), ListArray::Material),
        ];
        match lengths.iter().find(|(length, _)| *length != n) {
            Some(&(_, array)) => Err(ListError::Length(array)),
            None => Ok(()),
        }
    }

    #[inline(always)]
    fn check(&self, k: usize) -> Result<(), ListError> {
        checked::check(&self.sphere(k)).map_err(|error| ListError::Sphere { sphere: k, error })
    }
}

impl<F: Float> Spheres<F> for SphereSlice<'_, F> {
    #[inline(always)]
    fn len(&self) -> usize {
        self.spheres.len()
    }

    #[inline(always)]
    fn position(&self, k: usize) -> Vec3<F> {
        self.spheres[k].position
    }

    #[inline(always)]
    fn radius(&self, k: usize) -> F {
        self.spheres[k].radius
    }

    #[inline(always)]
    fn material(&self, k: usize) -> u32 {
        self.material[k]
    }

    #[inline(always)]
    fn sphere(&self, k: usize) -> Sphere<F> {
        *self.spheres[k]
    }

    fn check_lengths(&self) -> Result<(), ListError> {
        if self.material.len() == self.spheres.len() {
            Ok(())
        } else {
            Err(ListError::Length(ListArray::Material))
        }
    }

    #[inline(always)]
    fn check(&self, _: usize) -> Result<(), ListError> {
        Ok(())
    }
}
