//! Many-sphere scenes without allocation: a uniform cell grid built by counting sort into
//! caller-owned buffers, a Verlet list of candidate pairs within the contact distance plus a skin
//! (rebuilt from the grid only when a sphere has moved half the skin or crossed a periodic
//! boundary), per-sphere fixed-capacity contact slots for the history laws, walls as a
//! compile-time slot, and one step of symplectic Euler or velocity Verlet.
//!
//! The cell grid visits each pair once (a half-shell of 13 neighbour cells plus the cell itself),
//! so the cost grows with the number of spheres, not its square. Periodic directions use the
//! minimum image. Contacts are owned by the lower sphere index, so the evaluation order, the
//! stored state and the forces are the same bits for the same inputs.

use crate::backend::MathBackend;
use crate::body::{Sphere, Wall};
use crate::error::ContactError;
use crate::float::Float;
use crate::law::{ContactLaw, Interaction};
use crate::motion::{advance_solid_sphere, drift, half_kick};
use crate::normal::NormalModel;
use crate::rotation::Rotation;
use crate::tangential::TangentialModel;
use crate::time_step::TimeStep;
use crate::vector::Vec3;

/// Where the history update sits in a step: see [`crate::motion`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Integrator {
    /// Contacts at the start-of-step state, then kick and drift.
    SymplecticEuler,
    /// Half kick with the last forces, drift, contacts at the half-step velocities, half kick.
    VelocityVerlet,
}

/// The walls of a scene, chosen at compile time: [`NoWalls`] costs nothing.
pub trait WallSet<F: Float> {
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

/// Up to `K` contacts owned by one sphere: partner index and per-contact state.
#[derive(Clone, Copy, Debug)]
pub struct ContactSlots<S, const K: usize> {
    len: usize,
    partner: [u32; K],
    state: [S; K],
}

impl<S: Copy + Default, const K: usize> Default for ContactSlots<S, K> {
    fn default() -> Self {
        Self {
            len: 0,
            partner: [0; K],
            state: [S::default(); K],
        }
    }
}

impl<S: Copy + Default, const K: usize> ContactSlots<S, K> {
    /// Contacts held.
    pub fn len(&self) -> usize {
        self.len
    }

    /// No contact held.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The state stored for `partner`, or the relaxed state of a new contact.
    #[inline(always)]
    fn find(&self, partner: u32) -> S {
        let mut k = 0;
        while k < self.len {
            if self.partner[k] == partner {
                return self.state[k];
            }
            k += 1;
        }
        S::default()
    }

    #[inline(always)]
    fn push(&mut self, partner: u32, state: S) -> Result<(), ContactError> {
        if self.len == K {
            return Err(ContactError::HistoryFull);
        }
        self.partner[self.len] = partner;
        self.state[self.len] = state;
        self.len += 1;
        Ok(())
    }
}

/// A pair of spheres within contact distance plus the skin at the last list build; `j` is seen
/// through the periodic image `image` (multiples of the box lengths in x and y).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Candidate {
    i: u32,
    j: u32,
    image: [i8; 2],
}

/// The caller-owned buffers of a [`Scene`]. Lengths: one entry per sphere for `forces`,
/// `torques`, `slots`, `next_slots`, `cell_entries` and `anchors`; one per sphere and wall for
/// `wall_states`; one more than [`Scene::cells_needed`] for `cell_start`; `candidates` as many
/// candidate pairs as the list may hold (about 7 per sphere in a dense monodisperse packing with
/// a skin of a tenth of a diameter). Slots and wall states carry history between steps: keep
/// them, and zero (default) them for a fresh scene.
#[derive(Debug)]
pub struct SceneBuffers<'a, F, S, const K: usize> {
    /// Contact force on each sphere.
    pub forces: &'a mut [Vec3<F>],
    /// Contact torque on each sphere.
    pub torques: &'a mut [Vec3<F>],
    /// Pair contacts owned by each sphere (history).
    pub slots: &'a mut [ContactSlots<S, K>],
    /// Scratch for the next step's slots.
    pub next_slots: &'a mut [ContactSlots<S, K>],
    /// Per sphere and wall contact state (history).
    pub wall_states: &'a mut [S],
    /// Cell offsets of the grid.
    pub cell_start: &'a mut [u32],
    /// Sphere indices sorted by cell.
    pub cell_entries: &'a mut [u32],
    /// The Verlet list.
    pub candidates: &'a mut [Candidate],
    /// Positions at the last list build.
    pub anchors: &'a mut [Vec3<F>],
}

