//! The list seam takes the long-latency part of its contacts ahead of them, a chunk at a time:
//! each separation's `1 / d` and overlap, and each stored spring's turn into the current
//! tangent plane (its division and root). Whatever the tangential and rolling slots, a packing
//! of spheres of slightly different radii whose contacts roll, slide and cross a periodic side
//! gives, step after step, the bits of the one-contact path called pair by pair with the loads
//! summed in list order.

use host_tests::random::Xorshift;
use host_tests::seam::evaluate_swapping;
use soft_sphere::prelude::{
    CheckedPairs, CheckedSphere, ContactLaw, ElasticPlasticRolling, Float, Hertz, HertzImpact,
    Interaction, Law, LinearSpringDashpot, MaterialTable, MindlinAA, MindlinAALuding,
    MindlinParameters, ModelA, ModelAA, ModelAALuding, ModelB, ModelC, Sphere, SphereArrays,
    Stateless, Std, TangentialParameters, Vec3, effective_mass,
};

const RADIUS: f64 = 1.0e-3;
const DENSITY: f64 = 2500.0;
/// Spheres per side of the cubic lattice; the lattice is periodic along x.
const SIDE: usize = 4;
/// Lattice spacing: a little under a diameter, so neighbours overlap by 0.5 % of a radius.
const SPACING: f64 = 1.995e-3;

/// A jittered cubic lattice of spheres moving and spinning at random, and every pair closer
/// than 1.5 spacings, periodic images along x included (with their shifts).
struct Packing<F> {
    position: Vec<Vec3<F>>,
    velocity: Vec<Vec3<F>>,
    angular_velocity: Vec<Vec3<F>>,
    radius: Vec<F>,
    mass: Vec<F>,
    material: Vec<u32>,
    pairs: Vec<[u32; 2]>,
    shifts: Vec<Vec3<F>>,
}

impl<F: Float + From<f32>> Packing<F> {
    fn new(seed: u64) -> Self {
        let mut random = Xorshift::new(seed);
        let mut r = |scale: f64| F::from((scale * (2.0 * random.unit() - 1.0)) as f32);
        let f = |x: f64| F::from(x as f32);
        let count = SIDE * SIDE * SIDE;
        let mass = f(DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3));
        let mut p = Self {
            position: Vec::new(),
            velocity: Vec::new(),
            angular_velocity: Vec::new(),
            radius: Vec::new(),
            mass: vec![mass; count],
            material: vec![0; count],
            pairs: Vec::new(),
            shifts: Vec::new(),
        };
        for k in 0..count {
            let (x, y, z) = (k % SIDE, (k / SIDE) % SIDE, k / (SIDE * SIDE));
            let at = |n: usize| f(SPACING * n as f64);
            p.position.push(Vec3::new(
                at(x) + r(2.0e-6),
                at(y) + r(2.0e-6),
                at(z) + r(2.0e-6),
            ));
            // Radii 0.1 % apart: every pair has its own effective radius.
            p.radius.push(f(RADIUS) * (F::ONE + r(1.0e-3)));
            p.velocity.push(Vec3::new(r(0.02), r(0.02), r(0.02)));
            p.angular_velocity
                .push(Vec3::new(r(60.0), r(60.0), r(60.0)));
        }
        let period = f(SPACING * SIDE as f64);
        let reach = f(1.5 * SPACING);
        for i in 0..count {
            for j in i + 1..count {
                for shift in [F::ZERO, period, F::ZERO - period] {
                    let shift = Vec3::new(shift, F::ZERO, F::ZERO);
                    let d = p.position[j] + shift - p.position[i];
                    if d.norm_squared() < reach * reach {
                        p.pairs.push([i as u32, j as u32]);
                        p.shifts.push(shift);
                    }
                }
            }
        }
        p
    }

    fn arrays(&self) -> SphereArrays<'_, F> {
        SphereArrays {
            position: &self.position,
            velocity: &self.velocity,
            angular_velocity: &self.angular_velocity,
            radius: &self.radius,
            mass: &self.mass,
            material: &self.material,
        }
    }

    fn sphere(&self, k: usize, shift: Vec3<F>) -> CheckedSphere<F> {
        CheckedSphere::new(Sphere {
            position: self.position[k] + shift,
            velocity: self.velocity[k],
            angular_velocity: self.angular_velocity[k],
            radius: self.radius[k],
            mass: self.mass[k],
        })
        .unwrap()
    }

    /// Symplectic Euler, solid spheres.
    fn advance(&mut self, force: &[Vec3<F>], torque: &[Vec3<F>], dt: F) {
        let inertia = F::from(0.4) * self.mass[0] * self.radius[0] * self.radius[0];
        for k in 0..self.position.len() {
            self.velocity[k] += force[k] * (dt / self.mass[k]);
            self.position[k] += self.velocity[k] * dt;
            self.angular_velocity[k] += torque[k] * (dt / inertia);
        }
    }
}

fn bits<T: std::fmt::Debug>(value: &T) -> String {
    format!("{value:?}")
}

/// What the comparison covered: touching pair contact-steps, sliding ones, and whether a
/// periodic image touched.
struct Covered {
    touching: usize,
    sliding: usize,
    across: usize,
    /// Contact-steps that began with a stored state other than the default (a spring to turn).
    stored: usize,
}

