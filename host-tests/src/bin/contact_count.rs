//! One contact's work, for an instruction counter: the bound law (`BoundLaw::sphere_sphere`, the
//! engines' path) evaluates the per-contact benchmark's 1024 touching pairs (`pairs.rs`) a fixed
//! number of rounds, each round in [`measured`], which `host-tests/speed/guard.sh` counts under
//! callgrind (`--toggle-collect`). The count per contact is the same on every run of one build.
//!
//! Usage: `contact_count [linear-aa|hertz-aa] [ROUNDS]`; prints the contacts evaluated.

use std::error::Error;
use std::hint::black_box;

use host_tests::pairs::touching_pairs;
use soft_sphere::prelude::{
    BoundLaw, CheckedSphere, ContactLaw, Hertz, HertzImpact, Interaction, Law, LinearSpringDashpot,
    MindlinAA, MindlinParameters, ModelAA, TangentialParameters, effective_mass,
};

/// A pair of checked spheres, body i then body j.
type CheckedPair<F> = (CheckedSphere<F>, CheckedSphere<F>);

/// The pairs per round.
const PAIRS: usize = 1024;

/// One round over every pair: the region the guard counts. Never inlined, so that callgrind sees
/// it as a function of its own.
#[inline(never)]
fn measured<L: Law>(
    bound: &mut BoundLaw<L>,
    pairs: &[CheckedPair<L::Float>],
    states: &mut [L::State],
) -> usize {
    let mut touching = 0;
    for ((i, j), state) in pairs.iter().zip(states.iter_mut()) {
        if let Ok(Interaction::Touching(c)) = bound.sphere_sphere(i, j, state) {
            black_box(&c);
            touching += 1;
        }
    }
    touching
}

fn run<L: Law<Float = f64>>(law: L, rounds: usize) -> Result<usize, Box<dyn Error>> {
    let pairs: Vec<_> = touching_pairs::<f64>(PAIRS)
        .into_iter()
        .map(|(i, j)| Ok((CheckedSphere::new(i)?, CheckedSphere::new(j)?)))
        .collect::<Result<_, soft_sphere::prelude::ContactError>>()?;
    let m = effective_mass(pairs[0].0.mass, pairs[0].1.mass);
    let mut bound = law.at(law.time_step(law.recommended_time_step(m), m)?);
    let mut states = vec![L::State::default(); PAIRS];
    let mut contacts = 0;
    for _ in 0..rounds {
        let touching = measured(&mut bound, &pairs, &mut states);
        if touching != PAIRS {
            return Err(format!("{touching} of {PAIRS} pairs pushed apart").into());
        }
        contacts += touching;
    }
    Ok(contacts)
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut args = std::env::args().skip(1);
    let which = args.next().unwrap_or_else(|| "linear-aa".into());
    let rounds: usize = args.next().map_or(Ok(20), |r| r.parse())?;
    let tangential = TangentialParameters::new(285.7, 0.5, 0.5)?;
    let contacts = match which.as_str() {
        "linear-aa" => run(
            ContactLaw::new(LinearSpringDashpot::new(1000.0, 0.9)?, ModelAA(tangential)),
            rounds,
        )?,
        "hertz-aa" => {
            let impact = HertzImpact {
                speed: 1.0,
                effective_radius: 1.0e-3,
            };
            let hertz = Hertz::new(5.0e5, 0.9, impact)?;
            let mindlin = MindlinParameters::new(2.0e5, 0.5, 0.5)?;
            run(ContactLaw::new(hertz, MindlinAA(mindlin)), rounds)?
        }
        other => return Err(format!("unknown law {other}: linear-aa or hertz-aa").into()),
    };
    println!("contacts evaluated: {contacts}");
    Ok(())
}
