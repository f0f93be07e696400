//! The kernel's list of named laws (`soft_sphere::for_each_law!`) against every place that
//! names the laws: the kernel's aliases, the C ABI's codes and names, the LAMMPS docs, the
//! property tests, the validation cases, the benchmarks, the oblique-impact example and the
//! docs' tables. Each place is read as text, and the test fails, naming the place, when a law of
//! the list is missing from it (or, for the aliases and the C ABI, when a place has a law the
//! list lacks).

use std::fs;
use std::path::Path;

/// One law of the list.
#[derive(Debug)]
struct Law {
    alias: &'static str,
    name: &'static str,
    normal: &'static str,
    tangential: &'static str,
}

impl Law {
    fn linear(&self) -> bool {
        self.normal == "LinearSpringDashpot"
    }

    fn hertz(&self) -> bool {
        self.normal == "Hertz"
    }

    fn frictional(&self) -> bool {
        self.tangential != "Frictionless"
    }

    /// Whether a C ABI handle (`ss_law_new_*`) and so a name take it: micro-slip's state does
    /// not fit `ss_state`, so only the C ABI's tables take it, by code.
    fn named_in_c_abi(&self) -> bool {
        self.tangential != "MicroSlip"
    }
}

macro_rules! laws {
    ($($alias:ident = $name:literal, $normal:ident, $tangential:ident;)*) => {
        [$(Law {
            alias: stringify!($alias),
            name: $name,
            normal: stringify!($normal),
            tangential: stringify!($tangential),
        }),*]
    };
}

fn list() -> Vec<Law> {
    soft_sphere::for_each_law!(laws).into_iter().collect()
}

fn read(path: &str) -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    fs::read_to_string(root.join(path)).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The text of `path` from the first `start` to the first `end` after it.
fn section(path: &str, start: &str, end: &str) -> String {
    let text = read(path);
    let from = text
        .find(start)
        .unwrap_or_else(|| panic!("{path}: no `{start}`"));
    let rest = &text[from..];
    let to = rest[start.len()..]
        .find(end)
        .unwrap_or_else(|| panic!("{path}: no `{end}` after `{start}`"))
        + start.len();
    rest[..to].to_string()
}

/// Whether `word` occurs in `text` as a whole: where it begins (ends) with a letter, digit, `_`
/// or `/`, none of those may come before (after) it.
fn has_word(text: &str, word: &str) -> bool {
    let part = |c: char| c.is_alphanumeric() || c == '_' || c == '/';
    let open = word.chars().next().is_some_and(part);
    let close = word.chars().next_back().is_some_and(part);
    text.match_indices(word).any(|(i, _)| {
        let joined_before = open && text[..i].chars().next_back().is_some_and(part);
        let joined_after = close && text[i + word.len()..].chars().next().is_some_and(part);
        !joined_before && !joined_after
    })
}

/// One place that names the laws: where, which laws it must name, and how it names one.
struct Place {
    what: &'static str,
    text: String,
    takes: fn(&Law) -> bool,
    names: fn(&Law) -> String,
}

