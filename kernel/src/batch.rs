//! The batch path: `WIDTH` sphere-sphere contacts evaluated together, in structure-of-arrays form,
//! the same bits as evaluating them one at a time.
//!
//! A contact is a serial chain of roots and divisions; one at a time it leaves most of a vector
//! unit idle. A block of `WIDTH` contacts (`WIDTH` the vector width: [`LANES`]) runs the same
//! straight-line computation on every lane and keeps, per lane, what the one-contact path would have returned:
//! the forces where the pair touches, a reset state where it is apart, the unchanged state and the
//! same [`ContactError`] where its input is bad. Nothing branches on a lane's data, so the compiler
//! can put the lanes side by side in vector registers; with a backend whose square root it can
//! widen (`Std`, feature `std`) it does. The per-lane formulas are the one-contact path's own
//! (`geometry.rs`, `law.rs` and the slots), so the bits agree by construction; the host tests
//! check them lane by lane for every slot and status.

use crate::backend::MathBackend;
use crate::body::{Sphere, effective_mass};
use crate::checked::{CheckedSphere, sphere_checks};
use crate::engine::{BoundLaw, Law};
use crate::error::ContactError;
use crate::float::Float;
use crate::geometry::Separation;
use crate::law::{ContactForces, ContactLaw, Interaction, within_stable_step};
use crate::normal::{NormalModel, NormalOscillator};
use crate::rolling::RollingModel;
use crate::rotation::Rotation;
use crate::tangential::{ContactState, TangentialModel};
use crate::vector::Vec3;

mod group;
pub use group::{BlockGroup, BlockPairs};

/// The block length that ran fastest for `f64` on x86-64 in every build measured (portable SSE2,
/// `x86-64-v3`, `x86-64-v4`; `contact_batch_bench`): two SSE2 registers, one AVX register.
/// With AVX-512 and `-C target-feature=-prefer-256-bit`, blocks of 8 are faster; for `f32`, blocks
/// of `2 * LANES` fill the same registers. A block's lanes live in registers, so much longer
/// blocks are slower.
pub const LANES: usize = 4;

/// One 3-vector per lane, as three arrays of components.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vec3Lanes<F, const WIDTH: usize> {
    /// x components.
    pub x: [F; WIDTH],
    /// y components.
    pub y: [F; WIDTH],
    /// z components.
    pub z: [F; WIDTH],
}

impl<F: Float, const WIDTH: usize> Default for Vec3Lanes<F, WIDTH> {
    fn default() -> Self {
        Self {
            x: [F::ZERO; WIDTH],
            y: [F::ZERO; WIDTH],
            z: [F::ZERO; WIDTH],
        }
    }
}

impl<F: Float, const WIDTH: usize> Vec3Lanes<F, WIDTH> {
    /// Lane `lane`'s vector. Panics if `lane >= WIDTH`, as indexing does.
    #[inline(always)]
    pub fn get(&self, lane: usize) -> Vec3<F> {
        Vec3::new(self.x[lane], self.y[lane], self.z[lane])
    }

    /// Sets lane `lane`'s vector. Panics if `lane >= WIDTH`, as indexing does.
    #[inline(always)]
    pub fn set(&mut self, lane: usize, value: Vec3<F>) {
        self.x[lane] = value.x;
        self.y[lane] = value.y;
        self.z[lane] = value.z;
    }
}

/// One sphere per lane: the fields of [`Sphere`], each as arrays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereLanes<F: Float, const WIDTH: usize> {
    /// Centre positions (m).
    pub position: Vec3Lanes<F, WIDTH>,
    /// Centre velocities (m/s).
    pub velocity: Vec3Lanes<F, WIDTH>,
    /// Angular velocities (rad/s).
    pub angular_velocity: Vec3Lanes<F, WIDTH>,
    /// Radii (m).
    pub radius: [F; WIDTH],
    /// Masses (kg).
    pub mass: [F; WIDTH],
}

impl<F: Float, const WIDTH: usize> Default for SphereLanes<F, WIDTH> {
    fn default() -> Self {
        Self {
            position: Vec3Lanes::default(),
            velocity: Vec3Lanes::default(),
            angular_velocity: Vec3Lanes::default(),
            radius: [F::ZERO; WIDTH],
            mass: [F::ZERO; WIDTH],
        }
    }
}

