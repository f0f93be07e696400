//! The C ABI as a C host calls it: the bound-law entry points give the same bits as the shared
//! law's over pairs and walls of mixed masses (so that the remembered oscillator and wall are both
//! reused and replaced), a bound normal impact rebounds at the restitution it was given, and every
//! bad input has its documented code with the caller's state and output untouched.

use std::ptr::{null, null_mut};

use host_tests::random::Xorshift;
use soft_sphere_ffi::*;

fn params(model: i32) -> ss_params<f64> {
    ss_params {
        model,
        normal_stiffness: 1.0e4,
        restitution: 0.7,
        tangential_stiffness: 2.8e3,
        dashpot_ratio: 0.5,
        friction: 0.4,
        time_step: 1.0e-6,
        smallest_effective_mass: 1.0e-6,
        ..Default::default()
    }
}

const MODELS: [i32; 4] = [
    SS_MODEL_STATELESS,
    SS_MODEL_AA,
    SS_MODEL_AA_LUDING,
    SS_MODEL_FRICTIONLESS,
];

fn law(model: i32) -> *mut ss_law<f64> {
    let mut law = null_mut();
    // SAFETY: valid pointers.
    assert_eq!(unsafe { ss_law_new_f64(&params(model), &mut law) }, SS_OK);
    law
}

fn bound(law: *const ss_law<f64>) -> *mut ss_bound_law<f64> {
    let mut bound = null_mut();
    // SAFETY: valid pointers.
    assert_eq!(unsafe { ss_bound_law_new_f64(law, &mut bound) }, SS_OK);
    bound
}

fn v(x: f64, y: f64, z: f64) -> ss_vec3<f64> {
    ss_vec3 { x, y, z }
}

/// A 1 mm sphere of one of two densities, at `position`, with random velocity and spin.
fn sphere(random: &mut Xorshift, position: ss_vec3<f64>) -> ss_sphere<f64> {
    let mut next = || random.unit() * 2.0 - 1.0;
    let radius = 1.0e-3;
    let density = if next() > 0.0 { 2500.0 } else { 7800.0 };
    ss_sphere {
        position,
        velocity: v(0.3 * next(), 0.3 * next(), 0.3 * next()),
        angular_velocity: v(300.0 * next(), 300.0 * next(), 300.0 * next()),
        radius,
        mass: density * 4.0 / 3.0 * std::f64::consts::PI * radius * radius * radius,
    }
}

fn bits(f: &ss_forces<f64>) -> Vec<u64> {
    let mut all = vec![
        u64::from(f.touching as u32),
        u64::from(f.sliding as u32),
        f.overlap.to_bits(),
        f.normal_force.to_bits(),
    ];
    for w in [f.force_on_j, f.torque_on_i, f.torque_on_j] {
        all.extend([w.x.to_bits(), w.y.to_bits(), w.z.to_bits()]);
    }
    all
}

fn state_bits(s: &ss_state<f64>) -> [u64; 3] {
    [s.displacement.x, s.displacement.y, s.displacement.z].map(f64::to_bits)
}

