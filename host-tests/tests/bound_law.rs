//! A bound law holds a copy of its law: it outlives the value it was made from, can be stored
//! in an engine's own structures or sent to another thread, and still gives, contact by
//! contact, the bits of the law's own checked evaluation (the peer path).

use soft_sphere::prelude::{
    BoundLaw, CheckedSphere, ContactLaw, ContactState, Interaction, LinearAA, LinearSpringDashpot,
    ModelAA, Sphere, SpringDisplacement, TangentialParameters, Vec3,
};

type Linear = LinearAA<f64>;

fn law() -> Linear {
    ContactLaw::new(
        LinearSpringDashpot::new(1.0e4, 0.8).unwrap(),
        ModelAA(TangentialParameters::new(3.0e3, 0.5, 0.4).unwrap()),
    )
}

/// An oblique approach: the pair touches for some of the steps and slides for part of them.
fn pair(step: usize) -> (Sphere<f64>, Sphere<f64>) {
    let x = 2.05e-3 - 1.0e-6 * step as f64;
    let i = Sphere {
        velocity: Vec3::new(0.1, 0.05, 0.0),
        ..Sphere::solid(Vec3::ZERO, 1.0e-3, 2500.0)
    };
    let j = Sphere {
        velocity: Vec3::new(-0.1, -0.05, 0.02),
        ..Sphere::solid(Vec3::new(x, 1.0e-4, 0.0), 1.0e-3, 2500.0)
    };
    (i, j)
}

/// The bound law made inside a function whose law is gone when it returns.
fn bound_from_a_temporary_law() -> (BoundLaw<Linear>, soft_sphere::prelude::TimeStep<f64>) {
    let law = law();
    let dt = law
        .time_step(1.0e-6, 0.5 * Sphere::solid(Vec3::ZERO, 1.0e-3, 2500.0).mass)
        .unwrap();
    (law.at(dt), dt)
}

#[test]
fn a_bound_law_outlives_its_law_and_gives_its_bits_on_another_thread() {
    let (mut bound, dt) = bound_from_a_temporary_law();
    let outcomes = std::thread::spawn(move || {
        let mut state = SpringDisplacement::default();
        (0..200)
            .map(|step| {
                let (i, j) = pair(step);
                let (i, j) = (
                    CheckedSphere::new(i).unwrap(),
                    CheckedSphere::new(j).unwrap(),
                );
                (bound.sphere_sphere(&i, &j, &mut state).unwrap(), state)
            })
            .collect::<Vec<_>>()
    })
    .join()
    .unwrap();
    let peer = law();
    let mut state = SpringDisplacement::default();
    let mut touching = 0;
    for (step, (outcome, after)) in outcomes.into_iter().enumerate() {
        let (i, j) = pair(step);
        let expected = peer.sphere_sphere(&i, &j, &mut state, dt).unwrap();
        assert_eq!(
            format!("{outcome:?}"),
            format!("{expected:?}"),
            "step {step}"
        );
        assert!(after.same_bits(&state), "step {step}");
        touching += usize::from(matches!(expected, Interaction::Touching(_)));
    }
    assert!(touching > 50, "the pair touched in {touching} steps");
}
