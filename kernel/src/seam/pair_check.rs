//! A pair list checked once, when it is built.
//!
//! [`MaterialTable::evaluate`](crate::MaterialTable::evaluate) takes its pairs as
//! [`CheckedPairs`]: every index inside the spheres, every shift finite, as
//! [`CheckedSphere`](crate::CheckedSphere) carries a sphere's checks. A list made for one
//! call is checked as it is made ([`CheckedPairs::new`]); an engine's Verlet list, which lives
//! for many steps, is checked when it is built ([`PairList::rebuild`]) and evaluated at every
//! step with no check ([`PairList::checked`]).
//!
//! The seam adds each listed pair's force, so a pair listed twice (`[0, 1]` and `[0, 1]`, or
//! `[0, 1]` and `[1, 0]`) would be pushed twice as hard. Finding a repeat takes a sort, which
//! an engine pays once per list build, not once per step: [`check_pairs`] is that check.

use core::cmp::Ordering;

use crate::law::sifted::shift;
use crate::seam::list_error::{ListArray, ListError};
use crate::value::float::Float;
use crate::value::vector::{Vec3, all_finite};

/// Checks a pair list as an engine builds it, for `spheres` spheres: `shifts` none or one per
/// pair, every index inside the spheres, every shift finite, and no contact named twice. Two
/// entries name one contact when they join the same two spheres through the same image: `[i,
/// j]` with shift `s` and `[j, i]` with shift `-s` are one contact; so are `[i, i]` with `s`
/// and with `-s` (a sphere and its own periodic image). `order` is working memory, one entry
/// per pair; what it holds afterwards is unspecified.
///
/// ```
/// use soft_sphere::prelude::{ListError, Vec3, check_pairs};
///
/// let mut order = [0; 3];
/// let none: &[Vec3<f64>] = &[];
/// assert_eq!(check_pairs((&[[0, 1], [1, 2], [2, 0]], none), 3, &mut order), Ok(()));
/// assert_eq!(
///     check_pairs((&[[0, 1], [1, 2], [1, 0]], none), 3, &mut order),
///     Err(ListError::RepeatedPair { pair: 2, first: 0 })
/// );
/// // Through another periodic image, the same two spheres are another contact.
/// let shifts = [Vec3::ZERO, Vec3::new(0.01, 0.0, 0.0)];
/// assert_eq!(check_pairs((&[[0, 1], [0, 1]], &shifts[..]), 2, &mut order[..2]), Ok(()));
/// ```
///
/// # Errors
/// In this order, the first failure winning: [`ListError::Length`] for `shifts`
/// ([`ListArray::Shifts`]) or `order` ([`ListArray::Order`]) of another length;
/// [`ListError::PairIndex`] for the first pair naming a sphere past `spheres`;
/// [`ListError::Shift`] for the first shift that is not finite; [`ListError::RepeatedPair`]
/// for the first pair, in list order, that names a contact an earlier one names.
pub fn check_pairs<F: Float>(
    (pairs, shifts): (&[[u32; 2]], &[Vec3<F>]),
    spheres: usize,
    order: &mut [u32],
) -> Result<(), ListError> {
    shifts_fit(pairs.len(), shifts.len())?;
    if order.len() != pairs.len() || pairs.len() > u32::MAX as usize {
        return Err(ListError::Length(ListArray::Order));
    }
    check_places((pairs, shifts), spheres)?;
    let contact = |k: u32| contact_of(pairs[k as usize], shift(shifts, k as usize));
    for (k, place) in order.iter_mut().enumerate() {
        *place = k as u32;
    }
    // Equal contacts end up side by side, each run in list order.
    order.sort_unstable_by(|&a, &b| compare(&contact(a), &contact(b)).then(a.cmp(&b)));
    let mut repeat: Option<(u32, u32)> = None;
    for run in order.chunk_by(|&a, &b| compare(&contact(a), &contact(b)) == Ordering::Equal) {
        if let [first, second, ..] = *run {
            if repeat.is_none_or(|(pair, _)| second < pair) {
                repeat = Some((second, first));
            }
        }
    }
    match repeat {
        Some((pair, first)) => Err(ListError::RepeatedPair {
            pair: pair as usize,
            first: first as usize,
        }),
        None => Ok(()),
    }
}

/// A list's shifts are none, or one per pair ([`ListArray::Shifts`]).
fn shifts_fit(pairs: usize, shifts: usize) -> Result<(), ListError> {
    if shifts != 0 && shifts != pairs {
        return Err(ListError::Length(ListArray::Shifts));
    }
    Ok(())
}

