//! One family's material table: every pair of materials' law (given pair by pair, the rest by
//! the kernel's mixing rules) and the time step checked against every pair of materials
//! present; and the C types of the table entry points and of a neighbour list as LAMMPS keeps
//! it (flat per-atom arrays; a list of atoms, each with a count and a first neighbour;
//! per-neighbour history values and touch flags), which `list.rs` evaluates through the
//! kernel's list seam.

use soft_sphere::prelude::{
    ContactLaw, ElasticMaterial, ElasticPlasticRolling, HertzImpact, HertzMicroSlip, HertzMixing,
    Interaction, Law, LinearMaterial, ListError, Material, MaterialTable, MaterialWall,
    MathBackend, MicroSlip, MindlinAA, Mixing, NormalModel, ParameterError, Rotation, SphereArrays,
    TangentialModel, TimeStep, Vec3, Wall,
};

use crate::real::Real;
use crate::{
    Flat, SS_MICROSLIP_SPRINGS, SS_OK, SS_PARAMETER_NONE, parameter_code, rejected_parameter,
    ss_wall,
};

/// The most materials a table holds (LAMMPS atom types).
pub const SS_MATERIALS_MAX: usize = 16;

/// An array's length or a count is negative, past what the call can index, or disagrees with
/// another (a history with fewer values per neighbour than the law keeps).
pub const SS_ERR_LENGTH: i32 = 16;
/// An atom of the list, or a neighbour, is past the atoms.
pub const SS_ERR_INDEX: i32 = 17;
/// A material (an atom's type) is past the table, or a pair of materials has no law: neither
/// its own coefficients nor both materials' for the mixing rule.
pub const SS_ERR_MATERIAL: i32 = 18;
/// The table's time step has not been checked (`ss_table_prepare_*`) since it last changed.
pub const SS_ERR_NOT_PREPARED: i32 = 19;
/// A neighbour list names a pair twice (`ss_check_neighbours`): its force would be added twice.
pub const SS_ERR_REPEATED_PAIR: i32 = 21;

/// No rolling resistance.
pub const SS_ROLLING_NONE: i32 = 0;
/// The elastic-plastic spring-dashpot rolling resistance (the kernel's `ElasticPlasticRolling`;
/// Ai et al. 2011, model C): a rolling spring `k_r` limited to `mu_r R* |F_n|`, a dashpot
/// `eta_r` below the limit. Not with the frictionless families.
pub const SS_ROLLING_EPSD: i32 = 1;

/// What a table is made for: one family of laws for every pair of materials.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct ss_table_config<F> {
    /// `SS_MODEL_*`: every pair's law is of this family.
    pub model: i32,
    /// `SS_ROLLING_*`: every pair's rolling resistance.
    pub rolling: i32,
    /// `SS_ROLLING_EPSD`: the smallest effective moment of inertia of any contact (kg m^2; for
    /// two solid spheres, at least half the smaller `2/5 m R^2`), which the step is checked for.
    pub smallest_inertia: F,
    /// How many materials (at most `SS_MATERIALS_MAX`).
    pub materials: usize,
    /// `SS_MODEL_HERTZ_*`: the fastest normal approach the time step is checked for (m/s).
    pub largest_impact_speed: F,
    /// `SS_MODEL_HERTZ_*`: the largest effective radius `R*` the time step is checked for (m).
    pub largest_effective_radius: F,
}

/// The coefficients of a material, or of one pair of materials' contact. The linear laws read
/// the first five, the Hertz laws Young's modulus, Poisson's ratio, restitution, the dashpot
/// ratio and friction. The frictionless laws ignore the tangential ones.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ss_coefficients<F> {
    /// k_n (N/m), linear laws.
    pub normal_stiffness: F,
    /// Normal restitution e, in [0, 1].
    pub restitution: F,
    /// k_t (N/m), linear laws.
    pub tangential_stiffness: F,
    /// The dashpot ratio eta_t / eta_n.
    pub dashpot_ratio: F,
    /// Coulomb mu.
    pub friction: F,
    /// Young's modulus E (Pa), Hertz laws.
    pub youngs_modulus: F,
    /// Poisson's ratio nu, in (-1, 0.5], Hertz laws.
    pub poisson_ratio: F,
    /// `SS_ROLLING_EPSD`: the rolling friction `mu_r`.
    pub rolling_friction: F,
    /// `SS_ROLLING_EPSD`: the rolling stiffness `k_r` (N m/rad).
    pub rolling_stiffness: F,
    /// `SS_ROLLING_EPSD`: the rolling dashpot `eta_r` (N m s/rad).
    pub rolling_damping: F,
}

