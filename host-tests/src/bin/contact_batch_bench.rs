//! The batch path against the one-contact law, on the same touching pairs in one process: the
//! one-contact law as a C host's call runs it today (the bound law, libm, both spheres checked
//! at every call) and `BoundLaw::sphere_pairs` in blocks of `soft_sphere::batch::LANES`
//! (the `Std` backend, every lane checked), hot cache, the blocks gathered beforehand. Rounds
//! alternate between the two, and the ratio is of the medians, so the machine's drift cancels.
//! Before timing it runs both from the same states for a few steps and compares every result and
//! state bit for bit.
//!
//! Prints one row per law (blocks of `LANES` for f64, `2 * LANES` for f32, and twice that for
//! Model AA), and as its last line
//! `batch speed-up over the scalar law: X.XX (f64 model AA, N contacts, same bits: yes|no)`.
//!
//! Usage: `cargo run --release -p host-tests --bin contact_batch_bench -- [--pairs 1024]
//! [--rounds 31]`; build for the machine with `RUSTFLAGS="-C target-cpu=x86-64-v3"` (docs/performance.md,
//! "Builds for your CPU").

use std::error::Error;
use std::hint::black_box;
use std::time::Instant;

use host_tests::pairs::{Pair, blocks, in_blocks, one_at_a_time, touching_pairs};
use soft_sphere::batch::{ContactBlock, LANES};
use soft_sphere::{
    CheckedSphere, ContactLaw, Float, Frictionless, Interaction, Law, LinearSpringDashpot, ModelAA,
    Stateless, Std, TangentialParameters, TimeStep, effective_mass,
};

/// What one law's timing found.
struct Row {
    scalar_ns: f64,
    batch_ns: f64,
    same_bits: bool,
    sliding: f64,
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// Times `scalar` (the one-contact law) against `batch` (the same law on `Std`, in blocks of `N`).
fn compare<S: Law, B: Law<Float = S::Float, State = S::State>, const N: usize>(
    scalar: &S,
    batch: &B,
    time_step: (TimeStep<S::Float>, TimeStep<S::Float>),
    pairs: &[Pair<S::Float>],
    rounds: usize,
) -> Row {
    // Bits first: a few steps from the same states, so stored springs are exercised.
    let mut scalar_states = vec![S::State::default(); pairs.len()];
    let mut batch_states = scalar_states.clone();
    let mut same_bits = true;
    let mut sliding = 0;
    for _ in 0..4 {
        let a = one_at_a_time(scalar, time_step.0, pairs, &mut scalar_states);
        let b = in_blocks::<_, N>(batch, time_step.1, pairs, &mut batch_states);
        same_bits &= format!("{a:?}") == format!("{b:?}");
        same_bits &= format!("{scalar_states:?}") == format!("{batch_states:?}");
        sliding = a
            .iter()
            .filter(|r| matches!(r, Ok(Interaction::Touching(f)) if f.sliding))
            .count();
    }

    let gathered = blocks::<_, N>(pairs);
    let mut block_states = vec![[B::State::default(); N]; gathered.len()];
    let repeat = 200;
    let (mut scalar_ns, mut batch_ns) = (Vec::new(), Vec::new());
    let per_contact =
        |start: Instant| start.elapsed().as_secs_f64() * 1e9 / (repeat * pairs.len()) as f64;
    for _ in 0..rounds {
        let start = Instant::now();
        for _ in 0..repeat {
            black_box(scalar_pass(scalar, time_step.0, pairs, &mut scalar_states));
        }
        scalar_ns.push(per_contact(start));

        let start = Instant::now();
        let mut bound = batch.at(time_step.1);
        let mut out = ContactBlock::default();
        for _ in 0..repeat {
            let mut sum = <S::Float as Float>::ZERO;
            for (block, states) in gathered.iter().zip(block_states.iter_mut()) {
                bound.sphere_pairs(block, states, &mut out);
                sum += out.normal_force[0];
            }
            black_box(sum);
        }
        batch_ns.push(per_contact(start));
    }
    Row {
        scalar_ns: median(scalar_ns),
        batch_ns: median(batch_ns),
        same_bits,
        sliding: sliding as f64 / pairs.len() as f64,
    }
}

/// The one-contact loop a C host runs today: the bound law, both spheres checked, one pair at a
/// time.
fn scalar_pass<L: Law>(
    law: &L,
    time_step: TimeStep<L::Float>,
    pairs: &[Pair<L::Float>],
    states: &mut [L::State],
) -> L::Float {
    let mut bound = law.at(time_step);
    let mut sum = <L::Float as Float>::ZERO;
    for ((i, j), state) in pairs.iter().zip(states.iter_mut()) {
        let (Ok(i), Ok(j)) = (CheckedSphere::new(*i), CheckedSphere::new(*j)) else {
            continue;
        };
        if let Ok(Interaction::Touching(f)) = bound.sphere_sphere(&i, &j, state) {
            sum += f.normal_force;
        }
    }
    sum
}

fn time_steps<L: Law>(a: &L, b: &L, mass: L::Float) -> (TimeStep<L::Float>, TimeStep<L::Float>) {
    let seconds = a.recommended_time_step(mass);
    (
        a.time_step(seconds, mass).unwrap(),
        b.time_step(seconds, mass).unwrap(),
    )
}

fn main() -> Result<(), Box<dyn Error>> {
    let (mut count, mut rounds) = (1024, 31);
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        let mut value = || args.next().ok_or(format!("{arg} needs a value"));
        match arg.as_str() {
            "--pairs" => count = value()?.parse()?,
            "--rounds" => rounds = value()?.parse()?,
            _ => return Err(format!("unknown argument {arg}").into()),
        }
    }
    if count == 0 || rounds == 0 {
        return Err("--pairs and --rounds must be positive".into());
    }
    let build = host_tests::build::describe();
    println!(
        "build: {build}; {LANES} f64 lanes a block, {} f32 lanes",
        2 * LANES
    );
    println!(
        "{:<22} {:>12} {:>12} {:>9} {:>9} {:>10}",
        "law", "scalar ns", "batch ns", "speed-up", "sliding", "same bits"
    );
    let print = |name: &str, row: &Row| {
        println!(
            "{name:<22} {:>12.2} {:>12.2} {:>9.2} {:>8.0}% {:>10}",
            row.scalar_ns,
            row.batch_ns,
            row.scalar_ns / row.batch_ns,
            100.0 * row.sliding,
            if row.same_bits { "yes" } else { "no" }
        )
    };

