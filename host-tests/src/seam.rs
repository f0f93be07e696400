//! The kernel's list seam called as an engine calls it: states double-buffered, the next ones
//! taken as current only when the call succeeds.

use soft_sphere::executor::{Executor, Serial};
use soft_sphere::prelude::{
    CheckedPairs, ContactList, Interaction, Law, ListError, ListOutput, ListStats, MaterialTable,
    MaterialWall, PairLoad, Spheres, TimeStep, Vec3,
};

/// One [`MaterialTable::evaluate`] of `pairs` and `walls`: on success `states` and
/// `wall_states` hold the next states (the second buffer copied over them, as an engine swaps
/// its two) and `force` and `torque` each sphere's contact load (whatever they held before); on
/// an error `states` and `wall_states` are as they were.
///
/// # Errors
/// The seam's.
pub fn evaluate_swapping<L: Law, const MATERIALS: usize>(
    table: &MaterialTable<L, MATERIALS>,
    dt: TimeStep<L::Float>,
    spheres: &impl Spheres<L::Float>,
    contacts: Contacts<'_, '_, L>,
    (force, torque): Loads<'_, L::Float>,
    records: Option<&mut [Interaction<L::Float>]>,
) -> Result<ListStats<L::Float>, ListError> {
    let out = (force, torque, records);
    evaluate_swapping_on(table, (&Serial, &mut []), dt, spheres, contacts, out)
}

/// The pairs and walls of one evaluation, and their states.
pub type Contacts<'a, 's, L> = (
    (
        CheckedPairs<'a, <L as Law>::Float>,
        &'a [MaterialWall<<L as Law>::Float>],
    ),
    (&'s mut [<L as Law>::State], &'s mut [<L as Law>::State]),
);

/// Each sphere's force and torque.
pub type Loads<'o, F> = (&'o mut [Vec3<F>], &'o mut [Vec3<F>]);

/// The loads and, when given, the records an evaluation writes.
pub type Written<'o, F> = (
    &'o mut [Vec3<F>],
    &'o mut [Vec3<F>],
    Option<&'o mut [Interaction<F>]>,
);

/// [`evaluate_swapping`] through [`MaterialTable::evaluate_on`] with `executor` (its pairs
/// spread over the executor's threads when `loads` is one per pair).
///
/// # Errors
/// The seam's.
pub fn evaluate_swapping_on<L: Law, E: Executor, const MATERIALS: usize>(
    table: &MaterialTable<L, MATERIALS>,
    (executor, loads): (&E, &mut [PairLoad<L::Float>]),
    dt: TimeStep<L::Float>,
    spheres: &impl Spheres<L::Float>,
    ((pairs, walls), (states, wall_states)): Contacts<'_, '_, L>,
    (force, torque, records): Written<'_, L::Float>,
) -> Result<ListStats<L::Float>, ListError> {
    // The second buffers start with other contacts' states (the list reversed): a place the
    // seam failed to write would show.
    let mut next: Vec<_> = states.iter().rev().copied().collect();
    let mut next_walls: Vec<_> = wall_states.iter().rev().copied().collect();
    let stats = table.evaluate_on(
        (executor, loads),
        dt,
        spheres,
        ContactList {
            pairs,
            pair_states: states,
            walls,
            wall_states,
        },
        ListOutput {
            force,
            torque,
            next_pair_states: &mut next,
            next_wall_states: &mut next_walls,
            records,
        },
    )?;
    states.copy_from_slice(&next);
    wall_states.copy_from_slice(&next_walls);
    Ok(stats)
}
