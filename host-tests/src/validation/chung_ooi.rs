//! docs/physics.md, section 5.5: Chung & Ooi's benchmark of contact laws at the impact level
//! (Granular Matter 13 (2011) 643-656, Tests 1 to 8), run with Hertz-Mindlin and, beside it, the
//! linear Model AA, against Hertz's closed forms, rigid-body theory, the Kharaz experiment and the
//! benchmark's published reference curves.

use soft_sphere::prelude::{
    ContactLaw, Frictionless, Hertz, HertzImpact, HertzMicroSlip, Law, LinearAA,
    LinearSpringDashpot, Material, MicroSlip, MindlinAA, MindlinAALuding, MindlinParameters,
    MindlinStateless, ModelAA, Sphere, TangentialParameters, Vec3, effective_mass,
};

use super::{CaseOutput, Cell, Table, rms};
use crate::analytic::rigid_body_oblique;
use crate::data;
use crate::impact::{floor, pair_collision, wall_impact};

/// Steps per contact duration in every run here but Test 3's.
pub const STEPS_PER_CONTACT: f64 = 400.0;
/// Test 3's steps per contact: symplectic Euler is first order, and the `delta^(1/4)` dashpot
/// of a strongly damped impact needs finer steps to rebound within 0.5 % of `e`.
pub const RESTITUTION_STEPS_PER_CONTACT: f64 = 2000.0;

/// A material of the benchmark: elastic constants and density.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solid {
    /// Name in tables.
    pub name: &'static str,
    /// Young's modulus (Pa).
    pub youngs_modulus: f64,
    /// Poisson's ratio.
    pub poisson_ratio: f64,
    /// Density (kg/m3).
    pub density: f64,
}

impl Solid {
    /// A material named `name`: Young's modulus (Pa), Poisson's ratio, density (kg/m3).
    const fn new(
        name: &'static str,
        youngs_modulus: f64,
        poisson_ratio: f64,
        density: f64,
    ) -> Self {
        Self {
            name,
            youngs_modulus,
            poisson_ratio,
            density,
        }
    }

    /// The kernel's material.
    pub fn material(&self) -> Material<f64> {
        Material::new(self.youngs_modulus, self.poisson_ratio).expect("a valid material")
    }
}

/// Test 1's glass.
pub const GLASS: Solid = Solid::new("glass", 4.8e10, 0.20, 2800.0);
/// Test 1's limestone.
pub const LIMESTONE: Solid = Solid::new("limestone", 2.0e10, 0.25, 2500.0);
/// Tests 2, 6, 7, 8's aluminium alloy.
pub const AL_ALLOY: Solid = Solid::new("al_alloy", 7.0e10, 0.30, 2699.0);
/// Test 2's magnesium alloy.
pub const MG_ALLOY: Solid = Solid::new("mg_alloy", 4.0e10, 0.35, 1800.0);
/// Tests 3 and 4's alumina.
pub const ALUMINA: Solid = Solid::new("alumina", 3.8e11, 0.23, 4000.0);
/// Test 3's cast iron.
pub const CAST_IRON: Solid = Solid::new("cast_iron", 1.0e11, 0.25, 7000.0);
/// Test 4's aluminium alloy plate (Kharaz et al.).
pub const AL_PLATE: Solid = Solid::new("al_plate", 7.0e10, 0.33, 2700.0);
/// Test 5's steel.
pub const STEEL: Solid = Solid::new("steel", 2.08e11, 0.30, 7850.0);
/// Test 7's copper.
pub const COPPER: Solid = Solid::new("copper", 1.2e11, 0.35, 8900.0);

/// The contact laws compared, in CSV column order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Contact {
    /// Hertz with Mindlin's spring and Model AA's plain cap.
    HertzAA,
    /// Hertz with Mindlin's spring and Luding's reset.
    HertzAALuding,
    /// Hertz with the stateless Mindlin law.
    HertzStateless,
    /// Hertz with Mindlin & Deresiewicz's micro-slip, [`MICRO_SLIP_SPRINGS`] springs.
    HertzMicroSlip,
    /// The linear Model AA with the Mindlin stiffness ratio and Hertz's contact duration.
    LinearAA,
}

/// Springs across the contact radius of the micro-slip law in the validation run: where Test 5's
/// distance from the finite-element curve has settled (`micro_slip_springs` table).
pub const MICRO_SLIP_SPRINGS: usize = 16;

impl Contact {
    /// Every law.
    pub const ALL: [Self; 5] = [
        Self::HertzAA,
        Self::HertzAALuding,
        Self::HertzStateless,
        Self::HertzMicroSlip,
        Self::LinearAA,
    ];

    /// The CSV column.
    pub fn name(self) -> &'static str {
        match self {
            Self::HertzAA => "hertz_aa",
            Self::HertzAALuding => "hertz_aa_luding",
            Self::HertzStateless => "hertz_stateless",
            Self::HertzMicroSlip => "hertz_microslip",
            Self::LinearAA => "linear_aa",
        }
    }
}

/// One impact's inputs: the pair's effective constants and the friction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pair {
    /// `E*` (Pa).
    pub effective_modulus: f64,
    /// `G*` (Pa).
    pub effective_shear_modulus: f64,
    /// `R*` (m).
    pub effective_radius: f64,
    /// `m*` (kg).
    pub effective_mass: f64,
    /// Normal approach speed (m/s).
    pub speed: f64,
    /// Restitution.
    pub restitution: f64,
    /// Coulomb friction.
    pub friction: f64,
    /// Tangential dashpot over the normal one, `eta_t / eta_n` (0: none).
    pub tangential_dashpot: f64,
}

impl Pair {
    /// A sphere of `solid` and `radius` against a rigid wall.
    pub fn on_wall(
        solid: &Solid,
        radius: f64,
        speed: f64,
        restitution: f64,
        friction: f64,
    ) -> Self {
        let m = solid.material();
        Self {
            effective_modulus: m.modulus_against_rigid(),
            effective_shear_modulus: m.shear_modulus_against_rigid(),
            effective_radius: radius,
            effective_mass: sphere_of(solid, radius).mass,
            speed,
            restitution,
            friction,
            tangential_dashpot: 0.0,
        }
    }

    /// Two spheres of `solid` and `radius` approaching at `speed`.
    pub fn identical(
        solid: &Solid,
        radius: f64,
        speed: f64,
        restitution: f64,
        friction: f64,
    ) -> Self {
        let m = solid.material();
        let mass = sphere_of(solid, radius).mass;
        Self {
            effective_modulus: m.effective_modulus(&m),
            effective_shear_modulus: m.effective_shear_modulus(&m),
            effective_radius: radius / 2.0,
            effective_mass: effective_mass(mass, mass),
            speed,
            restitution,
            friction,
            tangential_dashpot: 0.0,
        }
    }