impl<F: Float, const WIDTH: usize> SphereLanes<F, WIDTH> {
    /// Lane `lane`'s sphere. Panics if `lane >= WIDTH`, as indexing does.
    #[inline(always)]
    pub fn get(&self, lane: usize) -> Sphere<F> {
        Sphere {
            position: self.position.get(lane),
            velocity: self.velocity.get(lane),
            angular_velocity: self.angular_velocity.get(lane),
            radius: self.radius[lane],
            mass: self.mass[lane],
        }
    }

    /// Sets lane `lane`'s sphere. Panics if `lane >= WIDTH`, as indexing does.
    #[inline(always)]
    pub fn set(&mut self, lane: usize, sphere: &Sphere<F>) {
        self.position.set(lane, sphere.position);
        self.velocity.set(lane, sphere.velocity);
        self.angular_velocity.set(lane, sphere.angular_velocity);
        self.radius[lane] = sphere.radius;
        self.mass[lane] = sphere.mass;
    }
}

/// `WIDTH` pairs of spheres, lane by lane: lane `k` is the contact between `i`'s sphere `k` and
/// `j`'s sphere `k`. Plain data, like [`Sphere`]: [`BoundLaw::sphere_pairs`] checks every lane.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PairBlock<F: Float, const WIDTH: usize> {
    /// Body i of each lane.
    pub i: SphereLanes<F, WIDTH>,
    /// Body j of each lane.
    pub j: SphereLanes<F, WIDTH>,
}

impl<F: Float, const WIDTH: usize> PairBlock<F, WIDTH> {
    /// Sets lane `lane` to the pair `(i, j)`. Panics if `lane >= WIDTH`, as indexing does.
    #[inline(always)]
    pub fn set(&mut self, lane: usize, i: &Sphere<F>, j: &Sphere<F>) {
        self.i.set(lane, i);
        self.j.set(lane, j);
    }
}

/// What each lane of a block gave: the fields of [`ContactForces`] as arrays (zero where the lane
/// does not touch), and each lane's outcome, read with [`ContactBlock::outcome`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactBlock<F: Float, const WIDTH: usize> {
    /// Unit normals from i to j.
    pub normal: Vec3Lanes<F, WIDTH>,
    /// Overlaps (m).
    pub overlap: [F; WIDTH],
    /// Normal forces on j along the normal (N).
    pub normal_force: [F; WIDTH],
    /// Tangential forces on j (N).
    pub tangential_force: Vec3Lanes<F, WIDTH>,
    /// Slip velocities (m/s).
    pub slip_velocity: Vec3Lanes<F, WIDTH>,
    /// Torques on i (N m).
    pub torque_on_i: Vec3Lanes<F, WIDTH>,
    /// Torques on j (N m).
    pub torque_on_j: Vec3Lanes<F, WIDTH>,
    /// Whether each contact slid.
    pub sliding: [bool; WIDTH],
    status: [u8; WIDTH],
}

impl<F: Float, const WIDTH: usize> Default for ContactBlock<F, WIDTH> {
    fn default() -> Self {
        Self {
            normal: Vec3Lanes::default(),
            overlap: [F::ZERO; WIDTH],
            normal_force: [F::ZERO; WIDTH],
            tangential_force: Vec3Lanes::default(),
            slip_velocity: Vec3Lanes::default(),
            torque_on_i: Vec3Lanes::default(),
            torque_on_j: Vec3Lanes::default(),
            sliding: [false; WIDTH],
            status: [Status::APART; WIDTH],
        }
    }
}

impl<F: Float, const WIDTH: usize> ContactBlock<F, WIDTH> {
    /// Lane `lane`'s result, exactly what [`BoundLaw::sphere_sphere`] or
    /// [`ContactLaw::sphere_sphere`] returns for that pair. A block not yet evaluated reads as
    /// apart. Panics if `lane >= WIDTH`, as indexing does.
    ///
    /// # Errors
    /// The lane's [`ContactError`], as the one-contact path gives it.
    #[inline(always)]
    pub fn outcome(&self, lane: usize) -> Result<Interaction<F>, ContactError> {
        match Status::decode(self.status[lane]) {
            Ok(false) => Ok(Interaction::Apart),
            Ok(true) => Ok(Interaction::Touching(self.forces(lane))),
            Err(error) => Err(error),
        }
    }

