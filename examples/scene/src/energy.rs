//! The scene's energy account: where the energy of the spheres went, step by step.
//!
//! Kinetic and rotational energy are read from the spheres; the energy stored in the contacts'
//! springs from the kernel ([`Law::stored_energy`]); gravity's work is summed over each drift as
//! the integrator moves the spheres, and a moving wall's as the force on it times its velocity.
//! What the contacts took from the spheres and do not hold is dissipated: each step, a
//! contact's power into the spheres (`F_j . (v_j - v_i) + T_i . w_i + T_j . w_j`) times the step,
//! less the change of its stored energy. The normal part goes to the dashpots; the tangential
//! and rolling part to the sliders when the contact slid that step, else to the dashpots. The
//! balance `kinetic + rotational + stored + dissipated - gravity_work - wall_work` is then
//! constant up to the integrator's error, which falls with the step (`docs/physics.md`, 4.3).

use soft_sphere::{Float, Interaction, Law, MaterialTable};

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

/// The running totals of the energy account, and what the last step's contacts will have
/// dissipated by the next (their power covers the step that follows their evaluation).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Ledger<F> {
    started: bool,
    stored: F,
    normal_stored: F,
    pub(crate) gravity_work: F,
    wall_work: F,
    dashpots: F,
    sliding: F,
    pending_normal_power: F,
    pending_dashpots: F,
    pending_sliding: F,
    pending_wall_work: F,
}

impl<F: Float> Ledger<F> {
    /// The account without the spheres' motion (filled in by `account_motion`).
    pub(crate) fn energy(&self) -> Energy<F> {
        Energy {
            kinetic: F::ZERO,
            rotational: F::ZERO,
            stored: self.stored,
            gravity_work: self.gravity_work,
            wall_work: self.wall_work,
            dissipated_dashpots: self.dashpots,
            dissipated_sliding: self.sliding,
        }
    }
}

/// The sums of one step's contacts.
#[derive(Clone, Copy, Debug, Default)]
struct Sums<F> {
    normal_stored: F,
    spring_stored: F,
    normal_power: F,
    dashpots: F,
    sliding: F,
    wall_work: F,
}

impl<L: Law, W: WallSet<L::Float>, const K: usize> Scene<'_, L, W, K> {
    /// Books the contacts of a committed evaluation: their stored energy now, what the last
    /// step's contacts dissipated, and what this step's will. Reads the records, the states
    /// after the step and the seam's copy of the states before it.
    pub(crate) fn account_contacts<const M: usize>(
        &mut self,
        table: &MaterialTable<L, M>,
        dt: L::Float,
    ) {
        let count = self.candidate_count;
        let mut sums = Sums::default();
        for k in 0..count {
            let [i, j] = self.pairs[k].map(|x| x as usize);
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
            let states = (&self.saved_states[k], &self.pair_states[k]);
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
                let velocity = wall.wall.velocity();
                let motion = [
                    (sphere.velocity, sphere.angular_velocity),
                    (velocity, soft_sphere::Vec3::ZERO),
                ];
                let states = (
                    &self.saved_states[k],
                    &self.wall_states[s * walls.len() + w],
                );
                let record = &self.records[k];
                book(law, (sphere.radius, dt), motion, states, record, &mut sums);
                if let Interaction::Touching(c) = record {
                    // The drive that keeps the wall moving against the contact's push.
                    sums.wall_work -= c.force_on_j().dot(velocity) * dt;
                }
            }
        }
        let ledger = &mut self.ledger;
        if ledger.started {
            let normal_change = sums.normal_stored - ledger.normal_stored;
            ledger.dashpots +=
                ledger.pending_dashpots - ledger.pending_normal_power * dt - normal_change;
            ledger.sliding += ledger.pending_sliding;
            ledger.wall_work += ledger.pending_wall_work;
        }
        ledger.started = true;
        ledger.normal_stored = sums.normal_stored;
        ledger.stored = sums.normal_stored + sums.spring_stored;
        ledger.pending_normal_power = sums.normal_power;
        ledger.pending_dashpots = sums.dashpots;
        ledger.pending_sliding = sums.sliding;
        ledger.pending_wall_work = sums.wall_work;
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

/// One contact's share of a step: the springs it holds before the step (its state then, the
/// normal spring at this overlap), and what it dissipates over the step. `motion` is the
/// velocity and spin of body i and body j (a wall's velocity and no spin); `states` the state
/// before and after the step.
fn book<L: Law>(
    law: &L,
    (radius, dt): (L::Float, L::Float),
    [(v_i, w_i), (v_j, w_j)]: [(soft_sphere::Vec3<L::Float>, soft_sphere::Vec3<L::Float>); 2],
    (before, after): (&L::State, &L::State),
    record: &Interaction<L::Float>,
    sums: &mut Sums<L::Float>,
) {
    let zero = L::Float::ZERO;
    // At zero overlap the normal spring holds nothing: what is left is the tangential and
    // rolling springs of the state.
    let spring_before = law.stored_energy(zero, radius, before);
    sums.spring_stored += spring_before;
    match record {
        Interaction::Touching(c) => {
            let spring_after = law.stored_energy(zero, radius, after);
            sums.normal_stored += law.stored_energy(c.overlap, radius, after) - spring_after;
            let relative = v_j - v_i;
            let normal_power = c.normal_force * relative.dot(c.normal);
            let power =
                c.force_on_j().dot(relative) + c.torque_on_i.dot(w_i) + c.torque_on_j.dot(w_j);
            sums.normal_power += normal_power;
            let loss = -(power - normal_power) * dt - (spring_after - spring_before);
            if c.sliding {
                sums.sliding += loss;
            } else {
                sums.dashpots += loss;
            }
        }
        // A contact that parted let its springs go: their energy is lost to the spheres.
        Interaction::Apart => sums.dashpots += spring_before,
    }
}
