//! The checked-in C header is what cbindgen makes of `src/lib.rs` now. Regenerate it with
//! `UPDATE_HEADER=1 cargo test -p soft-sphere-ffi --test header`.
//!
//! The f32 and f64 entry points are written once, as the `entry_points!` macro; cbindgen does not
//! expand macros, so this test expands its invocations (a plain substitution of the macro's
//! parameters) and hands cbindgen the source with the expansions appended. The laws' `SS_MODEL_*`
//! codes are made by the registry's macro from its list (`src/registry.rs`); this test writes
//! each entry's documentation and code as a constant where `codes.rs` names the list. The
//! modules' items join the crate root's, as one file.

use std::path::PathBuf;

/// `source` with every `entry_points!(...)` invocation's expansion appended.
fn expanded(source: &str) -> String {
    let arm = source
        .split_once("macro_rules! entry_points {")
        .expect("the entry_points macro")
        .1;
    let (pattern, rest) = arm.split_once("=> {").expect("one macro arm");
    let body = rest.split_once("\n    };\n}").expect("the arm's end").0;
    let parameters: Vec<&str> = pattern
        .split('$')
        .skip(1)
        .map(|p| p.split(':').next().unwrap().trim())
        .collect();
    let mut out = source.to_string();
    for invocation in source.split("\nentry_points!(").skip(1) {
        let arguments = invocation.split_once(");").unwrap().0;
        let (real, names) = arguments.split_once(':').unwrap();
        let values: Vec<&str> = std::iter::once(real.trim())
            .chain(names.split(',').map(str::trim))
            .collect();
        assert_eq!(values.len(), parameters.len(), "{arguments}");
        let mut expansion = body.to_string();
        // Longest names first, so that no parameter is a prefix of one replaced after it.
        let mut pairs: Vec<_> = parameters.iter().zip(&values).collect();
        pairs.sort_by_key(|(p, _)| std::cmp::Reverse(p.len()));
        for (parameter, value) in pairs {
            expansion = expansion.replace(&format!("${parameter}"), value);
        }
        out.push_str(&expansion);
    }
    out
}

/// The marker in `codes.rs` where the registry's codes belong.
const CODES_MARKER: &str =
    "// The laws' codes, SS_MODEL_STATELESS to SS_MODEL_HERTZ_MICROSLIP: registry.rs's list.\n";

/// The `SS_MODEL_*` constants of the registry's list (`with_laws!`), as Rust source: each
/// entry's doc lines, then `pub const CODE: i32 = value;`.
fn registry_codes(registry: &str) -> String {
    let list = registry
        .split_once("macro_rules! with_laws {")
        .expect("the list of laws")
        .1;
    let list = list
        .split_once("$callback! { $($d)?")
        .expect("the list's start")
        .1;
    let list = list.split_once('}').expect("the list's end").0;
    let mut out = String::new();
    let mut entries = 0;
    // The part brackets aside, every line is a doc line or an entry.
    let lines = list.lines().map(str::trim);
    for line in lines.filter(|l| !l.is_empty() && *l != "[" && *l != "]") {
        if line.starts_with("///") {
            out.push_str(line);
            out.push('\n');
            continue;
        }
        let mut parts = line
            .split(',')
            .next()
            .unwrap()
            .split('=')
            .map(str::trim)
            .skip(1);
        let (Some(code), Some(value)) = (parts.next(), parts.next()) else {
            panic!("an entry without a code and value: {line}");
        };
        out.push_str(&format!("pub const {code}: i32 = {value};\n"));
        entries += 1;
    }
    assert!(entries >= 9, "the list holds every law ({entries} read)");
    out
}

