//! docs/physics.md, sections 5.2 and 5.4: the Kharaz oblique impact with every tangential model, against the
//! experiment, rigid-body theory, the MFiX DEM05 linear-model reference, and itself at a fine step.

use soft_sphere::prelude::{
    ContactLaw, LinearSpringDashpot, ModelA, ModelAA, ModelAALuding, ModelB, ModelC, Stateless,
    TangentialModel, TangentialParameters,
};

use super::{CaseOutput, Cell, Table, rms};
use crate::analytic::rigid_body_oblique;
use crate::data;
use crate::impact::{Integrator, floor, incoming_sphere, wall_impact_with};

/// The inputs of one Kharaz-type impact series.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setup {
    /// Sphere radius (m).
    pub radius: f64,
    /// Sphere density (kg/m3).
    pub density: f64,
    /// Impact speed (m/s).
    pub speed: f64,
    /// k_n (N/m).
    pub normal_stiffness: f64,
    /// k_t (N/m).
    pub tangential_stiffness: f64,
    /// Normal restitution e.
    pub restitution: f64,
    /// Coulomb friction mu.
    pub friction: f64,
    /// eta_t / eta_n.
    pub dashpot_ratio: f64,
}

/// Elghannay & Tafti's parameters (docs/physics.md, sections 5.2 and 5.4, eta_t = 0).
pub const TALK: Setup = Setup {
    radius: 2.5e-3,
    density: 2700.0,
    speed: 3.9,
    normal_stiffness: 1000.0,
    tangential_stiffness: 860.0,
    restitution: 0.98,
    friction: 0.092,
    dashpot_ratio: 0.0,
};

/// The MFiX DEM05 inputs behind `linear_model_reference_mfix_dem05.csv`.
pub const MFIX_DEM05: Setup = Setup {
    radius: 2.5e-3,
    density: 4000.0,
    speed: 3.9,
    normal_stiffness: 1.72e7,
    tangential_stiffness: 1.48e7,
    restitution: 1.0,
    friction: 0.092,
    dashpot_ratio: 0.0,
};

impl Setup {
    /// The settings as one line, for the CSV comment; `step` says the time step (`t_c/50`).
    pub fn describe(&self, step: &str) -> String {
        format!(
            "d = {} m, density = {} kg/m3, |V| = {} m/s, k_n = {} N/m, k_t = {} N/m, e = {}, \
             mu = {}, eta_t/eta_n = {}, no gravity, no initial spin, sphere-wall, torque arm R, \
             symplectic Euler, dt = {step}, f64",
            2.0 * self.radius,
            self.density,
            self.speed,
            self.normal_stiffness,
            self.tangential_stiffness,
            self.restitution,
            self.friction,
            self.dashpot_ratio
        )
    }

    /// The impact angle (deg from the normal) above which the rigid-body sphere slides throughout.
    pub fn sliding_threshold_deg(&self) -> f64 {
        (3.5 * self.friction * (1.0 + self.restitution))
            .atan()
            .to_degrees()
    }
}

/// The tangential models, in the order tables and plots list them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Model {
    /// The stateless law (docs/physics.md, section 3.1).
    Stateless,
    /// Model A (Cundall & Strack).
    ModelA,
    /// Model B (Tsuji et al.).
    ModelB,
    /// Model C (this step's slip only).
    ModelC,
    /// Model AA (stored spring, limited).
    ModelAA,
    /// Model AA with Luding's reset.
    ModelAALuding,
}

/// Something to do with one tangential law, whichever [`Model`] names it: see
/// [`Model::with_law`].
pub trait WithLaw {
    /// What it gives.
    type Output;
    /// Does it with `tangential`.
    fn run<T: TangentialModel<f64>>(self, tangential: T) -> Self::Output;
}

impl Model {
    /// Runs `action` with this model's tangential law and parameters `p`.
    pub fn with_law<A: WithLaw>(self, p: TangentialParameters<f64>, action: A) -> A::Output {
        match self {
            Self::Stateless => action.run(Stateless(p)),
            Self::ModelA => action.run(ModelA(p)),
            Self::ModelB => action.run(ModelB(p)),
            Self::ModelC => action.run(ModelC(p)),
            Self::ModelAA => action.run(ModelAA(p)),
            Self::ModelAALuding => action.run(ModelAALuding(p)),
        }
    }

    /// Every model.
    pub const ALL: [Self; 6] = [
        Self::Stateless,
        Self::ModelA,
        Self::ModelB,
        Self::ModelC,
        Self::ModelAA,
        Self::ModelAALuding,
    ];

    /// The name used in file names and tables.
    pub fn name(self) -> &'static str {
        match self {
            Self::Stateless => "stateless",
            Self::ModelA => "model_a",
            Self::ModelB => "model_b",
            Self::ModelC => "model_c",
            Self::ModelAA => "model_aa",
            Self::ModelAALuding => "model_aa_luding",
        }
    }
}

