//! What a user names: the laws and their slots, spheres, walls, time steps, forces, errors, the
//! material tables and the list seam's types. `use soft_sphere::prelude::*;` brings them in;
//! each is here once, and its home module is the crate's own.

pub use crate::law::contact_law::ContactLaw;
pub use crate::law::engine::{BoundLaw, Law};
pub use crate::law::geometry::LeverArm;
pub use crate::law::laws::{
    HertzAA, HertzAALuding, HertzFrictionless, HertzLaw, HertzMicroSlip, HertzStateless, LinearAA,
    LinearAALuding, LinearFrictionless, LinearLaw, LinearStateless,
};
pub use crate::law::mixing::{ElasticMaterial, HertzMixing, LinearMaterial, LinearMixing, Mixing};
pub use crate::law::normal::{
    Hertz, HertzImpact, LinearSpring, LinearSpringDashpot, NormalContact, NormalModel,
    NormalOscillator,
};
pub use crate::law::rolling::{
    ConstantRolling, ElasticPlasticRolling, NoRolling, RollingModel, RollingSpring,
};
pub use crate::law::rotation::{NonRotating, Rotating, Rotation};
pub use crate::law::tangential::{
    ContactState, Frictionless, MicroSlip, MicroSlipSprings, MindlinAA, MindlinAALuding,
    MindlinParameters, MindlinSpring, MindlinStateless, ModelA, ModelAA, ModelAALuding, ModelB,
    ModelC, SpringDisplacement, Stateless, TangentialModel, TangentialOutput, TangentialParameters,
};
pub use crate::seam::list::{ContactList, ListOutput, MaterialWall};
pub use crate::seam::list_error::{ListArray, ListError};
pub use crate::seam::pair_check::{CheckedPairs, PairList, check_pairs};
pub use crate::seam::spheres::{SphereArrays, SphereSlice, Spheres};
pub use crate::seam::spread::PairLoad;
pub use crate::seam::stats::ListStats;
pub use crate::seam::store::{ContactHistory, ContactKey};
pub use crate::seam::table::{MaterialTable, TableError};
#[cfg(feature = "std")]
pub use crate::value::backend::Std;
pub use crate::value::backend::{Libm, MathBackend, Micromath};
pub use crate::value::body::{Sphere, effective_mass};
pub use crate::value::checked::CheckedSphere;
pub use crate::value::error::{ContactError, Parameter, ParameterError};
pub use crate::value::float::Float;
pub use crate::value::forces::{ContactForces, Interaction};
pub use crate::value::material::Material;
pub use crate::value::time_step::TimeStep;
pub use crate::value::vector::Vec3;
pub use crate::value::wall::{Wall, WallShape};
