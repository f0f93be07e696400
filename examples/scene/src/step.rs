//! One step of a scene: the contact forces of the whole Verlet list and the walls in one call
//! of the kernel's list seam, then the integrator's kick and drift, spread over an
//! [`Executor`]'s threads with the same bits.

use core::array;

use soft_sphere::motion::Kick;
use soft_sphere::prelude::{ContactList, Float, Law, ListOutput, SphereSlice, Vec3};

use crate::parallel::{Executor, MAX_PIECES, Serial, piece_length};
use crate::{Energy, Integrator, Scene, StepError, StepInput, StepStats, WallSet};

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
                &soft_sphere::prelude::Sphere::at_rest(Vec3::ZERO, F::ONE, F::ONE),
                F::ONE,
            ),
            dt,
        }
    }

    #[inline(always)]
    fn get(&mut self, sphere: &soft_sphere::prelude::Sphere<F>) -> Kick<F> {
        let kind = [sphere.mass, sphere.radius];
        if kind != self.kind {
            self.kind = kind;
            self.kick = Kick::new(sphere, self.dt);
        }
        self.kick
    }
}

/// One piece of an integration phase: a stretch of spheres.
struct AdvancePiece<'p, F> {
    spheres: &'p mut [soft_sphere::prelude::CheckedSphere<F>],
    force: &'p [Vec3<F>],
    torque: &'p [Vec3<F>],
    anchor: &'p [Vec3<F>],
    /// The offset of the stretch's first sphere in the scene.
    first: usize,
    /// The first sphere of the stretch that diverged.
    diverged: Option<usize>,
    stale: bool,
    /// Work the contact forces and torques did on the stretch's spheres in the kick (J).
    contact_work: F,
    /// Work gravity did on the stretch's spheres in the kick (J).
    gravity_work: F,
}

