//! Normal impact against the analytic linear spring-dashpot solution (docs/physics.md, sections 2 and 5.1):
//! rebound ratio e, duration t_c, peak overlap, and the clamped-force restitution of
//! Schwager & Poeschel (2007).

use host_tests::analytic;
use host_tests::impact::{floor, incoming_sphere, wall_impact};
use soft_sphere::prelude::{
    ContactLaw, Frictionless, Law, LinearSpring, LinearSpringDashpot, Micromath, ParameterError,
};

const STIFFNESS: f64 = 1000.0;
const RADIUS: f64 = 2.5e-3;
const DENSITY: f64 = 2700.0;
const SPEED: f64 = 3.9;
const RESTITUTIONS: [f64; 7] = [0.1, 0.3, 0.5, 0.7, 0.9, 0.98, 1.0];

struct Measured {
    rebound_ratio: f64,
    duration: f64,
    max_overlap: f64,
    mass: f64,
}

fn head_on_f64(restitution: f64, clamped: bool, steps_per_contact: f64) -> Measured {
    let mut normal = LinearSpringDashpot::new(STIFFNESS, restitution).unwrap();
    if clamped {
        normal = normal.with_attraction_clamped();
    }
    let law = ContactLaw::new(normal, Frictionless);
    let sphere = incoming_sphere(RADIUS, DENSITY, SPEED, 0.0);
    let mass = sphere.mass;
    let duration = analytic::contact_duration(STIFFNESS, restitution, mass);
    let dt = law.time_step(duration / steps_per_contact, mass).unwrap();
    let outcome = wall_impact(
        &law,
        sphere,
        &floor(),
        dt,
        10 * steps_per_contact as usize,
        |_| {},
    )
    .expect("the sphere rebounds");
    Measured {
        rebound_ratio: outcome.rebound.velocity.z / SPEED,
        duration: outcome.contact_duration,
        max_overlap: outcome.max_overlap,
        mass,
    }
}

#[test]
fn free_impact_rebounds_with_e_and_lasts_t_c() {
    for e in RESTITUTIONS {
        let m = head_on_f64(e, false, 20_000.0);
        let t_c = analytic::contact_duration(STIFFNESS, e, m.mass);
        let peak = analytic::max_overlap(STIFFNESS, e, m.mass, SPEED);
        assert!(
            (m.rebound_ratio - e).abs() < 1e-4,
            "e = {e}: rebound ratio {}",
            m.rebound_ratio
        );
        assert!(
            (m.duration / t_c - 1.0).abs() < 1e-4,
            "e = {e}: duration {} vs t_c {t_c}",
            m.duration
        );
        assert!(
            (m.max_overlap / peak - 1.0).abs() < 1e-4,
            "e = {e}: peak overlap {} vs {peak}",
            m.max_overlap
        );
    }
}

#[test]
fn clamped_impact_matches_schwager_poeschel() {
    // The published figures (docs/physics.md, section 2): 0.5 -> 0.5503, 0.9 -> 0.9020.
    assert!((analytic::clamped_restitution(0.5) - 0.5503).abs() < 5e-5);
    assert!((analytic::clamped_restitution(0.9) - 0.9020).abs() < 5e-5);
    for e in RESTITUTIONS {
        let m = head_on_f64(e, true, 20_000.0);
        let expected = analytic::clamped_restitution(e);
        assert!(
            (m.rebound_ratio - expected).abs() < 1e-4,
            "e = {e}: clamped rebound {} vs analytic {expected}",
            m.rebound_ratio
        );
    }
}

