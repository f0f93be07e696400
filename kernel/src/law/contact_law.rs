//! The contact law: model slots composed at compile time, evaluated for one contact at a time.

use core::marker::PhantomData;

use crate::law::engine::{BoundLaw, Law, sealed};
use crate::law::geometry::{self, ContactFrame, LeverArm, Separation};
use crate::law::normal::{Accuracy, NormalModel, NormalOscillator, scan_accuracy};
use crate::law::rolling::{NoRolling, RollingInput, RollingModel};
use crate::law::rotation::{NonRotating, Rotating, Rotation};
use crate::law::tangential::{
    ContactState, TangentialInput, TangentialModel, rotate_into_tangent_plane,
};
use crate::value::backend::MathBackend;
use crate::value::body::{Sphere, effective_mass};
use crate::value::checked::{self, CheckedSphere};
use crate::value::error::{ContactError, Parameter, ParameterError, positive};
use crate::value::float::Float;
use crate::value::forces::{ContactForces, Interaction};
use crate::value::time_step::TimeStep;
use crate::value::vector::Vec3;
use crate::value::wall::Wall;

/// A soft-sphere contact law built from slots: `N` the normal law, `T` the tangential law,
/// `M` the math backend, `R` whether rotation counts. Slots that a scene does not need are
/// zero-sized ([`Frictionless`](crate::Frictionless), [`NonRotating`]) and their work is
/// removed at compile time.
///
/// Build it with [`ContactLaw::new`] ([`Libm`](crate::Libm) backend, rotating spheres), then optionally
/// [`with_backend`](ContactLaw::with_backend), [`without_rotation`](ContactLaw::without_rotation)
/// and [`with_lever_arm`](ContactLaw::with_lever_arm).
///
/// ```
/// use soft_sphere::prelude::{
///     ContactLaw, Frictionless, Interaction, LinearSpringDashpot, Micromath, NonRotating, Sphere,
///     Vec3, Wall,
/// };
///
/// // A frictionless, non-rotating f32 law on the fast approximate backend: no slip velocity, no
/// // tangential force, no torque and no per-contact state are computed or stored.
/// type Light = ContactLaw<f32, LinearSpringDashpot<f32>, Frictionless, Micromath, NonRotating>;
/// let law: Light = ContactLaw::new(LinearSpringDashpot::new(500.0, 0.9).unwrap(), Frictionless)
///     .with_backend::<Micromath>()
///     .without_rotation();
///
/// let floor = Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap();
/// let sphere = Sphere::solid(Vec3::new(0.0, 0.0, 0.99e-3), 1.0e-3, 2500.0);
/// let dt = law.time_step(1.0e-6, sphere.mass).unwrap();
/// let Interaction::Touching(contact) = law.sphere_wall(&sphere, &floor, &mut (), dt).unwrap() else {
///     unreachable!()
/// };
/// assert!(contact.force_on_i().z > 0.0); // the floor pushes the sphere up
/// assert_eq!(contact.torque_on_i, Vec3::ZERO);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct ContactLaw<
    F: Float,
    N,
    T,
    M = <F as Float>::DefaultBackend,
    R = Rotating,
    Ro = NoRolling,
> {
    normal: N,
    tangential: T,
    rolling: Ro,
    lever_arm: LeverArm,
    /// The largest phase `w0 dt` (rad) that a step may advance a contact's normal oscillator by
    /// and keep its normal and tangential modes stable (see [`ContactLaw::stable_phase`]).
    stable_phase: F,
    /// The normal law's accuracy limit (see [`ContactLaw::accurate_phase`]), before the
    /// stability limit is taken into account.
    normal_accuracy: Accuracy<F>,
    slots: Slots<F, M, R>,
}

/// Marks the type-only slots without owning them (keeps the law `Send`, `Sync` and `Copy`).
type Slots<F, M, R> = PhantomData<fn() -> (F, M, R)>;

