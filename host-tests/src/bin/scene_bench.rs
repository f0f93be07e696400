//! The reference scene, timed: a settled column of spheres on a floor, periodic in x
//! and y, stepped 10,000 times at dt = 2e-6 s (k_n = 1000 N/m, k_t = 2/7 k_n, e = 0.9, eta_t =
//! eta_n / 2, mu = 0.5, Model AA, f64), one thread. Prints the loop time (min/median/max over
//! repeats), particle-steps per second, and the physics at the end (kinetic energy, contacts per
//! particle, mean overlap). Writes the settled packing and a LAMMPS deck for the same physics with
//! `--lammps DIR`.
//!
//! Usage: `cargo run --release -p host-tests --bin scene_bench -- [--spheres 10000|50000]
//! [--steps 10000] [--repeat 3] [--integrator euler|verlet] [--variant full|frictionless|
//! non-rotating|undamped|no-walls|mixture] [--threads N] [--lammps DIR]`. Without `--threads`
//! the step is the scene's serial one; with it, the integration is spread over a rayon pool of
//! N threads (the same bits). `mixture` makes half the spheres a second material, twice as
//! stiff with 0.6 of the friction.

use std::error::Error;
use std::path::PathBuf;
use std::time::Instant;

use host_tests::scene::{
    Column, OwnedScene, SceneExt, Threads, pair_and_wall, positions_csv, wall_of,
    wall_restitution_for_same_dashpot, write_lammps_data,
};
use soft_sphere::prelude::{
    ContactLaw, Frictionless, Law, LinearMaterial, LinearMixing, LinearSpring, LinearSpringDashpot,
    MaterialTable, MaterialWall, ModelAA, Sphere, Std, TangentialParameters, Vec3, Wall,
};
use soft_sphere_scene::{Integrator, NoWalls, StepInput, StepStats, WallSet};

const NORMAL_STIFFNESS: f64 = 1000.0;
const RESTITUTION: f64 = 0.9;
const FRICTION: f64 = 0.5;
const DASHPOT_RATIO: f64 = 0.5;
const TIME_STEP: f64 = 2e-6;
const GRAVITY: f64 = 9.81;
/// Verlet-list skin, the same as LAMMPS's `neighbor 1e-4 bin`.
const SKIN: f64 = 1e-4;

struct Options {
    column: Column,
    steps: usize,
    repeat: usize,
    integrator: Integrator,
    variant: String,
    lammps: Option<PathBuf>,
    /// None: the kernel's serial step; Some(n): a rayon pool of n threads.
    threads: Option<usize>,
}

