/* soft-sphere C ABI. Generated from examples/c-abi/src/lib.rs by cbindgen; do not edit. */

#ifndef SOFT_SPHERE_H
#define SOFT_SPHERE_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

/**
 * Success.
 */
#define SS_OK 0

/**
 * A null pointer was passed.
 */
#define SS_ERR_NULL 1

/**
 * A parameter is not finite.
 */
#define SS_ERR_NON_FINITE_PARAMETER 2

/**
 * A parameter that must be positive is not.
 */
#define SS_ERR_NOT_POSITIVE 3

/**
 * A parameter that must not be negative is.
 */
#define SS_ERR_NEGATIVE 4

/**
 * Restitution outside [0, 1].
 */
#define SS_ERR_RESTITUTION 5

/**
 * The time step is at or past the law's stability limit.
 */
#define SS_ERR_UNSTABLE_TIME_STEP 6

/**
 * Unknown model code.
 */
#define SS_ERR_UNKNOWN_MODEL 7

/**
 * A position, velocity, radius or mass is not finite.
 */
#define SS_ERR_NON_FINITE_INPUT 8

/**
 * A radius is not positive.
 */
#define SS_ERR_NON_POSITIVE_RADIUS 9

/**
 * A mass is not positive.
 */
#define SS_ERR_NON_POSITIVE_MASS 10

/**
 * The two centres coincide.
 */
#define SS_ERR_COINCIDENT_CENTRES 11

/**
 * The result would not be finite.
 */
#define SS_ERR_NON_FINITE_RESULT 12

/**
 * The wall normal is zero, or a wall field is not finite.
 */
#define SS_ERR_BAD_WALL 13

/**
 * Poisson's ratio outside `(-1, 0.5]`.
 */
#define SS_ERR_POISSON_RATIO 14

/**
 * The contact is stiffer than the time step was checked for (a pair lighter than the declared
 * mass, a Hertz overlap past the declared impact's): explicit integration would be unstable.
 */
#define SS_ERR_PAST_STABLE_STEP 15

/**
 * The stateless (simplified) law: no tangential history is read or written.
 */
#define SS_MODEL_STATELESS 0

/**
 * Model AA: stored tangential spring limited to `mu |F_n| / k_t`.
 */
#define SS_MODEL_AA 1

/**
 * Model AA with Luding's reset: after sliding, spring plus dashpot equal the sliding force.
 */
#define SS_MODEL_AA_LUDING 2

/**
 * No friction: normal force only (no tangential force, no torque, no state).
 */
#define SS_MODEL_FRICTIONLESS 3

/**
 * Hertz, no friction.
 */
#define SS_MODEL_HERTZ_FRICTIONLESS 4

/**
 * Hertz with the stateless Mindlin law.
 */
#define SS_MODEL_HERTZ_STATELESS 5

/**
 * Hertz with Mindlin's stored spring and Model AA's cap.
 */
#define SS_MODEL_HERTZ_AA 6

/**
 * Hertz with Mindlin's stored spring and Luding's reset.
 */
#define SS_MODEL_HERTZ_AA_LUDING 7

/**
 * No parameter was rejected.
 */
#define SS_PARAMETER_NONE 0

/**
 * k_n.
 */
#define SS_PARAMETER_NORMAL_STIFFNESS 1

/**
 * e.
 */
#define SS_PARAMETER_RESTITUTION 2

/**
 * k_t.
 */
#define SS_PARAMETER_TANGENTIAL_STIFFNESS 3

/**
 * eta_t / eta_n.
 */
#define SS_PARAMETER_DASHPOT_RATIO 4

/**
 * mu.
 */
#define SS_PARAMETER_FRICTION 5

/**
 * The time step.
 */
#define SS_PARAMETER_TIME_STEP 6

/**
 * The smallest effective mass.
 */
#define SS_PARAMETER_MASS 7

/**
 * The model code.
 */
#define SS_PARAMETER_MODEL 8

/**
 * An elastic modulus (`effective_modulus`, `effective_shear_modulus`, or a material's).
 */
#define SS_PARAMETER_MODULUS 9

