//! The per-contact view: which bodies touch after a step, and how (for force chains and
//! analysis), read from the records the kernel's list seam wrote.

use soft_sphere::prelude::{ContactForces, Interaction, Law};

use crate::{Scene, WallSet};

/// The two bodies of a contact.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContactBodies {
    /// Spheres `[i, j]`, lower index first (body i of the forces).
    Pair([usize; 2]),
    /// Sphere `sphere` against wall `wall`.
    Wall {
        /// The sphere (body i).
        sphere: usize,
        /// The wall's place in the scene's walls.
        wall: usize,
    },
}

/// One touching contact of the last step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactView<F> {
    /// Which bodies.
    pub bodies: ContactBodies,
    /// Its normal, overlap, forces, slip and torques.
    pub forces: ContactForces<F>,
}

impl<L: Law, W: WallSet<L::Float>, const K: usize> Scene<'_, L, W, K> {
    /// Every touching contact of the last committed step, pairs in list order then spheres
    /// against walls; nothing when the scene keeps no records ([`crate::SceneBuffers::records`])
    /// or has not stepped.
    pub fn contacts(&self) -> impl Iterator<Item = ContactView<L::Float>> + '_ {
        let count = self.list.len();
        let walls = W::COUNT;
        let recorded = if self.records.is_empty() || !self.records_current {
            0
        } else {
            count + self.spheres.len() * walls
        };
        self.records[..recorded]
            .iter()
            .enumerate()
            .filter_map(move |(k, record)| {
                let Interaction::Touching(forces) = record else {
                    return None;
                };
                let bodies = if k < count {
                    ContactBodies::Pair(self.list.checked().pairs()[k].map(|x| x as usize))
                } else {
                    let place = k - count;
                    ContactBodies::Wall {
                        sphere: place / walls,
                        wall: place % walls,
                    }
                };
                Some(ContactView {
                    bodies,
                    forces: *forces,
                })
            })
    }
}
