//! The pair phase of the list seam: chunk by chunk, the candidate pairs sifted for contact
//! ([`Sifts`]), the touching ones evaluated one at a time from their states by the one-contact
//! path's formulas, and committed in list order to a [`Commit`]: the [`Sink`] of the engine's
//! arrays on one thread, or a thread's per-pair loads ([`spread`](crate::seam::spread)).

use crate::law::engine::sealed::Deferred;
use crate::law::engine::{BoundLaw, Law};
use crate::law::sifted::{SIFT, Sifts, shift};
use crate::law::tangential::ContactState;
use crate::seam::list_error::ListError;
use crate::seam::spheres::Spheres;
use crate::seam::stats::ListStats;
use crate::value::body::Sphere;
use crate::value::checked::CheckedSphere;
use crate::value::error::ContactError;
use crate::value::float::Float;
use crate::value::forces::{ContactForces, Interaction};
use crate::value::vector::Vec3;

/// Where a chunk's touching pairs go as they are evaluated, in list order within the chunk:
/// the [`Sink`] (added into the engine's arrays at once, on one thread) or a piece's
/// [`PairLoads`](crate::seam::spread::PairLoads) (kept per pair, added in list order after the
/// threads).
pub(crate) trait Commit<F> {
    /// Places `first..first + len` are about to be evaluated: apart until committed. Returns the
    /// running totals the chunk's contacts are counted on.
    fn begin_chunk(&mut self, first: usize, len: usize) -> Tally<F>;

    /// Pair `[i, j]`, the `k`-th contact of the list, touching with `c`: its loads.
    fn pair(&mut self, k: usize, pair: [usize; 2], c: &ContactForces<F>);

    /// The chunk's contacts are committed and counted on `tally`.
    fn end_chunk(&mut self, tally: Tally<F>);
}

/// The running totals of the touching pairs, counted in list order in a chunk's own local
/// value rather than through the engine's arrays' owner, which the compiler cannot keep in
/// registers across the stores of the forces.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Tally<F> {
    contacts: usize,
    sliding: usize,
    overlap_sum: F,
}

impl<F: Float> Tally<F> {
    /// One more touching pair of this overlap, sliding or not.
    #[inline(always)]
    pub(crate) fn count(&mut self, overlap: F, sliding: bool) {
        self.contacts += 1;
        self.sliding += usize::from(sliding);
        self.overlap_sum += overlap;
    }
}

/// Where the contacts' outcomes go, in list order.
pub(crate) struct Sink<'o, F> {
    pub(crate) force: &'o mut [Vec3<F>],
    pub(crate) torque: &'o mut [Vec3<F>],
    pub(crate) records: Option<&'o mut [Interaction<F>]>,
    pub(crate) stats: ListStats<F>,
}

impl<F: Float> Commit<F> for Sink<'_, F> {
    #[inline(always)]
    fn begin_chunk(&mut self, first: usize, len: usize) -> Tally<F> {
        if let Some(records) = self.records.as_deref_mut() {
            records[first..first + len].fill(Interaction::Apart);
        }
        Tally {
            contacts: self.stats.pair_contacts,
            sliding: self.stats.sliding_contacts,
            overlap_sum: self.stats.overlap_sum,
        }
    }

    #[inline(always)]
    fn pair(&mut self, k: usize, pair: [usize; 2], c: &ContactForces<F>) {
        self.add_loads(pair, (c.force_on_j(), c.torque_on_i, c.torque_on_j));
        self.record(k, Interaction::Touching(*c));
    }

    #[inline(always)]
    fn end_chunk(&mut self, tally: Tally<F>) {
        self.stats.pair_contacts = tally.contacts;
        self.stats.sliding_contacts = tally.sliding;
        self.stats.overlap_sum = tally.overlap_sum;
    }
}

