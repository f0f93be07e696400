//! Tangential laws against rigid-body theory, the MFiX DEM05 linear-model reference, Elghannay & Tafti's
//! model comparison (docs/physics.md, sections 5.2 and 5.4), and the invariants every law must keep: the Coulomb
//! limit, action and reaction bit for bit, and a stored spring that follows a rolling pair.

use host_tests::analytic::{self, rigid_body_oblique};
use host_tests::data;
use host_tests::impact::{oblique_rebound, pair_collision};
use host_tests::precision::{bits, epsilon};
use soft_sphere::prelude::{
    ContactForces, ContactLaw, Float, Frictionless, Interaction, LeverArm, LinearSpringDashpot,
    Micromath, ModelA, ModelAA, ModelAALuding, ModelB, ModelC, Sphere, SpringDisplacement,
    Stateless, TangentialModel, TangentialParameters, Vec3, effective_mass,
};

// Elghannay & Tafti's Kharaz setup (docs/physics.md, section 5.2).
const RADIUS: f64 = 2.5e-3;
const DENSITY: f64 = 2700.0;
const SPEED: f64 = 3.9;
const FRICTION: f64 = 0.092;
const RESTITUTION: f64 = 0.98;

fn parameters<F: Float>(
    stiffness: f64,
    dashpot_ratio: f64,
    friction: f64,
) -> TangentialParameters<F> {
    TangentialParameters::new(
        F::from_f64(stiffness),
        F::from_f64(dashpot_ratio),
        F::from_f64(friction),
    )
    .unwrap()
}

fn kharaz<F: Float, T: TangentialModel<F>>(
    tangential: T,
) -> ContactLaw<F, LinearSpringDashpot<F>, T> {
    let normal = LinearSpringDashpot::new(F::from_f64(1000.0), F::from_f64(RESTITUTION)).unwrap();
    ContactLaw::new(normal, tangential)
}

fn relative_error(value: f64, expected: f64) -> f64 {
    (value / expected - 1.0).abs()
}

/// `|F_t| <= mu |F_n| (1 + margin)`.
fn assert_coulomb<F: Float>(forces: &ContactForces<F>, friction: f64, margin: f64, what: &str) {
    let tangential = forces.tangential_force.norm_squared().to_f64().sqrt();
    let limit = friction * forces.normal_force.to_f64().abs();
    assert!(
        tangential <= limit * (1.0 + margin),
        "{what}: |F_t| = {tangential:e} > mu |F_n| = {limit:e}"
    );
}

macro_rules! for_each_frictional_model {
    ($parameters:expr, $check:ident) => {{
        let p = $parameters;
        $check("stateless", Stateless(p));
        $check("model_c", ModelC(p));
        $check("model_a", ModelA(p));
        $check("model_b", ModelB(p));
        $check("model_aa", ModelAA(p));
        $check("model_aa_luding", ModelAALuding(p));
    }};
}

#[test]
fn coulomb_limit_holds_at_every_step_of_oblique_impacts() {
    fn check<F: Float, T: TangentialModel<F>>(name: &str, tangential: T) {
        let margin = 64.0 * epsilon::<F>();
        let law = kharaz::<F, T>(tangential);
        for angle in (1..90).step_by(4) {
            let what = format!("{name} {}-bit at {angle} deg", 8 * size_of::<F>());
            let mut steps = 0;
            oblique_rebound(
                &law,
                F::from_f64(RADIUS),
                F::from_f64(DENSITY),
                SPEED,
                angle as f64,
                50.0,
                |f| {
                    steps += 1;
                    assert_coulomb(f, FRICTION, margin, &what);
                },
            );
            assert!(steps > 10, "{what}: only {steps} steps in contact");
        }
    }
    // A tangential dashpot (eta_t = eta_n / 2) so the trial force includes it.
    for_each_frictional_model!(parameters::<f64>(860.0, 0.5, FRICTION), check);
    for_each_frictional_model!(parameters::<f32>(860.0, 0.5, FRICTION), check);
}

#[test]
fn coulomb_limit_with_micromath_stays_within_its_sqrt_error() {
    fn check<T: TangentialModel<f32>>(name: &str, tangential: T) {
        let law = kharaz::<f32, T>(tangential).with_backend::<Micromath>();
        for angle in (1..90).step_by(4) {
            let what = format!("{name} micromath at {angle} deg");
            oblique_rebound(
                &law,
                RADIUS as f32,
                DENSITY as f32,
                SPEED,
                angle as f64,
                50.0,
                |f| {
                    // micromath's 1/sqrt guess is within 3.5 % of the true value.
                    assert_coulomb(f, FRICTION, 0.035, &what);
                },
            );
        }
    }
    for_each_frictional_model!(parameters::<f32>(860.0, 0.5, FRICTION), check);
}

