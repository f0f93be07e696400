//! Why a scene could not be set up or stepped.

use core::fmt;

use soft_sphere::prelude::{ContactError, ListError, ParameterError};

use crate::limits::MAX_CELLS;

/// Why a scene could not be set up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneError {
    /// A buffer's length is not the one [`Scene::buffer_sizes`](crate::Scene::buffer_sizes)
    /// gives for these spheres, cells, walls and list capacity.
    BufferLength,
    /// The domain or cell size is not finite and positive, or a periodic direction has fewer
    /// than 3 cells (the half-shell would visit a pair twice).
    Domain,
    /// The domain cut into cells no smaller than the largest diameter plus the skin gives more
    /// cells than a scene holds ([`MAX_CELLS`]): a cell size given in the
    /// wrong unit, or a domain far larger than its spheres. Refused before anything is
    /// allocated.
    TooManyCells {
        /// How many cells the domain would have (saturating at `u64::MAX`).
        cells: u64,
    },
    /// Sphere `index` is larger than the declared largest diameter, which sizes the grid's
    /// cells: its contacts with spheres two cells away would go unseen.
    Diameter {
        /// The sphere.
        index: usize,
    },
    /// Sphere `index`'s centre is outside the domain along a direction that is not periodic.
    Outside {
        /// The sphere.
        index: usize,
    },
    /// A stored pair state in the list belongs to a pair whose spheres are not this scene's
    /// (the buffers were not fresh, or come from another scene).
    History,
    /// The material ids are not one per sphere.
    Materials,
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
            Self::TooManyCells { cells } => write!(
                f,
                "the domain would have {cells} cells, more than a scene holds ({}): is the \
                 largest diameter or the domain in the wrong unit?",
                MAX_CELLS
            ),
            Self::Diameter { index } => write!(
                f,
                "sphere {index} is larger than the scene's declared largest diameter"
            ),
            Self::Outside { index } => {
                write!(f, "sphere {index}'s centre is outside the scene's domain")
            }
            Self::History => f.write_str(
                "a stored pair state belongs to spheres that are not this scene's (use fresh buffers)",
            ),
            Self::Materials => f.write_str("the material ids are not one per sphere"),
            Self::Sphere { index, error } => write!(f, "sphere {index} is invalid: {error}"),
        }
    }
}

impl core::error::Error for SceneError {}

/// Why a step failed. The contact history is then as it was before the step (see
/// [`Scene::step_on`](crate::Scene::step_on) for the spheres).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StepError {
    /// The contact of spheres `spheres` was refused (coincident centres, an overflowing force,
    /// past the step's stability limit).
    Pair {
        /// The two spheres, lower index first.
        spheres: [usize; 2],
        /// Why.
        error: ContactError,
    },
    /// The contact of sphere `sphere` with wall `wall` was refused.
    Wall {
        /// The sphere.
        sphere: usize,
        /// The wall.
        wall: usize,
        /// Why.
        error: ContactError,
    },
    /// Sphere `sphere`'s material id is not a row of the step's table.
    Material {
        /// The sphere.
        sphere: usize,
        /// Its id.
        material: u32,
    },
    /// Wall `wall`'s material id is not a row of the step's table.
    WallMaterial {
        /// The wall.
        wall: usize,
        /// Its id.
        material: u32,
    },
    /// The step is refused by the law of materials `materials` at the smallest effective mass
    /// the scene's spheres give that pair ([`Scene::time_step`](crate::Scene::time_step)).
    TimeStep {
        /// The two material ids (a wall's second).
        materials: [u32; 2],
        /// The law's answer.
        error: ParameterError,
    },
    /// At a list rebuild, the Verlet list needed more entries than its buffer holds. Nothing is
    /// lost: build the scene again over larger buffers and the same history.
    ListFull,
    /// At a list rebuild, a sphere owned more than `K` touching contacts with stored states.
    /// Nothing is lost: build the scene again with a larger `K` (an
    /// [`OwnedScene`](crate::OwnedScene): [`with_parking`](crate::OwnedScene::with_parking),
    /// which keeps the history).
    ParkingFull,
    /// Finite forces moved sphere `index` to a non-finite position or velocity. That sphere keeps
    /// its state from before the step, the others have moved, and the scene refuses to go on.
    Diverged {
        /// The first sphere that diverged.
        index: usize,
    },
    /// Sphere `index`'s centre was found outside the domain along a direction that is not
    /// periodic when the Verlet list was rebuilt (it flew out through an open side, or through
    /// a wall too soft for its speed). The history is as before the step; the scene refuses to
    /// step until that sphere is back inside.
    Outside {
        /// The sphere.
        index: usize,
    },
    /// An earlier step diverged; the scene does not step again.
    Halted,
    /// The step's gravity is not finite. Refused before anything changes.
    Gravity,
    /// An owned scene's buffers no longer fit its spheres (see
    /// [`OwnedScene::scene`](crate::OwnedScene)).
    Scene(SceneError),
    /// The kernel's list seam refused an array the scene built itself (its lengths, a
    /// shift, a sphere): a defect of the scene, reported rather than hidden.
    List(ListError),
}

impl From<SceneError> for StepError {
    fn from(error: SceneError) -> Self {
        Self::Scene(error)
    }
}

impl StepError {
    /// The scene's reading of what the kernel's list seam refused: pairs named by their
    /// spheres.
    pub(crate) fn from_list(error: ListError, pairs: &[[u32; 2]]) -> Self {
        let spheres = |pair: usize| pairs.get(pair).map_or([0, 0], |p| p.map(|k| k as usize));
        match error {
            ListError::Pair { pair, error } => Self::Pair {
                spheres: spheres(pair),
                error,
            },
            ListError::Wall {
                sphere,
                wall,
                error,
            } => Self::Wall {
                sphere,
                wall,
                error,
            },
            ListError::Material { sphere, material } => Self::Material { sphere, material },
            ListError::WallMaterial { wall, material } => Self::WallMaterial { wall, material },
            ListError::TimeStep { materials, error } => Self::TimeStep { materials, error },
            other => Self::List(other),
        }
    }
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Pair { spheres, error } => write!(
                f,
                "the contact of spheres {} and {} was refused: {error}",
                spheres[0], spheres[1]
            ),
            Self::Wall {
                sphere,
                wall,
                error,
            } => write!(
                f,
                "the contact of sphere {sphere} with wall {wall} was refused: {error}"
            ),
            Self::Material { sphere, material } => write!(
                f,
                "sphere {sphere}'s material {material} is not in the material table"
            ),
            Self::WallMaterial { wall, material } => write!(
                f,
                "wall {wall}'s material {material} is not in the material table"
            ),
            Self::TimeStep { materials, error } => write!(
                f,
                "the time step is refused for materials {} and {}: {error}",
                materials[0], materials[1]
            ),
            Self::ListFull => f.write_str("the Verlet list buffer is too short"),
            Self::ParkingFull => f.write_str(
                "a sphere owns more touching contacts than its parking holds \
                     (OwnedScene::with_parking gives it more room, keeping the history)",
            ),
            Self::Diverged { index } => write!(f, "sphere {index} diverged to a non-finite state"),
            Self::Outside { index } => write!(
                f,
                "sphere {index} has left the domain through a side that is not periodic"
            ),
            Self::Halted => f.write_str("an earlier step diverged; the scene has stopped"),
            Self::Gravity => f.write_str("the step's gravity is not finite"),
            Self::Scene(error) => write!(f, "the scene could not be built: {error}"),
            Self::List(error) => write!(f, "the scene's own contact list was refused: {error}"),
        }
    }
}

impl core::error::Error for StepError {}
