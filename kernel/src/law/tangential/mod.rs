//! The tangential slot: spring, dashpot and Coulomb slider, in the implementations compared by
//! Elghannay & Tafti (2017). They differ only in what happens when the contact slides
//! (`docs/physics.md`, section 3):
//!
//! | slot | displacement used in the trial force | sliding force | displacement kept |
//! |---|---|---|---|
//! | [`Frictionless`] | none (no tangential work at all) | none | none |
//! | [`Stateless`] | `v_t t_e`, `t_e` the elapsed contact time from the normal oscillator | along the trial force | none |
//! | [`ModelC`] | `v_t dt` (this step only) | against the slip | none |
//! | [`ModelA`] (Cundall & Strack) | stored | along the trial force | grows without bound |
//! | [`ModelB`] (Tsuji et al.) | stored | against the slip | grows without bound |
//! | [`ModelAA`] (Elghannay & Tafti's proper implementation) | stored | along the trial force | limited to `mu |F_n| / k_t` |
//! | [`ModelAALuding`] (Luding 2008) | stored | along the trial force | `-(F_t + eta_t v_t) / k_t` |
//!
//! Under a [`Hertz`](crate::Hertz) normal law the spring is Mindlin's, `k_t = 8 G* a`, stiffening
//! with the contact radius `a`:
//!
//! | slot | spring used in the trial force | sliding force | spring kept |
//! |---|---|---|---|
//! | [`MindlinStateless`] | `-k_t(a) v_t t_e` | along the trial force | none |
//! | [`MindlinAA`] | stored force `F_s`, `+= -k_t(a) v_t dt`, times `a / a_prev` when unloading | along the trial force | limited to `mu |F_n|` |
//! | [`MindlinAALuding`] | as [`MindlinAA`] | along the trial force | `F_t + eta_t v_t` |
//! | [`MicroSlip`] | a bed of springs across the contact, `8 G* dx` each, its profile kept in up to `SPRINGS` breakpoints that follow the slip fronts (Mindlin & Deresiewicz by Popov & Heß's MDR) | along the trial force | each spring's, limited to its share of `mu |F_n|` |
//!
//! Trial force `F* = -k_t xi - eta_t v_t` with `eta_t = r eta_n` (`r` the dashpot ratio); the contact sticks
//! while `|F*| <= mu |F_n|`. Every slot keeps `|F_t| <= mu |F_n|` (to rounding with an exact
//! square root; within the backend's square-root error otherwise).

mod frictionless;
mod history;
mod micro_slip;
mod mindlin;
mod model_c;
mod stateless;
mod stored;

pub use frictionless::Frictionless;
pub(crate) use history::rotate_into_tangent_plane;
pub use history::{ModelA, ModelAA, ModelAALuding, ModelB, SpringDisplacement};
pub use micro_slip::{MicroSlip, MicroSlipSprings};
pub use mindlin::{MindlinAA, MindlinAALuding, MindlinParameters, MindlinSpring, MindlinStateless};
pub use model_c::ModelC;
pub use stateless::Stateless;
pub(crate) use stateless::elapsed_contact_time;

use crate::law::normal::{NormalContact, NormalOscillator};
use crate::value::backend::MathBackend;
use crate::value::error::{Parameter, ParameterError, non_negative, positive};
use crate::value::float::{Float, inverse_root};
use crate::value::vector::Vec3;

/// Per-contact state a tangential slot keeps between steps. `()` for slots that keep none.
pub trait ContactState: Copy + core::fmt::Debug + Default + PartialEq + Send + Sync {
    /// True when every stored number is finite.
    fn is_finite(&self) -> bool;

    /// True when every stored number has the same bits as `other`'s (what "left as it was"
    /// means after a refused evaluation, NaNs included). Defaults to `==`, which is the same for
    /// a state without floats.
    fn same_bits(&self, other: &Self) -> bool {
        self == other
    }
}

impl ContactState for () {
    #[inline(always)]
    fn is_finite(&self) -> bool {
        true
    }
}

/// What a tangential slot sees of one contact at one step.
#[derive(Clone, Copy, Debug, PartialEq)]
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
    /// The contact's normal oscillator at this overlap (gives `eta_n`, and the elapsed-time
    /// estimate).
    pub oscillator: NormalOscillator<F>,
    /// Radius of the contact area (m) for a normal law that has one ([`Hertz`](crate::Hertz)),
    /// else zero.
    pub contact_radius: F,
    /// The time step.
    pub time_step: F,
}

