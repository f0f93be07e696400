//! Cylindrical and turning walls. A sphere inside a cylinder meets it as it would meet the plane
//! tangent to the cylinder nearest its centre; a wall turning at `w` about its axis moves its
//! surface at `w a x (c - p)` at a surface point `c`. Each is checked against the analytic
//! answer: the normal force `k_n delta` towards the axis, the restitution of a radial impact, the
//! Coulomb limit along the surface's motion, no tangential force on a sphere moving with it.

use soft_sphere::prelude::{
    CheckedSphere, ConstantRolling, ContactError, ContactForces, ContactLaw, ElasticPlasticRolling,
    Float, Interaction, LeverArm, LinearAA, LinearSpringDashpot, ModelAA, Parameter,
    ParameterError, Sphere, SpringDisplacement, TangentialParameters, Vec3, Wall, WallShape,
};

/// `k_n` 1e4 N/m, `e` 0.8, `k_t` 3e3 N/m, tangential dashpot ratio 0.5, `mu` 0.4.
fn law<F: Float>() -> LinearAA<F> {
    let f = F::from_f64;
    ContactLaw::new(
        LinearSpringDashpot::new(f(1.0e4), f(0.8)).unwrap(),
        ModelAA(TangentialParameters::new(f(3.0e3), f(0.5), f(MU)).unwrap()),
    )
}

const DRUM_RADIUS: f64 = 0.05;
const SPHERE_RADIUS: f64 = 1.0e-3;
const MU: f64 = 0.4;

/// A drum about an axis through an odd point in an odd direction, and two unit vectors across
/// its axis (`across`, and `around`: the axis times `across`).
fn drum() -> (Wall<f64>, Vec3<f64>, Vec3<f64>) {
    let axis = Vec3::new(1.0, 2.0, -2.0) * (1.0 / 3.0);
    let wall = Wall::cylinder(Vec3::new(0.1, -0.2, 0.3), axis * 7.0, DRUM_RADIUS).unwrap();
    let across = Vec3::new(2.0, 1.0, 2.0) * (1.0 / 3.0);
    assert!(axis.dot(across).abs() < 1e-15);
    (wall, across, axis.cross(across))
}

/// A sphere at rest whose centre is `depth` past touching the drum along `across`, `along` up
/// its axis.
fn pressed(wall: &Wall<f64>, across: Vec3<f64>, depth: f64, along: f64) -> Sphere<f64> {
    let centre =
        wall.point() + wall.direction() * along + across * (DRUM_RADIUS - SPHERE_RADIUS + depth);
    Sphere::solid(centre, SPHERE_RADIUS, 2500.0)
}

fn touching<F: Float>(outcome: Result<Interaction<F>, ContactError>) -> ContactForces<F> {
    match outcome {
        Ok(Interaction::Touching(c)) => c,
        other => panic!("expected a contact, got {other:?}"),
    }
}

fn close(a: Vec3<f64>, b: Vec3<f64>, tolerance: f64) -> bool {
    (a - b).norm_squared().sqrt() <= tolerance
}

#[test]
fn a_cylinder_pushes_a_pressed_sphere_towards_its_axis_by_k_delta() {
    let (wall, across, _) = drum();
    assert_eq!(
        wall.shape(),
        WallShape::Cylinder {
            radius: DRUM_RADIUS
        }
    );
    let law = law::<f64>();
    let dt = law.time_step(1.0e-6, 1.0e-5).unwrap();
    for depth in [1.0e-7, 1.0e-6, 1.0e-5] {
        let sphere = pressed(&wall, across, depth, 0.7);
        let c = touching(law.sphere_wall(&sphere, &wall, &mut Default::default(), dt));
        // Positions near 0.3 m carry rounding of 1e-17 m.
        assert!((c.overlap - depth).abs() < 1e-15, "{} {depth}", c.overlap);
        let expected = across * (-1.0e4 * depth);
        // k_n times the overlap's rounding, and the force's own.
        assert!(
            close(c.force_on_i(), expected, 1.0e4 * (1e-15 + 1e-12 * depth)),
            "{:?} {expected:?}",
            c.force_on_i()
        );
        assert!(close(c.normal, across, 1e-14));
        assert_eq!(c.tangential_force.norm_squared(), 0.0);
    }
    // Its distance is the radius less the distance from the axis.
    let centre = wall.point() + across * 0.03;
    assert!((wall.distance_to(centre) - 0.02).abs() < 1e-15);
}

