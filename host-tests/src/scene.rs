//! The std wrapper around the kernel's allocation-free scene: owns the buffers, builds the
//! reference packing (REFERENCE-style column of spheres on a floor), and writes it for LAMMPS.

use std::fmt::Write as _;
use std::path::Path;

use rayon::prelude::*;
use soft_sphere::scene::{
    Candidate, ContactSlots, Domain, Executor, PairResult, Scene, SceneBuffers, SceneError, Serial,
    StepInput, StepStats, WallSet,
};
use soft_sphere::{
    ContactError, ContactState, Float, MathBackend, NormalModel, Rotation, Sphere, TangentialModel,
    Vec3,
};

/// Contacts a sphere can own (monodisperse packings have at most 12 neighbours).
pub const SLOTS: usize = 16;

/// Verlet-list room per sphere: a dense monodisperse packing with a skin of a tenth of a
/// diameter lists about 4 pairs per sphere; 8 leaves room for looser skins and denser beds.
pub const CANDIDATES_PER_SPHERE: usize = 8;

/// A rayon thread pool as the kernel scene's [`Executor`]: each phase of a step (pairs, walls,
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

/// A scene and all its buffers.
#[derive(Clone, Debug)]
pub struct OwnedScene<F: Float, S> {
    /// The spheres.
    pub spheres: Vec<Sphere<F>>,
    forces: Vec<Vec3<F>>,
    torques: Vec<Vec3<F>>,
    slots: Vec<ContactSlots<S, SLOTS>>,
    wall_states: Vec<S>,
    next_wall_states: Vec<S>,
    walls: usize,
    cell_start: Vec<u32>,
    cell_entries: Vec<u32>,
    candidates: Vec<Candidate>,
    states: Vec<S>,
    next_states: Vec<S>,
    anchors: Vec<Vec3<F>>,
    pair_results: Vec<PairResult<F>>,
    /// The box.
    pub domain: Domain<F>,
    largest_diameter: F,
    skin: F,
    /// Verlet-list builds of the last run.
    pub list_builds: usize,
}

impl<F: Float, S: ContactState> OwnedScene<F, S> {
    /// A scene of `spheres` in `domain` with `walls` walls, a Verlet list with `skin`, and
    /// spheres no larger than `largest_diameter`. The spheres are reordered along the cell grid
    /// (z, then y, then x) so that neighbours sit close in memory, as LAMMPS's atom sort does.
    ///
    /// # Errors
    /// The kernel's [`SceneError`].
    pub fn new(
        mut spheres: Vec<Sphere<F>>,
        domain: Domain<F>,
        (largest_diameter, skin): (F, F),
        walls: usize,
    ) -> Result<Self, SceneError> {
        Scene::<F, S, SLOTS>::check_spheres(&spheres)?;
        let n = spheres.len();
        let cells = Scene::<F, S, SLOTS>::cells_needed(&domain, (largest_diameter, skin))?;
        let cell = (largest_diameter + skin).to_f64();
        let key = |s: &Sphere<F>| {
            let p = (s.position - domain.lower)
                .to_array()
                .map(|x| (x.to_f64() / cell) as i64);
            (p[2], p[1], p[0])
        };
        spheres.sort_by_key(key);
        Ok(Self {
            spheres,
            forces: vec![Vec3::ZERO; n],
            torques: vec![Vec3::ZERO; n],
            slots: vec![ContactSlots::default(); n],
            wall_states: vec![S::default(); n * walls],
            next_wall_states: vec![S::default(); n * walls],
            walls,
            cell_start: vec![0; cells + 1],
            cell_entries: vec![0; n],
            candidates: vec![Candidate::default(); CANDIDATES_PER_SPHERE * n + 64],
            states: vec![S::default(); CANDIDATES_PER_SPHERE * n + 64],
            next_states: vec![S::default(); CANDIDATES_PER_SPHERE * n + 64],
            anchors: vec![Vec3::ZERO; n],
            pair_results: vec![PairResult::default(); CANDIDATES_PER_SPHERE * n + 64],
            domain,
            largest_diameter,
            skin,
            list_builds: 0,
        })
    }

