//! A sphere the kernel has checked once, so that engines can evaluate it in many contacts without
//! checking it again.

use core::ops::Deref;

use crate::value::body::Sphere;
use crate::value::error::ContactError;
use crate::value::float::Float;
use crate::value::vector::{Vec3, all_finite};

/// A [`Sphere`] whose fields are finite and whose radius and mass are positive. It can only be
/// made by [`CheckedSphere::new`] and changed through [`CheckedSphere::update`] and
/// [`CheckedSphere::set_motion`], which check it, so
/// every contact evaluated with it skips those checks (see [`ContactLaw::at`](crate::ContactLaw::at)).
/// It reads as a [`Sphere`] through `Deref`.
///
/// ```
/// use soft_sphere::prelude::{CheckedSphere, ContactError, Sphere, Vec3};
///
/// let sphere = Sphere::solid(Vec3::new(0.0, 0.0, 1.0e-3), 1.0e-3, 2500.0_f64);
/// let mut checked = CheckedSphere::new(sphere).unwrap();
/// assert_eq!(checked.radius, 1.0e-3);
///
/// // A change that breaks the checks is refused and leaves the sphere as it was.
/// assert_eq!(checked.update(|s| s.mass = -1.0), Err(ContactError::NonPositiveMass));
/// assert_eq!(*checked, sphere);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CheckedSphere<F>(Sphere<F>);

impl<F: Float> CheckedSphere<F> {
    /// Checks a sphere.
    ///
    /// # Errors
    /// [`ContactError::NonFiniteInput`] for a NaN or infinite field (checked first, so the sign
    /// tests never see NaN), [`ContactError::NonPositiveRadius`], [`ContactError::NonPositiveMass`].
    #[inline(always)]
    pub fn new(sphere: Sphere<F>) -> Result<Self, ContactError> {
        check(&sphere)?;
        Ok(Self(sphere))
    }

    /// Applies `change` to a copy of the sphere and keeps the copy if it passes the checks of
    /// [`CheckedSphere::new`]; returns what `change` returned.
    ///
    /// # Errors
    /// As [`CheckedSphere::new`]; the sphere is then unchanged.
    #[inline(always)]
    pub fn update<R>(
        &mut self,
        change: impl FnOnce(&mut Sphere<F>) -> R,
    ) -> Result<R, ContactError> {
        let mut next = self.0;
        let returned = change(&mut next);
        *self = Self::new(next)?;
        Ok(returned)
    }

    /// Replaces the sphere's motion (its position, velocity and angular velocity), which is
    /// all an integrator changes. Only those are checked: the radius and mass stay as they were
    /// checked.
    ///
    /// ```
    /// use soft_sphere::prelude::{CheckedSphere, ContactError, Sphere, Vec3};
    ///
    /// let sphere = Sphere::solid(Vec3::ZERO, 1.0e-3, 2500.0_f64);
    /// let mut checked = CheckedSphere::new(sphere).unwrap();
    /// let velocity = Vec3::new(0.0, 0.0, -0.1);
    /// checked.set_motion(Vec3::new(0.0, 0.0, -1.0e-6), velocity, Vec3::ZERO).unwrap();
    /// assert_eq!(checked.velocity, velocity);
    /// let diverged = Vec3::new(f64::INFINITY, 0.0, 0.0);
    /// assert_eq!(
    ///     checked.set_motion(diverged, velocity, Vec3::ZERO),
    ///     Err(ContactError::NonFiniteInput)
    /// );
    /// assert_eq!(checked.position, Vec3::new(0.0, 0.0, -1.0e-6));
    /// ```
    ///
    /// # Errors
    /// [`ContactError::NonFiniteInput`] when a component is not finite; the sphere is then
    /// unchanged.
    #[inline(always)]
    pub fn set_motion(
        &mut self,
        position: Vec3<F>,
        velocity: Vec3<F>,
        angular_velocity: Vec3<F>,
    ) -> Result<(), ContactError> {
        // As three vectors, so that each probe's x and y go side by side.
        if !all_finite(&[position, velocity, angular_velocity]) {
            return Err(ContactError::NonFiniteInput);
        }
        self.0.position = position;
        self.0.velocity = velocity;
        self.0.angular_velocity = angular_velocity;
        Ok(())
    }

    /// The same sphere moved by `offset` (a periodic image, for example).
    ///
    /// # Errors
    /// [`ContactError::NonFiniteInput`] when the moved position is not finite.
    #[inline(always)]
    pub fn translated(&self, offset: Vec3<F>) -> Result<Self, ContactError> {
        let position = self.0.position + offset;
        if position.is_finite() {
            Ok(Self(Sphere { position, ..self.0 }))
        } else {
            Err(ContactError::NonFiniteInput)
        }
    }

    /// A sphere that the caller has just checked with [`check`] (the list seam checks every
    /// sphere of a call once, then evaluates them).
    #[inline(always)]
    pub(crate) fn trusted(sphere: Sphere<F>) -> Self {
        Self(sphere)
    }

    /// The sphere.
    #[inline(always)]
    pub fn into_inner(self) -> Sphere<F> {
        self.0
    }
}

impl<F> Deref for CheckedSphere<F> {
    type Target = Sphere<F>;

    #[inline(always)]
    fn deref(&self) -> &Sphere<F> {
        &self.0
    }
}

impl<F: Float> TryFrom<Sphere<F>> for CheckedSphere<F> {
    type Error = ContactError;

    fn try_from(sphere: Sphere<F>) -> Result<Self, ContactError> {
        Self::new(sphere)
    }
}

/// The checks of [`CheckedSphere::new`], in place (the per-call path checks its spheres without
/// copying them), in their order: finiteness first, so the sign tests never see NaN.
#[inline(always)]
pub(crate) fn check<F: Float>(sphere: &Sphere<F>) -> Result<(), ContactError> {
    if !sphere.is_finite() {
        Err(ContactError::NonFiniteInput)
    } else if sphere.radius <= F::ZERO {
        Err(ContactError::NonPositiveRadius)
    } else if sphere.mass <= F::ZERO {
        Err(ContactError::NonPositiveMass)
    } else {
        Ok(())
    }
}
