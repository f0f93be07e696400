//! The scene crate: the cell grid and Verlet list find exactly the touching
//! pairs a brute-force search finds, across periodic boundaries; an isolated periodic gas keeps its
//! momentum; runs are bit for bit repeatable; both integrators settle a bed under gravity; the
//! stored springs survive Verlet-list rebuilds; bad spheres and failed steps have defined answers.

use host_tests::random::Xorshift;
use host_tests::scene::{Column, OwnedScene, SceneExt, Threads, pair_and_wall, wall_of};
use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    CheckedSphere, ContactError, ContactLaw, Interaction, LinearAA, LinearSpringDashpot,
    LinearStateless, MaterialTable, MaterialWall, ModelAA, Sphere, SpringDisplacement, Stateless,
    TangentialParameters, Vec3, Wall,
};
use soft_sphere_scene::{
    Domain, Integrator, NoWalls, Parking, Scene, SceneBuffers, SceneError, StepError, StepInput,
    StepStats, WallSet,
};

const DIAMETER: f64 = 1e-3;

/// A small periodic gas: spheres on a jittered lattice with random velocities, some touching.
fn gas(count: usize, seed: u64) -> (Vec<Sphere<f64>>, Domain<f64>) {
    let column = Column {
        spheres: count,
        diameter: DIAMETER,
        density: 2500.0,
        width_x: 0.006,
        width_y: 0.006,
    };
    let (mut spheres, height) = column.lattice::<f64>();
    let mut random = Xorshift::new(seed);
    let mut next = || random.unit() - 0.5;
    for s in &mut spheres {
        s.velocity = Vec3::new(next(), next(), next()) * 0.2;
        s.angular_velocity = Vec3::new(next(), next(), next()) * 100.0;
        // Squeeze the lattice so that neighbours overlap now and then.
        s.position.z *= 0.85;
    }
    // Room above and below: nothing holds the gas in z, and a sphere that leaves the domain
    // along it is refused.
    let mut domain = column.domain(height);
    (domain.lower.z, domain.upper.z) = (-height, 2.0 * height);
    (spheres, domain)
}

fn law() -> Linear {
    ContactLaw::new(
        LinearSpringDashpot::new(1000.0, 0.9).unwrap(),
        ModelAA(TangentialParameters::new(285.7, 0.5, 0.5).unwrap()),
    )
}

type Linear = LinearAA<f64>;

/// One material: [`law`] for pairs and walls.
type Table = MaterialTable<Linear, 1>;

fn table() -> Table {
    MaterialTable::uniform(law())
}

/// A wall of the one material.
fn wall(point: Vec3<f64>, normal: Vec3<f64>) -> MaterialWall<f64> {
    MaterialWall {
        wall: Wall::new(point, normal).unwrap(),
        material: 0,
    }
}

/// One law for pairs and walls, stepped at `dt` for a pair of these spheres' mass.
fn input(
    table: &Table,
    (gravity, dt, sphere_mass): (Vec3<f64>, f64, f64),
    integrator: Integrator,
) -> StepInput<'_, Linear, 1> {
    let law = table.law(0, 0).unwrap();
    StepInput {
        table,
        gravity,
        time_step: law.time_step(dt, sphere_mass / 2.0).unwrap(),
        integrator,
    }
}

/// Touching pairs by brute force with the minimum image in x and y, and how many of them touch
/// through a periodic image.
fn brute_force_pairs(spheres: &[CheckedSphere<f64>], lx: f64, ly: f64) -> (usize, usize) {
    let (mut count, mut across) = (0, 0);
    for a in 0..spheres.len() {
        for b in a + 1..spheres.len() {
            let mut d = spheres[b].position - spheres[a].position;
            let (sx, sy) = ((d.x / lx).round(), (d.y / ly).round());
            d.x -= lx * sx;
            d.y -= ly * sy;
            let reach = spheres[a].radius + spheres[b].radius;
            if d.norm_squared() < reach * reach {
                count += 1;
                across += usize::from(sx != 0.0 || sy != 0.0);
            }
        }
    }
    (count, across)
}

/// `count` spheres placed at random in a 4 mm box periodic in x and y, no two closer than 0.9
/// diameters (with the periodic image): a dense packing with many pairs touching across the
/// periodic boundaries.
fn random_packing(count: usize, seed: u64) -> (Vec<Sphere<f64>>, Domain<f64>) {
    let side = 4.0e-3;
    let domain = Domain {
        lower: Vec3::ZERO,
        upper: Vec3::new(side, side, side),
        periodic_x: true,
        periodic_y: true,
    };
    let mut random = Xorshift::new(seed);
    let mut spheres: Vec<Sphere<f64>> = Vec::new();
    let image = |d: f64| d - side * (d / side).round();
    while spheres.len() < count {
        let r = DIAMETER / 2.0;
        let p = Vec3::new(
            random.unit() * side,
            random.unit() * side,
            r + random.unit() * (side - 2.0 * r),
        );
        let clear = spheres.iter().all(|s| {
            let d = s.position - p;
            let d = Vec3::new(image(d.x), image(d.y), d.z);
            d.norm_squared() >= (0.9 * DIAMETER) * (0.9 * DIAMETER)
        });
        if clear {
            let mut s = Sphere::solid(p, r, 2500.0);
            s.velocity = Vec3::new(
                random.unit() - 0.5,
                random.unit() - 0.5,
                random.unit() - 0.5,
            ) * 0.2;
            spheres.push(s);
        }
    }
    (spheres, domain)
}

#[test]
fn the_grid_finds_every_touching_pair_across_periodic_boundaries() {
    let law = table();
    // The box at the origin, and moved off it (cells are counted from its lower corner).
    let offset = Vec3::new(-3.1e-3, 1.7e-3, 2.3e-3);
    let mut across = 0;
    for (seed, shift) in (1..6).flat_map(|seed| [(seed, Vec3::ZERO), (seed, offset)]) {
        let (mut spheres, mut domain) = random_packing(40, seed);
        for s in &mut spheres {
            s.position += shift;
        }
        (domain.lower, domain.upper) = (domain.lower + shift, domain.upper + shift);
        let mut scene = OwnedScene::<Linear, _>::new(spheres, domain, 1e-4, NoWalls).unwrap();
        let m = scene.spheres()[0].mass;
        let input = input(&law, (Vec3::ZERO, 2e-6, m), Integrator::SymplecticEuler);
        let lengths = domain.upper - domain.lower;
        for _ in 0..20 {
            let before = scene.spheres().to_vec();
            let mut found = 0;
            scene
                .run(&input, 1, |_, stats| found = stats.pair_contacts)
                .unwrap();
            let (expected, crossing) = brute_force_pairs(&before, lengths.x, lengths.y);
            assert_eq!(found, expected, "seed {seed}, box moved by {shift:?}");
            across += crossing;
        }
    }
    assert!(
        across > 100,
        "{across} pair-steps across a periodic boundary"
    );
}

