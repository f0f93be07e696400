//! The "off" tangential slot.

use super::{TangentialInput, TangentialModel, TangentialOutput};
use crate::law::normal::NormalContact;
use crate::value::backend::MathBackend;
use crate::value::float::Float;
use crate::value::vector::Vec3;

/// No friction: a zero-sized slot with no state. A law built with it computes neither the slip
/// velocity, nor a tangential force, nor torques.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Frictionless;

impl<F: Float> TangentialModel<F> for Frictionless {
    type State = ();
    const ACTIVE: bool = false;

    #[inline(always)]
    fn force<M: MathBackend<F>>(&self, _: &(), _: &TangentialInput<F>) -> TangentialOutput<F, ()> {
        TangentialOutput {
            force: Vec3::ZERO,
            state: (),
            sliding: false,
        }
    }

    fn critical_time_step(&self, _: &NormalContact<F>, _: F) -> F {
        F::INFINITY
    }
}
