//! Advancing a sphere by one step, for callers (tests, examples, small loops) without an
//! integrator of their own.

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
    let dt = time_step.seconds();
    sphere.velocity += force * (dt / sphere.mass);
    sphere.angular_velocity += torque * (dt / sphere.solid_moment_of_inertia());
    sphere.position += sphere.velocity * dt;
}
