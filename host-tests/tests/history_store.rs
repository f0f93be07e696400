//! The fixed-capacity contact-history store: insert on first touch, update, drop when contact
//! ends, a full store as an error value with nothing lost, and the same bits whatever the order
//! contacts were inserted in.

use soft_sphere::prelude::{
    ContactError, ContactHistory, ContactKey, ContactLaw, Interaction, LinearAA,
    LinearSpringDashpot, ModelAA, Sphere, SpringDisplacement, TangentialParameters, TimeStep, Vec3,
};

type Linear = LinearAA<f64>;
type Store<const N: usize> = ContactHistory<SpringDisplacement<f64>, N>;

fn law() -> Linear {
    let normal = LinearSpringDashpot::new(1.0e4, 0.8).unwrap();
    ContactLaw::new(
        normal,
        ModelAA(TangentialParameters::new(3.0e3, 0.5, 0.4).unwrap()),
    )
}

fn dt(law: &Linear) -> TimeStep<f64> {
    law.time_step(1e-6, 1e-6).unwrap()
}

/// Sphere `k` of a row in which neighbours 1.9 mm apart touch; each slides sideways at its own speed.
fn sphere(k: u32) -> Sphere<f64> {
    let mut s = Sphere::solid(Vec3::new(1.9e-3 * k as f64, 0.0, 0.0), 1.0e-3, 2500.0);
    s.velocity = Vec3::new(0.0, 0.01 * k as f64, 0.0);
    s
}

fn step<const N: usize>(
    store: &mut Store<N>,
    law: &Linear,
    i: u32,
    j: u32,
) -> Result<Interaction<f64>, ContactError> {
    let (a, b) = (sphere(i), sphere(j));
    store.evaluate(ContactKey::new(i, j), |state| {
        law.sphere_sphere(&a, &b, state, dt(law))
    })
}

fn snapshot<const N: usize>(store: &Store<N>) -> Vec<(ContactKey, [u64; 3])> {
    let mut all: Vec<_> = store
        .iter()
        .map(|(k, s)| (k, s.displacement.to_array().map(f64::to_bits)))
        .collect();
    all.sort_by_key(|(k, _)| *k);
    all
}

#[test]
fn contacts_are_inserted_updated_and_dropped() {
    let law = law();
    let mut store = Store::<8>::new();
    assert!(store.is_empty());
    assert!(step(&mut store, &law, 0, 1).unwrap().forces().is_some());
    assert_eq!(store.len(), 1);
    assert!(!store.is_empty() && !store.is_full());
    let first = *store.get(ContactKey::new(0, 1)).unwrap();
    assert_ne!(
        first.displacement,
        Vec3::ZERO,
        "the spring stretched by the slip"
    );
    step(&mut store, &law, 0, 1).unwrap();
    let second = *store.get(ContactKey::new(0, 1)).unwrap();
    assert!(second.displacement.norm_squared() > first.displacement.norm_squared());
    assert_eq!(store.len(), 1);

    // A pair that does not touch is never stored.
    assert_eq!(step(&mut store, &law, 0, 2), Ok(Interaction::Apart));
    assert_eq!(store.len(), 1);

    // The contact ends: its state goes.
    let (a, mut b) = (sphere(0), sphere(1));
    b.position.x = 3.0e-3;
    let apart = store.evaluate(ContactKey::new(0, 1), |state| {
        law.sphere_sphere(&a, &b, state, dt(&law))
    });
    assert_eq!(apart, Ok(Interaction::Apart));
    assert!(store.get(ContactKey::new(0, 1)).is_none());
    assert!(store.is_empty());
}

#[test]
fn a_full_store_reports_it_and_loses_nothing() {
    let law = law();
    let mut store = Store::<4>::new();
    for k in 0..4 {
        assert!(!store.is_full(), "{k} of 4 stored");
        step(&mut store, &law, k, k + 1).unwrap();
    }
    assert!(store.is_full());
    assert_eq!(store.capacity(), 4);
    let before = snapshot(&store);

    assert_eq!(step(&mut store, &law, 4, 5), Err(ContactError::HistoryFull));
    assert_eq!(snapshot(&store), before, "a refused insert changes nothing");
    // Pairs that do not touch need no slot, so a full store does not refuse them.
    assert_eq!(step(&mut store, &law, 0, 7), Ok(Interaction::Apart));
    // Stored contacts still update while the store is full.
    step(&mut store, &law, 2, 3).unwrap();
    assert_ne!(snapshot(&store), before);
    // Removing one makes room.
    assert!(store.remove(ContactKey::new(0, 1)).is_some());
    assert!(step(&mut store, &law, 4, 5).unwrap().forces().is_some());
    assert_eq!(store.len(), 4);
}

#[test]
fn a_rejected_evaluation_leaves_the_store_unchanged() {
    let law = law();
    let mut store = Store::<4>::new();
    step(&mut store, &law, 0, 1).unwrap();
    step(&mut store, &law, 1, 2).unwrap();
    let before = snapshot(&store);
    let (mut a, b) = (sphere(0), sphere(1));
    a.velocity.x = f64::NAN;
    let result = store.evaluate(ContactKey::new(0, 1), |state| {
        law.sphere_sphere(&a, &b, state, dt(&law))
    });
    assert_eq!(result, Err(ContactError::NonFiniteInput));
    let c = Sphere {
        radius: -1.0,
        ..sphere(7)
    };
    let result = store.evaluate(ContactKey::new(7, 8), |state| {
        law.sphere_sphere(&c, &sphere(8), state, dt(&law))
    });
    assert_eq!(result, Err(ContactError::NonPositiveRadius));
    assert_eq!(snapshot(&store), before);
}

#[test]
fn stored_and_caller_owned_states_give_the_same_bits_in_any_insertion_order() {
    let law = law();
    let pairs: Vec<(u32, u32)> = (0..6).map(|k| (k, k + 1)).collect();
    let mut forward = Store::<8>::new();
    let mut backward = Store::<8>::new();
    let mut owned = vec![SpringDisplacement::default(); pairs.len()];
    for round in 0..20 {
        for (n, &(i, j)) in pairs.iter().enumerate() {
            let a = step(&mut forward, &law, i, j).unwrap();
            let b = law
                .sphere_sphere(&sphere(i), &sphere(j), &mut owned[n], dt(&law))
                .unwrap();
            assert_eq!(
                a, b,
                "round {round}: the store computes what the caller-owned state does"
            );
        }
        for &(i, j) in pairs.iter().rev() {
            step(&mut backward, &law, i, j).unwrap();
        }
        assert_eq!(snapshot(&forward), snapshot(&backward), "round {round}");
        let owned_bits: Vec<_> = pairs
            .iter()
            .zip(&owned)
            .map(|(&(i, j), s)| {
                (
                    ContactKey::new(i, j),
                    s.displacement.to_array().map(f64::to_bits),
                )
            })
            .collect();
        assert_eq!(snapshot(&forward), owned_bits);
    }
}

#[test]
fn retain_and_clear_drop_contacts() {
    let law = law();
    let mut store = Store::<8>::new();
    for k in 0..5 {
        step(&mut store, &law, k, k + 1).unwrap();
    }
    store.retain(|key, _| key.i % 2 == 0);
    let mut kept: Vec<u32> = store.iter().map(|(key, _)| key.i).collect();
    kept.sort();
    assert_eq!(kept, vec![0, 2, 4]);
    store.clear();
    assert!(store.is_empty());
}