    /// The same impact with LIGGGHTS' (and EDEM's) tangential dashpot for Hertz-Mindlin: the
    /// normal damping ratio in the tangential spring, `eta_t / eta_n = sqrt(k_t / k_n)` =
    /// `sqrt(4 G* / E*)`.
    pub fn with_matched_damping(self) -> Self {
        Self {
            tangential_dashpot: (4.0 * self.effective_shear_modulus / self.effective_modulus)
                .sqrt(),
            ..self
        }
    }

    /// The Hertz normal law, declared for this impact.
    pub fn hertz(&self) -> Hertz<f64> {
        let largest = HertzImpact {
            speed: self.speed,
            effective_radius: self.effective_radius,
        };
        Hertz::new(self.effective_modulus, self.restitution, largest).expect("a valid Hertz law")
    }

    /// Mindlin's parameters.
    pub fn mindlin(&self) -> MindlinParameters<f64> {
        MindlinParameters::new(
            self.effective_shear_modulus,
            self.tangential_dashpot,
            self.friction,
        )
        .expect("valid")
    }

    /// The linear law a user would set up for the same impact: `k_n` with Hertz's contact
    /// duration, `k_t / k_n = 4 G* / E*` (Mindlin's ratio, `2 (1 - nu) / (2 - nu)` for one
    /// material), the same `e` and dashpot ratio.
    pub fn linear(&self) -> LinearAA<f64> {
        let duration = self.hertz_duration();
        let undamped = LinearSpringDashpot::new(1.0, self.restitution).expect("valid");
        // t_c = pi / wd with wd = sqrt(k / m*) sqrt(1 - zeta^2).
        let zeta = undamped.damping_ratio();
        let stiffness =
            self.effective_mass * (std::f64::consts::PI / duration).powi(2) / (1.0 - zeta * zeta);
        let ratio = 4.0 * self.effective_shear_modulus / self.effective_modulus;
        ContactLaw::new(
            LinearSpringDashpot::new(stiffness, self.restitution).expect("valid"),
            ModelAA(
                TangentialParameters::new(
                    ratio * stiffness,
                    self.tangential_dashpot,
                    self.friction,
                )
                .expect("valid"),
            ),
        )
    }

    /// Hertz with micro-slip, its profile in up to `SPRINGS` breakpoints.
    pub fn micro_slip<const SPRINGS: usize>(&self) -> HertzMicroSlip<f64, SPRINGS> {
        ContactLaw::new(self.hertz(), MicroSlip::new(self.mindlin()))
    }

    /// Hertz's duration of this impact (the kernel's, for its restitution).
    pub fn hertz_duration(&self) -> f64 {
        let law = ContactLaw::new(self.hertz(), Frictionless);
        law.contact_duration(self.effective_mass)
    }

    /// Runs `action` with `contact`'s law for this pair.
    pub fn with<A: WithContact>(&self, contact: Contact, action: A) -> A::Output {
        match contact {
            Contact::HertzAA => {
                action.run(&ContactLaw::new(self.hertz(), MindlinAA(self.mindlin())))
            }
            Contact::HertzAALuding => action.run(&ContactLaw::new(
                self.hertz(),
                MindlinAALuding(self.mindlin()),
            )),
            Contact::HertzStateless => action.run(&ContactLaw::new(
                self.hertz(),
                MindlinStateless(self.mindlin()),
            )),
            Contact::HertzMicroSlip => action.run(&self.micro_slip::<MICRO_SLIP_SPRINGS>()),
            Contact::LinearAA => action.run(&self.linear()),
        }
    }
}

/// Something to do with a law, whichever [`Contact`] names it.
pub trait WithContact {
    /// What it gives.
    type Output;
    /// Does it with `law`.
    fn run<L: Law<Float = f64>>(self, law: &L) -> Self::Output;
}

/// A sphere of `solid` at rest at the origin.
pub fn sphere_of(solid: &Solid, radius: f64) -> Sphere<f64> {
    Sphere::solid(Vec3::ZERO, radius, solid.density)
}

/// The step for `law`: its contact duration over [`STEPS_PER_CONTACT`], checked.
fn step_for<L: Law<Float = f64>>(
    law: &L,
    effective_mass: f64,
) -> soft_sphere::prelude::TimeStep<f64> {
    step_with(law, effective_mass, STEPS_PER_CONTACT)
}

/// The step for `law`: its contact duration over `steps`, checked.
fn step_with<L: Law<Float = f64>>(
    law: &L,
    effective_mass: f64,
    steps: f64,
) -> soft_sphere::prelude::TimeStep<f64> {
    let duration = law.contact_duration(effective_mass);
    // A contact that never ends (e = 0) takes the step of its undamped half-period.
    let duration = if duration.is_finite() {
        duration
    } else {
        50.0 * law.recommended_time_step(effective_mass)
    };
    law.time_step(duration / steps, effective_mass)
        .expect("a stable step")
}

/// A wall impact: the sphere's velocity and spin just after it left the wall.
struct WallImpact {
    sphere: Sphere<f64>,
}

impl WithContact for WallImpact {
    type Output = Sphere<f64>;
    fn run<L: Law<Float = f64>>(self, law: &L) -> Sphere<f64> {
        let dt = step_for(law, self.sphere.mass);
        let steps = 40 * STEPS_PER_CONTACT as usize;
        wall_impact(law, self.sphere, &floor(), dt, steps, |_| {})
            .expect("the sphere rebounds")
            .rebound
    }
}

/// A collision of two spheres (and their effective mass): both spheres after they part.
struct Collide(Sphere<f64>, Sphere<f64>, f64, f64);

impl WithContact for Collide {
    type Output = [Sphere<f64>; 2];
    fn run<L: Law<Float = f64>>(self, law: &L) -> [Sphere<f64>; 2] {
        let dt = step_with(law, self.2, self.3);
        let steps = 40 * self.3 as usize;
        pair_collision(law, self.0, self.1, dt, steps, |_, _, _| {}).expect("the spheres part")
    }
}

/// A sphere of `solid` touching the floor with centre velocity `(v_t, 0, -v_n)` and spin `w_y`.
fn wall_sphere(solid: &Solid, radius: f64, v_n: f64, v_t: f64, spin_y: f64) -> Sphere<f64> {
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, radius), radius, solid.density);
    sphere.velocity = Vec3::new(v_t, 0.0, -v_n);
    sphere.angular_velocity = Vec3::new(0.0, spin_y, 0.0);
    sphere
}

