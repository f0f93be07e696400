//! Why a list evaluation was refused: the error and the array it names.

use crate::value::error::{ContactError, ParameterError};

/// One of the arrays an evaluation is given.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ListArray {
    /// [`SphereArrays::velocity`](crate::SphereArrays::velocity).
    Velocity,
    /// [`SphereArrays::angular_velocity`](crate::SphereArrays::angular_velocity).
    AngularVelocity,
    /// [`SphereArrays::radius`](crate::SphereArrays::radius).
    Radius,
    /// [`SphereArrays::mass`](crate::SphereArrays::mass).
    Mass,
    /// [`SphereArrays::material`](crate::SphereArrays::material).
    Material,
    /// A pair list's shifts (none, or one per pair:
    /// [`CheckedPairs::new`](crate::CheckedPairs::new)).
    Shifts,
    /// A pair list's pairs: no more than its buffers hold
    /// ([`PairList::rebuild`](crate::PairList::rebuild)).
    Pairs,
    /// [`ContactList::pair_states`](crate::ContactList::pair_states) (one per pair).
    PairStates,
    /// [`ContactList::wall_states`](crate::ContactList::wall_states) (one per sphere and wall).
    WallStates,
    /// [`ListOutput::force`](crate::ListOutput::force).
    Force,
    /// [`ListOutput::torque`](crate::ListOutput::torque).
    Torque,
    /// [`ListOutput::records`](crate::ListOutput::records)
    /// ([`ListOutput::records_needed`](crate::ListOutput::records_needed)).
    Records,
    /// [`ListOutput::next_pair_states`](crate::ListOutput::next_pair_states) (one per pair).
    NextPairStates,
    /// [`ListOutput::next_wall_states`](crate::ListOutput::next_wall_states) (one per sphere and
    /// wall).
    NextWallStates,
    /// The per-pair loads of [`MaterialTable::evaluate_on`](crate::MaterialTable::evaluate_on)
    /// (none, or one per pair).
    Loads,
    /// The working memory of [`check_pairs`](crate::check_pairs) (one per pair).
    Order,
}

/// Why a list evaluation or its time step was refused. What the call reads (spheres, states,
/// walls) is unchanged; what it writes holds nothing of meaning.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ListError {
    /// An array's length disagrees with the spheres' (or, for states and records, with the
    /// contacts').
    Length(ListArray),
    /// Sphere `sphere`'s material id is not a row of the table.
    Material {
        /// The sphere.
        sphere: usize,
        /// Its id.
        material: u32,
    },
    /// Wall `wall`'s material id is not a row of the table.
    WallMaterial {
        /// The wall.
        wall: usize,
        /// Its id.
        material: u32,
    },
    /// Sphere `sphere` is invalid (a non-finite field, a radius or mass not positive).
    Sphere {
        /// The sphere.
        sphere: usize,
        /// What is wrong with it.
        error: ContactError,
    },
    /// Pair `pair` names a sphere past the arrays.
    PairIndex {
        /// The pair's place in the list.
        pair: usize,
    },
    /// Pair `pair`'s shift is not finite.
    Shift {
        /// The pair's place in the list.
        pair: usize,
    },
    /// Pair `pair` names the contact pair `first` names (the same two spheres through the same
    /// image, either way round): its force would be added twice
    /// ([`check_pairs`](crate::check_pairs)).
    RepeatedPair {
        /// The pair's place in the list.
        pair: usize,
        /// The earlier pair it repeats.
        first: usize,
    },
    /// The contact of pair `pair` was refused (coincident centres, an overflow, past the
    /// stable step).
    Pair {
        /// The pair's place in the list.
        pair: usize,
        /// Why.
        error: ContactError,
    },
    /// The contact of sphere `sphere` with wall `wall` was refused.
    Wall {
        /// The sphere.
        sphere: usize,
        /// The wall.
        wall: usize,
        /// Why.
        error: ContactError,
    },
    /// The step is refused by the law of materials `materials` (a wall's material second) at
    /// the smallest effective mass the spheres present give that pair.
    TimeStep {
        /// The two material ids.
        materials: [u32; 2],
        /// The law's answer ([`ParameterError::TimeStepUnstable`] with its limit).
        error: ParameterError,
    },
}

impl core::fmt::Display for ListError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Length(array) => write!(f, "the {array:?} array has the wrong length"),
            Self::Material { sphere, material } => {
                write!(f, "sphere {sphere}'s material {material} is past the table")
            }
            Self::WallMaterial { wall, material } => {
                write!(f, "wall {wall}'s material {material} is past the table")
            }
            Self::Sphere { sphere, error } => write!(f, "sphere {sphere}: {error}"),
            Self::PairIndex { pair } => write!(f, "pair {pair} names a sphere past the arrays"),
            Self::Shift { pair } => write!(f, "pair {pair}'s shift is not finite"),
            Self::RepeatedPair { pair, first } => write!(
                f,
                "pair {pair} repeats pair {first} (the same two spheres through the same image)"
            ),
            Self::Pair { pair, error } => write!(f, "pair {pair}: {error}"),
            Self::Wall {
                sphere,
                wall,
                error,
            } => write!(f, "sphere {sphere} against wall {wall}: {error}"),
            Self::TimeStep { materials, error } => write!(
                f,
                "materials {} and {}: {error}",
                materials[0], materials[1]
            ),
        }
    }
}

impl core::error::Error for ListError {}