#[test]
fn an_isolated_periodic_gas_keeps_its_momentum_and_repeats_bit_for_bit() {
    let law = table();
    let run = |integrator| {
        let (spheres, domain) = gas(300, 9);
        let mut scene = OwnedScene::<Linear, _>::new(spheres, domain, 1e-4, NoWalls).unwrap();
        let m = scene.spheres()[0].mass;
        let input = input(&law, (Vec3::ZERO, 2e-6, m), integrator);
        let momentum = |s: &[CheckedSphere<f64>]| {
            s.iter()
                .fold(Vec3::ZERO, |p, s| p + s.velocity * s.mass)
                .to_array()
        };
        let before = momentum(scene.spheres());
        let mut contacts = 0;
        scene
            .run(&input, 2000, |_, stats| contacts += stats.pair_contacts)
            .unwrap();
        let after = momentum(scene.spheres());
        let scale: f64 = scene.spheres().iter().map(|s| s.mass * 0.2).sum();
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
        scene.spheres().to_vec()
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
    let law = table();
    let floor = [wall(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0))];
    for integrator in [Integrator::SymplecticEuler, Integrator::VelocityVerlet] {
        let (spheres, domain) = gas(150, 3);
        let potential: f64 = spheres.iter().map(|s| s.mass * 9.81 * s.position.z).sum();
        let mut scene = OwnedScene::<Linear, _>::new(spheres, domain, 1e-4, floor).unwrap();
        let m = scene.spheres()[0].mass;
        let gravity = Vec3::new(0.0, 0.0, -9.81);
        let input = input(&law, (gravity, 4e-6, m), integrator);
        scene.run(&input, 40_000, |_, _| {}).unwrap();
        let lowest = scene
            .spheres()
            .iter()
            .map(|s| s.position.z)
            .fold(f64::MAX, f64::min);
        let highest = scene
            .spheres()
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

/// A 6 mm periodic box with no walls and room above.
fn open_box() -> Domain<f64> {
    Domain {
        lower: Vec3::ZERO,
        upper: Vec3::new(0.006, 0.006, 0.006),
        periodic_x: true,
        periodic_y: true,
    }
}

/// Two spheres meeting obliquely across the periodic boundary in x; neither crosses it.
fn oblique_pair() -> Vec<Sphere<f64>> {
    let mut a = Sphere::solid(Vec3::new(0.55e-3, 3e-3, 3.0e-3), DIAMETER / 2.0, 2500.0);
    let mut b = Sphere::solid(Vec3::new(5.591e-3, 3e-3, 3.3e-3), DIAMETER / 2.0, 2500.0);
    a.velocity = Vec3::new(-0.1, 0.0, 0.0);
    b.velocity = Vec3::new(0.1, 0.0, 0.0);
    a.angular_velocity = Vec3::new(0.0, 30.0, 0.0);
    vec![a, b]
}

#[test]
fn the_stored_springs_survive_list_rebuilds_bit_for_bit() {
    let table = table();
    let law = law();
    let steps = 150;
    let mass = oblique_pair()[0].mass;
    let dt = law.time_step(2e-6, mass / 2.0).unwrap();

    // The contact law applied to the pair directly, with B seen through its periodic image.
    let [mut a, mut b] = <[Sphere<f64>; 2]>::try_from(oblique_pair()).unwrap();
    let shift = Vec3::new(-open_box().upper.x, 0.0, 0.0);
    let mut state = SpringDisplacement::default();
    let mut touching_steps = 0;
    let mut largest_spring: f64 = 0.0;
    for _ in 0..steps {
        let mut image = b;
        image.position = b.position + shift;
        let (mut on_a, mut on_b) = ((Vec3::ZERO, Vec3::ZERO), (Vec3::ZERO, Vec3::ZERO));
        if let Interaction::Touching(c) = law.sphere_sphere(&a, &image, &mut state, dt).unwrap() {
            on_a = (Vec3::ZERO - c.force_on_j(), Vec3::ZERO + c.torque_on_i);
            on_b = (Vec3::ZERO + c.force_on_j(), Vec3::ZERO + c.torque_on_j);
            touching_steps += 1;
            largest_spring = largest_spring.max(state.displacement.norm_squared().sqrt());
        }
        advance_solid_sphere(&mut a, on_a.0, on_a.1, dt);
        advance_solid_sphere(&mut b, on_b.0, on_b.1, dt);
    }
    // The pair met, the spring stretched, and the contact ended within the run.
    assert!(touching_steps > 20 && state == SpringDisplacement::default());
    assert!(largest_spring > 1e-7, "spring {largest_spring:e} m");

    // The scene: a wide skin (one list build), no skin (a build every step), and a fresh scene
    // every step (the history parked and found again each time).
    let input = input(
        &table,
        (Vec3::ZERO, 2e-6, mass),
        Integrator::SymplecticEuler,
    );
    for (skin, calls) in [(1e-4, 1), (0.0, 1), (1e-4, steps)] {
        let mut scene =
            OwnedScene::<Linear, _>::new(oblique_pair(), open_box(), skin, NoWalls).unwrap();
        assert!(
            scene.spheres()[0].position.x < 1e-3,
            "sorted: A is sphere 0"
        );
        for _ in 0..calls {
            scene.run(&input, steps / calls, |_, _| {}).unwrap();
        }
        for (ours, direct) in scene.spheres().iter().zip([a, b]) {
            let bits = |s: &Sphere<f64>| {
                [s.position, s.velocity, s.angular_velocity].map(|v| v.to_array().map(f64::to_bits))
            };
            assert_eq!(bits(ours), bits(&direct), "skin {skin}, {calls} calls");
        }
    }
}

#[test]
fn an_invalid_sphere_is_refused_when_the_scene_is_built() {
    type Spoil = fn(&mut Sphere<f64>);
    let cases: [(Spoil, ContactError); 4] = [
        (|s| s.velocity.y = f64::NAN, ContactError::NonFiniteInput),
        (
            |s| s.angular_velocity.x = f64::INFINITY,
            ContactError::NonFiniteInput,
        ),
        (|s| s.radius = -s.radius, ContactError::NonPositiveRadius),
        (|s| s.mass = 0.0, ContactError::NonPositiveMass),
    ];
    for (spoil, error) in cases {
        let mut spheres = oblique_pair();
        spoil(&mut spheres[1]);
        let result = OwnedScene::<Linear, _>::new(spheres, open_box(), 1e-4, NoWalls);
        assert_eq!(result.err(), Some(SceneError::Sphere { index: 1, error }));
    }
}

/// Fresh buffers in vectors for `spheres` spheres in [`open_box`] without skin, a list of
/// `capacity` entries, states sized for `walls` walls (checked against `W`'s count by the
/// scene), and `K` parked contacts per sphere, all of material 0.
struct VecBuffers<const K: usize> {
    cells: Vec<u32>,
    pairs: Vec<[u32; 2]>,
    vectors: Vec<Vec3<f64>>,
    states: Vec<SpringDisplacement<f64>>,
    parking: Vec<Parking<SpringDisplacement<f64>, K>>,
    materials: Vec<u32>,
}

impl<const K: usize> VecBuffers<K> {
    fn new(spheres: usize, capacity: usize, walls: usize) -> Self {
        let sizes = Scene::<Linear, NoWalls, K>::buffer_sizes(
            &open_box(),
            (DIAMETER, 0.0),
            spheres,
            capacity,
            false,
        )
        .unwrap();
        Self {
            cells: vec![0; sizes.cells],
            pairs: vec![[0; 2]; sizes.pairs],
            vectors: vec![Vec3::ZERO; sizes.vectors],
            states: vec![SpringDisplacement::default(); sizes.states + 2 * spheres * walls],
            parking: vec![Parking::default(); sizes.parking],
            materials: vec![0; spheres],
        }
    }

    fn buffers(&mut self) -> (&[u32], SceneBuffers<'_, f64, SpringDisplacement<f64>, K>) {
        let buffers = SceneBuffers {
            cells: &mut self.cells,
            pairs: &mut self.pairs,
            vectors: &mut self.vectors,
            states: &mut self.states,
            parking: &mut self.parking,
            records: &mut [],
            loads: &mut [],
        };
        (&self.materials, buffers)
    }

    /// The contact history of `other` (its list's pairs and their states) at the front of
    /// these buffers, as a caller moves to a longer list or a larger parking.
    fn carry_history_from<const J: usize>(&mut self, other: &VecBuffers<J>) {
        let list = other.pairs.len();
        self.pairs[..list].copy_from_slice(&other.pairs);
        self.states[..list].copy_from_slice(&other.states[..list]);
    }

    /// A scene without walls over these buffers, run for at most `steps` steps; how many
    /// succeeded, whether a pair touched in the last, and the error that stopped it.
    fn run(
        &mut self,
        input: &StepInput<'_, Linear, 1>,
        spheres: &mut [CheckedSphere<f64>],
        steps: usize,
    ) -> (usize, bool, Option<StepError>) {
        let (materials, buffers) = self.buffers();
        let mut scene = Scene::new(
            open_box(),
            (DIAMETER, 0.0),
            (spheres, materials),
            buffers,
            NoWalls,
        )
        .unwrap();
        let mut touching = false;
        for done in 0..steps {
            match scene.step(input) {
                Ok(stats) => touching = stats.pair_contacts > 0,
                Err(error) => return (done, touching, Some(error)),
            }
        }
        (steps, touching, None)
    }
}

/// Buffers for the two spheres of [`oblique_pair`] with `walls` wall entries.
fn pair_buffers(walls: usize) -> VecBuffers<4> {
    VecBuffers::new(2, 4, walls)
}

fn checked_pair() -> Vec<CheckedSphere<f64>> {
    oblique_pair()
        .into_iter()
        .map(|s| CheckedSphere::new(s).unwrap())
        .collect()
}

#[test]
fn buffers_that_do_not_fit_the_walls_are_refused() {
    let floor = [wall(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0))];
    let two_walls = [
        floor[0],
        wall(Vec3::new(0.0, 0.0, 0.006), Vec3::new(0.0, 0.0, -1.0)),
    ];
    // States sized for 0, 1, 2 or 3 walls: only the walls' own count is taken.
    for (sized_for, refused_with_one, refused_with_two) in [
        (0, true, true),
        (1, false, true),
        (2, true, false),
        (3, true, true),
    ] {
        let refused = |error| error == Some(SceneError::BufferLength);
        assert_eq!(
            refused(pair_scene_error(sized_for, floor)),
            refused_with_one,
            "states for {sized_for} walls, one wall"
        );
        assert_eq!(
            refused(pair_scene_error(sized_for, two_walls)),
            refused_with_two,
            "states for {sized_for} walls, two walls"
        );
    }
    assert_eq!(pair_scene_error(0, NoWalls), None);
    assert_eq!(pair_scene_error(1, NoWalls), Some(SceneError::BufferLength));
}

#[test]
fn material_ids_that_are_not_one_per_sphere_are_refused() {
    let mut spheres = checked_pair();
    let mut b = pair_buffers(0);
    let (_, buffers) = b.buffers();
    let scene = Scene::<Linear, _, 4>::new(
        open_box(),
        (DIAMETER, 0.0),
        (&mut spheres, &[0]),
        buffers,
        NoWalls,
    );
    assert_eq!(scene.err(), Some(SceneError::Materials));
}

/// What building a scene of [`checked_pair`] over fresh buffers with states sized for
/// `sized_for` walls and `walls` gives: `None` when the scene is built.
fn pair_scene_error<W: WallSet<f64>>(sized_for: usize, walls: W) -> Option<SceneError> {
    let mut spheres = checked_pair();
    let mut b = pair_buffers(sized_for);
    let (materials, buffers) = b.buffers();
    Scene::<Linear, _, 4>::new(
        open_box(),
        (DIAMETER, 0.0),
        (&mut spheres, materials),
        buffers,
        walls,
    )
    .err()
}

/// A scene of [`checked_pair`] over `buffers`, stepped until the pair touches (at most 500 steps).
fn step_pair_until_touching<'a>(
    table: &Table,
    pair: &'a mut [CheckedSphere<f64>],
    buffers: &'a mut VecBuffers<4>,
) -> Scene<'a, Linear, NoWalls, 4> {
    let input = input(
        table,
        (Vec3::ZERO, 2e-6, pair[0].mass),
        Integrator::SymplecticEuler,
    );
    let (materials, buffers) = buffers.buffers();
    let mut scene = Scene::new(
        open_box(),
        (DIAMETER, 0.0),
        (pair, materials),
        buffers,
        NoWalls,
    )
    .unwrap();
    let touched = (0..500).any(|_| scene.step(&input).unwrap().pair_contacts > 0);
    assert!(touched, "the pair met");
    scene
}

