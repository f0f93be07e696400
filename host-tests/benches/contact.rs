//! Per-contact cost: one contact evaluation (hot cache, 1024 independent touching pairs
//! per iteration) for every named law of the kernel's list, Models A, B and C and the rolling
//! slots x f32/f64 x math backend, and the slots a scene can switch
//! off (friction, rotation, damping), and what an engine's way of calling costs (the law, the
//! bound law checking its spheres, the bound law on checked spheres). Also prints the per-contact
//! state size.
//!
//! Run: `cargo bench -p host-tests --bench contact` (add `-- --quick` for a fast pass).

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use host_tests::pairs::touching_pairs;
use soft_sphere::prelude::{
    CheckedSphere, ConstantRolling, ContactLaw, ElasticPlasticRolling, Float, Frictionless, Hertz,
    HertzImpact, Interaction, Libm, LinearSpring, LinearSpringDashpot, MathBackend, MicroSlip,
    Micromath, MindlinAA, MindlinAALuding, MindlinParameters, MindlinStateless, ModelA, ModelAA,
    ModelAALuding, ModelB, ModelC, NormalModel, RollingModel, Rotation, Sphere, Stateless,
    TangentialModel, TangentialParameters, TimeStep, Vec3, Wall, effective_mass,
};

const BATCH: usize = 1024;

fn pairs<F: Float>() -> Vec<(Sphere<F>, Sphere<F>)> {
    touching_pairs(BATCH)
}

fn bench_law<F, N, T, M, R, Ro>(c: &mut Criterion, name: &str, law: ContactLaw<F, N, T, M, R, Ro>)
where
    F: Float,
    N: NormalModel<F>,
    T: TangentialModel<F>,
    M: MathBackend<F>,
    R: Rotation,
    Ro: RollingModel<F>,
{
    let pairs = pairs::<F>();
    let m = effective_mass(pairs[0].0.mass, pairs[0].1.mass);
    let dt: TimeStep<F> = law.time_step(law.recommended_time_step(m), m).unwrap();
    let mut states = [Ro::State::<T::State>::default(); BATCH];
    let mut group = c.benchmark_group("contact");
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function(name, |b| {
        b.iter(|| {
            let mut sum = F::ZERO;
            for ((i, j), state) in pairs.iter().zip(states.iter_mut()) {
                if let Ok(Interaction::Touching(f)) = law.sphere_sphere(i, j, state, dt) {
                    sum += f.normal_force;
                }
            }
            black_box(sum)
        });
    });
    group.finish();
}

/// The tangential slot of a named law, made from its family's parameters (`p` for the linear
/// spring-dashpot, `mindlin` for Hertz).
macro_rules! slot {
    ($normal:ident, Frictionless, $F:ty) => {
        Frictionless
    };
    (Hertz, MicroSlip, $F:ty) => {
        MicroSlip::<$F, 16>::new(mindlin::<$F>())
    };
    (Hertz, $tangential:ident, $F:ty) => {
        $tangential(mindlin::<$F>())
    };
    (LinearSpringDashpot, $tangential:ident, $F:ty) => {
        $tangential(linear_tangential::<$F>())
    };
}

/// Every law of the kernel's list (`soft_sphere::for_each_law!`), timed under its name.
macro_rules! named_laws {
    ($($alias:ident = $name:literal, $normal:ident, $tangential:ident;)*) => {
        /// Times every named law in precision `$F` with backend `$M`.
        macro_rules! every_named_law {
            ($c:expr, $F:ty, $M:ty, $label:expr) => {{
                $(
                    bench_law(
                        $c,
                        &format!("{}/{}", $name, $label),
                        ContactLaw::new(normal_slot!($normal, $F), slot!($normal, $tangential, $F))
                            .with_backend::<$M>(),
                    );
                )*
            }};
        }
    };
}
soft_sphere::for_each_law!(named_laws);

/// The normal slot of a named law.
macro_rules! normal_slot {
    (LinearSpringDashpot, $F:ty) => {
        LinearSpringDashpot::new(1000.0 as $F, 0.9 as $F).unwrap()
    };
    (Hertz, $F:ty) => {
        hertz::<$F>()
    };
}

fn linear_tangential<F: Float>() -> TangentialParameters<F> {
    TangentialParameters::new(F::from_f64(285.7), F::from_f64(0.5), F::from_f64(0.5)).unwrap()
}

fn mindlin<F: Float>() -> MindlinParameters<F> {
    MindlinParameters::new(F::from_f64(2.0e5), F::from_f64(0.5), F::from_f64(0.5)).unwrap()
}

