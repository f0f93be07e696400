//! The tangential slot: spring, dashpot and Coulomb slider, in the implementations the talk
//! compares. They differ only in what happens when the contact slides:
//!
//! | slot | displacement used in the trial force | sliding force | displacement kept |
//! |---|---|---|---|
//! | [`Frictionless`] | none (no tangential work at all) | none | none |
//! | [`Stateless`] | `v_t t_e`, `t_e` the elapsed contact time from the normal oscillator | along the trial force | none |
//! | [`ModelC`] | `v_t dt` (this step only) | against the slip | none |
//! | [`ModelA`] (Cundall & Strack) | stored | along the trial force | grows without bound |
//! | [`ModelB`] (Tsuji et al.) | stored | against the slip | grows without bound |
//! | [`ModelAA`] (the talk's proper implementation) | stored | along the trial force | limited to `mu |F_n| / k_t` |
//!
//! Trial force `F* = -k_t xi - eta_t v_t` with `eta_t = (eta_t/eta_n) eta_n`; the contact sticks
//! while `|F*| <= mu |F_n|`. Every slot keeps `|F_t| <= mu |F_n|` (to rounding with an exact
//! square root; within the backend's square-root error otherwise).

mod frictionless;
mod history;
mod model_c;
mod stateless;

pub use frictionless::Frictionless;
pub use history::{ModelA, ModelAA, ModelB, SpringDisplacement, rotate_into_tangent_plane};
pub use model_c::ModelC;
pub use stateless::{Stateless, elapsed_contact_time};

use crate::backend::MathBackend;
use crate::error::{Parameter, ParameterError, non_negative, positive};
use crate::float::Float;
use crate::lanes::{LaneVec, Lanes, Mask, lanes};
use crate::normal::NormalOscillator;
use crate::vector::Vec3;

/// Per-contact state a tangential slot keeps between steps. `()` for slots that keep none.
pub trait ContactState: Copy + core::fmt::Debug + Default + PartialEq + Send + Sync {
    /// True when every stored number is finite.
    fn is_finite(&self) -> bool;
}

impl ContactState for () {
    #[inline(always)]
    fn is_finite(&self) -> bool {
        true
    }
}

/// What a tangential slot sees of one contact at one step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TangentialInput<F> {
    /// Unit normal from body i to body j.
    pub normal: Vec3<F>,
    /// Slip velocity of the contact point, j relative to i, in the tangent plane.
    pub slip_velocity: Vec3<F>,
    /// Normal force on j along the normal (positive repulsive); the Coulomb limit is `mu` times its
    /// magnitude.
    pub normal_force: F,
    /// Overlap `delta > 0`.
    pub overlap: F,
    /// Rate of change of the overlap, `-v_n` (positive while approaching).
    pub approach_rate: F,
    /// The contact's normal oscillator (gives `eta_n`, and the elapsed-time estimate).
    pub oscillator: NormalOscillator<F>,
    /// The time step.
    pub time_step: F,
}

/// What a tangential slot returns for one step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TangentialOutput<F, S> {
    /// Tangential force on body j (the force on i is its negative).
    pub force: Vec3<F>,
    /// The state to keep for the next step (committed only if the whole evaluation succeeds).
    pub state: S,
    /// True when the contact slid this step (the Coulomb limit was active).
    pub sliding: bool,
}

/// What a tangential slot sees of `L` contacts at one step, one per lane (the fields of
/// [`TangentialInput`]).
#[derive(Clone, Copy, Debug)]
pub struct TangentialLanes<F: Float, const L: usize> {
    /// Unit normals from body i to body j.
    pub normal: LaneVec<F, L>,
    /// Slip velocities of the contact points, j relative to i, in the tangent planes.
    pub slip_velocity: LaneVec<F, L>,
    /// Normal forces on j along the normals (positive repulsive).
    pub normal_force: Lanes<F, L>,
    /// Overlaps `delta > 0`.
    pub overlap: Lanes<F, L>,
    /// Rates of change of the overlaps, `-v_n`.
    pub approach_rate: Lanes<F, L>,
    /// The contacts' normal oscillators.
    pub oscillator: [NormalOscillator<F>; L],
    /// The time step (the same for every lane).
    pub time_step: F,
}

