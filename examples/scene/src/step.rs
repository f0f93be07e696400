//! One step of a scene: contact forces (pairs from the Verlet list, then walls), then the
//! integrator's kick and drift, on one thread or spread over an [`Executor`]'s threads with the
//! same bits.

use core::array;

use soft_sphere::batch::{ContactBlock, LANES, PairBlock};
use soft_sphere::motion::Kick;
use soft_sphere::{BoundLaw, CheckedSphere, ContactError, Float, Interaction, Law, Vec3};

use crate::buffers::{ListEntry, PairResult, SphereEntry, WallEntry};
use crate::grid::{Candidate, Grid};
use crate::parallel::{Executor, MAX_PIECES, Serial, piece_length};
use crate::{Integrator, Scene, StepError, StepInput, StepStats, WallSet, stores};

/// Candidates sifted for touching pairs at a time (a stack array of this many indices).
const SIFT_BLOCK: usize = 256;

/// The last sphere kind's kick (see [`Kick`]).
struct KickMemo<F> {
    kind: [F; 2],
    kick: Kick<F>,
    dt: F,
}

impl<F: Float> KickMemo<F> {
    /// Masses are positive in a scene, so the zeros it starts from never match.
    fn new(dt: F) -> Self {
        Self {
            kind: [F::ZERO; 2],
            kick: Kick::new(
                &soft_sphere::Sphere::at_rest(Vec3::ZERO, F::ONE, F::ONE),
                F::ONE,
            ),
            dt,
        }
    }

    #[inline(always)]
    fn get(&mut self, sphere: &soft_sphere::Sphere<F>) -> Kick<F> {
        let kind = [sphere.mass, sphere.radius];
        if kind != self.kind {
            self.kind = kind;
            self.kick = Kick::new(sphere, self.dt);
        }
        self.kick
    }
}

/// Blocks of the kernel's batch path gathered before any is evaluated (see
/// `PairContext::contacts`): 32 pairs, a few kilobytes, in L1 with the list's entries.
const GROUP: usize = 8;

/// A group of gathered blocks with their states, and one block's results.
type Staged<F, S> = (
    [PairBlock<F, LANES>; GROUP],
    [[S; LANES]; GROUP],
    ContactBlock<F, LANES>,
);

/// The spheres and the grid a contact is evaluated with.
struct PairContext<'c, F> {
    spheres: &'c [CheckedSphere<F>],
    grid: &'c Grid<F>,
}

