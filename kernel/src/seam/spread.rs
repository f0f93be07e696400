//! The list seam's pairs spread over an [`Executor`]'s threads: stretches of the list evaluated
//! each into its own per-pair loads, then added onto the spheres on one thread in list order, so
//! the sums are the bits one thread gives.

use core::array;

use crate::law::engine::{BoundLaw, Law};
use crate::law::sifted::SIFT;
use crate::seam::executor::{Executor, MAX_PIECES, piece_length};
use crate::seam::list_error::ListError;
use crate::seam::pairs::{Commit, Sink, Tally, evaluate_pairs};
use crate::seam::spheres::Spheres;
use crate::value::float::Float;
use crate::value::forces::{ContactForces, Interaction};
use crate::value::vector::Vec3;

/// One touching pair's loads, kept by the thread that evaluated it until they are added onto
/// the spheres in list order: working memory an engine gives
/// [`MaterialTable::evaluate_on`](crate::MaterialTable::evaluate_on), one per pair, filled
/// with `Default::default()` (what it holds between calls is of no meaning).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PairLoad<F> {
    force_on_j: Vec3<F>,
    torque_on_i: Vec3<F>,
    torque_on_j: Vec3<F>,
    overlap: F,
    pair: [u32; 2],
    sliding: bool,
}

/// A piece's touching pairs as they are committed: their loads one after another, in list
/// order, from the front of the piece's share of the loads.
pub(crate) struct PairLoads<'o, F> {
    /// The list place of the piece's first pair.
    offset: usize,
    loads: &'o mut [PairLoad<F>],
    /// How many loads are kept.
    count: usize,
    records: Option<&'o mut [Interaction<F>]>,
}

impl<F: Float> Commit<F> for PairLoads<'_, F> {
    #[inline(always)]
    fn begin_chunk(&mut self, first: usize, len: usize) -> Tally<F> {
        if let Some(records) = self.records.as_deref_mut() {
            let local = first - self.offset;
            records[local..local + len].fill(Interaction::Apart);
        }
        // The totals are counted as the loads are added in list order, after the threads.
        Tally::default()
    }

    #[inline(always)]
    fn end_chunk(&mut self, _: Tally<F>) {}

    #[inline(always)]
    fn pair(&mut self, k: usize, [i, j]: [usize; 2], c: &ContactForces<F>) {
        // A piece has as many loads as pairs, so a touching pair always finds its place.
        self.loads[self.count] = PairLoad {
            force_on_j: c.force_on_j(),
            torque_on_i: c.torque_on_i,
            torque_on_j: c.torque_on_j,
            overlap: c.overlap,
            pair: [i as u32, j as u32],
            sliding: c.sliding,
        };
        self.count += 1;
        if let Some(records) = self.records.as_deref_mut() {
            records[k - self.offset] = Interaction::Touching(*c);
        }
    }
}

/// A stretch of the list and what its thread leaves: the tolerated unstable contacts it
/// counted, or its first refused pair.
struct Piece<'p, F, S> {
    offset: usize,
    pairs: &'p [[u32; 2]],
    shifts: &'p [Vec3<F>],
    states: &'p [S],
    next: &'p mut [S],
    loads: PairLoads<'p, F>,
    outcome: Result<usize, ListError>,
}

/// Every pair, spread over `executor` in pieces of whole chunks, each with its own copy of the
/// bound laws; then, when every piece succeeded, their loads added onto the spheres in list
/// order. Returns the tolerated unstable contacts the pieces' bound laws counted, or the first
/// refused pair in list order (the earliest piece's first).
pub(crate) fn spread_pairs<L: Law, E: Executor, const MATERIALS: usize>(
    executor: &E,
    spheres: &impl Spheres<L::Float>,
    (pairs, shifts): (&[[u32; 2]], &[Vec3<L::Float>]),
    (states, next): (&[L::State], &mut [L::State]),
    loads: &mut [PairLoad<L::Float>],
    bound: &[[BoundLaw<L>; MATERIALS]; MATERIALS],
    sink: &mut Sink<'_, L::Float>,
) -> Result<usize, ListError> {
    // Stretches of at least four chunks: each thread's stretch starts its own working memory.
    let length = piece_length(pairs.len().div_ceil(SIFT), 4) * SIFT;
    let mut pair_pieces = pairs.chunks(length);
    let mut state_pieces = states.chunks(length);
    let mut next_pieces = next.chunks_mut(length);
    let mut load_pieces = loads.chunks_mut(length);
    let records = sink.records.as_deref_mut().map(|r| &mut r[..pairs.len()]);
    let mut record_pieces = records.map(|r| r.chunks_mut(length));
    let mut offset = 0;
    let mut pieces: [Option<Piece<'_, L::Float, L::State>>; MAX_PIECES] = array::from_fn(|_| {
        let pairs = pair_pieces.next()?;
        let piece = Piece {
            offset,
            pairs,
            shifts: shifts.get(offset..offset + pairs.len()).unwrap_or(&[]),
            states: state_pieces.next()?,
            next: next_pieces.next()?,
            loads: PairLoads {
                offset,
                loads: load_pieces.next()?,
                count: 0,
                records: record_pieces.as_mut().and_then(Iterator::next),
            },
            outcome: Ok(0),
        };
        offset += pairs.len();
        Some(piece)
    });
    executor.for_each_mut(&mut pieces, |piece| {
        let Some(piece) = piece else { return };
        let mut bound = *bound;
        piece.outcome = evaluate_pairs::<L, MATERIALS>(
            spheres,
            (piece.pairs, piece.shifts, piece.offset),
            (piece.states, &mut *piece.next),
            &mut bound,
            &mut piece.loads,
        )
        .map(|()| {
            bound
                .iter()
                .flatten()
                .map(BoundLaw::inaccurate_contacts)
                .sum()
        });
    });
    let refused = pieces
        .iter()
        .flatten()
        .find_map(|piece| piece.outcome.as_ref().err().copied());
    if let Some(error) = refused {
        return Err(error);
    }
    let unstable = pieces
        .iter()
        .flatten()
        .map(|piece| piece.outcome.as_ref().map_or(0, |&count| count))
        .sum();
    // Each piece's loads start at its first pair's place (the loads are cut as the pairs are).
    let kept: [(usize, usize); MAX_PIECES] = array::from_fn(|p| {
        pieces[p]
            .as_ref()
            .map_or((0, 0), |piece| (piece.offset, piece.loads.count))
    });
    for &(offset, count) in &kept {
        for load in &loads[offset..offset + count] {
            let pair = load.pair.map(|x| x as usize);
            let forces = (load.force_on_j, load.torque_on_i, load.torque_on_j);
            sink.add_pair(pair, forces, (load.overlap, load.sliding));
        }
    }
    Ok(unstable)
}