#[test]
fn coulomb_limit_holds_in_spinning_sphere_pairs() {
    fn check<F: Float, T: TangentialModel<F>>(name: &str, tangential: T) {
        let normal = LinearSpringDashpot::new(F::from_f64(2.0e4), F::from_f64(0.5)).unwrap();
        let law = ContactLaw::new(normal, tangential);
        let margin = 64.0 * epsilon::<F>();
        for case in 0..12 {
            let c = case as f64;
            let f = F::from_f64;
            let mut i = Sphere::solid(Vec3::new(f(0.0), f(0.0), f(0.0)), f(1.0e-3), f(2500.0));
            let mut j = Sphere::solid(
                Vec3::new(f(2.2e-3), f(0.3e-3 * c.sin()), f(0.0)),
                f(1.5e-3),
                f(1000.0),
            );
            i.velocity = Vec3::new(f(1.0), f(0.2 * c.cos()), f(-0.1));
            j.velocity = Vec3::new(f(-0.5), f(0.0), f(0.3 * c.sin()));
            i.angular_velocity = Vec3::new(f(300.0 * c.cos()), f(-500.0), f(800.0 * c.sin()));
            j.angular_velocity = Vec3::new(f(0.0), f(900.0 * c.cos()), f(-200.0));
            let m = effective_mass(i.mass, j.mass);
            let dt = law.time_step(law.recommended_time_step(m), m).unwrap();
            let mut steps = 0;
            pair_collision(&law, i, j, dt, 100_000, |forces, _, _| {
                steps += 1;
                assert_coulomb(forces, 0.3, margin, name);
            })
            .unwrap();
            assert!(steps > 10, "{name} case {case}: {steps} steps");
        }
    }
    for_each_frictional_model!(parameters::<f64>(2.0e4 * 2.0 / 7.0, 1.0, 0.3), check);
    for_each_frictional_model!(parameters::<f32>(2.0e4 * 2.0 / 7.0, 1.0, 0.3), check);
}

#[test]
fn gross_sliding_matches_the_rigid_body_closed_form() {
    // Above tan(theta) = 3.5 mu (1 + e) (about 32.5 deg) every law with a proper slider slides
    // through the whole contact. Model C is excluded: its weak dt-dependent dashpot never reaches
    // the Coulomb limit here (see model_c_stays_far_from_the_data).
    fn check<T: TangentialModel<f64>>(name: &str, tangential: T) {
        if name == "model_c" {
            return;
        }
        let law = kharaz::<f64, T>(tangential);
        for angle in (36..=86).step_by(5) {
            let angle = angle as f64;
            let (e_t, spin_ratio) = rigid_body_oblique(angle, RESTITUTION, FRICTION);
            let r = oblique_rebound(&law, RADIUS, DENSITY, SPEED, angle, 50.0, |_| {});
            let spin = spin_ratio * SPEED / RADIUS;
            assert!(
                relative_error(r.tangential_restitution, e_t) < 5e-3,
                "{name} {angle}: e_t {} vs {e_t}",
                r.tangential_restitution
            );
            assert!(
                relative_error(r.spin, spin) < 5e-3,
                "{name} {angle}: spin {} vs {spin}",
                r.spin
            );
        }
    }
    for_each_frictional_model!(parameters::<f64>(860.0, 0.0, FRICTION), check);
}

#[test]
fn stateless_law_rolls_off_at_five_sevenths_below_the_threshold() {
    let law = kharaz::<f64, _>(Stateless(parameters(860.0, 0.0, FRICTION)));
    for angle in 1..=30 {
        let angle = angle as f64;
        let r = oblique_rebound(&law, RADIUS, DENSITY, SPEED, angle, 50.0, |_| {});
        let rolling_spin = 5.0 / 7.0 * SPEED * angle.to_radians().sin() / RADIUS;
        assert!(
            relative_error(r.tangential_restitution, 5.0 / 7.0) < 0.01,
            "{angle}: {}",
            r.tangential_restitution
        );
        assert!(
            relative_error(r.spin, rolling_spin) < 0.01,
            "{angle}: spin {} vs {rolling_spin}",
            r.spin
        );
    }
}