fn hertz<F: Float>() -> Hertz<F> {
    let largest = HertzImpact {
        speed: F::from_f64(1.0),
        effective_radius: F::from_f64(1.0e-3),
    };
    Hertz::new(F::from_f64(5.0e5), F::from_f64(0.9), largest).unwrap()
}

/// Every named law, then Models C, A and B (the laws Elghannay & Tafti compare), then Model AA
/// with each rolling slot.
macro_rules! every_law {
    ($c:expr, $F:ty, $M:ty, $label:expr) => {{
        every_named_law!($c, $F, $M, $label);
        let normal = LinearSpringDashpot::new(1000.0 as $F, 0.9 as $F).unwrap();
        let p = linear_tangential::<$F>();
        let with = |name: &str| format!("{name}/{}", $label);
        bench_law(
            $c,
            &with("model_c"),
            ContactLaw::new(normal, ModelC(p)).with_backend::<$M>(),
        );
        bench_law(
            $c,
            &with("model_a"),
            ContactLaw::new(normal, ModelA(p)).with_backend::<$M>(),
        );
        bench_law(
            $c,
            &with("model_b"),
            ContactLaw::new(normal, ModelB(p)).with_backend::<$M>(),
        );
        bench_law(
            $c,
            &with("aa_constant_rolling"),
            ContactLaw::new(normal, ModelAA(p))
                .with_rolling(ConstantRolling::new(0.1 as $F).unwrap())
                .with_backend::<$M>(),
        );
        let epsd =
            ElasticPlasticRolling::new(0.1 as $F, 1.0e-4 as $F, 0.0 as $F, 1.0e-9 as $F).unwrap();
        bench_law(
            $c,
            &with("aa_epsd_rolling"),
            ContactLaw::new(normal, ModelAA(p))
                .with_rolling(epsd)
                .with_backend::<$M>(),
        );
    }};
}

fn laws(c: &mut Criterion) {
    every_law!(c, f64, Libm, "f64_libm");
    every_law!(c, f32, Libm, "f32_libm");
    every_law!(c, f32, Micromath, "f32_micromath");
}

/// Micro-slip at 4 to 32 breakpoints beside Hertz-Mindlin's single spring and the linear Model AA,
/// in f64 and f32: the cost side of the spring count (the error side is the validation run's
/// `microslip_loops.csv` and `chung_ooi_test5_micro_slip_springs` tables).
macro_rules! micro_slip_laws {
    ($c:expr, $F:ty, $label:expr) => {{
        let largest = HertzImpact {
            speed: 1.0 as $F,
            effective_radius: 1.0e-3 as $F,
        };
        let hertz = Hertz::new(5.0e5 as $F, 0.9 as $F, largest).unwrap();
        let mindlin = MindlinParameters::new(2.0e5 as $F, 0.5 as $F, 0.5 as $F).unwrap();
        let with = |name: &str| format!("micro_slip/{name}/{}", $label);
        bench_law(
            $c,
            &with("aa"),
            ContactLaw::new(
                LinearSpringDashpot::new(1000.0 as $F, 0.9 as $F).unwrap(),
                ModelAA(TangentialParameters::new(285.7 as $F, 0.5 as $F, 0.5 as $F).unwrap()),
            ),
        );
        bench_law(
            $c,
            &with("hertz/aa"),
            ContactLaw::new(hertz, MindlinAA(mindlin)),
        );
        bench_law(
            $c,
            &with("springs_04"),
            ContactLaw::new(hertz, MicroSlip::<$F, 4>::new(mindlin)),
        );
        bench_law(
            $c,
            &with("springs_08"),
            ContactLaw::new(hertz, MicroSlip::<$F, 8>::new(mindlin)),
        );
        bench_law(
            $c,
            &with("springs_16"),
            ContactLaw::new(hertz, MicroSlip::<$F, 16>::new(mindlin)),
        );
        bench_law(
            $c,
            &with("springs_32"),
            ContactLaw::new(hertz, MicroSlip::<$F, 32>::new(mindlin)),
        );
    }};
}

fn micro_slip(c: &mut Criterion) {
    micro_slip_laws!(c, f64, "f64");
    micro_slip_laws!(c, f32, "f32");
}