fn options() -> Result<Options, Box<dyn Error>> {
    let mut o = Options {
        column: Column::REFERENCE,
        steps: 10_000,
        repeat: 3,
        integrator: Integrator::SymplecticEuler,
        variant: "full".into(),
        lammps: None,
        threads: None,
    };
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        let mut value = || args.next().ok_or(format!("{arg} needs a value"));
        match arg.as_str() {
            "--spheres" => {
                o.column = match value()?.as_str() {
                    "10000" => Column::REFERENCE,
                    "50000" => Column::LONG,
                    other => return Err(format!("--spheres {other}: 10000 or 50000").into()),
                }
            }
            "--steps" => o.steps = value()?.parse()?,
            "--repeat" => o.repeat = value()?.parse::<usize>()?.max(1),
            "--integrator" => {
                o.integrator = match value()?.as_str() {
                    "euler" => Integrator::SymplecticEuler,
                    "verlet" => Integrator::VelocityVerlet,
                    other => return Err(format!("--integrator {other}: euler or verlet").into()),
                }
            }
            "--variant" => o.variant = value()?,
            "--lammps" => o.lammps = Some(value()?.into()),
            "--threads" => o.threads = Some(value()?.parse::<usize>()?.max(1)),
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    Ok(o)
}

fn tangential() -> TangentialParameters<f64> {
    TangentialParameters::new(2.0 / 7.0 * NORMAL_STIFFNESS, DASHPOT_RATIO, FRICTION).unwrap()
}

fn floor() -> [MaterialWall<f64>; 1] {
    [wall_of(
        Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap(),
        1,
    )]
}

/// Pours the column from its lattice and lets it settle (more damping, a longer step), then
/// stops every sphere. Cached in `target/scene/`.
/// Spheres and the height of the box they were poured into.
type Packing = (Vec<Sphere<f64>>, f64);

fn settled(column: &Column) -> Result<Packing, Box<dyn Error>> {
    let cache = PathBuf::from(format!("target/scene/packing_{}.csv", column.spheres));
    let (lattice, height) = column.lattice::<f64>();
    if let Ok(text) = std::fs::read_to_string(&cache) {
        let mut spheres = lattice.clone();
        for (s, line) in spheres.iter_mut().zip(text.lines().skip(1)) {
            let v: Vec<f64> = line.split(',').map(str::parse).collect::<Result<_, _>>()?;
            s.position = Vec3::new(v[0], v[1], v[2]);
        }
        return Ok((spheres, height));
    }
    eprintln!(
        "settling {} spheres (cached afterwards in {})",
        column.spheres,
        cache.display()
    );
    let mass = lattice[0].mass;
    let mut scene = OwnedScene::new(lattice, column.domain(height), SKIN, floor())?;
    let settle_e = 0.3;
    let law = ContactLaw::new(
        LinearSpringDashpot::new(NORMAL_STIFFNESS, settle_e)?,
        ModelAA(tangential()),
    );
    let wall_e = wall_restitution_for_same_dashpot(settle_e, mass / 2.0, mass);
    let wall_law = ContactLaw::new(
        LinearSpringDashpot::new(NORMAL_STIFFNESS, wall_e)?,
        ModelAA(tangential()),
    );
    let table = pair_and_wall(law, wall_law);
    let input = StepInput {
        table: &table,
        gravity: Vec3::new(0.0, 0.0, -GRAVITY),
        // Settling only prepares the packing: a coarse step, knowingly.
        time_step: law.coarse_time_step(4e-6, mass / 2.0)?,
        integrator: Integrator::SymplecticEuler,
    };
    for round in 0..40 {
        scene.run(&input, 2500, |_, _| {})?;
        let ke = scene.kinetic_energy();
        eprintln!("  settle round {round}: kinetic energy {ke:.3e} J");
        // 1e-13 J per sphere: the 10,000-sphere bed settles to below 1e-9 J.
        if round >= 8 && ke < 1e-13 * column.spheres as f64 {
            break;
        }
    }
    scene.stop();
    std::fs::create_dir_all(cache.parent().unwrap())?;
    let spheres = scene.plain_spheres();
    std::fs::write(&cache, positions_csv(&spheres))?;
    Ok((spheres, height))
}

struct Measured {
    seconds: Vec<f64>,
    kinetic_energy: f64,
    contacts_per_particle: f64,
    mean_overlap: f64,
    /// Sphere-sphere contact-steps at the Coulomb limit, over all contact-steps.
    sliding_fraction: f64,
    /// Sphere-sphere contact-steps of the last run (touching pairs summed over its steps).
    pair_contact_steps: usize,
}

fn time_runs<L: Law<Float = f64>, W: WallSet<f64> + Clone, const MATERIALS: usize>(
    o: &Options,
    (spheres, materials): (&[Sphere<f64>], &[u32]),
    height: f64,
    input: &StepInput<'_, L, MATERIALS>,
    walls: &W,
) -> Result<Measured, Box<dyn Error>> {
    let mut seconds = Vec::new();
    let mut last = (0.0, 0.0, 0.0);
    let mut sliding_fraction = 0.0;
    let mut pair_contact_steps = 0;
    for _ in 0..o.repeat {
        let mut scene = OwnedScene::<L, W>::new(
            spheres.to_vec(),
            o.column.domain(height),
            SKIN,
            walls.clone(),
        )?
        .with_materials(materials.to_vec())?;
        let mut stats = Default::default();
        let (mut touching, mut sliding) = (0usize, 0usize);
        let record = |_: usize, s: &StepStats<f64>| {
            stats = *s;
            touching += s.pair_contacts;
            sliding += s.sliding_contacts;
        };
        let pool = o.threads.map(Threads::new).transpose()?;
        let start = Instant::now();
        match &pool {
            None => scene.run(input, o.steps, record)?,
            Some(pool) => scene.run_on(input, o.steps, pool, record)?,
        }
        seconds.push(start.elapsed().as_secs_f64());
        eprintln!(
            "  run: {:.3} s, {} list builds",
            seconds[seconds.len() - 1],
            scene.list_builds()
        );
        let n = spheres.len() as f64;
        sliding_fraction = sliding as f64 / touching.max(1) as f64;
        pair_contact_steps = touching;
        last = (
            scene.kinetic_energy(),
            2.0 * stats.pair_contacts as f64 / n,
            if stats.pair_contacts > 0 {
                stats.overlap_sum / stats.pair_contacts as f64
            } else {
                0.0
            },
        );
    }
    seconds.sort_by(f64::total_cmp);
    Ok(Measured {
        seconds,
        kinetic_energy: last.0,
        contacts_per_particle: last.1,
        mean_overlap: last.2,
        sliding_fraction,
        pair_contact_steps,
    })
}

/// Times the pair law and the wall law of one variant (every sphere of material 0, the floor
/// of material 1).
fn run_variant<L: Law<Float = f64>, W: WallSet<f64> + Clone>(
    o: &Options,
    spheres: &[Sphere<f64>],
    height: f64,
    (law, wall_law): (L, L),
    walls: &W,
) -> Result<Measured, Box<dyn Error>> {
    let time_step = law.time_step(TIME_STEP, spheres[0].mass / 2.0)?;
    let table = pair_and_wall(law, wall_law);
    let input = StepInput {
        table: &table,
        gravity: Vec3::new(0.0, 0.0, -GRAVITY),
        time_step,
        integrator: o.integrator,
    };
    let materials = vec![0; spheres.len()];
    time_runs(o, (spheres, &materials), height, &input, walls)
}

/// The reference scene as a binary mixture: half the spheres (at random) of a second material
/// twice as stiff with 0.6 of the friction, pairs mixed by geometric means, the floor a third
/// material with the reference wall law's stiffness and restitution.
fn run_mixture(
    o: &Options,
    spheres: &[Sphere<f64>],
    height: f64,
    wall_e: f64,
) -> Result<Measured, Box<dyn Error>> {
    let first = LinearMaterial {
        normal_stiffness: NORMAL_STIFFNESS,
        restitution: RESTITUTION,
        tangential_stiffness: 2.0 / 7.0 * NORMAL_STIFFNESS,
        dashpot_ratio: DASHPOT_RATIO,
        friction: FRICTION,
    };
    let second = LinearMaterial {
        normal_stiffness: 2.0 * NORMAL_STIFFNESS,
        tangential_stiffness: 4.0 / 7.0 * NORMAL_STIFFNESS,
        friction: 0.6 * FRICTION,
        ..first
    };
    let floor_material = LinearMaterial {
        restitution: wall_e,
        ..first
    };
    let mixing = LinearMixing::new(ModelAA).with_backend::<Std>();
    let table = MaterialTable::<_, 3>::mixed(&mixing, &[first, second, floor_material])?;
    let mut random = host_tests::random::Xorshift::new(0x5eed);
    let materials: Vec<u32> = spheres
        .iter()
        .map(|_| u32::from(random.unit() < 0.5))
        .collect();
    let walls = [wall_of(Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0))?, 2)];
    let mut probe = OwnedScene::new(spheres.to_vec(), o.column.domain(height), SKIN, walls)?
        .with_materials(materials.clone())?;
    let time_step = probe.scene(|s| s.time_step(&table, TIME_STEP))??;
    let input = StepInput {
        table: &table,
        gravity: Vec3::new(0.0, 0.0, -GRAVITY),
        time_step,
        integrator: o.integrator,
    };
    time_runs(o, (spheres, &materials), height, &input, &walls)
}

