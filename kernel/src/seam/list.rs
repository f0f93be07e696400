//! The list seam: a whole contact list, over the engine's own arrays, in one call.
//!
//! An engine keeps its spheres as arrays (positions, velocities, spins, radii, masses, material
//! ids) and a neighbour list as index pairs. [`MaterialTable::evaluate`] takes those as they
//! are, checks every sphere once, evaluates each pair and each sphere-wall contact with its
//! pair of materials' law, reads the states the last step left and writes the next ones into a
//! second buffer (double buffering: the engine swaps the two when the call succeeds), and
//! writes each sphere's contact force and torque. The states it reads are borrowed shared, so
//! on an error they are as they were, and the error says which sphere, pair or wall and why.
//! The step is checked against the spheres present ([`MaterialTable::time_step`]): every pair
//! of materials present at the smallest effective mass its spheres give, and every wall's
//! material.

use crate::law::engine::{BoundLaw, Law};
use crate::law::geometry::reaches_wall;
use crate::seam::executor::{Executor, Serial};
use crate::seam::list_error::{ListArray, ListError};
use crate::seam::pair_check::{CheckedPairs, check_places};
use crate::seam::pairs::{Sink, evaluate_pairs};
use crate::seam::spheres::Spheres;
use crate::seam::spread::{PairLoad, spread_pairs};
use crate::seam::stats::ListStats;
use crate::seam::table::MaterialTable;
use crate::value::body::effective_mass;
use crate::value::checked::CheckedSphere;
use crate::value::error::{Parameter, ParameterError, positive};
use crate::value::float::Float;
use crate::value::forces::Interaction;
use crate::value::time_step::TimeStep;
use crate::value::vector::Vec3;
use crate::value::wall::Wall;

/// A wall (a plane or a cylinder) made of a material of the table.
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
    /// Sphere-sphere pairs `[i, j]` (`i` is body i) and their periodic shifts, checked for
    /// the spheres: by [`CheckedPairs::new`] for this call, or when the engine built its list
    /// ([`PairList::checked`](crate::PairList::checked)).
    pub pairs: CheckedPairs<'a, F>,
    /// One state per pair as the last step left it, kept beside the pairs from step to step
    /// (read; the next ones go to [`ListOutput::next_pair_states`]).
    pub pair_states: &'a [S],
    /// The walls.
    pub walls: &'a [MaterialWall<F>],
    /// One state per sphere and wall, sphere by sphere: sphere `k` against wall `w` is entry
    /// `k * walls.len() + w`; as the last step left them (read).
    pub wall_states: &'a [S],
}

/// Where an evaluation writes, every element in full: each sphere's contact force and torque,
/// each contact's next state (the second buffer of the engine's double-buffered states) and,
/// when given, each contact's outcome. What these arrays held before the call is not read;
/// after a refused call they hold nothing of meaning.
#[derive(Debug)]
pub struct ListOutput<'a, F, S> {
    /// Each sphere's force from its contacts (N): the sum, in list order, of its contacts'.
    pub force: &'a mut [Vec3<F>],
    /// Each sphere's torque from its contacts (N m), summed as [`ListOutput::force`] is.
    pub torque: &'a mut [Vec3<F>],
    /// Each pair's state after the step (one per pair; reset where apart). When the call
    /// succeeds the engine swaps this buffer with [`ContactList::pair_states`].
    pub next_pair_states: &'a mut [S],
    /// Each sphere-wall contact's state after the step, in the order of
    /// [`ContactList::wall_states`].
    pub next_wall_states: &'a mut [S],
    /// Each contact's outcome when given (for force chains): the pairs' first, then the
    /// walls' in the order of their states ([`ListOutput::records_needed`] of them).
    pub records: Option<&'a mut [Interaction<F>]>,
}

impl<F, S> ListOutput<'_, F, S> {
    /// The length of [`ListOutput::records`] for `pairs` pairs and `spheres` spheres against
    /// `walls` walls.
    pub fn records_needed(pairs: usize, spheres: usize, walls: usize) -> usize {
        pairs + spheres * walls
    }
}

/// Checks the spheres: lengths, material ids, every sphere (in that order, the first failure
/// winning). Returns the lightest sphere's mass of each material present.
fn check_spheres<F: Float, const MATERIALS: usize>(
    spheres: &impl Spheres<F>,
) -> Result<[Option<F>; MATERIALS], ListError> {
    check_materials::<F, MATERIALS>(spheres)?;
    let mut lightest = [None; MATERIALS];
    for k in 0..spheres.len() {
        let slot = &mut lightest[spheres.material(k) as usize];
        let mass = spheres.sphere(k).mass;
        *slot = Some(slot.map_or(mass, |m: F| m.min_of(mass)));
    }
    Ok(lightest)
}

