//! The scene's VTK frames (`soft_sphere_scene::Frames`) read back: every number the same bits
//! as the scene's (f64 and f32), the cells and offsets a VTK reader walks, each contact line
//! from its sphere's centre to the other centre (its periodic image) or to the wall, and the
//! collection listing every frame's two files at its time. `examples/pour/run.sh` reads a
//! pour's frames with VTK's own reader.

use std::collections::HashMap;
use std::fs;
use std::path::{Path, PathBuf};

use soft_sphere::prelude::{
    Float, LinearAA, LinearMaterial, LinearMixing, MaterialTable, MaterialWall, ModelAA, Sphere,
    Vec3, Wall,
};
use soft_sphere_scene::{
    ContactBodies, ContactView, Domain, Frames, Integrator, OwnedScene, StepInput,
};

type Floored<F> = OwnedScene<LinearAA<F>, [MaterialWall<F>; 1]>;

/// What a run wrote and what the scene held at its last frame.
struct Written<F> {
    dir: PathBuf,
    spheres: Vec<Sphere<F>>,
    contacts: Vec<ContactView<F>>,
    loads: Vec<Vec3<F>>,
}

/// One DataArray of a file: the element it sits in, its type, components and values as
/// written.
#[derive(Debug)]
struct Array {
    parent: String,
    kind: String,
    components: usize,
    values: Vec<String>,
}

/// A PolyData file's counts (points, verts, lines) and arrays by name.
fn read(path: &Path) -> ([usize; 3], HashMap<String, Array>) {
    let text = fs::read_to_string(path).unwrap();
    let attribute = |tag: &str, name: &str| -> String {
        let start = tag.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
        tag[start..][..tag[start..].find('"').unwrap()].to_string()
    };
    let piece = &text[text.find("<Piece").unwrap()..];
    let piece = &piece[..piece.find('>').unwrap()];
    let counts = ["NumberOfPoints", "NumberOfVerts", "NumberOfLines"]
        .map(|name| attribute(piece, name).parse().unwrap());
    assert_eq!(attribute(piece, "NumberOfPolys"), "0");
    // The elements nest: every one opened is closed, in order, inside the one VTKFile.
    let mut open: Vec<String> = Vec::new();
    let mut parents = Vec::new();
    for tag in text.split('<').skip(1).map(|t| &t[..t.find('>').unwrap()]) {
        let name = tag.split([' ', '/']).find(|n| !n.is_empty()).unwrap();
        if tag.starts_with('?') || tag.ends_with('/') {
            continue;
        } else if tag.starts_with('/') {
            assert_eq!(
                open.pop().as_deref(),
                Some(name),
                "{path:?}: </{name}> closes"
            );
        } else {
            assert!(
                !open.is_empty() || name == "VTKFile",
                "{path:?}: <{name}> outside VTKFile"
            );
            if name == "DataArray" {
                parents.push(open.last().unwrap().clone());
            }
            open.push(name.to_string());
        }
    }
    assert!(open.is_empty(), "{path:?}: {open:?} not closed");
    assert_eq!(text.matches("<VTKFile").count(), 1);
    // Long arrays are cut into lines of nine values (the last may hold fewer), for a reader's eye.
    assert!(text.lines().all(|l| l.split_whitespace().count() <= 9));
    let mut arrays = HashMap::new();
    for (chunk, parent) in text.split("<DataArray").skip(1).zip(parents) {
        let tag = &chunk[..chunk.find('>').unwrap()];
        let body = &chunk[tag.len() + 1..chunk.find("</DataArray>").unwrap()];
        assert_eq!(attribute(tag, "format"), "ascii");
        let rows: Vec<usize> = body.lines().map(|l| l.split_whitespace().count()).collect();
        let filled = rows.iter().filter(|&&n| n > 0).count();
        assert!(
            rows.iter()
                .filter(|&&n| n > 0)
                .take(filled.saturating_sub(1))
                .all(|&n| n == 9)
        );
        let array = Array {
            parent,
            kind: attribute(tag, "type"),
            components: attribute(tag, "NumberOfComponents").parse().unwrap(),
            values: body.split_whitespace().map(String::from).collect(),
        };
        assert!(arrays.insert(attribute(tag, "Name"), array).is_none());
    }
    (counts, arrays)
}

/// The element each array sits in: the points' coordinates in `Points`, the cells' in
/// `Verts` (spheres) or `Lines` (contacts), the rest in `PointData` or `CellData`.
fn parent(name: &str, cells: &str, data: &str) -> String {
    match name {
        "position" => "Points".into(),
        "connectivity" | "offsets" => cells.into(),
        _ => data.into(),
    }
}

