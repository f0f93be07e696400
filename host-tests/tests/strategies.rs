//! The kernel's published strategies (`soft_sphere::strategies`) draw what their documents say:
//! each range is checked on every draw, and the arbitrary bit patterns reach the values that
//! break careless code.

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;
use soft_sphere::prelude::{CheckedSphere, NormalModel, Vec3, WallShape, effective_mass};
use soft_sphere::strategies::{
    Collision, any_bits, any_sphere, collision, constant_rolling, elastic_plastic_rolling,
    grazing_pair, hertz, impact, linear_spring_dashpot, mindlin_parameters, sphere,
    tangential_parameters, touching_pair, unit_vector, wall,
};

fn within(x: f64, low: f64, high: f64) -> bool {
    x >= low * (1.0 - 1e-12) && x <= high * (1.0 + 1e-12)
}

proptest! {
    #![proptest_config(host_tests::strategies::config())]

    #[test]
    fn collisions_are_in_their_ranges_and_just_touch(c in collision()) {
        prop_assert!(within(c.speed, 0.05, 5.0));
        prop_assert!((0.0..=89.0).contains(&c.angle_deg));
        prop_assert!(within(c.first.radius, 1e-4, 0.1));
        prop_assert!(within(c.second.radius / c.first.radius, 0.1, 10.0));
        let m = c.material;
        prop_assert!((0.0..=1.0).contains(&m.restitution) && (0.0..=2.0).contains(&m.friction));
        prop_assert!(within(m.stiffness_ratio, 0.1, 2.0) && within(m.overlap_fraction, 1e-3, 0.05));
        let (i, j) = c.pair::<f64>();
        let gap = (j.position - i.position).norm_squared().sqrt() - i.radius - j.radius;
        prop_assert!(gap.abs() < 1e-12 * (i.radius + j.radius));
        // Approaching: the second moves towards the first.
        prop_assert!((j.velocity - i.velocity).dot(j.position - i.position) < 0.0);
        let (w, s) = c.wall::<f32>();
        prop_assert!((w.distance_to(s.position) / s.radius - 1.0).abs() < 1e-5);
    }

    #[test]
    fn a_collision_approaches_at_its_speed_and_angle_along_its_hint(c in collision()) {
        let (i, j) = c.pair::<f64>();
        let n = Vec3::from(c.normal);
        let v = j.velocity - i.velocity;
        let speed = v.norm_squared().sqrt();
        prop_assert!((speed / c.speed - 1.0).abs() < 1e-9, "{speed} against {}", c.speed);
        let along = -v.dot(n);
        let cos = c.angle_deg.to_radians().cos();
        prop_assert!((along - c.speed * cos).abs() < 1e-9 * c.speed, "{along}");
        // The tangential part points along the hint's tangential part.
        let hint = Vec3::from(c.tangent_hint);
        let hint_t = hint - n * hint.dot(n);
        let v_t = v + n * along;
        if c.angle_deg > 1.0 && hint_t.norm_squared() > 1e-6 {
            let alignment = v_t.dot(hint_t) / (v_t.norm_squared() * hint_t.norm_squared()).sqrt();
            prop_assert!(alignment > 1.0 - 1e-9, "{alignment}");
        }
        // Spin speeds are angular velocity times radius, on both spheres and at the wall.
        for (body, sphere) in [(c.first, i), (c.second, j), (c.second, c.wall::<f64>().1)] {
            let spin = sphere.angular_velocity * sphere.radius;
            let expected = Vec3::from(body.spin_speed);
            prop_assert!((spin - expected).norm_squared() <= 1e-20 + 1e-24 * expected.norm_squared());
        }
        // The wall's sphere approaches as the pair's second sphere does.
        let (_, s) = c.wall::<f64>();
        prop_assert!((s.velocity.dot(n) + c.speed * cos).abs() < 1e-9 * c.speed);
        // The stiffness gives the documented head-on peak overlap: v sqrt(m*/k_n).
        let m = effective_mass(i.mass, j.mass);
        let peak = c.speed * (m / c.normal_stiffness(m)).sqrt();
        let expected = c.material.overlap_fraction * c.first.radius.min(c.second.radius);
        prop_assert!((peak / expected - 1.0).abs() < 1e-9, "{peak} against {expected}");
    }

    #[test]
    fn impacts_take_the_angles_and_speeds_asked_for(c in impact(30.0..=40.0, 1.0..=2.0)) {
        prop_assert!((30.0..=40.0).contains(&c.angle_deg) && (1.0..=2.0).contains(&c.speed));
    }

    #[test]
    fn touching_pairs_overlap_and_grazing_pairs_barely(
        (a, b) in touching_pair::<f64>(),
        (g, h) in grazing_pair::<f64>(),
    ) {
        let overlap = a.radius + b.radius - (b.position - a.position).norm_squared().sqrt();
        prop_assert!(within(overlap / a.radius.min(b.radius), 1e-4, 0.05));
        let overlap = g.radius + h.radius - (h.position - g.position).norm_squared().sqrt();
        prop_assert!(overlap / g.radius.min(h.radius) < 2e-6);
    }

    #[test]
    fn spheres_walls_and_laws_are_valid(
        s in sphere::<f32>(),
        w in wall::<f64>(),
        linear in linear_spring_dashpot::<f64>(),
        h in hertz::<f32>(),
        t in tangential_parameters::<f64>(),
        m in mindlin_parameters::<f64>(),
        c in constant_rolling::<f64>(),
        e in elastic_plastic_rolling::<f64>(1e-12),
    ) {
        prop_assert!(CheckedSphere::new(s).is_ok());
        prop_assert!(s.position.to_array().iter().all(|x| x.abs() <= 1.0));
        prop_assert!((w.direction().norm_squared() - 1.0).abs() < 1e-12);
        prop_assert!(w.spin().abs() <= 20.0);
        if let WallShape::Cylinder { radius } = w.shape() {
            prop_assert!(within(radius, 0.05, 2.0));
        }
        prop_assert!(w.point().to_array().iter().all(|x| x.abs() <= 1.0));
        prop_assert!(w.velocity().to_array().iter().all(|x| x.abs() <= 2.0));
        let spin = (s.angular_velocity * s.radius).to_array();
        prop_assert!(spin.iter().all(|x| x.abs() <= 2.0 * (1.0 + 1e-6)));
        prop_assert!(within(linear.stiffness(), 10.0, 1e7));
        prop_assert!(within(f64::from(h.effective_modulus()), 1e6, 1e12) && h.critical_time_step(1.0) > 0.0);
        prop_assert!(within(t.stiffness(), 10.0, 1e7) && (0.0..=2.0).contains(&t.friction()));
        prop_assert!(within(m.shear_modulus(), 1e5, 1e11) && (0.0..=1.0).contains(&m.dashpot_ratio()));
        prop_assert!((0.0..=0.5).contains(&c.friction()));
        prop_assert!(within(e.stiffness(), 1e-9, 1.0));
    }
}

