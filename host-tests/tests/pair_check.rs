//! `check_pairs` against the definition of a repeated contact, checked pair by pair against
//! every earlier one.

use proptest::prelude::*;
use soft_sphere::prelude::{CheckedPairs, ListArray, ListError, PairList, Vec3, check_pairs};

/// Whether entries `a` and `b` name one contact: the same two spheres through the same image,
/// either way round (`[i, j]` shifted by `s` is `[j, i]` shifted by `-s`).
fn same(a: ([u32; 2], Vec3<f64>), b: ([u32; 2], Vec3<f64>)) -> bool {
    let (([i, j], s), ([k, l], t)) = (a, b);
    (i == k && j == l && s == t) || (i == l && j == k && s == -t)
}

/// The first entry, in list order, that names a contact an earlier one names, and that earlier
/// one.
fn first_repeat(pairs: &[[u32; 2]], shifts: &[Vec3<f64>]) -> Option<(usize, usize)> {
    let entry = |k: usize| (pairs[k], shifts.get(k).copied().unwrap_or(Vec3::ZERO));
    (0..pairs.len()).find_map(|k| (0..k).find(|&m| same(entry(m), entry(k))).map(|m| (k, m)))
}

fn checked(pairs: &[[u32; 2]], shifts: &[Vec3<f64>], spheres: usize) -> Result<(), ListError> {
    let mut order = vec![7; pairs.len()];
    check_pairs((pairs, shifts), spheres, &mut order)
}

/// A shift of 0 or plus or minus one box length along x or y, as a cell list's images are.
fn image() -> impl Strategy<Value = Vec3<f64>> {
    (-1i32..=1, -1i32..=1)
        .prop_map(|(x, y)| Vec3::new(0.01 * f64::from(x), 0.02 * f64::from(y), 0.0))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn the_first_repeat_is_named_with_the_pair_it_repeats(
        entries in prop::collection::vec(((0u32..6, 0u32..6), image()), 0..24),
        shifted in any::<bool>(),
    ) {
        let pairs: Vec<[u32; 2]> = entries.iter().map(|((i, j), _)| [*i, *j]).collect();
        let shifts: Vec<Vec3<f64>> = if shifted {
            entries.iter().map(|(_, s)| *s).collect()
        } else {
            Vec::new()
        };
        let expected = match first_repeat(&pairs, &shifts) {
            Some((pair, first)) => Err(ListError::RepeatedPair { pair, first }),
            None => Ok(()),
        };
        prop_assert_eq!(checked(&pairs, &shifts, 6), expected);
    }
}

#[test]
fn each_way_of_naming_a_contact_twice_is_found() {
    let none: &[Vec3<f64>] = &[];
    // The same order, the other order.
    assert_eq!(
        checked(&[[0, 1], [2, 3], [0, 1]], none, 4),
        Err(ListError::RepeatedPair { pair: 2, first: 0 })
    );
    assert_eq!(
        checked(&[[0, 1], [2, 3], [3, 2], [1, 0]], none, 4),
        Err(ListError::RepeatedPair { pair: 2, first: 1 })
    );
    // Through images: reversed with the shift negated is the same contact; another image or
    // the same shift reversed is not.
    let s = Vec3::new(0.01, 0.0, 0.0);
    assert_eq!(
        checked(&[[0, 1], [1, 0]], &[s, -s], 2),
        Err(ListError::RepeatedPair { pair: 1, first: 0 })
    );
    assert_eq!(checked(&[[0, 1], [1, 0]], &[s, s], 2), Ok(()));
    assert_eq!(checked(&[[0, 1], [0, 1]], &[s, Vec3::ZERO], 2), Ok(()));
    // A sphere and its own image, named from either side; 0 and -0 are one shift.
    assert_eq!(
        checked(&[[0, 0], [0, 0]], &[s, -s], 1),
        Err(ListError::RepeatedPair { pair: 1, first: 0 })
    );
    let zero = Vec3::new(0.0, -0.0, 0.0);
    assert_eq!(
        checked(&[[0, 1], [0, 1]], &[Vec3::ZERO, zero], 2),
        Err(ListError::RepeatedPair { pair: 1, first: 0 })
    );
    // Of two repeats the first in list order, whatever the spheres' order.
    assert_eq!(
        checked(&[[5, 6], [0, 1], [6, 5], [0, 1]], none, 7),
        Err(ListError::RepeatedPair { pair: 2, first: 0 })
    );
    assert_eq!(checked(&[], none, 0), Ok(()));
}

#[test]
fn bad_lists_are_named_before_repeats() {
    let none: &[Vec3<f64>] = &[];
    assert_eq!(
        checked(&[[0, 1], [0, 1]], &[Vec3::ZERO], 2),
        Err(ListError::Length(ListArray::Shifts))
    );
    let mut short = [0; 1];
    assert_eq!(
        check_pairs((&[[0, 1], [0, 1]], none), 2, &mut short),
        Err(ListError::Length(ListArray::Order))
    );
    assert_eq!(
        checked(&[[0, 1], [0, 1], [0, 2]], none, 2),
        Err(ListError::PairIndex { pair: 2 })
    );
    assert_eq!(
        checked(
            &[[0, 1], [0, 1]],
            &[Vec3::ZERO, Vec3::new(f64::NAN, 0.0, 0.0)],
            2
        ),
        Err(ListError::Shift { pair: 1 })
    );
    // A bad shift or index in every place of a list of 7 (the finiteness probe's four sums and
    // the remainder after them), named; an index equal to the sphere count is past the arrays.
    let pairs: Vec<[u32; 2]> = (0..7).map(|k| [k, k + 1]).collect();
    for pair in 0..7 {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let mut shifts = vec![Vec3::new(0.01, 0.0, 0.0); 7];
            shifts[pair].z = bad;
            assert_eq!(checked(&pairs, &shifts, 8), Err(ListError::Shift { pair }));
        }
        let mut past = pairs.clone();
        past[pair][pair % 2] = 8;
        assert_eq!(checked(&past, none, 8), Err(ListError::PairIndex { pair }));
    }
    assert_eq!(checked(&pairs, none, 8), Ok(()));
    let text = ListError::RepeatedPair { pair: 4, first: 1 }.to_string();
    assert!(text.contains("pair 4 repeats pair 1"), "{text}");
}