/**
 * A material's Poisson's ratio.
 */
#define SS_PARAMETER_POISSON_RATIO 10

/**
 * `largest_impact_speed`.
 */
#define SS_PARAMETER_SPEED 11

/**
 * `largest_effective_radius`.
 */
#define SS_PARAMETER_RADIUS 12

/**
 * A law bound to its time step, for one thread's run of calls (opaque to C). It remembers the
 * normal oscillator of the last pair of masses and the last wall it checked, so a host that
 * calls it over a neighbour list derives each once; the results are the same bits as the
 * `ss_law` entry points'.
 */
typedef struct ss_bound_law_f32 ss_bound_law_f32;

/**
 * A law bound to its time step, for one thread's run of calls (opaque to C). It remembers the
 * normal oscillator of the last pair of masses and the last wall it checked, so a host that
 * calls it over a neighbour list derives each once; the results are the same bits as the
 * `ss_law` entry points'.
 */
typedef struct ss_bound_law_f64 ss_bound_law_f64;

/**
 * A validated contact law and its checked time step (opaque to C).
 */
typedef struct ss_law_f32 ss_law_f32;

/**
 * A validated contact law and its checked time step (opaque to C).
 */
typedef struct ss_law_f64 ss_law_f64;

/**
 * An elastic material, for `ss_effective_moduli_*`.
 */
typedef struct {
  /**
   * Young's modulus (Pa).
   */
  double youngs_modulus;
  /**
   * Poisson's ratio, in (-1, 0.5].
   */
  double poisson_ratio;
} ss_material_f64;

/**
 * An elastic material, for `ss_effective_moduli_*`.
 */
typedef struct {
  /**
   * Young's modulus (Pa).
   */
  float youngs_modulus;
  /**
   * Poisson's ratio, in (-1, 0.5].
   */
  float poisson_ratio;
} ss_material_f32;

/**
 * Law parameters, validated once by the constructor.
 */
typedef struct {
  /**
   * `SS_MODEL_STATELESS`, `SS_MODEL_AA`, `SS_MODEL_AA_LUDING` or `SS_MODEL_FRICTIONLESS` (which
   * ignores the tangential parameters).
   */
  int32_t model;
  /**
   * k_n (N/m).
   */
  double normal_stiffness;
  /**
   * Normal restitution e, in [0, 1].
   */
  double restitution;
  /**
   * k_t (N/m).
   */
  double tangential_stiffness;
  /**
   * The dashpot ratio eta_t / eta_n.
   */
  double dashpot_ratio;
  /**
   * Coulomb mu.
   */
  double friction;
  /**
   * The time step (s) every call will use.
   */
  double time_step;
  /**
   * The smallest effective mass of any contact the step is checked for (kg).
   */
  double smallest_effective_mass;
  /**
   * `SS_MODEL_HERTZ_*`: Hertz's effective modulus `E*` (Pa), in place of `normal_stiffness`.
   */
  double effective_modulus;
  /**
   * `SS_MODEL_HERTZ_*` with friction: Mindlin's effective shear modulus `G*` (Pa), in place of
   * `tangential_stiffness`.
   */
  double effective_shear_modulus;
  /**
   * `SS_MODEL_HERTZ_*`: the fastest normal approach the time step is checked for (m/s).
   */
  double largest_impact_speed;
  /**
   * `SS_MODEL_HERTZ_*`: the largest effective radius `R*` the time step is checked for (m).
   */
  double largest_effective_radius;
} ss_params_f64;

/**
 * A vector of three components.
 */
typedef struct {
  /**
   * x
   */
  double x;
  /**
   * y
   */
  double y;
  /**
   * z
   */
  double z;
} ss_vec3_f64;

/**
 * A sphere: SI units; `angular_velocity` in rad/s.
 */
typedef struct {
  /**
   * Centre (m).
   */
  ss_vec3_f64 position;
  /**
   * Velocity (m/s).
   */
  ss_vec3_f64 velocity;
  /**
   * Angular velocity (rad/s).
   */
  ss_vec3_f64 angular_velocity;
  /**
   * Radius (m).
   */
  double radius;
  /**
   * Mass (kg).
   */
  double mass;
} ss_sphere_f64;