/// Checks the spheres as [`check_spheres`] does, without the masses an evaluation does not need.
fn check_materials<F: Float, const MATERIALS: usize>(
    spheres: &impl Spheres<F>,
) -> Result<(), ListError> {
    spheres.check_lengths()?;
    // Valid spheres, the rule, cost sums over whole arrays; only when one fails are they
    // checked one by one, to name the first.
    if spheres.all_valid(MATERIALS) {
        return Ok(());
    }
    for k in 0..spheres.len() {
        let material = spheres.material(k);
        if material as usize >= MATERIALS {
            return Err(ListError::Material {
                sphere: k,
                material,
            });
        }
        spheres.check(k)?;
    }
    Ok(())
}

fn check_walls<F, const MATERIALS: usize>(walls: &[MaterialWall<F>]) -> Result<(), ListError> {
    match walls.iter().position(|w| w.material as usize >= MATERIALS) {
        Some(wall) => Err(ListError::WallMaterial {
            wall,
            material: walls[wall].material,
        }),
        None => Ok(()),
    }
}

impl<L: Law, const MATERIALS: usize> MaterialTable<L, MATERIALS> {
    /// Checks `seconds` for these spheres and walls, for accuracy
    /// ([`ContactLaw::time_step`](crate::ContactLaw::time_step)): against the law of every pair of materials
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
        spheres: &impl Spheres<L::Float>,
        walls: &[MaterialWall<L::Float>],
    ) -> Result<TimeStep<L::Float>, ListError> {
        self.step_by(seconds, spheres, walls, L::time_step)
            .map(|()| TimeStep::accurate(seconds))
    }

    /// Checks `seconds` for stability only, as [`MaterialTable::time_step`] checks it for
    /// accuracy: with [`ContactLaw::coarse_time_step`](crate::ContactLaw::coarse_time_step) for
    /// every pair of materials present and every material with every wall's. A step past the
    /// accuracy limit, asked for knowingly.
    ///
    /// # Errors
    /// As [`MaterialTable::time_step`], without
    /// [`ParameterError::TimeStepInaccurate`](crate::ParameterError::TimeStepInaccurate).
    pub fn coarse_time_step(
        &self,
        seconds: L::Float,
        spheres: &impl Spheres<L::Float>,
        walls: &[MaterialWall<L::Float>],
    ) -> Result<TimeStep<L::Float>, ListError> {
        self.step_by(seconds, spheres, walls, L::coarse_time_step)
            .map(|()| TimeStep::checked(seconds))
    }

    /// Checks `seconds` with `check` for every pair of materials present and every material
    /// with every wall's (see [`MaterialTable::time_step`]).
    fn step_by(
        &self,
        seconds: L::Float,
        spheres: &impl Spheres<L::Float>,
        walls: &[MaterialWall<L::Float>],
        check: impl Fn(&L, L::Float, L::Float) -> Result<TimeStep<L::Float>, ParameterError>,
    ) -> Result<(), ListError> {
        let lightest = check_spheres::<_, MATERIALS>(spheres)?;
        check_walls::<_, MATERIALS>(walls)?;
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
                check(&laws[a][b], seconds, effective_mass(mass_a, mass_b))
                    .map_err(refused(a, b))?;
            }
            for wall in walls {
                let w = wall.material as usize;
                check(&laws[a][w], seconds, mass_a).map_err(refused(a, w))?;
            }
        }
        Ok(())
    }

    /// The largest step every law present recommends ([`ContactLaw::recommended_time_step`](crate::ContactLaw::recommended_time_step))
    /// for the effective masses [`MaterialTable::time_step`] checks; `None` when nothing is
    /// present.
    ///
    /// # Errors
    /// As [`MaterialTable::time_step`] for bad arrays.
    pub fn recommended_time_step(
        &self,
        spheres: &impl Spheres<L::Float>,
        walls: &[MaterialWall<L::Float>],
    ) -> Result<Option<L::Float>, ListError> {
        let lightest = check_spheres::<_, MATERIALS>(spheres)?;
        check_walls::<_, MATERIALS>(walls)?;
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
    /// checked once. Each contact's next state (its state advanced from `list`'s, reset where
    /// apart) is written into `out`'s state buffers, each sphere's force and torque is written
    /// as the sum of its touching contacts' in list order (so the sums are the same bits on any
    /// number of threads), and `out.records`, when given, receives every contact's outcome.
    /// `list`'s states are only read: after a refused call they are as they were, and an engine
    /// swaps its two state buffers only after a call that succeeded.
    ///
    /// ```
    /// use soft_sphere::prelude::{
    ///     CheckedPairs, ContactList, LinearMaterial, LinearMixing, ListOutput, MaterialTable,
    ///     ModelAA, SphereArrays, Vec3,
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
    /// // Double-buffered states: read from one, written into the other, swapped on success.
    /// let (mut states, mut next) = ([Default::default(); 2], [Default::default(); 2]);
    /// let list = ContactList {
    ///     pairs: CheckedPairs::new(&[[0, 1], [1, 2]], &[], 3).unwrap(),
    ///     pair_states: &states,
    ///     walls: &[],
    ///     wall_states: &[],
    /// };
    /// let (mut force, mut torque) = ([Vec3::ZERO; 3], [Vec3::ZERO; 3]);
    /// let out = ListOutput {
    ///     force: &mut force,
    ///     torque: &mut torque,
    ///     next_pair_states: &mut next,
    ///     next_wall_states: &mut [],
    ///     records: None,
    /// };
    /// let stats = table.evaluate(step, &spheres, list, out).unwrap();
    /// core::mem::swap(&mut states, &mut next);
    /// assert_eq!(stats.pair_contacts, 2);
    /// assert!(force[0].x < 0.0 && force[2].x > 0.0); // pushed apart by the steel sphere
    /// assert!(force[1].x.abs() < 1e-15); // ... which is squeezed evenly
    /// ```
    ///
    /// # Errors
    /// In this order, the first failure winning; `list` is unchanged and `out` holds nothing of
    /// meaning: [`ListError::Length`] for an array of the wrong length;
    /// [`ListError::Material`] / [`ListError::Sphere`] for the first bad sphere;
    /// [`ListError::WallMaterial`];
    /// [`ListError::PairIndex`] (then [`ListError::Shift`]) for the first bad pair, only when
    /// the pairs were checked for more spheres than these (a list checked for these spheres or
    /// fewer is not checked again); [`ListError::Pair`] and
    /// [`ListError::Wall`] for the first refused contact, in list order.
    pub fn evaluate(
        &self,
        time_step: TimeStep<L::Float>,
        spheres: &impl Spheres<L::Float>,
        list: ContactList<'_, L::Float, L::State>,
        out: ListOutput<'_, L::Float, L::State>,
    ) -> Result<ListStats<L::Float>, ListError> {
        self.evaluate_with((&Serial, &mut []), time_step, spheres, list, out)
    }

    /// [`MaterialTable::evaluate`] with the pairs spread over `executor`'s threads: each
    /// thread evaluates stretches of the list into `loads` (one per pair, working memory the
    /// engine keeps), then one thread adds them onto the spheres in list order. The same bits,
    /// states, records, statistics and errors as [`MaterialTable::evaluate`] for any executor and
    /// any number of threads. With a [`Serial`] executor, or `loads` empty, the pairs are
    /// evaluated on this thread as [`MaterialTable::evaluate`] does.
    ///
    /// # Errors
    /// As [`MaterialTable::evaluate`]; [`ListError::Length`] with [`ListArray::Loads`] for
    /// `loads` neither empty nor one per pair.
    pub fn evaluate_on<E: Executor>(
        &self,
        (executor, loads): (&E, &mut [PairLoad<L::Float>]),
        time_step: TimeStep<L::Float>,
        spheres: &impl Spheres<L::Float>,
        list: ContactList<'_, L::Float, L::State>,
        out: ListOutput<'_, L::Float, L::State>,
    ) -> Result<ListStats<L::Float>, ListError> {
        self.evaluate_with((executor, loads), time_step, spheres, list, out)
    }

    fn evaluate_with<E: Executor>(
        &self,
        (executor, loads): (&E, &mut [PairLoad<L::Float>]),
        time_step: TimeStep<L::Float>,
        spheres: &impl Spheres<L::Float>,
        list: ContactList<'_, L::Float, L::State>,
        out: ListOutput<'_, L::Float, L::State>,
    ) -> Result<ListStats<L::Float>, ListError> {
        let n = spheres.len();
        let (pairs, shifts, walls) = (list.pairs.pairs(), list.pairs.shifts(), list.walls);
        let contacts =
            ListOutput::<L::Float, L::State>::records_needed(pairs.len(), n, walls.len());
        let records = out.records.as_ref().map_or(contacts, |r| r.len());
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
                out.next_pair_states.len(),
                pairs.len(),
                ListArray::NextPairStates,
            ),
            (
                out.next_wall_states.len(),
                n * walls.len(),
                ListArray::NextWallStates,
            ),
            (records, contacts, ListArray::Records),
            (
                loads.len(),
                if loads.is_empty() { 0 } else { pairs.len() },
                ListArray::Loads,
            ),
        ];
        if let Some(&(_, _, array)) = lengths.iter().find(|(got, wanted, _)| got != wanted) {
            return Err(ListError::Length(array));
        }
        check_materials::<_, MATERIALS>(spheres)?;
        check_walls::<_, MATERIALS>(walls)?;
        // Checked when the pairs were made, for as many spheres as these or fewer; a list
        // checked for more is checked again against these.
        if list.pairs.spheres() > n {
            check_places((pairs, shifts), n)?;
        }
        out.force.fill(Vec3::ZERO);
        out.torque.fill(Vec3::ZERO);
        let mut sink = Sink {
            force: out.force,
            torque: out.torque,
            records: out.records,
            stats: ListStats::default(),
        };
        let laws = self.rows();
        let mut bound: [[BoundLaw<L>; MATERIALS]; MATERIALS] =
            core::array::from_fn(|a| core::array::from_fn(|b| laws[a][b].at(time_step)));
        let states = (list.pair_states, &mut *out.next_pair_states);
        let outcome = if E::PARALLEL && !loads.is_empty() {
            spread_pairs(
                executor,
                spheres,
                (pairs, shifts),
                states,
                loads,
                &bound,
                &mut sink,
            )
        } else {
            evaluate_pairs::<L, MATERIALS>(
                spheres,
                (pairs, shifts, 0),
                states,
                &mut bound,
                &mut sink,
            )
            .map(|()| 0)
        };
        let spread_unstable = outcome?;
        let wall_states = (list.wall_states, &mut *out.next_wall_states);
        evaluate_walls(
            spheres,
            walls,
            wall_states,
            &mut bound,
            &mut sink,
            pairs.len(),
        )?;
        sink.stats.inaccurate_contacts = spread_unstable
            + bound
                .iter()
                .flatten()
                .map(BoundLaw::inaccurate_contacts)
                .sum::<usize>();
        Ok(sink.stats)
    }
}