#[test]
fn stored_states_of_pairs_outside_the_scene_are_refused() {
    let law = table();
    let mut pair = checked_pair();
    let mut b = pair_buffers(0);
    step_pair_until_touching(&law, &mut pair, &mut b);
    // The list now holds the pair's stored spring. The same two spheres take it back...
    let mut again = pair.clone();
    let (materials, buffers) = b.buffers();
    assert!(
        Scene::<Linear, _, 4>::new(
            open_box(),
            (DIAMETER, 0.0),
            (&mut again, materials),
            buffers,
            NoWalls
        )
        .is_ok()
    );
    // ... a scene of the first sphere alone does not own it.
    let alone =
        Scene::<Linear, NoWalls, 4>::buffer_sizes(&open_box(), (DIAMETER, 0.0), 1, 4, false)
            .unwrap();
    let buffers = SceneBuffers {
        cells: &mut b.cells[..alone.cells],
        pairs: &mut b.pairs,
        vectors: &mut b.vectors[..alone.vectors],
        states: &mut b.states[..alone.states],
        parking: &mut b.parking[..1],
        records: &mut [],
        loads: &mut [],
    };
    let alone = Scene::<Linear, _, 4>::new(
        open_box(),
        (DIAMETER, 0.0),
        (&mut pair[..1], &[0]),
        buffers,
        NoWalls,
    );
    assert_eq!(alone.err(), Some(SceneError::History));
}

#[test]
fn a_failed_step_leaves_the_scene_as_it_was() {
    let law = table();
    let mut spheres = oblique_pair();
    // A third sphere on top of the first: its contact has no normal.
    spheres.push(spheres[0]);
    let mass = spheres[0].mass;
    let mut scene = OwnedScene::<Linear, _>::new(spheres, open_box(), 1e-4, NoWalls).unwrap();
    let before = scene.spheres().to_vec();
    let input = input(&law, (Vec3::ZERO, 2e-6, mass), Integrator::SymplecticEuler);
    assert_eq!(
        scene.run(&input, 1, |_, _| {}),
        Err(StepError::Pair {
            spheres: [0, 2],
            error: ContactError::CoincidentCentres
        })
    );
    assert_eq!(scene.spheres(), before);
}

#[test]
fn a_diverging_step_is_reported_and_the_scene_refuses_to_go_on() {
    let law = table();
    let mut spheres = checked_pair();
    // Finite, so the sphere is valid; gravity along it pushes it past the largest float in one
    // kick.
    spheres[0].update(|s| s.velocity.x = f64::MAX).unwrap();
    let before = spheres.clone();
    let gravity = Vec3::new(1e300, 0.0, 0.0);
    let input = input(
        &law,
        (gravity, 2e-6, before[0].mass),
        Integrator::SymplecticEuler,
    );
    let mut b = pair_buffers(0);
    let (materials, buffers) = b.buffers();
    let mut scene = Scene::<Linear, _, 4>::new(
        open_box(),
        (DIAMETER, 0.0),
        (&mut spheres, materials),
        buffers,
        NoWalls,
    )
    .unwrap();
    assert_eq!(scene.step(&input), Err(StepError::Diverged { index: 0 }));
    // The diverged sphere kept its state; the other one moved.
    assert_eq!(scene.spheres()[0], before[0]);
    assert_ne!(scene.spheres()[1], before[1]);
    assert_eq!(scene.step(&input), Err(StepError::Halted));
}

#[test]
fn non_finite_gravity_is_refused_and_changes_nothing() {
    // It was taken for a divergence of sphere 0, and the scene halted.
    let law = table();
    for bad in [f64::NAN, f64::INFINITY, -f64::INFINITY] {
        for integrator in Integrator::ALL {
            let spheres = oblique_pair();
            let mass = spheres[0].mass;
            let mut scene =
                OwnedScene::<Linear, _>::new(spheres, open_box(), 1e-4, NoWalls).unwrap();
            let before = scene.spheres().to_vec();
            let gravity = Vec3::new(0.0, bad, -9.81);
            let refused = input(&law, (gravity, 2e-6, mass), integrator);
            assert_eq!(scene.run(&refused, 1, |_, _| {}), Err(StepError::Gravity));
            assert_eq!(scene.spheres(), before);
            // Not halted: a finite gravity steps on.
            let fine = input(&law, (Vec3::new(0.0, 0.0, -9.81), 2e-6, mass), integrator);
            assert!(scene.run(&fine, 1, |_, _| {}).is_ok());
        }
    }
    assert!(StepError::Gravity.to_string().contains("gravity"));
}

#[test]
fn threads_give_the_same_bits_as_one_thread() {
    let law = table();
    // A floor, and a ceiling through the top layer, so that spheres at both ends of the sphere
    // order (each end in another thread's stretch) have stored wall contacts.
    let top = gas(1000, 5)
        .0
        .iter()
        .map(|s| s.position.z)
        .fold(0.0, f64::max);
    let walls = [
        wall(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)),
        wall(
            Vec3::new(0.0, 0.0, top + 0.45 * DIAMETER),
            Vec3::new(0.0, 0.0, -1.0),
        ),
    ];
    let gravity = Vec3::new(0.0, 0.0, -9.81);
    for integrator in [Integrator::SymplecticEuler, Integrator::VelocityVerlet] {
        let run = |threads: Option<usize>| {
            let (spheres, domain) = gas(1000, 5);
            let mut scene = OwnedScene::<Linear, _>::new(spheres, domain, 1e-4, walls).unwrap();
            let m = scene.spheres()[0].mass;
            let input = input(&law, (gravity, 4e-6, m), integrator);
            let mut contacts = Vec::new();
            let record = |_: usize, s: &StepStats<f64>| {
                contacts.push((s.pair_contacts, s.wall_contacts, s.overlap_sum.to_bits()));
            };
            match threads {
                None => scene.run(&input, 1000, record).unwrap(),
                Some(n) => {
                    let pool = Threads::new(n).unwrap();
                    scene.run_on(&input, 1000, &pool, record).unwrap();
                }
            }
            (scene.spheres().to_vec(), contacts)
        };
        let (serial, serial_contacts) = run(None);
        // The gas fell onto the floor and collided on the way.
        assert!(serial_contacts.iter().any(|c| c.1 > 0 && c.0 > 0));
        for threads in [1, 2, 3] {
            let (spheres, contacts) = run(Some(threads));
            assert_eq!(
                contacts, serial_contacts,
                "{integrator:?}, {threads} threads"
            );
            for (a, b) in spheres.iter().zip(&serial) {
                let bits = |s: &Sphere<f64>| {
                    [s.position, s.velocity, s.angular_velocity]
                        .map(|v| v.to_array().map(f64::to_bits))
                };
                assert_eq!(bits(a), bits(b), "{integrator:?}, {threads} threads");
            }
        }
    }
}