/**
 * Per-contact state, owned by the caller: zero for a new contact.
 */
typedef struct {
  /**
   * Stored tangential displacement (m) of `SS_MODEL_AA` and `SS_MODEL_AA_LUDING`.
   */
  ss_vec3_f64 displacement;
  /**
   * Stored tangential spring force (N) of `SS_MODEL_HERTZ_AA` and `SS_MODEL_HERTZ_AA_LUDING`.
   */
  ss_vec3_f64 spring_force;
  /**
   * The contact radius (m) at which `SS_MODEL_HERTZ_AA*` last updated `spring_force`.
   */
  double contact_radius;
} ss_state_f64;

/**
 * The result of one contact evaluation. Forces act on j (on the sphere, for a wall); i receives
 * the negative.
 */
typedef struct {
  /**
   * 1 when touching; 0 when apart (then every other field is zero).
   */
  int32_t touching;
  /**
   * 1 when the contact slid this step.
   */
  int32_t sliding;
  /**
   * Overlap (m).
   */
  double overlap;
  /**
   * Normal force magnitude (N), positive when repulsive.
   */
  double normal_force;
  /**
   * Total contact force on j (N).
   */
  ss_vec3_f64 force_on_j;
  /**
   * Torque on i (N m).
   */
  ss_vec3_f64 torque_on_i;
  /**
   * Torque on j (N m).
   */
  ss_vec3_f64 torque_on_j;
} ss_forces_f64;

/**
 * A plane wall through `point` with outward `normal` (any length), moving at `velocity`.
 */
typedef struct {
  /**
   * A point on the plane (m).
   */
  ss_vec3_f64 point;
  /**
   * The side the spheres are on.
   */
  ss_vec3_f64 normal;
  /**
   * Wall velocity (m/s).
   */
  ss_vec3_f64 velocity;
} ss_wall_f64;

/**
 * Spheres as arrays, one pointer per field (structure of arrays): sphere `k` is element `k` of
 * every array. Every pointer must be valid for the call's `count` elements.
 */
typedef struct {
  /**
   * Centre x (m).
   */
  const double *position_x;
  /**
   * Centre y (m).
   */
  const double *position_y;
  /**
   * Centre z (m).
   */
  const double *position_z;
  /**
   * Velocity x (m/s).
   */
  const double *velocity_x;
  /**
   * Velocity y (m/s).
   */
  const double *velocity_y;
  /**
   * Velocity z (m/s).
   */
  const double *velocity_z;
  /**
   * Angular velocity x (rad/s).
   */
  const double *angular_velocity_x;
  /**
   * Angular velocity y (rad/s).
   */
  const double *angular_velocity_y;
  /**
   * Angular velocity z (rad/s).
   */
  const double *angular_velocity_z;
  /**
   * Radius (m).
   */
  const double *radius;
  /**
   * Mass (kg).
   */
  const double *mass;
} ss_sphere_arrays_f64;

/**
 * Per-contact states as arrays: element `k` holds what `ss_state_*` holds for pair `k`. A law
 * reads only its own arrays (`SS_MODEL_AA*`: the displacement; `SS_MODEL_HERTZ_AA*`: the spring
 * force and the contact radius); the others, and all of them for the stateless and frictionless
 * laws, may be null.
 */
typedef struct {
  /**
   * Displacement x.
   */
  double *displacement_x;
  /**
   * Displacement y.
   */
  double *displacement_y;
  /**
   * Displacement z.
   */
  double *displacement_z;
  /**
   * Spring force x.
   */
  double *spring_force_x;
  /**
   * Spring force y.
   */
  double *spring_force_y;
  /**
   * Spring force z.
   */
  double *spring_force_z;
  /**
   * Contact radius.
   */
  double *contact_radius;
} ss_state_arrays_f64;

/**
 * What a batch call writes, as arrays: element `k` of each holds what `ss_forces_*` holds for
 * pair `k`, and `status[k]` that pair's code (`SS_OK` or the error the single call gives).
 */
