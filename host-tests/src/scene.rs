//! The std wrapper around the scene crate's allocation-free [`Scene`]: owns the buffers, builds
//! the reference packing (a column of spheres on a floor), and writes it for LAMMPS.

use std::fmt::Write as _;
use std::path::Path;

use rayon::prelude::*;

use crate::energy::kinetic;
use crate::random::Xorshift;
use soft_sphere::{CheckedSphere, Float, Law, Sphere, Vec3};
use soft_sphere_scene::{
    Domain, Executor, ListEntry, PairResult, Parking, Scene, SceneBuffers, SceneError, Serial,
    SphereEntry, StepError, StepInput, StepStats, WallEntry, WallSet, check_spheres,
};

/// Stored contacts a sphere can own at a list rebuild (monodisperse packings have at most 12
/// neighbours).
pub const PARKING: usize = 16;

/// Verlet-list room per sphere: a dense monodisperse packing with a skin of a tenth of a
/// diameter lists about 4.5 pairs per sphere; 8 leaves room for looser skins and denser beds.
pub const CANDIDATES_PER_SPHERE: usize = 8;

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

/// A scene of law `L` with walls `W`, and all its buffers.
#[derive(Clone, Debug)]
pub struct OwnedScene<L: Law, W> {
    /// The spheres.
    pub spheres: Vec<CheckedSphere<L::Float>>,
    /// The walls.
    pub walls: W,
    entries: Vec<SphereEntry<L::Float>>,
    cells: Vec<u32>,
    list: Vec<ListEntry<L::State>>,
    parking: Vec<Parking<L::State, PARKING>>,
    wall_states: Vec<WallEntry<L::State>>,
    pair_results: Vec<PairResult<L::Float>>,
    /// The box.
    pub domain: Domain<L::Float>,
    largest_diameter: L::Float,
    skin: L::Float,
    /// Verlet-list builds of the last run.
    pub list_builds: usize,
}

impl<L: Law, W: WallSet<L::Float> + Clone> OwnedScene<L, W> {
    /// A scene of `spheres` in `domain` with `walls`, a Verlet list with `skin`, and spheres no
    /// larger than `largest_diameter`. The spheres are checked, then reordered along the cell
    /// grid (z, then y, then x) so that neighbours sit close in memory, as LAMMPS's atom sort
    /// does.
    ///
    /// # Errors
    /// The scene's [`SceneError`]; [`SceneError::Sphere`] names the sphere by its index in
    /// `spheres`.
    pub fn new(
        spheres: Vec<Sphere<L::Float>>,
        domain: Domain<L::Float>,
        (largest_diameter, skin): (L::Float, L::Float),
        walls: W,
    ) -> Result<Self, SceneError> {
        let mut spheres = check_spheres(spheres).collect::<Result<Vec<_>, _>>()?;
        let n = spheres.len();
        let capacity = CANDIDATES_PER_SPHERE * n + 64;
        let sizes = Scene::<L, W, PARKING>::buffer_sizes(
            &domain,
            (largest_diameter, skin),
            n,
            capacity,
            true,
        )?;
        let cell = (largest_diameter + skin).to_f64();
        let key = |s: &CheckedSphere<L::Float>| {
            let p = (s.position - domain.lower)
                .to_array()
                .map(|x| (x.to_f64() / cell) as i64);
            (p[2], p[1], p[0])
        };
        spheres.sort_by_key(key);
        Ok(Self {
            spheres,
            walls,
            entries: vec![SphereEntry::default(); sizes.spheres],
            cells: vec![0; sizes.cells],
            list: vec![ListEntry::default(); sizes.list],
            parking: vec![Parking::default(); sizes.parking],
            wall_states: vec![WallEntry::default(); sizes.walls],
            pair_results: vec![PairResult::default(); sizes.pair_results],
            domain,
            largest_diameter,
            skin,
            list_builds: 0,
        })
    }

    /// Runs `steps` steps, calling `each` with every step's totals.
    ///
    /// Each call starts the scene afresh (the list is rebuilt, the stored springs carry over).
    ///
    /// # Errors
    /// The first [`StepError`].
    pub fn run(
        &mut self,
        input: &StepInput<'_, L>,
        steps: usize,
        each: impl FnMut(usize, &StepStats<L::Float>),
    ) -> Result<(), StepError> {
        self.run_on(input, steps, &Serial, each)
    }

    /// [`OwnedScene::run`] with the work of each step spread over `executor` (for example
    /// [`Threads`]); the same bits as a serial run.
    ///
    /// # Errors
    /// As [`OwnedScene::run`].
    pub fn run_on<E: Executor>(
        &mut self,
        input: &StepInput<'_, L>,
        steps: usize,
        executor: &E,
        mut each: impl FnMut(usize, &StepStats<L::Float>),
    ) -> Result<(), StepError> {
        let buffers = SceneBuffers {
            spheres: &mut self.entries,
            cells: &mut self.cells,
            list: &mut self.list,
            parking: &mut self.parking,
            walls: &mut self.wall_states,
            pair_results: &mut self.pair_results,
        };
        let mut scene = Scene::new(
            self.domain,
            (self.largest_diameter, self.skin),
            &mut self.spheres,
            buffers,
            self.walls.clone(),
        )
        .unwrap_or_else(|error| unreachable!("checked by OwnedScene::new: {error}"));
        let mut outcome = Ok(());
        for step in 0..steps {
            match scene.step_on(input, executor) {
                Ok(stats) => each(step, &stats),
                Err(error) => {
                    outcome = Err(error);
                    break;
                }
            }
        }
        self.list_builds = scene.list_builds();
        self.walls = scene.walls().clone();
        outcome
    }

    /// The spheres, unchecked.
    pub fn plain_spheres(&self) -> Vec<Sphere<L::Float>> {
        self.spheres.iter().map(|s| s.into_inner()).collect()
    }

    /// Sets every velocity and spin to zero (keeps the contacts' stored springs).
    pub fn stop(&mut self) {
        for s in &mut self.spheres {
            let stopped = s.update(|s| {
                s.velocity = Vec3::ZERO;
                s.angular_velocity = Vec3::ZERO;
            });
            debug_assert!(stopped.is_ok(), "zero velocities keep a sphere valid");
        }
    }

    /// Translational plus rotational kinetic energy (J).
    pub fn kinetic_energy(&self) -> f64 {
        self.spheres.iter().map(|s| kinetic(s)).sum()
    }
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
