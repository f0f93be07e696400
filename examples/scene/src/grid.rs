//! The uniform cell grid of a scene and the Verlet list built from it.
//!
//! Spheres are sorted into cells by a counting sort (no allocation: the caller owns the
//! buffers). The list holds every pair within contact distance plus a skin, found by visiting
//! each cell and the 13 cells of its half shell, so each pair is seen once and the cost grows with
//! the number of spheres, not its square. Periodic directions use the minimum image.

use soft_sphere::prelude::{CheckedSphere, Float, Vec3};

use crate::error::SceneError;
use crate::limits::MAX_CELLS;

/// The box the spheres live in. `x` and `y` may be periodic; `z` never is (use walls).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Domain<F> {
    /// Lower corner (m).
    pub lower: Vec3<F>,
    /// Upper corner (m).
    pub upper: Vec3<F>,
    /// Periodic in x.
    pub periodic_x: bool,
    /// Periodic in y.
    pub periodic_y: bool,
}

/// Where a list build writes its pairs (`[i, j]`, `i < j`) and the shift of each pair's `j`
/// (its periodic image).
pub(crate) type ListSlots<'l, F> = (&'l mut [[u32; 2]], &'l mut [Vec3<F>]);

/// The cell and half shell of neighbour cells a pair search visits from each cell.
const HALF_SHELL: [(isize, isize, isize); 14] = [
    (0, 0, 0),
    (1, 0, 0),
    (-1, 1, 0),
    (0, 1, 0),
    (1, 1, 0),
    (-1, -1, 1),
    (0, -1, 1),
    (1, -1, 1),
    (-1, 0, 1),
    (0, 0, 1),
    (1, 0, 1),
    (-1, 1, 1),
    (0, 1, 1),
    (1, 1, 1),
];

/// A domain cut into cells at least as large as the largest contact distance plus the skin.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Grid<F> {
    pub(crate) domain: Domain<F>,
    cells: [usize; 3],
    cell_size: [F; 3],
    lengths: [F; 3],
}

impl<F: Float> Grid<F> {
    /// The grid of `domain` with cells no smaller than `min_cell_size`.
    pub(crate) fn new(domain: Domain<F>, min_cell_size: F) -> Result<Self, SceneError> {
        let extent = domain.upper - domain.lower;
        let mut cells = [0usize; 3];
        let mut cell_size = [F::ZERO; 3];
        let mut total = 1.0f64;
        for (axis, length) in extent.to_array().into_iter().enumerate() {
            if !(length > F::ZERO && length.is_finite() && min_cell_size > F::ZERO) {
                return Err(SceneError::Domain);
            }
            let count = (length / min_cell_size).to_f64();
            if count.is_nan() || count >= 1e6 {
                return Err(SceneError::Domain);
            }
            let count = (count as usize).max(1);
            total *= count as f64;
            if Self::periodic(&domain, axis) && count < 3 {
                return Err(SceneError::Domain);
            }
            cells[axis] = count;
            cell_size[axis] = length / F::from_f64(count as f64);
        }
        // The product, not each axis, is what the buffers hold.
        if total > MAX_CELLS as f64 {
            // `as` saturates: a count past u64 reads as u64::MAX.
            return Err(SceneError::TooManyCells {
                cells: total as u64,
            });
        }
        Ok(Self {
            domain,
            cells,
            cell_size,
            lengths: extent.to_array(),
        })
    }

    fn periodic(domain: &Domain<F>, axis: usize) -> bool {
        (axis == 0 && domain.periodic_x) || (axis == 1 && domain.periodic_y)
    }

    /// The number of cells.
    pub(crate) fn total(&self) -> usize {
        self.cells[0] * self.cells[1] * self.cells[2]
    }

    /// The displacement of periodic image `image` (box lengths in x and y).
    #[inline(always)]
    fn image_shift(&self, image: [i8; 2]) -> Vec3<F> {
        Vec3::new(
            self.lengths[0] * F::from_f64(f64::from(image[0])),
            self.lengths[1] * F::from_f64(f64::from(image[1])),
            F::ZERO,
        )
    }

    fn coordinate(&self, value: F, axis: usize) -> usize {
        let lower = self.domain.lower.to_array()[axis];
        let index = ((value - lower) / self.cell_size[axis]).to_f64();
        // Spheres outside a non-periodic box (or rounding at its edge) go to the edge cells.
        if index <= 0.0 {
            0
        } else {
            (index as usize).min(self.cells[axis] - 1)
        }
    }

    #[inline(always)]
    fn index(&self, x: usize, y: usize, z: usize) -> usize {
        (z * self.cells[1] + y) * self.cells[0] + x
    }