/// Why `ss_table_prepare_*` refused: the pair of materials and, for a refused step, the largest
/// stable step of that pair.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ss_table_report<F> {
    /// The two materials (-1 when the error is about none).
    pub materials: [i64; 2],
    /// `SS_PARAMETER_*` the error is about.
    pub parameter: i32,
    /// For `SS_ERR_UNSTABLE_TIME_STEP` (`SS_ERR_INACCURATE_TIME_STEP`): the pair's largest stable
    /// (accurate) step (s).
    pub limit: F,
}

/// The atoms, as flat arrays of `count` entries (three per atom for vectors): owned atoms
/// first, then ghosts. The material of atom `k` is `types[k] - first_type`.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_atoms<F> {
    /// How many atoms every array holds (LAMMPS: `nlocal + nghost`).
    pub count: usize,
    /// The atoms `[0, owned)` are this process's own (LAMMPS: `nlocal`).
    pub owned: usize,
    /// Centres (m), x y z per atom.
    pub position: *const F,
    /// Velocities (m/s), x y z per atom.
    pub velocity: *const F,
    /// Angular velocities (rad/s), x y z per atom.
    pub angular_velocity: *const F,
    /// Radii (m).
    pub radius: *const F,
    /// Masses (kg).
    pub mass: *const F,
    /// Types.
    pub types: *const i32,
    /// The type of material 0 (LAMMPS: 1).
    pub first_type: i32,
}

/// A neighbour list as LAMMPS keeps it: `count` atoms (`atoms[0 .. count)`); atom `i`'s
/// neighbours are `first_neighbour[i][0 .. neighbour_counts[i])`, each masked with
/// `index_mask`. `neighbour_counts` and `first_neighbour` are indexed by atom, so they must hold
/// an entry for every atom the list names.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_neighbours {
    /// How many atoms the list holds (LAMMPS: `inum`).
    pub count: usize,
    /// The atoms (LAMMPS: `ilist`).
    pub atoms: *const i32,
    /// Per atom, how many neighbours (LAMMPS: `numneigh`).
    pub neighbour_counts: *const i32,
    /// Per atom, its first neighbour (LAMMPS: `firstneigh`).
    pub first_neighbour: *const *const i32,
    /// ANDed with each neighbour (LAMMPS: `NEIGHMASK`; -1 keeps every bit).
    pub index_mask: i32,
}

/// The per-neighbour history, beside the neighbour list: atom `i`'s `jj`-th neighbour keeps
/// `values` numbers from `first_value[i] + jj * values` and a touch flag at
/// `first_touch[i][jj]` (LAMMPS: `fix neigh/history`'s `firstvalue` and `firstflag`). The flag
/// is 1 where the neighbour keeps a state (not all zero): the kernel relaxes the state of a pair
/// apart to zero, so a host may drop every other neighbour's values when it rebuilds its list.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_history<F> {
    /// Numbers per neighbour, at least `ss_table_state_values_*`.
    pub values: usize,
    /// Per atom, its first neighbour's values.
    pub first_value: *const *mut F,
    /// Per atom, its first neighbour's touch flag.
    pub first_touch: *const *mut i32,
}

/// Where the forces go: added to `force` and `torque` (x y z per atom, `count` atoms), on every
/// atom when `newton` is 1 (LAMMPS `newton_pair on`: ghosts' forces are sent home), else only
/// on the owned atoms.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_loads<F> {
    /// Forces (N), added to.
    pub force: *mut F,
    /// Torques (N m), added to.
    pub torque: *mut F,
    /// 1: every atom receives; 0: only the owned atoms.
    pub newton: i32,
    /// Null, or three numbers per neighbour in list order: each pair's force on its atom `i`
    /// (N; zero for a pair apart), for a host's per-pair sums such as the virial.
    pub pair_force: *mut F,
}

