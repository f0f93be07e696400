//! C ABI for `soft-sphere`: build and validate a contact law once, then call it per contact with
//! plain structs. Every entry point returns an error code (`SS_OK` = 0) and never unwinds into C;
//! outputs are written only on success, so nothing the caller gave is half-updated.
//!
//! f64 entry points end in `_f64`, f32 ones in `_f32`. Laws: the stateless law, Model AA, Model
//! AA with Luding's reset and frictionless contacts over the linear spring-dashpot, and the same
//! four over Hertz with Mindlin's tangential spring (`SS_MODEL_HERTZ_*`; `ss_effective_moduli_*`
//! gives their `E*` and `G*` from two materials); the material tables (`ss_table_*`) also take
//! Hertz with micro-slip (`SS_MODEL_HERTZ_MICROSLIP`). The per-contact state
//! (`ss_state_*`) is the caller's: zero it for a new contact, keep it while the contact lasts (the
//! kernel resets it when the pair separates).
//!
//! Two ways to call a law: `ss_sphere_sphere_*` on the shared, read-only `ss_law_*` handle (any
//! thread), or `ss_bound_sphere_sphere_*` on an `ss_bound_law_*` made from it, one per thread,
//! which reuses what the previous call derived (the pair's oscillator, the wall) and so suits an
//! engine's loop over its neighbour list. Both give the same bits.
//!
//! The laws are listed once (`registry.rs`): the handles, their dispatch, the constructors, the
//! table kinds and the names (`ss_model_name`, `ss_model_of_name`, `names.rs`) follow from that
//! list. A material table and a whole neighbour list per call: `ss_table_*` (`table.rs`).
//!
//! The header `include/soft_sphere.h` is generated from `src/` by cbindgen; the test
//! `header_is_current` fails when it is stale (`UPDATE_HEADER=1 cargo test -p soft-sphere-ffi`
//! rewrites it).

#![allow(non_camel_case_types)] // C names: ss_law_f64, ss_sphere_f32, ...

#[macro_use]
mod registry;
mod names;
pub mod table;

pub use names::{
    ss_contact_error_text, ss_model_code, ss_model_count, ss_model_is_hertz, ss_model_name,
    ss_model_of_name, ss_parameter_error_text, ss_parameter_name,
};

pub use table::{
    SS_ERR_INDEX, SS_ERR_LENGTH, SS_ERR_MATERIAL, SS_ERR_NOT_PREPARED, SS_MATERIALS_MAX,
    SS_ROLLING_EPSD, SS_ROLLING_NONE, ss_atoms, ss_coefficients, ss_history, ss_list_report,
    ss_loads, ss_neighbours, ss_table, ss_table_config, ss_table_report, ss_walls,
};

use registry::{AnyBound, AnyLaw, hertz_family};
use soft_sphere::batch::{ContactBlock, LANES, PairBlock, SphereLanes};
use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::{
    BoundLaw, CheckedSphere, ContactError, ContactLaw, ContactState, Float, Frictionless, Hertz,
    HertzImpact, Interaction, Law, LinearSpringDashpot, Material, MathBackend, MicroSlipSprings,
    MindlinSpring, Parameter, ParameterError, RollingSpring, Sphere, SpringDisplacement, Std,
    TimeStep, Vec3, Wall,
};

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
/// A position, velocity, radius or mass is not finite.
pub const SS_ERR_NON_FINITE_INPUT: i32 = 8;
/// A radius is not positive.
pub const SS_ERR_NON_POSITIVE_RADIUS: i32 = 9;
/// A mass is not positive.
pub const SS_ERR_NON_POSITIVE_MASS: i32 = 10;
/// The two centres coincide.
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

/// The stateless (simplified) law: no tangential history is read or written.
pub const SS_MODEL_STATELESS: i32 = 0;
/// Model AA: stored tangential spring limited to `mu |F_n| / k_t`.
pub const SS_MODEL_AA: i32 = 1;
/// Model AA with Luding's reset: after sliding, spring plus dashpot equal the sliding force.
pub const SS_MODEL_AA_LUDING: i32 = 2;
/// No friction: normal force only (no tangential force, no torque, no state).
pub const SS_MODEL_FRICTIONLESS: i32 = 3;
/// Hertz, no friction.
pub const SS_MODEL_HERTZ_FRICTIONLESS: i32 = 4;
/// Hertz with the stateless Mindlin law.
pub const SS_MODEL_HERTZ_STATELESS: i32 = 5;
/// Hertz with Mindlin's stored spring and Model AA's cap.
pub const SS_MODEL_HERTZ_AA: i32 = 6;
/// Hertz with Mindlin's stored spring and Luding's reset.
pub const SS_MODEL_HERTZ_AA_LUDING: i32 = 7;
/// Hertz with Mindlin & Deresiewicz's micro-slip on `SS_MICROSLIP_SPRINGS` springs: material
/// tables only (`ss_table_*`; its state, `3 SS_MICROSLIP_SPRINGS + 4` numbers per contact, does
/// not fit `ss_state`, so `ss_law_new_*` answers `SS_ERR_UNKNOWN_MODEL`).
pub const SS_MODEL_HERTZ_MICROSLIP: i32 = 8;
/// Springs across the contact radius of `SS_MODEL_HERTZ_MICROSLIP`.
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
fn rejected_parameter(error: ParameterError) -> i32 {
    let parameter = match error {
        ParameterError::NonFinite(p)
        | ParameterError::NotPositive(p)
        | ParameterError::Negative(p) => p,
        ParameterError::RestitutionOutOfRange | ParameterError::ReboundUnreachable { .. } => {
            Parameter::Restitution
        }
        ParameterError::TimeStepUnstable { .. } => Parameter::TimeStep,
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

fn parameter_code(error: ParameterError) -> i32 {
    match error {
        ParameterError::NonFinite(_) => SS_ERR_NON_FINITE_PARAMETER,
        ParameterError::NotPositive(_) => SS_ERR_NOT_POSITIVE,
        ParameterError::Negative(_) => SS_ERR_NEGATIVE,
        ParameterError::RestitutionOutOfRange | ParameterError::ReboundUnreachable { .. } => {
            SS_ERR_RESTITUTION
        }
        ParameterError::TimeStepUnstable { .. } => SS_ERR_UNSTABLE_TIME_STEP,
        ParameterError::PoissonRatioOutOfRange => SS_ERR_POISSON_RATIO,
    }
}

fn contact_code(error: ContactError) -> i32 {
    match error {
        ContactError::NonFiniteInput => SS_ERR_NON_FINITE_INPUT,
        ContactError::NonPositiveRadius => SS_ERR_NON_POSITIVE_RADIUS,
        ContactError::NonPositiveMass => SS_ERR_NON_POSITIVE_MASS,
        ContactError::CoincidentCentres => SS_ERR_COINCIDENT_CENTRES,
        ContactError::PastStableStep => SS_ERR_PAST_STABLE_STEP,
        _ => SS_ERR_NON_FINITE_RESULT,
    }
}

/// A vector of three components.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct ss_vec3<F> {
    /// x
    pub x: F,
    /// y
    pub y: F,
    /// z
    pub z: F,
}

impl<F: Float> From<ss_vec3<F>> for Vec3<F> {
    fn from(v: ss_vec3<F>) -> Self {
        Vec3::new(v.x, v.y, v.z)
    }
}

impl<F: Float> From<Vec3<F>> for ss_vec3<F> {
    fn from(v: Vec3<F>) -> Self {
        Self {
            x: v.x,
            y: v.y,
            z: v.z,
        }
    }
}

/// A sphere: SI units; `angular_velocity` in rad/s.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct ss_sphere<F> {
    /// Centre (m).
    pub position: ss_vec3<F>,
    /// Velocity (m/s).
    pub velocity: ss_vec3<F>,
    /// Angular velocity (rad/s).
    pub angular_velocity: ss_vec3<F>,
    /// Radius (m).
    pub radius: F,
    /// Mass (kg).
    pub mass: F,
}

impl<F: Float> From<ss_sphere<F>> for Sphere<F> {
    fn from(s: ss_sphere<F>) -> Self {
        Sphere {
            position: s.position.into(),
            velocity: s.velocity.into(),
            angular_velocity: s.angular_velocity.into(),
            radius: s.radius,
            mass: s.mass,
        }
    }
}

