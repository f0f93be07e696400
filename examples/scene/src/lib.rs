//! A many-sphere engine on the soft-sphere kernel, without allocation: a uniform cell grid built
//! by counting sort into caller-owned buffers, a Verlet list of candidate pairs within the contact
//! distance plus a skin (rebuilt from the grid only when a sphere has moved half the skin or
//! crossed a periodic boundary), the stored contact states kept beside the list, walls with
//! materials as a compile-time slot, and one step of symplectic Euler or velocity Verlet; the
//! pairs and the integration can be spread over a caller's [`Executor`] with the same bits.
//!
//! It reaches the contact laws only through the kernel's list seam
//! ([`MaterialTable::evaluate`](soft_sphere::prelude::MaterialTable::evaluate)): each step hands it the
//! whole Verlet list (pairs, periodic shifts, states) and the walls over the scene's
//! [`CheckedSphere`]s and their material ids, and the seam picks each contact's law from the
//! table, checks it against the step, and adds the forces in list order. Contacts are owned by
//! the lower sphere index, so the stored state and the forces are the same bits for the same
//! inputs.
//!
//! Guarantees (tested in `host-tests/tests/scene.rs`):
//! - every touching pair is found, across periodic boundaries (against a brute-force search);
//! - stored springs survive list rebuilds, the same bits as the law applied to the pair directly;
//! - the same bits for any number of threads, and run to run;
//! - the step is checked against every pair of materials the spheres present
//!   ([`Scene::time_step`]), and every contact against it at every step;
//! - with a records buffer, each step's touching contacts can be read ([`Scene::contacts`]) and
//!   the step's statistics carry an energy account ([`Energy`]) whose balance stays constant
//!   to the integrator's error;
//! - buffers of the wrong length and stored states of pairs that are not the scene's are
//!   refused when the scene is built ([`SceneError::BufferLength`], [`SceneError::History`]); a
//!   failed step leaves the history as it was (with symplectic Euler, the whole scene); a step
//!   whose integration diverges is reported and the scene refuses to go on.
//!
//! With the `alloc` feature, [`OwnedScene`] owns its buffers: a std user writes no buffer code.
//! With the `vtk` feature (std), [`Frames`] writes the scene as files ParaView opens.

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

#[cfg(feature = "alloc")]
extern crate alloc;
#[cfg(feature = "vtk")]
extern crate std;

mod buffers;
mod energy;
mod error;
mod grid;
mod limits;
#[cfg(feature = "alloc")]
mod owned;
mod parallel;
mod parking;
mod states;
mod step;
mod view;
#[cfg(feature = "vtk")]
mod vtk;
mod walls;

pub use buffers::{BufferSizes, SceneBuffers};
pub use energy::Energy;
pub use error::{SceneError, StepError};
pub use grid::Domain;
pub use limits::MAX_CELLS;
#[cfg(feature = "alloc")]
pub use owned::{OwnedScene, PAIRS_PER_SPHERE, PARKING};
pub use parallel::{Executor, Serial};
pub use parking::Parking;
pub use view::{ContactBodies, ContactView};
#[cfg(feature = "vtk")]
pub use vtk::{Frames, write_contacts, write_spheres};
pub use walls::{NoWalls, WallSet};

use core::marker::PhantomData;

use soft_sphere::prelude::{
    CheckedSphere, Float, Interaction, Law, MaterialTable, PairList, PairLoad, SphereSlice,
    TimeStep, Vec3,
};

use energy::Ledger;
use grid::Grid;

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
    /// Contacts (pairs and walls) at the Coulomb limit.
    pub sliding_contacts: usize,
    /// Sphere-wall contacts touching.
    pub wall_contacts: usize,
    /// Touching contacts past their law's accuracy limit that the step evaluated knowingly: a
    /// coarse step's ([`Scene::coarse_time_step`]), or those a step made with
    /// [`TimeStep::tolerating_unstable_contacts`] let through (otherwise they stop the step).
    pub inaccurate_contacts: usize,
    /// Sum of the sphere-sphere overlaps (m).
    pub overlap_sum: F,
    /// The energy account at the end of the step, when the scene keeps records
    /// ([`SceneBuffers::records`]).
    pub energy: Option<Energy<F>>,
}