#[test]
fn the_loads_of_a_touching_pair_are_action_and_reaction() {
    let law = table();
    let mut pair = checked_pair();
    let mut b = pair_buffers(0);
    let scene = step_pair_until_touching(&law, &mut pair, &mut b);
    let ((f0, t0), (f1, t1)) = (scene.load(0).unwrap(), scene.load(1).unwrap());
    assert!(f0.norm_squared() > 0.0, "the pair pushes");
    assert_eq!(f0, -f1);
    // Equal spheres, radius arm: the torques are equal (both -R n x F_t).
    assert_eq!(t0, t1);
    assert_eq!(scene.load(2), None);
}

/// The oblique pair and a third sphere beside sphere `near` on the `side` (+1 or -1) in y,
/// keeping pace with it in x and closing in y, so that it comes within reach while the pair
/// touches.
fn trio((near, side): (usize, f64)) -> Vec<CheckedSphere<f64>> {
    let mut spheres = oblique_pair();
    let mut third = spheres[near];
    third.position.y += side * (DIAMETER + 4e-6);
    third.velocity = Vec3::new(third.velocity.x, -side * 0.1, 0.0);
    third.angular_velocity = Vec3::ZERO;
    spheres.push(third);
    spheres
        .into_iter()
        .map(|s| CheckedSphere::new(s).unwrap())
        .collect()
}

/// Every sphere's position, velocity and spin, as bits.
fn motion_bits(spheres: &[CheckedSphere<f64>]) -> Vec<[[u64; 3]; 3]> {
    let bits = |v: Vec3<f64>| v.to_array().map(f64::to_bits);
    spheres
        .iter()
        .map(|s| [bits(s.position), bits(s.velocity), bits(s.angular_velocity)])
        .collect()
}

#[test]
fn a_full_list_loses_no_history_and_a_larger_one_carries_on() {
    let law = table();
    let mass = oblique_pair()[0].mass;
    let input = input(&law, (Vec3::ZERO, 2e-6, mass), Integrator::SymplecticEuler);
    let after = 60;
    // On either side of either sphere: the grid finds the new pair before or after the old.
    for near in [(0, 1.0), (0, -1.0), (1, 1.0), (1, -1.0)] {
        // A list of one: it holds the pair until the third sphere comes within reach.
        let mut spheres = trio(near);
        let mut small = VecBuffers::<4>::new(3, 1, 0);
        let (steps, touching, error) = small.run(&input, &mut spheres, 500);
        assert_eq!(
            error,
            Some(StepError::ListFull),
            "third sphere beside {near:?}"
        );
        assert!(
            touching,
            "the pair touched (its spring is stored) when the list overflowed"
        );
        // The documented recovery: a larger list over the same history.
        let mut large = VecBuffers::<4>::new(3, 4, 0);
        large.carry_history_from(&small);
        let (done, _, error) = large.run(&input, &mut spheres, after);
        assert_eq!((done, error), (after, None));

        // A large list from the start, with a new scene at the same step.
        let mut reference = trio(near);
        let mut b = VecBuffers::<4>::new(3, 4, 0);
        assert_eq!(b.run(&input, &mut reference, steps), (steps, true, None));
        assert_eq!(b.run(&input, &mut reference, after).0, after);
        assert_eq!(
            motion_bits(&spheres),
            motion_bits(&reference),
            "third sphere beside {near:?}"
        );
    }
}

#[test]
fn a_full_parking_loses_no_history_and_a_larger_one_carries_on() {
    let law = table();
    let mass = oblique_pair()[0].mass;
    let input = input(&law, (Vec3::ZERO, 2e-6, mass), Integrator::SymplecticEuler);
    // Sphere 0 owns both its contacts (the lower index owns a pair): with room to park one,
    // the first rebuild with both springs stored fails.
    let mut spheres = trio((0, 1.0));
    let mut narrow = VecBuffers::<1>::new(3, 4, 0);
    let (steps, touching, error) = narrow.run(&input, &mut spheres, 500);
    assert_eq!(error, Some(StepError::ParkingFull));
    assert!(touching);
    // The same list with room to park four.
    let mut wide = VecBuffers::<4>::new(3, 4, 0);
    wide.carry_history_from(&narrow);
    let after = 60;
    assert_eq!(wide.run(&input, &mut spheres, after).0, after);

    let mut reference = trio((0, 1.0));
    let mut b = VecBuffers::<4>::new(3, 4, 0);
    assert_eq!(b.run(&input, &mut reference, steps).0, steps);
    assert_eq!(b.run(&input, &mut reference, after).0, after);
    assert_eq!(motion_bits(&spheres), motion_bits(&reference));
}

#[test]
fn each_steps_totals_are_what_a_brute_force_search_finds() {
    // The stateless law stores nothing, so the kernel's verdict on each pair (sliding or not)
    // can be had again outside the scene from the positions before the step.
    type Plain = LinearStateless<f64>;
    let law: Plain = ContactLaw::new(
        LinearSpringDashpot::new(1000.0, 0.9).unwrap(),
        Stateless(TangentialParameters::new(285.7, 0.5, 0.3).unwrap()),
    );
    let (spheres, domain) = gas(300, 3);
    // A floor through the lowest layer, so that some spheres touch it from the start.
    let lowest = spheres
        .iter()
        .map(|s| s.position.z)
        .fold(f64::INFINITY, f64::min);
    let height = lowest - 0.45 * DIAMETER;
    let floor = wall(Vec3::new(0.0, 0.0, height), Vec3::new(0.0, 0.0, 1.0));
    let mut scene = OwnedScene::<Plain, _>::new(spheres, domain, 1e-4, [floor]).unwrap();
    let m = scene.spheres()[0].mass;
    let plain_table = MaterialTable::<Plain, 1>::uniform(law);
    let input = StepInput {
        table: &plain_table,
        gravity: Vec3::new(0.0, 0.0, -9.81),
        time_step: law.time_step(4e-6, m / 2.0).unwrap(),
        integrator: Integrator::SymplecticEuler,
    };
    let (lx, ly) = (domain.upper.x, domain.upper.y);
    let (mut pairs_seen, mut sliding_seen, mut walls_seen) = (0, 0, 0);
    for _ in 0..200 {
        let before = scene.spheres().to_vec();
        let mut stats = StepStats::default();
        scene.run(&input, 1, |_, s| stats = *s).unwrap();
        let mut expected = StepStats::<f64>::default();
        let mut exact_overlaps = 0.0;
        for a in 0..before.len() {
            for b in a + 1..before.len() {
                let mut d = before[b].position - before[a].position;
                let shift = Vec3::new(-lx * (d.x / lx).round(), -ly * (d.y / ly).round(), 0.0);
                d += shift;
                let reach = before[a].radius + before[b].radius;
                if d.norm_squared() >= reach * reach {
                    continue;
                }
                let image = before[b].translated(shift).unwrap();
                let contact = law.sphere_sphere(&before[a], &image, &mut (), input.time_step);
                let Ok(Interaction::Touching(c)) = contact else {
                    panic!("pair ({a}, {b}) overlaps: {contact:?}");
                };
                expected.pair_contacts += 1;
                expected.sliding_contacts += usize::from(c.sliding);
                exact_overlaps += reach - d.norm_squared().sqrt();
            }
        }
        expected.wall_contacts = before
            .iter()
            .filter(|s| s.position.z - height < s.radius)
            .count();
        // Sliding counts the walls' contacts too.
        for sphere in &before {
            let contact = law.sphere_wall(sphere, &floor.wall, &mut (), input.time_step);
            if let Ok(Interaction::Touching(c)) = contact {
                expected.sliding_contacts += usize::from(c.sliding);
            }
        }
        assert_eq!(
            (
                stats.pair_contacts,
                stats.sliding_contacts,
                stats.wall_contacts
            ),
            (
                expected.pair_contacts,
                expected.sliding_contacts,
                expected.wall_contacts
            )
        );
        assert!(
            (stats.overlap_sum - exact_overlaps).abs() <= 1e-9 * exact_overlaps,
            "overlap sum {} against {exact_overlaps}",
            stats.overlap_sum
        );
        pairs_seen += stats.pair_contacts;
        sliding_seen += stats.sliding_contacts;
        walls_seen += stats.wall_contacts;
    }
    // The run had all three kinds, and sticking pairs too.
    assert!(
        walls_seen > 0 && sliding_seen > 0 && pairs_seen > sliding_seen,
        "{walls_seen} wall, {sliding_seen} sliding, {pairs_seen} pair contacts"
    );
}

