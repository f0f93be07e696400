/* soft-sphere C ABI. Generated from examples/c-abi/src by cbindgen; do not edit. */

#ifndef SOFT_SPHERE_H
#define SOFT_SPHERE_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

/* This header's version; ss_version() returns the loaded library's. */
#define SS_VERSION_MAJOR 0
#define SS_VERSION_MINOR 1
#define SS_VERSION_PATCH 0
#define SS_VERSION_STRING "0.1.0"


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
 * A position, velocity, radius or mass is not finite (or, for the table entries, a force or
 * torque given to be added to).
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
 * The two centres coincide, or a sphere wider than a cylinder wall is centred on its axis.
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
 * The time step is stable but at or past the law's accuracy limit: a contact could rebound
 * more than 0.02 of its impact speed off the law's restitution.
 */
#define SS_ERR_INACCURATE_TIME_STEP 20

/**
 * A new contact needs room in a full history store. The entries here keep no history store
 * of their own, so none returns it; it is the kernel's error, given its own code.
 */
#define SS_ERR_HISTORY_FULL 22

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
 * Hertz with Mindlin & Deresiewicz's micro-slip, its profile in up to `SS_MICROSLIP_SPRINGS`
 * breakpoints: material tables only (`ss_table_*`; its state, `4 SS_MICROSLIP_SPRINGS + 4`
 * numbers per contact, does
 * not fit `ss_state`, so `ss_law_new_*` answers `SS_ERR_UNKNOWN_MODEL`).
 */
#define SS_MODEL_HERTZ_MICROSLIP 8

/**
 * Breakpoints of `SS_MODEL_HERTZ_MICROSLIP`'s displacement profile.
 */
#define SS_MICROSLIP_SPRINGS 16

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
 * The rolling friction `mu_r`.
 */
#define SS_PARAMETER_ROLLING_FRICTION 13

/**
 * The rolling stiffness `k_r`.
 */
#define SS_PARAMETER_ROLLING_STIFFNESS 14

/**
 * The rolling dashpot `eta_r`.
 */
#define SS_PARAMETER_ROLLING_DAMPING 15

/**
 * A wall's point or normal.
 */
#define SS_PARAMETER_WALL 16

/**
 * Hertz's dashpot factor `alpha`, when given instead of the restitution.
 */
#define SS_PARAMETER_DAMPING_FACTOR 17

/**
 * The smallest moment of inertia a rolling spring is checked for.
 */
#define SS_PARAMETER_INERTIA 18

/**
 * The most materials a table holds (LAMMPS atom types).
 */
#define SS_MATERIALS_MAX 16

/**
 * An array's length or a count is negative, past what the call can index, or disagrees with
 * another (a history with fewer values per neighbour than the law keeps).
 */
#define SS_ERR_LENGTH 16

/**
 * An atom of the list, or a neighbour, is past the atoms.
 */
#define SS_ERR_INDEX 17

/**
 * A material (an atom's type) is past the table, or a pair of materials has no law: neither
 * its own coefficients nor both materials' for the mixing rule.
 */
#define SS_ERR_MATERIAL 18

/**
 * The table's time step has not been checked (`ss_table_prepare_*`) since it last changed.
 */
#define SS_ERR_NOT_PREPARED 19

/**
 * A neighbour list names a pair twice (`ss_check_neighbours`): its force would be added twice.
 */
#define SS_ERR_REPEATED_PAIR 21

/**
 * No rolling resistance.
 */
#define SS_ROLLING_NONE 0

/**
 * The elastic-plastic spring-dashpot rolling resistance (the kernel's `ElasticPlasticRolling`;
 * Ai et al. 2011, model C): a rolling spring `k_r` limited to `mu_r R* |F_n|`, a dashpot
 * `eta_r` below the limit. Not with the frictionless families.
 */
#define SS_ROLLING_EPSD 1

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
 * A table: its coefficients as given, the laws and the step once prepared, and the working
 * memory of evaluations (opaque to C).
 */
typedef struct ss_table_f32 ss_table_f32;

/**
 * A table: its coefficients as given, the laws and the step once prepared, and the working
 * memory of evaluations (opaque to C).
 */
typedef struct ss_table_f64 ss_table_f64;

/**
 * A neighbour list as LAMMPS keeps it: `count` atoms (`atoms[0 .. count)`); atom `i`'s
 * neighbours are `first_neighbour[i][0 .. neighbour_counts[i])`, each masked with
 * `index_mask`. `neighbour_counts` and `first_neighbour` are indexed by atom, so they must hold
 * an entry for every atom the list names.
 */
typedef struct {
  /**
   * How many atoms the list holds (LAMMPS: `inum`).
   */
  size_t count;
  /**
   * The atoms (LAMMPS: `ilist`).
   */
  const int32_t *atoms;
  /**
   * Per atom, how many neighbours (LAMMPS: `numneigh`).
   */
  const int32_t *neighbour_counts;
  /**
   * Per atom, its first neighbour (LAMMPS: `firstneigh`).
   */
  const int32_t *const *first_neighbour;
  /**
   * ANDed with each neighbour (LAMMPS: `NEIGHMASK`; -1 keeps every bit).
   */
  int32_t index_mask;
} ss_neighbours;

/**
 * What an evaluation found, and which atoms an error is about.
 */
