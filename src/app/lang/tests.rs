//! The Fluent files hold together: every English message exists in every
//! language with the same values put in, every message the code asks for
//! exists, and the languages and numbers behave.

use super::*;
use std::collections::{BTreeMap, BTreeSet};

/// Each message (and `message.attribute`) of `folder`, with the variables
/// its text uses, read from the files' text.
fn messages(folder: &str) -> BTreeMap<String, BTreeSet<String>> {
    let mut out: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (_, name, text) in FILES.iter().filter(|(f, _, _)| *f == folder) {
        let mut current: Option<String> = None;
        let mut message = String::new();
        for line in text.lines() {
            if line.starts_with('#') || line.trim().is_empty() {
                continue;
            }
            // A message starts at the line's start with its id; a line
            // that closes a select (`} wall …`) continues the one before.
            let starts_message =
                line.starts_with(|c: char| c.is_ascii_alphabetic()) && line.contains('=');
            let trimmed = line.trim_start();
            let starts_attribute =
                line.starts_with(' ') && trimmed.starts_with('.') && trimmed.contains('=');
            if starts_message {
                message = line.split('=').next().unwrap().trim().to_string();
                assert!(
                    !out.contains_key(&message),
                    "{folder}/{name}: {message} twice"
                );
                current = Some(message.clone());
            } else if starts_attribute {
                let attribute = trimmed[1..].split('=').next().unwrap().trim();
                current = Some(format!("{message}.{attribute}"));
            }
            let id = current
                .clone()
                .unwrap_or_else(|| panic!("{folder}/{name}: {line}"));
            let entry = out.entry(id).or_default();
            for piece in line.split('$').skip(1) {
                let var: String = piece
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == '-')
                    .collect();
                entry.insert(var);
            }
        }
    }
    out
}

