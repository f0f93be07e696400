//! The material table and the list seam: mixing rules against their closed forms, a whole
//! contact list of a mixture giving the one-contact path's bits pair by pair, every bad input
//! refused with its error and nothing changed, and the step checked against the spheres present.

use host_tests::impact::floor;
use host_tests::random::Xorshift;
use host_tests::scene::Threads;
use host_tests::seam::{evaluate_swapping, evaluate_swapping_on};
use proptest::prelude::*;
use soft_sphere::executor::{Executor, Serial};
use soft_sphere::prelude::{
    CheckedPairs, ContactError, ContactList, ElasticMaterial, HertzImpact, HertzMixing,
    Interaction, Law, LinearAA, LinearMaterial, LinearMixing, ListArray, ListError, ListOutput,
    ListStats, Material, MaterialTable, MaterialWall, MindlinAA, Mixing, ModelAA, ModelC, PairLoad,
    Parameter, ParameterError, SphereArrays, Spheres, SpringDisplacement, TableError, Vec3, Wall,
    effective_mass,
};

type Linear = LinearAA<f64>;
type State = SpringDisplacement<f64>;

fn glass() -> LinearMaterial<f64> {
    LinearMaterial {
        normal_stiffness: 1.0e4,
        restitution: 0.9,
        tangential_stiffness: 8.0e3,
        dashpot_ratio: 0.5,
        friction: 0.4,
    }
}

fn rubber() -> LinearMaterial<f64> {
    LinearMaterial {
        normal_stiffness: 4.0e2,
        restitution: 0.4,
        tangential_stiffness: 3.0e2,
        dashpot_ratio: 0.2,
        friction: 0.9,
    }
}

/// Glass, rubber, and a stiff floor material.
fn table() -> MaterialTable<Linear, 3> {
    MaterialTable::mixed(&LinearMixing::new(ModelAA), &[glass(), rubber(), steel()]).unwrap()
}

fn steel() -> LinearMaterial<f64> {
    LinearMaterial {
        normal_stiffness: 1.0e6,
        friction: 0.2,
        ..glass()
    }
}

#[test]
fn linear_mixing_takes_geometric_means_and_keeps_a_material_against_itself() {
    let t = table();
    let (g, r) = (glass(), rubber());
    let mixed = t.law(0, 1).unwrap();
    let close = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-15;
    assert!(close(
        mixed.normal().stiffness(),
        (g.normal_stiffness * r.normal_stiffness).sqrt()
    ));
    assert!(close(mixed.normal().restitution(), (0.9_f64 * 0.4).sqrt()));
    let p = mixed.tangential().0;
    assert!(close(p.stiffness(), (8.0e3_f64 * 3.0e2).sqrt()));
    assert!(close(p.dashpot_ratio(), (0.5_f64 * 0.2).sqrt()));
    assert!(close(p.friction(), (0.4_f64 * 0.9).sqrt()));
    // Symmetric, and a material against itself is that material exactly.
    assert_eq!(format!("{:?}", t.law(1, 0)), format!("{:?}", t.law(0, 1)));
    let own = t.law(1, 1).unwrap();
    assert_eq!(own.normal().stiffness(), r.normal_stiffness);
    assert_eq!(own.normal().restitution(), r.restitution);
    assert_eq!(own.tangential().0.friction(), r.friction);
    assert!(t.law(3, 0).is_none() && t.law(0, 3).is_none());
}

#[test]
fn hertz_mixing_follows_hertz_and_mindlin() {
    let steel = ElasticMaterial {
        elasticity: Material::new(208.0e9_f64, 0.3).unwrap(),
        restitution: 0.9,
        dashpot_ratio: 0.0,
        friction: 0.3,
    };
    let glass = ElasticMaterial {
        elasticity: Material::new(63.0e9, 0.2).unwrap(),
        restitution: 0.5,
        dashpot_ratio: 0.0,
        friction: 0.1,
    };
    let largest = HertzImpact {
        speed: 2.0,
        effective_radius: 1.0e-3,
    };
    let t = MaterialTable::mixed(&HertzMixing::new(largest, MindlinAA), &[steel, glass]).unwrap();
    let law = t.law(0, 1).unwrap();
    // 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2; 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2.
    let e_star = 1.0 / ((1.0 - 0.09) / 208.0e9 + (1.0 - 0.04) / 63.0e9);
    let g = |e: f64, nu: f64| e / (2.0 * (1.0 + nu));
    let g_star = 1.0 / ((2.0 - 0.3) / g(208.0e9, 0.3) + (2.0 - 0.2) / g(63.0e9, 0.2));
    assert!((law.normal().effective_modulus() / e_star - 1.0).abs() < 1e-14);
    assert!((law.normal().restitution() - (0.45_f64).sqrt()).abs() < 1e-15);
    assert!((law.tangential().0.shear_modulus() / g_star - 1.0).abs() < 1e-14);
    assert!((law.tangential().0.friction() - (0.03_f64).sqrt()).abs() < 1e-15);
    assert_eq!(law.normal().largest_impact(), largest);
}

#[test]
fn a_bad_material_or_pair_is_refused_with_its_place() {
    let bad = LinearMaterial {
        friction: -0.1,
        ..rubber()
    };
    let refused =
        MaterialTable::<Linear, 3>::mixed(&LinearMixing::new(ModelAA), &[glass(), glass(), bad]);
    assert_eq!(
        refused.unwrap_err(),
        TableError::Pair {
            materials: [2, 2],
            error: ParameterError::Negative(Parameter::Friction),
        }
    );
    let mut t = table();
    let before = format!("{t:?}");
    let other = LinearMixing::new(ModelAA).law(&glass(), &glass()).unwrap();
    assert_eq!(
        t.set(0, 3, other),
        Err(TableError::MaterialOutOfRange { material: 3 })
    );
    assert_eq!(format!("{t:?}"), before, "a refused set changes nothing");
    t.set(2, 1, other).unwrap();
    assert_eq!(format!("{:?}", t.law(1, 2)), format!("{:?}", Some(other)));
    assert_eq!(format!("{:?}", t.law(2, 1)), format!("{:?}", Some(other)));
}

/// A random mixture: spheres of two sizes and three materials in a box, jittered so that many
/// touch, with random velocities and spins.
#[derive(Clone, Debug)]
struct Mixture {
    position: Vec<Vec3<f64>>,
    velocity: Vec<Vec3<f64>>,
    angular_velocity: Vec<Vec3<f64>>,
    radius: Vec<f64>,
    mass: Vec<f64>,
    material: Vec<u32>,
    pairs: Vec<[u32; 2]>,
}

impl Mixture {
    fn new(count: usize, seed: u64) -> Self {
        let mut random = Xorshift::new(seed);
        let mut r = |scale: f64| scale * (2.0 * random.unit() - 1.0);
        let side = (count as f64).cbrt().ceil() as usize;
        let mut m = Self {
            position: Vec::new(),
            velocity: Vec::new(),
            angular_velocity: Vec::new(),
            radius: Vec::new(),
            mass: Vec::new(),
            material: Vec::new(),
            pairs: Vec::new(),
        };
        for k in 0..count {
            let (x, y, z) = (k % side, (k / side) % side, k / (side * side));
            let big = k % 3 == 0;
            let radius = if big { 1.2e-3 } else { 0.8e-3 };
            m.position.push(Vec3::new(
                1.9e-3 * x as f64 + r(2e-4),
                1.9e-3 * y as f64 + r(2e-4),
                1.9e-3 * z as f64 + 2.0e-3 + r(2e-4),
            ));
            m.velocity.push(Vec3::new(r(0.05), r(0.05), r(0.05)));
            m.angular_velocity
                .push(Vec3::new(r(20.0), r(20.0), r(20.0)));
            m.radius.push(radius);
            m.mass
                .push(2500.0 * 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3));
            m.material.push((k % 2) as u32 + u32::from(k % 5 == 0));
        }
        for i in 0..count {
            for j in i + 1..count {
                let d = m.position[j] - m.position[i];
                if d.norm_squared() < (3.0e-3_f64).powi(2) {
                    m.pairs.push([i as u32, j as u32]);
                }
            }
        }
        m
    }

    fn arrays(&self) -> SphereArrays<'_, f64> {
        SphereArrays {
            position: &self.position,
            velocity: &self.velocity,
            angular_velocity: &self.angular_velocity,
            radius: &self.radius,
            mass: &self.mass,
            material: &self.material,
        }
    }

    fn sphere(&self, k: usize) -> soft_sphere::prelude::Sphere<f64> {
        soft_sphere::prelude::Sphere {
            position: self.position[k],
            velocity: self.velocity[k],
            angular_velocity: self.angular_velocity[k],
            radius: self.radius[k],
            mass: self.mass[k],
        }
    }

    /// A symplectic Euler step under `force` and `torque` (solid spheres), no gravity.
    fn advance(&mut self, force: &[Vec3<f64>], torque: &[Vec3<f64>], dt: f64) {
        for k in 0..self.position.len() {
            let m = self.mass[k];
            self.velocity[k] += force[k] * (dt / m);
            let inertia = 0.4 * m * self.radius[k] * self.radius[k];
            self.angular_velocity[k] += torque[k] * (dt / inertia);
            self.position[k] += self.velocity[k] * dt;
        }
    }
}

