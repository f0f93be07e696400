//! Run time against error for the Kharaz impact (docs/physics.md, section 5.2, talk's parameters, Model AA):
//! every combination of precision (f32, f64), math backend (libm, micromath) and integrator
//! (symplectic Euler, velocity Verlet) at steps from t_c/10 to t_c/1000, against a converged f64
//! reference (t_c/20000). Writes `work_precision.csv` and the log-log plot
//! `work_precision.svg` into `--out` (default `target/work-precision`), and prints the Pareto
//! front.
//!
//! The same sweep for a scene: a shaken bed of 1,000 spheres with the reference scene's physics
//! (1 mm, density 2500, k_n = 1000 N/m, e = 0.9, k_t = 2/7 k_n, eta_t = eta_n / 2, mu = 0.5,
//! Model AA, floor, periodic in x and y). The bed is settled once (f64), then every sphere gets
//! the vertical velocity 0.05 sin(2 pi x / L_x) m/s and the bed runs for 10 contact durations;
//! the error is that of the final kinetic energy and of the mean pair overlap (over every touching
//! pair of every step: the overlap of the last step alone is dominated by which grazing contacts
//! happen to be open) against f64/libm/symplectic Euler at t_c/2000. Writes `work_precision_scene.csv` and `work_precision_scene.svg`.
//! (The 10,000-sphere reference scene itself at t_c/1000 would take an hour per point.)
//!
//! Usage: `cargo run --release -p host-tests --bin work_precision -- [--out DIR]`

use std::error::Error;
use std::path::PathBuf;
use std::time::Instant;

use host_tests::impact::{Integrator, floor, incoming_sphere, wall_impact_with};
use host_tests::plot::{Axes, Mark, Series, chart};
use host_tests::scene::{
    Column, OwnedScene, SceneExt, pair_and_wall, wall_of, wall_restitution_for_same_dashpot,
};
use host_tests::validation::kharaz::TALK;
use host_tests::validation::{Cell, Table};
use soft_sphere::prelude::{
    ContactLaw, Float, Libm, LinearSpringDashpot, MathBackend, Micromath, ModelAA, Sphere,
    TangentialParameters, Vec3, Wall,
};
use soft_sphere_scene::{self as scene, StepInput};

const ANGLES: [f64; 9] = [5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 60.0, 80.0];
const STEPS: [f64; 6] = [10.0, 20.0, 50.0, 100.0, 200.0, 1000.0];

/// e_t and spin at every angle, and the seconds one sweep takes (best of `repeats`).
fn sweep<F: Float, M: MathBackend<F>>(
    integrator: Integrator,
    steps_per_contact: f64,
    repeats: usize,
) -> (Vec<(f64, f64)>, f64) {
    let f = F::from_f64;
    let normal = LinearSpringDashpot::new(f(TALK.normal_stiffness), f(TALK.restitution)).unwrap();
    let p = TangentialParameters::new(
        f(TALK.tangential_stiffness),
        f(TALK.dashpot_ratio),
        f(TALK.friction),
    )
    .unwrap();
    let law = ContactLaw::new(normal, ModelAA(p)).with_backend::<M>();
    let mut best = f64::INFINITY;
    let mut out = Vec::new();
    for _ in 0..repeats {
        out.clear();
        let start = Instant::now();
        for angle in ANGLES {
            let sphere = incoming_sphere(f(TALK.radius), f(TALK.density), TALK.speed, angle);
            // Coarse steps too: the sweep measures the error against the step.
            let dt = law
                .coarse_time_step(
                    law.contact_duration(sphere.mass) / f(steps_per_contact),
                    sphere.mass,
                )
                .expect("stable");
            let max = 40 * steps_per_contact as usize;
            let r = wall_impact_with(integrator, &law, sphere, &floor(), dt, max, |_| {})
                .expect("rebounds");
            let e_t = (r.rebound.velocity.x / sphere.velocity.x).to_f64();
            out.push((e_t, r.rebound.angular_velocity.y.to_f64()));
        }
        best = best.min(start.elapsed().as_secs_f64());
    }
    (out, best)
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut args = std::env::args().skip(1);
    let mut out_dir = PathBuf::from("target/work-precision");
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--out" => out_dir = args.next().ok_or("--out needs a directory")?.into(),
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    std::fs::create_dir_all(&out_dir)?;
    impact_sweep(&out_dir)?;
    scene_sweep(&out_dir)
}

