//! Advancing a sphere by one step, for callers (tests, examples, small loops) without an
//! integrator of their own: semi-implicit (symplectic) Euler, and velocity Verlet in its two halves.
//!
//! Where the contact call goes, so that a history law sees each step's slip exactly once:
//! - symplectic Euler: evaluate the contact at the current positions and velocities, then
//!   [`advance_solid_sphere`];
//! - velocity Verlet: [`half_kick`] with the previous step's forces, [`drift`], evaluate the
//!   contact at the new positions (with the half-step velocities), then [`half_kick`] with the new
//!   forces. Keep the new forces for the next step's first half-kick.

use crate::body::Sphere;
use crate::float::Float;
use crate::time_step::TimeStep;
use crate::vector::Vec3;

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
    kick_by(sphere, force, torque, KickFactors::new(sphere, dt));
}

/// How much one kick of `dt` changes a sphere's velocity per newton and its angular velocity per
/// newton metre: `dt / m` and `dt / I`. They depend only on the mass, radius and step, so a
/// scene computes them once per kind of sphere instead of twice per sphere and step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct KickFactors<F> {
    linear: F,
    angular: F,
}

impl<F: Float> KickFactors<F> {
    #[inline(always)]
    pub(crate) fn new(sphere: &Sphere<F>, dt: F) -> Self {
        Self {
            linear: dt / sphere.mass,
            angular: dt / sphere.solid_moment_of_inertia(),
        }
    }
}

/// A kick with precomputed factors; the same bits as [`half_kick`] or the kick of
/// [`advance_solid_sphere`] with the factors of the same step.
#[inline(always)]
pub(crate) fn kick_by<F: Float>(
    sphere: &mut Sphere<F>,
    force: Vec3<F>,
    torque: Vec3<F>,
    factors: KickFactors<F>,
) {
    sphere.velocity += force * factors.linear;
    sphere.angular_velocity += torque * factors.angular;
}
