//! A scene of two materials: each contact gets the law of its pair of materials (the same bits
//! as that law applied to the pair directly), the per-contact view lists exactly the touching
//! contacts and adds up to the spheres' loads, and bad material ids are refused with their
//! sphere or wall named.

use host_tests::random::Xorshift;
use host_tests::scene::{Column, OwnedScene};
use soft_sphere::prelude::{
    CheckedSphere, Interaction, LinearMaterial, LinearMixing, LinearStateless, MaterialTable,
    MaterialWall, Sphere, Stateless, Vec3, Wall,
};
use soft_sphere_scene::{ContactBodies, Domain, Integrator, StepError, StepInput};

const DIAMETER: f64 = 1e-3;

type Plain = LinearStateless<f64>;

/// Glass (0) and a stiffer, rougher steel (1), mixed by the field's rules; the stateless law
/// keeps no history, so a contact can be evaluated again outside the scene.
fn table() -> MaterialTable<Plain, 2> {
    let glass = LinearMaterial {
        normal_stiffness: 1000.0,
        restitution: 0.9,
        tangential_stiffness: 285.7,
        dashpot_ratio: 0.5,
        friction: 0.3,
    };
    let steel = LinearMaterial {
        normal_stiffness: 4000.0,
        friction: 0.6,
        ..glass
    };
    let mixing = LinearMixing::new(Stateless);
    MaterialTable::mixed(&mixing, &[glass, steel]).unwrap()
}

/// A squeezed periodic gas of 300 spheres, half of them steel, between a steel floor and a
/// glass ceiling.
fn mixture() -> (OwnedScene<Plain, [MaterialWall<f64>; 2]>, Domain<f64>) {
    let column = Column {
        spheres: 300,
        diameter: DIAMETER,
        density: 2500.0,
        width_x: 0.006,
        width_y: 0.006,
    };
    let (mut spheres, height) = column.lattice::<f64>();
    let mut random = Xorshift::new(11);
    for s in &mut spheres {
        let mut next = || random.unit() - 0.5;
        s.velocity = Vec3::new(next(), next(), next()) * 0.2;
        s.angular_velocity = Vec3::new(next(), next(), next()) * 100.0;
        s.position.z *= 0.85;
    }
    let lowest = spheres
        .iter()
        .map(|s| s.position.z)
        .fold(f64::MAX, f64::min);
    let floor = MaterialWall {
        wall: Wall::new(
            Vec3::new(0.0, 0.0, lowest - 0.45 * DIAMETER),
            Vec3::new(0.0, 0.0, 1.0),
        )
        .unwrap(),
        material: 1,
    };
    let highest = spheres.iter().map(|s| s.position.z).fold(0.0, f64::max);
    let ceiling = MaterialWall {
        wall: Wall::new(
            Vec3::new(0.0, 0.0, highest + 0.45 * DIAMETER),
            Vec3::new(0.0, 0.0, -1.0),
        )
        .unwrap(),
        material: 0,
    };
    // Half of each, at random (the lattice's vertical neighbours would alternate otherwise).
    let materials = spheres
        .iter()
        .map(|_| u32::from(random.unit() < 0.5))
        .collect();
    let domain = column.domain(height);
    let scene = OwnedScene::new(spheres, domain, 1e-4, [floor, ceiling])
        .unwrap()
        .with_materials(materials)
        .unwrap()
        .with_records();
    (scene, domain)
}