/// What one impact produced, in the experiment's terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    /// Impact angle from the wall normal (deg).
    pub angle_deg: f64,
    /// `V_t,out / V_t,in` of the centre of mass.
    pub tangential_cor: f64,
    /// Magnitude of the rebound angular velocity (rad/s).
    pub spin: f64,
    /// Angle of the centre-of-mass rebound velocity from the normal (deg).
    pub rebound_angle_deg: f64,
    /// Angle of the contact point's rebound velocity from the normal (deg): `atan((V_t - w R)/V_n)`.
    pub contact_patch_rebound_angle_deg: f64,
}

/// One impact at `angle_deg` with `model`, at `dt = t_c / steps_per_contact`.
///
/// # Panics
/// When the kernel rejects the setup or the sphere does not rebound: a validation failure.
pub fn impact(
    model: Model,
    setup: &Setup,
    angle_deg: f64,
    steps_per_contact: f64,
    integrator: Integrator,
) -> Outcome {
    let p = TangentialParameters::new(
        setup.tangential_stiffness,
        setup.dashpot_ratio,
        setup.friction,
    )
    .expect("valid tangential parameters");
    struct Impact<'s>(&'s Setup, f64, f64, Integrator);
    impl WithLaw for Impact<'_> {
        type Output = Outcome;
        fn run<T: TangentialModel<f64>>(self, tangential: T) -> Outcome {
            impact_with(tangential, (self.0, self.1, self.2, self.3))
        }
    }
    model.with_law(p, Impact(setup, angle_deg, steps_per_contact, integrator))
}

fn impact_with<T: TangentialModel<f64>>(
    tangential: T,
    (setup, angle_deg, steps_per_contact, integrator): (&Setup, f64, f64, Integrator),
) -> Outcome {
    let normal = LinearSpringDashpot::new(setup.normal_stiffness, setup.restitution)
        .expect("valid normal parameters");
    let law = ContactLaw::new(normal, tangential);
    let sphere = incoming_sphere(setup.radius, setup.density, setup.speed, angle_deg);
    let dt = law
        .time_step(
            law.contact_duration(sphere.mass) / steps_per_contact,
            sphere.mass,
        )
        .expect("a stable step");
    let max_steps = 20 * steps_per_contact as usize;
    let out = wall_impact_with(integrator, &law, sphere, &floor(), dt, max_steps, |_| {})
        .expect("the sphere rebounds");
    let (v_in, v_out, spin) = (
        sphere.velocity,
        out.rebound.velocity,
        out.rebound.angular_velocity.y,
    );
    Outcome {
        angle_deg,
        tangential_cor: v_out.x / v_in.x,
        spin: spin.abs(),
        rebound_angle_deg: v_out.x.atan2(v_out.z).to_degrees(),
        contact_patch_rebound_angle_deg: (v_out.x - spin * setup.radius)
            .atan2(v_out.z)
            .to_degrees(),
    }
}

/// The columns of every `kharaz_*.csv`.
pub const HEADER: [&str; 5] = [
    "impact_angle_deg",
    "tangential_cor",
    "rebound_spin_rad_per_s",
    "rebound_angle_deg",
    "contact_patch_rebound_angle_deg",
];

/// A sweep's outcomes as a table.
pub fn table(outcomes: &[Outcome], comment: String) -> Table {
    let mut table = Table::new(&HEADER).with_comment(comment).shown_every(8);
    for o in outcomes {
        table.push(vec![
            o.angle_deg.into(),
            o.tangential_cor.into(),
            o.spin.into(),
            o.rebound_angle_deg.into(),
            o.contact_patch_rebound_angle_deg.into(),
        ]);
    }
    table
}

/// Relative tolerance between dt = t_c/50 and t_c/1000.
pub const CONVERGENCE_TOLERANCE: f64 = 5e-3;
/// Relative tolerance to the rigid-body closed form above the gross-sliding threshold.
pub const SLIDING_TOLERANCE: f64 = 5e-3;
/// Relative tolerance of the stateless law to rigid-body theory below the threshold.
pub const STATELESS_TOLERANCE: f64 = 1e-2;

/// Angles 1 to 89 degrees.
fn sweep_angles() -> impl Iterator<Item = f64> {
    (1..=89).map(f64::from)
}

