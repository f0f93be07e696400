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
//! list. The law handles are in `handle.rs`; a material table and a whole neighbour list per call,
//! `ss_table_*`, in `any_table.rs` (one family's table in `table.rs`, the list entry in `list.rs`).
//!
//! The header `include/soft_sphere.h` is generated from `src/` by cbindgen; the test
//! `header_is_current` fails when it is stale (`UPDATE_HEADER=1 cargo test -p soft-sphere-ffi`
//! rewrites it).

#![allow(non_camel_case_types)] // C names: ss_law_f64, ss_sphere_f32, ...

#[macro_use]
mod registry;
#[macro_use]
mod exports;
mod any_table;
mod arrays;
mod codes;
mod handle;
mod list;
mod names;
mod real;
mod state;
pub mod table;
mod types;

pub use arrays::*;
pub use codes::*;
pub use real::Real;
pub use registry::*; // the laws' SS_MODEL_* codes
pub use types::*;

pub use names::{
    ss_contact_error_text, ss_model_code, ss_model_count, ss_model_is_hertz, ss_model_name,
    ss_model_of_name, ss_parameter_error_text, ss_parameter_name, ss_version,
};

pub use any_table::{ss_check_neighbours, ss_table};
pub use table::{
    SS_ERR_INDEX, SS_ERR_LENGTH, SS_ERR_MATERIAL, SS_ERR_NOT_PREPARED, SS_ERR_REPEATED_PAIR,
    SS_MATERIALS_MAX, SS_ROLLING_EPSD, SS_ROLLING_NONE, ss_atoms, ss_coefficients, ss_history,
    ss_list_report, ss_loads, ss_neighbours, ss_table_config, ss_table_report, ss_walls,
};

pub use handle::*;
use state::*;

entry_points!(f64: ss_law_new_f64, ss_law_free_f64, ss_sphere_sphere_f64, ss_sphere_wall_f64, ss_bound_law_new_f64, ss_bound_law_free_f64, ss_bound_sphere_sphere_f64, ss_bound_sphere_wall_f64, ss_bound_sphere_pairs_f64, ss_advance_sphere_f64, ss_contact_duration_f64, ss_stability_limit_f64, ss_rejected_parameter_f64, ss_table_new_f64, ss_table_free_f64, ss_table_set_f64, ss_table_prepare_f64, ss_table_prepare_coarse_f64, ss_table_set_walls_f64, ss_table_set_pairs_f64, ss_table_evaluate_f64, ss_table_pair_f64, ss_table_state_values_f64, ss_table_mirror_state_f64, ss_table_evaluate_walls_f64);
entry_points!(f32: ss_law_new_f32, ss_law_free_f32, ss_sphere_sphere_f32, ss_sphere_wall_f32, ss_bound_law_new_f32, ss_bound_law_free_f32, ss_bound_sphere_sphere_f32, ss_bound_sphere_wall_f32, ss_bound_sphere_pairs_f32, ss_advance_sphere_f32, ss_contact_duration_f32, ss_stability_limit_f32, ss_rejected_parameter_f32, ss_table_new_f32, ss_table_free_f32, ss_table_set_f32, ss_table_prepare_f32, ss_table_prepare_coarse_f32, ss_table_set_walls_f32, ss_table_set_pairs_f32, ss_table_evaluate_f32, ss_table_pair_f32, ss_table_state_values_f32, ss_table_mirror_state_f32, ss_table_evaluate_walls_f32);