/// The lightest mass among the spheres of `material` (infinite when there are none).
fn lightest_of(mass: &[f64], materials: &[u32], material: u32) -> f64 {
    mass.iter()
        .zip(materials)
        .filter(|(_, k)| **k == material)
        .map(|(&mass, _)| mass)
        .fold(f64::INFINITY, f64::min)
}

fn floor_of(material: u32) -> MaterialWall<f64> {
    MaterialWall {
        wall: floor(),
        material,
    }
}

/// Everything one evaluation changes, as text (Debug prints the shortest decimal that reads back
/// to the same float, so equal text is equal bits).
fn all_finite(v: &[Vec3<f64>]) -> bool {
    v.iter().all(|x| x.is_finite())
}

fn bits<T: std::fmt::Debug>(value: &T) -> String {
    format!("{value:?}")
}

/// One step's forces, torques and contact outcomes.
type Step = (Vec<Vec3<f64>>, Vec<Vec3<f64>>, Vec<Interaction<f64>>);

/// The same step one contact at a time through the public one-contact path, forces added in
/// list order.
fn one_at_a_time(
    table: &MaterialTable<Linear, 3>,
    m: &Mixture,
    walls: &[MaterialWall<f64>],
    dt: soft_sphere::prelude::TimeStep<f64>,
    (pair_states, wall_states): (&mut [State], &mut [State]),
) -> Result<Step, ContactError> {
    let n = m.position.len();
    let (mut force, mut torque) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    let mut outcomes = Vec::new();
    for (&[i, j], state) in m.pairs.iter().zip(pair_states.iter_mut()) {
        let (i, j) = (i as usize, j as usize);
        let law = table
            .law(m.material[i] as usize, m.material[j] as usize)
            .unwrap();
        let outcome = law.sphere_sphere(&m.sphere(i), &m.sphere(j), state, dt)?;
        if let Interaction::Touching(c) = outcome {
            force[i] -= c.force_on_j();
            torque[i] += c.torque_on_i;
            force[j] += c.force_on_j();
            torque[j] += c.torque_on_j;
        }
        outcomes.push(outcome);
    }
    for k in 0..n {
        for (w, wall) in walls.iter().enumerate() {
            let law = table
                .law(m.material[k] as usize, wall.material as usize)
                .unwrap();
            let state = &mut wall_states[k * walls.len() + w];
            let outcome = law.sphere_wall(&m.sphere(k), &wall.wall, state, dt)?;
            if let Interaction::Touching(c) = outcome {
                force[k] += c.force_on_i();
                torque[k] += c.torque_on_i;
            }
            outcomes.push(outcome);
        }
    }
    Ok((force, torque, outcomes))
}

#[test]
fn a_mixture_list_gives_the_one_contact_bits_step_after_step() {
    // A steel floor under the lowest layer and a rubber side wall through the first column:
    // both touched from the first step.
    let wall = |point: Vec3<f64>, normal: Vec3<f64>, material| MaterialWall {
        wall: Wall::new(point, normal).unwrap(),
        material,
    };
    let both = [
        wall(Vec3::new(0.0, 0.0, 1.0e-3), Vec3::new(0.0, 0.0, 1.0), 2),
        wall(Vec3::new(-0.6e-3, 0.0, 0.0), Vec3::new(1.0, 0.0, 0.0), 1),
    ];
    // A steel drum about the columns, turning (0.24 m/s at its surface), that the corner
    // columns' large spheres touch, on the floor.
    let axis = Vec3::new(2.85e-3, 2.85e-3, 0.0);
    let drum = Wall::cylinder(axis, Vec3::new(0.0, 0.0, 1.0), 4.8e-3)
        .and_then(|w| w.with_spin(50.0))
        .unwrap();
    // The floor turning too (a turntable about the vertical through the first column).
    let turntable = MaterialWall {
        wall: both[0].wall.with_spin(-30.0).unwrap(),
        ..both[0]
    };
    let turning = [
        MaterialWall {
            wall: drum,
            material: 2,
        },
        turntable,
    ];
    // Both walls, and the floor alone (the walls' sift reads one wall once); the drum and
    // the turntable, and the drum alone.
    mixture_bits(&both);
    mixture_bits(&both[..1]);
    mixture_bits(&turning);
    mixture_bits(&turning[..1]);
}