/// Walls (planes or cylinders) for `ss_table_evaluate_walls_*`, all of one material of the table, and each
/// atom's state against each: atom `k`'s against wall `w` is the `ss_table_state_values_*`
/// numbers from `states + k * stride + w * wall_stride`.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_walls<F> {
    /// How many walls.
    pub count: usize,
    /// The walls.
    pub walls: *const ss_wall<F>,
    /// Their material.
    pub material: u32,
    /// The atoms' states against the walls.
    pub states: *mut F,
    /// Numbers per atom in `states`.
    pub stride: usize,
    /// Numbers between one wall's state and the next within an atom's.
    pub wall_stride: usize,
    /// Null: every owned atom meets the walls; else owned atom `k` does when
    /// `selected[k] & bit` is not 0 (LAMMPS: `mask` and a fix's `groupbit`).
    pub selected: *const i32,
    /// See `selected`.
    pub bit: i32,
}

/// What an evaluation found, and which atoms an error is about.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct ss_list_report {
    /// Touching pairs.
    pub contacts: usize,
    /// Pairs at the Coulomb limit.
    pub sliding: usize,
    /// The atoms (indices into the arrays) an error is about; -1 when none.
    pub atoms: [i64; 2],
    /// Touching contacts past their law's accuracy limit, evaluated because the table was
    /// prepared for a coarse step (`ss_table_prepare_coarse_*`); 0 otherwise.
    pub inaccurate: usize,
}

/// One family's table.
#[derive(Debug)]
pub(crate) struct Tabled<F: Real, X: Mixing<F>> {
    pub(crate) mixing: X,
    pub(crate) properties: fn(&ss_coefficients<F>) -> Result<X::Properties, ParameterError>,
    pub(crate) materials: usize,
    /// Each material's own coefficients, for the mixing rule.
    pub(crate) own: [Option<X::Properties>; SS_MATERIALS_MAX],
    /// Pairs given their own coefficients: their law is the mixing rule's of those with
    /// themselves.
    pub(crate) given: [[Option<X::Properties>; SS_MATERIALS_MAX]; SS_MATERIALS_MAX],
    pub(crate) ready: Option<(MaterialTable<X::Law, SS_MATERIALS_MAX>, TimeStep<F>)>,
    /// The materials walls are made of: the step is checked against each of them with every
    /// material present, at its lightest atom's mass.
    pub(crate) walls: Vec<u32>,
    /// The pairs of materials the table evaluates, both ways round; `None`: every pair. The
    /// others are another pair style's (LAMMPS `pair_style hybrid`): the step is not checked
    /// for them and the entries refuse them.
    pub(crate) evaluated: Option<Pairs>,
    /// For each material, the materials the last prepare gave a law against it, one bit each
    /// (bit `a` of `with_law[b]`). A pair without one is another style's, with nothing to mix
    /// from and no material present to meet a wall by it: the walls entry refuses it, as the
    /// list entry refuses the others' pairs.
    pub(crate) with_law: [u32; SS_MATERIALS_MAX],
    pub(crate) work: Workspace<F, <X::Law as Law>::State>,
    pub(crate) wall_work: WallWork<F, <X::Law as Law>::State>,
}

/// Which pairs of materials a table evaluates.
pub(crate) type Pairs = [[bool; SS_MATERIALS_MAX]; SS_MATERIALS_MAX];

/// The memory an evaluation gathers the list into and the kernel writes through.
#[derive(Debug, Default)]
pub(crate) struct Workspace<F, S> {
    pub(crate) material: Vec<u32>,
    pub(crate) pairs: Vec<[u32; 2]>,
    /// The states as the host holds them, and the next ones the kernel writes.
    pub(crate) states: Vec<S>,
    pub(crate) next: Vec<S>,
    pub(crate) force: Vec<Vec3<F>>,
    pub(crate) torque: Vec<Vec3<F>>,
    pub(crate) records: Vec<Interaction<F>>,
}

