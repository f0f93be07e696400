//! A contact stiffer than its time step was checked for is never evaluated silently: the three
//! ways a user of the public API stepped past the limit unnoticed (a stiffer wall law, a Hertz
//! impact faster than declared, a declared mass heavier than the pair's) are refused with
//! `ContactError::PastStableStep`, or, when the step tolerates them, evaluated and counted. The
//! limit is the one `ContactLaw::time_step` enforces, so a contact inside it is never refused.

use host_tests::impact::floor;
use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    CheckedSphere, ContactError, ContactLaw, Frictionless, Hertz, HertzImpact, Interaction, Law,
    LinearAA, LinearSpringDashpot, ModelAA, Sphere, TangentialParameters, Vec3, effective_mass,
};

const RADIUS: f64 = 1.0e-3;
const DENSITY: f64 = 2500.0;

fn linear_aa(stiffness: f64) -> LinearAA<f64> {
    ContactLaw::new(
        LinearSpringDashpot::new(stiffness, 0.7).unwrap(),
        ModelAA(TangentialParameters::new(0.8 * stiffness, 0.5, 0.4).unwrap()),
    )
}

/// A sphere dropped from `height` above the floor and stepped through its bounce: the highest
/// it rises after the first touch (m), or the first error.
fn drop_on_floor<L: Law<Float = f64>>(
    law: &L,
    time_step: soft_sphere::prelude::TimeStep<f64>,
    height: f64,
) -> Result<f64, ContactError> {
    bounce(law, time_step, height).map(|(highest, _, _)| highest)
}

/// As [`drop_on_floor`], with how many steps the sphere touched the floor and how many contacts
/// the bound law counted past the stable step.
fn bounce<L: Law<Float = f64>>(
    law: &L,
    time_step: soft_sphere::prelude::TimeStep<f64>,
    height: f64,
) -> Result<(f64, usize, usize), ContactError> {
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, RADIUS + height), RADIUS, DENSITY);
    let gravity = Vec3::new(0.0, 0.0, -9.81);
    let mut bound = law.at(time_step);
    let mut state = Default::default();
    let (mut touched, mut highest, mut touching) = (false, 0.0f64, 0);
    let dt = time_step;
    let steps = (4.0 * (2.0 * height / 9.81).sqrt() / dt.seconds()) as usize;
    for _ in 0..steps {
        let checked = CheckedSphere::new(sphere)?;
        let (force, torque) = match bound.sphere_wall(&checked, &floor(), &mut state)? {
            Interaction::Touching(c) => {
                touched = true;
                touching += 1;
                (c.force_on_i(), c.torque_on_i)
            }
            Interaction::Apart => (Vec3::ZERO, Vec3::ZERO),
        };
        let weight = gravity * sphere.mass;
        advance_solid_sphere(&mut sphere, force + weight, torque, dt);
        if touched {
            highest = highest.max(sphere.position.z - RADIUS);
        }
    }
    assert!(touched, "the sphere never reached the floor");
    Ok((highest, touching, bound.inaccurate_contacts()))
}

#[test]
fn a_wall_law_stiffer_than_the_step_is_refused() {
    // The step is checked against the pair law (k_n = 1e3 N/m, two spheres: m/2) and used for a
    // wall law 1000 times stiffer: 2.7 times past the wall law's own limit.
    let (pair_law, wall_law) = (linear_aa(1.0e3), linear_aa(1.0e6));
    let mass = Sphere::solid(Vec3::ZERO, RADIUS, DENSITY).mass;
    let seconds = 0.5 * pair_law.critical_time_step(mass / 2.0);
    let step = pair_law.coarse_time_step(seconds, mass / 2.0).unwrap();
    assert!(seconds > 2.0 * wall_law.critical_time_step(mass));
    assert_eq!(
        drop_on_floor(&wall_law, step, 2.0e-3),
        Err(ContactError::PastStableStep)
    );
    // Tolerated, the same drop shows why: the sphere is thrown far above where it fell from,
    // and every step it touched the wall is counted past the stable step.
    let (rise, touching, unstable) =
        bounce(&wall_law, step.tolerating_unstable_contacts(), 2.0e-3).unwrap();
    assert!(rise > 4.0e-3, "rose {rise}");
    assert!(
        touching > 0 && unstable == touching,
        "{unstable} of {touching}"
    );
    // With the wall law's own step the drop rebounds below its height (e = 0.7).
    let own = wall_law
        .coarse_time_step(wall_law.recommended_time_step(mass), mass)
        .unwrap();
    let (rise, touching, unstable) = bounce(&wall_law, own, 2.0e-3).unwrap();
    assert!(rise < 2.0e-3 * 0.7 * 0.7 * 1.05, "rose {rise}");
    assert!(touching > 0 && unstable == 0, "{unstable} of {touching}");
}

