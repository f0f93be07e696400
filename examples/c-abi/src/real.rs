//! The precisions the C ABI offers.

use soft_sphere::prelude::{Float, MathBackend, Std};

/// The precisions the C ABI offers, each with the math backend its laws take: `Std`, whose
/// square root gives libm's bits and is one the compiler widens and keeps in vector registers
/// (in an AVX build libm's, an SSE instruction in inline assembly, costs a switch of register
/// state at every root).
pub trait Real: Float {
    /// The laws' math backend.
    type Backend: MathBackend<Self>;
}

impl Real for f32 {
    type Backend = Std;
}

impl Real for f64 {
    type Backend = Std;
}
