//! The validation data shipped in `host-tests/data/` (see its README for sources).

use std::path::PathBuf;

/// Path of a data file by name.
pub fn path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("data")
        .join(name)
}

/// Rows of a numeric CSV file, skipping `#` comment lines and the header line.
///
/// # Panics
/// When the file is missing or a field is not a number: the data ships with the crate.
pub fn rows(name: &str) -> Vec<Vec<f64>> {
    let text = std::fs::read_to_string(path(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    text.lines()
        .filter(|line| !line.starts_with('#') && !line.trim().is_empty())
        .skip(1)
        .map(|line| {
            line.split(',')
                .map(|field| {
                    field
                        .trim()
                        .parse()
                        .unwrap_or_else(|e| panic!("{name}: {field}: {e}"))
                })
                .collect()
        })
        .collect()
}