fn mixture_bits(walls: &[MaterialWall<f64>]) {
    let t = table();
    let mut m = Mixture::new(60, 7);
    let dt = t.coarse_time_step(2.0e-6, &m.arrays(), walls).unwrap();
    let n = m.position.len();
    let mut states = vec![State::default(); m.pairs.len()];
    // Every sphere starts with a spring against each wall: those apart from it relax it.
    let preload = |k: usize| State {
        displacement: Vec3::new(0.0, 1e-9 * k as f64, 0.0),
    };
    let mut wall_states: Vec<State> = (0..n * walls.len()).map(preload).collect();
    let (mut ref_states, mut ref_wall_states) = (states.clone(), wall_states.clone());
    let contacts = m.pairs.len() + n * walls.len();
    let mut records = vec![Interaction::Apart; contacts];
    let (mut touching, mut mixed, mut sliding) = (0, 0, 0);
    let (mut on_walls, mut inaccurate) = (0, 0);
    let mut each_wall = vec![0; walls.len()];
    // Whatever the force arrays held: the seam writes them.
    let (mut force, mut torque) = (vec![Vec3::new(1.0, 2.0, 3.0); n], vec![Vec3::ZERO; n]);
    for step in 0..200 {
        let stats = evaluate_swapping(
            &t,
            dt,
            &m.arrays(),
            (
                (CheckedPairs::new(&m.pairs, &[], n).unwrap(), walls),
                (&mut states, &mut wall_states),
            ),
            (&mut force, &mut torque),
            Some(&mut records),
        )
        .unwrap();
        let (ref_force, ref_torque, outcomes) =
            one_at_a_time(&t, &m, walls, dt, (&mut ref_states, &mut ref_wall_states)).unwrap();
        assert_eq!(bits(&force), bits(&ref_force), "step {step}: forces");
        assert_eq!(bits(&torque), bits(&ref_torque), "step {step}: torques");
        assert_eq!(bits(&states), bits(&ref_states), "step {step}: states");
        assert_eq!(bits(&wall_states), bits(&ref_wall_states), "step {step}");
        assert_eq!(bits(&records), bits(&outcomes), "step {step}: records");
        let pairs_touching = outcomes[..m.pairs.len()]
            .iter()
            .filter(|o| o.forces().is_some())
            .count();
        assert_eq!(stats.pair_contacts, pairs_touching);
        // The totals are those of the outcomes: walls touching, contacts sliding, the pairs'
        // overlaps summed in list order.
        let touching_forces = |o: &&Interaction<f64>| o.forces().copied();
        let wall_forces: Vec<_> = outcomes[m.pairs.len()..]
            .iter()
            .filter_map(|o| touching_forces(&o))
            .collect();
        assert_eq!(stats.wall_contacts, wall_forces.len());
        for (k, o) in outcomes[m.pairs.len()..].iter().enumerate() {
            each_wall[k % walls.len()] += usize::from(o.forces().is_some());
        }
        on_walls += wall_forces.iter().filter(|c| c.sliding).count();
        let all: Vec<_> = outcomes
            .iter()
            .filter_map(|o| touching_forces(&o))
            .collect();
        assert_eq!(
            stats.sliding_contacts,
            all.iter().filter(|c| c.sliding).count()
        );
        let overlaps = outcomes[..m.pairs.len()]
            .iter()
            .filter_map(|o| touching_forces(&o))
            .fold(0.0, |sum, c| sum + c.overlap);
        assert_eq!(stats.overlap_sum, overlaps);
        // The coarse step's contacts past their law's accuracy limit, `w0 dt` at or past its
        // accurate phase, are counted.
        let past_accuracy = |a: usize, b: usize, mass: f64| {
            let law = t.law(m.material[a] as usize, b).unwrap();
            let rate = law.accurate_phase() / dt.seconds();
            law.normal().stiffness() >= mass * rate * rate
        };
        let pairs_past = m.pairs.iter().zip(&outcomes).filter(|([i, j], o)| {
            let (i, j) = (*i as usize, *j as usize);
            let mass = effective_mass(m.mass[i], m.mass[j]);
            o.forces().is_some() && past_accuracy(i, m.material[j] as usize, mass)
        });
        let walls_past = outcomes[m.pairs.len()..]
            .iter()
            .enumerate()
            .filter(|(k, o)| {
                let (sphere, wall) = (k / walls.len(), k % walls.len());
                let material = walls[wall].material as usize;
                o.forces().is_some() && past_accuracy(sphere, material, m.mass[sphere])
            });
        let counted = pairs_past.count() + walls_past.count();
        assert_eq!(stats.inaccurate_contacts, counted, "step {step}");
        inaccurate += counted;
        touching += stats.pair_contacts;
        sliding += stats.sliding_contacts;
        mixed += m
            .pairs
            .iter()
            .zip(&outcomes)
            .filter(|([i, j], o)| {
                o.forces().is_some() && m.material[*i as usize] != m.material[*j as usize]
            })
            .count();
        m.advance(&force, &torque, dt.seconds());
    }
    // The comparison covered what it claims: touching pairs of different materials, sliding.
    assert!(
        touching > 1000 && mixed > 300 && sliding > 10 && on_walls > 10 && inaccurate > 100,
        "{touching} {mixed} {sliding} {on_walls} {inaccurate}"
    );
    assert!(
        each_wall.iter().all(|&n| n > 100),
        "contacts on each wall: {each_wall:?}"
    );
}

/// A fresh list evaluation from preloaded springs, its forces and torques given NaN (the seam
/// writes them in full, so nothing the arrays held reaches its sums); on an error the states
/// are as they were.
fn try_evaluate(
    t: &MaterialTable<Linear, 3>,
    arrays: &SphereArrays<'_, f64>,
    pairs: &[[u32; 2]],
    walls: &[MaterialWall<f64>],
    dt: soft_sphere::prelude::TimeStep<f64>,
) -> Result<(), ListError> {
    let n = arrays.len();
    let preload = |k: usize| State {
        displacement: Vec3::new(0.0, 1e-7 * k as f64, 0.0),
    };
    let mut states: Vec<State> = (0..pairs.len()).map(preload).collect();
    let mut wall_states: Vec<State> = (0..n * walls.len()).map(preload).collect();
    let before = bits(&(&states, &wall_states));
    let (mut force, mut torque) = (vec![Vec3::new(f64::NAN, 0.0, 0.0); n], vec![Vec3::ZERO; n]);
    torque.iter_mut().for_each(|t| t.z = f64::INFINITY);
    let mut records = vec![Interaction::Apart; pairs.len() + n * walls.len()];
    let result = evaluate_swapping(
        t,
        dt,
        arrays,
        (
            (CheckedPairs::new(pairs, &[], n)?, walls),
            (&mut states, &mut wall_states),
        ),
        (&mut force, &mut torque),
        Some(&mut records),
    );
    match result {
        Err(_) => {
            let after = bits(&(&states, &wall_states));
            assert_eq!(after, before, "{result:?} changed the caller's states");
        }
        Ok(_) => assert!(all_finite(&force) && all_finite(&torque)),
    }
    result.map(|_| ())
}

/// An evaluation's outcome, and the forces and torques it added to zero.
type Plain = (
    Result<ListStats<f64>, ListError>,
    Vec<Vec3<f64>>,
    Vec<Vec3<f64>>,
);

/// One plain evaluation of `m`'s pairs (no shifts, walls or records) from `states`, advanced
/// in place; the forces and torques it adds to zero.
fn evaluate_plain<L: Law<Float = f64>>(
    t: &MaterialTable<L, 3>,
    m: &Mixture,
    dt: soft_sphere::prelude::TimeStep<f64>,
    states: &mut [L::State],
) -> Plain {
    let pairs = CheckedPairs::new(&m.pairs, &[], m.position.len()).unwrap();
    evaluate_checked_pairs(t, &m.arrays(), pairs, dt, states)
}

/// One evaluation of `pairs` (no walls or records) from `states`, advanced in place; the
/// forces and torques it writes.
fn evaluate_checked_pairs<L: Law<Float = f64>>(
    t: &MaterialTable<L, 3>,
    arrays: &SphereArrays<'_, f64>,
    pairs: CheckedPairs<'_, f64>,
    dt: soft_sphere::prelude::TimeStep<f64>,
    states: &mut [L::State],
) -> Plain {
    let n = arrays.len();
    let (mut force, mut torque) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    let outcome = evaluate_swapping(
        t,
        dt,
        arrays,
        ((pairs, &[]), (states, &mut [])),
        (&mut force, &mut torque),
        None,
    );
    (outcome, force, torque)
}

/// An evaluation of pairs checked elsewhere, which must leave the caller's states as they were
/// when it refuses.
fn evaluate_checked(
    t: &MaterialTable<Linear, 3>,
    arrays: &SphereArrays<'_, f64>,
    pairs: CheckedPairs<'_, f64>,
    dt: soft_sphere::prelude::TimeStep<f64>,
) -> Result<(), ListError> {
    let mut states = vec![State::default(); pairs.len()];
    let (result, force, torque) = evaluate_checked_pairs(t, arrays, pairs, dt, &mut states);
    if result.is_err() {
        assert!(states.iter().all(|s| *s == State::default()));
    } else {
        assert!(all_finite(&force) && all_finite(&torque));
    }
    result.map(|_| ())
}

