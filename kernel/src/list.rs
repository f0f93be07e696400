//! The list seam: a whole contact list, over the engine's own arrays, in one call.
//!
//! An engine keeps its spheres as arrays (positions, velocities, spins, radii, masses, material
//! ids) and a neighbour list as index pairs. [`MaterialTable::evaluate`] takes those as they
//! are, checks every sphere once, evaluates each pair and each sphere-wall contact with its
//! pair of materials' law, and only when every contact succeeded advances the states and adds
//! the forces and torques into the engine's arrays: on an error nothing the caller gave has
//! changed, and the error says which sphere, pair or wall and why. The step is checked against
//! the spheres present ([`MaterialTable::time_step`]): every pair of materials present at the
//! smallest effective mass its spheres give, and every wall's material.

use crate::batch::{ContactBlock, LANES, PairBlock};
use crate::body::{Sphere, Wall, effective_mass};
use crate::checked::{self, CheckedSphere};
use crate::engine::{BoundLaw, Law};
use crate::error::{ContactError, Parameter, ParameterError, positive};
use crate::float::Float;
use crate::geometry::Separation;
use crate::law::Interaction;
use crate::table::MaterialTable;
use crate::time_step::TimeStep;
use crate::vector::Vec3;

/// How [`MaterialTable::evaluate_by`] evaluates the touching pairs: the same results by every
/// route.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Route {
    /// Blocks where the law vectorises ([`Law::VECTORISES`]: its tangential slot computes every
    /// lane without branching, and the build has 256-bit vectors), else one at a time.
    #[default]
    Auto,
    /// Sorted by pair of materials into blocks of [`LANES`] through the batch path.
    Blocks,
    /// One pair at a time through the one-contact path.
    OneAtATime,
}

/// The engine's spheres, as its own arrays: sphere `k` is entry `k` of each. Every array must
/// be as long as `position`.
#[derive(Clone, Copy, Debug)]
pub struct SphereArrays<'a, F> {
    /// Centre positions (m).
    pub position: &'a [Vec3<F>],
    /// Centre velocities (m/s).
    pub velocity: &'a [Vec3<F>],
    /// Angular velocities (rad/s).
    pub angular_velocity: &'a [Vec3<F>],
    /// Radii (m).
    pub radius: &'a [F],
    /// Masses (kg).
    pub mass: &'a [F],
    /// Material ids, rows of the [`MaterialTable`].
    pub material: &'a [u32],
}

impl<F: Float> SphereArrays<'_, F> {
    /// How many spheres.
    pub fn len(&self) -> usize {
        self.position.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.position.is_empty()
    }

    /// Sphere `k`, which must be below [`SphereArrays::len`] and the arrays checked.
    #[inline(always)]
    fn sphere(&self, k: usize) -> Sphere<F> {
        Sphere {
            position: self.position[k],
            velocity: self.velocity[k],
            angular_velocity: self.angular_velocity[k],
            radius: self.radius[k],
            mass: self.mass[k],
        }
    }
}

/// A plane wall made of a material of the table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaterialWall<F> {
    /// The wall.
    pub wall: Wall<F>,
    /// Its material id.
    pub material: u32,
}

/// The contacts of one evaluation and their per-contact states, owned by the engine.
#[derive(Debug)]
pub struct ContactList<'a, F, S> {
    /// Sphere-sphere pairs, as indices into the [`SphereArrays`]; `i` is body i.
    pub pairs: &'a [[u32; 2]],
    /// One state per pair, kept beside the pairs from step to step.
    pub pair_states: &'a mut [S],
    /// The walls.
    pub walls: &'a [MaterialWall<F>],
    /// One state per sphere and wall, sphere by sphere: sphere `k` against wall `w` is entry
    /// `k * walls.len() + w`.
    pub wall_states: &'a mut [S],
}

/// Where an evaluation writes: the engine's force and torque arrays (one per sphere; the
/// contacts' forces and torques are added to what they hold), and one record per contact.
#[derive(Debug)]
pub struct ListOutput<'a, F, S> {
    /// Force on each sphere (N), added to.
    pub force: &'a mut [Vec3<F>],
    /// Torque on each sphere (N m), added to.
    pub torque: &'a mut [Vec3<F>],
    /// One record per contact: the pairs' first, then the walls' in the order of their states.
    /// Read them for force chains; [`ListOutput::records_needed`] gives the length.
    pub records: &'a mut [ContactRecord<F, S>],
}