/// The values of array `name`, checked for its type and components and parsed.
fn values<T: std::str::FromStr>(
    arrays: &HashMap<String, Array>,
    name: &str,
    kind: &str,
    components: usize,
) -> Vec<T>
where
    T::Err: std::fmt::Debug,
{
    let array = &arrays[name];
    assert_eq!(
        (array.kind.as_str(), array.components),
        (kind, components),
        "{name}"
    );
    array.values.iter().map(|v| v.parse().unwrap()).collect()
}

fn components<F: Float>(v: Vec3<F>) -> [F; 3] {
    [v.x, v.y, v.z]
}

/// Two spheres touching across the periodic boundary in x, a third pressed into the floor and
/// touching the second, all moving and spinning so that no array is all zeros.
fn scene<F: Float>() -> (Floored<F>, MaterialTable<LinearAA<F>, 2>) {
    let f = F::from_f64;
    let r = 1.0e-3;
    let at = |x: f64, y: f64, z: f64| Vec3::new(f(x), f(y), f(z));
    let mut spheres = vec![
        Sphere::solid(at(0.99e-3, 5.0e-3, 1.2e-3), f(r), f(2500.0)),
        Sphere::solid(at(9.02e-3, 5.0e-3, 1.2e-3), f(r), f(7800.0)),
        Sphere::solid(at(7.05e-3, 5.1e-3, 0.99e-3), f(r), f(7800.0)),
    ];
    for (k, s) in spheres.iter_mut().enumerate() {
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        s.velocity = at(0.01 * sign, 0.02, -0.03);
        s.angular_velocity = at(3.0, -2.0 * sign, 1.0);
    }
    let floor = MaterialWall {
        wall: Wall::new(Vec3::ZERO, at(0.0, 0.0, 1.0)).unwrap(),
        material: 1,
    };
    let domain = Domain {
        lower: Vec3::ZERO,
        upper: at(10.0e-3, 10.0e-3, 10.0e-3),
        periodic_x: true,
        periodic_y: true,
    };
    let glass = LinearMaterial {
        normal_stiffness: f(1000.0),
        restitution: f(0.9),
        tangential_stiffness: f(285.7),
        dashpot_ratio: f(0.5),
        friction: f(0.3),
    };
    let steel = LinearMaterial {
        normal_stiffness: f(4000.0),
        ..glass
    };
    let table = MaterialTable::mixed(&LinearMixing::new(ModelAA), &[glass, steel]).unwrap();
    let scene = OwnedScene::new(spheres, domain, f(1.0e-4), [floor])
        .unwrap()
        .with_materials(vec![0, 1, 1])
        .unwrap()
        .with_records();
    (scene, table)
}

