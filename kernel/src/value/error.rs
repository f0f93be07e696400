//! Error values. The kernel never panics on bad input; it returns one of these and leaves every
//! piece of caller state exactly as it was.

use core::fmt;

/// Which constructor argument an error is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Parameter {
    /// Normal spring stiffness `k_n`.
    NormalStiffness,
    /// Tangential spring stiffness `k_t`.
    TangentialStiffness,
    /// Coefficient of restitution `e`.
    Restitution,
    /// The dashpot ratio `eta_t / eta_n` of tangential to normal dashpot coefficient.
    DashpotRatio,
    /// Coulomb friction coefficient `mu`.
    Friction,
    /// A mass or effective mass.
    Mass,
    /// A radius.
    Radius,
    /// A time step.
    TimeStep,
    /// A wall's normal vector or reference point.
    Wall,
    /// An elastic modulus: Young's `E`, or a contact's `E*` or `G*`.
    Modulus,
    /// Poisson's ratio `nu`.
    PoissonRatio,
    /// An impact speed.
    Speed,
    /// The rolling-resistance coefficient `mu_r`.
    RollingFriction,
    /// The rolling stiffness `k_r`.
    RollingStiffness,
    /// The rolling dashpot `eta_r`.
    RollingDamping,
    /// Hertz's dashpot factor `alpha`, when given instead of the restitution.
    DampingFactor,
    /// The smallest moment of inertia a rolling spring is checked for.
    Inertia,
}

/// A parameter rejected by a constructor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParameterError {
    /// The value is NaN or infinite.
    NonFinite(Parameter),
    /// The value must be strictly positive (stiffness, mass, radius, time step) or, for a wall
    /// normal, non-zero.
    NotPositive(Parameter),
    /// The value must be at least zero (friction, dashpot ratio).
    Negative(Parameter),
    /// The coefficient of restitution must lie in `[0, 1]`.
    RestitutionOutOfRange,
    /// Poisson's ratio must lie in `(-1, 0.5]`.
    PoissonRatioOutOfRange,
    /// No damping ratio up to critical gives this rebound ratio with the attraction clipped
    /// ([`LinearSpringDashpot::clamped_with_rebound`](crate::LinearSpringDashpot::clamped_with_rebound)).
    ReboundUnreachable {
        /// The requested rebound ratio.
        rebound: f64,
        /// The lowest a clipped linear dashpot reaches, `exp(-2)`.
        lowest: f64,
    },
    /// The time step is at or past the explicit-integration stability limit of the law for the
    /// smallest effective mass the caller declared. `limit` is that bound in seconds (f64 for
    /// display; the law computed it in its own precision).
    TimeStepUnstable {
        /// The requested step.
        time_step: f64,
        /// The largest stable step for this law and mass.
        limit: f64,
    },
    /// The time step is stable but at or past the law's accuracy limit for the smallest
    /// effective mass the caller declared: a contact could rebound more than 0.02 of its impact
    /// speed off the law's restitution ([`ContactLaw::accurate_phase`](crate::ContactLaw::accurate_phase)).
    /// `limit` is that bound in seconds. [`ContactLaw::time_step`](crate::ContactLaw::time_step),
    /// which checks stability only, takes such a step.
    TimeStepInaccurate {
        /// The requested step.
        time_step: f64,
        /// The largest accurate step for this law and mass.
        limit: f64,
    },
}

impl fmt::Display for ParameterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite(p) => write!(f, "{p:?} is not finite"),
            Self::NotPositive(p) => write!(f, "{p:?} must be positive"),
            Self::Negative(p) => write!(f, "{p:?} must not be negative"),
            Self::RestitutionOutOfRange => write!(f, "restitution must lie in [0, 1]"),
            Self::PoissonRatioOutOfRange => write!(f, "Poisson's ratio must lie in (-1, 0.5]"),
            Self::ReboundUnreachable { rebound, lowest } => write!(
                f,
                "a clipped linear dashpot cannot rebound at {rebound}: the lowest is {lowest}"
            ),
            Self::TimeStepUnstable { time_step, limit } => write!(
                f,
                "time step {time_step:e} s is not below the stability limit {limit:e} s"
            ),
            Self::TimeStepInaccurate { time_step, limit } => write!(
                f,
                "time step {time_step:e} s is not below the accuracy limit {limit:e} s \
                 (contacts could rebound faster than their restitution allows)"
            ),
        }
    }
}

impl core::error::Error for ParameterError {}

/// Why one contact evaluation was rejected. When an evaluation returns an error, the per-contact
/// state and any history store it was given are unchanged.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ContactError {
    /// A position, velocity, angular velocity, radius, mass or wall field is NaN or infinite.
    NonFiniteInput,
    /// A radius is zero or negative.
    NonPositiveRadius,
    /// A mass is zero or negative.
    NonPositiveMass,
    /// The two centres coincide (their squared distance is below the smallest normal float), or
    /// a sphere reaching a cylinder wall is centred on its axis (one wider than the cylinder):
    /// the contact normal is undefined.
    CoincidentCentres,
    /// The inputs were finite but the force, torque or new state overflowed.
    NonFiniteResult,
    /// A new contact needs room in a [`ContactHistory`](crate::ContactHistory) that is full.
    HistoryFull,
    /// The contact is stiffer than its time step was checked for: a pair lighter than the mass
    /// the step was checked against, or a [`Hertz`](crate::Hertz) overlap past the one of the
    /// declared impact. Explicit integration of it would be unstable and could create energy
    /// (for a step made by [`ContactLaw::time_step`](crate::ContactLaw::time_step): it
    /// is past the law's accuracy limit, and could rebound faster than its restitution allows).
    /// (A step that [tolerates](crate::TimeStep::tolerating_unstable_contacts) such contacts
    /// evaluates and counts them instead.)
    PastStableStep,
}

impl fmt::Display for ContactError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match self {
            Self::NonFiniteInput => "an input is NaN or infinite",
            Self::NonPositiveRadius => "a radius is zero or negative",
            Self::NonPositiveMass => "a mass is zero or negative",
            Self::CoincidentCentres => {
                "the sphere centres coincide (or a sphere is centred on a cylinder wall's axis)"
            }
            Self::NonFiniteResult => "the contact force overflowed",
            Self::HistoryFull => "the contact-history store is full",
            Self::PastStableStep => {
                "the contact is stiffer than its time step was checked for (unstable or, for an accurate step, inaccurate)"
            }
        };
        f.write_str(text)
    }
}

impl core::error::Error for ContactError {}

/// Checks a value that must be finite and strictly positive.
pub(crate) fn positive<F: crate::Float>(value: F, what: Parameter) -> Result<F, ParameterError> {
    if !value.is_finite() {
        Err(ParameterError::NonFinite(what))
    } else if value > F::ZERO {
        Ok(value)
    } else {
        Err(ParameterError::NotPositive(what))
    }
}

/// Checks a value that must be finite and at least zero.
pub(crate) fn non_negative<F: crate::Float>(
    value: F,
    what: Parameter,
) -> Result<F, ParameterError> {
    if !value.is_finite() {
        Err(ParameterError::NonFinite(what))
    } else if value >= F::ZERO {
        Ok(value)
    } else {
        Err(ParameterError::Negative(what))
    }
}