impl<F, S> ListOutput<'_, F, S> {
    /// The length of [`ListOutput::records`] for `pairs` pairs and `spheres` spheres against
    /// `walls` walls.
    pub fn records_needed(pairs: usize, spheres: usize, walls: usize) -> usize {
        pairs + spheres * walls
    }
}

/// What one contact of the list gave in the last evaluation: its [`Interaction`] (forces,
/// normal, overlap, sliding), and the state it goes on from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactRecord<F, S> {
    interaction: Interaction<F>,
    state: S,
}

impl<F: Float, S: Default> Default for ContactRecord<F, S> {
    fn default() -> Self {
        Self {
            interaction: Interaction::Apart,
            state: S::default(),
        }
    }
}

impl<F, S> ContactRecord<F, S> {
    /// The contact's outcome: [`Interaction::Touching`] with its forces, or apart.
    pub fn interaction(&self) -> &Interaction<F> {
        &self.interaction
    }
}

/// Totals of one evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ListStats<F> {
    /// Sphere-sphere contacts touching.
    pub pair_contacts: usize,
    /// Sphere-wall contacts touching.
    pub wall_contacts: usize,
    /// Contacts (pairs and walls) at the Coulomb limit.
    pub sliding_contacts: usize,
    /// Contacts past the step's stability limit that the step tolerated (zero otherwise: they
    /// are refused).
    pub unstable_contacts: usize,
    /// Sum of the sphere-sphere overlaps (m).
    pub overlap_sum: F,
}

/// One of the arrays an evaluation is given.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ListArray {
    /// [`SphereArrays::velocity`].
    Velocity,
    /// [`SphereArrays::angular_velocity`].
    AngularVelocity,
    /// [`SphereArrays::radius`].
    Radius,
    /// [`SphereArrays::mass`].
    Mass,
    /// [`SphereArrays::material`].
    Material,
    /// [`ContactList::pair_states`] (one per pair).
    PairStates,
    /// [`ContactList::wall_states`] (one per sphere and wall).
    WallStates,
    /// [`ListOutput::force`].
    Force,
    /// [`ListOutput::torque`].
    Torque,
    /// [`ListOutput::records`] ([`ListOutput::records_needed`]).
    Records,
}

/// Why a list evaluation or its time step was refused. Nothing the caller gave has changed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ListError {
    /// An array's length disagrees with the spheres' (or, for states and records, with the
    /// contacts').
    Length(ListArray),
    /// Sphere `sphere`'s material id is not a row of the table.
    Material {
        /// The sphere.
        sphere: usize,
        /// Its id.
        material: u32,
    },
    /// Wall `wall`'s material id is not a row of the table.
    WallMaterial {
        /// The wall.
        wall: usize,
        /// Its id.
        material: u32,
    },
    /// Sphere `sphere` is invalid (a non-finite field, a radius or mass not positive).
    Sphere {
        /// The sphere.
        sphere: usize,
        /// What is wrong with it.
        error: ContactError,
    },
    /// Pair `pair` names a sphere past the arrays.
    PairIndex {
        /// The pair's place in the list.
        pair: usize,
    },
    /// The contact of pair `pair` was refused (coincident centres, an overflow, past the
    /// stable step).
    Pair {
        /// The pair's place in the list.
        pair: usize,
        /// Why.
        error: ContactError,
    },
    /// The contact of sphere `sphere` with wall `wall` was refused.
    Wall {
        /// The sphere.
        sphere: usize,
        /// The wall.
        wall: usize,
        /// Why.
        error: ContactError,
    },
    /// The step is refused by the law of materials `materials` (a wall's material second) at
    /// the smallest effective mass the spheres present give that pair.
    TimeStep {
        /// The two material ids.
        materials: [u32; 2],
        /// The law's answer ([`ParameterError::TimeStepUnstable`] with its limit).
        error: ParameterError,
    },
}