#[test]
fn kernel_contact_duration_matches_the_closed_form() {
    for e in RESTITUTIONS {
        let mass = 1.7e-4;
        let law = ContactLaw::new(
            LinearSpringDashpot::new(STIFFNESS, e).unwrap(),
            Frictionless,
        );
        let t_c = analytic::contact_duration(STIFFNESS, e, mass);
        assert!(
            (law.contact_duration(mass) / t_c - 1.0).abs() < 1e-12,
            "e = {e}"
        );
        assert!(
            (law.recommended_time_step(mass) * 50.0 / t_c - 1.0).abs() < 1e-12,
            "e = {e}"
        );
    }
    // Critical damping: the free contact never ends; the clamped one ends at t = 2 / beta.
    let critical = LinearSpringDashpot::new(STIFFNESS, 0.0).unwrap();
    assert!(
        !critical.clamps_attraction(),
        "the pull is kept unless the clamp is asked for"
    );
    assert_eq!(
        (critical.stiffness(), critical.restitution()),
        (STIFFNESS, 0.0)
    );
    let law = ContactLaw::new(critical, Frictionless);
    assert!(law.contact_duration(1.0).is_infinite());
    // Without an end, 1/50 of the undamped half-period pi / w0 stands in for the duration (it is
    // below a fifth of the limit, 0.166 / w0 at critical damping); an engine generic over the
    // sealed `Law` trait sees the same step.
    let w0 = (STIFFNESS / 1.0f64).sqrt();
    assert!(
        (law.recommended_time_step(1.0) * 50.0 * w0 / std::f64::consts::PI - 1.0).abs() < 1e-12
    );
    fn through_trait<L: Law<Float = f64>>(law: &L, mass: f64) -> f64 {
        law.recommended_time_step(mass)
    }
    assert_eq!(through_trait(&law, 1.0), law.recommended_time_step(1.0));
    let law = ContactLaw::new(critical.with_attraction_clamped(), Frictionless);
    let beta = w0;
    assert!((law.contact_duration(1.0) * beta / 2.0 - 1.0).abs() < 1e-12);
}

#[test]
fn the_oscillator_has_the_damping_ratio_of_its_restitution() {
    for e in RESTITUTIONS {
        let law = ContactLaw::new(
            LinearSpringDashpot::new(STIFFNESS, e).unwrap(),
            Frictionless,
        );
        let oscillator = law.oscillator(1.7e-4);
        // zeta = -ln e / sqrt(pi^2 + ln^2 e), and beta / w0 is that ratio.
        let zeta = -e.ln() / (std::f64::consts::PI.powi(2) + e.ln().powi(2)).sqrt();
        assert!((oscillator.damping_ratio() - zeta).abs() < 1e-12, "e = {e}");
        let w0 = (STIFFNESS / 1.7e-4f64).sqrt();
        assert!((oscillator.natural_frequency / w0 - 1.0).abs() < 1e-12);
    }
}

#[test]
fn first_order_error_shrinks_with_the_step() {
    // The symplectic Euler step is first order: halving dt roughly halves the rebound error.
    let coarse = (head_on_f64(0.1, false, 50.0).rebound_ratio - 0.1).abs();
    let fine = (head_on_f64(0.1, false, 400.0).rebound_ratio - 0.1).abs();
    assert!(
        coarse > 1e-3,
        "t_c/50 should show the integrator's error at e = 0.1 ({coarse})"
    );
    assert!(
        fine < coarse / 4.0,
        "error {fine} at t_c/400 vs {coarse} at t_c/50"
    );
}

#[test]
fn single_precision_and_micromath_rebound_close_to_e() {
    // f32 and the approximate backend, at t_c/2000: bounds stated in docs/validation.md.
    for e in [0.5f32, 0.9, 1.0] {
        let normal = LinearSpringDashpot::new(STIFFNESS as f32, e).unwrap();
        let sphere = incoming_sphere(RADIUS as f32, DENSITY as f32, SPEED, 0.0);
        let t_c = analytic::contact_duration(STIFFNESS, e as f64, sphere.mass as f64) as f32;
        let law = ContactLaw::new(normal, Frictionless);
        let dt = law.time_step(t_c / 2000.0, sphere.mass).unwrap();
        let exact = wall_impact(&law, sphere, &floor(), dt, 40_000, |_| {}).unwrap();
        let ratio = exact.rebound.velocity.z as f64 / SPEED;
        assert!((ratio - e as f64).abs() < 2e-3, "f32 libm e = {e}: {ratio}");

        let fast = law.with_backend::<Micromath>();
        let approx = wall_impact(&fast, sphere, &floor(), dt, 40_000, |_| {}).unwrap();
        let ratio = approx.rebound.velocity.z as f64 / SPEED;
        assert!(
            (ratio - e as f64).abs() < 1e-2,
            "f32 micromath e = {e}: {ratio}"
        );
    }
}

