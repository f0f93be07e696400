//! The fixed-loop scene (16 spheres, Model AA, f32) as Cortex-M4F firmware: static-size buffers,
//! no heap. It steps the scene, reports its energies and a bit-level fingerprint of the state over
//! semihosting, measures the stack each tangential law's contact call needs, and exits QEMU.
//!
//! Run: `cargo run --release` in this directory (needs `qemu-system-arm`); `tests/run.sh`
//! compares the output with the same scene stepped on the host.

#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use fixed_loop::BoxScene;
use panic_semihosting as _;
use soft_sphere::prelude::{
    ContactError, ContactLaw, Frictionless, Interaction, Libm, LinearLaw, LinearSpringDashpot,
    ModelA, ModelAA, ModelB, ModelC, Sphere, Stateless, TangentialModel, TangentialParameters,
    TimeStep, Vec3,
};

/// Steps of the scene compared with the host.
const STEPS: u32 = 20_000;

/// Per-law contact routines, kept out of line and by name so that their code size can be read
/// from the symbol table (`tests/run.sh`).
macro_rules! contact_routine {
    ($name:ident, $model:ty) => {
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $name(
            law: &ContactLaw<f32, LinearSpringDashpot<f32>, $model>,
            i: &Sphere<f32>,
            j: &Sphere<f32>,
            state: &mut <$model as TangentialModel<f32>>::State,
            dt: TimeStep<f32>,
        ) -> Result<Interaction<f32>, ContactError> {
            law.sphere_sphere(i, j, state, dt)
        }
    };
}

contact_routine!(ss_contact_frictionless, Frictionless);
contact_routine!(ss_contact_stateless, Stateless<f32>);
contact_routine!(ss_contact_model_c, ModelC<f32>);
contact_routine!(ss_contact_model_a, ModelA<f32>);
contact_routine!(ss_contact_model_b, ModelB<f32>);
contact_routine!(ss_contact_model_aa, ModelAA<f32>);

const PAINT: u32 = 0xDEAD_BEEF;
const PAINTED_BYTES: usize = 16 * 1024;

/// Stack bytes `f` uses below the caller's frame: paints the region below the stack pointer,
/// runs `f`, and finds the deepest word it overwrote.
#[inline(never)]
fn stack_used(f: impl FnOnce()) -> usize {
    let top = cortex_m::register::msp::read() as usize - 64;
    let bottom = top - PAINTED_BYTES;
    let mut address = bottom;
    while address < top {
        // SAFETY: the painted region lies inside RAM below the live stack (4 MiB of RAM, the
        // firmware needs a few KiB), and nothing else uses it.
        unsafe { core::ptr::write_volatile(address as *mut u32, PAINT) };
        address += 4;
    }
    f();
    let mut address = bottom;
    // SAFETY: as above, reading back the same region.
    while address < top && unsafe { core::ptr::read_volatile(address as *const u32) } == PAINT {
        address += 4;
    }
    top - address
}

fn pair() -> (Sphere<f32>, Sphere<f32>) {
    let i = Sphere::solid(Vec3::new(0.0, 0.0, 0.0), 1.0e-3, 2500.0);
    let mut j = Sphere::solid(Vec3::new(1.99e-3, 1.0e-5, 0.0), 1.0e-3, 2500.0);
    j.velocity = Vec3::new(-0.2, 0.05, 0.01);
    j.angular_velocity = Vec3::new(10.0, -30.0, 5.0);
    (i, j)
}

/// The signature of the per-law contact routines.
type Routine<T> = fn(
    &LinearLaw<f32, T>,
    &Sphere<f32>,
    &Sphere<f32>,
    &mut <T as TangentialModel<f32>>::State,
    TimeStep<f32>,
) -> Result<Interaction<f32>, ContactError>;

fn measure<T: TangentialModel<f32>>(name: &str, tangential: T, routine: Routine<T>) {
    let law = ContactLaw::new(LinearSpringDashpot::new(1000.0, 0.5).unwrap(), tangential);
    let (i, j) = pair();
    let m = i.mass / 2.0;
    let dt = law.time_step(law.recommended_time_step(m), m).unwrap();
    let mut state = T::State::default();
    let mut touching = false;
    let bytes = stack_used(|| {
        touching = matches!(
            routine(&law, &i, &j, &mut state, dt),
            Ok(Interaction::Touching(_))
        );
    });
    hprintln!("stack {} {} bytes (touching: {})", name, bytes, touching);
}

/// The scene loop, out of line so that its frame is inside the measured stack region.
#[inline(never)]
fn run_scene(scene: &mut BoxScene<Libm>) -> Result<(), ContactError> {
    for _ in 0..STEPS {
        scene.step()?;
    }
    Ok(())
}

#[entry]
fn main() -> ! {
    let p = TangentialParameters::new(300.0f32, 0.5, 0.5).unwrap();
    measure("frictionless", Frictionless, ss_contact_frictionless);
    measure("stateless", Stateless(p), ss_contact_stateless);
    measure("model_c", ModelC(p), ss_contact_model_c);
    measure("model_a", ModelA(p), ss_contact_model_a);
    measure("model_b", ModelB(p), ss_contact_model_b);
    measure("model_aa", ModelAA(p), ss_contact_model_aa);

    let mut scene = match BoxScene::<Libm>::new() {
        Ok(scene) => scene,
        Err(e) => {
            hprintln!("scene error {:?}", e);
            halt(debug::EXIT_FAILURE)
        }
    };
    let mut result = Ok(());
    let scene_stack = stack_used(|| result = run_scene(&mut scene));
    if let Err(e) = result {
        hprintln!("contact error {:?}", e);
        halt(debug::EXIT_FAILURE);
    }
    let s = scene.summary();
    hprintln!("stack scene_step {} bytes", scene_stack);
    hprintln!(
        "scene steps {} kinetic {:08x} potential {:08x} contacts {} fingerprint {:016x}",
        STEPS,
        s.kinetic_energy.to_bits(),
        s.potential_energy.to_bits(),
        s.pair_contacts,
        scene.fingerprint()
    );
    halt(debug::EXIT_SUCCESS)
}

/// Ends the QEMU session with `status`, then waits for interrupts forever (on hardware).
fn halt(status: debug::ExitStatus) -> ! {
    debug::exit(status);
    loop {
        cortex_m::asm::wfi();
    }
}
