//! The scene evaluates its touching pairs four at a time, as lanes (`soft_sphere::lanes`), with
//! the one-contact operations applied lane by lane. These tests hold it to the one-contact law,
//! bit for bit:
//! - a scene of isolated colliding pairs, many touching at once, against the law applied to each
//!   pair directly, for every tangential law, both precisions, both backends, without rotation
//!   and with the contact-plane lever arm;
//! - each law's `force_lanes` against its `force` lane by lane, on random contacts including the
//!   edge cases the lanes choose instead of branching on (sticking and sliding side by side, no
//!   slip, a spring along the normal, no spring).

use host_tests::scene::OwnedScene;
use host_tests::strategies::{config, unit_vector};
use proptest::prelude::*;
use soft_sphere::lanes::{LaneVec, Lanes};
use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::scene::{Domain, Integrator, NoWalls, StepInput};
use soft_sphere::tangential::{TangentialInput, TangentialLanes};
use soft_sphere::{
    ContactLaw, Float, Frictionless, Interaction, LeverArm, Libm, LinearSpringDashpot, MathBackend,
    Micromath, ModelA, ModelAA, ModelB, ModelC, NormalModel, Rotation, Sphere, SpringDisplacement,
    Stateless, TangentialModel, TangentialParameters, Vec3,
};

/// Pairs on a 4 x 4 grid, 3 mm apart, far from the periodic boundaries.
const PAIRS: usize = 16;
const STEPS: usize = 400;
const TIME_STEP: f64 = 2e-6;

/// A small xorshift generator: the same pairs on every run.
struct Noise(u64);

impl Noise {
    /// Uniform in [-1, 1).
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        2.0 * ((self.0 >> 11) as f64 / (1u64 << 53) as f64) - 1.0
    }

    fn vector(&mut self, scale: f64) -> [f64; 3] {
        [
            self.next() * scale,
            self.next() * scale,
            self.next() * scale,
        ]
    }
}

fn vec3<F: Float>(v: [f64; 3]) -> Vec3<F> {
    Vec3::new(F::from_f64(v[0]), F::from_f64(v[1]), F::from_f64(v[2]))
}

/// Isolated pairs about to collide obliquely, each sphere with its own radius (which identifies
/// it after the scene sorts the spheres), its own mass, spin and sliding speed.
fn colliding_pairs<F: Float>(seed: u64) -> Vec<[Sphere<F>; 2]> {
    let mut noise = Noise(seed);
    (0..PAIRS)
        .map(|p| {
            let centre = [
                1.5e-3 + 3e-3 * (p % 4) as f64,
                1.5e-3 + 3e-3 * (p / 4) as f64,
                3e-3,
            ];
            let radius = |k: usize| 0.4e-3 + 1e-6 * (2 * p + k) as f64;
            let (ra, rb) = (radius(0), radius(1));
            let axis = {
                let [x, y, z] = noise.vector(1.0);
                let n = (x * x + y * y + z * z).sqrt().max(1e-3);
                [x / n, y / n, z / n]
            };
            // Apart by a little more than contact, closing at 0.05-0.3 m/s, with a tangential
            // speed of up to 0.5 m/s and spins of up to 300 rad/s: some pairs stick, some slide.
            let gap = ra + rb + 2e-6;
            let closing = 0.175 + 0.125 * noise.next();
            let slide = noise.vector(0.5);
            let mut a = Sphere::solid(vec3(centre), F::from_f64(ra), F::from_f64(2500.0));
            let b_centre = [0, 1, 2].map(|k| centre[k] + axis[k] * gap);
            let mut b = Sphere::solid(vec3(b_centre), F::from_f64(rb), F::from_f64(2500.0));
            a.velocity = vec3([0, 1, 2].map(|k| axis[k] * closing / 2.0 + slide[k] / 2.0));
            b.velocity = vec3([0, 1, 2].map(|k| -axis[k] * closing / 2.0 - slide[k] / 2.0));
            a.angular_velocity = vec3(noise.vector(300.0));
            b.angular_velocity = vec3(noise.vector(300.0));
            [a, b]
        })
        .collect()
}

fn open_box<F: Float>() -> Domain<F> {
    Domain {
        lower: Vec3::ZERO,
        upper: vec3([12e-3, 12e-3, 6e-3]),
        periodic_x: true,
        periodic_y: true,
    }
}

