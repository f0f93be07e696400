//! The laws that store the tangential spring's displacement between steps: Models A, B, AA and
//! AA with Luding's reset. They share the update (rotate the stored displacement into the current
//! tangent plane, then add `v_t dt`) and differ in the sliding rule and in what they keep after
//! sliding.

use super::stored::{Keep, StoredSpring, stored_spring_model};
use super::{
    ContactState, Slide, TangentialInput, TangentialModel, TangentialOutput, TangentialParameters,
};
use crate::law::normal::NormalContact;
use crate::value::backend::MathBackend;
use crate::value::float::{Float, inverse_root};
use crate::value::vector::Vec3;

/// The stored tangential spring of one contact: the displacement `xi` of body j's contact point
/// relative to body i's, accumulated since first touch. 3 floats; the caller owns it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct SpringDisplacement<F> {
    /// The displacement `xi` (m), kept in the current tangent plane.
    pub displacement: Vec3<F>,
}

impl<F: Float> ContactState for SpringDisplacement<F> {
    #[inline(always)]
    fn is_finite(&self) -> bool {
        self.displacement.is_finite()
    }
    fn same_bits(&self, other: &Self) -> bool {
        self.displacement.same_bits(other.displacement)
    }
}

/// Turns a stored displacement into the tangent plane of the current normal `n`: removes its
/// normal component and restores its length, so a rolling pair neither tilts the spring out of
/// the plane nor shortens it. A displacement with no tangential part left (its squared length
/// below the smallest normal float) becomes zero.
#[inline(always)]
pub(crate) fn rotate_into_tangent_plane<F: Float, M: MathBackend<F>>(
    displacement: Vec3<F>,
    normal: Vec3<F>,
) -> Vec3<F> {
    let projected = displacement - normal * displacement.dot(normal);
    let projected_squared = projected.norm_squared();
    if projected_squared < F::MIN_POSITIVE {
        return Vec3::ZERO;
    }
    // One root of a ratio near 1: an approximate backend's root is at its best there, where the
    // product of two approximate roots would be off by their errors every step.
    projected * M::sqrt(displacement.norm_squared() / projected_squared)
}

/// The linear family's stored spring: the displacement `xi`, rotated into the current tangent
/// plane, then `xi += v_t dt`.
impl<F: Float> StoredSpring<F> for TangentialParameters<F> {
    type State = SpringDisplacement<F>;
    const NEEDS_CONTACT_RADIUS: bool = false;

    #[inline(always)]
    fn step<M: MathBackend<F>>(
        &self,
        state: &SpringDisplacement<F>,
        contact: &TangentialInput<F>,
        (slide, keep): (Slide, Keep),
        turned: Option<Vec3<F>>,
    ) -> TangentialOutput<F, SpringDisplacement<F>> {
        let turned = turned.unwrap_or_else(|| {
            rotate_into_tangent_plane::<F, M>(state.displacement, contact.normal)
        });
        let displacement = turned + contact.slip_velocity * contact.time_step;
        let (force, sliding) = self.slide::<M>(displacement, contact, slide);
        let kept = match keep {
            Keep::Capped if sliding => {
                let longest = self.limit(contact) / self.stiffness();
                let length_squared = displacement.norm_squared();
                if length_squared > longest * longest {
                    displacement * (longest * inverse_root::<F, M>(length_squared))
                } else {
                    displacement
                }
            }
            Keep::Luding if sliding => {
                -(force + contact.slip_velocity * self.dashpot(&contact.oscillator))
                    * (F::ONE / self.stiffness())
            }
            _ => displacement,
        };
        TangentialOutput {
            force,
            state: SpringDisplacement { displacement: kept },
            sliding,
        }
    }

    #[inline(always)]
    fn stored_vector(state: &SpringDisplacement<F>) -> Vec3<F> {
        state.displacement
    }

    fn stored_energy(&self, state: &SpringDisplacement<F>) -> F {
        F::HALF * self.stiffness() * state.displacement.norm_squared()
    }

    fn critical_spring_step(&self, design: &NormalContact<F>, tangential_mass: F) -> F {
        self.spring_critical_step(&design.oscillator, tangential_mass)
    }
}

/// Model A (Cundall & Strack 1979): a sliding contact pushes along the trial force, and the
/// stored displacement keeps growing while it slides. The oversized spring then throws a
/// rolling sphere backwards and exaggerates spin; shown here so that failure can be measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelA<F>(pub TangentialParameters<F>);

stored_spring_model!(ModelA(TangentialParameters) -> SpringDisplacement, Slide::AlongTrial, Keep::Everything);

/// Model B (Tsuji et al. 1992): a sliding contact pushes against the slip velocity, and the
/// stored displacement keeps growing while it slides. It locks at rigid-body rolling (5/7) at
/// small impact angles and misses the elastic recoil; shown so that failure can be measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelB<F>(pub TangentialParameters<F>);

stored_spring_model!(ModelB(TangentialParameters) -> SpringDisplacement, Slide::AgainstSlip, Keep::Everything);

/// Model AA (Elghannay & Tafti's proper implementation): Model A's sliding force, with the stored
/// displacement limited to `mu |F_n| / k_t` after every sliding step, as a deformation must be.
/// Reproduces the Kharaz oblique-impact data including the recoil dip near 20 degrees, and
/// rolling at 5/7 on a plate. This is the plain displacement cap; [`ModelAALuding`] is
/// Luding's variant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelAA<F>(pub TangentialParameters<F>);

stored_spring_model!(ModelAA(TangentialParameters) -> SpringDisplacement, Slide::AlongTrial, Keep::Capped);

/// Model AA with Luding's reset (Luding 2008; LAMMPS `gran/hooke/history`, `pair granular`
/// `linear_history`): Model A's sliding force, and after a sliding step the stored displacement
/// set so that spring plus dashpot equal the sliding force, `xi = -(F_t + eta_t v_t) / k_t`.
/// It differs from [`ModelAA`]'s plain cap through the dashpot term only, and equals it
/// without a tangential dashpot. It creates no kinetic energy, but with a strong tangential
/// dashpot the spring it keeps, `-eta_t v_t / k_t` in gross sliding, can store far more
/// energy than the cap allows (`host-tests/tests/properties.rs`, the energy search).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelAALuding<F>(pub TangentialParameters<F>);

stored_spring_model!(ModelAALuding(TangentialParameters) -> SpringDisplacement, Slide::AlongTrial, Keep::Luding);

#[cfg(test)]
mod tests {
    use super::rotate_into_tangent_plane;
    use crate::value::backend::Libm;
    use crate::value::vector::Vec3;

    #[test]
    fn a_spring_in_the_plane_keeps_its_length_down_to_the_smallest_normal_float() {
        let normal = Vec3::new(0.0, 0.0, 1.0);
        // A tangential part whose squared length is exactly the smallest normal float is a
        // spring; one float shorter it counts as none.
        let root = libm::sqrt(f64::MIN_POSITIVE);
        let kept = Vec3::new(root, 0.0, 1e-3);
        let turned = rotate_into_tangent_plane::<f64, Libm>(kept, normal);
        // Turned into the plane with its whole length.
        assert!(turned.x > 0.0 && turned.y == 0.0 && turned.z == 0.0);
        assert!(libm::fabs(turned.x / libm::sqrt(kept.norm_squared()) - 1.0) < 1e-12);
        let gone = Vec3::new(root.next_down(), 0.0, 1e-3);
        assert_eq!(
            rotate_into_tangent_plane::<f64, Libm>(gone, normal),
            Vec3::ZERO
        );
    }
}
