//! The core's modules import only from layers below their own (the table in
//! ARCHITECTURE.md): read from the source, so a new `use` that climbs up or
//! closes a circle fails here.

use std::collections::BTreeSet;
use std::path::Path;

/// The core's top-level modules, lowest layer first.
const LAYERS: &[&[&str]] = &[
    &[
        "alloc_count",
        "catalogue",
        "clock",
        "impact",
        "ledger",
        "math",
        "parallel",
        "particle",
        "rough",
    ],
    &["boundary", "integration", "metrics", "stats"],
    &["broad_phase", "laws"],
    &["narrow_phase"],
    &["resolution"],
    &["pipeline"],
    &["method"],
    &["auto"],
    &["world"],
    &["history", "presets", "scene", "warnings"],
    &["fingerprint", "stress"],
];

/// Items the crate root re-exports, and the module each comes from.
const RE_EXPORTS: &[(&str, &str)] = &[
    ("Axis", "boundary"),
    ("Boundary", "boundary"),
    ("Walls", "boundary"),
    ("Metrics", "metrics"),
    ("Color", "particle"),
    ("Particle", "particle"),
    ("Scene", "scene"),
    ("SceneError", "scene"),
    ("StepStats", "stats"),
    ("World", "world"),
];

fn layer_of(module: &str) -> Option<usize> {
    LAYERS.iter().position(|layer| layer.contains(&module))
}

/// The code of a file without comments and without its unit tests.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    text.lines()
        .map(|line| line.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The top-level modules a piece of code names through `crate::`.
fn imports(code: &str) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    let mut note = |name: &str| {
        let name = name.trim();
        let first = name.split("::").next().unwrap_or("").trim();
        if let Some((_, module)) = RE_EXPORTS.iter().find(|(item, _)| *item == first) {
            found.insert(module.to_string());
        } else if first.chars().next().is_some_and(|c| c.is_ascii_lowercase()) {
            found.insert(first.to_string());
        }
    };
    for piece in code.split("crate::").skip(1) {
        if let Some(group) = piece.strip_prefix('{') {
            // `crate::{a::b, C, d::{e, f}}`: the first name of each item.
            let (mut depth, mut item) = (0, String::new());
            for ch in group.chars() {
                match ch {
                    '{' => depth += 1,
                    '}' if depth == 0 => break,
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        note(&item);
                        item.clear();
                        continue;
                    }
                    _ => {}
                }
                if depth == 0 {
                    item.push(ch);
                }
            }
            note(&item);
        } else {
            let name: String = piece
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            note(&name);
        }
    }
    found
}

fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("the core's source directory") {
        let path = entry.expect("a directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn every_module_imports_only_from_layers_below_it() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut climbing = Vec::new();
    let mut modules_seen = BTreeSet::new();
    for file in &files {
        let relative = file.strip_prefix(&src).unwrap();
        let module = relative
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        if module == "lib" {
            continue;
        }
        let own = layer_of(&module)
            .unwrap_or_else(|| panic!("module {module} is in no layer: add it to LAYERS"));
        modules_seen.insert(module.clone());
        let text = std::fs::read_to_string(file).unwrap();
        for imported in imports(&code(&text)) {
            if imported == module {
                continue;
            }
            match layer_of(&imported) {
                Some(layer) if layer < own => {}
                Some(layer) => climbing.push(format!(
                    "{} (layer {own}) imports {imported} (layer {layer})",
                    relative.display()
                )),
                None => panic!(
                    "{} imports crate::{imported}, in no layer",
                    relative.display()
                ),
            }
        }
    }
    assert!(
        climbing.is_empty(),
        "imports that do not go down:\n{}",
        climbing.join("\n")
    );
    let listed: BTreeSet<String> = LAYERS
        .iter()
        .flat_map(|l| l.iter().map(|m| m.to_string()))
        .collect();
    assert_eq!(
        listed, modules_seen,
        "LAYERS lists a module that does not exist"
    );
}

#[test]
fn the_import_reader_sees_groups_re_exports_and_paths() {
    let found = imports(&code(
        "use crate::{laws::Laws, World, method::{exact, Setting}};\n\
         // use crate::auto;\n\
         let x = crate::math::unit(1.0);",
    ));
    let expected: BTreeSet<String> = ["laws", "world", "method", "math"].map(String::from).into();
    assert_eq!(found, expected);
}
