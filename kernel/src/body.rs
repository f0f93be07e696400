//! The bodies a contact is between: spheres and plane walls, as the caller's engine describes them
//! at one instant.

use crate::backend::MathBackend;
use crate::error::{Parameter, ParameterError};
use crate::float::{Float, all_finite};
use crate::vector::Vec3;

/// One sphere at one instant. Plain data: the caller owns it and may change any field between
/// steps; [`ContactLaw::sphere_sphere`](crate::ContactLaw::sphere_sphere) checks it at every call
/// (finite fields, positive radius and mass), a [`CheckedSphere`](crate::CheckedSphere) once.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct Sphere<F> {
    /// Centre position (m).
    pub position: Vec3<F>,
    /// Centre velocity (m/s).
    pub velocity: Vec3<F>,
    /// Angular velocity (rad/s).
    pub angular_velocity: Vec3<F>,
    /// Radius (m).
    pub radius: F,
    /// Mass (kg).
    pub mass: F,
}

impl<F: Float> Sphere<F> {
    /// A sphere at rest at `position`.
    pub fn at_rest(position: Vec3<F>, radius: F, mass: F) -> Self {
        Self {
            position,
            velocity: Vec3::ZERO,
            angular_velocity: Vec3::ZERO,
            radius,
            mass,
        }
    }

    /// A homogeneous sphere of the given density at rest at `position` (mass `4/3 pi R^3 rho`).
    pub fn solid(position: Vec3<F>, radius: F, density: F) -> Self {
        let volume = F::from_f64(4.0 / 3.0) * F::PI * radius * radius * radius;
        Self::at_rest(position, radius, volume * density)
    }

    /// Moment of inertia of a homogeneous solid sphere, `2/5 m R^2`.
    #[inline(always)]
    pub fn solid_moment_of_inertia(&self) -> F {
        F::from_f64(0.4) * self.mass * self.radius * self.radius
    }

    /// Every field finite.
    #[inline(always)]
    pub(crate) fn is_finite(&self) -> bool {
        let (p, v, w) = (self.position, self.velocity, self.angular_velocity);
        all_finite([
            p.x,
            p.y,
            p.z,
            v.x,
            v.y,
            v.z,
            w.x,
            w.y,
            w.z,
            self.radius,
            self.mass,
        ])
    }
}

/// An infinite plane wall. Spheres live on the side its normal points to. The wall may translate
/// (its velocity enters the contact's relative velocity); it does not rotate. Every field is
/// checked when it is set, so a wall is always valid and contacts never check it again.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wall<F> {
    point: Vec3<F>,
    normal: Vec3<F>,
    velocity: Vec3<F>,
}

impl<F: Float> Wall<F> {
    /// A wall through `point` whose outward normal (towards the spheres) is along `normal`.
    /// The normal is normalised here, once, with the reference backend.
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for a non-finite point or normal,
    /// [`ParameterError::NotPositive`] for a zero (or denormal-length) normal.
    pub fn new(point: Vec3<F>, normal: Vec3<F>) -> Result<Self, ParameterError> {
        if !point.is_finite() || !normal.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::Wall));
        }
        let length_squared = normal.norm_squared();
        if !length_squared.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::Wall));
        }
        if length_squared < F::MIN_POSITIVE {
            return Err(ParameterError::NotPositive(Parameter::Wall));
        }
        let unit = normal * F::DefaultBackend::inv_sqrt(length_squared);
        Ok(Self {
            point,
            normal: unit,
            velocity: Vec3::ZERO,
        })
    }

    /// The same wall moving with `velocity` (m/s), for moving floors and pistons (zero by
    /// default).
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for a non-finite velocity.
    pub fn with_velocity(mut self, velocity: Vec3<F>) -> Result<Self, ParameterError> {
        if !velocity.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::Wall));
        }
        self.velocity = velocity;
        Ok(self)
    }

    /// The same wall, translated so that it passes through `point` (for walls the caller moves).
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for a non-finite point.
    pub fn moved_to(mut self, point: Vec3<F>) -> Result<Self, ParameterError> {
        if !point.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::Wall));
        }
        self.point = point;
        Ok(self)
    }

    /// The wall's velocity (m/s).
    pub fn velocity(&self) -> Vec3<F> {
        self.velocity
    }

    /// A point on the wall.
    pub fn point(&self) -> Vec3<F> {
        self.point
    }

    /// The unit outward normal.
    pub fn normal(&self) -> Vec3<F> {
        self.normal
    }

    /// Signed distance from `position` to the plane (positive on the spheres' side).
    #[inline(always)]
    pub fn distance_to(&self, position: Vec3<F>) -> F {
        (position - self.point).dot(self.normal)
    }
}

/// Effective mass of a pair, `m_i m_j / (m_i + m_j)`. Symmetric bit for bit.
#[inline(always)]
pub fn effective_mass<F: Float>(mass_i: F, mass_j: F) -> F {
    mass_i * mass_j / (mass_i + mass_j)
}
