//! The walls a sphere meets: a plane, or the inside of a circular cylinder (a drum, a pipe), each
//! able to translate and to turn about its own axis with its surface staying in place.

use crate::value::backend::MathBackend;
use crate::value::error::{Parameter, ParameterError};
use crate::value::float::Float;
use crate::value::vector::Vec3;

/// The shape of a [`Wall`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WallShape<F> {
    /// An infinite plane; spheres live on the side its normal points to.
    Plane,
    /// The inside of an infinite circular cylinder of this radius (m) about the wall's axis;
    /// spheres live inside.
    Cylinder {
        /// The cylinder's radius (m).
        radius: F,
    },
}

/// A plane or cylindrical wall. It may translate (its velocity enters the contact's relative
/// velocity) and turn about its own axis ([`Wall::with_spin`]: a turntable, a rotating drum),
/// which moves its surface within itself. Every field is checked when it is set, so a wall is
/// always valid and contacts never check it again.
///
/// A sphere meets a wall as it would meet the plane tangent to the wall at the surface point
/// nearest its centre: the normal is the wall's there, the overlap the sphere's radius less the
/// centre's distance to the surface, the wall's velocity its surface's there. A cylinder's
/// curvature is not in the contact's stiffness (the effective radius is the sphere's, as
/// against a plane), which keeps every wall contact within the time step checked for its
/// sphere; in a cylinder of ten sphere radii a Hertz contact's mean-curvature radius would be
/// 5 % larger, its stiffness 2.6 %. A cylinder has one side: a sphere outside it is inside its
/// wall, and is pushed in by its whole depth.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wall<F> {
    point: Vec3<F>,
    /// A plane's unit normal towards the spheres; a cylinder's unit axis.
    direction: Vec3<F>,
    velocity: Vec3<F>,
    spin: F,
    shape: WallShape<F>,
}

/// `direction` normalised with the reference backend, once; refused when not finite or of no
/// length.
fn unit<F: Float>(point: Vec3<F>, direction: Vec3<F>) -> Result<Vec3<F>, ParameterError> {
    if !point.is_finite() || !direction.is_finite() {
        return Err(ParameterError::NonFinite(Parameter::Wall));
    }
    let length_squared = direction.norm_squared();
    if !length_squared.is_finite() {
        return Err(ParameterError::NonFinite(Parameter::Wall));
    }
    if length_squared < F::MIN_POSITIVE {
        return Err(ParameterError::NotPositive(Parameter::Wall));
    }
    Ok(direction * F::DefaultBackend::inv_sqrt(length_squared))
}

impl<F: Float> Wall<F> {
    /// A plane wall through `point` whose normal towards the spheres is along `normal`.
    /// The normal is normalised here, once, with the reference backend.
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for a non-finite point or normal,
    /// [`ParameterError::NotPositive`] for a zero (or denormal-length) normal.
    pub fn new(point: Vec3<F>, normal: Vec3<F>) -> Result<Self, ParameterError> {
        Ok(Self {
            point,
            direction: unit(point, normal)?,
            velocity: Vec3::ZERO,
            spin: F::ZERO,
            shape: WallShape::Plane,
        })
    }

