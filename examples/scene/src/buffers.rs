//! The caller-owned memory of a scene: a caller sizes the buffers with
//! [`Scene::buffer_sizes`](crate::Scene::buffer_sizes), fills them with `Default::default()`,
//! and keeps them together between scenes (the contact history lives in them).

use soft_sphere::prelude::{Interaction, PairLoad, Vec3};

use crate::parking::Parking;

/// The lengths a scene's buffers must have, from [`Scene::buffer_sizes`](crate::Scene::buffer_sizes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BufferSizes {
    /// The length of [`SceneBuffers::cells`]: one per grid cell, plus one, plus one per sphere.
    pub cells: usize,
    /// The length of [`SceneBuffers::pairs`]: the Verlet list's capacity (about 4.5 per sphere in a dense
    /// monodisperse packing with a skin of a tenth of a diameter).
    pub pairs: usize,
    /// The length of [`SceneBuffers::vectors`]: one per list place (its periodic shift) and
    /// three per sphere (force, torque, position at the last list build).
    pub vectors: usize,
    /// The length of [`SceneBuffers::states`]: twice (the states a step reads, and the buffer it
    /// writes the next ones into) one per list place and one per sphere and wall.
    pub states: usize,
    /// The length of [`SceneBuffers::parking`]: one per sphere, or none for a law that stores nothing.
    pub parking: usize,
    /// The length of [`SceneBuffers::records`]: one per list place and per sphere and wall when the scene
    /// keeps each contact's outcome (its per-contact view and energy accounting), else none.
    pub records: usize,
    /// The length of [`SceneBuffers::loads`]: one per list place, for a scene whose pairs are
    /// spread over an executor's threads (it may be empty: the pairs then take one thread).
    pub loads: usize,
}

/// The caller-owned buffers of a [`Scene`](crate::Scene), of the lengths
/// [`Scene::buffer_sizes`](crate::Scene::buffer_sizes) gives. `pairs` and the front of
/// `states` carry the contact history between steps and between scenes built over the same
/// buffers (the scene keeps every state past the end of its list relaxed, so a new scene finds
/// the history without knowing the old list's length); start a fresh scene from default
/// entries.
#[derive(Debug)]
pub struct SceneBuffers<'a, F, S, const K: usize> {
    /// The cell grid: cell offsets, then the spheres sorted by cell.
    pub cells: &'a mut [u32],
    /// The Verlet list: each candidate pair of sphere indices.
    pub pairs: &'a mut [[u32; 2]],
    /// Per list place and per sphere working vectors (see [`BufferSizes::vectors`]).
    pub vectors: &'a mut [Vec3<F>],
    /// The contact states of the list's pairs, then of each sphere against each wall, then as
    /// many again: the second buffer of the double-buffered states (a scene swaps the two at
    /// every committed step and puts the current ones back in front when it is dropped).
    pub states: &'a mut [S],
    /// Where each sphere's stored states wait while the list is rebuilt (at most `K` each).
    pub parking: &'a mut [Parking<S, K>],
    /// Each contact's outcome of the last step, or empty: then the scene keeps no per-contact
    /// view and does no energy accounting.
    pub records: &'a mut [Interaction<F>],
    /// Each pair's loads while its thread hands them on (working memory of
    /// [`MaterialTable::evaluate_on`](soft_sphere::prelude::MaterialTable::evaluate_on)), or empty: then
    /// the pairs are evaluated on one thread, whatever the executor.
    pub loads: &'a mut [PairLoad<F>],
}