#[test]
fn a_radial_impact_on_a_drum_rebounds_at_the_restitution() {
    let (wall, across, around) = drum();
    let law = law::<f64>();
    let mut sphere = pressed(&wall, across, -1.0e-4, -3.0);
    let speed = 0.5;
    sphere.velocity = across * speed;
    let seconds = law.accurate_time_step(sphere.mass) / 10.0;
    let dt = law.time_step(seconds, sphere.mass).unwrap();
    let mut state = SpringDisplacement::default();
    let (mut touched, mut steps) = (false, 0);
    loop {
        let outcome = law.sphere_wall(&sphere, &wall, &mut state, dt).unwrap();
        if let Interaction::Touching(c) = outcome {
            touched = true;
            sphere.velocity += c.force_on_i() * (seconds / sphere.mass);
        } else if touched {
            break;
        }
        sphere.position += sphere.velocity * seconds;
        steps += 1;
        assert!(steps < 100_000, "no rebound");
    }
    let radial = sphere.velocity.dot(across);
    assert!((radial + 0.8 * speed).abs() < 0.01 * speed, "{radial}");
    // Head-on: nothing along the axis or around it.
    let axial = sphere.velocity.dot(wall.direction());
    assert!(axial.abs() < 1e-12 && sphere.velocity.dot(around).abs() < 1e-12);
}

#[test]
fn a_turning_drum_drags_a_held_sphere_at_the_coulomb_limit_along_its_surface() {
    let (wall, across, around) = drum();
    // 20 rad/s: the surface passes the sphere at 1 m/s.
    let turning = wall.with_spin(20.0).unwrap();
    assert_eq!((wall.spin(), turning.spin()), (0.0, 20.0));
    let law = law::<f64>();
    let dt = law.time_step(1.0e-6, 1.0e-5).unwrap();
    let sphere = pressed(&turning, across, 1.0e-5, 0.0);
    let mut state = SpringDisplacement::default();
    let mut last = None;
    for _ in 0..2000 {
        last = Some(touching(law.sphere_wall(&sphere, &turning, &mut state, dt)));
    }
    let c = last.unwrap();
    assert!(c.sliding);
    let tangential = c.tangential_force.norm_squared().sqrt();
    assert!((tangential - MU * c.normal_force.abs()).abs() < 1e-9 * tangential);
    // On the sphere, along the surface's motion: at the contact, the axis times the way out.
    let on_sphere = -c.tangential_force * (1.0 / tangential);
    assert!(close(on_sphere, around, 1e-9), "{on_sphere:?} {around:?}");
    // Turning the other way drags the other way.
    let back = wall.with_spin(-20.0).unwrap();
    let mut state = SpringDisplacement::default();
    for _ in 0..2000 {
        last = Some(touching(law.sphere_wall(&sphere, &back, &mut state, dt)));
    }
    let c = last.unwrap();
    let direction = -c.tangential_force * (1.0 / c.tangential_force.norm_squared().sqrt());
    assert!(close(direction, -around, 1e-9));
}

#[test]
fn a_sphere_moving_with_a_turning_surface_feels_no_tangential_force() {
    let (wall, across, around) = drum();
    let law = law::<f64>();
    let dt = law.time_step(1.0e-6, 1.0e-5).unwrap();
    // A drum and a turntable (a floor turning about its normal through the origin).
    let floor = Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap();
    let spin = 20.0;
    let mut on_drum = pressed(&wall, across, 1.0e-5, 0.2);
    // The surface point under the sphere moves at spin R around the axis.
    on_drum.velocity = around * (spin * DRUM_RADIUS);
    let mut on_table = Sphere::solid(
        Vec3::new(0.03, 0.04, SPHERE_RADIUS - 1.0e-5),
        SPHERE_RADIUS,
        2500.0,
    );
    // At (0.03, 0.04) the table moves at spin z x (0.03, 0.04, 0).
    on_table.velocity = Vec3::new(-0.04 * spin, 0.03 * spin, 0.0);
    for (sphere, wall) in [
        (on_drum, wall.with_spin(spin).unwrap()),
        (on_table, floor.with_spin(spin).unwrap()),
    ] {
        let c = touching(law.sphere_wall(&sphere, &wall, &mut Default::default(), dt));
        let slip = c.slip_velocity.norm_squared().sqrt();
        assert!(slip < 1e-12, "{slip}");
        let tangential = c.tangential_force.norm_squared().sqrt();
        assert!(tangential < 1e-12 * c.normal_force, "{tangential}");
        // Still, the same sphere slips at the surface's speed.
        let mut still = sphere;
        still.velocity = Vec3::ZERO;
        let c = touching(law.sphere_wall(&still, &wall, &mut Default::default(), dt));
        let slip = c.slip_velocity.norm_squared().sqrt();
        let speed = sphere.velocity.norm_squared().sqrt();
        assert!((slip - speed).abs() < 1e-12, "{slip} {speed}");
    }
}