/// Every sphere against every wall, sifted by distance ([`next_reaching`]), one at a time from
/// its state in `states` into `next`, committed as they go.
fn evaluate_walls<L: Law, const MATERIALS: usize>(
    spheres: &impl Spheres<L::Float>,
    walls: &[MaterialWall<L::Float>],
    (states, next): (&[L::State], &mut [L::State]),
    bound: &mut [[BoundLaw<L>; MATERIALS]; MATERIALS],
    sink: &mut Sink<'_, L::Float>,
    first: usize,
) -> Result<(), ListError> {
    if walls.is_empty() {
        return Ok(());
    }
    if let Some(records) = sink.records.as_deref_mut() {
        records[first..first + states.len()].fill(Interaction::Apart);
    }
    let count = walls.len();
    let mut from = 0;
    while let Some(place) = next_reaching(spheres, walls, next, from) {
        from = place + 1;
        let (k, w) = (place / count, place % count);
        let wall = &walls[w];
        let body = CheckedSphere::trusted(spheres.sphere(k));
        let law = &mut bound[spheres.material(k) as usize][wall.material as usize];
        let mut state = states[place];
        let outcome = law.sphere_wall(&body, &wall.wall, &mut state);
        next[place] = state;
        match outcome {
            Ok(Interaction::Touching(c)) => sink.wall(first + place, k, &c),
            Ok(Interaction::Apart) => {}
            Err(error) => {
                return Err(ListError::Wall {
                    sphere: k,
                    wall: w,
                    error,
                });
            }
        }
    }
    Ok(())
}