impl core::fmt::Display for ListError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Length(array) => write!(f, "the {array:?} array has the wrong length"),
            Self::Material { sphere, material } => {
                write!(f, "sphere {sphere}'s material {material} is past the table")
            }
            Self::WallMaterial { wall, material } => {
                write!(f, "wall {wall}'s material {material} is past the table")
            }
            Self::Sphere { sphere, error } => write!(f, "sphere {sphere}: {error}"),
            Self::PairIndex { pair } => write!(f, "pair {pair} names a sphere past the arrays"),
            Self::Pair { pair, error } => write!(f, "pair {pair}: {error}"),
            Self::Wall {
                sphere,
                wall,
                error,
            } => write!(f, "sphere {sphere} against wall {wall}: {error}"),
            Self::TimeStep { materials, error } => write!(
                f,
                "materials {} and {}: {error}",
                materials[0], materials[1]
            ),
        }
    }
}

impl core::error::Error for ListError {}

/// Checks the sphere arrays: lengths, material ids, every sphere (in that order, the first
/// failure winning). Returns the lightest sphere's mass of each material present.
fn check_spheres<F: Float, const M: usize>(
    spheres: &SphereArrays<'_, F>,
) -> Result<[Option<F>; M], ListError> {
    let n = spheres.len();
    let lengths = [
        (spheres.velocity.len(), ListArray::Velocity),
        (spheres.angular_velocity.len(), ListArray::AngularVelocity),
        (spheres.radius.len(), ListArray::Radius),
        (spheres.mass.len(), ListArray::Mass),
        (spheres.material.len(), ListArray::Material),
    ];
    check_lengths(n, &lengths)?;
    let mut lightest = [None; M];
    for k in 0..n {
        let material = spheres.material[k];
        let Some(slot) = lightest.get_mut(material as usize) else {
            return Err(ListError::Material {
                sphere: k,
                material,
            });
        };
        let sphere = spheres.sphere(k);
        checked::check(&sphere).map_err(|error| ListError::Sphere { sphere: k, error })?;
        let mass = sphere.mass;
        *slot = Some(slot.map_or(mass, |m: F| m.min_of(mass)));
    }
    Ok(lightest)
}

fn check_lengths(expected: usize, lengths: &[(usize, ListArray)]) -> Result<(), ListError> {
    match lengths.iter().find(|(length, _)| *length != expected) {
        Some(&(_, array)) => Err(ListError::Length(array)),
        None => Ok(()),
    }
}

fn check_walls<F, const M: usize>(walls: &[MaterialWall<F>]) -> Result<(), ListError> {
    match walls.iter().position(|w| w.material as usize >= M) {
        Some(wall) => Err(ListError::WallMaterial {
            wall,
            material: walls[wall].material,
        }),
        None => Ok(()),
    }
}

impl<L: Law, const M: usize> MaterialTable<L, M> {
    /// Checks `seconds` for these spheres and walls: against the law of every pair of materials
    /// present, at the smallest effective mass two of their spheres give (the two lightest:
    /// `m_a m_b / (m_a + m_b)`), and against the law of every material present with every
    /// wall's material, at the lightest sphere's mass. No mass is declared by hand; a
    /// [`Hertz`](crate::Hertz) law's overlap is checked against its declared impact here, and
    /// against the step at every contact.
    ///
    /// # Errors
    /// [`ListError::Length`], [`ListError::Material`], [`ListError::WallMaterial`] and
    /// [`ListError::Sphere`] for bad arrays (as [`MaterialTable::evaluate`]);
    /// [`ListError::TimeStep`] for the first pair of materials whose law refuses the step (a
    /// non-finite or non-positive step is reported as material 0 with itself, whatever is
    /// present).
    pub fn time_step(
        &self,
        seconds: L::Float,
        spheres: &SphereArrays<'_, L::Float>,
        walls: &[MaterialWall<L::Float>],
    ) -> Result<TimeStep<L::Float>, ListError> {
        let lightest = check_spheres::<_, M>(spheres)?;
        check_walls::<_, M>(walls)?;
        let refused = |a: usize, b: usize| {
            move |error| ListError::TimeStep {
                materials: [a as u32, b as u32],
                error,
            }
        };
        let seconds = positive(seconds, Parameter::TimeStep).map_err(refused(0, 0))?;
        let laws = self.rows();
        for (a, mass_a) in lightest.iter().enumerate() {
            let Some(mass_a) = *mass_a else { continue };
            for (b, mass_b) in lightest.iter().enumerate().skip(a) {
                let Some(mass_b) = *mass_b else { continue };
                laws[a][b]
                    .time_step(seconds, effective_mass(mass_a, mass_b))
                    .map_err(refused(a, b))?;
            }
            for wall in walls {
                let w = wall.material as usize;
                laws[a][w]
                    .time_step(seconds, mass_a)
                    .map_err(refused(a, w))?;
            }
        }
        Ok(TimeStep::checked(seconds))
    }

