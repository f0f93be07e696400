//! # soft-sphere
//!
//! Linear soft-sphere contact laws for discrete-element (DEM) simulation: a normal spring and
//! dashpot, a tangential spring and dashpot, and a Coulomb slider, in the implementations compared
//! by Elghannay & Tafti (NETL 2017): the stateless simplified law, Model AA (stored spring with a
//! limited displacement), and Models A, B and C, kept so their failures can be shown.
//!
//! `#![no_std]`, no allocation, no `unsafe`; `f32` and `f64`; sphere-sphere and sphere-wall.
//!
//! ## Composing a law
//!
//! A [`ContactLaw`] is built from slots chosen at compile time: a normal law
//! ([`LinearSpringDashpot`]), a tangential law ([`Frictionless`], [`Stateless`], [`ModelC`],
//! [`ModelA`], [`ModelB`], [`ModelAA`]), a math backend ([`Libm`] by default, [`Micromath`] for
//! fast approximate `f32`) and rotation ([`Rotating`] by default, [`NonRotating`]). A frictionless
//! or non-rotating law computes no slip velocity, tangential force or torque at all.
//!
//! ```
//! use soft_sphere::{
//!     ContactLaw, Interaction, LinearSpringDashpot, ModelAA, Sphere, SpringDisplacement,
//!     TangentialParameters, Vec3, effective_mass,
//! };
//!
//! # fn main() -> Result<(), Box<dyn core::error::Error>> {
//! // The talk's oblique-impact parameters: k_n = 1000 N/m, e = 0.98, k_t = 860 N/m, mu = 0.092.
//! let normal = LinearSpringDashpot::new(1000.0_f64, 0.98)?;
//! let tangential = ModelAA(TangentialParameters::new(860.0, 0.5, 0.092)?);
//! let law = ContactLaw::new(normal, tangential);
//!
//! let mut a = Sphere::solid(Vec3::new(0.0, 0.0, 0.0), 2.5e-3, 2700.0);
//! let mut b = Sphere::solid(Vec3::new(4.9e-3, 0.0, 0.0), 2.5e-3, 2700.0);
//! a.velocity = Vec3::new(0.5, 0.1, 0.0);
//!
//! let m_star = effective_mass(a.mass, b.mass);
//! let dt = law.time_step(law.recommended_time_step(m_star), m_star)?;
//!
//! // Per-contact state: owned by the caller, 3 floats for the stored-spring laws.
//! let mut spring = SpringDisplacement::default();
//! match law.sphere_sphere(&a, &b, &mut spring, dt)? {
//!     Interaction::Touching(contact) => {
//!         assert!(contact.normal_force > 0.0); // 0.1 mm overlap pushes the spheres apart
//!         let on_b = contact.force_on_j();
//!         assert!(on_b.x > 0.0);
//!         // Coulomb: the tangential force never exceeds mu |F_n|.
//!         let ft = contact.tangential_force.norm_squared();
//!         assert!(ft <= (0.092 * contact.normal_force) * (0.092 * contact.normal_force) * (1.0 + 1e-12));
//!     }
//!     Interaction::Apart => unreachable!("the spheres overlap"),
//! }
//! # let _ = &mut b;
//! # Ok(())
//! # }
//! ```
//!
//! ## Guarantees
//!
//! Each is checked by the `host-tests` crate; the test that checks it is named.
//!
//! - **Bad input is an error value, never a panic or a silent NaN.** Constructors return
//!   [`ParameterError`] for non-finite or non-positive stiffness, mass, radius or time step, a
//!   restitution outside `[0, 1]`, a negative friction or damping ratio, and a time step at or past
//!   the law's stability limit. Contact evaluations return [`ContactError`] for non-finite inputs,
//!   non-positive radii or masses, coincident centres, overflowing results and a full history store.
//!   (`host-tests/tests/errors.rs`)
//! - **Nothing is half-updated.** A rejected evaluation leaves the per-contact state and the history
//!   store exactly as they were. (`host-tests/tests/errors.rs`, `host-tests/tests/history_store.rs`)
//! - **Coulomb.** `|F_t| <= mu |F_n|` for every tangential law, to rounding with [`Libm`] and
//!   within the square-root approximation error with [`Micromath`]. (`host-tests/tests/tangential.rs`)
//! - **Normal impact.** A free binary impact rebounds with ratio `e` and lasts
//!   `t_c = pi / sqrt(k_n/m* - (eta_n / 2m*)^2)`; with the attraction clamp it rebounds with
//!   Schwager & Poeschel's analytic ratio. (`host-tests/tests/normal_impact.rs`)
//! - **Action and reaction.** Swapping i and j negates the force bit for bit and swaps the
//!   torques. (`host-tests/tests/tangential.rs`)
//! - **Determinism.** Pure functions of their inputs: no global state, no fused multiply-add, no
//!   platform math; the same inputs give the same bits, whichever order a history store was filled
//!   in. (`host-tests/tests/history_store.rs`)
//! - **Stability limit.** [`ContactLaw::time_step`] refuses a step at or past the smaller of the
//!   normal and tangential modes' explicit-integration limits, `dt < (2/w)(sqrt(1 + z^2) - z)`;
//!   just below it a resting contact stays bounded, just above it it diverges.
//!   (`host-tests/tests/stability.rs`)
//! - **Pay for what you use.** [`Frictionless`], [`NonRotating`] and [`Rotating`] are zero-sized;
//!   [`Stateless`], [`ModelC`] and [`Frictionless`] keep no per-contact state; the stored-spring
//!   laws keep three floats. (`host-tests/tests/layout.rs`)
//! - **Momentum.** Linear momentum of an isolated pair is conserved to rounding; angular momentum
//!   too with [`LeverArm::ContactPlane`], while the default radius arm changes it at the rate
//!   `-delta n x F_t`. (`host-tests/tests/tangential.rs`)
//!
//! ## Conventions
//!
//! The unit normal `n` points from body i to body j (for a wall: from the sphere into the wall).
//! Forces in [`ContactForces`] act on j; i receives the negative. Lever arms are the radii by
//! default ([`LeverArm`]); the same arm is used for the slip velocity and the torque, which keeps
//! the contact passive. Physics and formulas follow `shared/reference/REFERENCE.md`.

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![deny(clippy::disallowed_methods)]

mod backend;
mod body;
mod error;
mod float;
mod geometry;
mod law;
pub mod motion;
mod normal;
mod rotation;
mod store;
pub mod tangential;
mod time_step;
mod vector;

pub use backend::{Libm, MathBackend, Micromath};
pub use body::{Sphere, Wall, effective_mass};
pub use error::{ContactError, Parameter, ParameterError};
pub use float::Float;
pub use geometry::LeverArm;
pub use law::{ContactForces, ContactLaw, Interaction};
pub use normal::{LinearSpringDashpot, NormalModel, NormalOscillator};
pub use rotation::{NonRotating, Rotating, Rotation};
pub use store::{ContactHistory, ContactKey};
pub use tangential::{
    ContactState, Frictionless, ModelA, ModelAA, ModelB, ModelC, SpringDisplacement, Stateless,
    TangentialModel, TangentialParameters,
};
pub use time_step::TimeStep;
pub use vector::Vec3;