impl<F: Float, N: NormalModel<F>, T: TangentialModel<F>> ContactLaw<F, N, T> {
    /// A law from its normal and tangential slots, with the libm backend, rotating spheres and
    /// the radius as lever arm.
    ///
    /// A tangential law whose stiffness grows with the contact radius (the Mindlin laws) needs a
    /// normal law that has one ([`Hertz`](crate::Hertz)); pairing it with a linear law does not
    /// compile.
    pub fn new(normal: N, tangential: T) -> Self {
        const {
            assert!(
                !T::NEEDS_CONTACT_RADIUS || N::CONTACT_RADIUS,
                "this tangential law's stiffness needs a normal law with a contact radius (Hertz)"
            );
        }
        Self {
            normal,
            tangential,
            rolling: NoRolling,
            lever_arm: LeverArm::Radius,
            stable_phase: stable_phase(&normal, &tangential, Rotating::ROTATES),
            normal_accuracy: scan_accuracy(&normal),
            slots: PhantomData,
        }
    }
}

/// The largest `w0 dt` for which the normal and tangential modes of a contact are stable, `w0`
/// the contact's normal natural frequency. Every mode's limit scales as `1 / w0`: a linear law's
/// rates all go as `1 / sqrt(m*)`, Hertz's and Mindlin's as `sqrt(a / m*)`, and every damping
/// ratio is constant. So the product is one number per law, here taken at a unit mass.
fn stable_phase<F: Float, N: NormalModel<F>, T: TangentialModel<F>>(
    normal: &N,
    tangential: &T,
    rotates: bool,
) -> F {
    // A unit effective mass; the tangential mode's is 2/7 of it for rotating solid spheres.
    let tangential_mass = if rotates {
        F::from_f64(2.0 / 7.0)
    } else {
        F::ONE
    };
    let design = normal.design_contact(F::ONE);
    let step = normal
        .critical_time_step(F::ONE)
        .min_of(tangential.critical_time_step(&design, tangential_mass));
    step * design.oscillator.natural_frequency
}