#[test]
fn bound_calls_give_the_shared_law_bits() {
    let floor = ss_wall {
        point: v(0.0, 0.0, 0.0),
        direction: v(0.0, 0.0, 1.0),
        velocity: v(0.0, 0.0, 0.0),
        ..ss_wall::default()
    };
    // A floor, a moving ceiling, a turning drum along x whose lowest line is the floor's, and a
    // drum about the floor's own normal (the spheres far inside it): the bound law's memo of
    // the last wall tells each from the others.
    let walls = [
        floor,
        ss_wall {
            point: v(0.0, 0.0, 1.98e-3),
            direction: v(0.0, -0.0, -2.0),
            velocity: v(0.01, 0.0, 0.0),
            ..ss_wall::default()
        },
        ss_wall {
            point: v(0.0, 0.0, 0.5),
            direction: v(1.0, 0.0, 0.0),
            radius: 0.5,
            spin: 0.2,
            ..floor
        },
        ss_wall {
            radius: 0.5,
            ..floor
        },
    ];
    for model in MODELS {
        let law = law(model);
        let bound = bound(law);
        let mut random = Xorshift::new(7 + model as u64);
        // 200 contacts, each followed for 50 steps so that springs build up and contacts slide.
        let (mut touching, mut sliding, mut on_walls) = (0, 0, 0);
        for _ in 0..200 {
            let gap = 2.0e-3 * (1.0 - 0.02 * random.unit());
            let mut dir = [
                random.unit() - 0.5,
                random.unit() - 0.5,
                random.unit() - 0.5,
            ];
            let length = dir.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-3);
            dir.iter_mut().for_each(|x| *x *= gap / length);
            // Low enough to touch the floor, high enough to touch the ceiling.
            let z = 1.0e-3 - 0.02e-3 * random.unit();
            let i = sphere(&mut random, v(0.0, 0.0, z));
            let j = sphere(&mut random, v(dir[0], dir[1], z + dir[2]));
            let wall = &walls[(4.0 * random.unit()) as usize % 4];
            let (mut shared, mut through_bound) = (ss_state::default(), ss_state::default());
            let (mut wall_shared, mut wall_bound) = (ss_state::default(), ss_state::default());
            for _ in 0..50 {
                let (mut a, mut b) = (ss_forces::default(), ss_forces::default());
                // SAFETY: valid pointers throughout.
                unsafe {
                    assert_eq!(
                        ss_sphere_sphere_f64(law, &i, &j, &mut shared, &mut a),
                        SS_OK
                    );
                    let code =
                        ss_bound_sphere_sphere_f64(bound, &i, &j, &mut through_bound, &mut b);
                    assert_eq!(code, SS_OK);
                }
                assert_eq!(bits(&a), bits(&b));
                assert_eq!(state_bits(&shared), state_bits(&through_bound));
                touching += a.touching;
                sliding += a.sliding;
                // SAFETY: valid pointers throughout.
                unsafe {
                    assert_eq!(
                        ss_sphere_wall_f64(law, &i, wall, &mut wall_shared, &mut a),
                        SS_OK
                    );
                    let code = ss_bound_sphere_wall_f64(bound, &i, wall, &mut wall_bound, &mut b);
                    assert_eq!(code, SS_OK);
                }
                assert_eq!(bits(&a), bits(&b));
                assert_eq!(state_bits(&wall_shared), state_bits(&wall_bound));
                on_walls += a.touching;
            }
        }
        assert!(touching > 5_000, "the pairs touch: {touching}");
        assert!(on_walls > 5_000, "the walls are touched: {on_walls}");
        if model != SS_MODEL_FRICTIONLESS {
            assert!(sliding > 100, "some contacts slide: {sliding}");
        }
        // SAFETY: handles from their constructors, not used afterwards.
        unsafe {
            ss_bound_law_free_f64(bound);
            ss_law_free_f64(law);
        }
    }
}

/// A head-on impact of equal spheres through the bound law, advanced by the kernel's integrator:
/// the separation speed over the approach speed is the restitution the law was given (the linear
/// spring-dashpot's rebound is independent of speed; the step resolves the contact in about 700 steps).
#[test]
fn bound_head_on_impact_rebounds_at_the_given_restitution() {
    let fine = ss_params {
        time_step: 1.0e-7,
        ..params(SS_MODEL_AA)
    };
    let mut law = null_mut();
    // SAFETY: valid pointers.
    assert_eq!(unsafe { ss_law_new_f64(&fine, &mut law) }, SS_OK);
    let bound = bound(law);
    let mass = 1.0e-5;
    let mut i = ss_sphere {
        position: v(0.0, 0.0, 0.0),
        velocity: v(0.5, 0.0, 0.0),
        radius: 1.0e-3,
        mass,
        ..Default::default()
    };
    let mut j = ss_sphere {
        position: v(2.0e-3 + 1.0e-6, 0.0, 0.0),
        velocity: v(-0.5, 0.0, 0.0),
        ..i
    };
    let mut state = ss_state::default();
    let mut touched = false;
    for _ in 0..100_000 {
        let mut out = ss_forces::default();
        // SAFETY: valid pointers.
        let code = unsafe { ss_bound_sphere_sphere_f64(bound, &i, &j, &mut state, &mut out) };
        assert_eq!(code, SS_OK);
        touched |= out.touching == 1;
        if touched && out.touching == 0 {
            break;
        }
        let f = out.force_on_j;
        let zero = v(0.0, 0.0, 0.0);
        // SAFETY: valid pointers.
        unsafe {
            ss_advance_sphere_f64(law, &mut i, v(-f.x, -f.y, -f.z), zero);
            ss_advance_sphere_f64(law, &mut j, f, zero);
        }
    }
    let approach = 1.0;
    let rebound = (j.velocity.x - i.velocity.x) / approach;
    assert!((rebound - 0.7).abs() < 2.0e-3, "rebound {rebound}");
    // SAFETY: handles from their constructors, not used afterwards.
    unsafe {
        ss_bound_law_free_f64(bound);
        ss_law_free_f64(law);
    }
}