/// Elghannay & Tafti's sweep for every model at t_c/50, its convergence against t_c/1000, the rigid-body
/// checks, Model C's step dependence, and the RMS distance of each model from the experiment.
pub fn talk_sweep(mut progress: impl FnMut(&str)) -> CaseOutput {
    let mut out = CaseOutput::default();
    let setup = TALK;
    let threshold = setup.sliding_threshold_deg();
    let mut rms_table = Table::new(&[
        "model",
        "rms_tangential_cor",
        "rms_rebound_spin_rad_per_s",
        "rms_rebound_angle_deg",
    ]);
    for model in Model::ALL {
        progress(&format!("kharaz {}", model.name()));
        let coarse: Vec<Outcome> = sweep_angles()
            .map(|a| impact(model, &setup, a, 50.0, Integrator::SymplecticEuler))
            .collect();
        let fine: Vec<Outcome> = sweep_angles()
            .map(|a| impact(model, &setup, a, 1000.0, Integrator::SymplecticEuler))
            .collect();
        if model != Model::ModelC {
            convergence_checks(&mut out, model, &coarse, &fine);
        }
        for o in &coarse {
            let (e_t, spin_r_over_v) =
                rigid_body_oblique(o.angle_deg, setup.restitution, setup.friction);
            let spin = spin_r_over_v * setup.speed / setup.radius;
            // One degree clear of the threshold, where the rigid body changes branch.
            if o.angle_deg >= threshold + 1.0 && model != Model::ModelC {
                let what = |q: &str| {
                    format!(
                        "kharaz {} {q}({} deg) vs rigid body",
                        model.name(),
                        o.angle_deg
                    )
                };
                out.relative(what("e_t"), o.tangential_cor, e_t, SLIDING_TOLERANCE);
                out.relative(what("spin"), o.spin, spin, SLIDING_TOLERANCE);
            }
            if model == Model::Stateless && o.angle_deg <= threshold - 1.0 {
                let what =
                    |q: &str| format!("kharaz stateless {q}({} deg) vs rigid body", o.angle_deg);
                out.relative(what("e_t"), o.tangential_cor, e_t, STATELESS_TOLERANCE);
                out.relative(what("spin"), o.spin, spin, STATELESS_TOLERANCE);
            }
        }
        rms_table.push(experiment_rms(model, &setup));
        out.tables.push((
            format!("kharaz_{}", model.name()),
            table(&coarse, setup.describe("t_c/50")),
        ));
    }
    out.tables.push(("kharaz_rms".into(), rms_table));
    out.tables
        .push(("kharaz_step_dependence".into(), step_dependence(&setup)));
    out
}

/// Model B's outcome below this angle (deg) jumps with the step: see [`STEP_DEPENDENT`].
pub const MODEL_B_BIFURCATION_BELOW: f64 = 10.0;
/// Below this angle (deg) the spin is under 3 % of its peak and the step in which the sphere
/// leaves the wall moves it by up to 0.7 % at t_c/50; the convergence tolerance there is 1 %.
pub const SMALL_ANGLE_BELOW: f64 = 3.0;
/// The convergence tolerance below [`SMALL_ANGLE_BELOW`].
pub const SMALL_ANGLE_CONVERGENCE_TOLERANCE: f64 = 1e-2;

fn convergence_checks(out: &mut CaseOutput, model: Model, coarse: &[Outcome], fine: &[Outcome]) {
    for (c, f) in coarse.iter().zip(fine) {
        // Model B's sliding force flips with the sign of the slip while its unbounded spring
        // remembers the whole contact: near 2-9 deg the rebound switches between branches as the
        // step changes (0.714 at t_c/50, 0.475 at t_c/1000 at 9 deg). Shown, not checked.
        if model == Model::ModelB && c.angle_deg < MODEL_B_BIFURCATION_BELOW {
            continue;
        }
        let (tol, label) = if c.angle_deg < SMALL_ANGLE_BELOW {
            (
                SMALL_ANGLE_CONVERGENCE_TOLERANCE,
                " (small-angle tolerance)",
            )
        } else {
            (CONVERGENCE_TOLERANCE, "")
        };
        let what = |q: &str| {
            format!(
                "kharaz {} {q}({} deg) t_c/50 vs t_c/1000{label}",
                model.name(),
                c.angle_deg
            )
        };
        out.relative(what("e_t"), c.tangential_cor, f.tangential_cor, tol);
        out.relative(what("spin"), c.spin, f.spin, tol);
        out.relative(
            what("rebound angle"),
            c.rebound_angle_deg,
            f.rebound_angle_deg,
            tol,
        );
    }
}

/// `[model, rms e_t, rms spin, rms rebound angle]` against the three Kharaz data sets, each model
/// run at the experiment's own angles.
fn experiment_rms(model: Model, setup: &Setup) -> Vec<Cell> {
    let against = |file: &str, quantity: fn(&Outcome) -> f64| {
        rms(data::rows(file).into_iter().map(|row| {
            let o = impact(model, setup, row[0], 50.0, Integrator::SymplecticEuler);
            (quantity(&o), row[1])
        }))
    };
    vec![
        model.name().into(),
        against("kharaz2001_tangential_cor.csv", |o| o.tangential_cor).into(),
        against("kharaz2001_rebound_spin.csv", |o| o.spin).into(),
        against("kharaz2001_rebound_angle.csv", |o| o.rebound_angle_deg).into(),
    ]
}