    fn cell_of(&self, position: Vec3<F>) -> usize {
        let p = position.to_array();
        self.index(
            self.coordinate(p[0], 0),
            self.coordinate(p[1], 1),
            self.coordinate(p[2], 2),
        )
    }

    /// Counting sort of the spheres into cells: cell `c` holds
    /// `entries[start[c]..start[c + 1]]`, by increasing sphere index.
    pub(crate) fn sort(
        &self,
        spheres: &[CheckedSphere<F>],
        start: &mut [u32],
        entries: &mut [u32],
    ) {
        start.fill(0);
        for s in spheres {
            start[self.cell_of(s.position) + 1] += 1;
        }
        for c in 0..self.total() {
            start[c + 1] += start[c];
        }
        for (index, s) in spheres.iter().enumerate() {
            // start[cell] serves as the running insert position, restored below.
            let cell = self.cell_of(s.position);
            entries[start[cell] as usize] = index as u32;
            start[cell] += 1;
        }
        for c in (0..self.total()).rev() {
            start[c + 1] = start[c];
        }
        start[0] = 0;
    }

    /// Neighbour cell along one axis, with the periodic image it lies in (-1, 0, 1), or `None`
    /// off a non-periodic edge.
    #[inline(always)]
    fn neighbour(&self, at: usize, step: isize, axis: usize) -> Option<(usize, i8)> {
        let count = self.cells[axis] as isize;
        let next = at as isize + step;
        let periodic = Self::periodic(&self.domain, axis);
        if next < 0 {
            periodic.then(|| ((next + count) as usize, -1))
        } else if next >= count {
            periodic.then(|| ((next - count) as usize, 1))
        } else {
            Some((next as usize, 0))
        }
    }

    /// Every pair within contact distance plus `skin` into `list`, the lower index first with
    /// the shift to the periodic image of the higher; returns how many. The spheres must have been sorted
    /// into `start` and `entries` by [`Grid::sort`].
    ///
    /// # Errors
    /// `Err` when `list` is too short.
    pub(crate) fn pairs(
        &self,
        spheres: &[CheckedSphere<F>],
        (start, entries): (&[u32], &[u32]),
        skin: F,
        mut list: ListSlots<'_, F>,
    ) -> Result<usize, ()> {
        let [nx, ny, nz] = self.cells;
        let mut count = 0;
        for cz in 0..nz {
            for cy in 0..ny {
                for cx in 0..nx {
                    let here = self.index(cx, cy, cz);
                    if start[here] == start[here + 1] {
                        continue; // empty: most of a tall box above a settled bed
                    }
                    for &(dx, dy, dz) in &HALF_SHELL {
                        let (Some((x, image_x)), Some((y, image_y)), Some((z, _))) = (
                            self.neighbour(cx, dx, 0),
                            self.neighbour(cy, dy, 1),
                            self.neighbour(cz, dz, 2),
                        ) else {
                            continue;
                        };
                        let there = self.index(x, y, z);
                        let cells = (
                            &entries[start[here] as usize..start[here + 1] as usize],
                            &entries[start[there] as usize..start[there + 1] as usize],
                        );
                        let same_cell = here == there;
                        count = self.cell_pairs(
                            spheres,
                            cells,
                            (same_cell, [image_x, image_y]),
                            skin,
                            (&mut list, count),
                        )?;
                    }
                }
            }
        }
        Ok(count)
    }

    fn cell_pairs(
        &self,
        spheres: &[CheckedSphere<F>],
        (here, there): (&[u32], &[u32]),
        (same_cell, image): (bool, [i8; 2]),
        skin: F,
        ((pairs, shifts), mut count): (&mut ListSlots<'_, F>, usize),
    ) -> Result<usize, ()> {
        let shift = self.image_shift(image);
        for (at, &a) in here.iter().enumerate() {
            // Within one cell each pair once: only later entries.
            let partners = if same_cell { &there[at + 1..] } else { there };
            let sphere_a = &spheres[a as usize];
            for &b in partners {
                let sphere_b = &spheres[b as usize];
                let reach = sphere_a.radius + sphere_b.radius + skin;
                let offset = sphere_b.position + shift - sphere_a.position;
                if offset.norm_squared() >= reach * reach {
                    continue;
                }
                let (Some(pair), Some(image_shift)) = (pairs.get_mut(count), shifts.get_mut(count))
                else {
                    return Err(());
                };
                // The lower index owns the pair and is body i, so its stored state keeps its
                // orientation whichever cell found the pair.
                (*pair, *image_shift) = if a < b {
                    ([a, b], shift)
                } else {
                    ([b, a], -shift)
                };
                count += 1;
            }
        }
        Ok(count)
    }
}
