//! What the tests and benchmarks add to the scene crate's [`OwnedScene`]: a rayon executor,
//! the reference packing (a column of spheres on a floor), and writing it for LAMMPS.

use std::fmt::Write as _;
use std::path::Path;

use rayon::prelude::*;

use crate::energy::kinetic;
use crate::random::Xorshift;
use soft_sphere::prelude::{Float, Law, MaterialTable, MaterialWall, Sphere, Vec3, Wall};
use soft_sphere_scene::{Domain, Executor, WallSet};

/// A rayon thread pool as the scene's [`Executor`]: each phase of a step (pairs, walls,
/// integration) is spread over the pool's threads.
#[derive(Debug)]
pub struct Threads {
    pool: rayon::ThreadPool,
}

impl Threads {
    /// A pool of `threads` threads.
    ///
    /// # Errors
    /// When the threads cannot be started.
    pub fn new(threads: usize) -> Result<Self, rayon::ThreadPoolBuildError> {
        Ok(Self {
            pool: rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()?,
        })
    }
}

impl Executor for Threads {
    const PARALLEL: bool = true;

    fn for_each_mut<T: Send, W: Fn(&mut T) + Sync + Send>(&self, items: &mut [T], work: W) {
        self.pool.install(|| items.par_iter_mut().for_each(work));
    }
}

pub use soft_sphere_scene::OwnedScene;

/// What the tests and benchmarks read of an [`OwnedScene`] beyond its own methods.
pub trait SceneExt<F> {
    /// The spheres, unchecked.
    fn plain_spheres(&self) -> Vec<Sphere<F>>;
    /// Sets every velocity and spin to zero (keeps the contacts' stored springs).
    fn stop(&mut self);
    /// Translational plus rotational kinetic energy (J).
    fn kinetic_energy(&self) -> f64;
}

impl<L: Law, W: WallSet<L::Float> + Clone> SceneExt<L::Float> for OwnedScene<L, W> {
    fn plain_spheres(&self) -> Vec<Sphere<L::Float>> {
        self.spheres().iter().map(|s| s.into_inner()).collect()
    }

    fn stop(&mut self) {
        for s in self.spheres_mut() {
            let stopped = s.update(|s| {
                s.velocity = Vec3::ZERO;
                s.angular_velocity = Vec3::ZERO;
            });
            debug_assert!(stopped.is_ok(), "zero velocities keep a sphere valid");
        }
    }

    fn kinetic_energy(&self) -> f64 {
        self.spheres().iter().map(|s| kinetic(s)).sum()
    }
}

/// The table of a scene whose spheres are material 0 and whose walls are material 1: `pair`
/// between spheres, `wall` between a sphere and a wall.
pub fn pair_and_wall<L: Law>(pair: L, wall: L) -> MaterialTable<L, 2> {
    let mut table = MaterialTable::uniform(pair);
    for (a, b) in [(0, 1), (1, 1)] {
        let set = table.set(a, b, wall);
        debug_assert!(
            set.is_ok(),
            "materials 0 and 1 are rows of a 2-material table"
        );
    }
    table
}

/// A wall of material `material` (1 in a [`pair_and_wall`] table).
pub fn wall_of<F: Float>(wall: Wall<F>, material: u32) -> MaterialWall<F> {
    MaterialWall { wall, material }
}

/// The reference scene: monodisperse spheres in a column periodic in x and y on a
/// floor at z = 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Column {
    /// Number of spheres.
    pub spheres: usize,
    /// Sphere diameter (m).
    pub diameter: f64,
    /// Density (kg/m3).
    pub density: f64,
    /// Column width in x (m).
    pub width_x: f64,
    /// Column width in y (m).
    pub width_y: f64,
}

impl Column {
    /// 10,000 spheres of 1 mm, density 2500, 20 mm x 20 mm.
    pub const REFERENCE: Self = Self {
        spheres: 10_000,
        diameter: 1e-3,
        density: 2500.0,
        width_x: 0.02,
        width_y: 0.02,
    };

    /// The same column 5 times longer in x: 50,000 spheres.
    pub const LONG: Self = Self {
        spheres: 50_000,
        diameter: 1e-3,
        density: 2500.0,
        width_x: 0.1,
        width_y: 0.02,
    };

