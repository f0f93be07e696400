//! Drives one sphere into a wall with a kernel law and the kernel's symplectic Euler step, and
//! reports what came out. Used by the normal-impact and oblique-impact tests.

use soft_sphere::motion::{advance_solid_sphere, drift, half_kick};
use soft_sphere::prelude::{
    CheckedSphere, ContactError, ContactForces, Float, Interaction, Law, Sphere, TimeStep, Vec3,
    Wall,
};

/// What a wall impact produced.
#[derive(Clone, Copy, Debug)]
pub struct ImpactOutcome<F> {
    /// The sphere just after it left the wall.
    pub rebound: Sphere<F>,
    /// Time from first touch to separation (s), the last step interpolated linearly in overlap.
    pub contact_duration: f64,
    /// Largest overlap seen (m).
    pub max_overlap: f64,
    /// Steps with the sphere touching the wall.
    pub steps_in_contact: usize,
}

/// The integrators, where each one evaluates the contact (see `soft_sphere::motion`): the
/// scene's, so that the impact driver and the scene name them alike.
pub use soft_sphere_scene::Integrator;

/// The floor `z = 0` with its normal up.
pub fn floor<F: Float>() -> Wall<F> {
    Wall::new(Vec3::ZERO, Vec3::new(F::ZERO, F::ZERO, F::ONE)).expect("the floor is valid")
}

/// A sphere just touching the floor, moving at `speed` at `angle_deg` from the floor's normal
/// (tangential component along +x, normal component along -z), without spin.
pub fn incoming_sphere<F: Float>(radius: F, density: F, speed: f64, angle_deg: f64) -> Sphere<F> {
    let mut sphere = Sphere::solid(Vec3::new(F::ZERO, F::ZERO, radius), radius, density);
    let theta = angle_deg.to_radians();
    sphere.velocity = Vec3::new(
        F::from_f64(speed * theta.sin()),
        F::ZERO,
        F::from_f64(-speed * theta.cos()),
    );
    sphere
}

/// Integrates `sphere` against `wall` with symplectic Euler until it separates (or `max_steps`
/// pass), calling `observe` with the contact forces of every step in contact.
///
/// # Errors
/// The first [`ContactError`] the kernel returns; `Err(None)` when the sphere had not separated
/// after `max_steps`.
pub fn wall_impact<L: Law>(
    law: &L,
    sphere: Sphere<L::Float>,
    wall: &Wall<L::Float>,
    time_step: TimeStep<L::Float>,
    max_steps: usize,
    observe: impl FnMut(&ContactForces<L::Float>),
) -> Result<ImpactOutcome<L::Float>, Option<ContactError>> {
    wall_impact_with(
        Integrator::SymplecticEuler,
        law,
        sphere,
        wall,
        time_step,
        max_steps,
        observe,
    )
}

/// [`wall_impact`] with a chosen integrator. The sphere starts at `t = 0`, which must be the
/// moment of first touch for `contact_duration` to mean the duration.
///
/// # Errors
/// As [`wall_impact`].
pub fn wall_impact_with<L: Law>(
    integrator: Integrator,
    law: &L,
    mut sphere: Sphere<L::Float>,
    wall: &Wall<L::Float>,
    time_step: TimeStep<L::Float>,
    max_steps: usize,
    mut observe: impl FnMut(&ContactForces<L::Float>),
) -> Result<ImpactOutcome<L::Float>, Option<ContactError>> {
    let dt = time_step.seconds().to_f64();
    let mut state = L::State::default();
    let mut touched = false;
    let mut steps_in_contact = 0;
    let mut max_overlap = 0.0f64;
    let mut last_overlap = 0.0f64;
    // Velocity Verlet carries the last forces into the next step's first half kick.
    let mut carried = (Vec3::ZERO, Vec3::ZERO);
    for step in 0..max_steps {
        // Symplectic Euler evaluates at the start of the step, velocity Verlet at its end.
        let evaluated_at = match integrator {
            Integrator::SymplecticEuler => step as f64,
            Integrator::VelocityVerlet => {
                half_kick(&mut sphere, carried.0, carried.1, time_step);
                drift(&mut sphere, time_step);
                step as f64 + 1.0
            }
        };
        let checked = CheckedSphere::new(sphere).map_err(Some)?;
        let (force, torque) = match law
            .at(time_step)
            .sphere_wall(&checked, wall, &mut state)
            .map_err(Some)?
        {
            Interaction::Touching(forces) => {
                touched = true;
                steps_in_contact += 1;
                last_overlap = forces.overlap.to_f64();
                max_overlap = max_overlap.max(last_overlap);
                observe(&forces);
                (forces.force_on_i(), forces.torque_on_i)
            }
            Interaction::Apart if touched => {
                if integrator == Integrator::VelocityVerlet {
                    half_kick(&mut sphere, Vec3::ZERO, Vec3::ZERO, time_step);
                }
                // Overlap went from last_overlap > 0 to the current (<= 0) over the last step.
                let now = (sphere.radius - wall.distance_to(sphere.position)).to_f64();
                let fraction = last_overlap / (last_overlap - now);
                let contact_duration = (evaluated_at - 1.0 + fraction) * dt;
                return Ok(ImpactOutcome {
                    rebound: sphere,
                    contact_duration,
                    max_overlap,
                    steps_in_contact,
                });
            }
            Interaction::Apart => (Vec3::ZERO, Vec3::ZERO),
        };
        match integrator {
            Integrator::SymplecticEuler => {
                advance_solid_sphere(&mut sphere, force, torque, time_step);
            }
            Integrator::VelocityVerlet => {
                half_kick(&mut sphere, force, torque, time_step);
                carried = (force, torque);
            }
        }
    }
    Err(None)
}

