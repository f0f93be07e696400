//! The Hertz normal slot and the Mindlin tangential slots: bad inputs give their error values;
//! the moduli, forces, stiffness, unloading rule and time steps follow their closed forms; and,
//! for random collisions (`host_tests::strategies`) in f32 and f64, every Mindlin law keeps the
//! Coulomb limit, creates no energy, is symmetric bit for bit, is frame invariant, and survives
//! arbitrary bit patterns. Restitution, duration and the benchmark cases are in `validation.rs`.

use host_tests::energy::kinetic;
use host_tests::precision::{bits, epsilon};
use host_tests::strategies::{Collision, collision, config};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    ContactLaw, Float, Frictionless, Hertz, HertzImpact, Interaction, Law, Material, MicroSlip,
    MindlinAA, MindlinAALuding, MindlinParameters, MindlinSpring, MindlinStateless, Parameter,
    ParameterError, Sphere, TangentialModel, Vec3, Wall, effective_mass,
};

fn impact(speed: f64, radius: f64) -> HertzImpact<f64> {
    HertzImpact {
        speed,
        effective_radius: radius,
    }
}

#[test]
fn bad_materials_and_laws_are_refused_with_their_error() {
    use ParameterError::*;
    assert_eq!(
        Material::new(f64::NAN, 0.3),
        Err(NonFinite(Parameter::Modulus))
    );
    assert_eq!(
        Material::new(-1.0, 0.3),
        Err(NotPositive(Parameter::Modulus))
    );
    assert_eq!(
        Material::new(1e9, f64::INFINITY),
        Err(NonFinite(Parameter::PoissonRatio))
    );
    assert_eq!(Material::new(1e9, 0.6), Err(PoissonRatioOutOfRange));
    assert_eq!(Material::new(1e9, -1.0), Err(PoissonRatioOutOfRange));
    assert!(Material::new(1e9, 0.5).is_ok() && Material::new(1e9, -0.99).is_ok());

    let good = impact(1.0, 1e-3);
    assert_eq!(
        Hertz::new(0.0, 0.5, good),
        Err(NotPositive(Parameter::Modulus))
    );
    assert_eq!(Hertz::new(1e9, 1.5, good), Err(RestitutionOutOfRange));
    assert_eq!(
        Hertz::new(1e9, f64::NAN, good),
        Err(NonFinite(Parameter::Restitution))
    );
    assert_eq!(
        Hertz::new(1e9, 0.5, impact(0.0, 1e-3)),
        Err(NotPositive(Parameter::Speed))
    );
    assert_eq!(
        Hertz::new(1e9, 0.5, impact(1.0, f64::INFINITY)),
        Err(NonFinite(Parameter::Radius))
    );
    assert_eq!(
        Hertz::with_damping_factor(1e9, -0.1, good),
        Err(Negative(Parameter::DampingFactor))
    );
    assert_eq!(
        Hertz::with_damping_factor(1e9, f64::NAN, good),
        Err(NonFinite(Parameter::DampingFactor))
    );
    assert_eq!(
        MindlinParameters::new(0.0, 0.5, 0.3),
        Err(NotPositive(Parameter::Modulus))
    );
    assert_eq!(
        MindlinParameters::new(1e9, -0.5, 0.3),
        Err(Negative(Parameter::DashpotRatio))
    );
    assert_eq!(
        MindlinParameters::new(1e9, 0.5, f64::NAN),
        Err(NonFinite(Parameter::Friction))
    );
}

#[test]
fn effective_moduli_follow_hertz_and_mindlin() {
    let (e1, n1, e2, n2) = (70.0e9, 0.3, 380.0e9, 0.23);
    let (a, b) = (
        Material::new(e1, n1).unwrap(),
        Material::new(e2, n2).unwrap(),
    );
    let e_star = 1.0 / ((1.0 - n1 * n1) / e1 + (1.0 - n2 * n2) / e2);
    let (g1, g2) = (e1 / (2.0 * (1.0 + n1)), e2 / (2.0 * (1.0 + n2)));
    let g_star = 1.0 / ((2.0 - n1) / g1 + (2.0 - n2) / g2);
    assert!((a.effective_modulus(&b) / e_star - 1.0).abs() < 1e-14);
    assert!((a.effective_shear_modulus(&b) / g_star - 1.0).abs() < 1e-14);
    assert!((a.modulus_against_rigid() / (e1 / (1.0 - n1 * n1)) - 1.0).abs() < 1e-14);
    assert!((a.shear_modulus_against_rigid() / (g1 / (2.0 - n1)) - 1.0).abs() < 1e-14);
}

/// A sphere of radius 1 mm, 2500 kg/m3, `overlap` into the floor, moving at `velocity`.
fn pressed(overlap: f64, velocity: Vec3<f64>) -> Sphere<f64> {
    let mut s = Sphere::solid(Vec3::new(0.0, 0.0, 1e-3 - overlap), 1e-3, 2500.0);
    s.velocity = velocity;
    s
}

fn floor() -> Wall<f64> {
    Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap()
}

