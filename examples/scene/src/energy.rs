//! The scene's energy account: where the energy of the spheres went, step by step.
//!
//! Kinetic and rotational energy are read from the spheres. The work of the contact forces and
//! of gravity is booked in every kick exactly as the integrator applies it (a force `F` that
//! takes a velocity from `v` to `v'` in `h` seconds does `F . (v + v') h / 2`), so the kinetic
//! energy's change is the booked work to rounding. The contacts' springs hold what the kernel
//! says they store ([`Law::stored_energy`]); a moving wall's drive does `-F . v_wall` per
//! second. What the contacts took from the spheres and neither hold nor got from a wall's drive
//! is dissipated. Of it, the sliders' share is each sliding contact's tangential power into
//! the spheres at its evaluation, less its springs' change; the rest is the dashpots'. The
//! balance `kinetic + rotational + stored + dissipated - gravity_work - wall_work` is then
//! constant to rounding (`docs/physics.md`, 4.3).

use soft_sphere::prelude::{Float, Interaction, Law, MaterialTable, Vec3};

use crate::{Scene, StepStats, WallSet};

/// Where the energy of a scene is, at the end of a step (J). Counted from the first step whose
/// contacts were recorded; the dissipated and work terms are totals since then.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Energy<F> {
    /// Translational kinetic energy of the spheres.
    pub kinetic: F,
    /// Rotational kinetic energy of the spheres (solid spheres, `2/5 m a^2`).
    pub rotational: F,
    /// Elastic energy held by the contacts' normal, tangential and rolling springs.
    pub stored: F,
    /// Work gravity has done on the spheres.
    pub gravity_work: F,
    /// Work moving walls have done on the spheres.
    pub wall_work: F,
    /// Energy dissipated by the normal dashpots, and by the tangential and rolling dashpots of
    /// contacts that stuck.
    pub dissipated_dashpots: F,
    /// Energy dissipated by contacts that slid (the Coulomb sliders).
    pub dissipated_sliding: F,
}

impl<F: Float> Energy<F> {
    /// What stays constant: `kinetic + rotational + stored + dissipated - gravity_work -
    /// wall_work`.
    pub fn balance(&self) -> F {
        self.kinetic
            + self.rotational
            + self.stored
            + self.dissipated_dashpots
            + self.dissipated_sliding
            - self.gravity_work
            - self.wall_work
    }
}

/// The running totals of the energy account since its first recorded step.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Ledger<F> {
    started: bool,
    /// The stored energy at the first recorded step.
    first_stored: F,
    stored: F,
    /// Work the contact forces and torques did on the spheres in every kick.
    pub(crate) contact_work: F,
    pub(crate) gravity_work: F,
    wall_work: F,
    sliding: F,
}

impl<F: Float> Ledger<F> {
    /// The account without the spheres' motion (filled in by `account_motion`).
    pub(crate) fn energy(&self) -> Energy<F> {
        let dissipated = self.wall_work - self.contact_work - (self.stored - self.first_stored);
        Energy {
            kinetic: F::ZERO,
            rotational: F::ZERO,
            stored: self.stored,
            gravity_work: self.gravity_work,
            wall_work: self.wall_work,
            dissipated_dashpots: dissipated - self.sliding,
            dissipated_sliding: self.sliding,
        }
    }
}

/// The sums of one step's contacts.
#[derive(Clone, Copy, Debug, Default)]
struct Sums<F> {
    stored: F,
    sliding: F,
    wall_work: F,
}