/// Tangential velocity of a sphere's lowest point along x: `v_x - w_y R`.
fn contact_point_velocity(sphere: &Sphere<f64>) -> f64 {
    sphere.velocity.x - sphere.angular_velocity.y * sphere.radius
}

// ---------------------------------------------------------------- Tests 1 and 2: elastic impact

/// Relative tolerance on Hertz's peak overlap and duration, and the RMS of the force-overlap
/// curve relative to the peak force.
pub const HERTZ_TOLERANCE: f64 = 5e-3;

/// Peak overlap of an undamped Hertz impact: `(15 m* v^2 / (16 E* sqrt(R*)))^(2/5)`.
pub fn hertz_peak_overlap(pair: &Pair) -> f64 {
    (15.0 * pair.effective_mass * pair.speed.powi(2)
        / (16.0 * pair.effective_modulus * pair.effective_radius.sqrt()))
    .powf(0.4)
}

/// Duration of an undamped Hertz impact: `2.868 (m*^2 / (R* E*^2 v))^(1/5)`.
pub fn hertz_duration(pair: &Pair) -> f64 {
    2.868
        * (pair.effective_mass.powi(2)
            / (pair.effective_radius * pair.effective_modulus.powi(2) * pair.speed))
            .powf(0.2)
}

/// Hertz's elastic force at `overlap`: `(4/3) E* sqrt(R*) delta^(3/2)`.
pub fn hertz_force(pair: &Pair, overlap: f64) -> f64 {
    4.0 / 3.0 * pair.effective_modulus * pair.effective_radius.sqrt() * overlap.powf(1.5)
}

/// Tests 1 and 2: elastic normal impacts, sphere-sphere and sphere-wall.
pub fn elastic(mut progress: impl FnMut(&str)) -> CaseOutput {
    progress("Chung & Ooi Tests 1 and 2");
    let mut out = CaseOutput::default();
    let mut table = Table::new(&[
        "test",
        "peak_overlap_m",
        "hertz_peak_overlap_m",
        "duration_s",
        "hertz_duration_s",
        "force_rms_over_peak",
    ])
    .with_comment(format!("Chung & Ooi Tests 1 (two spheres, R = 0.01 m, +-10 m/s) and 2 (sphere on a rigid plane, R = 0.1 m, 0.2 m/s), e = 1, Hertz with no friction, dt = t_c/{STEPS_PER_CONTACT}, symplectic Euler"));
    let mut curves = Table::new(&["test", "overlap_m", "force_n", "hertz_force_n"]).shown_every(0);
    let cases = [
        (1, GLASS, true),
        (1, LIMESTONE, true),
        (2, AL_ALLOY, false),
        (2, MG_ALLOY, false),
    ];
    for (test, solid, two) in cases {
        let label = format!("test{test}_{}", solid.name);
        let (pair, radius) = if two {
            (Pair::identical(&solid, 0.01, 20.0, 1.0, 0.0), 0.01)
        } else {
            (Pair::on_wall(&solid, 0.1, 0.2, 1.0, 0.0), 0.1)
        };
        let law = ContactLaw::new(pair.hertz(), Frictionless);
        let dt = step_for(&law, pair.effective_mass);
        let mut samples = Vec::new();
        let (peak, duration) = if two {
            let mut i = sphere_of(&solid, radius);
            let mut j = sphere_of(&solid, radius);
            j.position = Vec3::new(2.0 * radius, 0.0, 0.0);
            i.velocity = Vec3::new(10.0, 0.0, 0.0);
            j.velocity = Vec3::new(-10.0, 0.0, 0.0);
            let mut steps = 0usize;
            pair_collision(&law, i, j, dt, 100_000, |f, _, _| {
                steps += 1;
                samples.push((f.overlap, f.normal_force));
            })
            .expect("the spheres part");
            let peak = samples.iter().map(|s| s.0).fold(0.0, f64::max);
            // The pair touched from step 1 to `steps`; the last partial step is not resolved here,
            // so the duration is bounded to a step: take the midpoint.
            (peak, (steps as f64 + 0.5) * dt.seconds())
        } else {
            let sphere = wall_sphere(&solid, radius, 0.2, 0.0, 0.0);
            let o = wall_impact(&law, sphere, &floor(), dt, 100_000, |f| {
                samples.push((f.overlap, f.normal_force))
            })
            .expect("the sphere rebounds");
            (o.max_overlap, o.contact_duration)
        };
        let peak_force = hertz_force(&pair, hertz_peak_overlap(&pair));
        let force_rms = rms(samples.iter().map(|&(d, f)| (f, hertz_force(&pair, d)))) / peak_force;
        for &(d, f) in samples.iter().step_by(4) {
            curves.push(vec![
                Cell::Text(label.clone()),
                d.into(),
                f.into(),
                hertz_force(&pair, d).into(),
            ]);
        }
        table.push(vec![
            Cell::Text(label.clone()),
            peak.into(),
            hertz_peak_overlap(&pair).into(),
            duration.into(),
            hertz_duration(&pair).into(),
            force_rms.into(),
        ]);
        out.relative(
            format!("chung_ooi {label} peak overlap vs Hertz"),
            peak,
            hertz_peak_overlap(&pair),
            HERTZ_TOLERANCE,
        );
        out.relative(
            format!("chung_ooi {label} duration vs Hertz"),
            duration,
            hertz_duration(&pair),
            HERTZ_TOLERANCE,
        );
        out.absolute(
            format!("chung_ooi {label} force-overlap RMS / peak force"),
            force_rms,
            0.0,
            HERTZ_TOLERANCE,
        );
    }
    out.tables.push(("chung_ooi_tests1_2".into(), table));
    out.tables
        .push(("chung_ooi_tests1_2_force_overlap".into(), curves));
    out
}

// ---------------------------------------------------------------- Test 3: restitution

/// Relative tolerance on the rebound ratio (absolute at `e = 0`).
pub const RESTITUTION_TOLERANCE: f64 = 5e-3;

/// LAMMPS' `damping tsuji` coefficient: Tsuji's polynomial fit of `alpha(e)`.
pub fn tsuji_polynomial(e: f64) -> f64 {
    1.2728 - 4.2783 * e + 11.087 * e.powi(2) - 22.348 * e.powi(3) + 27.467 * e.powi(4)
        - 18.022 * e.powi(5)
        + 4.8218 * e.powi(6)
}