/// The points no other point beats on both time and error, fastest first.
fn pareto<'p>(points: &'p [(&'p str, f64, f64, f64)]) -> Vec<&'p (&'p str, f64, f64, f64)> {
    let mut front: Vec<_> = points
        .iter()
        .filter(|(_, _, t, e)| !points.iter().any(|(_, _, t2, e2)| t2 < t && e2 < e))
        .collect();
    front.sort_by(|a, b| a.2.total_cmp(&b.2));
    front
}

fn impact_sweep(out_dir: &std::path::Path) -> Result<(), Box<dyn Error>> {
    let (reference, _) = sweep::<f64, Libm>(Integrator::SymplecticEuler, 20_000.0, 1);
    let mut table = Table::new(&[
        "combination",
        "steps_per_contact",
        "seconds_per_sweep",
        "rms_relative_error_e_t",
        "rms_relative_error_spin",
    ])
    .with_comment(format!(
        "Kharaz impact, Model AA, talk's parameters, {} angles; error against f64/libm/symplectic \
         Euler at t_c/20000; time: best of 20 sweeps on one thread",
        ANGLES.len()
    ));
    type Run = fn(Integrator, f64, usize) -> (Vec<(f64, f64)>, f64);
    let combos: [(&str, Run, Integrator); 6] = [
        (
            "f64_libm_euler",
            sweep::<f64, Libm>,
            Integrator::SymplecticEuler,
        ),
        (
            "f64_libm_verlet",
            sweep::<f64, Libm>,
            Integrator::VelocityVerlet,
        ),
        (
            "f32_libm_euler",
            sweep::<f32, Libm>,
            Integrator::SymplecticEuler,
        ),
        (
            "f32_libm_verlet",
            sweep::<f32, Libm>,
            Integrator::VelocityVerlet,
        ),
        (
            "f32_micromath_euler",
            sweep::<f32, Micromath>,
            Integrator::SymplecticEuler,
        ),
        (
            "f32_micromath_verlet",
            sweep::<f32, Micromath>,
            Integrator::VelocityVerlet,
        ),
    ];
    let mut series = Vec::new();
    let mut points = Vec::new();
    for (name, run, integrator) in combos {
        let mut line = Vec::new();
        for steps in STEPS {
            let (values, seconds) = run(integrator, steps, 20);
            let rms = |pick: fn(&(f64, f64)) -> f64| {
                let sum: f64 = values
                    .iter()
                    .zip(&reference)
                    .map(|(v, r)| (pick(v) / pick(r) - 1.0).powi(2))
                    .sum();
                (sum / values.len() as f64).sqrt()
            };
            let (e_t, spin) = (rms(|v| v.0), rms(|v| v.1));
            table.push(vec![
                Cell::Text(name.into()),
                steps.into(),
                seconds.into(),
                e_t.into(),
                spin.into(),
            ]);
            line.push((seconds, e_t.max(spin)));
            points.push((name, steps, seconds, e_t.max(spin)));
        }
        series.push(Series::new(name, line, Mark::Line));
    }
    print!("{}", table.to_text());
    println!("Pareto front (time per sweep, worst RMS error of e_t and spin):");
    for (name, steps, seconds, error) in pareto(&points) {
        println!(
            "  {name:22} t_c/{steps:<5} {:8.1} us  {error:.2e}",
            seconds * 1e6
        );
    }
    table.write_csv(&out_dir.join("work_precision.csv"))?;
    chart(
        &out_dir.join("work_precision.svg"),
        "Kharaz impact, Model AA: error against run time (t_c/10 to t_c/1000)",
        (
            "seconds per 9-angle sweep",
            "RMS relative error (worst of e_t, spin)",
        ),
        &series,
        Axes::LogLog,
    )?;
    Ok(())
}

/// The shaken bed's column: 1,000 spheres over 10 mm x 10 mm.
const BED: Column = Column {
    spheres: 1000,
    diameter: 1e-3,
    density: 2500.0,
    width_x: 0.01,
    width_y: 0.01,
};
const BED_SKIN: f64 = 1e-4;
/// The shaken run lasts this many pair contact durations.
const SHAKE_DURATIONS: f64 = 10.0;
const SCENE_STEPS: [f64; 7] = [10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0];

/// The reference scene's laws (pair and floor) in precision `F` on backend `M`, at restitution
/// `restitution` for a pair.
fn scene_laws<F: Float, M: MathBackend<F>>(
    restitution: f64,
    mass: f64,
) -> [ContactLaw<F, LinearSpringDashpot<F>, ModelAA<F>, M>; 2] {
    let f = F::from_f64;
    let t = TangentialParameters::new(f(1000.0 * 2.0 / 7.0), f(0.5), f(0.5)).unwrap();
    let wall_e = wall_restitution_for_same_dashpot(restitution, mass / 2.0, mass);
    [restitution, wall_e].map(|e| {
        ContactLaw::new(
            LinearSpringDashpot::new(f(1000.0), f(e)).unwrap(),
            ModelAA(t),
        )
        .with_backend::<M>()
    })
}

/// A bed of spheres and its box.
type Bed = (Vec<Sphere<f64>>, scene::Domain<f64>);

/// The settled bed (f64; settled at e = 0.3 and stopped), then shaken.
fn shaken_bed() -> Result<Bed, Box<dyn Error>> {
    let (lattice, height) = BED.lattice::<f64>();
    let domain = BED.domain(height);
    let walls = [wall_of(Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0))?, 1)];
    let mass = lattice[0].mass;
    let [law, wall_law] = scene_laws::<f64, Libm>(0.3, mass);
    let mut bed = OwnedScene::new(lattice, domain, BED_SKIN, walls)?;
    let table = pair_and_wall(law, wall_law);
    let input = StepInput {
        table: &table,
        gravity: Vec3::new(0.0, 0.0, -9.81),
        // Settling only prepares the packing: a coarse step, knowingly.
        time_step: law.coarse_time_step(4e-6, mass / 2.0)?,
        integrator: Integrator::SymplecticEuler,
    };
    bed.run(&input, 40_000, |_, _| {})?;
    bed.stop();
    let mut spheres = bed.plain_spheres();
    for s in &mut spheres {
        let phase = 2.0 * std::f64::consts::PI * s.position.x / BED.width_x;
        s.velocity.z = 0.05 * phase.sin();
    }
    Ok((spheres, domain))
}

