//! Where the energy goes. The springs' stored energy (`Law::stored_energy`) is the work done
//! against them. The scene's energy account books the work of every kick as the integrator
//! applies it, so its balance closes to rounding over a settling bed (the kinetic energy read
//! from the spheres against the work summed from the forces); what it says of the sinks is
//! checked against physics: an elastic gas dissipates nothing, a head-on impact dissipates
//! `(1 - e^2)` of the pair's relative kinetic energy, a sphere sliding into rolling on a floor
//! gives the rigid-body `2/7` of its kinetic energy to the slider.

use host_tests::random::Xorshift;
use host_tests::scene::{Column, OwnedScene, pair_and_wall, wall_of};
use soft_sphere::prelude::{
    ContactLaw, ElasticPlasticRolling, Hertz, HertzImpact, Interaction, Law, LinearAA,
    LinearSpring, LinearSpringDashpot, MaterialTable, MaterialWall, MindlinAA, MindlinParameters,
    ModelAA, Sphere, SpringDisplacement, TangentialParameters, Vec3, Wall, effective_mass,
};
use soft_sphere_scene::{Domain, Energy, Integrator, NoWalls, StepInput};

const RADIUS: f64 = 0.5e-3;
const DENSITY: f64 = 2500.0;

type Linear = LinearAA<f64>;

fn linear(restitution: f64, friction: f64) -> Linear {
    ContactLaw::new(
        LinearSpringDashpot::new(1000.0, restitution).unwrap(),
        ModelAA(TangentialParameters::new(285.7, 0.5, friction).unwrap()),
    )
}