fn main() -> Result<(), Box<dyn Error>> {
    let o = options()?;
    let (spheres, _) = settled(&o.column)?;
    // The timed box ends two diameters above the settled bed: no empty cells to walk.
    let height = spheres.iter().map(|s| s.position.z).fold(0.0, f64::max) + 2.0 * o.column.diameter;
    let mass = spheres[0].mass;
    let wall_e = wall_restitution_for_same_dashpot(RESTITUTION, mass / 2.0, mass);
    if let Some(dir) = &o.lammps {
        std::fs::create_dir_all(dir)?;
        let domain = o.column.domain::<f64>(height);
        write_lammps_data(
            &dir.join("packing.data"),
            &spheres,
            &domain,
            o.column.density,
        )?;
        let native = lammps_deck(mass, o.steps);
        std::fs::write(dir.join("in.scene"), &native)?;
        std::fs::write(dir.join("in.plugin"), plugin_deck(&native, mass))?;
        eprintln!(
            "wrote {}/packing.data, in.scene and in.plugin",
            dir.display()
        );
    }
    let normal = LinearSpringDashpot::new(NORMAL_STIFFNESS, RESTITUTION)?;
    let wall_normal = LinearSpringDashpot::new(NORMAL_STIFFNESS, wall_e)?;
    let m = match o.variant.as_str() {
        "full" => run_variant(
            &o,
            &spheres,
            height,
            (
                ContactLaw::new(normal, ModelAA(tangential())).with_backend::<Std>(),
                ContactLaw::new(wall_normal, ModelAA(tangential())).with_backend::<Std>(),
            ),
            &floor(),
        )?,
        "frictionless" => run_variant(
            &o,
            &spheres,
            height,
            (
                ContactLaw::new(normal, Frictionless)
                    .with_backend::<Std>()
                    .without_rotation(),
                ContactLaw::new(wall_normal, Frictionless)
                    .with_backend::<Std>()
                    .without_rotation(),
            ),
            &floor(),
        )?,
        "non-rotating" => run_variant(
            &o,
            &spheres,
            height,
            (
                ContactLaw::new(normal, ModelAA(tangential()))
                    .with_backend::<Std>()
                    .without_rotation(),
                ContactLaw::new(wall_normal, ModelAA(tangential()))
                    .with_backend::<Std>()
                    .without_rotation(),
            ),
            &floor(),
        )?,
        "undamped" => {
            let spring = LinearSpring::new(NORMAL_STIFFNESS)?;
            let t = TangentialParameters::new(2.0 / 7.0 * NORMAL_STIFFNESS, 0.0, FRICTION)?;
            run_variant(
                &o,
                &spheres,
                height,
                (
                    ContactLaw::new(spring, ModelAA(t)).with_backend::<Std>(),
                    ContactLaw::new(spring, ModelAA(t)).with_backend::<Std>(),
                ),
                &floor(),
            )?
        }
        "no-walls" => run_variant(
            &o,
            &spheres,
            height,
            (
                ContactLaw::new(normal, ModelAA(tangential())).with_backend::<Std>(),
                ContactLaw::new(wall_normal, ModelAA(tangential())).with_backend::<Std>(),
            ),
            &NoWalls,
        )?,
        "mixture" => run_mixture(&o, &spheres, height, wall_e)?,
        other => return Err(format!("unknown variant {other}").into()),
    };
    let n = spheres.len() as f64;
    let median = m.seconds[m.seconds.len() / 2];
    let particle_steps = n * o.steps as f64;
    println!("build: {}", host_tests::build::describe());
    println!(
        "soft-sphere {} spheres, {} steps, variant {}, {:?}, {}: loop time min {:.3} s median {:.3} s max {:.3} s",
        spheres.len(),
        o.steps,
        o.variant,
        o.integrator,
        match o.threads {
            None => "serial".to_string(),
            Some(n) => format!("{n} threads"),
        },
        m.seconds[0],
        median,
        m.seconds[m.seconds.len() - 1]
    );
    println!(
        "  {:.3e} particle-steps/s (median), {:.1} ns per particle-step",
        particle_steps / median,
        1e9 * median / particle_steps
    );
    println!(
        "  end: kinetic energy {:.6e} J, contacts per particle {:.4}, mean overlap {:.6e} m",
        m.kinetic_energy, m.contacts_per_particle, m.mean_overlap
    );
    println!(
        "  sliding: {:.2} % of {} pair contact-steps",
        100.0 * m.sliding_fraction,
        m.pair_contact_steps
    );
    Ok(())
}