/// One step's fixed inputs.
#[derive(Debug)]
pub struct StepInput<'l, L: Law, const MATERIALS: usize> {
    /// The law of every pair of materials (walls' materials included).
    pub table: &'l MaterialTable<L, MATERIALS>,
    /// Gravitational acceleration (m/s^2).
    pub gravity: Vec3<L::Float>,
    /// The checked step: [`Scene::time_step`] checks it against the spheres present.
    pub time_step: TimeStep<L::Float>,
    /// The integrator.
    pub integrator: Integrator,
}

/// A scene of spheres under laws `L`, with walls `W` and at most `K` stored contacts per
/// sphere at a list rebuild, over caller-owned buffers ([`SceneBuffers`], sized by
/// [`Scene::buffer_sizes`]).
#[derive(Debug)]
pub struct Scene<'a, L: Law, W, const K: usize> {
    spheres: &'a mut [CheckedSphere<L::Float>],
    materials: &'a [u32],
    cell_start: &'a mut [u32],
    cell_entries: &'a mut [u32],
    /// The Verlet list: pairs and periodic shifts, checked by the kernel at each build.
    list: PairList<'a, L::Float>,
    force: &'a mut [Vec3<L::Float>],
    torque: &'a mut [Vec3<L::Float>],
    anchor: &'a mut [Vec3<L::Float>],
    /// The states the last committed step left (read by the next evaluation), and the buffer
    /// it writes into; swapped when a step commits ([`Scene::flip`]).
    pair_states: &'a mut [L::State],
    wall_states: &'a mut [L::State],
    next_pair_states: &'a mut [L::State],
    next_wall_states: &'a mut [L::State],
    /// The current states sit in the back half of the caller's `states` buffer: put back in
    /// front when the scene is dropped (see [`SceneBuffers`]).
    flipped: bool,
    parking: &'a mut [Parking<L::State, K>],
    records: &'a mut [Interaction<L::Float>],
    loads: &'a mut [PairLoad<L::Float>],
    walls: W,
    candidate_count: usize,
    grid: Grid<L::Float>,
    skin: L::Float,
    list_current: bool,
    list_builds: usize,
    /// The records hold the outcome of the list's pairs at the last evaluation.
    records_current: bool,
    forces_current: bool,
    /// A step's integration diverged: every later step refuses to run.
    halted: bool,
    ledger: Ledger<L::Float>,
    law: PhantomData<fn() -> L>,
}

/// Checks spheres for a scene, in order: each as a [`CheckedSphere`], or
/// [`SceneError::Sphere`] with its index and what is wrong with it.
///
/// ```
/// use soft_sphere::prelude::{ContactError, Sphere, Vec3};
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
    spheres: impl IntoIterator<Item = soft_sphere::prelude::Sphere<F>>,
) -> impl Iterator<Item = Result<CheckedSphere<F>, SceneError>> {
    spheres.into_iter().enumerate().map(|(index, sphere)| {
        CheckedSphere::new(sphere).map_err(|error| SceneError::Sphere { index, error })
    })
}

/// Checks each sphere against what the scene was built for: a diameter no larger than the
/// declared largest (the grid's cells are sized from it: a larger sphere's contacts across
/// cells would go unseen), and a centre inside the domain along its closed directions.
fn check_placement<F: Float>(
    spheres: &[CheckedSphere<F>],
    domain: &Domain<F>,
    largest_diameter: F,
) -> Result<(), SceneError> {
    for (index, sphere) in spheres.iter().enumerate() {
        if sphere.radius + sphere.radius > largest_diameter {
            return Err(SceneError::Diameter { index });
        }
    }
    match first_outside(spheres, domain) {
        Some(index) => Err(SceneError::Outside { index }),
        None => Ok(()),
    }
}

/// The first sphere whose centre is outside the domain along a direction that is not periodic.
fn first_outside<F: Float>(spheres: &[CheckedSphere<F>], domain: &Domain<F>) -> Option<usize> {
    let closed = [!domain.periodic_x, !domain.periodic_y, true];
    let (lo, hi) = (domain.lower.to_array(), domain.upper.to_array());
    spheres.iter().position(|sphere| {
        let p = sphere.position.to_array();
        (0..3).any(|axis| closed[axis] && !(p[axis] >= lo[axis] && p[axis] <= hi[axis]))
    })
}

