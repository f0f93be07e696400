//! The import graph of the kernel, the C ABI and the scene: which module names which (directly,
//! `crate::module::...` or `crate::folder::module::...`, or through the crate root's re-exports,
//! `crate::Name` and `use crate::*`), with no cycle, so that each module can be read, tested and moved after the
//! ones it builds on.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// Module name to the modules it names.
type Graph = BTreeMap<String, BTreeSet<String>>;

/// The source without comments, and without its unit tests (a `#[cfg(test)]` module, which
/// may name what it likes).
fn code(path: &Path) -> String {
    let text = fs::read_to_string(path).unwrap();
    let mut out = String::new();
    for line in text.lines() {
        let line = line.split("//").next().unwrap_or("");
        out.push_str(line);
        out.push('\n');
    }
    match out.find("#[cfg(test)]\nmod ") {
        Some(at) => out[..at].to_string(),
        None => out,
    }
}

/// Identifiers and the punctuation the scan needs (`::`, `{`, `}`, `,`, `*`, `;`, `.`).
fn tokens(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let chars: Vec<char> = code.chars().collect();
    let mut k = 0;
    while k < chars.len() {
        let c = chars[k];
        if c.is_alphanumeric() || c == '_' {
            let start = k;
            while k < chars.len() && (chars[k].is_alphanumeric() || chars[k] == '_') {
                k += 1;
            }
            out.push(chars[start..k].iter().collect());
            continue;
        }
        if c == ':' && chars.get(k + 1) == Some(&':') {
            out.push("::".into());
            k += 2;
            continue;
        }
        if "{},*;.".contains(c) {
            out.push(c.to_string());
        }
        k += 1;
    }
    out
}

/// The `.rs` files under `dir`, at any depth.
fn files_under(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in fs::read_dir(dir).unwrap() {
            let p = entry.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|e| e == "rs") {
                files.push(p);
            }
        }
    }
    files
}

/// Each module of `src` and the files it is made of: a top-level file or folder, or, for a
/// folder of concerns (one whose `mod.rs` only declares its modules, as the kernel's `law/`,
/// `seam/` and `value/`), each module in it, named `folder::module`.
fn modules(src: &Path) -> BTreeMap<String, Vec<PathBuf>> {
    let mut out = BTreeMap::new();
    for entry in fs::read_dir(src).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        if path.is_dir() {
            // Only `mod`, `use` and attribute lines (and comments, which `code` drops).
            let declares_only = code(&path.join("mod.rs")).lines().all(|line| {
                let line = line.trim();
                let bare = ["pub(crate) ", "pub "]
                    .iter()
                    .find_map(|p| line.strip_prefix(p))
                    .unwrap_or(line);
                line.is_empty()
                    || line.starts_with('#')
                    || bare.starts_with("mod ")
                    || bare.starts_with("use ")
            });
            if !declares_only {
                out.insert(name, files_under(&path));
                continue;
            }
            for entry in fs::read_dir(&path).unwrap() {
                let inner = entry.unwrap().path();
                let child = inner.file_stem().unwrap().to_string_lossy().to_string();
                if inner.is_dir() {
                    out.insert(format!("{name}::{child}"), files_under(&inner));
                } else if inner.extension().is_some_and(|e| e == "rs") && child != "mod" {
                    out.insert(format!("{name}::{child}"), vec![inner]);
                }
            }
        } else if path.extension().is_some_and(|e| e == "rs") && name != "lib" {
            out.insert(name, vec![path]);
        }
    }
    out
}

/// The module a path starting at token `k` names (`list`, or `seam :: list` in a folder of
/// concerns), and the number of tokens it spans.
fn module_at(
    t: &[String],
    k: usize,
    modules: &BTreeMap<String, Vec<PathBuf>>,
) -> Option<(String, usize)> {
    let first = t.get(k)?;
    if modules.contains_key(first) {
        return Some((first.clone(), 1));
    }
    if t.get(k + 1).map(String::as_str) == Some("::") {
        let nested = format!("{first}::{}", t.get(k + 2)?);
        if modules.contains_key(&nested) {
            return Some((nested, 3));
        }
    }
    None
}

/// The items a module defines at its top level (or in the macros that make them): types,
/// traits and constants at any indentation, functions at the start of a line.
fn defined(files: &[PathBuf]) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for file in files {
        for line in code(file).lines() {
            let trimmed = line.trim_start();
            let Some(rest) = trimmed.strip_prefix("pub") else {
                continue;
            };
            let rest = rest.strip_prefix("(crate)").unwrap_or(rest).trim_start();
            let words: Vec<&str> = rest.split_whitespace().collect();
            let at_start = trimmed.len() == line.len();
            let name = match words.as_slice() {
                ["const" | "struct" | "enum" | "trait" | "type", name, ..] => name,
                ["fn", name, ..] if at_start => name,
                ["unsafe", "fn", name, ..] if at_start => name,
                ["unsafe", "extern", _, "fn", name, ..] if at_start => name,
                ["extern", _, "fn", name, ..] if at_start => name,
                _ => continue,
            };
            let name: String = name
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            out.insert(name);
        }
    }
    out
}

