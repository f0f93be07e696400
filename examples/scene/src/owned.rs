//! A scene that owns its spheres and buffers (the `alloc` feature): what a std user builds.

use alloc::vec;
use alloc::vec::Vec;

use soft_sphere::prelude::{CheckedSphere, Interaction, Law, PairLoad, Sphere, Vec3};

use crate::energy::Ledger;
use crate::parallel::{Executor, Serial};
use crate::{
    Domain, Parking, Scene, SceneBuffers, SceneError, StepError, StepInput, StepStats, WallSet,
    check_spheres,
};

/// Verlet-list room per sphere: a dense monodisperse packing with a skin of a tenth of a
/// diameter lists about 4.5 pairs per sphere; 8 leaves room for looser skins and denser beds.
pub const PAIRS_PER_SPHERE: usize = 8;

/// Stored contacts a sphere of an [`OwnedScene`] can own at a list rebuild (a monodisperse
/// packing has at most 12 neighbours).
pub const PARKING: usize = 16;

/// A [`Scene`] that owns its spheres, material ids, walls and buffers, sized for
/// [`PAIRS_PER_SPHERE`] list entries per sphere and at most `K` ([`PARKING`] unless
/// [`OwnedScene::with_parking`] says otherwise) stored contacts per sphere.
/// Steps run inside [`OwnedScene::run`] or [`OwnedScene::scene`]; the contact history carries
/// over from one to the next.
///
/// ```
/// use soft_sphere::prelude::{ContactLaw, LinearSpringDashpot, MaterialTable, MaterialWall, ModelAA, Sphere, TangentialParameters, Vec3, Wall};
/// use soft_sphere_scene::{Domain, Integrator, OwnedScene, StepInput};
///
/// let law = ContactLaw::new(
///     LinearSpringDashpot::new(1.0e4_f64, 0.5).unwrap(),
///     ModelAA(TangentialParameters::new(8.0e3, 0.5, 0.4).unwrap()),
/// );
/// let table = MaterialTable::<_, 1>::uniform(law);
/// let floor = MaterialWall { wall: Wall::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)).unwrap(), material: 0 };
/// let domain = Domain {
///     lower: Vec3::ZERO, upper: Vec3::new(0.01, 0.01, 0.01), periodic_x: true, periodic_y: true,
/// };
/// let drop = Sphere::solid(Vec3::new(0.005, 0.005, 6.0e-4), 5.0e-4, 2500.0);
/// let mut scene = OwnedScene::new(vec![drop], domain, 1.0e-4, [floor])
///     .unwrap()
///     .with_records();
/// let time_step = scene.scene(|s| s.time_step(&table, 5.0e-7)).unwrap().unwrap();
/// let input = StepInput {
///     table: &table, gravity: Vec3::new(0.0, 0.0, -9.81), time_step,
///     integrator: Integrator::VelocityVerlet,
/// };
/// let mut last = None;
/// scene.run(&input, 40_000, |_, stats| last = stats.energy).unwrap();
/// assert!(scene.spheres()[0].position.z < 5.0e-4); // resting on the floor
/// let energy = last.unwrap();
/// assert!(energy.dissipated_dashpots > 0.0);
/// ```
#[derive(Clone, Debug)]
pub struct OwnedScene<L: Law, W, const K: usize = PARKING> {
    spheres: Vec<CheckedSphere<L::Float>>,
    materials: Vec<u32>,
    walls: W,
    domain: Domain<L::Float>,
    skin: L::Float,
    cells: Vec<u32>,
    pairs: Vec<[u32; 2]>,
    vectors: Vec<Vec3<L::Float>>,
    states: Vec<L::State>,
    parking: Vec<Parking<L::State, K>>,
    records: Vec<Interaction<L::Float>>,
    loads: Vec<PairLoad<L::Float>>,
    list_builds: usize,
    halted: bool,
    /// The energy account's running totals, carried from one [`OwnedScene::scene`] call to the
    /// next so that the account runs on across calls.
    ledger: Ledger<L::Float>,
}