/// A head-on impact at `speed` of two Hertz spheres under a law declared for 1 m/s, stepped at
/// `fraction` of its checked limit: the rebound speed, or the first error.
fn hertz_impact(speed: f64, fraction: f64, tolerate: bool) -> Result<(f64, usize), ContactError> {
    let largest = HertzImpact {
        speed: 1.0,
        effective_radius: RADIUS / 2.0,
    };
    let law = ContactLaw::new(Hertz::new(1.0e8, 0.7, largest).unwrap(), Frictionless);
    let mass = Sphere::solid(Vec3::ZERO, RADIUS, DENSITY).mass;
    let m_star = effective_mass(mass, mass);
    let mut step = law
        .coarse_time_step(fraction * law.critical_time_step(m_star), m_star)
        .unwrap();
    if tolerate {
        step = step.tolerating_unstable_contacts();
    }
    let mut i = Sphere::solid(Vec3::new(-RADIUS, 0.0, 0.0), RADIUS, DENSITY);
    let mut j = Sphere::solid(Vec3::new(RADIUS * 1.0001, 0.0, 0.0), RADIUS, DENSITY);
    i.velocity.x = speed / 2.0;
    j.velocity.x = -speed / 2.0;
    let mut bound = law.at(step);
    let dt = step;
    for _ in 0..1_000_000 {
        let (a, b) = (CheckedSphere::new(i)?, CheckedSphere::new(j)?);
        match bound.sphere_sphere(&a, &b, &mut ())? {
            Interaction::Touching(c) => {
                advance_solid_sphere(&mut i, c.force_on_i(), Vec3::ZERO, dt);
                advance_solid_sphere(&mut j, c.force_on_j(), Vec3::ZERO, dt);
            }
            Interaction::Apart if j.velocity.x > i.velocity.x => {
                return Ok((j.velocity.x - i.velocity.x, bound.inaccurate_contacts()));
            }
            Interaction::Apart => {
                advance_solid_sphere(&mut i, Vec3::ZERO, Vec3::ZERO, dt);
                advance_solid_sphere(&mut j, Vec3::ZERO, Vec3::ZERO, dt);
            }
        }
    }
    panic!("the impact did not end");
}

#[test]
fn a_hertz_impact_faster_than_declared_is_refused() {
    // Declared for 1 m/s, stepped at 0.9 of the checked limit: the declared impact is evaluated
    // with no contact refused (coarsely: two steps a contact, each past the accuracy limit and
    // counted), and at a tenth of it, within the accuracy limit, rebounds at e.
    let (_, coarse) = hertz_impact(1.0, 0.9, false).unwrap();
    assert!((1..=3).contains(&coarse), "{coarse} counted");
    let (rebound, unstable) = hertz_impact(1.0, 0.1, false).unwrap();
    assert!((rebound - 0.7_f64).abs() < 0.02, "rebound {rebound}");
    assert_eq!(unstable, 0);
    // At 20 m/s the overlap, and with it the stiffness, passes what the step was checked for.
    assert_eq!(
        hertz_impact(20.0, 0.9, false),
        Err(ContactError::PastStableStep)
    );
    // Tolerated, it is evaluated and counted.
    let (_, counted) = hertz_impact(20.0, 0.9, true).unwrap();
    assert!(counted > 0);
}

/// A head-on impact of two equal linear spheres with the step checked against `declared`; the
/// outcome and the contacts past the limit counted.
fn linear_pair(declared: f64, fraction: f64, tolerate: bool) -> Result<usize, ContactError> {
    let law = linear_aa(1.0e3);
    let mass = Sphere::solid(Vec3::ZERO, RADIUS, DENSITY).mass;
    let mut step = law
        .coarse_time_step(fraction * law.critical_time_step(declared), declared)
        .unwrap();
    if tolerate {
        step = step.tolerating_unstable_contacts();
    }
    let mut bound = law.at(step);
    let i = CheckedSphere::new(Sphere::solid(Vec3::ZERO, RADIUS, DENSITY)).unwrap();
    let j = CheckedSphere::new(Sphere::solid(
        Vec3::new(1.9 * RADIUS, 0.0, 0.0),
        RADIUS,
        DENSITY,
    ))
    .unwrap();
    assert_eq!(effective_mass(i.mass, j.mass), mass / 2.0);
    let mut state = Default::default();
    bound.sphere_sphere(&i, &j, &mut state)?;
    Ok(bound.inaccurate_contacts())
}

