//! The table a C host holds (`ss_table_*`): one family's table, picked by the configuration's
//! law and rolling resistance from the registry's list, and the entry points that reach it.

use soft_sphere::prelude::{
    ElasticMaterial, ElasticPlasticRolling, HertzImpact, HertzMixing, Law, Material, MindlinAA,
    Mixing,
};

use crate::real::Real;
use crate::registry::{PlainTable, RolledTable, hertz_model};
use crate::table::*;
use crate::*;

/// A table: its coefficients as given, the laws and the step once prepared, and the working
/// memory of evaluations (opaque to C).
#[derive(Debug)]
pub struct ss_table<F: Real> {
    table: AnyTable<F>,
}

/// A table of the registry's laws (`registry.rs`), with or without rolling resistance.
#[derive(Debug)]
pub(crate) enum AnyTable<F: Real> {
    Plain(PlainTable<F>),
    Rolled(RolledTable<F>),
}

/// `$body` with `$t` bound to the table inside an [`AnyTable`].
macro_rules! each_table {
    ($any:expr, $t:pat => $body:expr) => {
        match $any {
            AnyTable::Plain(plain) => each_table_of!(plain, PlainTable, $t => $body),
            AnyTable::Rolled(rolled) => each_table_of!(rolled, RolledTable, $t => $body),
        }
    };
}

pub(crate) fn new_table<F: Real>(config: &ss_table_config<F>) -> Result<AnyTable<F>, i32> {
    let m = config.materials;
    if m == 0 || m > SS_MATERIALS_MAX {
        return Err(SS_ERR_MATERIAL);
    }
    let impact = HertzImpact {
        speed: config.largest_impact_speed,
        effective_radius: config.largest_effective_radius,
    };
    let hertz = hertz_model(config.model);
    if hertz {
        // The declared impact is checked by the Hertz law: probe it with a valid material.
        let probe = ElasticMaterial {
            elasticity: Material::new(F::ONE, F::ZERO).map_err(parameter_code)?,
            restitution: F::HALF,
            dashpot_ratio: F::ZERO,
            friction: F::ZERO,
        };
        HertzMixing::new(impact, MindlinAA)
            .law(&probe, &probe)
            .map_err(parameter_code)?;
    }
    match config.rolling {
        SS_ROLLING_NONE => PlainTable::new(config.model, impact, m)
            .map(AnyTable::Plain)
            .ok_or(SS_ERR_UNKNOWN_MODEL),
        SS_ROLLING_EPSD => rolled_table(config, impact),
        _ => Err(SS_ERR_UNKNOWN_MODEL),
    }
}

/// A table of laws with the elastic-plastic rolling resistance (the smallest inertia checked
/// here).
pub(crate) fn rolled_table<F: Real>(
    config: &ss_table_config<F>,
    impact: HertzImpact<F>,
) -> Result<AnyTable<F>, i32> {
    let (m, smallest_inertia) = (config.materials, config.smallest_inertia);
    ElasticPlasticRolling::new(F::ZERO, F::ONE, F::ZERO, smallest_inertia)
        .map_err(parameter_code)?;
    RolledTable::new(config.model, impact, m, smallest_inertia)
        .map(AnyTable::Rolled)
        .ok_or(SS_ERR_UNKNOWN_MODEL)
}

/// # Safety
/// As the exported table constructors.
pub(crate) unsafe fn table_new<F: Real>(
    config: *const ss_table_config<F>,
    out: *mut *mut ss_table<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(config), false) = (unsafe { config.as_ref() }, out.is_null()) else {
        return SS_ERR_NULL;
    };
    match new_table(config) {
        Ok(table) => {
            // SAFETY: out was checked non-null.
            unsafe { *out = Box::into_raw(Box::new(ss_table { table })) };
            SS_OK
        }
        Err(code) => code,
    }
}

/// # Safety
/// As the exported table destructors.
pub(crate) unsafe fn table_free<F: Real>(table: *mut ss_table<F>) {
    if !table.is_null() {
        // SAFETY: the handle came from Box::into_raw in table_new.
        drop(unsafe { Box::from_raw(table) });
    }
}

/// # Safety
/// As the exported pair setters.
pub(crate) unsafe fn table_set<F: Real>(
    table: *mut ss_table<F>,
    a: usize,
    b: usize,
    coefficients: *const ss_coefficients<F>,
    parameter: *mut i32,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(table), Some(c)) = (unsafe { table.as_mut() }, unsafe { coefficients.as_ref() })
    else {
        return SS_ERR_NULL;
    };
    let outcome = each_table!(&mut table.table, t => t.set(a, b, c));
    let (code, rejected) = match outcome {
        Ok(()) => (SS_OK, SS_PARAMETER_NONE),
        Err(refused) => refused,
    };
    // SAFETY: null is allowed; the caller promises validity otherwise.
    if let Some(parameter) = unsafe { parameter.as_mut() } {
        *parameter = rejected;
    }
    code
}

