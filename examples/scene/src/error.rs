//! Why a scene could not be set up or stepped.

use core::fmt;

use soft_sphere::ContactError;

/// Why a scene could not be set up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneError {
    /// A buffer's length is not the one [`Scene::buffer_sizes`](crate::Scene::buffer_sizes)
    /// gives for these spheres, cells, walls and list capacity.
    BufferLength,
    /// The domain or cell size is not finite and positive, or a periodic direction has fewer
    /// than 3 cells (the half-shell would visit a pair twice).
    Domain,
    /// A stored pair state in the list belongs to a pair whose spheres are not this scene's
    /// (the buffers were not fresh, or come from another scene).
    History,
    /// Sphere `index` is not valid (`error` says why: a non-finite field, a radius or mass that
    /// is not positive); what [`check_spheres`](crate::check_spheres) reports.
    Sphere {
        /// Its index.
        index: usize,
        /// What is wrong with it.
        error: ContactError,
    },
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::BufferLength => f.write_str(
                "a scene buffer's length does not match the spheres, cells, walls or list capacity",
            ),
            Self::Domain => f.write_str(
                "the scene domain or cell size is invalid (periodic directions need 3 cells)",
            ),
            Self::History => f.write_str(
                "a stored pair state belongs to spheres that are not this scene's (use fresh buffers)",
            ),
            Self::Sphere { index, error } => write!(f, "sphere {index} is invalid: {error}"),
        }
    }
}

impl core::error::Error for SceneError {}

/// Why a step failed. The contact history is then as it was before the step (see
/// [`Scene::step_on`](crate::Scene::step_on) for the spheres).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepError {
    /// A contact evaluation was rejected (coincident centres, an overflowing force).
    Contact(ContactError),
    /// At a list rebuild, the Verlet list needed more entries than its buffer holds. Nothing is
    /// lost: build the scene again over larger buffers and the same history.
    ListFull,
    /// At a list rebuild, a sphere owned more than `K` touching contacts with stored states.
    /// Nothing is lost: build the scene again with a larger `K`.
    ParkingFull,
    /// Finite forces moved sphere `index` to a non-finite position or velocity. That sphere keeps
    /// its state from before the step, the others have moved, and the scene refuses to go on.
    Diverged {
        /// The first sphere that diverged.
        index: usize,
    },
    /// An earlier step diverged; the scene does not step again.
    Halted,
}

impl From<ContactError> for StepError {
    fn from(error: ContactError) -> Self {
        Self::Contact(error)
    }
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Contact(error) => write!(f, "a contact was rejected: {error}"),
            Self::ListFull => f.write_str("the Verlet list buffer is too short"),
            Self::ParkingFull => {
                f.write_str("a sphere owns more touching contacts than its parking holds")
            }
            Self::Diverged { index } => write!(f, "sphere {index} diverged to a non-finite state"),
            Self::Halted => f.write_str("an earlier step diverged; the scene has stopped"),
        }
    }
}

impl core::error::Error for StepError {}