#[test]
fn model_aa_matches_the_mfix_linear_reference() {
    // docs/physics.md, section 5.2: MFiX DEM05 inputs; MFiX integrates at t_c/50 with the contact-plane arm.
    // Below 5 degrees MFiX's published values sit 1-2.3 % lower in e_t and 4-15 % higher in spin
    // than Model AA (at t_c/50 and at t_c/1000, with either arm); that residual is examined by the
    // validation run, so this check starts at 5 degrees.
    let normal = LinearSpringDashpot::new(1.72e7, 1.0).unwrap();
    let law = ContactLaw::new(normal, ModelAA(parameters::<f64>(1.48e7, 0.0, FRICTION)));
    let rows = data::rows("linear_model_reference_mfix_dem05.csv");
    assert_eq!(rows.len(), 30);
    for row in rows.into_iter().filter(|row| row[0] >= 5.0) {
        let (angle, e_t, spin) = (row[0], row[1], row[2]);
        let r = oblique_rebound(&law, RADIUS, 4000.0, SPEED, angle, 50.0, |_| {});
        let (e_t_tolerance, spin_tolerance) = if angle >= 25.0 {
            (0.01, 0.01)
        } else {
            (0.015, 0.04)
        };
        assert!(
            relative_error(r.tangential_restitution, e_t) < e_t_tolerance,
            "{angle}: e_t {} vs MFiX {e_t}",
            r.tangential_restitution
        );
        assert!(
            relative_error(r.spin, spin) < spin_tolerance,
            "{angle}: spin {} vs MFiX {spin}",
            r.spin
        );
    }
}

#[test]
fn the_contact_plane_arm_is_mfixs_arm() {
    // In gross sliding MFiX's spin is matched to 0.05 % with the contact-plane arm (R - delta for
    // a wall), while the radius arm overshoots it by 0.2-0.4 %: the arm is the only difference.
    let normal = LinearSpringDashpot::new(1.72e7, 1.0).unwrap();
    let law = ContactLaw::new(normal, ModelAA(parameters::<f64>(1.48e7, 0.0, FRICTION)));
    for row in data::rows("linear_model_reference_mfix_dem05.csv")
        .into_iter()
        .filter(|row| row[0] >= 35.0)
    {
        let (angle, spin) = (row[0], row[2]);
        let plane = oblique_rebound(
            &law.with_lever_arm(LeverArm::ContactPlane),
            RADIUS,
            4000.0,
            SPEED,
            angle,
            50.0,
            |_| {},
        );
        let radius = oblique_rebound(&law, RADIUS, 4000.0, SPEED, angle, 50.0, |_| {});
        assert!(
            relative_error(plane.spin, spin) < 5e-4,
            "{angle}: {} vs {spin}",
            plane.spin
        );
        assert!(
            radius.spin / spin - 1.0 > 1.5e-3,
            "{angle}: {} vs {spin}",
            radius.spin
        );
    }
}

#[test]
fn the_talks_model_comparison_is_reproduced() {
    // docs/physics.md, section 5.4, e = 0.98, k_t/k_n = 0.86, eta_t = 0.
    fn rebound<T: TangentialModel<f64>>(tangential: T, angle: f64) -> (f64, f64) {
        let r = oblique_rebound(
            &kharaz::<f64, T>(tangential),
            RADIUS,
            DENSITY,
            SPEED,
            angle,
            50.0,
            |_| {},
        );
        (r.tangential_restitution, r.spin)
    }
    let p = parameters::<f64>(860.0, 0.0, FRICTION);
    let (aa, a, b) = (
        |angle| rebound(ModelAA(p), angle),
        |angle| rebound(ModelA(p), angle),
        |angle| rebound(ModelB(p), angle),
    );
    // Model AA: about 0.594 at 15 deg, minimum about 0.59 near 17.5 deg (the elastic recoil dip).
    let (aa15, aa175, aa20) = (aa(15.0).0, aa(17.5).0, aa(20.0).0);
    assert!((aa15 - 0.594).abs() < 0.005, "AA(15) = {aa15}");
    assert!(
        aa175 < aa15 && aa175 < aa20 && (aa175 - 0.59).abs() < 0.005,
        "AA(17.5) = {aa175}"
    );
    // Model A: dips to about 0.40 at 15 deg and over-predicts the peak spin (about 676 rad/s).
    let a15 = a(15.0).0;
    assert!((a15 - 0.40).abs() < 0.01, "A(15) = {a15}");
    let a_peak = (10..=30).map(|angle| a(angle as f64).1).fold(0.0, f64::max);
    assert!(relative_error(a_peak, 676.0) < 0.02, "A peak spin {a_peak}");
    // Model B: locks at 5/7 from about 5 deg up to the threshold.
    for angle in (5..=30).step_by(5) {
        let b_e_t = b(angle as f64).0;
        assert!(
            relative_error(b_e_t, 5.0 / 7.0) < 0.01,
            "B({angle}) = {b_e_t}"
        );
    }
}