#[test]
fn a_step_checked_against_a_heavier_mass_is_refused() {
    let mass = Sphere::solid(Vec3::ZERO, RADIUS, DENSITY).mass;
    // Checked against m, the pair's m/2 is 1.41 times past its limit at 0.99 of m's.
    assert_eq!(
        linear_pair(mass, 0.99, false),
        Err(ContactError::PastStableStep)
    );
    assert_eq!(linear_pair(mass, 0.99, true), Ok(1));
    // Against the pair's own effective mass, just inside the limit: evaluated, and counted as
    // past the accuracy limit (the step is coarse); at a tenth of it, within both.
    assert_eq!(linear_pair(mass / 2.0, 0.999, false), Ok(1));
    assert_eq!(linear_pair(mass / 2.0, 0.1, false), Ok(0));
    // The per-call path refuses it too, and leaves the state as it was.
    let law = linear_aa(1.0e3);
    let step = law
        .coarse_time_step(0.99 * law.critical_time_step(mass), mass)
        .unwrap();
    let i = Sphere::solid(Vec3::ZERO, RADIUS, DENSITY);
    let mut j = Sphere::solid(Vec3::new(1.9 * RADIUS, 0.0, 0.0), RADIUS, DENSITY);
    j.velocity.y = 0.1;
    let mut state = soft_sphere::prelude::SpringDisplacement {
        displacement: Vec3::new(0.0, 1.0e-6, 0.0),
    };
    let before = state;
    assert_eq!(
        law.sphere_sphere(&i, &j, &mut state, step),
        Err(ContactError::PastStableStep)
    );
    assert_eq!(state, before);
}

#[test]
fn the_stable_phase_of_a_linear_oscillator_is_its_closed_form() {
    // 2 (sqrt(1 + z^2) - z): 2 undamped, smaller with damping (docs/physics.md, section 4).
    let spring = ContactLaw::new(
        soft_sphere::prelude::LinearSpring::new(1.0e3_f64).unwrap(),
        Frictionless,
    );
    assert!((spring.stable_phase() - 2.0).abs() < 1e-15);
    for e in [0.1_f64, 0.5, 0.9] {
        let law = ContactLaw::new(LinearSpringDashpot::new(1.0e3, e).unwrap(), Frictionless);
        let z = e.ln().abs() / (std::f64::consts::PI.powi(2) + e.ln().powi(2)).sqrt();
        let closed = 2.0 * ((1.0 + z * z).sqrt() - z);
        assert!((law.stable_phase() / closed - 1.0).abs() < 1e-14, "e = {e}");
    }
}

#[test]
fn the_stable_phase_is_the_critical_step_times_the_frequency_at_every_mass() {
    // The per-contact check and ContactLaw::time_step agree: a contact of effective mass m is
    // within the limit exactly when the step is below critical_time_step(m).
    let law = linear_aa(1.0e3);
    for mass in [1.0e-9, 1.0e-6, 1.0e-3, 1.0, 1.0e3] {
        let frequency = law.oscillator(mass).natural_frequency;
        let phase = law.critical_time_step(mass) * frequency;
        assert!((phase / law.stable_phase() - 1.0).abs() < 1e-12, "{mass}");
    }
    let largest = HertzImpact {
        speed: 3.0,
        effective_radius: 2.0e-3,
    };
    let hertz = ContactLaw::new(Hertz::new(5.0e9, 0.5, largest).unwrap(), Frictionless);
    for mass in [1.0e-9_f64, 1.0e-6, 1.0e-3, 1.0] {
        let design = soft_sphere::prelude::NormalModel::design_contact(hertz.normal(), mass);
        let phase = hertz.critical_time_step(mass) * design.oscillator.natural_frequency;
        assert!((phase / hertz.stable_phase() - 1.0).abs() < 1e-9, "{mass}");
    }
}

/// A Hertz contact just inside and just past its own limit (the step made for its overlap, its
/// radii and its masses from the closed forms, `w0 = sqrt(2 E* a / m*)`, `a = sqrt(R* delta)`):
/// the one-contact path evaluates the first and refuses the second, and the bound law on
/// checked spheres (the engines' path) gives the same verdict.
#[test]
fn a_hertz_contact_at_its_own_limit_gets_the_same_verdict_on_every_path() {
    // Declared for a slow impact, so that the step check at design passes both steps below.
    let largest = HertzImpact {
        speed: 1.0e-3,
        effective_radius: 4.0e-4,
    };
    let law = ContactLaw::new(Hertz::new(2.0e8, 0.6, largest).unwrap(), Frictionless);
    let (r_i, r_j, overlap) = (1.0e-3_f64, 0.6e-3, 2.0e-5);
    let i = Sphere::solid(Vec3::ZERO, r_i, 2500.0);
    let j = Sphere::solid(Vec3::new(r_i + r_j - overlap, 0.0, 0.0), r_j, 7800.0);
    let m_star = effective_mass(i.mass, j.mass);
    let a = (r_i * r_j / (r_i + r_j) * overlap).sqrt();
    let frequency = (2.0 * 2.0e8 * a / m_star).sqrt();
    let limit = law.stable_phase() / frequency;
    for (fraction, within) in [(0.999, true), (1.001, false)] {
        let step = law.coarse_time_step(fraction * limit, m_star).unwrap();
        let one = law.sphere_sphere(&i, &j, &mut (), step);
        assert_eq!(one.is_ok(), within, "{fraction}: {one:?}");
        let (a, b) = (
            CheckedSphere::new(i).unwrap(),
            CheckedSphere::new(j).unwrap(),
        );
        let bound = law.at(step).sphere_sphere(&a, &b, &mut ());
        assert_eq!(bound, one, "{fraction}");
    }
}
