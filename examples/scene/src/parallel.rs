//! Spreading a scene step over threads without giving up determinism: the kernel's
//! [`Executor`]. The scene hands it the contacts of stretches of the Verlet list (through the
//! kernel's list seam, each stretch with its own states and per-pair loads, summed onto the
//! spheres in list order on one thread) and the integration of stretches of spheres, so the
//! result is the same bits for any number of threads, and the same bits as [`Serial`].

pub use soft_sphere::executor::{Executor, Serial};
pub(crate) use soft_sphere::executor::{MAX_PIECES, piece_length};