    /// The box: periodic x and y, from the floor up to a height that holds the pour.
    pub fn domain<F: Float>(&self, height: f64) -> Domain<F> {
        Domain {
            lower: Vec3::ZERO,
            upper: Vec3::new(
                F::from_f64(self.width_x),
                F::from_f64(self.width_y),
                F::from_f64(height),
            ),
            periodic_x: true,
            periodic_y: true,
        }
    }

    /// Spheres on a jittered cubic lattice of spacing 1.2 diameters above the floor, at rest.
    /// The jitter is a fixed-seed generator, so the pour is the same every time.
    pub fn lattice<F: Float>(&self) -> (Vec<Sphere<F>>, f64) {
        let spacing = 1.2 * self.diameter;
        let (nx, ny) = (
            (self.width_x / spacing).floor() as usize,
            (self.width_y / spacing).floor() as usize,
        );
        let mut random = Xorshift::new(0x2545_f491_4f6c_dd1d);
        let mut jitter = || (random.unit() - 0.5) * 0.1 * self.diameter;
        let mut spheres = Vec::with_capacity(self.spheres);
        let radius = 0.5 * self.diameter;
        let mut k = 0;
        while spheres.len() < self.spheres {
            let (ix, iy, iz) = (k % nx, (k / nx) % ny, k / (nx * ny));
            let centre = Vec3::new(
                F::from_f64((ix as f64 + 0.5) * self.width_x / nx as f64 + jitter()),
                F::from_f64((iy as f64 + 0.5) * self.width_y / ny as f64 + jitter()),
                F::from_f64(radius + iz as f64 * spacing + 0.2 * self.diameter + jitter().abs()),
            );
            spheres.push(Sphere::solid(
                centre,
                F::from_f64(radius),
                F::from_f64(self.density),
            ));
            k += 1;
        }
        let top = spheres
            .iter()
            .map(|s| s.position.z.to_f64())
            .fold(0.0, f64::max);
        (spheres, top + self.diameter)
    }
}

/// Writes spheres as a LAMMPS data file (`atom_style sphere`: id type diameter density x y z).
///
/// # Errors
/// The file system's.
pub fn write_lammps_data<F: Float>(
    path: &Path,
    spheres: &[Sphere<F>],
    domain: &Domain<F>,
    density: f64,
) -> std::io::Result<()> {
    let mut text = String::new();
    let (lo, hi) = (domain.lower, domain.upper);
    let _ = writeln!(
        text,
        "soft-sphere settled packing\n\n{} atoms\n1 atom types\n",
        spheres.len()
    );
    let _ = writeln!(text, "{:e} {:e} xlo xhi", lo.x.to_f64(), hi.x.to_f64());
    let _ = writeln!(text, "{:e} {:e} ylo yhi", lo.y.to_f64(), hi.y.to_f64());
    let _ = writeln!(text, "{:e} {:e} zlo zhi\n", lo.z.to_f64(), hi.z.to_f64());
    let _ = writeln!(text, "Atoms # sphere\n");
    for (k, s) in spheres.iter().enumerate() {
        let p = s.position;
        let _ = writeln!(
            text,
            "{} 1 {:e} {:e} {:e} {:e} {:e}",
            k + 1,
            2.0 * s.radius.to_f64(),
            density,
            p.x.to_f64(),
            p.y.to_f64(),
            p.z.to_f64()
        );
    }
    std::fs::write(path, text)
}

/// `(x, y, z)` of every sphere as CSV text, full precision.
pub fn positions_csv<F: Float>(spheres: &[Sphere<F>]) -> String {
    let mut text = String::from("x,y,z\n");
    for s in spheres {
        let p = s.position;
        let _ = writeln!(
            text,
            "{:e},{:e},{:e}",
            p.x.to_f64(),
            p.y.to_f64(),
            p.z.to_f64()
        );
    }
    text
}

/// Restitution a wall contact needs for the same dashpot `eta_n` as a pair contact with
/// restitution `e` (LAMMPS's `gamma_n` multiplies the effective mass, which is `m` at a wall and
/// `m/2` between equal spheres): `zeta_wall = zeta sqrt(m*_pair / m_wall)`.
pub fn wall_restitution_for_same_dashpot(restitution: f64, pair_mass: f64, wall_mass: f64) -> f64 {
    let l = restitution.ln();
    let zeta = -l / (std::f64::consts::PI.powi(2) + l * l).sqrt();
    let zeta_wall = zeta * (pair_mass / wall_mass).sqrt();
    (-std::f64::consts::PI * zeta_wall / (1.0 - zeta_wall * zeta_wall).sqrt()).exp()
}
