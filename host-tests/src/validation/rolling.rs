//! docs/physics.md, section 5.6: rolling resistance. A sphere rolling on a plate under a constant
//! rolling torque stops at the closed-form deceleration and distance; on an incline the
//! elastic-plastic spring (EPSD) holds it below its rolling angle, `tan(theta) = mu_r`, and
//! above it lets it roll down at the closed-form acceleration.

use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    ConstantRolling, ContactLaw, ElasticPlasticRolling, Interaction, Law, LinearSpringDashpot,
    ModelAA, RollingModel, Sphere, TangentialParameters, Vec3,
};

use super::{CaseOutput, Cell, Table};
use crate::impact::floor;

/// Sphere radius (m), density (kg/m3), gravity (m/s2): the plate case's.
const RADIUS: f64 = 5.0e-3;
const DENSITY: f64 = 2500.0;
const GRAVITY: f64 = 9.81;
/// The contact: the plate case's springs, sliding friction well above any slope here.
const NORMAL_STIFFNESS: f64 = 1000.0;
const TANGENTIAL_STIFFNESS: f64 = 860.0;
const RESTITUTION: f64 = 0.9;
const FRICTION: f64 = 0.7;
/// The rolling-resistance coefficient.
pub const ROLLING_FRICTION: f64 = 0.1;
/// Initial rolling speed on the plate (m/s).
pub const ROLLING_SPEED: f64 = 0.5;
/// Relative tolerance on the stop time and distance, and on the acceleration down the slope.
pub const TOLERANCE: f64 = 1e-2;
/// Largest creep speed allowed to a sphere held on a slope (m/s), over the last half of the run.
pub const CREEP_BOUND: f64 = 1e-9;
const STEPS_PER_CONTACT: f64 = 50.0;

fn sphere_mass() -> f64 {
    Sphere::solid(Vec3::ZERO, RADIUS, DENSITY).mass
}

/// The contact law with rolling slot `rolling`.
fn law<Ro: RollingModel<f64>>(
    rolling: Ro,
) -> impl Law<Float = f64, State = Ro::State<soft_sphere::prelude::SpringDisplacement<f64>>> {
    let normal = LinearSpringDashpot::new(NORMAL_STIFFNESS, RESTITUTION).expect("valid");
    let p = TangentialParameters::new(TANGENTIAL_STIFFNESS, 0.5, FRICTION).expect("valid");
    ContactLaw::new(normal, ModelAA(p)).with_rolling(rolling)
}

/// The elastic-plastic rolling slot: `k_r = k_t R^2`, its dashpot at 0.3 of critical for a
/// sphere rocking about its contact point.
pub fn elastic_plastic() -> ElasticPlasticRolling<f64> {
    let mass = sphere_mass();
    let stiffness = TANGENTIAL_STIFFNESS * RADIUS * RADIUS;
    let rocking = 1.4 * mass * RADIUS * RADIUS;
    let damping = 0.3 * 2.0 * (rocking * stiffness).sqrt();
    ElasticPlasticRolling::new(
        ROLLING_FRICTION,
        stiffness,
        damping,
        0.4 * mass * RADIUS * RADIUS,
    )
    .expect("valid")
}

/// Runs a sphere on the floor under gravity tilted by `slope_deg` (downhill along +x), starting
/// at its static overlap with velocity `speed` along x rolling without slip, for `duration`
/// seconds; returns `(t, x, v_x)` after every step.
fn run<L: Law<Float = f64>>(law: &L, slope_deg: f64, speed: f64, duration: f64) -> Vec<[f64; 3]> {
    let mass = sphere_mass();
    let theta = slope_deg.to_radians();
    let weight = Vec3::new(
        mass * GRAVITY * theta.sin(),
        0.0,
        -mass * GRAVITY * theta.cos(),
    );
    let overlap = mass * GRAVITY * theta.cos() / NORMAL_STIFFNESS;
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, RADIUS - overlap), RADIUS, DENSITY);
    sphere.velocity = Vec3::new(speed, 0.0, 0.0);
    sphere.angular_velocity = Vec3::new(0.0, speed / RADIUS, 0.0);
    let seconds = law.contact_duration(mass) / STEPS_PER_CONTACT;
    let dt = law.time_step(seconds, mass).expect("a stable step");
    let wall = floor();
    let mut state = L::State::default();
    let mut bound = law.at(dt);
    let mut series = Vec::new();
    let steps = (duration / seconds).ceil() as usize;
    for step in 1..=steps {
        let checked = soft_sphere::prelude::CheckedSphere::new(sphere).expect("a valid sphere");
        let (force, torque) = match bound.sphere_wall(&checked, &wall, &mut state) {
            Ok(Interaction::Touching(c)) => (c.force_on_i(), c.torque_on_i),
            Ok(Interaction::Apart) => panic!("the sphere left the plate"),
            Err(e) => panic!("kernel error {e:?}"),
        };
        advance_solid_sphere(&mut sphere, force + weight, torque, dt);
        series.push([step as f64 * seconds, sphere.position.x, sphere.velocity.x]);
    }
    series
}

