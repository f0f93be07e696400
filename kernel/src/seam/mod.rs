//! The list seam: a whole contact list over the engine's own arrays in one call (`list.rs`), the
//! table of laws per pair of materials (`table.rs`), the spheres' layouts (`spheres.rs`), the pair
//! list checked once (`pair_check.rs`), the pair phase chunk by chunk (`pairs.rs`) and spread over
//! threads (`spread.rs`, `executor.rs`), what a refusal names (`list_error.rs`), the totals
//! (`stats.rs`), and the history store for callers without a pair list (`store.rs`).

pub mod executor;
pub(crate) mod list;
pub(crate) mod list_error;
pub(crate) mod pair_check;
pub(crate) mod pairs;
pub(crate) mod spheres;
pub(crate) mod spread;
pub(crate) mod stats;
pub(crate) mod store;
pub(crate) mod table;
