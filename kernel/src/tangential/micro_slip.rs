//! Micro-slip under a [`Hertz`](crate::Hertz) contact: Mindlin & Deresiewicz's tangential
//! contact, computed by Popov & Heß's method of dimensionality reduction (MDR).
//!
//! The axisymmetric contact becomes a bed of independent springs along a line, on the profile
//! `g(x) = x^2 / R*`. The spring at `x` presses with `E* (delta - g(x)) dx` (their sum is Hertz's
//! `(4/3) E* a delta`), shears with stiffness `8 G* dx` for both sides of the line (their sum is
//! Mindlin's `8 G* a`) and slips on its own once its shear reaches `mu` times its press. A spring
//! that comes into contact starts free of shear (Maw, Barber & Fawcett 1976); one that leaves
//! takes its shear with it. The law is exact for Cattaneo & Mindlin's loading and Mindlin &
//! Deresiewicz's unloading and reloading as the springs get finer (`docs/physics.md`, section
//! 3.3).
//!
//! The line `[0, s]` is cut into `SPRINGS` equal cells, `s` the largest contact radius the law is
//! declared for ([`Hertz::largest_contact_radius`](crate::Hertz::largest_contact_radius)). Each
//! cell keeps one displacement, the mean over its part of the contact; a cell the contact edge
//! crosses counts only its covered part, so the stuck stiffness and the sum of the slip limits
//! are exact at any spring count. A contact wider than `s` gives the rim to the last cell, which
//! widens to cover it: still Coulomb's limit and Mindlin's stiffness, with coarser micro-slip.

use super::{
    ContactState, MindlinParameters, Slide, TangentialInput, TangentialModel, TangentialOutput,
    coulomb,
};
use crate::backend::MathBackend;
use crate::error::{Parameter, ParameterError, positive};
use crate::float::Float;
use crate::normal::NormalContact;
use crate::vector::Vec3;

/// The springs of one micro-slip contact: each cell's displacement, and the normal and contact
/// radius they were last updated at. `3 SPRINGS + 4` floats; the caller owns it.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C)]
pub struct MicroSlipSprings<F, const SPRINGS: usize> {
    /// The unit normal at the last update (zero before first touch).
    pub normal: Vec3<F>,
    /// The contact radius `a` (m) at the last update.
    pub contact_radius: F,
    /// Each cell's tangential displacement (m), j relative to i, in the tangent plane of
    /// `normal`; the cell's shear force on j is `-8 G* L u`, `L` its covered length.
    pub displacements: [Vec3<F>; SPRINGS],
}

impl<F: Float, const SPRINGS: usize> Default for MicroSlipSprings<F, SPRINGS> {
    fn default() -> Self {
        Self {
            normal: Vec3::ZERO,
            contact_radius: F::ZERO,
            displacements: [Vec3::ZERO; SPRINGS],
        }
    }
}

impl<F: Float, const SPRINGS: usize> ContactState for MicroSlipSprings<F, SPRINGS> {
    fn is_finite(&self) -> bool {
        self.normal.is_finite()
            && self.contact_radius.is_finite()
            && self.displacements.iter().all(|u| u.is_finite())
    }
    fn same_bits(&self, other: &Self) -> bool {
        self.normal.same_bits(other.normal)
            && self.contact_radius.to_bits_u64() == other.contact_radius.to_bits_u64()
            && (self.displacements.iter())
                .zip(other.displacements.iter())
                .all(|(a, b)| a.same_bits(*b))
    }
}

/// Hertz-Mindlin with micro-slip (Mindlin & Deresiewicz 1953), `SPRINGS` cells across the
/// largest contact radius.
///
/// The tangential dashpot `eta_t = r eta_n` acts on the whole contact, and the total is held to
/// `mu |F_n|` along its own direction, as in [`MindlinAA`](crate::MindlinAA). Each cell's slip
/// limit is its share of `mu |F_n|` in proportion to its share of Hertz's pressure, so the limits
/// sum to Coulomb's with the normal dashpot included.
///
/// ```
/// use soft_sphere::{ContactLaw, Hertz, HertzImpact, Material, MicroSlip, MindlinParameters};
/// let steel = Material::new(2.08e11_f64, 0.3).unwrap();
/// let largest = HertzImpact { speed: 5.0, effective_radius: 0.01 };
/// let normal = Hertz::new(steel.modulus_against_rigid(), 1.0, largest).unwrap();
/// let mass = 0.0329; // a 10 mm steel sphere
/// let span = normal.largest_contact_radius(mass);
/// let mindlin = MindlinParameters::new(steel.shear_modulus_against_rigid(), 0.0, 0.3).unwrap();
/// let law = ContactLaw::new(normal, MicroSlip::<f64, 16>::new(mindlin, span).unwrap());
/// // sqrt(R* delta) at the peak overlap delta = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5): 0.8 mm.
/// assert!((span - 8.05e-4).abs() < 0.01e-4);
/// # let _ = law;
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MicroSlip<F, const SPRINGS: usize> {
    parameters: MindlinParameters<F>,
    cell: F,
}

