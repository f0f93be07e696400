//! Spreading a scene step over threads without giving up determinism.
//!
//! The scene owns no threads. A caller with threads implements [`Executor`] (the std wrapper in
//! `host-tests` does it with rayon); the scene hands it independent pieces of work: the contacts
//! of a stretch of the Verlet list (each with its own stored state and its own result slot),
//! the walls of a stretch of spheres, the integration of a stretch of spheres. The per-contact
//! forces are then added onto the spheres by one thread in list order, exactly as the serial
//! step adds them, so the result is the same bits for any number of threads, and the same bits
//! as [`Serial`].

/// Runs independent pieces of a scene step, on as many threads as it likes.
pub trait Executor {
    /// False for an executor that runs items one after another: the scene then adds each
    /// contact's forces as it goes, without the per-contact result buffer.
    const PARALLEL: bool;

    /// Calls `work` once on every item, in any order and on any thread, and returns when all
    /// are done.
    fn for_each_mut<T: Send, W: Fn(&mut T) + Sync + Send>(&self, items: &mut [T], work: W);
}

/// One thread, in order: what [`Scene::step`](crate::Scene::step) uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Serial;

impl Executor for Serial {
    const PARALLEL: bool = false;

    fn for_each_mut<T: Send, W: Fn(&mut T) + Sync + Send>(&self, items: &mut [T], work: W) {
        items.iter_mut().for_each(work);
    }
}

/// At most this many pieces per phase: enough to keep a many-core machine busy, few enough for
/// a stack array.
pub(crate) const MAX_PIECES: usize = 64;

/// The length of each of at most [`MAX_PIECES`] pieces covering `total` items (at least
/// `smallest`, so that tiny scenes are not cut into slivers).
pub(crate) fn piece_length(total: usize, smallest: usize) -> usize {
    total.div_ceil(MAX_PIECES).max(smallest).max(1)
}
