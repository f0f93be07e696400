//! What a slot of one's own is written against: the inputs the law hands a tangential or a
//! rolling slot, and what a tangential slot gives back. The slot traits themselves
//! ([`TangentialModel`](crate::prelude::TangentialModel),
//! [`RollingModel`](crate::prelude::RollingModel)) are in the prelude.

pub use crate::law::rolling::RollingInput;
pub use crate::law::tangential::{TangentialInput, TangentialOutput};
