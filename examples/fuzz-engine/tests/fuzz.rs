//! Fuzzing the engine: the kernel's strategies make the cases, its checks judge them.

use arbitrary::{Arbitrary, Unstructured};
use fuzz_engine::Engine;
use proptest::prelude::*;
use soft_sphere::checks;
use soft_sphere::prelude::{Sphere, Wall};
use soft_sphere::strategies::{collision, touching_pair};

proptest! {
    /// Any binary collision, and the same sphere onto a wall: Coulomb at every contact, and no
    /// energy created once they have parted.
    #[test]
    fn collisions_keep_coulomb_and_create_no_energy(c in collision()) {
        let (i, j) = c.pair::<f64>();
        let (wall, sphere) = c.wall::<f64>();
        let m = c.material;
        let k_n = c.normal_stiffness(i.mass * j.mass / (i.mass + j.mass));
        for (spheres, walls) in [(vec![i, j], vec![]), (vec![sphere], vec![wall])] {
            let mut engine = Engine::new(spheres, walls, (k_n, m.restitution, m.friction))
                .map_err(|e| TestCaseError::fail(format!("{e:?}")))?;
            let before: f64 = engine.spheres.iter().map(checks::kinetic_energy).sum();
            for _ in 0..5_000 {
                for touch in engine.step().map_err(|e| TestCaseError::fail(format!("{e:?}")))? {
                    prop_assert_eq!(checks::coulomb(&touch.forces, m.friction), Ok(()));
                }
            }
            if engine.springs.is_empty() && engine.wall_springs.is_empty() {
                let after: f64 = engine.spheres.iter().map(checks::kinetic_energy).sum();
                prop_assert_eq!(checks::no_energy_created::<f64>(before, after), Ok(()));
            }
        }
    }

    /// Pairs already in contact: swapping the spheres' order gives the reaction.
    #[test]
    fn a_pair_in_either_order_gives_the_reaction((a, b) in touching_pair::<f64>()) {
        let run = |spheres: Vec<Sphere<f64>>| {
            Engine::new(spheres, vec![], (1e3, 0.9, 0.5)).ok()?.step().ok()
        };
        if let (Some(one), Some(two)) = (run(vec![a, b]), run(vec![b, a])) {
            prop_assert_eq!(one.len(), two.len());
            for (x, y) in one.iter().zip(&two) {
                prop_assert_eq!(checks::action_reaction(&x.forces, &y.forces), Ok(()));
            }
        }
    }

    /// Whatever bytes a fuzzer sends: the engine steps or refuses, and a refusal changes nothing.
    #[test]
    fn arbitrary_spheres_step_or_are_refused_whole(bytes in proptest::collection::vec(any::<u8>(), 0..512)) {
        let mut u = Unstructured::new(&bytes);
        let (Ok(a), Ok(b), Ok(wall)) = (Sphere::arbitrary(&mut u), Sphere::arbitrary(&mut u), Wall::arbitrary(&mut u)) else {
            return Ok(());
        };
        let Ok(mut engine) = Engine::new(vec![a, b], vec![wall], (1e3, 0.9, 0.5)) else {
            return Ok(());
        };
        let before = engine.clone();
        match engine.step() {
            Ok(touches) => for t in touches {
                prop_assert_eq!(checks::finite(&t.forces), Ok(()));
                prop_assert_eq!(checks::coulomb(&t.forces, 0.5), Ok(()));
            },
            Err(_) => {
                prop_assert_eq!(format!("{:?}", engine.spheres), format!("{:?}", before.spheres));
                for (key, spring) in &before.springs {
                    prop_assert_eq!(checks::state_unchanged(spring, &engine.springs[key]), Ok(()));
                }
            }
        }
    }
}
