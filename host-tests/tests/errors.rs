//! Every error value is produced by the input that should produce it, nothing panics, and a
//! rejected evaluation leaves the caller's per-contact state exactly as it was.

use soft_sphere::prelude::{
    CheckedSphere, ContactError, ContactLaw, Frictionless, Interaction, LinearAA,
    LinearSpringDashpot, ModelAA, Parameter, ParameterError, Sphere, SpringDisplacement, Stateless,
    TangentialParameters, Vec3, Wall,
};

fn law() -> LinearAA<f64> {
    let normal = LinearSpringDashpot::new(1.0e4, 0.8).unwrap();
    ContactLaw::new(
        normal,
        ModelAA(TangentialParameters::new(3.0e3, 0.5, 0.4).unwrap()),
    )
}

fn touching_pair() -> (Sphere<f64>, Sphere<f64>) {
    let mut i = Sphere::solid(Vec3::new(0.0, 0.0, 0.0), 1.0e-3, 2500.0);
    let mut j = Sphere::solid(Vec3::new(1.9e-3, 0.0, 0.0), 1.0e-3, 2500.0);
    i.velocity = Vec3::new(0.1, 0.05, 0.0);
    j.angular_velocity = Vec3::new(0.0, 0.0, 30.0);
    (i, j)
}

#[test]
fn normal_law_parameters_are_validated() {
    use ParameterError::*;
    let k = Parameter::NormalStiffness;
    assert_eq!(LinearSpringDashpot::new(f64::NAN, 0.5), Err(NonFinite(k)));
    assert_eq!(
        LinearSpringDashpot::new(f64::INFINITY, 0.5),
        Err(NonFinite(k))
    );
    assert_eq!(LinearSpringDashpot::new(0.0, 0.5), Err(NotPositive(k)));
    assert_eq!(LinearSpringDashpot::new(-1.0, 0.5), Err(NotPositive(k)));
    assert_eq!(
        LinearSpringDashpot::new(1.0, f64::NAN),
        Err(NonFinite(Parameter::Restitution))
    );
    assert_eq!(
        LinearSpringDashpot::new(1.0, -0.01),
        Err(RestitutionOutOfRange)
    );
    assert_eq!(
        LinearSpringDashpot::new(1.0, 1.01),
        Err(RestitutionOutOfRange)
    );
    assert_eq!(
        LinearSpringDashpot::new(1.0f32, 1.0 + f32::EPSILON),
        Err(RestitutionOutOfRange)
    );
    // The ends of [0, 1] are valid: critical damping and no damping.
    assert_eq!(
        LinearSpringDashpot::new(1.0, 0.0).unwrap().damping_ratio(),
        1.0
    );
    assert_eq!(
        LinearSpringDashpot::new(1.0, 1.0).unwrap().damping_ratio(),
        0.0
    );
}

#[test]
fn tangential_parameters_are_validated() {
    use ParameterError::*;
    let new = TangentialParameters::<f64>::new;
    assert_eq!(
        new(f64::NAN, 0.5, 0.3),
        Err(NonFinite(Parameter::TangentialStiffness))
    );
    assert_eq!(
        new(0.0, 0.5, 0.3),
        Err(NotPositive(Parameter::TangentialStiffness))
    );
    assert_eq!(
        new(-5.0, 0.5, 0.3),
        Err(NotPositive(Parameter::TangentialStiffness))
    );
    assert_eq!(new(1.0, -0.1, 0.3), Err(Negative(Parameter::DashpotRatio)));
    assert_eq!(
        new(1.0, f64::INFINITY, 0.3),
        Err(NonFinite(Parameter::DashpotRatio))
    );
    assert_eq!(new(1.0, 0.5, -0.3), Err(Negative(Parameter::Friction)));
    assert_eq!(
        new(1.0, 0.5, f64::INFINITY),
        Err(NonFinite(Parameter::Friction))
    );
    assert!(
        new(1.0, 0.0, 0.0).is_ok(),
        "no dashpot and no friction are valid"
    );
}

