//! The window's code keeps the shape ARCHITECTURE.md gives it, read from
//! the source: `src/app`'s modules import only from layers below their own
//! (the model at the bottom with no window in it, the views above it), no
//! file there is over 500 lines and no struct has more than 15 fields.

use std::path::{Path, PathBuf};

/// `src/app`'s modules, lowest layer first (`mod` is `src/app/mod.rs`).
const LAYERS: &[&[&str]] = &[
    &["lang"],
    &["numbers", "layout", "display", "frame_stats"],
    &["model"],
    &["look"],
    &["drawing", "idle", "audio"],
    &["ui"],
    &["input", "page"],
    &["dump", "screenshot", "options"],
    &["mod"],
];

fn layer_of(module: &str) -> usize {
    LAYERS
        .iter()
        .position(|layer| layer.contains(&module))
        .unwrap_or_else(|| {
            panic!("src/app/{module} is in no layer: add it to LAYERS and ARCHITECTURE.md")
        })
}

fn app() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src/app")
}

/// Every `.rs` file under `dir`.
fn files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            out.extend(files(&path));
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
    out.sort();
    out
}

/// The top-level module of `src/app` a file belongs to, and how deep it is
/// below `src/app` (`model/mod.rs`: 1 as `model/`, `model/tick.rs`: 1).
fn module_of(file: &Path) -> (String, usize) {
    let rel = file.strip_prefix(app()).unwrap();
    let parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_string_lossy().trim_end_matches(".rs").to_string())
        .collect();
    let depth = parts.len() - usize::from(parts.last().is_some_and(|p| p == "mod"));
    (parts[0].clone(), depth)
}

/// The code without comments and unit tests.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    text.lines()
        .map(|line| line.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The top-level `src/app` modules a file of depth `depth` names: through
/// `crate::app::` or through as many `super::` as lead up to `src/app`.
fn imports(code: &str, depth: usize) -> Vec<String> {
    let mut found = Vec::new();
    let up = "super::".repeat(depth);
    for prefix in ["crate::app::".to_string(), up] {
        if prefix.is_empty() {
            continue;
        }
        for piece in code.split(prefix.as_str()).skip(1) {
            let name: String = piece
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            if name.chars().next().is_some_and(|c| c.is_ascii_lowercase()) && name != "super" {
                found.push(name);
            }
        }
    }
    found
}

#[test]
fn modules_import_only_from_below() {
    let mut climbs = Vec::new();
    for file in files(&app()) {
        let (module, depth) = module_of(&file);
        let text = std::fs::read_to_string(&file).unwrap();
        for target in imports(&code(&text), depth) {
            if target != module && layer_of(&target) > layer_of(&module) {
                climbs.push(format!("{} uses {target}", file.display()));
            }
        }
    }
    assert!(
        climbs.is_empty(),
        "imports that climb up:\n{}",
        climbs.join("\n")
    );
}

#[test]
fn the_model_has_no_window_in_it() {
    for file in files(&app().join("model")) {
        let text = code(&std::fs::read_to_string(&file).unwrap());
        for window in ["macroquad", "egui"] {
            assert!(!text.contains(window), "{} names {window}", file.display());
        }
    }
}

#[test]
fn no_file_is_over_500_lines_and_no_struct_has_more_than_15_fields() {
    for file in files(&app()) {
        let text = std::fs::read_to_string(&file).unwrap();
        let lines = text.lines().count();
        assert!(lines <= 500, "{}: {lines} lines", file.display());
        let mut open: Option<(String, usize, i32)> = None;
        for line in text.lines() {
            let t = line.trim();
            if open.is_none() {
                let words: Vec<&str> = t.split_whitespace().collect();
                let at = words.iter().position(|w| *w == "struct");
                if let Some(k) = at.filter(|_| t.ends_with('{')) {
                    open = Some((words.get(k + 1).unwrap_or(&"?").to_string(), 0, 0));
                }
                continue;
            }
            let (name, fields, depth) = open.as_mut().unwrap();
            if *depth == 0
                && !t.starts_with("//")
                && !t.starts_with('#')
                && t.contains(": ")
                && t.ends_with(',')
            {
                *fields += 1;
            }
            *depth += t.matches(['{', '(', '[']).count() as i32
                - t.matches(['}', ')', ']']).count() as i32;
            if *depth < 0 {
                assert!(
                    *fields <= 15,
                    "{}: struct {name} has {fields} fields",
                    file.display()
                );
                open = None;
            }
        }
    }
}