#[test]
fn a_sphere_carried_round_by_a_turning_drum_does_not_roll() {
    // Moving rigidly with the drum (its centre at w a x (x - p), its spin w a), the sphere's
    // contact point moves with the surface and it turns as the drum does: no slip, no rolling,
    // so neither rolling law resists it. Spun the other way, it rolls, and is resisted. (The
    // contact-plane lever arm puts the contact point on the surface: with the radius as the
    // arm, the point R - delta from the centre would slip at w delta.)
    let (wall, across, _) = drum();
    let spin = 20.0;
    let turning = wall.with_spin(spin).unwrap();
    let law = law::<f64>().with_lever_arm(LeverArm::ContactPlane);
    let dt = law.time_step(1.0e-6, 1.0e-5).unwrap();
    let mut sphere = pressed(&turning, across, 1.0e-5, 0.3);
    let omega = turning.direction() * spin;
    sphere.velocity = omega.cross(sphere.position - turning.point());
    sphere.angular_velocity = omega;
    let constant = law.with_rolling(ConstantRolling::new(0.3).unwrap());
    let epsd = law.with_rolling(ElasticPlasticRolling::new(0.3, 1e-4, 1e-7, 1e-12).unwrap());
    let a = touching(constant.sphere_wall(&sphere, &turning, &mut Default::default(), dt));
    let mut state = Default::default();
    let b = touching(epsd.sphere_wall(&sphere, &turning, &mut state, dt));
    // The constant law's torque at its limit: mu_r R F_n.
    let limit = 0.3 * SPHERE_RADIUS * a.normal_force;
    for c in [a, b] {
        let torque = c.torque_on_i.norm_squared().sqrt();
        assert!(torque < 1e-9 * limit, "{torque:e} of {limit:e}");
        assert!(c.slip_velocity.norm_squared().sqrt() < 1e-12);
    }
    sphere.angular_velocity = -omega;
    let c = touching(constant.sphere_wall(&sphere, &turning, &mut Default::default(), dt));
    // Against the rolling, about the axis.
    let about_axis = c.torque_on_i.dot(turning.direction());
    assert!(about_axis > 0.5 * limit, "{about_axis:e} of {limit:e}");
}

#[test]
fn a_cylinder_contact_is_the_contact_against_its_tangent_plane() {
    let (wall, across, around) = drum();
    let law = law::<f64>();
    let dt = law.time_step(1.0e-6, 1.0e-5).unwrap();
    let spin = -7.0;
    let turning = wall
        .with_velocity(Vec3::new(0.01, -0.02, 0.03))
        .and_then(|w| w.with_spin(spin))
        .unwrap();
    for (k, angle) in [0.0_f64, 1.0, 2.5, 4.0].into_iter().enumerate() {
        let way = across * angle.cos() + around * angle.sin();
        let mut sphere = pressed(&turning, way, 2.0e-6 * (k + 1) as f64, 0.1 * k as f64);
        sphere.velocity = Vec3::new(0.1, -0.3, 0.2);
        sphere.angular_velocity = Vec3::new(40.0, 10.0, -25.0);
        // The tangent plane at the surface point nearest the centre, moving with the surface
        // there.
        let from_axis = sphere.position - turning.point();
        let radial = from_axis - turning.direction() * from_axis.dot(turning.direction());
        let out = radial * (1.0 / radial.norm_squared().sqrt());
        let contact = turning.point()
            + turning.direction() * from_axis.dot(turning.direction())
            + out * DRUM_RADIUS;
        let surface =
            turning.velocity() + turning.direction().cross(contact - turning.point()) * spin;
        let plane = Wall::new(contact, -out)
            .and_then(|w| w.with_velocity(surface))
            .unwrap();
        let state = SpringDisplacement {
            displacement: around * 1.0e-7,
        };
        let (mut a, mut b) = (state, state);
        let on_cylinder = touching(law.sphere_wall(&sphere, &turning, &mut a, dt));
        let on_plane = touching(law.sphere_wall(&sphere, &plane, &mut b, dt));
        let scale = on_plane.normal_force.abs();
        assert!(close(
            on_cylinder.force_on_i(),
            on_plane.force_on_i(),
            1e-9 * scale
        ));
        assert!(close(
            on_cylinder.torque_on_i,
            on_plane.torque_on_i,
            1e-9 * scale * 1e-3
        ));
        assert!(close(a.displacement, b.displacement, 1e-9 * 1e-6));
    }
}