#[test]
fn model_c_stays_far_from_the_data() {
    // docs/physics.md, section 3.1: the literal stateless reading leaves e_t near 0.85-0.96 (up to 65 degrees;
    // it climbs towards 1 at grazing incidence, 0.984 at 85 degrees).
    let law = kharaz::<f64, _>(ModelC(parameters(860.0, 0.0, FRICTION)));
    for angle in (5..=65).step_by(10) {
        let r = oblique_rebound(&law, RADIUS, DENSITY, SPEED, angle as f64, 50.0, |_| {});
        assert!(
            (0.85..=0.96).contains(&r.tangential_restitution),
            "C({angle}) = {}",
            r.tangential_restitution
        );
    }
}

#[test]
fn swapping_the_pair_negates_forces_bit_for_bit() {
    fn check<F: Float, T: TangentialModel<F>>(name: &str, tangential: T) {
        let normal = LinearSpringDashpot::new(F::from_f64(2.0e4), F::from_f64(0.7)).unwrap();
        for lever_arm in [LeverArm::Radius, LeverArm::ContactPlane] {
            let law = ContactLaw::new(normal, tangential).with_lever_arm(lever_arm);
            let f = F::from_f64;
            let mut i = Sphere::solid(Vec3::new(f(0.1), f(-0.2), f(0.3)), f(1.0e-3), f(2500.0));
            let mut j = Sphere::solid(
                Vec3::new(f(0.1021), f(-0.1996), f(0.3003)),
                f(1.3e-3),
                f(1500.0),
            );
            i.velocity = Vec3::new(f(0.7), f(0.1), f(-0.2));
            j.velocity = Vec3::new(f(-0.3), f(0.4), f(0.1));
            i.angular_velocity = Vec3::new(f(100.0), f(-700.0), f(250.0));
            j.angular_velocity = Vec3::new(f(-40.0), f(300.0), f(-900.0));
            let m = effective_mass(i.mass, j.mass);
            let dt = law.time_step(law.recommended_time_step(m), m).unwrap();
            let (mut state_ij, mut state_ji) = (T::State::default(), T::State::default());
            let mut touching_steps = 0;
            for _ in 0..400 {
                let forward = law.sphere_sphere(&i, &j, &mut state_ij, dt).unwrap();
                let backward = law.sphere_sphere(&j, &i, &mut state_ji, dt).unwrap();
                let (Interaction::Touching(ij), Interaction::Touching(ji)) = (forward, backward)
                else {
                    assert_eq!(
                        forward,
                        Interaction::Apart,
                        "{name}: one ordering touches, the other not"
                    );
                    assert_eq!(backward, Interaction::Apart);
                    break;
                };
                touching_steps += 1;
                let bits = |v: Vec3<F>| v.to_array().map(|x| bits(x));
                assert_eq!(
                    bits(ij.force_on_j()),
                    bits(ji.force_on_i()),
                    "{name} {lever_arm:?}"
                );
                assert_eq!(
                    bits(ij.force_on_i()),
                    bits(ji.force_on_j()),
                    "{name} {lever_arm:?}"
                );
                assert_eq!(
                    bits(ij.torque_on_i),
                    bits(ji.torque_on_j),
                    "{name} {lever_arm:?}"
                );
                assert_eq!(
                    bits(ij.torque_on_j),
                    bits(ji.torque_on_i),
                    "{name} {lever_arm:?}"
                );
                soft_sphere::motion::advance_solid_sphere(
                    &mut i,
                    ij.force_on_i(),
                    ij.torque_on_i,
                    dt,
                );
                soft_sphere::motion::advance_solid_sphere(
                    &mut j,
                    ij.force_on_j(),
                    ij.torque_on_j,
                    dt,
                );
            }
            assert!(touching_steps > 20, "{name}: {touching_steps} steps");
        }
    }
    for_each_frictional_model!(parameters::<f64>(8.0e3, 0.5, 0.4), check);
    for_each_frictional_model!(parameters::<f32>(8.0e3, 0.5, 0.4), check);
    check::<f64, _>("frictionless", Frictionless);
}

