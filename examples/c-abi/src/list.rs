//! The list entry: a whole neighbour list over LAMMPS-shaped arrays (atoms, per-atom
//! neighbour pages, per-neighbour history) checked, gathered into the kernel's list seam,
//! evaluated and scattered back, all or nothing.

use soft_sphere::prelude::{
    CheckedPairs, CheckedSphere, ContactList, Interaction, Law, ListError, ListOutput, ListStats,
    Mixing, Sphere, SphereArrays, Vec3, check_pairs,
};

use crate::{
    Flat, SS_ERR_NON_FINITE_INPUT, SS_ERR_NULL, SS_ERR_UNSTABLE_TIME_STEP, SS_OK, contact_code,
    forces_of, ss_forces, ss_sphere,
};

use crate::real::Real;
use crate::table::*;

/// A null pointer is refused only when there is something to read through it.
pub(crate) fn present<T>(pointer: *const T, count: usize) -> bool {
    count == 0 || !pointer.is_null()
}

/// Checks every pointer and count of the list, and each of its atoms, in list order (the
/// neighbours are checked as they are gathered).
///
/// # Safety
/// As `ss_table_evaluate_*`.
pub(crate) unsafe fn check_list<F>(
    atoms: &ss_atoms<F>,
    list: &ss_neighbours,
    history: Option<(&ss_history<F>, usize)>,
    report: &mut ss_list_report,
) -> i32 {
    let n = atoms.count;
    let arrays = [
        atoms.position.cast::<u8>(),
        atoms.velocity.cast(),
        atoms.angular_velocity.cast(),
        atoms.radius.cast(),
        atoms.mass.cast(),
        atoms.types.cast(),
    ];
    if arrays.iter().any(|a| !present(*a, n)) {
        return SS_ERR_NULL;
    }
    if atoms.owned > n {
        return SS_ERR_LENGTH;
    }
    // SAFETY: forwarded contract.
    unsafe { check_pages(n, list, history, report) }
}

/// Checks the list's pointers and counts and each of its atoms for `n` atoms, in list order,
/// and the history's pointers when given (the neighbours are checked as they are gathered).
///
/// # Safety
/// As `ss_table_evaluate_*`.
unsafe fn check_pages<F>(
    n: usize,
    list: &ss_neighbours,
    history: Option<(&ss_history<F>, usize)>,
    report: &mut ss_list_report,
) -> i32 {
    if n > u32::MAX as usize || list.count > n {
        return SS_ERR_LENGTH;
    }
    let lists = [
        list.atoms.cast::<u8>(),
        list.neighbour_counts.cast(),
        list.first_neighbour.cast(),
    ];
    if lists.iter().any(|a| !present(*a, list.count)) {
        return SS_ERR_NULL;
    }
    if let Some((h, needed)) = history {
        if h.values < needed {
            return SS_ERR_LENGTH;
        }
        if !present(h.first_value, list.count) || !present(h.first_touch, list.count) {
            return SS_ERR_NULL;
        }
    }
    for ii in 0..list.count {
        // SAFETY: `atoms` holds `count` entries (the caller's promise).
        let i = unsafe { *list.atoms.add(ii) };
        report.atoms = [i64::from(i), -1];
        if i < 0 || i as usize >= n {
            return SS_ERR_INDEX;
        }
        let i = i as usize;
        // SAFETY: the per-atom arrays hold an entry for every atom the list names.
        let (count, first) =
            unsafe { (*list.neighbour_counts.add(i), *list.first_neighbour.add(i)) };
        if count < 0 {
            return SS_ERR_LENGTH;
        }
        let count = count as usize;
        if !present(first, count) {
            return SS_ERR_NULL;
        }
        if let Some((h, _)) = history {
            // SAFETY: as above.
            let (values, touch) = unsafe { (*h.first_value.add(i), *h.first_touch.add(i)) };
            if !present(values, count) || !present(touch, count) {
                return SS_ERR_NULL;
            }
        }
    }
    report.atoms = [-1, -1];
    SS_OK
}

