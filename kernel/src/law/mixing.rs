//! Mixing rules: the law of a contact between two materials from each material's properties
//! (`docs/physics.md`, section 3.5).
//!
//! The rules are LAMMPS `pair granular`'s: Hertz's effective moduli `E*` and `G*` from each
//! body's `E` and `nu` (physics, not a convention), and the geometric mean `sqrt(x_i x_j)` of
//! every other coefficient (stiffness, restitution, dashpot ratio, friction). Two bodies of one
//! material get that material's own values. A [`MaterialTable`](crate::MaterialTable) applies
//! a rule to every pair and lets any pair be given its own law instead.

use core::marker::PhantomData;

use crate::law::contact_law::ContactLaw;
use crate::law::engine::Law;
use crate::law::normal::{Hertz, HertzImpact, LinearSpringDashpot};
use crate::law::tangential::{MindlinParameters, TangentialModel, TangentialParameters};
use crate::value::backend::MathBackend;
use crate::value::error::ParameterError;
use crate::value::float::Float;
use crate::value::material::Material;

/// How a [`MaterialTable`](crate::MaterialTable) makes the law of a pair of materials from
/// their properties. Every pair gets a law of one type ([`Mixing::Law`]), so one table holds
/// one family of laws with parameters per pair.
pub trait Mixing<F: Float>: Copy + core::fmt::Debug {
    /// What each material is described by.
    type Properties: Copy + core::fmt::Debug + PartialEq;
    /// The law every pair gets.
    type Law: Law<Float = F>;

    /// The law between bodies of materials `i` and `j`; symmetric in `i` and `j`.
    ///
    /// # Errors
    /// The law's constructor's [`ParameterError`] for properties it refuses.
    fn law(&self, i: &Self::Properties, j: &Self::Properties) -> Result<Self::Law, ParameterError>;
}

/// `sqrt(a b)`, exactly `a` when `a == b` (so a material against itself keeps its own value),
/// symmetric bit for bit.
fn geometric_mean<F: Float>(a: F, b: F) -> F {
    if a == b {
        a
    } else {
        F::DefaultBackend::sqrt(a * b)
    }
}

/// A material of the linear laws: the coefficients of a [`LinearSpringDashpot`] and of
/// [`TangentialParameters`] that the contact of two bodies of this material would have.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearMaterial<F> {
    /// Normal stiffness `k_n` (N/m).
    pub normal_stiffness: F,
    /// Coefficient of restitution `e`.
    pub restitution: F,
    /// Tangential stiffness `k_t` (N/m).
    pub tangential_stiffness: F,
    /// Dashpot ratio `eta_t / eta_n`.
    pub dashpot_ratio: F,
    /// Coulomb friction coefficient `mu`.
    pub friction: F,
}

/// The linear laws' mixing rule: every coefficient of a [`LinearMaterial`] by its geometric
/// mean, into a linear spring-dashpot and the tangential law `T` (built by `tangential`, for
/// example `ModelAA` or `Stateless`: a tuple struct's name is its constructor).
///
/// ```
/// use soft_sphere::prelude::{LinearMaterial, LinearMixing, Mixing, ModelAA};
/// let glass = LinearMaterial {
///     normal_stiffness: 1.0e4_f64, restitution: 0.9, tangential_stiffness: 8.0e3,
///     dashpot_ratio: 0.5, friction: 0.4,
/// };
/// let rubber = LinearMaterial { normal_stiffness: 1.0e2, friction: 0.9, ..glass };
/// let law = LinearMixing::new(ModelAA).law(&glass, &rubber).unwrap();
/// assert!((law.normal().stiffness() - 1.0e3).abs() < 1e-9); // sqrt(1e4 * 1e2)
/// assert!((law.tangential().0.friction() - 0.6).abs() < 1e-12); // sqrt(0.4 * 0.9)
/// ```
#[derive(Clone, Copy, Debug)]
pub struct LinearMixing<F: Float, T, M = <F as Float>::DefaultBackend> {
    tangential: fn(TangentialParameters<F>) -> T,
    backend: PhantomData<fn() -> M>,
}

impl<F: Float, T> LinearMixing<F, T> {
    /// The rule, with the tangential law built by `tangential`.
    pub fn new(tangential: fn(TangentialParameters<F>) -> T) -> Self {
        Self {
            tangential,
            backend: PhantomData,
        }
    }
}

impl<F: Float, T, M> LinearMixing<F, T, M> {
    /// The same rule, its laws computing with backend `B` (see
    /// [`ContactLaw::with_backend`]).
    pub fn with_backend<B: MathBackend<F>>(self) -> LinearMixing<F, T, B> {
        LinearMixing {
            tangential: self.tangential,
            backend: PhantomData,
        }
    }
}

