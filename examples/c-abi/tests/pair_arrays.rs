//! The batch entry points (`ss_bound_sphere_pairs_*`) as a C host calls them, with arrays of
//! each field: every pair gives the bits, state and code of a single bound call, bad pairs
//! included, for every model and both precisions; null arrays are refused before anything is
//! written.

use std::ptr::{null, null_mut};

use host_tests::random::Xorshift;
use soft_sphere_ffi::*;

/// The arrays a host keeps, one `Vec` per field.
#[derive(Clone, Debug, Default)]
struct Columns<F> {
    fields: Vec<Vec<F>>,
}

impl<F: Copy + Default> Columns<F> {
    fn new(count: usize, width: usize) -> Self {
        Self {
            fields: vec![vec![F::default(); count]; width],
        }
    }
}

fn spheres<F: Copy>(c: &Columns<F>) -> ss_sphere_arrays<F> {
    let p = |k: usize| c.fields[k].as_ptr();
    ss_sphere_arrays {
        position_x: p(0),
        position_y: p(1),
        position_z: p(2),
        velocity_x: p(3),
        velocity_y: p(4),
        velocity_z: p(5),
        angular_velocity_x: p(6),
        angular_velocity_y: p(7),
        angular_velocity_z: p(8),
        radius: p(9),
        mass: p(10),
    }
}

fn states<F>(c: &mut Columns<F>) -> ss_state_arrays<F> {
    let [x, y, z, fx, fy, fz, a] = &mut c.fields[..] else {
        panic!("seven columns")
    };
    ss_state_arrays {
        displacement_x: x.as_mut_ptr(),
        displacement_y: y.as_mut_ptr(),
        displacement_z: z.as_mut_ptr(),
        spring_force_x: fx.as_mut_ptr(),
        spring_force_y: fy.as_mut_ptr(),
        spring_force_z: fz.as_mut_ptr(),
        contact_radius: a.as_mut_ptr(),
    }
}

fn outputs<F>(reals: &mut Columns<F>, codes: &mut Columns<i32>) -> ss_forces_arrays<F> {
    let mut r = reals.fields.iter_mut().map(|f| f.as_mut_ptr());
    let mut c = codes.fields.iter_mut().map(|f| f.as_mut_ptr());
    let mut next = || r.next().unwrap();
    ss_forces_arrays {
        status: c.next().unwrap(),
        touching: c.next().unwrap(),
        sliding: c.next().unwrap(),
        overlap: next(),
        normal_force: next(),
        force_on_j_x: next(),
        force_on_j_y: next(),
        force_on_j_z: next(),
        torque_on_i_x: next(),
        torque_on_i_y: next(),
        torque_on_i_z: next(),
        torque_on_j_x: next(),
        torque_on_j_y: next(),
        torque_on_j_z: next(),
    }
}

