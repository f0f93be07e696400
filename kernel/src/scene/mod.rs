//! Many-sphere scenes without allocation: a uniform cell grid built by counting sort into
//! caller-owned buffers, a Verlet list of candidate pairs within the contact distance plus a skin
//! (rebuilt from the grid only when a sphere has moved half the skin or crossed a periodic
//! boundary), the stored contact states kept beside the list, walls as a compile-time slot, and
//! one step of symplectic Euler or velocity Verlet.
//!
//! Contacts are owned by the lower sphere index and evaluated in list order, so the stored
//! state and the forces are the same bits for the same inputs. The spheres are checked once, when
//! the scene takes them (their radii and masses never change in a scene), and their positions and
//! velocities after every step; the per-contact work is then the law alone, with the parts that
//! depend only on the masses (effective mass, normal oscillator, `dt / m`) computed once per kind
//! of sphere.

mod grid;
mod parallel;
mod slots;
mod step;
mod walls;

pub use grid::{Candidate, Domain};
pub use parallel::{Executor, PairResult, Serial};
pub use slots::ContactSlots;
pub use walls::{NoWalls, WallSet};

use crate::body::Sphere;
use crate::error::ContactError;
use crate::float::Float;
use crate::geometry::validate;
use crate::law::ContactLaw;
use crate::tangential::ContactState;
use crate::time_step::TimeStep;
use crate::vector::Vec3;

use grid::Grid;

/// Where the history update sits in a step: see [`crate::motion`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Integrator {
    /// Contacts at the start-of-step state, then kick and drift.
    SymplecticEuler,
    /// Half kick with the last forces, drift, contacts at the half-step velocities, half kick.
    VelocityVerlet,
}

/// The caller-owned buffers of a [`Scene`]. Lengths:
/// - one entry per sphere: `forces`, `torques`, `slots`, `cell_entries`, `anchors`;
/// - one per sphere and wall: `wall_states`, `next_wall_states`;
/// - one more than [`Scene::cells_needed`]: `cell_start`;
/// - as many as the Verlet list may hold: `candidates`, `states`, `next_states` (about 4 per
///   sphere in a dense monodisperse packing with a skin of a tenth of a diameter).
///
/// `candidates`, `states` and `wall_states` carry the contact history between steps, and
/// between scenes built over the same buffers: keep them together, and zero (default) `states`,
/// `next_states`, `wall_states` and `next_wall_states` for a fresh scene (the scene keeps every
/// state past the end of its list relaxed, so a new scene finds the history without knowing the
/// old list's length). The `next_` buffers are scratch that makes a step's history
/// update all-or-nothing; `slots` is where the history waits while the list is rebuilt.
#[derive(Debug)]
pub struct SceneBuffers<'a, F, S, const K: usize> {
    /// Contact force on each sphere.
    pub forces: &'a mut [Vec3<F>],
    /// Contact torque on each sphere.
    pub torques: &'a mut [Vec3<F>],
    /// Pair contacts owned by each sphere while the list is rebuilt (at most `K` each).
    pub slots: &'a mut [ContactSlots<S, K>],
    /// Per sphere and wall contact state (history).
    pub wall_states: &'a mut [S],
    /// Scratch for the next step's wall states.
    pub next_wall_states: &'a mut [S],
    /// Cell offsets of the grid.
    pub cell_start: &'a mut [u32],
    /// Sphere indices sorted by cell.
    pub cell_entries: &'a mut [u32],
    /// The Verlet list.
    pub candidates: &'a mut [Candidate],
    /// The contact state of each candidate pair (history).
    pub states: &'a mut [S],
    /// Scratch for the next step's pair states.
    pub next_states: &'a mut [S],
    /// Positions at the last list build.
    pub anchors: &'a mut [Vec3<F>],
    /// Empty, or as long as `candidates`: each pair's forces in a step spread over threads
    /// ([`Scene::step_on`] with a parallel [`Executor`]; with an empty buffer it runs serially).
    pub pair_results: &'a mut [PairResult<F>],
}

/// Why a scene could not be set up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneError {
    /// A buffer's length does not match the number of spheres, cells, walls or candidates.
    BufferLength,
    /// The domain or cell size is not finite and positive, or a periodic direction has fewer
    /// than 3 cells (the half-shell would visit a pair twice).
    Domain,
    /// A stored pair state in `states` belongs to a candidate whose spheres are not this
    /// scene's (the buffers were not zeroed for a fresh scene, or come from another one).
    History,
    /// Sphere `index` is not valid (`error` says why: a non-finite field, a radius or mass that
    /// is not positive).
    Sphere {
        /// Its index.
        index: usize,
        /// What is wrong with it.
        error: ContactError,
    },
}

