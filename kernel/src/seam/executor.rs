//! Spreading independent pieces of work over a caller's threads without giving up determinism.
//!
//! The kernel owns no threads. A caller with threads implements [`Executor`] (`host-tests` does
//! it with rayon); the list seam ([`MaterialTable::evaluate_on`](crate::MaterialTable::evaluate_on))
//! hands it stretches of the pair list, each with its own states and its own per-pair loads,
//! then adds the loads onto the spheres on one thread in list order, exactly as one thread adds
//! them as it goes: the same bits for any executor and any number of threads.

/// Runs independent pieces of work, on as many threads as it likes.
pub trait Executor {
    /// False for an executor that runs items one after another: the list seam then adds each
    /// contact's forces as it goes, without the per-pair loads.
    const PARALLEL: bool;

    /// Calls `work` once on every item, in any order and on any thread, and returns when all
    /// are done.
    fn for_each_mut<T: Send, W: Fn(&mut T) + Sync + Send>(&self, items: &mut [T], work: W);
}

/// One thread, in order.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Serial;

impl Executor for Serial {
    const PARALLEL: bool = false;

    fn for_each_mut<T: Send, W: Fn(&mut T) + Sync + Send>(&self, items: &mut [T], work: W) {
        items.iter_mut().for_each(work);
    }
}

/// At most this many pieces per phase: enough to keep a many-core machine busy, few enough for
/// an array on the stack.
pub const MAX_PIECES: usize = 64;

/// The length of each of at most [`MAX_PIECES`] pieces covering `total` items (at least
/// `smallest`, so that small problems are not cut into slivers).
pub fn piece_length(total: usize, smallest: usize) -> usize {
    total.div_ceil(MAX_PIECES).max(smallest).max(1)
}