macro_rules! batch_matches_single_calls {
    ($name:ident, $real:ty, $law_new:ident, $bound_new:ident, $single:ident, $batch:ident, $bound_free:ident, $law_free:ident) => {
        #[test]
        fn $name() {
            type R = $real;
            let count = 103;
            for model in [
                SS_MODEL_STATELESS,
                SS_MODEL_AA,
                SS_MODEL_AA_LUDING,
                SS_MODEL_FRICTIONLESS,
                SS_MODEL_HERTZ_STATELESS,
                SS_MODEL_HERTZ_AA,
                SS_MODEL_HERTZ_AA_LUDING,
                SS_MODEL_HERTZ_FRICTIONLESS,
            ] {
                let params = ss_params::<R> {
                    model,
                    normal_stiffness: 1.0e4,
                    restitution: 0.7,
                    tangential_stiffness: 2.8e3,
                    dashpot_ratio: 0.5,
                    friction: 0.4,
                    time_step: 1.0e-6,
                    smallest_effective_mass: 1.0e-6,
                    effective_modulus: 5.0e5,
                    effective_shear_modulus: 2.0e5,
                    largest_impact_speed: 1.0,
                    largest_effective_radius: 1.0e-3,
                };
                let (mut law, mut bound) = (null_mut(), null_mut());
                // SAFETY: valid pointers.
                unsafe {
                    assert_eq!($law_new(&params, &mut law), SS_OK);
                    assert_eq!($bound_new(law, &mut bound), SS_OK);
                }
                let mut random = Xorshift::new(11 + model as u64);
                let mut next = || random.unit() * 2.0 - 1.0;
                let (mut i, mut j) = (Columns::<R>::new(count, 11), Columns::<R>::new(count, 11));
                let mut singles = Vec::new();
                for k in 0..count {
                    let mut pair = [ss_sphere::<R>::default(); 2];
                    for (side, s) in pair.iter_mut().enumerate() {
                        let centre = if side == 0 { 0.0 } else { 1.99e-3 };
                        s.position = ss_vec3 {
                            x: (centre + 1e-5 * next()) as R,
                            y: (1e-4 * next()) as R,
                            z: 0.0,
                        };
                        s.velocity = ss_vec3 {
                            x: (0.3 * next()) as R,
                            y: (0.3 * next()) as R,
                            z: (0.3 * next()) as R,
                        };
                        s.angular_velocity = ss_vec3 {
                            x: (300.0 * next()) as R,
                            y: 0.0,
                            z: (300.0 * next()) as R,
                        };
                        s.radius = 1.0e-3;
                        s.mass = (if next() > 0.0 { 1.0e-5 } else { 3.0e-5 }) as R;
                    }
                    // Every eleventh pair is bad in its own way.
                    match k % 11 {
                        3 => pair[1].mass = -1.0,
                        5 => pair[0].position.y = R::NAN,
                        7 => pair[1].position = pair[0].position,
                        9 => pair[0].radius = 0.0,
                        _ => {}
                    }
                    for (columns, s) in [(&mut i, pair[0]), (&mut j, pair[1])] {
                        let values = [
                            s.position.x,
                            s.position.y,
                            s.position.z,
                            s.velocity.x,
                            s.velocity.y,
                            s.velocity.z,
                            s.angular_velocity.x,
                            s.angular_velocity.y,
                            s.angular_velocity.z,
                            s.radius,
                            s.mass,
                        ];
                        for (field, value) in columns.fields.iter_mut().zip(values) {
                            field[k] = value;
                        }
                    }
                    singles.push(pair);
                }
                let mut batch_states = Columns::<R>::new(count, 7);
                let mut single_states = vec![ss_state::<R>::default(); count];
                for step in 0..20 {
                    let mut reals = Columns::<R>::new(count, 11);
                    let mut codes = Columns::<i32>::new(count, 3);
                    let before = batch_states.clone();
                    // SAFETY: every array has `count` elements; the written ones are disjoint.
                    let code = unsafe {
                        $batch(
                            bound,
                            count,
                            &spheres(&i),
                            &spheres(&j),
                            &states(&mut batch_states),
                            &outputs(&mut reals, &mut codes),
                        )
                    };
                    assert_eq!(code, SS_OK);
                    for k in 0..count {
                        let mut out = ss_forces::<R>::default();
                        // SAFETY: valid pointers.
                        let single = unsafe {
                            $single(
                                bound,
                                &singles[k][0],
                                &singles[k][1],
                                &mut single_states[k],
                                &mut out,
                            )
                        };
                        assert_eq!(
                            codes.fields[0][k], single,
                            "model {model} step {step} pair {k}"
                        );
                        let state =
                            [0, 1, 2, 3, 4, 5, 6].map(|c| batch_states.fields[c][k].to_bits());
                        let (d, f) = (single_states[k].displacement, single_states[k].spring_force);
                        let a = single_states[k].contact_radius;
                        let single_state = [d.x, d.y, d.z, f.x, f.y, f.z, a].map(<R>::to_bits);
                        assert_eq!(state, single_state, "model {model} pair {k}");
                        if single != SS_OK {
                            assert_eq!(
                                state,
                                [0, 1, 2, 3, 4, 5, 6].map(|c| before.fields[c][k].to_bits()),
                                "a failed pair keeps its state"
                            );
                            assert!(
                                reals.fields.iter().all(|f| f[k] == 0.0),
                                "a failed pair's outputs stay untouched"
                            );
                            continue;
                        }
                        let got: Vec<_> = reals.fields.iter().map(|f| f[k].to_bits()).collect();
                        let f = out;
                        let want: Vec<_> = [
                            f.overlap,
                            f.normal_force,
                            f.force_on_j.x,
                            f.force_on_j.y,
                            f.force_on_j.z,
                            f.torque_on_i.x,
                            f.torque_on_i.y,
                            f.torque_on_i.z,
                            f.torque_on_j.x,
                            f.torque_on_j.y,
                            f.torque_on_j.z,
                        ]
                        .iter()
                        .map(|x| x.to_bits())
                        .collect();
                        assert_eq!(got, want, "model {model} step {step} pair {k}");
                        assert_eq!(
                            [codes.fields[1][k], codes.fields[2][k]],
                            [f.touching, f.sliding]
                        );
                    }
                }
                let failing = (0..count)
                    .filter(|k| [3, 5, 7, 9].contains(&(k % 11)))
                    .count();
                assert!(failing >= 30);
                // Null arrays: refused, nothing written (states may be null only without state).
                let mut reals = Columns::<R>::new(count, 11);
                let mut codes = Columns::<i32>::new(count, 3);
                let mut out = outputs(&mut reals, &mut codes);
                out.torque_on_j_z = null_mut();
                let mut no_states = states(&mut batch_states);
                // SAFETY: as above, with one null array.
                unsafe {
                    assert_eq!(
                        $batch(bound, count, &spheres(&i), &spheres(&j), &no_states, &out),
                        SS_ERR_NULL
                    );
                    let mut no_radius = spheres(&j);
                    no_radius.radius = null();
                    let out = outputs(&mut reals, &mut codes);
                    assert_eq!(
                        $batch(bound, count, &spheres(&i), &no_radius, &no_states, &out),
                        SS_ERR_NULL
                    );
                    let stateful = match model {
                        SS_MODEL_AA | SS_MODEL_AA_LUDING => {
                            no_states.displacement_y = null_mut();
                            true
                        }
                        SS_MODEL_HERTZ_AA | SS_MODEL_HERTZ_AA_LUDING => {
                            no_states.contact_radius = null_mut();
                            true
                        }
                        _ => {
                            no_states.displacement_y = null_mut();
                            no_states.contact_radius = null_mut();
                            false
                        }
                    };
                    let expected = if stateful { SS_ERR_NULL } else { SS_OK };
                    assert_eq!(
                        $batch(bound, count, &spheres(&i), &spheres(&j), &no_states, &out),
                        expected
                    );
                    if stateful {
                        assert!(codes.fields[0].iter().all(|&c| c == 0), "nothing written");
                    }
                    assert_eq!(
                        $batch(
                            null_mut(),
                            count,
                            &spheres(&i),
                            &spheres(&j),
                            &no_states,
                            &out
                        ),
                        SS_ERR_NULL
                    );
                    assert_eq!(
                        $batch(
                            bound,
                            0,
                            &spheres(&i),
                            &spheres(&j),
                            &states(&mut batch_states),
                            &out
                        ),
                        SS_OK
                    );
                    $bound_free(bound);
                    $law_free(law);
                }
            }
        }
    };
}

batch_matches_single_calls!(
    f64_batch_calls_give_the_single_call_bits,
    f64,
    ss_law_new_f64,
    ss_bound_law_new_f64,
    ss_bound_sphere_sphere_f64,
    ss_bound_sphere_pairs_f64,
    ss_bound_law_free_f64,
    ss_law_free_f64
);
batch_matches_single_calls!(
    f32_batch_calls_give_the_single_call_bits,
    f32,
    ss_law_new_f32,
    ss_bound_law_new_f32,
    ss_bound_sphere_sphere_f32,
    ss_bound_sphere_pairs_f32,
    ss_bound_law_free_f32,
    ss_law_free_f32
);
