//! A pair list checked once, when it is built: every pair named once.
//!
//! [`MaterialTable::evaluate`](crate::MaterialTable::evaluate) adds each listed pair's force,
//! so a pair listed twice (`[0, 1]` and `[0, 1]`, or `[0, 1]` and `[1, 0]`) would be pushed
//! twice as hard. Finding a repeat takes a sort, which an engine pays once per list build (a
//! Verlet list lives for many steps), not once per step: [`check_pairs`] is that check, and
//! the evaluation checks only what it must to stay in bounds.

use core::cmp::Ordering;

use crate::float::Float;
use crate::list::{ListArray, ListError};
use crate::sifted::shift;
use crate::vector::{Vec3, all_finite};

/// Checks a pair list as an engine builds it, for `spheres` spheres: `shifts` none or one per
/// pair, every index inside the spheres, every shift finite, and no contact named twice. Two
/// entries name one contact when they join the same two spheres through the same image: `[i,
/// j]` with shift `s` and `[j, i]` with shift `-s` are one contact; so are `[i, i]` with `s`
/// and with `-s` (a sphere and its own periodic image). `order` is working memory, one entry
/// per pair; what it holds afterwards is unspecified.
///
/// ```
/// use soft_sphere::{ListError, Vec3, check_pairs};
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
    if !shifts.is_empty() && shifts.len() != pairs.len() {
        return Err(ListError::Length(ListArray::Shifts));
    }
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
