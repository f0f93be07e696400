//! What one contact evaluation gives: the forces and torques of a touching contact, or apart.

use crate::value::float::{Float, all_finite};
use crate::value::vector::Vec3;

/// The forces and torques of one touching contact. Forces act on body j; body i receives the
/// negative (action and reaction). For a sphere-wall contact the sphere is body i.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactForces<F> {
    /// Unit normal from i to j (for a wall: from the sphere into the wall).
    pub normal: Vec3<F>,
    /// Overlap `delta > 0` (m).
    pub overlap: F,
    /// Normal force on j along `normal` (N); positive pushes the bodies apart, negative is the
    /// dashpot's pull at the end of an unclamped contact.
    pub normal_force: F,
    /// Tangential force on j (N); `|tangential_force| <= mu |normal_force|`.
    pub tangential_force: Vec3<F>,
    /// Slip velocity of the contact point, j relative to i, in the tangent plane (m/s): `v_t =
    /// v_rel - (v_rel . n) n` with `v_rel = v_j - v_i - (a_i w_i + a_j w_j) x n` (no spin term for
    /// a [`NonRotating`](crate::NonRotating) law). Zero for a [`Frictionless`](crate::Frictionless)
    /// law, which does not compute it.
    pub slip_velocity: Vec3<F>,
    /// Torque on i about its centre (N m): `-a_i n x F_t`.
    pub torque_on_i: Vec3<F>,
    /// Torque on j about its centre (N m): `-a_j n x F_t` (zero for a wall).
    pub torque_on_j: Vec3<F>,
    /// True when the tangential force was at the Coulomb limit this step.
    pub sliding: bool,
}

impl<F: Float> ContactForces<F> {
    /// Total contact force on body j.
    #[inline(always)]
    pub fn force_on_j(&self) -> Vec3<F> {
        self.normal * self.normal_force + self.tangential_force
    }

    /// Total contact force on body i (exactly the negative of [`ContactForces::force_on_j`]).
    #[inline(always)]
    pub fn force_on_i(&self) -> Vec3<F> {
        -self.force_on_j()
    }

    /// The sum of every number [`ContactForces::is_finite`] tests, in pairs: finite only when
    /// each of them is (a NaN or an infinity stays in any sum), so a chunk's contacts are tested
    /// by summing their probes once. A finite-valued sum can still overflow; its caller then
    /// re-runs the contacts checked.
    #[inline(always)]
    pub(crate) fn finite_probe(&self) -> F {
        let (t, s, a, b) = (
            self.tangential_force,
            self.slip_velocity,
            self.torque_on_i,
            self.torque_on_j,
        );
        let v = (t + s) + (a + b);
        (v.x + v.y) + (v.z + self.normal_force)
    }

    #[inline(always)]
    pub(crate) fn is_finite(&self) -> bool {
        let (t, s, a, b) = (
            self.tangential_force,
            self.slip_velocity,
            self.torque_on_i,
            self.torque_on_j,
        );
        all_finite([
            self.normal_force,
            t.x,
            t.y,
            t.z,
            s.x,
            s.y,
            s.z,
            a.x,
            a.y,
            a.z,
            b.x,
            b.y,
            b.z,
        ])
    }
}

/// The outcome of evaluating a pair.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Interaction<F> {
    /// The bodies do not overlap. Their per-contact state has been reset for the next contact.
    Apart,
    /// The bodies overlap and push on each other.
    Touching(ContactForces<F>),
}

impl<F> Interaction<F> {
    /// The forces, when touching.
    pub fn forces(&self) -> Option<&ContactForces<F>> {
        match self {
            Self::Apart => None,
            Self::Touching(forces) => Some(forces),
        }
    }
}