#[test]
fn the_hertz_force_and_mindlin_stiffness_follow_their_closed_forms() {
    let (e_star, g_star, mu) = (1.0e9, 0.4e9, 0.5);
    let hertz = Hertz::new(e_star, 1.0, impact(1.0, 1e-3)).unwrap();
    let law = ContactLaw::new(
        hertz,
        MindlinAA(MindlinParameters::new(g_star, 0.0, mu).unwrap()),
    );
    let delta = 2e-6;
    let slip = 1e-4;
    let sphere = pressed(delta, Vec3::new(slip, 0.0, 0.0));
    let dt = law.time_step(1e-8, sphere.mass).unwrap();
    let mut state = MindlinSpring::default();
    let Ok(Interaction::Touching(f)) = law.sphere_wall(&sphere, &floor(), &mut state, dt) else {
        panic!("touching")
    };
    let a = (1e-3 * delta).sqrt();
    let elastic = 4.0 / 3.0 * e_star * (1e-3f64).sqrt() * delta.powf(1.5);
    assert!(
        (f.normal_force / elastic - 1.0).abs() < 1e-12,
        "{} vs {elastic}",
        f.normal_force
    );
    // One sticking step from rest: F_t = -8 G* a v_t dt, on the wall (body j) along +x.
    let expected = 8.0 * g_star * a * slip * 1e-8;
    assert!((f.tangential_force.x / expected - 1.0).abs() < 1e-12);
    assert!((state.contact_radius / a - 1.0).abs() < 1e-12);

    // With both dashpots: eta_n = alpha sqrt(m* (4/3) E* a) against the approach, and
    // eta_t = r eta_n against the slip.
    let (ratio, approach) = (0.5, 1e-3);
    let hertz = Hertz::new(e_star, 0.5, impact(1.0, 1e-3)).unwrap();
    let p = MindlinParameters::new(g_star, ratio, mu).unwrap();
    let law = ContactLaw::new(hertz, MindlinAA(p));
    let sphere = pressed(delta, Vec3::new(slip, 0.0, -approach));
    let mut state = MindlinSpring::default();
    let Ok(Interaction::Touching(f)) = law.sphere_wall(&sphere, &floor(), &mut state, dt) else {
        panic!("touching")
    };
    let eta = hertz.damping_factor() * (sphere.mass * 4.0 / 3.0 * e_star * a).sqrt();
    assert!((f.normal_force / (elastic + eta * approach) - 1.0).abs() < 1e-12);
    let expected = 8.0 * g_star * a * slip * 1e-8 + ratio * eta * slip;
    assert!((f.tangential_force.x / expected - 1.0).abs() < 1e-12);
}

#[test]
fn an_unloading_contact_shrinks_its_spring_with_the_contact_radius() {
    let hertz = Hertz::new(1.0e9, 1.0, impact(1.0, 1e-3)).unwrap();
    let law = ContactLaw::new(
        hertz,
        MindlinAA(MindlinParameters::new(0.4e9, 0.0, 0.5).unwrap()),
    );
    let dt = law.time_step(1e-8, 1e-6).unwrap();
    let spring = Vec3::new(1e-3, 0.0, 0.0);
    // Loaded at a = sqrt(R 4e-6); now at a quarter of that overlap, half the radius, no slip.
    let a_then = (1e-3f64 * 4e-6).sqrt();
    let mut state = MindlinSpring {
        force: spring,
        contact_radius: a_then,
    };
    let f = law
        .sphere_wall(&pressed(1e-6, Vec3::ZERO), &floor(), &mut state, dt)
        .unwrap();
    let a_now = (1e-3f64 * 1e-6).sqrt();
    assert!((state.force.x / (spring.x * a_now / a_then) - 1.0).abs() < 1e-12);
    assert_eq!(f.forces().unwrap().tangential_force, state.force);
    // Loading does not grow it.
    let mut state = MindlinSpring {
        force: spring,
        contact_radius: a_now,
    };
    law.sphere_wall(&pressed(4e-6, Vec3::ZERO), &floor(), &mut state, dt)
        .unwrap();
    assert_eq!(state.force, spring);
}

#[test]
fn a_spring_loaded_small_and_released_large_gives_back_no_more_than_it_took() {
    // The cycle that makes a stored displacement create energy (docs/physics.md, section 3.2):
    // load the spring at a small overlap, press the contact deeper, then let the spring push
    // the slip back to where it started. Work done on the spring must not come back larger.
    let hertz = Hertz::new(1.0e9, 1.0, impact(1.0, 1e-3)).unwrap();
    let law = ContactLaw::new(
        hertz,
        MindlinAA(MindlinParameters::new(0.4e9, 0.0, 10.0).unwrap()),
    );
    let dt = law.time_step(1e-8, 1e-6).unwrap();
    let mut state = MindlinSpring::default();
    let mut work_in = 0.0;
    let v = 1e-3;
    // Tangential work done by the sphere on the contact: -F_on_sphere . v = F_on_wall . v.
    let step = |overlap: f64, slip: f64, state: &mut MindlinSpring<f64>| {
        let s = pressed(overlap, Vec3::new(slip, 0.0, 0.0));
        let f = law.sphere_wall(&s, &floor(), state, dt).unwrap();
        f.forces().unwrap().tangential_force.x * slip * 1e-8
    };
    for _ in 0..100 {
        work_in += step(1e-7, v, &mut state);
    }
    for k in 0..100 {
        step(1e-7 + 1e-8 * f64::from(k), 0.0, &mut state);
    }
    let mut work_out = 0.0;
    while state.force.x > 0.0 {
        work_out -= step(1.1e-6, -v, &mut state);
    }
    assert!(work_in > 0.0);
    assert!(
        work_out <= work_in * (1.0 + 1e-9),
        "out {work_out} > in {work_in}"
    );
}