/// `count` draws of `strategy` from a fixed seed.
fn draws<T: std::fmt::Debug>(strategy: impl Strategy<Value = T>, count: usize) -> Vec<T> {
    let mut runner = TestRunner::deterministic();
    (0..count)
        .map(|_| strategy.new_tree(&mut runner).unwrap().current())
        .collect()
}

#[test]
fn unit_vectors_are_uniform_on_the_sphere() {
    let vectors = draws(unit_vector(), 4000);
    let mut octants = [0usize; 8];
    for v in &vectors {
        assert!(((v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1.0).abs() < 1e-12);
        let octant =
            usize::from(v[0] > 0.0) + 2 * usize::from(v[1] > 0.0) + 4 * usize::from(v[2] > 0.0);
        octants[octant] += 1;
    }
    // Uniform: each octant holds an eighth, 500 of 4000, within 4.5 standard deviations (21).
    assert!(octants.iter().all(|&n| n.abs_diff(500) < 95), "{octants:?}");
}

#[test]
fn velocities_and_spins_fill_their_range_both_ways() {
    let collisions = draws(collision(), 2000);
    let components =
        |pick: fn(&Collision) -> [f64; 3]| collisions.iter().flat_map(pick).collect::<Vec<f64>>();
    for (what, values) in [
        ("velocity", components(|c| c.first.velocity)),
        ("spin", components(|c| c.second.spin_speed)),
    ] {
        assert!(values.iter().all(|x| x.abs() <= 2.0), "{what}");
        // Uniform on [-2, 2]: a quarter of them below -1, a quarter above 1.
        let below = values.iter().filter(|&&x| x < -1.0).count() as f64 / values.len() as f64;
        let above = values.iter().filter(|&&x| x > 1.0).count() as f64 / values.len() as f64;
        assert!(
            (below - 0.25).abs() < 0.03 && (above - 0.25).abs() < 0.03,
            "{what}: {below} {above}"
        );
    }
}

#[test]
fn spheres_spin_across_their_range() {
    // Spin speeds (angular velocity times radius) are uniform within +-2 m/s per component.
    let spins: Vec<f64> = draws(sphere::<f64>(), 500)
        .iter()
        .flat_map(|s| (s.angular_velocity * s.radius).to_array())
        .collect();
    assert!(spins.iter().all(|w| w.abs() <= 2.0 * (1.0 + 1e-12)));
    let fast = spins.iter().filter(|w| w.abs() > 1.0).count() as f64 / spins.len() as f64;
    assert!((fast - 0.5).abs() < 0.05, "{fast}");
}

#[test]
fn a_hint_along_the_normal_still_gives_a_tangent() {
    let mut c = draws(impact(45.0..=45.0, 1.0..=1.0), 1).remove(0);
    let axes = [
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [-1.0, 0.0, 0.0],
    ];
    // Off the axes too, so that the stand-in direction has a part along the normal to remove.
    let oblique = [[0.6, 0.8, 0.0], [0.96, 0.28, 0.0], [0.0, -0.6, 0.8]];
    for normal in axes.into_iter().chain(oblique) {
        c.normal = normal;
        c.tangent_hint = normal;
        let (i, j) = c.pair::<f64>();
        let n = Vec3::from(normal);
        let v = j.velocity - i.velocity;
        let along = -v.dot(n);
        let v_t = v + n * along;
        let expected = std::f64::consts::FRAC_1_SQRT_2;
        assert!((along - expected).abs() < 1e-12, "{normal:?}: {along}");
        assert!(
            (v_t.norm_squared().sqrt() - expected).abs() < 1e-12,
            "{normal:?}: {v_t:?}"
        );
    }
}

#[test]
fn arbitrary_bits_reach_every_special_value() {
    let mut runner = TestRunner::deterministic();
    let (mut nan, mut infinite, mut negative_zero, mut subnormal, mut huge) = (0, 0, 0, 0, 0);
    for _ in 0..2000 {
        let x: f32 = any_bits::<f32>().new_tree(&mut runner).unwrap().current();
        nan += usize::from(x.is_nan());
        infinite += usize::from(x.is_infinite());
        negative_zero += usize::from(x == 0.0 && x.is_sign_negative());
        subnormal += usize::from(x.is_subnormal());
        huge += usize::from(x == f32::MAX);
    }
    assert!(
        nan > 20 && infinite > 20 && negative_zero > 20,
        "{nan} {infinite} {negative_zero}"
    );
    assert!(subnormal > 20 && huge > 20, "{subnormal} {huge}");
    // A sphere of arbitrary bits is refused or accepted, never a panic.
    for _ in 0..2000 {
        let s = any_sphere::<f64>().new_tree(&mut runner).unwrap().current();
        let _ = CheckedSphere::new(s);
    }
}
