//! What a scene pays in memory for each slot: "off" slots are zero-sized, stateless laws keep no
//! per-contact state, and the stored spring is three floats.

use std::mem::size_of;

use soft_sphere::prelude::{
    ContactLaw, Frictionless, LinearFrictionless, LinearSpringDashpot, ModelA, ModelAA, ModelB,
    ModelC, NonRotating, Rotating, SpringDisplacement, Stateless, TangentialModel,
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
    // A frictionless law is its normal slot plus the lever-arm choice, its stable phase and its
    // two accuracy phases (the step's and the contact's), nothing for friction.
    assert_eq!(
        size_of::<LinearFrictionless<f64>>(),
        size_of::<
            ContactLaw<
                f64,
                LinearSpringDashpot<f64>,
                Frictionless,
                soft_sphere::prelude::Libm,
                NonRotating,
            >,
        >()
    );
    assert!(size_of::<LinearFrictionless<f64>>() <= size_of::<LinearSpringDashpot<f64>>() + 32);
}

#[test]
fn stored_spring_laws_keep_three_floats_per_contact() {
    assert_eq!(size_of::<SpringDisplacement<f32>>(), 12);
    assert_eq!(size_of::<SpringDisplacement<f64>>(), 24);
    // Mindlin's: the spring's force and the contact radius.
    assert_eq!(size_of::<soft_sphere::prelude::MindlinSpring<f32>>(), 16);
    assert_eq!(size_of::<soft_sphere::prelude::MindlinSpring<f64>>(), 32);
    assert_eq!(
        state_size::<soft_sphere::prelude::MindlinStateless<f64>>(),
        0
    );
    assert_eq!(state_size::<ModelA<f64>>(), 24);
    assert_eq!(state_size::<ModelB<f64>>(), 24);
    assert_eq!(state_size::<ModelAA<f64>>(), 24);
}

#[test]
fn a_law_reports_the_slots_it_was_built_with() {
    use soft_sphere::prelude::{LeverArm, TangentialParameters};
    let normal = LinearSpringDashpot::new(1000.0, 0.7).unwrap();
    let tangential = ModelAA(TangentialParameters::new(300.0, 0.4, 0.5).unwrap());
    let law = ContactLaw::new(normal, tangential);
    assert_eq!((law.normal(), law.tangential()), (&normal, &tangential));
    let parameters = tangential.0;
    assert_eq!(
        (
            parameters.stiffness(),
            parameters.dashpot_ratio(),
            parameters.friction()
        ),
        (300.0, 0.4, 0.5)
    );
    // The radius is the lever arm unless the contact plane is asked for.
    assert_eq!(law.lever_arm(), LeverArm::Radius);
    let plane = law.with_lever_arm(LeverArm::ContactPlane);
    assert_eq!(plane.lever_arm(), LeverArm::ContactPlane);
}

#[test]
fn vectors_convert_to_and_from_arrays() {
    use soft_sphere::prelude::Vec3;
    let v = Vec3::new(1.5f64, -2.0, 0.25);
    assert_eq!(v.to_array(), [1.5, -2.0, 0.25]);
    assert_eq!(Vec3::from([1.5, -2.0, 0.25]), v);
    assert_eq!(Vec3::from(v.to_array()), v);
}