/// The first entry naming a sphere at or past `spheres`, then the first shift that is not
/// finite: what a checked list may not hold.
fn first_outside(pairs: &[[u32; 2]], shifts: &[Vec3<f64>], spheres: u32) -> Option<ListError> {
    let index = pairs
        .iter()
        .position(|p| p[0] >= spheres || p[1] >= spheres);
    let shift = shifts
        .iter()
        .position(|s| !(s.x.is_finite() && s.y.is_finite() && s.z.is_finite()));
    index
        .map(|pair| ListError::PairIndex { pair })
        .or(shift.map(|pair| ListError::Shift { pair }))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn a_pair_list_holds_only_what_its_last_build_checked(
        builds in prop::collection::vec(
            (prop::collection::vec(((0u32..9, 0u32..9), -1i32..=2), 0..10), 0usize..12),
            1..6,
        ),
    ) {
        let (mut pairs, mut shifts) = ([[0; 2]; 8], [Vec3::<f64>::ZERO; 8]);
        let mut list = PairList::new(&mut pairs, &mut shifts).unwrap();
        prop_assert_eq!(list.capacity(), 8);
        // What the buffers hold, kept here: a build writes over the front and leaves the rest.
        let (mut held_pairs, mut held_shifts) = ([[0u32; 2]; 8], [Vec3::<f64>::ZERO; 8]);
        for (entries, count) in builds {
            let wanted: Vec<[u32; 2]> = entries.iter().map(|((i, j), _)| [*i, *j]).collect();
            // -1 marks a shift that is not finite.
            let images: Vec<Vec3<f64>> = entries
                .iter()
                .map(|(_, s)| Vec3::new(if *s < 0 { f64::NAN } else { 0.01 * f64::from(*s) }, 0.0, 0.0))
                .collect();
            let written = wanted.len().min(8);
            held_pairs[..written].copy_from_slice(&wanted[..written]);
            held_shifts[..written].copy_from_slice(&images[..written]);
            let built = list.rebuild(8, |p, s| {
                p[..written].copy_from_slice(&wanted[..written]);
                s[..written].copy_from_slice(&images[..written]);
                count
            });
            let expected = if count > 8 {
                Err(ListError::Length(ListArray::Pairs))
            } else {
                first_outside(&held_pairs[..count], &held_shifts[..count], 8).map_or(Ok(count), Err)
            };
            prop_assert_eq!(built, expected);
            let checked = list.checked();
            match built {
                Ok(count) => {
                    prop_assert_eq!(checked.len(), count);
                    prop_assert_eq!((list.len(), list.is_empty()), (count, count == 0));
                    prop_assert_eq!(checked.is_empty(), count == 0);
                    prop_assert_eq!(checked.spheres(), 8);
                    prop_assert_eq!(checked.pairs(), &held_pairs[..count]);
                    prop_assert_eq!(checked.shifts().len(), count);
                    prop_assert_eq!(list.buffers().0, &held_pairs[..]);
                    // What a build checked, a one-call check accepts.
                    prop_assert!(CheckedPairs::new(checked.pairs(), checked.shifts(), 8).is_ok());
                }
                Err(_) => prop_assert!(checked.is_empty() && list.is_empty()),
            }
        }
    }
}

#[test]
fn a_pair_list_without_shifts_keeps_none_and_buffers_must_agree() {
    let (mut pairs, mut shifts) = ([[0; 2]; 3], [Vec3::<f64>::ZERO; 2]);
    assert_eq!(
        PairList::new(&mut pairs, &mut shifts).err(),
        Some(ListError::Length(ListArray::Shifts))
    );
    let mut list = PairList::<f64>::new(&mut pairs, &mut []).unwrap();
    assert!(list.is_empty() && list.checked().is_empty());
    assert_eq!(
        list.rebuild(3, |p, s| {
            assert!(s.is_empty());
            p[..2].copy_from_slice(&[[0, 2], [1, 2]]);
            2
        }),
        Ok(2)
    );
    let checked = list.checked();
    assert_eq!(
        (checked.pairs(), checked.shifts().len()),
        (&[[0, 2], [1, 2]][..], 0)
    );
    // The same pairs are outside two spheres.
    assert_eq!(
        list.rebuild(2, |_, _| 2),
        Err(ListError::PairIndex { pair: 0 })
    );
    assert!(list.is_empty());
    // A one-call list: shifts none or one per pair.
    let one = [Vec3::<f64>::ZERO];
    assert_eq!(
        CheckedPairs::new(&[[0, 1], [1, 2]], &one, 3).err(),
        Some(ListError::Length(ListArray::Shifts))
    );
    assert!(CheckedPairs::<f64>::empty().is_empty());
}