#[test]
fn the_time_steps_come_from_the_declared_impact() {
    let (e_star, speed, radius, mass) = (1.0e9, 2.0, 1e-3, 1e-5);
    let hertz = Hertz::new(e_star, 1.0, impact(speed, radius)).unwrap();
    let law = ContactLaw::new(hertz, Frictionless).without_rotation();
    let delta = (15.0 * mass * speed * speed / (16.0 * e_star * radius.sqrt())).powf(0.4);
    let frequency = (2.0 * e_star * (radius * delta).sqrt() / mass).sqrt();
    let limit = law.critical_time_step(mass);
    assert!(
        (limit * frequency / 2.0 - 1.0).abs() < 1e-9,
        "{limit} vs {}",
        2.0 / frequency
    );
    assert!(matches!(
        law.coarse_time_step(limit, mass),
        Err(ParameterError::TimeStepUnstable { .. })
    ));
    assert!(law.coarse_time_step(0.999 * limit, mass).is_ok());
    let duration = 2.868 * (mass * mass / (radius * e_star * e_star * speed)).powf(0.2);
    assert!((law.contact_duration(mass) / duration - 1.0).abs() < 1e-3);
    assert!(law.recommended_time_step(mass) <= law.contact_duration(mass) / 50.0);
}

/// Pairing a Mindlin law with a linear normal law does not compile:
///
/// ```compile_fail
/// use soft_sphere::prelude::{ContactLaw, LinearSpringDashpot, MindlinAA, MindlinParameters};
/// let law = ContactLaw::new(
///     LinearSpringDashpot::new(1.0e4_f64, 0.8).unwrap(),
///     MindlinAA(MindlinParameters::new(1.0e9, 0.0, 0.3).unwrap()),
/// );
/// ```
#[test]
fn mindlin_needs_a_contact_radius() {
    const { assert!(<MindlinAA<f64> as TangentialModel<f64>>::NEEDS_CONTACT_RADIUS) };
    const { assert!(<Hertz<f64> as soft_sphere::prelude::NormalModel<f64>>::CONTACT_RADIUS) };
}

// Random collisions ----------------------------------------------------------------------------

/// The Hertz-Mindlin law for a collision: `E*` giving the collision's peak overlap fraction,
/// `G*` giving its stiffness ratio `k_t / k_n = 4 G* / E*`, its restitution, friction and
/// dashpot ratio.
fn hertz_for<F: Float>(
    c: &Collision,
    m_star: f64,
    r_star: f64,
) -> (Hertz<F>, MindlinParameters<F>) {
    let m = c.material;
    let radius = c.first.radius.min(c.second.radius);
    let delta = m.overlap_fraction * radius;
    let e_star = 15.0 * m_star * c.speed.powi(2) / (16.0 * r_star.sqrt() * delta.powf(2.5));
    let largest = HertzImpact {
        speed: F::from_f64(c.speed),
        effective_radius: F::from_f64(r_star),
    };
    let hertz = Hertz::new(F::from_f64(e_star), F::from_f64(m.restitution), largest).unwrap();
    let shear = m.stiffness_ratio * e_star / 4.0;
    let p = MindlinParameters::new(
        F::from_f64(shear),
        F::from_f64(m.dashpot_ratio),
        F::from_f64(m.friction),
    )
    .unwrap();
    (hertz, p)
}

/// What one collision showed: kinetic energy before and after, the largest Coulomb excess.
struct Outcome {
    kinetic_before: f64,
    kinetic_after: f64,
    coulomb_excess: f64,
    /// How many roundings of the coordinates the slowest step moves a sphere.
    ulps_per_step: f64,
}

/// f32's rebound error is within `F32_ROUNDING_FACTOR / u` of the approach speed, `u` the
/// roundings per step (properties.rs measures it).
const F32_ROUNDING_FACTOR: f64 = 10.0;

/// The collision at `step_fraction` of the law's recommended step.
fn collide<F: Float, T: TangentialModel<F>>(
    c: &Collision,
    make: impl Fn(MindlinParameters<F>) -> T,
    against_wall: bool,
    step_fraction: f64,
) -> Result<Outcome, TestCaseError> {
    let (mut i, mut j) = c.pair::<F>();
    let (wall, sphere) = c.wall::<F>();
    if against_wall {
        j = sphere;
    }
    let (m_star, r_star) = if against_wall {
        (j.mass.to_f64(), j.radius.to_f64())
    } else {
        let (a, b) = (i.radius.to_f64(), j.radius.to_f64());
        (effective_mass(i.mass, j.mass).to_f64(), a * b / (a + b))
    };
    let (hertz, p) = hertz_for::<F>(c, m_star, r_star);
    let m = F::from_f64(m_star);
    let law = ContactLaw::new(hertz, make(p));
    let recommended = law.recommended_time_step(m) * F::from_f64(step_fraction);
    let dt = law.time_step(recommended, m).expect("stable");
    let extent = (i.radius + j.radius).to_f64();
    let ulps_per_step = 0.1 * c.speed * dt.seconds().to_f64() / (epsilon::<F>() * extent);
    if ulps_per_step < 10.0 {
        return Err(TestCaseError::reject(
            "the precision cannot resolve one step",
        ));
    }
    let energy = |i: &Sphere<F>, j: &Sphere<F>| {
        if against_wall {
            kinetic(j)
        } else {
            kinetic(i) + kinetic(j)
        }
    };
    let before = energy(&i, &j);
    let mut state = T::State::default();
    let mut excess = 0.0f64;
    let mut touched = false;
    for _ in 0..200_000 {
        let interaction = if against_wall {
            law.sphere_wall(&j, &wall, &mut state, dt)
        } else {
            law.sphere_sphere(&i, &j, &mut state, dt)
        }
        .map_err(|e| TestCaseError::fail(format!("kernel error {e:?}")))?;
        match interaction {
            Interaction::Touching(f) => {
                touched = true;
                let t = f.tangential_force.norm_squared().to_f64().sqrt();
                let limit = c.material.friction * f.normal_force.to_f64().abs();
                excess = excess.max(if limit > 0.0 { t / limit - 1.0 } else { t });
                if !against_wall {
                    advance_solid_sphere(&mut i, f.force_on_i(), f.torque_on_i, dt);
                }
                let (force, torque) = if against_wall {
                    (f.force_on_i(), f.torque_on_i)
                } else {
                    (f.force_on_j(), f.torque_on_j)
                };
                advance_solid_sphere(&mut j, force, torque, dt);
            }
            Interaction::Apart if touched => {
                return Ok(Outcome {
                    kinetic_before: before,
                    kinetic_after: energy(&i, &j),
                    coulomb_excess: excess,
                    ulps_per_step,
                });
            }
            Interaction::Apart => {
                advance_solid_sphere(&mut i, Vec3::ZERO, Vec3::ZERO, dt);
                advance_solid_sphere(&mut j, Vec3::ZERO, Vec3::ZERO, dt);
            }
        }
    }
    // e = 0: the overlap creeps back to zero without parting; the energy is then only falling.
    Ok(Outcome {
        kinetic_before: before,
        kinetic_after: energy(&i, &j),
        coulomb_excess: excess,
        ulps_per_step,
    })
}

