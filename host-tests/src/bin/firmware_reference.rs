//! The firmware example's scene stepped on the host with the same code, printed in the
//! firmware's format, so that `examples/firmware/run.sh` can compare the Cortex-M4F run with it
//! bit for bit.
//!
//! Usage: `cargo run --release -p host-tests --bin firmware_reference -- STEPS`.

use std::process::ExitCode;

use fixed_loop::BoxScene;
use soft_sphere::prelude::Libm;

fn main() -> ExitCode {
    let steps: u32 = match std::env::args().nth(1).map(|a| a.parse()) {
        Some(Ok(steps)) => steps,
        _ => {
            eprintln!("usage: firmware_reference STEPS");
            return ExitCode::from(2);
        }
    };
    let mut scene = match BoxScene::<Libm>::new() {
        Ok(scene) => scene,
        Err(e) => {
            eprintln!("scene error {e:?}");
            return ExitCode::FAILURE;
        }
    };
    for _ in 0..steps {
        if let Err(e) = scene.step() {
            eprintln!("contact error {e:?}");
            return ExitCode::FAILURE;
        }
    }
    let s = scene.summary();
    println!(
        "scene steps {steps} kinetic {:08x} potential {:08x} contacts {} fingerprint {:016x}",
        s.kinetic_energy.to_bits(),
        s.potential_energy.to_bits(),
        s.pair_contacts,
        scene.fingerprint()
    );
    ExitCode::SUCCESS
}