typedef struct {
  /**
   * Each pair's code: `SS_OK`, or the error code of `ss_bound_sphere_sphere_*` for it.
   */
  int32_t *status;
  /**
   * 1 when touching, 0 when apart.
   */
  int32_t *touching;
  /**
   * 1 when the contact slid.
   */
  int32_t *sliding;
  /**
   * Overlap (m).
   */
  double *overlap;
  /**
   * Normal force (N).
   */
  double *normal_force;
  /**
   * Force on j, x (N).
   */
  double *force_on_j_x;
  /**
   * Force on j, y (N).
   */
  double *force_on_j_y;
  /**
   * Force on j, z (N).
   */
  double *force_on_j_z;
  /**
   * Torque on i, x (N m).
   */
  double *torque_on_i_x;
  /**
   * Torque on i, y (N m).
   */
  double *torque_on_i_y;
  /**
   * Torque on i, z (N m).
   */
  double *torque_on_i_z;
  /**
   * Torque on j, x (N m).
   */
  double *torque_on_j_x;
  /**
   * Torque on j, y (N m).
   */
  double *torque_on_j_y;
  /**
   * Torque on j, z (N m).
   */
  double *torque_on_j_z;
} ss_forces_arrays_f64;

/**
 * Law parameters, validated once by the constructor.
 */
typedef struct {
  /**
   * `SS_MODEL_STATELESS`, `SS_MODEL_AA`, `SS_MODEL_AA_LUDING` or `SS_MODEL_FRICTIONLESS` (which
   * ignores the tangential parameters).
   */
  int32_t model;
  /**
   * k_n (N/m).
   */
  float normal_stiffness;
  /**
   * Normal restitution e, in [0, 1].
   */
  float restitution;
  /**
   * k_t (N/m).
   */
  float tangential_stiffness;
  /**
   * The dashpot ratio eta_t / eta_n.
   */
  float dashpot_ratio;
  /**
   * Coulomb mu.
   */
  float friction;
  /**
   * The time step (s) every call will use.
   */
  float time_step;
  /**
   * The smallest effective mass of any contact the step is checked for (kg).
   */
  float smallest_effective_mass;
  /**
   * `SS_MODEL_HERTZ_*`: Hertz's effective modulus `E*` (Pa), in place of `normal_stiffness`.
   */
  float effective_modulus;
  /**
   * `SS_MODEL_HERTZ_*` with friction: Mindlin's effective shear modulus `G*` (Pa), in place of
   * `tangential_stiffness`.
   */
  float effective_shear_modulus;
  /**
   * `SS_MODEL_HERTZ_*`: the fastest normal approach the time step is checked for (m/s).
   */
  float largest_impact_speed;
  /**
   * `SS_MODEL_HERTZ_*`: the largest effective radius `R*` the time step is checked for (m).
   */
  float largest_effective_radius;
} ss_params_f32;

/**
 * A vector of three components.
 */
typedef struct {
  /**
   * x
   */
  float x;
  /**
   * y
   */
  float y;
  /**
   * z
   */
  float z;
} ss_vec3_f32;

/**
 * A sphere: SI units; `angular_velocity` in rad/s.
 */
typedef struct {
  /**
   * Centre (m).
   */
  ss_vec3_f32 position;
  /**
   * Velocity (m/s).
   */
  ss_vec3_f32 velocity;
  /**
   * Angular velocity (rad/s).
   */
  ss_vec3_f32 angular_velocity;
  /**
   * Radius (m).
   */
  float radius;
  /**
   * Mass (kg).
   */
  float mass;
} ss_sphere_f32;

/**
 * Per-contact state, owned by the caller: zero for a new contact.
 */
typedef struct {
  /**
   * Stored tangential displacement (m) of `SS_MODEL_AA` and `SS_MODEL_AA_LUDING`.
   */
  ss_vec3_f32 displacement;
  /**
   * Stored tangential spring force (N) of `SS_MODEL_HERTZ_AA` and `SS_MODEL_HERTZ_AA_LUDING`.
   */
  ss_vec3_f32 spring_force;
  /**
   * The contact radius (m) at which `SS_MODEL_HERTZ_AA*` last updated `spring_force`.
   */
  float contact_radius;
} ss_state_f32;