#[test]
fn walls_are_validated() {
    let up = Vec3::new(0.0, 0.0, 2.0);
    assert_eq!(
        Wall::new(Vec3::new(f64::NAN, 0.0, 0.0), up),
        Err(ParameterError::NonFinite(Parameter::Wall))
    );
    assert_eq!(
        Wall::new(Vec3::ZERO, Vec3::new(0.0, f64::INFINITY, 0.0)),
        Err(ParameterError::NonFinite(Parameter::Wall))
    );
    assert_eq!(
        Wall::new(Vec3::ZERO, Vec3::new(1e200, 1e200, 0.0)),
        Err(ParameterError::NonFinite(Parameter::Wall))
    );
    assert_eq!(
        Wall::new(Vec3::<f64>::ZERO, Vec3::ZERO),
        Err(ParameterError::NotPositive(Parameter::Wall))
    );
    // A valid normal is normalised.
    assert_eq!(
        Wall::new(Vec3::ZERO, up).unwrap().direction(),
        Vec3::new(0.0, 0.0, 1.0)
    );
}

#[test]
fn time_steps_are_checked_against_the_analytic_stability_limit() {
    use ParameterError::*;
    let (k_n, k_t, e, ratio, mass) = (1.0e4, 3.0e3, 0.8f64, 0.5, 1.0e-5);
    let law = law();
    assert_eq!(
        law.coarse_time_step(f64::NAN, mass),
        Err(NonFinite(Parameter::TimeStep))
    );
    assert_eq!(
        law.coarse_time_step(0.0, mass),
        Err(NotPositive(Parameter::TimeStep))
    );
    assert_eq!(
        law.coarse_time_step(-1e-6, mass),
        Err(NotPositive(Parameter::TimeStep))
    );
    assert_eq!(
        law.coarse_time_step(1e-6, 0.0),
        Err(NotPositive(Parameter::Mass))
    );
    assert_eq!(
        law.coarse_time_step(1e-6, f64::INFINITY),
        Err(NonFinite(Parameter::Mass))
    );

    // Independent formula: dt < (2/w)(sqrt(1 + z^2) - z) for the normal mode (w0, zeta) and the
    // tangential spring (k_t on 2/7 m*, dashpot eta_t = ratio * eta_n).
    let bound = |w: f64, z: f64| 2.0 / w * ((1.0 + z * z).sqrt() - z);
    let zeta = -e.ln() / (std::f64::consts::PI.powi(2) + e.ln().powi(2)).sqrt();
    let eta_n = 2.0 * zeta * (mass * k_n).sqrt();
    let normal_limit = bound((k_n / mass).sqrt(), zeta);
    let m_t = 2.0 / 7.0 * mass;
    let tangential_limit = bound(
        (k_t / m_t).sqrt(),
        ratio * eta_n / (2.0 * (k_t * m_t).sqrt()),
    );
    let limit = normal_limit.min(tangential_limit);
    assert!((law.critical_time_step(mass) / limit - 1.0).abs() < 1e-12);
    assert!(law.coarse_time_step(limit * 0.999, mass).is_ok());
    match law.coarse_time_step(limit * 1.001, mass) {
        Err(TimeStepUnstable {
            time_step,
            limit: reported,
        }) => {
            assert_eq!(time_step, limit * 1.001);
            assert!((reported / limit - 1.0).abs() < 1e-12);
        }
        other => panic!("expected TimeStepUnstable, got {other:?}"),
    }
    // The documented boundary, to the last bit: a step at the limit is refused, the largest
    // float below it is accepted as given.
    let exact = law.critical_time_step(mass);
    assert!(matches!(
        law.coarse_time_step(exact, mass),
        Err(TimeStepUnstable { .. })
    ));
    let below = exact.next_down();
    assert_eq!(law.coarse_time_step(below, mass).unwrap().seconds(), below);
    // Without friction only the normal mode limits the step.
    let frictionless = ContactLaw::new(*law.normal(), Frictionless);
    assert!((frictionless.critical_time_step(mass) / normal_limit - 1.0).abs() < 1e-12);
}

/// Runs `evaluate` on a state holding a stored displacement and checks it fails with `expected`
/// and leaves the state bit for bit as it was.
fn rejects(
    expected: ContactError,
    evaluate: impl FnOnce(&mut SpringDisplacement<f64>) -> Result<Interaction<f64>, ContactError>,
) {
    let before = SpringDisplacement {
        displacement: Vec3::new(1.0e-7, -2.0e-7, 3.0e-8),
    };
    let mut state = before;
    assert_eq!(evaluate(&mut state), Err(expected));
    assert_eq!(
        state.displacement.to_array().map(f64::to_bits),
        before.displacement.to_array().map(f64::to_bits)
    );
}

