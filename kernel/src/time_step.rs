//! A time step checked against a law's stability limit.

use crate::float::Float;

/// A time step (s) that a [`ContactLaw`](crate::ContactLaw) has checked: finite, positive and
/// below the law's explicit-integration stability limit for the smallest effective mass the
/// caller declared. Made by [`ContactLaw::time_step`](crate::ContactLaw::time_step).
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct TimeStep<F>(F);

impl<F: Float> TimeStep<F> {
    pub(crate) fn checked(seconds: F) -> Self {
        Self(seconds)
    }

    /// The step in seconds.
    #[inline(always)]
    pub fn seconds(self) -> F {
        self.0
    }
}
