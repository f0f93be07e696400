//! A time step checked against a law's accuracy limit (or, knowingly, its stability limit only).

use crate::value::float::Float;

/// A time step (s) that a [`ContactLaw`](crate::ContactLaw) has checked: finite, positive and
/// below the law's accuracy limit for the smallest effective mass the caller declared (a
/// [coarse](crate::ContactLaw::coarse_time_step) step: below its explicit-integration stability
/// limit). Made by [`ContactLaw::time_step`](crate::ContactLaw::time_step) (or, from the spheres
/// actually present, by a [`MaterialTable`](crate::MaterialTable)).
///
/// Every contact evaluated with it is checked against the law's accuracy limit: a contact
/// stiffer than the step allows (a lighter pair than the one declared, a
/// [`Hertz`](crate::Hertz) overlap past the declared impact's) is refused with
/// [`ContactError::PastStableStep`](crate::ContactError::PastStableStep), unless the step
/// [tolerates](TimeStep::tolerating_unstable_contacts) such contacts or is coarse and the contact
/// within the stability limit: then it is evaluated and counted
/// ([`BoundLaw::inaccurate_contacts`](crate::BoundLaw::inaccurate_contacts)).
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct TimeStep<F> {
    seconds: F,
    tolerate: bool,
    accurate: bool,
}

impl<F: Float> TimeStep<F> {
    pub(crate) fn checked(seconds: F) -> Self {
        Self {
            seconds,
            tolerate: false,
            accurate: false,
        }
    }

    /// A step checked against the accuracy limit: its contacts are checked against the law's
    /// [`accurate_phase`](crate::ContactLaw::accurate_phase).
    pub(crate) fn accurate(seconds: F) -> Self {
        Self {
            accurate: true,
            ..Self::checked(seconds)
        }
    }

    /// Whether the step was checked for accuracy ([`ContactLaw::time_step`](crate::ContactLaw::time_step)),
    /// so that a contact past the law's [`accurate_phase`](crate::ContactLaw::accurate_phase)
    /// is refused; a coarse step evaluates and counts it while it is within the
    /// [`stable_phase`](crate::ContactLaw::stable_phase).
    #[inline(always)]
    pub fn is_accurate(self) -> bool {
        self.accurate
    }

    /// The step in seconds.
    #[inline(always)]
    pub fn seconds(self) -> F {
        self.seconds
    }

    /// The same step, with contacts past its limits (accuracy, and stability) evaluated instead
    /// of refused: a [`BoundLaw`](crate::BoundLaw) counts them
    /// ([`BoundLaw::inaccurate_contacts`](crate::BoundLaw::inaccurate_contacts)). For studies of
    /// instability, and for engines that report them in their statistics rather than stop.
    pub fn tolerating_unstable_contacts(self) -> Self {
        Self {
            tolerate: true,
            ..self
        }
    }

    /// Whether contacts past the stability limit are evaluated (and counted) instead of refused.
    #[inline(always)]
    pub fn tolerates_unstable_contacts(self) -> bool {
        self.tolerate
    }
}