impl<L: Law, W: WallSet<L::Float> + Clone> OwnedScene<L, W> {
    /// A scene of `spheres` (all of material 0) in `domain` with `walls` and a Verlet list with
    /// `skin`. The grid's cells are sized from the spheres' largest diameter, found again at
    /// every [`OwnedScene::scene`] call (spheres changed between calls resize them).
    ///
    /// # Errors
    /// [`SceneError::Sphere`] for the first invalid sphere; [`SceneError::Domain`] for a bad
    /// domain or skin; [`SceneError::TooManyCells`] for a domain too finely cut;
    /// [`SceneError::Outside`] for the first sphere outside the domain.
    pub fn new(
        spheres: Vec<Sphere<L::Float>>,
        domain: Domain<L::Float>,
        skin: L::Float,
        walls: W,
    ) -> Result<Self, SceneError> {
        let spheres = check_spheres(spheres).collect::<Result<Vec<_>, _>>()?;
        let n = spheres.len();
        let capacity = PAIRS_PER_SPHERE * n + 64;
        let largest = largest_diameter(&spheres, &domain);
        let sizes =
            Scene::<L, W, PARKING>::buffer_sizes(&domain, (largest, skin), n, capacity, false)?;
        let skin_ok = skin >= soft_sphere::prelude::Float::ZERO
            && soft_sphere::prelude::Float::is_finite(skin);
        if !skin_ok {
            return Err(SceneError::Domain);
        }
        crate::check_placement(&spheres, &domain, largest)?;
        Ok(Self {
            spheres,
            materials: vec![0; n],
            walls,
            domain,
            skin,
            cells: vec![0; sizes.cells],
            pairs: vec![[0; 2]; sizes.pairs],
            vectors: vec![Vec3::ZERO; sizes.vectors],
            states: vec![L::State::default(); sizes.states],
            parking: vec![Parking::default(); sizes.parking],
            records: Vec::new(),
            loads: vec![PairLoad::default(); sizes.loads],
            list_builds: 0,
            halted: false,
            ledger: Ledger::default(),
        })
    }

    /// The same scene, its spheres, history and energy account kept, with room for `P`
    /// stored contacts per sphere at a list rebuild: what a scene that stopped with
    /// [`StepError::ParkingFull`] (a large sphere among many small ones) goes on with.
    pub fn with_parking<const P: usize>(self) -> OwnedScene<L, W, P> {
        let parking = if self.parking.is_empty() {
            Vec::new()
        } else {
            vec![Parking::default(); self.spheres.len()]
        };
        OwnedScene {
            spheres: self.spheres,
            materials: self.materials,
            walls: self.walls,
            domain: self.domain,
            skin: self.skin,
            cells: self.cells,
            pairs: self.pairs,
            vectors: self.vectors,
            states: self.states,
            parking,
            records: self.records,
            loads: self.loads,
            list_builds: self.list_builds,
            halted: self.halted,
            ledger: self.ledger,
        }
    }
}

impl<L: Law, W: WallSet<L::Float> + Clone, const K: usize> OwnedScene<L, W, K> {
    /// The same scene with material ids `materials`, one per sphere.
    ///
    /// # Errors
    /// [`SceneError::Materials`] when they are not one per sphere.
    pub fn with_materials(mut self, materials: Vec<u32>) -> Result<Self, SceneError> {
        if materials.len() != self.spheres.len() {
            return Err(SceneError::Materials);
        }
        self.materials = materials;
        Ok(self)
    }

    /// The same scene keeping each contact's outcome: [`Scene::contacts`] and the energy
    /// account in [`StepStats::energy`].
    pub fn with_records(mut self) -> Self {
        self.records = vec![Interaction::Apart; self.pairs.len() + self.spheres.len() * W::COUNT];
        self
    }