/// The memory a walls evaluation gathers the selected atoms into.
#[derive(Debug)]
pub(crate) struct WallWork<F, S> {
    pub(crate) index: Vec<usize>,
    /// Selected atoms clear of every wall.
    pub(crate) clear: Vec<usize>,
    pub(crate) position: Vec<Vec3<F>>,
    pub(crate) velocity: Vec<Vec3<F>>,
    pub(crate) spin: Vec<Vec3<F>>,
    pub(crate) radius: Vec<F>,
    pub(crate) mass: Vec<F>,
    pub(crate) material: Vec<u32>,
    pub(crate) walls: Vec<MaterialWall<F>>,
    /// The states as the host holds them, and the next ones the kernel writes.
    pub(crate) states: Vec<S>,
    pub(crate) next: Vec<S>,
    pub(crate) force: Vec<Vec3<F>>,
    pub(crate) torque: Vec<Vec3<F>>,
}

impl<F, S> WallWork<F, S> {
    pub(crate) fn new() -> Self {
        Self {
            index: Vec::new(),
            clear: Vec::new(),
            position: Vec::new(),
            velocity: Vec::new(),
            spin: Vec::new(),
            radius: Vec::new(),
            mass: Vec::new(),
            material: Vec::new(),
            walls: Vec::new(),
            states: Vec::new(),
            next: Vec::new(),
            force: Vec::new(),
            torque: Vec::new(),
        }
    }
}

/// A family's properties with the rolling coefficients beside them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Rolling<P, F> {
    material: P,
    /// `mu_r`, `k_r`, `eta_r`.
    rolling: [F; 3],
}

/// A family's mixing rule with the elastic-plastic rolling resistance added to every law, its
/// coefficients mixed by their geometric means, as the family's own.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rolled<X, F> {
    pub(crate) mixing: X,
    pub(crate) smallest_inertia: F,
}

impl<F, X, N, T, M, R> Mixing<F> for Rolled<X, F>
where
    F: Real,
    X: Mixing<F, Law = ContactLaw<F, N, T, M, R>>,
    N: NormalModel<F>,
    T: TangentialModel<F>,
    M: MathBackend<F>,
    R: Rotation,
{
    type Properties = Rolling<X::Properties, F>;
    type Law = ContactLaw<F, N, T, M, R, ElasticPlasticRolling<F>>;

    fn law(&self, i: &Self::Properties, j: &Self::Properties) -> Result<Self::Law, ParameterError> {
        let law = self.mixing.law(&i.material, &j.material)?;
        let mean = |k: usize| {
            let (a, b) = (i.rolling[k], j.rolling[k]);
            if a == b {
                a
            } else {
                F::DefaultBackend::sqrt(a * b)
            }
        };
        let rolling = ElasticPlasticRolling::new(mean(0), mean(1), mean(2), self.smallest_inertia)?;
        Ok(law.with_rolling(rolling))
    }
}

pub(crate) fn rolling_of<F: Real>(c: &ss_coefficients<F>) -> [F; 3] {
    [c.rolling_friction, c.rolling_stiffness, c.rolling_damping]
}

pub(crate) fn rolled_linear<F: Real>(
    c: &ss_coefficients<F>,
) -> Result<Rolling<LinearMaterial<F>, F>, ParameterError> {
    Ok(Rolling {
        material: linear(c)?,
        rolling: rolling_of(c),
    })
}

pub(crate) fn rolled_elastic<F: Real>(
    c: &ss_coefficients<F>,
) -> Result<Rolling<ElasticMaterial<F>, F>, ParameterError> {
    Ok(Rolling {
        material: elastic(c)?,
        rolling: rolling_of(c),
    })
}

/// The Hertz-Mindlin mixing rule with micro-slip: [`HertzMixing`]'s Hertz law and Mindlin
/// parameters, the profile in `SS_MICROSLIP_SPRINGS` breakpoints.
#[derive(Clone, Copy, Debug)]
pub(crate) struct MicroSlipMixing<F: Real> {
    /// The declared impact of the Hertz law.
    pub(crate) largest: HertzImpact<F>,
}