/// The same scene with the soft-sphere plugin (`examples/lammps`): `pair_style soft/sphere aa` and
/// `fix wall/soft/sphere aa` in place of the native styles, the floor at the restitution that gives
/// it the pairs' `eta_n`. The plugin's path comes in as the LAMMPS variable `plugin`.
fn plugin_deck(native: &str, mass: f64) -> String {
    let wall_e = wall_restitution_for_same_dashpot(RESTITUTION, mass / 2.0, mass);
    let k_t = 2.0 / 7.0 * NORMAL_STIFFNESS;
    let law = |e: f64| format!("aa {NORMAL_STIFFNESS} {e:e} {k_t:e} {DASHPOT_RATIO} {FRICTION}");
    native
        .lines()
        .map(|line| {
            if line.starts_with("pair_style") {
                format!(
                    "plugin load ${{plugin}}\npair_style soft/sphere {}",
                    law(RESTITUTION)
                )
            } else if line.starts_with("fix floor") {
                format!(
                    "fix floor all wall/soft/sphere {} zplane 0.0 NULL",
                    law(wall_e)
                )
            } else {
                line.replace(
                    "soft-sphere reference scene.",
                    "soft-sphere reference scene, plugin styles.",
                )
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
}

/// The same physics for LAMMPS: `gran/hooke/history` with `gamma_n` chosen so that the pair
/// dashpot `m* gamma_n` equals the kernel's `eta_n` at e = 0.9, and the floor's `gamma_n` halved so
/// that `m gamma_n` is the same `eta_n` (the "same eta_n for the floor").
fn lammps_deck(mass: f64, steps: usize) -> String {
    let pair_mass = mass / 2.0;
    let l = RESTITUTION.ln();
    let zeta = -l / (std::f64::consts::PI.powi(2) + l * l).sqrt();
    let eta_n = 2.0 * zeta * (pair_mass * NORMAL_STIFFNESS).sqrt();
    let gamma_n = eta_n / pair_mass;
    let gamma_t = DASHPOT_RATIO * gamma_n;
    let k_t = 2.0 / 7.0 * NORMAL_STIFFNESS;
    format!(
        "# Generated by host-tests/src/bin/scene_bench.rs: the soft-sphere reference scene.\n\
         units si\n\
         atom_style sphere\n\
         boundary p p f\n\
         newton off\n\
         comm_modify vel yes\n\
         read_data packing.data\n\
         pair_style gran/hooke/history {NORMAL_STIFFNESS} {k_t} {gamma_n} {gamma_t} {FRICTION} 1\n\
         pair_coeff * *\n\
         neighbor 1e-4 bin\n\
         neigh_modify every 1 delay 0 check yes\n\
         fix integrate all nve/sphere\n\
         fix weight all gravity {GRAVITY} vector 0 0 -1\n\
         fix floor all wall/gran hooke/history {NORMAL_STIFFNESS} {k_t} {gw} {gtw} {FRICTION} 1 zplane 0.0 NULL\n\
         timestep {TIME_STEP}\n\
         compute rotational all erotate/sphere\n\
         compute contacts all contact/atom\n\
         compute total_contacts all reduce sum c_contacts\n\
         thermo_style custom step ke c_rotational c_total_contacts\n\
         thermo_modify format float %.16e\n\
         thermo {steps}\n\
         run {steps}\n",
        gw = gamma_n / 2.0,
        gtw = gamma_t / 2.0,
    )
}