#[test]
fn the_list_is_rebuilt_when_a_sphere_has_moved_half_the_skin_or_crossed_the_box() {
    let law = table();
    let skin = 1e-4;
    // One sphere drifting in x at 1.1e-6 m a step, one at rest far from it: after 46 steps
    // it has moved 5.06e-5 m, past half the skin (5e-5 m), after 45 only 4.95e-5 m.
    let spheres = |x: f64| {
        let mut moving = Sphere::solid(Vec3::new(x, 1e-3, 1e-3), DIAMETER / 2.0, 2500.0);
        moving.velocity = Vec3::new(0.55, 0.0, 0.0);
        let resting = Sphere::solid(Vec3::new(3e-3, 4e-3, 4e-3), DIAMETER / 2.0, 2500.0);
        vec![moving, resting]
    };
    let builds = |x: f64, skin: f64, steps: usize, integrator| {
        let mass = spheres(x)[0].mass;
        let input = input(&law, (Vec3::ZERO, 2e-6, mass), integrator);
        let mut scene =
            OwnedScene::<Linear, _>::new(spheres(x), open_box(), skin, NoWalls).unwrap();
        scene.run(&input, steps, |_, _| {}).unwrap();
        scene.list_builds()
    };
    // Symplectic Euler evaluates before it moves, so the 47th step's evaluation sees the 46th
    // step's motion; velocity Verlet moves first, so its 46th step does.
    // Without a skin, any motion is too much: a build at every evaluation after a move (velocity
    // Verlet's first evaluation comes before any).
    for (integrator, last_quiet, every_step) in [
        (Integrator::SymplecticEuler, 46, 10),
        (Integrator::VelocityVerlet, 45, 11),
    ] {
        assert_eq!(
            builds(1e-3, skin, last_quiet, integrator),
            1,
            "{integrator:?}"
        );
        assert_eq!(
            builds(1e-3, skin, last_quiet + 1, integrator),
            2,
            "{integrator:?}"
        );
        assert_eq!(
            builds(1e-3, 0.0, 10, integrator),
            every_step,
            "{integrator:?}"
        );
        // Crossing the periodic boundary in x at the 10th step stales the list at once.
        let near_edge = open_box().upper.x - 9.5 * 1.1e-6;
        assert_eq!(
            builds(near_edge, skin, last_quiet, integrator),
            2,
            "{integrator:?}"
        );
    }
}

#[test]
fn buffer_sizes_follow_the_documented_counts_and_bad_domains_are_refused() {
    type Plain = LinearStateless<f64>;
    // Cells at least 1.1 mm on a side in a 6 mm box: 5 x 5 x 5.
    let reach = (DIAMETER, 1e-4);
    let stored =
        Scene::<Linear, [MaterialWall<f64>; 2], 4>::buffer_sizes(&open_box(), reach, 7, 40, true);
    assert_eq!(
        stored,
        Ok(soft_sphere_scene::BufferSizes {
            cells: 125 + 1 + 7,
            pairs: 40,
            vectors: 40 + 3 * 7,
            // The list's states and two per sphere (one per wall), double-buffered.
            states: 2 * (40 + 7 * 2),
            parking: 7,
            records: 40 + 7 * 2,
            // One per list place, for the pairs spread over threads.
            loads: 40,
        })
    );
    // A law that stores nothing needs no parking; a scene without records no records.
    let plain =
        Scene::<Plain, [MaterialWall<f64>; 2], 4>::buffer_sizes(&open_box(), reach, 7, 40, false);
    let plain = plain.unwrap();
    assert_eq!((plain.parking, plain.records), (0, 0));

    // A periodic direction needs 3 cells (the half shell would visit a pair twice); a closed
    // one does with fewer.
    let mut narrow = open_box();
    narrow.upper.x = 3.0e-3; // 2 cells of 1.5 mm
    let sizes = |domain: &Domain<f64>| {
        Scene::<Linear, NoWalls, 4>::buffer_sizes(domain, reach, 2, 4, false).map(|s| s.cells)
    };
    assert_eq!(sizes(&narrow), Err(SceneError::Domain));
    narrow.periodic_x = false;
    assert_eq!(sizes(&narrow), Ok(2 * 5 * 5 + 1 + 2));
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let mut domain = open_box();
        domain.upper.z = bad;
        assert_eq!(sizes(&domain), Err(SceneError::Domain), "height {bad}");
    }
    // More cells than a scene can hold (a 1 m box cut into 10 um cells, 1e15 of them, each axis
    // below the per-axis bound): refused with the count, before anything is allocated (the
    // owned scene aborted the process asking for 3e15 bytes).
    let unit = Domain {
        lower: Vec3::ZERO,
        upper: Vec3::new(1.0, 1.0, 1.0),
        periodic_x: true,
        periodic_y: true,
    };
    let tiny = Scene::<Linear, NoWalls, 4>::buffer_sizes(&unit, (1e-5, 0.0), 2, 4, false);
    match tiny {
        Err(SceneError::TooManyCells { cells }) => assert!(cells >= 99_999u64.pow(3)),
        other => panic!("expected TooManyCells, got {other:?}"),
    }
    let owned = OwnedScene::<Linear, NoWalls>::new(
        vec![Sphere::solid(Vec3::new(0.5, 0.5, 0.5), 5e-6, 2500.0)],
        unit,
        0.0,
        NoWalls,
    );
    assert!(matches!(owned.err(), Some(SceneError::TooManyCells { .. })));
    assert!(
        SceneError::TooManyCells { cells: 1 << 50 }
            .to_string()
            .contains("cells")
    );
    // A negative or non-finite skin.
    for skin in [-1e-4, f64::NAN, f64::INFINITY] {
        let mut spheres = checked_pair();
        let mut b = pair_buffers(0);
        let (materials, buffers) = b.buffers();
        let scene = Scene::<Linear, _, 4>::new(
            open_box(),
            (DIAMETER, skin),
            (&mut spheres, materials),
            buffers,
            NoWalls,
        );
        assert_eq!(scene.err(), Some(SceneError::Domain), "skin {skin}");
    }
}

#[test]
fn integrators_have_distinct_file_name_safe_names() {
    let names = Integrator::ALL.map(Integrator::name);
    assert_ne!(names[0], names[1]);
    for name in names {
        assert!(!name.is_empty() && name.bytes().all(|b| b.is_ascii_lowercase() || b == b'_'));
    }
}

#[test]
fn a_wall_moved_between_steps_pushes_the_sphere_it_reaches() {
    let law = table();
    let mut spheres = checked_pair();
    let mass = spheres[0].mass;
    let input = input(&law, (Vec3::ZERO, 2e-6, mass), Integrator::SymplecticEuler);
    // A wall facing +x, 0.1 mm beyond sphere 0's left side (sphere 1 is far in front of it).
    let left = spheres[0].position.x - spheres[0].radius;
    let wall = wall(Vec3::new(left - 1e-4, 0.0, 0.0), Vec3::new(1.0, 0.0, 0.0));
    let mut b = pair_buffers(1);
    let (materials, buffers) = b.buffers();
    let mut scene = Scene::<Linear, _, 4>::new(
        open_box(),
        (DIAMETER, 0.0),
        (&mut spheres, materials),
        buffers,
        [wall],
    )
    .unwrap();
    assert_eq!(scene.step(&input).unwrap().wall_contacts, 0);
    // Moved 0.2 mm toward the sphere: it now overlaps sphere 0 by about 0.1 mm.
    let moved = scene.walls()[0]
        .wall
        .moved_to(Vec3::new(left + 1e-4, 0.0, 0.0))
        .unwrap();
    scene.walls_mut()[0].wall = moved;
    assert_eq!(scene.walls()[0].wall.point(), moved.point());
    assert_eq!(scene.step(&input).unwrap().wall_contacts, 1);
    let (force, _) = scene.load(0).unwrap();
    assert!(force.x > 0.0, "the wall pushes sphere 0 in +x: {force:?}");
    assert_eq!(scene.load(1).unwrap().0, Vec3::ZERO);
}