#[test]
fn bad_input_to_a_bound_law_has_its_code_and_changes_nothing() {
    let law = law(SS_MODEL_AA);
    let bound = bound(law);
    let mut random = Xorshift::new(3);
    let good_i = sphere(&mut random, v(0.0, 0.0, 1.0e-3));
    let good_j = sphere(&mut random, v(1.9e-3, 0.0, 1.0e-3));
    let floor = ss_wall {
        point: v(0.0, 0.0, 0.0),
        direction: v(0.0, 0.0, 1.0),
        velocity: v(0.0, 0.0, 0.0),
        ..ss_wall::default()
    };
    let spring = ss_state {
        displacement: v(1.0e-6, -2.0e-6, 0.0),
        ..Default::default()
    };
    let sentinel = ss_forces {
        touching: 7,
        ..Default::default()
    };
    let with = |change: fn(&mut ss_sphere<f64>)| {
        let mut s = good_j;
        change(&mut s);
        s
    };
    let bad_spheres = [
        (with(|s| s.position.x = f64::NAN), SS_ERR_NON_FINITE_INPUT),
        (
            with(|s| s.angular_velocity.z = f64::INFINITY),
            SS_ERR_NON_FINITE_INPUT,
        ),
        (with(|s| s.radius = -1.0e-3), SS_ERR_NON_POSITIVE_RADIUS),
        (with(|s| s.mass = 0.0), SS_ERR_NON_POSITIVE_MASS),
        (
            ss_sphere {
                position: good_i.position,
                ..good_j
            },
            SS_ERR_COINCIDENT_CENTRES,
        ),
    ];
    for (bad, code) in bad_spheres {
        let (mut state, mut out) = (spring, sentinel);
        // SAFETY: valid pointers.
        let got = unsafe { ss_bound_sphere_sphere_f64(bound, &good_i, &bad, &mut state, &mut out) };
        assert_eq!(got, code, "{bad:?}");
        assert_eq!(state_bits(&state), state_bits(&spring));
        assert_eq!(out.touching, 7);
        if code != SS_ERR_COINCIDENT_CENTRES {
            // SAFETY: valid pointers.
            let got =
                unsafe { ss_bound_sphere_wall_f64(bound, &bad, &floor, &mut state, &mut out) };
            assert_eq!(got, code, "{bad:?} on the wall");
            assert_eq!(state_bits(&state), state_bits(&spring));
            assert_eq!(out.touching, 7);
        }
    }
    // A bad wall is refused, also right after a good one was remembered, and is not remembered.
    let bad_walls = [
        ss_wall {
            direction: v(0.0, 0.0, 0.0),
            ..floor
        },
        ss_wall {
            velocity: v(f64::NAN, 0.0, 0.0),
            ..floor
        },
        ss_wall {
            point: v(0.0, f64::INFINITY, 0.0),
            ..floor
        },
        // A cylinder's radius negative or not finite, a spin not finite.
        ss_wall {
            radius: -0.1,
            ..floor
        },
        ss_wall {
            radius: f64::NAN,
            ..floor
        },
        ss_wall {
            radius: f64::INFINITY,
            ..floor
        },
        ss_wall {
            spin: f64::NAN,
            ..floor
        },
        ss_wall {
            spin: f64::NEG_INFINITY,
            ..floor
        },
    ];
    let low = ss_sphere {
        position: v(0.0, 0.0, 0.9e-3),
        ..good_i
    };
    for bad in bad_walls {
        let (mut state, mut out) = (spring, sentinel);
        // SAFETY: valid pointers.
        unsafe {
            assert_eq!(
                ss_bound_sphere_wall_f64(bound, &low, &floor, &mut state, &mut out),
                SS_OK
            );
            assert_eq!(out.touching, 1);
            let (mut state, mut out) = (spring, sentinel);
            let got = ss_bound_sphere_wall_f64(bound, &low, &bad, &mut state, &mut out);
            assert_eq!(got, SS_ERR_BAD_WALL);
            assert_eq!(state_bits(&state), state_bits(&spring));
            assert_eq!(out.touching, 7);
            let got = ss_bound_sphere_wall_f64(bound, &low, &bad, &mut state, &mut out);
            assert_eq!(got, SS_ERR_BAD_WALL, "a refused wall is not remembered");
        }
    }
    // Null pointers.
    let (mut state, mut out) = (spring, sentinel);
    // SAFETY: null is what is being tested; the other pointers are valid.
    unsafe {
        let mut handle = null_mut();
        assert_eq!(ss_bound_law_new_f64(null(), &mut handle), SS_ERR_NULL);
        assert!(handle.is_null());
        assert_eq!(ss_bound_law_new_f64(law, null_mut()), SS_ERR_NULL);
        let calls = [
            ss_bound_sphere_sphere_f64(null_mut(), &good_i, &good_j, &mut state, &mut out),
            ss_bound_sphere_sphere_f64(bound, null(), &good_j, &mut state, &mut out),
            ss_bound_sphere_sphere_f64(bound, &good_i, &good_j, null_mut(), &mut out),
            ss_bound_sphere_sphere_f64(bound, &good_i, &good_j, &mut state, null_mut()),
            ss_bound_sphere_wall_f64(bound, &good_i, null(), &mut state, &mut out),
            ss_bound_sphere_wall_f64(null_mut(), &good_i, &floor, &mut state, &mut out),
        ];
        assert_eq!(calls, [SS_ERR_NULL; 6]);
        ss_bound_law_free_f64(null_mut());
    }
    assert_eq!(state_bits(&state), state_bits(&spring));
    assert_eq!(out.touching, 7);
    // SAFETY: handles from their constructors, not used afterwards.
    unsafe {
        ss_bound_law_free_f64(bound);
        ss_law_free_f64(law);
    }
}