/// The models whose result moves with the step: Model C by construction (a dashpot `k_t dt`
/// strong), Model B through its branch switching at small angles; Model AA for contrast.
pub const STEP_DEPENDENT: [Model; 3] = [Model::ModelC, Model::ModelB, Model::ModelAA];

/// e_t against the step for [`STEP_DEPENDENT`].
fn step_dependence(setup: &Setup) -> Table {
    let angles = [2.0, 9.0, 15.0, 30.0, 45.0];
    let mut table = Table::new(&[
        "model",
        "steps_per_contact",
        "e_t_2deg",
        "e_t_9deg",
        "e_t_15deg",
        "e_t_30deg",
        "e_t_45deg",
    ])
    .with_comment(format!(
        "tangential restitution against the step; {}",
        setup.describe("t_c/steps_per_contact")
    ));
    for model in STEP_DEPENDENT {
        for steps in [10.0, 20.0, 50.0, 100.0, 200.0, 1000.0, 5000.0] {
            let mut row = vec![model.name().into(), steps.into()];
            row.extend(angles.iter().map(|&a| {
                impact(model, setup, a, steps, Integrator::SymplecticEuler)
                    .tangential_cor
                    .into()
            }));
            table.push(row);
        }
    }
    table
}

/// Below this angle (deg) the published MFiX values are not reproduced by a converged linear
/// model, nor by an MFiX-like discretisation; see docs/validation.md.
pub const MFIX_SMALL_ANGLE: f64 = 5.0;
/// From this angle (deg) on, MFiX's output is matched to [`MFIX_TOLERANCE`].
pub const MFIX_LARGE_ANGLE: f64 = 25.0;
/// Relative tolerance on `e_t` and the spin against MFiX's published output from
/// [`MFIX_LARGE_ANGLE`].
pub const MFIX_TOLERANCE: [f64; 2] = [0.01, 0.01];
/// The same from [`MFIX_SMALL_ANGLE`] to [`MFIX_LARGE_ANGLE`].
pub const MFIX_MEDIUM_ANGLE_TOLERANCE: [f64; 2] = [0.015, 0.04];
/// The bound on the documented gap below [`MFIX_SMALL_ANGLE`].
pub const MFIX_SMALL_ANGLE_BOUND: [f64; 2] = [0.03, 0.20];

/// Model AA with the MFiX DEM05 inputs at the reference's 30 angles, against it.
pub fn mfix_check(mut progress: impl FnMut(&str)) -> CaseOutput {
    progress("kharaz mfix check");
    let mut out = CaseOutput::default();
    let setup = MFIX_DEM05;
    let reference = data::rows("linear_model_reference_mfix_dem05.csv");
    let outcomes: Vec<Outcome> = reference
        .iter()
        .map(|row| {
            impact(
                Model::ModelAA,
                &setup,
                row[0],
                50.0,
                Integrator::SymplecticEuler,
            )
        })
        .collect();
    for (o, row) in outcomes.iter().zip(&reference) {
        // Below 5 deg the gap to the published numbers is a documented departure, bounded so
        // that it cannot grow unnoticed.
        let ([e_t_tol, spin_tol], label) = if o.angle_deg >= MFIX_LARGE_ANGLE {
            (MFIX_TOLERANCE, "")
        } else if o.angle_deg >= MFIX_SMALL_ANGLE {
            (MFIX_MEDIUM_ANGLE_TOLERANCE, "")
        } else {
            (MFIX_SMALL_ANGLE_BOUND, " (documented small-angle gap)")
        };
        let what = |q: &str| format!("mfix model_aa {q}({} deg){label}", o.angle_deg);
        out.relative(what("e_t"), o.tangential_cor, row[1], e_t_tol);
        out.relative(what("spin"), o.spin, row[2], spin_tol);
    }
    let mut gap = Table::new(&[
        "impact_angle_deg",
        "tangential_cor",
        "mfix_tangential_cor",
        "rebound_spin_rad_per_s",
        "mfix_rebound_spin_rad_per_s",
    ]);
    for (o, row) in outcomes.iter().zip(&reference) {
        gap.push(vec![
            o.angle_deg.into(),
            o.tangential_cor.into(),
            row[1].into(),
            o.spin.into(),
            row[2].into(),
        ]);
    }
    out.tables.push((
        "kharaz_mfix_check".into(),
        table(&outcomes, setup.describe("t_c/50")),
    ));
    out.tables.push(("kharaz_mfix_side_by_side".into(), gap));
    out
}