typedef struct {
  /**
   * Touching pairs.
   */
  size_t contacts;
  /**
   * Pairs at the Coulomb limit.
   */
  size_t sliding;
  /**
   * The atoms (indices into the arrays) an error is about; -1 when none.
   */
  int64_t atoms[2];
  /**
   * Touching contacts past their law's accuracy limit, evaluated because the table was
   * prepared for a coarse step (`ss_table_prepare_coarse_*`); 0 otherwise.
   */
  size_t inaccurate;
} ss_list_report;

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
 * A wall: a plane through `point` whose normal towards the spheres is `direction` (any length),
 * or, when `radius` is positive, the inside of a cylinder of that radius about the axis through
 * `point` along `direction`. It moves at `velocity` and turns at `spin` about its axis (a plane's: its
 * normal through `point`), its surface staying in place. A zeroed struct's fields after
 * `direction` make a still plane.
 */
typedef struct {
  /**
   * A point on the plane; a point on the cylinder's axis (m).
   */
  ss_vec3_f64 point;
  /**
   * The plane's normal towards the spheres; the cylinder's axis.
   */
  ss_vec3_f64 direction;
  /**
   * Wall velocity (m/s).
   */
  ss_vec3_f64 velocity;
  /**
   * Zero for a plane; a cylinder's radius (m), the spheres inside.
   */
  double radius;
  /**
   * Turning rate about the axis, right-handed about `direction` (rad/s; a rate, the angular
   * velocity being `spin` times the unit `direction`).
   */
  double spin;
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
 * What a table is made for: one family of laws for every pair of materials.
 */
typedef struct {
  /**
   * `SS_MODEL_*`: every pair's law is of this family.
   */
  int32_t model;
  /**
   * `SS_ROLLING_*`: every pair's rolling resistance.
   */
  int32_t rolling;
  /**
   * `SS_ROLLING_EPSD`: the smallest effective moment of inertia of any contact (kg m^2; for
   * two solid spheres, at least half the smaller `2/5 m R^2`), which the step is checked for.
   */
  double smallest_inertia;
  /**
   * How many materials (at most `SS_MATERIALS_MAX`).
   */
  size_t materials;
  /**
   * `SS_MODEL_HERTZ_*`: the fastest normal approach the time step is checked for (m/s).
   */
  double largest_impact_speed;
  /**
   * `SS_MODEL_HERTZ_*`: the largest effective radius `R*` the time step is checked for (m).
   */
  double largest_effective_radius;
} ss_table_config_f64;

/**
 * The coefficients of a material, or of one pair of materials' contact. The linear laws read
 * the first five, the Hertz laws Young's modulus, Poisson's ratio, restitution, the dashpot
 * ratio and friction. The frictionless laws ignore the tangential ones.
 */
typedef struct {
  /**
   * k_n (N/m), linear laws.
   */
  double normal_stiffness;
  /**
   * Normal restitution e, in [0, 1].
   */
  double restitution;
  /**
   * k_t (N/m), linear laws.
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
   * Young's modulus E (Pa), Hertz laws.
   */
  double youngs_modulus;
  /**
   * Poisson's ratio nu, in (-1, 0.5], Hertz laws.
   */
  double poisson_ratio;
  /**
   * `SS_ROLLING_EPSD`: the rolling friction `mu_r`.
   */
  double rolling_friction;
  /**
   * `SS_ROLLING_EPSD`: the rolling stiffness `k_r` (N m/rad).
   */
  double rolling_stiffness;
  /**
   * `SS_ROLLING_EPSD`: the rolling dashpot `eta_r` (N m s/rad).
   */
  double rolling_damping;
} ss_coefficients_f64;

/**
 * Why `ss_table_prepare_*` refused: the pair of materials and, for a refused step, the largest
 * stable step of that pair.
 */
typedef struct {
  /**
   * The two materials (-1 when the error is about none).
   */
  int64_t materials[2];
  /**
   * `SS_PARAMETER_*` the error is about.
   */
  int32_t parameter;
  /**
   * For `SS_ERR_UNSTABLE_TIME_STEP` (`SS_ERR_INACCURATE_TIME_STEP`): the pair's largest stable
   * (accurate) step (s).
   */
  double limit;
} ss_table_report_f64;

/**
 * The atoms, as flat arrays of `count` entries (three per atom for vectors): owned atoms
 * first, then ghosts. The material of atom `k` is `types[k] - first_type`.
 */
typedef struct {
  /**
   * How many atoms every array holds (LAMMPS: `nlocal + nghost`).
   */
  size_t count;
  /**
   * The atoms `[0, owned)` are this process's own (LAMMPS: `nlocal`).
   */
  size_t owned;
  /**
   * Centres (m), x y z per atom.
   */
  const double *position;
  /**
   * Velocities (m/s), x y z per atom.
   */
  const double *velocity;
  /**
   * Angular velocities (rad/s), x y z per atom.
   */
  const double *angular_velocity;
  /**
   * Radii (m).
   */
  const double *radius;
  /**
   * Masses (kg).
   */
  const double *mass;
  /**
   * Types.
   */
  const int32_t *types;
  /**
   * The type of material 0 (LAMMPS: 1).
   */
  int32_t first_type;
} ss_atoms_f64;

/**
 * The per-neighbour history, beside the neighbour list: atom `i`'s `jj`-th neighbour keeps
 * `values` numbers from `first_value[i] + jj * values` and a touch flag at
 * `first_touch[i][jj]` (LAMMPS: `fix neigh/history`'s `firstvalue` and `firstflag`). The flag
 * is 1 where the neighbour keeps a state (not all zero): the kernel relaxes the state of a pair
 * apart to zero, so a host may drop every other neighbour's values when it rebuilds its list.
 */
typedef struct {
  /**
   * Numbers per neighbour, at least `ss_table_state_values_*`.
   */
  size_t values;
  /**
   * Per atom, its first neighbour's values.
   */
  double *const *first_value;
  /**
   * Per atom, its first neighbour's touch flag.
   */
  int32_t *const *first_touch;
} ss_history_f64;

/**
 * Where the forces go: added to `force` and `torque` (x y z per atom, `count` atoms), on every
 * atom when `newton` is 1 (LAMMPS `newton_pair on`: ghosts' forces are sent home), else only
 * on the owned atoms.
 */
typedef struct {
  /**
   * Forces (N), added to.
   */
  double *force;
  /**
   * Torques (N m), added to.
   */
  double *torque;
  /**
   * 1: every atom receives; 0: only the owned atoms.
   */
  int32_t newton;
  /**
   * Null, or three numbers per neighbour in list order: each pair's force on its atom `i`
   * (N; zero for a pair apart), for a host's per-pair sums such as the virial.
   */
  double *pair_force;
} ss_loads_f64;

/**
 * Walls (planes or cylinders) for `ss_table_evaluate_walls_*`, all of one material of the table, and each
 * atom's state against each: atom `k`'s against wall `w` is the `ss_table_state_values_*`
 * numbers from `states + k * stride + w * wall_stride`.
 */
typedef struct {
  /**
   * How many walls.
   */
  size_t count;
  /**
   * The walls.
   */
  const ss_wall_f64 *walls;
  /**
   * Their material.
   */
  uint32_t material;
  /**
   * The atoms' states against the walls.
   */
  double *states;
  /**
   * Numbers per atom in `states`.
   */
  size_t stride;
  /**
   * Numbers between one wall's state and the next within an atom's.
   */
  size_t wall_stride;
  /**
   * Null: every owned atom meets the walls; else owned atom `k` does when
   * `selected[k] & bit` is not 0 (LAMMPS: `mask` and a fix's `groupbit`).
   */
  const int32_t *selected;
  /**
   * See `selected`.
   */
  int32_t bit;
} ss_walls_f64;

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
 * A wall: a plane through `point` whose normal towards the spheres is `direction` (any length),
 * or, when `radius` is positive, the inside of a cylinder of that radius about the axis through
 * `point` along `direction`. It moves at `velocity` and turns at `spin` about its axis (a plane's: its
 * normal through `point`), its surface staying in place. A zeroed struct's fields after
 * `direction` make a still plane.
 */
typedef struct {
  /**
   * A point on the plane; a point on the cylinder's axis (m).
   */
  ss_vec3_f32 point;
  /**
   * The plane's normal towards the spheres; the cylinder's axis.
   */
  ss_vec3_f32 direction;
  /**
   * Wall velocity (m/s).
   */
  ss_vec3_f32 velocity;
  /**
   * Zero for a plane; a cylinder's radius (m), the spheres inside.
   */
  float radius;
  /**
   * Turning rate about the axis, right-handed about `direction` (rad/s; a rate, the angular
   * velocity being `spin` times the unit `direction`).
   */
  float spin;
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

/**
 * What a table is made for: one family of laws for every pair of materials.
 */
typedef struct {
  /**
   * `SS_MODEL_*`: every pair's law is of this family.
   */
  int32_t model;
  /**
   * `SS_ROLLING_*`: every pair's rolling resistance.
   */
  int32_t rolling;
  /**
   * `SS_ROLLING_EPSD`: the smallest effective moment of inertia of any contact (kg m^2; for
   * two solid spheres, at least half the smaller `2/5 m R^2`), which the step is checked for.
   */
  float smallest_inertia;
  /**
   * How many materials (at most `SS_MATERIALS_MAX`).
   */
  size_t materials;
  /**
   * `SS_MODEL_HERTZ_*`: the fastest normal approach the time step is checked for (m/s).
   */
  float largest_impact_speed;
  /**
   * `SS_MODEL_HERTZ_*`: the largest effective radius `R*` the time step is checked for (m).
   */
  float largest_effective_radius;
} ss_table_config_f32;

/**
 * The coefficients of a material, or of one pair of materials' contact. The linear laws read
 * the first five, the Hertz laws Young's modulus, Poisson's ratio, restitution, the dashpot
 * ratio and friction. The frictionless laws ignore the tangential ones.
 */
typedef struct {
  /**
   * k_n (N/m), linear laws.
   */
  float normal_stiffness;
  /**
   * Normal restitution e, in [0, 1].
   */
  float restitution;
  /**
   * k_t (N/m), linear laws.
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
   * Young's modulus E (Pa), Hertz laws.
   */
  float youngs_modulus;
  /**
   * Poisson's ratio nu, in (-1, 0.5], Hertz laws.
   */
  float poisson_ratio;
  /**
   * `SS_ROLLING_EPSD`: the rolling friction `mu_r`.
   */
  float rolling_friction;
  /**
   * `SS_ROLLING_EPSD`: the rolling stiffness `k_r` (N m/rad).
   */
  float rolling_stiffness;
  /**
   * `SS_ROLLING_EPSD`: the rolling dashpot `eta_r` (N m s/rad).
   */
  float rolling_damping;
} ss_coefficients_f32;

/**
 * Why `ss_table_prepare_*` refused: the pair of materials and, for a refused step, the largest
 * stable step of that pair.
 */
typedef struct {
  /**
   * The two materials (-1 when the error is about none).
   */
  int64_t materials[2];
  /**
   * `SS_PARAMETER_*` the error is about.
   */
  int32_t parameter;
  /**
   * For `SS_ERR_UNSTABLE_TIME_STEP` (`SS_ERR_INACCURATE_TIME_STEP`): the pair's largest stable
   * (accurate) step (s).
   */
  float limit;
} ss_table_report_f32;

/**
 * The atoms, as flat arrays of `count` entries (three per atom for vectors): owned atoms
 * first, then ghosts. The material of atom `k` is `types[k] - first_type`.
 */
typedef struct {
  /**
   * How many atoms every array holds (LAMMPS: `nlocal + nghost`).
   */
  size_t count;
  /**
   * The atoms `[0, owned)` are this process's own (LAMMPS: `nlocal`).
   */
  size_t owned;
  /**
   * Centres (m), x y z per atom.
   */
  const float *position;
  /**
   * Velocities (m/s), x y z per atom.
   */
  const float *velocity;
  /**
   * Angular velocities (rad/s), x y z per atom.
   */
  const float *angular_velocity;
  /**
   * Radii (m).
   */
  const float *radius;
  /**
   * Masses (kg).
   */
  const float *mass;
  /**
   * Types.
   */
  const int32_t *types;
  /**
   * The type of material 0 (LAMMPS: 1).
   */
  int32_t first_type;
} ss_atoms_f32;

/**
 * The per-neighbour history, beside the neighbour list: atom `i`'s `jj`-th neighbour keeps
 * `values` numbers from `first_value[i] + jj * values` and a touch flag at
 * `first_touch[i][jj]` (LAMMPS: `fix neigh/history`'s `firstvalue` and `firstflag`). The flag
 * is 1 where the neighbour keeps a state (not all zero): the kernel relaxes the state of a pair
 * apart to zero, so a host may drop every other neighbour's values when it rebuilds its list.
 */
typedef struct {
  /**
   * Numbers per neighbour, at least `ss_table_state_values_*`.
   */
  size_t values;
  /**
   * Per atom, its first neighbour's values.
   */
  float *const *first_value;
  /**
   * Per atom, its first neighbour's touch flag.
   */
  int32_t *const *first_touch;
} ss_history_f32;

/**
 * Where the forces go: added to `force` and `torque` (x y z per atom, `count` atoms), on every
 * atom when `newton` is 1 (LAMMPS `newton_pair on`: ghosts' forces are sent home), else only
 * on the owned atoms.
 */
typedef struct {
  /**
   * Forces (N), added to.
   */
  float *force;
  /**
   * Torques (N m), added to.
   */
  float *torque;
  /**
   * 1: every atom receives; 0: only the owned atoms.
   */
  int32_t newton;
  /**
   * Null, or three numbers per neighbour in list order: each pair's force on its atom `i`
   * (N; zero for a pair apart), for a host's per-pair sums such as the virial.
   */
  float *pair_force;
} ss_loads_f32;

/**
 * Walls (planes or cylinders) for `ss_table_evaluate_walls_*`, all of one material of the table, and each
 * atom's state against each: atom `k`'s against wall `w` is the `ss_table_state_values_*`
 * numbers from `states + k * stride + w * wall_stride`.
 */
typedef struct {
  /**
   * How many walls.
   */
  size_t count;
  /**
   * The walls.
   */
  const ss_wall_f32 *walls;
  /**
   * Their material.
   */
  uint32_t material;
  /**
   * The atoms' states against the walls.
   */
  float *states;
  /**
   * Numbers per atom in `states`.
   */
  size_t stride;
  /**
   * Numbers between one wall's state and the next within an atom's.
   */
  size_t wall_stride;
  /**
   * Null: every owned atom meets the walls; else owned atom `k` does when
   * `selected[k] & bit` is not 0 (LAMMPS: `mask` and a fix's `groupbit`).
   */
  const int32_t *selected;
  /**
   * See `selected`.
   */
  int32_t bit;
} ss_walls_f32;

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

/**
 * Checks a neighbour list of `atoms` atoms once, when the host builds it: every count and
 * index, and no pair named twice (atom `i`'s neighbours naming `j` twice, or `i`'s naming `j`
 * and `j`'s naming `i`), whose force `ss_table_evaluate_*` would add twice. It takes a sort,
 * so it belongs to the list build, not to every step (LAMMPS's half lists name each pair
 * once). Returns `SS_OK`, `SS_ERR_NULL`, `SS_ERR_LENGTH`, `SS_ERR_INDEX` or
 * `SS_ERR_REPEATED_PAIR`; `*report` (when not null) names the atoms an error is about (the
 * repeated pair's two).
 *
 * # Safety
 * `list` as for `ss_table_evaluate_*`, for `atoms` atoms.
 */
int32_t ss_check_neighbours(size_t atoms, const ss_neighbours *list, ss_list_report *report);

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
 * The library's version, `"MAJOR.MINOR.PATCH"` (NUL-terminated, static): the crate's version,
 * which the header's `SS_VERSION_*` macros also hold, so that a host can check at run time
 * that the library it loaded is the one its header describes (`docs/c-abi.md`, "Versions").
 */
const char *ss_version(void);

/**
 * How many laws the C ABI names (`ss_model_code` counts them; the material tables also take
 * `SS_MODEL_HERTZ_MICROSLIP`, which has no name).
 */
size_t ss_model_count(void);

/**
 * The `SS_MODEL_*` code of the `index`-th named law (from 0), or -1 past the last.
 */
int32_t ss_model_code(size_t index);

/**
 * The name of law `model` as an input script writes it (`"aa"`, `"hertz/aa/luding"`, ...), or
 * null for a code with no name.
 */
const char *ss_model_name(int32_t model);

/**
 * Writes the `SS_MODEL_*` code of the law named `name` (NUL-terminated) to `*model`. Returns
 * `SS_OK`, `SS_ERR_NULL`, or `SS_ERR_UNKNOWN_MODEL` (then `*model` is unchanged).
 *
 * # Safety
 * Non-null pointers must be valid; `name` must be NUL-terminated.
 */
int32_t ss_model_of_name(const char *name, int32_t *model);

/**
 * 1 when law `model` is of Hertz's family (its parameters are `E`, `nu` and a declared
 * impact; `SS_MODEL_HERTZ_MICROSLIP` included), 0 otherwise.
 */
int32_t ss_model_is_hertz(int32_t model);

/**
 * What an `SS_PARAMETER_*` code names, for a law of `model` (the modulus is Young's `E` for
 * Hertz's family), as a user reads it: `"k_n (normal stiffness)"`, ...
 */
const char *ss_parameter_name(int32_t parameter, int32_t model);

/**
 * What an error code says of the parameter it is about, to follow its name: `"must be
 * positive"`, ...
 */
const char *ss_parameter_error_text(int32_t code);

/**
 * What a contact or list error code means, as a sentence.
 */
const char *ss_contact_error_text(int32_t code);

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
 * pair's state and outputs are left as they were.
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
 * (infinite at e = 0), from the normal law of `params.model`'s family (micro-slip's is
 * Hertz's). `SS_ERR_UNKNOWN_MODEL` for a code no law has; `*out` is untouched on
 * error.
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
 * A material table of `config->materials` materials, every pair's law of the family
 * `config->model`, written to `*out` (free it with the matching `ss_table_free_*`).
 * Give it coefficients with `ss_table_set_*`, then check its step with
 * `ss_table_prepare_*`. Returns `SS_OK`, `SS_ERR_NULL`, `SS_ERR_UNKNOWN_MODEL`,
 * `SS_ERR_MATERIAL` (no materials, or more than `SS_MATERIALS_MAX`) or, for a Hertz
 * family, the code of a bad declared impact; `*out` is untouched on error.
 *
 * # Safety
 * `config` and `out` must be valid pointers or null.
 */
int32_t ss_table_new_f64(const ss_table_config_f64 *config, ss_table_f64 **out);

/**
 * Frees a table (null is ignored).
 *
 * # Safety
 * `table` must come from the matching constructor and not be used afterwards.
 */
void ss_table_free_f64(ss_table_f64 *table);

/**
 * Gives materials `a` and `b` their coefficients. `a == b`: material `a`'s own, which
 * also make its law with every material not given a pair of its own (the kernel's
 * mixing rule: geometric means, Hertz's and Mindlin's effective moduli). `a != b`: that
 * pair's law, the rule's of `*coefficients` with themselves. Checked now: on error
 * (`SS_ERR_MATERIAL` for a material past the table, or the parameter's code, with the
 * `SS_PARAMETER_*` in `*parameter` when it is not null) the table is unchanged.
 * The table must be prepared again before it evaluates.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_table_set_f64(ss_table_f64 *table,
                         size_t a,
                         size_t b,
                         const ss_coefficients_f64 *coefficients,
                         int32_t *parameter);

/**
 * Makes every pair's law and checks `time_step` against the law of every pair of
 * materials present, at the effective mass of their lightest atoms:
 * `lightest_mass[m]` is material `m`'s lightest atom mass over the whole run (every
 * process's), 0 for a material with no atoms. On error (`SS_ERR_MATERIAL` for a pair
 * with no law, `SS_ERR_UNSTABLE_TIME_STEP` and the others of the parameters,
 * `SS_ERR_NON_FINITE_INPUT` for a mass that is not finite), `*report` (when not null)
 * names the pair of materials, the parameter and the pair's stability limit, and the
 * table does not evaluate until prepared.
 *
 * # Safety
 * `lightest_mass` must hold one number per material; the others be valid or null.
 */
int32_t ss_table_prepare_f64(ss_table_f64 *table,
                             double time_step,
                             const double *lightest_mass,
                             ss_table_report_f64 *report);

/**
 * The materials the walls a host evaluates (`ss_table_evaluate_walls_*`) are made of,
 * `count` ids (replacing any given before; none by default): each prepare then also
 * checks the step against the law of every material present with each of them, at
 * the mass of the material's lightest atom (a sphere against a wall). Returns `SS_OK`,
 * `SS_ERR_NULL`, or `SS_ERR_MATERIAL` for an id past the table (nothing changed).
 * The table does not evaluate until prepared again.
 *
 * # Safety
 * `materials` must hold `count` ids (it may be null when `count` is 0); `table` be
 * valid or null.
 */
int32_t ss_table_set_walls_f64(ss_table_f64 *table, const uint32_t *materials, size_t count);

/**
 * The pairs of materials the table evaluates, `count` pairs of ids in `pairs` (`a, b`
 * names both orders; replacing any given before; none: every pair, the default). The
 * others are another pair style's (LAMMPS `pair_style hybrid`): each prepare checks
 * the step for the pairs named alone (and every material present against the walls,
 * which then needs coefficients to meet them by), a material in none of them needs no
 * coefficients, and the entries refuse a pair of the others (`SS_ERR_MATERIAL`, with
 * its atoms in the report), as the walls entry refuses an atom of a material absent
 * at the prepare with no law against the walls' material. Returns `SS_OK`,
 * `SS_ERR_NULL`, `SS_ERR_LENGTH` for a count past memory, or `SS_ERR_MATERIAL` for an
 * id past the table (nothing changed). The table does not evaluate until prepared
 * again.
 *
 * # Safety
 * `pairs` must hold `2 count` ids (it may be null when `count` is 0); `table` be valid
 * or null.
 */
int32_t ss_table_set_pairs_f64(ss_table_f64 *table, const uint32_t *pairs, size_t count);

/**
 * As `ss_table_prepare_*`, for a step taken knowingly past the accuracy limit: a step
 * within every pair's stability limit is accepted (`SS_ERR_UNSTABLE_TIME_STEP` past
 * it), and each evaluation counts its contacts past their law's accuracy limit in
 * `ss_list_report.inaccurate` (they may rebound faster than the restitution allows).
 *
 * # Safety
 * As `ss_table_prepare_*`.
 */
int32_t ss_table_prepare_coarse_f64(ss_table_f64 *table,
                                    double time_step,
                                    const double *lightest_mass,
                                    ss_table_report_f64 *report);

/**
 * The whole neighbour list in one call: every pair `(i, j)` with the law of their
 * materials, its state read from the history (zero where `history` is null), each
 * contact the same bits as `ss_sphere_sphere_*` with that law. On success the forces
 * and torques are added into `*loads` (each atom's in list order), each neighbour's
 * touch flag is set (1 where it keeps a state), and, when `advance` is not 0, its
 * history values are advanced
 * (LAMMPS's setup evaluation passes 0). Every count and index is checked first; on any
 * error nothing is written but `*report`, which names the atoms (indices) it is
 * about: `SS_ERR_NULL`, `SS_ERR_LENGTH`, `SS_ERR_INDEX`, `SS_ERR_MATERIAL`,
 * `SS_ERR_NOT_PREPARED`, `SS_ERR_NON_FINITE_INPUT` for an atom whose force or torque
 * in `*loads` is not finite before anything is added (a NaN there would pass through
 * every sum), or a contact's code (`SS_ERR_NON_FINITE_INPUT`, ...,
 * `SS_ERR_PAST_STABLE_STEP`). One thread at a time per table (it keeps its working
 * memory).
 *
 * # Safety
 * Every array must hold what its field says; the written arrays (forces, torques,
 * history) must not overlap each other or the inputs.
 */
int32_t ss_table_evaluate_f64(ss_table_f64 *table,
                              const ss_atoms_f64 *atoms,
                              const ss_neighbours *neighbours,
                              const ss_history_f64 *history,
                              const ss_loads_f64 *loads,
                              int32_t advance,
                              ss_list_report *report);

/**
 * The walls in one call: every selected owned atom against every wall of
 * `*walls` (all of one material of the table), each contact the same bits as
 * `ss_sphere_wall_*` with the law of the atom's material and the walls', its state read
 * from `walls->states`. On success the forces and torques are added into `*loads` (the
 * selected atoms only) and, when `advance` is not 0, the states advanced (an atom clear
 * of every wall is not evaluated: its states are set to zero, as the kernel would). On any error
 * nothing is written but `*report` (the atom it is about): `SS_ERR_NULL`,
 * `SS_ERR_LENGTH`, `SS_ERR_MATERIAL` (a material past the table, or with no law
 * against the walls', see `ss_table_set_pairs_*`), `SS_ERR_BAD_WALL`, `SS_ERR_NOT_PREPARED`,
 * `SS_ERR_NON_FINITE_INPUT` for an owned atom whose force or torque in `*loads` is not
 * finite, or a contact's code. One thread at a time per table.
 *
 * # Safety
 * Every array must hold what its field says (`loads->pair_force` is not read); the
 * written arrays must not overlap each other or the inputs.
 */
int32_t ss_table_evaluate_walls_f64(ss_table_f64 *table,
                                    const ss_atoms_f64 *atoms,
                                    const ss_walls_f64 *walls,
                                    const ss_loads_f64 *loads,
                                    int32_t advance,
                                    ss_list_report *report);

/**
 * One pair's contact with the law of materials `a` and `b`, its state read from
 * `values` (`ss_table_state_values_*` numbers; null for a fresh contact) and not
 * written: what a host reports per pair (LAMMPS `single()`). Writes `*out` on success.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_table_pair_f64(const ss_table_f64 *table,
                          size_t a,
                          size_t b,
                          const ss_sphere_f64 *i,
                          const ss_sphere_f64 *j,
                          const double *values,
                          ss_forces_f64 *out);

/**
 * How many numbers the table's law keeps per contact (0 for the stateless and
 * frictionless laws, 3 for Model AA's displacement, 4 for Mindlin's spring force and
 * contact radius); 0 for a null table.
 *
 * # Safety
 * `table` must be valid or null.
 */
size_t ss_table_state_values_f64(const ss_table_f64 *table);

/**
 * Writes to `target` the state `source` seen from the other body (the pair's i and j
 * swapped): a displacement or spring force is negated, a contact radius kept. `source`
 * and `target` may be the same.
 *
 * # Safety
 * `source` and `target` must hold `ss_table_state_values_*` numbers, or be null.
 */
int32_t ss_table_mirror_state_f64(const ss_table_f64 *table, const double *source, double *target);

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
 * pair's state and outputs are left as they were.
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
 * (infinite at e = 0), from the normal law of `params.model`'s family (micro-slip's is
 * Hertz's). `SS_ERR_UNKNOWN_MODEL` for a code no law has; `*out` is untouched on
 * error.
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

/**
 * A material table of `config->materials` materials, every pair's law of the family
 * `config->model`, written to `*out` (free it with the matching `ss_table_free_*`).
 * Give it coefficients with `ss_table_set_*`, then check its step with
 * `ss_table_prepare_*`. Returns `SS_OK`, `SS_ERR_NULL`, `SS_ERR_UNKNOWN_MODEL`,
 * `SS_ERR_MATERIAL` (no materials, or more than `SS_MATERIALS_MAX`) or, for a Hertz
 * family, the code of a bad declared impact; `*out` is untouched on error.
 *
 * # Safety
 * `config` and `out` must be valid pointers or null.
 */
int32_t ss_table_new_f32(const ss_table_config_f32 *config, ss_table_f32 **out);

/**
 * Frees a table (null is ignored).
 *
 * # Safety
 * `table` must come from the matching constructor and not be used afterwards.
 */
void ss_table_free_f32(ss_table_f32 *table);

/**
 * Gives materials `a` and `b` their coefficients. `a == b`: material `a`'s own, which
 * also make its law with every material not given a pair of its own (the kernel's
 * mixing rule: geometric means, Hertz's and Mindlin's effective moduli). `a != b`: that
 * pair's law, the rule's of `*coefficients` with themselves. Checked now: on error
 * (`SS_ERR_MATERIAL` for a material past the table, or the parameter's code, with the
 * `SS_PARAMETER_*` in `*parameter` when it is not null) the table is unchanged.
 * The table must be prepared again before it evaluates.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_table_set_f32(ss_table_f32 *table,
                         size_t a,
                         size_t b,
                         const ss_coefficients_f32 *coefficients,
                         int32_t *parameter);

/**
 * Makes every pair's law and checks `time_step` against the law of every pair of
 * materials present, at the effective mass of their lightest atoms:
 * `lightest_mass[m]` is material `m`'s lightest atom mass over the whole run (every
 * process's), 0 for a material with no atoms. On error (`SS_ERR_MATERIAL` for a pair
 * with no law, `SS_ERR_UNSTABLE_TIME_STEP` and the others of the parameters,
 * `SS_ERR_NON_FINITE_INPUT` for a mass that is not finite), `*report` (when not null)
 * names the pair of materials, the parameter and the pair's stability limit, and the
 * table does not evaluate until prepared.
 *
 * # Safety
 * `lightest_mass` must hold one number per material; the others be valid or null.
 */
int32_t ss_table_prepare_f32(ss_table_f32 *table,
                             float time_step,
                             const float *lightest_mass,
                             ss_table_report_f32 *report);

/**
 * The materials the walls a host evaluates (`ss_table_evaluate_walls_*`) are made of,
 * `count` ids (replacing any given before; none by default): each prepare then also
 * checks the step against the law of every material present with each of them, at
 * the mass of the material's lightest atom (a sphere against a wall). Returns `SS_OK`,
 * `SS_ERR_NULL`, or `SS_ERR_MATERIAL` for an id past the table (nothing changed).
 * The table does not evaluate until prepared again.
 *
 * # Safety
 * `materials` must hold `count` ids (it may be null when `count` is 0); `table` be
 * valid or null.
 */
int32_t ss_table_set_walls_f32(ss_table_f32 *table, const uint32_t *materials, size_t count);

/**
 * The pairs of materials the table evaluates, `count` pairs of ids in `pairs` (`a, b`
 * names both orders; replacing any given before; none: every pair, the default). The
 * others are another pair style's (LAMMPS `pair_style hybrid`): each prepare checks
 * the step for the pairs named alone (and every material present against the walls,
 * which then needs coefficients to meet them by), a material in none of them needs no
 * coefficients, and the entries refuse a pair of the others (`SS_ERR_MATERIAL`, with
 * its atoms in the report), as the walls entry refuses an atom of a material absent
 * at the prepare with no law against the walls' material. Returns `SS_OK`,
 * `SS_ERR_NULL`, `SS_ERR_LENGTH` for a count past memory, or `SS_ERR_MATERIAL` for an
 * id past the table (nothing changed). The table does not evaluate until prepared
 * again.
 *
 * # Safety
 * `pairs` must hold `2 count` ids (it may be null when `count` is 0); `table` be valid
 * or null.
 */
int32_t ss_table_set_pairs_f32(ss_table_f32 *table, const uint32_t *pairs, size_t count);

/**
 * As `ss_table_prepare_*`, for a step taken knowingly past the accuracy limit: a step
 * within every pair's stability limit is accepted (`SS_ERR_UNSTABLE_TIME_STEP` past
 * it), and each evaluation counts its contacts past their law's accuracy limit in
 * `ss_list_report.inaccurate` (they may rebound faster than the restitution allows).
 *
 * # Safety
 * As `ss_table_prepare_*`.
 */
int32_t ss_table_prepare_coarse_f32(ss_table_f32 *table,
                                    float time_step,
                                    const float *lightest_mass,
                                    ss_table_report_f32 *report);

/**
 * The whole neighbour list in one call: every pair `(i, j)` with the law of their
 * materials, its state read from the history (zero where `history` is null), each
 * contact the same bits as `ss_sphere_sphere_*` with that law. On success the forces
 * and torques are added into `*loads` (each atom's in list order), each neighbour's
 * touch flag is set (1 where it keeps a state), and, when `advance` is not 0, its
 * history values are advanced
 * (LAMMPS's setup evaluation passes 0). Every count and index is checked first; on any
 * error nothing is written but `*report`, which names the atoms (indices) it is
 * about: `SS_ERR_NULL`, `SS_ERR_LENGTH`, `SS_ERR_INDEX`, `SS_ERR_MATERIAL`,
 * `SS_ERR_NOT_PREPARED`, `SS_ERR_NON_FINITE_INPUT` for an atom whose force or torque
 * in `*loads` is not finite before anything is added (a NaN there would pass through
 * every sum), or a contact's code (`SS_ERR_NON_FINITE_INPUT`, ...,
 * `SS_ERR_PAST_STABLE_STEP`). One thread at a time per table (it keeps its working
 * memory).
 *
 * # Safety
 * Every array must hold what its field says; the written arrays (forces, torques,
 * history) must not overlap each other or the inputs.
 */
int32_t ss_table_evaluate_f32(ss_table_f32 *table,
                              const ss_atoms_f32 *atoms,
                              const ss_neighbours *neighbours,
                              const ss_history_f32 *history,
                              const ss_loads_f32 *loads,
                              int32_t advance,
                              ss_list_report *report);

/**
 * The walls in one call: every selected owned atom against every wall of
 * `*walls` (all of one material of the table), each contact the same bits as
 * `ss_sphere_wall_*` with the law of the atom's material and the walls', its state read
 * from `walls->states`. On success the forces and torques are added into `*loads` (the
 * selected atoms only) and, when `advance` is not 0, the states advanced (an atom clear
 * of every wall is not evaluated: its states are set to zero, as the kernel would). On any error
 * nothing is written but `*report` (the atom it is about): `SS_ERR_NULL`,
 * `SS_ERR_LENGTH`, `SS_ERR_MATERIAL` (a material past the table, or with no law
 * against the walls', see `ss_table_set_pairs_*`), `SS_ERR_BAD_WALL`, `SS_ERR_NOT_PREPARED`,
 * `SS_ERR_NON_FINITE_INPUT` for an owned atom whose force or torque in `*loads` is not
 * finite, or a contact's code. One thread at a time per table.
 *
 * # Safety
 * Every array must hold what its field says (`loads->pair_force` is not read); the
 * written arrays must not overlap each other or the inputs.
 */
int32_t ss_table_evaluate_walls_f32(ss_table_f32 *table,
                                    const ss_atoms_f32 *atoms,
                                    const ss_walls_f32 *walls,
                                    const ss_loads_f32 *loads,
                                    int32_t advance,
                                    ss_list_report *report);

/**
 * One pair's contact with the law of materials `a` and `b`, its state read from
 * `values` (`ss_table_state_values_*` numbers; null for a fresh contact) and not
 * written: what a host reports per pair (LAMMPS `single()`). Writes `*out` on success.
 *
 * # Safety
 * All pointers must be valid or null.
 */
int32_t ss_table_pair_f32(const ss_table_f32 *table,
                          size_t a,
                          size_t b,
                          const ss_sphere_f32 *i,
                          const ss_sphere_f32 *j,
                          const float *values,
                          ss_forces_f32 *out);

/**
 * How many numbers the table's law keeps per contact (0 for the stateless and
 * frictionless laws, 3 for Model AA's displacement, 4 for Mindlin's spring force and
 * contact radius); 0 for a null table.
 *
 * # Safety
 * `table` must be valid or null.
 */
size_t ss_table_state_values_f32(const ss_table_f32 *table);

/**
 * Writes to `target` the state `source` seen from the other body (the pair's i and j
 * swapped): a displacement or spring force is negated, a contact radius kept. `source`
 * and `target` may be the same.
 *
 * # Safety
 * `source` and `target` must hold `ss_table_state_values_*` numbers, or be null.
 */
int32_t ss_table_mirror_state_f32(const ss_table_f32 *table, const float *source, float *target);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* SOFT_SPHERE_H */
