//! The batch path over an engine's arrays: pairs gathered from them into a group of blocks,
//! evaluated, and their outcomes scattered back, in one place for every engine.

use super::{ContactBlock, LANES, PairBlock};
use crate::body::Sphere;
use crate::engine::{BoundLaw, Law};
use crate::error::ContactError;
use crate::float::Float;
use crate::law::Interaction;
use crate::tangential::ContactState;

/// Blocks gathered before the first is evaluated: a block read as vectors straight after its
/// lanes were stored one by one waits on every load (`list_bench`).
const GROUP: usize = 8;

/// The pairs a [`BlockGroup`] evaluates, named by place: where each pair's spheres and state are
/// read from and where its outcome goes (an engine's arrays).
pub trait BlockPairs<L: Law> {
    /// The spheres of the pair at `place` (j as this contact sees it: a periodic image is
    /// already shifted) and its state before the step. The spheres need not be checked: the
    /// batch path checks every lane.
    fn gather(&self, place: usize) -> (Sphere<L::Float>, Sphere<L::Float>, L::State);

    /// The outcome of the pair at `place`, what [`BoundLaw::sphere_sphere`] returns for it, with
    /// the state after the step (on an error, the state [`BlockPairs::gather`] gave).
    fn scatter(
        &mut self,
        place: usize,
        outcome: Result<Interaction<L::Float>, ContactError>,
        state: &L::State,
    );
}

/// The working memory of the batch path over an engine's arrays: a group of blocks of [`LANES`]
/// pairs, gathered, evaluated and scattered by [`BlockGroup::evaluate`], the one gather and
/// scatter every engine of this workspace uses (the list seam's blocks route and the C ABI's
/// arrays entry). Keep one across calls: it is large (a few kB) and building it writes all of
/// it.
#[derive(Clone, Debug)]
pub struct BlockGroup<F: Float, S> {
    blocks: [PairBlock<F, LANES>; GROUP],
    states: [[S; LANES]; GROUP],
    out: [ContactBlock<F, LANES>; GROUP],
    places: [[usize; LANES]; GROUP],
}

impl<F: Float, S: ContactState> Default for BlockGroup<F, S> {
    fn default() -> Self {
        Self {
            blocks: [PairBlock::default(); GROUP],
            states: [[S::default(); LANES]; GROUP],
            out: [ContactBlock::default(); GROUP],
            places: [[0; LANES]; GROUP],
        }
    }
}