impl<F: Float, const L: usize> TangentialLanes<F, L> {
    /// Lane `l`'s contact.
    #[inline(always)]
    pub fn lane(&self, l: usize) -> TangentialInput<F> {
        TangentialInput {
            normal: self.normal.lane(l),
            slip_velocity: self.slip_velocity.lane(l),
            normal_force: self.normal_force.0[l],
            overlap: self.overlap.0[l],
            approach_rate: self.approach_rate.0[l],
            oscillator: self.oscillator[l],
            time_step: self.time_step,
        }
    }
}

/// What a tangential slot returns for `L` contacts, one per lane (the fields of
/// [`TangentialOutput`]).
#[derive(Clone, Copy, Debug)]
pub struct TangentialLanesOutput<F: Float, S, const L: usize> {
    /// Tangential forces on body j.
    pub force: LaneVec<F, L>,
    /// The states to keep.
    pub states: [S; L],
    /// Which contacts slid.
    pub sliding: Mask<L>,
}

/// A tangential force law: the second slot of a [`ContactLaw`](crate::ContactLaw).
pub trait TangentialModel<F: Float>: Copy + core::fmt::Debug + Send + Sync {
    /// Per-contact state (`()` when the law stores nothing).
    type State: ContactState;

    /// False only for [`Frictionless`]: the law then skips the slip velocity, the tangential force
    /// and the torques at compile time.
    const ACTIVE: bool = true;

    /// Tangential force for this step, and the state to keep.
    fn force<M: MathBackend<F>>(
        &self,
        state: &Self::State,
        contact: &TangentialInput<F>,
    ) -> TangentialOutput<F, Self::State>;

    /// `L` contacts side by side: lane `l` must be exactly, to the bit, what
    /// [`TangentialModel::force`] gives for `states[l]` and `contacts.lane(l)`. The default runs
    /// `force` lane by lane; the stored-spring laws override it with a form that takes no
    /// branch on the data (see [`crate::lanes`]). A scene evaluates its touching pairs this way.
    #[inline(always)]
    fn force_lanes<M: MathBackend<F>, const L: usize>(
        &self,
        states: &[Self::State; L],
        contacts: &TangentialLanes<F, L>,
    ) -> TangentialLanesOutput<F, Self::State, L> {
        let outputs: [TangentialOutput<F, Self::State>; L] =
            lanes(|l| self.force::<M>(&states[l], &contacts.lane(l)));
        TangentialLanesOutput {
            force: LaneVec::from_fn(|l| outputs[l].force),
            states: lanes(|l| outputs[l].state),
            sliding: lanes(|l| outputs[l].sliding),
        }
    }

    /// Largest stable explicit time step of the tangential mode, for a contact with the given normal
    /// oscillator and tangential effective mass (`2/7 m*` for rotating solid spheres, `m*` without
    /// rotation). Infinite when the law adds no stiffness or damping.
    fn critical_time_step(&self, oscillator: &NormalOscillator<F>, tangential_mass: F) -> F;
}

/// Stiffness, damping and friction shared by every frictional slot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TangentialParameters<F> {
    stiffness: F,
    damping_ratio: F,
    friction: F,
}

impl<F: Float> TangentialParameters<F> {
    /// Tangential stiffness `k_t` (N/m), the ratio `eta_t / eta_n` of tangential to normal damping
    /// (MFiX uses 1/2; 0 removes the tangential dashpot) and the Coulomb coefficient `mu`.
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for any non-finite value, [`ParameterError::NotPositive`]
    /// for `k_t <= 0`, [`ParameterError::Negative`] for a negative damping ratio or `mu`.
    pub fn new(stiffness: F, damping_ratio: F, friction: F) -> Result<Self, ParameterError> {
        Ok(Self {
            stiffness: positive(stiffness, Parameter::TangentialStiffness)?,
            damping_ratio: non_negative(damping_ratio, Parameter::TangentialDampingRatio)?,
            friction: non_negative(friction, Parameter::Friction)?,
        })
    }

    /// Tangential stiffness `k_t` (N/m).
    pub fn stiffness(&self) -> F {
        self.stiffness
    }

    /// `eta_t / eta_n`.
    pub fn damping_ratio(&self) -> F {
        self.damping_ratio
    }

    /// Coulomb friction coefficient `mu`.
    pub fn friction(&self) -> F {
        self.friction
    }

    /// `eta_t` for a contact with normal dashpot `eta_n`.
    #[inline(always)]
    pub(crate) fn dashpot(&self, oscillator: &NormalOscillator<F>) -> F {
        self.damping_ratio * oscillator.damping_coefficient
    }