#[test]
fn a_clamped_law_built_for_a_rebound_ratio_rebounds_with_it() {
    for target in [0.2, 0.5, 0.75, 0.9, 0.98, 1.0] {
        let normal = LinearSpringDashpot::clamped_with_rebound(STIFFNESS, target).unwrap();
        assert!(normal.clamps_attraction());
        assert_eq!(
            (normal.stiffness(), normal.restitution()),
            (STIFFNESS, target)
        );
        // Its oscillator, and the end of its force at wd t = 2 atan(wd / beta).
        let mass = 1.7e-4;
        let zeta = normal.damping_ratio();
        let w0 = (STIFFNESS / mass).sqrt();
        let (beta, wd) = (zeta * w0, w0 * (1.0 - zeta * zeta).sqrt());
        let oscillator = ContactLaw::new(normal, Frictionless).oscillator(mass);
        assert!(
            (oscillator.damped_frequency - wd).abs() <= 1e-12 * w0,
            "target {target}"
        );
        let end = if beta > 0.0 {
            2.0 * (wd / beta).atan() / wd
        } else {
            std::f64::consts::PI / w0
        };
        let duration = ContactLaw::new(normal, Frictionless).contact_duration(mass);
        assert!((duration / end - 1.0).abs() < 1e-12, "target {target}");
        // Schwager & Poeschel's closed form, written independently in `analytic`, for the
        // unclipped restitution with the same damping ratio gives the target back.
        let same_dashpot = (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
        assert!(
            (analytic::clamped_restitution(same_dashpot) - target).abs() < 1e-9,
            "target {target}"
        );
        // And an impact integrated at t_c / 20000 rebounds at it.
        let law = ContactLaw::new(normal, Frictionless);
        let sphere = incoming_sphere(RADIUS, DENSITY, SPEED, 0.0);
        let dt = law
            .time_step(law.contact_duration(sphere.mass) / 20_000.0, sphere.mass)
            .unwrap();
        let outcome = wall_impact(&law, sphere, &floor(), dt, 200_000, |_| {}).unwrap();
        let rebound = outcome.rebound.velocity.z / SPEED;
        assert!(
            (rebound - target).abs() < 1e-4,
            "target {target}: {rebound}"
        );
    }
    // The user's bisection found e = 0.4363 for a clipped rebound of 0.5.
    let half = LinearSpringDashpot::clamped_with_rebound(STIFFNESS, 0.5).unwrap();
    let bisected = LinearSpringDashpot::new(STIFFNESS, 0.4363).unwrap();
    assert!((half.damping_ratio() - bisected.damping_ratio()).abs() < 1e-4);
    // Below exp(-2) no damping ratio up to critical reaches it; the error says where the floor is.
    for unreachable in [0.0, 0.1, 0.135] {
        assert_eq!(
            LinearSpringDashpot::clamped_with_rebound(STIFFNESS, unreachable),
            Err(ParameterError::ReboundUnreachable {
                rebound: unreachable,
                lowest: (-2.0f64).exp()
            })
        );
    }
    // exp(-2) itself is critical damping.
    let lowest = LinearSpringDashpot::clamped_with_rebound(STIFFNESS, (-2.0f64).exp()).unwrap();
    assert!((lowest.damping_ratio() - 1.0).abs() < 1e-12);
    assert!(LinearSpringDashpot::clamped_with_rebound(STIFFNESS, 0.136).is_ok());
    assert_eq!(
        LinearSpringDashpot::clamped_with_rebound(STIFFNESS, 1.5),
        Err(ParameterError::RestitutionOutOfRange)
    );
}

#[test]
fn the_undamped_spring_rebounds_elastically_at_the_closed_form_duration() {
    let law = ContactLaw::new(LinearSpring::new(STIFFNESS).unwrap(), Frictionless);
    let sphere = incoming_sphere(RADIUS, DENSITY, SPEED, 0.0);
    let mass = sphere.mass;
    let w0 = (STIFFNESS / mass).sqrt();
    let oscillator = law.oscillator(mass);
    assert!((oscillator.natural_frequency / w0 - 1.0).abs() < 1e-12);
    assert_eq!(oscillator.damped_frequency, oscillator.natural_frequency);
    assert_eq!(
        (oscillator.damping_coefficient, oscillator.decay_rate),
        (0.0, 0.0)
    );
    // Half an undamped period; the stability bound 2 / w0.
    let t_c = std::f64::consts::PI / w0;
    assert!((law.contact_duration(mass) / t_c - 1.0).abs() < 1e-12);
    assert!((law.critical_time_step(mass) * w0 / 2.0 - 1.0).abs() < 1e-12);
    let dt = law.time_step(t_c / 2000.0, mass).unwrap();
    let outcome = wall_impact(&law, sphere, &floor(), dt, 20_000, |_| {}).unwrap();
    assert!((outcome.rebound.velocity.z / SPEED - 1.0).abs() < 1e-5);
    assert!((outcome.contact_duration / t_c - 1.0).abs() < 1e-3);
    assert!((outcome.max_overlap * w0 / SPEED - 1.0).abs() < 1e-3);
}
