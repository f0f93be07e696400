//! The spheres a contact is between, as the caller's engine describes them at one instant
//! (walls: [`Wall`](crate::Wall)).

use crate::value::float::{Float, all_finite};
use crate::value::vector::Vec3;

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

/// Effective mass of a pair, `m_i m_j / (m_i + m_j)`. Symmetric bit for bit.
#[inline(always)]
pub fn effective_mass<F: Float>(mass_i: F, mass_j: F) -> F {
    mass_i * mass_j / (mass_i + mass_j)
}
