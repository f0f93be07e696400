//! docs/physics.md, section 5.3: a sphere launched sliding without spin on a plate, under gravity, until it rolls.

use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    ContactLaw, Frictionless, Interaction, LinearSpringDashpot, Sphere, TangentialModel,
    TangentialParameters, Vec3,
};

use super::kharaz::{Model, WithLaw};
use super::{CaseOutput, Table};
use crate::analytic::rolling_onset;
use crate::impact::floor;

// Elghannay & Tafti's plate case (docs/physics.md, section 5.3).
/// Sphere radius (m).
pub const RADIUS: f64 = 5.0e-3;
/// Density (kg/m3).
pub const DENSITY: f64 = 2500.0;
/// Initial sliding speed (m/s).
pub const INITIAL_SPEED: f64 = 1.0;
/// Friction coefficient.
pub const FRICTION: f64 = 0.7;
/// Gravity (m/s2).
pub const GRAVITY: f64 = 9.81;
/// k_n (N/m).
pub const NORMAL_STIFFNESS: f64 = 1000.0;
/// k_t (N/m).
pub const TANGENTIAL_STIFFNESS: f64 = 860.0;
/// e.
pub const RESTITUTION: f64 = 0.9;
/// eta_t / eta_n: MFiX's default, so that the stored spring's oscillation after the stick decays.
pub const DASHPOT_RATIO: f64 = 0.5;
const STEPS_PER_CONTACT: f64 = 50.0;
const DURATION: f64 = 0.1;
/// Rolling has begun when the slip `u - w R` first falls to this fraction of `u0`.
const ROLLING_SLIP: f64 = 1e-3;

/// Models that must roll at 5/7 on time (A and C are shown as they are).
pub const PASSING: [Model; 4] = [
    Model::ModelAA,
    Model::ModelAALuding,
    Model::ModelB,
    Model::Stateless,
];
/// Relative tolerance on the final ratios against 5/7.
pub const RATIO_TOLERANCE: f64 = 5e-3;
/// Relative tolerance on the rolling onset against `2 u0 / (7 mu g)`.
pub const ONSET_TOLERANCE: f64 = 2e-2;

/// A plate run: the time series and its summary.
#[derive(Clone, Debug, PartialEq)]
pub struct Slide {
    /// `(t, u/u0, w R/u0)` after every step, starting with `(0, 1, 0)`.
    pub series: Vec<[f64; 3]>,
    /// First time the slip fell to `ROLLING_SLIP u0` (s), if it did.
    pub rolling_onset: Option<f64>,
}

/// Runs the plate case with `model`.
///
/// # Panics
/// When the kernel rejects the setup or the sphere leaves the plate: a validation failure.
pub fn slide(model: Model) -> Slide {
    let p = TangentialParameters::new(TANGENTIAL_STIFFNESS, DASHPOT_RATIO, FRICTION)
        .expect("valid tangential parameters");
    struct Plate;
    impl WithLaw for Plate {
        type Output = Slide;
        fn run<T: TangentialModel<f64>>(self, tangential: T) -> Slide {
            slide_with(tangential)
        }
    }
    model.with_law(p, Plate)
}

/// The run's step (s), its number of steps, and the sphere's starting height (m): at the static
/// overlap `m g / k_n`, so that it does not bounce.
pub fn timing() -> (f64, usize, f64) {
    let normal = LinearSpringDashpot::new(NORMAL_STIFFNESS, RESTITUTION).expect("valid");
    let mass = Sphere::solid(Vec3::ZERO, RADIUS, DENSITY).mass;
    let dt = ContactLaw::new(normal, Frictionless).contact_duration(mass) / STEPS_PER_CONTACT;
    let static_overlap = mass * GRAVITY / NORMAL_STIFFNESS;
    (dt, (DURATION / dt).ceil() as usize, RADIUS - static_overlap)
}