    /// Runs `steps` steps, calling `each` with every step's totals.
    ///
    /// Each call starts the kernel's scene afresh (the list is rebuilt, the stored springs carry
    /// over).
    ///
    /// # Errors
    /// The first contact error; [`ContactError::HistoryFull`] past [`SLOTS`] contacts; the error
    /// of an invalid sphere.
    pub fn run<N, T, M, R, W>(
        &mut self,
        input: &StepInput<'_, F, N, T, M, R, W>,
        steps: usize,
        each: impl FnMut(usize, &StepStats<F>),
    ) -> Result<(), ContactError>
    where
        N: NormalModel<F>,
        T: TangentialModel<F, State = S>,
        M: MathBackend<F>,
        R: Rotation,
        W: WallSet<F>,
    {
        self.run_on(input, steps, &Serial, each)
    }

    /// [`OwnedScene::run`] with the work of each step spread over `executor` (for example
    /// [`Threads`]); the same bits as a serial run.
    ///
    /// # Errors
    /// As [`OwnedScene::run`].
    pub fn run_on<N, T, M, R, W, E>(
        &mut self,
        input: &StepInput<'_, F, N, T, M, R, W>,
        steps: usize,
        executor: &E,
        mut each: impl FnMut(usize, &StepStats<F>),
    ) -> Result<(), ContactError>
    where
        N: NormalModel<F>,
        T: TangentialModel<F, State = S>,
        M: MathBackend<F>,
        R: Rotation,
        W: WallSet<F>,
        E: Executor,
    {
        let buffers = SceneBuffers {
            forces: &mut self.forces,
            torques: &mut self.torques,
            slots: &mut self.slots,
            wall_states: &mut self.wall_states,
            next_wall_states: &mut self.next_wall_states,
            cell_start: &mut self.cell_start,
            cell_entries: &mut self.cell_entries,
            candidates: &mut self.candidates,
            states: &mut self.states,
            next_states: &mut self.next_states,
            anchors: &mut self.anchors,
            pair_results: &mut self.pair_results,
        };
        // The domain and buffers were checked by `new`; a sphere made non-finite by an earlier
        // run's overflow is reported as the contact error it is.
        let mut scene = match Scene::new(
            self.domain,
            (self.largest_diameter, self.skin),
            &mut self.spheres,
            buffers,
            self.walls,
        ) {
            Ok(scene) => scene,
            Err(SceneError::Sphere { error, .. }) => return Err(error),
            Err(other) => unreachable!("domain and buffers checked by OwnedScene::new: {other}"),
        };
        for step in 0..steps {
            let stats = scene.step_on(input, executor)?;
            each(step, &stats);
        }
        self.list_builds = scene.list_builds();
        Ok(())
    }

    /// Sets every velocity and spin to zero (keeps the contacts' stored springs).
    pub fn stop(&mut self) {
        for s in &mut self.spheres {
            s.velocity = Vec3::ZERO;
            s.angular_velocity = Vec3::ZERO;
        }
    }

    /// Translational plus rotational kinetic energy (J).
    pub fn kinetic_energy(&self) -> f64 {
        self.spheres
            .iter()
            .map(|s| {
                0.5 * s.mass.to_f64() * s.velocity.norm_squared().to_f64()
                    + 0.5
                        * s.solid_moment_of_inertia().to_f64()
                        * s.angular_velocity.norm_squared().to_f64()
            })
            .sum()
    }
}

/// The reference scene of issue 5: monodisperse spheres in a column periodic in x and y on a
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
        let mut random = 0x2545_f491_4f6c_dd1du64;
        let mut jitter = || {
            // xorshift64*: enough for a deterministic jitter.
            random ^= random >> 12;
            random ^= random << 25;
            random ^= random >> 27;
            let unit =
                (random.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64;
            (unit - 0.5) * 0.1 * self.diameter
        };
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
