//! What an engine calls: any contact law as one type parameter ([`Law`]), bound to its checked
//! time step ([`BoundLaw`]) and evaluated on checked spheres with no repeated checks.

use crate::law::normal::NormalOscillator;
use crate::law::tangential::ContactState;
use crate::value::checked::CheckedSphere;
use crate::value::error::{ContactError, ParameterError};
use crate::value::float::Float;
use crate::value::forces::Interaction;
use crate::value::time_step::TimeStep;
use crate::value::wall::Wall;

pub(crate) mod sealed {
    /// Only the kernel's [`ContactLaw`](crate::ContactLaw) is a [`Law`](super::Law).
    pub trait Sealed {}

    /// Only the kernel can make one: it opens the list seam's hooks, which take a chunk's roots
    /// ahead of its contacts and leave the finiteness test of a contact's results to the seam
    /// (it tests a whole chunk at once and re-runs a failing chunk checked).
    #[derive(Clone, Copy, Debug)]
    pub struct Deferred(pub(crate) ());

    /// Only the kernel can make one: a law's own evaluations take it, so that an engine reaches
    /// them only through [`BoundLaw`](super::BoundLaw), whose calls are the public ones.
    #[derive(Clone, Copy, Debug)]
    pub struct Internal(pub(crate) ());

    pub use crate::law::sifted::{Sifted, Sifts};
}

/// A [`ContactLaw`](crate::ContactLaw), whatever its slots: lets an engine take the law as one
/// type parameter and name its precision and per-contact state (`L::Float`, `L::State`) without
/// knowing which slots it was built from. Sealed.
///
/// ```
/// use soft_sphere::prelude::{CheckedSphere, ContactError, Interaction, Law, TimeStep};
///
/// /// An engine's inner loop over a list of pairs, for any law.
/// fn pair_forces<L: Law>(
///     law: &L,
///     time_step: TimeStep<L::Float>,
///     spheres: &[CheckedSphere<L::Float>],
///     pairs: &[(usize, usize)],
///     states: &mut [L::State],
/// ) -> Result<usize, ContactError> {
///     let mut bound = law.at(time_step);
///     let mut touching = 0;
///     for (&(i, j), state) in pairs.iter().zip(states.iter_mut()) {
///         if let Interaction::Touching(_) = bound.sphere_sphere(&spheres[i], &spheres[j], state)? {
///             touching += 1;
///         }
///     }
///     Ok(touching)
/// }
/// # use soft_sphere::prelude::{ContactLaw, LinearSpringDashpot, ModelAA, Sphere, TangentialParameters, Vec3};
/// # let law = ContactLaw::new(
/// #     LinearSpringDashpot::new(1.0e4_f64, 0.8).unwrap(),
/// #     ModelAA(TangentialParameters::new(3.0e3, 0.5, 0.4).unwrap()),
/// # );
/// # let spheres = [0.0, 1.9e-3, 5.0e-3].map(|x| {
/// #     CheckedSphere::new(Sphere::solid(Vec3::new(x, 0.0, 0.0), 1.0e-3, 2500.0)).unwrap()
/// # });
/// # let dt = law.time_step(1.0e-6, spheres[0].mass / 2.0).unwrap();
/// # let mut states = [Default::default(); 2];
/// # assert_eq!(pair_forces(&law, dt, &spheres, &[(0, 1), (1, 2)], &mut states), Ok(1));
/// ```
pub trait Law: sealed::Sealed + Copy + core::fmt::Debug + Send + Sync + Sized {
    /// The precision, `f32` or `f64`.
    type Float: Float;
    /// The per-contact state the law keeps: `()` for laws that store nothing, a
    /// [`SpringDisplacement`](crate::SpringDisplacement) for the stored-spring laws.
    type State: ContactState;

    /// Checks a time step; see [`ContactLaw::time_step`](crate::ContactLaw::time_step).
    ///
    /// # Errors
    /// As [`ContactLaw::time_step`](crate::ContactLaw::time_step).
    fn time_step(
        &self,
        seconds: Self::Float,
        smallest_effective_mass: Self::Float,
    ) -> Result<TimeStep<Self::Float>, ParameterError>;

    /// Checks a time step for stability only; see
    /// [`ContactLaw::coarse_time_step`](crate::ContactLaw::coarse_time_step).
    ///
    /// # Errors
    /// As [`ContactLaw::coarse_time_step`](crate::ContactLaw::coarse_time_step).
    fn coarse_time_step(
        &self,
        seconds: Self::Float,
        smallest_effective_mass: Self::Float,
    ) -> Result<TimeStep<Self::Float>, ParameterError>;

    /// See [`ContactLaw::recommended_time_step`](crate::ContactLaw::recommended_time_step).
    fn recommended_time_step(&self, effective_mass: Self::Float) -> Self::Float;