    /// The largest step every law present recommends ([`ContactLaw::recommended_time_step`](crate::ContactLaw::recommended_time_step))
    /// for the effective masses [`MaterialTable::time_step`] checks; `None` when nothing is
    /// present.
    ///
    /// # Errors
    /// As [`MaterialTable::time_step`] for bad arrays.
    pub fn recommended_time_step(
        &self,
        spheres: &SphereArrays<'_, L::Float>,
        walls: &[MaterialWall<L::Float>],
    ) -> Result<Option<L::Float>, ListError> {
        let lightest = check_spheres::<_, M>(spheres)?;
        check_walls::<_, M>(walls)?;
        let laws = self.rows();
        let mut smallest: Option<L::Float> = None;
        let mut keep = |step: L::Float| smallest = Some(smallest.map_or(step, |s| s.min_of(step)));
        for (a, mass_a) in lightest.iter().enumerate() {
            let Some(mass_a) = *mass_a else { continue };
            for (b, mass_b) in lightest.iter().enumerate().skip(a) {
                let Some(mass_b) = *mass_b else { continue };
                keep(laws[a][b].recommended_time_step(effective_mass(mass_a, mass_b)));
            }
            for wall in walls {
                keep(laws[a][wall.material as usize].recommended_time_step(mass_a));
            }
        }
        Ok(smallest)
    }

    /// Evaluates every contact of `list` for one step: each pair `[i, j]` of spheres with the
    /// law of their materials and its state, then each sphere against each wall, in that order.
    /// Each contact gives the same bits, state and outcome as
    /// [`ContactLaw::sphere_sphere`](crate::ContactLaw::sphere_sphere) or
    /// [`ContactLaw::sphere_wall`](crate::ContactLaw::sphere_wall) with its law. Every sphere is
    /// checked once. When every contact succeeded, each state is advanced (reset where apart),
    /// each touching contact's forces and torques are added into `out.force` and `out.torque`
    /// in list order, and `out.records` holds every contact's outcome.
    ///
    /// ```
    /// use soft_sphere::{
    ///     ContactList, LinearMaterial, LinearMixing, ListOutput, MaterialTable, ModelAA,
    ///     SphereArrays, Vec3,
    /// };
    ///
    /// let glass = LinearMaterial {
    ///     normal_stiffness: 1.0e4_f64, restitution: 0.9, tangential_stiffness: 8.0e3,
    ///     dashpot_ratio: 0.5, friction: 0.4,
    /// };
    /// let steel = LinearMaterial { normal_stiffness: 4.0e4, ..glass };
    /// let table = MaterialTable::mixed(&LinearMixing::new(ModelAA), &[glass, steel]).unwrap();
    ///
    /// // Three spheres of 1 mm radius in a row, the middle one of steel, touching both others.
    /// let position = [0.0, 1.9e-3, 3.8e-3].map(|x| Vec3::new(x, 0.0, 0.0));
    /// let zero = [Vec3::ZERO; 3];
    /// let spheres = SphereArrays {
    ///     position: &position, velocity: &zero, angular_velocity: &zero,
    ///     radius: &[1.0e-3; 3], mass: &[1.0e-5; 3], material: &[0, 1, 0],
    /// };
    /// let step = table.time_step(1.0e-6, &spheres, &[]).unwrap();
    ///
    /// let mut pair_states = [Default::default(); 2];
    /// let list = ContactList {
    ///     pairs: &[[0, 1], [1, 2]], pair_states: &mut pair_states, walls: &[], wall_states: &mut [],
    /// };
    /// let (mut force, mut torque) = ([Vec3::ZERO; 3], [Vec3::ZERO; 3]);
    /// let mut records = [Default::default(); 2];
    /// let out = ListOutput { force: &mut force, torque: &mut torque, records: &mut records };
    /// let stats = table.evaluate(step, &spheres, list, out).unwrap();
    /// assert_eq!(stats.pair_contacts, 2);
    /// assert!(force[0].x < 0.0 && force[2].x > 0.0); // pushed apart by the steel sphere
    /// assert!(force[1].x.abs() < 1e-15); // ... which is squeezed evenly
    /// ```
    ///
    /// # Errors
    /// In this order, the first failure winning; nothing the caller gave is changed (states,
    /// forces, torques; the records are then unspecified):
    /// [`ListError::Length`] for an array of the wrong length; [`ListError::Material`] /
    /// [`ListError::Sphere`] for the first bad sphere; [`ListError::WallMaterial`];
    /// [`ListError::PairIndex`] for the first pair past the arrays; [`ListError::Pair`] and
    /// [`ListError::Wall`] for the first refused contact, in list order.
    pub fn evaluate(
        &self,
        time_step: TimeStep<L::Float>,
        spheres: &SphereArrays<'_, L::Float>,
        list: ContactList<'_, L::Float, L::State>,
        out: ListOutput<'_, L::Float, L::State>,
    ) -> Result<ListStats<L::Float>, ListError> {
        self.evaluate_by(Route::Auto, time_step, spheres, list, out)
    }