impl<F: Float> PairContext<'_, F> {
    /// The touching pairs of `block` (at most [`SIFT_BLOCK`] entries) as positions in it.
    /// Whether a pair touches is a coin toss the branch predictor loses; sifting first keeps a
    /// lost guess from throwing away a contact evaluation in flight.
    #[inline(always)]
    fn sift<S>(&self, block: &[ListEntry<S>], touching: &mut [u32; SIFT_BLOCK]) -> usize {
        let mut found = 0;
        for (k, entry) in block.iter().enumerate() {
            let Candidate { i, j, image } = entry.candidate;
            let (sphere_i, sphere_j) = (&self.spheres[i as usize], &self.spheres[j as usize]);
            let offset = sphere_j.position + self.grid.image_shift(image) - sphere_i.position;
            let reach = sphere_i.radius + sphere_j.radius;
            touching[found] = k as u32;
            found += usize::from(offset.norm_squared() < reach * reach);
        }
        found
    }

    /// One sifted pair's contact, its state advanced in place.
    #[inline(always)]
    fn contact<L: Law<Float = F>>(
        &self,
        Candidate { i, j, image }: Candidate,
        law: &mut BoundLaw<'_, L>,
        state: &mut L::State,
    ) -> Result<PairResult<F>, ContactError> {
        let sphere_i = &self.spheres[i as usize];
        let partner = self.spheres[j as usize].translated(self.grid.image_shift(image))?;
        Ok(pair_result(law.sphere_sphere(sphere_i, &partner, state)?))
    }

    /// The contacts of a stretch of the list: each pair's next state into the entry's other
    /// state, and what it contributes to `add` (with its position in the stretch), in list order.
    fn stretch<L: Law<Float = F>>(
        &self,
        law: &L,
        time_step: soft_sphere::TimeStep<F>,
        (entries, live): (&mut [ListEntry<L::State>], usize),
        mut add: impl FnMut(usize, Candidate, PairResult<F>),
    ) -> Result<(), ContactError> {
        let next = 1 - live;
        let mut law = law.at(time_step);
        let mut touching = [0u32; SIFT_BLOCK];
        let mut staged: Staged<F, L::State> = (
            [PairBlock::default(); GROUP],
            [[L::State::default(); LANES]; GROUP],
            ContactBlock::default(),
        );
        for (b, block) in entries.chunks_mut(SIFT_BLOCK).enumerate() {
            let first = b * SIFT_BLOCK;
            if stores::<L::State>() {
                // Apart: relaxed. Touching pairs overwrite theirs below.
                for entry in block.iter_mut() {
                    entry.states[next] = L::State::default();
                }
            }
            let found = self.sift(block, &mut touching);
            if L::VECTORISES {
                for group in touching[..found].chunks(LANES * GROUP) {
                    self.contacts(group, block, live, (&mut law, &mut staged), |k, c, r| {
                        add(first + k, c, r)
                    })?;
                }
            } else {
                for &k in &touching[..found] {
                    let entry = &mut block[k as usize];
                    let mut state = entry.states[live];
                    let result = self.contact(entry.candidate, &mut law, &mut state)?;
                    entry.states[next] = state;
                    add(first + k as usize, entry.candidate, result);
                }
            }
        }
        Ok(())
    }

    /// Up to [`GROUP`] blocks of [`LANES`] sifted pairs (`group`, positions in `block`) through
    /// the kernel's batch path. All of them are gathered before the first is evaluated: a block
    /// read as vectors straight after its lanes were stored one by one would wait on every
    /// load (store-to-load forwarding cannot merge the narrow stores). Results are then taken
    /// lane by lane in list order, so the first failing pair's error is the one returned, as one
    /// at a time. Unused lanes repeat the last pair and are ignored.
    #[inline(always)]
    fn contacts<L: Law<Float = F>>(
        &self,
        group: &[u32],
        block: &mut [ListEntry<L::State>],
        live: usize,
        (law, staged): (&mut BoundLaw<'_, L>, &mut Staged<F, L::State>),
        mut add: impl FnMut(usize, Candidate, PairResult<F>),
    ) -> Result<(), ContactError> {
        let (pairs, states, out) = staged;
        for (lanes, (pairs, states)) in group
            .chunks(LANES)
            .zip(pairs.iter_mut().zip(states.iter_mut()))
        {
            for lane in 0..LANES {
                let entry = &block[lanes[lane.min(lanes.len() - 1)] as usize];
                let Candidate { i, j, image } = entry.candidate;
                let mut partner: soft_sphere::Sphere<F> = *self.spheres[j as usize];
                // As `CheckedSphere::translated`; a position it would refuse fails the lane's
                // check.
                partner.position += self.grid.image_shift(image);
                pairs.set(lane, &self.spheres[i as usize], &partner);
                states[lane] = entry.states[live];
            }
        }
        for (lanes, (pairs, states)) in group.chunks(LANES).zip(pairs.iter().zip(states.iter_mut()))
        {
            evaluate_block(law, pairs, states, out);
            for (lane, &k) in lanes.iter().enumerate() {
                let entry = &mut block[k as usize];
                let result = pair_result(out.outcome(lane)?);
                entry.states[1 - live] = states[lane];
                add(k as usize, entry.candidate, result);
            }
        }
        Ok(())
    }
}

/// One block through the kernel's batch path, compiled as a function of its own: inlined into
/// the threaded pair phase, the compiler no longer widened the lanes into vector instructions.
#[inline(never)]
fn evaluate_block<L: Law>(
    law: &mut BoundLaw<'_, L>,
    pairs: &PairBlock<L::Float, LANES>,
    states: &mut [L::State; LANES],
    out: &mut ContactBlock<L::Float, LANES>,
) {
    law.sphere_pairs(pairs, states, out);
}

