//! The touching pairs every per-contact benchmark times: 1 mm spheres at overlaps up to 1 % of
//! the radius, random directions, velocities and spins (fixed seed), and how to run them through
//! the kernel one contact at a time.

use soft_sphere::prelude::{
    CheckedSphere, ContactError, Float, Interaction, Law, Sphere, TimeStep, Vec3,
};

use crate::random::Xorshift;
use crate::triple::to_vec3;

/// A pair of spheres, body i then body j.
pub type Pair<F> = (Sphere<F>, Sphere<F>);

/// `count` touching pairs (the same ones on every run).
pub fn touching_pairs<F: Float>(count: usize) -> Vec<(Sphere<F>, Sphere<F>)> {
    let mut random = Xorshift::new(0x9e37_79b9_7f4a_7c15);
    let mut next = || random.unit() * 2.0 - 1.0;
    (0..count)
        .map(|_| {
            let r = 5e-4;
            let direction = [next(), next(), next()];
            let length = (direction.iter().map(|x| x * x).sum::<f64>())
                .sqrt()
                .max(1e-3);
            let distance = 2.0 * r * (1.0 - 0.005 * (1.0 + next()));
            let f = F::from_f64;
            let v = |a: [f64; 3], s: f64| to_vec3::<F>(a.map(|x| x * s));
            let i = Sphere::solid(Vec3::ZERO, f(r), f(2500.0));
            let mut j = Sphere::solid(v(direction, distance / length), f(r), f(2500.0));
            j.velocity = v([next(), next(), next()], 0.1);
            j.angular_velocity = v([next(), next(), next()], 100.0);
            (i, j)
        })
        .collect()
}

/// Every pair one at a time, each sphere checked at every call as a C host's call does, each
/// pair with its state.
pub fn one_at_a_time<L: Law>(
    law: &L,
    time_step: TimeStep<L::Float>,
    pairs: &[Pair<L::Float>],
    states: &mut [L::State],
) -> Vec<Result<Interaction<L::Float>, ContactError>> {
    let mut bound = law.at(time_step);
    pairs
        .iter()
        .zip(states.iter_mut())
        .map(|((i, j), state)| {
            let i = CheckedSphere::new(*i)?;
            let j = CheckedSphere::new(*j)?;
            bound.sphere_sphere(&i, &j, state)
        })
        .collect()
}
