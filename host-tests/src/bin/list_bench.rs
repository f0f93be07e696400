//! The list seam (`MaterialTable::evaluate`) against one contact at a time, on the same packing
//! in one process: a jittered cubic packing of spheres whose neighbour list holds every pair
//! closer than 1.1 diameters (about half of them touching), f64 Model AA, one material and a
//! binary mixture (alternate spheres of two materials). One contact at a time is what an engine
//! writes around the kernel without the seam: gather both spheres from its arrays, check them,
//! pick the pair's law, evaluate, add the forces. Rounds alternate between the routes and the
//! ratios are of medians, so the machine's drift cancels. Before timing, both routes run from
//! the same states for a few steps and every force, torque and state is compared bit for bit.
//!
//! Usage: `cargo run --release -p host-tests --bin list_bench -- [--spheres 10000]
//! [--rounds 15]`; build for the machine with `RUSTFLAGS="-C target-cpu=x86-64-v3"`.

use std::error::Error;
use std::hint::black_box;
use std::time::Instant;

use host_tests::random::Xorshift;
use soft_sphere::prelude::{
    CheckedPairs, CheckedSphere, ContactLaw, ContactList, Interaction, Law, LinearMaterial,
    LinearMixing, LinearSpringDashpot, ListOutput, MaterialTable, ModelAA, Sphere, SphereArrays,
    SpringDisplacement, Std, TimeStep, Vec3,
};

type StdAA = ContactLaw<f64, LinearSpringDashpot<f64>, ModelAA<f64>, Std>;

struct Packing {
    position: Vec<Vec3<f64>>,
    velocity: Vec<Vec3<f64>>,
    angular_velocity: Vec<Vec3<f64>>,
    radius: Vec<f64>,
    mass: Vec<f64>,
    pairs: Vec<[u32; 2]>,
}

impl Packing {
    fn new(spheres: usize) -> Self {
        let d = 1.0e-3;
        let side = (spheres as f64).cbrt().ceil() as usize;
        let mut random = Xorshift::new(17);
        let mut r = |scale: f64| scale * (2.0 * random.unit() - 1.0);
        let mut p = Self {
            position: Vec::new(),
            velocity: Vec::new(),
            angular_velocity: Vec::new(),
            radius: vec![0.5 * d; spheres],
            mass: vec![2500.0 * std::f64::consts::PI / 6.0 * d * d * d; spheres],
            pairs: Vec::new(),
        };
        for k in 0..spheres {
            let (x, y, z) = (k % side, (k / side) % side, k / (side * side));
            let at = |i: usize| i as f64 * d;
            p.position.push(Vec3::new(
                at(x) + r(0.03 * d),
                at(y) + r(0.03 * d),
                at(z) + r(0.03 * d),
            ));
            p.velocity.push(Vec3::new(r(0.01), r(0.01), r(0.01)));
            p.angular_velocity
                .push(Vec3::new(r(10.0), r(10.0), r(10.0)));
        }
        // Forward lattice neighbours (the half shell), kept when closer than 1.1 diameters.
        let index = |x: usize, y: usize, z: usize| x + side * (y + side * z);
        for k in 0..spheres {
            let (x, y, z) = (k % side, (k / side) % side, k / (side * side));
            for (dx, dy, dz) in [
                (1, 0, 0),
                (0, 1, 0),
                (0, 0, 1),
                (1, 1, 0),
                (1, 0, 1),
                (0, 1, 1),
            ] {
                let (a, b, c) = (x + dx, y + dy, z + dz);
                if a >= side || b >= side || c >= side {
                    continue;
                }
                let j = index(a, b, c);
                if j < spheres
                    && (p.position[j] - p.position[k]).norm_squared() < (1.1 * d) * (1.1 * d)
                {
                    p.pairs.push([k as u32, j as u32]);
                }
            }
        }
        p
    }

    fn arrays<'a>(&'a self, material: &'a [u32]) -> SphereArrays<'a, f64> {
        SphereArrays {
            position: &self.position,
            velocity: &self.velocity,
            angular_velocity: &self.angular_velocity,
            radius: &self.radius,
            mass: &self.mass,
            material,
        }
    }
}

/// Forces, torques and states of one step.
type Outcome = (Vec<Vec3<f64>>, Vec<Vec3<f64>>);

