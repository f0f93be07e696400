//! The kernel's guarantees as checks, for an engine author's own property tests and fuzz
//! targets: each answers `Ok(())` or the [`Violation`] it found, with the tolerance the kernel's
//! own tests hold it to. They allocate nothing and work in `no_std`.
//!
//! ```
//! use soft_sphere::checks;
//! use soft_sphere::prelude::{ContactLaw, Interaction, LinearSpringDashpot, ModelAA, Sphere};
//! use soft_sphere::prelude::{SpringDisplacement, TangentialParameters, Vec3};
//!
//! let law = ContactLaw::new(
//!     LinearSpringDashpot::new(1000.0_f64, 0.9).unwrap(),
//!     ModelAA(TangentialParameters::new(860.0, 0.5, 0.3).unwrap()),
//! );
//! let mut a = Sphere::solid(Vec3::ZERO, 1e-3, 2500.0);
//! let b = Sphere::solid(Vec3::new(1.9e-3, 0.0, 0.0), 1e-3, 2500.0);
//! a.velocity = Vec3::new(0.0, 0.3, 0.0);
//! let dt = law.time_step(1e-6, a.mass / 2.0).unwrap();
//! let (mut ij, mut ji) = (SpringDisplacement::default(), SpringDisplacement::default());
//! let one = law.sphere_sphere(&a, &b, &mut ij, dt).unwrap();
//! let two = law.sphere_sphere(&b, &a, &mut ji, dt).unwrap();
//! if let (Interaction::Touching(x), Interaction::Touching(y)) = (one, two) {
//!     checks::coulomb(&x, 0.3).unwrap();
//!     checks::action_reaction(&x, &y).unwrap();
//! }
//! ```

use crate::law::tangential::ContactState;
use crate::value::body::Sphere;
use crate::value::float::Float;
use crate::value::forces::ContactForces;
use crate::value::vector::Vec3;

/// Units of rounding by which `|F_t|` may exceed `mu |F_n|` with an exact square root ([`Libm`](crate::Libm),
/// `Std`): the kernel's Coulomb property holds every law to it.
pub const COULOMB_ULPS: f64 = 64.0;

/// Relative tolerance of [`coulomb_within`] for a law on [`Micromath`](crate::Micromath):
/// its reciprocal square root is within 3.5 %.
pub const MICROMATH_COULOMB_TOLERANCE: f64 = 0.035;

/// How much a closed binary impact's kinetic energy may grow, relative, at the recommended step
/// of a law that creates none: symplectic Euler's error at `t_c/50`. f32 adds `1000` units of
/// rounding for the positions ([`no_energy_created`]).
pub const IMPACT_ENERGY_TOLERANCE: f64 = 1e-3;

/// What a check found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Violation {
    /// `|F_t|` is above `mu |F_n|` by more than the tolerance.
    Coulomb {
        /// `|F_t|` (N).
        tangential: f64,
        /// `mu |F_n|` (N).
        limit: f64,
    },
    /// Swapping the bodies did not negate the force or swap the torques.
    ActionReaction,
    /// A closed impact left more kinetic energy than it found, beyond the tolerance.
    EnergyCreated {
        /// Kinetic energy before (J).
        before: f64,
        /// Kinetic energy after (J).
        after: f64,
    },
    /// A refused evaluation changed the state it was given.
    StateChanged,
    /// A force or torque left the kernel not finite.
    NonFinite,
}

impl core::fmt::Display for Violation {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Coulomb { tangential, limit } => {
                write!(f, "|F_t| = {tangential:e} N exceeds mu |F_n| = {limit:e} N")
            }
            Self::ActionReaction => f.write_str("swapping i and j did not give the reaction"),
            Self::EnergyCreated { before, after } => {
                write!(f, "kinetic energy grew from {before:e} J to {after:e} J")
            }
            Self::StateChanged => f.write_str("a refused evaluation changed the state"),
            Self::NonFinite => f.write_str("a force or torque is not finite"),
        }
    }
}

impl core::error::Error for Violation {}