/// The f32 entry points are generated from the same source: one bound contact equals the shared
/// law's bits.
#[test]
fn f32_bound_calls_give_the_shared_law_bits() {
    let p = params(SS_MODEL_AA);
    let p32 = ss_params {
        model: p.model,
        normal_stiffness: p.normal_stiffness as f32,
        restitution: p.restitution as f32,
        tangential_stiffness: p.tangential_stiffness as f32,
        dashpot_ratio: p.dashpot_ratio as f32,
        friction: p.friction as f32,
        time_step: p.time_step as f32,
        smallest_effective_mass: p.smallest_effective_mass as f32,
        ..Default::default()
    };
    let mut random = Xorshift::new(11);
    let to32 = |s: ss_sphere<f64>| {
        let w = |a: ss_vec3<f64>| ss_vec3 {
            x: a.x as f32,
            y: a.y as f32,
            z: a.z as f32,
        };
        ss_sphere {
            position: w(s.position),
            velocity: w(s.velocity),
            angular_velocity: w(s.angular_velocity),
            radius: s.radius as f32,
            mass: s.mass as f32,
        }
    };
    let i = to32(sphere(&mut random, v(0.0, 0.0, 0.0)));
    let j = to32(sphere(&mut random, v(1.99e-3, 0.0, 0.0)));
    // SAFETY: valid pointers; handles freed once.
    unsafe {
        let (mut law, mut bound) = (null_mut(), null_mut());
        assert_eq!(ss_law_new_f32(&p32, &mut law), SS_OK);
        assert_eq!(ss_bound_law_new_f32(law, &mut bound), SS_OK);
        let (mut s1, mut s2) = (ss_state::default(), ss_state::default());
        for _ in 0..20 {
            let (mut a, mut b) = (ss_forces::default(), ss_forces::default());
            assert_eq!(ss_sphere_sphere_f32(law, &i, &j, &mut s1, &mut a), SS_OK);
            assert_eq!(
                ss_bound_sphere_sphere_f32(bound, &i, &j, &mut s2, &mut b),
                SS_OK
            );
            assert_eq!(a.touching, 1);
            assert_eq!(a.force_on_j.x.to_bits(), b.force_on_j.x.to_bits());
            assert_eq!(a.torque_on_i.y.to_bits(), b.torque_on_i.y.to_bits());
            assert_eq!(s1.displacement.z.to_bits(), s2.displacement.z.to_bits());
        }
        ss_bound_law_free_f32(bound);
        ss_law_free_f32(law);
    }
}