#[test]
fn every_language_has_every_english_message_with_the_same_values() {
    let english = messages("en");
    assert!(english.len() > 100, "{} English messages", english.len());
    let mut missing = Vec::new();
    for lang in &Lang::SHIPPED[1..] {
        let theirs = messages(lang.code());
        for (id, vars) in &english {
            match theirs.get(id) {
                None => missing.push(format!("{}: {id} missing", lang.code())),
                Some(v) if v != vars => missing.push(format!(
                    "{}: {id} uses {v:?}, English {vars:?}",
                    lang.code()
                )),
                _ => {}
            }
        }
        for id in theirs.keys().filter(|id| !english.contains_key(*id)) {
            missing.push(format!("{}: {id} is not an English message", lang.code()));
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
}

#[test]
fn every_file_parses_in_every_language() {
    for lang in Lang::SHIPPED.into_iter().chain([Lang::Qps]) {
        let words = Words::new(lang);
        assert!(words.has("this-language"), "{lang:?}");
    }
}

/// Every `tr!("id"…)` in the window's code, and the ids it builds from
/// literal prefixes.
fn ids_in_code() -> BTreeSet<String> {
    fn walk(dir: &std::path::Path, out: &mut Vec<String>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs")
                && !path.ends_with("lang/tests.rs")
            {
                out.push(std::fs::read_to_string(path).unwrap());
            }
        }
    }
    let mut sources = Vec::new();
    walk(
        &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/app"),
        &mut sources,
    );
    let mut ids = BTreeSet::new();
    for source in sources {
        // `tr!("id"`, not `include_str!("file"`.
        for (at, _) in source.match_indices("tr!(\"") {
            if source[..at].ends_with(|c: char| c.is_alphanumeric() || c == '_') {
                continue;
            }
            let rest = &source[at + 5..];
            ids.insert(rest.split('"').next().unwrap().to_string());
        }
        // Undo's names for changes, put into messages later.
        for piece in source.split("\"edit-").skip(1) {
            ids.insert(format!("edit-{}", piece.split('"').next().unwrap()));
        }
    }
    ids
}

#[test]
fn every_message_the_code_asks_for_exists_in_english() {
    let english = messages("en");
    let missing: Vec<String> = ids_in_code()
        .into_iter()
        .filter(|id| !english.contains_key(id))
        .collect();
    assert!(missing.is_empty(), "not in assets/lang/en: {missing:?}");
}

#[test]
fn a_missing_message_falls_back_to_english_and_a_count_picks_the_plural() {
    let words = Words::new(Lang::De);
    assert_eq!(words.get("this-language", &[]), "Deutsch");
    let english = Words::new(Lang::En);
    assert_eq!(
        english.get("discs-count", &[("count", Arg::Count(1))]),
        "1 disc"
    );
    assert_eq!(
        english.get("discs-count", &[("count", Arg::Count(3))]),
        "3 discs"
    );
    // Unknown everywhere: the id, so the gap shows (and the test above
    // keeps it from happening).
    assert_eq!(words.get("no-such-message", &[]), "no-such-message");
}

#[test]
fn the_pseudo_language_accents_lengthens_and_brackets() {
    let words = Words::new(Lang::Qps);
    let out = words.get("discs-count", &[("count", Arg::Count(3))]);
    assert!(out.starts_with('[') && out.ends_with(']'), "{out}");
    assert!(out.contains('3'), "placeables stay as they are: {out}");
    assert!(!out.chars().any(|c| c.is_ascii_alphabetic()), "{out}");
}

#[test]
fn locales_name_languages() {
    assert_eq!(Lang::from_tag("es_ES.UTF-8"), Some(Lang::Es));
    assert_eq!(Lang::from_tag("de-AT"), Some(Lang::De));
    assert_eq!(Lang::from_tag("pt_PT"), Some(Lang::PtBr));
    assert_eq!(Lang::from_tag("pt-BR"), Some(Lang::PtBr));
    assert_eq!(Lang::from_tag("fr-CA"), Some(Lang::Fr));
    assert_eq!(Lang::from_tag("en_GB.UTF-8"), Some(Lang::En));
    assert_eq!(Lang::from_tag("qps"), Some(Lang::Qps));
    assert_eq!(Lang::from_tag("C"), None);
    assert_eq!(Lang::from_tag("ja_JP"), None);
    for lang in Lang::SHIPPED {
        assert_eq!(Lang::from_tag(lang.code()), Some(lang));
    }
}

#[test]
fn the_language_is_the_threads() {
    set_language(Lang::Fr);
    assert!(decimal_comma());
    std::thread::spawn(|| assert_eq!(language(), Lang::En))
        .join()
        .unwrap();
    set_language(Lang::En);
    assert!(!decimal_comma());
}

/// The string literals of a Rust source, with their line, outside comments
/// and unit tests (raw strings are not used for words here).
fn literals(source: &str) -> Vec<(usize, String, String)> {
    let code = source.split("#[cfg(test)]").next().unwrap_or("");
    let lines: Vec<&str> = code.lines().collect();
    let mut out = Vec::new();
    for (n, line) in lines.iter().enumerate() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("//") || trimmed.starts_with("#[") {
            continue;
        }
        // The call a literal is in may start a line or two above.
        let context = lines[n.saturating_sub(2)..=n].join("\n");
        let mut chars = line.char_indices().peekable();
        let mut current: Option<String> = None;
        while let Some((_, c)) = chars.next() {
            match (&mut current, c) {
                (None, '/') if chars.peek().is_some_and(|(_, d)| *d == '/') => break,
                (None, '\'') => {
                    // A char literal ('"') or a lifetime: skip a quoted char.
                    let rest: String = chars.clone().take(3).map(|(_, c)| c).collect();
                    if rest.starts_with("\"'") || rest.starts_with("\\\"") {
                        chars.next();
                        chars.next();
                    }
                }
                (None, '"') => current = Some(String::new()),
                (Some(text), '\\') => {
                    if let Some((_, e)) = chars.next() {
                        text.push(e);
                    }
                }
                (Some(text), '"') => {
                    out.push((n + 1, std::mem::take(text), context.clone()));
                    current = None;
                }
                (Some(text), c) => text.push(c),
                _ => {}
            }
        }
    }
    out
}

/// Whether a literal reads as words a person would read: a word of three
/// letters or more with a space, or a capitalised word.
fn reads_as_words(text: &str) -> bool {
    // What `format!` puts in ({name}, {:.2}) is not a word.
    let mut bare = String::new();
    let mut depth = 0;
    for c in text.chars() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            c if depth == 0 => bare.push(c),
            _ => {}
        }
    }
    let text = bare.as_str();
    if text.starts_with("--") {
        return false; // a command-line flag
    }
    let words: Vec<&str> = text
        .split(|c: char| !c.is_alphabetic())
        .filter(|w| w.chars().count() >= 3)
        .collect();
    let capitalised = words.iter().any(|w| {
        let mut c = w.chars();
        c.next().is_some_and(char::is_uppercase) && c.all(char::is_lowercase)
    });
    !words.is_empty() && (text.contains(' ') || capitalised)
}

/// Where a literal is not for a person to read in the window: the terminal
/// (which stays English), names in the state dump and egui's ids (and its
/// reasons to run a pass again, for debugging), shader
/// and thread names, command-line flags, file names.
const NOT_WORDS: &[&str] = &[
    "eprintln!(",
    "println!(",
    "panic!(",
    "expect(",
    "unreachable!(",
    "anyhow::bail!(",
    "bail!(",
    "debug_assert",
    "assert!(",
    "Id::new(",
    "id_salt(",
    "request_discard(",
    "UniformDesc::new(",
    "VertexAttribute::",
    "#[arg(",
    ".name(\"idle",
    "HEADLESS_HINT",
    // A line can say why its literal is not words.
    "// not words:",
];