/// One contact at a time, as an engine without the seam writes it.
fn one_at_a_time(
    table: &MaterialTable<StdAA, 2>,
    time_step: TimeStep<f64>,
    spheres: &SphereArrays<'_, f64>,
    pairs: &[[u32; 2]],
    states: &mut [SpringDisplacement<f64>],
    (force, torque): (&mut [Vec3<f64>], &mut [Vec3<f64>]),
) -> usize {
    let mut bound: [[_; 2]; 2] = std::array::from_fn(|a| {
        std::array::from_fn(|b| table.law(a, b).expect("two materials").at(time_step))
    });
    let sphere = |k: usize| Sphere {
        position: spheres.position[k],
        velocity: spheres.velocity[k],
        angular_velocity: spheres.angular_velocity[k],
        radius: spheres.radius[k],
        mass: spheres.mass[k],
    };
    let mut touching = 0;
    for (&[i, j], state) in pairs.iter().zip(states.iter_mut()) {
        let (i, j) = (i as usize, j as usize);
        let (Ok(a), Ok(b)) = (CheckedSphere::new(sphere(i)), CheckedSphere::new(sphere(j))) else {
            continue;
        };
        let law = &mut bound[spheres.material[i] as usize][spheres.material[j] as usize];
        if let Ok(Interaction::Touching(c)) = law.sphere_sphere(&a, &b, state) {
            force[i] -= c.force_on_j();
            torque[i] += c.torque_on_i;
            force[j] += c.force_on_j();
            torque[j] += c.torque_on_j;
            touching += 1;
        }
    }
    touching
}

/// An engine's double-buffered states: read from `states`, written into `next`, swapped.
struct Seam {
    states: Vec<SpringDisplacement<f64>>,
    next: Vec<SpringDisplacement<f64>>,
}