#[test]
fn a_stuck_spring_follows_a_rigidly_rotating_pair() {
    // Two spheres stuck together turn 90 degrees about y in 100 steps, with no slip. The stored
    // displacement must turn with them and keep its length: projection alone would lose 1.2 %.
    let normal = LinearSpringDashpot::new(1000.0, 0.5).unwrap();
    let law = ContactLaw::new(normal, ModelAA(parameters::<f64>(1000.0, 0.5, 1.0)))
        .with_lever_arm(LeverArm::ContactPlane);
    let (radius, overlap) = (1.0e-3, 1.0e-5);
    let half_span = radius - overlap / 2.0;
    let mut state = SpringDisplacement {
        displacement: Vec3::new(0.0, 0.0, 1.0e-6),
    };
    let expected = 1000.0 * 1.0e-6;
    let dt = law.time_step(1.0e-6, 1.0e-6).unwrap();
    let turns = 100;
    for step in 1..=turns {
        let angle = std::f64::consts::FRAC_PI_2 * step as f64 / turns as f64;
        let axis = Vec3::new(angle.cos(), 0.0, -angle.sin());
        let i = Sphere::solid(axis * -half_span, radius, 2500.0);
        let j = Sphere::solid(axis * half_span, radius, 2500.0);
        let Interaction::Touching(forces) = law.sphere_sphere(&i, &j, &mut state, dt).unwrap()
        else {
            panic!("the pair touches");
        };
        let ft = forces.tangential_force;
        assert!(!forces.sliding);
        assert!(
            relative_error(ft.norm_squared().sqrt(), expected) < 1e-12,
            "step {step}: |F_t| = {}",
            ft.norm_squared().sqrt()
        );
        assert!(
            ft.dot(forces.normal).abs() < 1e-12 * expected,
            "step {step}: F_t leaves the tangent plane"
        );
        // The displacement turned with the pair: F_t = -k_t |xi| (sin a, 0, cos a).
        let turned = Vec3::new(angle.sin(), 0.0, angle.cos()) * -expected;
        assert!(
            (ft - turned).norm_squared().sqrt() < 1e-9 * expected,
            "step {step}: {ft:?} vs {turned:?}"
        );
    }
}

#[test]
fn frictionless_and_non_rotating_slots_do_no_tangential_work() {
    let normal = LinearSpringDashpot::new(1000.0, RESTITUTION).unwrap();
    // Frictionless: no tangential force, no torque; the tangential velocity passes unchanged.
    let law = ContactLaw::new(normal, Frictionless);
    let r = oblique_rebound(&law, RADIUS, DENSITY, SPEED, 45.0, 50.0, |f| {
        assert_eq!(f.tangential_force, Vec3::ZERO);
        assert_eq!((f.torque_on_i, f.torque_on_j), (Vec3::ZERO, Vec3::ZERO));
    });
    assert_eq!((r.tangential_restitution, r.spin), (1.0, 0.0));

    // Non-rotating Model AA: friction acts, torque does not; sliding still follows the closed form.
    let law = ContactLaw::new(normal, ModelAA(parameters::<f64>(860.0, 0.0, FRICTION)))
        .without_rotation();
    let r = oblique_rebound(&law, RADIUS, DENSITY, SPEED, 60.0, 50.0, |f| {
        assert_eq!(f.torque_on_i, Vec3::ZERO);
    });
    let (e_t, _) = rigid_body_oblique(60.0, RESTITUTION, FRICTION);
    assert_eq!(r.spin, 0.0);
    assert!(relative_error(r.tangential_restitution, e_t) < 5e-3);

    // A spinning sphere dropped straight down: only a rotating law feels its spin.
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, RADIUS * 0.99), RADIUS, DENSITY);
    sphere.velocity = Vec3::new(0.0, 0.0, -1.0);
    sphere.angular_velocity = Vec3::new(0.0, 200.0, 0.0);
    let floor = host_tests::impact::floor::<f64>();
    let rotating = ContactLaw::new(normal, ModelAA(parameters::<f64>(860.0, 0.0, FRICTION)));
    let dt = rotating.time_step(1e-6, sphere.mass).unwrap();
    let with_spin = rotating
        .sphere_wall(&sphere, &floor, &mut Default::default(), dt)
        .unwrap();
    let without_spin = rotating
        .without_rotation()
        .sphere_wall(&sphere, &floor, &mut Default::default(), dt)
        .unwrap();
    assert!(
        with_spin.forces().unwrap().tangential_force.x < 0.0,
        "backspin at the contact pushes -x... on the wall"
    );
    assert_eq!(without_spin.forces().unwrap().tangential_force, Vec3::ZERO);
}

