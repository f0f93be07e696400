//! The stability limit the kernel enforces is where explicit integration actually fails: just
//! below it a contact behaves, just above it the normal mode diverges, and for the stateless law
//! the sticking phase starts to chatter. (A `TimeStep` is checked against the effective mass the
//! caller declares; declaring a heavier one and tolerating the contacts past it is how these
//! tests step past the limit on purpose: otherwise the kernel refuses them, `unstable_contacts.rs`.)

use host_tests::impact::{floor, incoming_sphere, wall_impact};
use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    ContactLaw, Frictionless, Interaction, LinearSpringDashpot, Sphere, Stateless,
    TangentialParameters, Vec3,
};

/// Largest distance from the static overlap over the last quarter of `steps`, relative to the
/// initial 1 % perturbation, for a sphere resting on the floor under gravity, stepped at `fraction`
/// of the limit. (The perturbation is small so the contact never opens: near the limit the discrete
/// oscillation is several times larger than the continuous one, and an opening contact would turn
/// the test into a bouncing ball.)
fn resting_oscillation(restitution: f64, fraction: f64, steps: usize) -> f64 {
    let normal = LinearSpringDashpot::new(1000.0, restitution).unwrap();
    let law = ContactLaw::new(normal, Frictionless);
    let (radius, density, gravity) = (1.0e-3, 2500.0, 9.81);
    let mass = Sphere::solid(Vec3::ZERO, radius, density).mass;
    let static_overlap = mass * gravity / 1000.0;
    let mut sphere = Sphere::solid(
        Vec3::new(0.0, 0.0, radius - 1.01 * static_overlap),
        radius,
        density,
    );
    let limit = law.critical_time_step(mass);
    let dt = law
        .coarse_time_step(fraction * limit, 4.0 * mass)
        .unwrap()
        .tolerating_unstable_contacts();
    let wall = floor();
    let mut worst = 0.0f64;
    for step in 0..steps {
        let (force, torque) = match law.sphere_wall(&sphere, &wall, &mut (), dt).unwrap() {
            Interaction::Touching(c) => (c.force_on_i(), c.torque_on_i),
            Interaction::Apart => (Vec3::ZERO, Vec3::ZERO),
        };
        advance_solid_sphere(
            &mut sphere,
            force + Vec3::new(0.0, 0.0, -gravity * mass),
            torque,
            dt,
        );
        if step >= 3 * steps / 4 {
            worst = worst.max((radius - sphere.position.z - static_overlap).abs());
        }
    }
    worst / (0.01 * static_overlap)
}

#[test]
fn the_normal_mode_is_stable_below_the_limit_and_diverges_above_it() {
    for e in [1.0, 0.9, 0.5, 0.1] {
        let below = resting_oscillation(e, 0.98, 4000);
        let above = resting_oscillation(e, 1.03, 4000);
        println!(
            "e = {e}: oscillation / initial perturbation after 4000 steps: {below:.3e} at 0.98 x limit, {above:.3e} at 1.03 x limit"
        );
        // Below the limit the discrete amplitude stays bounded (at most 1/sqrt(1 - 0.98^2) = 5x).
        assert!(below <= 5.1, "e = {e}: grew below the limit ({below})");
        assert!(
            above > 10.0,
            "e = {e}: did not diverge above the limit ({above})"
        );
    }
}