/// Why a scene could not be set up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneError {
    /// A buffer's length does not match the number of spheres, cells or walls.
    BufferLength,
    /// The domain or cell size is not finite and positive, or a periodic direction has fewer
    /// than 3 cells (the half-shell would visit a pair twice).
    Domain,
}

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

/// Totals of one step's contacts.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepStats<F> {
    /// Sphere-sphere contacts touching.
    pub pair_contacts: usize,
    /// Sphere-wall contacts touching.
    pub wall_contacts: usize,
    /// Sum of the sphere-sphere overlaps (m).
    pub overlap_sum: F,
}

/// A scene over caller-owned buffers (see [`Scene::new`] for their lengths).
#[derive(Debug)]
pub struct Scene<'a, F, S, const K: usize> {
    spheres: &'a mut [Sphere<F>],
    forces: &'a mut [Vec3<F>],
    torques: &'a mut [Vec3<F>],
    slots: &'a mut [ContactSlots<S, K>],
    next_slots: &'a mut [ContactSlots<S, K>],
    wall_states: &'a mut [S],
    cell_start: &'a mut [u32],
    cell_entries: &'a mut [u32],
    candidates: &'a mut [Candidate],
    candidate_count: usize,
    anchors: &'a mut [Vec3<F>],
    skin: F,
    list_current: bool,
    list_builds: usize,
    domain: Domain<F>,
    cells: [usize; 3],
    cell_size: [F; 3],
    lengths: [F; 3],
    forces_current: bool,
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