/// Final kinetic energy and mean pair overlap (over every touching pair of every step) of the
/// shaken bed, and the best run time of at least `repeats` runs (more for short runs, until
/// half a second has been spent).
fn shake<F: Float, M: MathBackend<F>>(
    (bed, domain): (&[Sphere<f64>], &scene::Domain<f64>),
    integrator: Integrator,
    steps_per_contact: f64,
    repeats: usize,
) -> Result<((f64, f64), f64), Box<dyn Error>> {
    let f = F::from_f64;
    let v = |a: Vec3<f64>| Vec3::new(f(a.x), f(a.y), f(a.z));
    let spheres: Vec<Sphere<F>> = bed
        .iter()
        .map(|s| Sphere {
            position: v(s.position),
            velocity: v(s.velocity),
            angular_velocity: v(s.angular_velocity),
            radius: f(s.radius),
            mass: f(s.mass),
        })
        .collect();
    let domain = scene::Domain {
        lower: v(domain.lower),
        upper: v(domain.upper),
        periodic_x: domain.periodic_x,
        periodic_y: domain.periodic_y,
    };
    let mass = bed[0].mass;
    let [law, wall_law] = scene_laws::<F, M>(0.9, mass);
    let contact = law.contact_duration(f(mass / 2.0)).to_f64();
    let dt = contact / steps_per_contact;
    let steps = (SHAKE_DURATIONS * steps_per_contact).round() as usize;
    let walls = [wall_of(
        Wall::new(Vec3::ZERO, Vec3::new(F::ZERO, F::ZERO, F::ONE))?,
        1,
    )];
    let table = pair_and_wall(law, wall_law);
    let input = StepInput {
        table: &table,
        gravity: Vec3::new(F::ZERO, F::ZERO, f(-9.81)),
        time_step: law.coarse_time_step(f(dt), f(mass / 2.0))?,
        integrator,
    };
    let mut best = f64::INFINITY;
    let mut result = (0.0, 0.0);
    let (mut runs, mut spent) = (0, 0.0);
    while runs < repeats || spent < 0.5 {
        runs += 1;
        let mut scene = OwnedScene::new(spheres.clone(), domain, f(BED_SKIN), walls)?;
        let (mut overlap, mut contacts) = (0.0, 0);
        let start = Instant::now();
        scene.run(&input, steps, |_, s| {
            overlap += s.overlap_sum.to_f64();
            contacts += s.pair_contacts;
        })?;
        let seconds = start.elapsed().as_secs_f64();
        (best, spent) = (best.min(seconds), spent + seconds);
        result = (scene.kinetic_energy(), overlap / contacts.max(1) as f64);
    }
    Ok((result, best))
}