/// True when the law keeps a per-contact state: a stateless law's scene parks none.
const fn stores<S>() -> bool {
    size_of::<S>() > 0
}

impl<'a, L: Law, W: WallSet<L::Float>, const K: usize> Scene<'a, L, W, K> {
    /// The buffer lengths of a scene of `spheres` spheres in `domain` whose Verlet list holds
    /// up to `list_capacity` pairs, keeping each contact's outcome when `records`. Grid cells
    /// are at least `largest_diameter + skin` on a side.
    ///
    /// # Errors
    /// [`SceneError::Domain`] for a bad domain or cell size.
    pub fn buffer_sizes(
        domain: &Domain<L::Float>,
        (largest_diameter, skin): (L::Float, L::Float),
        spheres: usize,
        list_capacity: usize,
        records: bool,
    ) -> Result<BufferSizes, SceneError> {
        let cells = Grid::new(*domain, largest_diameter + skin)?.total();
        let contacts = list_capacity + spheres * W::COUNT;
        Ok(BufferSizes {
            cells: cells + 1 + spheres,
            pairs: list_capacity,
            vectors: list_capacity + 3 * spheres,
            states: 2 * contacts,
            parking: if stores::<L::State>() { spheres } else { 0 },
            records: if records { contacts } else { 0 },
            loads: list_capacity,
        })
    }

    /// A scene over `spheres` of materials `materials` (one id per sphere, rows of the step's
    /// [`MaterialTable`]) in `domain` with `walls`, a Verlet list with `skin`, spheres no
    /// larger than `largest_diameter`, and the buffers of [`Scene::buffer_sizes`].
    ///
    /// # Errors
    /// [`SceneError::Domain`] for a bad domain or skin; [`SceneError::Materials`] for material
    /// ids that are not one per sphere; [`SceneError::Diameter`] for a sphere larger than
    /// `largest_diameter`, [`SceneError::Outside`] for one outside the domain along a closed
    /// direction; [`SceneError::BufferLength`] for a buffer of another
    /// length than [`Scene::buffer_sizes`] gives (`records` and `loads` may be empty);
    /// [`SceneError::History`] for stored states of pairs that are not this scene's.
    pub fn new(
        domain: Domain<L::Float>,
        (largest_diameter, skin): (L::Float, L::Float),
        (spheres, materials): (&'a mut [CheckedSphere<L::Float>], &'a [u32]),
        buffers: SceneBuffers<'a, L::Float, L::State, K>,
        walls: W,
    ) -> Result<Self, SceneError> {
        if !(skin >= L::Float::ZERO && skin.is_finite()) {
            return Err(SceneError::Domain);
        }
        let grid = Grid::new(domain, largest_diameter + skin)?;
        let n = spheres.len();
        if materials.len() != n {
            return Err(SceneError::Materials);
        }
        check_placement(spheres, &domain, largest_diameter)?;
        let b = buffers;
        let list = b.pairs.len();
        let sizes = Self::buffer_sizes(&domain, (largest_diameter, skin), n, list, true)?;
        let lengths_ok = b.cells.len() == sizes.cells
            && b.vectors.len() == sizes.vectors
            && b.states.len() == sizes.states
            && b.parking.len() == sizes.parking
            && n <= u32::MAX as usize
            && (b.records.is_empty() || b.records.len() == sizes.records)
            && (b.loads.is_empty() || b.loads.len() == sizes.loads);
        if !lengths_ok {
            return Err(SceneError::BufferLength);
        }
        let relaxed = L::State::default();
        let foreign = b
            .pairs
            .iter()
            .zip(b.states.iter())
            .any(|(&[i, j], state)| *state != relaxed && !(i < j && (j as usize) < n));
        if foreign {
            return Err(SceneError::History);
        }
        let (cell_start, cell_entries) = b.cells.split_at_mut(grid.total() + 1);
        let (shifts, per_sphere) = b.vectors.split_at_mut(list);
        let (force, per_sphere) = per_sphere.split_at_mut(n);
        let (torque, per_sphere) = per_sphere.split_at_mut(n);
        let anchor = per_sphere;
        let (current, next) = b.states.split_at_mut(list + n * W::COUNT);
        let (pair_states, wall_states) = current.split_at_mut(list);
        // Nothing to clear: the seam writes the second buffer in full up to the list's length,
        // and the first build relaxes both buffers past it (`rebuild_list`).
        let (next_pair_states, next_wall_states) = next.split_at_mut(list);
        // The shifts were cut to the pairs' length.
        let verlet = PairList::new(b.pairs, shifts).map_err(|_| SceneError::BufferLength)?;
        Ok(Self {
            spheres,
            materials,
            cell_start,
            cell_entries,
            list: verlet,
            force,
            torque,
            anchor,
            pair_states,
            wall_states,
            next_pair_states,
            next_wall_states,
            flipped: false,
            parking: b.parking,
            records: b.records,
            loads: b.loads,
            walls,
            // Until the first build, the whole buffer: its relaxed states are skipped.
            candidate_count: list,
            grid,
            skin,
            list_current: false,
            list_builds: 0,
            records_current: false,
            forces_current: false,
            halted: false,
            ledger: Ledger::default(),
            law: PhantomData,
        })
    }