/// `steps` steps of the packing through the list seam beside the one-contact path, compared
/// bit for bit after every step.
fn list_gives_one_contact_bits<L: Law>(law: L, steps: usize) -> Covered
where
    L::Float: From<f32>,
{
    let table = MaterialTable::<L, 1>::uniform(law);
    let mut p = Packing::<L::Float>::new(11);
    let mass = effective_mass(p.mass[0], p.mass[0]);
    let seconds = law.recommended_time_step(mass) * L::Float::from(0.5);
    let dt = table.coarse_time_step(seconds, &p.arrays(), &[]).unwrap();
    let n = p.position.len();
    let mut states = vec![L::State::default(); p.pairs.len()];
    let mut reference = states.clone();
    let mut covered = Covered {
        touching: 0,
        sliding: 0,
        across: 0,
        stored: 0,
    };
    for step in 0..steps {
        let (mut force, mut torque) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        let contacts = (
            (CheckedPairs::new(&p.pairs, &p.shifts, n).unwrap(), &[][..]),
            (&mut states[..], &mut [][..]),
        );
        let loads = (&mut force[..], &mut torque[..]);
        evaluate_swapping(&table, dt, &p.arrays(), contacts, loads, None).unwrap();

        let mut bound = table.law(0, 0).unwrap().at(dt);
        let (mut ref_force, mut ref_torque) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        for (k, &[i, j]) in p.pairs.iter().enumerate() {
            let (i, j) = (i as usize, j as usize);
            let (a, b) = (p.sphere(i, Vec3::ZERO), p.sphere(j, p.shifts[k]));
            covered.stored += usize::from(reference[k] != L::State::default());
            let outcome = bound.sphere_sphere(&a, &b, &mut reference[k]).unwrap();
            if let Interaction::Touching(c) = outcome {
                ref_force[i] -= c.force_on_j();
                ref_torque[i] += c.torque_on_i;
                ref_force[j] += c.force_on_j();
                ref_torque[j] += c.torque_on_j;
                covered.touching += 1;
                covered.sliding += usize::from(c.sliding);
                covered.across += usize::from(p.shifts[k] != Vec3::ZERO);
            }
        }
        assert_eq!(bits(&states), bits(&reference), "step {step}: states");
        assert_eq!(bits(&force), bits(&ref_force), "step {step}: forces");
        assert_eq!(bits(&torque), bits(&ref_torque), "step {step}: torques");
        p.advance(&force, &torque, dt.seconds());
    }
    covered
}

/// Runs the comparison and checks that it covered sliding, the periodic side and (for a law
/// that stores a spring) stored springs to turn.
fn check<L: Law>(name: &str, law: L, stores: bool)
where
    L::Float: From<f32>,
{
    let covered = list_gives_one_contact_bits(law, 80);
    assert!(
        covered.touching > 5000
            && covered.sliding > 100
            && covered.across > 500
            && (covered.stored > 4000 || !stores),
        "{name}: {} touching, {} sliding, {} across, {} stored",
        covered.touching,
        covered.sliding,
        covered.across,
        covered.stored
    );
}

fn linear<F: Float + From<f32>>() -> (LinearSpringDashpot<F>, TangentialParameters<F>) {
    let f = |x: f32| F::from(x);
    (
        LinearSpringDashpot::new(f(1.0e4), f(0.8)).unwrap(),
        TangentialParameters::new(f(2.857e3), f(0.5), f(0.3)).unwrap(),
    )
}

#[test]
fn stored_springs_turned_ahead_give_the_one_contact_bits() {
    let (normal, t) = linear::<f64>();
    check("Model A", ContactLaw::new(normal, ModelA(t)), true);
    check("Model B", ContactLaw::new(normal, ModelB(t)), true);
    check("Model AA", ContactLaw::new(normal, ModelAA(t)), true);
    check(
        "Model AA, Luding",
        ContactLaw::new(normal, ModelAALuding(t)),
        true,
    );
    let std = ContactLaw::new(normal, ModelAA(t)).with_backend::<Std>();
    check("Model AA, Std", std, true);
    let (normal, t) = linear::<f32>();
    check("Model AA, f32", ContactLaw::new(normal, ModelAA(t)), true);
    let std = ContactLaw::new(normal, ModelAA(t)).with_backend::<Std>();
    check("Model AA, f32, Std", std, true);
}

#[test]
fn laws_that_turn_nothing_and_rolling_give_the_one_contact_bits() {
    let (normal, t) = linear::<f64>();
    check("Model C", ContactLaw::new(normal, ModelC(t)), false);
    check("stateless", ContactLaw::new(normal, Stateless(t)), false);
    let inertia = 0.4 * 4.0e-6 * RADIUS * RADIUS;
    let rolling = ElasticPlasticRolling::new(0.1, 1.0e-5, 1.0e-9, inertia).unwrap();
    let law = ContactLaw::new(normal, ModelAA(t)).with_rolling(rolling);
    check("Model AA, rolling", law, true);
}

#[test]
fn mindlin_springs_turned_ahead_give_the_one_contact_bits() {
    let impact = HertzImpact {
        speed: 0.5,
        effective_radius: RADIUS / 2.0,
    };
    let hertz = Hertz::new(1.0e8, 0.8, impact).unwrap();
    let t = MindlinParameters::new(4.0e7, 0.5, 0.3).unwrap();
    check("Mindlin AA", ContactLaw::new(hertz, MindlinAA(t)), true);
    check(
        "Mindlin AA, Luding",
        ContactLaw::new(hertz, MindlinAALuding(t)),
        true,
    );
    let std = ContactLaw::new(hertz, MindlinAA(t)).with_backend::<Std>();
    check("Mindlin AA, Std", std, true);
    let impact = HertzImpact {
        speed: 0.5_f32,
        effective_radius: RADIUS as f32 / 2.0,
    };
    let hertz = Hertz::new(1.0e8, 0.8, impact).unwrap();
    let t = MindlinParameters::new(4.0e7, 0.5, 0.3).unwrap();
    check(
        "Mindlin AA, f32",
        ContactLaw::new(hertz, MindlinAA(t)),
        true,
    );
}