    /// [`MaterialTable::evaluate`] by a chosen [`Route`]: the same bits, states, records and
    /// errors by any route; only the speed differs.
    ///
    /// # Errors
    /// As [`MaterialTable::evaluate`].
    pub fn evaluate_by(
        &self,
        route: Route,
        time_step: TimeStep<L::Float>,
        spheres: &SphereArrays<'_, L::Float>,
        list: ContactList<'_, L::Float, L::State>,
        out: ListOutput<'_, L::Float, L::State>,
    ) -> Result<ListStats<L::Float>, ListError> {
        let blocks = match route {
            Route::Auto => L::VECTORISES,
            Route::Blocks => true,
            Route::OneAtATime => false,
        };
        let n = spheres.len();
        let (pairs, walls) = (list.pairs, list.walls);
        let lengths = [
            (list.pair_states.len(), pairs.len(), ListArray::PairStates),
            (
                list.wall_states.len(),
                n * walls.len(),
                ListArray::WallStates,
            ),
            (out.force.len(), n, ListArray::Force),
            (out.torque.len(), n, ListArray::Torque),
            (
                out.records.len(),
                ListOutput::<L::Float, L::State>::records_needed(pairs.len(), n, walls.len()),
                ListArray::Records,
            ),
        ];
        if let Some(&(_, _, array)) = lengths.iter().find(|(got, wanted, _)| got != wanted) {
            return Err(ListError::Length(array));
        }
        check_spheres::<_, M>(spheres)?;
        check_walls::<_, M>(walls)?;
        if let Some(pair) = pairs
            .iter()
            .position(|&[i, j]| i as usize >= n || j as usize >= n)
        {
            return Err(ListError::PairIndex { pair });
        }
        let (pair_records, wall_records) = out.records.split_at_mut(pairs.len());
        let laws = self.rows();
        let mut bound: [[BoundLaw<'_, L>; M]; M] =
            core::array::from_fn(|a| core::array::from_fn(|b| laws[a][b].at(time_step)));
        // The checks above made every sphere valid: no sphere is checked again.
        let sphere = |k: usize| CheckedSphere::trusted(spheres.sphere(k));
        let material = |k: usize| spheres.material[k] as usize;
        let mut staged = Staged::new();
        for (c, chunk) in pairs.chunks(SIFT).enumerate() {
            let first = c * SIFT;
            let states = &list.pair_states[first..first + chunk.len()];
            let records = &mut pair_records[first..first + chunk.len()];
            let failed = if blocks {
                staged.in_blocks(spheres, chunk, states, records, &mut bound)
            } else {
                let mut failed = None;
                for k in sift(spheres, chunk, records, &mut staged.touching) {
                    let [i, j] = chunk[k].map(|x| x as usize);
                    let mut next = states[k];
                    let law = &mut bound[material(i)][material(j)];
                    match law.sphere_sphere(&sphere(i), &sphere(j), &mut next) {
                        Ok(interaction) => {
                            records[k] = ContactRecord {
                                interaction,
                                state: next,
                            }
                        }
                        Err(error) => {
                            failed = Some((k, error));
                            break;
                        }
                    }
                }
                failed
            };
            if let Some((k, error)) = failed {
                return Err(ListError::Pair {
                    pair: first + k,
                    error,
                });
            }
        }
        if !walls.is_empty() {
            for (k, (states, records)) in list
                .wall_states
                .chunks(walls.len())
                .zip(wall_records.chunks_mut(walls.len()))
                .enumerate()
            {
                let body = sphere(k);
                for (w, ((wall, state), record)) in
                    walls.iter().zip(states).zip(records).enumerate()
                {
                    let mut next = *state;
                    let law = &mut bound[material(k)][wall.material as usize];
                    let interaction =
                        law.sphere_wall(&body, &wall.wall, &mut next)
                            .map_err(|error| ListError::Wall {
                                sphere: k,
                                wall: w,
                                error,
                            })?;
                    *record = ContactRecord {
                        interaction,
                        state: next,
                    };
                }
            }
        }
        let mut stats = ListStats {
            unstable_contacts: bound
                .iter()
                .flatten()
                .map(BoundLaw::unstable_contacts)
                .sum(),
            ..ListStats::default()
        };
        // Every contact succeeded: commit, in list order.
        for ((&[i, j], state), record) in pairs
            .iter()
            .zip(list.pair_states.iter_mut())
            .zip(pair_records.iter())
        {
            *state = record.state;
            if let Interaction::Touching(c) = &record.interaction {
                let (i, j) = (i as usize, j as usize);
                let on_j = c.force_on_j();
                out.force[i] -= on_j;
                out.torque[i] += c.torque_on_i;
                out.force[j] += on_j;
                out.torque[j] += c.torque_on_j;
                stats.pair_contacts += 1;
                stats.sliding_contacts += usize::from(c.sliding);
                stats.overlap_sum += c.overlap;
            }
        }
        for (k, (state, record)) in list
            .wall_states
            .iter_mut()
            .zip(wall_records.iter())
            .enumerate()
        {
            *state = record.state;
            if let Interaction::Touching(c) = &record.interaction {
                let sphere = k / walls.len();
                out.force[sphere] += c.force_on_i();
                out.torque[sphere] += c.torque_on_i;
                stats.wall_contacts += 1;
                stats.sliding_contacts += usize::from(c.sliding);
            }
        }
        Ok(stats)
    }
}

/// Candidate pairs sifted for contact at a time.
const SIFT: usize = 256;

/// Blocks gathered before the first is evaluated (as the scene does: a block read as vectors
/// straight after its lanes were stored one by one waits on every load).
const GROUP: usize = 8;

/// The places in `chunk` of the pairs the one-contact path would evaluate (overlapping or
/// coincident), into `touching`; every other pair's record is set to apart with a reset state,
/// as that path answers. Sifting first keeps the coin toss of touching or not out of the
/// contact evaluation's branches.
#[inline(always)]
fn sift<'t, F: Float, S: Default>(
    spheres: &SphereArrays<'_, F>,
    chunk: &[[u32; 2]],
    records: &mut [ContactRecord<F, S>],
    touching: &'t mut [u16; SIFT],
) -> impl Iterator<Item = usize> + 't {
    let mut found = 0;
    for (k, (&[i, j], record)) in chunk.iter().zip(records.iter_mut()).enumerate() {
        let (i, j) = (i as usize, j as usize);
        let separation = Separation::between(
            (spheres.position[i], spheres.radius[i]),
            (spheres.position[j], spheres.radius[j]),
        );
        *record = ContactRecord::default();
        touching[found] = k as u16;
        found += usize::from(separation.needs_evaluation());
    }
    touching[..found].iter().map(|&k| usize::from(k))
}

