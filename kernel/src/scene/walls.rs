//! The walls of a scene as a compile-time slot: a scene without walls pays nothing for them.

use crate::body::Wall;
use crate::float::Float;

/// The walls of a scene, chosen at compile time: [`NoWalls`] costs nothing.
pub trait WallSet<F: Float>: Sync {
    /// How many walls.
    const COUNT: usize;
    /// Wall `k` (`k < COUNT`).
    fn wall(&self, k: usize) -> &Wall<F>;
}

/// A scene without walls.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoWalls;

impl<F: Float> WallSet<F> for NoWalls {
    const COUNT: usize = 0;
    fn wall(&self, _: usize) -> &Wall<F> {
        unreachable!("NoWalls has no wall")
    }
}

impl<F: Float, const N: usize> WallSet<F> for [Wall<F>; N] {
    const COUNT: usize = N;
    fn wall(&self, k: usize) -> &Wall<F> {
        &self[k]
    }
}