/// What the scene keeps of one pair's outcome.
#[inline(always)]
fn pair_result<F: Float>(interaction: Interaction<F>) -> PairResult<F> {
    match interaction {
        Interaction::Touching(c) => PairResult {
            force_on_j: c.force_on_j(),
            torque_on_i: c.torque_on_i,
            torque_on_j: c.torque_on_j,
            overlap: c.overlap,
            touching: true,
            sliding: c.sliding,
        },
        Interaction::Apart => PairResult::default(),
    }
}

/// Adds one pair's contribution onto its spheres.
#[inline(always)]
fn add_pair<F: Float>(
    entries: &mut [SphereEntry<F>],
    stats: &mut StepStats<F>,
    Candidate { i, j, .. }: Candidate,
    result: &PairResult<F>,
) {
    let (i, j) = (i as usize, j as usize);
    entries[i].force -= result.force_on_j;
    entries[i].torque += result.torque_on_i;
    entries[j].force += result.force_on_j;
    entries[j].torque += result.torque_on_j;
    stats.pair_contacts += 1;
    stats.sliding_contacts += usize::from(result.sliding);
    stats.overlap_sum += result.overlap;
}

/// One piece of a parallel pair phase.
struct PairPiece<'p, F, S> {
    entries: &'p mut [ListEntry<S>],
    results: &'p mut [PairResult<F>],
    outcome: Result<(), ContactError>,
}

/// One piece of a wall phase: a stretch of spheres.
struct WallPiece<'p, F, S> {
    spheres: &'p [CheckedSphere<F>],
    entries: &'p mut [SphereEntry<F>],
    states: &'p mut [WallEntry<S>],
    outcome: Result<usize, ContactError>,
}

/// One piece of an integration phase: a stretch of spheres.
struct AdvancePiece<'p, F> {
    spheres: &'p mut [CheckedSphere<F>],
    entries: &'p [SphereEntry<F>],
    /// The offset of the stretch's first sphere in the scene.
    first: usize,
    /// The first sphere of the stretch that diverged.
    diverged: Option<usize>,
    stale: bool,
}

