//! The contact laws and their slots: the law composed from its slots (`contact_law.rs`), the
//! handle an engine binds to a step (`engine.rs`), the named laws and their list (`laws.rs`), the
//! contact frame (`geometry.rs`), the slots (`normal/`, `tangential/`, `rolling.rs`,
//! `rotation.rs`), the mixing rules of a material table (`mixing.rs`), the kernel's guarantees as
//! checks (`checks.rs`) and the chunk the list seam's hooks fill (`sifted.rs`).

pub mod checks;
pub(crate) mod contact_law;
pub(crate) mod engine;
pub(crate) mod geometry;
pub(crate) mod laws;
pub(crate) mod mixing;
pub(crate) mod normal;
pub(crate) mod rolling;
pub(crate) mod rotation;
pub(crate) mod sifted;
pub(crate) mod tangential;
