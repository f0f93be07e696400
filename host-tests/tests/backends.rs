//! The math backends' errors, measured against std's functions over the ranges the laws use:
//! `Libm` agrees with std to the bit for square roots and within an ulp or two elsewhere;
//! `Micromath` is within the bounds its documentation states.

use host_tests::random::Xorshift;
use soft_sphere::prelude::{Libm, MathBackend, Micromath};

/// Largest error of `f` against `exact` over 20,000 log-uniform arguments in `[lo, hi]`:
/// relative to the exact value, or, for functions that pass through zero, absolute.
fn worst_error(
    f: impl Fn(f32) -> f32,
    exact: impl Fn(f64) -> f64,
    (lo, hi): (f64, f64),
    relative: bool,
) -> f64 {
    let mut random = Xorshift::new(11);
    let mut worst: f64 = 0.0;
    for _ in 0..20_000 {
        let x = (lo.ln() + random.unit() * (hi / lo).ln()).exp() as f32;
        let want = exact(f64::from(x));
        let scale = if relative { want.abs() } else { 1.0 };
        worst = worst.max((f64::from(f(x)) - want).abs() / scale);
    }
    worst
}

/// Largest absolute error of an `atan2` against std's over directions all round the circle and
/// lengths over twelve decades.
fn worst_angle(f: impl Fn(f32, f32) -> f32) -> f64 {
    let mut random = Xorshift::new(12);
    let mut worst: f64 = 0.0;
    for _ in 0..20_000 {
        let angle = (random.unit() - 0.5) * 2.0 * std::f64::consts::PI;
        let length = 10f64.powf(random.unit() * 12.0 - 6.0);
        let (y, x) = ((length * angle.sin()) as f32, (length * angle.cos()) as f32);
        let want = f64::from(y).atan2(f64::from(x));
        worst = worst.max((f64::from(f(y, x)) - want).abs());
    }
    worst
}

#[test]
fn micromath_errors_are_within_its_documented_bounds() {
    let range = (1e-12, 1e12);
    let sqrt = worst_error(
        <Micromath as MathBackend<f32>>::sqrt,
        f64::sqrt,
        range,
        true,
    );
    let inv_sqrt = worst_error(
        <Micromath as MathBackend<f32>>::inv_sqrt,
        |x| 1.0 / x.sqrt(),
        range,
        true,
    );
    let atan2 = worst_angle(<Micromath as MathBackend<f32>>::atan2);
    let ln = worst_error(
        <Micromath as MathBackend<f32>>::ln,
        f64::ln,
        (1e-6, 1e6),
        false,
    );
    println!(
        "micromath: sqrt {sqrt:.2e}, 1/sqrt {inv_sqrt:.2e}, atan2 {atan2:.2e} rad, ln {ln:.2e}"
    );
    // The bounds in `Micromath`'s documentation.
    assert!(sqrt < 0.065, "sqrt {sqrt}");
    assert!(inv_sqrt < 0.035, "1/sqrt {inv_sqrt}");
    assert!(atan2 < 0.003, "atan2 {atan2}");
    assert!(ln < 0.12, "ln {ln}");
}

/// `Libm` against std for one precision: square roots the same bits (both are correctly
/// rounded), `1/sqrt` within its documented 1.5 ulp, `atan2` and `ln` within 2 ulp (plus the
/// f64 reference's own rounding).
macro_rules! libm_matches_std {
    ($name:ident, $t:ty) => {
        #[test]
        fn $name() {
            type B = Libm;
            let mut random = Xorshift::new(14);
            let eps = f64::from(<$t>::EPSILON);
            let reference = 2.0 * f64::EPSILON;
            for _ in 0..20_000 {
                let x = (random.unit() * 60.0 - 30.0).exp2() as $t;
                assert_eq!(
                    <B as MathBackend<$t>>::sqrt(x).to_bits(),
                    x.sqrt().to_bits()
                );
                let inv = f64::from(<B as MathBackend<$t>>::inv_sqrt(x));
                let exact = 1.0 / f64::from(x).sqrt();
                assert!(
                    ((inv - exact) / exact).abs() <= 1.5 * eps + reference,
                    "1/sqrt({x})"
                );
                let ln = f64::from(<B as MathBackend<$t>>::ln(x));
                let exact = f64::from(x).ln();
                assert!(
                    (ln - exact).abs() <= (2.0 * eps + reference) * exact.abs().max(1.0),
                    "ln({x})"
                );
                let y = (random.unit() - 0.5) as $t * x;
                let angle = f64::from(<B as MathBackend<$t>>::atan2(y, x));
                let exact = f64::from(y).atan2(f64::from(x));
                assert!(
                    (angle - exact).abs() <= (2.0 * eps + reference) * exact.abs(),
                    "atan2({y}, {x})"
                );
                let angle = f64::from(<B as MathBackend<$t>>::atan2(x, -y));
                let exact = f64::from(x).atan2(-f64::from(y));
                assert!(
                    (angle - exact).abs() <= (2.0 * eps + reference) * exact.abs(),
                    "atan2({x}, {})",
                    -y
                );
            }
        }
    };
}

libm_matches_std!(libm_f32_matches_std, f32);
libm_matches_std!(libm_f64_matches_std, f64);