/**
 * The result of one contact evaluation. Forces act on j (on the sphere, for a wall); i receives
 * the negative.
 */
typedef struct {
  /**
   * 1 when touching; 0 when apart (then every other field is zero).
   */
  int32_t touching;
  /**
   * 1 when the contact slid this step.
   */
  int32_t sliding;
  /**
   * Overlap (m).
   */
  float overlap;
  /**
   * Normal force magnitude (N), positive when repulsive.
   */
  float normal_force;
  /**
   * Total contact force on j (N).
   */
  ss_vec3_f32 force_on_j;
  /**
   * Torque on i (N m).
   */
  ss_vec3_f32 torque_on_i;
  /**
   * Torque on j (N m).
   */
  ss_vec3_f32 torque_on_j;
} ss_forces_f32;

/**
 * A plane wall through `point` with outward `normal` (any length), moving at `velocity`.
 */
typedef struct {
  /**
   * A point on the plane (m).
   */
  ss_vec3_f32 point;
  /**
   * The side the spheres are on.
   */
  ss_vec3_f32 normal;
  /**
   * Wall velocity (m/s).
   */
  ss_vec3_f32 velocity;
} ss_wall_f32;

/**
 * Spheres as arrays, one pointer per field (structure of arrays): sphere `k` is element `k` of
 * every array. Every pointer must be valid for the call's `count` elements.
 */
typedef struct {
  /**
   * Centre x (m).
   */
  const float *position_x;
  /**
   * Centre y (m).
   */
  const float *position_y;
  /**
   * Centre z (m).
   */
  const float *position_z;
  /**
   * Velocity x (m/s).
   */
  const float *velocity_x;
  /**
   * Velocity y (m/s).
   */
  const float *velocity_y;
  /**
   * Velocity z (m/s).
   */
  const float *velocity_z;
  /**
   * Angular velocity x (rad/s).
   */
  const float *angular_velocity_x;
  /**
   * Angular velocity y (rad/s).
   */
  const float *angular_velocity_y;
  /**
   * Angular velocity z (rad/s).
   */
  const float *angular_velocity_z;
  /**
   * Radius (m).
   */
  const float *radius;
  /**
   * Mass (kg).
   */
  const float *mass;
} ss_sphere_arrays_f32;

/**
 * Per-contact states as arrays: element `k` holds what `ss_state_*` holds for pair `k`. A law
 * reads only its own arrays (`SS_MODEL_AA*`: the displacement; `SS_MODEL_HERTZ_AA*`: the spring
 * force and the contact radius); the others, and all of them for the stateless and frictionless
 * laws, may be null.
 */
typedef struct {
  /**
   * Displacement x.
   */
  float *displacement_x;
  /**
   * Displacement y.
   */
  float *displacement_y;
  /**
   * Displacement z.
   */
  float *displacement_z;
  /**
   * Spring force x.
   */
  float *spring_force_x;
  /**
   * Spring force y.
   */
  float *spring_force_y;
  /**
   * Spring force z.
   */
  float *spring_force_z;
  /**
   * Contact radius.
   */
  float *contact_radius;
} ss_state_arrays_f32;

/**
 * What a batch call writes, as arrays: element `k` of each holds what `ss_forces_*` holds for
 * pair `k`, and `status[k]` that pair's code (`SS_OK` or the error the single call gives).
 */
typedef struct {
  /**
   * Each pair's code: `SS_OK`, or the error code of `ss_bound_sphere_sphere_*` for it.
   */
  int32_t *status;
  /**
   * 1 when touching, 0 when apart.
   */
  int32_t *touching;
  /**
   * 1 when the contact slid.
   */
  int32_t *sliding;
  /**
   * Overlap (m).
   */
  float *overlap;
  /**
   * Normal force (N).
   */
  float *normal_force;
  /**
   * Force on j, x (N).
   */
  float *force_on_j_x;
  /**
   * Force on j, y (N).
   */
  float *force_on_j_y;
  /**
   * Force on j, z (N).
   */
  float *force_on_j_z;
  /**
   * Torque on i, x (N m).
   */
  float *torque_on_i_x;
  /**
   * Torque on i, y (N m).
   */
  float *torque_on_i_y;
  /**
   * Torque on i, z (N m).
   */
  float *torque_on_i_z;
  /**
   * Torque on j, x (N m).
   */
  float *torque_on_j_x;
  /**
   * Torque on j, y (N m).
   */
  float *torque_on_j_y;
  /**
   * Torque on j, z (N m).
   */
  float *torque_on_j_z;
} ss_forces_arrays_f32;

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