/// LIGGGHTS' `hertz` dashpot written as this kernel's `alpha`: `2 sqrt(5/6) beta sqrt(2 E* a m*)`
/// with `beta = -ln e / sqrt(ln^2 e + pi^2)` is `alpha = 2 sqrt(5/4) beta`.
pub fn liggghts_alpha(e: f64) -> f64 {
    if e <= 0.0 {
        return 2.0 * 1.25f64.sqrt();
    }
    let l = e.ln();
    2.0 * 1.25f64.sqrt() * (-l) / (l * l + std::f64::consts::PI.powi(2)).sqrt()
}

/// The rebound ratio of a normal impact of `solid` (R = 2.5 mm) on a rigid wall at `speed` with
/// the Hertz law `hertz`.
fn rebound_ratio(solid: &Solid, hertz: Hertz<f64>, speed: f64) -> f64 {
    let law = ContactLaw::new(hertz, Frictionless);
    let sphere = wall_sphere(solid, 2.5e-3, speed, 0.0, 0.0);
    let dt = step_with(&law, sphere.mass, RESTITUTION_STEPS_PER_CONTACT);
    // At e = 0 the overlap creeps back to zero; a rebound below 1e-4 of the approach counts as
    // none.
    match wall_impact(
        &law,
        sphere,
        &floor(),
        dt,
        100 * RESTITUTION_STEPS_PER_CONTACT as usize,
        |_| {},
    ) {
        Ok(o) => o.rebound.velocity.z / speed,
        Err(None) => 0.0,
        Err(Some(e)) => panic!("the kernel refused the impact: {e}"),
    }
}

/// Test 3: the rebound ratio against the input `e` over a factor 100 in impact speed, for the
/// solved dashpot, LAMMPS' polynomial and LIGGGHTS' formula.
pub fn restitution(mut progress: impl FnMut(&str)) -> CaseOutput {
    progress("Chung & Ooi Test 3");
    let mut out = CaseOutput::default();
    let mut table = Table::new(&["material", "speed_m_per_s", "e", "solved", "lammps_tsuji_polynomial", "liggghts_hertz"])
        .with_comment("Chung & Ooi Test 3: R = 2.5 mm on a rigid plane, rebound speed over approach speed; the solved dashpot (this kernel), LAMMPS' Tsuji polynomial and LIGGGHTS' formula for alpha, all integrated by the kernel at dt = t_c/2000")
        .shown_every(3);
    let (mut lammps, mut liggghts) = (Vec::new(), Vec::new());
    for solid in [ALUMINA, CAST_IRON] {
        let modulus = solid.material().modulus_against_rigid();
        for speed in [0.039, 0.39, 3.9] {
            let largest = HertzImpact {
                speed,
                effective_radius: 2.5e-3,
            };
            for k in 0..=10 {
                let e = f64::from(k) / 10.0;
                let solved = rebound_ratio(
                    &solid,
                    Hertz::new(modulus, e, largest).expect("valid"),
                    speed,
                );
                let poly = Hertz::with_damping_factor(modulus, tsuji_polynomial(e), largest)
                    .expect("valid");
                let lig =
                    Hertz::with_damping_factor(modulus, liggghts_alpha(e), largest).expect("valid");
                let (poly, lig) = (
                    rebound_ratio(&solid, poly, speed),
                    rebound_ratio(&solid, lig, speed),
                );
                lammps.push((poly, e));
                liggghts.push((lig, e));
                table.push(vec![
                    Cell::Text(solid.name.into()),
                    speed.into(),
                    e.into(),
                    solved.into(),
                    poly.into(),
                    lig.into(),
                ]);
                let what = format!("chung_ooi test3 {} v = {speed} e = {e} rebound", solid.name);
                if e == 0.0 {
                    out.absolute(what, solved, 0.0, RESTITUTION_TOLERANCE);
                } else {
                    out.relative(what, solved, e, RESTITUTION_TOLERANCE);
                }
            }
        }
    }
    out.notes.push(format!(
        "Test 3: RMS distance of the rebound ratio from the input e: LAMMPS' Tsuji polynomial {:.4}, LIGGGHTS' formula {:.4} (the solved dashpot is within {RESTITUTION_TOLERANCE} relative)",
        rms(lammps), rms(liggghts)
    ));
    out.tables.push(("chung_ooi_test3".into(), table));
    out
}

// ---------------------------------------------------------------- Test 4: Kharaz

/// Relative tolerance on the tangential restitution against rigid-body theory in gross sliding.
pub const SLIDING_TOLERANCE: f64 = 5e-3;

/// Test 4's inputs: alumina (R = 2.5 mm) on an aluminium alloy plate at 3.9 m/s.
pub fn kharaz_pair() -> Pair {
    let (sphere, plate) = (ALUMINA.material(), AL_PLATE.material());
    Pair {
        effective_modulus: sphere.effective_modulus(&plate),
        effective_shear_modulus: sphere.effective_shear_modulus(&plate),
        effective_radius: 2.5e-3,
        effective_mass: sphere_of(&ALUMINA, 2.5e-3).mass,
        speed: 3.9,
        restitution: 0.98,
        friction: 0.092,
        tangential_dashpot: 0.0,
    }
}