impl<F: Real, X: Mixing<F>> Tabled<F, X>
where
    <X::Law as Law>::State: Flat<F>,
{
    /// The list entry: checks, gathers, evaluates through the seam, and on success writes the
    /// states (when `advance`), the touch flags and the forces back.
    ///
    /// # Safety
    /// As `ss_table_evaluate_*`.
    pub(crate) unsafe fn evaluate(
        &mut self,
        atoms: &ss_atoms<F>,
        list: &ss_neighbours,
        history: Option<&ss_history<F>>,
        loads: &ss_loads<F>,
        advance: bool,
        report: &mut ss_list_report,
    ) -> i32 {
        let values = <<X::Law as Law>::State as Flat<F>>::VALUES;
        let Some((table, step)) = &self.ready else {
            return SS_ERR_NOT_PREPARED;
        };
        // SAFETY: forwarded contract.
        let code = unsafe { check_list(atoms, list, history.map(|h| (h, values)), report) };
        if code != SS_OK {
            return code;
        }
        let n = atoms.count;
        if !present(loads.force, n) || !present(loads.torque, n) {
            return SS_ERR_NULL;
        }
        let receivers = if loads.newton == 1 { n } else { atoms.owned };
        // SAFETY: three numbers per atom in each.
        if let Some(k) = unsafe { first_unfinite_load(loads, receivers) } {
            report.atoms = [k as i64, -1];
            return SS_ERR_NON_FINITE_INPUT;
        }
        let vectors = |p: *const F| -> &[Vec3<F>] {
            if n == 0 {
                return &[];
            }
            // SAFETY: three numbers per atom (the caller's promise); `Vec3` is `repr(C)` of
            // three `F`s, with `F`'s alignment.
            unsafe { std::slice::from_raw_parts(p.cast::<Vec3<F>>(), n) }
        };
        let scalars = |p: *const F| -> &[F] {
            if n == 0 {
                return &[];
            }
            // SAFETY: one number per atom.
            unsafe { std::slice::from_raw_parts(p, n) }
        };
        let work = &mut self.work;
        work.material.clear();
        for k in 0..n {
            // SAFETY: one type per atom.
            let t = i64::from(unsafe { *atoms.types.add(k) }) - i64::from(atoms.first_type);
            if t < 0 || t as usize >= self.materials {
                report.atoms = [k as i64, -1];
                return SS_ERR_MATERIAL;
            }
            work.material.push(t as u32);
        }
        // Gather the pairs and their states, checking each neighbour, in list order: one pass
        // over the list.
        let mut total = 0;
        for ii in 0..list.count {
            // SAFETY: checked by `check_list`.
            total += unsafe { *list.neighbour_counts.add(*list.atoms.add(ii) as usize) } as usize;
        }
        work.pairs.resize(total, [0; 2]);
        work.states.resize(total, Default::default());
        let mut k = 0;
        for ii in 0..list.count {
            // SAFETY: checked by `check_list`.
            let (i, count, first) = unsafe {
                let i = *list.atoms.add(ii) as usize;
                (
                    i,
                    *list.neighbour_counts.add(i) as usize,
                    *list.first_neighbour.add(i),
                )
            };
            // SAFETY: atom i's neighbours hold `count` entries.
            let neighbours = unsafe { std::slice::from_raw_parts(first, count) };
            let run = k..k + count;
            // Each neighbour's index and state in one pass: the page is read once.
            let pages = history.filter(|_| values > 0).map(|h| {
                // SAFETY: checked present by `check_list`; `values` numbers per neighbour.
                (unsafe { *h.first_value.add(i) }, h.values)
            });
            let places = work.pairs[run.clone()]
                .iter_mut()
                .zip(&mut work.states[run]);
            for (jj, (&j, (pair, state))) in neighbours.iter().zip(places).enumerate() {
                let j = j & list.index_mask;
                if j < 0 || j as usize >= n {
                    report.atoms = [i as i64, i64::from(j)];
                    return SS_ERR_INDEX;
                }
                *pair = [i as u32, j as u32];
                *state = match pages {
                    // SAFETY: as above.
                    Some((at, stride)) => Flat::read(unsafe {
                        std::slice::from_raw_parts(at.add(jj * stride), values)
                    }),
                    None => Default::default(),
                };
            }
            k += count;
        }
        // Another pair style's pairs (the table names those it evaluates) are refused.
        if let Some(evaluated) = &self.evaluated {
            let material = |k: u32| work.material[k as usize] as usize;
            let foreign = |&&[i, j]: &&[u32; 2]| !evaluated[material(i)][material(j)];
            if let Some(&[i, j]) = work.pairs.iter().find(foreign) {
                report.atoms = [i64::from(i), i64::from(j)];
                return SS_ERR_MATERIAL;
            }
        }
        let contacts = work.pairs.len();
        // Written in full by the kernel.
        work.next.resize(contacts, Default::default());
        work.force.resize(n, Vec3::ZERO);
        work.torque.resize(n, Vec3::ZERO);
        let per_pair = !loads.pair_force.is_null();
        work.records.clear();
        if per_pair {
            work.records.resize(contacts, Interaction::Apart);
        }
        let spheres = SphereArrays {
            position: vectors(atoms.position),
            velocity: vectors(atoms.velocity),
            angular_velocity: vectors(atoms.angular_velocity),
            radius: scalars(atoms.radius),
            mass: scalars(atoms.mass),
            material: &work.material,
        };
        let pairs = match CheckedPairs::new(&work.pairs, &[], n) {
            Ok(pairs) => pairs,
            Err(error) => return list_code(error, &work.pairs, report),
        };
        let outcome = table.evaluate(
            *step,
            &spheres,
            ContactList {
                pairs,
                pair_states: &work.states,
                walls: &[],
                wall_states: &[],
            },
            ListOutput {
                force: &mut work.force,
                torque: &mut work.torque,
                next_pair_states: &mut work.next,
                next_wall_states: &mut [],
                records: per_pair.then_some(&mut work.records[..]),
            },
        );
        let stats: ListStats<F> = match outcome {
            Ok(stats) => stats,
            Err(error) => return list_code(error, &work.pairs, report),
        };
        report.contacts = stats.pair_contacts;
        report.sliding = stats.sliding_contacts;
        report.inaccurate = stats.inaccurate_contacts;
        // Scatter: touch flags and (when advancing) states, in list order again. A neighbour
        // "touches" when it keeps a state: the kernel relaxes an apart pair's state to zero, and
        // a host that drops the state of a neighbour that does not touch (as LAMMPS does when it
        // rebuilds its lists) then loses nothing.
        if let Some(h) = history {
            let mut k = 0;
            for ii in 0..list.count {
                // SAFETY: checked by `check_list`; `values` numbers and one flag per neighbour.
                unsafe {
                    let i = *list.atoms.add(ii) as usize;
                    let count = *list.neighbour_counts.add(i) as usize;
                    let touch = std::slice::from_raw_parts_mut(*h.first_touch.add(i), count);
                    let kept = if advance { &work.next } else { &work.states };
                    let at = *h.first_value.add(i);
                    // Each neighbour's flag and state in one pass: the state is read once.
                    for (jj, (flag, state)) in touch.iter_mut().zip(&kept[k..k + count]).enumerate()
                    {
                        *flag = i32::from(state.keeps());
                        if advance && values > 0 {
                            state.write(std::slice::from_raw_parts_mut(
                                at.add(jj * h.values),
                                values,
                            ));
                        }
                    }
                    k += count;
                }
            }
        }
        if per_pair {
            // SAFETY: three numbers per neighbour (the caller's promise).
            let out = unsafe { std::slice::from_raw_parts_mut(loads.pair_force, 3 * contacts) };
            for (place, record) in out.chunks_exact_mut(3).zip(&work.records) {
                let on_i = match record {
                    Interaction::Touching(c) => c.force_on_i(),
                    Interaction::Apart => Vec3::ZERO,
                };
                place.copy_from_slice(&[on_i.x, on_i.y, on_i.z]);
            }
        }
        for (out, sums) in [(loads.force, &work.force), (loads.torque, &work.torque)] {
            // SAFETY: three numbers per atom; not overlapping the inputs (the caller's promise).
            let out = unsafe { std::slice::from_raw_parts_mut(out, 3 * n) };
            for (place, sum) in out.chunks_exact_mut(3).zip(&sums[..receivers]) {
                place[0] += sum.x;
                place[1] += sum.y;
                place[2] += sum.z;
            }
        }
        SS_OK
    }

    /// The walls entry: the selected owned atoms against every wall, through the seam (no
    /// pairs); on success the states (when `advance`) and the forces written back.
    ///
    /// # Safety
    /// As `ss_table_evaluate_walls_*`.
    pub(crate) unsafe fn evaluate_walls(
        &mut self,
        atoms: &ss_atoms<F>,
        walls: &ss_walls<F>,
        loads: &ss_loads<F>,
        advance: bool,
        report: &mut ss_list_report,
    ) -> i32 {
        let values = <<X::Law as Law>::State as Flat<F>>::VALUES;
        let Some((table, step)) = &self.ready else {
            return SS_ERR_NOT_PREPARED;
        };
        let n = atoms.owned;
        let arrays = [
            atoms.position.cast::<u8>(),
            atoms.velocity.cast(),
            atoms.angular_velocity.cast(),
            atoms.radius.cast(),
            atoms.mass.cast(),
            atoms.types.cast(),
            loads.force.cast(),
            loads.torque.cast(),
        ];
        if arrays.iter().any(|a| !present(*a, n)) || !present(walls.walls, walls.count) {
            return SS_ERR_NULL;
        }
        if n > atoms.count || n > u32::MAX as usize {
            return SS_ERR_LENGTH;
        }
        // SAFETY: three numbers per atom in each.
        if let Some(k) = unsafe { first_unfinite_load(loads, n) } {
            report.atoms = [k as i64, -1];
            return SS_ERR_NON_FINITE_INPUT;
        }
        let needed = if walls.count == 0 {
            0
        } else {
            (walls.count - 1) * walls.wall_stride + values
        };
        if values > 0 && (walls.wall_stride < values || walls.stride < needed) {
            return SS_ERR_LENGTH;
        }
        if values > 0 && walls.count > 0 && !present(walls.states, n) {
            return SS_ERR_NULL;
        }
        let wall_material = walls.material as usize;
        if wall_material >= self.materials {
            return SS_ERR_MATERIAL;
        }
        // The materials that meet these walls by a law, one bit each.
        let meets = self.with_law[wall_material];
        let work = &mut self.wall_work;
        work.walls.clear();
        for w in 0..walls.count {
            // SAFETY: `count` walls (the caller's promise).
            match crate::wall_of(unsafe { &*walls.walls.add(w) }) {
                Ok(wall) => work.walls.push(soft_sphere::prelude::MaterialWall {
                    wall,
                    material: walls.material,
                }),
                Err(code) => return code,
            }
        }
        // Gather the selected atoms and their states.
        for v in [&mut work.position, &mut work.velocity, &mut work.spin] {
            v.clear();
        }
        work.index.clear();
        work.clear.clear();
        work.radius.clear();
        work.mass.clear();
        work.material.clear();
        work.states.clear();
        let vector = |p: *const F, k: usize| {
            // SAFETY: three numbers per atom.
            unsafe { Vec3::new(*p.add(3 * k), *p.add(3 * k + 1), *p.add(3 * k + 2)) }
        };
        for k in 0..n {
            // SAFETY: one flag per atom when given.
            if !walls.selected.is_null() && unsafe { *walls.selected.add(k) } & walls.bit == 0 {
                continue;
            }
            // SAFETY: one type per atom.
            let t = i64::from(unsafe { *atoms.types.add(k) }) - i64::from(atoms.first_type);
            // Below the first type, past the table or with no law against the walls: no bit.
            if !(0..SS_MATERIALS_MAX as i64).contains(&t) || meets >> t & 1 == 0 {
                report.atoms = [k as i64, -1];
                return SS_ERR_MATERIAL;
            }
            // An atom clear of every wall (the kernel's own test: `radius - distance <= 0`) would
            // only have its states relaxed to zero: that is done after success, without the seam.
            let position = vector(atoms.position, k);
            // SAFETY: one number per atom.
            let radius = unsafe { *atoms.radius.add(k) };
            let mut clear = true;
            for w in &work.walls {
                clear &= radius - w.wall.distance_to(position) <= F::ZERO;
            }
            if clear {
                work.clear.push(k);
                continue;
            }
            work.index.push(k);
            work.material.push(t as u32);
            work.position.push(position);
            work.velocity.push(vector(atoms.velocity, k));
            work.spin.push(vector(atoms.angular_velocity, k));
            // SAFETY: one number per atom.
            unsafe {
                work.radius.push(*atoms.radius.add(k));
                work.mass.push(*atoms.mass.add(k));
            }
            for w in 0..walls.count {
                work.states.push(if values > 0 {
                    // SAFETY: `stride` numbers per atom, checked to hold every wall's state.
                    Flat::read(unsafe {
                        std::slice::from_raw_parts(
                            walls.states.add(k * walls.stride + w * walls.wall_stride),
                            values,
                        )
                    })
                } else {
                    Default::default()
                });
            }
        }
        let m = work.index.len();
        // Written in full by the kernel.
        work.next.resize(m * walls.count, Default::default());
        work.force.resize(m, Vec3::ZERO);
        work.torque.resize(m, Vec3::ZERO);
        let spheres = SphereArrays {
            position: &work.position,
            velocity: &work.velocity,
            angular_velocity: &work.spin,
            radius: &work.radius,
            mass: &work.mass,
            material: &work.material,
        };
        let outcome = table.evaluate(
            *step,
            &spheres,
            ContactList {
                pairs: CheckedPairs::empty(),
                pair_states: &[],
                walls: &work.walls,
                wall_states: &work.states,
            },
            ListOutput {
                force: &mut work.force,
                torque: &mut work.torque,
                next_pair_states: &mut [],
                next_wall_states: &mut work.next,
                records: None,
            },
        );
        let stats = match outcome {
            Ok(stats) => stats,
            Err(ListError::Wall { sphere, error, .. }) => {
                report.atoms = [work.index[sphere] as i64, -1];
                return contact_code(error);
            }
            Err(ListError::Sphere { sphere, error }) => {
                report.atoms = [work.index[sphere] as i64, -1];
                return contact_code(error);
            }
            Err(error) => return list_code(error, &[], report),
        };
        report.contacts = stats.wall_contacts;
        report.sliding = stats.sliding_contacts;
        report.inaccurate = stats.inaccurate_contacts;
        if advance && values > 0 {
            for &k in &work.clear {
                for w in 0..walls.count {
                    // SAFETY: as the gather.
                    let kept = unsafe {
                        std::slice::from_raw_parts_mut(
                            walls.states.add(k * walls.stride + w * walls.wall_stride),
                            values,
                        )
                    };
                    kept.fill(F::ZERO);
                }
            }
        }
        for (s, &k) in work.index.iter().enumerate() {
            if advance && values > 0 {
                for w in 0..walls.count {
                    // SAFETY: as the gather.
                    work.next[s * walls.count + w].write(unsafe {
                        std::slice::from_raw_parts_mut(
                            walls.states.add(k * walls.stride + w * walls.wall_stride),
                            values,
                        )
                    });
                }
            }
            for (out, sum) in [(loads.force, work.force[s]), (loads.torque, work.torque[s])] {
                // SAFETY: three numbers per atom; not overlapping the inputs.
                unsafe {
                    *out.add(3 * k) += sum.x;
                    *out.add(3 * k + 1) += sum.y;
                    *out.add(3 * k + 2) += sum.z;
                }
            }
        }
        SS_OK
    }

    /// One pair's contact with the law of its materials, its state read and not written (for a
    /// host's per-pair report, such as LAMMPS's `single()`).
    pub(crate) fn pair(
        &self,
        (a, b): (usize, usize),
        (i, j): (&ss_sphere<F>, &ss_sphere<F>),
        values: Option<&[F]>,
        out: &mut ss_forces<F>,
    ) -> i32 {
        let Some((table, step)) = &self.ready else {
            return SS_ERR_NOT_PREPARED;
        };
        // A material of the table (the kernel's holds `SS_MATERIALS_MAX`), in a pair it evaluates.
        let ours = a < self.materials && b < self.materials && self.evaluates(a, b);
        let (true, Some(law)) = (ours, table.law(a, b)) else {
            return SS_ERR_MATERIAL;
        };
        let mut state = match values {
            Some(values) => Flat::read(values),
            None => Default::default(),
        };
        let (i, j): (Sphere<F>, Sphere<F>) = ((*i).into(), (*j).into());
        let i = match CheckedSphere::new(i) {
            Ok(i) => i,
            Err(e) => return contact_code(e),
        };
        let j = match CheckedSphere::new(j) {
            Ok(j) => j,
            Err(e) => return contact_code(e),
        };
        match law.at(*step).sphere_sphere(&i, &j, &mut state) {
            Ok(interaction) => {
                *out = forces_of(interaction);
                SS_OK
            }
            Err(e) => contact_code(e),
        }
    }
}