#[test]
fn an_isolated_pair_keeps_its_momentum() {
    // Linear momentum is conserved by action = reaction. Angular momentum about the origin changes
    // at the rate (d - a_i - a_j) n x F_t: zero with the contact-plane arm (a_i + a_j = d), and
    // -delta n x F_t with the radius arm, whose arms overlap by delta.
    let normal = LinearSpringDashpot::new(2.0e4, 0.7).unwrap();
    let tangential = ModelAA(parameters::<f64>(8.0e3, 0.5, 0.4));
    let momenta = |a: &Sphere<f64>, b: &Sphere<f64>| {
        let linear = a.velocity * a.mass + b.velocity * b.mass;
        let angular = a.position.cross(a.velocity * a.mass)
            + b.position.cross(b.velocity * b.mass)
            + a.angular_velocity * a.solid_moment_of_inertia()
            + b.angular_velocity * b.solid_moment_of_inertia();
        (linear, angular)
    };
    for (lever_arm, conserves_spin) in [(LeverArm::ContactPlane, true), (LeverArm::Radius, false)] {
        let law = ContactLaw::new(normal, tangential).with_lever_arm(lever_arm);
        let mut i = Sphere::solid(Vec3::new(0.0, 0.0, 0.0), 1.0e-3, 2500.0);
        let mut j = Sphere::solid(Vec3::new(2.2e-3, 0.4e-3, -0.2e-3), 1.3e-3, 1500.0);
        i.velocity = Vec3::new(1.0, 0.3, 0.0);
        j.velocity = Vec3::new(-0.6, 0.0, 0.2);
        i.angular_velocity = Vec3::new(0.0, 300.0, -500.0);
        j.angular_velocity = Vec3::new(800.0, 0.0, 100.0);
        let m = effective_mass(i.mass, j.mass);
        let dt = law.time_step(law.recommended_time_step(m), m).unwrap();
        let (p0, l0) = momenta(&i, &j);
        let [a, b] = pair_collision(&law, i, j, dt, 100_000, |_, _, _| {}).unwrap();
        let (p1, l1) = momenta(&a, &b);
        let dp = (p1 - p0).norm_squared().sqrt() / p0.norm_squared().sqrt();
        let dl = (l1 - l0).norm_squared().sqrt() / l0.norm_squared().sqrt();
        println!("{lever_arm:?}: relative change of linear momentum {dp:.1e}, angular {dl:.1e}");
        assert!(
            dp < 1e-14,
            "{lever_arm:?}: linear momentum changed by {dp:e}"
        );
        if conserves_spin {
            assert!(
                dl < 1e-12,
                "{lever_arm:?}: angular momentum changed by {dl:e}"
            );
        } else {
            assert!(
                dl > 1e-6,
                "{lever_arm:?}: the radius arm should not conserve it ({dl:e})"
            );
        }
    }
}

#[test]
fn the_slip_velocity_is_the_contact_points_and_vanishes_in_rolling() {
    // A sphere on the floor moving along x at 1 m/s: its lowest point moves at v - w R along x
    // (spin about y), so the floor's contact point slips at -(v - w R) relative to it.
    let law = kharaz::<f64, _>(ModelAA(parameters(860.0, 0.0, FRICTION)));
    let floor = host_tests::impact::floor::<f64>();
    let dt = law.time_step(1e-6, 1e-4).unwrap();
    for spin in [0.0, 200.0, 1.0 / RADIUS, 600.0] {
        let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, 0.99 * RADIUS), RADIUS, DENSITY);
        sphere.velocity = Vec3::new(1.0, 0.0, 0.0);
        sphere.angular_velocity = Vec3::new(0.0, spin, 0.0);
        let Interaction::Touching(c) = law
            .sphere_wall(&sphere, &floor, &mut SpringDisplacement::default(), dt)
            .unwrap()
        else {
            panic!("the sphere overlaps the floor");
        };
        let expected = -(1.0 - spin * RADIUS);
        assert!(
            (c.slip_velocity.x - expected).abs() < 1e-12,
            "spin {spin}: {:?}",
            c.slip_velocity
        );
        assert_eq!((c.slip_velocity.y, c.slip_velocity.z), (0.0, 0.0));
    }
}