fn skipping(c: &mut Criterion) {
    let normal = LinearSpringDashpot::new(1000.0f64, 0.9).unwrap();
    let p = TangentialParameters::new(285.7f64, 0.5, 0.5).unwrap();
    bench_law(c, "skip/full_aa_f64", ContactLaw::new(normal, ModelAA(p)));
    bench_law(
        c,
        "skip/non_rotating_aa_f64",
        ContactLaw::new(normal, ModelAA(p)).without_rotation(),
    );
    bench_law(
        c,
        "skip/frictionless_non_rotating_f64",
        ContactLaw::new(normal, Frictionless).without_rotation(),
    );
    let undamped = TangentialParameters::new(285.7f64, 0.0, 0.5).unwrap();
    bench_law(
        c,
        "skip/undamped_aa_f64",
        ContactLaw::new(LinearSpring::new(1000.0f64).unwrap(), ModelAA(undamped)),
    );
    // What a scene without walls saves: one wall check per sphere and step, for the spheres away
    // from the wall (nearly all of a deep bed).
    let floor = Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap();
    let law = ContactLaw::new(normal, ModelAA(p));
    let spheres: Vec<Sphere<f64>> = pairs::<f64>()
        .into_iter()
        .map(|(_, mut j)| {
            j.position.z += 0.01;
            j
        })
        .collect();
    let dt = law
        .time_step(law.recommended_time_step(spheres[0].mass), spheres[0].mass)
        .unwrap();
    let mut group = c.benchmark_group("contact");
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function("skip/wall_check_away_from_wall_f64", |b| {
        let mut states = [Default::default(); BATCH];
        b.iter(|| {
            let mut touching = 0usize;
            for (s, state) in spheres.iter().zip(states.iter_mut()) {
                if let Ok(Interaction::Touching(_)) = law.sphere_wall(s, &floor, state, dt) {
                    touching += 1;
                }
            }
            black_box(touching)
        });
    });
    group.finish();
    println!(
        "per-contact state: Model A/B/AA {} bytes (f64), {} bytes (f32); stateless, C, frictionless {} bytes",
        size_of::<<ModelAA<f64> as TangentialModel<f64>>::State>(),
        size_of::<<ModelAA<f32> as TangentialModel<f32>>::State>(),
        size_of::<<Stateless<f64> as TangentialModel<f64>>::State>(),
    );
}

/// What an engine's way of calling costs, Model AA f64: the law checking both spheres and deriving
/// the pair's oscillator at every call, the bound law with the spheres checked at every call (what
/// a C host's call does), and the bound law on spheres checked once (the scene).
fn paths(c: &mut Criterion) {
    let normal = LinearSpringDashpot::new(1000.0f64, 0.9).unwrap();
    let p = TangentialParameters::new(285.7f64, 0.5, 0.5).unwrap();
    let law = ContactLaw::new(normal, ModelAA(p));
    let pairs = pairs::<f64>();
    let m = effective_mass(pairs[0].0.mass, pairs[0].1.mass);
    let dt = law.time_step(law.recommended_time_step(m), m).unwrap();
    let checked: Vec<_> = pairs
        .iter()
        .map(|&(i, j)| {
            (
                CheckedSphere::new(i).unwrap(),
                CheckedSphere::new(j).unwrap(),
            )
        })
        .collect();
    let mut group = c.benchmark_group("contact");
    group.throughput(Throughput::Elements(BATCH as u64));
    let mut states = [Default::default(); BATCH];
    group.bench_function("path/unbound_aa_f64", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for ((i, j), state) in pairs.iter().zip(states.iter_mut()) {
                if let Ok(Interaction::Touching(f)) = law.sphere_sphere(i, j, state, dt) {
                    sum += f.normal_force;
                }
            }
            black_box(sum)
        });
    });
    group.bench_function("path/bound_checking_spheres_aa_f64", |b| {
        b.iter(|| {
            let mut bound = law.at(dt);
            let mut sum = 0.0;
            for ((i, j), state) in pairs.iter().zip(states.iter_mut()) {
                let Ok(i) = CheckedSphere::new(*i) else {
                    continue;
                };
                let Ok(j) = CheckedSphere::new(*j) else {
                    continue;
                };
                if let Ok(Interaction::Touching(f)) = bound.sphere_sphere(&i, &j, state) {
                    sum += f.normal_force;
                }
            }
            black_box(sum)
        });
    });
    group.bench_function("path/bound_aa_f64", |b| {
        b.iter(|| {
            let mut bound = law.at(dt);
            let mut sum = 0.0;
            for ((i, j), state) in checked.iter().zip(states.iter_mut()) {
                if let Ok(Interaction::Touching(f)) = bound.sphere_sphere(i, j, state) {
                    sum += f.normal_force;
                }
            }
            black_box(sum)
        });
    });
    group.finish();
}

criterion_group!(benches, laws, micro_slip, skipping, paths);
criterion_main!(benches);