impl<'a, F: Float, S: Copy + Default, const K: usize> Scene<'a, F, S, K> {
    /// A scene over `spheres` in `domain` with `walls` walls ([`WallSet::COUNT`]) and the
    /// buffers described at [`SceneBuffers`]. Grid cells are at least `largest_diameter + skin`
    /// on a side; [`Scene::cells_needed`] gives their number for `cell_start`.
    ///
    /// # Errors
    /// [`SceneError`] for mismatched buffers or a bad domain or skin.
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
        let (cells, cell_size) = Self::grid(&domain, largest_diameter + skin)?;
        let n = spheres.len();
        let total = cells[0] * cells[1] * cells[2];
        let b = buffers;
        let lengths_ok = b.forces.len() == n
            && b.torques.len() == n
            && b.slots.len() == n
            && b.next_slots.len() == n
            && b.cell_entries.len() == n
            && b.anchors.len() == n
            && b.cell_start.len() == total + 1
            && n <= u32::MAX as usize
            && b.wall_states.len() == n * walls;
        if !lengths_ok {
            return Err(SceneError::BufferLength);
        }
        Ok(Self {
            spheres,
            forces: b.forces,
            torques: b.torques,
            slots: b.slots,
            next_slots: b.next_slots,
            wall_states: b.wall_states,
            cell_start: b.cell_start,
            cell_entries: b.cell_entries,
            candidates: b.candidates,
            candidate_count: 0,
            anchors: b.anchors,
            skin,
            list_current: false,
            list_builds: 0,
            domain,
            cells,
            cell_size,
            lengths: (domain.upper - domain.lower).to_array(),
            forces_current: false,
        })
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
        let (cells, _) = Self::grid(domain, largest_diameter + skin)?;
        Ok(cells[0] * cells[1] * cells[2])
    }

    fn grid(domain: &Domain<F>, min_cell_size: F) -> Result<([usize; 3], [F; 3]), SceneError> {
        let extent = domain.upper - domain.lower;
        let mut cells = [0usize; 3];
        let mut size = [F::ZERO; 3];
        for (axis, length) in extent.to_array().into_iter().enumerate() {
            if !(length > F::ZERO && length.is_finite() && min_cell_size > F::ZERO) {
                return Err(SceneError::Domain);
            }
            let count = (length / min_cell_size).to_f64();
            if count.is_nan() || count >= 1e6 {
                return Err(SceneError::Domain);
            }
            let count = (count as usize).max(1);
            let periodic = (axis == 0 && domain.periodic_x) || (axis == 1 && domain.periodic_y);
            if periodic && count < 3 {
                return Err(SceneError::Domain);
            }
            cells[axis] = count;
            size[axis] = length / F::from_f64(count as f64);
        }
        Ok((cells, size))
    }

    /// The spheres.
    pub fn spheres(&self) -> &[Sphere<F>] {
        self.spheres
    }

    /// The contact forces of the last evaluation, one per sphere.
    pub fn forces(&self) -> &[Vec3<F>] {
        self.forces
    }

    /// The contact slots (pair contacts owned by each sphere).
    pub fn slots(&self) -> &[ContactSlots<S, K>] {
        self.slots
    }

    fn cell_coordinate(&self, value: F, axis: usize) -> usize {
        let lower = self.domain.lower.to_array()[axis];
        let index = ((value - lower) / self.cell_size[axis]).to_f64();
        // Spheres outside a non-periodic box (or rounding at its edge) go to the edge cells.
        if index <= 0.0 {
            0
        } else {
            (index as usize).min(self.cells[axis] - 1)
        }
    }

    fn build_cells(&mut self) {
        let total = self.cells[0] * self.cells[1] * self.cells[2];
        self.cell_start.fill(0);
        for s in self.spheres.iter() {
            let p = s.position.to_array();
            let cell = self.cell_index(
                self.cell_coordinate(p[0], 0),
                self.cell_coordinate(p[1], 1),
                self.cell_coordinate(p[2], 2),
            );
            self.cell_start[cell + 1] += 1;
        }
        for c in 0..total {
            self.cell_start[c + 1] += self.cell_start[c];
        }
        // Fill in sphere order, so that each cell lists its spheres by increasing index.
        for (index, s) in self.spheres.iter().enumerate() {
            let p = s.position.to_array();
            let cell = self.cell_index(
                self.cell_coordinate(p[0], 0),
                self.cell_coordinate(p[1], 1),
                self.cell_coordinate(p[2], 2),
            );
            // cell_start[cell] is used as the running insert position, restored below.
            let at = self.cell_start[cell] as usize;
            self.cell_entries[at] = index as u32;
            self.cell_start[cell] += 1;
        }
        for c in (0..total).rev() {
            self.cell_start[c + 1] = self.cell_start[c];
        }
        self.cell_start[0] = 0;
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

    #[inline(always)]
    fn cell_index(&self, x: usize, y: usize, z: usize) -> usize {
        (z * self.cells[1] + y) * self.cells[0] + x
    }

    /// Neighbour cell along one axis, with the periodic image it lies in (-1, 0, 1), or `None`
    /// off a non-periodic edge.
    #[inline(always)]
    fn neighbour(
        &self,
        at: usize,
        step: isize,
        axis: usize,
        periodic: bool,
    ) -> Option<(usize, i8)> {
        let count = self.cells[axis] as isize;
        let next = at as isize + step;
        if next < 0 {
            periodic.then(|| ((next + count) as usize, -1))
        } else if next >= count {
            periodic.then(|| ((next - count) as usize, 1))
        } else {
            Some((next as usize, 0))
        }
    }

    /// One step of the scene.
    ///
    /// # Errors
    /// The first [`ContactError`] of any contact (the scene is then partly advanced: restore it
    /// from your own copy if you need to retry), and [`ContactError::HistoryFull`] when a sphere
    /// owns more than `K` touching contacts.
    pub fn step<N, T, M, R, W>(
        &mut self,
        input: &StepInput<'_, F, N, T, M, R, W>,
    ) -> Result<StepStats<F>, ContactError>
    where
        N: NormalModel<F>,
        T: TangentialModel<F, State = S>,
        M: MathBackend<F>,
        R: Rotation,
        W: WallSet<F>,
    {
        let dt = input.time_step;
        match input.integrator {
            Integrator::SymplecticEuler => {
                let stats = self.evaluate(input)?;
                for (k, sphere) in self.spheres.iter_mut().enumerate() {
                    let force = self.forces[k] + input.gravity * sphere.mass;
                    advance_solid_sphere(sphere, force, self.torques[k], dt);
                }
                self.wrap();
                self.forces_current = false;
                Ok(stats)
            }
            Integrator::VelocityVerlet => {
                if !self.forces_current {
                    self.evaluate(input)?;
                }
                for (k, sphere) in self.spheres.iter_mut().enumerate() {
                    let force = self.forces[k] + input.gravity * sphere.mass;
                    half_kick(sphere, force, self.torques[k], dt);
                    drift(sphere, dt);
                }
                self.wrap();
                let stats = self.evaluate(input)?;
                for (k, sphere) in self.spheres.iter_mut().enumerate() {
                    let force = self.forces[k] + input.gravity * sphere.mass;
                    half_kick(sphere, force, self.torques[k], dt);
                }
                self.forces_current = true;
                Ok(stats)
            }
        }
    }

    /// Brings spheres back into the periodic box; a sphere that crosses invalidates the list's
    /// image shifts, so the list is rebuilt. Also checks the skin: a sphere that moved more than
    /// half of it since the last build could now touch a pair the list does not hold.
    fn wrap(&mut self) {
        let (lower, upper) = (self.domain.lower, self.domain.upper);
        let half_skin_squared = self.skin * self.skin * F::from_f64(0.25);
        let mut stale = false;
        for (sphere, anchor) in self.spheres.iter_mut().zip(self.anchors.iter()) {
            let p = &mut sphere.position;
            if self.domain.periodic_x {
                let wrapped = wrap_into(p.x, lower.x, upper.x);
                stale |= wrapped != p.x;
                p.x = wrapped;
            }
            if self.domain.periodic_y {
                let wrapped = wrap_into(p.y, lower.y, upper.y);
                stale |= wrapped != p.y;
                p.y = wrapped;
            }
            stale |= (*p - *anchor).norm_squared() > half_skin_squared;
        }
        if stale {
            self.list_current = false;
        }
    }

    /// Contact forces and torques at the current state into the force buffers, history slots
    /// swapped to the new contacts.
    fn evaluate<N, T, M, R, W>(
        &mut self,
        input: &StepInput<'_, F, N, T, M, R, W>,
    ) -> Result<StepStats<F>, ContactError>
    where
        N: NormalModel<F>,
        T: TangentialModel<F, State = S>,
        M: MathBackend<F>,
        R: Rotation,
        W: WallSet<F>,
    {
        self.build_cells();
        self.forces.fill(Vec3::ZERO);
        self.torques.fill(Vec3::ZERO);
        for slot in self.next_slots.iter_mut() {
            slot.len = 0;
        }
        let mut stats = StepStats {
            pair_contacts: 0,
            wall_contacts: 0,
            overlap_sum: F::ZERO,
        };
        if !self.list_current {
            self.build_list()?;
        }
        let law = input.law;
        for c in 0..self.candidate_count {
            let Candidate { i, j, image } = self.candidates[c];
            let (i, j) = (i as usize, j as usize);
            let shift = self.image_shift(image);
            // Most candidates are within the skin but not touching: test before copying j.
            let partner_position = self.spheres[j].position + shift;
            let reach = self.spheres[i].radius + self.spheres[j].radius;
            if (partner_position - self.spheres[i].position).norm_squared() >= reach * reach {
                continue;
            }
            let mut partner = self.spheres[j];
            partner.position = partner_position;
            // Stateless laws store nothing: no lookup, no slot, no capacity limit.
            let stores = size_of::<S>() > 0;
            let mut state = if stores {
                self.slots[i].find(j as u32)
            } else {
                S::default()
            };
            if let Interaction::Touching(contact) =
                law.sphere_sphere(&self.spheres[i], &partner, &mut state, input.time_step)?
            {
                let on_j = contact.force_on_j();
                self.forces[i] -= on_j;
                self.forces[j] += on_j;
                self.torques[i] += contact.torque_on_i;
                self.torques[j] += contact.torque_on_j;
                stats.pair_contacts += 1;
                stats.overlap_sum += contact.overlap;
                if stores {
                    self.next_slots[i].push(j as u32, state)?;
                }
            }
        }
        core::mem::swap(&mut self.slots, &mut self.next_slots);
        if W::COUNT > 0 {
            self.wall_forces(input, &mut stats)?;
        }
        Ok(stats)
    }

    /// Rebuilds the Verlet list from the cell grid: every pair within contact distance plus the
    /// skin, the lower index first, with the periodic image of the higher.
    fn build_list(&mut self) -> Result<(), ContactError> {
        self.build_cells();
        self.candidate_count = 0;
        let [nx, ny, nz] = self.cells;
        // The cell itself and the 13 cells of a half shell.
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
        for cz in 0..nz {
            for cy in 0..ny {
                for cx in 0..nx {
                    let here = self.cell_index(cx, cy, cz);
                    if self.cell_start[here] == self.cell_start[here + 1] {
                        continue; // empty: most of a tall box above a settled bed
                    }
                    for &(dx, dy, dz) in &HALF_SHELL {
                        let Some((x, image_x)) = self.neighbour(cx, dx, 0, self.domain.periodic_x)
                        else {
                            continue;
                        };
                        let Some((y, image_y)) = self.neighbour(cy, dy, 1, self.domain.periodic_y)
                        else {
                            continue;
                        };
                        let Some((z, _)) = self.neighbour(cz, dz, 2, false) else {
                            continue;
                        };
                        let there = self.cell_index(x, y, z);
                        self.list_cell_pairs((here, there), [image_x, image_y])?;
                    }
                }
            }
        }
        for (anchor, sphere) in self.anchors.iter_mut().zip(self.spheres.iter()) {
            *anchor = sphere.position;
        }
        self.list_current = true;
        self.list_builds += 1;
        Ok(())
    }

    fn list_cell_pairs(
        &mut self,
        (here, there): (usize, usize),
        image: [i8; 2],
    ) -> Result<(), ContactError> {
        let shift = self.image_shift(image);
        let (a_start, a_end) = (
            self.cell_start[here] as usize,
            self.cell_start[here + 1] as usize,
        );
        let (b_start, b_end) = (
            self.cell_start[there] as usize,
            self.cell_start[there + 1] as usize,
        );
        for ia in a_start..a_end {
            let a = self.cell_entries[ia] as usize;
            // Within one cell each pair once: only later entries.
            let first = if here == there { ia + 1 } else { b_start };
            for ib in first..b_end {
                let b = self.cell_entries[ib] as usize;
                let (pa, pb) = (self.spheres[a].position, self.spheres[b].position + shift);
                let reach = self.spheres[a].radius + self.spheres[b].radius + self.skin;
                if (pb - pa).norm_squared() >= reach * reach {
                    continue;
                }
                if self.candidate_count == self.candidates.len() {
                    return Err(ContactError::HistoryFull);
                }
                // The lower index owns the pair and is body i, so its stored state keeps its
                // orientation whichever cell found the pair.
                self.candidates[self.candidate_count] = if a < b {
                    Candidate {
                        i: a as u32,
                        j: b as u32,
                        image,
                    }
                } else {
                    Candidate {
                        i: b as u32,
                        j: a as u32,
                        image: [-image[0], -image[1]],
                    }
                };
                self.candidate_count += 1;
            }
        }
        Ok(())
    }

    fn wall_forces<N, T, M, R, W>(
        &mut self,
        input: &StepInput<'_, F, N, T, M, R, W>,
        stats: &mut StepStats<F>,
    ) -> Result<(), ContactError>
    where
        N: NormalModel<F>,
        T: TangentialModel<F, State = S>,
        M: MathBackend<F>,
        R: Rotation,
        W: WallSet<F>,
    {
        for (index, sphere) in self.spheres.iter().enumerate() {
            for k in 0..W::COUNT {
                let state = &mut self.wall_states[index * W::COUNT + k];
                let wall = input.walls.wall(k);
                let contact = input
                    .wall_law
                    .sphere_wall(sphere, wall, state, input.time_step)?;
                if let Interaction::Touching(c) = contact {
                    self.forces[index] += c.force_on_i();
                    self.torques[index] += c.torque_on_i;
                    stats.wall_contacts += 1;
                }
            }
        }
        Ok(())
    }
}

#[inline(always)]
fn wrap_into<F: Float>(value: F, lower: F, upper: F) -> F {
    let length = upper - lower;
    if value < lower {
        value + length
    } else if value >= upper {
        value - length
    } else {
        value
    }
}

impl core::fmt::Display for SceneError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Self::BufferLength => {
                "a scene buffer's length does not match the spheres, cells or walls"
            }
            Self::Domain => {
                "the scene domain or cell size is invalid (periodic directions need 3 cells)"
            }
        })
    }
}

impl core::error::Error for SceneError {}