impl<F: Real> Mixing<F> for MicroSlipMixing<F> {
    type Properties = ElasticMaterial<F>;
    type Law = HertzMicroSlip<F, SS_MICROSLIP_SPRINGS>;

    fn law(&self, i: &Self::Properties, j: &Self::Properties) -> Result<Self::Law, ParameterError> {
        let mindlin = HertzMixing::new(self.largest, MindlinAA).law(i, j)?;
        let micro = MicroSlip::new(mindlin.tangential().0);
        Ok(ContactLaw::new(*mindlin.normal(), micro))
    }
}

pub(crate) fn linear<F: Real>(c: &ss_coefficients<F>) -> Result<LinearMaterial<F>, ParameterError> {
    Ok(LinearMaterial {
        normal_stiffness: c.normal_stiffness,
        restitution: c.restitution,
        tangential_stiffness: c.tangential_stiffness,
        dashpot_ratio: c.dashpot_ratio,
        friction: c.friction,
    })
}

/// A frictionless law reads no tangential coefficient: valid placeholders stand in for them.
pub(crate) fn linear_frictionless<F: Real>(
    c: &ss_coefficients<F>,
) -> Result<LinearMaterial<F>, ParameterError> {
    Ok(LinearMaterial {
        tangential_stiffness: F::ONE,
        dashpot_ratio: F::ZERO,
        friction: F::ZERO,
        ..linear(c)?
    })
}

pub(crate) fn elastic<F: Real>(
    c: &ss_coefficients<F>,
) -> Result<ElasticMaterial<F>, ParameterError> {
    Ok(ElasticMaterial {
        elasticity: Material::new(c.youngs_modulus, c.poisson_ratio)?,
        restitution: c.restitution,
        dashpot_ratio: c.dashpot_ratio,
        friction: c.friction,
    })
}

pub(crate) fn elastic_frictionless<F: Real>(
    c: &ss_coefficients<F>,
) -> Result<ElasticMaterial<F>, ParameterError> {
    Ok(ElasticMaterial {
        dashpot_ratio: F::ZERO,
        friction: F::ZERO,
        ..elastic(c)?
    })
}