/// Test 4: the Kharaz oblique impact (5 to 85 degrees), RMS distance to the experiment for each
/// law, for the tangential restitution, the rebound spin and the rebound angle.
pub fn kharaz(mut progress: impl FnMut(&str)) -> CaseOutput {
    progress("Chung & Ooi Test 4");
    let mut out = CaseOutput::default();
    let pair = kharaz_pair();
    let mut header = vec!["impact_angle_deg".to_string()];
    for c in Contact::ALL {
        for q in [
            "tangential_cor",
            "rebound_spin_rad_per_s",
            "rebound_angle_deg",
        ] {
            header.push(format!("{}_{q}", c.name()));
        }
    }
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    let mut table = Table::new(&header)
        .with_comment("Chung & Ooi Test 4: alumina sphere (R = 2.5 mm, 4000 kg/m3) on an Al alloy plate (E = 70 GPa, nu = 0.33), 3.9 m/s, e = 0.98, mu = 0.092, no tangential dashpot, dt = t_c/400")
        .shown_every(10);
    let speed = pair.speed;
    let outcome = |c: Contact, angle: f64| {
        let t = angle.to_radians();
        let sphere = wall_sphere(&ALUMINA, 2.5e-3, speed * t.cos(), speed * t.sin(), 0.0);
        let after = pair.with(c, WallImpact { sphere });
        let (v, w) = (after.velocity, after.angular_velocity.y);
        [
            v.x / sphere.velocity.x,
            w.abs(),
            v.x.atan2(v.z).to_degrees(),
        ]
    };
    let threshold = (3.5 * pair.friction * (1.0 + pair.restitution))
        .atan()
        .to_degrees();
    for angle in (1..=17).map(|k| f64::from(5 * k)) {
        let mut row = vec![angle.into()];
        for c in Contact::ALL {
            let o = outcome(c, angle);
            if angle > threshold + 5.0 {
                let (rigid, _) = rigid_body_oblique(angle, pair.restitution, pair.friction);
                out.relative(
                    format!(
                        "chung_ooi test4 {} e_t({angle} deg) vs rigid body",
                        c.name()
                    ),
                    o[0],
                    rigid,
                    SLIDING_TOLERANCE,
                );
            }
            row.extend(o.map(Cell::from));
        }
        table.push(row);
    }
    let files = [
        "kharaz2001_tangential_cor.csv",
        "kharaz2001_rebound_spin.csv",
        "kharaz2001_rebound_angle.csv",
    ];
    for c in Contact::ALL {
        let distances: Vec<f64> = files
            .iter()
            .enumerate()
            .map(|(q, file)| {
                let points = data::rows(file);
                rms(points.iter().map(|p| (outcome(c, p[0])[q], p[1])))
            })
            .collect();
        out.notes.push(format!(
            "Test 4 {}: RMS distance to Kharaz et al. (2001): tangential restitution {:.3}, spin {:.1} rad/s, rebound angle {:.2} deg",
            c.name(), distances[0], distances[1], distances[2]
        ));
    }
    out.tables.push(("chung_ooi_test4".into(), table));
    out
}

// ---------------------------------------------------------------- Tests 5 and 6: oblique impacts

/// The RMS distance from the reference curves of Tests 5 and 6 that the run reports Hertz-Mindlin
/// (plain cap) against; measured and shown, not enforced (docs/validation.md, "Hertz-Mindlin and
/// Chung & Ooi's benchmark", says why it is not reached).
pub const REFERENCE_RMS_GOAL: f64 = 0.10;

/// Absolute tolerance on the RMS distance from rigid-body theory in gross sliding at `e = 1`.
pub const ELASTIC_SLIDING_TOLERANCE: f64 = 1e-4;
/// Test 7: spheres whose contact points move together exchange nothing: the tangential velocity
/// left (m/s, absolute) and the spin kept (relative), to rounding.
pub const NO_EXCHANGE_TOLERANCE: f64 = 1e-9;
/// The same at `e = 0.5`, where the Coulomb limit includes the normal dashpot
/// ([`TangentialParameters`]' note: 6.7 % more friction impulse than rigid-body theory).
pub const DAMPED_SLIDING_TOLERANCE: f64 = 0.04;

/// Steps per contact of the runs held to LAMMPS (which takes about 22000).
pub const PEER_STEPS_PER_CONTACT: f64 = 2000.0;
/// Absolute tolerance on `V_s'/(mu V_n')` against LAMMPS: its torque arm is `R - delta/2`, the
/// kernel's `R` (measured within 0.016).
pub const PEER_TOLERANCE: f64 = 0.02;

/// The factor on `G*` of the sensitivity note: the stiffness ratio of LAMMPS 20220106's
/// `fix wall/gran hertz/material` wall.
pub const SOFTENED_SHEAR: f64 = 0.47;

/// RMS distance from Test 5's finite-element curve the micro-slip law is held to (its
/// digitisation scatters by about 0.065).
pub const MICRO_SLIP_FEM_TOLERANCE: f64 = 0.08;
/// RMS distance from Test 6's Al alloy curve the micro-slip law with LIGGGHTS' tangential
/// dashpot is held to (0.152 measured).
pub const MICRO_SLIP_TEST6_TOLERANCE: f64 = 0.16;

/// Test 5 at `psi` with micro-slip on `SPRINGS` springs.
pub fn test5_micro_slip<const SPRINGS: usize>(psi: f64) -> f64 {
    let pair = test5_pair();
    let v_t = psi * pair.friction * pair.speed;
    let sphere = wall_sphere(&STEEL, TEST5_RADIUS, pair.speed, v_t, 0.0);
    let after = WallImpact { sphere }.run(&pair.micro_slip::<SPRINGS>());
    contact_point_velocity(&after) / (pair.friction * after.velocity.z)
}

/// One abscissa's outcome of a sweep.
type Run = fn(f64) -> f64;

/// Test 5's distance from the finite-element curve against the number of micro-slip springs.
fn micro_slip_springs(fem: &[Vec<f64>]) -> Table {
    let mut table = Table::new(&["springs", "rms_to_fem"]).with_comment(
        "test5: RMS distance of hertz_microslip from the finite-element curve against the number of breakpoints of its profile",
    );
    let runs: [(usize, Run); 6] = [
        (3, test5_micro_slip::<3>),
        (4, test5_micro_slip::<4>),
        (8, test5_micro_slip::<8>),
        (16, test5_micro_slip::<16>),
        (32, test5_micro_slip::<32>),
        (64, test5_micro_slip::<64>),
    ];
    for (springs, run) in runs {
        let distance = rms(fem.iter().map(|p| (run(p[0]), p[1])));
        table.push(vec![(springs as f64).into(), distance.into()]);
    }
    table
}

/// Test 5's pair: steel on a rigid plane, 5 m/s, e = 1, mu = 0.3.
pub fn test5_pair() -> Pair {
    Pair::on_wall(&STEEL, TEST5_RADIUS, 5.0, 1.0, 0.3)
}
const TEST5_RADIUS: f64 = 0.01;

/// Test 5 at `psi = V_s / (mu V_n)`: `V_s' / (mu V_n')` of the contact point.
pub fn test5(contact: Contact, psi: f64) -> f64 {
    test5_of(&test5_pair(), contact, psi)
}

/// Test 5 for `pair` (Test 5's but for what a sensitivity study changes).
pub fn test5_of(pair: &Pair, contact: Contact, psi: f64) -> f64 {
    let v_t = psi * pair.friction * pair.speed;
    let sphere = wall_sphere(&STEEL, TEST5_RADIUS, pair.speed, v_t, 0.0);
    let after = pair.with(contact, WallImpact { sphere });
    contact_point_velocity(&after) / (pair.friction * after.velocity.z)
}

