//! What a scene pays in memory for each slot: "off" slots are zero-sized, stateless laws keep no
//! per-contact state, and the stored spring is three floats.

use std::mem::size_of;

use soft_sphere::{
    ContactLaw, Frictionless, LinearSpringDashpot, ModelA, ModelAA, ModelB, ModelC, NonRotating,
    Rotating, SpringDisplacement, Stateless, TangentialModel,
};

fn state_size<T: TangentialModel<f64>>() -> usize {
    size_of::<T::State>()
}

#[test]
fn off_slots_and_stateless_laws_cost_no_memory() {
    assert_eq!(size_of::<Frictionless>(), 0);
    assert_eq!(size_of::<Rotating>(), 0);
    assert_eq!(size_of::<NonRotating>(), 0);
    assert_eq!(state_size::<Frictionless>(), 0);
    assert_eq!(state_size::<Stateless<f64>>(), 0);
    assert_eq!(state_size::<ModelC<f64>>(), 0);
    // A frictionless law is its normal slot plus the lever-arm choice, nothing for friction.
    assert_eq!(
        size_of::<ContactLaw<f64, LinearSpringDashpot<f64>, Frictionless>>(),
        size_of::<
            ContactLaw<f64, LinearSpringDashpot<f64>, Frictionless, soft_sphere::Libm, NonRotating>,
        >()
    );
    assert!(
        size_of::<ContactLaw<f64, LinearSpringDashpot<f64>, Frictionless>>()
            <= size_of::<LinearSpringDashpot<f64>>() + 8
    );
}

#[test]
fn stored_spring_laws_keep_three_floats_per_contact() {
    assert_eq!(size_of::<SpringDisplacement<f32>>(), 12);
    assert_eq!(size_of::<SpringDisplacement<f64>>(), 24);
    assert_eq!(state_size::<ModelA<f64>>(), 24);
    assert_eq!(state_size::<ModelB<f64>>(), 24);
    assert_eq!(state_size::<ModelAA<f64>>(), 24);
}
