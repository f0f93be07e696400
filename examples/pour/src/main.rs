//! Spheres of three materials poured into a box, to rest, written as frames ParaView opens.
//!
//! ```text
//! cargo run --release -p pour -- --out DIR [--spheres N] [--time SECONDS] [--every SECONDS]
//! ```
//!
//! A stiff glass-like, a heavy steel-like and a soft polymer-like material (radii 0.5-2 mm)
//! fall from a loose lattice into a box whose floor and four side walls are of a fourth
//! material, under the Hertz-Mindlin law with Model AA's tangential spring, every pair of
//! materials mixed by the Hertz-Mindlin rules. Every `--every` seconds of simulated time
//! (default 5 ms) the scene is written to `DIR` (`pour.pvd` and its frames; see
//! `soft_sphere_scene::Frames`); at the end the energy account and the load the walls carry
//! are printed. `examples/pour/picture.py` draws the last frame.
//!
//! The Young's moduli are a thousandth of the real materials' (the usual softening of DEM
//! practice, which keeps the contacts' duration, and so the step, a few hundred times the
//! step a real modulus would need); densities, Poisson's ratios and friction are the real ones.

use std::path::PathBuf;
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressStyle};
use soft_sphere::prelude::{
    ElasticMaterial, HertzAA, HertzImpact, HertzMixing, Material, MaterialTable, MaterialWall,
    MindlinAA, Sphere, Vec3, Wall,
};
use soft_sphere_scene::{ContactBodies, Domain, Energy, Frames, Integrator, OwnedScene, StepInput};

/// The box's inner width along x and y (m).
const WIDTH: f64 = 0.03;
/// The box's height (m): the top of the pour's lattice, with room.
const HEIGHT: f64 = 0.07;
/// The smallest and the largest radius (m).
const RADII: [f64; 2] = [0.5e-3, 2.0e-3];
/// Standard gravity (m/s^2).
const GRAVITY: f64 = 9.81;

/// What each material is: its name (for the printout), density and contact properties.
struct Kind {
    name: &'static str,
    density: f64,
    material: ElasticMaterial<f64>,
}

/// Glass, steel, polymer, and the box's own material (aluminium-like).
fn kinds() -> [Kind; 4] {
    let kind = |name, density, youngs_modulus, poisson_ratio, restitution, friction| Kind {
        name,
        density,
        material: ElasticMaterial {
            elasticity: Material::new(youngs_modulus, poisson_ratio).expect("a valid material"),
            restitution,
            dashpot_ratio: 0.5,
            friction,
        },
    };
    [
        kind("glass", 2500.0, 63.0e6, 0.22, 0.9, 0.3),
        kind("steel", 7800.0, 208.0e6, 0.30, 0.8, 0.25),
        kind("polymer", 1150.0, 2.5e6, 0.40, 0.6, 0.45),
        kind("box", 2700.0, 70.0e6, 0.33, 0.8, 0.3),
    ]
}

/// The box's material id.
const BOX: u32 = 3;

/// What the command line asks for.
struct Options {
    out: PathBuf,
    spheres: usize,
    time: f64,
    every: f64,
}

fn options() -> Result<Options, String> {
    let mut options = Options {
        out: PathBuf::new(),
        spheres: 600,
        time: 0.6,
        every: 0.005,
    };
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let value = args.next().ok_or(format!("{flag} needs a value"))?;
        let number = || {
            value
                .parse::<f64>()
                .map_err(|_| format!("{flag}: not a number"))
        };
        match flag.as_str() {
            "--out" => options.out = PathBuf::from(&value),
            "--spheres" => {
                options.spheres = value.parse().map_err(|_| "--spheres: not a count")?;
            }
            "--time" => options.time = number()?,
            "--every" => options.every = number()?,
            _ => return Err(format!("unknown flag {flag}")),
        }
    }
    if options.out.as_os_str().is_empty() {
        return Err("--out DIR is required".into());
    }
    let positive = |x: f64| x.is_finite() && x > 0.0;
    if !(positive(options.time) && positive(options.every) && options.spheres > 0) {
        return Err("--spheres, --time and --every must be positive".into());
    }
    Ok(options)
}

/// A small deterministic generator (xorshift64*): the same pour on every run.
struct Random(u64);

