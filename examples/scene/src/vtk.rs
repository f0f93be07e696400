//! Frames a viewer opens (the `vtk` feature, which links std): per frame a VTK XML PolyData
//! file of the spheres and one of the touching contacts, and a ParaView collection (`.pvd`)
//! listing the frames with their times. ParaView, VisIt and VTK's own readers open them.
//!
//! The files are written as text (VTK's `ascii` format): each number in its shortest form that
//! reads back to the same bits, so a reader gets the scene's own values. The format is a few
//! lines of XML; a crate for it would add more than it saves.
//!
//! The spheres' file holds one point per sphere, at its centre, with the point arrays
//! `radius`, `mass`, `velocity`, `angular_velocity`, `material` and `contact_force` (the sum of
//! the last step's contact forces on it). The contacts' file holds one line per touching
//! contact of the last step ([`Scene::contacts`]): from sphere i's centre to sphere j's centre
//! as seen from i (across a periodic boundary, the image j touches), or to the point of the
//! wall under sphere i; its cell arrays are `spheres` (i and j, or i and -1 for a wall),
//! `wall` (the wall's place, -1 for a pair), `normal`, `overlap`, `normal_force`,
//! `tangential_force`, `force` (the total force on body j: the sphere j or the wall),
//! `force_magnitude` and `sliding` (1 at the Coulomb limit).

use std::fmt::Display;
use std::fs::{self, File};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::string::String;
use std::vec::Vec;
use std::{format, write, writeln};

use soft_sphere::prelude::{Float, Law, Vec3};

use crate::{ContactBodies, Scene, WallSet};

/// The frames of a run in a directory: `NAME_NNNNN_spheres.vtp`, `NAME_NNNNN_contacts.vtp`
/// and the collection `NAME.pvd`, written again with each frame so that a run stopped early
/// still leaves a collection of the frames it wrote.
///
/// ```
/// use soft_sphere::prelude::{ContactLaw, Frictionless, LinearSpringDashpot, MaterialTable, MaterialWall, Sphere, Vec3, Wall};
/// use soft_sphere_scene::{Domain, Frames, Integrator, OwnedScene, StepInput};
///
/// let law = ContactLaw::new(LinearSpringDashpot::new(1.0e4_f64, 0.5).unwrap(), Frictionless);
/// let table = MaterialTable::<_, 1>::uniform(law);
/// let floor = MaterialWall { wall: Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap(), material: 0 };
/// let domain = Domain {
///     lower: Vec3::ZERO, upper: Vec3::new(0.01, 0.01, 0.01), periodic_x: true, periodic_y: true,
/// };
/// let drop = Sphere::solid(Vec3::new(0.005, 0.005, 4.9e-4), 5.0e-4, 2500.0);
/// let mut scene = OwnedScene::new(vec![drop], domain, 1.0e-4, [floor]).unwrap().with_records();
/// let dir = std::env::temp_dir().join("soft-sphere-frames-doc");
/// let mut frames = Frames::create(&dir, "drop").unwrap();
/// scene
///     .scene(|s| {
///         let time_step = s.time_step(&table, 5.0e-7).unwrap();
///         let input = StepInput {
///             table: &table, gravity: Vec3::new(0.0, 0.0, -9.81), time_step,
///             integrator: Integrator::VelocityVerlet,
///         };
///         s.step(&input).unwrap();
///         frames.write(s, 5.0e-7) // the sphere, and its contact with the floor
///     })
///     .unwrap()
///     .unwrap();
/// assert!(dir.join("drop.pvd").exists() && dir.join("drop_00000_contacts.vtp").exists());
/// ```
#[derive(Debug)]
pub struct Frames {
    dir: PathBuf,
    name: String,
    /// The time of each frame written, in order.
    times: Vec<f64>,
}

impl Frames {
    /// Frames named `name` in `dir` (created with its parents when missing).
    ///
    /// # Errors
    /// The error of creating the directory.
    pub fn create(dir: impl AsRef<Path>, name: &str) -> io::Result<Self> {
        let dir = dir.as_ref().to_path_buf();
        fs::create_dir_all(&dir)?;
        Ok(Self {
            dir,
            name: name.into(),
            times: Vec::new(),
        })
    }

    /// The collection's path, `DIR/NAME.pvd`.
    pub fn collection(&self) -> PathBuf {
        self.dir.join(format!("{}.pvd", self.name))
    }

    /// How many frames have been written.
    pub fn count(&self) -> usize {
        self.times.len()
    }

