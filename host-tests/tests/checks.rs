//! The public checks (`soft_sphere::checks`): each passes what the guarantee allows and names
//! what breaks it, at the tolerance the kernel's own tests use.

use soft_sphere::checks::{self, Violation};
use soft_sphere::prelude::{
    ContactForces, MicroSlipSprings, MindlinSpring, RollingSpring, Sphere, SpringDisplacement, Vec3,
};

fn forces(normal: f64, tangential: f64) -> ContactForces<f64> {
    ContactForces {
        normal: Vec3::new(0.0, 0.0, 1.0),
        overlap: 1e-5,
        normal_force: normal,
        tangential_force: Vec3::new(tangential, 0.0, 0.0),
        slip_velocity: Vec3::ZERO,
        torque_on_i: Vec3::new(0.0, -1e-3 * tangential, 0.0),
        torque_on_j: Vec3::new(0.0, -1e-3 * tangential, 0.0),
        sliding: false,
    }
}

#[test]
fn coulomb_passes_the_limit_to_its_rounding_and_refuses_beyond() {
    let mu = 0.3;
    assert_eq!(checks::coulomb(&forces(10.0, 3.0), mu), Ok(()));
    assert_eq!(checks::coulomb(&forces(10.0, 0.0), mu), Ok(()));
    // A force along two axes: |(2.4, 3.2, 0)| = 4 > 3.
    let mut skew = forces(10.0, 2.4);
    skew.tangential_force.y = 3.2;
    assert!(matches!(
        checks::coulomb(&skew, mu),
        Err(Violation::Coulomb { tangential, .. }) if (tangential - 4.0).abs() < 1e-12
    ));
    assert_eq!(checks::coulomb(&forces(-10.0, -3.0), mu), Ok(()));
    // 64 units of rounding above the limit pass, 128 do not.
    let limit = 3.0_f64;
    assert_eq!(
        checks::coulomb(&forces(10.0, limit * (1.0 + 60.0 * f64::EPSILON)), mu),
        Ok(())
    );
    assert!(matches!(
        checks::coulomb(&forces(10.0, limit * (1.0 + 200.0 * f64::EPSILON)), mu),
        Err(Violation::Coulomb { .. })
    ));
    // f32's rounding is f32's.
    let f32_forces = ContactForces {
        normal: Vec3::new(0.0, 0.0, 1.0_f32),
        overlap: 1e-5,
        normal_force: 10.0,
        tangential_force: Vec3::new(3.0 * (1.0 + 60.0 * f32::EPSILON), 0.0, 0.0),
        slip_velocity: Vec3::ZERO,
        torque_on_i: Vec3::ZERO,
        torque_on_j: Vec3::ZERO,
        sliding: true,
    };
    assert_eq!(checks::coulomb(&f32_forces, 0.3), Ok(()));
    assert!(checks::coulomb_within(&forces(10.0, 3.05), mu, 0.035).is_ok());
    assert!(checks::coulomb_within(&forces(10.0, 3.2), mu, 0.035).is_err());
    // Without friction any tangential force is too much.
    assert!(checks::coulomb(&forces(10.0, 1e-100), 0.0).is_err());
    assert_eq!(
        checks::coulomb(&forces(f64::NAN, 0.0), mu),
        Err(Violation::NonFinite)
    );
}

#[test]
fn action_reaction_wants_the_negated_force_and_swapped_torques() {
    let ij = forces(10.0, 2.0);
    let mut ji = ij;
    ji.normal = -ij.normal;
    ji.tangential_force = -ij.tangential_force;
    ji.torque_on_i = ij.torque_on_j;
    ji.torque_on_j = ij.torque_on_i;
    assert_eq!(checks::action_reaction(&ij, &ji), Ok(()));
    let mut off = ji;
    off.tangential_force.x *= 1.0 + f64::EPSILON;
    assert_eq!(
        checks::action_reaction(&ij, &off),
        Err(Violation::ActionReaction)
    );
    let mut twisted = ji;
    twisted.torque_on_i.y += 1e-9;
    assert_eq!(
        checks::action_reaction(&ij, &twisted),
        Err(Violation::ActionReaction)
    );
    let mut twisted = ji;
    twisted.torque_on_j.y += 1e-9;
    assert_eq!(
        checks::action_reaction(&ij, &twisted),
        Err(Violation::ActionReaction)
    );
    let mut bad = ji;
    bad.torque_on_j.z = f64::INFINITY;
    assert_eq!(
        checks::action_reaction(&ij, &bad),
        Err(Violation::NonFinite)
    );
    assert_eq!(
        checks::action_reaction(&bad, &ij),
        Err(Violation::NonFinite)
    );
}