/// Test 5 at `psi` as two identical steel spheres (R = 10 mm) approaching at `V_n` = 5 m/s with
/// relative tangential speed `psi mu V_n`: the relative contact-point `V_s' / (mu V_n')`, both
/// along the initial axes. The relative motion is Test 5's while the spheres' lateral travel in
/// contact is small against their radius (`psi` up to about 4); beyond it the line of centres
/// turns during contact. The case LAMMPS runs beside the kernel (`examples/lammps/check.sh`).
///
/// At `steps_per_contact` steps per contact duration (symplectic Euler, first order).
pub fn test5_spheres(contact: Contact, psi: f64, steps_per_contact: f64) -> f64 {
    let radius = TEST5_RADIUS;
    let pair = Pair::identical(&STEEL, radius, 5.0, 1.0, 0.3);
    let half = 0.5 * psi * pair.friction * pair.speed;
    let mut i = sphere_of(&STEEL, radius);
    let mut j = sphere_of(&STEEL, radius);
    j.position = Vec3::new(0.0, 0.0, 2.0 * radius);
    i.velocity = Vec3::new(-half, 0.0, 2.5);
    j.velocity = Vec3::new(half, 0.0, -2.5);
    let [a, b] = pair.with(
        contact,
        Collide(i, j, pair.effective_mass, steps_per_contact),
    );
    // i's contact point is at +R z, j's at -R z: v_x + w_y z.
    let point_i = a.velocity.x + a.angular_velocity.y * radius;
    let point_j = b.velocity.x - b.angular_velocity.y * radius;
    (point_j - point_i) / (pair.friction * (b.velocity.z - a.velocity.z).abs())
}

/// Rigid-body theory for Test 5 (e = 1): `(psi - 7)` in gross sliding, `psi >= 7`; `None` below.
pub fn test5_rigid(psi: f64) -> Option<f64> {
    (psi >= 7.0).then_some(psi - 7.0)
}

/// Test 6's pair: aluminium alloy (R = 0.1 m) on a rigid plane, 0.2 m/s, e = 0.5, mu = 0.4.
pub fn test6_pair() -> Pair {
    Pair::on_wall(&AL_ALLOY, 0.1, 0.2, 0.5, 0.4)
}

/// Test 6 at `x = 3.5 mu (1 + e) V_n / V_s`: `beta = -(contact-point velocity after) / V_s`, the
/// sphere spinning so that its contact point moves at `V_s = R w0` with no centre velocity.
pub fn test6(contact: Contact, x: f64) -> f64 {
    test6_of(&test6_pair(), contact, x)
}

/// Test 6 for `pair` (Test 6's but for what a sensitivity study changes).
pub fn test6_of(pair: &Pair, contact: Contact, x: f64) -> f64 {
    let v_s = 3.5 * pair.friction * (1.0 + pair.restitution) * pair.speed / x;
    let sphere = wall_sphere(&AL_ALLOY, 0.1, pair.speed, 0.0, -v_s / 0.1);
    let after = pair.with(contact, WallImpact { sphere });
    -contact_point_velocity(&after) / v_s
}

/// Multiples of LIGGGHTS' tangential dashpot ([`Pair::with_matched_damping`]) Test 6 is swept
/// over.
pub const TEST6_DASHPOT_SCALES: [f64; 8] = [0.0, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0];

/// The overdamped limit of Tests 6 and 8: the contact point slides as a rigid body until it
/// stops (`x <= 1`), and a tangential mode too damped to ring keeps it stopped: `beta =
/// min(x - 1, 0)`.
pub fn beta_overdamped(x: f64) -> f64 {
    (x - 1.0).min(0.0)
}

/// Test 6's distance from the Al alloy curve against the tangential dashpot, for Hertz-Mindlin
/// and micro-slip. The dashpot only takes energy from the tangential mode, so the strongest
/// one ends at the overdamped limit ([`beta_overdamped`]), checked at every point within
/// [`DAMPED_SLIDING_TOLERANCE`] (its Coulomb limit includes the normal dashpot, as in gross
/// sliding); the curve's reversal at large `x` needs a contact that rings back, which takes a
/// weaker dashpot. The sweep says how close any dashpot of this form comes.
fn test6_dashpot(out: &mut CaseOutput, points: &[Vec<f64>]) -> Table {
    let liggghts = test6_pair().with_matched_damping().tangential_dashpot;
    let overdamped = rms(points.iter().map(|p| (beta_overdamped(p[0]), p[1])));
    let mut table = Table::new(&["dashpot_scale", "eta_t_over_eta_n", "hertz_aa", "hertz_microslip"])
        .with_comment(format!("Chung & Ooi Test 6: RMS distance from the Al alloy curve against the tangential dashpot, in multiples of LIGGGHTS' eta_t/eta_n = {liggghts:.3}; the overdamped limit beta = min(x - 1, 0) is {overdamped:.4} from the curve"));
    let laws = [Contact::HertzAA, Contact::HertzMicroSlip];
    let pair_at = |scale: f64| Pair {
        tangential_dashpot: scale * liggghts,
        ..test6_pair()
    };
    for scale in TEST6_DASHPOT_SCALES {
        let pair = pair_at(scale);
        let [linear, micro] =
            laws.map(|c| rms(points.iter().map(|p| (test6_of(&pair, c, p[0]), p[1]))));
        table.push(vec![
            scale.into(),
            (scale * liggghts).into(),
            linear.into(),
            micro.into(),
        ]);
    }
    let strongest = TEST6_DASHPOT_SCALES[TEST6_DASHPOT_SCALES.len() - 1];
    let pair = pair_at(strongest);
    for contact in laws {
        let to_limit = rms(points
            .iter()
            .map(|p| (test6_of(&pair, contact, p[0]), beta_overdamped(p[0]))));
        out.absolute(
            format!(
                "chung_ooi test6 {} with {strongest}x LIGGGHTS' tangential dashpot, RMS to the overdamped limit",
                contact.name(),
            ),
            to_limit,
            0.0,
            DAMPED_SLIDING_TOLERANCE,
        );
    }
    table
}

/// Rigid-body theory for Tests 6 and 8 in gross sliding (`x <= 1`): `beta = -1 + x`.
pub fn beta_rigid(x: f64) -> Option<f64> {
    (x <= 1.0).then_some(x - 1.0)
}

/// Test 8 at `x`: a sphere of aluminium alloy spinning so that its contact point moves at
/// `V_s`, hitting an identical sphere at rest at 0.2 m/s; `beta` of the relative contact-point
/// velocity.
pub fn test8(contact: Contact, x: f64) -> f64 {
    test8_of(&test8_pair(), contact, x)
}

/// Test 8's pair: two aluminium alloy spheres (R = 0.1 m), 0.2 m/s, e = 0.5, mu = 0.4.
pub fn test8_pair() -> Pair {
    Pair::identical(&AL_ALLOY, 0.1, 0.2, 0.5, 0.4)
}

