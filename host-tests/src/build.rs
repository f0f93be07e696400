//! Which build a benchmark ran in, for its report: the vector instructions the compiler was
//! allowed to use (`RUSTFLAGS="-C target-cpu=..."`; docs/performance.md, "Builds for your CPU").

/// The build's instruction level, as the benchmarks report it.
pub fn describe() -> &'static str {
    if cfg!(target_feature = "avx512f") {
        "x86-64-v4 (AVX-512)"
    } else if cfg!(target_feature = "avx2") {
        "x86-64-v3 (AVX2)"
    } else if cfg!(target_feature = "avx") {
        "AVX"
    } else {
        "portable (no AVX)"
    }
}
