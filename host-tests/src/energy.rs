//! Kinetic energy of spheres, in f64 whatever the kernel's precision.

use soft_sphere::prelude::{Float, Sphere};

/// Translational plus rotational kinetic energy of a homogeneous solid sphere (J).
pub fn kinetic<F: Float>(s: &Sphere<F>) -> f64 {
    let (m, inertia) = (s.mass.to_f64(), s.solid_moment_of_inertia().to_f64());
    0.5 * m * s.velocity.norm_squared().to_f64()
        + 0.5 * inertia * s.angular_velocity.norm_squared().to_f64()
}