#[test]
fn the_stateless_law_chatters_past_its_tangential_limit() {
    // Kharaz setup: rotating spheres, k_t/k_n = 0.86, so the stateless law's sticking phase
    // limits the step to about t_c/15, well before the normal mode's 0.63 t_c.
    let normal = LinearSpringDashpot::new(1000.0, 0.98).unwrap();
    let law = ContactLaw::new(
        normal,
        Stateless(TangentialParameters::new(860.0, 0.0, 0.092).unwrap()),
    );
    let mass = incoming_sphere(2.5e-3, 2700.0, 3.9, 0.0).mass;
    let t_c = law.contact_duration(mass);
    let limit = law.critical_time_step(mass);
    println!("stateless law: limit = t_c / {:.2}", t_c / limit);
    assert!((14.0..16.0).contains(&(t_c / limit)));
    for angle in [5.0, 15.0, 25.0] {
        let e_t = |steps: f64| {
            let sphere = incoming_sphere(2.5e-3, 2700.0, 3.9, angle);
            let dt = law
                .coarse_time_step(t_c / steps, 100.0 * mass)
                .unwrap()
                .tolerating_unstable_contacts();
            let out = wall_impact(&law, sphere, &floor(), dt, 10_000, |_| {}).unwrap();
            out.rebound.velocity.x / sphere.velocity.x
        };
        let (inside, outside) = (e_t(16.0), e_t(10.0));
        println!(
            "{angle} deg: e_t = {inside:.5} at t_c/16, {outside:.5} at t_c/10 (theory 5/7 = 0.71429)"
        );
        assert!((inside - 5.0 / 7.0).abs() < 1e-3, "{angle}: {inside}");
        assert!((outside - 5.0 / 7.0).abs() > 5e-4, "{angle}: {outside}");
    }
}

#[test]
fn below_the_limit_accuracy_depends_on_where_a_step_meets_the_contact() {
    // The limit guards stability, not accuracy: an undamped impact's rebound depends on the phase
    // at which a step first finds the overlap. Across 50 entry phases: within 0.01 % at t_c/50,
    // 0.25 % at t_c/10, a few percent at t_c/5.
    let law = ContactLaw::new(LinearSpringDashpot::new(1000.0, 1.0).unwrap(), Frictionless);
    let incoming = incoming_sphere(2.5e-3, 2700.0, 3.9, 0.0);
    let t_c = law.contact_duration(incoming.mass);
    for (steps, tolerance) in [(50.0, 1e-4), (10.0, 2.5e-3), (5.0, 2.5e-2)] {
        let dt = law.coarse_time_step(t_c / steps, incoming.mass).unwrap();
        let mut spread = 0.0f64;
        for phase in 0..50 {
            let mut sphere = incoming;
            sphere.position.z += 3.9 * dt.seconds() * phase as f64 / 50.0;
            let out = wall_impact(&law, sphere, &floor(), dt, 10_000, |_| {}).unwrap();
            spread = spread.max((out.rebound.velocity.z / 3.9 - 1.0).abs());
        }
        println!("t_c/{steps}: rebound ratio within {spread:.2e} of 1 over 50 entry phases");
        assert!(spread < tolerance, "t_c/{steps}: {spread}");
    }
}

#[test]
fn model_c_is_limited_by_the_root_of_its_step_dependent_dashpot() {
    use soft_sphere::prelude::ModelC;
    // Model C's tangential force is a dashpot of strength c = k_t dt + eta_t: a sticking contact
    // of mass m_t stays stable while c dt < 2 m_t, that is below the positive root of
    // k_t dt^2 + eta_t dt = 2 m_t. A stiff tangential spring makes that root the law's limit.
    let (k_n, k_t, ratio, e, mass): (f64, f64, f64, f64, f64) = (1000.0, 8000.0, 0.5, 0.7, 1.0e-5);
    let normal = LinearSpringDashpot::new(k_n, e).unwrap();
    let law = ContactLaw::new(
        normal,
        ModelC(TangentialParameters::new(k_t, ratio, 0.3).unwrap()),
    );
    let eta_t = ratio * law.oscillator(mass).damping_coefficient;
    let m_t = 2.0 / 7.0 * mass;
    let root = (-eta_t + (eta_t * eta_t + 8.0 * k_t * m_t).sqrt()) / (2.0 * k_t);
    let normal_limit = ContactLaw::new(normal, Frictionless).critical_time_step(mass);
    assert!(root < normal_limit);
    assert!((law.critical_time_step(mass) / root - 1.0).abs() < 1e-12);
}