impl<F, N, T, M, R, Ro> ContactLaw<F, N, T, M, R, Ro>
where
    F: Float,
    N: NormalModel<F>,
    T: TangentialModel<F>,
    M: MathBackend<F>,
    R: Rotation,
    Ro: RollingModel<F>,
{
    /// The same law computing its per-contact math with backend `B`.
    pub fn with_backend<B: MathBackend<F>>(self) -> ContactLaw<F, N, T, B, R, Ro> {
        ContactLaw {
            normal: self.normal,
            tangential: self.tangential,
            rolling: self.rolling,
            lever_arm: self.lever_arm,
            stable_phase: self.stable_phase,
            normal_accuracy: self.normal_accuracy,
            slots: PhantomData,
        }
    }

    /// The same law for spheres that do not rotate.
    pub fn without_rotation(self) -> ContactLaw<F, N, T, M, NonRotating, Ro> {
        ContactLaw {
            normal: self.normal,
            tangential: self.tangential,
            rolling: self.rolling,
            lever_arm: self.lever_arm,
            stable_phase: stable_phase(&self.normal, &self.tangential, NonRotating::ROTATES),
            normal_accuracy: self.normal_accuracy,
            slots: PhantomData,
        }
    }

    /// The same law with rolling resistance `rolling` (see [`RollingModel`]). A law that does
    /// not rotate has no rolling to resist: the slot then only keeps its state.
    pub fn with_rolling<Q: RollingModel<F>>(self, rolling: Q) -> ContactLaw<F, N, T, M, R, Q> {
        ContactLaw {
            normal: self.normal,
            tangential: self.tangential,
            rolling,
            lever_arm: self.lever_arm,
            stable_phase: self.stable_phase,
            normal_accuracy: self.normal_accuracy,
            slots: PhantomData,
        }
    }

    /// The rolling-resistance slot.
    pub fn rolling(&self) -> &Ro {
        &self.rolling
    }

    /// The same law with a different lever arm (see [`LeverArm`]).
    pub fn with_lever_arm(mut self, lever_arm: LeverArm) -> Self {
        self.lever_arm = lever_arm;
        self
    }

    /// The normal slot.
    pub fn normal(&self) -> &N {
        &self.normal
    }

    /// The tangential slot.
    pub fn tangential(&self) -> &T {
        &self.tangential
    }

    /// The lever arm in use.
    pub fn lever_arm(&self) -> LeverArm {
        self.lever_arm
    }

    /// The largest phase `w0 dt` (rad) a step may advance a contact's normal oscillator by, `w0`
    /// the contact's undamped normal frequency (for [`Hertz`](crate::Hertz), at its current
    /// overlap), and keep the normal and the tangential modes stable. Every evaluation with a
    /// [coarse](ContactLaw::coarse_time_step) step refuses a contact past it
    /// ([`ContactError::PastStableStep`]); every step first checks against the smaller
    /// [`ContactLaw::accurate_phase`]. It is
    /// [`ContactLaw::critical_time_step`] times `w0`, the same for every mass (rolling aside:
    /// its limit is checked by [`ContactLaw::time_step`]).
    pub fn stable_phase(&self) -> F {
        self.stable_phase
    }

    /// The largest phase `w0 dt` (rad) a step may advance a contact's normal oscillator by and
    /// still give the law's rebound: a head-on impact first seen at any phase of its step
    /// rebounds at most 0.02 (of its impact speed) above the rebound at a vanishing step.
    /// Derived from the integrators' discrete map when the law is built (`docs/physics.md`, the
    /// accuracy limit), and never past [`ContactLaw::stable_phase`]. Every evaluation checks
    /// its contact against it ([`ContactError::PastStableStep`]), `w0` its tangent stiffness's
    /// frequency; [`ContactLaw::time_step`] accepts steps up to
    /// [`ContactLaw::accurate_time_step`], for a [`Hertz`](crate::Hertz) law a little less (its
    /// stepped impacts overshoot the declared impact's peak overlap, and this phase allows for
    /// it).
    pub fn accurate_phase(&self) -> F {
        self.normal_accuracy.contact.min_of(self.stable_phase)
    }

    /// The elastic energy a touching contact holds (J): its normal spring at `overlap` for
    /// effective radius `R*` (a sphere's own radius against a wall), plus the tangential and
    /// rolling springs of `state` (the state after the step that gave `overlap`). Dashpots and
    /// sliders hold none. See [`NormalModel::elastic_energy`] and
    /// [`TangentialModel::stored_energy`].
    pub fn stored_energy(&self, overlap: F, effective_radius: F, state: &Ro::State<T::State>) -> F {
        self.normal.elastic_energy(overlap, effective_radius)
            + self.tangential.stored_energy(Ro::tangential(state))
            + self.rolling.stored_energy(state)
    }

    /// What the normal law derives for a pair of this effective mass (reference backend): a
    /// linear law's oscillator; see [`NormalModel::oscillator`].
    pub fn oscillator(&self, effective_mass: F) -> NormalOscillator<F> {
        self.normal.oscillator::<F::DefaultBackend>(effective_mass)
    }

    /// Duration of a binary impact with this effective mass (s); see
    /// [`NormalModel::contact_duration`].
    pub fn contact_duration(&self, effective_mass: F) -> F {
        self.normal.contact_duration(effective_mass)
    }

    /// The largest stable time step for contacts with this effective mass: the smaller of the
    /// normal and the tangential mode's bound. The tangential effective mass is `2/7 m*` for
    /// rotating homogeneous solid spheres (conservative for any sphere with `I >= 2/5 m R^2`) and
    /// `m*` without rotation.
    pub fn critical_time_step(&self, effective_mass: F) -> F {
        let tangential_mass = if R::ROTATES {
            F::from_f64(2.0 / 7.0) * effective_mass
        } else {
            effective_mass
        };
        let design = self.normal.design_contact(effective_mass);
        let tangential = self.tangential.critical_time_step(&design, tangential_mass);
        self.normal
            .critical_time_step(effective_mass)
            .min_of(tangential)
            .min_of(self.rolling.critical_time_step())
    }

    /// The largest accurate time step for contacts with this effective mass: the step at which
    /// the declared contact (for [`Hertz`](crate::Hertz), the declared impact's peak) advances
    /// by [`ContactLaw::accurate_phase`], and never more than
    /// [`ContactLaw::critical_time_step`].
    pub fn accurate_time_step(&self, effective_mass: F) -> F {
        let frequency = self
            .normal
            .design_contact(effective_mass)
            .oscillator
            .natural_frequency;
        (self.normal_accuracy.design / frequency).min_of(self.critical_time_step(effective_mass))
    }

    /// A step of 1/50 of the contact duration (MFiX's default), and never more than a fifth of
    /// [`ContactLaw::critical_time_step`]: a stiff tangential spring (`k_t/k_n` near 10 with
    /// rotation) or the stateless law's stick-phase dashpot at low restitution can be faster than
    /// the normal mode. When the duration is infinite (critical damping, no clamp), 1/50 of the
    /// undamped half-period `pi / w0` stands in for it.
    pub fn recommended_time_step(&self, effective_mass: F) -> F {
        let duration = self.contact_duration(effective_mass);
        let duration = if duration.is_finite() {
            duration
        } else {
            F::PI
                / self
                    .normal
                    .design_contact(effective_mass)
                    .oscillator
                    .natural_frequency
        };
        let margin = self.critical_time_step(effective_mass) / F::from_f64(5.0);
        (duration / F::from_f64(50.0)).min_of(margin)
    }

    /// Checks a time step for a scene whose lightest contact has effective mass
    /// `smallest_effective_mass` (for equal spheres of mass m: m/2 between spheres, m against a
    /// wall), for accuracy: below [`ContactLaw::accurate_time_step`], so that no head-on impact
    /// stepped with it, at any phase, rebounds more than 0.02 of its impact speed above the
    /// law's restitution; and every contact evaluated with it is checked against
    /// [`ContactLaw::accurate_phase`] ([`ContactError::PastStableStep`] past it).
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] / [`ParameterError::NotPositive`] for the step or the mass;
    /// [`ParameterError::TimeStepUnstable`] when the step is at or past
    /// [`ContactLaw::critical_time_step`]; [`ParameterError::TimeStepInaccurate`] when it is
    /// stable but at or past [`ContactLaw::accurate_time_step`] (a caller who wants it anyway
    /// says so with [`ContactLaw::coarse_time_step`]).
    pub fn time_step(
        &self,
        seconds: F,
        smallest_effective_mass: F,
    ) -> Result<TimeStep<F>, ParameterError> {
        let step = self.coarse_time_step(seconds, smallest_effective_mass)?;
        let limit = self.accurate_time_step(smallest_effective_mass);
        if step.seconds() < limit {
            Ok(TimeStep::accurate(step.seconds()))
        } else {
            Err(ParameterError::TimeStepInaccurate {
                time_step: step.seconds().to_f64(),
                limit: limit.to_f64(),
            })
        }
    }

    /// A step past the accuracy limit, asked for knowingly: checked for stability only (below
    /// [`ContactLaw::critical_time_step`]). A contact evaluated with it past
    /// [`ContactLaw::stable_phase`] is refused; one past [`ContactLaw::accurate_phase`] only is
    /// evaluated and counted ([`BoundLaw::inaccurate_contacts`](crate::BoundLaw::inaccurate_contacts)):
    /// such contacts can rebound faster than they came (up to twice near the stability limit).
    /// [`TimeStep::is_accurate`] tells such a step apart.
    ///
    /// # Errors
    /// As [`ContactLaw::time_step`], without [`ParameterError::TimeStepInaccurate`].
    pub fn coarse_time_step(
        &self,
        seconds: F,
        smallest_effective_mass: F,
    ) -> Result<TimeStep<F>, ParameterError> {
        let seconds = positive(seconds, Parameter::TimeStep)?;
        let mass = positive(smallest_effective_mass, Parameter::Mass)?;
        let limit = self.critical_time_step(mass);
        if seconds < limit {
            Ok(TimeStep::checked(seconds))
        } else {
            Err(ParameterError::TimeStepUnstable {
                time_step: seconds.to_f64(),
                limit: limit.to_f64(),
            })
        }
    }

    /// Evaluates the contact between spheres `i` and `j` for one step, checking both spheres.
    /// An engine that evaluates each sphere in many contacts checks it once instead, as a
    /// [`CheckedSphere`], and evaluates through [`ContactLaw::at`].
    ///
    /// `state` is this pair's per-contact state, owned by the caller and passed in the same (i, j)
    /// order every step. On success it is advanced; when the spheres are apart it is reset; on
    /// error it is left exactly as it was.
    ///
    /// # Errors
    /// [`ContactError::NonFiniteInput`], [`ContactError::NonPositiveRadius`],
    /// [`ContactError::NonPositiveMass`], [`ContactError::CoincidentCentres`] for bad inputs;
    /// [`ContactError::NonFiniteResult`] when finite inputs overflow;
    /// [`ContactError::PastStableStep`] when the contact is stiffer than `time_step` was checked
    /// for (a lighter pair than the declared mass, a [`Hertz`](crate::Hertz) overlap past the
    /// declared impact's), unless the step tolerates such contacts.
    #[inline]
    pub fn sphere_sphere(
        &self,
        i: &Sphere<F>,
        j: &Sphere<F>,
        state: &mut Ro::State<T::State>,
        time_step: TimeStep<F>,
    ) -> Result<Interaction<F>, ContactError> {
        checked::check(i)?;
        checked::check(j)?;
        let frame = geometry::sphere_sphere::<F, M>(i, j, self.lever_arm)?;
        let oscillator = || {
            let mass = effective_mass(i.mass, j.mass);
            (self.normal.oscillator::<M>(mass), mass)
        };
        let allowed = self.allowed_rate_squared(time_step);
        Ok(self
            .interaction::<true>(frame, oscillator, state, (time_step, allowed), None)?
            .0)
    }

    /// Evaluates the contact between a sphere (body i) and a wall (body j) for one step, checking
    /// the sphere. State handling and errors as for [`ContactLaw::sphere_sphere`] (a wall is valid
    /// by construction).
    ///
    /// # Errors
    /// As [`ContactLaw::sphere_sphere`]; [`ContactError::CoincidentCentres`] only for a sphere
    /// centred on a cylinder's axis that reaches it (one wider than the cylinder).
    #[inline]
    pub fn sphere_wall(
        &self,
        sphere: &Sphere<F>,
        wall: &Wall<F>,
        state: &mut Ro::State<T::State>,
        time_step: TimeStep<F>,
    ) -> Result<Interaction<F>, ContactError> {
        checked::check(sphere)?;
        let frame = geometry::sphere_wall(sphere, wall, self.lever_arm)?;
        let oscillator = || (self.normal.oscillator::<M>(sphere.mass), sphere.mass);
        let allowed = self.allowed_rate_squared(time_step);
        Ok(self
            .interaction::<true>(frame, oscillator, state, (time_step, allowed), None)?
            .0)
    }

    /// The law bound to a checked time step: it evaluates [`CheckedSphere`]s with no repeated
    /// checks, and computes the normal oscillator once per pair of masses instead of once per
    /// contact. The same bits as [`ContactLaw::sphere_sphere`] and [`ContactLaw::sphere_wall`].
    pub fn at(&self, time_step: TimeStep<F>) -> BoundLaw<Self> {
        BoundLaw::new(*self, time_step)
    }

    /// The outcome for an overlap (`Some` frame) or none, and whether it was a contact past the
    /// stable step that the step tolerates. `allowed` is the step's
    /// [`allowed_rate_squared`](Self::allowed_rate_squared), derived once per step by a bound law.
    /// With `FINITE` false the forces and the new state are not tested for finiteness: the
    /// caller tests them ([`Law::evaluate_sifted_deferred`]). `turned` is the tangential slot's
    /// stored vector already turned into the tangent plane, when the caller turned it.
    #[inline(always)]
    fn interaction<const FINITE: bool>(
        &self,
        frame: Option<ContactFrame<F>>,
        oscillator: impl FnOnce() -> (NormalOscillator<F>, F),
        state: &mut Ro::State<T::State>,
        (time_step, allowed): (TimeStep<F>, F),
        turned: Option<Vec3<F>>,
    ) -> Result<(Interaction<F>, bool), ContactError> {
        match frame {
            None => {
                *state = Default::default();
                Ok((Interaction::Apart, false))
            }
            Some(frame) => {
                let (oscillator, effective_mass) = oscillator();
                let (forces, next_state, stiffness) =
                    self.touching(&frame, &oscillator, (state, turned), time_step);
                let counted = !within_stable_step(stiffness, effective_mass, allowed);
                if counted && !self.evaluates_past_accuracy(stiffness, effective_mass, time_step) {
                    return Err(ContactError::PastStableStep);
                }
                if FINITE && !(forces.is_finite() && next_state.is_finite()) {
                    return Err(ContactError::NonFiniteResult);
                }
                *state = next_state;
                Ok((Interaction::Touching(forces), counted))
            }
        }
    }

    /// `(phi / dt)^2`, the squared frequency within which a contact is evaluated as usual, `phi`
    /// the [`accurate_phase`](Self::accurate_phase): one division per step, which a bound law
    /// makes once ([`BoundLaw`]) rather than at every contact.
    #[inline(always)]
    pub(crate) fn allowed_rate_squared(&self, time_step: TimeStep<F>) -> F {
        let rate = self.accurate_phase() / time_step.seconds();
        rate * rate
    }

    /// Whether a contact past the step's accuracy limit (of tangent stiffness `stiffness`, at
    /// effective mass `effective_mass`) is evaluated, and counted, rather than refused: when the
    /// step [tolerates](TimeStep::tolerating_unstable_contacts) such contacts, or is
    /// [coarse](Self::coarse_time_step) and the contact within the stability limit. Asked only
    /// of contacts past the accuracy limit, so its division is paid by them alone.
    #[inline]
    pub(crate) fn evaluates_past_accuracy(
        &self,
        stiffness: F,
        effective_mass: F,
        time_step: TimeStep<F>,
    ) -> bool {
        let stable = || {
            let rate = self.stable_phase / time_step.seconds();
            within_stable_step(stiffness, effective_mass, rate * rate)
        };
        time_step.tolerates_unstable_contacts() || (!time_step.is_accurate() && stable())
    }

    /// The forces of a touching contact, the state to keep and the contact's tangent stiffness
    /// ([`NormalModel::tangent_stiffness`]), not yet checked for finiteness or stability; `turned`
    /// as for [`interaction`](Self::interaction).
    #[inline(always)]
    pub(crate) fn touching(
        &self,
        frame: &ContactFrame<F>,
        oscillator: &NormalOscillator<F>,
        (state, turned): (&Ro::State<T::State>, Option<Vec3<F>>),
        time_step: TimeStep<F>,
    ) -> (ContactForces<F>, Ro::State<T::State>, F) {
        let n = frame.normal;
        let normal_velocity = frame.velocity.dot(n);
        let normal = self.normal.contact::<M>(
            frame.overlap,
            normal_velocity,
            frame.effective_radius,
            oscillator,
        );
        let normal_force = normal.force;

        let mut forces = ContactForces {
            normal: n,
            overlap: frame.overlap,
            normal_force,
            tangential_force: Vec3::ZERO,
            slip_velocity: Vec3::ZERO,
            torque_on_i: Vec3::ZERO,
            torque_on_j: Vec3::ZERO,
            sliding: false,
        };
        let mut next_tangential = *Ro::tangential(state);
        if T::ACTIVE {
            let mut slip_velocity = frame.velocity - n * normal_velocity;
            if R::ROTATES {
                let spin =
                    frame.angular_velocity_i * frame.arm_i + frame.angular_velocity_j * frame.arm_j;
                slip_velocity -= spin.cross(n);
            }
            let input = TangentialInput {
                normal: n,
                slip_velocity,
                normal_force,
                overlap: frame.overlap,
                approach_rate: -normal_velocity,
                oscillator: normal.oscillator,
                contact_radius: normal.contact_radius,
                time_step: time_step.seconds(),
            };
            let stored = Ro::tangential(state);
            let output = match turned {
                Some(turned) => self.tangential.force_turned::<M>(stored, &input, turned),
                None => self.tangential.force::<M>(stored, &input),
            };
            forces.tangential_force = output.force;
            forces.slip_velocity = slip_velocity;
            forces.sliding = output.sliding;
            next_tangential = output.state;
            if R::ROTATES {
                let moment = n.cross(output.force);
                forces.torque_on_i = moment * -frame.arm_i;
                forces.torque_on_j = moment * -frame.arm_j;
            }
        }
        if !Ro::ACTIVE {
            let (_, next_state) = self.rolling.resist::<M, _>(
                state,
                next_tangential,
                &RollingInput {
                    normal: n,
                    relative_spin: Vec3::ZERO,
                    normal_force,
                    effective_radius: frame.effective_radius,
                    time_step: time_step.seconds(),
                },
            );
            return (forces, next_state, self.normal.tangent_stiffness(&normal));
        }
        let relative_spin = if R::ROTATES {
            frame.angular_velocity_i - frame.angular_velocity_j
        } else {
            Vec3::ZERO
        };
        let (torque, next_state) = self.rolling.resist::<M, _>(
            state,
            next_tangential,
            &RollingInput {
                normal: n,
                relative_spin,
                normal_force,
                effective_radius: frame.effective_radius,
                time_step: time_step.seconds(),
            },
        );
        forces.torque_on_i += torque;
        forces.torque_on_j -= torque;
        (forces, next_state, self.normal.tangent_stiffness(&normal))
    }
}