fn slide_with<T: TangentialModel<f64>>(tangential: T) -> Slide {
    let normal = LinearSpringDashpot::new(NORMAL_STIFFNESS, RESTITUTION).expect("valid");
    let law = ContactLaw::new(normal, tangential);
    let mass = Sphere::solid(Vec3::ZERO, RADIUS, DENSITY).mass;
    let (seconds, steps, height) = timing();
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, height), RADIUS, DENSITY);
    sphere.velocity = Vec3::new(INITIAL_SPEED, 0.0, 0.0);
    let dt = law.time_step(seconds, mass).expect("a stable step");
    let weight = Vec3::new(0.0, 0.0, -mass * GRAVITY);
    let wall = floor();
    let mut state = T::State::default();
    let ratios = |s: &Sphere<f64>| {
        [
            s.velocity.x / INITIAL_SPEED,
            s.angular_velocity.y * RADIUS / INITIAL_SPEED,
        ]
    };
    let mut series = vec![[0.0, 1.0, 0.0]];
    let mut rolling_onset = None;
    for step in 1..=steps {
        let (force, torque) = match law.sphere_wall(&sphere, &wall, &mut state, dt) {
            Ok(Interaction::Touching(c)) => (c.force_on_i(), c.torque_on_i),
            Ok(Interaction::Apart) => panic!("the sphere left the plate"),
            Err(e) => panic!("kernel error {e:?}"),
        };
        advance_solid_sphere(&mut sphere, force + weight, torque, dt);
        let t = step as f64 * dt.seconds();
        let [u, w] = ratios(&sphere);
        series.push([t, u, w]);
        if rolling_onset.is_none() && u - w <= ROLLING_SLIP {
            rolling_onset = Some(t);
        }
    }
    Slide {
        series,
        rolling_onset,
    }
}

/// Every model on the plate: time series, the summary table, and the checks.
pub fn case(mut progress: impl FnMut(&str)) -> CaseOutput {
    let mut out = CaseOutput::default();
    let theory_onset = rolling_onset(INITIAL_SPEED, FRICTION, GRAVITY);
    let mut summary = Table::new(&[
        "model",
        "rolling_onset_s",
        "final_velocity_ratio",
        "final_spin_ratio",
    ])
    .with_comment(format!(
        "theory: onset {theory_onset} s, final ratios 5/7 = {}",
        5.0 / 7.0
    ));
    for model in Model::ALL {
        progress(&format!("plate {}", model.name()));
        let run = slide(model);
        let [_, u, w] = *run.series.last().expect("at least one step");
        let onset = run.rolling_onset.unwrap_or(f64::NAN);
        if PASSING.contains(&model) {
            let what = |q: &str| format!("plate {} {q}", model.name());
            out.relative(what("rolling onset"), onset, theory_onset, ONSET_TOLERANCE);
            out.relative(what("final u/u0"), u, 5.0 / 7.0, RATIO_TOLERANCE);
            out.relative(what("final w R/u0"), w, 5.0 / 7.0, RATIO_TOLERANCE);
        }
        summary.push(vec![model.name().into(), onset.into(), u.into(), w.into()]);
        let mut table = Table::new(&["time_s", "velocity_ratio", "spin_ratio"])
            .shown_every(0)
            .with_comment(format!(
                "sphere sliding on a plate, {}: d = {} m, density = {DENSITY} kg/m3, u0 = \
                 {INITIAL_SPEED} m/s, mu = {FRICTION}, g = {GRAVITY} m/s2, k_n = \
                 {NORMAL_STIFFNESS} N/m, k_t = {TANGENTIAL_STIFFNESS} N/m, e = {RESTITUTION}, \
                 eta_t/eta_n = {DASHPOT_RATIO}, dt = t_c/{STEPS_PER_CONTACT}, symplectic Euler, \
                 starting at the static overlap",
                model.name(),
                2.0 * RADIUS
            ));
        for [t, u, w] in run.series {
            table.push(vec![t.into(), u.into(), w.into()]);
        }
        out.tables.push((format!("plate_{}", model.name()), table));
    }
    out.tables.push(("plate_summary".into(), summary));
    out
}
