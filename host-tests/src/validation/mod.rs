//! The validation cases of docs/physics.md, section 5, each run against its closed form or data, with the
//! tolerance the project states for it. The `validate` binary prints and writes them; the
//! `validation` test runs the same cases and fails when a tolerance is missed.

pub mod chung_ooi;
pub mod kharaz;
pub mod micro_slip;
pub mod normal;
pub mod plate;
pub mod precision;
pub mod rolling;
pub mod table;

use std::fmt;

pub use table::{Cell, Table};

/// One tolerance check: a measured value against an expected one.
#[derive(Clone, Debug)]
pub struct Check {
    /// The case and quantity, for example `kharaz model_aa e_t(40 deg) vs rigid body`.
    pub what: String,
    /// What the run produced.
    pub measured: f64,
    /// What theory or data says.
    pub expected: f64,
    /// The difference allowed.
    pub tolerance: f64,
    /// Whether `tolerance` is relative to `expected` (otherwise absolute).
    pub relative: bool,
}

impl Check {
    /// The difference measured in the tolerance's terms.
    pub fn deviation(&self) -> f64 {
        let difference = (self.measured - self.expected).abs();
        if self.relative {
            difference / self.expected.abs()
        } else {
            difference
        }
    }

    /// Whether the check holds (a NaN never does).
    pub fn passed(&self) -> bool {
        self.deviation() <= self.tolerance
    }
}

impl fmt::Display for Check {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = if self.relative {
            "relative"
        } else {
            "absolute"
        };
        write!(
            f,
            "{}: measured {:.6}, expected {:.6}, {kind} deviation {:.3e} (tolerance {:.1e})",
            self.what,
            self.measured,
            self.expected,
            self.deviation(),
            self.tolerance
        )
    }
}

/// What one case produced: tables to print and write, and the checks it made.
#[derive(Clone, Debug, Default)]
pub struct CaseOutput {
    /// Tables, by file name (`.csv` appended when written).
    pub tables: Vec<(String, Table)>,
    /// Tolerance checks.
    pub checks: Vec<Check>,
    /// Lines of commentary printed after the tables (measured facts that are shown, not checked).
    pub notes: Vec<String>,
}

impl CaseOutput {
    /// Records a check with a relative tolerance.
    pub fn relative(&mut self, what: impl Into<String>, measured: f64, expected: f64, tol: f64) {
        self.checks.push(Check {
            what: what.into(),
            measured,
            expected,
            tolerance: tol,
            relative: true,
        });
    }

    /// Records a check with an absolute tolerance.
    pub fn absolute(&mut self, what: impl Into<String>, measured: f64, expected: f64, tol: f64) {
        self.checks.push(Check {
            what: what.into(),
            measured,
            expected,
            tolerance: tol,
            relative: false,
        });
    }

    /// The table written under `name`.
    ///
    /// # Panics
    /// When the case wrote no such table.
    pub fn table(&self, name: &str) -> &Table {
        &self
            .tables
            .iter()
            .find(|(file, _)| file == name)
            .unwrap_or_else(|| panic!("no table {name}"))
            .1
    }

    /// The checks that failed.
    pub fn failures(&self) -> Vec<&Check> {
        self.checks.iter().filter(|c| !c.passed()).collect()
    }
}

/// RMS of the differences between pairs.
pub fn rms(pairs: impl IntoIterator<Item = (f64, f64)>) -> f64 {
    let (sum, count) = pairs.into_iter().fold((0.0, 0usize), |(sum, n), (a, b)| {
        (sum + (a - b) * (a - b), n + 1)
    });
    (sum / count as f64).sqrt()
}