impl<F: Real, X: Mixing<F>> Tabled<F, X>
where
    <X::Law as Law>::State: Flat<F>,
{
    pub(crate) fn new(
        mixing: X,
        properties: fn(&ss_coefficients<F>) -> Result<X::Properties, ParameterError>,
        materials: usize,
    ) -> Box<Self> {
        Box::new(Self {
            mixing,
            properties,
            materials,
            own: [None; SS_MATERIALS_MAX],
            given: [[None; SS_MATERIALS_MAX]; SS_MATERIALS_MAX],
            ready: None,
            walls: Vec::new(),
            evaluated: None,
            with_law: [0; SS_MATERIALS_MAX],
            work: Workspace {
                material: Vec::new(),
                pairs: Vec::new(),
                states: Vec::new(),
                next: Vec::new(),
                force: Vec::new(),
                torque: Vec::new(),
                records: Vec::new(),
            },
            wall_work: WallWork::new(),
        })
    }

    /// Materials `a` and `b` given `c`: `a == b` is the material's own (and mixes with the
    /// others); otherwise the pair's law is the rule's of `c` with itself.
    pub(crate) fn set(
        &mut self,
        a: usize,
        b: usize,
        c: &ss_coefficients<F>,
    ) -> Result<(), (i32, i32)> {
        if a >= self.materials || b >= self.materials {
            return Err((SS_ERR_MATERIAL, SS_PARAMETER_NONE));
        }
        let refused = |e: ParameterError| (parameter_code(e), rejected_parameter(e));
        let properties = (self.properties)(c).map_err(refused)?;
        self.mixing.law(&properties, &properties).map_err(refused)?;
        if a == b {
            self.own[a] = Some(properties);
        }
        self.given[a][b] = Some(properties);
        self.given[b][a] = Some(properties);
        self.ready = None;
        Ok(())
    }

    /// The law of materials `a` and `b`: their own coefficients', else the rule's of both
    /// materials'.
    fn law(&self, a: usize, b: usize) -> Result<X::Law, (i32, i32)> {
        let refused = |e: ParameterError| (parameter_code(e), rejected_parameter(e));
        match (self.given[a][b], self.own[a], self.own[b]) {
            (Some(p), _, _) => self.mixing.law(&p, &p).map_err(refused),
            (None, Some(p), Some(q)) => self.mixing.law(&p, &q).map_err(refused),
            _ => Err((SS_ERR_MATERIAL, SS_PARAMETER_NONE)),
        }
    }

    /// The materials walls are made of: every id a material of the table, or nothing changes.
    pub(crate) fn set_walls(&mut self, walls: &[u32]) -> i32 {
        if walls.iter().any(|&m| m as usize >= self.materials) {
            return SS_ERR_MATERIAL;
        }
        self.walls = walls.to_vec();
        self.ready = None;
        SS_OK
    }

    /// The pairs of materials the table evaluates, as pairs of ids (`a, b` names both orders;
    /// none: every pair): every id a material of the table, or nothing changes.
    pub(crate) fn set_pairs(&mut self, ids: &[u32]) -> i32 {
        if ids.iter().any(|&m| m as usize >= self.materials) {
            return SS_ERR_MATERIAL;
        }
        self.evaluated = (!ids.is_empty()).then(|| {
            let mut evaluated = [[false; SS_MATERIALS_MAX]; SS_MATERIALS_MAX];
            for pair in ids.chunks_exact(2) {
                let (a, b) = (pair[0] as usize, pair[1] as usize);
                evaluated[a][b] = true;
                evaluated[b][a] = true;
            }
            evaluated
        });
        self.ready = None;
        SS_OK
    }

    /// Whether the table evaluates materials `a` and `b` together.
    pub(crate) fn evaluates(&self, a: usize, b: usize) -> bool {
        self.evaluated.is_none_or(|e| e[a][b])
    }

    /// Builds every law and checks `dt` against each pair of materials present (the lightest
    /// mass of each; absent where it is not a positive finite number), for accuracy, or for
    /// stability only when `coarse`.
    pub(crate) fn prepare(
        &mut self,
        (dt, coarse): (F, bool),
        lightest: &[F],
        report: &mut ss_table_report<F>,
    ) -> i32 {
        self.ready = None;
        let mut with_law = [0u32; SS_MATERIALS_MAX];
        // The first pair the table evaluates (material 0 with itself, for a table of every
        // pair) seeds the table; another style's pairs keep that law, never evaluated.
        let materials = self.materials;
        let pairs = (0..materials).flat_map(|a| (a..materials).map(move |b| (a, b)));
        // The walls meet every material present, whatever pairs the table evaluates: its law
        // against a wall's material is built (and refused) as an evaluated pair's.
        let wall = |m: usize| self.walls.iter().any(|&w| w as usize == m);
        let meets = |m: usize| lightest.get(m).is_some_and(|&mass| mass > F::ZERO);
        let built = |a: usize, b: usize| {
            self.evaluates(a, b) || (wall(a) && meets(b)) || (wall(b) && meets(a))
        };
        let (a0, b0) = (pairs.clone())
            .find(|&(a, b)| built(a, b))
            .unwrap_or((0, 0));
        let mut table = match self.law(a0, b0) {
            Ok(law) => MaterialTable::<X::Law, SS_MATERIALS_MAX>::uniform(law),
            Err((code, parameter)) => {
                report.materials = [a0 as i64, b0 as i64];
                report.parameter = parameter;
                return code;
            }
        };
        for (a, b) in pairs {
            report.materials = [a as i64, b as i64];
            let law = match self.law(a, b) {
                Ok(law) => law,
                Err(_) if !built(a, b) => continue,
                Err((code, parameter)) => {
                    report.parameter = parameter;
                    return code;
                }
            };
            if table.set(a, b, law).is_err() {
                return SS_ERR_MATERIAL;
            }
            with_law[a] |= 1 << b;
            with_law[b] |= 1 << a;
        }
        self.with_law = with_law;
        // One sphere of each material present, of its lightest mass: the kernel checks the step
        // against every pair of them.
        if !lightest.iter().all(|m| m.is_finite()) {
            report.materials = [-1, -1];
            return crate::SS_ERR_NON_FINITE_INPUT;
        }
        let present = |m: F| m > F::ZERO;
        let mut mass = Vec::new();
        let mut material = Vec::new();
        for (a, &m) in lightest.iter().enumerate().filter(|(_, m)| present(**m)) {
            mass.push(m);
            material.push(a as u32);
        }
        let zero = vec![Vec3::ZERO; mass.len()];
        let spheres = SphereArrays {
            position: &zero,
            velocity: &zero,
            angular_velocity: &zero,
            radius: &vec![F::ONE; mass.len()],
            mass: &mass,
            material: &material,
        };
        // Only a wall's material enters the step's check; where the wall lies does not.
        let Ok(plane) = Wall::new(Vec3::ZERO, Vec3::new(F::ZERO, F::ZERO, F::ONE)) else {
            return SS_ERR_MATERIAL;
        };
        let walls: Vec<MaterialWall<F>> = (self.walls.iter())
            .map(|&material| MaterialWall {
                wall: plane,
                material,
            })
            .collect();
        let step = match self.evaluated {
            None if coarse => table.coarse_time_step(dt, &spheres, &walls),
            None => table.time_step(dt, &spheres, &walls),
            Some(evaluated) => {
                step_of_pairs(&table, (dt, coarse), (&mass, &material), &walls, &evaluated)
            }
        };
        let step = match step {
            Ok(step) => step,
            Err(ListError::TimeStep { materials, error }) => {
                report.materials = materials.map(i64::from);
                report.parameter = rejected_parameter(error);
                if let ParameterError::TimeStepUnstable { limit, .. }
                | ParameterError::TimeStepInaccurate { limit, .. } = error
                {
                    report.limit = F::from_f64(limit);
                }
                return parameter_code(error);
            }
            Err(_) => return SS_ERR_MATERIAL,
        };
        report.materials = [-1, -1];
        self.ready = Some((table, step));
        SS_OK
    }
}