impl<L: Law, W: WallSet<L::Float>, const K: usize> Scene<'_, L, W, K> {
    /// One step of the scene, on this thread. The same as [`Scene::step_on`] with [`Serial`].
    ///
    /// # Errors
    /// As [`Scene::step_on`].
    pub fn step(&mut self, input: &StepInput<'_, L>) -> Result<StepStats<L::Float>, StepError> {
        self.step_on(input, &Serial)
    }

    /// One step of the scene, its contact and integration work spread over `executor`'s
    /// threads. The result is the same bits for any executor and any number of threads (the
    /// per-pair forces are added in list order on one thread). A parallel executor needs the
    /// `pair_results` buffer ([`crate::SceneBuffers`]); without it the pairs run serially.
    ///
    /// # Errors
    /// - [`StepError::Contact`]: the first rejected contact, in list order and then sphere order
    ///   for walls. With symplectic Euler the scene is then exactly as before the call; with
    ///   velocity Verlet the spheres have had the step's first half kick and drift, and the
    ///   contact history is as before.
    /// - [`StepError::ListFull`], [`StepError::ParkingFull`] at a list rebuild. Nothing is lost:
    ///   the list buffer still holds every stored state, so copying it to the front of a longer
    ///   list (or keeping it with a larger parking) and building a scene again carries on from
    ///   the same history.
    /// - [`StepError::Diverged`] when finite forces moved a sphere to a non-finite position or
    ///   velocity; that sphere keeps its previous state, and every later step returns
    ///   [`StepError::Halted`].
    pub fn step_on<E: Executor>(
        &mut self,
        input: &StepInput<'_, L>,
        executor: &E,
    ) -> Result<StepStats<L::Float>, StepError> {
        if self.halted {
            return Err(StepError::Halted);
        }
        let dt = input.time_step.seconds();
        let half = <L::Float as Float>::HALF;
        match input.integrator {
            Integrator::SymplecticEuler => {
                let stats = self.evaluate(input, true, executor)?;
                self.forces_current = false;
                self.advance(input.gravity, (dt, Some(dt)), executor)?;
                Ok(stats)
            }
            Integrator::VelocityVerlet => {
                if !self.forces_current {
                    // The first step's forces: the history is not advanced by them.
                    self.evaluate(input, false, executor)?;
                }
                // The forces no longer belong to the positions until the evaluation succeeds.
                self.forces_current = false;
                self.advance(input.gravity, (dt * half, Some(dt)), executor)?;
                let stats = self.evaluate(input, true, executor)?;
                self.forces_current = true;
                self.advance(input.gravity, (dt * half, None), executor)?;
                Ok(stats)
            }
        }
    }

    /// Kicks every sphere by `kick` seconds under its contact force and torque and gravity,
    /// then, given a `drift`, moves it that long at its new velocity, wraps it into the periodic
    /// box and checks the skin (a sphere that moved more than half of it since the last build
    /// could touch a pair the list does not hold; one that wrapped has broken its pairs' image
    /// shifts, and is a box length from where it was).
    ///
    /// # Errors
    /// [`StepError::Diverged`] when a sphere's position or velocity would no longer be finite;
    /// the scene then refuses every later step.
    fn advance<E: Executor>(
        &mut self,
        gravity: Vec3<L::Float>,
        (kick, drift): (L::Float, Option<L::Float>),
        executor: &E,
    ) -> Result<(), StepError> {
        let n = self.spheres.len();
        let length = if E::PARALLEL {
            piece_length(n, 512)
        } else {
            n.max(1)
        };
        let mut spheres = self.spheres.chunks_mut(length);
        let mut entries = self.entries.chunks(length);
        let mut first = 0;
        let mut pieces: [Option<AdvancePiece<'_, L::Float>>; MAX_PIECES] = array::from_fn(|_| {
            let piece = AdvancePiece {
                spheres: spheres.next()?,
                entries: entries.next()?,
                first,
                diverged: None,
                stale: false,
            };
            first += piece.spheres.len();
            Some(piece)
        });
        let domain = self.grid.domain;
        let quarter = <L::Float as Float>::HALF * <L::Float as Float>::HALF;
        let half_skin_squared = self.skin * self.skin * quarter;
        executor.for_each_mut(&mut pieces, |piece| {
            let Some(piece) = piece else { return };
            let mut memo = KickMemo::new(kick);
            for (k, checked) in piece.spheres.iter_mut().enumerate() {
                let (force, torque) = piece.entries[k].load();
                let anchor = piece.entries[k].anchor;
                let moved = checked.update(|sphere| {
                    let kick = memo.get(sphere);
                    kick.apply(sphere, force + gravity * sphere.mass, torque);
                    let Some(dt) = drift else { return false };
                    sphere.position += sphere.velocity * dt;
                    let p = &mut sphere.position;
                    if domain.periodic_x {
                        p.x = wrap_into(p.x, domain.lower.x, domain.upper.x);
                    }
                    if domain.periodic_y {
                        p.y = wrap_into(p.y, domain.lower.y, domain.upper.y);
                    }
                    // A sphere that wrapped sits about a box length (at least three cells) from
                    // its anchor, so this also stales the list whose image shifts it broke.
                    (*p - anchor).norm_squared() > half_skin_squared
                });
                match moved {
                    Ok(stale) => piece.stale |= stale,
                    Err(_) => {
                        piece.diverged = piece.diverged.or(Some(piece.first + k));
                    }
                }
            }
        });
        let pieces = pieces.iter().flatten();
        let (diverged, stale) = pieces.fold((None, false), |(diverged, stale), piece| {
            (Option::or(diverged, piece.diverged), stale || piece.stale)
        });
        if stale {
            self.list_current = false;
        }
        if let Some(index) = diverged {
            self.halted = true;
            return Err(StepError::Diverged { index });
        }
        Ok(())
    }

    /// Contact forces and torques at the current state into the sphere entries, and, when
    /// `commit`, the history advanced (all or nothing).
    fn evaluate<E: Executor>(
        &mut self,
        input: &StepInput<'_, L>,
        commit: bool,
        executor: &E,
    ) -> Result<StepStats<L::Float>, StepError> {
        if !self.list_current {
            self.rebuild_list()?;
        }
        for entry in self.entries.iter_mut() {
            entry.force = Vec3::ZERO;
            entry.torque = Vec3::ZERO;
        }
        let mut stats = StepStats::default();
        let context = PairContext {
            spheres: self.spheres,
            grid: &self.grid,
        };
        let (law, time_step, live) = (input.law, input.time_step, self.live);
        let count = self.candidate_count;
        let parallel = E::PARALLEL && self.pair_results.len() == self.list.len();
        let list = &mut self.list[..count];
        if parallel {
            let length = piece_length(count, 1024);
            let mut stretches = list.chunks_mut(length);
            let mut results = self.pair_results[..count].chunks_mut(length);
            let mut pieces: [Option<PairPiece<'_, L::Float, L::State>>; MAX_PIECES] =
                array::from_fn(|_| {
                    Some(PairPiece {
                        entries: stretches.next()?,
                        results: results.next()?,
                        outcome: Ok(()),
                    })
                });
            executor.for_each_mut(&mut pieces, |piece| {
                let Some(piece) = piece else { return };
                piece.results.fill(PairResult::default());
                let results = &mut *piece.results;
                piece.outcome =
                    context.stretch(law, time_step, (piece.entries, live), |at, _, result| {
                        results[at] = result;
                    });
            });
            for piece in pieces.iter().flatten() {
                piece.outcome?;
            }
            for (entry, result) in self.list[..count].iter().zip(self.pair_results.iter()) {
                if result.touching {
                    add_pair(self.entries, &mut stats, entry.candidate, result);
                }
            }
        } else {
            let entries = &mut *self.entries;
            context.stretch(law, time_step, (list, live), |_, candidate, result| {
                if result.touching {
                    add_pair(entries, &mut stats, candidate, &result);
                }
            })?;
        }
        if W::COUNT > 0 {
            stats.wall_contacts = self.wall_forces(input, executor)?;
        }
        if commit {
            self.live = 1 - self.live;
        }
        Ok(stats)
    }

    /// Every sphere against every wall; returns the touching count.
    fn wall_forces<E: Executor>(
        &mut self,
        input: &StepInput<'_, L>,
        executor: &E,
    ) -> Result<usize, ContactError> {
        let n = self.spheres.len();
        let length = if E::PARALLEL {
            piece_length(n, 512)
        } else {
            n.max(1)
        };
        let per_sphere = if stores::<L::State>() { W::COUNT } else { 0 };
        let mut spheres = self.spheres.chunks(length);
        let mut entries = self.entries.chunks_mut(length);
        let mut states = self.wall_states.chunks_mut((length * per_sphere).max(1));
        let mut pieces: [Option<WallPiece<'_, L::Float, L::State>>; MAX_PIECES] =
            array::from_fn(|_| {
                Some(WallPiece {
                    spheres: spheres.next()?,
                    entries: entries.next()?,
                    states: states.next().unwrap_or(&mut []),
                    outcome: Ok(0),
                })
            });
        let (walls, live) = (&self.walls, self.live);
        executor.for_each_mut(&mut pieces, |piece| {
            let Some(piece) = piece else { return };
            piece.outcome = walls_of(input, walls, live, piece);
        });
        let mut touching = 0;
        for piece in pieces.iter().flatten() {
            touching += piece.outcome?;
        }
        Ok(touching)
    }
}

/// The wall contacts of one stretch of spheres.
fn walls_of<L: Law, W: WallSet<L::Float>>(
    input: &StepInput<'_, L>,
    walls: &W,
    live: usize,
    piece: &mut WallPiece<'_, L::Float, L::State>,
) -> Result<usize, ContactError> {
    let mut law = input.wall_law.at(input.time_step);
    let next = 1 - live;
    let mut touching = 0;
    for (index, sphere) in piece.spheres.iter().enumerate() {
        for k in 0..W::COUNT {
            let Some(wall) = walls.wall(k) else { continue };
            let entry = if stores::<L::State>() {
                piece.states.get_mut(index * W::COUNT + k)
            } else {
                None
            };
            let mut state = entry
                .as_ref()
                .map_or_else(L::State::default, |e| e.states[live]);
            let contact = law.sphere_wall(sphere, wall, &mut state)?;
            if let Some(entry) = entry {
                entry.states[next] = state;
            }
            if let Interaction::Touching(c) = contact {
                piece.entries[index].force += c.force_on_i();
                piece.entries[index].torque += c.torque_on_i;
                touching += 1;
            }
        }
    }
    Ok(touching)
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