    /// `(phi / dt)^2`: the squared normal frequency `w0^2` below which a contact is within
    /// `time_step`'s accuracy limit, `phi` being
    /// [`ContactLaw::accurate_phase`](crate::ContactLaw::accurate_phase). A [`BoundLaw`] derives
    /// it once, so each contact's check is a product and a comparison; only a contact past it
    /// is asked more (refused, or for a coarse or tolerating step evaluated and counted).
    fn allowed_rate_squared(&self, time_step: TimeStep<Self::Float>) -> Self::Float;

    /// See [`ContactLaw::contact_duration`](crate::ContactLaw::contact_duration).
    fn contact_duration(&self, effective_mass: Self::Float) -> Self::Float;

    /// See [`ContactLaw::stored_energy`](crate::ContactLaw::stored_energy).
    fn stored_energy(
        &self,
        overlap: Self::Float,
        effective_radius: Self::Float,
        state: &Self::State,
    ) -> Self::Float;

    /// The law bound to a checked time step; see [`ContactLaw::at`](crate::ContactLaw::at).
    fn at(&self, time_step: TimeStep<Self::Float>) -> BoundLaw<Self> {
        BoundLaw::new(*self, time_step)
    }

    /// What [`BoundLaw::sphere_sphere`] calls: the law's own evaluation, which for
    /// [`ContactLaw`](crate::ContactLaw) lives in `contact_law.rs` beside the one-contact path whose
    /// private core it shares (the bound law is the engine's handle; the physics stays with the
    /// law). Only the kernel can call it.
    ///
    /// # Errors
    /// As [`BoundLaw::sphere_sphere`].
    #[doc(hidden)]
    fn evaluate_pair(
        bound: &mut BoundLaw<Self>,
        i: &CheckedSphere<Self::Float>,
        j: &CheckedSphere<Self::Float>,
        state: &mut Self::State,
        internal: sealed::Internal,
    ) -> Result<Interaction<Self::Float>, ContactError>;

    /// The roots of a sifted chunk's first `found` pairs ([`sealed::Sifts`]), by the law's
    /// backend, taken before any of them is evaluated, in loops whose iterations the processor
    /// overlaps: each pair's `1 / d` and overlap (a loop the compiler widens with the `Std`
    /// backend), and its stored state's (`states[k]`, `k` its index in the chunk)
    /// [stored vector](crate::TangentialModel::stored_vector) turned into its tangent plane.
    /// Only the kernel can call it.
    #[doc(hidden)]
    fn sifted_roots(
        sifts: &mut sealed::Sifts<Self::Float>,
        found: usize,
        states: &[Self::State],
        deferred: sealed::Deferred,
    );

    /// [`Law::evaluate_pair`] on a pair the list seam sifted, its separation and roots given
    /// (the same bits), without the finiteness test of the forces and the new state, which the
    /// caller makes (the list seam, once per chunk); the state is written even when it is not
    /// finite. Only the kernel can call it.
    ///
    /// # Errors
    /// As [`BoundLaw::sphere_sphere`], except [`ContactError::NonFiniteResult`].
    #[doc(hidden)]
    fn evaluate_sifted_deferred(
        bound: &mut BoundLaw<Self>,
        i: &CheckedSphere<Self::Float>,
        j: &CheckedSphere<Self::Float>,
        sifted: &sealed::Sifted<Self::Float>,
        state: &mut Self::State,
        deferred: sealed::Deferred,
    ) -> Result<Interaction<Self::Float>, ContactError>;

    /// What [`BoundLaw::sphere_wall`] calls. Only the kernel can call it.
    ///
    /// # Errors
    /// As [`BoundLaw::sphere_wall`].
    #[doc(hidden)]
    fn evaluate_wall(
        bound: &mut BoundLaw<Self>,
        sphere: &CheckedSphere<Self::Float>,
        wall: &Wall<Self::Float>,
        state: &mut Self::State,
        internal: sealed::Internal,
    ) -> Result<Interaction<Self::Float>, ContactError>;
}

/// A law bound to a checked time step, made by [`ContactLaw::at`](crate::ContactLaw::at): the
/// checked fast path. Its inputs were checked once (the spheres as [`CheckedSphere`]s, walls by
/// construction, the step by [`ContactLaw::time_step`](crate::ContactLaw::time_step)), so each
/// evaluation does only the contact's own work. It remembers the normal oscillator of the last
/// pair of masses it saw (and of the last sphere against a wall), so a scene of one kind of
/// sphere derives it once; a new pair of masses recomputes it, the same bits as the law's own
/// evaluation. It holds a copy of the law (laws are small and `Copy`), so it borrows nothing and
/// can be stored or moved freely. Cheap to make: make one per thread.
#[derive(Clone, Copy, Debug)]
pub struct BoundLaw<L: Law> {
    // The fields are the crate's so that an evaluation can borrow the law and the memos apart.
    pub(crate) law: L,
    pub(crate) time_step: TimeStep<L::Float>,
    /// The step's [`Law::allowed_rate_squared`], derived once.
    pub(crate) allowed: L::Float,
    pub(crate) pair: Memo<[L::Float; 2], PairOscillator<L::Float>>,
    pub(crate) wall: Memo<L::Float, NormalOscillator<L::Float>>,
    pub(crate) unstable: usize,
}

