//! Elastic materials, and the effective moduli of a contact between two of them (Hertz, Mindlin).

use crate::value::error::{Parameter, ParameterError, positive};
use crate::value::float::Float;

/// An isotropic elastic material: Young's modulus `E` and Poisson's ratio `nu`.
///
/// ```
/// use soft_sphere::prelude::Material;
/// let steel = Material::new(208.0e9_f64, 0.3).unwrap();
/// // E* = E / (2 (1 - nu^2)) between two steel spheres, E / (1 - nu^2) against a rigid wall.
/// assert!((steel.effective_modulus(&steel) - 114.29e9).abs() < 0.01e9);
/// assert!((steel.modulus_against_rigid() - 228.57e9).abs() < 0.01e9);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material<F> {
    youngs_modulus: F,
    poisson_ratio: F,
}

impl<F: Float> Material<F> {
    /// A material of Young's modulus `E` (Pa) and Poisson's ratio `nu`.
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] / [`ParameterError::NotPositive`] for `E`;
    /// [`ParameterError::NonFinite`] or [`ParameterError::PoissonRatioOutOfRange`] for `nu`
    /// outside `(-1, 0.5]`.
    pub fn new(youngs_modulus: F, poisson_ratio: F) -> Result<Self, ParameterError> {
        let youngs_modulus = positive(youngs_modulus, Parameter::Modulus)?;
        if !poisson_ratio.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::PoissonRatio));
        }
        if !(poisson_ratio > -F::ONE && poisson_ratio <= F::HALF) {
            return Err(ParameterError::PoissonRatioOutOfRange);
        }
        Ok(Self {
            youngs_modulus,
            poisson_ratio,
        })
    }

    /// Young's modulus `E` (Pa).
    pub fn youngs_modulus(&self) -> F {
        self.youngs_modulus
    }

    /// Poisson's ratio `nu`.
    pub fn poisson_ratio(&self) -> F {
        self.poisson_ratio
    }

    /// Shear modulus `G = E / (2 (1 + nu))` (Pa).
    pub fn shear_modulus(&self) -> F {
        self.youngs_modulus / (F::TWO * (F::ONE + self.poisson_ratio))
    }

    /// `(1 - nu^2) / E`, this body's share of `1 / E*`.
    fn normal_compliance(&self) -> F {
        (F::ONE - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus
    }

    /// `(2 - nu) / G`, this body's share of `1 / G*`.
    fn shear_compliance(&self) -> F {
        (F::TWO - self.poisson_ratio) / self.shear_modulus()
    }

    /// Hertz's effective modulus of a contact with `other`:
    /// `1 / E* = (1 - nu_i^2) / E_i + (1 - nu_j^2) / E_j`.
    pub fn effective_modulus(&self, other: &Self) -> F {
        F::ONE / (self.normal_compliance() + other.normal_compliance())
    }

    /// `E*` against a rigid body (a wall): `E / (1 - nu^2)`.
    pub fn modulus_against_rigid(&self) -> F {
        F::ONE / self.normal_compliance()
    }

    /// Mindlin's effective shear modulus of a contact with `other`:
    /// `1 / G* = (2 - nu_i) / G_i + (2 - nu_j) / G_j`.
    pub fn effective_shear_modulus(&self, other: &Self) -> F {
        F::ONE / (self.shear_compliance() + other.shear_compliance())
    }

    /// `G*` against a rigid body (a wall): `G / (2 - nu)`.
    pub fn shear_modulus_against_rigid(&self) -> F {
        F::ONE / self.shear_compliance()
    }
}