/// The code of a seam refusal, with the atoms it is about.
/// The list checked as a host builds it ([`check_pairs`]): its counts and indices, and no pair
/// named twice (`i`'s page naming `j` twice, or `i`'s naming `j` and `j`'s naming `i`). A
/// repeated pair is `SS_ERR_REPEATED_PAIR` with its two atoms in the report.
///
/// # Safety
/// As `ss_check_neighbours`.
pub(crate) unsafe fn check_neighbours(
    n: usize,
    list: &ss_neighbours,
    report: &mut ss_list_report,
) -> i32 {
    // SAFETY: forwarded contract.
    let code = unsafe { check_pages::<f64>(n, list, None, report) };
    if code != SS_OK {
        return code;
    }
    let mut pairs = Vec::new();
    for ii in 0..list.count {
        // SAFETY: checked by `check_pages`: the atom, its count and its page are there.
        let (i, neighbours) = unsafe {
            let i = *list.atoms.add(ii) as usize;
            let count = *list.neighbour_counts.add(i) as usize;
            let first = *list.first_neighbour.add(i);
            (
                i,
                if count == 0 {
                    &[][..]
                } else {
                    std::slice::from_raw_parts(first, count)
                },
            )
        };
        for &j in neighbours {
            let j = j & list.index_mask;
            if j < 0 || j as usize >= n {
                report.atoms = [i as i64, i64::from(j)];
                return SS_ERR_INDEX;
            }
            pairs.push([i as u32, j as u32]);
        }
    }
    let mut order = vec![0; pairs.len()];
    let none: &[Vec3<f64>] = &[];
    match check_pairs((&pairs, none), n, &mut order) {
        Ok(()) => SS_OK,
        Err(error) => list_code(error, &pairs, report),
    }
}