/// The pairs through a scene and through the law directly; asserts the same bits for every
/// sphere, and that the scene had at least two full lanes of touching pairs at once.
fn scene_matches_direct_law<F, N, T, M, R>(name: &str, law: ContactLaw<F, N, T, M, R>, seed: u64)
where
    F: Float,
    N: NormalModel<F>,
    T: TangentialModel<F>,
    M: MathBackend<F>,
    R: Rotation,
{
    let pairs = colliding_pairs::<F>(seed);
    let lightest = pairs
        .iter()
        .flatten()
        .map(|s| s.mass.to_f64())
        .fold(f64::MAX, f64::min);
    let dt = law
        .time_step(F::from_f64(TIME_STEP), F::from_f64(lightest / 2.0))
        .unwrap();

    // Directly: each pair alone, symplectic Euler as the scene does it.
    let mut direct = pairs.clone();
    let mut touching_steps = 0;
    for [a, b] in &mut direct {
        let mut state = T::State::default();
        for _ in 0..STEPS {
            let (mut on_a, mut on_b) = ((Vec3::ZERO, Vec3::ZERO), (Vec3::ZERO, Vec3::ZERO));
            if let Interaction::Touching(c) = law.sphere_sphere(a, b, &mut state, dt).unwrap() {
                on_a = (Vec3::ZERO - c.force_on_j(), Vec3::ZERO + c.torque_on_i);
                on_b = (Vec3::ZERO + c.force_on_j(), Vec3::ZERO + c.torque_on_j);
                touching_steps += 1;
            }
            advance_solid_sphere(a, on_a.0, on_a.1, dt);
            advance_solid_sphere(b, on_b.0, on_b.1, dt);
        }
    }
    assert!(touching_steps > 20 * PAIRS, "{name}: the pairs met");

    let spheres: Vec<Sphere<F>> = pairs.iter().flatten().copied().collect();
    let largest = F::from_f64(0.9e-3);
    let mut scene =
        OwnedScene::<F, T::State>::new(spheres, open_box(), (largest, F::from_f64(1e-4)), 0)
            .unwrap();
    let input = StepInput {
        law: &law,
        wall_law: &law,
        walls: &NoWalls,
        gravity: Vec3::ZERO,
        time_step: dt,
        integrator: Integrator::SymplecticEuler,
    };
    let mut most_touching = 0;
    scene
        .run(&input, STEPS, |_, stats| {
            most_touching = most_touching.max(stats.pair_contacts);
        })
        .unwrap();
    assert!(
        most_touching >= 8,
        "{name}: {most_touching} pairs touched at once"
    );

    let bits = |s: &Sphere<F>| {
        [s.position, s.velocity, s.angular_velocity].map(|v| v.to_array().map(F::to_bits_u64))
    };
    for expected in direct.iter().flatten() {
        let ours = scene
            .spheres
            .iter()
            .find(|s| s.radius == expected.radius)
            .unwrap();
        assert_eq!(
            bits(ours),
            bits(expected),
            "{name}: sphere of radius {:?}",
            expected.radius
        );
    }
}

fn dashpot<F: Float>() -> LinearSpringDashpot<F> {
    LinearSpringDashpot::new(F::from_f64(1000.0), F::from_f64(0.9)).unwrap()
}

fn tangential<F: Float>(friction: f64) -> TangentialParameters<F> {
    TangentialParameters::new(F::from_f64(285.7), F::from_f64(0.5), F::from_f64(friction)).unwrap()
}

#[test]
fn a_scene_of_many_touching_pairs_gives_the_direct_laws_bits_for_every_law() {
    for seed in [1, 2, 3] {
        for friction in [0.5, 0.1] {
            let p = tangential::<f64>(friction);
            scene_matches_direct_law("AA", ContactLaw::new(dashpot(), ModelAA(p)), seed);
            scene_matches_direct_law("A", ContactLaw::new(dashpot(), ModelA(p)), seed);
            scene_matches_direct_law("B", ContactLaw::new(dashpot(), ModelB(p)), seed);
            scene_matches_direct_law("C", ContactLaw::new(dashpot(), ModelC(p)), seed);
            scene_matches_direct_law("stateless", ContactLaw::new(dashpot(), Stateless(p)), seed);
        }
        scene_matches_direct_law(
            "frictionless",
            ContactLaw::new(dashpot::<f64>(), Frictionless),
            seed,
        );
    }
}

#[test]
fn the_lanes_give_the_direct_laws_bits_in_f32_on_both_backends_and_for_every_slot() {
    for seed in [4, 5] {
        let aa = ContactLaw::new(dashpot::<f32>(), ModelAA(tangential(0.3)));
        scene_matches_direct_law("AA f32 libm", aa, seed);
        scene_matches_direct_law("AA f32 micromath", aa.with_backend::<Micromath>(), seed);
        scene_matches_direct_law("AA f32 non-rotating", aa.without_rotation(), seed);
        let plane = aa.with_lever_arm(LeverArm::ContactPlane);
        scene_matches_direct_law("AA f32 contact plane", plane, seed);
        let aa = ContactLaw::new(dashpot::<f64>(), ModelAA(tangential(0.3)));
        let clamped = ContactLaw::new(
            dashpot::<f64>().with_attraction_clamped(),
            ModelAA(tangential(0.3)),
        );
        scene_matches_direct_law("AA f64 non-rotating", aa.without_rotation(), seed);
        scene_matches_direct_law(
            "AA f64 contact plane",
            aa.with_lever_arm(LeverArm::ContactPlane),
            seed,
        );
        scene_matches_direct_law("AA f64 clamped", clamped, seed);
    }
}