/// Steps the scene twice, writing a frame after each; returns the frames' directory and what
/// the scene held at the last frame.
fn run<F: Float>(name: &str) -> Written<F> {
    let (mut owned, table) = scene::<F>();
    let dir = std::env::temp_dir().join(format!("soft-sphere-vtk-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    let mut frames = Frames::create(&dir, name).unwrap();
    let mut last = (Vec::new(), Vec::new(), Vec::new());
    for frame in 1..=2 {
        owned
            .scene(|s| {
                let time_step = s.time_step(&table, F::from_f64(1.0e-6)).unwrap();
                let input = StepInput {
                    table: &table,
                    gravity: Vec3::new(F::ZERO, F::ZERO, F::from_f64(-9.81)),
                    time_step,
                    integrator: Integrator::VelocityVerlet,
                };
                s.step(&input).unwrap();
                frames
                    .write(s, F::from_f64(frame as f64 * 0.25e-6))
                    .unwrap();
                last = (
                    s.spheres().iter().map(|c| c.into_inner()).collect(),
                    s.contacts().collect(),
                    (0..3).map(|k| s.load(k).unwrap().0).collect(),
                );
            })
            .unwrap();
    }
    assert_eq!(frames.count(), 2);
    assert_eq!(frames.collection(), dir.join(format!("{name}.pvd")));
    Written {
        dir,
        spheres: last.0,
        contacts: last.1,
        loads: last.2,
    }
}

/// Every number of the files reads back to the scene's bits.
fn round_trip<F: Float + std::str::FromStr>(name: &str, float: &str)
where
    F::Err: std::fmt::Debug,
{
    let Written {
        dir,
        spheres,
        contacts,
        loads,
    } = run::<F>(name);
    assert_eq!(
        contacts.len(),
        3,
        "two pairs (one across x) and one on the floor"
    );

    let ([points, verts, lines], arrays) = read(&dir.join(format!("{name}_00001_spheres.vtp")));
    assert_eq!((points, verts, lines), (3, 3, 0));
    assert_eq!(arrays.len(), 9);
    for (array_name, array) in &arrays {
        assert_eq!(
            array.parent,
            parent(array_name, "Verts", "PointData"),
            "{array_name}"
        );
    }
    let floats = |name: &str, components: usize| values::<F>(&arrays, name, float, components);
    let expect = |got: Vec<F>, want: Vec<F>| {
        assert_eq!(got.len(), want.len());
        for (g, w) in got.iter().zip(&want) {
            assert_eq!(g.to_bits_u64(), w.to_bits_u64());
        }
    };
    let flat = |pick: fn(&Sphere<F>) -> Vec3<F>| -> Vec<F> {
        spheres.iter().flat_map(|s| components(pick(s))).collect()
    };
    expect(floats("position", 3), flat(|s| s.position));
    expect(floats("velocity", 3), flat(|s| s.velocity));
    expect(floats("angular_velocity", 3), flat(|s| s.angular_velocity));
    expect(
        floats("radius", 1),
        spheres.iter().map(|s| s.radius).collect(),
    );
    expect(floats("mass", 1), spheres.iter().map(|s| s.mass).collect());
    expect(
        floats("contact_force", 3),
        loads.iter().flat_map(|&l| components(l)).collect(),
    );
    assert_eq!(values::<u32>(&arrays, "material", "UInt32", 1), [0, 1, 1]);
    assert_eq!(
        values::<i64>(&arrays, "connectivity", "Int64", 1),
        [0, 1, 2]
    );
    assert_eq!(values::<i64>(&arrays, "offsets", "Int64", 1), [1, 2, 3]);

    let ([points, verts, lines], arrays) = read(&dir.join(format!("{name}_00001_contacts.vtp")));
    assert_eq!((points, verts, lines), (6, 0, 3));
    assert_eq!(arrays.len(), 12);
    for (array_name, array) in &arrays {
        assert_eq!(
            array.parent,
            parent(array_name, "Lines", "CellData"),
            "{array_name}"
        );
    }
    let floats = |name: &str, components: usize| values::<F>(&arrays, name, float, components);
    assert_eq!(
        values::<i64>(&arrays, "connectivity", "Int64", 1),
        [0, 1, 2, 3, 4, 5]
    );
    assert_eq!(values::<i64>(&arrays, "offsets", "Int64", 1), [2, 4, 6]);
    let forces = || contacts.iter().map(|c| c.forces);
    expect(
        floats("normal", 3),
        forces().flat_map(|f| components(f.normal)).collect(),
    );
    expect(floats("overlap", 1), forces().map(|f| f.overlap).collect());
    expect(
        floats("normal_force", 1),
        forces().map(|f| f.normal_force).collect(),
    );
    let tangential = forces().flat_map(|f| components(f.tangential_force));
    expect(floats("tangential_force", 3), tangential.collect());
    let on_j = forces().flat_map(|f| components(f.force_on_j()));
    expect(floats("force", 3), on_j.collect());
    let sliding = forces().map(|f| u8::from(f.sliding)).collect::<Vec<_>>();
    assert_eq!(values::<u8>(&arrays, "sliding", "UInt8", 1), sliding);
    for (magnitude, f) in floats("force_magnitude", 1).iter().zip(forces()) {
        let want = f.force_on_j().norm_squared().to_f64().sqrt();
        assert!(
            (magnitude.to_f64() - want).abs() <= 1e-6 * want,
            "{magnitude:?} {want}"
        );
        assert!(want > 0.0);
    }
    let bodies = values::<i64>(&arrays, "spheres", "Int64", 2);
    let walls = values::<i64>(&arrays, "wall", "Int64", 1);
    let ends = floats("position", 3);
    let mut seen = Vec::new();
    for (k, c) in contacts.iter().enumerate() {
        let (i, other, wall) = match c.bodies {
            ContactBodies::Pair([i, j]) => (i, j as i64, -1),
            ContactBodies::Wall { sphere, wall } => (sphere, -1, wall as i64),
        };
        assert_eq!(
            [bodies[2 * k], bodies[2 * k + 1], walls[k]],
            [i as i64, other, wall]
        );
        let end = |e: usize| {
            Vec3::new(
                ends[6 * k + 3 * e],
                ends[6 * k + 3 * e + 1],
                ends[6 * k + 3 * e + 2],
            )
        };
        let (from, to) = (end(0), end(1));
        assert_eq!(from, spheres[i].position);
        // The line runs along the normal, as long as the bodies' distance.
        let reach = if other < 0 {
            spheres[i].radius
        } else {
            spheres[i].radius + spheres[other as usize].radius
        };
        let length = (to - from).norm_squared().to_f64().sqrt();
        let want = (reach - c.forces.overlap).to_f64();
        assert!((length - want).abs() < 1e-5 * want, "{length} {want}");
        let along = (to - from).dot(c.forces.normal).to_f64();
        assert!((along - length).abs() < 1e-5 * length);
        if other >= 0 {
            // At j's centre, or its periodic image one domain width away in x.
            let gap = to - spheres[other as usize].position;
            let x = gap.x.to_f64().abs();
            assert!(x < 1e-6 || (x - 10.0e-3).abs() < 1e-6, "{gap:?}");
            assert!(gap.y.to_f64().abs() < 1e-6 && gap.z.to_f64().abs() < 1e-6);
            seen.push(x > 1e-6);
        } else {
            // On the floor.
            assert!(to.z.to_f64().abs() < 1e-6 * spheres[i].radius.to_f64());
        }
    }
    assert_eq!(
        seen.iter().filter(|&&across| across).count(),
        1,
        "one pair across x"
    );

    let collection = fs::read_to_string(dir.join(format!("{name}.pvd"))).unwrap();
    let entries: Vec<_> = collection
        .lines()
        .filter(|l| l.contains("<DataSet"))
        .collect();
    assert_eq!(entries.len(), 4);
    for (k, entry) in entries.iter().enumerate() {
        let (frame, part) = (k / 2, k % 2);
        let kind = ["spheres", "contacts"][part];
        let time = F::from_f64((frame + 1) as f64 * 0.25e-6).to_f64();
        assert!(entry.contains(&format!(
            r#"timestep="{time}" part="{part}" file="{name}_{frame:05}_{kind}.vtp""#
        )));
        assert!(dir.join(format!("{name}_{frame:05}_{kind}.vtp")).exists());
    }
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn f64_frames_read_back_to_the_scenes_bits() {
    round_trip::<f64>("double", "Float64");
}

#[test]
fn f32_frames_read_back_to_the_scenes_bits_in_their_shortest_form() {
    round_trip::<f32>("single", "Float32");
    // An f32 is written as itself, not as its f64 widening (0.1f32 is 0.10000000149011612).
    let (owned, _) = scene::<f32>();
    let dir = std::env::temp_dir().join(format!("soft-sphere-vtk-short-{}", std::process::id()));
    let mut frames = Frames::create(&dir, "short").unwrap();
    let mut owned = owned;
    owned.spheres_mut()[0]
        .update(|s| s.velocity.x = 0.1)
        .unwrap();
    owned.scene(|s| frames.write(s, 0.1)).unwrap().unwrap();
    let text = fs::read_to_string(dir.join("short_00000_spheres.vtp")).unwrap();
    let (_, arrays) = read(&dir.join("short_00000_spheres.vtp"));
    assert_eq!(arrays["velocity"].values[0], "0.1", "{text}");
    let collection = fs::read_to_string(frames.collection()).unwrap();
    assert!(collection.contains(r#"timestep="0.10000000149011612""#));
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_scene_not_stepped_writes_no_contacts() {
    let (mut owned, _) = scene::<f64>();
    let dir = std::env::temp_dir().join(format!("soft-sphere-vtk-none-{}", std::process::id()));
    let mut frames = Frames::create(&dir, "none").unwrap();
    owned.scene(|s| frames.write(s, 0.0)).unwrap().unwrap();
    let ([points, verts, lines], arrays) = read(&dir.join("none_00000_contacts.vtp"));
    assert_eq!((points, verts, lines), (0, 0, 0));
    assert!(arrays["normal_force"].values.is_empty());
    let (counts, _) = read(&dir.join("none_00000_spheres.vtp"));
    assert_eq!(counts, [3, 3, 0]);
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_directory_that_cannot_be_made_is_an_error() {
    let file = std::env::temp_dir().join(format!("soft-sphere-vtk-file-{}", std::process::id()));
    fs::write(&file, "not a directory").unwrap();
    assert!(Frames::create(file.join("frames"), "x").is_err());
    fs::remove_file(file).unwrap();
}