#[test]
fn every_bad_input_is_refused_with_its_place_and_changes_nothing() {
    let t = table();
    let m = Mixture::new(20, 3);
    let walls = [floor_of(2)];
    let dt = t.coarse_time_step(1.0e-6, &m.arrays(), &walls).unwrap();
    assert_eq!(try_evaluate(&t, &m.arrays(), &m.pairs, &walls, dt), Ok(()));
    // Lengths, one array at a time.
    let short = &m.position[..19];
    let cases: [(SphereArrays<'_, f64>, ListArray); 5] = [
        (
            SphereArrays {
                velocity: short,
                ..m.arrays()
            },
            ListArray::Velocity,
        ),
        (
            SphereArrays {
                angular_velocity: short,
                ..m.arrays()
            },
            ListArray::AngularVelocity,
        ),
        (
            SphereArrays {
                radius: &m.radius[1..],
                ..m.arrays()
            },
            ListArray::Radius,
        ),
        (
            SphereArrays {
                mass: &m.mass[1..],
                ..m.arrays()
            },
            ListArray::Mass,
        ),
        (
            SphereArrays {
                material: &m.material[1..],
                ..m.arrays()
            },
            ListArray::Material,
        ),
    ];
    for (arrays, array) in cases {
        assert_eq!(
            try_evaluate(&t, &arrays, &m.pairs, &walls, dt),
            Err(ListError::Length(array))
        );
        assert_eq!(
            t.coarse_time_step(1.0e-6, &arrays, &walls),
            Err(ListError::Length(array))
        );
    }
    // The caller's own buffers of the wrong length.
    let n = m.position.len();
    let states = vec![State::default(); m.pairs.len()];
    let wall_states = vec![State::default(); n];
    let (mut force, mut torque) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    let mut records = vec![Interaction::Apart; m.pairs.len() + n];
    let (mut next, mut next_walls) = (states.clone(), wall_states.clone());
    let mut run = |cut: usize| {
        let (p, w) = (states.len(), wall_states.len());
        let (f, r) = (force.len(), records.len());
        t.evaluate(
            dt,
            &m.arrays(),
            ContactList {
                pairs: CheckedPairs::new(&m.pairs, &[], n).unwrap(),
                pair_states: &states[..p - usize::from(cut == 0)],
                walls: &walls,
                wall_states: &wall_states[..w - usize::from(cut == 1)],
            },
            ListOutput {
                force: &mut force[..f - usize::from(cut == 2)],
                torque: &mut torque[..f - usize::from(cut == 3)],
                next_pair_states: &mut next[..p - usize::from(cut == 4)],
                next_wall_states: &mut next_walls[..w - usize::from(cut == 5)],
                records: Some(&mut records[..r - usize::from(cut == 6)]),
            },
        )
    };
    let expected = [
        ListArray::PairStates,
        ListArray::WallStates,
        ListArray::Force,
        ListArray::Torque,
        ListArray::NextPairStates,
        ListArray::NextWallStates,
        ListArray::Records,
    ];
    for (cut, array) in expected.into_iter().enumerate() {
        assert_eq!(run(cut), Err(ListError::Length(array)));
    }
    assert!(run(7).is_ok());
    // A material past the table, a sphere's or a wall's.
    let mut material = m.material.clone();
    material[7] = 3;
    let arrays = SphereArrays {
        material: &material,
        ..m.arrays()
    };
    let refused = Err(ListError::Material {
        sphere: 7,
        material: 3,
    });
    assert_eq!(try_evaluate(&t, &arrays, &m.pairs, &walls, dt), refused);
    assert_eq!(
        t.coarse_time_step(1.0e-6, &arrays, &walls).map(|_| ()),
        refused
    );
    let bad_wall = [floor_of(2), floor_of(9)];
    let refused = Err(ListError::WallMaterial {
        wall: 1,
        material: 9,
    });
    assert_eq!(
        try_evaluate(&t, &m.arrays(), &m.pairs, &bad_wall, dt),
        refused
    );
    // Invalid spheres, reported before any contact is evaluated.
    for (field, error) in [
        (0, ContactError::NonFiniteInput),
        (1, ContactError::NonPositiveRadius),
        (2, ContactError::NonPositiveMass),
    ] {
        let (mut position, mut radius, mut mass) =
            (m.position.clone(), m.radius.clone(), m.mass.clone());
        match field {
            0 => position[11].z = f64::NAN,
            1 => radius[11] = 0.0,
            _ => mass[11] = -1.0,
        }
        let arrays = SphereArrays {
            position: &position,
            radius: &radius,
            mass: &mass,
            ..m.arrays()
        };
        assert_eq!(
            try_evaluate(&t, &arrays, &m.pairs, &walls, dt),
            Err(ListError::Sphere { sphere: 11, error })
        );
    }
    // Two invalid spheres: the first named. Finite numbers whose sum overflows are valid.
    let (mut velocity, mut radius) = (m.velocity.clone(), m.radius.clone());
    velocity[13].y = f64::NEG_INFINITY;
    radius[5] = -0.0;
    let arrays = SphereArrays {
        velocity: &velocity,
        radius: &radius,
        ..m.arrays()
    };
    let error = ContactError::NonPositiveRadius;
    assert_eq!(
        t.coarse_time_step(1.0e-6, &arrays, &walls).map(|_| ()),
        Err(ListError::Sphere { sphere: 5, error })
    );
    let velocity: Vec<_> = (0..m.velocity.len())
        .map(|k| Vec3::new(f64::MAX, -f64::MAX, f64::MAX) * if k % 2 == 0 { 1.0 } else { 0.5 })
        .collect();
    let huge = SphereArrays {
        velocity: &velocity,
        ..m.arrays()
    };
    assert!(t.coarse_time_step(1.0e-6, &huge, &walls).is_ok());
    // A pair naming a sphere past the arrays.
    let mut pairs = m.pairs.clone();
    pairs[3] = [2, 20];
    assert_eq!(
        try_evaluate(&t, &m.arrays(), &pairs, &walls, dt),
        Err(ListError::PairIndex { pair: 3 })
    );
    // Pairs checked for more spheres than the call gives are checked again against these; a
    // list checked for fewer is not (its indices are inside these too).
    let mut pairs = m.pairs.clone();
    pairs[4] = [2, 19];
    let few = Mixture::new(19, 3);
    let few_dt = t.coarse_time_step(1.0e-6, &few.arrays(), &walls).unwrap();
    let pair = pairs.iter().position(|p| p.contains(&19)).unwrap();
    assert!(pair <= 4);
    let checked = CheckedPairs::new(&pairs, &[], 20).unwrap();
    assert_eq!(
        evaluate_checked(&t, &few.arrays(), checked, few_dt),
        Err(ListError::PairIndex { pair })
    );
    let checked = CheckedPairs::new(&few.pairs, &[], 19).unwrap();
    assert_eq!(evaluate_checked(&t, &m.arrays(), checked, dt), Ok(()));
    // A contact refused: coincident centres, then an overflowing force, each with its pair.
    let mut pairs = m.pairs.clone();
    pairs[5] = [4, 4];
    assert_eq!(
        try_evaluate(&t, &m.arrays(), &pairs, &walls, dt),
        Err(ListError::Pair {
            pair: 5,
            error: ContactError::CoincidentCentres
        })
    );
    // Several refused: the first in list order, whatever the materials' order in a block.
    let long = Mixture::new(60, 5);
    let dt_long = t.coarse_time_step(1.0e-6, &long.arrays(), &walls).unwrap();
    assert!(long.pairs.len() > 300, "{}", long.pairs.len());
    let mut pairs = long.pairs.clone();
    let by_material = |material: u32| (0..60u32).find(|&k| long.material[k as usize] == material);
    let (glass_sphere, steel_sphere) = (by_material(0).unwrap(), by_material(2).unwrap());
    // The later pair is of the materials evaluated first (glass before steel).
    pairs[290] = [glass_sphere, glass_sphere];
    pairs[270] = [steel_sphere, steel_sphere];
    pairs[260] = [glass_sphere, 59];
    assert_eq!(
        try_evaluate(&t, &long.arrays(), &pairs, &walls, dt_long),
        Err(ListError::Pair {
            pair: 270,
            error: ContactError::CoincidentCentres
        })
    );
    let mut velocity = m.velocity.clone();
    let [i, j] = m.pairs[0];
    velocity[i as usize].x = 1.7e308;
    velocity[j as usize].x = -1.7e308;
    let arrays = SphereArrays {
        velocity: &velocity,
        ..m.arrays()
    };
    let refused = try_evaluate(&t, &arrays, &m.pairs, &walls, dt);
    assert!(
        matches!(
            refused,
            Err(ListError::Pair {
                error: ContactError::NonFiniteResult,
                ..
            }) | Err(ListError::Wall {
                error: ContactError::NonFiniteResult,
                ..
            })
        ),
        "{refused:?}"
    );
    // A floor stiffer than the step allows: glass spheres whose step is checked without the
    // steel floor, one of them resting on it. The wall contact is refused with its place.
    let glass_only = vec![0u32; m.position.len()];
    let mut position = m.position.clone();
    position[13].z = 0.9 * m.radius[13];
    let arrays = SphereArrays {
        position: &position,
        material: &glass_only,
        ..m.arrays()
    };
    let light = m.mass.iter().copied().fold(f64::INFINITY, f64::min);
    let pair_limit = t.law(0, 0).unwrap().critical_time_step(light / 2.0);
    let wall_limit = t.law(0, 2).unwrap().critical_time_step(m.mass[13]);
    assert!(wall_limit < 0.8 * pair_limit);
    let dt = t.coarse_time_step(0.9 * pair_limit, &arrays, &[]).unwrap();
    assert!(
        t.coarse_time_step(0.9 * pair_limit, &arrays, &walls)
            .is_err()
    );
    assert_eq!(
        try_evaluate(&t, &arrays, &m.pairs, &walls, dt),
        Err(ListError::Wall {
            sphere: 13,
            wall: 0,
            error: ContactError::PastStableStep
        })
    );
    // A drum narrower than sphere 7, about the vertical through its centre: it reaches the wall
    // with no normal, and is refused with its place (the spheres before it, outside the drum and
    // so inside its wall, are evaluated).
    let up = Vec3::new(0.0, 0.0, 1.0);
    let narrow = [MaterialWall {
        wall: Wall::cylinder(m.position[7], up, 0.5 * m.radius[7]).unwrap(),
        material: 2,
    }];
    let dt = t.coarse_time_step(1.0e-7, &m.arrays(), &narrow).unwrap();
    assert_eq!(
        try_evaluate(&t, &m.arrays(), &m.pairs, &narrow, dt),
        Err(ListError::Wall {
            sphere: 7,
            wall: 0,
            error: ContactError::CoincidentCentres
        })
    );
}

#[test]
fn the_step_is_checked_against_every_material_pair_and_wall_present() {
    let t = table();
    let m = Mixture::new(30, 11);
    // Glass and rubber spheres only; steel is the floor's material.
    let two: Vec<u32> = m.material.iter().map(|&k| k.min(1)).collect();
    let spheres = SphereArrays {
        material: &two,
        ..m.arrays()
    };
    // Each mode's explicit-integration limit in closed form, 2 (sqrt(1 + z^2) - z) / w, for the
    // mixed coefficients: the normal mode on m*, the tangential spring on 2/7 m*.
    let limit = |a: &LinearMaterial<f64>, b: &LinearMaterial<f64>, m_star: f64| {
        let bound = |w: f64, z: f64| 2.0 / w * ((1.0 + z * z).sqrt() - z);
        let k = (a.normal_stiffness * b.normal_stiffness).sqrt();
        let e = (a.restitution * b.restitution).sqrt();
        let zeta = e.ln().abs() / (std::f64::consts::PI.powi(2) + e.ln().powi(2)).sqrt();
        let kt = (a.tangential_stiffness * b.tangential_stiffness).sqrt();
        let eta_t = (a.dashpot_ratio * b.dashpot_ratio).sqrt() * 2.0 * zeta * (m_star * k).sqrt();
        let mt = 2.0 / 7.0 * m_star;
        let wt = (kt / mt).sqrt();
        bound((k / m_star).sqrt(), zeta).min(bound(wt, eta_t / (2.0 * mt * wt)))
    };
    let lightest = |material: u32| lightest_of(&m.mass, &two, material);
    let materials = [glass(), rubber(), steel()];
    let pair_limit = |a: u32, b: u32| {
        let m_star = effective_mass(lightest(a), lightest(b));
        limit(&materials[a as usize], &materials[b as usize], m_star)
    };
    let smallest = pair_limit(0, 0).min(pair_limit(0, 1)).min(pair_limit(1, 1));
    // Just below the smallest pair limit: accepted; just above: refused, naming a pair.
    assert!(t.coarse_time_step(0.999 * smallest, &spheres, &[]).is_ok());
    let refused = t.coarse_time_step(1.001 * smallest, &spheres, &[]);
    assert!(
        matches!(
            refused,
            Err(ListError::TimeStep {
                error: ParameterError::TimeStepUnstable { .. },
                ..
            })
        ),
        "{refused:?}"
    );
    // A steel floor is stiffer than any pair: a step inside every pair's limit is refused with
    // the wall's material second, while a rubber floor passes.
    let wall_limit = (0..2u32)
        .map(|a| limit(&materials[a as usize], &steel(), lightest(a)))
        .fold(f64::INFINITY, f64::min);
    assert!(wall_limit < 0.85 * smallest, "{wall_limit} {smallest}");
    let step = 0.9 * smallest;
    assert!(t.coarse_time_step(step, &spheres, &[floor_of(1)]).is_ok());
    let refused = t.coarse_time_step(step, &spheres, &[floor_of(1), floor_of(2)]);
    assert!(
        matches!(
            refused,
            Err(ListError::TimeStep {
                materials: [_, 2],
                ..
            })
        ),
        "{refused:?}"
    );
    assert!(
        t.coarse_time_step(0.999 * wall_limit, &spheres, &[floor_of(2)])
            .is_ok()
    );
    assert!(
        t.coarse_time_step(1.001 * wall_limit, &spheres, &[floor_of(2)])
            .is_err()
    );
    // A material not present does not limit the step: rubber spheres alone, with their own
    // lightest pair, take a longer step than glass allows.
    let only_rubber = vec![1u32; m.position.len()];
    let arrays = SphereArrays {
        material: &only_rubber,
        ..m.arrays()
    };
    let light = m.mass.iter().copied().fold(f64::INFINITY, f64::min);
    let rubber_limit = limit(&rubber(), &rubber(), light / 2.0);
    assert!(rubber_limit > 2.0 * smallest);
    assert!(
        t.coarse_time_step(0.999 * rubber_limit, &arrays, &[])
            .is_ok()
    );
    assert!(
        t.coarse_time_step(1.001 * rubber_limit, &arrays, &[])
            .is_err()
    );
    // A bad step is refused whatever is present; the recommended step is accepted.
    assert!(matches!(
        t.coarse_time_step(-1.0, &spheres, &[]),
        Err(ListError::TimeStep {
            error: ParameterError::NotPositive(Parameter::TimeStep),
            ..
        })
    ));
    let walls = [floor_of(2)];
    let recommended = t.recommended_time_step(&spheres, &walls).unwrap().unwrap();
    assert!(t.coarse_time_step(recommended, &spheres, &walls).is_ok());
    assert!(recommended <= 0.2 * wall_limit * 1.0001);
    let none = SphereArrays {
        position: &[],
        velocity: &[],
        angular_velocity: &[],
        radius: &[],
        mass: &[],
        material: &[],
    };
    assert_eq!(t.recommended_time_step(&none, &walls), Ok(None));
}

#[test]
fn a_mixture_hertz_impact_faster_than_declared_is_refused_at_its_pair() {
    let elastic = |e: f64| ElasticMaterial {
        elasticity: Material::new(e, 0.3).unwrap(),
        restitution: 0.7,
        dashpot_ratio: 0.5,
        friction: 0.3,
    };
    let largest = HertzImpact {
        speed: 1.0,
        effective_radius: 5.0e-4,
    };
    let t = MaterialTable::mixed(
        &HertzMixing::new(largest, MindlinAA),
        &[elastic(1.0e8), elastic(5.0e8)],
    )
    .unwrap();
    let mass = 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * 1.0e-9;
    let position = [
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(2.0e-3, 0.0, 0.0),
        Vec3::new(4.0e-3, 0.0, 0.0),
    ];
    let run = |speed: f64| -> Result<usize, ListError> {
        let mut p = position.to_vec();
        let mut v = vec![
            Vec3::new(speed / 2.0, 0.0, 0.0),
            Vec3::new(-speed / 2.0, 0.0, 0.0),
            Vec3::ZERO,
        ];
        let w = vec![Vec3::ZERO; 3];
        let (radius, masses, material) = ([1.0e-3; 3], [mass; 3], [0u32, 1, 1]);
        let arrays = |p: &[Vec3<f64>], v: &[Vec3<f64>]| -> (Vec<Vec3<f64>>, Vec<Vec3<f64>>) {
            (p.to_vec(), v.to_vec())
        };
        let (p0, v0) = arrays(&p, &v);
        let spheres = SphereArrays {
            position: &p0,
            velocity: &v0,
            angular_velocity: &w,
            radius: &radius,
            mass: &masses,
            material: &material,
        };
        let m_star = effective_mass(mass, mass);
        let smallest = [(0, 0), (0, 1), (1, 1)]
            .map(|(a, b)| t.law(a, b).unwrap().critical_time_step(m_star))
            .into_iter()
            .fold(f64::INFINITY, f64::min);
        let step = t.coarse_time_step(0.9 * smallest, &spheres, &[])?;
        let dt = step.seconds();
        let pairs = [[0u32, 1], [1, 2]];
        let mut states = [Default::default(); 2];
        let mut touched = 0;
        for _ in 0..200_000 {
            let (mut force, mut torque) = ([Vec3::ZERO; 3], [Vec3::ZERO; 3]);
            let spheres = SphereArrays {
                position: &p,
                velocity: &v,
                angular_velocity: &w,
                radius: &radius,
                mass: &masses,
                material: &material,
            };
            let contacts = (
                (CheckedPairs::new(&pairs, &[], p.len()).unwrap(), &[][..]),
                (&mut states[..], &mut [][..]),
            );
            let loads = (&mut force[..], &mut torque[..]);
            let stats = evaluate_swapping(&t, step, &spheres, contacts, loads, None)?;
            touched += stats.pair_contacts;
            for k in 0..3 {
                v[k] += force[k] * (dt / mass);
                p[k] += v[k] * dt;
            }
            if touched > 0 && stats.pair_contacts == 0 {
                break;
            }
        }
        Ok(touched)
    };
    assert!(run(1.0).unwrap() > 0);
    assert_eq!(
        run(60.0),
        Err(ListError::Pair {
            pair: 0,
            error: ContactError::PastStableStep
        })
    );
}

proptest! {
    #![proptest_config(host_tests::strategies::config())]

    /// Arbitrary bits in every array and pair: a result or an error, never a panic, and on an
    /// error nothing the caller gave has changed (checked inside `try_evaluate`).
    #[test]
    fn arbitrary_arrays_give_a_result_or_an_error(
        words in prop::collection::vec(any::<u64>(), 48),
        pair_words in prop::collection::vec((0u32..6, 0u32..6), 0..6),
        materials in prop::collection::vec(0u32..4, 4),
    ) {
        let t = table();
        let f = |k: usize| f64::from_bits(words[k]);
        let v = |k: usize| Vec3::new(f(k), f(k + 1), f(k + 2));
        let position: Vec<_> = (0..4).map(|k| v(3 * k)).collect();
        let velocity: Vec<_> = (0..4).map(|k| v(12 + 3 * k)).collect();
        let angular_velocity: Vec<_> = (0..4).map(|k| v(24 + 3 * k)).collect();
        let radius: Vec<_> = (0..4).map(|k| f(36 + k)).collect();
        let mass: Vec<_> = (0..4).map(|k| f(40 + k)).collect();
        let arrays = SphereArrays {
            position: &position, velocity: &velocity, angular_velocity: &angular_velocity,
            radius: &radius, mass: &mass, material: &materials,
        };
        let pairs: Vec<[u32; 2]> = pair_words.iter().map(|&(i, j)| [i, j]).collect();
        let walls = [floor_of(2)];
        let dt = t.coarse_time_step(1e-7, &SphereArrays {
            position: &[Vec3::ZERO], velocity: &[Vec3::ZERO], angular_velocity: &[Vec3::ZERO],
            radius: &[1e-3], mass: &[1e-5], material: &[0],
        }, &walls).unwrap();
        let _ = try_evaluate(&t, &arrays, &pairs, &walls, dt);
        let _ = t.coarse_time_step(1e-7, &arrays, &walls);
        let _ = t.recommended_time_step(&arrays, &walls);
    }
}

#[test]
fn an_empty_list_and_walls_alone_work() {
    let t = table();
    let position = [Vec3::new(0.0, 0.0, 0.99e-3)];
    let zero = [Vec3::ZERO];
    let arrays = SphereArrays {
        position: &position,
        velocity: &zero,
        angular_velocity: &zero,
        radius: &[1.0e-3],
        mass: &[1.0e-5],
        material: &[1],
    };
    let walls = [floor_of(0)];
    let dt = t.coarse_time_step(1.0e-6, &arrays, &walls).unwrap();
    let mut wall_states = [State::default()];
    let (mut force, mut torque) = ([Vec3::ZERO], [Vec3::ZERO]);
    let mut records = [Interaction::Apart];
    let stats = evaluate_swapping(
        &t,
        dt,
        &arrays,
        ((CheckedPairs::empty(), &walls), (&mut [], &mut wall_states)),
        (&mut force, &mut torque),
        Some(&mut records),
    )
    .unwrap();
    assert_eq!((stats.pair_contacts, stats.wall_contacts), (0, 1));
    // The rubber sphere on a glass floor: the mixed spring pushes it up by k_n delta.
    let k = (glass().normal_stiffness * rubber().normal_stiffness).sqrt();
    assert!(
        (force[0].z / (k * 1.0e-5) - 1.0).abs() < 1e-9,
        "{:?}",
        force[0]
    );
    assert!(matches!(records[0], Interaction::Touching(_)));
    let _ = Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0));
}