impl<L: Law, W: WallSet<L::Float>, const K: usize> Scene<'_, L, W, K> {
    /// One step of the scene, on this thread. The same as [`Scene::step_on`] with [`Serial`].
    ///
    /// # Errors
    /// As [`Scene::step_on`].
    pub fn step<const MATERIALS: usize>(
        &mut self,
        input: &StepInput<'_, L, MATERIALS>,
    ) -> Result<StepStats<L::Float>, StepError> {
        self.step_on(input, &Serial)
    }

    /// One step of the scene spread over `executor`'s threads: the pairs through the kernel's
    /// list seam ([`MaterialTable::evaluate_on`](soft_sphere::prelude::MaterialTable::evaluate_on), when
    /// the scene has its per-pair loads), the integration in stretches of spheres. The result is
    /// the same bits for any executor and any number of threads.
    ///
    /// # Errors
    /// - [`StepError::Pair`], [`StepError::Wall`]: the first refused contact, in list order and
    ///   then sphere order for walls; [`StepError::Material`], [`StepError::WallMaterial`] for
    ///   an id past the table. With symplectic Euler the scene is then exactly as before the
    ///   call; with velocity Verlet the spheres have had the step's first half kick and drift,
    ///   and the contact history is as before.
    /// - [`StepError::ListFull`], [`StepError::ParkingFull`] at a list rebuild. Nothing is lost:
    ///   the list buffers still hold every stored state, so copying them to the front of longer
    ///   ones (or keeping them with a larger parking) and building a scene again carries on
    ///   from the same history.
    /// - [`StepError::Outside`] for the first sphere found outside the domain along a closed
    ///   direction when the list is rebuilt (at the latest once it has moved half the skin);
    ///   the history is as before, and the spheres as for a refused contact.
    /// - [`StepError::Diverged`] when finite forces moved a sphere to a non-finite position or
    ///   velocity; that sphere keeps its previous state, and every later step returns
    ///   [`StepError::Halted`].
    /// - [`StepError::Gravity`] for a non-finite gravity, before anything changes.
    pub fn step_on<E: Executor, const MATERIALS: usize>(
        &mut self,
        input: &StepInput<'_, L, MATERIALS>,
        executor: &E,
    ) -> Result<StepStats<L::Float>, StepError> {
        if self.halted {
            return Err(StepError::Halted);
        }
        if !input.gravity.is_finite() {
            return Err(StepError::Gravity);
        }
        let dt = input.time_step.seconds();
        let half = <L::Float as Float>::HALF;
        let mut stats = match input.integrator {
            Integrator::SymplecticEuler => {
                let stats = self.evaluate(input, true, executor)?;
                self.forces_current = false;
                self.advance(input.gravity, (dt, Some(dt)), executor)?;
                stats
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
                stats
            }
        };
        if stats.energy.is_some() {
            stats.energy = Some(self.ledger.energy());
            self.account_motion(&mut stats);
        }
        Ok(stats)
    }

    /// Kicks every sphere by `kick` seconds under its contact force and torque and gravity,
    /// then, given a `drift`, moves it that long at its new velocity, wraps it into the periodic
    /// box and checks the skin (a sphere that moved more than half of it since the last build
    /// could touch a pair the list does not hold; one that wrapped has broken its pairs'
    /// shifts, and is a box length from where it was). Books the kick's work of the contacts and
    /// of gravity in the energy account, summed piece by piece in a fixed order (the pieces do
    /// not depend on the executor).
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
        let length = piece_length(self.spheres.len(), 512);
        let mut spheres = self.spheres.chunks_mut(length);
        let mut force = self.force.chunks(length);
        let mut torque = self.torque.chunks(length);
        let mut anchor = self.anchor.chunks(length);
        let mut first = 0;
        let mut pieces: [Option<AdvancePiece<'_, L::Float>>; MAX_PIECES] = array::from_fn(|_| {
            let piece = AdvancePiece {
                spheres: spheres.next()?,
                force: force.next()?,
                torque: torque.next()?,
                anchor: anchor.next()?,
                first,
                diverged: None,
                stale: false,
                contact_work: L::Float::ZERO,
                gravity_work: L::Float::ZERO,
            };
            first += piece.spheres.len();
            Some(piece)
        });
        let domain = self.grid.domain;
        let quarter = <L::Float as Float>::HALF * <L::Float as Float>::HALF;
        let half_skin_squared = self.skin * self.skin * quarter;
        let half_kick = kick * <L::Float as Float>::HALF;
        // The energy account needs the kicks' work; a scene without records skips it.
        let book = !self.records.is_empty();
        let (periodic_x, periodic_y) = (domain.periodic_x, domain.periodic_y);
        // The step's numbers taken by value: read through references, they were loaded again
        // for every sphere.
        executor.for_each_mut(&mut pieces, move |piece| {
            let Some(piece) = piece else { return };
            let mut memo = KickMemo::new(kick);
            let loads = piece.force.iter().zip(piece.torque).zip(piece.anchor);
            for (k, (checked, ((&force, &torque), &anchor))) in
                piece.spheres.iter_mut().zip(loads).enumerate()
            {
                let mut sphere = **checked;
                let (velocity, spin) = (sphere.velocity, sphere.angular_velocity);
                let pull = force + gravity * sphere.mass;
                memo.get(&sphere).apply(&mut sphere, pull, torque);
                // Each force's work as the kick applies it: F . (v + v') h / 2.
                let (contact, gravity_work) = if book {
                    let mean = (velocity + sphere.velocity) * half_kick;
                    let mean_spin = (spin + sphere.angular_velocity) * half_kick;
                    (
                        force.dot(mean) + torque.dot(mean_spin),
                        gravity.dot(mean) * sphere.mass,
                    )
                } else {
                    (L::Float::ZERO, L::Float::ZERO)
                };
                let mut stale = false;
                if let Some(dt) = drift {
                    let p = &mut sphere.position;
                    *p += sphere.velocity * dt;
                    if periodic_x {
                        p.x = wrap_into(p.x, domain.lower.x, domain.upper.x);
                    }
                    if periodic_y {
                        p.y = wrap_into(p.y, domain.lower.y, domain.upper.y);
                    }
                    // A sphere that wrapped sits about a box length (at least three cells) from
                    // its anchor, so this also stales the list whose shifts it broke.
                    stale = (*p - anchor).norm_squared() > half_skin_squared;
                }
                // Only the motion changed: only it is checked again.
                let moved =
                    checked.set_motion(sphere.position, sphere.velocity, sphere.angular_velocity);
                match moved {
                    Ok(()) => {
                        piece.stale |= stale;
                        piece.contact_work += contact;
                        piece.gravity_work += gravity_work;
                    }
                    Err(_) => {
                        piece.diverged = piece.diverged.or(Some(piece.first + k));
                    }
                }
            }
        });
        let pieces = pieces.iter().flatten();
        let zero = L::Float::ZERO;
        let (diverged, stale, work) = pieces.fold(
            (None, false, (zero, zero)),
            |(diverged, stale, (contact, gravity)), piece| {
                (
                    Option::or(diverged, piece.diverged),
                    stale || piece.stale,
                    (contact + piece.contact_work, gravity + piece.gravity_work),
                )
            },
        );
        if stale {
            self.list_current = false;
        }
        if let Some(index) = diverged {
            self.halted = true;
            return Err(StepError::Diverged { index });
        }
        self.ledger.contact_work += work.0;
        self.ledger.gravity_work += work.1;
        Ok(())
    }

    /// Contact forces and torques at the current state into the force and torque arrays, in
    /// one call of the kernel's list seam, and, when `commit`, the history advanced (all or
    /// nothing: the seam reads the current states and writes the next buffer, which becomes
    /// current only when the call succeeds and the step commits).
    fn evaluate<E: Executor, const MATERIALS: usize>(
        &mut self,
        input: &StepInput<'_, L, MATERIALS>,
        commit: bool,
        executor: &E,
    ) -> Result<StepStats<L::Float>, StepError> {
        if !self.list_current {
            self.rebuild_list()?;
        }
        let count = self.candidate_count;
        let n = self.spheres.len();
        let contacts = count + n * W::COUNT;
        let keep_records = !self.records.is_empty();
        let spheres = SphereSlice {
            spheres: self.spheres,
            material: self.materials,
        };
        let list = ContactList {
            pairs: self.list.checked(),
            pair_states: &self.pair_states[..count],
            walls: self.walls.walls(),
            wall_states: self.wall_states,
        };
        let out = ListOutput {
            force: &mut *self.force,
            torque: &mut *self.torque,
            next_pair_states: &mut self.next_pair_states[..count],
            next_wall_states: self.next_wall_states,
            records: keep_records.then(|| &mut self.records[..contacts]),
        };
        self.records_current = false;
        // Empty (the pairs on this thread), or one per list place.
        let loads = if self.loads.is_empty() {
            &mut [][..]
        } else {
            &mut self.loads[..count]
        };
        let outcome =
            input
                .table
                .evaluate_on((executor, loads), input.time_step, &spheres, list, out);
        let list_stats = match outcome {
            Ok(stats) => stats,
            Err(error) => {
                // A refused evaluation leaves no forces of meaning: none, as before any.
                self.force.fill(Vec3::ZERO);
                self.torque.fill(Vec3::ZERO);
                return Err(StepError::from_list(error, self.list.checked().pairs()));
            }
        };
        self.records_current = keep_records;
        if commit {
            self.flip();
        }
        let mut stats = StepStats {
            pair_contacts: list_stats.pair_contacts,
            sliding_contacts: list_stats.sliding_contacts,
            wall_contacts: list_stats.wall_contacts,
            inaccurate_contacts: list_stats.inaccurate_contacts,
            overlap_sum: list_stats.overlap_sum,
            energy: None,
        };
        if commit && keep_records {
            self.account_contacts(input.table, input.time_step.seconds());
            // Filled in at the end of the step, after its kicks.
            stats.energy = Some(Energy::default());
        }
        Ok(stats)
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