/// The Hertz-Mindlin models through the C ABI: the Rust kernel's law and bits, its state in
/// `spring_force` and `contact_radius`, and each bad Hertz input refused with its code.
#[test]
fn hertz_models_give_the_kernels_bits_and_refuse_bad_materials() {
    use soft_sphere::prelude::{
        ContactLaw, Hertz, HertzImpact, Interaction, MindlinAA, MindlinParameters, MindlinSpring,
        Sphere, Vec3,
    };
    let (steel, rigid) = (
        ss_material {
            youngs_modulus: 208.0e9,
            poisson_ratio: 0.3,
        },
        null(),
    );
    let (mut e, mut g) = (0.0, 0.0);
    // SAFETY: valid pointers (j null: a rigid body).
    assert_eq!(
        unsafe { ss_effective_moduli_f64(&steel, rigid, &mut e, &mut g) },
        SS_OK
    );
    assert!((e - 208.0e9 / 0.91).abs() < 1.0 && (g - 80.0e9 / 1.7).abs() < 1.0);
    let bad = ss_material {
        youngs_modulus: 1.0e9,
        poisson_ratio: 0.7,
    };
    let (mut e2, mut g2) = (-1.0, -1.0);
    // SAFETY: valid pointers.
    let code = unsafe { ss_effective_moduli_f64(&steel, &bad, &mut e2, &mut g2) };
    assert_eq!((code, e2, g2), (SS_ERR_POISSON_RATIO, -1.0, -1.0));

    let p = ss_params {
        model: SS_MODEL_HERTZ_AA,
        restitution: 0.8,
        dashpot_ratio: 0.5,
        friction: 0.3,
        time_step: 1.0e-8,
        smallest_effective_mass: 1.0e-3,
        effective_modulus: e,
        effective_shear_modulus: g,
        largest_impact_speed: 1.0,
        largest_effective_radius: 0.01,
        ..Default::default()
    };
    let mut law = null_mut();
    // SAFETY: valid pointers.
    assert_eq!(unsafe { ss_law_new_f64(&p, &mut law) }, SS_OK);
    let largest = HertzImpact {
        speed: 1.0,
        effective_radius: 0.01,
    };
    let rust = ContactLaw::new(
        Hertz::new(e, 0.8, largest).unwrap(),
        MindlinAA(MindlinParameters::new(g, 0.5, 0.3).unwrap()),
    );
    let dt = rust.time_step(1.0e-8, 1.0e-3).unwrap();
    let mut sphere = Sphere::solid(Vec3::new(0.0, 0.0, 0.01 - 2e-6), 0.01, 7850.0);
    sphere.velocity = Vec3::new(0.2, 0.0, -0.1);
    let floor = ss_wall {
        point: v(0.0, 0.0, 0.0),
        direction: v(0.0, 0.0, 1.0),
        velocity: v(0.0, 0.0, 0.0),
        ..ss_wall::default()
    };
    let plane = soft_sphere::prelude::Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap();
    // A turning drum about an axis along x whose lowest line is the floor's.
    let drum = ss_wall {
        point: v(0.0, 0.0, 0.5),
        direction: v(2.0, 0.0, 0.0),
        radius: 0.5,
        spin: 3.0,
        ..floor
    };
    let turning = soft_sphere::prelude::Wall::cylinder(
        Vec3::new(0.0, 0.0, 0.5),
        Vec3::new(2.0, 0.0, 0.0),
        0.5,
    )
    .and_then(|w| w.with_spin(3.0))
    .unwrap();
    // A radius of -0.0 is a plane, as 0.0 is.
    let signed = ss_wall {
        radius: -0.0,
        ..floor
    };
    for (floor, wall) in [(floor, plane), (signed, plane), (drum, turning)] {
        let mut ours = MindlinSpring::default();
        let mut theirs = ss_state::default();
        for _ in 0..3 {
            let mut out = ss_forces::default();
            let c_sphere = ss_sphere {
                position: v(sphere.position.x, sphere.position.y, sphere.position.z),
                velocity: v(sphere.velocity.x, sphere.velocity.y, sphere.velocity.z),
                angular_velocity: v(0.0, 0.0, 0.0),
                radius: sphere.radius,
                mass: sphere.mass,
            };
            // SAFETY: valid pointers.
            assert_eq!(
                unsafe { ss_sphere_wall_f64(law, &c_sphere, &floor, &mut theirs, &mut out) },
                SS_OK
            );
            let Ok(Interaction::Touching(f)) = rust.sphere_wall(&sphere, &wall, &mut ours, dt)
            else {
                panic!("touching")
            };
            // The C ABI reports the sphere's force as the one on j.
            assert_eq!(out.normal_force.to_bits(), f.normal_force.to_bits());
            assert_eq!(out.force_on_j.x.to_bits(), f.force_on_i().x.to_bits());
            assert_eq!(theirs.spring_force.x.to_bits(), ours.force.x.to_bits());
            assert_eq!(
                theirs.contact_radius.to_bits(),
                ours.contact_radius.to_bits()
            );
            assert_eq!(
                theirs.displacement.x, 0.0,
                "the linear laws' field stays unused"
            );
            assert_eq!(out.torque_on_j.y.to_bits(), f.torque_on_i.y.to_bits());
        }
    }
    let mut duration = 0.0;
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { ss_contact_duration_f64(&p, 1.0e-3, &mut duration) },
        SS_OK
    );
    assert_eq!(duration, rust.contact_duration(1.0e-3));
    // SAFETY: the handle came from ss_law_new_f64.
    unsafe { ss_law_free_f64(law) };

    for (change, code, parameter) in [
        (
            (|p: &mut ss_params<f64>| p.effective_modulus = 0.0) as fn(&mut ss_params<f64>),
            SS_ERR_NOT_POSITIVE,
            SS_PARAMETER_MODULUS,
        ),
        (
            |p| p.effective_shear_modulus = f64::NAN,
            SS_ERR_NON_FINITE_PARAMETER,
            SS_PARAMETER_MODULUS,
        ),
        (
            |p| p.largest_impact_speed = -1.0,
            SS_ERR_NOT_POSITIVE,
            SS_PARAMETER_SPEED,
        ),
        (
            |p| p.largest_effective_radius = 0.0,
            SS_ERR_NOT_POSITIVE,
            SS_PARAMETER_RADIUS,
        ),
        (
            |p| p.restitution = 2.0,
            SS_ERR_RESTITUTION,
            SS_PARAMETER_RESTITUTION,
        ),
        (
            |p| p.time_step = 1.0,
            SS_ERR_UNSTABLE_TIME_STEP,
            SS_PARAMETER_TIME_STEP,
        ),
    ] {
        let mut q = p;
        change(&mut q);
        let mut law = null_mut();
        // SAFETY: valid pointers.
        assert_eq!(unsafe { ss_law_new_f64(&q, &mut law) }, code);
        assert!(law.is_null(), "nothing written on error");
        // SAFETY: a valid pointer.
        assert_eq!(unsafe { ss_rejected_parameter_f64(&q) }, parameter);
    }
}