/// The first pair naming a sphere past `spheres` ([`ListError::PairIndex`]), then the first
/// shift that is not finite ([`ListError::Shift`]): what keeps an evaluation in bounds, checked
/// by the list seam at every call and by [`check_pairs`] when a list is built.
#[inline(always)]
pub(crate) fn check_places<F: Float>(
    (pairs, shifts): (&[[u32; 2]], &[Vec3<F>]),
    spheres: usize,
) -> Result<(), ListError> {
    // Reductions with no branch per pair; the first offender is looked for only when one fails.
    let largest = pairs.iter().fold(0, |m: u32, &[i, j]| m.max(i).max(j));
    if largest as usize >= spheres {
        let outside = |&[i, j]: &[u32; 2]| i as usize >= spheres || j as usize >= spheres;
        if let Some(pair) = pairs.iter().position(outside) {
            return Err(ListError::PairIndex { pair });
        }
    }
    if !all_finite(shifts) {
        if let Some(pair) = shifts.iter().position(|shift| !shift.is_finite()) {
            return Err(ListError::Shift { pair });
        }
    }
    Ok(())
}

/// The contact a pair names, written one way: the lower index first, with the shift that
/// takes the second sphere to the image the first one touches (a self-image pair takes the
/// larger of its two shifts).
fn contact_of<F: Float>([i, j]: [u32; 2], shift: Vec3<F>) -> ([u32; 2], [F; 3]) {
    let (ahead, back) = (shift.to_array(), (-shift).to_array());
    match i.cmp(&j) {
        Ordering::Less => ([i, j], ahead),
        Ordering::Greater => ([j, i], back),
        Ordering::Equal if compare_shifts(&ahead, &back) == Ordering::Less => ([i, i], back),
        Ordering::Equal => ([i, i], ahead),
    }
}

fn compare<F: Float>(a: &([u32; 2], [F; 3]), b: &([u32; 2], [F; 3])) -> Ordering {
    a.0.cmp(&b.0).then_with(|| compare_shifts(&a.1, &b.1))
}

/// Finite shifts by value, component by component (0 and -0 are one image).
fn compare_shifts<F: Float>(a: &[F; 3], b: &[F; 3]) -> Ordering {
    a.iter()
        .zip(b)
        .map(|(x, y)| x.partial_cmp(y).unwrap_or(Ordering::Equal))
        .find(|o| o.is_ne())
        .unwrap_or(Ordering::Equal)
}

/// Pairs of spheres, as indices, with their periodic shifts (none, or one per pair), checked
/// for a number of spheres: every index inside them, every shift finite. Made by
/// [`CheckedPairs::new`], which checks, or by [`PairList::checked`], which was checked when it
/// was built.
///
/// ```
/// use soft_sphere::prelude::{CheckedPairs, ListError, Vec3};
///
/// let none: &[Vec3<f64>] = &[];
/// let pairs = CheckedPairs::new(&[[0, 1], [1, 2]], none, 3).unwrap();
/// assert_eq!((pairs.len(), pairs.spheres()), (2, 3));
/// assert_eq!(
///     CheckedPairs::new(&[[0, 1], [1, 3]], none, 3).unwrap_err(),
///     ListError::PairIndex { pair: 1 }
/// );
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CheckedPairs<'a, F> {
    pairs: &'a [[u32; 2]],
    shifts: &'a [Vec3<F>],
    spheres: usize,
}

impl<'a, F: Float> CheckedPairs<'a, F> {
    /// `pairs` with `shifts` (none, or one per pair: added to sphere `j`'s position for that
    /// pair, a periodic image as a cell list finds it; the forces still go to sphere `j`),
    /// checked for `spheres` spheres.
    ///
    /// # Errors
    /// In this order: [`ListError::Length`] ([`ListArray::Shifts`]) for shifts neither none
    /// nor one per pair; [`ListError::PairIndex`] for the first pair naming a sphere past
    /// `spheres`; [`ListError::Shift`] for the first shift that is not finite.
    pub fn new(
        pairs: &'a [[u32; 2]],
        shifts: &'a [Vec3<F>],
        spheres: usize,
    ) -> Result<Self, ListError> {
        shifts_fit(pairs.len(), shifts.len())?;
        check_places((pairs, shifts), spheres)?;
        Ok(Self {
            pairs,
            shifts,
            spheres,
        })
    }

    /// No pairs (a list of walls only), for any number of spheres.
    pub fn empty() -> Self {
        Self {
            pairs: &[],
            shifts: &[],
            spheres: 0,
        }
    }