/**
 * Hertz's `E*` and Mindlin's `G*` of a contact between materials `*i` and `*j` (`j` null: a
 * rigid body, such as a wall), for `ss_params_f64`. Returns `SS_OK`, `SS_ERR_NULL`, or the
 * material's error (`SS_ERR_NOT_POSITIVE`, `SS_ERR_NON_FINITE_PARAMETER`,
 * `SS_ERR_POISSON_RATIO`); the outputs are written only on success.
 *
 * # Safety
 * Non-null pointers must be valid.
 */
int32_t ss_effective_moduli_f64(const ss_material_f64 *i,
                                const ss_material_f64 *j,
                                double *effective_modulus,
                                double *effective_shear_modulus);

/**
 * As `ss_effective_moduli_f64`, in f32.
 *
 * # Safety
 * Non-null pointers must be valid.
 */
int32_t ss_effective_moduli_f32(const ss_material_f32 *i,
                                const ss_material_f32 *j,
                                float *effective_modulus,
                                float *effective_shear_modulus);

/**
 * Validates `*params` and writes a new law handle to `*out` (free it with the matching
 * `ss_law_free_*`). Returns `SS_OK` or an error code; `*out` is untouched on error.
 *
 * # Safety
 * `params` and `out` must be valid pointers or null.
 */
int32_t ss_law_new_f64(const ss_params_f64 *params, ss_law_f64 **out);

/**
 * Frees a law handle (null is ignored).
 *
 * # Safety
 * `law` must come from the matching constructor and not be used afterwards.
 */
void ss_law_free_f64(ss_law_f64 *law);

/**
 * One sphere-sphere evaluation: reads and updates `*state`, writes `*out`. On error
 * neither is changed.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_sphere_sphere_f64(const ss_law_f64 *law,
                             const ss_sphere_f64 *i,
                             const ss_sphere_f64 *j,
                             ss_state_f64 *state,
                             ss_forces_f64 *out);

/**
 * One sphere-wall evaluation; `force_on_j` and `torque_on_j` are what the sphere
 * receives. On error neither `*state` nor `*out` is changed.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_sphere_wall_f64(const ss_law_f64 *law,
                           const ss_sphere_f64 *sphere,
                           const ss_wall_f64 *wall,
                           ss_state_f64 *state,
                           ss_forces_f64 *out);

/**
 * Binds `*law` to its time step for one thread's run of calls and writes the new handle
 * to `*out` (free it with the matching `ss_bound_law_free_*`; the handle keeps its own
 * copy of the law). Returns `SS_OK` or `SS_ERR_NULL`; `*out` is untouched on error.
 *
 * # Safety
 * `law` and `out` must be valid pointers or null.
 */
int32_t ss_bound_law_new_f64(const ss_law_f64 *law, ss_bound_law_f64 **out);

/**
 * Frees a bound-law handle (null is ignored).
 *
 * # Safety
 * `bound` must come from the matching constructor and not be used afterwards.
 */
void ss_bound_law_free_f64(ss_bound_law_f64 *bound);

