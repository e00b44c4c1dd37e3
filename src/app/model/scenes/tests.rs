//! The presets' files, names and descriptions; saved files' names.
use super::*;

#[test]
fn every_preset_has_its_name_and_description_in_every_language() {
    for p in &PRESETS {
        let scene = Scene::parse(p.text, p.path).unwrap();
        for lang in &crate::app::lang::Lang::SHIPPED[1..] {
            let words = scene.translations.get(lang.code());
            let (name, description) = words
                .map(|w| (w.name.as_deref(), w.description.as_deref()))
                .unwrap_or_default();
            assert!(
                name.is_some_and(|n| n != scene.name.as_deref().unwrap_or_default())
                    && description.is_some(),
                "{}: no {} name or description",
                p.path,
                lang.code()
            );
        }
    }
}

#[test]
fn slugs_are_file_names() {
    assert_eq!(slug("Head-on, equal masses"), "head-on-equal-masses");
    assert_eq!(slug("  Blocks that count π!  "), "blocks-that-count-π");
    assert_eq!(
        slug("Choc frontal, masses égales"),
        "choc-frontal-masses-égales"
    );
    assert_eq!(slug("Zentraler Stoß"), "zentraler-stoß");
    assert_eq!(slug("???"), "scene");
}

#[test]
fn free_path_skips_existing_files() {
    let dir = std::env::temp_dir().join(format!("impulse-free-path-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let first = free_file(&dir, "gas", "toml");
    assert_eq!(first, dir.join("gas.toml"));
    std::fs::write(&first, "x").unwrap();
    assert_eq!(free_file(&dir, "gas", "toml"), dir.join("gas-2.toml"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn every_preset_parses_and_builds() {
    for p in &PRESETS {
        let scene = Scene::parse(p.text, p.path).unwrap_or_else(|e| panic!("{e}"));
        scene.build(p.path).unwrap_or_else(|e| panic!("{e}"));
        assert!(
            scene.name.is_some() && scene.description.is_some(),
            "{}",
            p.path
        );
    }
}