    /// The Coulomb limit `mu |F_n|`.
    #[inline(always)]
    pub(crate) fn limit(&self, contact: &TangentialInput<F>) -> F {
        self.friction * contact.normal_force.abs()
    }

    /// Trial force `-k_t xi - eta_t v_t`.
    #[inline(always)]
    pub(crate) fn trial_force(
        &self,
        displacement: Vec3<F>,
        contact: &TangentialInput<F>,
    ) -> Vec3<F> {
        -(displacement * self.stiffness) - contact.slip_velocity * self.dashpot(&contact.oscillator)
    }

    /// [`TangentialParameters::limit`] lane by lane.
    #[inline(always)]
    pub(crate) fn limit_lanes<const L: usize>(
        &self,
        contacts: &TangentialLanes<F, L>,
    ) -> Lanes<F, L> {
        Lanes::splat(self.friction) * contacts.normal_force.abs()
    }

    /// [`TangentialParameters::trial_force`] lane by lane.
    #[inline(always)]
    pub(crate) fn trial_force_lanes<const L: usize>(
        &self,
        displacement: LaneVec<F, L>,
        contacts: &TangentialLanes<F, L>,
    ) -> LaneVec<F, L> {
        let dashpot = Lanes::from_fn(|l| self.dashpot(&contacts.oscillator[l]));
        -(displacement * Lanes::splat(self.stiffness)) - contacts.slip_velocity * dashpot
    }

    /// The trial force for `displacement` put through the Coulomb slider: the step every
    /// frictional law shares once it knows its displacement. Returns the force and whether the
    /// contact slid.
    #[inline(always)]
    pub(crate) fn slide<M: MathBackend<F>>(
        &self,
        displacement: Vec3<F>,
        contact: &TangentialInput<F>,
        slide: Slide,
    ) -> (Vec3<F>, bool) {
        let trial = self.trial_force(displacement, contact);
        coulomb::<F, M>(trial, contact.slip_velocity, self.limit(contact), slide)
    }

    /// Stability bound of a tangential spring with this stiffness and dashpot.
    pub(crate) fn spring_critical_step(&self, oscillator: &NormalOscillator<F>, mass: F) -> F {
        let frequency = F::DefaultBackend::sqrt(self.stiffness / mass);
        let damping_ratio = self.dashpot(oscillator) / (F::TWO * mass * frequency);
        crate::normal::damped_critical_step(frequency, damping_ratio)
    }
}

/// Which way a sliding contact's force points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Slide {
    /// Along the trial force (Cundall & Strack; Model AA; the stateless law).
    AlongTrial,
    /// Against the slip velocity (Tsuji et al.; Model C). Falls back to the trial force's direction
    /// when there is no slip, so the force stays bounded.
    AgainstSlip,
}

/// [`coulomb`] lane by lane, without a branch on the data: every lane's sliding force is
/// computed and then chosen, with the same operations, so the same bits.
#[inline(always)]
pub(crate) fn coulomb_lanes<F: Float, M: MathBackend<F>, const L: usize>(
    trial: LaneVec<F, L>,
    slip: LaneVec<F, L>,
    limit: Lanes<F, L>,
    slide: Slide,
) -> (LaneVec<F, L>, Mask<L>) {
    let sticking = trial.norm_squared().less_or_equal(limit * limit);
    let direction = match slide {
        Slide::AgainstSlip => {
            let no_slip = slip.norm_squared().less(Lanes::splat(F::MIN_POSITIVE));
            LaneVec::select(no_slip, trial, -slip)
        }
        Slide::AlongTrial => trial,
    };
    let limited = direction * (limit * direction.norm_squared().map(M::inv_sqrt));
    (
        LaneVec::select(sticking, trial, limited),
        lanes(|l| !sticking[l]),
    )
}

/// The Coulomb slider: the trial force if it is within `limit`, else a force of magnitude `limit`
/// in the direction `slide` says. Returns the force and whether the contact slid.
#[inline(always)]
pub(crate) fn coulomb<F: Float, M: MathBackend<F>>(
    trial: Vec3<F>,
    slip: Vec3<F>,
    limit: F,
    slide: Slide,
) -> (Vec3<F>, bool) {
    let trial_squared = trial.norm_squared();
    if trial_squared <= limit * limit {
        return (trial, false);
    }
    let direction = match slide {
        Slide::AgainstSlip if slip.norm_squared() >= F::MIN_POSITIVE => -slip,
        _ => trial,
    };
    (
        direction * (limit * M::inv_sqrt(direction.norm_squared())),
        true,
    )
}