fn coulomb_and_energy_for<F: Float, T: TangentialModel<F>>(
    name: &str,
    make: impl Fn(MindlinParameters<F>) -> T + Copy,
    c: &Collision,
) -> Result<(), TestCaseError> {
    coulomb_and_energy_at(name, make, c, 1.0)
}

fn coulomb_and_energy_at<F: Float, T: TangentialModel<F>>(
    name: &str,
    make: impl Fn(MindlinParameters<F>) -> T + Copy,
    c: &Collision,
    step_fraction: f64,
) -> Result<(), TestCaseError> {
    for wall in [false, true] {
        let o = collide(c, make, wall, step_fraction)
            .map_err(|e| named(&format!("{name} (wall: {wall})"), e))?;
        prop_assert!(
            o.coulomb_excess <= 64.0 * epsilon::<F>(),
            "{name}: Coulomb exceeded by {:e}",
            o.coulomb_excess
        );
        // At t_c/50 symplectic Euler's energy error, plus the precision's rounding of positions:
        // f32's error is set by how many roundings of the coordinates one step moves a sphere
        // (`F32_ROUNDING_FACTOR / u`, as in properties.rs; nil for f64).
        let rounding = F32_ROUNDING_FACTOR / o.ulps_per_step;
        let energy = soft_sphere::checks::no_energy_created::<F>(
            o.kinetic_before,
            o.kinetic_after / (1.0 + rounding),
        );
        prop_assert_eq!(
            energy,
            Ok(()),
            "{} (wall: {}), u = {}",
            name,
            wall,
            o.ulps_per_step
        );
    }
    Ok(())
}

fn swap_negates_for<F: Float, T: TangentialModel<F>>(
    name: &str,
    make: impl Fn(MindlinParameters<F>) -> T + Copy,
    c: &Collision,
) -> Result<(), TestCaseError> {
    let (mut i, mut j) = c.pair::<F>();
    let (a, b) = (i.radius.to_f64(), j.radius.to_f64());
    let m_star = effective_mass(i.mass, j.mass);
    let (hertz, p) = hertz_for::<F>(c, m_star.to_f64(), a * b / (a + b));
    let law = ContactLaw::new(hertz, make(p));
    let dt = law
        .time_step(law.recommended_time_step(m_star), m_star)
        .expect("stable");
    let (mut ij, mut ji) = (T::State::default(), T::State::default());
    let bits = |v: Vec3<F>| v.to_array().map(|x| if x == F::ZERO { 0 } else { bits(x) });
    for _ in 0..200_000 {
        match (
            law.sphere_sphere(&i, &j, &mut ij, dt).unwrap(),
            law.sphere_sphere(&j, &i, &mut ji, dt).unwrap(),
        ) {
            (Interaction::Touching(x), Interaction::Touching(y)) => {
                prop_assert_eq!(bits(x.force_on_j()), bits(y.force_on_i()), "{}", name);
                prop_assert_eq!(bits(x.torque_on_i), bits(y.torque_on_j), "{}", name);
                advance_solid_sphere(&mut i, x.force_on_i(), x.torque_on_i, dt);
                advance_solid_sphere(&mut j, x.force_on_j(), x.torque_on_j, dt);
            }
            (Interaction::Apart, Interaction::Apart) => return Ok(()),
            _ => prop_assert!(false, "{}: one ordering touches, the other not", name),
        }
    }
    Ok(())
}

macro_rules! each_mindlin_law {
    ($property:ident, $F:ty, $c:expr) => {{
        $property::<$F, _>("mindlin_aa", |p| MindlinAA(p), $c)?;
        $property::<$F, _>("mindlin_aa_luding", |p| MindlinAALuding(p), $c)?;
        $property::<$F, _>("mindlin_stateless", |p| MindlinStateless(p), $c)?;
        $property::<$F, _>("micro_slip_8", |p| MicroSlip::<$F, 8>::new(p), $c)?;
    }};
}

fn sound<F: Float>(c: &Collision) -> Result<(), TestCaseError> {
    each_mindlin_law!(coulomb_and_energy_for, F, c);
    each_mindlin_law!(swap_negates_for, F, c);
    Ok(())
}