/// Totals of one step's contacts.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepStats<F> {
    /// Sphere-sphere contacts touching.
    pub pair_contacts: usize,
    /// Sphere-sphere contacts at the Coulomb limit.
    pub sliding_contacts: usize,
    /// Sphere-wall contacts touching.
    pub wall_contacts: usize,
    /// Sum of the sphere-sphere overlaps (m).
    pub overlap_sum: F,
}

/// One step's fixed inputs.
#[derive(Debug)]
pub struct StepInput<'l, F: Float, N, T, M, R, W> {
    /// The contact law of sphere-sphere contacts.
    pub law: &'l ContactLaw<F, N, T, M, R>,
    /// The contact law of sphere-wall contacts (often the same law; a different restitution
    /// gives the walls the same dashpot as a pair, whose effective mass is smaller).
    pub wall_law: &'l ContactLaw<F, N, T, M, R>,
    /// The walls.
    pub walls: &'l W,
    /// Gravitational acceleration (m/s^2).
    pub gravity: Vec3<F>,
    /// The checked step.
    pub time_step: TimeStep<F>,
    /// The integrator.
    pub integrator: Integrator,
}

/// A scene over caller-owned buffers (see [`SceneBuffers`] for their lengths).
#[derive(Debug)]
pub struct Scene<'a, F, S: Copy, const K: usize> {
    spheres: &'a mut [Sphere<F>],
    forces: &'a mut [Vec3<F>],
    torques: &'a mut [Vec3<F>],
    slots: &'a mut [ContactSlots<S, K>],
    wall_states: &'a mut [S],
    next_wall_states: &'a mut [S],
    cell_start: &'a mut [u32],
    cell_entries: &'a mut [u32],
    candidates: &'a mut [Candidate],
    states: &'a mut [S],
    next_states: &'a mut [S],
    candidate_count: usize,
    anchors: &'a mut [Vec3<F>],
    pair_results: &'a mut [PairResult<F>],
    grid: Grid<F>,
    skin: F,
    list_current: bool,
    /// The history has been moved from `states` into `slots` by a list rebuild that has not
    /// finished (it failed): the next rebuild takes it from there.
    history_parked: bool,
    list_builds: usize,
    forces_current: bool,
    /// A step's integration gave a non-finite sphere: every later step refuses to run.
    overflowed: bool,
    /// The live history is in the caller's `next_` buffers (each committed step swaps them).
    swapped: bool,
}

/// Hands the history back in the buffers the caller named `states` and `wall_states`, so a
/// scene built over the same buffers later goes on from it.
impl<F, S: Copy, const K: usize> Drop for Scene<'_, F, S, K> {
    fn drop(&mut self) {
        if self.swapped {
            let live = self.candidate_count.min(self.states.len());
            self.next_states[..live].copy_from_slice(&self.states[..live]);
            self.next_wall_states.copy_from_slice(self.wall_states);
        }
    }
}

impl<'a, F: Float, S: ContactState, const K: usize> Scene<'a, F, S, K> {
    /// A scene over `spheres` in `domain` with `walls` walls ([`WallSet::COUNT`]) and the
    /// buffers described at [`SceneBuffers`]. Grid cells are at least `largest_diameter + skin`
    /// on a side; [`Scene::cells_needed`] gives their number for `cell_start`.
    ///
    /// # Errors
    /// [`SceneError`] for mismatched buffers, a bad domain or skin, or an invalid sphere.
    pub fn new(
        domain: Domain<F>,
        (largest_diameter, skin): (F, F),
        spheres: &'a mut [Sphere<F>],
        buffers: SceneBuffers<'a, F, S, K>,
        walls: usize,
    ) -> Result<Self, SceneError> {
        if !(skin >= F::ZERO && skin.is_finite()) {
            return Err(SceneError::Domain);
        }
        let grid = Grid::new(domain, largest_diameter + skin)?;
        let n = spheres.len();
        let b = buffers;
        let per_sphere = [
            b.forces.len(),
            b.torques.len(),
            b.anchors.len(),
            b.slots.len(),
            b.cell_entries.len(),
        ];
        let lengths_ok = per_sphere.iter().all(|&len| len == n)
            && b.cell_start.len() == grid.total() + 1
            && n <= u32::MAX as usize
            && b.wall_states.len() == n * walls
            && b.next_wall_states.len() == n * walls
            && b.states.len() == b.candidates.len()
            && b.next_states.len() == b.candidates.len()
            && (b.pair_results.is_empty() || b.pair_results.len() == b.candidates.len());
        if !lengths_ok {
            return Err(SceneError::BufferLength);
        }
        Self::check_spheres(spheres)?;
        let listed = b.candidates.len();
        let foreign = b
            .candidates
            .iter()
            .zip(b.states.iter())
            .any(|(c, state)| *state != S::default() && !(c.i < c.j && (c.j as usize) < n));
        if foreign {
            return Err(SceneError::History);
        }
        Ok(Self {
            spheres,
            forces: b.forces,
            torques: b.torques,
            slots: b.slots,
            wall_states: b.wall_states,
            next_wall_states: b.next_wall_states,
            cell_start: b.cell_start,
            cell_entries: b.cell_entries,
            candidates: b.candidates,
            states: b.states,
            next_states: b.next_states,
            // Until the first build, the whole buffer: its relaxed states are skipped.
            candidate_count: listed,
            anchors: b.anchors,
            pair_results: b.pair_results,
            grid,
            skin,
            list_current: false,
            history_parked: false,
            list_builds: 0,
            forces_current: false,
            overflowed: false,
            swapped: false,
        })
    }