/// The contact duration reads the normal law of the model's family: Hertz's for micro-slip
/// (a Hertz law, though only tables hold it) and Hertz's closed form `t_c` (Johnson; `e` = 1)
/// for its parameters, the spring's `pi sqrt(m*/k_n)` for a linear law, and
/// `SS_ERR_UNKNOWN_MODEL` with the output untouched for a code no law has.
#[test]
fn contact_duration_follows_the_models_family_and_refuses_unknown_codes() {
    let (e_star, r_star, m_star) = (1.0e9, 1.0e-3, 1.0e-5);
    let hertz = |model| ss_params {
        model,
        restitution: 1.0,
        effective_modulus: e_star,
        effective_shear_modulus: 0.4 * e_star,
        largest_impact_speed: 1.0,
        largest_effective_radius: r_star,
        ..Default::default()
    };
    let duration = |p: &ss_params<f64>| {
        let mut out = -1.0;
        // SAFETY: valid pointers.
        let code = unsafe { ss_contact_duration_f64(p, m_star, &mut out) };
        (code, out)
    };
    // Hertz's elastic contact time at impact speed v: 2.868 (m*^2 / (R* E*^2 v))^(1/5)
    // (Johnson, Contact Mechanics, section 11.4). The law's design impact is its declared one.
    let closed_form = 2.868 * (m_star * m_star / (r_star * e_star * e_star * 1.0)).powf(0.2);
    for model in [SS_MODEL_HERTZ_AA, SS_MODEL_HERTZ_MICROSLIP] {
        let (code, t_c) = duration(&hertz(model));
        assert_eq!(code, SS_OK, "model {model}");
        assert!(
            (t_c / closed_form - 1.0).abs() < 2e-3,
            "model {model}: {t_c} vs Hertz's {closed_form}"
        );
    }
    let linear = ss_params {
        restitution: 1.0,
        ..params(SS_MODEL_AA)
    };
    let (code, t_c) = duration(&linear);
    assert_eq!(code, SS_OK);
    let spring = std::f64::consts::PI * (m_star / linear.normal_stiffness).sqrt();
    assert!((t_c / spring - 1.0).abs() < 1e-12, "{t_c} vs {spring}");
    for unknown in [-1, 9, 99] {
        assert_eq!(
            duration(&hertz(unknown)),
            (SS_ERR_UNKNOWN_MODEL, -1.0),
            "code {unknown}"
        );
    }
}

