//! The rolling-resistance slots: bad parameters give their error; the off slot is zero-sized and
//! keeps exactly the tangential state; the time step is checked against the rolling spring; and
//! for random collisions the rolling torque stays within `mu_r R* |F_n|`, creates no energy and
//! is the same bits with the bodies swapped. The closed-form cases are in `validation.rs`.

use host_tests::energy::kinetic;
use host_tests::strategies::{Collision, collision, config};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    ConstantRolling, ContactLaw, ElasticPlasticRolling, Interaction, Law, LinearSpringDashpot,
    ModelAA, NoRolling, Parameter, ParameterError, RollingModel, RollingSpring, Sphere,
    SpringDisplacement, TangentialParameters, Vec3, effective_mass,
};

#[test]
fn bad_rolling_parameters_are_refused_with_their_error() {
    use ParameterError::*;
    assert_eq!(
        ConstantRolling::new(-0.1),
        Err(Negative(Parameter::RollingFriction))
    );
    assert_eq!(
        ConstantRolling::new(f64::NAN),
        Err(NonFinite(Parameter::RollingFriction))
    );
    let e = ElasticPlasticRolling::new;
    assert_eq!(
        e(0.1, 0.0, 0.0, 1e-9),
        Err(NotPositive(Parameter::RollingStiffness))
    );
    assert_eq!(
        e(0.1, 1.0, -1.0, 1e-9),
        Err(Negative(Parameter::RollingDamping))
    );
    assert_eq!(e(0.1, 1.0, 0.0, 0.0), Err(NotPositive(Parameter::Inertia)));
    assert_eq!(
        e(f64::INFINITY, 1.0, 0.0, 1e-9),
        Err(NonFinite(Parameter::RollingFriction))
    );
}

#[test]
fn the_off_slot_costs_nothing_and_the_spring_three_floats() {
    assert_eq!(size_of::<NoRolling>(), 0);
    assert_eq!(
        size_of::<<NoRolling as RollingModel<f64>>::State<SpringDisplacement<f64>>>(),
        24
    );
    assert_eq!(
        size_of::<<ConstantRolling<f64> as RollingModel<f64>>::State<SpringDisplacement<f64>>>(),
        24
    );
    assert_eq!(size_of::<RollingSpring<SpringDisplacement<f64>, f64>>(), 48);
    assert_eq!(size_of::<RollingSpring<(), f32>>(), 12);
}

#[test]
fn the_time_step_is_checked_against_the_rolling_spring() {
    let normal = LinearSpringDashpot::new(1000.0, 0.9).unwrap();
    let p = TangentialParameters::new(860.0, 0.5, 0.5).unwrap();
    let (stiffness, inertia) = (1.0_f64, 1e-9_f64);
    let rolling = ElasticPlasticRolling::new(0.1, stiffness, 0.0, inertia).unwrap();
    let law = ContactLaw::new(normal, ModelAA(p)).with_rolling(rolling);
    let limit = 2.0 / (stiffness / inertia).sqrt();
    assert!((law.critical_time_step(1.0) / limit - 1.0).abs() < 1e-12);
    assert!(matches!(
        law.time_step(limit, 1.0),
        Err(ParameterError::TimeStepUnstable { .. })
    ));
    assert!(law.time_step(0.99 * limit, 1.0).is_ok());
    // With its dashpot: (2 / w) (sqrt(1 + z^2) - z), z = eta_r / (2 sqrt(k_r I)).
    let zeta = 0.3;
    let damping = 2.0 * zeta * (stiffness * inertia).sqrt();
    let rolling = ElasticPlasticRolling::new(0.1, stiffness, damping, inertia).unwrap();
    let law = ContactLaw::new(normal, ModelAA(p)).with_rolling(rolling);
    let damped = limit * ((1.0 + zeta * zeta).sqrt() - zeta);
    assert!((law.critical_time_step(1.0) / damped - 1.0).abs() < 1e-12);
}

const ROLLING_FRICTION: f64 = 0.2;

