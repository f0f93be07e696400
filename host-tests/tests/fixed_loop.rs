//! The firmware-style example scene (examples/fixed-loop): spheres dropped into an open box come to
//! rest on the floor, inside the walls, without the total energy ever rising above its start.
//! (The law has no rolling resistance, so a sphere left rolling on the floor keeps a little
//! kinetic energy for a long time: "at rest" means almost all of the drop's energy is gone.)

use fixed_loop::{BOX_SIDE, BoxScene, RADIUS, SPHERES};
use soft_sphere::prelude::{Libm, MathBackend, Micromath};

fn settles<M: MathBackend<f32>>(name: &str) {
    let mut scene = BoxScene::<M>::new().unwrap();
    let start = scene.summary();
    let initial_energy = start.kinetic_energy + start.potential_energy;
    // 0.37 s of settling at dt = t_c/50.
    for step in 0..80_000 {
        scene
            .step()
            .unwrap_or_else(|e| panic!("{name}: step {step}: {e}"));
        if step % 500 == 0 {
            let now = scene.summary();
            let energy = now.kinetic_energy + now.potential_energy;
            assert!(
                energy <= initial_energy * (1.0 + 1e-6),
                "{name}: step {step}: energy {energy} rose above {initial_energy}"
            );
        }
    }
    let end = scene.summary();
    assert!(
        end.kinetic_energy < 1e-4 * start.potential_energy,
        "{name}: still moving ({:e} J)",
        end.kinetic_energy
    );
    // The pile dropped: 16 spheres of 2 mm in an 8 mm box rest in one to two layers.
    assert!(
        end.potential_energy < 0.3 * start.potential_energy,
        "{name}: {end:?}"
    );
    assert!(
        end.pair_contacts >= SPHERES / 2,
        "{name}: {} pair contacts",
        end.pair_contacts
    );
    // Overlaps stay small (m g / k_n is 0.1 um): every sphere inside the box to within 1 % of R,
    // and none left higher than 5.4 R (a third layer would put centres near 5 R and above).
    let slack = 0.01 * RADIUS;
    for s in &scene.spheres {
        let p = s.position;
        assert!(p.z > RADIUS - slack && p.z < 5.4 * RADIUS, "{name}: {p:?}");
        for c in [p.x, p.y] {
            assert!(
                c > RADIUS - slack && c < BOX_SIDE - RADIUS + slack,
                "{name}: {p:?}"
            );
        }
    }
}

#[test]
fn spheres_settle_in_the_box_with_libm() {
    settles::<Libm>("libm");
}

#[test]
fn spheres_settle_in_the_box_with_micromath() {
    settles::<Micromath>("micromath");
}
