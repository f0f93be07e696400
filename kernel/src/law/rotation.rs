//! The rotation slot: whether the bodies' spin enters the contact.

/// Whether a contact law accounts for rotation. Implemented by the zero-sized [`Rotating`] and
/// [`NonRotating`]; the choice is made at compile time.
pub trait Rotation: Copy + Default + core::fmt::Debug + 'static {
    /// True when angular velocities enter the slip velocity and torques are produced.
    const ROTATES: bool;
}

/// Spheres rotate: the slip velocity includes `(a_i w_i + a_j w_j) x n` and torques are returned.
/// The default.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rotating;

/// Spheres do not rotate: angular velocities are ignored, no torque is computed (torques are
/// returned as zero), and the tangential mode's effective mass is `m*` rather than `2/7 m*`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NonRotating;

impl Rotation for Rotating {
    const ROTATES: bool = true;
}

impl Rotation for NonRotating {
    const ROTATES: bool = false;
}