/// Whether a contact of tangent stiffness `stiffness` between bodies of effective mass
/// `effective_mass` is within the step's stability limit: `w0 dt < phi` with
/// `w0^2 = stiffness / m*`, compared squared against `allowed = (phi / dt)^2` without a root or a
/// division (false for a NaN).
#[inline(always)]
pub(crate) fn within_stable_step<F: Float>(stiffness: F, effective_mass: F, allowed: F) -> bool {
    stiffness < effective_mass * allowed
}

impl<F: Float, N, T, M, R, Ro> sealed::Sealed for ContactLaw<F, N, T, M, R, Ro> {}

impl<F, N, T, M, R, Ro> Law for ContactLaw<F, N, T, M, R, Ro>
where
    F: Float,
    N: NormalModel<F>,
    T: TangentialModel<F>,
    M: MathBackend<F>,
    R: Rotation,
    Ro: RollingModel<F>,
{
    type Float = F;
    type State = Ro::State<T::State>;

    fn time_step(
        &self,
        seconds: F,
        smallest_effective_mass: F,
    ) -> Result<TimeStep<F>, ParameterError> {
        ContactLaw::time_step(self, seconds, smallest_effective_mass)
    }

    fn coarse_time_step(
        &self,
        seconds: F,
        smallest_effective_mass: F,
    ) -> Result<TimeStep<F>, ParameterError> {
        ContactLaw::coarse_time_step(self, seconds, smallest_effective_mass)
    }

    fn recommended_time_step(&self, effective_mass: F) -> F {
        ContactLaw::recommended_time_step(self, effective_mass)
    }

    fn allowed_rate_squared(&self, time_step: TimeStep<F>) -> F {
        ContactLaw::allowed_rate_squared(self, time_step)
    }

    fn contact_duration(&self, effective_mass: F) -> F {
        ContactLaw::contact_duration(self, effective_mass)
    }

    fn stored_energy(&self, overlap: F, effective_radius: F, state: &Self::State) -> F {
        ContactLaw::stored_energy(self, overlap, effective_radius, state)
    }

    #[inline(always)]
    fn evaluate_pair(
        bound: &mut BoundLaw<Self>,
        i: &CheckedSphere<F>,
        j: &CheckedSphere<F>,
        state: &mut Ro::State<T::State>,
        _: sealed::Internal,
    ) -> Result<Interaction<F>, ContactError> {
        bound_pair(bound, i, j, state)
    }

    #[inline(always)]
    fn sifted_roots(
        sifts: &mut sealed::Sifts<F>,
        found: usize,
        states: &[Self::State],
        _: sealed::Deferred,
    ) {
        let reach = &sifts.reach[..found];
        let separations = sifts.distance_squared[..found].iter().zip(reach);
        let roots = sifts
            .inverse_distance
            .iter_mut()
            .zip(sifts.overlap.iter_mut());
        for ((&distance_squared, &reach), (inverse_distance, overlap)) in separations.zip(roots) {
            let roots = Separation::roots::<M>(distance_squared, reach);
            (*inverse_distance, *overlap) = (roots.inverse_distance, roots.overlap);
        }
        if !T::TURNS {
            return;
        }
        // The normal as the frame makes it (`offset / d`), and each pair's stored vector.
        let places = &sifts.places[..found];
        let normals = sifts.offset.iter().zip(sifts.inverse_distance.iter());
        for ((&place, (&offset, &inverse_distance)), turned) in
            places.iter().zip(normals).zip(sifts.turned.iter_mut())
        {
            let stored = T::stored_vector(Ro::tangential(&states[usize::from(place)]));
            *turned = rotate_into_tangent_plane::<F, M>(stored, offset * inverse_distance);
        }
    }

    #[inline(always)]
    fn evaluate_sifted_deferred(
        bound: &mut BoundLaw<Self>,
        i: &CheckedSphere<F>,
        j: &CheckedSphere<F>,
        sifted: &sealed::Sifted<F>,
        state: &mut Ro::State<T::State>,
        _: sealed::Deferred,
    ) -> Result<Interaction<F>, ContactError> {
        // Sifted pairs overlap unless coincident: no second test of apart.
        let frame = geometry::sifted_frame(
            (i, j),
            &sifted.separation,
            sifted.roots,
            bound.law.lever_arm,
        )?;
        let turned = Some(sifted.turned);
        bound_frame::<_, _, _, _, _, _, false>(bound, (i, j), Some(frame), (state, turned))
    }

    #[inline(always)]
    fn evaluate_wall(
        bound: &mut BoundLaw<Self>,
        sphere: &CheckedSphere<F>,
        wall: &Wall<F>,
        state: &mut Ro::State<T::State>,
        _: sealed::Internal,
    ) -> Result<Interaction<F>, ContactError> {
        let BoundLaw {
            law,
            time_step,
            allowed,
            wall: memo,
            unstable: count,
            ..
        } = bound;
        let frame = geometry::sphere_wall(sphere, wall, law.lever_arm)?;
        let oscillator = || {
            let oscillator = *memo.get(sphere.mass, |mass| law.normal.oscillator::<M>(*mass));
            (oscillator, sphere.mass)
        };
        let (interaction, unstable) =
            law.interaction::<true>(frame, oscillator, state, (*time_step, *allowed), None)?;
        *count += usize::from(unstable);
        Ok(interaction)
    }
}