#[test]
fn bad_cylinders_and_spins_are_refused() {
    use ParameterError::{NonFinite, NotPositive};
    let z = Vec3::new(0.0, 0.0, 1.0);
    let wall = Parameter::Wall;
    for radius in [0.0, -0.1, -0.0] {
        assert_eq!(
            Wall::cylinder(Vec3::ZERO, z, radius),
            Err(NotPositive(wall))
        );
    }
    for radius in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(Wall::cylinder(Vec3::ZERO, z, radius), Err(NonFinite(wall)));
    }
    assert_eq!(
        Wall::cylinder(Vec3::ZERO, Vec3::ZERO, 0.1),
        Err(NotPositive(wall))
    );
    let nan = Vec3::new(f64::NAN, 0.0, 0.0);
    assert_eq!(Wall::cylinder(nan, z, 0.1), Err(NonFinite(wall)));
    assert_eq!(Wall::cylinder(Vec3::ZERO, nan, 0.1), Err(NonFinite(wall)));
    let drum = Wall::cylinder(Vec3::ZERO, z, 0.1).unwrap();
    for spin in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(drum.with_spin(spin), Err(NonFinite(wall)));
        let floor = Wall::new(Vec3::ZERO, z).unwrap();
        assert_eq!(floor.with_spin(spin), Err(NonFinite(wall)));
    }
}

#[test]
fn a_sphere_centred_on_the_axis_is_refused_only_when_it_reaches_the_wall() {
    let z = Vec3::new(0.0, 0.0, 1.0);
    let drum = Wall::cylinder(Vec3::new(0.5, 0.5, 0.0), z, 0.1).unwrap();
    let law = law::<f64>();
    let dt = law.time_step(1.0e-6, 1.0e-5).unwrap();
    let before = SpringDisplacement {
        displacement: Vec3::new(1.0e-7, -2.0e-7, 3.0e-8),
    };
    // Wider than the drum, on its axis: the normal is undefined.
    let wide = Sphere::solid(Vec3::new(0.5, 0.5, 3.0), 0.12, 2500.0);
    let mut state = before;
    assert_eq!(
        law.sphere_wall(&wide, &drum, &mut state, dt),
        Err(ContactError::CoincidentCentres)
    );
    assert_eq!(state, before);
    let checked = CheckedSphere::new(wide).unwrap();
    assert_eq!(
        law.at(dt).sphere_wall(&checked, &drum, &mut state),
        Err(ContactError::CoincidentCentres)
    );
    assert_eq!(state, before);
    // The axis is where the squared distance from it is below the smallest normal float, as
    // for coincident centres: 2^-511 from it (squared, exactly that float) has a normal,
    // 2^-512 has none.
    let about_z = Wall::cylinder(Vec3::ZERO, z, 0.1).unwrap();
    let at = |x: f64| Sphere::solid(Vec3::new(x, 0.0, 3.0), 0.12, 2500.0);
    let c = touching(law.sphere_wall(&at(2.0_f64.powi(-511)), &about_z, &mut state, dt));
    assert_eq!(c.normal, Vec3::new(1.0, 0.0, 0.0));
    let mut state = before;
    assert_eq!(
        law.sphere_wall(&at(2.0_f64.powi(-512)), &about_z, &mut state, dt),
        Err(ContactError::CoincidentCentres)
    );
    assert_eq!(state, before);
    // Narrower, on the axis: apart, its spring relaxed.
    let narrow = Sphere::solid(Vec3::new(0.5, 0.5, 3.0), 0.05, 2500.0);
    assert_eq!(
        law.sphere_wall(&narrow, &drum, &mut state, dt),
        Ok(Interaction::Apart)
    );
    assert_eq!(state, SpringDisplacement::default());
}

#[test]
fn a_cylinder_in_f32_pushes_a_pressed_sphere_towards_its_axis_by_k_delta() {
    let law = law::<f32>();
    let dt = law.time_step(1.0e-6, 1.0e-5).unwrap();
    let drum = Wall::cylinder(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0), 0.05_f32).unwrap();
    let depth = 1.0e-5_f32;
    let sphere = Sphere::solid(
        Vec3::new(0.0, -(0.05 - 1.0e-3 + depth), 0.2),
        1.0e-3,
        2500.0,
    );
    let c = touching(law.sphere_wall(&sphere, &drum, &mut Default::default(), dt));
    // Positions near 0.05 m carry f32 rounding of 4e-9 m: 4e-4 of the depth.
    assert!((c.overlap - depth).abs() < 1e-3 * depth, "{}", c.overlap);
    let force = c.force_on_i();
    assert!(
        (force.y - 1.0e4 * depth).abs() < 1e-3 * 1.0e4 * depth,
        "{force:?}"
    );
    assert!(force.x == 0.0 && force.z == 0.0);
}
