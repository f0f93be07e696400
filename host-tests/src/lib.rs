//! Test and validation machinery for `soft-sphere`: a small impact driver built on the kernel's
//! public API, closed-form physics written independently of the kernel, and the validation cases,
//! so that tests compare the kernel against theory and data rather than against itself.

pub mod analytic;
pub mod build;
pub mod data;
pub mod energy;
pub mod impact;
pub mod pairs;
pub mod plot;
pub mod precision;
pub mod random;
pub mod scene;
pub mod seam;
pub mod strategies;
pub mod triple;
pub mod validation;