/// # Safety
/// As the exported pair setters.
pub(crate) unsafe fn table_set_pairs<F: Real>(
    table: *mut ss_table<F>,
    pairs: *const u32,
    count: usize,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let Some(table) = (unsafe { table.as_mut() }) else {
        return SS_ERR_NULL;
    };
    let Some(ids) = count.checked_mul(2) else {
        return SS_ERR_LENGTH;
    };
    // SAFETY: `2 count` ids (the caller's promise); null only with none.
    let given = match unsafe { read(pairs, ids) } {
        Some(given) => given,
        None if count == 0 => &[],
        None => return SS_ERR_NULL,
    };
    each_table!(&mut table.table, t => t.set_pairs(given))
}

/// # Safety
/// As the exported wall-material setters.
pub(crate) unsafe fn table_set_walls<F: Real>(
    table: *mut ss_table<F>,
    materials: *const u32,
    count: usize,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let Some(table) = (unsafe { table.as_mut() }) else {
        return SS_ERR_NULL;
    };
    // SAFETY: `count` ids (the caller's promise); null only with none.
    let given = match unsafe { read(materials, count) } {
        Some(given) => given,
        None if count == 0 => &[],
        None => return SS_ERR_NULL,
    };
    each_table!(&mut table.table, t => t.set_walls(given))
}

/// # Safety
/// As the exported preparers.
pub(crate) unsafe fn table_prepare<F: Real>(
    table: *mut ss_table<F>,
    time_step: (F, bool),
    lightest_mass: *const F,
    report: *mut ss_table_report<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let Some(table) = (unsafe { table.as_mut() }) else {
        return SS_ERR_NULL;
    };
    let materials = each_table!(&table.table, t => t.materials);
    if lightest_mass.is_null() {
        return SS_ERR_NULL;
    }
    // SAFETY: one mass per material (the caller's promise).
    let lightest = unsafe { std::slice::from_raw_parts(lightest_mass, materials) };
    let mut found = ss_table_report {
        materials: [-1, -1],
        parameter: SS_PARAMETER_NONE,
        limit: F::ZERO,
    };
    let code = each_table!(&mut table.table, t => t.prepare(time_step, lightest, &mut found));
    // SAFETY: null is allowed; the caller promises validity otherwise.
    if let Some(report) = unsafe { report.as_mut() } {
        *report = found;
    }
    code
}

