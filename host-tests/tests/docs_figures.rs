//! README.md's figures are a summary of the docs: every measured figure in its "Accuracy" and
//! "Speed" sections (a decimal number, or a power of ten such as `1e-3`) must be stated in
//! `docs/`, the figure's home, so that the front page can never give a figure the docs do not
//! (or no longer) give. The docs' own tolerance table is checked by `validation.rs`.

use std::fs;
use std::path::Path;

fn read(path: &Path) -> String {
    fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The figures of `text`: numbers with a decimal point (`0.039`, `553.7`) or an exponent
/// (`1e-3`, `1e-9`), read whole (`13.12`, not `13`); whole numbers (`10,000`) and dates are not
/// figures here.
fn figures(text: &str) -> Vec<String> {
    let bytes = text.as_bytes();
    let mut found = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let starts = bytes[i].is_ascii_digit()
            && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_'));
        if !starts {
            i += 1;
            continue;
        }
        let digit = |k: usize| bytes.get(k).is_some_and(u8::is_ascii_digit);
        let mut j = i;
        loop {
            j += match bytes.get(j) {
                Some(b) if b.is_ascii_digit() => 1,
                Some(b'.' | b',') if digit(j + 1) => 2,
                Some(b'e') if digit(j + 1) => 2,
                Some(b'e') if bytes.get(j + 1) == Some(&b'-') && digit(j + 2) => 3,
                _ => break,
            };
        }
        let figure = &text[i..j];
        if figure.contains('.') || figure.contains('e') {
            found.push(figure.to_string());
        }
        i = j.max(i + 1);
    }
    found
}

/// The README's text from `start` to the next second-level heading (the accuracy and speed
/// tables and what follows them).
fn readme_section(readme: &str, start: &str) -> String {
    let from = readme
        .find(start)
        .unwrap_or_else(|| panic!("README.md: no `{start}`"));
    let rest = &readme[from..];
    let to = rest.find("\n## ").unwrap_or(rest.len());
    rest[..to].to_string()
}

#[test]
fn every_figure_on_the_front_page_is_stated_in_the_docs() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let readme = read(&root.join("README.md"));
    let mut docs = Vec::new();
    for entry in fs::read_dir(root.join("docs")).expect("docs/") {
        let path = entry.expect("an entry").path();
        if path.extension().is_some_and(|e| e == "md") {
            docs.extend(figures(&read(&path)));
        }
    }
    let section = readme_section(&readme, "**Accuracy**");
    assert!(
        section.contains("**Speed**"),
        "README.md: no Speed after Accuracy"
    );
    let front = figures(&section);
    assert!(front.len() > 20, "README.md: {front:?}");
    let missing: Vec<String> = front.into_iter().filter(|f| !docs.contains(f)).collect();
    assert!(
        missing.is_empty(),
        "README.md states figures docs/ does not:\n{}",
        missing.join("\n")
    );
}

#[test]
fn figures_are_read_as_written() {
    assert_eq!(
        figures(
            "RMS 0.039; 1e-3 of `e`, 13.12 s on 2026-12-06, 10,000 spheres, x86-64-v3, 1.21-1.24"
        ),
        ["0.039", "1e-3", "13.12", "1.21", "1.24"]
    );
}
