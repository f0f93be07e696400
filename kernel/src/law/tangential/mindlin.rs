//! The tangential laws under a [`Hertz`](crate::Hertz) contact: Mindlin's no-slip stiffness
//! `k_t = 8 G* a`, which grows with the contact radius `a`, with Model AA's slider.
//!
//! The stored laws keep the spring's force, not its displacement, and update it by increments,
//! `F_s += -k_t(a) v_t dt`, rescaling it by `a / a_prev` when the contact unloads (Thornton et
//! al. 2013; LAMMPS `mindlin_rescale/force`). Of the ways to let `k_t` follow the overlap this is
//! the one that creates no energy: with a stored displacement (`F_s = -k_t(a) xi`, LAMMPS
//! `mindlin`) loading at a fixed displacement stiffens the spring for free, and a spring loaded at
//! a small contact and released at a large one gives back more work than it took
//! (`docs/physics.md`, section 3.2; the energy test in `host-tests/tests/hertz.rs`).

use super::stored::{Keep, StoredSpring, stored_spring_model};
use super::{
    ContactState, Slide, TangentialInput, TangentialModel, TangentialOutput, coulomb,
    rotate_into_tangent_plane, spring_critical_step,
};
use crate::law::normal::{NormalContact, NormalOscillator};
use crate::value::backend::MathBackend;
use crate::value::error::{Parameter, ParameterError, non_negative, positive};
use crate::value::float::{Float, inverse_root};
use crate::value::vector::Vec3;

/// Mindlin's shear modulus, dashpot and friction, shared by the Mindlin laws.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MindlinParameters<F> {
    shear_modulus: F,
    dashpot_ratio: F,
    friction: F,
}

impl<F: Float> MindlinParameters<F> {
    /// Effective shear modulus `G*` (Pa; [`Material`](crate::Material) computes it), the dashpot
    /// ratio `r = eta_t / eta_n` and the Coulomb coefficient `mu`.
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for any non-finite value, [`ParameterError::NotPositive`]
    /// for `G* <= 0`, [`ParameterError::Negative`] for a negative dashpot ratio or `mu`.
    pub fn new(shear_modulus: F, dashpot_ratio: F, friction: F) -> Result<Self, ParameterError> {
        Ok(Self {
            shear_modulus: positive(shear_modulus, Parameter::Modulus)?,
            dashpot_ratio: non_negative(dashpot_ratio, Parameter::DashpotRatio)?,
            friction: non_negative(friction, Parameter::Friction)?,
        })
    }

    /// Effective shear modulus `G*` (Pa).
    pub fn shear_modulus(&self) -> F {
        self.shear_modulus
    }

    /// The dashpot ratio `eta_t / eta_n`.
    pub fn dashpot_ratio(&self) -> F {
        self.dashpot_ratio
    }

    /// Coulomb friction coefficient `mu`.
    pub fn friction(&self) -> F {
        self.friction
    }

    /// Mindlin's no-slip stiffness `k_t = 8 G* a` at contact radius `a`.
    #[inline(always)]
    pub fn stiffness(&self, contact_radius: F) -> F {
        F::from_f64(8.0) * self.shear_modulus * contact_radius
    }

    #[inline(always)]
    pub(super) fn dashpot(&self, oscillator: &NormalOscillator<F>) -> F {
        self.dashpot_ratio * oscillator.damping_coefficient
    }

    #[inline(always)]
    pub(super) fn limit(&self, contact: &TangentialInput<F>) -> F {
        self.friction * contact.normal_force.abs()
    }

    pub(super) fn critical_step(&self, design: &NormalContact<F>, mass: F) -> F {
        let stiffness = self.stiffness(design.contact_radius);
        spring_critical_step(stiffness, self.dashpot(&design.oscillator), mass)
    }
}

/// The stored Mindlin spring of one contact: the spring's force and the contact radius it was
/// last updated at. 4 floats; the caller owns it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct MindlinSpring<F> {
    /// The spring's force on body j (N), kept in the current tangent plane (the tangential
    /// force without its dashpot).
    pub force: Vec3<F>,
    /// The contact radius `a` (m) at the last update.
    pub contact_radius: F,
}

impl<F: Float> ContactState for MindlinSpring<F> {
    #[inline(always)]
    fn is_finite(&self) -> bool {
        self.force.is_finite() && self.contact_radius.is_finite()
    }
    fn same_bits(&self, other: &Self) -> bool {
        self.force.same_bits(other.force)
            && self.contact_radius.to_bits_u64() == other.contact_radius.to_bits_u64()
    }
}

/// Hertz's stored spring: Mindlin's force and the contact radius it was last updated at, rotated
/// into the current tangent plane, rescaled on unloading, then `F_s += -k_t(a) v_t dt`.
impl<F: Float> StoredSpring<F> for MindlinParameters<F> {
    type State = MindlinSpring<F>;
    const NEEDS_CONTACT_RADIUS: bool = true;

