//! Model C: the literal stateless reading of the spring-dashpot-slider.

use super::{Slide, TangentialInput, TangentialModel, TangentialOutput, TangentialParameters};
use crate::law::normal::NormalContact;
use crate::value::backend::MathBackend;
use crate::value::float::Float;

/// Model C: the spring sees only this step's displacement, `xi = v_t dt`, and a sliding contact
/// pushes against the slip. Nothing is stored.
///
/// This is a dashpot whose strength, `k_t dt + eta_t`, depends on the time step: the results
/// change with `dt` by construction. It is here so that failure can be shown, not for use.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelC<F>(pub TangentialParameters<F>);

impl<F: Float> TangentialModel<F> for ModelC<F> {
    type State = ();

    #[inline(always)]
    fn force<M: MathBackend<F>>(
        &self,
        _: &(),
        contact: &TangentialInput<F>,
    ) -> TangentialOutput<F, ()> {
        let displacement = contact.slip_velocity * contact.time_step;
        let (force, sliding) = self.0.slide::<M>(displacement, contact, Slide::AgainstSlip);
        TangentialOutput {
            force,
            state: (),
            sliding,
        }
    }

    /// For this law the bound depends on the step itself (`c = k_t dt + eta_t`); the returned value
    /// is the root of `k_t dt^2 + eta_t dt = 2 m_t`, the largest step for which the explicit update of
    /// a sticking contact does not overshoot.
    fn critical_time_step(&self, design: &NormalContact<F>, tangential_mass: F) -> F {
        let oscillator = &design.oscillator;
        let stiffness = self.0.stiffness();
        let dashpot = self.0.dashpot(oscillator);
        let discriminant = dashpot * dashpot + F::from_f64(8.0) * stiffness * tangential_mass;
        // The rationalised root, free of cancellation when the dashpot dominates.
        F::from_f64(4.0) * tangential_mass / (dashpot + F::DefaultBackend::sqrt(discriminant))
    }
}