/// A sphere spinning at 1.45 m/s at its surface lands head-on at 1 m/s (on a wall, and on a
/// sphere at rest), `e` = 1, no dashpot, `k_t / k_n` 0.3, `mu` 0.99: the tangential force brakes
/// the spin while the contact grows, so the micro-slip profile bends up in `1 - t^2` and a full
/// profile has to drop breakpoints whose line lies above it. No energy may come of that, at
/// the recommended step and half of it, with few breakpoints and many.
#[test]
fn a_spinning_sphere_landing_head_on_gains_no_energy_from_micro_slip() {
    let body = |spin: f64| host_tests::strategies::Body {
        radius: 0.1,
        density: 500.0,
        velocity: [0.0; 3],
        spin_speed: [0.0, spin, 0.0],
    };
    let c = Collision {
        first: body(0.0),
        second: body(-1.4491719670173744),
        normal: [1.0, 0.0, 0.0],
        speed: 1.0,
        angle_deg: 0.0,
        tangent_hint: [1.0, 0.0, 0.0],
        material: host_tests::strategies::Coefficients {
            restitution: 1.0,
            friction: 0.9868434013035681,
            stiffness_ratio: 0.29743111064305394,
            dashpot_ratio: 0.0,
            overlap_fraction: 0.05,
        },
    };
    for fraction in [1.0, 0.5] {
        let outcomes = [
            coulomb_and_energy_at::<f64, _>("3", MicroSlip::<f64, 3>::new, &c, fraction),
            coulomb_and_energy_at::<f64, _>("4", MicroSlip::<f64, 4>::new, &c, fraction),
            coulomb_and_energy_at::<f64, _>("8", MicroSlip::<f64, 8>::new, &c, fraction),
            coulomb_and_energy_at::<f64, _>("16", MicroSlip::<f64, 16>::new, &c, fraction),
        ];
        for outcome in outcomes {
            assert!(outcome.is_ok(), "at {fraction} of the step: {outcome:?}");
        }
    }
}

proptest! {
    #![proptest_config(config())]
    #[test]
    fn mindlin_laws_keep_coulomb_create_no_energy_and_are_symmetric_f64(c in collision()) {
        sound::<f64>(&c)?;
    }
    #[test]
    fn mindlin_laws_keep_coulomb_create_no_energy_and_are_symmetric_f32(c in collision()) {
        sound::<f32>(&c)?;
    }
}

/// Micro-slip's frame invariance, relative to the largest force. Its breakpoints come of
/// threshold tests (a spring midway is kept where two slipping trials turn apart by more than
/// a squared sine of 1e-4, which keeps the line within 1.3e-5 of the limit it stands for): a
/// frame's rounding can tip one, and the profile then differs by up to that much of the
/// Coulomb limit (`mu` up to 1.5 of the normal force) for the rest of the contact. Seen:
/// 1.1e-6, a tipped decision as a contact stops sliding, held for the remaining steps.
const MICRO_SLIP_FRAME_TOLERANCE: f64 = 2e-5;

/// A failure named by the law it is about.
fn named(law: &str, error: TestCaseError) -> TestCaseError {
    match error {
        TestCaseError::Fail(why) => TestCaseError::fail(format!("{law}: {why}")),
        reject => reject,
    }
}