/// Test 8 for `pair` (Test 8's but for what a sensitivity study changes).
pub fn test8_of(pair: &Pair, contact: Contact, x: f64) -> f64 {
    let radius = 0.1;
    let v_s = 3.5 * pair.friction * (1.0 + pair.restitution) * pair.speed / x;
    let mut i = sphere_of(&AL_ALLOY, radius);
    let mut j = sphere_of(&AL_ALLOY, radius);
    j.position = Vec3::new(2.0 * radius, 0.0, 0.0);
    i.velocity = Vec3::new(pair.speed, 0.0, 0.0);
    // i's contact point (+x side) moves along +z at R w.
    i.angular_velocity = Vec3::new(0.0, -v_s / radius, 0.0);
    let [a, b] = pair.with(
        contact,
        Collide(i, j, pair.effective_mass, STEPS_PER_CONTACT),
    );
    // Contact-point velocities along z: i's at +R x, j's at -R x.
    let point_i = a.velocity.z - a.angular_velocity.y * radius;
    let point_j = b.velocity.z + b.angular_velocity.y * radius;
    -(point_i - point_j) / v_s
}

/// Test 7 at spin `w0`: two identical spheres approaching at 0.2 m/s each, spinning so that
/// their contact points move together: the final tangential centre velocity and spin of sphere
/// i. The reference is no tangential exchange: `(0, w0)`.
pub fn test7(contact: Contact, solid: &Solid, spin: f64) -> (f64, f64) {
    let radius = 0.1;
    let pair = Pair::identical(solid, radius, 0.4, 0.5, 0.4);
    let mut i = sphere_of(solid, radius);
    let mut j = sphere_of(solid, radius);
    j.position = Vec3::new(2.0 * radius, 0.0, 0.0);
    i.velocity = Vec3::new(0.2, 0.0, 0.0);
    j.velocity = Vec3::new(-0.2, 0.0, 0.0);
    i.angular_velocity = Vec3::new(0.0, spin, 0.0);
    j.angular_velocity = Vec3::new(0.0, -spin, 0.0);
    let [a, _] = pair.with(
        contact,
        Collide(i, j, pair.effective_mass, STEPS_PER_CONTACT),
    );
    (a.velocity.z, a.angular_velocity.y)
}

/// Log-spaced points from `low` to `high`.
fn log_spaced(low: f64, high: f64, count: usize) -> Vec<f64> {
    (0..count)
        .map(|k| low * (high / low).powf(k as f64 / (count - 1) as f64))
        .collect()
}

/// Every law at every abscissa, one row per abscissa.
fn sweep(header: &str, xs: &[f64], run: impl Fn(Contact, f64) -> f64, comment: String) -> Table {
    let mut columns = vec![header];
    columns.extend(Contact::ALL.map(Contact::name));
    let mut table = Table::new(&columns).with_comment(comment).shown_every(8);
    for &x in xs {
        let mut row = vec![x.into()];
        row.extend(Contact::ALL.map(|c| Cell::from(run(c, x))));
        table.push(row);
    }
    table
}

/// RMS distance of each law from a reference curve, evaluated at the reference's abscissae.
fn distances(
    out: &mut CaseOutput,
    test: &str,
    reference: &str,
    pair: Pair,
    run: impl Fn(&Pair, Contact, f64) -> f64,
    rigid: impl Fn(f64) -> Option<f64>,
    rigid_tolerance: f64,
) -> Table {
    let points = data::rows(reference);
    // Test 5's digitised steel curve behaves as another DEM code's output with about half of
    // Mindlin's stiffness: reported, not a target (the finite-element curve is).
    let what = if reference.contains("test5_steel") {
        "the digitised steel curve (a DEM output, not a target)"
    } else {
        "the reference curve"
    };
    let damped = pair.with_matched_damping();
    let mut table = Table::new(&["law", "rms_to_reference", "rms_to_rigid_body_in_gross_sliding", "rms_to_reference_with_tangential_dashpot"])
        .with_comment(format!("{test}: RMS distance of each law from the benchmark's reference curve ({reference}, at its {} points) and from rigid-body theory where the sphere slides throughout; the last column with LIGGGHTS' tangential dashpot, eta_t/eta_n = sqrt(4 G*/E*) = {:.3}", points.len(), damped.tangential_dashpot));
    for c in Contact::ALL {
        let to_reference = rms(points.iter().map(|p| (run(&pair, c, p[0]), p[1])));
        let sliding: Vec<(f64, f64)> = points
            .iter()
            .filter_map(|p| rigid(p[0]).map(|r| (run(&pair, c, p[0]), r)))
            .collect();
        let to_rigid = rms(sliding);
        let damped_to_reference = rms(points.iter().map(|p| (run(&damped, c, p[0]), p[1])));
        table.push(vec![
            Cell::Text(c.name().into()),
            to_reference.into(),
            to_rigid.into(),
            damped_to_reference.into(),
        ]);
        out.notes.push(format!(
            "{test} {}: RMS {to_reference:.3} from {what} (against {REFERENCE_RMS_GOAL} asked of hertz_aa); {damped_to_reference:.3} with LIGGGHTS' tangential dashpot",
            c.name()
        ));
        out.absolute(
            format!(
                "chung_ooi {test} {} RMS to rigid-body theory in gross sliding",
                c.name()
            ),
            to_rigid,
            0.0,
            rigid_tolerance,
        );
    }
    table
}