#[test]
fn a_sphere_in_free_fall_follows_each_integrators_closed_form() {
    let law = table();
    let g = 9.81;
    let (dt, steps) = (2e-6, 500);
    for integrator in Integrator::ALL {
        let mut sphere = Sphere::solid(Vec3::new(3e-3, 3e-3, 3e-3), DIAMETER / 2.0, 2500.0);
        sphere.velocity = Vec3::new(0.0, 0.0, 0.3);
        let mass = sphere.mass;
        let far = Sphere::solid(Vec3::new(0.5e-3, 0.5e-3, 0.5e-3), DIAMETER / 2.0, 2500.0);
        let mut scene =
            OwnedScene::<Linear, _>::new(vec![sphere, far], open_box(), 1e-4, NoWalls).unwrap();
        let input = input(&law, (Vec3::new(0.0, 0.0, -g), dt, mass), integrator);
        scene.run(&input, steps, |_, _| {}).unwrap();
        let moved = scene
            .spheres()
            .iter()
            .find(|s| s.position.x > 1e-3)
            .unwrap();
        // Velocity Verlet is exact under a constant force; symplectic Euler kicks first, so it
        // falls g dt^2 n / 2 further.
        let (n, v0) = (steps as f64, 0.3);
        let t = n * dt;
        let exact = 3e-3 + v0 * t - 0.5 * g * t * t;
        let expected = match integrator {
            Integrator::VelocityVerlet => exact,
            Integrator::SymplecticEuler => exact - 0.5 * g * dt * dt * n,
        };
        assert!(
            (moved.position.z - expected).abs() < 1e-15,
            "{integrator:?}: {} against {expected}",
            moved.position.z
        );
        assert!(
            (moved.velocity.z - (v0 - g * t)).abs() < 1e-12,
            "{integrator:?}"
        );
    }
}

#[test]
fn a_diverging_sphere_is_named_by_its_index_whichever_thread_moved_it() {
    let law = table();
    let (spheres, domain) = gas(1000, 7);
    let mut scene = OwnedScene::<Linear, _>::new(spheres, domain, 1e-4, NoWalls).unwrap();
    let m = scene.spheres()[0].mass;
    // Far into the second half of the spheres, which a second thread advances.
    scene.spheres_mut()[900]
        .update(|s| s.velocity.x = f64::MAX)
        .unwrap();
    let input = input(
        &law,
        (Vec3::new(1e300, 0.0, 0.0), 2e-6, m),
        Integrator::SymplecticEuler,
    );
    let pool = Threads::new(2).unwrap();
    let outcome = scene.run_on(&input, 1, &pool, |_, _| {});
    assert_eq!(outcome, Err(StepError::Diverged { index: 900 }));
    // The owned scene remembers it: no later run steps again.
    assert_eq!(scene.run(&input, 1, |_, _| {}), Err(StepError::Halted));
    assert_eq!(scene.scene(|_| ()), Err(StepError::Halted));
}

/// A box of side 2^-7 m centred on the origin, periodic in x and y, and a sphere in it moving at
/// `speed` in x, stepped at 2^-19 s: each step moves it by exactly 2^-20 m, so positions are
/// exact and ties can be reached on purpose. A second sphere rests far from it.
fn exact_motion(speed: f64, start_x: f64) -> (OwnedScene<Linear, NoWalls>, StepInputParts) {
    let half = 2f64.powi(-8);
    let domain = Domain {
        lower: Vec3::new(-half, -half, -half),
        upper: Vec3::new(half, half, half),
        periodic_x: true,
        periodic_y: true,
    };
    let mut moving = Sphere::solid(Vec3::new(start_x, 0.0, 0.0), DIAMETER / 2.0, 2500.0);
    moving.velocity = Vec3::new(speed, 0.0, 0.0);
    let resting = Sphere::solid(Vec3::new(0.0, 2.5e-3, 2.5e-3), DIAMETER / 2.0, 2500.0);
    let mass = moving.mass;
    let scene = OwnedScene::new(vec![moving, resting], domain, 2f64.powi(-13), NoWalls).unwrap();
    (scene, (2f64.powi(-19), mass))
}

/// The step and the sphere mass of [`exact_motion`].
type StepInputParts = (f64, f64);

#[test]
fn the_box_is_half_open_and_the_skin_test_strict() {
    let law = table();
    let step = 2f64.powi(-20);
    let lower = -(2f64.powi(-8));
    let moving = |scene: &OwnedScene<Linear, NoWalls>| {
        scene
            .spheres()
            .iter()
            .find(|s| s.velocity.x != 0.0)
            .unwrap()
            .position
            .x
    };
    // Moving down to the lower face: a sphere on it stays there; one step on it wraps to just
    // below the upper face.
    let (mut scene, (dt, mass)) = exact_motion(-0.5, lower + 1024.0 * step);
    let down = input(&law, (Vec3::ZERO, dt, mass), Integrator::SymplecticEuler);
    scene.run(&down, 1024, |_, _| {}).unwrap();
    assert_eq!(moving(&scene), lower);
    scene.run(&down, 1, |_, _| {}).unwrap();
    assert_eq!(moving(&scene), -lower - step);
    // The list is rebuilt when a sphere has moved more than half the skin (2^-14 m, 64 steps):
    // after exactly half it is not.
    let builds = |steps: usize| {
        let (mut scene, (dt, mass)) = exact_motion(0.5, 0.0);
        let input = input(&law, (Vec3::ZERO, dt, mass), Integrator::SymplecticEuler);
        scene.run(&input, steps, |_, _| {}).unwrap();
        scene.list_builds()
    };
    assert_eq!((builds(65), builds(66)), (1, 2));
}

#[test]
fn threads_keep_every_spheres_wall_history() {
    // A monolayer sliding on the floor: every sphere, in every thread's stretch, has a stored
    // wall spring, and two threads must give the serial bits.
    let law = table();
    let (side, spacing) = (32, 1.2 * DIAMETER);
    let width = side as f64 * spacing;
    let domain = Domain {
        lower: Vec3::ZERO,
        upper: Vec3::new(width, width, 3e-3),
        periodic_x: true,
        periodic_y: true,
    };
    let mut random = Xorshift::new(21);
    let mut spheres = Vec::new();
    for k in 0..side * side {
        let (x, y) = ((k % side) as f64 + 0.5, (k / side) as f64 + 0.5);
        let mut s = Sphere::solid(
            Vec3::new(x * spacing, y * spacing, 0.5e-3 - 2e-8),
            DIAMETER / 2.0,
            2500.0,
        );
        // Slow enough that the floor contacts stick: their springs carry the history.
        s.velocity = Vec3::new(random.unit() - 0.5, random.unit() - 0.5, 0.0) * 2e-4;
        s.angular_velocity = Vec3::new(random.unit() - 0.5, random.unit() - 0.5, 0.0) * 0.2;
        spheres.push(s);
    }
    // Two walls (a ceiling nobody reaches), so each sphere owns two wall states.
    let walls = [
        wall(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)),
        wall(Vec3::new(0.0, 0.0, 3e-3), Vec3::new(0.0, 0.0, -1.0)),
    ];
    let m = spheres[0].mass;
    let input = input(
        &law,
        (Vec3::new(0.0, 0.0, -9.81), 4e-6, m),
        Integrator::SymplecticEuler,
    );
    // Serial (one stretch) against two threads (two stretches of the wall states).
    let run = |threads: Option<usize>| {
        let mut scene = OwnedScene::<Linear, _>::new(spheres.clone(), domain, 1e-4, walls).unwrap();
        let mut on_floor = 0;
        let record = |_: usize, s: &StepStats<f64>| on_floor = s.wall_contacts;
        match threads {
            None => scene.run(&input, 200, record).unwrap(),
            Some(n) => scene
                .run_on(&input, 200, &Threads::new(n).unwrap(), record)
                .unwrap(),
        }
        (motion_bits(scene.spheres()), on_floor)
    };
    let (serial, on_floor) = run(None);
    assert_eq!(on_floor, side * side, "every sphere touches the floor");
    assert_eq!(run(Some(2)).0, serial);
}

#[test]
fn a_threaded_step_over_caller_buffers_gives_the_bits_of_one_thread() {
    let law = table();
    let mass = oblique_pair()[0].mass;
    let input = input(&law, (Vec3::ZERO, 2e-6, mass), Integrator::SymplecticEuler);
    let pool = Threads::new(2).unwrap();
    let mut serial = trio((0, 1.0));
    VecBuffers::<4>::new(3, 4, 0).run(&input, &mut serial, 80);
    let mut threaded = trio((0, 1.0));
    let mut b = VecBuffers::<4>::new(3, 4, 0);
    let (materials, buffers) = b.buffers();
    let mut scene = Scene::new(
        open_box(),
        (DIAMETER, 0.0),
        (&mut threaded, materials),
        buffers,
        NoWalls,
    )
    .unwrap();
    let touching = (0..80)
        .map(|_| scene.step_on(&input, &pool).unwrap().pair_contacts)
        .max();
    assert_eq!(touching, Some(2), "both pairs touched at once");
    drop(scene);
    assert_eq!(motion_bits(&threaded), motion_bits(&serial));
}