fn places() -> Vec<Place> {
    let all: fn(&Law) -> bool = |_| true;
    vec![
        Place {
            what: "kernel/src/law/laws.rs: the aliases",
            text: read("kernel/src/law/laws.rs"),
            takes: all,
            names: |l| format!("pub type {}<", l.alias),
        },
        Place {
            what: "examples/c-abi/src/registry.rs: the C ABI's codes",
            text: section(
                "examples/c-abi/src/registry.rs",
                "macro_rules! with_laws {",
                "\n}\n",
            ),
            takes: all,
            names: |l| format!("{} = ", l.alias),
        },
        Place {
            what: "docs/lammps.md: the pair_coeff lines",
            text: section("docs/lammps.md", "pair_coeff I J LAW k_n", "rolling mu_r"),
            takes: Law::named_in_c_abi,
            names: |l| l.name.to_string(),
        },
        Place {
            what: "docs/usage.md: the slot table's tangential row",
            text: section("docs/usage.md", "| tangential |", "\n"),
            takes: all,
            names: |l| format!("`{}`", l.tangential),
        },
        Place {
            what: "docs/usage.md: the slot table's normal row",
            text: section("docs/usage.md", "| normal |", "\n"),
            takes: all,
            names: |l| format!("`{}`", l.normal),
        },
        Place {
            what: "README.md: the named laws",
            text: section("README.md", "The common laws have names (", ")."),
            takes: all,
            names: |l| l.alias.to_string(),
        },
        Place {
            what: "docs/performance.md: the one-contact table",
            text: section(
                "docs/performance.md",
                "| law | f64, libm | f32, libm | f32, micromath |",
                "\n\n",
            ),
            takes: all,
            names: |l| format!("| `{}` |", l.name),
        },
        Place {
            what: "host-tests/tests/properties.rs: each_law!",
            text: section(
                "host-tests/tests/properties.rs",
                "macro_rules! each_law {",
                "\n}\n",
            ),
            takes: Law::linear,
            names: |l| l.tangential.to_string(),
        },
        Place {
            what: "host-tests/tests/hertz.rs: each_mindlin_law!",
            text: section(
                "host-tests/tests/hertz.rs",
                "macro_rules! each_mindlin_law {",
                "\n}\n",
            ),
            // Hertz without friction has the linear law's slot, which properties.rs checks.
            takes: |l| l.hertz() && l.frictional(),
            names: |l| l.tangential.to_string(),
        },
        Place {
            what: "host-tests/tests/tangential.rs: for_each_frictional_model!",
            text: section(
                "host-tests/tests/tangential.rs",
                "macro_rules! for_each_frictional_model {",
                "\n}\n",
            ),
            takes: |l| l.linear() && l.frictional(),
            names: |l| format!("{}(p)", l.tangential),
        },
        Place {
            what: "host-tests/src/validation/kharaz.rs: the oblique impacts' laws",
            text: read("host-tests/src/validation/kharaz.rs"),
            takes: |l| l.linear() && l.frictional(),
            names: |l| format!("Self::{} =>", l.tangential),
        },
        Place {
            what: "host-tests/src/validation/chung_ooi.rs: Chung & Ooi's laws",
            text: read("host-tests/src/validation/chung_ooi.rs"),
            takes: |l| l.hertz() && l.frictional(),
            names: |l| format!("Self::{} =>", l.alias),
        },
        Place {
            what: "examples/oblique-impact/src/main.rs: the table of laws",
            text: read("examples/oblique-impact/src/main.rs"),
            takes: |l| l.linear() && l.frictional(),
            names: |l| format!("impact({}(p)", l.tangential),
        },
    ]
}