impl<F: Float, const SPRINGS: usize> MicroSlip<F, SPRINGS> {
    /// Mindlin's parameters, with the springs spread over contact radii up to
    /// `largest_contact_radius` (m).
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] / [`ParameterError::NotPositive`] for the radius
    /// ([`Parameter::Radius`]).
    pub fn new(
        parameters: MindlinParameters<F>,
        largest_contact_radius: F,
    ) -> Result<Self, ParameterError> {
        const { assert!(SPRINGS > 0, "a micro-slip bed needs at least one spring") };
        let span = positive(largest_contact_radius, Parameter::Radius)?;
        Ok(Self {
            parameters,
            cell: span / F::from_f64(SPRINGS as f64),
        })
    }

    /// Mindlin's parameters.
    pub fn parameters(&self) -> &MindlinParameters<F> {
        &self.parameters
    }

    /// The contact radius the springs span (m); past it the last cell widens.
    pub fn largest_contact_radius(&self) -> F {
        self.cell * F::from_f64(SPRINGS as f64)
    }

    /// Where cell `i` ends (m); the last cell has no end.
    #[inline(always)]
    fn cell_end(&self, i: usize) -> F {
        if i + 1 == SPRINGS {
            F::INFINITY
        } else {
            self.cell * F::from_f64((i + 1) as f64)
        }
    }

    /// How much of cell `i` a contact of radius `radius` covers (m).
    #[inline(always)]
    fn covered(&self, i: usize, radius: F) -> F {
        let start = self.cell * F::from_f64(i as f64);
        self.cell_end(i).min_of(radius) - start.min_of(radius)
    }
}

/// The share of Hertz's pressure between the centre and `t = x / a` of the contact radius:
/// `(3/2) (t - t^3 / 3)`, from `int (delta - g(x)) dx` over `int_0^a (delta - g(x)) dx`.
#[inline(always)]
fn pressure_share<F: Float>(t: F) -> F {
    F::from_f64(1.5) * t - F::HALF * t * t * t
}

impl<F: Float, const SPRINGS: usize> TangentialModel<F> for MicroSlip<F, SPRINGS> {
    type State = MicroSlipSprings<F, SPRINGS>;
    const NEEDS_CONTACT_RADIUS: bool = true;
    // Each cell branches on its own slip: the springs run one after another, and the lanes of a
    // block one at a time.
    const VECTORISES: bool = false;

    fn force<M: MathBackend<F>>(
        &self,
        state: &Self::State,
        contact: &TangentialInput<F>,
    ) -> TangentialOutput<F, Self::State> {
        let radius = contact.contact_radius;
        let before = state.contact_radius;
        // The smallest rotation taking the last normal to this one, applied to every cell:
        // `R u = c u + w x u + w (w . u) / (1 + c)`, `c` the cosine and `w` the cross product.
        let n = contact.normal;
        let cosine = state.normal.dot(n);
        let axis = state.normal.cross(n);
        let turned = F::ONE + cosine;
        // Before first touch (no normal yet) or on a reversed normal, no spring survives.
        let keep = turned > F::MIN_POSITIVE;
        let inverse_turned = if keep { F::ONE / turned } else { F::ZERO };

        let limit = self.parameters.limit(contact);
        let step = contact.slip_velocity * contact.time_step;
        let inverse_radius = F::ONE / radius;

        let mut next = Self::State {
            normal: n,
            contact_radius: radius,
            displacements: [Vec3::ZERO; SPRINGS],
        };
        let mut spring_force = Vec3::ZERO;
        let mut every_cell_slid = true;
        let mut share_below = F::ZERO;
        for (i, kept) in next.displacements.iter_mut().enumerate() {
            let covered = self.covered(i, radius);
            // Cells are in order from the centre: past the contact's edge every one is empty.
            if covered <= F::ZERO {
                break;
            }
            let share_above = pressure_share((self.cell_end(i) * inverse_radius).min_of(F::ONE));
            let share = share_above - share_below;
            share_below = share_above;
            let old = state.displacements[i];
            let mut u = if keep {
                old * cosine + axis.cross(old) + axis * (axis.dot(old) * inverse_turned)
            } else {
                Vec3::ZERO
            };
            // New contact area is laid down free of shear: a growing cell's mean thins.
            let was = self.covered(i, before);
            if covered > was {
                u = u * (was / covered);
            }
            u += step;
            let mut force = u * -self.parameters.stiffness(covered);
            let cell_limit = limit * share;
            let force_squared = force.norm_squared();
            if force_squared > cell_limit * cell_limit {
                let scale = cell_limit * M::inv_sqrt(force_squared);
                force = force * scale;
                u = u * scale;
            } else {
                every_cell_slid = false;
            }
            *kept = u;
            spring_force += force;
        }
        let dashpot = contact.slip_velocity * self.parameters.dashpot(&contact.oscillator);
        let (force, capped) = coulomb::<F, M>(
            spring_force - dashpot,
            contact.slip_velocity,
            limit,
            Slide::AlongTrial,
        );
        TangentialOutput {
            force,
            state: next,
            sliding: capped || every_cell_slid,
        }
    }

    /// `sum 8 G* L |u|^2 / 2` over the cells, at the state's contact radius.
    fn stored_energy(&self, state: &Self::State) -> F {
        state
            .displacements
            .iter()
            .enumerate()
            .fold(F::ZERO, |sum, (i, u)| {
                sum + self
                    .parameters
                    .stiffness(self.covered(i, state.contact_radius))
                    * u.norm_squared()
                    * F::HALF
            })
    }

    /// Mindlin's no-slip stiffness at the stiffest contact: the springs never exceed it.
    fn critical_time_step(&self, design: &NormalContact<F>, tangential_mass: F) -> F {
        self.parameters.critical_step(design, tangential_mass)
    }
}
