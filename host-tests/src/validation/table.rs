//! A small table of numbers (and labels): written as CSV with full precision, printed aligned.

use std::fmt::Write as _;
use std::io;
use std::path::Path;

/// One table cell.
#[derive(Clone, Debug, PartialEq)]
pub enum Cell {
    /// A label, such as a model name.
    Text(String),
    /// A number, written with full round-trip precision.
    Number(f64),
}

impl From<f64> for Cell {
    fn from(value: f64) -> Self {
        Self::Number(value)
    }
}

impl From<&str> for Cell {
    fn from(value: &str) -> Self {
        Self::Text(value.to_owned())
    }
}

/// A header, rows, and an optional leading `#` comment line with the settings.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// The `#` comment line (without the `#`).
    pub comment: Option<String>,
    /// Column names.
    pub header: Vec<String>,
    /// Rows, each as long as the header.
    pub rows: Vec<Vec<Cell>>,
    /// When printed, every `n`-th row (and the last) is shown; 0 prints none (CSV only).
    pub shown_every: usize,
}

impl Table {
    /// An empty table with these columns.
    pub fn new(header: &[&str]) -> Self {
        Self {
            comment: None,
            header: header.iter().map(|h| (*h).to_owned()).collect(),
            rows: Vec::new(),
            shown_every: 1,
        }
    }

    /// The same table, printed every `n`-th row (0: not printed).
    pub fn shown_every(mut self, n: usize) -> Self {
        self.shown_every = n;
        self
    }

    /// The same table with a comment line.
    pub fn with_comment(mut self, comment: impl Into<String>) -> Self {
        self.comment = Some(comment.into());
        self
    }

    /// Appends a row.
    pub fn push(&mut self, row: Vec<Cell>) {
        debug_assert_eq!(row.len(), self.header.len());
        self.rows.push(row);
    }

    /// The numbers of column `name` (NaN for labels).
    ///
    /// # Panics
    /// When there is no such column.
    pub fn column(&self, name: &str) -> Vec<f64> {
        let index = self
            .header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name}"));
        self.rows
            .iter()
            .map(|row| match row[index] {
                Cell::Number(x) => x,
                Cell::Text(_) => f64::NAN,
            })
            .collect()
    }

    /// CSV text: the comment line, the header, the rows.
    pub fn to_csv(&self) -> String {
        let mut out = String::new();
        if let Some(comment) = &self.comment {
            let _ = writeln!(out, "# {comment}");
        }
        let _ = writeln!(out, "{}", self.header.join(","));
        for row in &self.rows {
            let cells: Vec<String> = row
                .iter()
                .map(|cell| match cell {
                    Cell::Text(text) => text.clone(),
                    Cell::Number(x) => format!("{x}"),
                })
                .collect();
            let _ = writeln!(out, "{}", cells.join(","));
        }
        out
    }

    /// Writes the CSV text to `path`.
    ///
    /// # Errors
    /// The file system's.
    pub fn write_csv(&self, path: &Path) -> io::Result<()> {
        std::fs::write(path, self.to_csv())
    }

    /// Aligned text with numbers to five significant digits, every `shown_every`-th row (and
    /// the last); empty when `shown_every` is 0.
    pub fn to_text(&self) -> String {
        if self.shown_every == 0 {
            return String::new();
        }
        let stride = self.shown_every;
        let last = self.rows.len().saturating_sub(1);
        let shown: Vec<Vec<String>> = self
            .rows
            .iter()
            .enumerate()
            .filter(|(i, _)| i % stride == 0 || *i == last)
            .map(|(_, row)| {
                row.iter()
                    .map(|cell| match cell {
                        Cell::Text(text) => text.clone(),
                        Cell::Number(x) => significant(*x, 5),
                    })
                    .collect()
            })
            .collect();
        let widths: Vec<usize> = (0..self.header.len())
            .map(|c| {
                shown
                    .iter()
                    .map(|row| row[c].len())
                    .chain([self.header[c].len()])
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let mut out = String::new();
        let line = |cells: &[String], out: &mut String| {
            let padded: Vec<String> = cells
                .iter()
                .zip(&widths)
                .map(|(cell, w)| format!("{cell:>w$}"))
                .collect();
            let _ = writeln!(out, "  {}", padded.join("  "));
        };
        line(&self.header, &mut out);
        for row in &shown {
            line(row, &mut out);
        }
        out
    }
}

/// `x` with `digits` significant digits, in plain or exponent notation as fits.
pub fn significant(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor() as i32;
    if (-3..6).contains(&magnitude) {
        let decimals = (digits as i32 - 1 - magnitude).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.prec$e}", prec = digits - 1)
    }
}
