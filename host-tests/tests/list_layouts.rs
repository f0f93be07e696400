//! The list seam over the layouts engines keep: spheres as one array per field or as one array
//! of checked spheres give the same bits; a pair seen through a periodic image (its shift) is
//! the pair with its second sphere moved; bad shifts are refused with their pair.

use host_tests::random::Xorshift;
use host_tests::seam::evaluate_swapping;
use soft_sphere::prelude::{
    CheckedPairs, CheckedSphere, ContactError, Interaction, LinearMaterial, LinearMixing,
    ListArray, ListError, MaterialTable, ModelAA, Sphere, SphereArrays, SphereSlice, Spheres,
    SpringDisplacement, TimeStep, Vec3,
};

const RADIUS: f64 = 0.5e-3;
const BOX: f64 = 4e-3;

type Table = MaterialTable<
    soft_sphere::prelude::ContactLaw<
        f64,
        soft_sphere::prelude::LinearSpringDashpot<f64>,
        ModelAA<f64>,
    >,
    2,
>;

fn table() -> Table {
    let glass = LinearMaterial {
        normal_stiffness: 1000.0,
        restitution: 0.8,
        tangential_stiffness: 285.7,
        dashpot_ratio: 0.5,
        friction: 0.3,
    };
    let steel = LinearMaterial {
        normal_stiffness: 3000.0,
        friction: 0.5,
        ..glass
    };
    MaterialTable::mixed(&LinearMixing::new(ModelAA), &[glass, steel]).unwrap()
}

/// Spheres in a periodic box of side [`BOX`] with random velocities and spins, random
/// materials, and every pair within reach through the minimum image, with its shift.
#[derive(Clone)]
struct Gas {
    spheres: Vec<Sphere<f64>>,
    materials: Vec<u32>,
    pairs: Vec<[u32; 2]>,
    shifts: Vec<Vec3<f64>>,
}

impl Gas {
    /// The spheres, checked.
    fn checked(&self) -> Vec<CheckedSphere<f64>> {
        self.spheres
            .iter()
            .map(|s| CheckedSphere::new(*s).unwrap())
            .collect()
    }

    /// The spheres as one array of checked spheres, beside their materials.
    fn slice<'a>(&'a self, checked: &'a [CheckedSphere<f64>]) -> SphereSlice<'a, f64> {
        SphereSlice {
            spheres: checked,
            material: &self.materials,
        }
    }

    /// Pair `k` through the one-contact path of its materials' law, its second sphere moved
    /// by its shift.
    fn one_contact(
        &self,
        table: &Table,
        dt: TimeStep<f64>,
        k: usize,
        state: &mut SpringDisplacement<f64>,
    ) -> Result<Interaction<f64>, ContactError> {
        let [i, j] = self.pairs[k].map(|i| i as usize);
        let law = table
            .law(self.materials[i] as usize, self.materials[j] as usize)
            .unwrap();
        let mut image = self.spheres[j];
        image.position += self.shifts[k];
        law.sphere_sphere(&self.spheres[i], &image, state, dt)
    }

    fn new(count: usize, seed: u64) -> Self {
        let mut random = Xorshift::new(seed);
        let mut spheres = Vec::new();
        let mut materials = Vec::new();
        for _ in 0..count {
            let mut next = || random.unit();
            let mut s = Sphere::solid(
                Vec3::new(next() * BOX, next() * BOX, next() * BOX),
                RADIUS * (0.8 + 0.4 * next()),
                2500.0,
            );
            s.velocity = Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5) * 0.2;
            s.angular_velocity = Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5) * 100.0;
            spheres.push(s);
            materials.push(u32::from(random.unit() < 0.5));
        }
        let (mut pairs, mut shifts) = (Vec::new(), Vec::new());
        for i in 0..count {
            for j in i + 1..count {
                let d = spheres[j].position - spheres[i].position;
                let image = |x: f64| -BOX * (x / BOX).round();
                let shift = Vec3::new(image(d.x), image(d.y), image(d.z));
                if (d + shift).norm_squared() < (3.0 * RADIUS).powi(2) {
                    pairs.push([i as u32, j as u32]);
                    shifts.push(shift);
                }
            }
        }
        Self {
            spheres,
            materials,
            pairs,
            shifts,
        }
    }
}