fn frame_invariant<T: TangentialModel<f64>>(
    c: &Collision,
    angle: f64,
    make: impl Fn(MindlinParameters<f64>) -> T,
    tolerance: f64,
) -> Result<(), TestCaseError> {
    // Rotating every vector of a collision about z rotates the forces and the stored spring.
    let (i, j) = c.pair::<f64>();
    let (a, b) = (i.radius, j.radius);
    let m = effective_mass(i.mass, j.mass);
    let (hertz, p) = hertz_for::<f64>(c, m, a * b / (a + b));
    let law = ContactLaw::new(hertz, make(p));
    let dt = law
        .time_step(law.recommended_time_step(m), m)
        .expect("stable");
    let (s, co) = angle.sin_cos();
    let turn = |v: Vec3<f64>| Vec3::new(co * v.x - s * v.y, s * v.x + co * v.y, v.z);
    let turned = |x: &Sphere<f64>| Sphere {
        position: turn(x.position),
        velocity: turn(x.velocity),
        angular_velocity: turn(x.angular_velocity),
        ..*x
    };
    let (mut i, mut j) = (i, j);
    let (mut state, mut turned_state) = (T::State::default(), T::State::default());
    // Relative to the largest force so far: near the end of contact the force passes zero.
    let mut scale = f64::MIN_POSITIVE;
    for _ in 0..200_000 {
        let one = law.sphere_sphere(&i, &j, &mut state, dt).unwrap();
        let two = law
            .sphere_sphere(&turned(&i), &turned(&j), &mut turned_state, dt)
            .unwrap();
        match (one, two) {
            (Interaction::Touching(x), Interaction::Touching(y)) => {
                scale = scale.max(x.normal_force.abs() + x.tangential_force.norm_squared().sqrt());
                let d = turn(x.force_on_j()) - y.force_on_j();
                // An overlap within rounding of the centre distance (the creeping end of an
                // e = 0 contact) is only known to its rounding, and so is its force.
                // Each step's rounding stays in the stored spring and adds up over a long (e = 0)
                // contact; a wrong rotation would be off by the force itself.
                if x.overlap > 1e-10 * (a + b) {
                    prop_assert!(
                        d.norm_squared().sqrt() <= tolerance * scale,
                        "force differs by {:e}",
                        d.norm_squared().sqrt() / scale
                    );
                }
                advance_solid_sphere(&mut i, x.force_on_i(), x.torque_on_i, dt);
                advance_solid_sphere(&mut j, x.force_on_j(), x.torque_on_j, dt);
            }
            (Interaction::Apart, Interaction::Apart) => return Ok(()),
            _ => {
                return Err(TestCaseError::reject(
                    "a rounding-sized overlap decided differently",
                ));
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(config())]
    #[test]
    fn mindlin_aa_and_micro_slip_are_frame_invariant(c in collision(), angle in 0.0..std::f64::consts::TAU) {
        frame_invariant(&c, angle, MindlinAA, 1e-6).map_err(|e| named("mindlin_aa", e))?;
        frame_invariant(&c, angle, MicroSlip::<f64, 8>::new, MICRO_SLIP_FRAME_TOLERANCE)
            .map_err(|e| named("micro_slip_8", e))?;
    }

    #[test]
    fn arbitrary_bits_in_a_micro_slip_contact_give_a_value_or_leave_it_alone(bits in proptest::array::uniform32(any::<u64>())) {
        let x = |k: usize| f64::from_bits(bits[k]);
        let v = |k: usize| Vec3::new(x(k), x(k + 1), x(k + 2));
        let largest = HertzImpact { speed: x(0), effective_radius: x(1) };
        let (Ok(hertz), Ok(p)) = (Hertz::new(x(2), x(3).abs().min(1.0), largest), MindlinParameters::new(x(4), 0.5, x(5))) else {
            return Ok(());
        };
        let micro = MicroSlip::<f64, 4>::new(p);
        let law = ContactLaw::new(hertz, micro);
        let Ok(dt) = law.time_step(1e-300, 1.0) else { return Ok(()); };
        let mut i = Sphere::solid(v(6), x(9), 2500.0);
        i.velocity = v(10);
        let j = Sphere::solid(v(13), x(14), x(15));
        let before = soft_sphere::prelude::MicroSlipSprings {
            normal: v(17),
            contact_radius: x(20),
            positions: [x(16), x(3), x(7), x(8)],
            displacements: [v(21), v(24), v(27), Vec3::new(x(30), x(31), x(0))],
        };
        let mut state = before;
        let flat = |s: &soft_sphere::prelude::MicroSlipSprings<f64, 4>| {
            let mut out = vec![s.contact_radius.to_bits()];
            out.extend(s.positions.map(f64::to_bits));
            for u in std::iter::once(&s.normal).chain(s.displacements.iter()) {
                out.extend(u.to_array().map(f64::to_bits));
            }
            out
        };
        match law.sphere_sphere(&i, &j, &mut state, dt) {
            Ok(Interaction::Touching(f)) => prop_assert!(f.force_on_j().is_finite() && f.torque_on_i.is_finite() && soft_sphere::prelude::ContactState::is_finite(&state)),
            Ok(Interaction::Apart) => prop_assert_eq!(state, Default::default()),
            Err(_) => prop_assert_eq!(flat(&state), flat(&before)),
        }
    }

    #[test]
    fn arbitrary_bits_never_panic_and_leave_a_refused_state_alone(bits in proptest::array::uniform16(any::<u64>())) {
        let x = |k: usize| f64::from_bits(bits[k]);
        let v = |k: usize| Vec3::new(x(k), x(k + 1), x(k + 2));
        let largest = HertzImpact { speed: x(0), effective_radius: x(1) };
        let (Ok(hertz), Ok(p)) = (Hertz::new(x(2), x(3).abs().min(1.0), largest), MindlinParameters::new(x(4), 0.5, x(5))) else {
            return Ok(());
        };
        let law = ContactLaw::new(hertz, MindlinAA(p));
        let Ok(dt) = law.time_step(1e-300, 1.0) else { return Ok(()); };
        let mut i = Sphere::solid(v(6), x(9), 2500.0);
        i.velocity = v(10);
        let j = Sphere::solid(v(13), x(14), x(15));
        let before = MindlinSpring { force: v(10), contact_radius: x(12) };
        let mut state = before;
        match law.sphere_sphere(&i, &j, &mut state, dt) {
            Ok(Interaction::Touching(f)) => prop_assert!(f.force_on_j().is_finite() && f.torque_on_i.is_finite()),
            Ok(Interaction::Apart) => prop_assert_eq!(state, MindlinSpring::default()),
            Err(_) => prop_assert_eq!(
                [state.force.x, state.force.y, state.force.z, state.contact_radius].map(f64::to_bits),
                [before.force.x, before.force.y, before.force.z, before.contact_radius].map(f64::to_bits)
            ),
        }
    }
}

#[test]
fn a_law_over_hertz_is_a_law() {
    fn name<L: Law>(_: &L) -> usize {
        size_of::<L::State>()
    }
    let hertz = Hertz::new(
        1.0e9_f32,
        0.5,
        HertzImpact {
            speed: 1.0,
            effective_radius: 1e-3,
        },
    )
    .unwrap();
    let p = MindlinParameters::new(0.4e9, 0.0, 0.3).unwrap();
    assert_eq!(name(&ContactLaw::new(hertz, MindlinAA(p))), 16);
    assert_eq!(name(&ContactLaw::new(hertz, MindlinStateless(p))), 0);
    // Micro-slip: four floats per breakpoint, plus the normal and the contact radius.
    let micro = MicroSlip::<f32, 8>::new(p);
    assert_eq!(name(&ContactLaw::new(hertz, micro)), 4 * (4 * 8 + 4));
}

#[test]
fn the_slots_give_back_what_they_were_built_from() {
    let m = Material::new(70.0e9, 0.33).unwrap();
    assert_eq!((m.youngs_modulus(), m.poisson_ratio()), (70.0e9, 0.33));
    assert_eq!(m.shear_modulus(), 70.0e9 / 2.66);
    let largest = impact(3.9, 2.5e-3);
    let h = Hertz::new(2.0e11, 0.5, largest).unwrap();
    assert_eq!(
        (h.effective_modulus(), h.restitution(), h.largest_impact()),
        (2.0e11, 0.5, largest)
    );
    let p = MindlinParameters::new(4.0e10, 0.5, 0.3).unwrap();
    assert_eq!(
        (p.shear_modulus(), p.dashpot_ratio(), p.friction()),
        (4.0e10, 0.5, 0.3)
    );
    assert_eq!(p.stiffness(1e-4), 8.0 * 4.0e10 * 1e-4);
    let c = soft_sphere::prelude::ConstantRolling::new(0.1).unwrap();
    assert_eq!(c.friction(), 0.1);
    let e = soft_sphere::prelude::ElasticPlasticRolling::new(0.2, 3.0, 0.0, 1e-9).unwrap();
    assert_eq!((e.friction(), e.stiffness()), (0.2, 3.0));
    // A given damping factor reports the rebound it gives: the solved one's inverse.
    let again = Hertz::with_damping_factor(2.0e11, h.damping_factor(), largest).unwrap();
    assert!(
        (again.restitution() - 0.5).abs() < 1e-6,
        "{}",
        again.restitution()
    );
}

/// Largest distance from equilibrium over the last quarter of `steps`, relative to a 1 %
/// perturbation, of a sphere pressed onto the floor to its declared impact's peak overlap (where
/// the contact is stiffest) and stepped at `fraction` of the limit. Declaring a heavier mass is
/// how the step passes the check on purpose.
fn pressed_oscillation(restitution: f64, fraction: f64, steps: usize) -> f64 {
    let (radius, density, speed, e_star) = (1.0e-3, 2500.0, 1.0, 1.0e9);
    let hertz = Hertz::new(e_star, restitution, impact(speed, radius)).unwrap();
    let law = ContactLaw::new(hertz, Frictionless);
    let mass = Sphere::solid(Vec3::ZERO, radius, density).mass;
    let peak = (15.0 * mass * speed * speed / (16.0 * e_star * radius.sqrt())).powf(0.4);
    let press = 4.0 / 3.0 * e_star * radius.sqrt() * peak.powf(1.5);
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, radius - 1.01 * peak), radius, density);
    let limit = law.critical_time_step(mass);
    let dt = law
        .coarse_time_step(fraction * limit, 4.0 * mass)
        .unwrap()
        .tolerating_unstable_contacts();
    let mut worst = 0.0f64;
    for step in 0..steps {
        let force = match law.sphere_wall(&sphere, &floor(), &mut (), dt).unwrap() {
            Interaction::Touching(c) => c.force_on_i(),
            Interaction::Apart => Vec3::ZERO,
        };
        advance_solid_sphere(
            &mut sphere,
            force + Vec3::new(0.0, 0.0, -press),
            Vec3::ZERO,
            dt,
        );
        if step >= 3 * steps / 4 {
            worst = worst.max((radius - sphere.position.z - peak).abs());
        }
    }
    worst / (0.01 * peak)
}