    /// Whether lane `lane` touches (its outcome is [`Interaction::Touching`]).
    #[inline(always)]
    pub fn touching(&self, lane: usize) -> bool {
        self.status[lane] == Status::TOUCHING
    }

    /// Total force on body j of lane `lane` (zero unless it touches); see
    /// [`ContactForces::force_on_j`].
    #[inline(always)]
    pub fn force_on_j(&self, lane: usize) -> Vec3<F> {
        self.normal.get(lane) * self.normal_force[lane] + self.tangential_force.get(lane)
    }

    #[inline(always)]
    fn forces(&self, lane: usize) -> ContactForces<F> {
        ContactForces {
            normal: self.normal.get(lane),
            overlap: self.overlap[lane],
            normal_force: self.normal_force[lane],
            tangential_force: self.tangential_force.get(lane),
            slip_velocity: self.slip_velocity.get(lane),
            torque_on_i: self.torque_on_i.get(lane),
            torque_on_j: self.torque_on_j.get(lane),
            sliding: self.sliding[lane],
        }
    }

    #[inline(always)]
    fn set(&mut self, lane: usize, forces: &ContactForces<F>, status: u8) {
        self.normal.set(lane, forces.normal);
        self.overlap[lane] = forces.overlap;
        self.normal_force[lane] = forces.normal_force;
        self.tangential_force.set(lane, forces.tangential_force);
        self.slip_velocity.set(lane, forces.slip_velocity);
        self.torque_on_i.set(lane, forces.torque_on_i);
        self.torque_on_j.set(lane, forces.torque_on_j);
        self.sliding[lane] = forces.sliding;
        self.status[lane] = status;
    }
}

/// A lane's outcome as one byte, so that choosing it is a select and not a branch.
struct Status;

impl Status {
    const TOUCHING: u8 = 0;
    const APART: u8 = 1;
    const NON_FINITE_INPUT: u8 = 2;
    const NON_POSITIVE_RADIUS: u8 = 3;
    const NON_POSITIVE_MASS: u8 = 4;
    const COINCIDENT_CENTRES: u8 = 5;
    const NON_FINITE_RESULT: u8 = 6;
    const PAST_STABLE_STEP: u8 = 7;

    /// An error's status.
    fn encode(error: ContactError) -> u8 {
        match error {
            ContactError::NonFiniteInput => Self::NON_FINITE_INPUT,
            ContactError::NonPositiveRadius => Self::NON_POSITIVE_RADIUS,
            ContactError::NonPositiveMass => Self::NON_POSITIVE_MASS,
            ContactError::CoincidentCentres => Self::COINCIDENT_CENTRES,
            ContactError::PastStableStep => Self::PAST_STABLE_STEP,
            // The one-contact path gives no other error (a history store's is its own).
            _ => Self::NON_FINITE_RESULT,
        }
    }

    /// `Ok(touching)` or the error.
    fn decode(status: u8) -> Result<bool, ContactError> {
        match status {
            Self::TOUCHING => Ok(true),
            Self::APART => Ok(false),
            Self::NON_FINITE_INPUT => Err(ContactError::NonFiniteInput),
            Self::NON_POSITIVE_RADIUS => Err(ContactError::NonPositiveRadius),
            Self::NON_POSITIVE_MASS => Err(ContactError::NonPositiveMass),
            Self::COINCIDENT_CENTRES => Err(ContactError::CoincidentCentres),
            Self::PAST_STABLE_STEP => Err(ContactError::PastStableStep),
            _ => Err(ContactError::NonFiniteResult),
        }
    }

    /// The first failed check of one sphere, in the order of `checked::sphere_checks`, or
    /// `otherwise`.
    #[inline(always)]
    fn of_sphere<F: Float>(sphere: &Sphere<F>, otherwise: u8) -> u8 {
        sphere_checks(sphere)
            .into_iter()
            .rev()
            .fold(otherwise, |status, (failed, error)| {
                select(failed, Self::encode(error), status)
            })
    }