/// # Safety
/// As the exported list entries.
pub(crate) unsafe fn table_evaluate<F: Real>(
    table: *mut ss_table<F>,
    atoms: *const ss_atoms<F>,
    list: *const ss_neighbours,
    history: *const ss_history<F>,
    loads: *const ss_loads<F>,
    advance: i32,
    report: *mut ss_list_report,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(table), Some(atoms), Some(list), Some(loads)) = (unsafe {
        (
            table.as_mut(),
            atoms.as_ref(),
            list.as_ref(),
            loads.as_ref(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    // SAFETY: null is allowed (no history).
    let history = unsafe { history.as_ref() };
    let run = |found: &mut ss_list_report| {
        each_table!(&mut table.table, t => {
            // SAFETY: forwarded contract.
            unsafe { t.evaluate(atoms, list, history, loads, advance != 0, found) }
        })
    };
    // SAFETY: forwarded contract.
    unsafe { reported(report, run) }
}

/// Runs an entry with a fresh report, then hands the report to the caller when it asked.
///
/// # Safety
/// `report` must be valid or null.
pub(crate) unsafe fn reported(
    report: *mut ss_list_report,
    run: impl FnOnce(&mut ss_list_report) -> i32,
) -> i32 {
    let mut found = ss_list_report {
        contacts: 0,
        sliding: 0,
        atoms: [-1, -1],
        inaccurate: 0,
    };
    let code = run(&mut found);
    // SAFETY: null is allowed; the caller promises validity otherwise.
    if let Some(report) = unsafe { report.as_mut() } {
        *report = found;
    }
    code
}

/// Checks a neighbour list of `atoms` atoms once, when the host builds it: every count and
/// index, and no pair named twice (atom `i`'s neighbours naming `j` twice, or `i`'s naming `j`
/// and `j`'s naming `i`), whose force `ss_table_evaluate_*` would add twice. It takes a sort,
/// so it belongs to the list build, not to every step (LAMMPS's half lists name each pair
/// once). Returns `SS_OK`, `SS_ERR_NULL`, `SS_ERR_LENGTH`, `SS_ERR_INDEX` or
/// `SS_ERR_REPEATED_PAIR`; `*report` (when not null) names the atoms an error is about (the
/// repeated pair's two).
///
/// # Safety
/// `list` as for `ss_table_evaluate_*`, for `atoms` atoms.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ss_check_neighbours(
    atoms: usize,
    list: *const ss_neighbours,
    report: *mut ss_list_report,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let Some(list) = (unsafe { list.as_ref() }) else {
        return SS_ERR_NULL;
    };
    // SAFETY: forwarded contract.
    unsafe { reported(report, |found| list::check_neighbours(atoms, list, found)) }
}

/// # Safety
/// As the exported walls entries.
pub(crate) unsafe fn table_evaluate_walls<F: Real>(
    table: *mut ss_table<F>,
    atoms: *const ss_atoms<F>,
    walls: *const ss_walls<F>,
    loads: *const ss_loads<F>,
    advance: i32,
    report: *mut ss_list_report,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(table), Some(atoms), Some(walls), Some(loads)) = (unsafe {
        (
            table.as_mut(),
            atoms.as_ref(),
            walls.as_ref(),
            loads.as_ref(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let run = |found: &mut ss_list_report| {
        each_table!(&mut table.table, t => {
            // SAFETY: forwarded contract.
            unsafe { t.evaluate_walls(atoms, walls, loads, advance != 0, found) }
        })
    };
    // SAFETY: forwarded contract.
    unsafe { reported(report, run) }
}

/// # Safety
/// As the exported per-pair calls.
pub(crate) unsafe fn table_pair<F: Real>(
    table: *const ss_table<F>,
    a: usize,
    b: usize,
    (i, j): (*const ss_sphere<F>, *const ss_sphere<F>),
    values: *const F,
    out: *mut ss_forces<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(table), Some(i), Some(j), Some(out)) =
        (unsafe { (table.as_ref(), i.as_ref(), j.as_ref(), out.as_mut()) })
    else {
        return SS_ERR_NULL;
    };
    each_table!(&table.table, t => table_pair_in(&**t, (a, b), (i, j), values, out))
}

pub(crate) fn table_pair_in<F: Real, X: Mixing<F>>(
    t: &Tabled<F, X>,
    materials: (usize, usize),
    spheres: (&ss_sphere<F>, &ss_sphere<F>),
    values: *const F,
    out: &mut ss_forces<F>,
) -> i32
where
    <X::Law as Law>::State: Flat<F>,
{
    let count = <<X::Law as Law>::State as Flat<F>>::VALUES;
    let values = if values.is_null() || count == 0 {
        None
    } else {
        // SAFETY: `count` numbers (the caller's promise: `ss_table_state_values_*`).
        Some(unsafe { std::slice::from_raw_parts(values, count) })
    };
    t.pair(materials, spheres, values, out)
}

/// How many numbers the table's law keeps per contact.
pub(crate) fn state_values<F: Real>(table: *const ss_table<F>) -> usize {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let Some(table) = (unsafe { table.as_ref() }) else {
        return 0;
    };
    each_table!(&table.table, t => values_of(&**t))
}

pub(crate) fn values_of<F: Real, X: Mixing<F>>(_: &Tabled<F, X>) -> usize
where
    <X::Law as Law>::State: Flat<F>,
{
    <<X::Law as Law>::State as Flat<F>>::VALUES
}

/// # Safety
/// As the exported state mirrors.
pub(crate) unsafe fn table_mirror<F: Real>(
    table: *const ss_table<F>,
    source: *const F,
    target: *mut F,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let Some(table) = (unsafe { table.as_ref() }) else {
        return SS_ERR_NULL;
    };
    each_table!(&table.table, t => mirror_in(&**t, source, target))
}

pub(crate) fn mirror_in<F: Real, X: Mixing<F>>(
    _: &Tabled<F, X>,
    source: *const F,
    target: *mut F,
) -> i32
where
    <X::Law as Law>::State: Flat<F>,
{
    let count = <<X::Law as Law>::State as Flat<F>>::VALUES;
    if count == 0 {
        return SS_OK;
    }
    if source.is_null() || target.is_null() {
        return SS_ERR_NULL;
    }
    // SAFETY: `count` numbers each (the caller's promise); read fully before writing, so they
    // may be the same.
    let state: <X::Law as Law>::State =
        Flat::read(unsafe { std::slice::from_raw_parts(source, count) });
    state
        .mirrored()
        .write(unsafe { std::slice::from_raw_parts_mut(target, count) });
    SS_OK
}