#[test]
fn energy_may_not_grow_past_the_step_error() {
    let mut s = Sphere::solid(Vec3::ZERO, 0.01, 2500.0);
    s.velocity = Vec3::new(3.0, 0.0, 4.0);
    s.angular_velocity = Vec3::new(0.0, 10.0, 0.0);
    // m v^2 / 2 + (2/5) m R^2 w^2 / 2 for a solid sphere.
    let m = s.mass;
    let expected = 0.5 * m * 25.0 + 0.2 * m * 1e-4 * 100.0;
    assert!((checks::kinetic_energy(&s) / expected - 1.0).abs() < 1e-15);
    assert_eq!(checks::no_energy_created::<f64>(1.0, 1.0009), Ok(()));
    assert_eq!(checks::no_energy_created::<f64>(1.0, 0.5), Ok(()));
    assert!(checks::no_energy_created::<f64>(1.0, 1.0011).is_err());
    // f32 adds a thousand units of its rounding (1.2e-4).
    assert_eq!(checks::no_energy_created::<f32>(1.0, 1.0011), Ok(()));
    assert!(checks::no_energy_created::<f32>(1.0, 1.0013).is_err());
    assert!(checks::no_energy_created::<f64>(1.0, f64::NAN).is_err());
}

#[test]
fn a_state_is_unchanged_only_to_the_bit() {
    let a = SpringDisplacement {
        displacement: Vec3::new(f64::NAN, 0.0, 1.0),
    };
    assert_eq!(checks::state_unchanged(&a, &a), Ok(()));
    let mut b = a;
    b.displacement.y = -0.0;
    assert_eq!(
        checks::state_unchanged(&a, &b),
        Err(Violation::StateChanged)
    );
    let m = MindlinSpring {
        force: Vec3::new(1.0, 2.0, 3.0),
        contact_radius: 1e-4,
    };
    let mut n = m;
    n.contact_radius = 1.0000000001e-4;
    assert_eq!(checks::state_unchanged(&m, &m), Ok(()));
    assert_eq!(
        checks::state_unchanged(&m, &n),
        Err(Violation::StateChanged)
    );
    assert_eq!(checks::state_unchanged(&(), &()), Ok(()));
    // Micro-slip springs and a rolling spring: every number counts.
    let springs = MicroSlipSprings::<f64, 2> {
        normal: Vec3::new(0.0, 0.0, 1.0),
        contact_radius: 1e-4,
        positions: [0.0, 0.5],
        displacements: [Vec3::new(f64::NAN, 1e-6, 0.0), Vec3::new(2e-6, 0.0, 0.0)],
    };
    assert_eq!(checks::state_unchanged(&springs, &springs), Ok(()));
    let mut moved = springs;
    moved.normal.z = -1.0;
    assert_eq!(
        checks::state_unchanged(&springs, &moved),
        Err(Violation::StateChanged)
    );
    let mut moved = springs;
    moved.contact_radius = 2e-4;
    assert_eq!(
        checks::state_unchanged(&springs, &moved),
        Err(Violation::StateChanged)
    );
    let mut moved = springs;
    moved.positions[1] = 0.6;
    assert_eq!(
        checks::state_unchanged(&springs, &moved),
        Err(Violation::StateChanged)
    );
    for k in 0..2 {
        let mut moved = springs;
        moved.displacements[k].y += 1e-9;
        assert_eq!(
            checks::state_unchanged(&springs, &moved),
            Err(Violation::StateChanged)
        );
    }
    let rolled = RollingSpring {
        tangential: a,
        torque: Vec3::new(1e-6, 0.0, 0.0),
    };
    assert_eq!(checks::state_unchanged(&rolled, &rolled), Ok(()));
    let mut turned = rolled;
    turned.torque.x = 2e-6;
    assert_eq!(
        checks::state_unchanged(&rolled, &turned),
        Err(Violation::StateChanged)
    );
    let mut turned = rolled;
    turned.tangential = b;
    assert_eq!(
        checks::state_unchanged(&rolled, &turned),
        Err(Violation::StateChanged)
    );
}

#[test]
fn violations_say_what_broke() {
    let text = Violation::Coulomb {
        tangential: 2.0,
        limit: 1.0,
    }
    .to_string();
    assert!(text.contains("exceeds"), "{text}");
    for v in [
        Violation::ActionReaction,
        Violation::EnergyCreated {
            before: 1.0,
            after: 2.0,
        },
        Violation::StateChanged,
        Violation::NonFinite,
    ] {
        assert!(!v.to_string().is_empty());
    }
}
