//! A fixed-capacity table of contact laws, one per pair of materials.

use crate::law::engine::Law;
use crate::law::mixing::Mixing;
use crate::value::error::ParameterError;

/// The contact laws of a scene of up to `MATERIALS` materials: one law of type `L` per pair of
/// material ids, symmetric, made by a [`Mixing`] rule from each material's properties and
/// overridable pair by pair. Walls are materials of the same table. No allocation:
/// `MATERIALS * MATERIALS` laws inline.
///
/// Engines evaluate whole contact lists through it ([`MaterialTable::evaluate`]), with the time
/// step checked against the spheres actually present ([`MaterialTable::time_step`]).
///
/// ```
/// use soft_sphere::prelude::{LinearMaterial, LinearMixing, MaterialTable, ModelAA};
///
/// let glass = LinearMaterial {
///     normal_stiffness: 1.0e4_f64, restitution: 0.9, tangential_stiffness: 8.0e3,
///     dashpot_ratio: 0.5, friction: 0.4,
/// };
/// let steel = LinearMaterial { normal_stiffness: 4.0e4, friction: 0.2, ..glass };
/// let mut table = MaterialTable::mixed(&LinearMixing::new(ModelAA), &[glass, steel]).unwrap();
/// assert_eq!(table.law(0, 1).unwrap().normal().stiffness(), 2.0e4); // sqrt(1e4 * 4e4)
///
/// // Any pair can be given its own law (both orders).
/// let rough = LinearMixing::new(ModelAA).law(&glass, &LinearMaterial { friction: 0.9, ..steel });
/// table.set(1, 0, rough.unwrap()).unwrap();
/// assert!((table.law(0, 1).unwrap().tangential().0.friction() - 0.6).abs() < 1e-15);
/// assert!(table.law(0, 2).is_none()); // past the table
/// # use soft_sphere::prelude::Mixing;
/// ```
#[derive(Clone, Copy, Debug)]
pub struct MaterialTable<L, const MATERIALS: usize> {
    laws: [[L; MATERIALS]; MATERIALS],
}

/// Why a [`MaterialTable`] could not be built or changed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TableError {
    /// A material id is not below the table's capacity `MATERIALS`.
    MaterialOutOfRange {
        /// The id.
        material: usize,
    },
    /// The law of this pair of materials refused its parameters.
    Pair {
        /// The two material ids.
        materials: [usize; 2],
        /// What the law's constructor said.
        error: ParameterError,
    },
}

impl core::fmt::Display for TableError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::MaterialOutOfRange { material } => {
                write!(f, "material {material} is past the material table")
            }
            Self::Pair { materials, error } => write!(
                f,
                "the law between materials {} and {}: {error}",
                materials[0], materials[1]
            ),
        }
    }
}

impl core::error::Error for TableError {}

impl<L: Law, const MATERIALS: usize> MaterialTable<L, MATERIALS> {
    /// Every pair of materials under the same law.
    pub fn uniform(law: L) -> Self {
        const {
            assert!(
                MATERIALS > 0,
                "a material table holds at least one material"
            )
        };
        Self {
            laws: [[law; MATERIALS]; MATERIALS],
        }
    }

    /// The table that `mixing` makes of `materials`: the law of materials `a` and `b` is
    /// `mixing.law(&materials[a], &materials[b])`.
    ///
    /// # Errors
    /// [`TableError::Pair`] for the first material whose own law refuses its properties (as
    /// the pair `[a, a]`), else the first pair in row order whose law refuses its mixed
    /// parameters.
    pub fn mixed<X: Mixing<L::Float, Law = L>>(
        mixing: &X,
        materials: &[X::Properties; MATERIALS],
    ) -> Result<Self, TableError> {
        let law = |a: usize, b: usize| {
            mixing
                .law(&materials[a], &materials[b])
                .map_err(|error| TableError::Pair {
                    materials: [a, b],
                    error,
                })
        };
        let mut table = Self::uniform(law(0, 0)?);
        // Each material against itself first, so that a bad property is reported as its own
        // material's, not as a mixed pair's (whose mean of it may not even be a number).
        for a in 0..MATERIALS {
            table.put(a, a, law(a, a)?);
        }
        for a in 0..MATERIALS {
            for b in a + 1..MATERIALS {
                table.put(a, b, law(a, b)?);
            }
        }
        Ok(table)
    }

    /// Gives the pair of materials `a` and `b` (in either order) its own law.
    ///
    /// # Errors
    /// [`TableError::MaterialOutOfRange`] for an id not below `MATERIALS`; the table is then
    /// unchanged.
    pub fn set(&mut self, a: usize, b: usize, law: L) -> Result<(), TableError> {
        for material in [a, b] {
            if material >= MATERIALS {
                return Err(TableError::MaterialOutOfRange { material });
            }
        }
        self.put(a, b, law);
        Ok(())
    }

    /// The law between materials `a` and `b`, `None` when either is not below `MATERIALS`.
    #[inline(always)]
    pub fn law(&self, a: usize, b: usize) -> Option<&L> {
        self.laws.get(a)?.get(b)
    }

    /// Every row of laws: row `a` holds material `a`'s law with each material.
    pub(crate) fn rows(&self) -> &[[L; MATERIALS]; MATERIALS] {
        &self.laws
    }

    fn put(&mut self, a: usize, b: usize, law: L) {
        self.laws[a][b] = law;
        self.laws[b][a] = law;
    }
}
