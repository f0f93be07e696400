//! A many-sphere engine on the soft-sphere kernel, without allocation: a uniform cell grid built
//! by counting sort into caller-owned buffers, a Verlet list of candidate pairs within the contact
//! distance plus a skin (rebuilt from the grid only when a sphere has moved half the skin or
//! crossed a periodic boundary), the stored contact states kept beside the list, walls as a
//! compile-time slot, and one step of symplectic Euler or velocity Verlet, on one thread or
//! spread over a caller's [`Executor`] with the same bits.
//!
//! It reaches the contact laws only through the kernel's public checked path: the spheres are
//! [`CheckedSphere`]s (checked when the caller makes them, and by the scene after every step), the
//! law is any [`Law`] bound to its step with [`Law::at`], which derives each pair of masses'
//! normal oscillator once. Contacts are owned by the lower sphere index and evaluated in list
//! order, so the stored state and the forces are the same bits for the same inputs.
//!
//! Guarantees (tested in `host-tests/tests/scene.rs`):
//! - every touching pair is found, across periodic boundaries (against a brute-force search);
//! - stored springs survive list rebuilds, the same bits as the law applied to the pair directly;
//! - the same bits for any number of threads, and run to run;
//! - buffers of the wrong length (for the spheres, the cells, the walls' type) and stored states
//!   of pairs that are not the scene's are refused when the scene is built
//!   ([`SceneError::BufferLength`], [`SceneError::History`]); a failed step leaves the history
//!   as it was (with symplectic Euler, the whole scene); a step whose integration diverges is
//!   reported and the scene refuses to go on.

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod buffers;
mod error;
mod grid;
mod parallel;
mod parking;
mod step;
mod walls;

pub use buffers::{BufferSizes, ListEntry, PairResult, SceneBuffers, SphereEntry, WallEntry};
pub use error::{SceneError, StepError};
pub use grid::Domain;
pub use parallel::{Executor, Serial};
pub use parking::Parking;
pub use walls::{NoWalls, WallSet};

use core::marker::PhantomData;

use soft_sphere::{CheckedSphere, Float, Law, TimeStep, Vec3};

use grid::{Candidate, Grid};

/// Where the history update sits in a step: see the kernel's `motion` module.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Integrator {
    /// Contacts at the start-of-step state, then kick and drift.
    SymplecticEuler,
    /// Half kick with the last forces, drift, contacts at the half-step velocities, half kick.
    VelocityVerlet,
}

impl Integrator {
    /// Both, in a fixed order.
    pub const ALL: [Self; 2] = [Self::SymplecticEuler, Self::VelocityVerlet];

    /// A short name for tables and file names.
    pub fn name(self) -> &'static str {
        match self {
            Self::SymplecticEuler => "symplectic_euler",
            Self::VelocityVerlet => "velocity_verlet",
        }
    }
}

/// The contact force and torque on one sphere.
pub type Load<F> = (Vec3<F>, Vec3<F>);

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
pub struct StepInput<'l, L: Law> {
    /// The contact law of sphere-sphere contacts.
    pub law: &'l L,
    /// The contact law of sphere-wall contacts (often the same law; a different restitution
    /// gives the walls the same dashpot as a pair, whose effective mass is smaller).
    pub wall_law: &'l L,
    /// Gravitational acceleration (m/s^2).
    pub gravity: Vec3<L::Float>,
    /// The checked step.
    pub time_step: TimeStep<L::Float>,
    /// The integrator.
    pub integrator: Integrator,
}

/// A scene of spheres under law `L`, with walls `W` and at most `K` stored contacts per sphere
/// at a list rebuild, over caller-owned buffers ([`SceneBuffers`], sized by
/// [`Scene::buffer_sizes`]).
#[derive(Debug)]
pub struct Scene<'a, L: Law, W, const K: usize> {
    spheres: &'a mut [CheckedSphere<L::Float>],
    entries: &'a mut [SphereEntry<L::Float>],
    cell_start: &'a mut [u32],
    cell_entries: &'a mut [u32],
    list: &'a mut [ListEntry<L::State>],
    parking: &'a mut [Parking<L::State, K>],
    wall_states: &'a mut [WallEntry<L::State>],
    pair_results: &'a mut [PairResult<L::Float>],
    walls: W,
    candidate_count: usize,
    grid: Grid<L::Float>,
    skin: L::Float,
    list_current: bool,
    list_builds: usize,
    forces_current: bool,
    /// A step's integration diverged: every later step refuses to run.
    halted: bool,
    /// Which of each entry's two states is live (each committed step flips it).
    live: usize,
    law: PhantomData<fn() -> L>,
}