#[test]
fn every_list_and_table_error_says_where_and_why() {
    let texts = [
        (
            ListError::Length(ListArray::Mass).to_string(),
            vec!["Mass", "length"],
        ),
        (
            ListError::Material {
                sphere: 7,
                material: 3,
            }
            .to_string(),
            vec!["sphere 7", "material 3"],
        ),
        (
            ListError::WallMaterial {
                wall: 1,
                material: 9,
            }
            .to_string(),
            vec!["wall 1", "material 9"],
        ),
        (
            ListError::Sphere {
                sphere: 11,
                error: ContactError::NonPositiveMass,
            }
            .to_string(),
            vec!["sphere 11", "mass"],
        ),
        (
            ListError::PairIndex { pair: 3 }.to_string(),
            vec!["pair 3", "past"],
        ),
        (
            ListError::Pair {
                pair: 5,
                error: ContactError::CoincidentCentres,
            }
            .to_string(),
            vec!["pair 5", "coincide"],
        ),
        (
            ListError::Wall {
                sphere: 13,
                wall: 0,
                error: ContactError::PastStableStep,
            }
            .to_string(),
            vec!["sphere 13", "wall 0", "stiffer"],
        ),
        (
            ListError::TimeStep {
                materials: [0, 2],
                error: ParameterError::TimeStepUnstable {
                    time_step: 1e-5,
                    limit: 1e-6,
                },
            }
            .to_string(),
            vec!["materials 0 and 2", "stability limit"],
        ),
        (
            TableError::MaterialOutOfRange { material: 4 }.to_string(),
            vec!["material 4", "past"],
        ),
        (
            TableError::Pair {
                materials: [1, 2],
                error: ParameterError::Negative(Parameter::Friction),
            }
            .to_string(),
            vec!["materials 1 and 2", "Friction"],
        ),
        (
            ContactError::PastStableStep.to_string(),
            vec!["stiffer", "time step"],
        ),
    ];
    for (text, words) in texts {
        for word in words {
            assert!(text.contains(word), "{text:?} lacks {word:?}");
        }
    }
    // The arrays' own size questions.
    let m = Mixture::new(4, 1);
    assert_eq!((m.arrays().len(), m.arrays().is_empty()), (4, false));
    let none = Mixture::new(0, 1);
    assert_eq!((none.arrays().len(), none.arrays().is_empty()), (0, true));
}