    /// The pairs.
    pub fn pairs(&self) -> &'a [[u32; 2]] {
        self.pairs
    }

    /// The shifts: none, or one per pair.
    pub fn shifts(&self) -> &'a [Vec3<F>] {
        self.shifts
    }

    /// The number of spheres the pairs were checked for: every index is below it.
    pub fn spheres(&self) -> usize {
        self.spheres
    }

    /// The number of pairs.
    pub fn len(&self) -> usize {
        self.pairs.len()
    }

    /// No pairs.
    pub fn is_empty(&self) -> bool {
        self.pairs.is_empty()
    }
}

/// An engine's pair list in buffers of its own, kept from one build to the next and checked at
/// each build ([`PairList::rebuild`]), so that evaluating it at every step
/// ([`PairList::checked`]) costs no check. Between builds only the list itself can change it.
///
/// ```
/// use soft_sphere::prelude::{ListError, PairList, Vec3};
///
/// let (mut pairs, mut shifts) = ([[0; 2]; 4], [Vec3::<f64>::ZERO; 4]);
/// let mut list = PairList::new(&mut pairs, &mut shifts).unwrap();
/// let built = list.rebuild(3, |pairs, _shifts| {
///     pairs[..2].copy_from_slice(&[[0, 1], [1, 2]]);
///     2
/// });
/// assert_eq!(built, Ok(2));
/// assert_eq!(list.checked().pairs(), &[[0, 1], [1, 2]]);
/// // A build naming a sphere past the three leaves the list empty.
/// let built = list.rebuild(3, |pairs, _| {
///     pairs[0] = [2, 3];
///     1
/// });
/// assert_eq!(built, Err(ListError::PairIndex { pair: 0 }));
/// assert!(list.checked().is_empty());
/// ```
#[derive(Debug)]
pub struct PairList<'a, F> {
    pairs: &'a mut [[u32; 2]],
    shifts: &'a mut [Vec3<F>],
    len: usize,
    spheres: usize,
}

impl<'a, F: Float> PairList<'a, F> {
    /// An empty list over buffers for `pairs.len()` pairs: `shifts` empty for a list with no
    /// periodic images, or as long as `pairs`.
    ///
    /// # Errors
    /// [`ListError::Length`] ([`ListArray::Shifts`]) for shifts of another length.
    pub fn new(pairs: &'a mut [[u32; 2]], shifts: &'a mut [Vec3<F>]) -> Result<Self, ListError> {
        shifts_fit(pairs.len(), shifts.len())?;
        Ok(Self {
            pairs,
            shifts,
            len: 0,
            spheres: 0,
        })
    }

    /// How many pairs the buffers hold.
    pub fn capacity(&self) -> usize {
        self.pairs.len()
    }

    /// Builds the list for `spheres` spheres: `build` writes the first pairs (and their shifts,
    /// when the list has them) into the whole buffers and returns how many it wrote; they are
    /// then checked as [`CheckedPairs::new`] checks. Returns the count.
    ///
    /// # Errors
    /// [`ListError::Length`] ([`ListArray::Pairs`]) for a count past the capacity;
    /// otherwise as [`CheckedPairs::new`]. The list is then empty; the buffers hold what `build`
    /// wrote.
    pub fn rebuild(
        &mut self,
        spheres: usize,
        build: impl FnOnce(&mut [[u32; 2]], &mut [Vec3<F>]) -> usize,
    ) -> Result<usize, ListError> {
        self.len = 0;
        let count = build(self.pairs, self.shifts);
        if count > self.pairs.len() {
            return Err(ListError::Length(ListArray::Pairs));
        }
        let shifts = self.shifts.get(..count).unwrap_or_default();
        CheckedPairs::new(&self.pairs[..count], shifts, spheres)?;
        (self.len, self.spheres) = (count, spheres);
        Ok(count)
    }

    /// The list as last built: its pairs checked for the spheres it was built for.
    pub fn checked(&self) -> CheckedPairs<'_, F> {
        CheckedPairs {
            pairs: &self.pairs[..self.len],
            shifts: self.shifts.get(..self.len).unwrap_or_default(),
            spheres: self.spheres,
        }
    }

    /// The number of pairs in the list.
    pub fn len(&self) -> usize {
        self.len
    }

    /// The whole buffers as they are, past the list's end as well (an engine carrying the
    /// history of a list it did not build, as a restart's, reads them before its first build).
    pub fn buffers(&self) -> (&[[u32; 2]], &[Vec3<F>]) {
        (self.pairs, self.shifts)
    }

    /// No pairs in the list.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}