#[test]
fn bad_sphere_inputs_get_their_error_and_change_nothing() {
    let law = law();
    let dt = law.time_step(1e-7, 1e-6).unwrap();
    let floor = Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap();
    type Spoil = fn(&mut Sphere<f64>);
    let cases: [(ContactError, Spoil); 9] = [
        (ContactError::NonFiniteInput, |s| s.position.y = f64::NAN),
        (ContactError::NonFiniteInput, |s| {
            s.velocity.z = f64::INFINITY
        }),
        (ContactError::NonFiniteInput, |s| {
            s.angular_velocity.x = f64::NEG_INFINITY
        }),
        (ContactError::NonFiniteInput, |s| s.radius = f64::NAN),
        (ContactError::NonFiniteInput, |s| s.mass = f64::INFINITY),
        (ContactError::NonPositiveRadius, |s| s.radius = 0.0),
        (ContactError::NonPositiveRadius, |s| s.radius = -1.0e-3),
        (ContactError::NonPositiveMass, |s| s.mass = 0.0),
        (ContactError::NonPositiveMass, |s| s.mass = -1.0),
    ];
    for (expected, spoil) in cases {
        let (mut i, j) = touching_pair();
        spoil(&mut i);
        rejects(expected, |state| law.sphere_sphere(&i, &j, state, dt));
        rejects(expected, |state| law.sphere_sphere(&j, &i, state, dt));
        let mut on_floor = Sphere::solid(Vec3::new(0.0, 0.0, 0.9e-3), 1.0e-3, 2500.0);
        spoil(&mut on_floor);
        rejects(expected, |state| {
            law.sphere_wall(&on_floor, &floor, state, dt)
        });
        // Checking once refuses it the same way.
        assert_eq!(CheckedSphere::new(i), Err(expected));
        assert_eq!(CheckedSphere::try_from(i), Err(expected));
        // A checked sphere given this motion refuses it and stays as it was; radius and mass
        // are not the motion's, and stay as checked.
        let mut moved = CheckedSphere::new(touching_pair().0).unwrap();
        let before = moved;
        let refused = moved.set_motion(i.position, i.velocity, i.angular_velocity);
        let motion_spoilt =
            !(i.position.is_finite() && i.velocity.is_finite() && i.angular_velocity.is_finite());
        assert_eq!(refused.is_err(), motion_spoilt);
        if motion_spoilt {
            assert_eq!(refused, Err(ContactError::NonFiniteInput));
            assert_eq!(moved, before);
        } else {
            assert_eq!((moved.radius, moved.mass), (before.radius, before.mass));
        }
    }
    // Every component of a motion is checked, and a finite one is taken whole.
    let (i, _) = touching_pair();
    for component in 0..9 {
        let mut motion = [i.position, i.velocity, i.angular_velocity].map(|v| [v.x, v.y, v.z]);
        motion[component / 3][component % 3] = f64::NAN;
        let [p, v, w] = motion.map(|[x, y, z]| Vec3::new(x, y, z));
        let mut checked = CheckedSphere::new(i).unwrap();
        assert_eq!(
            checked.set_motion(p, v, w),
            Err(ContactError::NonFiniteInput)
        );
        assert_eq!(*checked, i);
    }
    let mut checked = CheckedSphere::new(i).unwrap();
    let (p, v, w) = (
        Vec3::new(1.0, 2.0, 3.0),
        Vec3::new(4.0, 5.0, 6.0),
        Vec3::new(7.0, 8.0, 9.0),
    );
    checked.set_motion(p, v, w).unwrap();
    assert_eq!(
        *checked,
        Sphere {
            position: p,
            velocity: v,
            angular_velocity: w,
            ..i
        }
    );
    // A valid sphere passes, reads as itself and gives itself back; an image moved past the
    // largest float is refused.
    let (i, _) = touching_pair();
    let checked = CheckedSphere::new(i).unwrap();
    assert_eq!((*checked, checked.into_inner()), (i, i));
    let far = Vec3::new(f64::MAX, 0.0, 0.0);
    assert_eq!(
        checked.translated(far).map(CheckedSphere::into_inner),
        Ok(Sphere {
            position: i.position + far,
            ..i
        })
    );
    assert_eq!(
        checked.translated(far * 2.0),
        Err(ContactError::NonFiniteInput)
    );
}

