//! What the stored-spring laws of both families share: what a law keeps of its spring after a
//! sliding step ([`Keep`]), a family's step behind one trait ([`StoredSpring`]: the linear
//! spring stores a displacement, Mindlin's a force and the contact radius), and the slot's
//! behaviour built from them (`stored_spring_model!`), so that a law is its struct, its sliding
//! rule and what it keeps.

use super::{Slide, TangentialInput, TangentialOutput};
use crate::law::normal::NormalContact;
use crate::value::backend::MathBackend;
use crate::value::float::Float;
use crate::value::vector::Vec3;

/// What a stored-spring law keeps of its spring after a sliding step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Keep {
    /// All of it: the spring grows without bound (Models A and B).
    Everything,
    /// At most what friction holds: `mu |F_n| / k_t` of displacement, or `mu |F_n|` of
    /// Mindlin's force (Model AA and its Hertz counterpart).
    Capped,
    /// The spring whose force with the dashpot's is the sliding force, `F_t + eta_t v_t`
    /// (Luding 2008).
    Luding,
}

/// A family's stored spring, implemented by its parameters: the step and what the state holds.
pub(crate) trait StoredSpring<F: Float> {
    /// The per-contact state.
    type State;
    /// Whether the step reads the contact radius.
    const NEEDS_CONTACT_RADIUS: bool;

    /// One step: the force and the state to keep. `turned` is the state's
    /// [`stored_vector`](Self::stored_vector) already turned into the current tangent plane
    /// (the list seam turns a chunk's at once), or `None` to turn it here.
    fn step<M: MathBackend<F>>(
        &self,
        state: &Self::State,
        contact: &TangentialInput<F>,
        rule: (Slide, Keep),
        turned: Option<Vec3<F>>,
    ) -> TangentialOutput<F, Self::State>;

    /// The vector the step turns into the current tangent plane.
    fn stored_vector(state: &Self::State) -> Vec3<F>;

    /// The elastic energy the spring holds.
    fn stored_energy(&self, state: &Self::State) -> F;

    /// The largest stable step of the spring on `tangential_mass` at the stiffest contact.
    fn critical_spring_step(&self, design: &NormalContact<F>, tangential_mass: F) -> F;
}

/// The slot's behaviour for a law struct `$name<F>($parameters<F>)` declared beside its
/// invocation, whose state is `$state<F>`.
macro_rules! stored_spring_model {
    ($name:ident($parameters:ident) -> $state:ident, $slide:expr, $keep:expr) => {
        impl<F: Float> TangentialModel<F> for $name<F> {
            type State = $state<F>;
            const NEEDS_CONTACT_RADIUS: bool =
                <$parameters<F> as $crate::law::tangential::stored::StoredSpring<F>>::NEEDS_CONTACT_RADIUS;

            #[inline(always)]
            fn force<M: MathBackend<F>>(
                &self,
                state: &$state<F>,
                contact: &TangentialInput<F>,
            ) -> TangentialOutput<F, $state<F>> {
                $crate::law::tangential::stored::StoredSpring::step::<M>(
                    &self.0,
                    state,
                    contact,
                    ($slide, $keep),
                    None,
                )
            }

            const TURNS: bool = true;

            #[inline(always)]
            fn stored_vector(state: &$state<F>) -> Vec3<F> {
                <$parameters<F> as $crate::law::tangential::stored::StoredSpring<F>>::stored_vector(
                    state,
                )
            }

            #[inline(always)]
            fn force_turned<M: MathBackend<F>>(
                &self,
                state: &$state<F>,
                contact: &TangentialInput<F>,
                turned: Vec3<F>,
            ) -> TangentialOutput<F, $state<F>> {
                $crate::law::tangential::stored::StoredSpring::step::<M>(
                    &self.0,
                    state,
                    contact,
                    ($slide, $keep),
                    Some(turned),
                )
            }

            fn stored_energy(&self, state: &$state<F>) -> F {
                $crate::law::tangential::stored::StoredSpring::stored_energy(&self.0, state)
            }

            fn critical_time_step(&self, design: &NormalContact<F>, tangential_mass: F) -> F {
                $crate::law::tangential::stored::StoredSpring::critical_spring_step(
                    &self.0,
                    design,
                    tangential_mass,
                )
            }
        }
    };
}
pub(crate) use stored_spring_model;