/// What a tangential slot returns for one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TangentialOutput<F, S> {
    /// Tangential force on body j (the force on i is its negative).
    pub force: Vec3<F>,
    /// The state to keep for the next step (committed only if the whole evaluation succeeds).
    pub state: S,
    /// True when the contact slid this step (the Coulomb limit was active).
    pub sliding: bool,
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

    /// Whether the step turns a stored vector into the current tangent plane
    /// (`rotate_into_tangent_plane`) before using it: then the list seam turns it for a whole
    /// chunk of contacts before evaluating them ([`force_turned`](Self::force_turned)). Only
    /// the kernel reads it.
    #[doc(hidden)]
    const TURNS: bool = false;

    /// The stored vector the step turns ([`TURNS`](Self::TURNS)); zero for a law that turns
    /// none. Only the kernel calls it.
    #[doc(hidden)]
    #[inline(always)]
    fn stored_vector(state: &Self::State) -> Vec3<F> {
        let _ = state;
        Vec3::ZERO
    }

    /// [`force`](Self::force) with `turned` the [`stored_vector`](Self::stored_vector) of the
    /// same state already turned into the tangent plane of the contact's normal by
    /// `rotate_into_tangent_plane` with the same backend: the same bits. Only the kernel calls
    /// it.
    #[doc(hidden)]
    #[inline(always)]
    fn force_turned<M: MathBackend<F>>(
        &self,
        state: &Self::State,
        contact: &TangentialInput<F>,
        turned: Vec3<F>,
    ) -> TangentialOutput<F, Self::State> {
        let _ = turned;
        self.force::<M>(state, contact)
    }

    /// The elastic energy the stored spring of `state` holds (J): `k_t |xi|^2 / 2` for the
    /// stored-displacement laws, `|F_s|^2 / (2 k_t(a))` for the stored Mindlin laws, zero for a
    /// law that stores nothing (its spring's work is not kept, so it counts as dissipated).
    fn stored_energy(&self, state: &Self::State) -> F {
        let _ = state;
        F::ZERO
    }

    /// Whether the law's stiffness grows with the contact radius, so that it needs a normal law
    /// that has one ([`NormalModel::CONTACT_RADIUS`](crate::NormalModel::CONTACT_RADIUS)); a
    /// [`ContactLaw`](crate::ContactLaw) pairing it with one that has none does not compile.
    const NEEDS_CONTACT_RADIUS: bool = false;

    /// Largest stable explicit time step of the tangential mode, for the normal law's stiffest
    /// expected contact ([`NormalModel::design_contact`](crate::NormalModel::design_contact))
    /// and the tangential effective mass (`2/7 m*` for rotating solid spheres, `m*` without
    /// rotation). Infinite when the law adds no stiffness or damping.
    fn critical_time_step(&self, design: &NormalContact<F>, tangential_mass: F) -> F;
}

/// Stiffness, dashpot and friction shared by every frictional slot.
///
/// The Coulomb limit is `mu |F_n|` with the normal force *including* its dashpot (as MFiX does).
/// In an impact the dashpot adds to `F_n` while the spheres approach and pulls while they
/// separate, so with `e < 1` the impulse of the Coulomb limit is larger than rigid-body theory's
/// `mu (1 + e) m v_n`: by 6.7 % at `e = 0.5` (`docs/physics.md`, section 3; the stateless law,
/// which sticks for the first moments of contact, gives 6.3 % at 60 degrees). The stateless law and Model AA
/// therefore match rigid-body theory's gross-sliding branch exactly only near `e = 1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TangentialParameters<F> {
    stiffness: F,
    dashpot_ratio: F,
    friction: F,
}

impl<F: Float> TangentialParameters<F> {
    /// Tangential stiffness `k_t` (N/m), the dashpot ratio `r = eta_t / eta_n` of tangential to
    /// normal dashpot coefficient (MFiX uses 1/2; 0 removes the tangential dashpot) and the
    /// Coulomb coefficient `mu`.
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for any non-finite value, [`ParameterError::NotPositive`]
    /// for `k_t <= 0`, [`ParameterError::Negative`] for a negative dashpot ratio or `mu`.
    pub fn new(stiffness: F, dashpot_ratio: F, friction: F) -> Result<Self, ParameterError> {
        Ok(Self {
            stiffness: positive(stiffness, Parameter::TangentialStiffness)?,
            dashpot_ratio: non_negative(dashpot_ratio, Parameter::DashpotRatio)?,
            friction: non_negative(friction, Parameter::Friction)?,
        })
    }

    /// Tangential stiffness `k_t` (N/m).
    pub fn stiffness(&self) -> F {
        self.stiffness
    }

    /// The dashpot ratio `eta_t / eta_n`.
    pub fn dashpot_ratio(&self) -> F {
        self.dashpot_ratio
    }

    /// Coulomb friction coefficient `mu`.
    pub fn friction(&self) -> F {
        self.friction
    }

    /// `eta_t` for a contact with normal dashpot `eta_n`.
    #[inline(always)]
    pub(crate) fn dashpot(&self, oscillator: &NormalOscillator<F>) -> F {
        self.dashpot_ratio * oscillator.damping_coefficient
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
        spring_critical_step(self.stiffness, self.dashpot(oscillator), mass)
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
        if trial_squared < F::INFINITY {
            return (trial, false);
        }
        // Both squares overflowed and compare equal: compare the lengths scaled down by the
        // trial's largest component instead.
        let largest = largest_component(trial);
        let scaled_limit = limit / largest;
        if (trial * (F::ONE / largest)).norm_squared() <= scaled_limit * scaled_limit {
            return (trial, false);
        }
    }
    let direction = match slide {
        Slide::AgainstSlip if slip.norm_squared() >= F::MIN_POSITIVE => -slip,
        _ => trial,
    };
    let length_squared = direction.norm_squared();
    if length_squared < F::INFINITY {
        return (
            direction * (limit * inverse_root::<F, M>(length_squared)),
            true,
        );
    }
    // A direction too long to square: shrink it by its largest component first (a non-finite
    // one gives a non-finite force, which the evaluation refuses).
    let shrunk = direction * (F::ONE / largest_component(direction));
    (shrunk * (limit * M::inv_sqrt(shrunk.norm_squared())), true)
}

/// The largest magnitude of `v`'s components.
fn largest_component<F: Float>(v: Vec3<F>) -> F {
    v.x.abs().max_of(v.y.abs()).max_of(v.z.abs())
}

/// Stability bound of a tangential spring `stiffness` with dashpot `dashpot` on `mass`.
pub(crate) fn spring_critical_step<F: Float>(stiffness: F, dashpot: F, mass: F) -> F {
    let frequency = F::DefaultBackend::sqrt(stiffness / mass);
    let damping_ratio = dashpot / (F::TWO * mass * frequency);
    crate::law::normal::damped_critical_step(frequency, damping_ratio)
}