/// Checks spheres for a scene, in order: each as a [`CheckedSphere`], or
/// [`SceneError::Sphere`] with its index and what is wrong with it.
///
/// ```
/// use soft_sphere::{ContactError, Sphere, Vec3};
/// use soft_sphere_scene::{SceneError, check_spheres};
///
/// let good = Sphere::solid(Vec3::new(0.0, 0.0, 1.0e-3), 1.0e-3, 2500.0_f64);
/// let bad = Sphere { mass: 0.0, ..good };
/// let mut checked = check_spheres([good, bad]);
/// assert!(checked.next().unwrap().is_ok());
/// assert_eq!(
///     checked.next().unwrap(),
///     Err(SceneError::Sphere { index: 1, error: ContactError::NonPositiveMass })
/// );
/// ```
pub fn check_spheres<F: Float>(
    spheres: impl IntoIterator<Item = soft_sphere::Sphere<F>>,
) -> impl Iterator<Item = Result<CheckedSphere<F>, SceneError>> {
    spheres.into_iter().enumerate().map(|(index, sphere)| {
        CheckedSphere::new(sphere).map_err(|error| SceneError::Sphere { index, error })
    })
}

/// True when the law keeps a per-contact state: a stateless law's scene reads and writes none.
const fn stores<S>() -> bool {
    size_of::<S>() > 0
}

/// Hands the history back in the first of each entry's two states, so that a scene built over
/// the same buffers later goes on from it.
impl<L: Law, W, const K: usize> Drop for Scene<'_, L, W, K> {
    fn drop(&mut self) {
        if self.live == 1 {
            for entry in self.list.iter_mut() {
                entry.states[0] = entry.states[1];
            }
            for entry in self.wall_states.iter_mut() {
                entry.states[0] = entry.states[1];
            }
        }
    }
}

impl<'a, L: Law, W: WallSet<L::Float>, const K: usize> Scene<'a, L, W, K> {
    /// The buffer lengths of a scene of `spheres` spheres in `domain` whose Verlet list holds
    /// up to `list_capacity` pairs, with room for a step spread over threads when `parallel`.
    /// Grid cells are at least `largest_diameter + skin` on a side.
    ///
    /// # Errors
    /// [`SceneError::Domain`] for a bad domain or cell size.
    pub fn buffer_sizes(
        domain: &Domain<L::Float>,
        (largest_diameter, skin): (L::Float, L::Float),
        spheres: usize,
        list_capacity: usize,
        parallel: bool,
    ) -> Result<BufferSizes, SceneError> {
        let cells = Grid::new(*domain, largest_diameter + skin)?.total();
        let stateful = if stores::<L::State>() { spheres } else { 0 };
        Ok(BufferSizes {
            spheres,
            cells: cells + 1 + spheres,
            list: list_capacity,
            parking: stateful,
            walls: stateful * W::COUNT,
            pair_results: if parallel { list_capacity } else { 0 },
        })
    }

    /// A scene over `spheres` in `domain` with `walls`, a Verlet list with `skin`, spheres no
    /// larger than `largest_diameter`, and the buffers of [`Scene::buffer_sizes`].
    ///
    /// # Errors
    /// [`SceneError::Domain`] for a bad domain or skin; [`SceneError::BufferLength`] for a
    /// buffer of another length than [`Scene::buffer_sizes`] gives (`pair_results` may be
    /// empty); [`SceneError::History`] for stored states of pairs that are not this scene's.
    pub fn new(
        domain: Domain<L::Float>,
        (largest_diameter, skin): (L::Float, L::Float),
        spheres: &'a mut [CheckedSphere<L::Float>],
        buffers: SceneBuffers<'a, L::Float, L::State, K>,
        walls: W,
    ) -> Result<Self, SceneError> {
        if !(skin >= L::Float::ZERO && skin.is_finite()) {
            return Err(SceneError::Domain);
        }
        let grid = Grid::new(domain, largest_diameter + skin)?;
        let n = spheres.len();
        let b = buffers;
        let sizes = Self::buffer_sizes(&domain, (largest_diameter, skin), n, b.list.len(), true)?;
        let lengths_ok = b.spheres.len() == sizes.spheres
            && b.cells.len() == sizes.cells
            && b.parking.len() == sizes.parking
            && b.walls.len() == sizes.walls
            && n <= u32::MAX as usize
            && (b.pair_results.is_empty() || b.pair_results.len() == sizes.pair_results);
        if !lengths_ok {
            return Err(SceneError::BufferLength);
        }
        let relaxed = L::State::default();
        let foreign = b.list.iter().any(|entry| {
            let c = entry.candidate;
            entry.states != [relaxed; 2] && !(c.i < c.j && (c.j as usize) < n)
        });
        if foreign {
            return Err(SceneError::History);
        }
        let listed = b.list.len();
        let (cell_start, cell_entries) = b.cells.split_at_mut(grid.total() + 1);
        Ok(Self {
            spheres,
            entries: b.spheres,
            cell_start,
            cell_entries,
            list: b.list,
            parking: b.parking,
            wall_states: b.walls,
            pair_results: b.pair_results,
            walls,
            // Until the first build, the whole buffer: its relaxed states are skipped.
            candidate_count: listed,
            grid,
            skin,
            list_current: false,
            list_builds: 0,
            forces_current: false,
            halted: false,
            live: 0,
            law: PhantomData,
        })
    }

