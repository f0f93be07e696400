//! The property-test configuration, and the kernel's own strategies (`soft_sphere::strategies`,
//! feature `proptest`) that the property tests draw from.

use proptest::test_runner::{Config, FileFailurePersistence};

pub use soft_sphere::strategies::*;

/// Cases per property: `PROPTEST_CASES` when set (the slow configuration raises it), else 64.
/// Failures are kept beside the test file (`tests/<name>.proptest-regressions`, committed) and
/// replayed first on every run.
pub fn config() -> Config {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(64);
    Config {
        cases,
        // f32 cases whose steps the precision cannot resolve are rejected (see the properties).
        max_global_rejects: 4 * cases,
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions",
        ))),
        ..Config::default()
    }
}