#[test]
fn bad_wall_state_coincident_centres_and_overflow_get_their_errors() {
    let law = law();
    let dt = law.time_step(1e-7, 1e-6).unwrap();
    let floor = Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap();
    // A wall checks its velocity and point when they are set, so no contact sees a bad one.
    let wall_error = Err(ParameterError::NonFinite(Parameter::Wall));
    assert_eq!(
        floor.with_velocity(Vec3::new(f64::NAN, 0.0, 0.0)),
        wall_error
    );
    assert_eq!(
        floor.moved_to(Vec3::new(0.0, 0.0, f64::INFINITY)),
        wall_error
    );
    let moving = floor.with_velocity(Vec3::new(1.0, 0.0, 0.0)).unwrap();
    assert_eq!(moving.velocity(), Vec3::new(1.0, 0.0, 0.0));

    let (i, _) = touching_pair();
    rejects(ContactError::CoincidentCentres, |state| {
        law.sphere_sphere(&i, &i, state, dt)
    });

    // Finite inputs whose relative velocity overflows.
    let (mut i, mut j) = touching_pair();
    i.velocity.x = f64::MAX;
    j.velocity.x = -f64::MAX;
    rejects(ContactError::NonFiniteResult, |state| {
        law.sphere_sphere(&i, &j, state, dt)
    });
}

#[test]
fn single_precision_overflow_and_tiny_separations_are_defined() {
    let normal = LinearSpringDashpot::new(1.0e4f32, 0.8).unwrap();
    let law = ContactLaw::new(
        normal,
        Stateless(TangentialParameters::new(3.0e3, 0.5, 0.4).unwrap()),
    );
    let dt = law.time_step(1e-7, 1e-6).unwrap();
    let mut i = Sphere::solid(Vec3::new(0.0f32, 0.0, 0.0), 1.0e-3, 2500.0);
    let mut j = Sphere::solid(Vec3::new(1.0e-20, 0.0, 0.0), 1.0e-3, 2500.0);
    // Centres 1e-20 m apart: the squared distance underflows f32's normal range.
    assert_eq!(
        law.sphere_sphere(&i, &j, &mut (), dt),
        Err(ContactError::CoincidentCentres)
    );
    j.position.x = 1.9e-3;
    i.velocity.x = 3.0e38;
    j.velocity.x = -3.0e38;
    assert_eq!(
        law.sphere_sphere(&i, &j, &mut (), dt),
        Err(ContactError::NonFiniteResult)
    );
}

#[test]
fn separating_resets_the_state_and_touching_advances_it() {
    let law = law();
    let dt = law.time_step(1e-6, 1e-6).unwrap();
    let (i, mut j) = touching_pair();
    let mut state = SpringDisplacement {
        displacement: Vec3::new(0.0, 1e-7, 0.0),
    };
    let touching = law.sphere_sphere(&i, &j, &mut state, dt).unwrap();
    assert!(touching.forces().is_some());
    assert_ne!(
        state,
        SpringDisplacement {
            displacement: Vec3::new(0.0, 1e-7, 0.0)
        }
    );
    j.position.x = 2.5e-3;
    assert_eq!(
        law.sphere_sphere(&i, &j, &mut state, dt),
        Ok(Interaction::Apart)
    );
    assert_eq!(state, SpringDisplacement::default());
}

/// Every error says what went wrong in words a user can act on: each message is distinct and
/// names the parameter, index or values it carries.
#[test]
fn every_error_message_names_what_went_wrong() {
    use soft_sphere_scene::{SceneError, StepError};
    let messages: Vec<(String, &[&str])> = vec![
        (
            ParameterError::NonFinite(Parameter::Mass).to_string(),
            &["Mass", "finite"],
        ),
        (
            ParameterError::NotPositive(Parameter::Radius).to_string(),
            &["Radius", "positive"],
        ),
        (
            ParameterError::Negative(Parameter::Friction).to_string(),
            &["Friction", "negative"],
        ),
        (
            ParameterError::RestitutionOutOfRange.to_string(),
            &["restitution", "[0, 1]"],
        ),
        (
            ParameterError::ReboundUnreachable {
                rebound: 0.05,
                lowest: 0.135,
            }
            .to_string(),
            &["0.05", "0.135"],
        ),
        (
            ParameterError::TimeStepUnstable {
                time_step: 2e-6,
                limit: 1.5e-6,
            }
            .to_string(),
            &["2e-6", "1.5e-6"],
        ),
        (ContactError::NonFiniteInput.to_string(), &["NaN"]),
        (ContactError::NonPositiveRadius.to_string(), &["radius"]),
        (ContactError::NonPositiveMass.to_string(), &["mass"]),
        (ContactError::CoincidentCentres.to_string(), &["centres"]),
        (ContactError::NonFiniteResult.to_string(), &["overflow"]),
        (ContactError::HistoryFull.to_string(), &["full"]),
        (SceneError::BufferLength.to_string(), &["buffer"]),
        (SceneError::Domain.to_string(), &["domain"]),
        (SceneError::History.to_string(), &["stored"]),
        (
            SceneError::Sphere {
                index: 7,
                error: ContactError::NonPositiveMass,
            }
            .to_string(),
            &["sphere 7", "mass"],
        ),
        (
            StepError::Pair {
                spheres: [4, 9],
                error: ContactError::CoincidentCentres,
            }
            .to_string(),
            &["spheres 4 and 9", "centres"],
        ),
        (
            StepError::Wall {
                sphere: 2,
                wall: 1,
                error: ContactError::PastStableStep,
            }
            .to_string(),
            &["sphere 2", "wall 1", "stab"],
        ),
        (
            StepError::Material {
                sphere: 5,
                material: 3,
            }
            .to_string(),
            &["sphere 5", "material 3"],
        ),
        (
            StepError::WallMaterial {
                wall: 1,
                material: 8,
            }
            .to_string(),
            &["wall 1", "material 8"],
        ),
        (SceneError::Materials.to_string(), &["material"]),
        (StepError::ListFull.to_string(), &["list"]),
        (StepError::ParkingFull.to_string(), &["parking"]),
        (StepError::Diverged { index: 3 }.to_string(), &["sphere 3"]),
        (StepError::Halted.to_string(), &["stopped"]),
    ];
    for (k, (message, words)) in messages.iter().enumerate() {
        for word in *words {
            assert!(message.contains(word), "{message:?} should name {word:?}");
        }
        assert!(
            messages[..k].iter().all(|(other, _)| other != message),
            "{message:?} is not distinct"
        );
    }
}

