//! The error, model and parameter codes every entry point speaks, and the kernel's errors
//! mapped onto them.

use soft_sphere::prelude::{ContactError, Parameter, ParameterError};

/// Success.
pub const SS_OK: i32 = 0;
/// A null pointer was passed.
pub const SS_ERR_NULL: i32 = 1;
/// A parameter is not finite.
pub const SS_ERR_NON_FINITE_PARAMETER: i32 = 2;
/// A parameter that must be positive is not.
pub const SS_ERR_NOT_POSITIVE: i32 = 3;
/// A parameter that must not be negative is.
pub const SS_ERR_NEGATIVE: i32 = 4;
/// Restitution outside [0, 1].
pub const SS_ERR_RESTITUTION: i32 = 5;
/// The time step is at or past the law's stability limit.
pub const SS_ERR_UNSTABLE_TIME_STEP: i32 = 6;
/// Unknown model code.
pub const SS_ERR_UNKNOWN_MODEL: i32 = 7;
/// A position, velocity, radius or mass is not finite (or, for the table entries, a force or
/// torque given to be added to).
pub const SS_ERR_NON_FINITE_INPUT: i32 = 8;
/// A radius is not positive.
pub const SS_ERR_NON_POSITIVE_RADIUS: i32 = 9;
/// A mass is not positive.
pub const SS_ERR_NON_POSITIVE_MASS: i32 = 10;
/// The two centres coincide, or a sphere wider than a cylinder wall is centred on its axis.
pub const SS_ERR_COINCIDENT_CENTRES: i32 = 11;
/// The result would not be finite.
pub const SS_ERR_NON_FINITE_RESULT: i32 = 12;
/// The wall normal is zero, or a wall field is not finite.
pub const SS_ERR_BAD_WALL: i32 = 13;
/// Poisson's ratio outside `(-1, 0.5]`.
pub const SS_ERR_POISSON_RATIO: i32 = 14;
/// The contact is stiffer than the time step was checked for (a pair lighter than the declared
/// mass, a Hertz overlap past the declared impact's): explicit integration would be unstable.
pub const SS_ERR_PAST_STABLE_STEP: i32 = 15;
/// The time step is stable but at or past the law's accuracy limit: a contact could rebound
/// more than 0.02 of its impact speed off the law's restitution.
pub const SS_ERR_INACCURATE_TIME_STEP: i32 = 20;
/// A new contact needs room in a full history store. The entries here keep no history store
/// of their own, so none returns it; it is the kernel's error, given its own code.
pub const SS_ERR_HISTORY_FULL: i32 = 22;

// The laws' codes, SS_MODEL_STATELESS to SS_MODEL_HERTZ_MICROSLIP: registry.rs's list.
/// Breakpoints of `SS_MODEL_HERTZ_MICROSLIP`'s displacement profile.
pub const SS_MICROSLIP_SPRINGS: usize = 16;

/// No parameter was rejected.
pub const SS_PARAMETER_NONE: i32 = 0;
/// k_n.
pub const SS_PARAMETER_NORMAL_STIFFNESS: i32 = 1;
/// e.
pub const SS_PARAMETER_RESTITUTION: i32 = 2;
/// k_t.
pub const SS_PARAMETER_TANGENTIAL_STIFFNESS: i32 = 3;
/// eta_t / eta_n.
pub const SS_PARAMETER_DASHPOT_RATIO: i32 = 4;
/// mu.
pub const SS_PARAMETER_FRICTION: i32 = 5;
/// The time step.
pub const SS_PARAMETER_TIME_STEP: i32 = 6;
/// The smallest effective mass.
pub const SS_PARAMETER_MASS: i32 = 7;
/// The model code.
pub const SS_PARAMETER_MODEL: i32 = 8;
/// An elastic modulus (`effective_modulus`, `effective_shear_modulus`, or a material's).
pub const SS_PARAMETER_MODULUS: i32 = 9;
/// A material's Poisson's ratio.
pub const SS_PARAMETER_POISSON_RATIO: i32 = 10;
/// `largest_impact_speed`.
pub const SS_PARAMETER_SPEED: i32 = 11;
/// `largest_effective_radius`.
pub const SS_PARAMETER_RADIUS: i32 = 12;
/// The rolling friction `mu_r`.
pub const SS_PARAMETER_ROLLING_FRICTION: i32 = 13;
/// The rolling stiffness `k_r`.
pub const SS_PARAMETER_ROLLING_STIFFNESS: i32 = 14;
/// The rolling dashpot `eta_r`.
pub const SS_PARAMETER_ROLLING_DAMPING: i32 = 15;
/// A wall's point or normal.
pub const SS_PARAMETER_WALL: i32 = 16;
/// Hertz's dashpot factor `alpha`, when given instead of the restitution.
pub const SS_PARAMETER_DAMPING_FACTOR: i32 = 17;
/// The smallest moment of inertia a rolling spring is checked for.
pub const SS_PARAMETER_INERTIA: i32 = 18;