/// Tests 5 to 8: the oblique impacts, written as CSVs, with their distances from the reference
/// curves and rigid-body theory.
pub fn oblique(mut progress: impl FnMut(&str)) -> CaseOutput {
    let mut out = CaseOutput::default();
    progress("Chung & Ooi Test 5");
    let psi: Vec<f64> = (0..48)
        .map(|k| 0.05 + (13.0 - 0.05) * f64::from(k) / 47.0)
        .collect();
    out.tables.push((
        "chung_ooi_test5".into(),
        sweep("psi", &psi, test5, format!("Chung & Ooi Test 5: steel sphere (R = {TEST5_RADIUS} m) on a rigid plane, V_n = 5 m/s, e = 1, mu = 0.3, no initial spin, no tangential dashpot; contact-point V_s'/(mu V_n') against psi = V_s/(mu V_n); dt = t_c/400")),
    ));
    let t5 = distances(
        &mut out,
        "test5",
        "chung_ooi2011_test5_steel.csv",
        test5_pair(),
        test5_of,
        test5_rigid,
        ELASTIC_SLIDING_TOLERANCE,
    );
    out.tables.push(("chung_ooi_test5_distances".into(), t5));
    // The same figure's finite-element curve: the continuum answer, micro-slip included.
    let fem = data::rows("chung_ooi2011_test5_fem.csv");
    let mut t5_fem = Table::new(&["law", "rms_to_fem"]).with_comment(format!(
        "test5: RMS distance of each law from the benchmark's finite-element curve (chung_ooi2011_test5_fem.csv, at its {} points)",
        fem.len()
    ));
    for c in Contact::ALL {
        let to_fem = rms(fem.iter().map(|p| (test5(c, p[0]), p[1])));
        t5_fem.push(vec![Cell::Text(c.name().into()), to_fem.into()]);
        out.notes.push(format!(
            "test5 {}: RMS {to_fem:.3} from the finite-element curve",
            c.name()
        ));
    }
    out.tables
        .push(("chung_ooi_test5_fem_distances".into(), t5_fem));
    let micro = rms(fem
        .iter()
        .map(|p| (test5(Contact::HertzMicroSlip, p[0]), p[1])));
    out.absolute(
        "chung_ooi test5 hertz_microslip RMS to the finite-element curve",
        micro,
        0.0,
        MICRO_SLIP_FEM_TOLERANCE,
    );
    out.tables.push((
        "chung_ooi_test5_micro_slip_springs".into(),
        micro_slip_springs(&fem),
    ));

    // What the steel curve asks of the spring: Mindlin's at 0.47 of its stiffness.
    let soft = |mut pair: Pair| {
        pair.effective_shear_modulus *= SOFTENED_SHEAR;
        pair
    };
    let (soft5, soft6) = (soft(test5_pair()), soft(test6_pair()));
    let steel = data::rows("chung_ooi2011_test5_steel.csv");
    let al = data::rows("chung_ooi2011_test6_al_alloy.csv");
    let rms5 = rms(steel
        .iter()
        .map(|p| (test5_of(&soft5, Contact::HertzAA, p[0]), p[1])));
    let rms6 = rms(al
        .iter()
        .map(|p| (test6_of(&soft6, Contact::HertzAA, p[0]), p[1])));
    out.notes.push(format!(
        "hertz_aa with G* x {SOFTENED_SHEAR} (k_t/k_n 0.39 instead of 0.82): RMS {rms5:.3} from the Test 5 steel curve, {rms6:.3} from the Test 6 Al alloy curve"
    ));

    // The peer: LAMMPS's own Hertz-Mindlin on Test 5 as two spheres.
    for row in data::rows("lammps_pair_granular_test5.csv") {
        let ours = test5_spheres(Contact::HertzAA, row[0], PEER_STEPS_PER_CONTACT);
        out.absolute(
            format!(
                "chung_ooi test5 two spheres psi = {} hertz_aa vs LAMMPS pair granular",
                row[0]
            ),
            ours,
            row[1],
            PEER_TOLERANCE,
        );
    }

    progress("Chung & Ooi Test 6");
    let xs = log_spaced(0.15, 25.0, 48);
    out.tables.push((
        "chung_ooi_test6".into(),
        sweep("x", &xs, test6, "Chung & Ooi Test 6: Al alloy sphere (R = 0.1 m) spinning onto a rigid plane, V_n = 0.2 m/s, e = 0.5, mu = 0.4, no tangential centre velocity, no tangential dashpot; beta against x = 3.5 mu (1 + e) V_n / V_s; dt = t_c/400".into()),
    ));
    let t6 = distances(
        &mut out,
        "test6",
        "chung_ooi2011_test6_al_alloy.csv",
        test6_pair(),
        test6_of,
        beta_rigid,
        DAMPED_SLIDING_TOLERANCE,
    );
    out.tables.push(("chung_ooi_test6_distances".into(), t6));
    let damped6 = test6_pair().with_matched_damping();
    let micro6 = rms(al
        .iter()
        .map(|p| (test6_of(&damped6, Contact::HertzMicroSlip, p[0]), p[1])));
    out.absolute(
        "chung_ooi test6 hertz_microslip with LIGGGHTS' tangential dashpot, RMS to the Al alloy curve",
        micro6,
        0.0,
        MICRO_SLIP_TEST6_TOLERANCE,
    );
    let dashpot6 = test6_dashpot(&mut out, &al);
    out.tables
        .push(("chung_ooi_test6_dashpot".into(), dashpot6));

    progress("Chung & Ooi Test 7");
    let mut t7 = Table::new(&["material", "law", "initial_spin_rad_per_s", "final_tangential_velocity_m_per_s", "final_spin_rad_per_s"])
        .with_comment("Chung & Ooi Test 7: two identical spheres (R = 0.1 m) at +-0.2 m/s, spins w0 and -w0 so that their contact points move together; reference: no tangential exchange")
        .shown_every(0);
    for solid in [AL_ALLOY, COPPER] {
        for spin in log_spaced(0.175, 21.0, 9) {
            for c in Contact::ALL {
                let (v, w) = test7(c, &solid, spin);
                t7.push(vec![
                    Cell::Text(solid.name.into()),
                    Cell::Text(c.name().into()),
                    spin.into(),
                    v.into(),
                    w.into(),
                ]);
                out.absolute(
                    format!(
                        "chung_ooi test7 {} {} w0 = {spin:.3} tangential velocity",
                        solid.name,
                        c.name()
                    ),
                    v,
                    0.0,
                    NO_EXCHANGE_TOLERANCE,
                );
                out.relative(
                    format!(
                        "chung_ooi test7 {} {} w0 = {spin:.3} spin kept",
                        solid.name,
                        c.name()
                    ),
                    w,
                    spin,
                    NO_EXCHANGE_TOLERANCE,
                );
            }
        }
    }
    out.tables.push(("chung_ooi_test7".into(), t7));

    progress("Chung & Ooi Test 8");
    out.tables.push((
        "chung_ooi_test8".into(),
        sweep("x", &log_spaced(0.15, 25.0, 24), test8, "Chung & Ooi Test 8: Al alloy sphere (R = 0.1 m) spinning into an identical sphere at rest, V_n = 0.2 m/s, e = 0.5, mu = 0.4; beta of the relative contact-point velocity against x; dt = t_c/400".into()),
    ));
    let t8 = distances(
        &mut out,
        "test8",
        "chung_ooi2011_test8_al_alloy.csv",
        test8_pair(),
        test8_of,
        beta_rigid,
        DAMPED_SLIDING_TOLERANCE,
    );
    out.tables.push(("chung_ooi_test8_distances".into(), t8));
    out
}