/// From place `from` on (sphere by sphere, wall by wall), writes the relaxed state of every
/// contact whose sphere cannot reach its wall by the one-contact path's own test, and returns
/// the first place whose sphere can. Most spheres are far from every wall: a small loop of its
/// own keeps their cost to a distance and a store.
#[inline(never)]
fn next_reaching<F: Float, S: Default>(
    spheres: &impl Spheres<F>,
    walls: &[MaterialWall<F>],
    states: &mut [S],
    from: usize,
) -> Option<usize> {
    let count = walls.len();
    if let [one] = walls {
        // One wall (a floor, a drum): read once, a place per sphere.
        let states = states.get_mut(from..).unwrap_or_default();
        let places = (from..spheres.len()).zip(states);
        for (k, state) in places {
            if reaches_wall(spheres.position(k), spheres.radius(k), &one.wall) {
                return Some(k);
            }
            *state = S::default();
        }
        return None;
    }
    let (mut k, mut w) = (from / count, from % count);
    while k < spheres.len() {
        let (position, radius) = (spheres.position(k), spheres.radius(k));
        while w < count {
            let place = k * count + w;
            if reaches_wall(position, radius, &walls[w].wall) {
                return Some(place);
            }
            states[place] = S::default();
            w += 1;
        }
        (k, w) = (k + 1, 0);
    }
    None
}