    /// How many times the Verlet list has been built.
    pub fn list_builds(&self) -> usize {
        self.list_builds
    }

    /// The spheres.
    pub fn spheres(&self) -> &[CheckedSphere<L::Float>] {
        self.spheres
    }

    /// The walls.
    pub fn walls(&self) -> &W {
        &self.walls
    }

    /// The walls, to move them between steps.
    pub fn walls_mut(&mut self) -> &mut W {
        &mut self.walls
    }

    /// The contact force and torque on sphere `index` from the last evaluation, `None` past the
    /// last sphere.
    pub fn load(&self, index: usize) -> Option<Load<L::Float>> {
        self.entries.get(index).map(SphereEntry::load)
    }

    /// Rebuilds the Verlet list from the cell grid and carries each touching pair's state over
    /// to its new place in the list (through the parking, so a sphere can own at most `K`).
    /// A failed build leaves the history in the list, as a list of the stored pairs.
    fn rebuild_list(&mut self) -> Result<(), StepError> {
        let live = self.live;
        let relaxed = L::State::default();
        if stores::<L::State>() {
            for parking in self.parking.iter_mut() {
                parking.clear();
            }
            for entry in &self.list[..self.candidate_count] {
                // A relaxed state is what a new contact starts from: nothing to carry.
                let state = entry.states[live];
                if state != relaxed {
                    let c = entry.candidate;
                    self.parking[c.i as usize]
                        .push(c.j, state)
                        .map_err(|()| StepError::ParkingFull)?;
                }
            }
        }
        let old_count = self.candidate_count;
        self.grid
            .sort(self.spheres, self.cell_start, self.cell_entries);
        let Ok(count) = self.grid.pairs(
            self.spheres,
            (self.cell_start, self.cell_entries),
            self.skin,
            self.list,
        ) else {
            // The list's pairs were overwritten up to its end: write the parked history back,
            // for the next attempt or for a scene over a larger list.
            self.unpark(old_count);
            return Err(StepError::ListFull);
        };
        self.candidate_count = count;
        if stores::<L::State>() {
            // Keep every state past the list relaxed (see `SceneBuffers`).
            for entry in self.list[count..old_count.max(count)].iter_mut() {
                entry.states = [relaxed; 2];
            }
            for entry in self.list[..count].iter_mut() {
                let c = entry.candidate;
                entry.states[live] = self.parking[c.i as usize].find(c.j);
            }
        }
        for (entry, sphere) in self.entries.iter_mut().zip(self.spheres.iter()) {
            entry.anchor = sphere.position;
        }
        self.list_current = true;
        self.list_builds += 1;
        Ok(())
    }

    /// Writes the parked states back as the list's first entries (each pair with no image
    /// shift: the list is not current, so only its pairs and states are read) and relaxes the
    /// rest up to `old_count`. They fit: they were parked from the first `old_count` entries.
    fn unpark(&mut self, old_count: usize) {
        if !stores::<L::State>() {
            return;
        }
        let relaxed = L::State::default();
        let mut count = 0;
        for (i, parking) in self.parking.iter().enumerate() {
            for (j, state) in parking.parked() {
                self.list[count] = ListEntry {
                    candidate: Candidate {
                        i: i as u32,
                        j,
                        image: [0, 0],
                    },
                    states: [state; 2],
                };
                count += 1;
            }
        }
        for entry in self.list[count..old_count.max(count)].iter_mut() {
            entry.states = [relaxed; 2];
        }
        self.candidate_count = count;
    }
}
