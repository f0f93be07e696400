//! `check_pairs` against the definition of a repeated contact, checked pair by pair against
//! every earlier one.

use proptest::prelude::*;
use soft_sphere::{ListArray, ListError, Vec3, check_pairs};

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