/**
 * As `ss_sphere_sphere_*`, the same bits, through a bound law: a pair of masses seen
 * by the previous call reuses its oscillator. One thread at a time per handle.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_bound_sphere_sphere_f64(ss_bound_law_f64 *bound,
                                   const ss_sphere_f64 *i,
                                   const ss_sphere_f64 *j,
                                   ss_state_f64 *state,
                                   ss_forces_f64 *out);

/**
 * As `ss_sphere_wall_*`, the same bits, through a bound law: the wall of the previous
 * call (the same bits) is not checked again, and a sphere mass seen by the previous
 * call reuses its oscillator. One thread at a time per handle.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_bound_sphere_wall_f64(ss_bound_law_f64 *bound,
                                 const ss_sphere_f64 *sphere,
                                 const ss_wall_f64 *wall,
                                 ss_state_f64 *state,
                                 ss_forces_f64 *out);

/**
 * `count` sphere-sphere evaluations in one call, pair `k` being element `k` of the arrays
 * of `*i`, `*j`, `*states` and `*out` (structure of arrays): per pair the same bits,
 * state handling and code as `ss_bound_sphere_sphere_*`, in `out->status[k]`; a failed
 * pair's state and outputs are left as they were. The kernel evaluates the pairs in
 * vector-width blocks (build for your CPU to use its vectors: README, "Batches").
 * Returns `SS_ERR_NULL` when a pointer or array is null (the state arrays may be null
 * for the stateless and frictionless laws), before touching anything; else `SS_OK`.
 *
 * # Safety
 * Every array must be valid for `count` elements; the written arrays (`*out`'s and the
 * states) must not overlap each other or the inputs. One thread at a time per handle.
 */
int32_t ss_bound_sphere_pairs_f64(ss_bound_law_f64 *bound,
                                  size_t count,
                                  const ss_sphere_arrays_f64 *i,
                                  const ss_sphere_arrays_f64 *j,
                                  const ss_state_arrays_f64 *states,
                                  const ss_forces_arrays_f64 *out);

/**
 * Advances a homogeneous solid sphere by the law's step with the kernel's symplectic
 * Euler (`motion::advance_solid_sphere`), for hosts that want the identical arithmetic.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_advance_sphere_f64(const ss_law_f64 *law,
                              ss_sphere_f64 *sphere,
                              ss_vec3_f64 force,
                              ss_vec3_f64 torque);

/**
 * Contact duration `t_c` (s) of a free binary impact with effective mass `m_star`
 * (infinite at e = 0). `*out` is untouched on error.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_contact_duration_f64(const ss_params_f64 *params, double m_star, double *out);

/**
 * The largest stable time step (s) of the law `*params` describes, for contacts of
 * `params->smallest_effective_mass` (its `time_step` is not used): the bound that
 * `SS_ERR_UNSTABLE_TIME_STEP` enforces. `*out` is untouched on error.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_stability_limit_f64(const ss_params_f64 *params, double *out);

/**
 * Which parameter of `*params` the law's constructor rejects (`SS_PARAMETER_*`;
 * `SS_PARAMETER_NONE` when it accepts them, or for a null pointer), so that a host can
 * name it in its error message.
 *
 * # Safety
 * `params` must be a valid pointer or null.
 */
int32_t ss_rejected_parameter_f64(const ss_params_f64 *params);

/**
 * Validates `*params` and writes a new law handle to `*out` (free it with the matching
 * `ss_law_free_*`). Returns `SS_OK` or an error code; `*out` is untouched on error.
 *
 * # Safety
 * `params` and `out` must be valid pointers or null.
 */
int32_t ss_law_new_f32(const ss_params_f32 *params, ss_law_f32 **out);

/**
 * Frees a law handle (null is ignored).
 *
 * # Safety
 * `law` must come from the matching constructor and not be used afterwards.
 */
void ss_law_free_f32(ss_law_f32 *law);

/**
 * One sphere-sphere evaluation: reads and updates `*state`, writes `*out`. On error
 * neither is changed.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_sphere_sphere_f32(const ss_law_f32 *law,
                             const ss_sphere_f32 *i,
                             const ss_sphere_f32 *j,
                             ss_state_f32 *state,
                             ss_forces_f32 *out);

/**
 * One sphere-wall evaluation; `force_on_j` and `torque_on_j` are what the sphere
 * receives. On error neither `*state` nor `*out` is changed.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_sphere_wall_f32(const ss_law_f32 *law,
                           const ss_sphere_f32 *sphere,
                           const ss_wall_f32 *wall,
                           ss_state_f32 *state,
                           ss_forces_f32 *out);

/**
 * Binds `*law` to its time step for one thread's run of calls and writes the new handle
 * to `*out` (free it with the matching `ss_bound_law_free_*`; the handle keeps its own
 * copy of the law). Returns `SS_OK` or `SS_ERR_NULL`; `*out` is untouched on error.
 *
 * # Safety
 * `law` and `out` must be valid pointers or null.
 */