/// One random contact as a tangential slot sees it. `kind` picks an edge case: 0 a general
/// contact, 1 no slip, 2 a stored spring along the normal, 3 no stored spring.
#[derive(Clone, Debug)]
struct Contact {
    normal: [f64; 3],
    slip: [f64; 3],
    spring: [f64; 3],
    normal_force: f64,
    approach_rate: f64,
}

fn contact() -> impl Strategy<Value = Contact> {
    (
        unit_vector(),
        prop::array::uniform3(-0.5..0.5f64),
        prop::array::uniform3(-2e-5..2e-5f64),
        -0.02..0.2f64,
        -0.3..0.3f64,
        0..4u8,
    )
        .prop_map(
            |(normal, slip, spring, normal_force, approach_rate, kind)| {
                // Keep the slip in the tangent plane, as the law delivers it.
                let along = |v: [f64; 3]| v[0] * normal[0] + v[1] * normal[1] + v[2] * normal[2];
                let s = along(slip);
                let mut slip = [0, 1, 2].map(|k| slip[k] - s * normal[k]);
                let mut spring = spring;
                match kind {
                    1 => slip = [0.0; 3],
                    2 => spring = normal.map(|n| n * 1e-5),
                    3 => spring = [0.0; 3],
                    _ => {}
                }
                Contact {
                    normal,
                    slip,
                    spring,
                    normal_force,
                    approach_rate,
                }
            },
        )
}

/// Each law's lanes against its one-contact `force`, bit for bit.
fn lanes_match_force<F: Float, M: MathBackend<F>>(contacts: &[Contact; 4]) {
    let n = dashpot::<F>();
    let mass = F::from_f64(2.6e-6);
    let oscillator = n.oscillator::<M>(mass);
    let dt = F::from_f64(TIME_STEP);
    let inputs: [TangentialInput<F>; 4] = contacts.clone().map(|c| TangentialInput {
        normal: vec3(c.normal),
        slip_velocity: vec3(c.slip),
        normal_force: F::from_f64(c.normal_force),
        overlap: F::from_f64(1e-6),
        approach_rate: F::from_f64(c.approach_rate),
        oscillator,
        time_step: dt,
    });
    let lanes = TangentialLanes {
        normal: LaneVec::from_fn(|l| inputs[l].normal),
        slip_velocity: LaneVec::from_fn(|l| inputs[l].slip_velocity),
        normal_force: Lanes::from_fn(|l| inputs[l].normal_force),
        overlap: Lanes::from_fn(|l| inputs[l].overlap),
        approach_rate: Lanes::from_fn(|l| inputs[l].approach_rate),
        oscillator: [oscillator; 4],
        time_step: dt,
    };
    let springs = contacts.clone().map(|c| SpringDisplacement {
        displacement: vec3::<F>(c.spring),
    });
    fn check<F: Float, M: MathBackend<F>, T: TangentialModel<F>>(
        name: &str,
        law: T,
        states: &[T::State; 4],
        inputs: &[TangentialInput<F>; 4],
        lanes: &TangentialLanes<F, 4>,
    ) {
        let together = law.force_lanes::<M, 4>(states, lanes);
        for l in 0..4 {
            let alone = law.force::<M>(&states[l], &inputs[l]);
            let bits = |v: Vec3<F>| v.to_array().map(F::to_bits_u64);
            assert_eq!(
                bits(together.force.lane(l)),
                bits(alone.force),
                "{name} lane {l}"
            );
            assert_eq!(together.states[l], alone.state, "{name} lane {l}");
            assert_eq!(together.sliding[l], alone.sliding, "{name} lane {l}");
        }
    }
    let p = tangential::<F>(0.5);
    check::<F, M, _>("AA", ModelAA(p), &springs, &inputs, &lanes);
    check::<F, M, _>("A", ModelA(p), &springs, &inputs, &lanes);
    check::<F, M, _>("B", ModelB(p), &springs, &inputs, &lanes);
    check::<F, M, _>("C", ModelC(p), &[(); 4], &inputs, &lanes);
    check::<F, M, _>("stateless", Stateless(p), &[(); 4], &inputs, &lanes);
    check::<F, M, _>("frictionless", Frictionless, &[(); 4], &inputs, &lanes);
    // The stored spring: kept bit for bit too (SpringDisplacement compares by value; zero signs
    // matter for the next step's sums).
    let together = ModelAA(p).force_lanes::<M, 4>(&springs, &lanes);
    for l in 0..4 {
        let alone = ModelAA(p).force::<M>(&springs[l], &inputs[l]);
        let bits = |s: SpringDisplacement<F>| s.displacement.to_array().map(F::to_bits_u64);
        assert_eq!(
            bits(together.states[l]),
            bits(alone.state),
            "AA spring, lane {l}"
        );
    }
}

proptest! {
    #![proptest_config(config())]
    #[test]
    fn every_laws_lanes_give_its_one_contact_bits(contacts in prop::array::uniform4(contact())) {
        lanes_match_force::<f64, Libm>(&contacts);
        lanes_match_force::<f32, Libm>(&contacts);
        lanes_match_force::<f32, Micromath>(&contacts);
    }
}