/// What the crate root makes of each name: the module it comes from (`use m::{..}` and
/// `use m::*`, public or not), or `lib` for an item the root defines itself.
fn root_names(src: &Path, modules: &BTreeMap<String, Vec<PathBuf>>) -> BTreeMap<String, String> {
    let mut out: BTreeMap<String, String> = defined(&[src.join("lib.rs")])
        .into_iter()
        .map(|name| (name, "lib".to_string()))
        .collect();
    imports(&tokens(&code(&src.join("lib.rs"))), modules, &mut out, true);
    out
}

/// The names the `use` statements of `t` bring in, each to the module it comes from (a path
/// from the root or from `crate::`). With `follow`, a glob of a module that only re-exports (the
/// kernel's `use prelude::*`) brings in what that module's own `use` statements name.
fn imports(
    t: &[String],
    modules: &BTreeMap<String, Vec<PathBuf>>,
    out: &mut BTreeMap<String, String>,
    follow: bool,
) {
    for k in 0..t.len() {
        if t[k] != "use" {
            continue;
        }
        let from = if t.get(k + 1).map(String::as_str) == Some("crate") {
            k + 3
        } else {
            k + 1
        };
        let Some((module, span)) = module_at(t, from, modules) else {
            continue;
        };
        let at = from + span;
        // `use law::checks;`: the root names a module itself.
        if t.get(at).map(String::as_str) == Some(";") {
            let last = module.rsplit("::").next().unwrap_or(&module).to_string();
            out.insert(last, module.clone());
            continue;
        }
        if at + 1 >= t.len() || t[at] != "::" {
            continue;
        }
        let module = &module;
        match t[at + 1].as_str() {
            "*" => {
                for name in defined(&modules[module]) {
                    out.entry(name).or_insert_with(|| module.clone());
                }
                if follow {
                    for file in &modules[module] {
                        imports(&tokens(&code(file)), modules, out, false);
                    }
                }
            }
            "{" => {
                for token in t[at + 2..].iter().take_while(|x| *x != "}") {
                    if token.chars().all(|c| c.is_alphanumeric() || c == '_') {
                        out.insert(token.clone(), module.clone());
                    }
                }
            }
            name => {
                out.insert(name.to_string(), module.clone());
            }
        }
    }
}

/// The import graph of the crate at `src`, its root (`lib`, what `lib.rs` holds besides its
/// module declarations and imports) among the modules.
fn graph(src: &Path) -> Graph {
    let mut modules = modules(src);
    let names = root_names(src, &modules);
    let root = src.join("lib.rs");
    let mut out = Graph::new();
    // The root's own code: its statements but the `mod` and `use` ones.
    let mut own = String::new();
    for statement in code(&root).split_inclusive(';') {
        let words = statement.split_whitespace().collect::<Vec<_>>().join(" ");
        let declaration = ["mod ", "pub mod ", "use ", "pub use ", "#[macro_use] mod "]
            .iter()
            .any(|start| words.starts_with(start) || words.contains(&format!("] {start}")));
        if !declaration {
            own.push_str(statement);
        }
    }
    // One file per test thread, as the tests run side by side.
    let thread = format!("{:?}", std::thread::current().id());
    let thread: String = thread.chars().filter(char::is_ascii_digit).collect();
    let scratch =
        std::env::temp_dir().join(format!("module_graph_{}_{thread}.rs", std::process::id()));
    fs::write(&scratch, own).unwrap();
    modules.insert("lib".to_string(), vec![scratch.clone()]);
    for (module, files) in &modules {
        let own = defined(files);
        let mut deps = BTreeSet::new();
        let add = |name: &str, deps: &mut BTreeSet<String>| {
            if modules.contains_key(name) {
                deps.insert(name.to_string());
            } else if let Some(m) = names.get(name).filter(|_| !own.contains(name)) {
                deps.insert(m.clone());
            }
        };
        for file in files {
            let t = tokens(&code(file));
            // A path that starts at a module (`list::check_neighbours`, through `use crate::*`
            // or the root's own scope).
            for k in 0..t.len().saturating_sub(1) {
                let head = k == 0 || t[k - 1] != "::";
                if let Some((named, span)) = module_at(&t, k, &modules).filter(|_| head) {
                    if t.get(k + span).map(String::as_str) == Some("::") {
                        add(&named, &mut deps);
                    }
                } else if head && t[k + 1] == "::" {
                    // A module the root names (`checks::coulomb` through `pub use law::checks`).
                    let module_itself = |m: &&String| m.rsplit("::").next() == Some(t[k].as_str());
                    if let Some(m) = names.get(&t[k]).filter(module_itself) {
                        deps.insert(m.clone());
                    }
                }
            }
            for k in 0..t.len().saturating_sub(2) {
                if t[k] != "crate" || t[k + 1] != "::" {
                    continue;
                }
                if let Some((named, _)) = module_at(&t, k + 2, &modules) {
                    add(&named, &mut deps);
                    continue;
                }
                match t[k + 2].as_str() {
                    "*" => {
                        // Every name the file uses of the root's, but a method (`.name`), a
                        // path's later segment (`Flat::read`) or a function the file defines
                        // itself (`fn name`).
                        for (j, token) in t.iter().enumerate() {
                            let before = j.checked_sub(1).map(|b| t[b].as_str());
                            if names.contains_key(token)
                                && !matches!(before, Some("." | "fn" | "::"))
                            {
                                add(token, &mut deps);
                            }
                        }
                    }
                    "{" => {
                        let mut depth = 0;
                        for token in &t[k + 2..] {
                            match token.as_str() {
                                "{" => depth += 1,
                                "}" => {
                                    depth -= 1;
                                    if depth == 0 {
                                        break;
                                    }
                                }
                                _ => add(token, &mut deps),
                            }
                        }
                    }
                    name => add(name, &mut deps),
                }
            }
        }
        deps.remove(module);
        out.insert(module.clone(), deps);
    }
    let _ = fs::remove_file(&scratch);
    out
}