int32_t ss_bound_law_new_f32(const ss_law_f32 *law, ss_bound_law_f32 **out);

/**
 * Frees a bound-law handle (null is ignored).
 *
 * # Safety
 * `bound` must come from the matching constructor and not be used afterwards.
 */
void ss_bound_law_free_f32(ss_bound_law_f32 *bound);

/**
 * As `ss_sphere_sphere_*`, the same bits, through a bound law: a pair of masses seen
 * by the previous call reuses its oscillator. One thread at a time per handle.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_bound_sphere_sphere_f32(ss_bound_law_f32 *bound,
                                   const ss_sphere_f32 *i,
                                   const ss_sphere_f32 *j,
                                   ss_state_f32 *state,
                                   ss_forces_f32 *out);

/**
 * As `ss_sphere_wall_*`, the same bits, through a bound law: the wall of the previous
 * call (the same bits) is not checked again, and a sphere mass seen by the previous
 * call reuses its oscillator. One thread at a time per handle.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_bound_sphere_wall_f32(ss_bound_law_f32 *bound,
                                 const ss_sphere_f32 *sphere,
                                 const ss_wall_f32 *wall,
                                 ss_state_f32 *state,
                                 ss_forces_f32 *out);

/**
 * `count` sphere-sphere evaluations in one call, pair `k` being element `k` of the arrays
 * of `*i`, `*j`, `*states` and `*out` (structure of arrays): per pair the same bits,
 * state handling and code as `ss_bound_sphere_sphere_*`, in `out->status[k]`; a failed
 * pair's state and outputs are left as they were. The kernel evaluates the pairs in
 * vector-width blocks (build for your CPU to use its vectors: README, "Batches").
 * Returns `SS_ERR_NULL` when a pointer or array is null (the state arrays may be null
 * for the stateless and frictionless laws), before touching anything; else `SS_OK`.
 *
 * # Safety
 * Every array must be valid for `count` elements; the written arrays (`*out`'s and the
 * states) must not overlap each other or the inputs. One thread at a time per handle.
 */
int32_t ss_bound_sphere_pairs_f32(ss_bound_law_f32 *bound,
                                  size_t count,
                                  const ss_sphere_arrays_f32 *i,
                                  const ss_sphere_arrays_f32 *j,
                                  const ss_state_arrays_f32 *states,
                                  const ss_forces_arrays_f32 *out);

/**
 * Advances a homogeneous solid sphere by the law's step with the kernel's symplectic
 * Euler (`motion::advance_solid_sphere`), for hosts that want the identical arithmetic.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_advance_sphere_f32(const ss_law_f32 *law,
                              ss_sphere_f32 *sphere,
                              ss_vec3_f32 force,
                              ss_vec3_f32 torque);

/**
 * Contact duration `t_c` (s) of a free binary impact with effective mass `m_star`
 * (infinite at e = 0). `*out` is untouched on error.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_contact_duration_f32(const ss_params_f32 *params, float m_star, float *out);

/**
 * The largest stable time step (s) of the law `*params` describes, for contacts of
 * `params->smallest_effective_mass` (its `time_step` is not used): the bound that
 * `SS_ERR_UNSTABLE_TIME_STEP` enforces. `*out` is untouched on error.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_stability_limit_f32(const ss_params_f32 *params, float *out);

/**
 * Which parameter of `*params` the law's constructor rejects (`SS_PARAMETER_*`;
 * `SS_PARAMETER_NONE` when it accepts them, or for a null pointer), so that a host can
 * name it in its error message.
 *
 * # Safety
 * `params` must be a valid pointer or null.
 */
int32_t ss_rejected_parameter_f32(const ss_params_f32 *params);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* SOFT_SPHERE_H */