    /// What the one-contact path returns for this pair: its checks in the same order (sphere i,
    /// sphere j, coincident centres, apart, a non-finite result), the first failure winning
    /// (the stability check, which that path makes just before finiteness, is made apart: see
    /// `sphere_pairs`).
    #[inline(always)]
    fn of_pair<F: Float>(
        i: &Sphere<F>,
        j: &Sphere<F>,
        separation: &Separation<F>,
        finite: bool,
    ) -> u8 {
        let status = select(finite, Self::TOUCHING, Self::NON_FINITE_RESULT);
        let status = select(separation.apart(), Self::APART, status);
        let status = select(separation.coincident(), Self::COINCIDENT_CENTRES, status);
        Self::of_sphere(i, Self::of_sphere(j, status))
    }
}

/// `a` if `condition`, else `b`, both already computed: a select, never a branch.
#[inline(always)]
fn select<T>(condition: bool, a: T, b: T) -> T {
    if condition { a } else { b }
}

/// Evaluates a block; see [`BoundLaw::sphere_pairs`].
#[inline(always)]
pub(crate) fn sphere_pairs<F, Nm, T, M, R, Ro, const WIDTH: usize>(
    bound: &mut BoundLaw<ContactLaw<F, Nm, T, M, R, Ro>>,
    block: &PairBlock<F, WIDTH>,
    states: &mut [Ro::State<T::State>; WIDTH],
    out: &mut ContactBlock<F, WIDTH>,
) where
    F: Float,
    Nm: NormalModel<F>,
    T: TangentialModel<F>,
    M: MathBackend<F>,
    R: Rotation,
    Ro: RollingModel<F>,
{
    let untouched = ContactForces {
        normal: Vec3::ZERO,
        overlap: F::ZERO,
        normal_force: F::ZERO,
        tangential_force: Vec3::ZERO,
        slip_velocity: Vec3::ZERO,
        torque_on_i: Vec3::ZERO,
        torque_on_j: Vec3::ZERO,
        sliding: false,
    };
    if !T::VECTORISES {
        for (lane, state) in states.iter_mut().enumerate() {
            let (i, j) = (block.i.get(lane), block.j.get(lane));
            let outcome = CheckedSphere::new(i).and_then(|i| {
                let j = CheckedSphere::new(j)?;
                bound.sphere_sphere(&i, &j, state)
            });
            let (forces, status) = match outcome {
                Ok(Interaction::Touching(forces)) => (forces, Status::TOUCHING),
                Ok(Interaction::Apart) => (untouched, Status::APART),
                Err(error) => (untouched, Status::encode(error)),
            };
            out.set(lane, &forces, status);
        }
        return;
    }
    let (law, time_step) = (bound.law, bound.time_step);
    // Local copies: the lanes then live in registers, with no aliasing between the ~35 streams.
    let pairs = *block;
    let mut kept = *states;
    // Each lane derives its pair's oscillator: in vector registers that costs less than testing
    // whether the block's masses match the bound law's remembered pair (contact_batch_bench).
    let derive = |m: [F; 2]| law.normal().oscillator::<M>(effective_mass(m[0], m[1]));
    for (lane, state) in kept.iter_mut().enumerate() {
        let (i, j) = (pairs.i.get(lane), pairs.j.get(lane));
        let separation = Separation::of(&i, &j);
        let frame = separation.frame::<M>(&i, &j, law.lever_arm());
        let oscillator = derive([i.mass, j.mass]);
        let (forces, next, _) = law.touching(&frame, &oscillator, (state, None), time_step);
        let finite = forces.is_finite() && next.is_finite();
        let status = Status::of_pair(&i, &j, &separation, finite);
        let touching = status == Status::TOUCHING;
        let apart = status == Status::APART;
        *state = select(touching, next, select(apart, Default::default(), *state));
        out.set(lane, &select(touching, forces, untouched), status);
    }
    // The stability check, lane by lane after the widened loop (one more compare inside it and
    // the compiler stopped widening the lanes). The one-contact path checks it before
    // finiteness, so touching and non-finite lanes are both asked; each lane's stiffness and
    // effective mass are derived again from the same inputs by the same formulas, so the
    // verdict is the one-contact path's.
    let mut unstable = 0usize;
    for (lane, state) in kept.iter_mut().enumerate() {
        let status = out.status[lane];
        if status != Status::TOUCHING && status != Status::NON_FINITE_RESULT {
            continue;
        }
        let (i, j) = (pairs.i.get(lane), pairs.j.get(lane));
        let frame = Separation::of(&i, &j).frame::<M>(&i, &j, law.lever_arm());
        let unit = NormalOscillator::default();
        let contact =
            law.normal()
                .contact::<M>(frame.overlap, F::ZERO, frame.effective_radius, &unit);
        let stiffness = law.normal().tangent_stiffness(&contact);
        let mass = effective_mass(i.mass, j.mass);
        if within_stable_step(stiffness, mass, bound.allowed) {
            continue;
        }
        if law.evaluates_past_accuracy(stiffness, mass, time_step) {
            unstable += usize::from(status == Status::TOUCHING);
        } else {
            *state = states[lane];
            out.set(lane, &untouched, Status::PAST_STABLE_STEP);
        }
    }
    *states = kept;
    bound.count_unstable(unstable);
}