#[test]
fn each_contact_of_a_mixture_gets_the_law_of_its_pair_of_materials() {
    let table = table();
    let (mut scene, domain) = mixture();
    let time_step = scene.scene(|s| s.time_step(&table, 2e-6)).unwrap().unwrap();
    let input = StepInput {
        table: &table,
        gravity: Vec3::new(0.0, 0.0, -9.81),
        time_step,
        integrator: Integrator::SymplecticEuler,
    };
    let (lx, ly) = (domain.upper.x, domain.upper.y);
    let mut seen = [[0usize; 2]; 2];
    let mut walls_seen = [0; 2];
    for _ in 0..100 {
        let before = scene.spheres().to_vec();
        let materials = scene.materials().to_vec();
        scene
            .scene(|s| {
                s.step(&input).unwrap();
                let mut touching = 0;
                for view in s.contacts() {
                    touching += 1;
                    let direct = match view.bodies {
                        ContactBodies::Pair([i, j]) => {
                            let (a, b) = (materials[i] as usize, materials[j] as usize);
                            seen[a.min(b)][a.max(b)] += 1;
                            let d = before[j].position - before[i].position;
                            let shift =
                                Vec3::new(-lx * (d.x / lx).round(), -ly * (d.y / ly).round(), 0.0);
                            let image = before[j].translated(shift).unwrap();
                            let law = table.law(a, b).unwrap();
                            law.sphere_sphere(&before[i], &image, &mut (), time_step)
                        }
                        ContactBodies::Wall { sphere, wall } => {
                            walls_seen[wall] += 1;
                            let w = &s.walls()[wall];
                            let law = table
                                .law(materials[sphere] as usize, w.material as usize)
                                .unwrap();
                            law.sphere_wall(&before[sphere], &w.wall, &mut (), time_step)
                        }
                    };
                    assert_eq!(direct, Ok(Interaction::Touching(view.forces)));
                }
                // Every listed contact touches; the loads are their sum, in the same order.
                let mut loads = vec![(Vec3::ZERO, Vec3::ZERO); before.len()];
                for view in s.contacts() {
                    let c = view.forces;
                    match view.bodies {
                        ContactBodies::Pair([i, j]) => {
                            loads[i].0 -= c.force_on_j();
                            loads[i].1 += c.torque_on_i;
                            loads[j].0 += c.force_on_j();
                            loads[j].1 += c.torque_on_j;
                        }
                        ContactBodies::Wall { sphere, .. } => {
                            loads[sphere].0 += c.force_on_i();
                            loads[sphere].1 += c.torque_on_i;
                        }
                    }
                }
                for (k, load) in loads.iter().enumerate() {
                    assert_eq!(s.load(k), Some(*load), "sphere {k}");
                }
                assert!(touching > 0);
            })
            .unwrap();
    }
    // Glass on glass, glass on steel and steel on steel all met, and the floor.
    assert!(
        seen[0][0] > 0 && seen[0][1] > 0 && seen[1][1] > 0,
        "{seen:?}"
    );
    assert!(walls_seen[0] > 0 && walls_seen[1] > 0, "{walls_seen:?}");
}

/// The pairs of materials [`mixture`] presents with the effective mass each is checked at: every
/// pair between spheres (pairs of `m/2`), and each material with the steel floor and the glass
/// ceiling (`m`).
fn present(mass: f64) -> [(usize, usize, f64); 6] {
    [
        (0, 0, mass / 2.0),
        (0, 1, mass / 2.0),
        (1, 1, mass / 2.0),
        (0, 1, mass),
        (1, 1, mass),
        (0, 0, mass),
    ]
}

#[test]
fn the_step_is_checked_against_the_stiffest_pair_of_materials_present() {
    let table = table();
    let (mut scene, _) = mixture();
    let mass = scene.spheres()[0].mass;
    // The smallest limit among the pairs present, and whose it is.
    let present = present(mass);
    let (limit, materials) = present
        .iter()
        .map(|&(a, b, m)| {
            (
                table.law(a, b).unwrap().critical_time_step(m),
                [a as u32, b as u32],
            )
        })
        .fold((f64::INFINITY, [0, 0]), |best, next| {
            if next.0 < best.0 { next } else { best }
        });
    let mut step = |dt| {
        scene
            .scene(|s| s.coarse_time_step(&table, dt).map(|_| ()))
            .unwrap()
    };
    assert_eq!(step(0.99 * limit), Ok(()));
    let refused = step(1.01 * limit);
    assert!(
        matches!(refused, Err(StepError::TimeStep { materials: m, .. }) if m == materials),
        "{refused:?}, the smallest limit {limit:e} s is materials {materials:?}'"
    );
}

#[test]
fn the_recommended_step_is_the_smallest_of_the_pairs_present() {
    let table = table();
    let (mut scene, _) = mixture();
    let mass = scene.spheres()[0].mass;
    let present = present(mass);
    let smallest = present
        .iter()
        .map(|&(a, b, m)| table.law(a, b).unwrap().recommended_time_step(m))
        .fold(f64::INFINITY, f64::min);
    let recommended = scene.scene(|s| s.recommended_time_step(&table)).unwrap();
    assert_eq!(recommended, Ok(Some(smallest)));
    assert!(smallest > 0.0 && smallest.is_finite());
}

