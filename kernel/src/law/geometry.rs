//! Contact geometry and kinematics: normal, overlap, lever arms and the bodies'
//! velocities, for sphere-sphere and sphere-wall contacts.

use crate::value::backend::MathBackend;
use crate::value::body::Sphere;
use crate::value::error::ContactError;
use crate::value::float::Float;
use crate::value::vector::Vec3;
use crate::value::wall::Wall;

/// The lever arm from a sphere's centre to the contact point, used for both the slip velocity and
/// the torque (the same arm in both keeps the contact energetically passive).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LeverArm {
    /// The radius `R` (rigid-body theory, Elghannay & Tafti, LAMMPS `gran/hooke`). The default.
    #[default]
    Radius,
    /// The distance from the centre to the contact plane: the plane of the two spheres'
    /// intersection circle, `(d^2 + R_i^2 - R_j^2) / (2 d)`, or, for a wall, the distance to the
    /// wall, `R - delta` (as MFiX does). Shorter than `R` by about the overlap; with very soft
    /// springs that changes small-angle oblique impacts markedly.
    ContactPlane,
}

/// One touching contact, seen from body i towards body j (for a wall, j is the wall).
#[derive(Clone, Copy, Debug)]
pub(crate) struct ContactFrame<F> {
    pub normal: Vec3<F>,
    pub overlap: F,
    /// `R* = R_i R_j / (R_i + R_j)`, or `R` against a wall. Only a Hertz law reads it; for the
    /// others the division is dead code and is removed.
    pub effective_radius: F,
    pub arm_i: F,
    pub arm_j: F,
    /// Translational velocity of j relative to i.
    pub velocity: Vec3<F>,
    pub angular_velocity_i: Vec3<F>,
    pub angular_velocity_j: Vec3<F>,
}

/// Where two checked spheres stand before any root is taken: the offset from i to j, its squared
/// length and the sum of the radii. Both the one-contact path and the list seam's sift classify
/// a pair by it, so they agree on where contact begins.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Separation<F> {
    pub offset: Vec3<F>,
    pub distance_squared: F,
    pub reach: F,
}

impl<F: Float> Separation<F> {
    #[inline(always)]
    pub(crate) fn of(i: &Sphere<F>, j: &Sphere<F>) -> Self {
        Self::between((i.position, i.radius), (j.position, j.radius))
    }

    /// The separation of spheres at these centres with these radii (the same bits as
    /// [`Separation::of`] on spheres that have them).
    #[inline(always)]
    pub(crate) fn between((at_i, radius_i): (Vec3<F>, F), (at_j, radius_j): (Vec3<F>, F)) -> Self {
        let offset = at_j - at_i;
        Self {
            offset,
            distance_squared: offset.norm_squared(),
            reach: radius_i + radius_j,
        }
    }

    /// Whether the one-contact path evaluates the pair (overlapping, or coincident: an error)
    /// rather than answering apart.
    #[inline(always)]
    pub(crate) fn needs_evaluation(&self) -> bool {
        !self.apart() || self.coincident()
    }

    /// The centres are too close for a contact normal.
    #[inline(always)]
    pub(crate) fn coincident(&self) -> bool {
        self.distance_squared < F::MIN_POSITIVE
    }

    /// The spheres do not overlap (an overflowed distance counts as apart).
    #[inline(always)]
    pub(crate) fn apart(&self) -> bool {
        self.distance_squared >= self.reach * self.reach
    }

    /// The separation's two roots, the long-latency part of its frame: `1 / d` and the overlap
    /// `S - d`. Branch-free and of plain numbers, so the list seam takes them for a whole chunk
    /// of sifted pairs in one loop the compiler widens.
    #[inline(always)]
    pub(crate) fn roots<M: MathBackend<F>>(distance_squared: F, reach: F) -> Roots<F> {
        let inverse_distance = M::inv_sqrt(distance_squared);
        let distance = distance_squared * inverse_distance;
        // (S^2 - d^2) / (S + d) keeps its relative accuracy when delta << S even with an
        // approximate square root, where S - d would cancel.
        let overlap = (reach * reach - distance_squared) / (reach + distance);
        Roots {
            inverse_distance,
            overlap,
        }
    }

    /// The contact frame from the separation's [`roots`](Self::roots).
    #[inline(always)]
    pub(crate) fn frame_with(
        &self,
        roots: Roots<F>,
        i: &Sphere<F>,
        j: &Sphere<F>,
        lever_arm: LeverArm,
    ) -> ContactFrame<F> {
        let Roots {
            inverse_distance,
            overlap,
        } = roots;
        let (arm_i, arm_j) = match lever_arm {
            LeverArm::Radius => (i.radius, j.radius),
            LeverArm::ContactPlane => {
                let (ri, rj) = (i.radius * i.radius, j.radius * j.radius);
                let half_inverse = F::HALF * inverse_distance;
                let distance_squared = self.distance_squared;
                (
                    ((distance_squared + ri - rj) * half_inverse).max_of(F::ZERO),
                    ((distance_squared + rj - ri) * half_inverse).max_of(F::ZERO),
                )
            }
        };
        ContactFrame {
            normal: self.offset * inverse_distance,
            overlap,
            effective_radius: i.radius * j.radius / self.reach,
            arm_i,
            arm_j,
            velocity: j.velocity - i.velocity,
            angular_velocity_i: i.angular_velocity,
            angular_velocity_j: j.angular_velocity,
        }
    }
}