/// The first pair the one-contact path refuses, in list order, with its error.
fn first_refused_one_at_a_time(
    t: &MaterialTable<Linear, 3>,
    m: &Mixture,
    pairs: &[[u32; 2]],
    dt: soft_sphere::prelude::TimeStep<f64>,
) -> Option<ListError> {
    pairs.iter().enumerate().find_map(|(pair, &[i, j])| {
        let (i, j) = (i as usize, j as usize);
        let law = t
            .law(m.material[i] as usize, m.material[j] as usize)
            .unwrap();
        let mut state = State::default();
        let outcome = law.sphere_sphere(&m.sphere(i), &m.sphere(j), &mut state, dt);
        outcome.err().map(|error| ListError::Pair { pair, error })
    })
}

/// The seam tests a chunk's results for finiteness once (a sum) and re-runs a failing chunk
/// checked: whichever failure it meets first, it names the one the one-contact path meets first
/// in list order; a chunk whose results are finite but whose sum overflows stands, with the
/// one-contact path's bits.
/// A law that keeps no state (Model C: the state is `()`, always finite) is tested on its
/// forces alone: a contact that overflows is refused by the chunk's probe.
#[test]
fn a_contact_of_a_law_without_state_is_refused_on_its_forces() {
    let t = MaterialTable::<soft_sphere::prelude::ContactLaw<f64, _, ModelC<f64>>, 3>::mixed(
        &LinearMixing::new(ModelC),
        &[glass(), rubber(), steel()],
    )
    .unwrap();
    let mut m = Mixture::new(60, 5);
    let dt = t.coarse_time_step(1.0e-6, &m.arrays(), &[]).unwrap();
    let touching = |m: &Mixture, k: usize| {
        let [i, j] = m.pairs[k].map(|x| x as usize);
        let reach = m.radius[i] + m.radius[j];
        (m.position[j] - m.position[i]).norm_squared() < reach * reach
    };
    let k = (0..m.pairs.len()).find(|&k| touching(&m, k)).unwrap();
    let [i, j] = m.pairs[k].map(|x| x as usize);
    // The pair meets at +-1.7e308 m/s: its dashpot force overflows.
    m.velocity[i].x = 1.7e308;
    m.velocity[j].x = -1.7e308;
    let mut states = vec![(); m.pairs.len()];
    let (outcome, _, _) = evaluate_plain(&t, &m, dt, &mut states);
    assert_eq!(
        outcome.map(|_| ()),
        Err(ListError::Pair {
            pair: k,
            error: ContactError::NonFiniteResult
        })
    );
}

