//! How each law's per-contact state sits in the caller's memory: in an `ss_state` for the
//! single-contact calls, as flat numbers in a host's per-neighbour history for the list entry.

use soft_sphere::prelude::{
    ContactState, Float, MicroSlipSprings, MindlinSpring, RollingSpring, SpringDisplacement, Vec3,
};

use crate::*;

/// How a law's per-contact state is kept flat, as numbers in a host's per-neighbour history
/// (the list entry's).
pub(crate) trait Flat<F: Float>: ContactState {
    /// How many numbers the state is when kept flat.
    const VALUES: usize;
    /// The state from its `VALUES` flat numbers.
    fn read(values: &[F]) -> Self;
    /// The state into its `VALUES` flat numbers.
    fn write(&self, values: &mut [F]);
    /// The same contact's state seen from the other body (i and j swapped).
    fn mirrored(&self) -> Self;
}

/// How a law's per-contact state sits in the caller's [`ss_state`] (the single-contact calls').
pub(crate) trait Stored<F: Float>: Flat<F> {
    /// Which of `ss_state_arrays`' arrays the batch call needs for this state.
    const ARRAYS: StateArrays;
    fn load(state: &ss_state<F>) -> Self;
    fn store(&self, state: &mut ss_state<F>);
}

/// The arrays a law's state lives in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum StateArrays {
    None,
    Displacement,
    Mindlin,
}

/// The normal, the contact radius, each breakpoint's position, then each one's displacement.
impl<F: Float, const SPRINGS: usize> Flat<F> for MicroSlipSprings<F, SPRINGS> {
    const VALUES: usize = 4 * SPRINGS + 4;
    fn read(values: &[F]) -> Self {
        let vector = |k: usize| Vec3::new(values[k], values[k + 1], values[k + 2]);
        let mut springs = MicroSlipSprings {
            normal: vector(0),
            contact_radius: values[3],
            ..Default::default()
        };
        springs.positions.copy_from_slice(&values[4..4 + SPRINGS]);
        for (k, u) in springs.displacements.iter_mut().enumerate() {
            *u = vector(4 + SPRINGS + 3 * k);
        }
        springs
    }
    fn write(&self, values: &mut [F]) {
        let n = self.normal;
        values[..4].copy_from_slice(&[n.x, n.y, n.z, self.contact_radius]);
        values[4..4 + SPRINGS].copy_from_slice(&self.positions);
        for (k, u) in self.displacements.iter().enumerate() {
            let at = 4 + SPRINGS + 3 * k;
            values[at..at + 3].copy_from_slice(&[u.x, u.y, u.z]);
        }
    }
    /// Seen from the other body the normal and every displacement are negated.
    fn mirrored(&self) -> Self {
        let mut springs = *self;
        springs.normal = -self.normal;
        for u in &mut springs.displacements {
            *u = -*u;
        }
        springs
    }
}

impl<F: Float> Flat<F> for () {
    const VALUES: usize = 0;
    #[inline(always)]
    fn read(_: &[F]) -> Self {}
    #[inline(always)]
    fn write(&self, _: &mut [F]) {}
    fn mirrored(&self) -> Self {}
}

impl<F: Float> Stored<F> for () {
    const ARRAYS: StateArrays = StateArrays::None;
    #[inline(always)]
    fn load(_: &ss_state<F>) -> Self {}
    #[inline(always)]
    fn store(&self, _: &mut ss_state<F>) {}
}

impl<F: Float> Flat<F> for SpringDisplacement<F> {
    const VALUES: usize = 3;
    #[inline(always)]
    fn read(values: &[F]) -> Self {
        SpringDisplacement {
            displacement: Vec3::new(values[0], values[1], values[2]),
        }
    }
    #[inline(always)]
    fn write(&self, values: &mut [F]) {
        let d = self.displacement;
        values[..3].copy_from_slice(&[d.x, d.y, d.z]);
    }
    /// The displacement of j relative to i: negated.
    fn mirrored(&self) -> Self {
        SpringDisplacement {
            displacement: -self.displacement,
        }
    }
}

impl<F: Float> Stored<F> for SpringDisplacement<F> {
    const ARRAYS: StateArrays = StateArrays::Displacement;
    #[inline(always)]
    fn load(state: &ss_state<F>) -> Self {
        SpringDisplacement {
            displacement: state.displacement.into(),
        }
    }
    #[inline(always)]
    fn store(&self, state: &mut ss_state<F>) {
        state.displacement = self.displacement.into();
    }
}

impl<F: Float> Flat<F> for MindlinSpring<F> {
    const VALUES: usize = 4;
    #[inline(always)]
    fn read(values: &[F]) -> Self {
        MindlinSpring {
            force: Vec3::new(values[0], values[1], values[2]),
            contact_radius: values[3],
        }
    }
    #[inline(always)]
    fn write(&self, values: &mut [F]) {
        let f = self.force;
        values[..4].copy_from_slice(&[f.x, f.y, f.z, self.contact_radius]);
    }
    /// The spring's force on j becomes the force on i: negated; the contact radius stays.
    fn mirrored(&self) -> Self {
        MindlinSpring {
            force: -self.force,
            contact_radius: self.contact_radius,
        }
    }
}

impl<F: Float> Stored<F> for MindlinSpring<F> {
    const ARRAYS: StateArrays = StateArrays::Mindlin;
    #[inline(always)]
    fn load(state: &ss_state<F>) -> Self {
        MindlinSpring {
            force: state.spring_force.into(),
            contact_radius: state.contact_radius,
        }
    }
    #[inline(always)]
    fn store(&self, state: &mut ss_state<F>) {
        state.spring_force = self.force.into();
        state.contact_radius = self.contact_radius;
    }
}

/// The rolling spring beside a tangential state: its torque on i after the tangential numbers
/// (the list entry's flat history only; the single-contact calls have no rolling).
impl<F: Float, S: Flat<F>> Flat<F> for RollingSpring<S, F> {
    const VALUES: usize = S::VALUES + 3;
    #[inline(always)]
    fn read(values: &[F]) -> Self {
        let (tangential, torque) = values.split_at(S::VALUES);
        RollingSpring {
            tangential: S::read(tangential),
            torque: Vec3::new(torque[0], torque[1], torque[2]),
        }
    }
    #[inline(always)]
    fn write(&self, values: &mut [F]) {
        let (tangential, torque) = values.split_at_mut(S::VALUES);
        self.tangential.write(tangential);
        let t = self.torque;
        torque[..3].copy_from_slice(&[t.x, t.y, t.z]);
    }
    /// The torque on i becomes the torque on j: negated.
    fn mirrored(&self) -> Self {
        RollingSpring {
            tangential: self.tangential.mirrored(),
            torque: -self.torque,
        }
    }
}

impl<F: Float, S: Stored<F>> Stored<F> for RollingSpring<S, F> {
    const ARRAYS: StateArrays = S::ARRAYS;
    fn load(state: &ss_state<F>) -> Self {
        RollingSpring {
            tangential: S::load(state),
            torque: Vec3::ZERO,
        }
    }
    fn store(&self, state: &mut ss_state<F>) {
        self.tangential.store(state);
    }
}