#[test]
fn every_place_names_every_law_of_the_list() {
    let laws = list();
    let mut missing = Vec::new();
    for place in places() {
        for law in laws.iter().filter(|l| (place.takes)(l)) {
            let name = (place.names)(law);
            if !has_word(&place.text, &name) {
                missing.push(format!("{}: no `{name}` ({})", place.what, law.alias));
            }
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
}

#[test]
fn the_c_abi_names_each_law_as_the_list_does() {
    let registry = section(
        "examples/c-abi/src/registry.rs",
        "macro_rules! with_laws {",
        "\n}\n",
    );
    for law in list() {
        let line = registry
            .lines()
            .find(|line| {
                line.trim_start()
                    .starts_with(&format!("{} = SS_MODEL_", law.alias))
            })
            .unwrap_or_else(|| panic!("registry.rs: no entry for {}", law.alias));
        let named = line.contains(&format!(", \"{}\",", law.name));
        assert_eq!(
            named,
            law.named_in_c_abi(),
            "registry.rs names {} otherwise than the list (`{}`): {line}",
            law.alias,
            law.name
        );
        // Its family and its slot (a tables-only law names its table's mixing rule instead).
        let family = if law.linear() {
            ", linear, "
        } else {
            ", hertz, "
        };
        let slot = has_word(line, law.tangential)
            || line.contains(&format!(", {}Mixing<", law.tangential));
        assert!(
            line.contains(family) && slot,
            "registry.rs gives {} another family or slot than the list ({}, {}): {line}",
            law.alias,
            law.normal,
            law.tangential
        );
    }
}

#[test]
fn the_list_holds_every_alias_and_every_c_abi_law() {
    let laws = list();
    let known = |alias: &str| laws.iter().any(|l| l.alias == alias);
    for line in read("kernel/src/law/laws.rs").lines() {
        if let Some(rest) = line.strip_prefix("pub type ") {
            let alias = &rest[..rest.find('<').expect("an alias is generic")];
            // A family (`LinearLaw<F, T, ..>`) leaves the tangential slot open: no law.
            if rest[alias.len()..].starts_with("<F, T,") {
                continue;
            }
            assert!(known(alias), "laws.rs's {alias} is not in for_each_law!");
        }
    }
    let registry = section(
        "examples/c-abi/src/registry.rs",
        "macro_rules! with_laws {",
        "\n}\n",
    );
    let entries: Vec<&str> = registry
        .lines()
        .filter_map(|line| line.trim_start().split_once(" = SS_MODEL_"))
        .map(|(alias, _)| alias)
        .collect();
    assert_eq!(entries.len(), laws.len(), "registry.rs: {entries:?}");
    for alias in entries {
        assert!(
            known(alias),
            "registry.rs's {alias} is not in for_each_law!"
        );
    }
}

#[test]
fn the_benchmarks_time_the_list() {
    let bench = read("host-tests/benches/contact.rs");
    assert!(
        bench.contains("soft_sphere::for_each_law!(named_laws)"),
        "benches/contact.rs no longer builds its timings from the list"
    );
    let every_law = section(
        "host-tests/benches/contact.rs",
        "macro_rules! every_law {",
        "\n}\n",
    );
    assert!(
        every_law.contains("every_named_law!("),
        "benches/contact.rs no longer times the list's laws"
    );
}

/// The tangential slot's type in `f64` (micro-slip at 16 breakpoints).
macro_rules! slot_type {
    (Frictionless) => {
        soft_sphere::prelude::Frictionless
    };
    (MicroSlip) => {
        soft_sphere::prelude::MicroSlip<f64, 16>
    };
    ($tangential:ident) => {
        soft_sphere::prelude::$tangential<f64>
    };
}

/// The alias's type in `f64`.
macro_rules! alias_type {
    (HertzMicroSlip) => {
        soft_sphere::prelude::HertzMicroSlip<f64, 16>
    };
    ($alias:ident) => {
        soft_sphere::prelude::$alias<f64>
    };
}

/// Compiles only where each entry's alias is the law its slots make.
macro_rules! aliases_are_their_slots {
    ($($alias:ident = $name:literal, $normal:ident, $tangential:ident;)*) => {
        fn same_type<T>(_: Option<T>, _: Option<T>) {}
        $(
            same_type(
                None::<alias_type!($alias)>,
                None::<soft_sphere::prelude::ContactLaw<f64, soft_sphere::prelude::$normal<f64>, slot_type!($tangential)>>,
            );
        )*
    };
}

#[test]
fn each_alias_is_the_law_its_entry_names() {
    soft_sphere::for_each_law!(aliases_are_their_slots);
}

#[test]
fn a_missing_word_is_found_missing() {
    assert!(has_word("`aa`, `hertz/aa`", "aa"));
    assert!(!has_word("`hertz/aa`", "aa"));
    assert!(!has_word("ModelAALuding(p)", "ModelAA"));
    assert!(has_word("ModelAA(p)", "ModelAA"));
    assert!(has_word("pub type HertzAA<F>", "pub type HertzAA<"));
    assert!(!has_word("Self::ModelAALuding =>", "Self::ModelAA =>"));
}