#[test]
fn the_dashpot_in_the_coulomb_limit_adds_to_the_friction_impulse() {
    // In gross sliding the friction impulse is mu times the normal impulse's magnitude, which
    // with e < 1 includes the dashpot's pull at the end of contact: 6.7 % more than rigid-body
    // theory's mu (1 + e) m v_n at e = 0.5 (the claim in the Stateless and
    // TangentialParameters docs), nothing at e = 1.
    let excess = analytic::normal_impulse_magnitude(0.5) / 1.5 - 1.0;
    assert!((excess - 0.067).abs() < 0.001, "excess {excess}");
    assert!((analytic::normal_impulse_magnitude(1.0) - 2.0).abs() < 1e-9);
    for e in [0.5, 0.98] {
        let law = ContactLaw::new(
            LinearSpringDashpot::new(1000.0, e).unwrap(),
            Stateless(parameters(860.0, 0.0, FRICTION)),
        );
        let angle: f64 = 60.0;
        let r = oblique_rebound(&law, RADIUS, DENSITY, SPEED, angle, 10_000.0, |_| {});
        let friction_impulse = (1.0 - r.tangential_restitution) * angle.to_radians().tan();
        // The spring force starts below the limit, so the first moments of contact stick: the
        // impulse falls short of mu times the magnitude by 0.4 % at e = 0.5 (converged in dt).
        let expected = FRICTION * analytic::normal_impulse_magnitude(e);
        assert!(
            relative_error(friction_impulse, expected) < 5e-3,
            "e = {e}: {friction_impulse} vs {expected}"
        );
        let rigid_body = FRICTION * (1.0 + e);
        if e == 0.5 {
            assert!(friction_impulse > 1.05 * rigid_body, "{friction_impulse}");
        }
    }
}

#[test]
fn ludings_reset_leaves_spring_and_dashpot_equal_to_the_sliding_force() {
    // A sphere sliding on the floor with a tangential dashpot: after every sliding step the kept
    // spring satisfies -k_t xi - eta_t v_t = F_t (Luding 2008), so it differs from the plain cap
    // by the dashpot term; without a dashpot the two rules keep the same spring.
    let dashpot_ratio = 0.5;
    let p = parameters::<f64>(860.0, dashpot_ratio, FRICTION);
    let law = kharaz::<f64, _>(ModelAALuding(p));
    let capped = kharaz::<f64, _>(ModelAA(p));
    let floor = host_tests::impact::floor::<f64>();
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, 0.9 * RADIUS), RADIUS, DENSITY);
    sphere.velocity = Vec3::new(1.0, 0.0, -0.1);
    let dt = law.time_step(1e-6, sphere.mass).unwrap();
    let eta_n = law.oscillator(sphere.mass).damping_coefficient;
    let (mut luding, mut cap) = (SpringDisplacement::default(), SpringDisplacement::default());
    // The sphere is held in place: the spring grows by v_t dt each step until it slides.
    let mut slid = 0;
    for _ in 0..200 {
        let Interaction::Touching(c) = law.sphere_wall(&sphere, &floor, &mut luding, dt).unwrap()
        else {
            panic!("touching")
        };
        capped.sphere_wall(&sphere, &floor, &mut cap, dt).unwrap();
        if c.sliding {
            slid += 1;
            let spring_and_dashpot =
                -(luding.displacement * 860.0) - c.slip_velocity * (dashpot_ratio * eta_n);
            let gap = (spring_and_dashpot - c.tangential_force)
                .norm_squared()
                .sqrt();
            assert!(
                gap <= 1e-12 * c.tangential_force.norm_squared().sqrt(),
                "{gap:e}"
            );
            // Both keep at most mu |F_n| / k_t; Luding's reset less, by the dashpot's share.
            let limit = FRICTION * c.normal_force.abs() / 860.0;
            let kept = cap.displacement.norm_squared().sqrt();
            assert!(kept <= limit * (1.0 + 1e-12), "{kept:e} vs {limit:e}");
            assert!(luding.displacement.norm_squared().sqrt() < limit);
        }
    }
    assert!(slid > 100, "the held sphere slid ({slid} steps)");
    // Without a dashpot both rules keep the same spring, bit for bit.
    let p = parameters::<f64>(860.0, 0.0, FRICTION);
    let (law, capped) = (
        kharaz::<f64, _>(ModelAALuding(p)),
        kharaz::<f64, _>(ModelAA(p)),
    );
    let (mut a, mut b) = (SpringDisplacement::default(), SpringDisplacement::default());
    let ra = law.sphere_wall(&sphere, &floor, &mut a, dt).unwrap();
    let rb = capped.sphere_wall(&sphere, &floor, &mut b, dt).unwrap();
    assert_eq!((ra, a), (rb, b));
}

/// A pair overlapping by 0.1 mm along x, j moving at `speed` in y relative to i, no spin.
fn sliding_pair(speed: f64) -> (Sphere<f64>, Sphere<f64>) {
    let i = Sphere::solid(Vec3::ZERO, 1.0e-3, 2500.0);
    let mut j = Sphere::solid(Vec3::new(1.9e-3, 0.0, 0.0), 1.0e-3, 2500.0);
    j.velocity = Vec3::new(0.0, speed, 0.0);
    (i, j)
}

