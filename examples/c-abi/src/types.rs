//! The plain structs a C host fills and reads: vectors, spheres, walls, law parameters,
//! materials, the per-contact state and the forces.

use soft_sphere::prelude::{Float, Sphere, Vec3};

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

/// A wall: a plane through `point` whose normal towards the spheres is `direction` (any length),
/// or, when `radius` is positive, the inside of a cylinder of that radius about the axis through
/// `point` along `direction`. It moves at `velocity` and turns at `spin` about its axis (a plane's: its
/// normal through `point`), its surface staying in place. A zeroed struct's fields after
/// `direction` make a still plane.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct ss_wall<F> {
    /// A point on the plane; a point on the cylinder's axis (m).
    pub point: ss_vec3<F>,
    /// The plane's normal towards the spheres; the cylinder's axis.
    pub direction: ss_vec3<F>,
    /// Wall velocity (m/s).
    pub velocity: ss_vec3<F>,
    /// Zero for a plane; a cylinder's radius (m), the spheres inside.
    pub radius: F,
    /// Turning rate about the axis, right-handed about `direction` (rad/s; a rate, the angular
    /// velocity being `spin` times the unit `direction`).
    pub spin: F,
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