/// Pairs, their shifts and their states before a call.
type List<'a> = (
    &'a [[u32; 2]],
    &'a [Vec3<f64>],
    &'a [SpringDisplacement<f64>],
);

/// Everything one evaluation changes or reports.
#[derive(Debug, PartialEq)]
struct Outcome {
    forces: Vec<Vec3<f64>>,
    torques: Vec<Vec3<f64>>,
    states: Vec<SpringDisplacement<f64>>,
    records: Vec<Interaction<f64>>,
}

fn evaluate(
    table: &Table,
    dt: TimeStep<f64>,
    spheres: &impl Spheres<f64>,
    (pairs, shifts, states): List<'_>,
) -> Result<Outcome, ListError> {
    let n = spheres.len();
    let mut out = Outcome {
        forces: vec![Vec3::ZERO; n],
        torques: vec![Vec3::ZERO; n],
        states: states.to_vec(),
        records: vec![Interaction::Apart; pairs.len()],
    };
    let contacts = (
        (CheckedPairs::new(pairs, shifts, n)?, &[][..]),
        (&mut out.states[..], &mut [][..]),
    );
    let loads = (&mut out.forces[..], &mut out.torques[..]);
    evaluate_swapping(table, dt, spheres, contacts, loads, Some(&mut out.records))?;
    Ok(out)
}

/// Stored springs of some length, so that every status path has history to carry.
fn preloaded(pairs: usize) -> Vec<SpringDisplacement<f64>> {
    (0..pairs)
        .map(|k| SpringDisplacement {
            displacement: Vec3::new(1e-8 * k as f64, -2e-8, 0.0),
        })
        .collect()
}

#[test]
fn both_layouts_and_shifted_pairs_give_the_one_contact_bits() {
    let table = table();
    let gas = Gas::new(120, 5);
    let position: Vec<_> = gas.spheres.iter().map(|s| s.position).collect();
    let velocity: Vec<_> = gas.spheres.iter().map(|s| s.velocity).collect();
    let spin: Vec<_> = gas.spheres.iter().map(|s| s.angular_velocity).collect();
    let radius: Vec<_> = gas.spheres.iter().map(|s| s.radius).collect();
    let mass: Vec<_> = gas.spheres.iter().map(|s| s.mass).collect();
    let arrays = SphereArrays {
        position: &position,
        velocity: &velocity,
        angular_velocity: &spin,
        radius: &radius,
        mass: &mass,
        material: &gas.materials,
    };
    let checked = gas.checked();
    let slice = gas.slice(&checked);
    let dt = table.time_step(1e-6, &arrays, &[]).unwrap();
    let states = preloaded(gas.pairs.len());
    let list = (&gas.pairs[..], &gas.shifts[..], &states[..]);
    let reference = evaluate(&table, dt, &arrays, list).unwrap();
    let across = gas.shifts.iter().filter(|s| **s != Vec3::ZERO).count();
    let touching = reference
        .records
        .iter()
        .filter(|r| r.forces().is_some())
        .count();
    assert!(
        across > 10 && touching > 20,
        "{across} shifted, {touching} touching"
    );
    // Each pair against the law of its materials applied to it directly, its second sphere
    // moved by its shift.
    for (k, &before) in states.iter().enumerate() {
        let mut state = before;
        let direct = gas.one_contact(&table, dt, k, &mut state);
        assert_eq!(direct, Ok(reference.records[k]), "pair {k}");
        assert_eq!(state, reference.states[k], "pair {k}");
    }
    // The other layout: the same bits.
    assert_eq!(evaluate(&table, dt, &slice, list).as_ref(), Ok(&reference));
}

