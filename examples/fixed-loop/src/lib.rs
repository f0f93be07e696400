//! A firmware-style simulation loop: a fixed number of spheres settling in an open box under
//! gravity, `f32`, Model AA, with every buffer sized at compile time and no heap.
//!
//! It shows both ways of keeping tangential history: the sphere-sphere springs live in the
//! kernel's fixed-capacity [`ContactHistory`]; the sphere-wall springs live in a plain array the
//! loop owns. The spheres are [`CheckedSphere`]s evaluated through the law bound to its step
//! ([`ContactLaw::at`]), the checked path every engine uses. It does not use the scene crate
//! (`examples/scene`) because at 16 spheres the plain all-pairs loop a firmware writer would write
//! is simpler than a cell grid, and showing that loop is its point.
//!
//! [`BoxScene`] is generic over the math backend; [`settle_with_libm`] and
//! [`settle_with_micromath`] are concrete instances, so building this crate for a bare-metal
//! target compiles the kernel with both backends.
//!
//! ```
//! let summary = fixed_loop::settle_with_libm(2_000).expect("valid scene");
//! assert!(summary.kinetic_energy >= 0.0);
//! ```

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    CheckedSphere, ContactError, ContactHistory, ContactKey, ContactLaw, Interaction, Libm,
    LinearLaw, LinearSpringDashpot, MathBackend, Micromath, ModelAA, ParameterError, Sphere,
    SpringDisplacement, TangentialParameters, TimeStep, Vec3, Wall, effective_mass,
};

/// Number of spheres.
pub const SPHERES: usize = 16;
/// Floor and four side walls; the box is open at the top.
pub const WALLS: usize = 5;
/// Room for simultaneous sphere-sphere contacts in the history store (a power of two above the 6
/// per sphere that a dense layer can reach, halved because each contact is shared).
pub const PAIR_CAPACITY: usize = 64;
/// Sphere radius (m).
pub const RADIUS: f32 = 1.0e-3;
/// Side of the square box (m).
pub const BOX_SIDE: f32 = 8.0e-3;
/// Sphere density (kg/m^3).
pub const DENSITY: f32 = 2500.0;
/// Gravitational acceleration (m/s^2), along -z.
pub const GRAVITY: f32 = 9.81;

/// The law every contact of the scene uses.
pub type LoopLaw<M> = LinearLaw<f32, ModelAA<f32>, M>;

/// Energies of the scene at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Summary {
    /// Translational plus rotational kinetic energy (J).
    pub kinetic_energy: f32,
    /// Gravitational potential energy above the floor (J).
    pub potential_energy: f32,
    /// Sphere-sphere contacts currently stored.
    pub pair_contacts: usize,
}

/// Spheres in an open box, stepped with fixed-size buffers only.
#[derive(Clone, Debug)]
pub struct BoxScene<M: MathBackend<f32>> {
    /// The spheres, in the caller's index order.
    pub spheres: [CheckedSphere<f32>; SPHERES],
    walls: [Wall<f32>; WALLS],
    wall_springs: [[SpringDisplacement<f32>; WALLS]; SPHERES],
    pair_springs: ContactHistory<SpringDisplacement<f32>, PAIR_CAPACITY>,
    law: LoopLaw<M>,
    time_step: TimeStep<f32>,
}