    /// Writes the scene as it is now as the next frame, at `time` (s), and the collection
    /// with it. The contacts are those of the last step; a scene without records
    /// ([`crate::SceneBuffers::records`]) or not yet stepped writes none.
    ///
    /// # Errors
    /// The first error of writing a file.
    pub fn write<L: Law, W: WallSet<L::Float>, const K: usize>(
        &mut self,
        scene: &Scene<'_, L, W, K>,
        time: L::Float,
    ) -> io::Result<()> {
        let frame = self.times.len();
        let (spheres, contacts) = self.frame_files(frame);
        write_spheres(&mut create(&self.dir.join(&spheres))?, scene)?;
        write_contacts(&mut create(&self.dir.join(&contacts))?, scene)?;
        self.times.push(time.to_f64());
        self.write_collection()
    }

    /// The file names of frame `frame`: spheres, contacts.
    fn frame_files(&self, frame: usize) -> (String, String) {
        let stem = format!("{}_{frame:05}", self.name);
        (
            format!("{stem}_spheres.vtp"),
            format!("{stem}_contacts.vtp"),
        )
    }

    fn write_collection(&self) -> io::Result<()> {
        let mut out = create(&self.collection())?;
        writeln!(out, r#"<?xml version="1.0"?>"#)?;
        writeln!(out, r#"<VTKFile type="Collection" version="0.1">"#)?;
        writeln!(out, "  <Collection>")?;
        for (frame, time) in self.times.iter().enumerate() {
            let (spheres, contacts) = self.frame_files(frame);
            for (part, file) in [spheres, contacts].iter().enumerate() {
                writeln!(
                    out,
                    r#"    <DataSet timestep="{time}" part="{part}" file="{file}"/>"#
                )?;
            }
        }
        writeln!(out, "  </Collection>")?;
        writeln!(out, "</VTKFile>")?;
        out.flush()
    }
}

fn create(path: &Path) -> io::Result<BufWriter<File>> {
    File::create(path).map(BufWriter::new)
}

/// Writes the scene's spheres as a VTK XML PolyData file (see the module's documentation for
/// its arrays).
///
/// # Errors
/// The first error of `out`.
pub fn write_spheres<L: Law, W: WallSet<L::Float>, const K: usize>(
    out: &mut impl Write,
    scene: &Scene<'_, L, W, K>,
) -> io::Result<()> {
    let spheres = scene.spheres();
    let n = spheres.len();
    let mut file = PolyData::begin(out, n, n, 0)?;
    file.points(spheres.iter().map(|s| s.position))?;
    file.cells("Verts", (0..n).map(|k| [k]))?;
    file.open("PointData")?;
    file.scalars("radius", spheres.iter().map(|s| s.radius))?;
    file.scalars("mass", spheres.iter().map(|s| s.mass))?;
    file.vectors("velocity", spheres.iter().map(|s| s.velocity))?;
    file.vectors(
        "angular_velocity",
        spheres.iter().map(|s| s.angular_velocity),
    )?;
    file.array("material", "UInt32", 1, scene.materials().iter())?;
    let force = (0..n).map(|k| scene.load(k).map_or(Vec3::ZERO, |(force, _)| force));
    file.vectors("contact_force", force)?;
    file.close("PointData")?;
    file.end()
}

/// Writes the last step's touching contacts as a VTK XML PolyData file of lines (see the
/// module's documentation for its arrays).
///
/// # Errors
/// The first error of `out`.
pub fn write_contacts<L: Law, W: WallSet<L::Float>, const K: usize>(
    out: &mut impl Write,
    scene: &Scene<'_, L, W, K>,
) -> io::Result<()> {
    let contacts: Vec<_> = scene.contacts().collect();
    let spheres = scene.spheres();
    let n = contacts.len();
    let mut file = PolyData::begin(out, 2 * n, 0, n)?;
    let ends = contacts.iter().flat_map(|c| {
        let (i, reach) = match c.bodies {
            ContactBodies::Pair([i, j]) => (i, spheres[i].radius + spheres[j].radius),
            ContactBodies::Wall { sphere, .. } => (sphere, spheres[sphere].radius),
        };
        let from = spheres[i].position;
        [from, from + c.forces.normal * (reach - c.forces.overlap)]
    });
    file.points(ends)?;
    file.cells("Lines", (0..n).map(|k| [2 * k, 2 * k + 1]))?;
    file.open("CellData")?;
    let bodies = contacts.iter().flat_map(|c| match c.bodies {
        ContactBodies::Pair([i, j]) => [i as i64, j as i64],
        ContactBodies::Wall { sphere, .. } => [sphere as i64, -1],
    });
    file.array("spheres", "Int64", 2, bodies)?;
    let walls = contacts.iter().map(|c| match c.bodies {
        ContactBodies::Pair(_) => -1,
        ContactBodies::Wall { wall, .. } => wall as i64,
    });
    file.array("wall", "Int64", 1, walls)?;
    let forces = || contacts.iter().map(|c| c.forces);
    file.vectors("normal", forces().map(|f| f.normal))?;
    file.scalars("overlap", forces().map(|f| f.overlap))?;
    file.scalars("normal_force", forces().map(|f| f.normal_force))?;
    file.vectors("tangential_force", forces().map(|f| f.tangential_force))?;
    file.vectors("force", forces().map(|f| f.force_on_j()))?;
    let magnitude = forces().map(|f| length(f.force_on_j()));
    file.scalars("force_magnitude", magnitude)?;
    file.array("sliding", "UInt8", 1, forces().map(|f| u8::from(f.sliding)))?;
    file.close("CellData")?;
    file.end()
}

/// A vector's length, for display: computed in f64, written in the scene's float.
fn length<F: Float>(v: Vec3<F>) -> F {
    let [x, y, z] = [v.x, v.y, v.z].map(Float::to_f64);
    F::from_f64((x * x + y * y + z * z).sqrt())
}

/// One piece of a PolyData file, written in order: points, cells, data arrays.
struct PolyData<'w, W: Write> {
    out: &'w mut W,
}

impl<'w, W: Write> PolyData<'w, W> {
    fn begin(out: &'w mut W, points: usize, verts: usize, lines: usize) -> io::Result<Self> {
        writeln!(out, r#"<?xml version="1.0"?>"#)?;
        writeln!(
            out,
            r#"<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">"#
        )?;
        writeln!(out, "  <PolyData>")?;
        writeln!(
            out,
            r#"    <Piece NumberOfPoints="{points}" NumberOfVerts="{verts}" NumberOfLines="{lines}" NumberOfStrips="0" NumberOfPolys="0">"#
        )?;
        Ok(Self { out })
    }

    fn points<F: Float>(&mut self, points: impl Iterator<Item = Vec3<F>>) -> io::Result<()> {
        self.open("Points")?;
        self.vectors("position", points)?;
        self.close("Points")
    }

    /// Cells of `N` points each: their connectivity and offsets.
    fn cells<const N: usize>(
        &mut self,
        kind: &str,
        cells: impl Iterator<Item = [usize; N]> + Clone,
    ) -> io::Result<()> {
        self.open(kind)?;
        self.array("connectivity", "Int64", 1, cells.clone().flatten())?;
        let offsets = cells.enumerate().map(|(k, _)| (k + 1) * N);
        self.array("offsets", "Int64", 1, offsets)?;
        self.close(kind)
    }

    fn open(&mut self, tag: &str) -> io::Result<()> {
        writeln!(self.out, "      <{tag}>")
    }

    fn close(&mut self, tag: &str) -> io::Result<()> {
        writeln!(self.out, "      </{tag}>")
    }

    fn scalars<F: Float>(&mut self, name: &str, values: impl Iterator<Item = F>) -> io::Result<()> {
        self.array(name, float_type::<F>(), 1, values.map(Number))
    }

    fn vectors<F: Float>(
        &mut self,
        name: &str,
        values: impl Iterator<Item = Vec3<F>>,
    ) -> io::Result<()> {
        let components = values.flat_map(|v| [v.x, v.y, v.z].map(Number));
        self.array(name, float_type::<F>(), 3, components)
    }

    /// A data array.
    fn array<T: Display>(
        &mut self,
        name: &str,
        kind: &str,
        components: usize,
        values: impl Iterator<Item = T>,
    ) -> io::Result<()> {
        writeln!(
            self.out,
            r#"        <DataArray type="{kind}" Name="{name}" NumberOfComponents="{components}" format="ascii">"#
        )?;
        for (k, value) in values.enumerate() {
            let separator = if k % 9 == 8 { "\n" } else { " " };
            write!(self.out, "{value}{separator}")?;
        }
        writeln!(self.out, "\n        </DataArray>")
    }

    fn end(self) -> io::Result<()> {
        writeln!(self.out, "    </Piece>")?;
        writeln!(self.out, "  </PolyData>")?;
        writeln!(self.out, "</VTKFile>")?;
        self.out.flush()
    }
}

/// Whether `F` is `f32`.
fn single<F: Float>() -> bool {
    size_of::<F>() == 4
}

/// The VTK type of `F`.
fn float_type<F: Float>() -> &'static str {
    if single::<F>() { "Float32" } else { "Float64" }
}

/// A float written in the shortest form that reads back to the same bits of its own type.
struct Number<F>(F);

impl<F: Float> Display for Number<F> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let value = self.0.to_f64();
        // An f32 widened to f64 is exact; narrowed back it prints as the f32's shortest form.
        if single::<F>() {
            write!(f, "{}", value as f32)
        } else {
            write!(f, "{value}")
        }
    }
}