#[test]
fn material_ids_past_the_table_are_refused_with_their_sphere_or_wall() {
    let table = table();
    let (scene, _) = mixture();
    let spheres: Vec<Sphere<f64>> = scene.spheres().iter().map(|s| s.into_inner()).collect();
    let domain = *scene.domain();
    let floor = scene.walls()[0];
    let mut materials = scene.materials().to_vec();
    materials[7] = 2;
    let mut bad = OwnedScene::new(spheres.clone(), domain, 1e-4, [floor])
        .unwrap()
        .with_materials(materials)
        .unwrap();
    let time_step = table.law(1, 1).unwrap().time_step(1e-7, 1e-9).unwrap();
    let input = StepInput {
        table: &table,
        gravity: Vec3::ZERO,
        time_step,
        integrator: Integrator::SymplecticEuler,
    };
    let before: Vec<CheckedSphere<f64>> = bad.spheres().to_vec();
    assert_eq!(
        bad.run(&input, 1, |_, _| {}),
        Err(StepError::Material {
            sphere: 7,
            material: 2
        })
    );
    assert_eq!(bad.spheres(), &before[..], "nothing moved");
    assert!(matches!(
        bad.scene(|s| s.time_step(&table, 1e-7)).unwrap(),
        Err(StepError::Material { sphere: 7, .. })
    ));
    let far_wall = MaterialWall {
        material: 5,
        ..floor
    };
    let mut bad_wall = OwnedScene::new(spheres, domain, 1e-4, [far_wall]).unwrap();
    assert_eq!(
        bad_wall.run(&input, 1, |_, _| {}),
        Err(StepError::WallMaterial {
            wall: 0,
            material: 5
        })
    );
    assert_eq!(
        OwnedScene::<Plain, _>::new(vec![], domain, 1e-4, [floor])
            .unwrap()
            .with_materials(vec![0])
            .err(),
        Some(soft_sphere_scene::SceneError::Materials)
    );
}

#[test]
fn a_refused_step_leaves_no_view() {
    let table = table();
    let glass_only = MaterialTable::<Plain, 1>::uniform(*table.law(0, 0).unwrap());
    let (mut scene, _) = mixture();
    let time_step = scene.scene(|s| s.time_step(&table, 2e-6)).unwrap().unwrap();
    let input = |integrator| (time_step, integrator);
    scene
        .scene(|s| {
            let (dt, integrator) = input(Integrator::SymplecticEuler);
            let good = StepInput {
                table: &table,
                gravity: Vec3::ZERO,
                time_step: dt,
                integrator,
            };
            s.step(&good).unwrap();
            assert!(s.contacts().count() > 0);
            // Steel is not a material of this table: the step is refused, and what the records
            // held of the last step no longer describes the scene.
            let refused = StepInput {
                table: &glass_only,
                gravity: Vec3::ZERO,
                time_step: dt,
                integrator,
            };
            assert!(matches!(
                s.step(&refused),
                Err(StepError::Material { material: 1, .. })
            ));
            assert_eq!(s.contacts().count(), 0);
        })
        .unwrap();
}

#[test]
fn a_scene_without_records_has_no_view_and_no_account() {
    let table = table();
    let (scene, _) = mixture();
    let spheres: Vec<Sphere<f64>> = scene.spheres().iter().map(|s| s.into_inner()).collect();
    let mut plain = OwnedScene::new(spheres, *scene.domain(), 1e-4, *scene.walls())
        .unwrap()
        .with_materials(scene.materials().to_vec())
        .unwrap();
    let time_step = plain.scene(|s| s.time_step(&table, 2e-6)).unwrap().unwrap();
    let input = StepInput {
        table: &table,
        gravity: Vec3::ZERO,
        time_step,
        integrator: Integrator::VelocityVerlet,
    };
    plain
        .scene(|s| {
            assert_eq!(s.contacts().count(), 0, "not stepped");
            let stats = s.step(&input).unwrap();
            assert!(stats.pair_contacts > 0 && stats.energy.is_none());
            assert_eq!(s.contacts().count(), 0);
        })
        .unwrap();
}
