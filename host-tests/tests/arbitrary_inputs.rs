//! The kernel's `Arbitrary` inputs (feature `arbitrary`), as a cargo-fuzz target would use them,
//! run on stable over deterministic bytes: every sphere and state a fuzzer can build gives a
//! finite contact within Coulomb's limit, or an error that leaves the state as it was.

use arbitrary::{Arbitrary, Unstructured};
use host_tests::random::Xorshift;
use soft_sphere::checks;
use soft_sphere::prelude::{
    ContactLaw, ContactState, Hertz, HertzImpact, Interaction, LinearSpringDashpot, MicroSlip,
    MicroSlipSprings, MindlinParameters, ModelAA, Sphere, SpringDisplacement, TangentialParameters,
    Wall, WallShape,
};

/// Bytes for one case: either raw (any bit pattern) or the little-endian bytes of ordinary
/// numbers laid out as two spheres and a state read them (millimetre spheres within a millimetre
/// of each other, m/s velocities, micrometre displacements), which touch often.
fn bytes(random: &mut Xorshift, physical: bool) -> Vec<u8> {
    let mut out = Vec::new();
    for k in 0..64 {
        let mut u = || random.unit() - 0.5;
        let x = if physical {
            match k {
                // Each sphere: position, velocity, spin, radius, mass.
                0..=2 | 11..=13 => 1e-3 * u(),
                3..=5 | 14..=16 => u(),
                6..=8 | 17..=19 => 100.0 * u(),
                9 | 20 => 1e-3 * (1.5 + u()),
                10 | 21 => 1e-5 * (1.5 + u()),
                // The state.
                _ => 1e-6 * u(),
            }
        } else {
            f64::from_bits(((u() + 0.5) * 2f64.powi(64)) as u64)
        };
        out.extend_from_slice(&x.to_le_bytes());
    }
    out
}

/// Evaluates `law` on arbitrary spheres and state; returns whether they touched.
fn case<L, S>(
    law: &L,
    friction: f64,
    data: &[u8],
    evaluate: impl Fn(
        &L,
        &Sphere<f64>,
        &Sphere<f64>,
        &mut S,
    ) -> Result<Interaction<f64>, soft_sphere::prelude::ContactError>,
) -> bool
where
    S: ContactState + for<'a> Arbitrary<'a>,
{
    let mut u = Unstructured::new(data);
    let (Ok(a), Ok(b), Ok(before)) = (
        Sphere::<f64>::arbitrary(&mut u),
        Sphere::<f64>::arbitrary(&mut u),
        S::arbitrary(&mut u),
    ) else {
        return false;
    };
    let mut state = before;
    match evaluate(law, &a, &b, &mut state) {
        Ok(Interaction::Touching(f)) => {
            assert_eq!(checks::finite(&f), Ok(()));
            assert_eq!(
                checks::coulomb(&f, friction),
                Ok(()),
                "{a:?} {b:?} {before:?}"
            );
            true
        }
        Ok(Interaction::Apart) => {
            assert_eq!(state, S::default());
            false
        }
        Err(_) => {
            assert_eq!(checks::state_unchanged(&before, &state), Ok(()));
            false
        }
    }
}

#[test]
fn arbitrary_spheres_and_states_give_a_contact_or_an_error() {
    let linear = ContactLaw::new(
        LinearSpringDashpot::new(1000.0, 0.9).unwrap(),
        ModelAA(TangentialParameters::new(860.0, 0.5, 0.3).unwrap()),
    );
    let largest = HertzImpact {
        speed: 5.0,
        effective_radius: 1e-3,
    };
    let hertz = Hertz::new(1e8, 0.7, largest).unwrap();
    let micro = ContactLaw::new(
        hertz,
        MicroSlip::<f64, 4>::new(MindlinParameters::new(4e7, 0.5, 0.3).unwrap()),
    );
    let dt_linear = linear
        .coarse_time_step(1e-6, 1e-9)
        .unwrap()
        .tolerating_unstable_contacts();
    let dt_micro = micro
        .coarse_time_step(1e-8, 1e-9)
        .unwrap()
        .tolerating_unstable_contacts();
    let mut random = Xorshift::new(11);
    let (mut touched_linear, mut touched_micro) = (0, 0);
    for k in 0..20_000 {
        let data = bytes(&mut random, k % 2 == 0);
        touched_linear += usize::from(case(
            &linear,
            0.3,
            &data,
            |l, a, b, s: &mut SpringDisplacement<f64>| l.sphere_sphere(a, b, s, dt_linear),
        ));
        touched_micro += usize::from(case(
            &micro,
            0.3,
            &data,
            |l, a, b, s: &mut MicroSlipSprings<f64, 4>| l.sphere_sphere(a, b, s, dt_micro),
        ));
    }
    assert!(
        touched_linear > 200 && touched_micro > 200,
        "{touched_linear} {touched_micro}"
    );
}

#[test]
fn arbitrary_walls_and_laws_are_valid_or_skipped() {
    let mut random = Xorshift::new(5);
    let (mut walls, mut laws, mut cylinders) = (0, 0, 0);
    for k in 0..5_000 {
        let data = bytes(&mut random, k % 2 == 0);
        let mut u = Unstructured::new(&data);
        if let Ok(w) = Wall::<f64>::arbitrary(&mut u) {
            assert!((w.direction().norm_squared() - 1.0).abs() < 1e-12 && w.velocity().is_finite());
            assert!(w.spin().is_finite() && w.point().is_finite());
            if let WallShape::Cylinder { radius } = w.shape() {
                assert!(radius > 0.0 && radius.is_finite());
                cylinders += 1;
            }
            walls += 1;
        }
        let mut u = Unstructured::new(&data);
        if let Ok(t) = TangentialParameters::<f32>::arbitrary(&mut u) {
            assert!(t.stiffness() > 0.0 && t.friction() >= 0.0 && t.dashpot_ratio() >= 0.0);
            laws += 1;
        }
    }
    assert!(
        walls > 100 && laws > 100 && cylinders > 20,
        "{walls} {laws} {cylinders}"
    );
}

/// The states take the fuzzer's bytes field by field, in declaration order, so a target can aim
/// at any stored number.
#[test]
fn states_are_read_field_by_field() {
    use soft_sphere::prelude::{MindlinSpring, RollingSpring, Vec3};
    let values: Vec<f64> = (1..=16).map(|k| k as f64 * 0.5).collect();
    let bytes: Vec<u8> = values.iter().flat_map(|x| x.to_le_bytes()).collect();
    let read = |k: usize| Vec3::new(values[k], values[k + 1], values[k + 2]);
    let mut u = Unstructured::new(&bytes);
    let s = SpringDisplacement::<f64>::arbitrary(&mut u).unwrap();
    assert_eq!(s.displacement, read(0));
    let mut u = Unstructured::new(&bytes);
    let m = MindlinSpring::<f64>::arbitrary(&mut u).unwrap();
    assert_eq!((m.force, m.contact_radius), (read(0), values[3]));
    let mut u = Unstructured::new(&bytes);
    let springs = MicroSlipSprings::<f64, 2>::arbitrary(&mut u).unwrap();
    assert_eq!(
        (springs.normal, springs.contact_radius),
        (read(0), values[3])
    );
    assert_eq!(springs.positions, [values[4], values[5]]);
    assert_eq!(springs.displacements, [read(6), read(9)]);
    let mut u = Unstructured::new(&bytes);
    let rolled = RollingSpring::<SpringDisplacement<f64>, f64>::arbitrary(&mut u).unwrap();
    assert_eq!(
        (rolled.tangential.displacement, rolled.torque),
        (read(0), read(3))
    );
}