/// A plane wall through `point` with outward `normal` (any length), moving at `velocity`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct ss_wall<F> {
    /// A point on the plane (m).
    pub point: ss_vec3<F>,
    /// The side the spheres are on.
    pub normal: ss_vec3<F>,
    /// Wall velocity (m/s).
    pub velocity: ss_vec3<F>,
}

/// Law parameters, validated once by the constructor.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct ss_params<F> {
    /// `SS_MODEL_STATELESS`, `SS_MODEL_AA`, `SS_MODEL_AA_LUDING` or `SS_MODEL_FRICTIONLESS` (which
    /// ignores the tangential parameters).
    pub model: i32,
    /// k_n (N/m).
    pub normal_stiffness: F,
    /// Normal restitution e, in [0, 1].
    pub restitution: F,
    /// k_t (N/m).
    pub tangential_stiffness: F,
    /// The dashpot ratio eta_t / eta_n.
    pub dashpot_ratio: F,
    /// Coulomb mu.
    pub friction: F,
    /// The time step (s) every call will use.
    pub time_step: F,
    /// The smallest effective mass of any contact the step is checked for (kg).
    pub smallest_effective_mass: F,
    /// `SS_MODEL_HERTZ_*`: Hertz's effective modulus `E*` (Pa), in place of `normal_stiffness`.
    pub effective_modulus: F,
    /// `SS_MODEL_HERTZ_*` with friction: Mindlin's effective shear modulus `G*` (Pa), in place of
    /// `tangential_stiffness`.
    pub effective_shear_modulus: F,
    /// `SS_MODEL_HERTZ_*`: the fastest normal approach the time step is checked for (m/s).
    pub largest_impact_speed: F,
    /// `SS_MODEL_HERTZ_*`: the largest effective radius `R*` the time step is checked for (m).
    pub largest_effective_radius: F,
}

/// An elastic material, for `ss_effective_moduli_*`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct ss_material<F> {
    /// Young's modulus (Pa).
    pub youngs_modulus: F,
    /// Poisson's ratio, in (-1, 0.5].
    pub poisson_ratio: F,
}

/// Per-contact state, owned by the caller: zero for a new contact.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct ss_state<F> {
    /// Stored tangential displacement (m) of `SS_MODEL_AA` and `SS_MODEL_AA_LUDING`.
    pub displacement: ss_vec3<F>,
    /// Stored tangential spring force (N) of `SS_MODEL_HERTZ_AA` and `SS_MODEL_HERTZ_AA_LUDING`.
    pub spring_force: ss_vec3<F>,
    /// The contact radius (m) at which `SS_MODEL_HERTZ_AA*` last updated `spring_force`.
    pub contact_radius: F,
}

/// The result of one contact evaluation. Forces act on j (on the sphere, for a wall); i receives
/// the negative.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct ss_forces<F> {
    /// 1 when touching; 0 when apart (then every other field is zero).
    pub touching: i32,
    /// 1 when the contact slid this step.
    pub sliding: i32,
    /// Overlap (m).
    pub overlap: F,
    /// Normal force magnitude (N), positive when repulsive.
    pub normal_force: F,
    /// Total contact force on j (N).
    pub force_on_j: ss_vec3<F>,
    /// Torque on i (N m).
    pub torque_on_i: ss_vec3<F>,
    /// Torque on j (N m).
    pub torque_on_j: ss_vec3<F>,
}

/// A validated contact law and its checked time step (opaque to C).
#[derive(Debug)]
pub struct ss_law<F: Float> {
    law: AnyLaw<F>,
    time_step: TimeStep<F>,
}

fn build_law<F: Float>(p: &ss_params<F>) -> Result<ss_law<F>, i32> {
    checked_law(p).map_err(|(code, _)| code)
}

/// The law `*p` describes, or the error code and the `SS_PARAMETER_*` it is about.
fn checked_law<F: Float>(p: &ss_params<F>) -> Result<ss_law<F>, (i32, i32)> {
    let Some(law) = AnyLaw::new(p) else {
        return Err((SS_ERR_UNKNOWN_MODEL, SS_PARAMETER_MODEL));
    };
    let refused = |e| (parameter_code(e), rejected_parameter(e));
    let law = law.map_err(refused)?;
    let time_step = law.time_step(p).map_err(refused)?;
    Ok(ss_law { law, time_step })
}

/// The stability limit of the law `*params` describes, for its smallest effective mass: what a
/// host reports when `SS_ERR_UNSTABLE_TIME_STEP` refuses its step.
fn limit_of<F: Float>(p: &ss_params<F>) -> Result<F, i32> {
    let probe = ss_params {
        time_step: F::MIN_POSITIVE,
        ..*p
    };
    let law = build_law(&probe)?;
    let m = p.smallest_effective_mass;
    Ok(each_law!(law.law, AnyLaw, l => l.critical_time_step(m)))
}

/// # Safety
/// As the exported constructors.
unsafe fn law_new<F: Float>(params: *const ss_params<F>, out: *mut *mut ss_law<F>) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(p), false) = (unsafe { params.as_ref() }, out.is_null()) else {
        return SS_ERR_NULL;
    };
    match build_law(p) {
        Ok(law) => {
            // SAFETY: out was checked non-null.
            unsafe { *out = Box::into_raw(Box::new(law)) };
            SS_OK
        }
        Err(code) => code,
    }
}

/// # Safety
/// As the exported destructors.
unsafe fn law_free<F: Float>(law: *mut ss_law<F>) {
    if !law.is_null() {
        // SAFETY: the handle came from Box::into_raw in law_new.
        drop(unsafe { Box::from_raw(law) });
    }
}

/// How a law's per-contact state is kept flat, as numbers in a host's per-neighbour history
/// (the list entry's).
trait Flat<F: Float>: ContactState {
    /// How many numbers the state is when kept flat.
    const VALUES: usize;
    /// The state from its `VALUES` flat numbers.
    fn read(values: &[F]) -> Self;
    /// The state into its `VALUES` flat numbers.
    fn write(&self, values: &mut [F]);
    /// The same contact's state seen from the other body (i and j swapped).
    fn mirrored(&self) -> Self;
}

/// How a law's per-contact state sits in the caller's [`ss_state`] (the single-contact calls').
trait Stored<F: Float>: Flat<F> {
    /// Which of `ss_state_arrays`' arrays the batch call needs for this state.
    const ARRAYS: StateArrays;
    fn load(state: &ss_state<F>) -> Self;
    fn store(&self, state: &mut ss_state<F>);
}

/// The arrays a law's state lives in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum StateArrays {
    None,
    Displacement,
    Mindlin,
}

/// The normal, the contact radius, then each spring's displacement.
impl<F: Float, const SPRINGS: usize> Flat<F> for MicroSlipSprings<F, SPRINGS> {
    const VALUES: usize = 3 * SPRINGS + 4;
    fn read(values: &[F]) -> Self {
        let vector = |k: usize| Vec3::new(values[k], values[k + 1], values[k + 2]);
        let mut springs = MicroSlipSprings {
            normal: vector(0),
            contact_radius: values[3],
            ..Default::default()
        };
        for (k, u) in springs.displacements.iter_mut().enumerate() {
            *u = vector(4 + 3 * k);
        }
        springs
    }
    fn write(&self, values: &mut [F]) {
        let n = self.normal;
        values[..4].copy_from_slice(&[n.x, n.y, n.z, self.contact_radius]);
        for (k, u) in self.displacements.iter().enumerate() {
            values[4 + 3 * k..7 + 3 * k].copy_from_slice(&[u.x, u.y, u.z]);
        }
    }
    /// Seen from the other body the normal and every displacement are negated.
    fn mirrored(&self) -> Self {
        let mut springs = *self;
        springs.normal = -self.normal;
        for u in &mut springs.displacements {
            *u = -*u;
        }
        springs
    }
}

impl<F: Float> Flat<F> for () {
    const VALUES: usize = 0;
    #[inline(always)]
    fn read(_: &[F]) -> Self {}
    #[inline(always)]
    fn write(&self, _: &mut [F]) {}
    fn mirrored(&self) -> Self {}
}