/// A pair of masses' normal oscillator and effective mass.
pub(crate) type PairOscillator<F> = (NormalOscillator<F>, F);

/// The value derived from the last key. Masses are positive, so the zeros an empty memo starts
/// from never match.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Memo<K, V> {
    key: K,
    value: V,
}

impl<K: PartialEq, V> Memo<K, V> {
    /// The value of `key`, derived by `derive` only when it differs from the last key.
    #[inline(always)]
    pub(crate) fn get(&mut self, key: K, derive: impl FnOnce(&K) -> V) -> &V {
        if key != self.key {
            self.value = derive(&key);
            self.key = key;
        }
        &self.value
    }
}

impl<L: Law> BoundLaw<L> {
    pub(crate) fn new(law: L, time_step: TimeStep<L::Float>) -> Self {
        Self {
            law,
            time_step,
            allowed: law.allowed_rate_squared(time_step),
            pair: Memo {
                key: [<L::Float as Float>::ZERO; 2],
                value: (NormalOscillator::default(), <L::Float as Float>::ZERO),
            },
            wall: Memo {
                key: <L::Float as Float>::ZERO,
                value: NormalOscillator::default(),
            },
            unstable: 0,
        }
    }

    /// How many touching contacts past the law's accuracy limit
    /// ([`ContactLaw::accurate_phase`](crate::ContactLaw::accurate_phase)) this bound law has
    /// evaluated, knowingly: those of a [coarse](crate::ContactLaw::coarse_time_step) step
    /// (within its stability limit; past it they are refused) and any that a step made with
    /// [`TimeStep::tolerating_unstable_contacts`] let through. Always zero for a step from
    /// [`ContactLaw::time_step`](crate::ContactLaw::time_step): it refuses them with
    /// [`ContactError::PastStableStep`].
    pub fn inaccurate_contacts(&self) -> usize {
        self.unstable
    }

    /// The law.
    #[inline(always)]
    pub fn law(&self) -> &L {
        &self.law
    }

    /// The time step.
    #[inline(always)]
    pub fn time_step(&self) -> TimeStep<L::Float> {
        self.time_step
    }

    /// Evaluates the contact between checked spheres `i` and `j` for one step. State handling as
    /// [`ContactLaw::sphere_sphere`](crate::ContactLaw::sphere_sphere), and the same bits.
    ///
    /// # Errors
    /// [`ContactError::CoincidentCentres`]; [`ContactError::NonFiniteResult`] when the checked
    /// inputs overflow; [`ContactError::PastStableStep`] for a contact stiffer than the step
    /// allows. The state is then unchanged.
    #[inline(always)]
    pub fn sphere_sphere(
        &mut self,
        i: &CheckedSphere<L::Float>,
        j: &CheckedSphere<L::Float>,
        state: &mut L::State,
    ) -> Result<Interaction<L::Float>, ContactError> {
        L::evaluate_pair(self, i, j, state, sealed::Internal(()))
    }

    /// [`BoundLaw::sphere_sphere`] on a pair the list seam sifted, whose caller tests the forces
    /// and the new state for finiteness itself (see [`Law::evaluate_sifted_deferred`]).
    #[inline(always)]
    pub(crate) fn sphere_sphere_sifted(
        &mut self,
        i: &CheckedSphere<L::Float>,
        j: &CheckedSphere<L::Float>,
        sifted: &sealed::Sifted<L::Float>,
        state: &mut L::State,
    ) -> Result<Interaction<L::Float>, ContactError> {
        L::evaluate_sifted_deferred(self, i, j, sifted, state, sealed::Deferred(()))
    }

    /// Evaluates the contact between a checked sphere (body i) and a wall (body j) for one step;
    /// see [`ContactLaw::sphere_wall`](crate::ContactLaw::sphere_wall).
    ///
    /// # Errors
    /// [`ContactError::NonFiniteResult`] when the checked inputs overflow;
    /// [`ContactError::PastStableStep`] for a contact stiffer than the step allows;
    /// [`ContactError::CoincidentCentres`] for a sphere centred on a cylinder's axis that reaches
    /// it. The state is then unchanged.
    #[inline(always)]
    pub fn sphere_wall(
        &mut self,
        sphere: &CheckedSphere<L::Float>,
        wall: &Wall<L::Float>,
        state: &mut L::State,
    ) -> Result<Interaction<L::Float>, ContactError> {
        L::evaluate_wall(self, sphere, wall, state, sealed::Internal(()))
    }
}
