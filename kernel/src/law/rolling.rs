//! The rolling-resistance slot: a torque against the relative rolling of two bodies.
//!
//! | slot | torque on i | state |
//! |---|---|---|
//! | [`NoRolling`] (default, zero-sized) | none | none |
//! | [`ConstantRolling`] (Ai et al. 2011, their rolling model A) | `-mu_r R* |F_n| w_r / |w_r|` | none |
//! | [`ElasticPlasticRolling`] (Ai et al. 2011, their rolling model C, "EPSD"; LAMMPS `rolling sds`) | spring `M_k += -k_r w_r dt`, limited to `mu_r R* |F_n|`, plus `-eta_r w_r` below the limit | the spring torque, 3 floats |
//!
//! `w_r` is the rolling part of the relative angular velocity `w_i - w_j`: its component in the
//! tangent plane (the twisting part about the normal is not resisted). Body j receives the
//! opposite torque, so the pair's angular momentum is kept.

use crate::law::normal::damped_critical_step;
use crate::law::tangential::{ContactState, rotate_into_tangent_plane};
use crate::value::backend::MathBackend;
use crate::value::error::{Parameter, ParameterError, non_negative, positive};
use crate::value::float::{Float, inverse_root};
use crate::value::vector::Vec3;

/// What a rolling slot sees of one contact at one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RollingInput<F> {
    /// Unit normal from body i to body j.
    pub normal: Vec3<F>,
    /// Relative angular velocity `w_i - w_j` (rad/s); zero for a non-rotating law.
    pub relative_spin: Vec3<F>,
    /// Normal force on j (N); the limit is `mu_r R* |F_n|`.
    pub normal_force: F,
    /// Effective radius `R*` (m).
    pub effective_radius: F,
    /// The time step (s).
    pub time_step: F,
}

impl<F: Float> RollingInput<F> {
    /// The rolling part of the relative angular velocity: its component in the tangent plane.
    #[inline(always)]
    fn rolling_spin(&self) -> Vec3<F> {
        self.relative_spin - self.normal * self.relative_spin.dot(self.normal)
    }

    #[inline(always)]
    fn limit(&self, friction: F) -> F {
        friction * self.effective_radius * self.normal_force.abs()
    }
}

/// A rolling-resistance law: the last slot of a [`ContactLaw`](crate::ContactLaw).
pub trait RollingModel<F: Float>: Copy + core::fmt::Debug + Send + Sync {
    /// The per-contact state of a law whose tangential slot keeps `S`: `S` itself when this slot
    /// keeps nothing, so a law without rolling resistance keeps exactly its tangential state.
    type State<S: ContactState>: ContactState;

    /// False only for [`NoRolling`]: no rolling torque is computed.
    const ACTIVE: bool = true;

    /// The tangential slot's part of the state.
    fn tangential<S: ContactState>(state: &Self::State<S>) -> &S;

    /// The rolling torque on body i for this step, and the state to keep, with `tangential` the
    /// tangential slot's next state.
    fn resist<M: MathBackend<F>, S: ContactState>(
        &self,
        state: &Self::State<S>,
        tangential: S,
        contact: &RollingInput<F>,
    ) -> (Vec3<F>, Self::State<S>);

    /// Largest stable explicit time step of the rolling mode; infinite when the law adds no
    /// stiffness or damping.
    fn critical_time_step(&self) -> F;

    /// The elastic energy of the rolling spring in `state` (J): `|M_k|^2 / (2 k_r)`, zero for
    /// a slot without one.
    fn stored_energy<S: ContactState>(&self, state: &Self::State<S>) -> F {
        let _ = state;
        F::ZERO
    }
}

/// No rolling resistance: a zero-sized slot with no state and no work.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoRolling;

impl<F: Float> RollingModel<F> for NoRolling {
    type State<S: ContactState> = S;
    const ACTIVE: bool = false;

    #[inline(always)]
    fn tangential<S: ContactState>(state: &S) -> &S {
        state
    }

    #[inline(always)]
    fn resist<M: MathBackend<F>, S: ContactState>(
        &self,
        _: &S,
        tangential: S,
        _: &RollingInput<F>,
    ) -> (Vec3<F>, S) {
        (Vec3::ZERO, tangential)
    }

    fn critical_time_step(&self) -> F {
        F::INFINITY
    }
}

/// A constant torque `mu_r R* |F_n|` against the relative rolling (Ai et al. 2011, their rolling
/// model A). Stores nothing. With no spring it cannot hold a body at rest: at zero rolling speed it flips
/// from one side to the other every step, a chatter of one step's angular impulse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstantRolling<F> {
    friction: F,
}

impl<F: Float> ConstantRolling<F> {
    /// A constant rolling torque with coefficient `mu_r` (dimensionless: the torque is
    /// `mu_r R* |F_n|`).
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] / [`ParameterError::Negative`] for `mu_r`
    /// ([`Parameter::RollingFriction`]).
    pub fn new(friction: F) -> Result<Self, ParameterError> {
        Ok(Self {
            friction: non_negative(friction, Parameter::RollingFriction)?,
        })
    }

    /// The coefficient `mu_r`.
    pub fn friction(&self) -> F {
        self.friction
    }
}