/// `|F_t| <= mu |F_n|` to [`COULOMB_ULPS`] units of rounding of `F`.
///
/// # Errors
/// [`Violation::Coulomb`] when it is exceeded, [`Violation::NonFinite`] for a non-finite force.
pub fn coulomb<F: Float>(forces: &ContactForces<F>, friction: F) -> Result<(), Violation> {
    coulomb_within(forces, friction, COULOMB_ULPS * F::EPSILON.to_f64())
}

/// `|F_t| <= mu |F_n| (1 + relative)`.
///
/// # Errors
/// As [`coulomb`].
pub fn coulomb_within<F: Float>(
    forces: &ContactForces<F>,
    friction: F,
    relative: f64,
) -> Result<(), Violation> {
    finite(forces)?;
    let t = forces.tangential_force.map_to_f64();
    // |F_t| without overflow: scaled by its largest component.
    let largest = t.x.abs().max(t.y.abs()).max(t.z.abs());
    let tangential = if largest > 0.0 {
        largest * libm::sqrt((t * (1.0 / largest)).norm_squared())
    } else {
        0.0
    };
    let limit = friction.to_f64() * forces.normal_force.to_f64().abs();
    if tangential <= limit * (1.0 + relative) {
        Ok(())
    } else {
        Err(Violation::Coulomb { tangential, limit })
    }
}

/// The contact evaluated as `(i, j)` and as `(j, i)` gives the reaction: the force on i of one
/// is the force on j of the other, and the torques swap, to the bit (a zero may change sign).
///
/// # Errors
/// [`Violation::ActionReaction`], or [`Violation::NonFinite`].
pub fn action_reaction<F: Float>(
    ij: &ContactForces<F>,
    ji: &ContactForces<F>,
) -> Result<(), Violation> {
    finite(ij)?;
    finite(ji)?;
    // `==` on the values: equal bits but for the sign of a zero.
    if ij.force_on_i() == ji.force_on_j()
        && ij.torque_on_i == ji.torque_on_j
        && ij.torque_on_j == ji.torque_on_i
    {
        Ok(())
    } else {
        Err(Violation::ActionReaction)
    }
}

/// Every force and torque finite.
///
/// # Errors
/// [`Violation::NonFinite`].
pub fn finite<F: Float>(forces: &ContactForces<F>) -> Result<(), Violation> {
    if forces.is_finite() {
        Ok(())
    } else {
        Err(Violation::NonFinite)
    }
}

/// Kinetic energy of a solid sphere (J): `m |v|^2 / 2 + (2/5) m R^2 |w|^2 / 2`, in `f64`.
pub fn kinetic_energy<F: Float>(sphere: &Sphere<F>) -> f64 {
    let (m, r) = (sphere.mass.to_f64(), sphere.radius.to_f64());
    let v = sphere.velocity.map_to_f64().norm_squared();
    let w = sphere.angular_velocity.map_to_f64().norm_squared();
    0.5 * m * v + 0.2 * m * r * r * w
}

/// A closed impact created no kinetic energy: `after <= before (1 + tolerance)`, the tolerance
/// [`IMPACT_ENERGY_TOLERANCE`] plus `1000` units of rounding of `F`.
///
/// # Errors
/// [`Violation::EnergyCreated`] (also for a non-finite energy).
pub fn no_energy_created<F: Float>(before: f64, after: f64) -> Result<(), Violation> {
    let tolerance = IMPACT_ENERGY_TOLERANCE + 1000.0 * F::EPSILON.to_f64();
    if after <= before * (1.0 + tolerance) {
        Ok(())
    } else {
        Err(Violation::EnergyCreated { before, after })
    }
}

/// The state after a refused evaluation is the state before, to the bit.
///
/// # Errors
/// [`Violation::StateChanged`].
pub fn state_unchanged<S: ContactState>(before: &S, after: &S) -> Result<(), Violation> {
    if before.same_bits(after) {
        Ok(())
    } else {
        Err(Violation::StateChanged)
    }
}

impl<F: Float> Vec3<F> {
    /// The same vector in `f64`.
    fn map_to_f64(self) -> Vec3<f64> {
        Vec3::new(self.x.to_f64(), self.y.to_f64(), self.z.to_f64())
    }
}