#[test]
fn model_aa_cuts_its_spring_only_when_the_contact_slides() {
    // A stored spring of 1.5 times the Coulomb limit, and slips that run back against it: the
    // dashpot then holds the trial force within the limit, the contact sticks, and the spring is
    // kept whole (Model AA limits the displacement only in a sliding step).
    let (k_n, k_t, mu) = (1.0e4, 3.0e3, 0.4);
    let law = ContactLaw::new(
        LinearSpringDashpot::new(k_n, 0.3).unwrap(),
        ModelAA(TangentialParameters::new(k_t, 1.0, mu).unwrap()),
    );
    let dt = law.time_step(1e-7, 1e-6).unwrap();
    let limit = mu * k_n * 1.0e-4; // the normal force is about k_n delta: no approach speed
    let stored = SpringDisplacement {
        displacement: Vec3::new(0.0, -1.5 * limit / k_t, 0.0),
    };
    let (mut sticking_past_the_cap, mut sliding) = (0, 0);
    for k in -200..=200 {
        let speed = 5.0 * k as f64 / 200.0;
        let (i, j) = sliding_pair(speed);
        let mut state = stored;
        let Ok(Interaction::Touching(c)) = law.sphere_sphere(&i, &j, &mut state, dt) else {
            panic!("the pair touches");
        };
        // No spin and a normal along x: the slip is j's velocity, (0, speed, 0).
        let grown = stored.displacement + Vec3::new(0.0, speed, 0.0) * dt.seconds();
        if c.sliding {
            sliding += 1;
            let longest = mu * c.normal_force / k_t;
            assert!(state.displacement.norm_squared().sqrt() <= longest * (1.0 + 1e-12));
        } else {
            assert_eq!(
                state.displacement, grown,
                "a sticking contact keeps its whole spring"
            );
            if grown.norm_squared().sqrt() > 1.2 * limit / k_t {
                sticking_past_the_cap += 1;
            }
        }
    }
    assert!(
        sliding > 0 && sticking_past_the_cap > 0,
        "{sliding} sliding, {sticking_past_the_cap} sticking past the cap"
    );
}

/// A trial force and a limit both too large to square (the squares overflow to infinity and
/// compare equal) still slide at the limit, along the trial force.
#[test]
fn forces_too_large_to_square_still_meet_coulomb() {
    use soft_sphere::prelude::{Libm, NormalOscillator, TangentialModel};
    use soft_sphere::slots::TangentialInput;
    let law = ModelAA(TangentialParameters::new(1e10_f64, 0.0, 0.3).unwrap());
    let state = SpringDisplacement {
        displacement: Vec3::new(1e150, -2e150, 0.0),
    };
    let input = TangentialInput {
        normal: Vec3::new(0.0, 0.0, 1.0),
        slip_velocity: Vec3::ZERO,
        normal_force: 1e160,
        overlap: 1e-6,
        approach_rate: 0.0,
        oscillator: NormalOscillator::default(),
        contact_radius: 0.0,
        time_step: 1e-6,
    };
    let out = law.force::<Libm>(&state, &input);
    let f = out.force;
    assert!(out.sliding && f.is_finite(), "{out:?}");
    // |F_t| = 0.3e160, pointing along the trial force -k_t xi = (-1, 2, 0) 1e160.
    let scaled = f * 1e-160;
    let length = scaled.norm_squared().sqrt();
    assert!((length / 0.3 - 1.0).abs() < 1e-12, "{length}");
    assert!(
        (scaled.y / scaled.x + 2.0).abs() < 1e-12 && scaled.x < 0.0,
        "{f:?}"
    );
    // Under a limit larger still (both squares overflow), the trial force stands.
    let loose = TangentialInput {
        normal_force: 1e200,
        ..input
    };
    let out = law.force::<Libm>(&state, &loose);
    assert!(
        !out.sliding && out.force == Vec3::new(-1e160, 2e160, -0.0),
        "{out:?}"
    );
    // A limit just below |F*| = 2.236e160 (2.1e160, its square overflowing too) slides.
    let close = TangentialInput {
        normal_force: 7e160,
        ..input
    };
    let out = law.force::<Libm>(&state, &close);
    let length = (out.force * 1e-160).norm_squared().sqrt();
    assert!(out.sliding && (length / 2.1 - 1.0).abs() < 1e-12, "{out:?}");
}
