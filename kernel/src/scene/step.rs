//! One step of a scene: contact forces (pairs from the Verlet list, then walls), then the
//! integrator's kick and drift, on one thread or spread over an [`Executor`]'s threads with the
//! same bits.

use core::array;

use super::grid::Grid;
use super::parallel::{Executor, MAX_PIECES, PairResult, Serial, piece_length};
use super::{Candidate, Integrator, Scene, StepInput, StepStats, WallSet};
use crate::backend::MathBackend;
use crate::body::{Sphere, effective_mass};
use crate::error::ContactError;
use crate::float::Float;
use crate::law::{ContactLaw, Interaction};
use crate::motion::{KickFactors, kick_by};
use crate::normal::{NormalModel, NormalOscillator};
use crate::rotation::Rotation;
use crate::tangential::{ContactState, TangentialModel};
use crate::time_step::TimeStep;
use crate::vector::Vec3;

/// Candidates sifted for touching pairs at a time (a stack array of this many indices).
const SIFT_BLOCK: usize = 256;

/// The last mass pair's oscillator: in a scene of one kind of sphere it is computed once.
/// Recomputing it for a new pair of masses gives the same bits as the law's own evaluation.
struct OscillatorMemo<F> {
    masses: [F; 2],
    oscillator: NormalOscillator<F>,
}

impl<F: Float> OscillatorMemo<F> {
    /// Masses are positive in a scene, so zero never matches.
    fn new() -> Self {
        Self {
            masses: [F::ZERO; 2],
            oscillator: NormalOscillator::default(),
        }
    }

    #[inline(always)]
    fn get<N, T, M, R>(
        &mut self,
        law: &ContactLaw<F, N, T, M, R>,
        effective: impl FnOnce() -> F,
        masses: [F; 2],
    ) -> &NormalOscillator<F>
    where
        N: NormalModel<F>,
        T: TangentialModel<F>,
        M: MathBackend<F>,
        R: Rotation,
    {
        if masses != self.masses {
            self.masses = masses;
            self.oscillator = law.contact_oscillator(effective());
        }
        &self.oscillator
    }
}

/// The last sphere kind's kick factors (see [`KickFactors`]).
struct KickMemo<F> {
    kind: [F; 2],
    factors: KickFactors<F>,
    dt: F,
}

impl<F: Float> KickMemo<F> {
    fn new(dt: F) -> Self {
        Self {
            kind: [F::ZERO; 2],
            factors: KickFactors::new(&Sphere::default(), F::ONE),
            dt,
        }
    }

    #[inline(always)]
    fn get(&mut self, sphere: &Sphere<F>) -> KickFactors<F> {
        let kind = [sphere.mass, sphere.radius];
        if kind != self.kind {
            self.kind = kind;
            self.factors = KickFactors::new(sphere, self.dt);
        }
        self.factors
    }
}

/// The law, the spheres and the grid a contact is evaluated with.
struct PairContext<'c, F: Float, N, T, M, R> {
    law: &'c ContactLaw<F, N, T, M, R>,
    spheres: &'c [Sphere<F>],
    grid: &'c Grid<F>,
    time_step: TimeStep<F>,
}