impl<F: Float> Sink<'_, F> {
    /// A touching pair's force on j and torques on i and j added onto its spheres, and counted:
    /// the loads of a pair another thread evaluated, in list order.
    #[inline(always)]
    pub(crate) fn add_pair(
        &mut self,
        pair: [usize; 2],
        loads: (Vec3<F>, Vec3<F>, Vec3<F>),
        (overlap, sliding): (F, bool),
    ) {
        self.add_loads(pair, loads);
        self.stats.pair_contacts += 1;
        self.stats.sliding_contacts += usize::from(sliding);
        self.stats.overlap_sum += overlap;
    }

    /// A touching pair's force on j and torques on i and j added onto its spheres: the one
    /// place where a pair's loads meet the engine's arrays, whichever thread evaluated it.
    #[inline(always)]
    fn add_loads(
        &mut self,
        [i, j]: [usize; 2],
        (on_j, torque_on_i, torque_on_j): (Vec3<F>, Vec3<F>, Vec3<F>),
    ) {
        self.force[i] -= on_j;
        self.torque[i] += torque_on_i;
        self.force[j] += on_j;
        self.torque[j] += torque_on_j;
    }

    /// Sphere `sphere`, the `k`-th contact of the list, touching a wall with `c`.
    #[inline(always)]
    pub(crate) fn wall(&mut self, k: usize, sphere: usize, c: &ContactForces<F>) {
        self.force[sphere] += c.force_on_i();
        self.torque[sphere] += c.torque_on_i;
        self.stats.wall_contacts += 1;
        self.stats.sliding_contacts += usize::from(c.sliding);
        self.record(k, Interaction::Touching(*c));
    }

    #[inline(always)]
    fn record(&mut self, k: usize, interaction: Interaction<F>) {
        if let Some(records) = self.records.as_deref_mut() {
            records[k] = interaction;
        }
    }
}

/// `sphere` moved by `shift`.
#[inline(always)]
fn shifted<F: Float>(sphere: Sphere<F>, shift: Vec3<F>) -> Sphere<F> {
    Sphere {
        position: sphere.position + shift,
        ..sphere
    }
}

/// A stretch of the pair list: its pairs, their shifts (or none), and the list place of its
/// first pair.
pub(crate) type Stretch<'a, F> = (&'a [[u32; 2]], &'a [Vec3<F>], usize);

/// Every pair, chunk by chunk: sifted, evaluated one at a time from its state in `states` into
/// `next`, and committed in list order. `offset` is the list place of `pairs[0]`. Stops at the
/// first chunk with a refused pair, naming the first in list order.
pub(crate) fn evaluate_pairs<L: Law, const MATERIALS: usize>(
    spheres: &impl Spheres<L::Float>,
    (pairs, shifts, offset): Stretch<'_, L::Float>,
    (states, next): (&[L::State], &mut [L::State]),
    bound: &mut [[BoundLaw<L>; MATERIALS]; MATERIALS],
    sink: &mut impl Commit<L::Float>,
) -> Result<(), ListError> {
    let spheres = &spheres.evened();
    let mut sifts = Sifts::<L::Float>::new();
    let chunks = pairs.chunks(SIFT).zip(states.chunks(SIFT));
    for (c, ((chunk, states), next)) in chunks.zip(next.chunks_mut(SIFT)).enumerate() {
        let local = c * SIFT;
        let first = offset + local;
        // Written afresh: a pair apart is left relaxed, as the one-contact path leaves it, with
        // no branch on the coin toss of touching.
        if size_of::<L::State>() > 0 {
            next.fill(L::State::default());
        }
        let buffers = (&mut *next, states);
        let shifts = shifts.get(local..local + chunk.len()).unwrap_or(&[]);
        let found = sifts.sift(spheres, (chunk, shifts));
        let mut tally = sink.begin_chunk(first, chunk.len());
        let failed = one_at_a_time(
            (&mut sifts, found),
            spheres,
            (chunk, shifts),
            buffers,
            bound,
            sink,
            (first, &mut tally),
        );
        sink.end_chunk(tally);
        if let Some((k, error)) = failed {
            let pair = first + k;
            return Err(ListError::Pair { pair, error });
        }
    }
    Ok(())
}