    /// A cylindrical wall of `radius` whose axis passes through `point` along `axis` (any
    /// length; normalised here, once, with the reference backend), with the spheres inside.
    ///
    /// ```
    /// use soft_sphere::prelude::{Vec3, Wall};
    /// let drum = Wall::cylinder(Vec3::ZERO, Vec3::new(0.0, 0.0, 2.0), 0.1_f64).unwrap();
    /// // A centre 0.08 m from the axis is 0.02 m from the surface.
    /// assert!((drum.distance_to(Vec3::new(0.08, 0.0, 5.0)) - 0.02).abs() < 1e-15);
    /// ```
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for a non-finite point, axis or radius,
    /// [`ParameterError::NotPositive`] for a zero axis or a radius that is not positive.
    pub fn cylinder(point: Vec3<F>, axis: Vec3<F>, radius: F) -> Result<Self, ParameterError> {
        let direction = unit(point, axis)?;
        if !radius.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::Wall));
        }
        if radius <= F::ZERO {
            return Err(ParameterError::NotPositive(Parameter::Wall));
        }
        Ok(Self {
            point,
            direction,
            velocity: Vec3::ZERO,
            spin: F::ZERO,
            shape: WallShape::Cylinder { radius },
        })
    }

    /// The same wall moving with `velocity` (m/s), for moving floors and pistons (zero by
    /// default).
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for a non-finite velocity.
    pub fn with_velocity(mut self, velocity: Vec3<F>) -> Result<Self, ParameterError> {
        if !velocity.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::Wall));
        }
        self.velocity = velocity;
        Ok(self)
    }

    /// The same wall turning at `spin` rad/s (a rate, the angular velocity being
    /// `spin direction`) about its own axis, right-handed about [`Wall::direction`]: a cylinder
    /// about its axis (a rotating drum), a plane about its normal through [`Wall::point`] (a
    /// turntable). Its surface stays where it is and moves within itself: at a point `c` of the
    /// surface, at [`Wall::velocity`] plus `spin direction x (c - point)`. Zero by default.
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for a non-finite spin.
    pub fn with_spin(mut self, spin: F) -> Result<Self, ParameterError> {
        if !spin.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::Wall));
        }
        self.spin = spin;
        Ok(self)
    }

    /// The same wall, translated so that it (a cylinder: its axis) passes through `point` (for
    /// walls the caller moves).
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] for a non-finite point.
    pub fn moved_to(mut self, point: Vec3<F>) -> Result<Self, ParameterError> {
        if !point.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::Wall));
        }
        self.point = point;
        Ok(self)
    }

    /// The wall's velocity (m/s).
    pub fn velocity(&self) -> Vec3<F> {
        self.velocity
    }

    /// The wall's turning rate about its axis (rad/s).
    pub fn spin(&self) -> F {
        self.spin
    }

    /// The wall's angular velocity, `spin direction` (rad/s; exactly zero for a wall that does
    /// not turn).
    #[inline(always)]
    pub fn angular_velocity(&self) -> Vec3<F> {
        if self.spin == F::ZERO {
            Vec3::ZERO
        } else {
            self.direction * self.spin
        }
    }

    /// The velocity of the wall's surface at the point nearest `position` (m/s): what a sphere
    /// centred there meets, and what the wall's drive moves a contact's force along. For a
    /// centre on a cylinder's axis, where no point is nearest, the wall's velocity.
    pub fn surface_velocity(&self, position: Vec3<F>) -> Vec3<F> {
        self.surface_at(position)
            .map_or(self.velocity, |(_, _, velocity)| velocity)
    }

    /// A point on the plane; a point on the cylinder's axis.
    pub fn point(&self) -> Vec3<F> {
        self.point
    }

    /// The plane's unit normal towards the spheres; the cylinder's unit axis.
    pub fn direction(&self) -> Vec3<F> {
        self.direction
    }

    /// The wall's shape.
    pub fn shape(&self) -> WallShape<F> {
        self.shape
    }

    /// Signed distance from `position` to the wall's surface, positive on the spheres' side
    /// (for a cylinder: its radius less the distance from the axis, by the reference backend).
    #[inline(always)]
    pub fn distance_to(&self, position: Vec3<F>) -> F {
        match self.shape {
            WallShape::Plane => (position - self.point).dot(self.direction),
            WallShape::Cylinder { radius } => {
                radius - F::DefaultBackend::sqrt(self.radial(position).norm_squared())
            }
        }
    }

    /// The part of `position - point` across a cylinder's axis.
    #[inline(always)]
    fn radial(&self, position: Vec3<F>) -> Vec3<F> {
        let offset = position - self.point;
        offset - self.direction * offset.dot(self.direction)
    }

    /// The surface nearest `position`: its unit normal there towards the spheres, the
    /// signed distance to it ([`Wall::distance_to`]) and the surface's velocity there. `None`
    /// for a centre on a cylinder's axis (closer than the smallest normal float), where the
    /// normal is undefined.
    #[inline(always)]
    pub(crate) fn surface_at(&self, position: Vec3<F>) -> Option<(Vec3<F>, F, Vec3<F>)> {
        let (normal, distance) = match self.shape {
            WallShape::Plane => (self.direction, self.distance_to(position)),
            WallShape::Cylinder { radius } => {
                let radial = self.radial(position);
                let squared = radial.norm_squared();
                // A NaN (an overflow of finite inputs) goes on, to be reported as a non-finite
                // result.
                if squared < F::MIN_POSITIVE {
                    return None;
                }
                let from_axis = F::DefaultBackend::sqrt(squared);
                // Towards the axis, where the spheres are.
                (radial * (-F::ONE / from_axis), radius - from_axis)
            }
        };
        if self.spin == F::ZERO {
            return Some((normal, distance, self.velocity));
        }
        let contact = position - normal * distance;
        let turning = self.angular_velocity().cross(contact - self.point);
        Some((normal, distance, self.velocity + turning))
    }
}