impl<F, N, T, M, R> PairContext<'_, F, N, T, M, R>
where
    F: Float,
    N: NormalModel<F>,
    T: TangentialModel<F>,
    M: MathBackend<F>,
    R: Rotation,
{
    /// The touching pairs of `block` (at most [`SIFT_BLOCK`] candidates) as positions in it.
    /// Whether a pair touches is a coin toss the branch predictor loses; sifting first keeps a
    /// lost guess from throwing away a contact evaluation in flight.
    #[inline(always)]
    fn sift(&self, block: &[Candidate], touching: &mut [u32; SIFT_BLOCK]) -> usize {
        let mut found = 0;
        for (k, &Candidate { i, j, image }) in block.iter().enumerate() {
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
    fn contact(
        &self,
        Candidate { i, j, image }: Candidate,
        memo: &mut OscillatorMemo<F>,
        state: &mut T::State,
    ) -> Result<PairResult<F>, ContactError> {
        let (sphere_i, sphere_j) = (&self.spheres[i as usize], &self.spheres[j as usize]);
        let mut partner = *sphere_j;
        partner.position = sphere_j.position + self.grid.image_shift(image);
        let oscillator = memo.get(
            self.law,
            || effective_mass(sphere_i.mass, sphere_j.mass),
            [sphere_i.mass, sphere_j.mass],
        );
        let interaction = self.law.sphere_sphere_validated(
            (sphere_i, &partner),
            oscillator,
            state,
            self.time_step,
        )?;
        Ok(match interaction {
            Interaction::Touching(c) => PairResult {
                force_on_j: c.force_on_j(),
                torque_on_i: c.torque_on_i,
                torque_on_j: c.torque_on_j,
                overlap: c.overlap,
                touching: true,
                sliding: c.sliding,
            },
            Interaction::Apart => PairResult::default(),
        })
    }

    /// The contacts of a stretch of the list: each pair's state into `next_states` and what it
    /// contributes to `add` (with its position in the stretch), in list order.
    fn stretch<S: ContactState>(
        &self,
        candidates: &[Candidate],
        (states, next_states): (&[S], &mut [S]),
        mut add: impl FnMut(usize, PairResult<F>),
    ) -> Result<(), ContactError>
    where
        T: TangentialModel<F, State = S>,
    {
        // Stateless laws store nothing: no state is read or written.
        let stores = size_of::<S>() > 0;
        let mut memo = OscillatorMemo::new();
        let mut touching = [0u32; SIFT_BLOCK];
        for (b, block) in candidates.chunks(SIFT_BLOCK).enumerate() {
            let first = b * SIFT_BLOCK;
            if stores {
                // Apart: relaxed. Touching pairs overwrite theirs below.
                next_states[first..first + block.len()].fill(S::default());
            }
            let found = self.sift(block, &mut touching);
            for &k in &touching[..found] {
                let at = first + k as usize;
                let mut state = if stores { states[at] } else { S::default() };
                let result = self.contact(block[k as usize], &mut memo, &mut state)?;
                if stores {
                    next_states[at] = state;
                }
                add(at, result);
            }
        }
        Ok(())
    }
}

/// Adds one pair's contribution onto its spheres.
#[inline(always)]
fn add_pair<F: Float>(
    (forces, torques): (&mut [Vec3<F>], &mut [Vec3<F>]),
    stats: &mut StepStats<F>,
    Candidate { i, j, .. }: Candidate,
    result: &PairResult<F>,
) {
    let (i, j) = (i as usize, j as usize);
    forces[i] -= result.force_on_j;
    forces[j] += result.force_on_j;
    torques[i] += result.torque_on_i;
    torques[j] += result.torque_on_j;
    stats.pair_contacts += 1;
    stats.sliding_contacts += usize::from(result.sliding);
    stats.overlap_sum += result.overlap;
}

/// One piece of a parallel pair phase.
struct PairPiece<'p, F, S> {
    candidates: &'p [Candidate],
    states: &'p [S],
    next_states: &'p mut [S],
    results: &'p mut [PairResult<F>],
    outcome: Result<(), ContactError>,
}

/// One piece of a wall phase: a stretch of spheres.
struct WallPiece<'p, F, S> {
    spheres: &'p [Sphere<F>],
    forces: &'p mut [Vec3<F>],
    torques: &'p mut [Vec3<F>],
    states: &'p [S],
    next_states: &'p mut [S],
    outcome: Result<usize, ContactError>,
}

/// One piece of an integration phase: a stretch of spheres.
struct AdvancePiece<'p, F> {
    spheres: &'p mut [Sphere<F>],
    forces: &'p [Vec3<F>],
    torques: &'p [Vec3<F>],
    anchors: &'p [Vec3<F>],
    finite: bool,
    stale: bool,
}