/// A cycle of the graph, if there is one (a path that comes back to its start).
fn cycle(graph: &Graph) -> Option<Vec<String>> {
    // Depth-first, colouring each module: on the current path (1) or finished (2).
    fn visit(
        graph: &Graph,
        module: &str,
        colour: &mut BTreeMap<String, u8>,
        path: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        colour.insert(module.to_string(), 1);
        path.push(module.to_string());
        for next in graph.get(module).into_iter().flatten() {
            match colour.get(next).copied().unwrap_or(0) {
                1 => {
                    let from = path.iter().position(|m| m == next).unwrap();
                    let mut found = path[from..].to_vec();
                    found.push(next.clone());
                    return Some(found);
                }
                0 => {
                    if let Some(found) = visit(graph, next, colour, path) {
                        return Some(found);
                    }
                }
                _ => {}
            }
        }
        path.pop();
        colour.insert(module.to_string(), 2);
        None
    }
    let mut colour = BTreeMap::new();
    for module in graph.keys() {
        if colour.get(module).copied().unwrap_or(0) == 0 {
            let mut path = Vec::new();
            if let Some(found) = visit(graph, module, &mut colour, &mut path) {
                return Some(found);
            }
        }
    }
    None
}

fn crate_src(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(relative)
}

#[test]
fn the_kernel_the_c_abi_and_the_scene_have_no_module_cycle() {
    for src in ["kernel/src", "examples/c-abi/src", "examples/scene/src"] {
        let graph = graph(&crate_src(src));
        let edges: usize = graph.values().map(BTreeSet::len).sum();
        assert!(graph.len() > 8 && edges > 10, "{src}: {graph:?}");
        assert_eq!(cycle(&graph), None, "{src}");
    }
}

/// The scan sees each way a module names another, and the search finds a cycle made of them.
#[test]
fn the_scan_sees_each_way_of_naming_and_the_search_finds_a_cycle() {
    let graph = graph(&crate_src("kernel/src"));
    let names = |m: &str| graph[m].iter().cloned().collect::<Vec<_>>();
    let (law, engine, forces) = ("law::contact_law", "law::engine", "value::forces");
    // `use crate::law::engine::{BoundLaw, Law}` (a module path in a folder of concerns) and
    // `crate::value::forces::...`.
    assert!(names(law).contains(&engine.to_string()), "{:?}", names(law));
    assert!(names(law).contains(&forces.to_string()));
    // A link to `crate::Frictionless` in a comment is not an import.
    assert!(!names(forces).contains(&"law::tangential".to_string()));
    // Through the prelude the root names each item's home: `Vec3` is `value::vector`'s.
    let names = root_names(&crate_src("kernel/src"), &modules(&crate_src("kernel/src")));
    assert_eq!(names.get("Vec3").map(String::as_str), Some("value::vector"));
    assert_eq!(names.get("checks").map(String::as_str), Some("law::checks"));
    // A folder inside a folder of concerns is one module.
    assert!(graph.contains_key("law::tangential") && !graph.contains_key("law"));
    let mut looped = graph.clone();
    looped.get_mut(forces).unwrap().insert(law.to_string());
    let found = cycle(&looped).expect("forces -> law -> forces");
    assert_eq!(found.first(), found.last());
    assert!(found.contains(&forces.to_string()) && found.contains(&law.to_string()));
    // Through the root: a `use crate::*` module names what it uses of the root's
    // (`forces_of`, the handles'), and a module path it reaches that way (`list::`).
    let abi = graph_of("examples/c-abi/src");
    assert!(abi["arrays"].contains("handle"), "{:?}", abi["arrays"]);
    assert!(abi["any_table"].contains("list"), "{:?}", abi["any_table"]);
    assert!(abi["any_table"].contains("registry"));
}

fn graph_of(src: &str) -> Graph {
    graph(&crate_src(src))
}