/// A separation's roots ([`Separation::roots`]).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Roots<F> {
    pub inverse_distance: F,
    pub overlap: F,
}

/// The contact between checked spheres i and j of `separation` (see [`crate::value::checked::check`]),
/// `None` when they do not overlap; `roots` gives its [`Separation::roots`], asked only of an
/// overlapping pair.
#[inline(always)]
pub(crate) fn separated_frame<F: Float>(
    (i, j): (&Sphere<F>, &Sphere<F>),
    separation: &Separation<F>,
    roots: impl FnOnce() -> Roots<F>,
    lever_arm: LeverArm,
) -> Result<Option<ContactFrame<F>>, ContactError> {
    if separation.coincident() {
        return Err(ContactError::CoincidentCentres);
    }
    if separation.apart() {
        return Ok(None);
    }
    Ok(Some(separation.frame_with(roots(), i, j, lever_arm)))
}

/// The contact frame of a pair the list seam sifted for evaluation
/// ([`Separation::needs_evaluation`]: overlapping or coincident), so only the coincident-centre
/// test remains; `roots` as for [`separated_frame`].
#[inline(always)]
pub(crate) fn sifted_frame<F: Float>(
    (i, j): (&Sphere<F>, &Sphere<F>),
    separation: &Separation<F>,
    roots: Roots<F>,
    lever_arm: LeverArm,
) -> Result<ContactFrame<F>, ContactError> {
    if separation.coincident() {
        return Err(ContactError::CoincidentCentres);
    }
    Ok(separation.frame_with(roots, i, j, lever_arm))
}

/// The contact between checked spheres i and j (see [`crate::value::checked::check`]), `None` when they
/// do not overlap; only the coincident-centre test remains to be made.
#[inline(always)]
pub(crate) fn sphere_sphere<F: Float, M: MathBackend<F>>(
    i: &Sphere<F>,
    j: &Sphere<F>,
    lever_arm: LeverArm,
) -> Result<Option<ContactFrame<F>>, ContactError> {
    let separation = Separation::of(i, j);
    let roots = || Separation::roots::<M>(separation.distance_squared, separation.reach);
    separated_frame((i, j), &separation, roots, lever_arm)
}

/// The contact between a checked sphere (body i) and a wall (body j), `None` when they do not
/// overlap ([`Wall`]: against the plane tangent to the wall nearest the centre).
///
/// # Errors
/// [`ContactError::CoincidentCentres`] for an overlapping sphere centred on a cylinder's axis.
#[inline(always)]
pub(crate) fn sphere_wall<F: Float>(
    sphere: &Sphere<F>,
    wall: &Wall<F>,
    lever_arm: LeverArm,
) -> Result<Option<ContactFrame<F>>, ContactError> {
    if !reaches_wall(sphere.position, sphere.radius, wall) {
        return Ok(None);
    }
    let Some((towards_spheres, distance, surface_velocity)) = wall.surface_at(sphere.position)
    else {
        return Err(ContactError::CoincidentCentres);
    };
    let arm_i = match lever_arm {
        LeverArm::Radius => sphere.radius,
        LeverArm::ContactPlane => distance.max_of(F::ZERO),
    };
    Ok(Some(ContactFrame {
        // From the sphere into the wall.
        normal: -towards_spheres,
        overlap: sphere.radius - distance,
        effective_radius: sphere.radius,
        arm_i,
        arm_j: F::ZERO,
        velocity: surface_velocity - sphere.velocity,
        angular_velocity_i: sphere.angular_velocity,
        // A turning cylinder's spin lies in the tangent plane: the rolling slot sees a sphere
        // carried round with it as not rolling.
        angular_velocity_j: wall.angular_velocity(),
    }))
}

/// Whether an overlap is evaluated: positive, or NaN (finite inputs whose distance overflowed),
/// which falls through and is reported as a non-finite result.
#[inline(always)]
#[allow(
    clippy::neg_cmp_op_on_partial_ord,
    reason = "NaN must reach: not `overlap > 0`"
)]
fn reaches<F: Float>(overlap: F) -> bool {
    !(overlap <= F::ZERO)
}

/// Whether [`sphere_wall`] evaluates a sphere at `position` of `radius` against `wall` (by the
/// same test), so an engine can sift its spheres against a wall before evaluating them.
#[inline(always)]
pub(crate) fn reaches_wall<F: Float>(position: Vec3<F>, radius: F, wall: &Wall<F>) -> bool {
    reaches(radius - wall.distance_to(position))
}