    /// `seconds` checked for accuracy against the laws of `table` for the spheres and walls
    /// present: every pair of materials at the smallest effective mass its spheres give, every
    /// sphere material with every wall's ([`MaterialTable::time_step`]). Per-contact checks at
    /// every step catch what this cannot see (a Hertz contact pressed harder than declared).
    ///
    /// # Errors
    /// [`StepError::TimeStep`] for the first pair of materials whose law refuses the step;
    /// [`StepError::Material`] / [`StepError::WallMaterial`] for an id past the table.
    pub fn time_step<const MATERIALS: usize>(
        &self,
        table: &MaterialTable<L, MATERIALS>,
        seconds: L::Float,
    ) -> Result<TimeStep<L::Float>, StepError> {
        table
            .time_step(seconds, &self.sphere_slice(), self.walls.walls())
            .map_err(|error| StepError::from_list(error, &[]))
    }

    /// As [`Scene::time_step`], checked for stability only
    /// ([`MaterialTable::coarse_time_step`]): a step past the accuracy limit, asked for
    /// knowingly (its contacts can rebound faster than they came).
    ///
    /// # Errors
    /// As [`Scene::time_step`].
    pub fn coarse_time_step<const MATERIALS: usize>(
        &self,
        table: &MaterialTable<L, MATERIALS>,
        seconds: L::Float,
    ) -> Result<TimeStep<L::Float>, StepError> {
        table
            .coarse_time_step(seconds, &self.sphere_slice(), self.walls.walls())
            .map_err(|error| StepError::from_list(error, &[]))
    }

    /// The largest step every law of `table` present in the scene recommends
    /// ([`MaterialTable::recommended_time_step`]); `None` without spheres.
    ///
    /// # Errors
    /// As [`Scene::time_step`] for material ids past the table.
    pub fn recommended_time_step<const MATERIALS: usize>(
        &self,
        table: &MaterialTable<L, MATERIALS>,
    ) -> Result<Option<L::Float>, StepError> {
        table
            .recommended_time_step(&self.sphere_slice(), self.walls.walls())
            .map_err(|error| StepError::from_list(error, &[]))
    }