/// The sifted pairs one at a time by the one-contact path's formulas, their roots taken for
/// the whole chunk first ([`Law::sifted_roots`]), each touching pair committed
/// to `sink` as it comes (`first` is the chunk's place in the list); returns the first
/// refused. The forces and states are tested for finiteness once for the chunk (a sum of their
/// probes) rather than at every contact; when that test or a contact fails, [`first_refused`]
/// re-runs the pairs checked to name the first refused in list order.
#[inline(always)]
fn one_at_a_time<L: Law, const MATERIALS: usize>(
    (sifts, found): (&mut Sifts<L::Float>, usize),
    spheres: &impl Spheres<L::Float>,
    (chunk, shifts): (&[[u32; 2]], &[Vec3<L::Float>]),
    (next, states): (&mut [L::State], &[L::State]),
    bound: &mut [[BoundLaw<L>; MATERIALS]; MATERIALS],
    sink: &mut impl Commit<L::Float>,
    (first, tally): (usize, &mut Tally<L::Float>),
) -> Option<(usize, ContactError)> {
    // Counted in a local copy, which stays in registers across the stores of the loads.
    let mut counted = *tally;
    L::sifted_roots(sifts, found, states, Deferred(()));
    let mut probe = <L::Float as Float>::ZERO;
    let mut finite_states = true;
    for (place, &k) in sifts.places[..found].iter().enumerate() {
        let k = usize::from(k);
        let [i, j] = chunk[k].map(|x| x as usize);
        let law = &mut bound[spheres.material(i) as usize][spheres.material(j) as usize];
        let (a, b) = (
            CheckedSphere::trusted(spheres.sphere(i)),
            CheckedSphere::trusted(shifted(spheres.sphere(j), shift(shifts, k))),
        );
        let sifted = sifts.pair(place);
        let mut state = states[k];
        match law.sphere_sphere_sifted(&a, &b, &sifted, &mut state) {
            Ok(Interaction::Touching(forces)) => {
                probe += forces.finite_probe();
                finite_states &= state.is_finite();
                sink.pair(first + k, [i, j], &forces);
                counted.count(forces.overlap, forces.sliding);
            }
            Ok(Interaction::Apart) => {}
            Err(error) => {
                let earlier = &sifts.places[..place];
                let refused = first_refused(spheres, (chunk, shifts), states, earlier, bound);
                return Some(refused.unwrap_or((k, error)));
            }
        }
        next[k] = state;
    }
    *tally = counted;
    if probe.is_finite() && finite_states {
        return None;
    }
    // A finite-valued probe that overflowed finds nothing: the chunk stands as evaluated.
    first_refused(
        spheres,
        (chunk, shifts),
        states,
        &sifts.places[..found],
        bound,
    )
}

/// The first of the sifted `places` that the one-contact path refuses, each evaluated checked
/// from its state on a copy of its bound law (nothing is written, nothing counted twice).
#[cold]
#[inline(never)]
fn first_refused<L: Law, const MATERIALS: usize>(
    spheres: &impl Spheres<L::Float>,
    (chunk, shifts): (&[[u32; 2]], &[Vec3<L::Float>]),
    states: &[L::State],
    places: &[u16],
    bound: &[[BoundLaw<L>; MATERIALS]; MATERIALS],
) -> Option<(usize, ContactError)> {
    places.iter().find_map(|&k| {
        let k = usize::from(k);
        let [i, j] = chunk[k].map(|x| x as usize);
        let mut law = bound[spheres.material(i) as usize][spheres.material(j) as usize];
        let (a, b) = (
            CheckedSphere::trusted(spheres.sphere(i)),
            CheckedSphere::trusted(shifted(spheres.sphere(j), shift(shifts, k))),
        );
        let mut state = states[k];
        law.sphere_sphere(&a, &b, &mut state)
            .err()
            .map(|error| (k, error))
    })
}
