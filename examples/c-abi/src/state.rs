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
    /// Whether the state is kept, `!= Default::default()`. Touching and apart pairs come in no
    /// order a processor can predict, so the states of a few numbers say it without a branch
    /// ([`any_nonzero`]).
    #[inline(always)]
    fn keeps(&self) -> bool {
        *self != Default::default()
    }
}

/// Whether any of `values` is other than zero (`-0.0` is zero, NaN is not), without a branch
/// per number: a sum of magnitudes is zero exactly when every one of them is, since adding a
/// non-negative number never rounds below the larger of the two.
#[inline(always)]
pub(crate) fn any_nonzero<F: Float, const N: usize>(values: [F; N]) -> bool {
    values.iter().fold(F::ZERO, |sum, v| sum + v.abs()) != F::ZERO
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
    #[inline(always)]
    fn keeps(&self) -> bool {
        let d = self.displacement;
        any_nonzero([d.x, d.y, d.z])
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
    #[inline(always)]
    fn keeps(&self) -> bool {
        let f = self.force;
        any_nonzero([f.x, f.y, f.z, self.contact_radius])
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
    #[inline(always)]
    fn keeps(&self) -> bool {
        let t = self.torque;
        self.tangential.keeps() | any_nonzero([t.x, t.y, t.z])
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Numbers a stored state can hold: both zeros, the smallest subnormal, ordinary values of
    /// both signs (two that cancel), the infinities and NaN.
    const SPECIAL: [f64; 9] = [
        0.0,
        -0.0,
        f64::from_bits(1),
        1.0,
        -1.0,
        -2.5e-300,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];

    /// `keeps` is `!= Default::default()` for every state of the stored-spring laws, over
    /// every combination of the special numbers (two of them per state, the rest zero, in every
    /// place).
    #[test]
    fn keeps_is_not_the_default_state() {
        for (a, b) in SPECIAL
            .iter()
            .flat_map(|&a| SPECIAL.iter().map(move |&b| (a, b)))
        {
            for (p, q) in [(0, 1), (0, 2), (1, 2), (2, 3), (0, 3), (3, 5), (4, 5)] {
                let mut v = [0.0; 6];
                v[p] = a;
                v[q] = b;
                let spring = SpringDisplacement::<f64>::read(&v[..3]);
                let mindlin = MindlinSpring::<f64>::read(&v[..4]);
                let rolling = RollingSpring::<MindlinSpring<f64>, f64>::read(&{
                    let mut w = [0.0; 7];
                    w[1..].copy_from_slice(&v);
                    w
                });
                assert_eq!(spring.keeps(), spring != Default::default(), "{v:?}");
                assert_eq!(mindlin.keeps(), mindlin != Default::default(), "{v:?}");
                assert_eq!(rolling.keeps(), rolling != Default::default(), "{v:?}");
            }
        }
        // The micro-slip profile, by the comparison itself: relaxed, and with one number set.
        type Profile = MicroSlipSprings<f64, 4>;
        assert!(!Profile::default().keeps());
        for place in 0..Profile::VALUES {
            let mut v = [0.0; Profile::VALUES];
            v[place] = 1.0;
            assert!(Profile::read(&v).keeps(), "{place}");
        }
    }
}