/// The first of the first `count` atoms whose force or torque, which the contacts are added
/// to, is not finite: a NaN the host's arrays already hold would pass through every sum.
///
/// # Safety
/// `loads.force` and `loads.torque` hold three numbers for each of `count` atoms.
unsafe fn first_unfinite_load<F: Real>(loads: &ss_loads<F>, count: usize) -> Option<usize> {
    if count == 0 {
        return None;
    }
    // SAFETY: the caller's promise.
    let (force, torque) = unsafe {
        (
            std::slice::from_raw_parts(loads.force, 3 * count),
            std::slice::from_raw_parts(loads.torque, 3 * count),
        )
    };
    if sum_is_finite(force, torque) {
        return None;
    }
    let finite = |at: usize| force[at].is_finite() && torque[at].is_finite();
    (0..count).find(|&k| !(3 * k..3 * k + 3).all(finite))
}

/// Whether the sum of every force and torque is finite, in independent lanes: false when one of
/// them is not (a NaN or an infinity stays in any sum), and for finite ones whose sum overflows
/// (the caller then looks at them one by one and finds nothing). Finite loads, the rule, cost
/// this sum rather than a test and a branch per number.
fn sum_is_finite<F: Real>(force: &[F], torque: &[F]) -> bool {
    let (forces, torques) = (force.chunks_exact(4), torque.chunks_exact(4));
    let rest = forces.remainder().iter().zip(torques.remainder());
    let mut lanes = [F::ZERO; 4];
    for (f, t) in forces.zip(torques) {
        for (lane, (&f, &t)) in lanes.iter_mut().zip(f.iter().zip(t)) {
            *lane += f + t;
        }
    }
    let lanes = lanes.iter().fold(F::ZERO, |sum, &lane| sum + lane);
    rest.fold(lanes, |sum, (&f, &t)| sum + (f + t)).is_finite()
}

pub(crate) fn list_code(error: ListError, pairs: &[[u32; 2]], report: &mut ss_list_report) -> i32 {
    let atoms = |pair: usize| pairs[pair].map(i64::from);
    match error {
        ListError::Sphere { sphere, error } => {
            report.atoms = [sphere as i64, -1];
            contact_code(error)
        }
        ListError::Pair { pair, error } => {
            report.atoms = atoms(pair);
            contact_code(error)
        }
        ListError::PairIndex { pair } => {
            report.atoms = atoms(pair);
            SS_ERR_INDEX
        }
        ListError::Material { sphere, .. } => {
            report.atoms = [sphere as i64, -1];
            SS_ERR_MATERIAL
        }
        ListError::RepeatedPair { pair, .. } => {
            report.atoms = atoms(pair);
            SS_ERR_REPEATED_PAIR
        }
        ListError::Length(_) | ListError::Shift { .. } => SS_ERR_LENGTH,
        ListError::WallMaterial { .. } => SS_ERR_MATERIAL,
        ListError::Wall { error, .. } => contact_code(error),
        ListError::TimeStep { .. } => SS_ERR_UNSTABLE_TIME_STEP,
    }
}
