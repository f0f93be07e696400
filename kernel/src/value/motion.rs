//! Advancing a sphere by one step, for callers (tests, examples, small loops) without an
//! integrator of their own: semi-implicit (symplectic) Euler, and velocity Verlet in its two halves.
//!
//! Where the contact call goes, so that a history law sees each step's slip exactly once:
//! - symplectic Euler: evaluate the contact at the current positions and velocities, then
//!   [`advance_solid_sphere`];
//! - velocity Verlet: [`half_kick`] with the previous step's forces, [`drift`], evaluate the
//!   contact at the new positions (with the half-step velocities), then [`half_kick`] with the new
//!   forces. Keep the new forces for the next step's first half-kick.

use crate::value::body::Sphere;
use crate::value::float::Float;
use crate::value::time_step::TimeStep;
use crate::value::vector::Vec3;

/// One semi-implicit (symplectic) Euler step of a homogeneous solid sphere under a total force
/// and torque: velocities first, then the position with the new velocity. Forces must be
/// evaluated at the current positions and velocities; history laws then see each step's slip once,
/// which is where their update belongs for this integrator.
#[inline]
pub fn advance_solid_sphere<F: Float>(
    sphere: &mut Sphere<F>,
    force: Vec3<F>,
    torque: Vec3<F>,
    time_step: TimeStep<F>,
) {
    kick(sphere, force, torque, time_step.seconds());
    drift(sphere, time_step);
}

/// Velocity Verlet's half kick: linear and angular velocity advanced by half a step under a total
/// force and torque (homogeneous solid sphere).
#[inline]
pub fn half_kick<F: Float>(
    sphere: &mut Sphere<F>,
    force: Vec3<F>,
    torque: Vec3<F>,
    time_step: TimeStep<F>,
) {
    kick(sphere, force, torque, time_step.seconds() * F::HALF);
}

/// Velocity Verlet's drift: the position advanced by a whole step at the current velocity.
#[inline]
pub fn drift<F: Float>(sphere: &mut Sphere<F>, time_step: TimeStep<F>) {
    sphere.position += sphere.velocity * time_step.seconds();
}

#[inline(always)]
fn kick<F: Float>(sphere: &mut Sphere<F>, force: Vec3<F>, torque: Vec3<F>, dt: F) {
    Kick::new(sphere, dt).apply(sphere, force, torque);
}

/// One kick of `dt` for one kind of sphere: how much it changes the velocity per newton (`dt / m`)
/// and the angular velocity per newton metre (`dt / I`, homogeneous solid sphere). They depend
/// only on the mass, radius and step, so an engine computes them once per kind of sphere instead
/// of twice per sphere and step; applying them gives the same bits as [`half_kick`] or the kick
/// of [`advance_solid_sphere`] with the same step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kick<F> {
    linear: F,
    angular: F,
}

impl<F: Float> Kick<F> {
    /// The kick of `dt` seconds for spheres of this mass and radius.
    #[inline(always)]
    pub fn new(sphere: &Sphere<F>, dt: F) -> Self {
        Self {
            linear: dt / sphere.mass,
            angular: dt / sphere.solid_moment_of_inertia(),
        }
    }

    /// Kicks `sphere` (of the mass and radius this was made for) under a total force and torque.
    #[inline(always)]
    pub fn apply(&self, sphere: &mut Sphere<F>, force: Vec3<F>, torque: Vec3<F>) {
        sphere.velocity += force * self.linear;
        sphere.angular_velocity += torque * self.angular;
    }
}