impl Seam {
    fn step<L: Law<Float = f64, State = SpringDisplacement<f64>>>(
        &mut self,
        table: &MaterialTable<L, 2>,
        time_step: TimeStep<f64>,
        spheres: &SphereArrays<'_, f64>,
        pairs: &[[u32; 2]],
        (force, torque): (&mut [Vec3<f64>], &mut [Vec3<f64>]),
    ) -> usize {
        let list = ContactList {
            pairs: CheckedPairs::new(pairs, &[], spheres.position.len()).unwrap(),
            pair_states: &self.states,
            walls: &[],
            wall_states: &[],
        };
        let out = ListOutput {
            force,
            torque,
            next_pair_states: &mut self.next,
            next_wall_states: &mut [],
            records: None,
        };
        let Ok(stats) = table.evaluate(time_step, spheres, list, out) else {
            return 0;
        };
        std::mem::swap(&mut self.states, &mut self.next);
        stats.pair_contacts
    }
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut args = std::env::args().skip(1);
    let (mut spheres, mut rounds) = (10_000, 15);
    while let Some(flag) = args.next() {
        let value = args.next().ok_or("a flag needs a value")?;
        match flag.as_str() {
            "--spheres" => spheres = value.parse()?,
            "--rounds" => rounds = value.parse()?,
            other => return Err(format!("unknown flag {other}").into()),
        }
    }
    let packing = Packing::new(spheres);
    let glass = LinearMaterial {
        normal_stiffness: 1.0e4,
        restitution: 0.7,
        tangential_stiffness: 8.0e3,
        dashpot_ratio: 0.5,
        friction: 0.3,
    };
    let soft = LinearMaterial {
        normal_stiffness: 2.0e3,
        friction: 0.6,
        ..glass
    };
    // Std's square root: the same bits as libm's, and one LLVM can widen (libm's is an SSE
    // instruction in inline assembly, which in an AVX build pays for every switch of state).
    let std_mixing = LinearMixing::new(ModelAA).with_backend::<Std>();
    let one_vector: MaterialTable<StdAA, 2> = MaterialTable::mixed(&std_mixing, &[glass, glass])?;
    let binary_vector: MaterialTable<StdAA, 2> = MaterialTable::mixed(&std_mixing, &[glass, soft])?;
    let n = packing.position.len();
    let alike = vec![0u32; n];
    let alternate: Vec<u32> = (0..n as u32).map(|k| k % 2).collect();
    let build = host_tests::build::describe();
    println!(
        "list_bench: {n} spheres, {} candidate pairs, f64 Model AA, {build}",
        packing.pairs.len()
    );
    println!("| route | materials | ns per candidate pair | ns per touching contact | same bits |");
    println!("|---|---|---|---|---|");
    let mut ratios = Vec::new();
    for (name, vector, material) in [
        ("one", &one_vector, &alike),
        ("two (binary mixture)", &binary_vector, &alternate),
    ] {
        let arrays = packing.arrays(material);
        let time_step = vector.time_step(1.0e-6, &arrays, &[])?;
        let pairs = &packing.pairs;
        let fresh = || vec![SpringDisplacement::default(); pairs.len()];
        let seam = || Seam {
            states: fresh(),
            next: fresh(),
        };
        let (mut single_states, mut scalar) = (fresh(), seam());
        // Bits first: a few steps from the same states.
        let mut same = true;
        let mut touching = 0;
        let zeros = || (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        for _ in 0..3 {
            let (mut a, mut b): (Outcome, Outcome) = (zeros(), zeros());
            touching = one_at_a_time(
                vector,
                time_step,
                &arrays,
                pairs,
                &mut single_states,
                (&mut a.0, &mut a.1),
            );
            let seen = scalar.step(vector, time_step, &arrays, pairs, (&mut b.0, &mut b.1));
            same &= seen == touching;
            same &= format!("{a:?}") == format!("{b:?}");
            same &= format!("{single_states:?}") == format!("{:?}", scalar.states);
        }
        let mut times = [Vec::new(), Vec::new()];
        let (mut force, mut torque) = zeros();
        let repeat = 20;
        let per_pair =
            |start: Instant| start.elapsed().as_secs_f64() * 1e9 / (repeat * pairs.len()) as f64;
        for _ in 0..rounds {
            let start = Instant::now();
            for _ in 0..repeat {
                black_box(one_at_a_time(
                    vector,
                    time_step,
                    &arrays,
                    pairs,
                    &mut single_states,
                    (&mut force, &mut torque),
                ));
            }
            times[0].push(per_pair(start));
            let start = Instant::now();
            for _ in 0..repeat {
                black_box(scalar.step(
                    vector,
                    time_step,
                    &arrays,
                    pairs,
                    (&mut force, &mut torque),
                ));
            }
            times[1].push(per_pair(start));
        }
        let per_contact = pairs.len() as f64 / touching.max(1) as f64;
        let [single, seam_one] = times.map(median);
        let yes = if same { "yes" } else { "no" };
        for (route, ns) in [
            ("caller's loop, one at a time", single),
            ("list seam, one at a time", seam_one),
        ] {
            println!(
                "| {route} | {name} | {ns:.1} | {:.1} | {yes} |",
                ns * per_contact
            );
        }
        ratios.push((name, single / seam_one, seam_one * per_contact));
        if name == "one" {
            phases(
                vector,
                &packing,
                material,
                (time_step, repeat, rounds),
                touching,
            );
        }
    }
    for (name, ratio, ns) in ratios {
        println!(
            "list seam over the caller's loop: {ratio:.2}x, {ns:.1} ns per touching contact ({name} material(s))"
        );
    }
    Ok(())
}

/// Where the seam's time goes, per touching contact (one material): the checks of every sphere
/// (`time_step` makes them alone), the whole call on the same list with the packing spread so
/// that nothing touches (checks, backup, sift, resets), and the whole call; the differences are
/// the phases.
fn phases(
    table: &MaterialTable<StdAA, 2>,
    packing: &Packing,
    material: &[u32],
    (time_step, repeat, rounds): (TimeStep<f64>, usize, usize),
    touching: usize,
) {
    let n = packing.position.len();
    let arrays = packing.arrays(material);
    let spread: Vec<_> = packing.position.iter().map(|&p| p * 2.0).collect();
    let apart = SphereArrays {
        position: &spread,
        ..packing.arrays(material)
    };
    let pairs = &packing.pairs;
    let mut seam = Seam {
        states: vec![SpringDisplacement::default(); pairs.len()],
        next: vec![SpringDisplacement::default(); pairs.len()],
    };
    let (mut force, mut torque) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    let mut times = [Vec::new(), Vec::new(), Vec::new()];
    let per_contact =
        |start: Instant| start.elapsed().as_secs_f64() * 1e9 / (repeat * touching) as f64;
    for _ in 0..rounds {
        let start = Instant::now();
        for _ in 0..repeat {
            black_box(table.time_step(1.0e-6, &arrays, &[]).is_ok());
        }
        times[0].push(per_contact(start));
        let start = Instant::now();
        for _ in 0..repeat {
            black_box(seam.step(table, time_step, &apart, pairs, (&mut force, &mut torque)));
        }
        times[1].push(per_contact(start));
        let start = Instant::now();
        for _ in 0..repeat {
            black_box(seam.step(table, time_step, &arrays, pairs, (&mut force, &mut torque)));
        }
        times[2].push(per_contact(start));
    }
    let [checks, nothing_touching, whole] = times.map(median);
    println!("where the seam's time goes, ns per touching contact (one material, one at a time):");
    println!(
        "| checking every sphere | backup, sift, resets | evaluating and adding the touching pairs | whole call |"
    );
    println!("|---|---|---|---|");
    println!(
        "| {checks:.1} | {:.1} | {:.1} | {whole:.1} |",
        nothing_touching - checks,
        whole - nothing_touching
    );
}