/// Which parameter `error` is about, as an `SS_PARAMETER_*` code.
pub(crate) fn rejected_parameter(error: ParameterError) -> i32 {
    let parameter = match error {
        ParameterError::NonFinite(p)
        | ParameterError::NotPositive(p)
        | ParameterError::Negative(p) => p,
        ParameterError::RestitutionOutOfRange | ParameterError::ReboundUnreachable { .. } => {
            Parameter::Restitution
        }
        ParameterError::TimeStepUnstable { .. } | ParameterError::TimeStepInaccurate { .. } => {
            Parameter::TimeStep
        }
        ParameterError::PoissonRatioOutOfRange => Parameter::PoissonRatio,
    };
    match parameter {
        Parameter::NormalStiffness => SS_PARAMETER_NORMAL_STIFFNESS,
        Parameter::Restitution => SS_PARAMETER_RESTITUTION,
        Parameter::TangentialStiffness => SS_PARAMETER_TANGENTIAL_STIFFNESS,
        Parameter::DashpotRatio => SS_PARAMETER_DASHPOT_RATIO,
        Parameter::Friction => SS_PARAMETER_FRICTION,
        Parameter::TimeStep => SS_PARAMETER_TIME_STEP,
        Parameter::Modulus => SS_PARAMETER_MODULUS,
        Parameter::PoissonRatio => SS_PARAMETER_POISSON_RATIO,
        Parameter::Speed => SS_PARAMETER_SPEED,
        Parameter::Radius => SS_PARAMETER_RADIUS,
        Parameter::RollingFriction => SS_PARAMETER_ROLLING_FRICTION,
        Parameter::RollingStiffness => SS_PARAMETER_ROLLING_STIFFNESS,
        Parameter::RollingDamping => SS_PARAMETER_ROLLING_DAMPING,
        Parameter::Mass => SS_PARAMETER_MASS,
        Parameter::Wall => SS_PARAMETER_WALL,
        Parameter::DampingFactor => SS_PARAMETER_DAMPING_FACTOR,
        Parameter::Inertia => SS_PARAMETER_INERTIA,
    }
}

pub(crate) fn parameter_code(error: ParameterError) -> i32 {
    match error {
        ParameterError::NonFinite(_) => SS_ERR_NON_FINITE_PARAMETER,
        ParameterError::NotPositive(_) => SS_ERR_NOT_POSITIVE,
        ParameterError::Negative(_) => SS_ERR_NEGATIVE,
        ParameterError::RestitutionOutOfRange | ParameterError::ReboundUnreachable { .. } => {
            SS_ERR_RESTITUTION
        }
        ParameterError::TimeStepUnstable { .. } => SS_ERR_UNSTABLE_TIME_STEP,
        ParameterError::TimeStepInaccurate { .. } => SS_ERR_INACCURATE_TIME_STEP,
        ParameterError::PoissonRatioOutOfRange => SS_ERR_POISSON_RATIO,
    }
}

pub(crate) fn contact_code(error: ContactError) -> i32 {
    match error {
        ContactError::NonFiniteInput => SS_ERR_NON_FINITE_INPUT,
        ContactError::NonPositiveRadius => SS_ERR_NON_POSITIVE_RADIUS,
        ContactError::NonPositiveMass => SS_ERR_NON_POSITIVE_MASS,
        ContactError::CoincidentCentres => SS_ERR_COINCIDENT_CENTRES,
        ContactError::PastStableStep => SS_ERR_PAST_STABLE_STEP,
        ContactError::NonFiniteResult => SS_ERR_NON_FINITE_RESULT,
        ContactError::HistoryFull => SS_ERR_HISTORY_FULL,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ss_contact_error_text;

    /// Every error a contact evaluation can return has a code of its own, and a sentence of
    /// its own: a full history store is not reported as an overflow.
    #[test]
    fn each_contact_error_has_its_own_code_and_sentence() {
        let errors = [
            ContactError::NonFiniteInput,
            ContactError::NonPositiveRadius,
            ContactError::NonPositiveMass,
            ContactError::CoincidentCentres,
            ContactError::NonFiniteResult,
            ContactError::HistoryFull,
            ContactError::PastStableStep,
        ];
        let codes: Vec<i32> = errors.iter().map(|&e| contact_code(e)).collect();
        // SAFETY: the texts are static, NUL-terminated.
        let text = |c| unsafe { std::ffi::CStr::from_ptr(ss_contact_error_text(c)) };
        let rejected = text(-1);
        for (error, &code) in errors.iter().zip(&codes) {
            assert_eq!(codes.iter().filter(|&&c| c == code).count(), 1, "{error:?}");
            assert_ne!(text(code), rejected, "{error:?}");
        }
    }
}