#[test]
fn a_chunk_tested_at_once_names_the_first_refused_pair_in_list_order() {
    let t = table();
    let base = Mixture::new(60, 5);
    assert!(base.pairs.len() > 300, "{}", base.pairs.len());
    let dt = t.coarse_time_step(1.0e-6, &base.arrays(), &[]).unwrap();
    let touching = |k: usize| {
        let [i, j] = base.pairs[k].map(|x| x as usize);
        let reach = base.radius[i] + base.radius[j];
        (base.position[j] - base.position[i]).norm_squared() < reach * reach
    };
    // Two touching pairs of the first chunk (256 pairs) with no sphere in common, a third in
    // the second chunk.
    let early = (10..256).find(|&k| touching(k)).unwrap();
    let shares = |a: usize, b: usize| {
        let (x, y) = (base.pairs[a], base.pairs[b]);
        x.iter().any(|s| y.contains(s))
    };
    let late = (early + 20..256)
        .find(|&k| touching(k) && !shares(early, k))
        .unwrap();
    let next_chunk = (256..base.pairs.len()).find(|&k| touching(k)).unwrap();
    // Pair k's contact overflows: its spheres meet at +-1.7e308 m/s.
    let overflowing = |m: &mut Mixture, k: usize| {
        let [i, j] = base.pairs[k].map(|x| x as usize);
        m.velocity[i].x = 1.7e308;
        m.velocity[j].x = -1.7e308;
    };
    let coincident = |pairs: &mut Vec<[u32; 2]>, k: usize| pairs[k] = [pairs[k][0]; 2];
    let refused = |m: &Mixture, pairs: &[[u32; 2]]| {
        let list = try_evaluate(&t, &m.arrays(), pairs, &[], dt);
        assert_eq!(list.err(), first_refused_one_at_a_time(&t, m, pairs, dt));
        list.err()
    };
    let pair = |pair: usize, error: ContactError| Some(ListError::Pair { pair, error });

    // A non-finite result before a coincident pair in the same chunk: the non-finite one; the
    // other way round: the coincident pair; a non-finite result alone, found by the chunk's
    // test, in the second chunk.
    for (overflows, coincides, first) in [
        (
            early,
            Some(late),
            pair(early, ContactError::NonFiniteResult),
        ),
        (
            late,
            Some(early),
            pair(early, ContactError::CoincidentCentres),
        ),
        (
            next_chunk,
            None,
            pair(next_chunk, ContactError::NonFiniteResult),
        ),
    ] {
        let mut m = Mixture::new(60, 5);
        overflowing(&mut m, overflows);
        let mut pairs = base.pairs.clone();
        if let Some(k) = coincides {
            coincident(&mut pairs, k);
        }
        assert_eq!(refused(&m, &pairs), first);
    }

    // Finite results whose sum overflows: one sphere sliding past all its neighbours at
    // 1e308 m/s. Accepted, with the one-contact path's bits.
    let mut m = Mixture::new(60, 5);
    let [fast, _] = base.pairs[early].map(|x| x as usize);
    m.velocity[fast] = Vec3::new(1.0e308, 1.0e308, 0.0);
    let neighbours = (0..256)
        .filter(|&k| touching(k) && base.pairs[k].contains(&(fast as u32)))
        .count();
    assert!(neighbours >= 2, "{neighbours}");
    assert_eq!(first_refused_one_at_a_time(&t, &m, &base.pairs, dt), None);
    let mut states = vec![State::default(); base.pairs.len()];
    let (outcome, force, torque) = evaluate_plain(&t, &m, dt, &mut states);
    outcome.unwrap();
    let mut peer_states = vec![State::default(); base.pairs.len()];
    let peer = one_at_a_time(&t, &m, &[], dt, (&mut peer_states, &mut [])).unwrap();
    assert_eq!(
        bits(&(&force, &torque, &states)),
        bits(&(&peer.0, &peer.1, &peer_states))
    );
}

/// What [`evaluate_on`] gives: the result, the forces and torques, and everything it wrote as
/// text.
type Evaluated = (
    Result<ListStats<f64>, ListError>,
    Vec<Vec3<f64>>,
    Vec<Vec3<f64>>,
    String,
);

/// One list evaluation of `m` on the given executor (`loads` empty: one thread), from `states`
/// and `wall_states`, which it advances: the forces, torques, records and statistics, as text.
fn evaluate_on<E: Executor>(
    t: &MaterialTable<Linear, 3>,
    (executor, loads): (&E, &mut [PairLoad<f64>]),
    (m, pairs, walls): (&Mixture, &[[u32; 2]], &[MaterialWall<f64>]),
    dt: soft_sphere::prelude::TimeStep<f64>,
    (states, wall_states): (&mut [State], &mut [State]),
) -> Evaluated {
    let n = m.position.len();
    let (mut force, mut torque) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    let contacts = pairs.len() + n * walls.len();
    let mut records = vec![Interaction::Apart; contacts];
    let contacts = (
        (CheckedPairs::new(pairs, &[], n).unwrap(), walls),
        (states, wall_states),
    );
    let out = (&mut force[..], &mut torque[..], Some(&mut records[..]));
    let result = evaluate_swapping_on(t, (executor, loads), dt, &m.arrays(), contacts, out);
    let text = bits(&(&force, &torque, &records));
    (result, force, torque, text)
}

/// A list spread over threads is evaluated whole, however long: past about 17,000 pairs,
/// stretches cut shorter than the list needs would run out of the executor's 64 pieces before
/// its end. Every pair is evaluated once, to the one-thread bits.
#[test]
fn a_long_list_spread_over_threads_evaluates_every_pair() {
    let t = table();
    let m = Mixture::new(2400, 17);
    assert!(
        m.pairs.len() > 64 * 4 * 256 / 4 + 4 * 256,
        "{} pairs",
        m.pairs.len()
    );
    let dt = t
        .coarse_time_step(1.0e-6, &m.arrays(), &[])
        .unwrap()
        .tolerating_unstable_contacts();
    let pool = Threads::new(2).unwrap();
    let mut loads = vec![PairLoad::default(); m.pairs.len()];
    let mut one = vec![State::default(); m.pairs.len()];
    let mut spread = one.clone();
    let pairs = (&m, &m.pairs[..], &[][..]);
    let (serial, _, _, serial_text) =
        evaluate_on(&t, (&Serial, &mut []), pairs, dt, (&mut one, &mut []));
    let (threaded, _, _, threaded_text) =
        evaluate_on(&t, (&pool, &mut loads), pairs, dt, (&mut spread, &mut []));
    assert!(serial.unwrap().pair_contacts > 1000);
    assert_eq!(threaded, serial);
    assert_eq!(threaded_text, serial_text);
    assert_eq!(bits(&spread), bits(&one));
}