impl<F: Float> Stored<F> for () {
    const ARRAYS: StateArrays = StateArrays::None;
    #[inline(always)]
    fn load(_: &ss_state<F>) -> Self {}
    #[inline(always)]
    fn store(&self, _: &mut ss_state<F>) {}
}

impl<F: Float> Flat<F> for SpringDisplacement<F> {
    const VALUES: usize = 3;
    #[inline(always)]
    fn read(values: &[F]) -> Self {
        SpringDisplacement {
            displacement: Vec3::new(values[0], values[1], values[2]),
        }
    }
    #[inline(always)]
    fn write(&self, values: &mut [F]) {
        let d = self.displacement;
        values[..3].copy_from_slice(&[d.x, d.y, d.z]);
    }
    /// The displacement of j relative to i: negated.
    fn mirrored(&self) -> Self {
        SpringDisplacement {
            displacement: -self.displacement,
        }
    }
}

impl<F: Float> Stored<F> for SpringDisplacement<F> {
    const ARRAYS: StateArrays = StateArrays::Displacement;
    #[inline(always)]
    fn load(state: &ss_state<F>) -> Self {
        SpringDisplacement {
            displacement: state.displacement.into(),
        }
    }
    #[inline(always)]
    fn store(&self, state: &mut ss_state<F>) {
        state.displacement = self.displacement.into();
    }
}

impl<F: Float> Flat<F> for MindlinSpring<F> {
    const VALUES: usize = 4;
    #[inline(always)]
    fn read(values: &[F]) -> Self {
        MindlinSpring {
            force: Vec3::new(values[0], values[1], values[2]),
            contact_radius: values[3],
        }
    }
    #[inline(always)]
    fn write(&self, values: &mut [F]) {
        let f = self.force;
        values[..4].copy_from_slice(&[f.x, f.y, f.z, self.contact_radius]);
    }
    /// The spring's force on j becomes the force on i: negated; the contact radius stays.
    fn mirrored(&self) -> Self {
        MindlinSpring {
            force: -self.force,
            contact_radius: self.contact_radius,
        }
    }
}

impl<F: Float> Stored<F> for MindlinSpring<F> {
    const ARRAYS: StateArrays = StateArrays::Mindlin;
    #[inline(always)]
    fn load(state: &ss_state<F>) -> Self {
        MindlinSpring {
            force: state.spring_force.into(),
            contact_radius: state.contact_radius,
        }
    }
    #[inline(always)]
    fn store(&self, state: &mut ss_state<F>) {
        state.spring_force = self.force.into();
        state.contact_radius = self.contact_radius;
    }
}

/// The rolling spring beside a tangential state: its torque on i after the tangential numbers
/// (the list entry's flat history only; the single-contact calls have no rolling).
impl<F: Float, S: Flat<F>> Flat<F> for RollingSpring<S, F> {
    const VALUES: usize = S::VALUES + 3;
    #[inline(always)]
    fn read(values: &[F]) -> Self {
        let (tangential, torque) = values.split_at(S::VALUES);
        RollingSpring {
            tangential: S::read(tangential),
            torque: Vec3::new(torque[0], torque[1], torque[2]),
        }
    }
    #[inline(always)]
    fn write(&self, values: &mut [F]) {
        let (tangential, torque) = values.split_at_mut(S::VALUES);
        self.tangential.write(tangential);
        let t = self.torque;
        torque[..3].copy_from_slice(&[t.x, t.y, t.z]);
    }
    /// The torque on i becomes the torque on j: negated.
    fn mirrored(&self) -> Self {
        RollingSpring {
            tangential: self.tangential.mirrored(),
            torque: -self.torque,
        }
    }
}

impl<F: Float, S: Stored<F>> Stored<F> for RollingSpring<S, F> {
    const ARRAYS: StateArrays = S::ARRAYS;
    fn load(state: &ss_state<F>) -> Self {
        RollingSpring {
            tangential: S::load(state),
            torque: Vec3::ZERO,
        }
    }
    fn store(&self, state: &mut ss_state<F>) {
        self.tangential.store(state);
    }
}

/// Evaluates `$call` on the law's state loaded from `*$state` (bound to `$s`); on success stores
/// the state back and writes `*$out`, on error leaves both as they were and gives the error's
/// code. A macro, not a function taking a closure: a closure is not inlined across codegen units,
/// and the call's result would then pass through memory.
macro_rules! evaluated {
    ($state:expr, $out:expr, $s:ident => $call:expr) => {{
        let mut $s = Stored::load($state);
        let result = $call;
        finish(result, &$s, $state, $out)
    }};
}

#[inline(always)]
fn finish<F: Float, S: Stored<F>>(
    result: Result<Interaction<F>, ContactError>,
    stored: &S,
    state: &mut ss_state<F>,
    out: &mut ss_forces<F>,
) -> i32 {
    match result {
        Ok(interaction) => {
            stored.store(state);
            *out = forces_of(interaction);
            SS_OK
        }
        Err(e) => contact_code(e),
    }
}

#[inline(always)]
fn forces_of<F: Float>(interaction: Interaction<F>) -> ss_forces<F> {
    match interaction {
        Interaction::Apart => ss_forces {
            touching: 0,
            sliding: 0,
            overlap: F::ZERO,
            normal_force: F::ZERO,
            force_on_j: Vec3::ZERO.into(),
            torque_on_i: Vec3::ZERO.into(),
            torque_on_j: Vec3::ZERO.into(),
        },
        Interaction::Touching(c) => ss_forces {
            touching: 1,
            sliding: i32::from(c.sliding),
            overlap: c.overlap,
            normal_force: c.normal_force,
            force_on_j: c.force_on_j().into(),
            torque_on_i: c.torque_on_i.into(),
            torque_on_j: c.torque_on_j.into(),
        },
    }
}

/// The kernel treats the sphere as body i against a wall: the C ABI reports its force as the one
/// on j, so that `force_on_j` and `torque_on_j` are always what the sphere receives.
#[inline(always)]
fn sphere_as_j<F: Float>(interaction: Interaction<F>) -> Interaction<F> {
    match interaction {
        Interaction::Touching(mut c) => {
            c.normal = -c.normal;
            c.tangential_force = -c.tangential_force;
            core::mem::swap(&mut c.torque_on_i, &mut c.torque_on_j);
            Interaction::Touching(c)
        }
        apart => apart,
    }
}

/// The kernel's wall for `*wall`, checked.
#[inline(always)]
fn plane_of<F: Float>(wall: &ss_wall<F>) -> Result<Wall<F>, i32> {
    Wall::new(wall.point.into(), wall.normal.into())
        .and_then(|plane| plane.with_velocity(wall.velocity.into()))
        .map_err(|_| SS_ERR_BAD_WALL)
}

