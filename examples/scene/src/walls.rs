//! The walls of a scene as a compile-time slot: a scene without walls pays nothing for them.

use soft_sphere::prelude::{Float, MaterialWall};

/// The walls of a scene, chosen at compile time: [`NoWalls`] costs nothing. The number of walls
/// is the type's, so the scene sizes its wall states from it. Each wall carries a material id
/// of the step's [`MaterialTable`](soft_sphere::prelude::MaterialTable).
pub trait WallSet<F: Float>: Sync {
    /// How many walls.
    const COUNT: usize;
    /// The walls, [`WallSet::COUNT`] of them.
    fn walls(&self) -> &[MaterialWall<F>];
}

/// A scene without walls.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoWalls;

impl<F: Float> WallSet<F> for NoWalls {
    const COUNT: usize = 0;
    fn walls(&self) -> &[MaterialWall<F>] {
        &[]
    }
}

impl<F: Float, const N: usize> WallSet<F> for [MaterialWall<F>; N] {
    const COUNT: usize = N;
    fn walls(&self) -> &[MaterialWall<F>] {
        self
    }
}
