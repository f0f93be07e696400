//! The walls of a scene as a compile-time slot: a scene without walls pays nothing for them.

use soft_sphere::{Float, Wall};

/// The walls of a scene, chosen at compile time: [`NoWalls`] costs nothing. The number of walls
/// is the type's, so the scene sizes its wall buffer from it.
pub trait WallSet<F: Float>: Sync {
    /// How many walls.
    const COUNT: usize;
    /// Wall `k`, `None` past [`WallSet::COUNT`].
    fn wall(&self, k: usize) -> Option<&Wall<F>>;
}

/// A scene without walls.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoWalls;

impl<F: Float> WallSet<F> for NoWalls {
    const COUNT: usize = 0;
    fn wall(&self, _: usize) -> Option<&Wall<F>> {
        None
    }
}

impl<F: Float, const N: usize> WallSet<F> for [Wall<F>; N] {
    const COUNT: usize = N;
    fn wall(&self, k: usize) -> Option<&Wall<F>> {
        self.get(k)
    }
}