impl Random {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The spheres on a loose lattice (one largest diameter and a gap apart), each of a random
/// material and radius, with a small random velocity so that the pour is not a lattice's.
fn lattice(count: usize, kinds: &[Kind]) -> Result<(Vec<Sphere<f64>>, Vec<u32>), String> {
    let pitch = 2.0 * RADII[1] * 1.05;
    let across = ((WIDTH - pitch) / pitch).floor() as usize + 1;
    let layers = count.div_ceil(across * across);
    let top = RADII[1] * 2.0 + (layers - 1) as f64 * pitch;
    if top + RADII[1] >= HEIGHT {
        return Err(format!("{count} spheres do not fit the box's lattice"));
    }
    let mut random = Random(0x9e37_79b9_7f4a_7c15);
    let mut spheres = Vec::with_capacity(count);
    let mut materials = Vec::with_capacity(count);
    for k in 0..count {
        let (layer, place) = (k / (across * across), k % (across * across));
        let at =
            |cell: usize| pitch / 2.0 + cell as f64 * pitch + (WIDTH - across as f64 * pitch) / 2.0;
        let position = Vec3::new(
            at(place % across),
            at(place / across),
            2.0 * RADII[1] + layer as f64 * pitch,
        );
        let material = (random.unit() * 3.0) as u32;
        let radius = RADII[0] + random.unit() * (RADII[1] - RADII[0]);
        let mut sphere = Sphere::solid(position, radius, kinds[material as usize].density);
        let mut jitter = || (random.unit() - 0.5) * 0.1;
        sphere.velocity = Vec3::new(jitter(), jitter(), jitter());
        spheres.push(sphere);
        materials.push(material);
    }
    Ok((spheres, materials))
}

/// The floor and the four side walls, of the box's material, their normals into the box.
fn walls() -> [MaterialWall<f64>; 5] {
    let wall = |point: [f64; 3], normal: [f64; 3]| MaterialWall {
        wall: Wall::new(point.into(), normal.into()).expect("a valid wall"),
        material: BOX,
    };
    [
        wall([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        wall([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
        wall([WIDTH, 0.0, 0.0], [-1.0, 0.0, 0.0]),
        wall([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        wall([0.0, WIDTH, 0.0], [0.0, -1.0, 0.0]),
    ]
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("pour: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<(), String> {
    let options = options()?;
    let kinds = kinds();
    // Every pair's Hertz law is declared for impacts up to 2 m/s (the pour lands at about
    // 1 m/s) at the largest effective radius, a largest sphere against a wall.
    let largest = HertzImpact {
        speed: 2.0,
        effective_radius: RADII[1],
    };
    let mixing = HertzMixing::new(largest, MindlinAA);
    let table: MaterialTable<HertzAA<f64>, 4> =
        MaterialTable::mixed(&mixing, &kinds.each_ref().map(|k| k.material))
            .map_err(|e| format!("materials: {e:?}"))?;

    let (spheres, materials) = lattice(options.spheres, &kinds)?;
    let domain = Domain {
        lower: Vec3::ZERO,
        upper: Vec3::new(WIDTH, WIDTH, HEIGHT),
        periodic_x: false,
        periodic_y: false,
    };
    // A skin of a smallest radius: the list is rebuilt every few tens of steps while the spheres
    // fall, rarely once they rest.
    let skin = RADII[0];
    let mut scene = OwnedScene::new(spheres, domain, skin, walls())
        .and_then(|scene| scene.with_materials(materials))
        .map_err(|e| format!("scene: {e:?}"))?
        .with_records();

    // The largest step every pair of materials present recommends, checked.
    let time_step = scene
        .scene(|s| {
            let seconds = s.recommended_time_step(&table)?.expect("spheres present");
            s.time_step(&table, seconds)
        })
        .and_then(|checked| checked)
        .map_err(|e| format!("time step: {e:?}"))?;
    let dt = time_step.seconds();
    let input = StepInput {
        table: &table,
        gravity: Vec3::new(0.0, 0.0, -GRAVITY),
        time_step,
        integrator: Integrator::VelocityVerlet,
    };
    let per_frame = ((options.every / dt).round() as usize).max(1);
    let frames_total = (options.time / (per_frame as f64 * dt)).ceil() as u64;
    println!(
        "{} spheres, step {dt:.3e} s, a frame every {per_frame} steps, {frames_total} frames",
        options.spheres
    );

    let mut frames = Frames::create(&options.out, "pour").map_err(|e| format!("{e}"))?;
    let bar = ProgressBar::new(frames_total).with_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} frames, {elapsed} {msg}")
            .expect("a valid template"),
    );
    let (mut first, mut energy, mut carried) = (None, None, 0.0);
    for frame in 0..frames_total {
        let written = scene
            .scene(|s| {
                for _ in 0..per_frame {
                    energy = s.step(&input)?.energy;
                    first = first.or(energy);
                }
                // What the walls hold up: the vertical force they put on the spheres.
                carried = s
                    .contacts()
                    .filter(|c| matches!(c.bodies, ContactBodies::Wall { .. }))
                    .map(|c| c.forces.force_on_i().z)
                    .sum();
                let time = (frame + 1) as f64 * per_frame as f64 * dt;
                Ok(frames.write(s, time))
            })
            .and_then(|stepped| stepped)
            .map_err(|e: soft_sphere_scene::StepError| format!("step: {e:?}"))?;
        written.map_err(|e| format!("writing a frame: {e}"))?;
        if let Some(energy) = energy {
            bar.set_message(format!("kinetic {:.2e} J", energy.kinetic));
        }
        bar.inc(1);
    }
    bar.finish();
    report(&scene, &kinds, first.zip(energy), carried);
    println!("wrote {}", frames.collection().display());
    Ok(())
}

/// The energy account and what the walls carry, at the end.
fn report(
    scene: &OwnedScene<HertzAA<f64>, [MaterialWall<f64>; 5]>,
    kinds: &[Kind],
    energy: Option<(Energy<f64>, Energy<f64>)>,
    carried: f64,
) {
    for (id, kind) in kinds.iter().enumerate().take(3) {
        let count = scene
            .materials()
            .iter()
            .filter(|&&m| m == id as u32)
            .count();
        println!("{:>8}: {count} spheres", kind.name);
    }
    if let Some((first, e)) = energy {
        // The balance is constant to the integrator's error: its change since the first step.
        let drift = e.balance() - first.balance();
        println!(
            "energy (J): kinetic {:.3e}, rotational {:.3e}, stored {:.3e}, gravity's work {:.3e}",
            e.kinetic, e.rotational, e.stored, e.gravity_work
        );
        println!(
            "            dissipated by dashpots {:.3e}, by sliding {:.3e}; the balance moved {drift:.2e} ({:.1e} of gravity's work)",
            e.dissipated_dashpots,
            e.dissipated_sliding,
            drift.abs() / e.gravity_work.abs()
        );
    }
    let weight: f64 = scene.spheres().iter().map(|s| s.mass * GRAVITY).sum();
    println!(
        "the walls carry {carried:.6e} N of the spheres' weight {weight:.6e} N ({:+.2e})",
        carried / weight - 1.0
    );
}