impl<F: Float, S: ContactState> BlockGroup<F, S> {
    /// Evaluates the pairs at `places` with `law` through blocks of [`LANES`]
    /// ([`BoundLaw::sphere_pairs`]): each gathered from `pairs`, and its outcome and state
    /// scattered back to it in the order of `places`. Every pair gets exactly what
    /// [`BoundLaw::sphere_sphere`] gives it one at a time, errors included; a bad pair does not
    /// disturb the others. Name each place once (a place named twice may be gathered twice
    /// before it is scattered, as a contact list never holds a pair twice).
    ///
    /// ```
    /// use soft_sphere::batch::{BlockGroup, BlockPairs};
    /// use soft_sphere::{
    ///     ContactError, ContactLaw, Interaction, LinearAA, LinearSpringDashpot, ModelAA, Sphere,
    ///     SpringDisplacement, TangentialParameters, Vec3,
    /// };
    ///
    /// /// Sphere k against sphere k + 1, the outcomes kept.
    /// struct Chain {
    ///     spheres: Vec<Sphere<f64>>,
    ///     states: Vec<SpringDisplacement<f64>>,
    ///     outcomes: Vec<Option<Result<Interaction<f64>, ContactError>>>,
    /// }
    /// impl BlockPairs<LinearAA<f64>> for Chain {
    ///     fn gather(&self, k: usize) -> (Sphere<f64>, Sphere<f64>, SpringDisplacement<f64>) {
    ///         (self.spheres[k], self.spheres[k + 1], self.states[k])
    ///     }
    ///     fn scatter(
    ///         &mut self,
    ///         k: usize,
    ///         outcome: Result<Interaction<f64>, ContactError>,
    ///         state: &SpringDisplacement<f64>,
    ///     ) {
    ///         self.states[k] = *state;
    ///         self.outcomes[k] = Some(outcome);
    ///     }
    /// }
    ///
    /// let law = ContactLaw::new(
    ///     LinearSpringDashpot::new(1.0e4_f64, 0.8).unwrap(),
    ///     ModelAA(TangentialParameters::new(3.0e3, 0.5, 0.4).unwrap()),
    /// );
    /// let sphere = |x: f64| Sphere::solid(Vec3::new(x, 0.0, 0.0), 1.0e-3, 2500.0);
    /// let spheres = vec![sphere(0.0), sphere(1.9e-3), sphere(1.9e-3), sphere(9.0e-3)];
    /// let dt = law.time_step(1.0e-6, spheres[0].mass / 2.0).unwrap();
    /// let mut chain = Chain { spheres, states: vec![Default::default(); 3], outcomes: vec![None; 3] };
    ///
    /// let mut group = BlockGroup::default();
    /// group.evaluate(&mut law.at(dt), [0, 1, 2], &mut chain);
    ///
    /// assert!(matches!(chain.outcomes[0], Some(Ok(Interaction::Touching(_)))));
    /// assert_eq!(chain.outcomes[1], Some(Err(ContactError::CoincidentCentres)));
    /// assert_eq!(chain.outcomes[2], Some(Ok(Interaction::Apart)));
    /// ```
    pub fn evaluate<L: Law<Float = F, State = S>>(
        &mut self,
        law: &mut BoundLaw<L>,
        places: impl IntoIterator<Item = usize>,
        pairs: &mut impl BlockPairs<L>,
    ) {
        let mut places = places.into_iter();
        loop {
            let gathered = self.gather(&mut places, pairs);
            for (b, start) in (0..gathered).step_by(LANES).enumerate() {
                let lanes = LANES.min(gathered - start);
                evaluate_block(law, &self.blocks[b], &mut self.states[b], &mut self.out[b]);
                for lane in 0..lanes {
                    let outcome = self.out[b].outcome(lane);
                    pairs.scatter(self.places[b][lane], outcome, &self.states[b][lane]);
                }
            }
            if gathered < LANES * GROUP {
                return;
            }
        }
    }

    /// Fills the group's blocks from `places` in order; returns how many pairs it holds. The
    /// unused lanes of the last block hold spheres of no size (refused, and not scattered).
    #[inline(always)]
    fn gather<L: Law<Float = F, State = S>>(
        &mut self,
        places: &mut impl Iterator<Item = usize>,
        pairs: &impl BlockPairs<L>,
    ) -> usize {
        let mut gathered = 0;
        for ((block, states), held) in self
            .blocks
            .iter_mut()
            .zip(&mut self.states)
            .zip(&mut self.places)
        {
            for lane in 0..LANES {
                let Some(place) = places.next() else {
                    for unused in lane..LANES {
                        block.set(unused, &Sphere::default(), &Sphere::default());
                    }
                    return gathered;
                };
                let (i, j, state) = pairs.gather(place);
                block.set(lane, &i, &j);
                states[lane] = state;
                held[lane] = place;
                gathered += 1;
            }
        }
        gathered
    }
}

/// One block through the batch path, in a function of its own: there the compiler keeps the
/// lanes in vector registers (inlined into an engine's large pair loop, it did not).
#[inline(never)]
fn evaluate_block<L: Law>(
    law: &mut BoundLaw<L>,
    block: &PairBlock<L::Float, LANES>,
    states: &mut [L::State; LANES],
    out: &mut ContactBlock<L::Float, LANES>,
) {
    law.sphere_pairs(block, states, out);
}