#[test]
fn the_hertz_mode_is_stable_below_the_limit_and_grows_above_it() {
    for e in [1.0, 0.5] {
        let below = pressed_oscillation(e, 0.98, 4000);
        let above = pressed_oscillation(e, 1.03, 4000);
        // Below the limit the discrete amplitude stays bounded (1/sqrt(1 - 0.98^2) = 5x at most).
        assert!(below <= 5.1, "e = {e}: grew below the limit ({below})");
        // Above it the perturbation grows past that bound until the contact opens and the
        // sphere bounces (the stiffening spring then limits the growth).
        assert!(
            above > 10.0 || !above.is_finite(),
            "e = {e}: did not grow above ({above})"
        );
    }
}

/// One contact evaluation of a law on a sphere and its state.
type Evaluate<'a> =
    dyn Fn(&Sphere<f64>, &mut MindlinSpring<f64>) -> soft_sphere::prelude::ContactForces<f64> + 'a;

#[test]
fn a_sliding_step_keeps_what_each_rule_says() {
    let (e_star, g_star, mu, ratio) = (1.0e9, 0.4e9, 0.5, 0.5);
    let hertz = Hertz::new(e_star, 0.5, impact(1.0, 1e-3)).unwrap();
    let p = MindlinParameters::new(g_star, ratio, mu).unwrap();
    let (cap, luding) = (
        ContactLaw::new(hertz, MindlinAA(p)),
        ContactLaw::new(hertz, MindlinAALuding(p)),
    );
    let delta = 2e-6_f64;
    let a = (1e-3 * delta).sqrt();
    let dt = cap.time_step(1e-9, 1e-6).unwrap();
    let step = |law: &Evaluate, slip: f64, spring: f64| {
        let mut state = MindlinSpring {
            force: Vec3::new(spring, 0.0, 0.0),
            contact_radius: a,
        };
        let f = law(&pressed(delta, Vec3::new(slip, 0.0, 0.0)), &mut state);
        (f, state)
    };
    let cap_law = |s: &Sphere<f64>, state: &mut MindlinSpring<f64>| {
        *cap.sphere_wall(s, &floor(), state, dt)
            .unwrap()
            .forces()
            .unwrap()
    };
    let luding_law = |s: &Sphere<f64>, state: &mut MindlinSpring<f64>| {
        *luding
            .sphere_wall(s, &floor(), state, dt)
            .unwrap()
            .forces()
            .unwrap()
    };
    let limit = |f: &soft_sphere::prelude::ContactForces<f64>| mu * f.normal_force.abs();
    // A spring ten times past the limit, no slip: both slide at the limit; the cap keeps the
    // limit, Luding keeps the sliding force (no dashpot without slip).
    let (f, kept) = step(&cap_law, 0.0, 1.0);
    let l = limit(&f);
    assert!(f.sliding && (f.tangential_force.x / l - 1.0).abs() < 1e-12);
    assert!(1.0 > 10.0 * l && (kept.force.x / l - 1.0).abs() < 1e-12);
    let (f, kept) = step(&luding_law, 0.0, 1.0);
    assert!(f.sliding && kept.force.x == f.tangential_force.x);
    // A spring within the limit whose dashpot makes the contact slide: the cap keeps the spring
    // as it is; Luding keeps the sliding force plus the dashpot's.
    let mass = pressed(delta, Vec3::ZERO).mass;
    let eta_t = ratio * hertz.damping_factor() * (mass * 4.0 / 3.0 * e_star * a).sqrt();
    let slip = -10.0 * l / eta_t;
    let spring = 0.5 * l;
    let (f, kept) = step(&cap_law, slip, spring);
    // The wall slips by -slip relative to the sphere: F_s += -k_t (-slip) dt.
    let grown = spring + 8.0 * g_star * a * slip * 1e-9;
    assert!(f.sliding, "the dashpot makes it slide");
    assert!(
        grown.abs() < limit(&f),
        "the spring itself stays within the limit"
    );
    assert!(
        (kept.force.x / grown - 1.0).abs() < 1e-12,
        "{} vs {grown}",
        kept.force.x
    );
    let (f, kept) = step(&luding_law, slip, spring);
    let dashpot = -eta_t * slip;
    assert!((kept.force.x - (f.tangential_force.x + dashpot)).abs() <= 1e-12 * dashpot.abs());
    // Just past the limit, no slip: capped to it.
    let (f, kept) = step(&cap_law, 0.0, 1.5 * l);
    assert!(f.sliding && (kept.force.x / l - 1.0).abs() < 1e-12);
    // Past the limit but held by the dashpot: not sliding, and the spring is kept whole.
    let slip = -0.5 * l / eta_t;
    let (f, kept) = step(&cap_law, slip, 1.2 * l);
    let grown = 1.2 * l + 8.0 * g_star * a * slip * 1e-9;
    assert!(!f.sliding && grown > limit(&f));
    assert!((kept.force.x / grown - 1.0).abs() < 1e-12);
}