fn scene_sweep(out_dir: &std::path::Path) -> Result<(), Box<dyn Error>> {
    eprintln!("settling the 1,000-sphere bed");
    let (bed, domain) = shaken_bed()?;
    let bed = (&bed[..], &domain);
    let euler = Integrator::SymplecticEuler;
    let verlet = Integrator::VelocityVerlet;
    eprintln!("reference run (f64, libm, symplectic Euler, t_c/2000)");
    let (reference, _) = shake::<f64, Libm>(bed, euler, 2000.0, 1)?;
    let mut table = Table::new(&[
        "combination",
        "steps_per_contact",
        "seconds_per_run",
        "relative_error_kinetic_energy",
        "relative_error_mean_overlap",
    ])
    .with_comment(format!(
        "shaken bed of {} spheres, reference-scene physics, {SHAKE_DURATIONS} contact durations; \
         error against f64/libm/symplectic Euler at t_c/2000 (kinetic energy {:.6e} J, mean \
         overlap {:.6e} m); time: best of 2 or more runs (0.5 s at least) on one thread",
        BED.spheres, reference.0, reference.1
    ));
    type Run = fn(
        (&[Sphere<f64>], &scene::Domain<f64>),
        Integrator,
        f64,
        usize,
    ) -> Result<((f64, f64), f64), Box<dyn Error>>;
    let combos: [(&str, Run, Integrator); 6] = [
        ("f64_libm_euler", shake::<f64, Libm>, euler),
        ("f64_libm_verlet", shake::<f64, Libm>, verlet),
        ("f32_libm_euler", shake::<f32, Libm>, euler),
        ("f32_libm_verlet", shake::<f32, Libm>, verlet),
        ("f32_micromath_euler", shake::<f32, Micromath>, euler),
        ("f32_micromath_verlet", shake::<f32, Micromath>, verlet),
    ];
    let mut series = Vec::new();
    let mut points = Vec::new();
    for (name, run, integrator) in combos {
        eprintln!("  {name}");
        let mut line = Vec::new();
        for steps in SCENE_STEPS {
            let ((energy, overlap), seconds) = run(bed, integrator, steps, 2)?;
            let errors = (
                (energy / reference.0 - 1.0).abs(),
                (overlap / reference.1 - 1.0).abs(),
            );
            table.push(vec![
                Cell::Text(name.into()),
                steps.into(),
                seconds.into(),
                errors.0.into(),
                errors.1.into(),
            ]);
            let worst = errors.0.max(errors.1);
            line.push((seconds, worst));
            points.push((name, steps, seconds, worst));
        }
        series.push(Series::new(name, line, Mark::Line));
    }
    print!("{}", table.to_text());
    println!("Pareto front (time per run, worse relative error of kinetic energy and overlap):");
    for (name, steps, seconds, error) in pareto(&points) {
        println!("  {name:22} t_c/{steps:<5} {seconds:8.3} s  {error:.2e}");
    }
    table.write_csv(&out_dir.join("work_precision_scene.csv"))?;
    chart(
        &out_dir.join("work_precision_scene.svg"),
        "Shaken 1,000-sphere bed, Model AA: error against run time (t_c/10 to t_c/1000)",
        (
            "seconds per run (10 contact durations)",
            "relative error (worse of kinetic energy, mean overlap)",
        ),
        &series,
        Axes::LogLog,
    )?;
    eprintln!("wrote {}", out_dir.display());
    Ok(())
}