/// # Safety
/// As the exported sphere-sphere calls.
unsafe fn pair<F: Float>(
    law: *const ss_law<F>,
    i: *const ss_sphere<F>,
    j: *const ss_sphere<F>,
    state: *mut ss_state<F>,
    out: *mut ss_forces<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(law), Some(i), Some(j), Some(state), Some(out)) = (unsafe {
        (
            law.as_ref(),
            i.as_ref(),
            j.as_ref(),
            state.as_mut(),
            out.as_mut(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let (i, j): (Sphere<F>, Sphere<F>) = ((*i).into(), (*j).into());
    let dt = law.time_step;
    each_law!(&law.law, AnyLaw, l => evaluated!(state, out, s => l.sphere_sphere(&i, &j, &mut s, dt)))
}

/// # Safety
/// As the exported sphere-wall calls.
unsafe fn on_wall<F: Float>(
    law: *const ss_law<F>,
    sphere: *const ss_sphere<F>,
    wall: *const ss_wall<F>,
    state: *mut ss_state<F>,
    out: *mut ss_forces<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(law), Some(sphere), Some(wall), Some(state), Some(out)) = (unsafe {
        (
            law.as_ref(),
            sphere.as_ref(),
            wall.as_ref(),
            state.as_mut(),
            out.as_mut(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let plane = match plane_of(wall) {
        Ok(plane) => plane,
        Err(code) => return code,
    };
    let sphere: Sphere<F> = (*sphere).into();
    let dt = law.time_step;
    each_law!(&law.law, AnyLaw, l => evaluated!(state, out, s => {
        l.sphere_wall(&sphere, &plane, &mut s, dt).map(sphere_as_j)
    }))
}

/// A law bound to its time step, for one thread's run of calls (opaque to C). It remembers the
/// normal oscillator of the last pair of masses and the last wall it checked, so a host that
/// calls it over a neighbour list derives each once; the results are the same bits as the
/// `ss_law` entry points'.
#[derive(Debug)]
pub struct ss_bound_law<F: Float> {
    bound: AnyBound<F>,
    /// The last wall that passed its checks, as given and as checked.
    wall: Option<(ss_wall<F>, Wall<F>)>,
}

/// The same bits, so that a memo keyed on them gives what a fresh check would (-0.0 and 0.0
/// differ; a NaN never passes the check, so it is never a key).
fn same_wall<F: Float>(a: &ss_wall<F>, b: &ss_wall<F>) -> bool {
    let bits = |w: &ss_wall<F>| {
        [w.point, w.normal, w.velocity].map(|v| [v.x, v.y, v.z].map(|x| x.to_f64().to_bits()))
    };
    bits(a) == bits(b)
}

/// # Safety
/// As the exported bound-law constructors.
unsafe fn bound_new<F: Float>(law: *const ss_law<F>, out: *mut *mut ss_bound_law<F>) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(law), false) = (unsafe { law.as_ref() }, out.is_null()) else {
        return SS_ERR_NULL;
    };
    let bound = law.law.at(law.time_step);
    let handle = ss_bound_law { bound, wall: None };
    // SAFETY: out was checked non-null.
    unsafe { *out = Box::into_raw(Box::new(handle)) };
    SS_OK
}

/// # Safety
/// As the exported bound-law destructors.
unsafe fn bound_free<F: Float>(bound: *mut ss_bound_law<F>) {
    if bound.is_null() {
        return;
    }
    // SAFETY: the handle came from Box::into_raw in bound_new.
    drop(unsafe { Box::from_raw(bound) });
}

/// # Safety
/// As the exported bound sphere-sphere calls.
unsafe fn bound_pair<F: Float>(
    bound: *mut ss_bound_law<F>,
    i: *const ss_sphere<F>,
    j: *const ss_sphere<F>,
    state: *mut ss_state<F>,
    out: *mut ss_forces<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(bound), Some(i), Some(j), Some(state), Some(out)) = (unsafe {
        (
            bound.as_mut(),
            i.as_ref(),
            j.as_ref(),
            state.as_mut(),
            out.as_mut(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    // One sphere at a time: a tuple of two results is copied through memory, a measurable cost
    // per call.
    let i = match CheckedSphere::new((*i).into()) {
        Ok(i) => i,
        Err(e) => return contact_code(e),
    };
    let j = match CheckedSphere::new((*j).into()) {
        Ok(j) => j,
        Err(e) => return contact_code(e),
    };
    each_law!(&mut bound.bound, AnyBound, b => evaluated!(state, out, s => b.sphere_sphere(&i, &j, &mut s)))
}

/// # Safety
/// As the exported bound sphere-wall calls.
unsafe fn bound_wall<F: Float>(
    bound: *mut ss_bound_law<F>,
    sphere: *const ss_sphere<F>,
    wall: *const ss_wall<F>,
    state: *mut ss_state<F>,
    out: *mut ss_forces<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(bound), Some(sphere), Some(wall), Some(state), Some(out)) = (unsafe {
        (
            bound.as_mut(),
            sphere.as_ref(),
            wall.as_ref(),
            state.as_mut(),
            out.as_mut(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let plane = match bound.wall {
        Some((given, plane)) if same_wall(&given, wall) => plane,
        _ => match plane_of(wall) {
            Ok(plane) => {
                bound.wall = Some((*wall, plane));
                plane
            }
            Err(code) => return code,
        },
    };
    let sphere = match CheckedSphere::new((*sphere).into()) {
        Ok(sphere) => sphere,
        Err(e) => return contact_code(e),
    };
    each_law!(&mut bound.bound, AnyBound, b => evaluated!(state, out, s => {
        b.sphere_wall(&sphere, &plane, &mut s).map(sphere_as_j)
    }))
}

/// Spheres as arrays, one pointer per field (structure of arrays): sphere `k` is element `k` of
/// every array. Every pointer must be valid for the call's `count` elements.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_sphere_arrays<F> {
    /// Centre x (m).
    pub position_x: *const F,
    /// Centre y (m).
    pub position_y: *const F,
    /// Centre z (m).
    pub position_z: *const F,
    /// Velocity x (m/s).
    pub velocity_x: *const F,
    /// Velocity y (m/s).
    pub velocity_y: *const F,
    /// Velocity z (m/s).
    pub velocity_z: *const F,
    /// Angular velocity x (rad/s).
    pub angular_velocity_x: *const F,
    /// Angular velocity y (rad/s).
    pub angular_velocity_y: *const F,
    /// Angular velocity z (rad/s).
    pub angular_velocity_z: *const F,
    /// Radius (m).
    pub radius: *const F,
    /// Mass (kg).
    pub mass: *const F,
}

/// Per-contact states as arrays: element `k` holds what `ss_state_*` holds for pair `k`. A law
/// reads only its own arrays (`SS_MODEL_AA*`: the displacement; `SS_MODEL_HERTZ_AA*`: the spring
/// force and the contact radius); the others, and all of them for the stateless and frictionless
/// laws, may be null.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_state_arrays<F> {
    /// Displacement x.
    pub displacement_x: *mut F,
    /// Displacement y.
    pub displacement_y: *mut F,
    /// Displacement z.
    pub displacement_z: *mut F,
    /// Spring force x.
    pub spring_force_x: *mut F,
    /// Spring force y.
    pub spring_force_y: *mut F,
    /// Spring force z.
    pub spring_force_z: *mut F,
    /// Contact radius.
    pub contact_radius: *mut F,
}

/// What a batch call writes, as arrays: element `k` of each holds what `ss_forces_*` holds for
/// pair `k`, and `status[k]` that pair's code (`SS_OK` or the error the single call gives).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_forces_arrays<F> {
    /// Each pair's code: `SS_OK`, or the error code of `ss_bound_sphere_sphere_*` for it.
    pub status: *mut i32,
    /// 1 when touching, 0 when apart.
    pub touching: *mut i32,
    /// 1 when the contact slid.
    pub sliding: *mut i32,
    /// Overlap (m).
    pub overlap: *mut F,
    /// Normal force (N).
    pub normal_force: *mut F,
    /// Force on j, x (N).
    pub force_on_j_x: *mut F,
    /// Force on j, y (N).
    pub force_on_j_y: *mut F,
    /// Force on j, z (N).
    pub force_on_j_z: *mut F,
    /// Torque on i, x (N m).
    pub torque_on_i_x: *mut F,
    /// Torque on i, y (N m).
    pub torque_on_i_y: *mut F,
    /// Torque on i, z (N m).
    pub torque_on_i_z: *mut F,
    /// Torque on j, x (N m).
    pub torque_on_j_x: *mut F,
    /// Torque on j, y (N m).
    pub torque_on_j_y: *mut F,
    /// Torque on j, z (N m).
    pub torque_on_j_z: *mut F,
}

/// `count` elements at `pointer`, or `None` for null.
///
/// # Safety
/// A non-null pointer must be valid for `count` reads.
unsafe fn read<'a, F>(pointer: *const F, count: usize) -> Option<&'a [F]> {
    // SAFETY: null is checked; the caller promises validity otherwise.
    (!pointer.is_null()).then(|| unsafe { core::slice::from_raw_parts(pointer, count) })
}

/// `count` elements at `pointer` to write, or `None` for null.
///
/// # Safety
/// A non-null pointer must be valid for `count` writes and overlap nothing else of the call.
unsafe fn write<'a, F>(pointer: *mut F, count: usize) -> Option<&'a mut [F]> {
    // SAFETY: null is checked; the caller promises validity otherwise.
    (!pointer.is_null()).then(|| unsafe { core::slice::from_raw_parts_mut(pointer, count) })
}

/// The spheres' arrays as slices, or `None` if one is null.
///
/// # Safety
/// As [`read`], for every field.
unsafe fn sphere_slices<'a, F>(s: &ss_sphere_arrays<F>, count: usize) -> Option<[&'a [F]; 11]> {
    let fields = [
        s.position_x,
        s.position_y,
        s.position_z,
        s.velocity_x,
        s.velocity_y,
        s.velocity_z,
        s.angular_velocity_x,
        s.angular_velocity_y,
        s.angular_velocity_z,
        s.radius,
        s.mass,
    ];
    let mut slices = [&[][..]; 11];
    for (slice, pointer) in slices.iter_mut().zip(fields) {
        // SAFETY: forwarded contract.
        *slice = unsafe { read(pointer, count) }?;
    }
    Some(slices)
}

/// The eleven field arrays of [`ss_sphere_arrays`], in its order.
type SphereSlices<'a, F> = [&'a [F]; 11];

/// Sphere `k` of the arrays.
#[inline(always)]
fn sphere_at<F: Float>(s: &[&[F]; 11], k: usize) -> Sphere<F> {
    Sphere {
        position: Vec3::new(s[0][k], s[1][k], s[2][k]),
        velocity: Vec3::new(s[3][k], s[4][k], s[5][k]),
        angular_velocity: Vec3::new(s[6][k], s[7][k], s[8][k]),
        radius: s[9][k],
        mass: s[10][k],
    }
}

/// A batch call's outputs, as slices.
struct Outputs<'a, F> {
    status: &'a mut [i32],
    flags: [&'a mut [i32]; 2],
    reals: [&'a mut [F]; 11],
}

impl<'a, F: Float> Outputs<'a, F> {
    /// The arrays of `*out`, or `None` if one is null.
    ///
    /// # Safety
    /// As [`write`], for every field.
    unsafe fn of(out: &ss_forces_arrays<F>, count: usize) -> Option<Self> {
        let reals = [
            out.overlap,
            out.normal_force,
            out.force_on_j_x,
            out.force_on_j_y,
            out.force_on_j_z,
            out.torque_on_i_x,
            out.torque_on_i_y,
            out.torque_on_i_z,
            out.torque_on_j_x,
            out.torque_on_j_y,
            out.torque_on_j_z,
        ];
        // SAFETY (all three): forwarded contract.
        let [Some(a), Some(b)] = [out.touching, out.sliding].map(|p| unsafe { write(p, count) })
        else {
            return None;
        };
        let reals = reals.map(|p| unsafe { write(p, count) });
        if reals.iter().any(Option::is_none) {
            return None;
        }
        Some(Self {
            status: unsafe { write(out.status, count) }?,
            flags: [a, b],
            reals: reals.map(Option::unwrap_or_default),
        })
    }

    /// A block of `N` pairs from `start`, every one of them a success: what [`Outputs::set`]
    /// writes for each.
    #[inline(always)]
    fn set_block<const N: usize>(&mut self, start: usize, block: &ContactBlock<F, N>) {
        for lane in 0..N {
            let (f, a, b) = (
                block.force_on_j(lane),
                block.torque_on_i.get(lane),
                block.torque_on_j.get(lane),
            );
            let (touching, sliding) = (block.touching(lane), block.sliding[lane]);
            let scalars = [block.overlap[lane], block.normal_force[lane]];
            self.write(
                start + lane,
                scalars,
                [f, a, b],
                [touching, sliding].map(i32::from),
            );
        }
    }

    /// Pair `k`'s result: its forces on success, only its code on error.
    #[inline(always)]
    fn set(&mut self, k: usize, result: Result<Interaction<F>, ContactError>) {
        match result {
            Ok(interaction) => {
                let f = forces_of(interaction);
                let vectors = [f.force_on_j, f.torque_on_i, f.torque_on_j].map(Vec3::from);
                self.write(
                    k,
                    [f.overlap, f.normal_force],
                    vectors,
                    [f.touching, f.sliding],
                );
            }
            Err(e) => self.status[k] = contact_code(e),
        }
    }

    /// A successful pair `k`: overlap and normal force, force on j and the two torques, and the
    /// touching and sliding flags, in the order of [`ss_forces_arrays`].
    #[inline(always)]
    fn write(&mut self, k: usize, scalars: [F; 2], vectors: [Vec3<F>; 3], flags: [i32; 2]) {
        let [overlap, normal_force] = scalars;
        let [f, a, b] = vectors;
        let values = [
            overlap,
            normal_force,
            f.x,
            f.y,
            f.z,
            a.x,
            a.y,
            a.z,
            b.x,
            b.y,
            b.z,
        ];
        for (array, value) in self.reals.iter_mut().zip(values) {
            array[k] = value;
        }
        self.flags[0][k] = flags[0];
        self.flags[1][k] = flags[1];
        self.status[k] = SS_OK;
    }
}

/// A batch call's states, as slices: the displacement's and the Mindlin spring's (`None` where
/// the caller gave null).
struct States<'a, F> {
    displacement: Option<[&'a mut [F]; 3]>,
    mindlin: Option<[&'a mut [F]; 4]>,
}

impl<F: Float> States<'_, F> {
    /// Whether the arrays a state of kind `arrays` lives in were given.
    fn has(&self, arrays: StateArrays) -> bool {
        match arrays {
            StateArrays::None => true,
            StateArrays::Displacement => self.displacement.is_some(),
            StateArrays::Mindlin => self.mindlin.is_some(),
        }
    }

    #[inline(always)]
    fn load<S: Stored<F>>(&self, k: usize) -> S {
        let mut state = ss_state::default();
        if let Some([x, y, z]) = &self.displacement {
            state.displacement = ss_vec3 {
                x: x[k],
                y: y[k],
                z: z[k],
            };
        }
        if let Some([x, y, z, a]) = &self.mindlin {
            state.spring_force = ss_vec3 {
                x: x[k],
                y: y[k],
                z: z[k],
            };
            state.contact_radius = a[k];
        }
        S::load(&state)
    }

    #[inline(always)]
    fn store<S: Stored<F>>(&mut self, k: usize, state: &S) {
        let mut out = ss_state::default();
        state.store(&mut out);
        match S::ARRAYS {
            StateArrays::None => {}
            StateArrays::Displacement => {
                if let Some([x, y, z]) = &mut self.displacement {
                    let d = out.displacement;
                    (x[k], y[k], z[k]) = (d.x, d.y, d.z);
                }
            }
            StateArrays::Mindlin => {
                if let Some([x, y, z, a]) = &mut self.mindlin {
                    let f = out.spring_force;
                    (x[k], y[k], z[k], a[k]) = (f.x, f.y, f.z, out.contact_radius);
                }
            }
        }
    }
}

/// The pairs in blocks of [`LANES`] through the kernel's batch path (`Std` square roots: the
/// same bits as the single calls'), each pair's state and result written back in order; one at
/// a time where the kernel says blocks do not pay ([`Law::VECTORISES`]).
#[inline(always)]
fn in_blocks<L: Law>(
    bound: &mut BoundLaw<L>,
    (i, j): (&SphereSlices<'_, L::Float>, &SphereSlices<'_, L::Float>),
    states: &mut States<'_, L::Float>,
    out: &mut Outputs<'_, L::Float>,
) where
    L::State: Stored<L::Float>,
{
    let count = out.status.len();
    if !L::VECTORISES {
        // Blocks would not pay in this build (Law::VECTORISES): one pair at a time, the same bits.
        for k in 0..count {
            let mut state = states.load(k);
            let result = CheckedSphere::new(sphere_at(i, k)).and_then(|a| {
                let b = CheckedSphere::new(sphere_at(j, k))?;
                bound.sphere_sphere(&a, &b, &mut state)
            });
            if result.is_ok() {
                states.store(k, &state);
            }
            out.set(k, result);
        }
        return;
    }
    let mut block = PairBlock::<L::Float, LANES>::default();
    let mut results = ContactBlock::default();
    for start in (0..count).step_by(LANES) {
        let lanes = LANES.min(count - start);
        let mut lane_states = [L::State::default(); LANES];
        if lanes == LANES {
            // Array to array, a vector at a time.
            fill(&mut block.i, i, start);
            fill(&mut block.j, j, start);
        }
        for (lane, state) in lane_states.iter_mut().enumerate() {
            // Unused lanes repeat the last pair and are ignored.
            let k = start + lane.min(lanes - 1);
            if lanes < LANES {
                block.set(lane, &sphere_at(i, k), &sphere_at(j, k));
            }
            *state = states.load(k);
        }
        bound.sphere_pairs(&block, &mut lane_states, &mut results);
        let all_ok = (0..lanes).all(|lane| results.outcome(lane).is_ok());
        if all_ok && lanes == LANES {
            out.set_block(start, &results);
            for (lane, state) in lane_states.iter().enumerate() {
                states.store(start + lane, state);
            }
            continue;
        }
        for (lane, state) in lane_states.iter().enumerate().take(lanes) {
            let result = results.outcome(lane);
            if result.is_ok() {
                states.store(start + lane, state);
            }
            out.set(start + lane, result);
        }
    }
}

/// Lanes `start..start + N` of the spheres' arrays into a block.
#[inline(always)]
fn fill<F: Float, const N: usize>(
    lanes: &mut SphereLanes<F, N>,
    s: &SphereSlices<'_, F>,
    start: usize,
) {
    let columns = [
        &mut lanes.position.x,
        &mut lanes.position.y,
        &mut lanes.position.z,
        &mut lanes.velocity.x,
        &mut lanes.velocity.y,
        &mut lanes.velocity.z,
        &mut lanes.angular_velocity.x,
        &mut lanes.angular_velocity.y,
        &mut lanes.angular_velocity.z,
        &mut lanes.radius,
        &mut lanes.mass,
    ];
    for (column, array) in columns.into_iter().zip(s) {
        column.copy_from_slice(&array[start..start + N]);
    }
}

/// The arrays the bound law's per-contact state lives in.
fn state_arrays<L: Law>(_: &BoundLaw<L>) -> StateArrays
where
    L::State: Stored<L::Float>,
{
    <L::State as Stored<L::Float>>::ARRAYS
}

/// # Safety
/// As the exported batch calls.
unsafe fn bound_pairs<F: Float>(
    bound: *mut ss_bound_law<F>,
    count: usize,
    i: *const ss_sphere_arrays<F>,
    j: *const ss_sphere_arrays<F>,
    states: *const ss_state_arrays<F>,
    out: *const ss_forces_arrays<F>,
) -> i32
where
    Std: MathBackend<F>,
{
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(bound), Some(i), Some(j), Some(states), Some(out)) = (unsafe {
        (
            bound.as_mut(),
            i.as_ref(),
            j.as_ref(),
            states.as_ref(),
            out.as_ref(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    // SAFETY (all below): the caller promises each array valid for `count` elements and the
    // written ones disjoint from each other and from the inputs.
    let (Some(i), Some(j), Some(mut out)) = (unsafe {
        (
            sphere_slices(i, count),
            sphere_slices(j, count),
            Outputs::of(out, count),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let displacement = [
        states.displacement_x,
        states.displacement_y,
        states.displacement_z,
    ]
    .map(|p| unsafe { write(p, count) });
    let mindlin = [
        states.spring_force_x,
        states.spring_force_y,
        states.spring_force_z,
        states.contact_radius,
    ]
    .map(|p| unsafe { write(p, count) });
    let mut states = States {
        displacement: match displacement {
            [Some(x), Some(y), Some(z)] => Some([x, y, z]),
            _ => None,
        },
        mindlin: match mindlin {
            [Some(x), Some(y), Some(z), Some(a)] => Some([x, y, z, a]),
            _ => None,
        },
    };
    // A law that keeps a per-contact state needs its arrays.
    let needed = each_law!(&bound.bound, AnyBound, b => state_arrays(b));
    if !states.has(needed) {
        return SS_ERR_NULL;
    }
    each_law!(&bound.bound, AnyBound, b => {
        let law = b.law().with_backend::<Std>();
        in_blocks(&mut law.at(b.time_step()), (&i, &j), &mut states, &mut out)
    });
    SS_OK
}

/// # Safety
/// As the exported advance calls.
unsafe fn advance<F: Float>(
    law: *const ss_law<F>,
    sphere: *mut ss_sphere<F>,
    force: ss_vec3<F>,
    torque: ss_vec3<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(law), Some(sphere)) = (unsafe { (law.as_ref(), sphere.as_mut()) }) else {
        return SS_ERR_NULL;
    };
    let mut s: Sphere<F> = (*sphere).into();
    advance_solid_sphere(&mut s, force.into(), torque.into(), law.time_step);
    sphere.position = s.position.into();
    sphere.velocity = s.velocity.into();
    sphere.angular_velocity = s.angular_velocity.into();
    SS_OK
}

/// # Safety
/// As the exported duration calls.
unsafe fn duration<F: Float>(params: *const ss_params<F>, m_star: F, out: *mut F) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(p), Some(out)) = (unsafe { (params.as_ref(), out.as_mut()) }) else {
        return SS_ERR_NULL;
    };
    if !(m_star > F::ZERO && m_star.is_finite()) {
        return SS_ERR_NOT_POSITIVE;
    }
    let duration = if hertz_family(p.model) {
        let largest = HertzImpact {
            speed: p.largest_impact_speed,
            effective_radius: p.largest_effective_radius,
        };
        Hertz::new(p.effective_modulus, p.restitution, largest)
            .map(|normal| ContactLaw::new(normal, Frictionless).contact_duration(m_star))
    } else {
        LinearSpringDashpot::new(p.normal_stiffness, p.restitution)
            .map(|normal| ContactLaw::new(normal, Frictionless).contact_duration(m_star))
    };
    match duration {
        Ok(duration) => {
            *out = duration;
            SS_OK
        }
        Err(e) => parameter_code(e),
    }
}

/// # Safety
/// As the exported stability-limit calls.
unsafe fn stability_limit<F: Float>(params: *const ss_params<F>, out: *mut F) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(p), Some(out)) = (unsafe { (params.as_ref(), out.as_mut()) }) else {
        return SS_ERR_NULL;
    };
    match limit_of(p) {
        Ok(limit) => {
            *out = limit;
            SS_OK
        }
        Err(code) => code,
    }
}

/// # Safety
/// As the exported moduli calls.
unsafe fn moduli<F: Float>(
    i: *const ss_material<F>,
    j: *const ss_material<F>,
    effective_modulus: *mut F,
    effective_shear_modulus: *mut F,
) -> i32 {
    // SAFETY: null is checked (j may be null: a rigid body); the caller promises validity.
    let (Some(i), j, Some(e), Some(g)) = (unsafe {
        (
            i.as_ref(),
            j.as_ref(),
            effective_modulus.as_mut(),
            effective_shear_modulus.as_mut(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let material = |m: &ss_material<F>| Material::new(m.youngs_modulus, m.poisson_ratio);
    let result = material(i).and_then(|a| match j {
        Some(j) => material(j).map(|b| (a.effective_modulus(&b), a.effective_shear_modulus(&b))),
        None => Ok((a.modulus_against_rigid(), a.shear_modulus_against_rigid())),
    });
    match result {
        Ok((modulus, shear)) => {
            (*e, *g) = (modulus, shear);
            SS_OK
        }
        Err(error) => parameter_code(error),
    }
}

/// Hertz's `E*` and Mindlin's `G*` of a contact between materials `*i` and `*j` (`j` null: a
/// rigid body, such as a wall), for `ss_params_f64`. Returns `SS_OK`, `SS_ERR_NULL`, or the
/// material's error (`SS_ERR_NOT_POSITIVE`, `SS_ERR_NON_FINITE_PARAMETER`,
/// `SS_ERR_POISSON_RATIO`); the outputs are written only on success.
///
/// # Safety
/// Non-null pointers must be valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ss_effective_moduli_f64(
    i: *const ss_material<f64>,
    j: *const ss_material<f64>,
    effective_modulus: *mut f64,
    effective_shear_modulus: *mut f64,
) -> i32 {
    // SAFETY: forwarded.
    unsafe { moduli(i, j, effective_modulus, effective_shear_modulus) }
}

/// As `ss_effective_moduli_f64`, in f32.
///
/// # Safety
/// Non-null pointers must be valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ss_effective_moduli_f32(
    i: *const ss_material<f32>,
    j: *const ss_material<f32>,
    effective_modulus: *mut f32,
    effective_shear_modulus: *mut f32,
) -> i32 {
    // SAFETY: forwarded.
    unsafe { moduli(i, j, effective_modulus, effective_shear_modulus) }
}

/// # Safety
/// As the exported rejected-parameter calls.
unsafe fn rejected<F: Float>(params: *const ss_params<F>) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let Some(p) = (unsafe { params.as_ref() }) else {
        return SS_PARAMETER_NONE;
    };
    match checked_law(p) {
        Ok(_) => SS_PARAMETER_NONE,
        Err((_, parameter)) => parameter,
    }
}

/// The exported functions of one precision: `entry_points!(REAL: names...)` writes them for
/// `REAL` under the given names. The header test expands these invocations for cbindgen, which
/// does not expand macros itself.
macro_rules! entry_points {
    ($real:ident: $law_new:ident, $law_free:ident, $sphere_sphere:ident, $sphere_wall:ident, $bound_new:ident, $bound_free:ident, $bound_sphere_sphere:ident, $bound_sphere_wall:ident, $bound_sphere_pairs:ident, $advance:ident, $duration:ident, $limit:ident, $rejected:ident, $table_new:ident, $table_free:ident, $table_set:ident, $table_prepare:ident, $table_evaluate:ident, $table_pair:ident, $table_values:ident, $table_mirror:ident, $table_walls:ident) => {
        /// Validates `*params` and writes a new law handle to `*out` (free it with the matching
        /// `ss_law_free_*`). Returns `SS_OK` or an error code; `*out` is untouched on error.
        ///
        /// # Safety
        /// `params` and `out` must be valid pointers or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $law_new(
            params: *const ss_params<$real>,
            out: *mut *mut ss_law<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { law_new(params, out) }
        }

        /// Frees a law handle (null is ignored).
        ///
        /// # Safety
        /// `law` must come from the matching constructor and not be used afterwards.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $law_free(law: *mut ss_law<$real>) {
            // SAFETY: forwarded contract.
            unsafe { law_free(law) }
        }

        /// One sphere-sphere evaluation: reads and updates `*state`, writes `*out`. On error
        /// neither is changed.
        ///
        /// # Safety
        /// All pointers must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $sphere_sphere(
            law: *const ss_law<$real>,
            i: *const ss_sphere<$real>,
            j: *const ss_sphere<$real>,
            state: *mut ss_state<$real>,
            out: *mut ss_forces<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { pair(law, i, j, state, out) }
        }

        /// One sphere-wall evaluation; `force_on_j` and `torque_on_j` are what the sphere
        /// receives. On error neither `*state` nor `*out` is changed.
        ///
        /// # Safety
        /// All pointers must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $sphere_wall(
            law: *const ss_law<$real>,
            sphere: *const ss_sphere<$real>,
            wall: *const ss_wall<$real>,
            state: *mut ss_state<$real>,
            out: *mut ss_forces<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { on_wall(law, sphere, wall, state, out) }
        }

        /// Binds `*law` to its time step for one thread's run of calls and writes the new handle
        /// to `*out` (free it with the matching `ss_bound_law_free_*`; the handle keeps its own
        /// copy of the law). Returns `SS_OK` or `SS_ERR_NULL`; `*out` is untouched on error.
        ///
        /// # Safety
        /// `law` and `out` must be valid pointers or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $bound_new(
            law: *const ss_law<$real>,
            out: *mut *mut ss_bound_law<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { bound_new(law, out) }
        }

        /// Frees a bound-law handle (null is ignored).
        ///
        /// # Safety
        /// `bound` must come from the matching constructor and not be used afterwards.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $bound_free(bound: *mut ss_bound_law<$real>) {
            // SAFETY: forwarded contract.
            unsafe { bound_free(bound) }
        }

        /// As `ss_sphere_sphere_*`, the same bits, through a bound law: a pair of masses seen
        /// by the previous call reuses its oscillator. One thread at a time per handle.
        ///
        /// # Safety
        /// All pointers must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $bound_sphere_sphere(
            bound: *mut ss_bound_law<$real>,
            i: *const ss_sphere<$real>,
            j: *const ss_sphere<$real>,
            state: *mut ss_state<$real>,
            out: *mut ss_forces<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { bound_pair(bound, i, j, state, out) }
        }

        /// As `ss_sphere_wall_*`, the same bits, through a bound law: the wall of the previous
        /// call (the same bits) is not checked again, and a sphere mass seen by the previous
        /// call reuses its oscillator. One thread at a time per handle.
        ///
        /// # Safety
        /// All pointers must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $bound_sphere_wall(
            bound: *mut ss_bound_law<$real>,
            sphere: *const ss_sphere<$real>,
            wall: *const ss_wall<$real>,
            state: *mut ss_state<$real>,
            out: *mut ss_forces<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { bound_wall(bound, sphere, wall, state, out) }
        }

        /// `count` sphere-sphere evaluations in one call, pair `k` being element `k` of the arrays
        /// of `*i`, `*j`, `*states` and `*out` (structure of arrays): per pair the same bits,
        /// state handling and code as `ss_bound_sphere_sphere_*`, in `out->status[k]`; a failed
        /// pair's state and outputs are left as they were. The kernel evaluates the pairs in
        /// vector-width blocks (build for your CPU to use its vectors: docs/performance.md, "Batches").
        /// Returns `SS_ERR_NULL` when a pointer or array is null (the state arrays may be null
        /// for the stateless and frictionless laws), before touching anything; else `SS_OK`.
        ///
        /// # Safety
        /// Every array must be valid for `count` elements; the written arrays (`*out`'s and the
        /// states) must not overlap each other or the inputs. One thread at a time per handle.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $bound_sphere_pairs(
            bound: *mut ss_bound_law<$real>,
            count: usize,
            i: *const ss_sphere_arrays<$real>,
            j: *const ss_sphere_arrays<$real>,
            states: *const ss_state_arrays<$real>,
            out: *const ss_forces_arrays<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { bound_pairs(bound, count, i, j, states, out) }
        }

        /// Advances a homogeneous solid sphere by the law's step with the kernel's symplectic
        /// Euler (`motion::advance_solid_sphere`), for hosts that want the identical arithmetic.
        ///
        /// # Safety
        /// All pointers must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $advance(
            law: *const ss_law<$real>,
            sphere: *mut ss_sphere<$real>,
            force: ss_vec3<$real>,
            torque: ss_vec3<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { advance(law, sphere, force, torque) }
        }

        /// Contact duration `t_c` (s) of a free binary impact with effective mass `m_star`
        /// (infinite at e = 0). `*out` is untouched on error.
        ///
        /// # Safety
        /// All pointers must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $duration(
            params: *const ss_params<$real>,
            m_star: $real,
            out: *mut $real,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { duration(params, m_star, out) }
        }

        /// The largest stable time step (s) of the law `*params` describes, for contacts of
        /// `params->smallest_effective_mass` (its `time_step` is not used): the bound that
        /// `SS_ERR_UNSTABLE_TIME_STEP` enforces. `*out` is untouched on error.
        ///
        /// # Safety
        /// All pointers must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $limit(params: *const ss_params<$real>, out: *mut $real) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { stability_limit(params, out) }
        }

        /// Which parameter of `*params` the law's constructor rejects (`SS_PARAMETER_*`;
        /// `SS_PARAMETER_NONE` when it accepts them, or for a null pointer), so that a host can
        /// name it in its error message.
        ///
        /// # Safety
        /// `params` must be a valid pointer or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $rejected(params: *const ss_params<$real>) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { rejected(params) }
        }
        /// A material table of `config->materials` materials, every pair's law of the family
        /// `config->model`, written to `*out` (free it with the matching `ss_table_free_*`).
        /// Give it coefficients with `ss_table_set_*`, then check its step with
        /// `ss_table_prepare_*`. Returns `SS_OK`, `SS_ERR_NULL`, `SS_ERR_UNKNOWN_MODEL`,
        /// `SS_ERR_MATERIAL` (no materials, or more than `SS_MATERIALS_MAX`) or, for a Hertz
        /// family, the code of a bad declared impact; `*out` is untouched on error.
        ///
        /// # Safety
        /// `config` and `out` must be valid pointers or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_new(
            config: *const table::ss_table_config<$real>,
            out: *mut *mut table::ss_table<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { table::table_new(config, out) }
        }

        /// Frees a table (null is ignored).
        ///
        /// # Safety
        /// `table` must come from the matching constructor and not be used afterwards.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_free(table: *mut table::ss_table<$real>) {
            // SAFETY: forwarded contract.
            unsafe { table::table_free(table) }
        }

        /// Gives materials `a` and `b` their coefficients. `a == b`: material `a`'s own, which
        /// also make its law with every material not given a pair of its own (the kernel's
        /// mixing rule: geometric means, Hertz's and Mindlin's effective moduli). `a != b`: that
        /// pair's law, the rule's of `*coefficients` with themselves. Checked now: on error
        /// (`SS_ERR_MATERIAL` for a material past the table, or the parameter's code, with the
        /// `SS_PARAMETER_*` in `*parameter` when it is not null) the table is unchanged.
        /// The table must be prepared again before it evaluates.
        ///
        /// # Safety
        /// All pointers must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_set(
            table: *mut table::ss_table<$real>,
            a: usize,
            b: usize,
            coefficients: *const table::ss_coefficients<$real>,
            parameter: *mut i32,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { table::table_set(table, a, b, coefficients, parameter) }
        }

        /// Makes every pair's law and checks `time_step` against the law of every pair of
        /// materials present, at the effective mass of their lightest atoms:
        /// `lightest_mass[m]` is material `m`'s lightest atom mass over the whole run (every
        /// process's), 0 for a material with no atoms. On error (`SS_ERR_MATERIAL` for a pair
        /// with no law, `SS_ERR_UNSTABLE_TIME_STEP` and the others of the parameters,
        /// `SS_ERR_NON_FINITE_INPUT` for a mass that is not finite), `*report` (when not null)
        /// names the pair of materials, the parameter and the pair's stability limit, and the
        /// table does not evaluate until prepared.
        ///
        /// # Safety
        /// `lightest_mass` must hold one number per material; the others be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_prepare(
            table: *mut table::ss_table<$real>,
            time_step: $real,
            lightest_mass: *const $real,
            report: *mut table::ss_table_report<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { table::table_prepare(table, time_step, lightest_mass, report) }
        }

        /// The whole neighbour list in one call: every pair `(i, j)` with the law of their
        /// materials, its state read from the history (zero where `history` is null), each
        /// contact the same bits as `ss_sphere_sphere_*` with that law. On success the forces
        /// and torques are added into `*loads` (each atom's in list order), each neighbour's
        /// touch flag is set (1 where it keeps a state), and, when `advance` is not 0, its
        /// history values are advanced
        /// (LAMMPS's setup evaluation passes 0). Every count and index is checked first; on any
        /// error nothing is written but `*report`, which names the atoms (indices) it is
        /// about: `SS_ERR_NULL`, `SS_ERR_LENGTH`, `SS_ERR_INDEX`, `SS_ERR_MATERIAL`,
        /// `SS_ERR_NOT_PREPARED`, or a contact's code (`SS_ERR_NON_FINITE_INPUT`, ...,
        /// `SS_ERR_PAST_STABLE_STEP`). One thread at a time per table (it keeps its working
        /// memory).
        ///
        /// # Safety
        /// Every array must hold what its field says; the written arrays (forces, torques,
        /// history) must not overlap each other or the inputs.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_evaluate(
            table: *mut table::ss_table<$real>,
            atoms: *const table::ss_atoms<$real>,
            neighbours: *const table::ss_neighbours,
            history: *const table::ss_history<$real>,
            loads: *const table::ss_loads<$real>,
            advance: i32,
            report: *mut table::ss_list_report,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe {
                table::table_evaluate(table, atoms, neighbours, history, loads, advance, report)
            }
        }

        /// The walls in one call: every selected owned atom against every wall of
        /// `*walls` (all of one material of the table), each contact the same bits as
        /// `ss_sphere_wall_*` with the law of the atom's material and the walls', its state read
        /// from `walls->states`. On success the forces and torques are added into `*loads` (the
        /// selected atoms only) and, when `advance` is not 0, the states advanced (an atom clear
        /// of every wall is not evaluated: its states are set to zero, as the kernel would). On any error
        /// nothing is written but `*report` (the atom it is about): `SS_ERR_NULL`,
        /// `SS_ERR_LENGTH`, `SS_ERR_MATERIAL`, `SS_ERR_BAD_WALL`, `SS_ERR_NOT_PREPARED`, or a
        /// contact's code. One thread at a time per table.
        ///
        /// # Safety
        /// Every array must hold what its field says (`loads->pair_force` is not read); the
        /// written arrays must not overlap each other or the inputs.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_walls(
            table: *mut table::ss_table<$real>,
            atoms: *const table::ss_atoms<$real>,
            walls: *const table::ss_walls<$real>,
            loads: *const table::ss_loads<$real>,
            advance: i32,
            report: *mut table::ss_list_report,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { table::table_evaluate_walls(table, atoms, walls, loads, advance, report) }
        }

        /// One pair's contact with the law of materials `a` and `b`, its state read from
        /// `values` (`ss_table_state_values_*` numbers; null for a fresh contact) and not
        /// written: what a host reports per pair (LAMMPS `single()`). Writes `*out` on success.
        ///
        /// # Safety
        /// All pointers must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_pair(
            table: *const table::ss_table<$real>,
            a: usize,
            b: usize,
            i: *const ss_sphere<$real>,
            j: *const ss_sphere<$real>,
            values: *const $real,
            out: *mut ss_forces<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { table::table_pair(table, a, b, (i, j), values, out) }
        }

        /// How many numbers the table's law keeps per contact (0 for the stateless and
        /// frictionless laws, 3 for Model AA's displacement, 4 for Mindlin's spring force and
        /// contact radius); 0 for a null table.
        ///
        /// # Safety
        /// `table` must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_values(table: *const table::ss_table<$real>) -> usize {
            table::state_values(table)
        }

        /// Writes to `target` the state `source` seen from the other body (the pair's i and j
        /// swapped): a displacement or spring force is negated, a contact radius kept. `source`
        /// and `target` may be the same.
        ///
        /// # Safety
        /// `source` and `target` must hold `ss_table_state_values_*` numbers, or be null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_mirror(
            table: *const table::ss_table<$real>,
            source: *const $real,
            target: *mut $real,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { table::table_mirror(table, source, target) }
        }
    };
}