/// The step checked, for accuracy or (`coarse`) stability only, as the kernel's
/// `MaterialTable::time_step` checks it but for the pairs of materials `evaluated` alone: each
/// such pair of the materials present (one sphere of each, of its lightest `mass`) at their
/// effective mass, and every material present against each wall at its own.
fn step_of_pairs<L: Law>(
    table: &MaterialTable<L, SS_MATERIALS_MAX>,
    (dt, coarse): (L::Float, bool),
    (mass, material): (&[L::Float], &[u32]),
    walls: &[MaterialWall<L::Float>],
    evaluated: &Pairs,
) -> Result<TimeStep<L::Float>, ListError> {
    let check = |a: u32, b: u32, effective_mass: L::Float| {
        // Every id is below `SS_MATERIALS_MAX` (checked where it was given).
        let law = (table.law(a as usize, b as usize)).ok_or(ListError::Material {
            sphere: 0,
            material: b,
        })?;
        let checked = if coarse {
            law.coarse_time_step(dt, effective_mass)
        } else {
            law.time_step(dt, effective_mass)
        };
        checked.map_err(|error| ListError::TimeStep {
            materials: [a, b],
            error,
        })
    };
    let present = material.iter().zip(mass);
    for (k, (&a, &mass_a)) in present.clone().enumerate() {
        for (&b, &mass_b) in present.clone().skip(k) {
            if evaluated[a as usize][b as usize] {
                check(a, b, soft_sphere::prelude::effective_mass(mass_a, mass_b))?;
            }
        }
        for wall in walls {
            check(a, wall.material, mass_a)?;
        }
    }
    // Nothing present to check with: the step itself (positive and finite).
    let none = SphereArrays {
        position: &[],
        velocity: &[],
        angular_velocity: &[],
        radius: &[],
        mass: &[],
        material: &[],
    };
    if coarse {
        table.coarse_time_step(dt, &none, &[])
    } else {
        table.time_step(dt, &none, &[])
    }
}