/// Rebound of an oblique wall impact, in the quantities the Kharaz experiment reports.
#[derive(Clone, Copy, Debug)]
pub struct Rebound {
    /// `V_t,out / V_t,in` of the centre of mass.
    pub tangential_restitution: f64,
    /// Rebound angular velocity about the axis of rolling (rad/s), positive for forward roll.
    pub spin: f64,
    /// Angle of the rebound velocity from the wall normal (degrees).
    pub rebound_angle_deg: f64,
}

/// The Kharaz oblique impact (docs/physics.md, section 5.2): a sphere of `radius` and `density` hitting the floor
/// at `speed` and `angle_deg` from its normal, integrated at `dt = t_c / steps_per_contact`.
///
/// # Panics
/// When the step is unstable or the sphere does not rebound: both are test failures.
pub fn oblique_rebound<L: Law>(
    law: &L,
    radius: L::Float,
    density: L::Float,
    speed: f64,
    angle_deg: f64,
    steps_per_contact: f64,
    observe: impl FnMut(&ContactForces<L::Float>),
) -> Rebound {
    let sphere = incoming_sphere(radius, density, speed, angle_deg);
    let duration = law.contact_duration(sphere.mass);
    let dt = law
        .time_step(
            duration / L::Float::from_f64(steps_per_contact),
            sphere.mass,
        )
        .expect("a stable step");
    let max_steps = 20 * steps_per_contact as usize;
    let out =
        wall_impact(law, sphere, &floor(), dt, max_steps, observe).expect("the sphere rebounds");
    let v_in = sphere.velocity;
    let v_out = out.rebound.velocity;
    Rebound {
        tangential_restitution: (v_out.x / v_in.x).to_f64(),
        spin: out.rebound.angular_velocity.y.to_f64(),
        rebound_angle_deg: v_out.x.to_f64().atan2(v_out.z.to_f64()).to_degrees(),
    }
}

/// Integrates two spheres through a collision until they separate (or `max_steps` pass), with
/// fresh per-contact state, calling `observe` every step they touch. Returns the spheres after.
///
/// # Errors
/// The first [`ContactError`]; `Err(None)` when they are still touching after `max_steps`.
pub fn pair_collision<L: Law>(
    law: &L,
    mut i: Sphere<L::Float>,
    mut j: Sphere<L::Float>,
    time_step: TimeStep<L::Float>,
    max_steps: usize,
    mut observe: impl FnMut(&ContactForces<L::Float>, &Sphere<L::Float>, &Sphere<L::Float>),
) -> Result<[Sphere<L::Float>; 2], Option<ContactError>> {
    let mut state = L::State::default();
    let mut touched = false;
    for _ in 0..max_steps {
        let (a, b) = (
            CheckedSphere::new(i).map_err(Some)?,
            CheckedSphere::new(j).map_err(Some)?,
        );
        match law
            .at(time_step)
            .sphere_sphere(&a, &b, &mut state)
            .map_err(Some)?
        {
            Interaction::Touching(forces) => {
                touched = true;
                observe(&forces, &i, &j);
                advance_solid_sphere(&mut i, forces.force_on_i(), forces.torque_on_i, time_step);
                advance_solid_sphere(&mut j, forces.force_on_j(), forces.torque_on_j, time_step);
            }
            Interaction::Apart if touched => return Ok([i, j]),
            Interaction::Apart => {
                advance_solid_sphere(&mut i, Vec3::ZERO, Vec3::ZERO, time_step);
                advance_solid_sphere(&mut j, Vec3::ZERO, Vec3::ZERO, time_step);
            }
        }
    }
    Err(None)
}
