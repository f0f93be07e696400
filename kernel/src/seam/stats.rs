//! Totals of one list evaluation.

/// Totals of one evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ListStats<F> {
    /// Sphere-sphere contacts touching.
    pub pair_contacts: usize,
    /// Sphere-wall contacts touching.
    pub wall_contacts: usize,
    /// Contacts (pairs and walls) at the Coulomb limit.
    pub sliding_contacts: usize,
    /// Touching contacts past their law's accuracy limit that the step evaluated knowingly (a
    /// [coarse](crate::MaterialTable::coarse_time_step) step's, or a tolerating step's:
    /// [`BoundLaw::inaccurate_contacts`](crate::BoundLaw::inaccurate_contacts)); zero for a step
    /// from [`MaterialTable::time_step`](crate::MaterialTable::time_step), which refuses them.
    pub inaccurate_contacts: usize,
    /// Sum of the sphere-sphere overlaps (m).
    pub overlap_sum: F,
}