impl<M: MathBackend<f32>> BoxScene<M> {
    /// Spheres on a jittered lattice above the floor, at rest. `k_n = 1000 N/m`,
    /// `k_t = 2/7 k_n`, `e = 0.5`, `eta_t = eta_n / 2`, `mu = 0.5`, `dt = t_c / 50`.
    ///
    /// # Errors
    /// Only if the constants above were edited into an invalid law or sphere.
    pub fn new() -> Result<Self, SceneError> {
        let normal = LinearSpringDashpot::new(1000.0, 0.5)?;
        let tangential = ModelAA(TangentialParameters::new(1000.0 * 2.0 / 7.0, 0.5, 0.5)?);
        let law = ContactLaw::new(normal, tangential).with_backend::<M>();
        let mut plain = [Sphere::default(); SPHERES];
        for (k, sphere) in plain.iter_mut().enumerate() {
            let (column, layer) = (k % 4, k / 4);
            // A fixed, index-derived jitter so the column does not stack perfectly.
            let jitter = ((k * 7919) % 13) as f32 / 13.0 - 0.5;
            let position = Vec3::new(
                2.0e-3 + 3.5e-3 * (column % 2) as f32 + 0.2e-3 * jitter,
                2.0e-3 + 3.5e-3 * (column / 2) as f32 - 0.2e-3 * jitter,
                1.5e-3 + 2.5e-3 * layer as f32,
            );
            *sphere = Sphere::solid(position, RADIUS, DENSITY);
        }
        let mut spheres = [CheckedSphere::new(plain[0])?; SPHERES];
        for (checked, sphere) in spheres.iter_mut().zip(plain) {
            *checked = CheckedSphere::new(sphere)?;
        }
        let pair_mass = effective_mass(spheres[0].mass, spheres[1].mass);
        let time_step = law.time_step(law.recommended_time_step(pair_mass), pair_mass)?;
        let side = BOX_SIDE;
        let walls = [
            Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0))?,
            Wall::new(Vec3::ZERO, Vec3::new(1.0, 0.0, 0.0))?,
            Wall::new(Vec3::new(side, 0.0, 0.0), Vec3::new(-1.0, 0.0, 0.0))?,
            Wall::new(Vec3::ZERO, Vec3::new(0.0, 1.0, 0.0))?,
            Wall::new(Vec3::new(0.0, side, 0.0), Vec3::new(0.0, -1.0, 0.0))?,
        ];
        Ok(Self {
            spheres,
            walls,
            wall_springs: [[SpringDisplacement::default(); WALLS]; SPHERES],
            pair_springs: ContactHistory::new(),
            law,
            time_step,
        })
    }

    /// The checked time step (s).
    pub fn time_step(&self) -> f32 {
        self.time_step.seconds()
    }

    /// One step: all contact forces at the current state, then symplectic Euler.
    ///
    /// # Errors
    /// A [`ContactError`] from the kernel (including a full pair store). The spheres are then
    /// not moved; contact states evaluated earlier in the same step have already advanced, so
    /// treat the error as the end of the run (as firmware would).
    pub fn step(&mut self) -> Result<(), ContactError> {
        let mut law = self.law.at(self.time_step);
        let mut forces = [Vec3::ZERO; SPHERES];
        let mut torques = [Vec3::ZERO; SPHERES];
        for (k, sphere) in self.spheres.iter().enumerate() {
            forces[k] = Vec3::new(0.0, 0.0, -GRAVITY * sphere.mass);
        }
        for i in 0..SPHERES {
            for j in i + 1..SPHERES {
                let (a, b) = (&self.spheres[i], &self.spheres[j]);
                let key = ContactKey::new(i as u32, j as u32);
                let interaction = self
                    .pair_springs
                    .evaluate(key, |spring| law.sphere_sphere(a, b, spring))?;
                if let Interaction::Touching(contact) = interaction {
                    forces[i] += contact.force_on_i();
                    forces[j] += contact.force_on_j();
                    torques[i] += contact.torque_on_i;
                    torques[j] += contact.torque_on_j;
                }
            }
            for (w, wall) in self.walls.iter().enumerate() {
                let spring = &mut self.wall_springs[i][w];
                let interaction = law.sphere_wall(&self.spheres[i], wall, spring)?;
                if let Interaction::Touching(contact) = interaction {
                    forces[i] += contact.force_on_i();
                    torques[i] += contact.torque_on_i;
                }
            }
        }
        let dt = self.time_step;
        for (k, sphere) in self.spheres.iter_mut().enumerate() {
            sphere.update(|s| advance_solid_sphere(s, forces[k], torques[k], dt))?;
        }
        Ok(())
    }

    /// A 64-bit FNV-1a hash of every position, velocity and angular velocity bit: equal
    /// fingerprints mean bit-identical states (used to compare a Cortex-M run with the host's).
    pub fn fingerprint(&self) -> u64 {
        let mut hash = 0xcbf2_9ce4_8422_2325u64;
        for s in &self.spheres {
            for v in [s.position, s.velocity, s.angular_velocity] {
                for x in v.to_array() {
                    for byte in x.to_bits().to_le_bytes() {
                        hash = (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
                    }
                }
            }
        }
        hash
    }

    /// Energies now.
    pub fn summary(&self) -> Summary {
        let mut kinetic_energy = 0.0;
        let mut potential_energy = 0.0;
        for s in &self.spheres {
            kinetic_energy += 0.5 * s.mass * s.velocity.norm_squared()
                + 0.5 * s.solid_moment_of_inertia() * s.angular_velocity.norm_squared();
            potential_energy += s.mass * GRAVITY * s.position.z;
        }
        Summary {
            kinetic_energy,
            potential_energy,
            pair_contacts: self.pair_springs.len(),
        }
    }
}

/// Why a run stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SceneError {
    /// The scene's constants make an invalid law.
    Parameter(ParameterError),
    /// A contact evaluation was rejected.
    Contact(ContactError),
}

impl From<ParameterError> for SceneError {
    fn from(e: ParameterError) -> Self {
        Self::Parameter(e)
    }
}

impl From<ContactError> for SceneError {
    fn from(e: ContactError) -> Self {
        Self::Contact(e)
    }
}

/// Builds the scene and runs `steps` steps.
fn settle<M: MathBackend<f32>>(steps: u32) -> Result<Summary, SceneError> {
    let mut scene = BoxScene::<M>::new()?;
    for _ in 0..steps {
        scene.step()?;
    }
    Ok(scene.summary())
}

/// The scene after `steps` steps, per-contact math with libm.
///
/// # Errors
/// See [`SceneError`].
pub fn settle_with_libm(steps: u32) -> Result<Summary, SceneError> {
    settle::<Libm>(steps)
}

/// The scene after `steps` steps, per-contact math with micromath's approximations.
///
/// # Errors
/// See [`SceneError`].
pub fn settle_with_micromath(steps: u32) -> Result<Summary, SceneError> {
    settle::<Micromath>(steps)
}