/// The time and distance at which the velocity first reaches zero, interpolated in the step.
fn stop(series: &[[f64; 3]]) -> Option<(f64, f64)> {
    series.windows(2).find(|w| w[1][2] <= 0.0).map(|w| {
        let f = w[0][2] / (w[0][2] - w[1][2]);
        (
            w[0][0] + f * (w[1][0] - w[0][0]),
            w[0][1] + f * (w[1][1] - w[0][1]),
        )
    })
}

/// The three rolling-resistance cases with their checks.
pub fn case(mut progress: impl FnMut(&str)) -> CaseOutput {
    let mut out = CaseOutput::default();
    let mut table = Table::new(&["case", "measured", "closed_form"]).with_comment(format!(
        "rolling resistance: d = {} m, density {DENSITY} kg/m3, g = {GRAVITY}, k_n = {NORMAL_STIFFNESS} N/m, k_t = {TANGENTIAL_STIFFNESS} N/m, e = {RESTITUTION}, mu = {FRICTION}, mu_r = {ROLLING_FRICTION}, Model AA, dt = t_c/{STEPS_PER_CONTACT}, symplectic Euler",
        2.0 * RADIUS
    ));
    let push =
        |out: &mut CaseOutput, table: &mut Table, what: &str, measured: f64, expected: f64| {
            table.push(vec![
                Cell::Text(what.into()),
                measured.into(),
                expected.into(),
            ]);
            out.relative(format!("rolling {what}"), measured, expected, TOLERANCE);
        };

    progress("rolling to a stop (constant torque)");
    let deceleration = 5.0 / 7.0 * ROLLING_FRICTION * GRAVITY;
    let series = run(
        &law(ConstantRolling::new(ROLLING_FRICTION).expect("valid")),
        0.0,
        ROLLING_SPEED,
        1.2 * ROLLING_SPEED / deceleration,
    );
    let (time, distance) = stop(&series).unwrap_or((f64::NAN, f64::NAN));
    push(
        &mut out,
        &mut table,
        "constant: stop time",
        time,
        ROLLING_SPEED / deceleration,
    );
    push(
        &mut out,
        &mut table,
        "constant: stop distance",
        distance,
        ROLLING_SPEED.powi(2) / (2.0 * deceleration),
    );
    let series = run(
        &law(elastic_plastic()),
        0.0,
        ROLLING_SPEED,
        1.2 * ROLLING_SPEED / deceleration,
    );
    let (time, distance) = stop(&series).unwrap_or((f64::NAN, f64::NAN));
    push(
        &mut out,
        &mut table,
        "epsd: stop time",
        time,
        ROLLING_SPEED / deceleration,
    );
    push(
        &mut out,
        &mut table,
        "epsd: stop distance",
        distance,
        ROLLING_SPEED.powi(2) / (2.0 * deceleration),
    );

    progress("held on a slope (EPSD)");
    let below = (0.5 * ROLLING_FRICTION).atan().to_degrees();
    let series = run(&law(elastic_plastic()), below, 0.0, 0.5);
    let half = series.len() / 2;
    let creep = series[half..]
        .iter()
        .map(|s| s[2].abs())
        .fold(0.0, f64::max);
    table.push(vec![
        Cell::Text(format!(
            "epsd at {below:.3} deg: largest speed over the last 0.25 s"
        )),
        creep.into(),
        0.0.into(),
    ]);
    out.absolute(
        "rolling epsd held below its rolling angle: creep speed",
        creep,
        0.0,
        CREEP_BOUND,
    );

    // The constant torque on the same slope: with no spring it flips every step at rest.
    let series = run(
        &law(ConstantRolling::new(ROLLING_FRICTION).expect("valid")),
        below,
        0.0,
        0.5,
    );
    let drift = series[series.len() - 1][1] - series[half][1];
    out.notes.push(format!(
        "the constant rolling torque on the same {below:.3} deg slope moves the sphere {drift:.3e} m over the last 0.25 s (largest speed {:.3e} m/s): it has no spring to hold it",
        series[half..].iter().map(|s| s[2].abs()).fold(0.0, f64::max)
    ));

    progress("rolling down a slope (EPSD)");
    let above = (2.0 * ROLLING_FRICTION).atan().to_degrees();
    let theta = above.to_radians();
    let expected = 5.0 / 7.0 * GRAVITY * (theta.sin() - ROLLING_FRICTION * theta.cos());
    let series = run(&law(elastic_plastic()), above, 0.0, 0.4);
    let (a, b) = (series[series.len() / 2], series[series.len() - 1]);
    push(
        &mut out,
        &mut table,
        &format!("epsd at {above:.3} deg: acceleration"),
        (b[2] - a[2]) / (b[0] - a[0]),
        expected,
    );
    out.tables.push(("rolling_resistance".into(), table));
    out
}
