//! The scene's fixed capacities, which its grid keeps to and its errors name.

/// The most cells a scene's grid holds: 2^26 (256 MiB of cell counts), far past any domain
/// cut into cells the size of its spheres that fits in memory beside them. A domain with more
/// is refused ([`SceneError::TooManyCells`](crate::SceneError::TooManyCells)) before anything is allocated.
pub const MAX_CELLS: usize = 1 << 26;
