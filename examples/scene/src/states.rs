//! The double-buffered contact states: a step reads the current buffer and the list seam
//! writes the next one in full, so a refused step leaves the history untouched without a copy;
//! a committed step swaps the two. The caller's `states` buffer holds the current ones in front
//! again once the scene is dropped ([`SceneBuffers`](crate::SceneBuffers)).

use soft_sphere::prelude::Law;

use crate::Scene;

impl<L: Law, W, const K: usize> Scene<'_, L, W, K> {
    /// A committed step's states become the current ones: the two buffers trade places.
    pub(crate) fn flip(&mut self) {
        core::mem::swap(&mut self.pair_states, &mut self.next_pair_states);
        core::mem::swap(&mut self.wall_states, &mut self.next_wall_states);
        self.flipped = !self.flipped;
    }
}

/// The history goes back to the front of the caller's `states` buffer, where the next scene
/// over the same buffers looks for it: one copy per scene, not per step.
impl<L: Law, W, const K: usize> Drop for Scene<'_, L, W, K> {
    fn drop(&mut self) {
        if self.flipped {
            self.next_pair_states.copy_from_slice(self.pair_states);
            self.next_wall_states.copy_from_slice(self.wall_states);
        }
    }
}

// The owned scene makes the buffers (the `alloc` feature, which the workspace's tests enable).
#[cfg(all(test, feature = "alloc"))]
mod tests {
    use soft_sphere::prelude::{
        ContactLaw, LinearSpringDashpot, MaterialTable, ModelAA, Sphere, TangentialParameters, Vec3,
    };

    use crate::{Domain, Integrator, NoWalls, OwnedScene, StepInput};

    /// A gas of spinning spheres in a periodic layer, colliding all the time: the list grows
    /// and shrinks at its frequent rebuilds while springs are stored, and both state buffers
    /// stay relaxed past the list (what the next scene over the buffers relies on, and what
    /// the swap would otherwise bring back).
    #[test]
    fn both_buffers_stay_relaxed_past_a_shrinking_list() {
        let law = ContactLaw::new(
            LinearSpringDashpot::new(1.0e4_f64, 0.5).unwrap(),
            ModelAA(TangentialParameters::new(8.0e3, 0.5, 0.4).unwrap()),
        );
        let table = MaterialTable::<_, 1>::uniform(law);
        let side = 0.012;
        let domain = Domain {
            lower: Vec3::ZERO,
            upper: Vec3::new(side, side, 0.002),
            periodic_x: true,
            periodic_y: true,
        };
        // A fixed linear congruential stream: the test is the same on every machine.
        let mut seed = 12_345_u64;
        let mut unit = move || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let spheres: [Sphere<f64>; 81] = core::array::from_fn(|k| {
            let at = Vec3::new((k % 9) as f64 + 0.5, (k / 9) as f64 + 0.5, 0.0) * (side / 9.0);
            let mut s = Sphere::solid(at + Vec3::new(0.0, 0.0, 0.001), 5.0e-4, 2500.0);
            s.velocity = Vec3::new(unit() - 0.5, unit() - 0.5, 0.0);
            s.angular_velocity = Vec3::new(unit() - 0.5, unit() - 0.5, unit() - 0.5) * 2000.0;
            s
        });
        let mut scene =
            OwnedScene::<_, NoWalls>::new(spheres.into(), domain, 1.0e-5, NoWalls).unwrap();
        let time_step = scene
            .scene(|s| s.time_step(&table, 5.0e-7))
            .unwrap()
            .unwrap();
        let input = StepInput {
            table: &table,
            gravity: Vec3::ZERO,
            time_step,
            integrator: Integrator::SymplecticEuler,
        };
        let relaxed = |states: &[_]| states.iter().all(|s| *s == Default::default());
        let mut shrunk_with_springs = 0;
        scene
            .scene(|s| {
                let mut last = (usize::MAX, false);
                for _ in 0..3000 {
                    s.step(&input).unwrap();
                    let count = s.candidate_count;
                    shrunk_with_springs += usize::from(count < last.0 && last.1);
                    last = (count, !relaxed(&s.pair_states[..count]));
                    assert!(relaxed(&s.pair_states[count..]));
                    assert!(relaxed(&s.next_pair_states[count..]));
                }
            })
            .unwrap();
        assert!(
            shrunk_with_springs > 5,
            "{shrunk_with_springs} shrinking builds"
        );
    }
}