/// The documented boundaries of contact, to the last bit: spheres touch while their distance is
/// below the sum of the radii (a sphere and a wall while its distance is below the radius), and
/// centres count as coincident while their squared distance is below the smallest normal float.
#[test]
fn contact_and_coincidence_begin_exactly_where_documented() {
    let law = law();
    let dt = law.time_step(1e-7, 1e-6).unwrap();
    let touches = |i: &Sphere<f64>, j: &Sphere<f64>| {
        matches!(
            law.sphere_sphere(i, j, &mut SpringDisplacement::default(), dt),
            Ok(Interaction::Touching(_))
        )
    };
    let (i, mut j) = touching_pair();
    let reach = i.radius + j.radius;
    j.position = Vec3::new(reach, 0.0, 0.0);
    assert!(!touches(&i, &j), "at the sum of the radii: apart");
    j.position.x = reach.next_down();
    assert!(touches(&i, &j), "just inside: touching");

    // Squared distance exactly the smallest normal: (2^-511)^2 = 2^-1022.
    let root = f64::MIN_POSITIVE.sqrt();
    assert_eq!(root * root, f64::MIN_POSITIVE);
    j.position = Vec3::new(root, 0.0, 0.0);
    assert!(
        touches(&i, &j),
        "at the smallest normal squared distance: a contact"
    );
    j.position.x = root.next_down();
    assert_eq!(
        law.sphere_sphere(&i, &j, &mut SpringDisplacement::default(), dt),
        Err(ContactError::CoincidentCentres)
    );

    let floor = Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap();
    let mut on_floor = Sphere::solid(Vec3::new(0.0, 0.0, 1.0e-3), 1.0e-3, 2500.0);
    let wall_touches = |s: &Sphere<f64>| {
        matches!(
            law.sphere_wall(s, &floor, &mut SpringDisplacement::default(), dt),
            Ok(Interaction::Touching(_))
        )
    };
    assert!(
        !wall_touches(&on_floor),
        "at one radius from the wall: apart"
    );
    on_floor.position.z = on_floor.radius.next_down();
    assert!(wall_touches(&on_floor), "just inside: touching");
}

#[test]
fn a_stored_state_that_would_overflow_is_refused_though_the_force_is_finite() {
    use soft_sphere::prelude::ModelAALuding;
    // Luding's reset divides by k_t: with a subnormal k_t the displacement it would store for a
    // sliding contact is infinite while the force (at the Coulomb limit) is finite.
    let law = ContactLaw::new(
        LinearSpringDashpot::new(1.0e4, 0.8).unwrap(),
        ModelAALuding(TangentialParameters::new(1e-310, 0.5, 1e-3).unwrap()),
    );
    let dt = law.time_step(1e-7, 1e-6).unwrap();
    let (i, j) = touching_pair();
    rejects(ContactError::NonFiniteResult, |state| {
        law.sphere_sphere(&i, &j, state, dt)
    });
}
