//! A fixed-capacity contact-history store, for callers that do not keep per-contact state next to
//! their own pair lists.

use heapless::index_map::FnvIndexMap;

use crate::law::tangential::ContactState;
use crate::value::error::ContactError;
use crate::value::forces::Interaction;

/// Identifies one contact: the caller's indices of body i and body j, in the order the contact is
/// evaluated (the stored spring is j relative to i, so `(3, 7)` and `(7, 3)` are different
/// contacts; use one order, e.g. the lower index first). For walls, give each wall an index that
/// no particle uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ContactKey {
    /// Index of body i.
    pub i: u32,
    /// Index of body j.
    pub j: u32,
}

impl ContactKey {
    /// The key of the contact between bodies `i` and `j`, in that order.
    pub const fn new(i: u32, j: u32) -> Self {
        Self { i, j }
    }
}

/// Per-contact states for up to `CAPACITY` simultaneous contacts, with no heap: an
/// open-addressing map with a fixed FNV hash, so its behaviour is the same on every run.
/// `CAPACITY` must be a power of two greater than one (checked at compile time).
///
/// [`ContactHistory::evaluate`] inserts a state on first touch, updates it while touching and
/// drops it when the contact ends. A new contact that finds the store full gets
/// [`ContactError::HistoryFull`], and nothing already stored is changed.
///
/// ```
/// use soft_sphere::prelude::{
///     ContactError, ContactHistory, ContactKey, ContactLaw, LinearSpringDashpot, ModelAA, Sphere,
///     SpringDisplacement, TangentialParameters, Vec3,
/// };
///
/// let law = ContactLaw::new(
///     LinearSpringDashpot::new(1.0e4_f32, 0.8).unwrap(),
///     ModelAA(TangentialParameters::new(3.0e3, 0.5, 0.4).unwrap()),
/// );
/// let dt = law.time_step(1.0e-6, 5.0e-6).unwrap();
/// let spheres = [
///     Sphere::solid(Vec3::new(0.0, 0.0, 0.0), 1.0e-3, 2500.0),
///     Sphere::solid(Vec3::new(1.9e-3, 0.0, 0.0), 1.0e-3, 2500.0),
///     Sphere::solid(Vec3::new(3.8e-3, 0.0, 0.0), 1.0e-3, 2500.0),
///     Sphere::solid(Vec3::new(5.7e-3, 0.0, 0.0), 1.0e-3, 2500.0),
/// ];
///
/// // Room for two contacts.
/// let mut history: ContactHistory<SpringDisplacement<f32>, 2> = ContactHistory::new();
/// let mut step = |i: usize, j: usize, history: &mut ContactHistory<_, 2>| {
///     let (a, b) = (&spheres[i], &spheres[j]);
///     history.evaluate(ContactKey::new(i as u32, j as u32), |state| {
///         law.sphere_sphere(a, b, state, dt)
///     })
/// };
/// assert!(step(0, 1, &mut history).is_ok());
/// assert!(step(1, 2, &mut history).is_ok());
/// assert_eq!(step(0, 2, &mut history).map(|i| i.forces().is_some()), Ok(false)); // apart: no slot
/// // A third touching pair does not fit: an error, and the two stored contacts are untouched.
/// let before = (history.get(ContactKey::new(0, 1)).copied(), history.get(ContactKey::new(1, 2)).copied());
/// assert_eq!(step(2, 3, &mut history), Err(ContactError::HistoryFull));
/// let after = (history.get(ContactKey::new(0, 1)).copied(), history.get(ContactKey::new(1, 2)).copied());
/// assert_eq!((history.len(), before), (2, after));
/// ```
#[derive(Clone, Debug)]
pub struct ContactHistory<S, const CAPACITY: usize> {
    states: FnvIndexMap<ContactKey, S, CAPACITY>,
}

impl<S: ContactState, const CAPACITY: usize> Default for ContactHistory<S, CAPACITY> {
    fn default() -> Self {
        Self::new()
    }
}

impl<S: ContactState, const CAPACITY: usize> ContactHistory<S, CAPACITY> {
    /// An empty store.
    pub const fn new() -> Self {
        Self {
            states: FnvIndexMap::new(),
        }
    }

    /// How many contacts are stored.
    pub fn len(&self) -> usize {
        self.states.len()
    }

    /// True when no contact is stored.
    pub fn is_empty(&self) -> bool {
        self.states.is_empty()
    }

    /// True when no new contact fits.
    pub fn is_full(&self) -> bool {
        self.states.len() == CAPACITY
    }

    /// The capacity `CAPACITY`.
    pub const fn capacity(&self) -> usize {
        CAPACITY
    }

    /// The stored state of a contact.
    pub fn get(&self, key: ContactKey) -> Option<&S> {
        self.states.get(&key)
    }

    /// Removes a contact (for example one whose pair left the caller's neighbour list) and
    /// returns its state.
    pub fn remove(&mut self, key: ContactKey) -> Option<S> {
        self.states.swap_remove(&key)
    }

    /// Keeps only the contacts for which `keep` returns true.
    pub fn retain(&mut self, mut keep: impl FnMut(ContactKey, &S) -> bool) {
        self.states.retain(|key, state| keep(*key, state));
    }

    /// Removes every contact.
    pub fn clear(&mut self) {
        self.states.clear();
    }

    /// The stored contacts, in the store's internal order.
    pub fn iter(&self) -> impl Iterator<Item = (ContactKey, &S)> {
        self.states.iter().map(|(key, state)| (*key, state))
    }

    /// Evaluates one contact with its stored state. `step` is a call of
    /// [`ContactLaw::sphere_sphere`](crate::ContactLaw::sphere_sphere) or
    /// [`ContactLaw::sphere_wall`](crate::ContactLaw::sphere_wall) on the state it is given.
    ///
    /// A stored contact is updated when still touching and removed when apart. An unknown contact
    /// starts from the default (relaxed) state and is stored only if it touches.
    ///
    /// # Errors
    /// Whatever `step` returns (the store is then unchanged), and [`ContactError::HistoryFull`]
    /// when a new touching contact does not fit (the store is then unchanged and the forces of
    /// that step are not returned: the caller decides whether to drop the contact or grow
    /// `CAPACITY`).
    pub fn evaluate<F>(
        &mut self,
        key: ContactKey,
        step: impl FnOnce(&mut S) -> Result<Interaction<F>, ContactError>,
    ) -> Result<Interaction<F>, ContactError> {
        if let Some(state) = self.states.get_mut(&key) {
            let interaction = step(state)?;
            if let Interaction::Apart = interaction {
                self.states.swap_remove(&key);
            }
            return Ok(interaction);
        }
        let mut state = S::default();
        let interaction = step(&mut state)?;
        if let Interaction::Touching(_) = interaction {
            self.states
                .insert(key, state)
                .map_err(|_| ContactError::HistoryFull)?;
        }
        Ok(interaction)
    }
}