impl<F: Float> RollingModel<F> for ConstantRolling<F> {
    type State<S: ContactState> = S;

    #[inline(always)]
    fn tangential<S: ContactState>(state: &S) -> &S {
        state
    }

    #[inline(always)]
    fn resist<M: MathBackend<F>, S: ContactState>(
        &self,
        _: &S,
        tangential: S,
        contact: &RollingInput<F>,
    ) -> (Vec3<F>, S) {
        let spin = contact.rolling_spin();
        let squared = spin.norm_squared();
        let torque = if squared >= F::MIN_POSITIVE {
            spin * -(contact.limit(self.friction) * M::inv_sqrt(squared))
        } else {
            Vec3::ZERO
        };
        (torque, tangential)
    }

    fn critical_time_step(&self) -> F {
        F::INFINITY
    }
}

/// The elastic-plastic spring-dashpot rolling law (Ai et al. 2011, their rolling model C; LAMMPS
/// `rolling sds`): a rolling spring `M_k += -k_r w_r dt`, limited to `mu_r R* |F_n|` (then it rolls
/// plastically, without the dashpot), and below the limit a dashpot `-eta_r w_r`. Holds a sphere
/// at rest on a slope up to `tan(theta) = mu_r`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElasticPlasticRolling<F> {
    friction: F,
    stiffness: F,
    damping: F,
    smallest_inertia: F,
}

impl<F: Float> ElasticPlasticRolling<F> {
    /// Coefficient `mu_r`, rolling stiffness `k_r` (N m/rad), rolling dashpot `eta_r`
    /// (N m s/rad), and the smallest effective moment of inertia of any contact (kg m^2; for a
    /// solid sphere on a wall `2/5 m R^2`), which the time step is checked for.
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for any non-finite value; [`ParameterError::Negative`] for
    /// a negative `mu_r` or `eta_r`; [`ParameterError::NotPositive`] for `k_r` or the inertia.
    pub fn new(
        friction: F,
        stiffness: F,
        damping: F,
        smallest_inertia: F,
    ) -> Result<Self, ParameterError> {
        Ok(Self {
            friction: non_negative(friction, Parameter::RollingFriction)?,
            stiffness: positive(stiffness, Parameter::RollingStiffness)?,
            damping: non_negative(damping, Parameter::RollingDamping)?,
            smallest_inertia: positive(smallest_inertia, Parameter::Inertia)?,
        })
    }

    /// The coefficient `mu_r`.
    pub fn friction(&self) -> F {
        self.friction
    }

    /// The rolling stiffness `k_r` (N m/rad).
    pub fn stiffness(&self) -> F {
        self.stiffness
    }
}

/// A contact's tangential state with the rolling spring beside it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct RollingSpring<S, F> {
    /// The tangential slot's state.
    pub tangential: S,
    /// The rolling spring's torque on body i (N m), kept in the current tangent plane.
    pub torque: Vec3<F>,
}

impl<S: ContactState, F: Float> ContactState for RollingSpring<S, F> {
    #[inline(always)]
    fn is_finite(&self) -> bool {
        self.tangential.is_finite() && self.torque.is_finite()
    }
    fn same_bits(&self, other: &Self) -> bool {
        self.tangential.same_bits(&other.tangential) && self.torque.same_bits(other.torque)
    }
}

impl<F: Float> RollingModel<F> for ElasticPlasticRolling<F> {
    type State<S: ContactState> = RollingSpring<S, F>;

    #[inline(always)]
    fn tangential<S: ContactState>(state: &RollingSpring<S, F>) -> &S {
        &state.tangential
    }

    #[inline(always)]
    fn resist<M: MathBackend<F>, S: ContactState>(
        &self,
        state: &RollingSpring<S, F>,
        tangential: S,
        contact: &RollingInput<F>,
    ) -> (Vec3<F>, RollingSpring<S, F>) {
        let spin = contact.rolling_spin();
        let rotated = rotate_into_tangent_plane::<F, M>(state.torque, contact.normal);
        let spring = rotated - spin * (self.stiffness * contact.time_step);
        let limit = contact.limit(self.friction);
        let squared = spring.norm_squared();
        let (torque, kept) = if squared > limit * limit {
            let capped = spring * (limit * inverse_root::<F, M>(squared));
            (capped, capped)
        } else {
            (spring - spin * self.damping, spring)
        };
        (
            torque,
            RollingSpring {
                tangential,
                torque: kept,
            },
        )
    }

    fn stored_energy<S: ContactState>(&self, state: &RollingSpring<S, F>) -> F {
        state.torque.norm_squared() / (F::TWO * self.stiffness)
    }

    /// The rolling oscillator `k_r` on the smallest inertia, with its dashpot.
    fn critical_time_step(&self) -> F {
        let inertia = self.smallest_inertia;
        let frequency = F::DefaultBackend::sqrt(self.stiffness / inertia);
        let ratio = self.damping / (F::TWO * inertia * frequency);
        damped_critical_step(frequency, ratio)
    }
}
