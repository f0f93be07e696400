//! docs/physics.md, section 5.1: head-on impacts against the closed forms, free and with the normal force
//! clipped at zero, and how the shipped integrators converge with the step.

use soft_sphere::prelude::{ContactLaw, Frictionless, LinearSpringDashpot, NormalModel, Vec3};

use super::{CaseOutput, Table};
use crate::analytic::{
    clamped_contact_duration, clamped_restitution, contact_duration, max_overlap,
};
use crate::impact::{ImpactOutcome, Integrator, floor, wall_impact_with};

const RADIUS: f64 = 2.5e-3;
const DENSITY: f64 = 2700.0;
const STIFFNESS: f64 = 1000.0;
const SPEED: f64 = 1.0;

/// The restitution coefficients of the table.
pub const RESTITUTIONS: [f64; 7] = [0.1, 0.3, 0.5, 0.7, 0.9, 0.98, 1.0];
/// Absolute tolerance on the rebound ratio at t_c/1000.
pub const REBOUND_TOLERANCE: f64 = 1e-3;
/// Relative tolerance on the contact duration at t_c/1000.
pub const DURATION_TOLERANCE: f64 = 2e-3;
/// Steps per contact of the convergence table.
pub const STEPS: [f64; 6] = [10.0, 20.0, 50.0, 100.0, 200.0, 1000.0];

/// A head-on impact at `SPEED` with restitution `e`, at `dt = t_c / steps_per_contact`.
///
/// # Panics
/// When the kernel rejects the setup or the sphere does not rebound: a validation failure.
pub fn head_on(
    restitution: f64,
    clamped: bool,
    steps_per_contact: f64,
    integrator: Integrator,
) -> ImpactOutcome<f64> {
    let normal = LinearSpringDashpot::new(STIFFNESS, restitution).expect("valid normal law");
    let normal = if clamped {
        normal.with_attraction_clamped()
    } else {
        normal
    };
    head_on_with(normal, steps_per_contact, integrator)
}

fn head_on_with<N: NormalModel<f64>>(
    normal: N,
    steps_per_contact: f64,
    integrator: Integrator,
) -> ImpactOutcome<f64> {
    let law = ContactLaw::new(normal, Frictionless).without_rotation();
    let mut sphere =
        soft_sphere::prelude::Sphere::solid(Vec3::new(0.0, 0.0, RADIUS), RADIUS, DENSITY);
    sphere.velocity = Vec3::new(0.0, 0.0, -SPEED);
    let dt = law
        .coarse_time_step(
            law.contact_duration(sphere.mass) / steps_per_contact,
            sphere.mass,
        )
        .expect("a stable step");
    let max_steps = 50 * steps_per_contact as usize;
    wall_impact_with(integrator, &law, sphere, &floor(), dt, max_steps, |_| {})
        .expect("the sphere rebounds")
}

fn mass() -> f64 {
    soft_sphere::prelude::Sphere::solid(Vec3::ZERO, RADIUS, DENSITY).mass
}

/// The normal-impact table at t_c/1000 with its checks, and the convergence table.
pub fn case(mut progress: impl FnMut(&str)) -> CaseOutput {
    progress("normal impact");
    let mut out = CaseOutput::default();
    let m = mass();
    let mut table = Table::new(&[
        "restitution",
        "clamped",
        "rebound_ratio",
        "analytic_rebound_ratio",
        "contact_duration_s",
        "analytic_contact_duration_s",
        "max_overlap_m",
        "analytic_max_overlap_m",
    ])
    .with_comment(format!(
        "head-on sphere-wall impact, d = {} m, density = {DENSITY} kg/m3, k_n = {STIFFNESS} N/m, \
         v0 = {SPEED} m/s, symplectic Euler, dt = t_c/1000, f64; clamped = 1: normal force never \
         attractive (Schwager & Poeschel 2007)",
        2.0 * RADIUS
    ));
    for e in RESTITUTIONS {
        for clamped in [false, true] {
            let run = head_on(e, clamped, 1000.0, Integrator::SymplecticEuler);
            let ratio = run.rebound.velocity.z / SPEED;
            let (expected_ratio, expected_duration) = if clamped {
                (
                    clamped_restitution(e),
                    clamped_contact_duration(STIFFNESS, e, m),
                )
            } else {
                (e, contact_duration(STIFFNESS, e, m))
            };
            let label = if clamped { "clamped" } else { "free" };
            out.absolute(
                format!("normal e = {e} {label} rebound ratio"),
                ratio,
                expected_ratio,
                REBOUND_TOLERANCE,
            );
            out.relative(
                format!("normal e = {e} {label} contact duration"),
                run.contact_duration,
                expected_duration,
                DURATION_TOLERANCE,
            );
            table.push(vec![
                e.into(),
                f64::from(u8::from(clamped)).into(),
                ratio.into(),
                expected_ratio.into(),
                run.contact_duration.into(),
                expected_duration.into(),
                run.max_overlap.into(),
                max_overlap(STIFFNESS, e, m, SPEED).into(),
            ]);
        }
    }
    out.tables.push(("normal_impact".into(), table));

    let mut convergence = Table::new(&[
        "integrator",
        "restitution",
        "steps_per_contact",
        "rebound_ratio_error",
        "contact_duration_relative_error",
    ])
    .with_comment("free head-on impact: rebound ratio minus e, and duration / t_c - 1")
    .shown_every(0);
    let mut pivot = Table::new(&[
        "integrator",
        "restitution",
        "error_tc10",
        "error_tc20",
        "error_tc50",
        "error_tc100",
        "error_tc200",
        "error_tc1000",
    ])
    .with_comment("free head-on impact: rebound ratio minus e at dt = t_c/N");
    let mut worst_first_order = 0.0f64;
    let mut integrators_apart = 0.0f64;
    for integrator in Integrator::ALL {
        for e in RESTITUTIONS {
            let mut row = vec![integrator.name().into(), e.into()];
            for steps in STEPS {
                let run = head_on(e, false, steps, integrator);
                let error = run.rebound.velocity.z / SPEED - e;
                row.push(error.into());
                if integrator == Integrator::VelocityVerlet {
                    let euler = head_on(e, false, steps, Integrator::SymplecticEuler);
                    let gap = (run.rebound.velocity.z - euler.rebound.velocity.z).abs() / SPEED;
                    integrators_apart = integrators_apart.max(gap);
                }
                if integrator == Integrator::SymplecticEuler && steps == 50.0 {
                    worst_first_order = worst_first_order.max(error.abs() / e);
                }
                let duration = contact_duration(STIFFNESS, e, m);
                convergence.push(vec![
                    integrator.name().into(),
                    e.into(),
                    steps.into(),
                    error.into(),
                    (run.contact_duration / duration - 1.0).into(),
                ]);
            }
            pivot.push(row);
        }
    }
    out.notes.push(format!(
        "symplectic Euler at t_c/50: rebound ratio off by up to {:.2} % of e (worst at e = 0.1)",
        100.0 * worst_first_order
    ));
    out.notes.push(format!(
        "velocity Verlet and symplectic Euler rebound within {integrators_apart:.1e} of each \
         other: with the dashpot evaluated at the half-step velocity (as LAMMPS's nve/sphere \
         does) both produce the same leapfrog positions, so both are first order here"
    ));
    out.tables
        .push(("normal_impact_convergence".into(), convergence));
    out.tables
        .push(("normal_impact_convergence_summary".into(), pivot));
    out
}