    /// Checks what a scene checks of its spheres when it takes them: every field finite,
    /// radius and mass positive.
    ///
    /// # Errors
    /// [`SceneError::Sphere`] for the first sphere that fails.
    pub fn check_spheres(spheres: &[Sphere<F>]) -> Result<(), SceneError> {
        for (index, sphere) in spheres.iter().enumerate() {
            validate(sphere).map_err(|error| SceneError::Sphere { index, error })?;
        }
        Ok(())
    }

    /// How many times the Verlet list has been built.
    pub fn list_builds(&self) -> usize {
        self.list_builds
    }

    /// The number of cells a domain needs (the length of `cell_start` is one more).
    ///
    /// # Errors
    /// [`SceneError::Domain`] for a bad domain or cell size.
    pub fn cells_needed(
        domain: &Domain<F>,
        (largest_diameter, skin): (F, F),
    ) -> Result<usize, SceneError> {
        Ok(Grid::new(*domain, largest_diameter + skin)?.total())
    }

    /// The spheres.
    pub fn spheres(&self) -> &[Sphere<F>] {
        self.spheres
    }

    /// The contact forces of the last evaluation, one per sphere.
    pub fn forces(&self) -> &[Vec3<F>] {
        self.forces
    }

    /// Rebuilds the Verlet list from the cell grid and carries each touching pair's state over
    /// to its new place in the list (through `slots`, so a sphere can own at most `K`).
    fn rebuild_list(&mut self) -> Result<(), ContactError> {
        let stores = size_of::<S>() > 0;
        if stores && !self.history_parked {
            for slot in self.slots.iter_mut() {
                slot.clear();
            }
            for (candidate, state) in self.candidates[..self.candidate_count]
                .iter()
                .zip(self.states.iter())
            {
                // A relaxed state is what a new contact starts from: nothing to carry.
                if *state != S::default() {
                    self.slots[candidate.i as usize].push(candidate.j, *state)?;
                }
            }
            self.history_parked = true;
        }
        let old_count = self.candidate_count;
        self.grid
            .sort(self.spheres, self.cell_start, self.cell_entries);
        // A failed build leaves the history parked and the old length, for the next attempt.
        let count = self.grid.pairs(
            self.spheres,
            (self.cell_start, self.cell_entries),
            self.skin,
            self.candidates,
        )?;
        self.candidate_count = count;
        if stores {
            // Keep every state past the list relaxed (see `SceneBuffers`).
            if count < old_count {
                self.states[count..old_count].fill(S::default());
                self.next_states[count..old_count].fill(S::default());
            }
            for (candidate, state) in self.candidates[..self.candidate_count]
                .iter()
                .zip(self.states.iter_mut())
            {
                *state = self.slots[candidate.i as usize].find(candidate.j);
            }
            self.history_parked = false;
        }
        for (anchor, sphere) in self.anchors.iter_mut().zip(self.spheres.iter()) {
            *anchor = sphere.position;
        }
        self.list_current = true;
        self.list_builds += 1;
        Ok(())
    }
}

impl core::fmt::Display for SceneError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::BufferLength => f.write_str(
                "a scene buffer's length does not match the spheres, cells, walls or candidates",
            ),
            Self::Domain => f.write_str(
                "the scene domain or cell size is invalid (periodic directions need 3 cells)",
            ),
            Self::History => f.write_str(
                "a stored pair state belongs to spheres that are not this scene's (zero the states \
                 for a fresh scene)",
            ),
            Self::Sphere { index, error } => write!(f, "sphere {index} is invalid: {error}"),
        }
    }
}

impl core::error::Error for SceneError {}