#[test]
fn bad_shifts_and_material_arrays_are_refused_with_their_place() {
    let table = table();
    let gas = Gas::new(40, 8);
    let checked = gas.checked();
    let slice = gas.slice(&checked);
    let dt = table.time_step(1e-6, &slice, &[]).unwrap();
    let states = preloaded(gas.pairs.len());
    assert!(gas.pairs.len() > 3);
    let mut shifts = gas.shifts.clone();
    shifts[3].y = f64::NAN;
    let bad = (&gas.pairs[..], &shifts[..], &states[..]);
    assert_eq!(
        evaluate(&table, dt, &slice, bad).err(),
        Some(ListError::Shift { pair: 3 })
    );
    let short = (&gas.pairs[..], &gas.shifts[1..], &states[..]);
    assert_eq!(
        evaluate(&table, dt, &slice, short).err(),
        Some(ListError::Length(ListArray::Shifts))
    );
    // No shifts at all is a list without periodic images.
    assert!(evaluate(&table, dt, &slice, (&gas.pairs, &[], &states)).is_ok());
    let short = SphereSlice {
        spheres: &checked,
        material: &gas.materials[1..],
    };
    assert_eq!(
        table.time_step(1e-6, &short, &[]).err(),
        Some(ListError::Length(ListArray::Material))
    );
    let mut past = gas.materials.clone();
    past[6] = 2;
    let past_table = SphereSlice {
        spheres: &checked,
        material: &past,
    };
    assert_eq!(
        evaluate(&table, dt, &past_table, (&gas.pairs, &gas.shifts, &states)).err(),
        Some(ListError::Material {
            sphere: 6,
            material: 2
        })
    );
    assert_eq!((slice.len(), slice.is_empty()), (40, false));
}

/// A pair seen through a periodic image whose result overflows is refused with its own place:
/// the seam tests a chunk's results once and then evaluates its pairs again, checked, each at
/// its image, to name the first refused in list order, which is the one the one-contact path
/// refuses first on the moved spheres.
#[test]
fn an_overflowing_pair_across_the_period_is_named() {
    let table = table();
    let gas = Gas::new(120, 5);
    let checked = gas.checked();
    let slice = gas.slice(&checked);
    let dt = table.time_step(1e-6, &slice, &[]).unwrap();
    let states = preloaded(gas.pairs.len());
    // The one-contact path on the images: the first pair in list order it refuses.
    let first_refused = |gas: &Gas| {
        (0..gas.pairs.len()).find_map(|k| {
            let mut state = states[k];
            gas.one_contact(&table, dt, k, &mut state)
                .err()
                .map(|error| ListError::Pair { pair: k, error })
        })
    };
    assert_eq!(first_refused(&gas), None);
    // Each touching pair across the period in turn, its spheres driven apart at speeds whose
    // difference overflows, until the first pair refused is one across the period.
    let mut tried = 0;
    for (k, &[i, j]) in gas.pairs.iter().enumerate() {
        if gas.shifts[k] == Vec3::ZERO {
            continue;
        }
        let mut driven = gas.clone();
        driven.spheres[i as usize].velocity = Vec3::new(-1.5e308, 0.0, 0.0);
        driven.spheres[j as usize].velocity = Vec3::new(1.5e308, 0.0, 0.0);
        let expected = first_refused(&driven);
        let Some(ListError::Pair { pair, .. }) = expected else {
            continue;
        };
        if driven.shifts[pair] == Vec3::ZERO {
            continue;
        }
        tried += 1;
        let list = (&driven.pairs[..], &driven.shifts[..], &states[..]);
        let checked = driven.checked();
        let slice = driven.slice(&checked);
        assert_eq!(
            evaluate(&table, dt, &slice, list).err(),
            expected,
            "pair {k}"
        );
    }
    assert!(tried > 3, "{tried} pairs across the period refused");
}