entry_points!(f64: ss_law_new_f64, ss_law_free_f64, ss_sphere_sphere_f64, ss_sphere_wall_f64, ss_bound_law_new_f64, ss_bound_law_free_f64, ss_bound_sphere_sphere_f64, ss_bound_sphere_wall_f64, ss_bound_sphere_pairs_f64, ss_advance_sphere_f64, ss_contact_duration_f64, ss_stability_limit_f64, ss_rejected_parameter_f64, ss_table_new_f64, ss_table_free_f64, ss_table_set_f64, ss_table_prepare_f64, ss_table_evaluate_f64, ss_table_pair_f64, ss_table_state_values_f64, ss_table_mirror_state_f64, ss_table_evaluate_walls_f64);
entry_points!(f32: ss_law_new_f32, ss_law_free_f32, ss_sphere_sphere_f32, ss_sphere_wall_f32, ss_bound_law_new_f32, ss_bound_law_free_f32, ss_bound_sphere_sphere_f32, ss_bound_sphere_wall_f32, ss_bound_sphere_pairs_f32, ss_advance_sphere_f32, ss_contact_duration_f32, ss_stability_limit_f32, ss_rejected_parameter_f32, ss_table_new_f32, ss_table_free_f32, ss_table_set_f32, ss_table_prepare_f32, ss_table_evaluate_f32, ss_table_pair_f32, ss_table_state_values_f32, ss_table_mirror_state_f32, ss_table_evaluate_walls_f32);