    /// Calls `work` with the scene over the owned buffers (to step it, read its contacts, check
    /// a time step). The contact history and the energy account carry over from one call to
    /// the next; the list is built afresh in each, so [`Scene::contacts`] holds the contacts of
    /// a step made in the same call (read them in `work`, or in [`OwnedScene::run`]'s `each`,
    /// not in a later call).
    ///
    /// # Errors
    /// [`StepError::Halted`] after a step diverged; [`StepError::Scene`] when the spheres as
    /// changed through [`OwnedScene::spheres_mut`] no longer fit the domain (one outside it,
    /// [`SceneError::Outside`], or so small that its grid would hold too many cells,
    /// [`SceneError::TooManyCells`]).
    pub fn scene<R>(
        &mut self,
        work: impl FnOnce(&mut Scene<'_, L, W, K>) -> R,
    ) -> Result<R, StepError> {
        if self.halted {
            return Err(StepError::Halted);
        }
        // The grid follows the spheres as they are now: a sphere grown since the last call
        // gets cells that hold its contacts.
        let largest = largest_diameter(&self.spheres, &self.domain);
        let sizes = Scene::<L, W, K>::buffer_sizes(
            &self.domain,
            (largest, self.skin),
            self.spheres.len(),
            self.pairs.len(),
            false,
        )?;
        self.cells.resize(sizes.cells, 0);
        let buffers = SceneBuffers {
            cells: &mut self.cells,
            pairs: &mut self.pairs,
            vectors: &mut self.vectors,
            states: &mut self.states,
            parking: &mut self.parking,
            records: &mut self.records,
            loads: &mut self.loads,
        };
        let mut scene = Scene::new(
            self.domain,
            (largest, self.skin),
            (&mut self.spheres, &self.materials),
            buffers,
            self.walls.clone(),
        )?;
        scene.ledger = self.ledger;
        let returned = work(&mut scene);
        self.ledger = scene.ledger;
        self.list_builds = scene.list_builds();
        self.halted = scene.halted();
        self.walls = scene.walls().clone();
        Ok(returned)
    }

    /// Runs `steps` steps, calling `each` with every step's totals.
    ///
    /// # Errors
    /// The first [`StepError`].
    pub fn run<const MATERIALS: usize>(
        &mut self,
        input: &StepInput<'_, L, MATERIALS>,
        steps: usize,
        each: impl FnMut(usize, &StepStats<L::Float>),
    ) -> Result<(), StepError> {
        self.run_on(input, steps, &Serial, each)
    }

    /// [`OwnedScene::run`] with each step's integration spread over `executor`; the same bits.
    ///
    /// # Errors
    /// As [`OwnedScene::run`].
    pub fn run_on<E: Executor, const MATERIALS: usize>(
        &mut self,
        input: &StepInput<'_, L, MATERIALS>,
        steps: usize,
        executor: &E,
        mut each: impl FnMut(usize, &StepStats<L::Float>),
    ) -> Result<(), StepError> {
        self.scene(|scene| {
            for step in 0..steps {
                each(step, &scene.step_on(input, executor)?);
            }
            Ok(())
        })?
    }

    /// The spheres.
    pub fn spheres(&self) -> &[CheckedSphere<L::Float>] {
        &self.spheres
    }

    /// The spheres, to change them between runs (their number stays).
    pub fn spheres_mut(&mut self) -> &mut [CheckedSphere<L::Float>] {
        &mut self.spheres
    }

    /// The material ids.
    pub fn materials(&self) -> &[u32] {
        &self.materials
    }

    /// The walls.
    pub fn walls(&self) -> &W {
        &self.walls
    }

    /// The walls, to move them between runs.
    pub fn walls_mut(&mut self) -> &mut W {
        &mut self.walls
    }

    /// The box.
    pub fn domain(&self) -> &Domain<L::Float> {
        &self.domain
    }

    /// Verlet-list builds of the last run.
    pub fn list_builds(&self) -> usize {
        self.list_builds
    }
}

/// The diameter that sizes an owned scene's cells: its largest sphere's, or, with no sphere, a
/// quarter of the domain's shortest side (cells of any size hold no contact; a periodic
/// direction needs three).
fn largest_diameter<F: soft_sphere::prelude::Float>(
    spheres: &[CheckedSphere<F>],
    domain: &Domain<F>,
) -> F {
    if spheres.is_empty() {
        let [x, y, z] = (domain.upper - domain.lower).to_array();
        let quarter = F::HALF * F::HALF;
        return x.min_of(y).min_of(z) * quarter;
    }
    spheres
        .iter()
        .fold(F::ZERO, |largest, s| largest.max_of(s.radius + s.radius))
}
