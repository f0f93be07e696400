//! Test and validation machinery for `soft-sphere`: a small impact driver built on the kernel's
//! public API, and closed-form physics written independently of the kernel, so that tests compare
//! the kernel against theory and data rather than against itself.

pub mod analytic;
pub mod data;
pub mod impact;