/// The pairs spread over 1, 2 and 3 threads (stretches of the list each with its own states
/// and loads, summed in list order after) give the one-thread bits step after step: forces,
/// torques, states, records and statistics, tolerated unstable contacts counted once; a refusal
/// in two stretches names the first in list order, whichever thread ends first, and changes
/// nothing.
#[test]
fn pairs_spread_over_threads_give_the_one_thread_bits() {
    let t = table();
    let walls = [floor_of(2)];
    let start = Mixture::new(400, 13);
    let chunks = start.pairs.len().div_ceil(256);
    assert!(chunks >= 4, "{} pairs", start.pairs.len());
    // A step checked for glass alone, past the steel pairs' limit, tolerated: those contacts
    // are counted, not refused.
    let glass_only = vec![0u32; start.position.len()];
    let glass = SphereArrays {
        material: &glass_only,
        ..start.arrays()
    };
    let light = start.mass.iter().copied().fold(f64::INFINITY, f64::min);
    let glass_limit = t.law(0, 0).unwrap().critical_time_step(light / 2.0);
    let dt = t
        .coarse_time_step(0.9 * glass_limit, &glass, &[])
        .unwrap()
        .tolerating_unstable_contacts();
    for threads in [1, 2, 3] {
        let pool = Threads::new(threads).unwrap();
        let mut m = Mixture::new(400, 13);
        let contacts = (m.pairs.len(), m.position.len() * walls.len());
        let mut one = (
            vec![State::default(); contacts.0],
            vec![State::default(); contacts.1],
        );
        let mut spread = one.clone();
        let mut loads = vec![PairLoad::default(); m.pairs.len()];
        let pairs = m.pairs.clone();
        for step in 0..20 {
            let (serial, force, torque, serial_text) = evaluate_on(
                &t,
                (&Serial, &mut []),
                (&m, &pairs, &walls),
                dt,
                (&mut one.0, &mut one.1),
            );
            let (threaded, _, _, threaded_text) = evaluate_on(
                &t,
                (&pool, &mut loads),
                (&m, &pairs, &walls),
                dt,
                (&mut spread.0, &mut spread.1),
            );
            assert_eq!(threaded, serial, "{threads} threads, step {step}");
            assert_eq!(threaded_text, serial_text, "{threads} threads, step {step}");
            assert_eq!(bits(&spread), bits(&one), "{threads} threads, step {step}");
            if step == 0 {
                let stats = serial.unwrap();
                assert!(
                    stats.pair_contacts > 100 && stats.inaccurate_contacts > 0,
                    "{stats:?}"
                );
            }
            m.advance(&force, &torque, 2.0e-5);
        }
        // Refusals in the second and the last stretch (a non-finite contact, coincident centres):
        // the second's, and the caller's arrays as they were.
        let mut m = Mixture::new(400, 13);
        let touching = |k: usize| {
            let [i, j] = m.pairs[k].map(|x| x as usize);
            let reach = m.radius[i] + m.radius[j];
            (m.position[j] - m.position[i]).norm_squared() < reach * reach
        };
        let second = (256..512).find(|&k| touching(k)).unwrap();
        let last = ((chunks - 1) * 256..m.pairs.len())
            .rev()
            .find(|&k| touching(k))
            .unwrap();
        let mut pairs = m.pairs.clone();
        pairs[last] = [pairs[last][0]; 2];
        let [i, j] = pairs[second].map(|x| x as usize);
        (m.velocity[i].x, m.velocity[j].x) = (1.7e308, -1.7e308);
        let preload = |k: usize| State {
            displacement: Vec3::new(1e-7 * k as f64, 0.0, 0.0),
        };
        let mut states: Vec<State> = (0..pairs.len()).map(preload).collect();
        let mut wall_states: Vec<State> = (0..m.position.len()).map(preload).collect();
        let before = bits(&(&states, &wall_states));
        let (refused, ..) = evaluate_on(
            &t,
            (&pool, &mut loads),
            (&m, &pairs, &walls),
            dt,
            (&mut states, &mut wall_states),
        );
        assert_eq!(
            refused.err(),
            Some(ListError::Pair {
                pair: second,
                error: ContactError::NonFiniteResult
            }),
            "{threads} threads"
        );
        assert_eq!(bits(&(&states, &wall_states)), before, "{threads} threads");
    }
}

/// The loads are empty or one per pair.
#[test]
fn loads_of_another_length_are_refused() {
    let t = table();
    let m = Mixture::new(30, 2);
    let dt = t.coarse_time_step(1.0e-6, &m.arrays(), &[]).unwrap();
    let pool = Threads::new(2).unwrap();
    let mut loads = vec![PairLoad::default(); m.pairs.len() + 1];
    let mut states = vec![State::default(); m.pairs.len()];
    let (refused, ..) = evaluate_on(
        &t,
        (&pool, &mut loads),
        (&m, &m.pairs, &[]),
        dt,
        (&mut states, &mut []),
    );
    assert_eq!(refused, Err(ListError::Length(ListArray::Loads)));
}

#[test]
fn the_step_is_checked_for_accuracy_against_every_material_pair_and_wall_present() {
    let t = table();
    let m = Mixture::new(30, 11);
    // Glass and rubber spheres only; steel is a floor's material.
    let two: Vec<u32> = m.material.iter().map(|&k| k.min(1)).collect();
    let spheres = SphereArrays {
        material: &two,
        ..m.arrays()
    };
    let lightest = |material: u32| lightest_of(&m.mass, &two, material);
    let pair = |a: u32, b: u32| {
        let law = t.law(a as usize, b as usize).unwrap();
        law.accurate_time_step(effective_mass(lightest(a), lightest(b)))
    };
    let wall = |a: u32, w: u32| {
        let law = t.law(a as usize, w as usize).unwrap();
        law.accurate_time_step(lightest(a))
    };
    let pairs = [(0, 0), (0, 1), (1, 1)];
    let (smallest, stiffest) =
        pairs
            .iter()
            .map(|&(a, b)| (pair(a, b), [a, b]))
            .fold(
                (f64::INFINITY, [0, 0]),
                |k, p| if p.0 < k.0 { p } else { k },
            );
    // Accurate steps lie well inside the stable ones.
    assert!(t.coarse_time_step(1.5 * smallest, &spheres, &[]).is_ok());
    let step = t.time_step(0.999 * smallest, &spheres, &[]).unwrap();
    let coarse = t.coarse_time_step(step.seconds(), &spheres, &[]).unwrap();
    assert!(step.is_accurate() && !coarse.is_accurate());
    match t.time_step(1.001 * smallest, &spheres, &[]) {
        Err(ListError::TimeStep {
            materials,
            error: ParameterError::TimeStepInaccurate { limit, .. },
        }) => {
            assert_eq!(materials, stiffest);
            assert_eq!(limit, smallest);
        }
        other => panic!("expected TimeStepInaccurate, got {other:?}"),
    }
    // A steel floor's accurate step is smaller still: checked too, naming the wall's material.
    let floor = (0..2u32).map(|a| wall(a, 2)).fold(f64::INFINITY, f64::min);
    assert!(floor < smallest);
    assert!(t.time_step(0.999 * floor, &spheres, &[floor_of(2)]).is_ok());
    assert!(matches!(
        t.time_step(1.001 * floor, &spheres, &[floor_of(2)]),
        Err(ListError::TimeStep {
            materials: [_, 2],
            error: ParameterError::TimeStepInaccurate { .. }
        })
    ));
}