#[test]
fn header_is_current() {
    let crate_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")).unwrap();
    // The version macros, from the crate's version (as `ss_version()` returns it).
    config.after_includes = Some(format!(
        "\n/* This header's version; ss_version() returns the loaded library's. */\n\
         #define SS_VERSION_MAJOR {}\n#define SS_VERSION_MINOR {}\n#define SS_VERSION_PATCH {}\n\
         #define SS_VERSION_STRING \"{}\"\n",
        env!("CARGO_PKG_VERSION_MAJOR"),
        env!("CARGO_PKG_VERSION_MINOR"),
        env!("CARGO_PKG_VERSION_PATCH"),
        env!("CARGO_PKG_VERSION"),
    ));
    let root = std::fs::read_to_string(crate_dir.join("src/lib.rs")).unwrap();
    // One file: the modules' declarations and re-exports dropped, their paths made local. The
    // registry holds no C item (and its macro input is not Rust cbindgen parses).
    let modules = [
        "any_table",
        "arrays",
        "codes",
        "exports",
        "handle",
        "list",
        "names",
        "real",
        "state",
        "table",
        "types",
    ];
    let mut root = root
        .replace("#[macro_use]\nmod registry;", "")
        .replace("#[macro_use]\nmod exports;", "")
        .replace("pub use registry::*; // the laws' SS_MODEL_* codes\n", "");
    for module in modules {
        root = root
            .replace(&format!("pub mod {module};\n"), "")
            .replace(&format!("mod {module};\n"), "")
            .replace(&format!("pub use {module}::*;\n"), "")
            .replace(&format!("use {module}::*;\n"), "");
        // A single item re-exported: `pub use module::Item;`.
        while let Some((before, after)) = root.split_once(&format!("pub use {module}::")) {
            if after.starts_with('{') {
                break;
            }
            root = format!("{before}{}", after.split_once(";\n").unwrap().1);
        }
        if let Some((before, after)) = root.split_once(&format!("pub use {module}::{{")) {
            root = format!("{before}{}", after.split_once("};").unwrap().1);
        }
    }
    let mut source = root;
    let registry = std::fs::read_to_string(crate_dir.join("src/registry.rs")).unwrap();
    for module in modules {
        let text = std::fs::read_to_string(crate_dir.join(format!("src/{module}.rs"))).unwrap();
        let text = if module == "codes" {
            assert!(
                text.contains(CODES_MARKER),
                "codes.rs names the registry's list"
            );
            text.replace(CODES_MARKER, &registry_codes(&registry))
        } else {
            text
        };
        let text: String = text
            .lines()
            .filter(|line| !line.starts_with("//!"))
            .map(|line| format!("{line}\n"))
            .collect();
        // The crate's own imports name nothing cbindgen needs (a `use` ends at its `;`).
        let mut text = text.as_str();
        let mut kept = String::new();
        while let Some((before, after)) = text.split_once("\nuse crate") {
            kept.push_str(before);
            text = after.split_once(';').expect("the use's end").1;
        }
        kept.push_str(text);
        let local = kept.replace("any_table::", "").replace("table::", "");
        source = format!("{source}\n{local}");
    }
    let scratch = std::env::temp_dir().join(format!("soft_sphere_ffi_{}.rs", std::process::id()));
    std::fs::write(&scratch, expanded(&source)).unwrap();
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_src(&scratch)
        .with_config(config)
        .generate()
        .expect("cbindgen parses the expanded source")
        .write(&mut generated);
    let _ = std::fs::remove_file(&scratch);
    let generated = String::from_utf8(generated).unwrap();
    let path = crate_dir.join("include/soft_sphere.h");
    if std::env::var_os("UPDATE_HEADER").is_some() {
        std::fs::write(&path, &generated).unwrap();
    }
    let checked_in = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        checked_in == generated,
        "include/soft_sphere.h is stale: run UPDATE_HEADER=1 cargo test -p soft-sphere-ffi --test header"
    );
    for symbol in [
        "ss_law_new_f64",
        "ss_law_new_f32",
        "ss_sphere_wall_f32",
        "ss_contact_duration_f32",
        "ss_forces_f64",
        "ss_law_f32",
        "dashpot_ratio",
        "ss_table_evaluate_f64",
        "ss_table_evaluate_f32",
        "ss_neighbours",
        "ss_history_f64",
        "ss_model_of_name",
        "ss_parameter_name",
        "SS_PARAMETER_INERTIA",
    ] {
        assert!(
            generated.contains(symbol),
            "{symbol} missing from the header"
        );
    }
}

/// Every error code is its own number: a host tells them apart by value alone (the accuracy
/// limit's code once took the list entry's length code's value).
#[test]
fn error_codes_are_distinct() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("include/soft_sphere.h");
    let header = std::fs::read_to_string(path).unwrap();
    let mut codes: Vec<(i64, &str)> = header
        .lines()
        .filter_map(|line| line.strip_prefix("#define SS_ERR_"))
        .map(|rest| {
            let (name, value) = rest.split_once(' ').unwrap();
            (value.trim().parse().unwrap(), name)
        })
        .collect();
    assert!(codes.len() >= 19, "{codes:?}");
    codes.sort();
    for pair in codes.windows(2) {
        assert_ne!(pair[0].0, pair[1].0, "{pair:?} share a value");
    }
    assert!(codes.iter().all(|&(value, _)| value > 0));
}