fn collide<Ro: RollingModel<f64>>(
    c: &Collision,
    make: impl Fn(f64, f64) -> Ro,
) -> Result<(), TestCaseError> {
    let (mut i, mut j) = c.pair::<f64>();
    // Equal radii: the rolling torque is then half the difference of the two torques.
    j.radius = i.radius;
    j.mass = i.mass;
    j.position = Vec3::new(c.normal[0], c.normal[1], c.normal[2]) * (2.0 * i.radius);
    let m = effective_mass(i.mass, j.mass);
    let k_n = c.normal_stiffness(m);
    let k_t = c.material.stiffness_ratio * k_n;
    let normal = LinearSpringDashpot::new(k_n, c.material.restitution).unwrap();
    let p = TangentialParameters::new(k_t, c.material.dashpot_ratio, c.material.friction).unwrap();
    let r_star = i.radius / 2.0;
    // k_r = k_t R*^2; the smallest inertia a sphere's own, 2/5 m R^2.
    let inertia = 0.4 * i.mass * i.radius * i.radius;
    let law =
        ContactLaw::new(normal, ModelAA(p)).with_rolling(make(k_t * r_star * r_star, inertia));
    let Ok(dt) = law.time_step(law.recommended_time_step(m), m) else {
        return Err(TestCaseError::reject(
            "the rolling spring needs a smaller step",
        ));
    };
    let before = kinetic(&i) + kinetic(&j);
    let (mut ij, mut ji) = (Default::default(), Default::default());
    let (mut touched, mut parted) = (false, false);
    for _ in 0..1_000_000 {
        let forward = law.sphere_sphere(&i, &j, &mut ij, dt).unwrap();
        let backward = law.sphere_sphere(&j, &i, &mut ji, dt).unwrap();
        match (forward, backward) {
            (Interaction::Touching(a), Interaction::Touching(b)) => {
                touched = true;
                prop_assert_eq!(a.torque_on_i, b.torque_on_j);
                let rolling = (a.torque_on_i - a.torque_on_j) * 0.5;
                let limit = ROLLING_FRICTION * r_star * a.normal_force.abs();
                let size = rolling.norm_squared().sqrt();
                prop_assert!(
                    size <= limit * (1.0 + 1e-12) + 1e-300,
                    "rolling torque {size:e} over {limit:e}"
                );
                advance_solid_sphere(&mut i, a.force_on_i(), a.torque_on_i, dt);
                advance_solid_sphere(&mut j, a.force_on_j(), a.torque_on_j, dt);
            }
            (Interaction::Apart, Interaction::Apart) if touched => {
                parted = true;
                break;
            }
            (Interaction::Apart, Interaction::Apart) => {
                advance_solid_sphere(&mut i, Vec3::ZERO, Vec3::ZERO, dt);
                advance_solid_sphere(&mut j, Vec3::ZERO, Vec3::ZERO, dt);
            }
            _ => prop_assert!(false, "one ordering touches, the other not"),
        }
    }
    // At e = 0 the normal mode is critically damped: the overlap decays without crossing zero
    // (`v t exp(-w t)`), so a perfectly plastic pair may move on together, touching ever less.
    prop_assert!(
        parted || c.material.restitution == 0.0,
        "the spheres are still touching"
    );
    let gain = (kinetic(&i) + kinetic(&j)) / before - 1.0;
    prop_assert!(gain <= 1e-3, "kinetic energy grew by {gain:e}");
    Ok(())
}

proptest! {
    #![proptest_config(config())]
    #[test]
    fn constant_rolling_is_bounded_symmetric_and_dissipative(c in collision()) {
        collide(&c, |_, _| ConstantRolling::new(ROLLING_FRICTION).unwrap())?;
    }

    #[test]
    fn elastic_plastic_rolling_is_bounded_symmetric_and_creates_no_energy(c in collision()) {
        collide(&c, |stiffness, inertia| ElasticPlasticRolling::new(ROLLING_FRICTION, stiffness, 0.0, inertia).unwrap())?;
    }
}

#[test]
fn a_law_with_rolling_is_a_law() {
    fn state_size<L: Law>(_: &L) -> usize {
        size_of::<L::State>()
    }
    let normal = LinearSpringDashpot::new(1000.0_f32, 0.9).unwrap();
    let p = TangentialParameters::new(860.0, 0.5, 0.5).unwrap();
    let law = ContactLaw::new(normal, ModelAA(p));
    assert_eq!(state_size(&law), 12);
    assert_eq!(
        state_size(&law.with_rolling(ConstantRolling::new(0.1).unwrap())),
        12
    );
    let epsd = ElasticPlasticRolling::new(0.1, 1.0, 0.0, 1e-9).unwrap();
    assert_eq!(state_size(&law.with_rolling(epsd)), 24);
    let _ = Sphere::<f32>::at_rest(Vec3::ZERO, 1.0, 1.0);
}

#[test]
fn twisting_about_the_normal_is_not_resisted() {
    // A sphere pressed on the floor spinning about the floor's normal: its contact point does not
    // slip and it does not roll, so neither rolling law puts a torque on it.
    let normal = LinearSpringDashpot::new(1000.0, 0.9).unwrap();
    let p = TangentialParameters::new(860.0, 0.5, 0.5).unwrap();
    let law = ContactLaw::new(normal, ModelAA(p));
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, 1.0e-3 - 1.0e-5), 1.0e-3, 2500.0);
    sphere.angular_velocity = Vec3::new(0.0, 0.0, 50.0);
    let floor = soft_sphere::prelude::Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap();
    let dt = law.time_step(1e-6, sphere.mass).unwrap();
    let constant = law.with_rolling(ConstantRolling::new(0.3).unwrap());
    let epsd = law.with_rolling(ElasticPlasticRolling::new(0.3, 1e-4, 1e-7, 1e-12).unwrap());
    let Ok(Interaction::Touching(a)) =
        constant.sphere_wall(&sphere, &floor, &mut Default::default(), dt)
    else {
        panic!("touching")
    };
    let mut state = Default::default();
    let Ok(Interaction::Touching(b)) = epsd.sphere_wall(&sphere, &floor, &mut state, dt) else {
        panic!("touching")
    };
    assert_eq!(a.torque_on_i, Vec3::ZERO);
    assert_eq!(b.torque_on_i, Vec3::ZERO);
    assert_eq!(state.torque, Vec3::ZERO);
    // Rolling about a tangent axis is resisted, against the spin.
    sphere.angular_velocity = Vec3::new(0.0, 50.0, 0.0);
    sphere.velocity = Vec3::new(50.0 * 1.0e-3, 0.0, 0.0);
    let Ok(Interaction::Touching(c)) =
        constant.sphere_wall(&sphere, &floor, &mut Default::default(), dt)
    else {
        panic!("touching")
    };
    assert!(c.torque_on_i.y < 0.0 && c.torque_on_i.x == 0.0);
}
