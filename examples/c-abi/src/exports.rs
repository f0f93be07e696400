//! The exported functions of both precisions, written once as a macro that the crate root
//! invokes for `f64` and `f32`.

/// The exported functions of one precision: `entry_points!(REAL: names...)` writes them for
/// `REAL` under the given names. The header test expands these invocations for cbindgen, which
/// does not expand macros itself.
macro_rules! entry_points {
    ($real:ident: $law_new:ident, $law_free:ident, $sphere_sphere:ident, $sphere_wall:ident, $bound_new:ident, $bound_free:ident, $bound_sphere_sphere:ident, $bound_sphere_wall:ident, $bound_sphere_pairs:ident, $advance:ident, $duration:ident, $limit:ident, $rejected:ident, $table_new:ident, $table_free:ident, $table_set:ident, $table_prepare:ident, $table_prepare_coarse:ident, $table_set_walls:ident, $table_set_pairs:ident, $table_evaluate:ident, $table_pair:ident, $table_values:ident, $table_mirror:ident, $table_walls:ident) => {
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
        /// pair's state and outputs are left as they were.
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
        /// (infinite at e = 0), from the normal law of `params.model`'s family (micro-slip's is
        /// Hertz's). `SS_ERR_UNKNOWN_MODEL` for a code no law has; `*out` is untouched on
        /// error.
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
            out: *mut *mut any_table::ss_table<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { any_table::table_new(config, out) }
        }

        /// Frees a table (null is ignored).
        ///
        /// # Safety
        /// `table` must come from the matching constructor and not be used afterwards.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_free(table: *mut any_table::ss_table<$real>) {
            // SAFETY: forwarded contract.
            unsafe { any_table::table_free(table) }
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
            table: *mut any_table::ss_table<$real>,
            a: usize,
            b: usize,
            coefficients: *const table::ss_coefficients<$real>,
            parameter: *mut i32,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { any_table::table_set(table, a, b, coefficients, parameter) }
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
            table: *mut any_table::ss_table<$real>,
            time_step: $real,
            lightest_mass: *const $real,
            report: *mut table::ss_table_report<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { any_table::table_prepare(table, (time_step, false), lightest_mass, report) }
        }

        /// The materials the walls a host evaluates (`ss_table_evaluate_walls_*`) are made of,
        /// `count` ids (replacing any given before; none by default): each prepare then also
        /// checks the step against the law of every material present with each of them, at
        /// the mass of the material's lightest atom (a sphere against a wall). Returns `SS_OK`,
        /// `SS_ERR_NULL`, or `SS_ERR_MATERIAL` for an id past the table (nothing changed).
        /// The table does not evaluate until prepared again.
        ///
        /// # Safety
        /// `materials` must hold `count` ids (it may be null when `count` is 0); `table` be
        /// valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_set_walls(
            table: *mut any_table::ss_table<$real>,
            materials: *const u32,
            count: usize,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { any_table::table_set_walls(table, materials, count) }
        }

        /// The pairs of materials the table evaluates, `count` pairs of ids in `pairs` (`a, b`
        /// names both orders; replacing any given before; none: every pair, the default). The
        /// others are another pair style's (LAMMPS `pair_style hybrid`): each prepare checks
        /// the step for the pairs named alone (and every material present against the walls,
        /// which then needs coefficients to meet them by), a material in none of them needs no
        /// coefficients, and the entries refuse a pair of the others (`SS_ERR_MATERIAL`, with
        /// its atoms in the report), as the walls entry refuses an atom of a material absent
        /// at the prepare with no law against the walls' material. Returns `SS_OK`,
        /// `SS_ERR_NULL`, `SS_ERR_LENGTH` for a count past memory, or `SS_ERR_MATERIAL` for an
        /// id past the table (nothing changed). The table does not evaluate until prepared
        /// again.
        ///
        /// # Safety
        /// `pairs` must hold `2 count` ids (it may be null when `count` is 0); `table` be valid
        /// or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_set_pairs(
            table: *mut any_table::ss_table<$real>,
            pairs: *const u32,
            count: usize,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { any_table::table_set_pairs(table, pairs, count) }
        }

        /// As `ss_table_prepare_*`, for a step taken knowingly past the accuracy limit: a step
        /// within every pair's stability limit is accepted (`SS_ERR_UNSTABLE_TIME_STEP` past
        /// it), and each evaluation counts its contacts past their law's accuracy limit in
        /// `ss_list_report.inaccurate` (they may rebound faster than the restitution allows).
        ///
        /// # Safety
        /// As `ss_table_prepare_*`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_prepare_coarse(
            table: *mut any_table::ss_table<$real>,
            time_step: $real,
            lightest_mass: *const $real,
            report: *mut table::ss_table_report<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { any_table::table_prepare(table, (time_step, true), lightest_mass, report) }
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
        /// `SS_ERR_NOT_PREPARED`, `SS_ERR_NON_FINITE_INPUT` for an atom whose force or torque
        /// in `*loads` is not finite before anything is added (a NaN there would pass through
        /// every sum), or a contact's code (`SS_ERR_NON_FINITE_INPUT`, ...,
        /// `SS_ERR_PAST_STABLE_STEP`). One thread at a time per table (it keeps its working
        /// memory).
        ///
        /// # Safety
        /// Every array must hold what its field says; the written arrays (forces, torques,
        /// history) must not overlap each other or the inputs.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_evaluate(
            table: *mut any_table::ss_table<$real>,
            atoms: *const table::ss_atoms<$real>,
            neighbours: *const table::ss_neighbours,
            history: *const table::ss_history<$real>,
            loads: *const table::ss_loads<$real>,
            advance: i32,
            report: *mut table::ss_list_report,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe {
                any_table::table_evaluate(table, atoms, neighbours, history, loads, advance, report)
            }
        }

        /// The walls in one call: every selected owned atom against every wall of
        /// `*walls` (all of one material of the table), each contact the same bits as
        /// `ss_sphere_wall_*` with the law of the atom's material and the walls', its state read
        /// from `walls->states`. On success the forces and torques are added into `*loads` (the
        /// selected atoms only) and, when `advance` is not 0, the states advanced (an atom clear
        /// of every wall is not evaluated: its states are set to zero, as the kernel would). On any error
        /// nothing is written but `*report` (the atom it is about): `SS_ERR_NULL`,
        /// `SS_ERR_LENGTH`, `SS_ERR_MATERIAL` (a material past the table, or with no law
        /// against the walls', see `ss_table_set_pairs_*`), `SS_ERR_BAD_WALL`, `SS_ERR_NOT_PREPARED`,
        /// `SS_ERR_NON_FINITE_INPUT` for an owned atom whose force or torque in `*loads` is not
        /// finite, or a contact's code. One thread at a time per table.
        ///
        /// # Safety
        /// Every array must hold what its field says (`loads->pair_force` is not read); the
        /// written arrays must not overlap each other or the inputs.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_walls(
            table: *mut any_table::ss_table<$real>,
            atoms: *const table::ss_atoms<$real>,
            walls: *const table::ss_walls<$real>,
            loads: *const table::ss_loads<$real>,
            advance: i32,
            report: *mut table::ss_list_report,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { any_table::table_evaluate_walls(table, atoms, walls, loads, advance, report) }
        }

        /// One pair's contact with the law of materials `a` and `b`, its state read from
        /// `values` (`ss_table_state_values_*` numbers; null for a fresh contact) and not
        /// written: what a host reports per pair (LAMMPS `single()`). Writes `*out` on success.
        ///
        /// # Safety
        /// All pointers must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_pair(
            table: *const any_table::ss_table<$real>,
            a: usize,
            b: usize,
            i: *const ss_sphere<$real>,
            j: *const ss_sphere<$real>,
            values: *const $real,
            out: *mut ss_forces<$real>,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { any_table::table_pair(table, a, b, (i, j), values, out) }
        }

        /// How many numbers the table's law keeps per contact (0 for the stateless and
        /// frictionless laws, 3 for Model AA's displacement, 4 for Mindlin's spring force and
        /// contact radius); 0 for a null table.
        ///
        /// # Safety
        /// `table` must be valid or null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_values(table: *const any_table::ss_table<$real>) -> usize {
            any_table::state_values(table)
        }

        /// Writes to `target` the state `source` seen from the other body (the pair's i and j
        /// swapped): a displacement or spring force is negated, a contact radius kept. `source`
        /// and `target` may be the same.
        ///
        /// # Safety
        /// `source` and `target` must hold `ss_table_state_values_*` numbers, or be null.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $table_mirror(
            table: *const any_table::ss_table<$real>,
            source: *const $real,
            target: *mut $real,
        ) -> i32 {
            // SAFETY: forwarded contract.
            unsafe { any_table::table_mirror(table, source, target) }
        }
    };
}
