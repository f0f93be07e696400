//! Per-sphere fixed-capacity contact slots: where a scene parks the stored contact states while
//! it rebuilds its Verlet list, so each touching pair finds its history again in the new list.

use crate::error::ContactError;

/// Up to `K` contacts owned by one sphere: partner index and per-contact state.
#[derive(Clone, Copy, Debug)]
pub struct ContactSlots<S, const K: usize> {
    len: usize,
    partner: [u32; K],
    state: [S; K],
}

impl<S: Copy + Default, const K: usize> Default for ContactSlots<S, K> {
    fn default() -> Self {
        Self {
            len: 0,
            partner: [0; K],
            state: [S::default(); K],
        }
    }
}

impl<S: Copy + Default, const K: usize> ContactSlots<S, K> {
    /// Contacts held.
    pub fn len(&self) -> usize {
        self.len
    }

    /// No contact held.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Forgets every contact.
    pub(crate) fn clear(&mut self) {
        self.len = 0;
    }

    /// The state stored for `partner`, or the relaxed state of a new contact.
    #[inline(always)]
    pub(crate) fn find(&self, partner: u32) -> S {
        let mut k = 0;
        while k < self.len {
            if self.partner[k] == partner {
                return self.state[k];
            }
            k += 1;
        }
        S::default()
    }

    /// Adds a contact; [`ContactError::HistoryFull`] when all `K` slots are taken.
    #[inline(always)]
    pub(crate) fn push(&mut self, partner: u32, state: S) -> Result<(), ContactError> {
        if self.len == K {
            return Err(ContactError::HistoryFull);
        }
        self.partner[self.len] = partner;
        self.state[self.len] = state;
        self.len += 1;
        Ok(())
    }
}