    #[inline(always)]
    fn step<M: MathBackend<F>>(
        &self,
        state: &MindlinSpring<F>,
        contact: &TangentialInput<F>,
        (slide, keep): (Slide, Keep),
        turned: Option<Vec3<F>>,
    ) -> TangentialOutput<F, MindlinSpring<F>> {
        let radius = contact.contact_radius;
        let rotated = turned
            .unwrap_or_else(|| rotate_into_tangent_plane::<F, M>(state.force, contact.normal));
        // Unloading shrinks the spring with the contact (`a < a_prev`); loading does not grow it.
        let unloaded = if radius < state.contact_radius {
            rotated * (radius / state.contact_radius)
        } else {
            rotated
        };
        let stiffness = self.stiffness(radius);
        let spring = unloaded - contact.slip_velocity * (stiffness * contact.time_step);
        let dashpot = contact.slip_velocity * self.dashpot(&contact.oscillator);
        let limit = self.limit(contact);
        let (force, sliding) =
            coulomb::<F, M>(spring - dashpot, contact.slip_velocity, limit, slide);
        let kept = match keep {
            Keep::Capped if sliding => {
                let length_squared = spring.norm_squared();
                if length_squared > limit * limit {
                    spring * (limit * inverse_root::<F, M>(length_squared))
                } else {
                    spring
                }
            }
            Keep::Luding if sliding => force + dashpot,
            _ => spring,
        };
        TangentialOutput {
            force,
            state: MindlinSpring {
                force: kept,
                contact_radius: radius,
            },
            sliding,
        }
    }

    #[inline(always)]
    fn stored_vector(state: &MindlinSpring<F>) -> Vec3<F> {
        state.force
    }

    fn stored_energy(&self, state: &MindlinSpring<F>) -> F {
        let stiffness = self.stiffness(state.contact_radius);
        if stiffness > F::ZERO {
            state.force.norm_squared() / (F::TWO * stiffness)
        } else {
            F::ZERO
        }
    }

    fn critical_spring_step(&self, design: &NormalContact<F>, tangential_mass: F) -> F {
        self.critical_step(design, tangential_mass)
    }
}

/// Hertz-Mindlin with Model AA's plain cap: Mindlin's spring `k_t = 8 G* a`, stored as a force
/// and rescaled on unloading, the sliding force along the trial force, and the stored spring
/// limited to `mu |F_n|` after every sliding step. The Hertz counterpart of
/// [`ModelAA`](crate::ModelAA).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MindlinAA<F>(pub MindlinParameters<F>);

stored_spring_model!(MindlinAA(MindlinParameters) -> MindlinSpring, Slide::AlongTrial, Keep::Capped);

/// Hertz-Mindlin with Luding's reset: as [`MindlinAA`], but after a sliding step the stored
/// spring is set so that spring plus dashpot equal the sliding force (LAMMPS `pair granular
/// tangential mindlin_rescale/force`). The Hertz counterpart of
/// [`ModelAALuding`](crate::ModelAALuding).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MindlinAALuding<F>(pub MindlinParameters<F>);

stored_spring_model!(MindlinAALuding(MindlinParameters) -> MindlinSpring, Slide::AlongTrial, Keep::Luding);

/// The stateless law under Hertz: `xi = v_t t_e` with Mindlin's stiffness at the current contact
/// radius, then Model AA's limit and sliding rule. Stores nothing. `t_e` comes from the contact's
/// oscillator linearised at the current overlap (as [`Stateless`](super::Stateless)'s does), an
/// estimate for a contact that stiffens as it loads.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MindlinStateless<F>(pub MindlinParameters<F>);

impl<F: Float> TangentialModel<F> for MindlinStateless<F> {
    type State = ();
    const NEEDS_CONTACT_RADIUS: bool = true;

    #[inline(always)]
    fn force<M: MathBackend<F>>(
        &self,
        _: &(),
        contact: &TangentialInput<F>,
    ) -> TangentialOutput<F, ()> {
        let elapsed = super::elapsed_contact_time::<F, M>(
            contact.overlap,
            contact.approach_rate,
            &contact.oscillator,
        );
        let stiffness = self.0.stiffness(contact.contact_radius);
        let trial =
            contact.slip_velocity * -(stiffness * elapsed + self.0.dashpot(&contact.oscillator));
        let (force, sliding) = coulomb::<F, M>(
            trial,
            contact.slip_velocity,
            self.0.limit(contact),
            Slide::AlongTrial,
        );
        TangentialOutput {
            force,
            state: (),
            sliding,
        }
    }

    /// As [`Stateless`](crate::Stateless): a dashpot of strength `k_t t_e + eta_t` at the
    /// stiffest contact, with `t_e` at most `pi / wd`.
    fn critical_time_step(&self, design: &NormalContact<F>, tangential_mass: F) -> F {
        let oscillator = &design.oscillator;
        super::stateless::stateless_critical_step(
            self.0.stiffness(design.contact_radius),
            self.0.dashpot(oscillator),
            oscillator,
            tangential_mass,
        )
    }
}