/// The working memory of the block route: sifted places, sorted by pair of materials, and a
/// group of gathered blocks.
struct Staged<F: Float, S> {
    touching: [u16; SIFT],
    sorted: [u16; SIFT],
    blocks: [PairBlock<F, LANES>; GROUP],
    states: [[S; LANES]; GROUP],
    out: ContactBlock<F, LANES>,
}

impl<F: Float, S: crate::tangential::ContactState> Staged<F, S> {
    fn new() -> Self {
        Self {
            touching: [0; SIFT],
            sorted: [0; SIFT],
            blocks: [PairBlock::default(); GROUP],
            states: [[S::default(); LANES]; GROUP],
            out: ContactBlock::default(),
        }
    }

    /// One chunk through the batch path: sifted, sorted by pair of materials (a block holds
    /// one law), gathered in groups of blocks straight from the arrays, evaluated, and each
    /// touching pair's outcome and next state written to its record. Returns the first failed
    /// pair in list order (its place in the chunk) and its error.
    #[inline(always)]
    fn in_blocks<L: Law<Float = F, State = S>, const M: usize>(
        &mut self,
        spheres: &SphereArrays<'_, F>,
        chunk: &[[u32; 2]],
        states: &[S],
        records: &mut [ContactRecord<F, S>],
        bound: &mut [[BoundLaw<'_, L>; M]; M],
    ) -> Option<(usize, ContactError)> {
        let material = |k: usize| spheres.material[k] as usize;
        let key = |k: usize| {
            let [i, j] = chunk[k].map(|x| material(x as usize));
            (i.min(j), i.max(j))
        };
        // A counting sort by pair of materials, stable, so each pair's run keeps list order.
        let mut counts = [[0usize; M]; M];
        let mut found = 0;
        for k in sift(spheres, chunk, records, &mut self.touching) {
            let (a, b) = key(k);
            counts[a][b] += 1;
            found += 1;
        }
        let mut starts = [[0usize; M]; M];
        let mut next = 0;
        for (row, starts) in counts.iter().zip(starts.iter_mut()) {
            for (count, start) in row.iter().zip(starts.iter_mut()) {
                *start = next;
                next += count;
            }
        }
        let mut place = starts;
        for &k in &self.touching[..found] {
            let (a, b) = key(usize::from(k));
            self.sorted[place[a][b]] = k;
            place[a][b] += 1;
        }
        let mut failed: Option<(usize, ContactError)> = None;
        for (a, row) in counts.iter().enumerate() {
            for (b, &count) in row.iter().enumerate() {
                let run = &self.sorted[starts[a][b]..starts[a][b] + count];
                for group in run.chunks(LANES * GROUP) {
                    let blocks = group.chunks(LANES);
                    for ((lanes, block), block_states) in
                        blocks.clone().zip(&mut self.blocks).zip(&mut self.states)
                    {
                        for lane in 0..LANES {
                            match lanes.get(lane) {
                                Some(&k) => {
                                    let [i, j] = chunk[usize::from(k)].map(|x| x as usize);
                                    block.set(lane, &spheres.sphere(i), &spheres.sphere(j));
                                    block_states[lane] = states[usize::from(k)];
                                }
                                // An unused lane: spheres of no size, refused and ignored.
                                None => block.set(lane, &Sphere::default(), &Sphere::default()),
                            }
                        }
                    }
                    for ((lanes, block), block_states) in
                        blocks.zip(&self.blocks).zip(&mut self.states)
                    {
                        evaluate_block(&mut bound[a][b], block, block_states, &mut self.out);
                        for (lane, &k) in lanes.iter().enumerate() {
                            let k = usize::from(k);
                            match self.out.outcome(lane) {
                                Ok(interaction) => {
                                    records[k] = ContactRecord {
                                        interaction,
                                        state: block_states[lane],
                                    }
                                }
                                Err(error) => {
                                    if failed.is_none_or(|(first, _)| k < first) {
                                        failed = Some((k, error));
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
        failed
    }
}

/// One block through the kernel's batch path, compiled as a function of its own so that the
/// compiler keeps its lanes in vector registers (inlined into a large loop, it stopped).
#[inline(never)]
fn evaluate_block<L: Law>(
    law: &mut BoundLaw<'_, L>,
    block: &PairBlock<L::Float, LANES>,
    states: &mut [L::State; LANES],
    out: &mut ContactBlock<L::Float, LANES>,
) {
    law.sphere_pairs(block, states, out);
}
