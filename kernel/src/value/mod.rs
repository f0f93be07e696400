//! The value types every part shares: the precision (`float.rs`) and the math backends
//! (`backend.rs`), vectors, spheres (`body.rs`, and `checked.rs` for a sphere checked once),
//! walls, materials' elastic constants, the forces a contact gives, the checked time step, the
//! error values, and the small integrator for callers without one (`motion.rs`).

pub(crate) mod backend;
pub(crate) mod body;
pub(crate) mod checked;
pub(crate) mod error;
pub(crate) mod float;
pub(crate) mod forces;
pub(crate) mod material;
pub mod motion;
pub(crate) mod time_step;
pub(crate) mod vector;
pub(crate) mod wall;
