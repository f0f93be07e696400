//! Per-sphere parking for stored contact states: where a scene keeps them while it rebuilds its
//! Verlet list, so that each touching pair finds its history again in the new list.

/// Up to `K` parked contacts owned by one sphere: partner index and per-contact state. One per
/// sphere in [`SceneBuffers::parking`](crate::SceneBuffers::parking).
#[derive(Clone, Copy, Debug)]
pub struct Parking<S, const K: usize> {
    len: usize,
    partner: [u32; K],
    state: [S; K],
}

impl<S: Copy + Default, const K: usize> Default for Parking<S, K> {
    fn default() -> Self {
        Self {
            len: 0,
            partner: [0; K],
            state: [S::default(); K],
        }
    }
}

impl<S: Copy + Default, const K: usize> Parking<S, K> {
    /// Forgets every contact.
    pub(crate) fn clear(&mut self) {
        self.len = 0;
    }

    /// The state parked for `partner`, or the relaxed state of a new contact.
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

    /// Every parked contact: partner index and state.
    pub(crate) fn parked(&self) -> impl Iterator<Item = (u32, S)> + '_ {
        self.partner[..self.len]
            .iter()
            .copied()
            .zip(self.state[..self.len].iter().copied())
    }

    /// Parks a contact; `Err` when all `K` places are taken.
    #[inline(always)]
    pub(crate) fn push(&mut self, partner: u32, state: S) -> Result<(), ()> {
        if self.len == K {
            return Err(());
        }
        self.partner[self.len] = partner;
        self.state[self.len] = state;
        self.len += 1;
        Ok(())
    }
}