/// Files whose literals are for the terminal, the dump or the lab, not the
/// window: the state dump, the frame-time CSV, the display check (the
/// command line's messages), the idle waker's threads, and this module.
const NOT_THE_WINDOW: &[&str] = &[
    "dump.rs",
    "frame_stats.rs",
    "display.rs",
    "idle.rs",
    "lang/mod.rs",
    "lang/pseudo.rs",
    "lang/tests.rs",
];

/// Literals that are symbols, units and names, the same in every language
/// (a font's name is egui's key for it, never shown).
const SYMBOLS: &[&str] = &[
    "Impulse",
    "Impulse - {name}",
    "Maxwell–Boltzmann",
    "DejaVu Sans",
];

#[test]
fn no_words_are_left_in_the_windows_code() {
    fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/app");
    let mut files = Vec::new();
    walk(&root, &mut files);
    let mut found = Vec::new();
    for file in files {
        let name = file
            .strip_prefix(&root)
            .unwrap()
            .to_string_lossy()
            .to_string();
        // Tests, in a tests.rs or a tests/ folder of their module.
        let test = name.ends_with("tests.rs") || name.contains("/tests/");
        if NOT_THE_WINDOW.iter().any(|f| name == *f) || test {
            continue;
        }
        let source = std::fs::read_to_string(&file).unwrap();
        for (line, text, code) in literals(&source) {
            if !reads_as_words(&text)
                || SYMBOLS.contains(&text.as_str())
                || NOT_WORDS.iter().any(|c| code.contains(c))
            {
                continue;
            }
            found.push(format!("src/app/{name}:{line}: {text:?}"));
        }
    }
    assert!(
        found.is_empty(),
        "words outside assets/lang (put them in a .ftl file, or say here why they are not words):\n{}",
        found.join("\n")
    );
}

#[test]
fn the_scan_finds_words_and_lets_ids_and_units_be() {
    let found = literals("ui.label(\"Hide\"); cx.note(\"dock_toggle\", &r); let u = \"kg·m/s\";\nx(\"two words\") // \"a comment\"");
    let words: Vec<&str> = found
        .iter()
        .filter(|(_, t, _)| reads_as_words(t))
        .map(|(_, t, _)| t.as_str())
        .collect();
    assert_eq!(words, ["Hide", "two words"]);
    assert!(!reads_as_words("{name} ({})"));
    assert!(!reads_as_words("--gas {count}"));
}

#[test]
fn every_letter_of_every_language_is_in_the_windows_font() {
    use ab_glyph::Font;
    let definitions = crate::app::look::font_definitions();
    let family = &definitions.families[&egui::FontFamily::Proportional];
    let fonts: Vec<ab_glyph::FontRef> = family
        .iter()
        .map(|name| {
            let data = &definitions.font_data[name];
            ab_glyph::FontRef::try_from_slice(&data.font).unwrap()
        })
        .collect();
    let drawn = |c: char| fonts.iter().any(|f| f.glyph_id(c).0 != 0);
    assert!(
        drawn('ß') && drawn('ç') && !drawn('漢'),
        "the check tells drawn from not"
    );
    // The range an edit is refused outside says "10⁻¹² kg" (a box before
    // the ¹²: egui's own fonts have no superscript minus).
    assert!(drawn('⁻'), "the superscript minus");
    // The top bar's short mark of an edited scene.
    assert!(drawn('✎'), "the pencil");
    let mut missing = BTreeSet::new();
    for (folder, name, text) in FILES {
        for line in text.lines().filter(|l| !l.starts_with('#')) {
            for c in line.chars().filter(|c| !c.is_whitespace() && !drawn(*c)) {
                missing.insert(format!("{c:?} in {folder}/{name}"));
            }
        }
    }
    // The pseudo-language's letters too.
    for c in ('a'..='z').chain('A'..='Z') {
        let accented: String = pseudo::accent(&c.to_string()).into_owned();
        for a in accented.chars().filter(|a| !drawn(*a)) {
            missing.insert(format!("{a:?} (qps for {c})"));
        }
    }
    assert!(missing.is_empty(), "drawn as a box: {missing:?}");
}

#[test]
fn languages_are_named_in_themselves() {
    assert_eq!(native_name(Lang::De), "Deutsch");
    assert_eq!(
        native_name(Lang::PtBr),
        Words::new(Lang::PtBr).get("this-language", &[])
    );
    assert!(native_name(Lang::Qps).starts_with('['));
}
