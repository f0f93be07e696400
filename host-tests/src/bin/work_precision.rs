//! Run time against error for the Kharaz impact (REFERENCE case 2, talk's parameters, Model AA):
//! every combination of precision (f32, f64), math backend (libm, micromath) and integrator
//! (symplectic Euler, velocity Verlet) at steps from t_c/10 to t_c/1000, against a converged f64
//! reference (t_c/20000). Writes `work_precision.csv` and the log-log plot
//! `work_precision.svg` into `--out` (default `target/work-precision`), and prints the Pareto
//! front.
//!
//! Usage: `cargo run --release -p host-tests --bin work_precision -- [--out DIR]`

use std::error::Error;
use std::path::PathBuf;
use std::time::Instant;

use host_tests::impact::{Integrator, floor, incoming_sphere, wall_impact_with};
use host_tests::plot::{Axes, Mark, Series, chart};
use host_tests::validation::kharaz::TALK;
use host_tests::validation::{Cell, Table};
use soft_sphere::{
    ContactLaw, Float, Libm, LinearSpringDashpot, MathBackend, Micromath, ModelAA,
    TangentialParameters,
};

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
        f(TALK.damping_ratio),
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
            let dt = law
                .time_step(
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
    // Pareto front: no other point is both faster and more accurate.
    let mut front: Vec<_> = points
        .iter()
        .filter(|(_, _, t, e)| !points.iter().any(|(_, _, t2, e2)| t2 < t && e2 < e))
        .collect();
    front.sort_by(|a, b| a.2.total_cmp(&b.2));
    print!("{}", table.to_text());
    println!("Pareto front (time per sweep, worst RMS error of e_t and spin):");
    for (name, steps, seconds, error) in front {
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
    eprintln!("wrote {}", out_dir.display());
    Ok(())
}
