//! The spheres of a list evaluation, as the engine keeps them: one array per field
//! ([`SphereArrays`], as LAMMPS does) or one array of checked spheres ([`SphereSlice`], as an
//! engine with a struct per particle does), with a material id per sphere.

use crate::seam::list_error::{ListArray, ListError};
use crate::value::body::Sphere;
use crate::value::checked::{self, CheckedSphere};
use crate::value::float::Float;
use crate::value::vector::{Vec3, all_finite};

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

    /// Whether every sphere passes [`Spheres::check`] and names a material below `materials`,
    /// answered by reductions over whole arrays with no branch per sphere. False does not say
    /// which sphere fails: the caller then checks them one by one, to name the first.
    #[doc(hidden)]
    fn all_valid(&self, materials: usize) -> bool;
}

/// Whether every value is positive and finite, counted without a branch per value: a value at
/// or below zero, or one whose `x * 0` is not zero (an infinity or a NaN), counts.
#[inline(always)]
fn all_positive<F: Float>(values: &[F]) -> bool {
    let outside = |x: F| usize::from((x <= F::ZERO) | (x * F::ZERO != F::ZERO));
    values.iter().map(|&x| outside(x)).sum::<usize>() == 0
}

/// Whether every material id is below `materials`, counted without a branch per id.
#[inline(always)]
fn all_below(material: &[u32], materials: usize) -> bool {
    let beyond = |m: u32| usize::from(m as usize >= materials);
    material.iter().map(|&m| beyond(m)).sum::<usize>() == 0
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

    fn all_valid(&self, materials: usize) -> bool {
        all_below(self.material, materials)
            & all_finite(self.position)
            & all_finite(self.velocity)
            & all_finite(self.angular_velocity)
            & all_positive(self.radius)
            & all_positive(self.mass)
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

    fn all_valid(&self, materials: usize) -> bool {
        all_below(self.material, materials)
    }
}

#[cfg(test)]
mod tests {
    use super::{SphereArrays, Spheres};
    use crate::value::vector::Vec3;

    /// Seven spheres: one full set of lanes and a remainder.
    const N: usize = 7;

    struct Fields {
        position: [Vec3<f64>; N],
        velocity: [Vec3<f64>; N],
        spin: [Vec3<f64>; N],
        radius: [f64; N],
        mass: [f64; N],
        material: [u32; N],
    }

    impl Fields {
        /// Valid spheres, the smallest positive mass among them.
        fn valid() -> Self {
            Self {
                position: [Vec3::new(1.0e3, -2.0, 0.0); N],
                velocity: [Vec3::new(-5.0, 0.0, 3.0e-300); N],
                spin: [Vec3::new(1.0, -2.0, -0.0); N],
                radius: [1.0e-3; N],
                mass: [f64::MIN_POSITIVE * f64::EPSILON; N],
                material: [1; N],
            }
        }

        fn all_valid(&self, materials: usize) -> bool {
            let arrays = SphereArrays {
                position: &self.position,
                velocity: &self.velocity,
                angular_velocity: &self.spin,
                radius: &self.radius,
                mass: &self.mass,
                material: &self.material,
            };
            arrays.all_valid(materials)
        }
    }

    #[test]
    fn every_invalid_field_of_every_sphere_is_noticed() {
        assert!(Fields::valid().all_valid(2));
        let unfinite = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
        let not_positive = [0.0, -0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
        for k in 0..N {
            for c in 0..3 {
                for bad in unfinite {
                    let component = |v: &mut Vec3<f64>| match c {
                        0 => v.x = bad,
                        1 => v.y = bad,
                        _ => v.z = bad,
                    };
                    for field in 0..3 {
                        let mut f = Fields::valid();
                        let vectors = match field {
                            0 => &mut f.position,
                            1 => &mut f.velocity,
                            _ => &mut f.spin,
                        };
                        component(&mut vectors[k]);
                        assert!(!f.all_valid(2), "sphere {k}, vector {field}, {c}: {bad}");
                    }
                }
            }
            for bad in not_positive {
                let mut f = Fields::valid();
                f.radius[k] = bad;
                assert!(!f.all_valid(2), "sphere {k}, radius {bad}");
                let mut f = Fields::valid();
                f.mass[k] = bad;
                assert!(!f.all_valid(2), "sphere {k}, mass {bad}");
            }
            for (material, materials) in [(2, 2), (u32::MAX, 2), (1, 1), (1, 0)] {
                let mut f = Fields::valid();
                f.material[k] = material;
                assert!(!f.all_valid(materials), "sphere {k}, material {material}");
            }
        }
    }
}