#[test]
fn each_sphere_keeps_its_own_spring_on_each_wall() {
    // Three spheres sliding slowly on the floor, the middle one also against a side wall: the
    // scene against the contact law applied to each sphere and wall with its own stored state.
    let law = table();
    let plain_law = self::law();
    let r = DIAMETER / 2.0;
    let sink = 2e-8;
    let mut spheres: Vec<Sphere<f64>> = (0..3)
        .map(|k| {
            let mut s = Sphere::solid(
                Vec3::new(1e-3 + 1.5e-3 * k as f64, 3e-3, r - sink),
                r,
                2500.0,
            );
            s.velocity = Vec3::new(1e-4 * (k as f64 + 1.0), 0.0, 0.0);
            s
        })
        .collect();
    let walls = [
        wall(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)),
        wall(
            Vec3::new(0.0, 3e-3 + r - sink, 0.0),
            Vec3::new(0.0, -1.0, 0.0),
        ),
    ];
    // The side wall touches every sphere: move the outer two away from it in y.
    spheres[0].position.y -= 1e-4;
    spheres[2].position.y -= 1e-4;
    // Gravity presses the spheres onto the floor and the middle one onto the side wall, each
    // a little past its static overlap, so that every contact lasts the run.
    let gravity = Vec3::new(0.0, 4.9, -9.81);
    let input = input(
        &law,
        (gravity, 2e-6, spheres[0].mass),
        Integrator::SymplecticEuler,
    );
    let steps = 300;

    let mut direct = spheres.clone();
    let mut states = [[SpringDisplacement::default(); 2]; 3];
    let mut touching = [[0; 2]; 3];
    for _ in 0..steps {
        for (s, sphere) in direct.iter_mut().enumerate() {
            let (mut force, mut torque) = (Vec3::ZERO, Vec3::ZERO);
            for (k, wall) in walls.iter().enumerate() {
                let contact =
                    plain_law.sphere_wall(sphere, &wall.wall, &mut states[s][k], input.time_step);
                if let Interaction::Touching(c) = contact.unwrap() {
                    force += c.force_on_i();
                    torque += c.torque_on_i;
                    touching[s][k] += 1;
                }
            }
            advance_solid_sphere(
                sphere,
                force + gravity * sphere.mass,
                torque,
                input.time_step,
            );
        }
    }
    // Every sphere stayed on the floor, only the middle one met the side wall, most of the run.
    assert_eq!(touching.map(|t| t[0]), [steps; 3]);
    assert!(touching[1][1] > steps / 2 && touching[0][1] == 0 && touching[2][1] == 0);

    let mut checked: Vec<CheckedSphere<f64>> = spheres
        .into_iter()
        .map(|s| CheckedSphere::new(s).unwrap())
        .collect();
    // Three spheres, two walls: six wall states.
    let mut b = VecBuffers::<4>::new(3, 8, 2);
    let (materials, buffers) = b.buffers();
    let mut scene = Scene::<Linear, _, 4>::new(
        open_box(),
        (DIAMETER, 0.0),
        (&mut checked, materials),
        buffers,
        walls,
    )
    .unwrap();
    for _ in 0..steps {
        scene.step(&input).unwrap();
    }
    drop(scene);
    let direct: Vec<CheckedSphere<f64>> = direct
        .into_iter()
        .map(|s| CheckedSphere::new(s).unwrap())
        .collect();
    assert_eq!(motion_bits(&checked), motion_bits(&direct));
}

/// The scene's steps go through the kernel's per-contact stability check: a wall law stiffer
/// than the step was checked for, and a step checked against a sphere's mass instead of the
/// pair's, stop the scene with `PastStableStep` at the first such contact (tolerated, the same
/// scene gains energy: spheres rise above where they fell from).
#[test]
fn contacts_stiffer_than_the_step_stop_the_scene() {
    let pair_law = law();
    let wall_law = ContactLaw::new(
        LinearSpringDashpot::new(1.0e6, 0.9).unwrap(),
        ModelAA(TangentialParameters::new(2.857e5, 0.5, 0.5).unwrap()),
    );
    // Spheres of material 0, the floor of material 1.
    let table = pair_and_wall(pair_law, wall_law);
    let floor = [wall_of(
        Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap(),
        1,
    )];
    let gravity = Vec3::new(0.0, 0.0, -9.81);
    let (spheres, domain) = gas(60, 5);
    let m = Sphere::solid(Vec3::ZERO, DIAMETER / 2.0, 2500.0).mass;
    let checked_for_pairs = pair_law
        .coarse_time_step(0.5 * pair_law.critical_time_step(m / 2.0), m / 2.0)
        .unwrap();
    // Kinetic plus gravitational energy.
    let energy = |scene: &OwnedScene<Linear, [MaterialWall<f64>; 1]>| {
        let height: f64 = scene
            .spheres()
            .iter()
            .map(|s| s.mass * 9.81 * s.position.z)
            .sum();
        scene.kinetic_energy() + height
    };
    for tolerate in [false, true] {
        let time_step = if tolerate {
            checked_for_pairs.tolerating_unstable_contacts()
        } else {
            checked_for_pairs
        };
        let input = StepInput {
            table: &table,
            gravity,
            time_step,
            integrator: Integrator::SymplecticEuler,
        };
        let mut scene = OwnedScene::<Linear, _>::new(spheres.clone(), domain, 1e-4, floor).unwrap();
        let start = energy(&scene);
        let mut walls_touched = 0;
        let outcome = scene.run(&input, 20_000, |_, stats| {
            walls_touched += stats.wall_contacts
        });
        if tolerate {
            // Evaluated, the floor's unstable contacts create energy.
            assert!(walls_touched > 0);
            let end = energy(&scene);
            assert!(
                outcome.is_err() || end > 2.0 * start,
                "{outcome:?}: {start} J -> {end} J"
            );
        } else {
            assert!(
                matches!(
                    outcome,
                    Err(StepError::Wall {
                        wall: 0,
                        error: ContactError::PastStableStep,
                        ..
                    })
                ),
                "{outcome:?}"
            );
            assert_eq!(walls_touched, 0, "refused at the first floor contact");
            assert!(energy(&scene) < start * (1.0 + 1e-6), "no energy appeared");
        }
    }
    // A step checked against one sphere's mass, for pairs of two: refused at the first
    // touching pair (the gas has overlapping neighbours from its first step).
    let input = StepInput {
        table: &table,
        gravity,
        time_step: pair_law
            .coarse_time_step(0.99 * pair_law.critical_time_step(m), m)
            .unwrap(),
        integrator: Integrator::SymplecticEuler,
    };
    let mut scene = OwnedScene::<Linear, _>::new(spheres.clone(), domain, 1e-4, floor).unwrap();
    let outcome = scene.run(&input, 2_000, |_, _| {});
    assert!(
        matches!(
            outcome,
            Err(StepError::Pair {
                error: ContactError::PastStableStep,
                ..
            })
        ),
        "{outcome:?}"
    );
    // The scene's own check of the step, from the spheres and walls present, refuses both
    // before a step is taken: the floor's law at a sphere's mass, then (with the floor's law
    // relaxed) the pairs' law at half a sphere's mass.
    let mut scene = OwnedScene::<Linear, _>::new(spheres, domain, 1e-4, floor).unwrap();
    let checked = |scene: &mut OwnedScene<Linear, _>, table: &MaterialTable<Linear, 2>, dt| {
        scene.scene(|s| s.coarse_time_step(table, dt)).unwrap()
    };
    let refused = checked(&mut scene, &table, checked_for_pairs.seconds());
    assert!(
        matches!(
            refused,
            Err(StepError::TimeStep {
                materials: [0, 1],
                ..
            })
        ),
        "{refused:?}"
    );
    let same = pair_and_wall(pair_law, pair_law);
    let pair_limit = pair_law.critical_time_step(m / 2.0);
    assert!(checked(&mut scene, &same, 0.99 * pair_limit).is_ok());
    let refused = checked(&mut scene, &same, 1.01 * pair_limit);
    assert!(
        matches!(
            refused,
            Err(StepError::TimeStep {
                materials: [0, 0],
                ..
            })
        ),
        "{refused:?}"
    );
}