#[test]
fn the_stateless_mindlin_law_follows_its_closed_form_and_step() {
    use soft_sphere::prelude::{Libm, NormalModel};
    let (e_star, g_star, mu, ratio) = (1.0e9, 0.4e9, 10.0, 0.5);
    let hertz = Hertz::new(e_star, 0.5, impact(1.0, 1e-3)).unwrap();
    let p = MindlinParameters::new(g_star, ratio, mu).unwrap();
    let law = ContactLaw::new(hertz, MindlinStateless(p));
    let (delta, slip, approach) = (2e-6_f64, 1e-4, 0.3);
    let sphere = pressed(delta, Vec3::new(slip, 0.0, -approach));
    let dt = law.time_step(1e-9, sphere.mass).unwrap();
    let Ok(Interaction::Touching(f)) = law.sphere_wall(&sphere, &floor(), &mut (), dt) else {
        panic!("touching")
    };
    // xi = v_t t_e with t_e from the oscillator at this overlap; trial -(k_t t_e + eta_t) v_t.
    let unit = hertz.oscillator::<Libm>(sphere.mass);
    let contact = hertz.contact::<Libm>(delta, -approach, 1e-3, &unit);
    // The time since first touch of the linearised oscillator's binary impact, at whose phase
    // the overlap is delta and grows at `approach`: tan(wd t) = wd delta / (delta' + beta delta).
    let o = contact.oscillator;
    let (wd, beta) = (o.damped_frequency, o.decay_rate);
    assert!(wd > beta, "underdamped");
    let elapsed = (wd * delta).atan2(approach + beta * delta) / wd;
    let a = contact.contact_radius;
    let eta_t = ratio * contact.oscillator.damping_coefficient;
    let expected = (8.0 * g_star * a * elapsed + eta_t) * slip;
    assert!(!f.sliding);
    assert!(
        (f.tangential_force.x / expected - 1.0).abs() < 1e-12,
        "{} vs {expected}",
        f.tangential_force.x
    );
    // Its step: a dashpot of k_t(a) pi / max(wd, beta) + eta_t at the stiffest contact.
    let m = sphere.mass;
    let design = hertz.design_contact(m);
    let o = design.oscillator;
    let longest = std::f64::consts::PI / o.damped_frequency.max(o.decay_rate);
    let dashpot = 8.0 * g_star * design.contact_radius * longest + ratio * o.damping_coefficient;
    let tangential = 2.0 * (2.0 / 7.0 * m) / dashpot;
    let expected = hertz.critical_time_step(m).min(tangential);
    assert!((law.critical_time_step(m) / expected - 1.0).abs() < 1e-12);
    assert!(
        tangential < hertz.critical_time_step(m),
        "the tangential bound is the one checked"
    );
}

/// A law built from another code's dashpot factor keeps that factor, and its rebound and
/// duration are the damped impact's, not the undamped one's.
#[test]
fn a_given_damping_factor_is_kept_with_its_rebound_and_duration() {
    let largest = impact(1.0, 1e-3);
    let given = Hertz::with_damping_factor(1.0e9, 0.5, largest).unwrap();
    let undamped = Hertz::new(1.0e9, 1.0, largest).unwrap();
    assert_eq!(given.damping_factor(), 0.5);
    assert!(given.restitution() < 0.9, "{}", given.restitution());
    let mass = 1.0e-5;
    let (damped, elastic) = (
        soft_sphere::prelude::NormalModel::contact_duration(&given, mass),
        soft_sphere::prelude::NormalModel::contact_duration(&undamped, mass),
    );
    assert!((damped / elastic - 1.0).abs() > 0.01, "{damped} {elastic}");
}
