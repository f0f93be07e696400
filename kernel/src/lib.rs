//! # soft-sphere
//!
//! Soft-sphere contact laws for discrete-element (DEM) simulation: a normal spring and dashpot
//! (linear, or Hertz's), a tangential spring and dashpot (linear, or Mindlin's), a Coulomb slider
//! and rolling resistance, in the implementations compared by Elghannay & Tafti (NETL 2017): the
//! stateless simplified law, Model AA (stored spring with a limited displacement), and Models A, B
//! and C, kept so their failures can be shown. The formulas, conventions and validation cases are
//! in `docs/physics.md`.
//!
//! `#![no_std]`, no allocation, no `unsafe`; `f32` and `f64`; sphere-sphere and sphere-wall.
//!
//! ## Composing a law
//!
//! A [`ContactLaw`] is built from slots chosen at compile time: a normal law
//! ([`LinearSpringDashpot`], [`LinearSpring`], [`Hertz`]), a tangential law ([`Frictionless`],
//! [`Stateless`], [`ModelC`], [`ModelA`], [`ModelB`], [`ModelAA`], [`ModelAALuding`]; under
//! Hertz, [`MindlinStateless`], [`MindlinAA`], [`MindlinAALuding`] and the micro-slip law
//! [`MicroSlip`]), rolling resistance ([`NoRolling`] by default, [`ConstantRolling`],
//! [`ElasticPlasticRolling`]), a math backend ([`Libm`] by default, [`Micromath`] for
//! fast approximate `f32`) and rotation ([`Rotating`] by default, [`NonRotating`]). A frictionless
//! or non-rotating law computes no slip velocity, tangential force or torque at all. The common
//! laws have names: [`LinearAA`], [`LinearAALuding`], [`LinearStateless`],
//! [`LinearFrictionless`], [`HertzAA`], [`HertzAALuding`], [`HertzStateless`],
//! [`HertzFrictionless`], [`HertzMicroSlip`].
//!
//! ```
//! use soft_sphere::prelude::{
//!     ContactLaw, Interaction, LinearSpringDashpot, ModelAA, Sphere, SpringDisplacement,
//!     TangentialParameters, Vec3, effective_mass,
//! };
//!
//! # fn main() -> Result<(), Box<dyn core::error::Error>> {
//! // Elghannay & Tafti's oblique-impact parameters: k_n = 1000 N/m, e = 0.98, k_t = 860 N/m,
//! // mu = 0.092.
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
//! Each is checked by the `host-tests` crate; the test that checks it is named. "Property" tests
//! (`host-tests/tests/properties.rs`) run over random collisions of any size, density, speed,
//! angle, spin, `e` in `[0, 1]`, `mu` in `[0, 2]` and `k_t/k_n` in `[0.1, 2]`, for every
//! tangential law in f32 and f64 (64 cases each by default, `PROPTEST_CASES` for more).
//!
//! - **Bad input is an error value, never a panic or a silent NaN.** Constructors return
//!   [`ParameterError`] for non-finite or non-positive stiffness, mass, radius or time step, a
//!   restitution outside `[0, 1]`, a negative friction or damping ratio, and a time step at or past
//!   the law's stability limit. Contact evaluations return [`ContactError`] for non-finite inputs,
//!   non-positive radii or masses, coincident centres, overflowing results and a full history store;
//!   a [`Wall`] checks every field when it is set.
//!   Arbitrary bit patterns in every input give a finite result or an error.
//!   (`errors.rs`; property `arbitrary_bit_patterns_give_a_value_or_an_error`)
//! - **Nothing is half-updated.** A rejected evaluation leaves the per-contact state and the history
//!   store exactly as they were. (`errors.rs`, `history_store.rs`, the bit-pattern property)
//! - **Coulomb.** `|F_t| <= mu |F_n|` at every step of every contact, for every tangential law,
//!   within 64 ulp with [`Libm`]; within the square-root approximation's error with [`Micromath`].
//!   (property `coulomb_limit_at_every_step`; `tangential.rs`)
//! - **No energy is created** by the stateless law, Model AA or frictionless contacts: after a
//!   binary collision (pair or wall) kinetic energy (translational and rotational) exceeds that
//!   before by at most 1e-3 at the recommended step (plus f32 position rounding, below); with
//!   `e = 1, mu = 0` it is conserved to that; in contact, kinetic plus stored spring energy rises by
//!   at most 8 % (symplectic Euler's oscillation at `t_c/50`). Models A and B store spring energy
//!   without bound while sliding, and Model A creates kinetic energy (15 % found): documented, not
//!   guaranteed; [`ModelAALuding`] creates no kinetic energy in the same search, but its reset can
//!   store a spring far beyond the impact's energy. (property `energy_is_never_created`, `energy_search_on_models_a_b_c_reports_what_it_finds`;
//!   grazing and head-on wall impacts in `stress.rs`)
//! - **Normal impact.** A free binary impact rebounds with ratio `e` and lasts
//!   `t_c = pi / sqrt(k_n/m* - (eta_n / 2m*)^2)`; with the attraction clamp it rebounds with
//!   Schwager & Poeschel's analytic ratio. (`normal_impact.rs`, `validation.rs`)
//! - **Action and reaction.** Swapping i and j negates the force and swaps the torques bit for
//!   bit (a zero may change sign). (property `action_equals_reaction`; `tangential.rs`)
//! - **Momentum.** Linear momentum of an isolated pair is conserved to rounding; angular momentum
//!   too with [`LeverArm::ContactPlane`], while the default radius arm changes it at the rate
//!   `-delta n x F_t`. (property `action_equals_reaction`; `tangential.rs`)
//! - **Frame invariance.** Rotating and translating the whole configuration rotates forces and
//!   torques, to a rounding bound that grows with the coordinates over the overlap; a stored spring
//!   follows a rigidly rotating stuck pair. (property `forces_rotate_with_the_frame`;
//!   `tangential.rs`)
//! - **Determinism.** Pure functions of their inputs: no global state, no fused multiply-add, no
//!   platform math; the same inputs give the same bits, run to run and whichever order a history
//!   store was filled in. (property `same_inputs_same_bits`; `history_store.rs`)
//! - **f32 tracks f64** to within `10 / u` of the approach speed, where `u` is how many roundings
//!   of the coordinates one step moves a sphere: overlaps much smaller than the radius and large
//!   coordinates are where f32 breaks down. (property `f32_collisions_track_f64`)
//! - **Micromath tracks libm**: forces within 15 % of the force plus spring force (median 0.6 %)
//!   for radii 1e-5 to 1 m and overlaps 1e-4 to 1e-1 of the radius.
//!   (property `micromath_forces_stay_within_their_bound_of_libm`)
//! - **Stability limit.** [`ContactLaw::time_step`] refuses a step at or past the smaller of the
//!   normal and tangential modes' explicit-integration limits, `dt < (2/w)(sqrt(1 + z^2) - z)`;
//!   just below it a resting contact stays bounded, just above it it diverges; past it on purpose,
//!   nothing non-finite leaves the kernel. (`stability.rs`, `stress.rs`)
//! - **Accuracy limit.** [`ContactLaw::time_step`] refuses a stable step at which a head-on
//!   impact, first seen at any phase of its step, could rebound more than 0.02 of its impact
//!   speed above the law's restitution ([`ContactLaw::accurate_time_step`], derived from the
//!   integrators' discrete map when the law is built), and checks each contact against
//!   [`ContactLaw::accurate_phase`]. (`accuracy.rs`)
//! - **No contact past its step goes on silently.** Every evaluation checks its contact against
//!   the step's limit ([`ContactLaw::stable_phase`]): a pair lighter than the declared mass, a
//!   [`Hertz`] overlap past the declared impact's, a wall law stiffer than the step's are refused
//!   with [`ContactError::PastStableStep`], or counted when the step
//!   [tolerates](TimeStep::tolerating_unstable_contacts) them. (`unstable_contacts.rs`,
//!   `scene.rs`)
//! - **Whole lists are one contact at a time.** [`MaterialTable::evaluate`] gives each contact
//!   of a list the one-contact bits with its pair of materials' law, writes each sphere's force as
//!   its contacts' sum in list order and the next states beside the ones it read, and on an error
//!   leaves the states it read as they were and names the sphere, pair or wall;
//!   [`MaterialTable::time_step`] checks the step against every pair of materials present;
//!   [`MaterialTable::evaluate_on`] spreads the pairs over a caller's [`Executor`](executor::Executor)'s threads
//!   with the same bits, states, records and errors. (`material_list.rs`)
//! - **Rest.** A sphere resting on a plate for 10^6 steps does not drift or gain energy; a stored
//!   spring holds a sphere on an incline below the friction angle, the stateless law lets it creep
//!   (1 mm/s at 20 degrees, `mu` = 0.5). (`stress.rs`)
//! - **Pay for what you use.** [`Frictionless`], [`NonRotating`] and [`Rotating`] are zero-sized;
//!   [`Stateless`], [`ModelC`], [`MindlinStateless`] and [`Frictionless`] keep no per-contact
//!   state; the stored-spring laws keep three floats, the stored Mindlin laws four, the
//!   micro-slip law `4 SPRINGS + 4`. (`layout.rs`, `hertz.rs`)
//! - **Hertz rebounds at `e`.** [`Hertz`]'s dashpot is solved from the restitution, so a free
//!   impact rebounds at `e` (within 0.5 %) at any speed; its force follows Hertz's closed form
//!   and the Mindlin laws keep the Coulomb limit, create no energy, are symmetric and frame
//!   invariant. (`validation.rs`, Chung & Ooi Tests 1-3; `hertz.rs`)
//! - **Micro-slip** follows Cattaneo & Mindlin's loading and Mindlin & Deresiewicz's unloading,
//!   reloading and dissipation, converging at second order in the spring width; it creates no
//!   energy over any loading cycle and comes within 0.08 RMS of Chung & Ooi's Test 5
//!   finite-element curve. (`micro_slip.rs`; `validation.rs`)
//! - **Rolling resistance** stays within `mu_r R* |F_n|`, acts as a couple (i and j receive
//!   opposite torques) and creates no energy; [`ElasticPlasticRolling`] holds a sphere on a slope
//!   below its rolling angle. (`rolling.rs`; `validation.rs`)
//!
//! ## Engines: the checked fast path
//!
//! An engine that evaluates each sphere in many contacts checks it once, as a [`CheckedSphere`],
//! binds the law to its checked time step with [`ContactLaw::at`], and evaluates through the
//! resulting [`BoundLaw`]: no input is checked twice, and the normal oscillator is derived once
//! per pair of masses. [`Law`] names any law as one type parameter, with its precision and
//! per-contact state (`L::Float`, `L::State`). The scene crate (`examples/scene`), the C ABI and
//! the examples reach the laws only through this public API; `docs/architecture.md` says where
//! everything lives.
//!
//! A whole problem at once: a [`MaterialTable`] holds one law per pair of materials (mixed from
//! each material's properties by a [`Mixing`] rule, any pair overridable), and
//! [`MaterialTable::evaluate`] takes an engine's own spheres (as arrays, [`SphereArrays`], or one
//! array of checked spheres, [`SphereSlice`]), its pair list with any periodic shifts and its
//! walls ([`ContactList`]) and writes the forces and the next states into its arrays
//! ([`ListOutput`]), all or nothing.
//! An engine with threads implements [`Executor`](executor::Executor) and calls [`MaterialTable::evaluate_on`] with
//! one [`PairLoad`] per pair as working memory: stretches of the list are evaluated on its
//! threads and their loads added in list order on one, so the sums are the one-thread bits.
//! [`ContactLaw::stored_energy`] says what a contact's springs hold, for energy accounts.
//!
//! ## Testing an engine around it
//!
//! [`checks`] holds the guarantees above as functions a user's property tests and fuzz targets
//! call, at the kernel's own tolerances. Two optional features (std, off by default) supply the
//! inputs: `proptest` adds `soft_sphere::strategies` (collisions, impacts, touching and grazing
//! pairs, spheres, walls, every slot's parameters, arbitrary bit patterns), `arbitrary` implements `arbitrary::Arbitrary` for the input types (cargo-fuzz,
//! bolero). `examples/fuzz-engine` fuzzes a small engine of its own with them.
//!
//! ## Conventions
//!
//! The unit normal `n` points from body i to body j (for a wall: from the sphere into the wall).
//! Forces in [`ContactForces`] act on j; i receives the negative. Lever arms are the radii by
//! default ([`LeverArm`]); the same arm is used for the slip velocity and the torque, which keeps
//! the contact passive. Physics and formulas: `docs/physics.md`.

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![deny(clippy::disallowed_methods)]

#[cfg(feature = "std")]
extern crate std;

#[cfg(feature = "arbitrary")]
mod fuzz_inputs;
mod law;
mod seam;
#[cfg(feature = "proptest")]
pub mod strategies;
mod value;

pub mod prelude;
pub mod slots;

pub use law::checks;
pub use seam::executor;
pub use value::motion;

// The crate's own code and docs name the prelude's items from the root.
use prelude::*;