impl<F: Float, T: TangentialModel<F>, M: MathBackend<F>> Mixing<F> for LinearMixing<F, T, M> {
    type Properties = LinearMaterial<F>;
    type Law = ContactLaw<F, LinearSpringDashpot<F>, T, M>;

    fn law(
        &self,
        i: &LinearMaterial<F>,
        j: &LinearMaterial<F>,
    ) -> Result<Self::Law, ParameterError> {
        let mix = |select: fn(&LinearMaterial<F>) -> F| geometric_mean(select(i), select(j));
        let normal = LinearSpringDashpot::new(mix(|m| m.normal_stiffness), mix(|m| m.restitution))?;
        let tangential = TangentialParameters::new(
            mix(|m| m.tangential_stiffness),
            mix(|m| m.dashpot_ratio),
            mix(|m| m.friction),
        )?;
        Ok(ContactLaw::new(normal, (self.tangential)(tangential)).with_backend())
    }
}

/// A material of the Hertz-Mindlin laws: its elasticity, and the restitution, dashpot ratio and
/// friction that the contact of two bodies of this material would have.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElasticMaterial<F> {
    /// Young's modulus and Poisson's ratio.
    pub elasticity: Material<F>,
    /// Coefficient of restitution `e`.
    pub restitution: F,
    /// Dashpot ratio `eta_t / eta_n`.
    pub dashpot_ratio: F,
    /// Coulomb friction coefficient `mu`.
    pub friction: F,
}

/// The Hertz-Mindlin laws' mixing rule: `E*` and `G*` from both bodies' elasticity (Hertz and
/// Mindlin), the other coefficients by their geometric mean, into a [`Hertz`] normal law
/// declared for impacts up to `largest` and the tangential law `T` (built by `tangential`, for
/// example `MindlinAA`).
///
/// ```
/// use soft_sphere::prelude::{
///     ElasticMaterial, HertzImpact, HertzMixing, Material, MindlinAA, Mixing,
/// };
/// let steel = ElasticMaterial {
///     elasticity: Material::new(208.0e9_f64, 0.3).unwrap(),
///     restitution: 0.9, dashpot_ratio: 0.0, friction: 0.3,
/// };
/// let glass = ElasticMaterial { elasticity: Material::new(63.0e9, 0.2).unwrap(), ..steel };
/// let largest = HertzImpact { speed: 2.0, effective_radius: 1.0e-3 };
/// let law = HertzMixing::new(largest, MindlinAA).law(&steel, &glass).unwrap();
/// let e_star = steel.elasticity.effective_modulus(&glass.elasticity);
/// assert_eq!(law.normal().effective_modulus(), e_star);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct HertzMixing<F: Float, T, M = <F as Float>::DefaultBackend> {
    largest: HertzImpact<F>,
    tangential: fn(MindlinParameters<F>) -> T,
    backend: PhantomData<fn() -> M>,
}

impl<F: Float, T> HertzMixing<F, T> {
    /// The rule, with every pair's Hertz law declared for impacts up to `largest` and the
    /// tangential law built by `tangential`.
    pub fn new(largest: HertzImpact<F>, tangential: fn(MindlinParameters<F>) -> T) -> Self {
        Self {
            largest,
            tangential,
            backend: PhantomData,
        }
    }
}

impl<F: Float, T, M> HertzMixing<F, T, M> {
    /// The same rule, its laws computing with backend `B` (see
    /// [`ContactLaw::with_backend`]).
    pub fn with_backend<B: MathBackend<F>>(self) -> HertzMixing<F, T, B> {
        HertzMixing {
            largest: self.largest,
            tangential: self.tangential,
            backend: PhantomData,
        }
    }
}

impl<F: Float, T: TangentialModel<F>, M: MathBackend<F>> Mixing<F> for HertzMixing<F, T, M> {
    type Properties = ElasticMaterial<F>;
    type Law = ContactLaw<F, Hertz<F>, T, M>;

    fn law(
        &self,
        i: &ElasticMaterial<F>,
        j: &ElasticMaterial<F>,
    ) -> Result<Self::Law, ParameterError> {
        let mix = |select: fn(&ElasticMaterial<F>) -> F| geometric_mean(select(i), select(j));
        let (a, b) = (&i.elasticity, &j.elasticity);
        let normal = Hertz::new(a.effective_modulus(b), mix(|m| m.restitution), self.largest)?;
        let tangential = MindlinParameters::new(
            a.effective_shear_modulus(b),
            mix(|m| m.dashpot_ratio),
            mix(|m| m.friction),
        )?;
        Ok(ContactLaw::new(normal, (self.tangential)(tangential)).with_backend())
    }
}