impl<L: Law> BoundLaw<L> {
    /// Evaluates `WIDTH` sphere-sphere contacts, lane `k` of `block` with `states[k]`, into `out`:
    /// for every lane the same bits, the same state handling and the same error as
    /// [`ContactLaw::sphere_sphere`] (which [`BoundLaw::sphere_sphere`] equals) on that pair.
    /// Every lane's spheres are checked, as that function checks them; a bad lane leaves its
    /// state as it was and does not disturb the others. Read each lane with
    /// [`ContactBlock::outcome`].
    ///
    /// Take `WIDTH` = [`LANES`] and a backend whose square root vectorises (`Std`, feature `std`);
    /// with [`Libm`](crate::Libm) the lanes run one after another, with the same bits.
    /// Inlined into a large function (a threaded pair loop), the compiler may stop widening the
    /// lanes; calling it from a small non-inlined function of the engine's keeps them widened
    /// (the scene does so).
    ///
    /// ```
    /// use soft_sphere::batch::{ContactBlock, PairBlock};
    /// use soft_sphere::{
    ///     ContactError, ContactLaw, Interaction, LinearSpringDashpot, ModelAA, Sphere,
    ///     TangentialParameters, Vec3,
    /// };
    ///
    /// let law = ContactLaw::new(
    ///     LinearSpringDashpot::new(1.0e4_f64, 0.8).unwrap(),
    ///     ModelAA(TangentialParameters::new(3.0e3, 0.5, 0.4).unwrap()),
    /// );
    /// let sphere = |x: f64| Sphere::solid(Vec3::new(x, 0.0, 0.0), 1.0e-3, 2500.0);
    /// let dt = law.time_step(1.0e-6, sphere(0.0).mass / 2.0).unwrap();
    ///
    /// let mut block = PairBlock::<f64, 2>::default();
    /// block.set(0, &sphere(0.0), &sphere(1.9e-3)); // touching
    /// block.set(1, &sphere(0.0), &sphere(0.0)); // coincident: an error for this lane only
    /// let mut states = [Default::default(); 2];
    /// let mut out = ContactBlock::default();
    /// law.at(dt).sphere_pairs(&block, &mut states, &mut out);
    ///
    /// let mut one_state = Default::default();
    /// let one = law.sphere_sphere(&sphere(0.0), &sphere(1.9e-3), &mut one_state, dt);
    /// assert_eq!(out.outcome(0), one);
    /// assert!(matches!(one, Ok(Interaction::Touching(_))));
    /// assert_eq!(states[0], one_state);
    /// assert_eq!(out.outcome(1), Err(ContactError::CoincidentCentres));
    /// ```
    #[inline(always)]
    pub fn sphere_pairs<const WIDTH: usize>(
        &mut self,
        block: &PairBlock<L::Float, WIDTH>,
        states: &mut [L::State; WIDTH],
        out: &mut ContactBlock<L::Float, WIDTH>,
    ) {
        L::evaluate_pairs(self, block, states, out);
    }
}
