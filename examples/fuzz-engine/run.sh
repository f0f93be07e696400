#!/usr/bin/env bash
# A user's own engine fuzzed with the kernel's strategies and checks: its tests, formatting and
# lints, built as a crate outside the workspace (its own lock file, the root's target directory).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
export CARGO_TARGET_DIR="$here/../../target/fuzz-engine"
cargo test --manifest-path "$here/Cargo.toml"
cargo fmt --manifest-path "$here/Cargo.toml" -- --check
cargo clippy --manifest-path "$here/Cargo.toml" --all-targets -- -D warnings
