//! The kernel's published strategies (`soft_sphere::strategies`) draw what their documents say:
//! each range is checked on every draw, and the arbitrary bit patterns reach the values that
//! break careless code.

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;
use soft_sphere::strategies::{
    any_bits, any_sphere, collision, constant_rolling, elastic_plastic_rolling, grazing_pair,
    hertz, impact, linear_spring_dashpot, mindlin_parameters, sphere, tangential_parameters,
    touching_pair, wall,
};
use soft_sphere::{CheckedSphere, NormalModel};

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
        prop_assert!((w.normal().norm_squared() - 1.0).abs() < 1e-12);
        prop_assert!(within(linear.stiffness(), 10.0, 1e7));
        prop_assert!(within(f64::from(h.effective_modulus()), 1e6, 1e12) && h.critical_time_step(1.0) > 0.0);
        prop_assert!(within(t.stiffness(), 10.0, 1e7) && (0.0..=2.0).contains(&t.friction()));
        prop_assert!(within(m.shear_modulus(), 1e5, 1e11) && (0.0..=1.0).contains(&m.dashpot_ratio()));
        prop_assert!((0.0..=0.5).contains(&c.friction()));
        prop_assert!(within(e.stiffness(), 1e-9, 1.0));
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