    /// The spheres and their materials as the kernel's list seam reads them.
    fn sphere_slice(&self) -> SphereSlice<'_, L::Float> {
        SphereSlice {
            spheres: self.spheres,
            material: self.materials,
        }
    }

    /// Whether a step diverged: the scene then refuses every later step.
    pub fn halted(&self) -> bool {
        self.halted
    }

    /// How many times the Verlet list has been built.
    pub fn list_builds(&self) -> usize {
        self.list_builds
    }

    /// The spheres.
    pub fn spheres(&self) -> &[CheckedSphere<L::Float>] {
        self.spheres
    }

    /// The spheres' material ids.
    pub fn materials(&self) -> &[u32] {
        self.materials
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
        Some((*self.force.get(index)?, *self.torque.get(index)?))
    }

    /// Rebuilds the Verlet list from the cell grid and carries each touching pair's state over
    /// to its new place in the list (through the parking, so a sphere can own at most `K`).
    /// A failed build leaves the history in the list, as a list of the stored pairs.
    fn rebuild_list(&mut self) -> Result<(), StepError> {
        // A sphere that has flown out of the box would sit in an edge cell while it flies on,
        // its contacts with the box's spheres still computed: refused before anything changes.
        if let Some(index) = first_outside(self.spheres, &self.grid.domain) {
            return Err(StepError::Outside { index });
        }
        let relaxed = L::State::default();
        let old_count = self.candidate_count;
        if stores::<L::State>() {
            for parking in self.parking.iter_mut() {
                parking.clear();
            }
            // Read from the buffers, which before the first build hold a restart's history.
            let stored = self.list.buffers().0.iter().zip(self.pair_states.iter());
            for (&[i, j], &state) in stored.take(old_count) {
                // A relaxed state is what a new contact starts from: nothing to carry.
                if state != relaxed {
                    self.parking[i as usize]
                        .push(j, state)
                        .map_err(|()| StepError::ParkingFull)?;
                }
            }
        }
        self.grid
            .sort(self.spheres, self.cell_start, self.cell_entries);
        let (grid, spheres, skin) = (&self.grid, &*self.spheres, self.skin);
        let cells = (&*self.cell_start, &*self.cell_entries);
        let mut full = false;
        let built = self.list.rebuild(spheres.len(), |pairs, shifts| {
            grid.pairs(spheres, cells, skin, (pairs, shifts))
                .unwrap_or_else(|()| {
                    full = true;
                    0
                })
        });
        let count = match built {
            Ok(count) if !full => count,
            // The list's pairs were overwritten up to its end: write the parked history back,
            // for the next attempt or for a scene over a larger list.
            Ok(_) => {
                self.unpark(old_count);
                return Err(StepError::ListFull);
            }
            // The grid names spheres of the scene only, with finite shifts.
            Err(error) => {
                self.unpark(old_count);
                return Err(StepError::List(error));
            }
        };
        self.candidate_count = count;
        if stores::<L::State>() {
            // Keep every state past the list relaxed (see `SceneBuffers`), in both buffers.
            self.pair_states[count..old_count.max(count)].fill(relaxed);
            self.next_pair_states[count..old_count.max(count)].fill(relaxed);
            let listed = self
                .list
                .checked()
                .pairs()
                .iter()
                .zip(self.pair_states.iter_mut());
            for (&[i, j], state) in listed.take(count) {
                *state = self.parking[i as usize].find(j);
            }
        }
        for (anchor, sphere) in self.anchor.iter_mut().zip(self.spheres.iter()) {
            *anchor = sphere.position;
        }
        self.list_current = true;
        self.records_current = false;
        self.list_builds += 1;
        Ok(())
    }

    /// Writes the parked states back as the list's first entries (each pair with no shift: the
    /// list is not current, so only its pairs and states are read) and relaxes the rest up to
    /// `old_count`. They fit: they were parked from the first `old_count` entries.
    fn unpark(&mut self, old_count: usize) {
        self.records_current = false;
        if !stores::<L::State>() {
            self.candidate_count = self.list.len();
            return;
        }
        let (parking, states) = (&*self.parking, &mut *self.pair_states);
        let written = self.list.rebuild(self.spheres.len(), |pairs, shifts| {
            let mut count = 0;
            for (i, parking) in parking.iter().enumerate() {
                for (j, state) in parking.parked() {
                    pairs[count] = [i as u32, j];
                    shifts[count] = Vec3::ZERO;
                    states[count] = state;
                    count += 1;
                }
            }
            count
        });
        // Parked from the scene's own pairs: inside the spheres and the buffers.
        let count = written.unwrap_or(0);
        self.pair_states[count..old_count.max(count)].fill(L::State::default());
        self.next_pair_states[count..old_count.max(count)].fill(L::State::default());
        self.candidate_count = count;
    }
}