    let pairs64 = touching_pairs::<f64>(count);
    let pairs32 = touching_pairs::<f32>(count);
    let m64 = effective_mass(pairs64[0].0.mass, pairs64[0].1.mass);
    let m32 = effective_mass(pairs32[0].0.mass, pairs32[0].1.mass);
    let normal64 = LinearSpringDashpot::new(1000.0, 0.9)?;
    let normal32 = LinearSpringDashpot::new(1000.0f32, 0.9)?;
    let p64 = TangentialParameters::new(285.7, 0.5, 0.5)?;
    let p32 = TangentialParameters::new(285.7f32, 0.5, 0.5)?;

    let aa64 = ContactLaw::new(normal64, ModelAA(p64));
    let aa64_std = aa64.with_backend::<Std>();
    let aa32 = ContactLaw::new(normal32, ModelAA(p32));
    let aa32_std = aa32.with_backend::<Std>();
    let stateless = ContactLaw::new(normal64, Stateless(p64));
    let frictionless = ContactLaw::new(normal64, Frictionless);

    let dt = time_steps(&aa32, &aa32, m32);
    let row = compare::<_, _, { 2 * LANES }>(&aa32, &aa32_std, dt, &pairs32, rounds);
    print("model_aa f32", &row);
    let dt = time_steps(&stateless, &stateless, m64);
    let row = compare::<_, _, LANES>(
        &stateless,
        &stateless.with_backend::<Std>(),
        dt,
        &pairs64,
        rounds,
    );
    print("stateless f64", &row);
    let dt = time_steps(&frictionless, &frictionless, m64);
    let row = compare::<_, _, LANES>(
        &frictionless,
        &frictionless.with_backend::<Std>(),
        dt,
        &pairs64,
        rounds,
    );
    print("frictionless f64", &row);
    // Twice the lanes: what AVX-512 at full width (-C target-feature=-prefer-256-bit) prefers.
    let dt = time_steps(&aa32, &aa32, m32);
    let row = compare::<_, _, { 4 * LANES }>(&aa32, &aa32_std, dt, &pairs32, rounds);
    print(&format!("model_aa f32, {} lanes", 4 * LANES), &row);
    let dt = time_steps(&aa64, &aa64, m64);
    let row = compare::<_, _, { 2 * LANES }>(&aa64, &aa64_std, dt, &pairs64, rounds);
    print(&format!("model_aa f64, {} lanes", 2 * LANES), &row);
    let row = compare::<_, _, LANES>(&aa64, &aa64_std, dt, &pairs64, rounds);
    print("model_aa f64", &row);
    println!(
        "batch speed-up over the scalar law: {:.2} (f64 model AA, {count} contacts, same bits: {})",
        row.scalar_ns / row.batch_ns,
        if row.same_bits { "yes" } else { "no" }
    );
    Ok(())
}