#[test]
fn a_large_sphere_among_many_small_ones_goes_on_with_a_larger_parking() {
    // A 4 mm sphere touched by 40 of 0.5 mm: past the owned scene's 16 parked contacts at the
    // second call's list rebuild. It stopped with ParkingFull and no way to go on.
    let mut big = Sphere::solid(Vec3::new(0.01, 0.01, 0.01), 4.0e-3, 2500.0);
    // Spinning, so that every contact's tangential spring is loaded (a relaxed one is not kept).
    big.angular_velocity = Vec3::new(0.3, 0.5, 1.0) * 100.0;
    let mut spheres = vec![big];
    let count = 40;
    let golden = std::f64::consts::PI * (3.0 - 5.0f64.sqrt());
    for k in 0..count {
        let z = 1.0 - 2.0 * (k as f64 + 0.5) / count as f64;
        let (r, phi) = ((1.0 - z * z).sqrt(), golden * k as f64);
        let direction = Vec3::new(r * phi.cos(), r * phi.sin(), z);
        let centre = big.position + direction * (4.5e-3 - 1.0e-6);
        spheres.push(Sphere::solid(centre, 0.5e-3, 2500.0));
    }
    let domain = Domain {
        lower: Vec3::ZERO,
        upper: Vec3::new(0.02, 0.02, 0.02),
        periodic_x: false,
        periodic_y: false,
    };
    let law = table();
    let small = spheres[1].mass;
    let step = |scene: &mut OwnedScene<Linear, NoWalls>| {
        let input = input(&law, (Vec3::ZERO, 1e-7, small), Integrator::SymplecticEuler);
        scene.run(&input, 1, |_, _| {})
    };
    let mut scene = OwnedScene::<Linear, _>::new(spheres.clone(), domain, 1e-4, NoWalls).unwrap();
    assert_eq!(step(&mut scene), Ok(()));
    assert_eq!(step(&mut scene), Err(StepError::ParkingFull));
    assert!(StepError::ParkingFull.to_string().contains("with_parking"));
    // With room for 64, the same scene goes on, its history kept: the same bits as a scene
    // built with that room.
    let mut roomy = scene.with_parking::<64>();
    let mut reference = OwnedScene::<Linear, _>::new(spheres, domain, 1e-4, NoWalls)
        .unwrap()
        .with_parking::<64>();
    let input = input(&law, (Vec3::ZERO, 1e-7, small), Integrator::SymplecticEuler);
    reference.run(&input, 1, |_, _| {}).unwrap();
    for _ in 0..3 {
        roomy.run(&input, 1, |_, _| {}).unwrap();
        reference.run(&input, 1, |_, _| {}).unwrap();
    }
    assert_eq!(roomy.spheres(), reference.spheres());
}

#[test]
fn the_grid_is_sized_from_the_spheres_and_spheres_outside_the_box_are_refused() {
    // Two 4 mm spheres declared as 1 mm met at 0.5 m/s and left at 2.11 m/s each: the owned
    // scene now sizes its cells from the spheres, and they leave no faster than they came.
    let pair = |radius: f64| {
        let mut a = Sphere::solid(Vec3::new(2.0e-3, 2.5e-3, 2.5e-3), radius, 2500.0);
        let mut b = Sphere::solid(
            Vec3::new(2.0e-3 + 2.0 * radius + 1e-4, 2.5e-3, 2.5e-3),
            radius,
            2500.0,
        );
        a.velocity.x = 0.25;
        b.velocity.x = -0.25;
        vec![a, b]
    };
    let closed = Domain {
        lower: Vec3::new(-0.02, 0.0, 0.0),
        upper: Vec3::new(0.03, 0.005, 0.005),
        periodic_x: false,
        periodic_y: false,
    };
    let built = |spheres: Vec<Sphere<f64>>| {
        OwnedScene::<Linear, NoWalls>::new(spheres, closed, 1e-4, NoWalls).err()
    };
    let law = table();
    let fastest_after = |scene: &mut OwnedScene<Linear, NoWalls>| {
        let mass = scene.spheres()[0].mass;
        let input = input(&law, (Vec3::ZERO, 2e-5, mass), Integrator::VelocityVerlet);
        scene.run(&input, 2000, |_, _| {}).unwrap();
        let speeds = scene
            .spheres()
            .iter()
            .map(|s| s.velocity.norm_squared().sqrt());
        speeds.fold(0.0, f64::max)
    };
    let mut large =
        OwnedScene::<Linear, NoWalls>::new(pair(2.0e-3), closed, 1e-4, NoWalls).unwrap();
    let after = fastest_after(&mut large);
    assert!(after > 0.0 && after <= 0.25, "left at {after} m/s");
    // Spheres grown between calls: the next call sizes the cells for them.
    let mut grown =
        OwnedScene::<Linear, NoWalls>::new(pair(0.5e-3), closed, 1e-4, NoWalls).unwrap();
    for (sphere, large) in grown.spheres_mut().iter_mut().zip(pair(2.0e-3)) {
        *sphere = CheckedSphere::new(large).unwrap();
    }
    let after = fastest_after(&mut grown);
    assert!(
        after > 0.0 && after <= 0.25,
        "grown spheres left at {after} m/s"
    );
    // A centre outside along a closed direction; along a periodic one it is the scene's to wrap.
    let mut outside = pair(0.5e-3);
    outside[1].position.z = -1e-3;
    assert_eq!(built(outside), Some(SceneError::Outside { index: 1 }));
    // With no sphere the cells are a quarter of the domain's shortest side: an empty scene
    // builds and steps in any valid domain, with any skin.
    let about_origin = Domain {
        lower: Vec3::new(-0.01, -0.01, -0.01),
        upper: Vec3::new(0.01, 0.01, 0.01),
        periodic_x: true,
        periodic_y: true,
    };
    let mut empty = OwnedScene::<Linear, NoWalls>::new(vec![], about_origin, 0.0, NoWalls).unwrap();
    let input = input(&law, (Vec3::ZERO, 1e-6, 1e-6), Integrator::SymplecticEuler);
    assert_eq!(empty.run(&input, 2, |_, _| {}), Ok(()));
    let mut past_x = pair(0.5e-3);
    past_x[1].position.x = 0.031;
    assert_eq!(built(past_x), Some(SceneError::Outside { index: 1 }));
    let mut beyond = pair(0.5e-3);
    beyond[0].position.y = 0.006;
    assert_eq!(
        built(beyond.clone()),
        Some(SceneError::Outside { index: 0 })
    );
    let periodic = Domain {
        periodic_y: true,
        ..closed
    };
    let wrapped = OwnedScene::<Linear, NoWalls>::new(beyond, periodic, 1e-4, NoWalls);
    assert!(wrapped.is_ok());
    // A scene over the caller's buffers has its cells sized by the diameter it was given, and
    // refuses a larger sphere.
    let mut buffers = pair_buffers(0);
    let (materials, parts) = buffers.buffers();
    let mut large = pair(2.0e-3)
        .into_iter()
        .map(|s| {
            CheckedSphere::new(Sphere {
                position: Vec3::new(s.position.x, 3e-3, 3e-3),
                ..s
            })
            .unwrap()
        })
        .collect::<Vec<_>>();
    let borrowed = Scene::<Linear, NoWalls, 4>::new(
        open_box(),
        (DIAMETER, 0.0),
        (&mut large[..], materials),
        parts,
        NoWalls,
    );
    assert_eq!(borrowed.err(), Some(SceneError::Diameter { index: 0 }));
    assert!(
        SceneError::Diameter { index: 3 }
            .to_string()
            .contains("sphere 3")
    );
    assert!(
        SceneError::Outside { index: 3 }
            .to_string()
            .contains("outside")
    );
}

#[test]
fn a_sphere_flying_out_of_the_box_is_named() {
    // Nothing above the spheres: the second flies up out of the closed z direction. It used to
    // fly on in the top cells, its contacts still computed.
    let resting = Sphere::solid(Vec3::new(3e-3, 3e-3, 1e-3), DIAMETER / 2.0, 2500.0);
    let mut rising = Sphere::solid(Vec3::new(1e-3, 1e-3, 3e-3), DIAMETER / 2.0, 2500.0);
    rising.velocity.z = 1.0;
    let mut scene =
        OwnedScene::<Linear, _>::new(vec![resting, rising], open_box(), 1e-4, NoWalls).unwrap();
    let law = table();
    let input = input(
        &law,
        (Vec3::ZERO, 1e-6, resting.mass),
        Integrator::SymplecticEuler,
    );
    let mut steps = 0;
    let outcome = scene.run(&input, 4000, |_, _| steps += 1);
    assert_eq!(outcome, Err(StepError::Outside { index: 1 }));
    // Found within half a skin of the top, after about 3 mm at 1 µm a step.
    let z = scene.spheres()[1].position.z;
    assert!(z > 6e-3 && z <= 6e-3 + 0.5e-4 + 1e-6, "found at {z}");
    assert!((3000..=3051).contains(&steps), "{steps} steps");
    // Refused again, when the owned scene is built for the next call, until it is back
    // inside; then the scene steps on.
    assert_eq!(
        scene.run(&input, 1, |_, _| {}),
        Err(StepError::Scene(SceneError::Outside { index: 1 }))
    );
    scene.spheres_mut()[1]
        .update(|s| s.position.z = 5e-3)
        .unwrap();
    assert_eq!(scene.run(&input, 1, |_, _| {}), Ok(()));
    assert!(
        StepError::Outside { index: 1 }
            .to_string()
            .contains("sphere 1")
    );
}