impl<L: Law, W: WallSet<L::Float>, const K: usize> Scene<'_, L, W, K> {
    /// Books the contacts of a committed evaluation: their stored energy, the sliders' share of
    /// the step's dissipation, a moving wall's drive. Reads the records, the states after the
    /// step and the seam's copy of the states before it.
    pub(crate) fn account_contacts<const MATERIALS: usize>(
        &mut self,
        table: &MaterialTable<L, MATERIALS>,
        dt: L::Float,
    ) {
        let count = self.list.len();
        let mut sums = Sums::default();
        for k in 0..count {
            let [i, j] = self.list.checked().pairs()[k].map(|x| x as usize);
            let (a, b) = (&self.spheres[i], &self.spheres[j]);
            let Some(law) = table.law(self.materials[i] as usize, self.materials[j] as usize)
            else {
                continue;
            };
            let radius = a.radius * b.radius / (a.radius + b.radius);
            let motion = [
                (a.velocity, a.angular_velocity),
                (b.velocity, b.angular_velocity),
            ];
            // Called after the flip: the step's states before are in the other buffer.
            let states = (&self.next_pair_states[k], &self.pair_states[k]);
            book(
                law,
                (radius, dt),
                motion,
                states,
                &self.records[k],
                &mut sums,
            );
        }
        let walls = self.walls.walls();
        for (s, sphere) in self.spheres.iter().enumerate() {
            for (w, wall) in walls.iter().enumerate() {
                let k = count + s * walls.len() + w;
                let Some(law) = table.law(self.materials[s] as usize, wall.material as usize)
                else {
                    continue;
                };
                // The wall's surface where the sphere meets it (a turning wall's moves with its
                // turn); the wall's torque is zero, so its spin adds no power.
                let velocity = wall.wall.surface_velocity(sphere.position);
                let motion = [
                    (sphere.velocity, sphere.angular_velocity),
                    (velocity, wall.wall.angular_velocity()),
                ];
                // The wall states follow the pairs' in the records.
                let k_wall = k - count;
                let states = (&self.next_wall_states[k_wall], &self.wall_states[k_wall]);
                let record = &self.records[k];
                book(law, (sphere.radius, dt), motion, states, record, &mut sums);
                if let Interaction::Touching(c) = record {
                    // The drive that keeps the wall moving against the contact's push.
                    sums.wall_work -= c.force_on_j().dot(velocity) * dt;
                }
            }
        }
        let ledger = &mut self.ledger;
        if !ledger.started {
            // The account opens here: work from now on, stored energy measured from now.
            *ledger = Ledger {
                started: true,
                first_stored: sums.stored,
                ..Ledger::default()
            };
        }
        ledger.stored = sums.stored;
        ledger.sliding += sums.sliding;
        ledger.wall_work += sums.wall_work;
    }

    /// The spheres' kinetic and rotational energy into the step's account.
    pub(crate) fn account_motion(&self, stats: &mut StepStats<L::Float>) {
        let Some(energy) = stats.energy.as_mut() else {
            return;
        };
        let half = <L::Float as Float>::HALF;
        for sphere in self.spheres.iter() {
            energy.kinetic += half * sphere.mass * sphere.velocity.norm_squared();
            energy.rotational +=
                half * sphere.solid_moment_of_inertia() * sphere.angular_velocity.norm_squared();
        }
    }
}

/// A body's velocity and spin.
type Motion<F> = (Vec3<F>, Vec3<F>);

/// One contact's share of a step: the springs it holds after the step, and, when it slid, what
/// its slider took (its tangential and rolling power into the spheres over the step, less the
/// change of its springs). `motion` is the velocity and spin of body i and body j (a wall's
/// velocity and no spin); `states` the state before and after the step.
fn book<L: Law>(
    law: &L,
    (radius, dt): (L::Float, L::Float),
    [(v_i, w_i), (v_j, w_j)]: [Motion<L::Float>; 2],
    (before, after): (&L::State, &L::State),
    record: &Interaction<L::Float>,
    sums: &mut Sums<L::Float>,
) {
    let Interaction::Touching(c) = record else {
        return;
    };
    sums.stored += law.stored_energy(c.overlap, radius, after);
    if c.sliding {
        // At zero overlap the normal spring holds nothing: what is left is the tangential and
        // rolling springs of the state.
        let zero = L::Float::ZERO;
        let springs =
            law.stored_energy(zero, radius, after) - law.stored_energy(zero, radius, before);
        let relative = v_j - v_i;
        let power =
            c.tangential_force.dot(relative) + c.torque_on_i.dot(w_i) + c.torque_on_j.dot(w_j);
        sums.sliding += -power * dt - springs;
    }
}