/// `ss_stability_limit_*` gives the step at which `ss_law_new_*` starts to refuse a law as
/// unstable, whatever step the parameters hold (a host asks it after its step was refused).
#[test]
fn the_stability_limit_is_where_the_constructor_starts_to_refuse() {
    for model in MODELS {
        for step in [1.0e-6, 1.0, f64::NAN, 0.0] {
            let given = ss_params {
                time_step: step,
                ..params(model)
            };
            let mut limit = 0.0;
            // SAFETY: valid pointers.
            let code = unsafe { ss_stability_limit_f64(&given, &mut limit) };
            assert_eq!(code, SS_OK, "model {model}, step {step}");
            let new_at = |time_step: f64| {
                let mut law = null_mut();
                let p = ss_params {
                    time_step,
                    ..params(model)
                };
                // SAFETY: valid pointers.
                let code = unsafe { ss_law_new_f64(&p, &mut law) };
                // SAFETY: from ss_law_new_f64 (null when refused).
                unsafe { ss_law_free_f64(law) };
                code
            };
            assert_eq!(new_at(limit), SS_ERR_UNSTABLE_TIME_STEP, "model {model}");
            // Just below it, stable (past the accuracy limit, which is lower).
            let below = f64::from_bits(limit.to_bits() - 1);
            assert_eq!(new_at(below), SS_ERR_INACCURATE_TIME_STEP, "model {model}");
        }
    }
}
