//! The kernel's scene runner (issue 5): the cell grid and Verlet list find exactly the touching
//! pairs a brute-force search finds, across periodic boundaries; an isolated periodic gas keeps its
//! momentum; runs are bit for bit repeatable; both integrators settle a bed under gravity.

use host_tests::scene::{Column, OwnedScene};
use soft_sphere::scene::{Integrator, NoWalls, StepInput, WallSet};
use soft_sphere::{
    ContactLaw, Libm, LinearSpringDashpot, ModelAA, Rotating, Sphere, TangentialParameters, Vec3,
    Wall,
};

const DIAMETER: f64 = 1e-3;

/// A small periodic gas: spheres on a jittered lattice with random velocities, some touching.
fn gas(count: usize, seed: u64) -> (Vec<Sphere<f64>>, soft_sphere::scene::Domain<f64>) {
    let column = Column {
        spheres: count,
        diameter: DIAMETER,
        density: 2500.0,
        width_x: 0.006,
        width_y: 0.006,
    };
    let (mut spheres, height) = column.lattice::<f64>();
    let mut state = seed;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for s in &mut spheres {
        s.velocity = Vec3::new(next(), next(), next()) * 0.2;
        s.angular_velocity = Vec3::new(next(), next(), next()) * 100.0;
        // Squeeze the lattice so that neighbours overlap now and then.
        s.position.z *= 0.85;
    }
    (spheres, column.domain(height))
}

fn law() -> Law {
    ContactLaw::new(
        LinearSpringDashpot::new(1000.0, 0.9).unwrap(),
        ModelAA(TangentialParameters::new(285.7, 0.5, 0.5).unwrap()),
    )
}

type Law = ContactLaw<f64, LinearSpringDashpot<f64>, ModelAA<f64>>;

/// One law for pairs and walls, stepped at `dt` for a pair of these spheres' mass.
fn input<'l, W: WallSet<f64>>(
    law: &'l Law,
    walls: &'l W,
    (gravity, dt, sphere_mass): (Vec3<f64>, f64, f64),
    integrator: Integrator,
) -> StepInput<'l, f64, LinearSpringDashpot<f64>, ModelAA<f64>, Libm, Rotating, W> {
    StepInput {
        law,
        wall_law: law,
        walls,
        gravity,
        time_step: law.time_step(dt, sphere_mass / 2.0).unwrap(),
        integrator,
    }
}

/// Touching pairs by brute force with the minimum image in x and y.
fn brute_force_pairs(spheres: &[Sphere<f64>], lx: f64, ly: f64) -> usize {
    let mut count = 0;
    for a in 0..spheres.len() {
        for b in a + 1..spheres.len() {
            let mut d = spheres[b].position - spheres[a].position;
            d.x -= lx * (d.x / lx).round();
            d.y -= ly * (d.y / ly).round();
            let reach = spheres[a].radius + spheres[b].radius;
            if d.norm_squared() < reach * reach {
                count += 1;
            }
        }
    }
    count
}

#[test]
fn the_grid_finds_every_touching_pair_across_periodic_boundaries() {
    let law = law();
    for seed in 1..6 {
        let (spheres, domain) = gas(300, seed);
        let mut scene = OwnedScene::<f64, _>::new(spheres, domain, (DIAMETER, 1e-4), 0).unwrap();
        let m = scene.spheres[0].mass;
        let input = input(
            &law,
            &NoWalls,
            (Vec3::ZERO, 2e-6, m),
            Integrator::SymplecticEuler,
        );
        for _ in 0..50 {
            let before: Vec<Sphere<f64>> = scene.spheres.clone();
            let mut found = 0;
            scene
                .run(&input, 1, |_, stats| found = stats.pair_contacts)
                .unwrap();
            let (lx, ly) = (domain.upper.x, domain.upper.y);
            assert_eq!(found, brute_force_pairs(&before, lx, ly), "seed {seed}");
        }
    }
}

#[test]
fn an_isolated_periodic_gas_keeps_its_momentum_and_repeats_bit_for_bit() {
    let law = law();
    let run = |integrator| {
        let (spheres, domain) = gas(300, 9);
        let mut scene = OwnedScene::<f64, _>::new(spheres, domain, (DIAMETER, 1e-4), 0).unwrap();
        let m = scene.spheres[0].mass;
        let input = input(&law, &NoWalls, (Vec3::ZERO, 2e-6, m), integrator);
        let momentum = |s: &[Sphere<f64>]| {
            s.iter()
                .fold(Vec3::ZERO, |p, s| p + s.velocity * s.mass)
                .to_array()
        };
        let before = momentum(&scene.spheres);
        let mut contacts = 0;
        scene
            .run(&input, 2000, |_, stats| contacts += stats.pair_contacts)
            .unwrap();
        let after = momentum(&scene.spheres);
        let scale: f64 = scene.spheres.iter().map(|s| s.mass * 0.2).sum();
        for k in 0..3 {
            assert!(
                (after[k] - before[k]).abs() < 1e-12 * scale,
                "{integrator:?} {k}"
            );
        }
        assert!(
            contacts > 100,
            "the gas collided ({contacts} contact-steps)"
        );
        scene.spheres
    };
    for integrator in [Integrator::SymplecticEuler, Integrator::VelocityVerlet] {
        let (a, b) = (run(integrator), run(integrator));
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(
                x.position.to_array().map(f64::to_bits),
                y.position.to_array().map(f64::to_bits)
            );
            assert_eq!(
                x.velocity.to_array().map(f64::to_bits),
                y.velocity.to_array().map(f64::to_bits)
            );
        }
    }
}

#[test]
fn both_integrators_settle_a_bed_on_the_floor() {
    let law = law();
    let floor = [Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap()];
    for integrator in [Integrator::SymplecticEuler, Integrator::VelocityVerlet] {
        let (spheres, domain) = gas(150, 3);
        let potential: f64 = spheres.iter().map(|s| s.mass * 9.81 * s.position.z).sum();
        let mut scene = OwnedScene::<f64, _>::new(spheres, domain, (DIAMETER, 1e-4), 1).unwrap();
        let m = scene.spheres[0].mass;
        let gravity = Vec3::new(0.0, 0.0, -9.81);
        let input = input(&law, &floor, (gravity, 4e-6, m), integrator);
        scene.run(&input, 40_000, |_, _| {}).unwrap();
        let lowest = scene
            .spheres
            .iter()
            .map(|s| s.position.z)
            .fold(f64::MAX, f64::min);
        let highest = scene
            .spheres
            .iter()
            .map(|s| s.position.z)
            .fold(0.0, f64::max);
        // 150 spheres of 1 mm over 6 mm x 6 mm: about four layers, resting on the floor.
        assert!(
            lowest > 0.45 * DIAMETER && lowest < 0.51 * DIAMETER,
            "{integrator:?}: {lowest}"
        );
        assert!(highest < 6.0 * DIAMETER, "{integrator:?}: top at {highest}");
        // Nearly all the pour's energy is gone (no rolling resistance: a little rolling remains).
        let kinetic = scene.kinetic_energy();
        assert!(
            kinetic < 1e-3 * potential,
            "{integrator:?}: {kinetic:e} J of {potential:e} J"
        );
    }
}
