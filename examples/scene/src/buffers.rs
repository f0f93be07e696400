//! The caller-owned memory of a scene. Their element types are opaque: a caller sizes the
//! buffers with [`Scene::buffer_sizes`](crate::Scene::buffer_sizes), fills them with
//! `Default::default()`, and keeps them together between scenes.

use soft_sphere::{Float, Vec3};

use crate::grid::Candidate;
use crate::parking::Parking;

/// What a scene keeps per sphere: the contact force and torque of the last evaluation, and the
/// position at the last list build.
#[derive(Clone, Copy, Debug, Default)]
pub struct SphereEntry<F> {
    pub(crate) force: Vec3<F>,
    pub(crate) torque: Vec3<F>,
    pub(crate) anchor: Vec3<F>,
}

/// One entry of the Verlet list: a candidate pair and its contact state, twice, so that a step's
/// history update is all or nothing (one is live, the other receives the next step's).
#[derive(Clone, Copy, Debug, Default)]
pub struct ListEntry<S> {
    pub(crate) candidate: Candidate,
    pub(crate) states: [S; 2],
}

/// One sphere's contact state against one wall, twice (see [`ListEntry`]).
#[derive(Clone, Copy, Debug, Default)]
pub struct WallEntry<S> {
    pub(crate) states: [S; 2],
}

/// What one candidate pair contributed in a step spread over threads, kept until the forces are
/// added up in list order.
#[derive(Clone, Copy, Debug, Default)]
pub struct PairResult<F> {
    pub(crate) force_on_j: Vec3<F>,
    pub(crate) torque_on_i: Vec3<F>,
    pub(crate) torque_on_j: Vec3<F>,
    pub(crate) overlap: F,
    pub(crate) touching: bool,
    pub(crate) sliding: bool,
}

/// The lengths a scene's buffers must have, from [`Scene::buffer_sizes`](crate::Scene::buffer_sizes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BufferSizes {
    /// [`SceneBuffers::spheres`]: one per sphere.
    pub spheres: usize,
    /// [`SceneBuffers::cells`]: one per grid cell, plus one, plus one per sphere.
    pub cells: usize,
    /// [`SceneBuffers::list`]: the Verlet list's capacity (about 4.5 per sphere in a dense
    /// monodisperse packing with a skin of a tenth of a diameter).
    pub list: usize,
    /// [`SceneBuffers::parking`]: one per sphere, or none for a law that stores nothing.
    pub parking: usize,
    /// [`SceneBuffers::walls`]: one per sphere and wall, or none for a law that stores nothing.
    pub walls: usize,
    /// [`SceneBuffers::pair_results`]: as long as the list for a step spread over threads,
    /// otherwise none.
    pub pair_results: usize,
}

/// The caller-owned buffers of a [`Scene`](crate::Scene), of the lengths
/// [`Scene::buffer_sizes`](crate::Scene::buffer_sizes) gives. `list` and `walls` carry the
/// contact history between steps and between scenes built over the same buffers (the scene
/// keeps every entry past the end of its list relaxed, so a new scene finds the history without
/// knowing the old list's length); start a fresh scene from default entries.
#[derive(Debug)]
pub struct SceneBuffers<'a, F, S, const K: usize> {
    /// Per sphere: contact force and torque, position at the last list build.
    pub spheres: &'a mut [SphereEntry<F>],
    /// The cell grid: cell offsets, then the spheres sorted by cell.
    pub cells: &'a mut [u32],
    /// The Verlet list and its pairs' contact states (history).
    pub list: &'a mut [ListEntry<S>],
    /// Where each sphere's stored states wait while the list is rebuilt (at most `K` each).
    pub parking: &'a mut [Parking<S, K>],
    /// Per sphere and wall contact state (history).
    pub walls: &'a mut [WallEntry<S>],
    /// Each pair's forces in a step spread over threads
    /// ([`Scene::step_on`](crate::Scene::step_on) with a parallel
    /// [`Executor`](crate::Executor)); with an empty buffer such a step runs its pairs serially.
    pub pair_results: &'a mut [PairResult<F>],
}

impl<F: Float> SphereEntry<F> {
    /// The contact force and torque of the last evaluation.
    pub(crate) fn load(&self) -> (Vec3<F>, Vec3<F>) {
        (self.force, self.torque)
    }
}
