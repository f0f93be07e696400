//! The Kharaz sweep straight from the kernel (no C ABI), printed in the format the C and Fortran
//! programs print, so that `tests/run.sh` can compare them digit for digit.
//!
//! Usage: `cargo run --release -p soft-sphere-ffi --example kharaz_reference [ANGLE]`.

use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    ContactLaw, Interaction, LinearSpringDashpot, ModelAA, Sphere, SpringDisplacement,
    TangentialParameters, Vec3, Wall,
};

fn tangential_restitution(angle_deg: f64) -> f64 {
    let normal = LinearSpringDashpot::new(1000.0, 0.98).unwrap();
    let law = ContactLaw::new(
        normal,
        ModelAA(TangentialParameters::new(860.0, 0.0, 0.092).unwrap()),
    );
    let radius = 2.5e-3;
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, radius), radius, 2700.0);
    let theta = angle_deg.to_radians();
    sphere.velocity = Vec3::new(3.9 * theta.sin(), 0.0, -3.9 * theta.cos());
    let incoming = sphere.velocity.x;
    let dt = law
        .time_step(law.contact_duration(sphere.mass) / 50.0, sphere.mass)
        .unwrap();
    let floor = Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap();
    let mut state = SpringDisplacement::default();
    let mut touched = false;
    loop {
        match law.sphere_wall(&sphere, &floor, &mut state, dt).unwrap() {
            Interaction::Touching(c) => {
                touched = true;
                advance_solid_sphere(&mut sphere, c.force_on_i(), c.torque_on_i, dt);
            }
            Interaction::Apart if touched => return sphere.velocity.x / incoming,
            Interaction::Apart => advance_solid_sphere(&mut sphere, Vec3::ZERO, Vec3::ZERO, dt),
        }
    }
}

fn main() {
    match std::env::args().nth(1).map(|a| a.parse::<i32>()) {
        Some(Ok(angle)) => println!("{angle:2} {:.15}", tangential_restitution(f64::from(angle))),
        _ => {
            for angle in 1..=89 {
                println!("{angle:2} {:.15}", tangential_restitution(f64::from(angle)));
            }
        }
    }
}