/// A bound law's sphere-sphere evaluation, its results tested for finiteness.
#[inline(always)]
fn bound_pair<F, N, T, M, R, Ro>(
    bound: &mut BoundLaw<ContactLaw<F, N, T, M, R, Ro>>,
    i: &CheckedSphere<F>,
    j: &CheckedSphere<F>,
    state: &mut Ro::State<T::State>,
) -> Result<Interaction<F>, ContactError>
where
    F: Float,
    N: NormalModel<F>,
    T: TangentialModel<F>,
    M: MathBackend<F>,
    R: Rotation,
    Ro: RollingModel<F>,
{
    let frame = geometry::sphere_sphere::<F, M>(i, j, bound.law.lever_arm)?;
    bound_frame::<_, _, _, _, _, _, true>(bound, (i, j), frame, (state, None))
}

/// A bound law's sphere-sphere evaluation from the pair's frame (none when apart), its results
/// tested for finiteness when `FINITE`; `turned` is the tangential slot's stored vector turned
/// into the tangent plane when the caller turned it ([`TangentialModel::force_turned`]).
#[inline(always)]
fn bound_frame<F, N, T, M, R, Ro, const FINITE: bool>(
    bound: &mut BoundLaw<ContactLaw<F, N, T, M, R, Ro>>,
    (i, j): (&CheckedSphere<F>, &CheckedSphere<F>),
    frame: Option<ContactFrame<F>>,
    (state, turned): (&mut Ro::State<T::State>, Option<Vec3<F>>),
) -> Result<Interaction<F>, ContactError>
where
    F: Float,
    N: NormalModel<F>,
    T: TangentialModel<F>,
    M: MathBackend<F>,
    R: Rotation,
    Ro: RollingModel<F>,
{
    let BoundLaw {
        law,
        time_step,
        allowed,
        pair,
        unstable: count,
        ..
    } = bound;
    let oscillator = || {
        *pair.get([i.mass, j.mass], |masses| {
            let mass = effective_mass(masses[0], masses[1]);
            (law.normal.oscillator::<M>(mass), mass)
        })
    };
    let (interaction, unstable) =
        law.interaction::<FINITE>(frame, oscillator, state, (*time_step, *allowed), turned)?;
    *count += usize::from(unstable);
    Ok(interaction)
}