/// Simpson's rule for `f` over `[0, end]` in `n` (even) intervals.
fn simpson(f: impl Fn(f64) -> f64, end: f64, n: usize) -> f64 {
    let h = end / n as f64;
    let inner: f64 = (1..n)
        .map(|k| f(k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (f(0.0) + inner + f(end)) * h / 3.0
}

/// The work of `law`'s normal force on spheres at rest pressed together from first touch to
/// each of `overlaps`, against the energy the law says its normal spring then stores.
fn normal_work<L: Law<Float = f64>>(law: &L, overlaps: &[f64]) {
    let a = Sphere::solid(Vec3::ZERO, RADIUS, DENSITY);
    let dt = law.time_step(1e-9, effective_mass(a.mass, a.mass)).unwrap();
    let force = |overlap: f64| {
        let b = Sphere {
            position: Vec3::new(2.0 * RADIUS - overlap, 0.0, 0.0),
            ..a
        };
        let mut state = L::State::default();
        let (i, j) = (
            soft_sphere::prelude::CheckedSphere::new(a).unwrap(),
            soft_sphere::prelude::CheckedSphere::new(b).unwrap(),
        );
        match law.at(dt).sphere_sphere(&i, &j, &mut state).unwrap() {
            Interaction::Touching(c) => c.normal_force,
            Interaction::Apart => 0.0,
        }
    };
    for &overlap in overlaps {
        let work = simpson(force, overlap, 2000);
        let stored = law.stored_energy(overlap, RADIUS / 2.0, &L::State::default());
        assert!(
            (stored - work).abs() < 1e-6 * work,
            "overlap {overlap:e}: stored {stored:e} J, work {work:e} J"
        );
    }
}

#[test]
fn normal_springs_store_the_work_of_their_elastic_force() {
    // No dashpot (e = 1, or none at all): at rest the normal force is the elastic force alone.
    let impact = HertzImpact {
        speed: 1.0,
        effective_radius: RADIUS / 2.0,
    };
    let hertz = ContactLaw::new(
        Hertz::new(5.0e8, 1.0, impact).unwrap(),
        MindlinAA(MindlinParameters::new(2.0e8, 0.5, 0.4).unwrap()),
    );
    normal_work(&hertz, &[1e-7, 1e-6, 5e-6]);
    let tangential = ModelAA(TangentialParameters::new(285.7, 0.5, 0.4).unwrap());
    normal_work(
        &ContactLaw::new(LinearSpring::new(1000.0).unwrap(), tangential),
        &[1e-7, 5e-6],
    );
    let undamped = LinearSpringDashpot::new(1000.0, 1.0).unwrap();
    normal_work(&ContactLaw::new(undamped, tangential), &[1e-7, 5e-6]);
}

/// Drives a contact quasi-statically (sphere j, pressed `overlap` into sphere i along x, moves
/// with `velocity` and turns with `spin`; no dashpot, no sliding) and returns the work done
/// against the contact and what the law says its tangential and rolling springs store.
fn spring_work<L: Law<Float = f64>>(
    law: &L,
    overlap: f64,
    (velocity, spin): (Vec3<f64>, Vec3<f64>),
) -> (f64, f64) {
    let a = Sphere::solid(Vec3::ZERO, RADIUS, DENSITY);
    let b = Sphere {
        position: Vec3::new(2.0 * RADIUS - overlap, 0.0, 0.0),
        velocity,
        angular_velocity: spin,
        ..a
    };
    let dt = law.time_step(1e-7, a.mass / 2.0).unwrap();
    let mut bound = law.at(dt);
    let (checked_a, checked_b) = (
        soft_sphere::prelude::CheckedSphere::new(a).unwrap(),
        soft_sphere::prelude::CheckedSphere::new(b).unwrap(),
    );
    let mut state = L::State::default();
    let mut work = 0.0;
    for _ in 0..10_000 {
        let Interaction::Touching(c) = bound
            .sphere_sphere(&checked_a, &checked_b, &mut state)
            .unwrap()
        else {
            panic!("the spheres stay pressed together");
        };
        assert!(!c.sliding);
        // The power the contact takes from the spheres: its force on j against j's velocity
        // relative to i, its torques against the spins.
        let power = c.force_on_j().dot(b.velocity - a.velocity)
            + c.torque_on_i.dot(a.angular_velocity)
            + c.torque_on_j.dot(b.angular_velocity);
        work -= power * dt.seconds();
    }
    let radius = RADIUS / 2.0;
    let relaxed = L::State::default();
    let springs =
        law.stored_energy(overlap, radius, &state) - law.stored_energy(overlap, radius, &relaxed);
    (work, springs)
}

/// j sliding past i in y at 0.1 mm/s.
fn sliding_past<L: Law<Float = f64>>(law: &L, overlap: f64) -> (f64, f64) {
    spring_work(law, overlap, (Vec3::new(0.0, 1e-4, 0.0), Vec3::ZERO))
}

#[test]
fn tangential_springs_store_the_work_done_against_them() {
    // No tangential dashpot, friction far above what the spring reaches.
    let aa: Linear = ContactLaw::new(
        LinearSpringDashpot::new(1000.0, 1.0).unwrap(),
        ModelAA(TangentialParameters::new(285.7, 0.0, 10.0).unwrap()),
    );
    let impact = HertzImpact {
        speed: 1.0,
        effective_radius: RADIUS / 2.0,
    };
    let mindlin = ContactLaw::new(
        Hertz::new(5.0e8, 1.0, impact).unwrap(),
        MindlinAA(MindlinParameters::new(2.0e8, 0.0, 10.0).unwrap()),
    );
    // 10,000 steps of the discrete spring: the work of the updated spring exceeds the stored
    // energy by 1/N.
    for (name, (work, stored)) in [
        ("model_aa", sliding_past(&aa, 1e-6)),
        ("mindlin_aa", sliding_past(&mindlin, 1e-6)),
    ] {
        assert!(stored > 0.0, "{name}");
        assert!(
            (work - stored).abs() < 2e-4 * stored,
            "{name}: work {work:e} J, stored {stored:e} J"
        );
    }
    // A relaxed state stores nothing; the normal spring alone is k delta^2 / 2.
    let state = SpringDisplacement::default();
    assert_eq!(aa.stored_energy(2e-6, 1.0, &state), 0.5 * 1000.0 * 4e-12);
    assert_eq!(aa.stored_energy(0.0, 1.0, &state), 0.0);
}

#[test]
fn a_rolling_spring_stores_the_work_done_against_it() {
    // Sphere j turns slowly about an axis in the tangent plane: the contact's tangential and
    // rolling springs both load (no dashpots, friction far above what they reach).
    let stiffness = 1e-4;
    let law = ContactLaw::new(
        LinearSpringDashpot::new(1000.0, 1.0).unwrap(),
        ModelAA(TangentialParameters::new(285.7, 0.0, 10.0).unwrap()),
    )
    .with_rolling(ElasticPlasticRolling::new(10.0, stiffness, 0.0, 1e-13).unwrap());
    let spin = 0.05;
    let (work, springs) = spring_work(&law, 1e-6, (Vec3::ZERO, Vec3::new(0.0, 0.0, spin)));
    // The rolling spring's share: `|M|^2 / (2 k_r)` with `|M| = k_r w t`, the spheres turning
    // against each other at `w` for `t` = 10,000 steps of 0.1 us.
    let turned = spin * 10_000.0 * 1e-7;
    let rolling = 0.5 * stiffness * turned * turned;
    assert!(
        rolling > 0.1 * springs && rolling < springs,
        "the rolling spring took {rolling:e} of {springs:e} J"
    );
    assert!(
        (work - springs).abs() < 2e-4 * springs,
        "work {work:e} J, stored {springs:e} J"
    );
}

/// A 6 mm box, periodic in x and y, room above.
fn open_box() -> Domain<f64> {
    Domain {
        lower: Vec3::ZERO,
        upper: Vec3::new(0.006, 0.006, 0.006),
        periodic_x: true,
        periodic_y: true,
    }
}

/// The account at the end of each step of `steps` of `scene`.
fn accounts<
    L: Law<Float = f64>,
    W: soft_sphere_scene::WallSet<f64> + Clone,
    const MATERIALS: usize,
>(
    scene: &mut OwnedScene<L, W>,
    input: &StepInput<'_, L, MATERIALS>,
    steps: usize,
) -> Vec<Energy<f64>> {
    let mut energies = Vec::with_capacity(steps);
    scene
        .run(input, steps, |_, stats| {
            energies.push(stats.energy.unwrap())
        })
        .unwrap();
    energies
}

#[test]
fn a_head_on_impact_dissipates_one_minus_e_squared_of_its_relative_kinetic_energy() {
    let speed = 0.1;
    for restitution in [0.3, 0.6, 0.9] {
        let law = linear(restitution, 0.4);
        let table = MaterialTable::<_, 1>::uniform(law);
        let mut a = Sphere::solid(Vec3::new(2.0e-3, 3e-3, 3e-3), RADIUS, DENSITY);
        let mut b = Sphere::solid(Vec3::new(3.1e-3, 3e-3, 3e-3), RADIUS, DENSITY);
        a.velocity.x = speed / 2.0;
        b.velocity.x = -speed / 2.0;
        let m = effective_mass(a.mass, b.mass);
        let duration = law.contact_duration(m);
        let dt = duration / 1000.0;
        let mut scene = OwnedScene::<_, _>::new(vec![a, b], open_box(), 1e-4, NoWalls)
            .unwrap()
            .with_records();
        let input = StepInput {
            table: &table,
            gravity: Vec3::ZERO,
            time_step: scene.scene(|s| s.time_step(&table, dt)).unwrap().unwrap(),
            integrator: Integrator::VelocityVerlet,
        };
        // 0.1 mm to close at 0.1 m/s, then the contact.
        let steps = ((1e-4 / speed + 2.0 * duration) / dt) as usize;
        let energies = accounts(&mut scene, &input, steps);
        let last = energies.last().unwrap();
        let expected = (1.0 - restitution * restitution) * 0.5 * m * speed * speed;
        assert!(last.stored == 0.0, "the contact has ended");
        assert!(
            (last.dissipated_dashpots - expected).abs() < 0.005 * expected,
            "e = {restitution}: {:e} J dissipated, (1 - e^2) m* v^2 / 2 = {expected:e} J",
            last.dissipated_dashpots
        );
        assert_eq!(last.dissipated_sliding, 0.0, "head on: nothing slides");
        let drift = (last.balance() - energies[0].balance()).abs();
        assert!(
            drift < 1e-3 * expected,
            "e = {restitution}: balance drifted {drift:e} J"
        );
    }
}

#[test]
fn an_oblique_impact_that_slides_throughout_gives_its_slider_the_rigid_body_share() {
    // Equal spheres meeting at 0.1 m/s along the line of centres and 0.2 m/s across it, mu =
    // 0.05, stiff enough that the line of centres turns by less than a degree in the contact, no
    // dashpots (e = 1, so the Coulomb limit is the elastic force's). The normal impulse is
    // J_n = 2 m* v_n; the contact slides throughout (7 mu v_n < v_t), so the tangential impulse
    // is mu J_n, the slip falls linearly with it by (7/2) J_t / m*, and the slider takes
    // J_t (v_t + v_t') / 2 = 2 mu m* v_n (v_t - 3.5 mu v_n).
    let (normal_speed, slip, friction) = (0.1, 0.2, 0.05);
    let law: Linear = ContactLaw::new(
        LinearSpringDashpot::new(1.0e4, 1.0).unwrap(),
        ModelAA(TangentialParameters::new(2857.0, 0.0, friction).unwrap()),
    );
    let table = MaterialTable::<_, 1>::uniform(law);
    let mut a = Sphere::solid(Vec3::new(2.0e-3, 3e-3, 3e-3), RADIUS, DENSITY);
    let mut b = Sphere::solid(Vec3::new(3.0001e-3, 3e-3, 3e-3), RADIUS, DENSITY);
    a.velocity = Vec3::new(normal_speed, slip, 0.0) * 0.5;
    b.velocity = -a.velocity;
    let m = effective_mass(a.mass, b.mass);
    let duration = law.contact_duration(m);
    let dt = duration / 1000.0;
    let mut scene = OwnedScene::<_, _>::new(vec![a, b], open_box(), 1e-3, NoWalls)
        .unwrap()
        .with_records();
    let input = StepInput {
        table: &table,
        gravity: Vec3::ZERO,
        time_step: scene.scene(|s| s.time_step(&table, dt)).unwrap().unwrap(),
        integrator: Integrator::VelocityVerlet,
    };
    let steps = ((1e-7 / normal_speed + 2.0 * duration) / dt) as usize;
    let energies = accounts(&mut scene, &input, steps);
    let last = energies.last().unwrap();
    let expected = 2.0 * friction * m * normal_speed * (slip - 3.5 * friction * normal_speed);
    assert!(last.stored == 0.0, "the contact has ended");
    assert!(
        (last.dissipated_sliding - expected).abs() < 0.02 * expected,
        "{:e} J to the slider, the rigid-body share {expected:e} J",
        last.dissipated_sliding
    );
    // At the deepest compression half the normal impulse has acted: the friction force has
    // done mu J (v_t - 1.75 mu J / m*) with J = m* v_n, of which the capped tangential spring
    // holds (mu F_n)^2 / (2 k_t) = x E_n (x = mu^2 k_n / k_t, E_n the normal spring's energy)
    // and the slider took the rest.
    let deepest = energies
        .iter()
        .max_by(|a, b| a.stored.total_cmp(&b.stored))
        .unwrap();
    let x = friction * friction * 1.0e4 / 2857.0;
    let capped_spring = deepest.stored * x / (1.0 + x);
    let halfway =
        friction * m * normal_speed * (slip - 1.75 * friction * normal_speed) - capped_spring;
    assert!(
        (deepest.dissipated_sliding - halfway).abs() < 0.02 * halfway,
        "{:e} J to the slider at the deepest compression, {halfway:e} J expected",
        deepest.dissipated_sliding
    );
    let total = last.dissipated_sliding + last.dissipated_dashpots;
    assert!(
        (total - expected).abs() < 0.02 * expected,
        "{total:e} J dissipated in all, {expected:e} J expected"
    );
}

#[test]
fn a_sphere_sliding_on_a_floor_loses_two_sevenths_of_its_kinetic_energy_to_the_slider() {
    let friction = 0.3;
    let law = linear(0.5, friction);
    let table = MaterialTable::<_, 1>::uniform(law);
    let g = 9.81;
    let v0 = 0.05;
    // A ceiling nobody reaches first, so that the floor's states are each sphere's second.
    let floor = [
        MaterialWall {
            wall: Wall::new(Vec3::new(0.0, 0.0, 5e-3), Vec3::new(0.0, 0.0, -1.0)).unwrap(),
            material: 0,
        },
        MaterialWall {
            wall: Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap(),
            material: 0,
        },
    ];
    let mut sphere = Sphere::solid(Vec3::new(1e-3, 3e-3, 0.0), RADIUS, DENSITY);
    // Resting at its static overlap, moving along x without spin.
    sphere.position.z = RADIUS - sphere.mass * g / 1000.0;
    sphere.velocity.x = v0;
    let kinetic = 0.5 * sphere.mass * v0 * v0;
    let mut scene = OwnedScene::<_, _>::new(vec![sphere], open_box(), 1e-4, floor)
        .unwrap()
        .with_records();
    let dt = 2e-6;
    let input = StepInput {
        table: &table,
        gravity: Vec3::new(0.0, 0.0, -g),
        time_step: scene.scene(|s| s.time_step(&table, dt)).unwrap().unwrap(),
        integrator: Integrator::SymplecticEuler,
    };
    // Sliding lasts 2 v0 / (7 mu g); run twice that.
    let steps = (4.0 * v0 / (7.0 * friction * g) / dt) as usize;
    let energies = accounts(&mut scene, &input, steps);
    let last = energies.last().unwrap();
    let expected = 2.0 / 7.0 * kinetic;
    assert!(
        (last.dissipated_sliding - expected).abs() < 0.02 * expected,
        "{:e} J to the slider, 2/7 of {kinetic:e} J = {expected:e} J",
        last.dissipated_sliding
    );
    let drift = (last.balance() - energies[0].balance()).abs();
    assert!(drift < 0.01 * expected, "balance drifted {drift:e} J");
}

/// How a [`pour`] is set up: the lattice's vertical spacing times `squeeze` (below 0.834 the
/// layers start pressed together), gravity, the ceiling's height and velocity, and the floor's
/// turning rate about the vertical through the origin (a turntable).
#[derive(Clone, Copy)]
struct Pour {
    squeeze: f64,
    gravity: f64,
    ceiling: (f64, f64),
    floor_spin: f64,
}

/// Falling onto a still floor; the ceiling far above.
const SETTLING: Pour = Pour {
    squeeze: 0.9,
    gravity: 9.81,
    ceiling: (0.02, 0.0),
    floor_spin: 0.0,
};

/// A pour of 150 spheres with random velocities in a 6 mm periodic box between a floor and a
/// ceiling, under `table` (spheres material 0, the walls 1) for `seconds` at step `dt`: every
/// step's account. A moving ceiling is moved to where its velocity takes it after each step.
fn pour<L: Law<Float = f64>>(
    table: &MaterialTable<L, 2>,
    (integrator, setup): (Integrator, Pour),
    (dt, seconds): (f64, f64),
) -> Vec<Energy<f64>> {
    pour_in_calls(table, (integrator, setup), (dt, seconds), 1)
}

/// [`pour`] with its steps spread over `calls` calls of `OwnedScene::scene`.
fn pour_in_calls<L: Law<Float = f64>>(
    table: &MaterialTable<L, 2>,
    (integrator, setup): (Integrator, Pour),
    (dt, seconds): (f64, f64),
    calls: usize,
) -> Vec<Energy<f64>> {
    let column = Column {
        spheres: 150,
        diameter: 2.0 * RADIUS,
        density: DENSITY,
        width_x: 0.006,
        width_y: 0.006,
    };
    let (mut spheres, _) = column.lattice::<f64>();
    let mut random = Xorshift::new(17);
    for s in &mut spheres {
        s.velocity = Vec3::new(
            random.unit() - 0.5,
            random.unit() - 0.5,
            random.unit() - 0.5,
        ) * 0.1;
        s.position.z = RADIUS + (s.position.z - RADIUS) * setup.squeeze;
    }
    let mass = spheres[0].mass;
    let up = Vec3::new(0.0, 0.0, 1.0);
    let (height, speed) = setup.ceiling;
    let ceiling = Wall::new(Vec3::new(0.0, 0.0, height), -up)
        .unwrap()
        .with_velocity(-up * speed)
        .unwrap();
    let walls = [
        wall_of(
            Wall::new(Vec3::ZERO, up)
                .and_then(|floor| floor.with_spin(setup.floor_spin))
                .unwrap(),
            1,
        ),
        wall_of(ceiling, 1),
    ];
    let domain = column.domain(0.02);
    let mut scene = OwnedScene::<_, _>::new(spheres, domain, 1e-4, walls)
        .unwrap()
        .with_records();
    let input = StepInput {
        table,
        gravity: -up * setup.gravity,
        time_step: table
            .law(0, 0)
            .unwrap()
            .coarse_time_step(dt, mass / 2.0)
            .unwrap(),
        integrator,
    };
    let steps = (seconds / dt) as usize;
    let mut energies = Vec::with_capacity(steps);
    for _ in 0..calls {
        scene
            .scene(|s| {
                for _ in 0..steps / calls {
                    energies.push(s.step(&input).unwrap().energy.unwrap());
                    let ceiling = &mut s.walls_mut()[1].wall;
                    *ceiling = ceiling.moved_to(ceiling.point() - up * speed * dt).unwrap();
                }
            })
            .unwrap();
    }
    energies
}

#[test]
fn the_account_runs_on_across_calls_of_an_owned_scene() {
    // It started afresh at every call: a balance compared across calls drifted by 14 times
    // the energy dissipated.
    let table = pair_and_wall(linear(0.5, 0.5), linear(0.6, 0.3));
    let energies = pour_in_calls(
        &table,
        (Integrator::SymplecticEuler, SETTLING),
        (4e-6, 0.02),
        5,
    );
    let last = energies.last().unwrap();
    let dissipated = last.dissipated_dashpots + last.dissipated_sliding;
    assert!(
        last.gravity_work > 0.0 && dissipated > 0.3 * last.gravity_work,
        "{last:?}"
    );
    let start = energies[0].balance();
    for (step, energy) in energies.iter().enumerate() {
        let drift = (energy.balance() - start).abs();
        assert!(
            drift < 1e-9 * dissipated,
            "step {step}: the balance moved {drift:e} J of {dissipated:e} J"
        );
    }
    // The totals only grow across calls: gravity's work and the dissipation.
    for pair in energies.windows(2) {
        assert!(pair[1].gravity_work > pair[0].gravity_work);
        assert!(pair[1].dissipated_sliding >= pair[0].dissipated_sliding);
    }
}

#[test]
fn the_balance_of_a_settling_bed_closes_to_rounding() {
    let table = pair_and_wall(linear(0.5, 0.5), linear(0.6, 0.3));
    for integrator in Integrator::ALL {
        let energies = pour(&table, (integrator, SETTLING), (4e-6, 0.04));
        let last = energies.last().unwrap();
        let dissipated = last.dissipated_dashpots + last.dissipated_sliding;
        // The pour fell, collided and slid: both sinks took energy, and most of what gravity
        // gave.
        assert!(last.gravity_work > 0.0 && last.wall_work == 0.0);
        assert!(last.dissipated_dashpots > 0.0 && last.dissipated_sliding > 0.0);
        assert!(dissipated > 0.5 * last.gravity_work, "{last:?}");
        let start = energies[0].balance();
        for (step, energy) in energies.iter().enumerate() {
            let by_hand = energy.kinetic
                + energy.rotational
                + energy.stored
                + energy.dissipated_dashpots
                + energy.dissipated_sliding
                - energy.gravity_work
                - energy.wall_work;
            assert!((energy.balance() - by_hand).abs() <= 1e-12 * by_hand.abs());
            let drift = (energy.balance() - start).abs();
            assert!(
                drift < 1e-9 * dissipated,
                "{integrator:?} step {step}: the balance moved {drift:e} J of {dissipated:e} J"
            );
        }
    }
}

/// The largest dissipation an elastic pour reports at step `dt`, over the energy in play (the
/// pour's kinetic energy, the springs' at the start, and the work of gravity and the ceiling),
/// and how much of it the springs and the ceiling's drive held or did at most.
fn elastic_pour<L: Law<Float = f64>>(
    law: L,
    (integrator, setup): (Integrator, Pour),
    (dt, seconds): (f64, f64),
) -> (f64, f64, f64) {
    let table = pair_and_wall(law, law);
    let energies = pour(&table, (integrator, setup), (dt, seconds));
    let (first, last) = (energies[0], *energies.last().unwrap());
    let scale = first.kinetic
        + first.rotational
        + first.stored
        + last.gravity_work.abs()
        + last.wall_work.abs();
    let mut worst: f64 = 0.0;
    for energy in &energies {
        // The balance closes with the ceiling's drive in it.
        let by_hand = energy.kinetic
            + energy.rotational
            + energy.stored
            + energy.dissipated_dashpots
            + energy.dissipated_sliding
            - energy.gravity_work
            - energy.wall_work;
        assert!((energy.balance() - by_hand).abs() <= 1e-12 * scale);
        assert!((energy.balance() - first.balance()).abs() < 1e-9 * scale);
        assert!(
            energy.dissipated_sliding.abs() < 1e-12 * scale,
            "nothing slides"
        );
        worst = worst.max((energy.dissipated_dashpots + energy.dissipated_sliding).abs());
    }
    let held = energies.iter().map(|e| e.stored).fold(0.0, f64::max);
    (worst / scale, held / scale, last.wall_work / scale)
}

/// No dashpots, no friction: every contact is a spring.
fn elastic_linear() -> Linear {
    ContactLaw::new(
        LinearSpringDashpot::new(1000.0, 1.0).unwrap(),
        ModelAA(TangentialParameters::new(285.7, 0.0, 0.0).unwrap()),
    )
}

#[test]
fn an_elastic_gas_dissipates_nothing() {
    // What the account calls dissipated in an elastic gas is the integrator's energy error:
    // bounded, and falling with the step (measured: symplectic Euler 4.0e-3 at 4 us, 2.1e-3
    // at 2 us; velocity Verlet 4.1e-4, 1.3e-4).
    for (integrator, bound) in [
        (Integrator::SymplecticEuler, 8e-3),
        (Integrator::VelocityVerlet, 1e-3),
    ] {
        let (coarse, held, _) =
            elastic_pour(elastic_linear(), (integrator, SETTLING), (4e-6, 0.02));
        let (fine, _, _) = elastic_pour(elastic_linear(), (integrator, SETTLING), (2e-6, 0.02));
        assert!(held > 1e-4, "the spheres collided");
        assert!(
            coarse < bound,
            "{integrator:?}: {coarse:e} of the energy in play"
        );
        assert!(
            fine < 0.7 * coarse,
            "{integrator:?}: {coarse:e} at 4 us, {fine:e} at 2 us"
        );
    }
}

/// The two elastic laws of the squeezed gas.
#[derive(Clone, Copy)]
enum Law2<H> {
    Linear(Linear),
    Hertz(H),
}

#[test]
fn an_elastic_gas_pressed_together_and_squeezed_by_a_ceiling_dissipates_nothing() {
    // Layers pressed together from the start (the springs hold energy before the first step),
    // no gravity, and a ceiling coming down at 2 cm/s through the top layer: its drive does
    // work on the gas, which the springs and the spheres hold. A Hertz gas too, whose springs
    // depend on each pair's effective radius. What is reported as dissipated is the
    // integrator's error: first order in the step with symplectic Euler (measured 9.6e-3 of
    // the energy in play at 1 us, 4.9e-3 at 0.5 us, linear), about second with velocity Verlet
    // (3.6e-4, 9.0e-5).
    let squeezed = Pour {
        squeeze: 0.83,
        gravity: 0.0,
        ceiling: (6.0e-3, 0.02),
        floor_spin: 0.0,
    };
    let impact = HertzImpact {
        speed: 0.5,
        effective_radius: RADIUS / 2.0,
    };
    let hertz = ContactLaw::new(
        Hertz::new(5.0e6, 1.0, impact).unwrap(),
        MindlinAA(MindlinParameters::new(2.0e6, 0.0, 0.0).unwrap()),
    );
    for integrator in Integrator::ALL {
        for (name, law) in [
            ("linear", Law2::Linear(elastic_linear())),
            ("Hertz", Law2::Hertz(hertz)),
        ] {
            let run = |dt| match law {
                Law2::Linear(l) => elastic_pour(l, (integrator, squeezed), (dt, 0.008)),
                Law2::Hertz(h) => elastic_pour(h, (integrator, squeezed), (dt, 0.008)),
            };
            let (coarse, held, driven) = run(1e-6);
            let (fine, _, _) = run(0.5e-6);
            assert!(
                held > 0.1 && driven > 0.01,
                "held {held:e}, driven {driven:e}"
            );
            assert!(coarse < 2e-2, "{integrator:?}, {name}: {coarse:e}");
            assert!(
                fine < 0.7 * coarse,
                "{integrator:?}, {name}: {coarse:e} -> {fine:e}"
            );
        }
    }
}

#[test]
fn the_balance_closes_with_a_turning_floors_drive() {
    // A turntable floor (30 rad/s about the vertical through the origin) drags the settling
    // bed round by friction: its drive does work along its surface's velocity under each
    // sphere, and the balance closes with that work in it, to rounding.
    let table = pair_and_wall(linear(0.5, 0.5), linear(0.6, 0.3));
    let turning = Pour {
        floor_spin: 30.0,
        ..SETTLING
    };
    let energies = pour(&table, (Integrator::SymplecticEuler, turning), (4e-6, 0.04));
    let last = energies.last().unwrap();
    let dissipated = last.dissipated_dashpots + last.dissipated_sliding;
    // The drive gave energy, much of it to the bed's turning (at 30 rad/s a sphere 5 mm from
    // the axis moves at 0.15 m/s).
    assert!(
        last.wall_work > 0.05 * last.gravity_work && last.dissipated_sliding > 0.0,
        "{last:?}"
    );
    let start = energies[0].balance();
    for (step, energy) in energies.iter().enumerate() {
        let drift = (energy.balance() - start).abs();
        assert!(
            drift < 1e-9 * (dissipated + last.wall_work),
            "step {step}: the balance moved {drift:e} J of {dissipated:e} J dissipated, {:e} J driven",
            last.wall_work
        );
    }
}
