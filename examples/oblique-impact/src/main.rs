//! One oblique sphere-wall impact, the Kharaz et al. (2001) setup with Elghannay & Tafti's parameters,
//! run with every tangential law of `soft-sphere` and printed next to rigid-body theory.
//!
//! This is also the smallest complete use of the kernel: build a law, check a time step, and
//! call the contact once per step from your own integration loop.
//!
//! Usage: `cargo run --release -p oblique-impact -- [ANGLE_DEG]` (default 20 degrees).

use std::error::Error;

use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    ContactLaw, Interaction, LinearSpringDashpot, ModelA, ModelAA, ModelAALuding, ModelB, ModelC,
    Sphere, Stateless, TangentialModel, TangentialParameters, Vec3, Wall,
};

// Elghannay & Tafti's parameters.
const DIAMETER: f64 = 5.0e-3;
const DENSITY: f64 = 2700.0;
const SPEED: f64 = 3.9;
const NORMAL_STIFFNESS: f64 = 1000.0;
const TANGENTIAL_STIFFNESS: f64 = 860.0;
const RESTITUTION: f64 = 0.98;
const FRICTION: f64 = 0.092;
const STEPS_PER_CONTACT: f64 = 50.0;

/// What one impact produced.
struct Outcome {
    tangential_restitution: f64,
    spin: f64,
    rebound_angle_deg: f64,
    steps_in_contact: usize,
    sliding_steps: usize,
}

fn impact<T: TangentialModel<f64>>(
    tangential: T,
    angle_deg: f64,
) -> Result<Outcome, Box<dyn Error>> {
    let normal = LinearSpringDashpot::new(NORMAL_STIFFNESS, RESTITUTION)?;
    let law = ContactLaw::new(normal, tangential);
    let floor = Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0))?;

    let radius = DIAMETER / 2.0;
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, radius), radius, DENSITY);
    let theta = angle_deg.to_radians();
    sphere.velocity = Vec3::new(SPEED * theta.sin(), 0.0, -SPEED * theta.cos());
    let incoming = sphere.velocity;

    // Against a wall the effective mass is the sphere's own.
    let dt = law.time_step(
        law.contact_duration(sphere.mass) / STEPS_PER_CONTACT,
        sphere.mass,
    )?;
    let mut state = T::State::default();
    let (mut steps_in_contact, mut sliding_steps) = (0, 0);
    for _ in 0..100 * STEPS_PER_CONTACT as usize {
        match law.sphere_wall(&sphere, &floor, &mut state, dt)? {
            Interaction::Touching(contact) => {
                steps_in_contact += 1;
                sliding_steps += usize::from(contact.sliding);
                advance_solid_sphere(&mut sphere, contact.force_on_i(), contact.torque_on_i, dt);
            }
            Interaction::Apart if steps_in_contact > 0 => {
                let out = sphere.velocity;
                return Ok(Outcome {
                    tangential_restitution: out.x / incoming.x,
                    spin: sphere.angular_velocity.y,
                    rebound_angle_deg: out.x.atan2(out.z).to_degrees(),
                    steps_in_contact,
                    sliding_steps,
                });
            }
            Interaction::Apart => advance_solid_sphere(&mut sphere, Vec3::ZERO, Vec3::ZERO, dt),
        }
    }
    Err("the sphere did not leave the wall".into())
}

/// Rigid-body theory for a solid sphere (docs/physics.md, section 5.2): `(e_t, w, rebound angle)`.
fn rigid_body(angle_deg: f64) -> (f64, f64, f64) {
    let theta = angle_deg.to_radians();
    let impulse = FRICTION * (1.0 + RESTITUTION);
    let (e_t, spin_ratio) = if theta.tan() >= 3.5 * impulse {
        (1.0 - impulse / theta.tan(), 2.5 * impulse * theta.cos())
    } else {
        (5.0 / 7.0, 5.0 / 7.0 * theta.sin())
    };
    let angle = (e_t * theta.sin())
        .atan2(RESTITUTION * theta.cos())
        .to_degrees();
    (e_t, spin_ratio * SPEED / (DIAMETER / 2.0), angle)
}

fn main() -> Result<(), Box<dyn Error>> {
    let angle_deg: f64 = match std::env::args().nth(1) {
        Some(text) => text
            .parse()
            .map_err(|_| format!("usage: oblique-impact [ANGLE_DEG], not {text:?}"))?,
        None => 20.0,
    };
    if !(angle_deg > 0.0 && angle_deg < 90.0) {
        return Err("the impact angle must lie strictly between 0 and 90 degrees".into());
    }
    println!(
        "soft-sphere: one oblique impact (Kharaz et al. 2001 setup, Elghannay & Tafti parameters)"
    );
    println!(
        "  sphere d = {} mm, rho = {DENSITY} kg/m3, |V| = {SPEED} m/s at {angle_deg} deg from the wall normal, no spin",
        DIAMETER * 1e3
    );
    println!(
        "  k_n = {NORMAL_STIFFNESS} N/m, k_t = {TANGENTIAL_STIFFNESS} N/m, e = {RESTITUTION}, mu = {FRICTION}, eta_t = 0, dt = t_c/{STEPS_PER_CONTACT}"
    );
    println!();
    println!(
        "{:<16} {:>8} {:>14} {:>20} {:>7} {:>8}",
        "law", "e_t", "spin (rad/s)", "rebound angle (deg)", "steps", "sliding"
    );
    let p = TangentialParameters::new(TANGENTIAL_STIFFNESS, 0.0, FRICTION)?;
    let rows = [
        ("stateless", impact(Stateless(p), angle_deg)?),
        ("model AA", impact(ModelAA(p), angle_deg)?),
        ("model AA, Luding", impact(ModelAALuding(p), angle_deg)?),
        ("model A", impact(ModelA(p), angle_deg)?),
        ("model B", impact(ModelB(p), angle_deg)?),
        ("model C", impact(ModelC(p), angle_deg)?),
    ];
    for (name, o) in rows {
        println!(
            "{name:<16} {:>8.4} {:>14.1} {:>20.2} {:>7} {:>8}",
            o.tangential_restitution,
            o.spin,
            o.rebound_angle_deg,
            o.steps_in_contact,
            o.sliding_steps
        );
    }
    let (e_t, spin, angle) = rigid_body(angle_deg);
    println!("{:<16} {e_t:>8.4} {spin:>14.1} {angle:>20.2}", "rigid body");
    Ok(())
}
