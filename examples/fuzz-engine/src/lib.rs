//! A user's own small engine: spheres in a box of walls, every pair tried each step, the
//! per-pair springs in a map, symplectic Euler. Nothing here is the kernel's: it only calls the
//! kernel's public API, as any engine would, and `tests/fuzz.rs` fuzzes it with the kernel's
//! strategies and checks.

use std::collections::HashMap;

use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    ContactError, ContactForces, ContactLaw, Interaction, LinearAA, LinearSpringDashpot, ModelAA,
    Sphere, SpringDisplacement, TangentialParameters, TimeStep, Vec3, Wall,
};

/// The law this engine uses.
pub type Linear = LinearAA<f64>;

/// The engine's whole state.
#[derive(Clone, Debug)]
pub struct Engine {
    /// The spheres.
    pub spheres: Vec<Sphere<f64>>,
    /// The walls.
    pub walls: Vec<Wall<f64>>,
    /// The springs of the pairs in contact, `(i, j)` with `i < j`.
    pub springs: HashMap<(usize, usize), SpringDisplacement<f64>>,
    /// The springs of the sphere-wall contacts, `(sphere, wall)`.
    pub wall_springs: HashMap<(usize, usize), SpringDisplacement<f64>>,
    law: Linear,
    step: TimeStep<f64>,
}

/// One contact of a step, for whoever wants to look.
#[derive(Clone, Copy, Debug)]
pub struct Touch {
    /// The spheres (`j` is `None` for a wall).
    pub i: usize,
    /// The other sphere.
    pub j: Option<usize>,
    /// What the kernel said.
    pub forces: ContactForces<f64>,
}

impl Engine {
    /// An engine with the given spheres and walls, `k_n`, `e`, `k_t = 2/7 k_n`, `mu`, stepped
    /// at the kernel's recommended step for the lightest pair.
    ///
    /// # Errors
    /// The kernel's, for bad coefficients or masses.
    pub fn new(
        spheres: Vec<Sphere<f64>>,
        walls: Vec<Wall<f64>>,
        (stiffness, restitution, friction): (f64, f64, f64),
    ) -> Result<Self, soft_sphere::prelude::ParameterError> {
        let law = ContactLaw::new(
            LinearSpringDashpot::new(stiffness, restitution)?,
            ModelAA(TangentialParameters::new(
                2.0 / 7.0 * stiffness,
                0.5,
                friction,
            )?),
        );
        let lightest = spheres.iter().map(|s| s.mass).fold(f64::INFINITY, f64::min) / 2.0;
        let step = law.time_step(law.recommended_time_step(lightest), lightest)?;
        Ok(Self {
            spheres,
            walls,
            springs: HashMap::new(),
            wall_springs: HashMap::new(),
            law,
            step,
        })
    }

    /// One step: every pair and every sphere-wall contact, then the motion. All or nothing: on
    /// an error the engine is left as it was.
    ///
    /// # Errors
    /// The first contact the kernel refused.
    pub fn step(&mut self) -> Result<Vec<Touch>, ContactError> {
        let n = self.spheres.len();
        let mut springs = self.springs.clone();
        let mut wall_springs = self.wall_springs.clone();
        let mut force = vec![Vec3::ZERO; n];
        let mut torque = vec![Vec3::ZERO; n];
        let mut touches = Vec::new();
        for i in 0..n {
            for j in i + 1..n {
                let mut spring = springs.get(&(i, j)).copied().unwrap_or_default();
                let outcome = self.law.sphere_sphere(
                    &self.spheres[i],
                    &self.spheres[j],
                    &mut spring,
                    self.step,
                )?;
                if let Interaction::Touching(f) = outcome {
                    springs.insert((i, j), spring);
                    force[i] += f.force_on_i();
                    force[j] += f.force_on_j();
                    torque[i] += f.torque_on_i;
                    torque[j] += f.torque_on_j;
                    touches.push(Touch {
                        i,
                        j: Some(j),
                        forces: f,
                    });
                } else {
                    springs.remove(&(i, j));
                }
            }
            for (w, wall) in self.walls.iter().enumerate() {
                let mut spring = wall_springs.get(&(i, w)).copied().unwrap_or_default();
                match self
                    .law
                    .sphere_wall(&self.spheres[i], wall, &mut spring, self.step)?
                {
                    Interaction::Touching(f) => {
                        wall_springs.insert((i, w), spring);
                        force[i] += f.force_on_i();
                        torque[i] += f.torque_on_i;
                        touches.push(Touch {
                            i,
                            j: None,
                            forces: f,
                        });
                    }
                    Interaction::Apart => {
                        wall_springs.remove(&(i, w));
                    }
                }
            }
        }
        for (k, sphere) in self.spheres.iter_mut().enumerate() {
            advance_solid_sphere(sphere, force[k], torque[k], self.step);
        }
        self.springs = springs;
        self.wall_springs = wall_springs;
        Ok(touches)
    }
}