impl<F: Float, S: ContactState, const K: usize> Scene<'_, F, S, K> {
    /// One step of the scene, on this thread. The same as [`Scene::step_on`] with [`Serial`].
    ///
    /// # Errors
    /// As [`Scene::step_on`].
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
        self.step_on(input, &Serial)
    }

    /// One step of the scene, its contact and integration work spread over `executor`'s
    /// threads. The result is the same bits for any executor and any number of threads (the
    /// per-pair forces are added in list order on one thread). A parallel executor needs the
    /// `pair_results` buffer ([`super::SceneBuffers`]); without it the pairs run serially.
    ///
    /// # Errors
    /// - The first [`ContactError`] of any contact, in list order and then sphere order for
    ///   walls. With symplectic Euler the scene is then exactly as before the call; with
    ///   velocity Verlet the spheres have had the step's first half kick and drift, and the
    ///   contact history is as before.
    /// - [`ContactError::HistoryFull`] when, at a list rebuild, a sphere owns more than `K`
    ///   touching contacts or the list needs more candidates than its buffer holds (nothing is
    ///   lost: enlarge the buffers and build the scene again over the same states).
    /// - [`ContactError::NonFiniteResult`] when finite forces moved a sphere to a non-finite
    ///   position or velocity; the step is complete, and every later step returns
    ///   [`ContactError::NonFiniteInput`].
    pub fn step_on<N, T, M, R, W, E>(
        &mut self,
        input: &StepInput<'_, F, N, T, M, R, W>,
        executor: &E,
    ) -> Result<StepStats<F>, ContactError>
    where
        N: NormalModel<F>,
        T: TangentialModel<F, State = S>,
        M: MathBackend<F>,
        R: Rotation,
        W: WallSet<F>,
        E: Executor,
    {
        if self.overflowed {
            return Err(ContactError::NonFiniteInput);
        }
        let dt = input.time_step.seconds();
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
                self.advance(input.gravity, (dt * F::HALF, Some(dt)), executor)?;
                let stats = self.evaluate(input, true, executor)?;
                self.forces_current = true;
                self.advance(input.gravity, (dt * F::HALF, None), executor)?;
                Ok(stats)
            }
        }
    }

    /// Kicks every sphere by `kick` seconds under its contact force and torque and gravity,
    /// then, given a `drift`, moves it that long at its new velocity, wraps it into the periodic
    /// box (a sphere that crosses invalidates the list's image shifts) and checks the skin (a
    /// sphere that moved more than half of it since the last build could touch a pair the list
    /// does not hold).
    ///
    /// # Errors
    /// [`ContactError::NonFiniteResult`] when a sphere's position or velocity is no longer
    /// finite; the scene then refuses every later step.
    fn advance<E: Executor>(
        &mut self,
        gravity: Vec3<F>,
        (kick, drift): (F, Option<F>),
        executor: &E,
    ) -> Result<(), ContactError> {
        let n = self.spheres.len();
        let length = if E::PARALLEL {
            piece_length(n, 512)
        } else {
            n.max(1)
        };
        let mut spheres = self.spheres.chunks_mut(length);
        let (mut forces, mut torques) = (self.forces.chunks(length), self.torques.chunks(length));
        let mut anchors = self.anchors.chunks(length);
        let mut pieces: [Option<AdvancePiece<'_, F>>; MAX_PIECES] = array::from_fn(|_| {
            Some(AdvancePiece {
                spheres: spheres.next()?,
                forces: forces.next()?,
                torques: torques.next()?,
                anchors: anchors.next()?,
                finite: true,
                stale: false,
            })
        });
        let domain = self.grid.domain;
        let half_skin_squared = self.skin * self.skin * F::from_f64(0.25);
        executor.for_each_mut(&mut pieces, |piece| {
            let Some(piece) = piece else { return };
            let mut memo = KickMemo::new(kick);
            for (k, sphere) in piece.spheres.iter_mut().enumerate() {
                let factors = memo.get(sphere);
                let force = piece.forces[k] + gravity * sphere.mass;
                kick_by(sphere, force, piece.torques[k], factors);
                if let Some(dt) = drift {
                    sphere.position += sphere.velocity * dt;
                    let p = &mut sphere.position;
                    if domain.periodic_x {
                        let wrapped = wrap_into(p.x, domain.lower.x, domain.upper.x);
                        piece.stale |= wrapped != p.x;
                        p.x = wrapped;
                    }
                    if domain.periodic_y {
                        let wrapped = wrap_into(p.y, domain.lower.y, domain.upper.y);
                        piece.stale |= wrapped != p.y;
                        p.y = wrapped;
                    }
                    piece.stale |= (*p - piece.anchors[k]).norm_squared() > half_skin_squared;
                }
                piece.finite &= sphere.is_finite();
            }
        });
        let pieces = pieces.iter().flatten();
        let (finite, stale) = pieces.fold((true, false), |(finite, stale), piece| {
            (finite && piece.finite, stale || piece.stale)
        });
        if stale {
            self.list_current = false;
        }
        if !finite {
            self.overflowed = true;
            return Err(ContactError::NonFiniteResult);
        }
        Ok(())
    }

    /// Contact forces and torques at the current state into the force buffers, and, when
    /// `commit`, the history advanced (all or nothing).
    fn evaluate<N, T, M, R, W, E>(
        &mut self,
        input: &StepInput<'_, F, N, T, M, R, W>,
        commit: bool,
        executor: &E,
    ) -> Result<StepStats<F>, ContactError>
    where
        N: NormalModel<F>,
        T: TangentialModel<F, State = S>,
        M: MathBackend<F>,
        R: Rotation,
        W: WallSet<F>,
        E: Executor,
    {
        if !self.list_current {
            self.rebuild_list()?;
        }
        self.forces.fill(Vec3::ZERO);
        self.torques.fill(Vec3::ZERO);
        let mut stats = StepStats::default();
        let context = PairContext {
            law: input.law,
            spheres: self.spheres,
            grid: &self.grid,
            time_step: input.time_step,
        };
        let count = self.candidate_count;
        let candidates = &self.candidates[..count];
        if E::PARALLEL && self.pair_results.len() == self.candidates.len() {
            let length = piece_length(count, 1024);
            let mut states = self.states.chunks(length);
            let mut next_states = self.next_states.chunks_mut(length);
            let mut results = self.pair_results[..count].chunks_mut(length);
            let mut stretches = candidates.chunks(length);
            let mut pieces: [Option<PairPiece<'_, F, S>>; MAX_PIECES] = array::from_fn(|_| {
                Some(PairPiece {
                    candidates: stretches.next()?,
                    states: states.next()?,
                    next_states: next_states.next()?,
                    results: results.next()?,
                    outcome: Ok(()),
                })
            });
            executor.for_each_mut(&mut pieces, |piece| {
                let Some(piece) = piece else { return };
                piece.results.fill(PairResult::default());
                let results = &mut *piece.results;
                piece.outcome = context.stretch(
                    piece.candidates,
                    (piece.states, piece.next_states),
                    |at, result| results[at] = result,
                );
            });
            for piece in pieces.iter().flatten() {
                piece.outcome?;
            }
            for (candidate, result) in candidates.iter().zip(self.pair_results.iter()) {
                if result.touching {
                    add_pair((self.forces, self.torques), &mut stats, *candidate, result);
                }
            }
        } else {
            let (forces, torques) = (&mut *self.forces, &mut *self.torques);
            context.stretch(candidates, (self.states, self.next_states), |c, result| {
                if result.touching {
                    add_pair((forces, torques), &mut stats, candidates[c], &result);
                }
            })?;
        }
        if W::COUNT > 0 {
            stats.wall_contacts = self.wall_forces(input, executor)?;
        }
        if commit {
            core::mem::swap(&mut self.wall_states, &mut self.next_wall_states);
            core::mem::swap(&mut self.states, &mut self.next_states);
            self.swapped = !self.swapped;
        }
        Ok(stats)
    }

    /// Every sphere against every wall; returns the touching count.
    fn wall_forces<N, T, M, R, W, E>(
        &mut self,
        input: &StepInput<'_, F, N, T, M, R, W>,
        executor: &E,
    ) -> Result<usize, ContactError>
    where
        N: NormalModel<F>,
        T: TangentialModel<F, State = S>,
        M: MathBackend<F>,
        R: Rotation,
        W: WallSet<F>,
        E: Executor,
    {
        for k in 0..W::COUNT {
            // A wall's velocity is a public field: checked once per step, not per sphere.
            if !input.walls.wall(k).is_finite() {
                return Err(ContactError::NonFiniteInput);
            }
        }
        let n = self.spheres.len();
        let length = if E::PARALLEL {
            piece_length(n, 512)
        } else {
            n.max(1)
        };
        let mut spheres = self.spheres.chunks(length);
        let (mut forces, mut torques) = (
            self.forces.chunks_mut(length),
            self.torques.chunks_mut(length),
        );
        let mut states = self.wall_states.chunks(length * W::COUNT);
        let mut next_states = self.next_wall_states.chunks_mut(length * W::COUNT);
        let mut pieces: [Option<WallPiece<'_, F, S>>; MAX_PIECES] = array::from_fn(|_| {
            Some(WallPiece {
                spheres: spheres.next()?,
                forces: forces.next()?,
                torques: torques.next()?,
                states: states.next()?,
                next_states: next_states.next()?,
                outcome: Ok(0),
            })
        });
        executor.for_each_mut(&mut pieces, |piece| {
            let Some(piece) = piece else { return };
            piece.outcome = walls_of(input, piece);
        });
        let mut touching = 0;
        for piece in pieces.iter().flatten() {
            touching += piece.outcome?;
        }
        Ok(touching)
    }
}

/// The wall contacts of one stretch of spheres.
fn walls_of<F, N, T, M, R, W>(
    input: &StepInput<'_, F, N, T, M, R, W>,
    piece: &mut WallPiece<'_, F, T::State>,
) -> Result<usize, ContactError>
where
    F: Float,
    N: NormalModel<F>,
    T: TangentialModel<F>,
    M: MathBackend<F>,
    R: Rotation,
    W: WallSet<F>,
{
    let mut memo = OscillatorMemo::new();
    let mut touching = 0;
    for (index, sphere) in piece.spheres.iter().enumerate() {
        for k in 0..W::COUNT {
            let at = index * W::COUNT + k;
            let mut state = piece.states[at];
            let oscillator = memo.get(input.wall_law, || sphere.mass, [sphere.mass, F::ONE]);
            let contact = input.wall_law.sphere_wall_validated(
                (sphere, input.walls.wall(k)),
                oscillator,
                &mut state,
                input.time_step,
            )?;
            piece.next_states[at] = state;
            if let Interaction::Touching(c) = contact {
                piece.forces[index] += c.force_on_i();
                piece.torques[index] += c.torque_on_i;
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
