//! What a reset and the scene's title say about edits: a reset that drops
//! them says so and undo brings them back; a named scene edited is marked
//! in its title.

use super::*;
use crate::app::model::command::EditPlace;

/// The scene's name as the top bar has room to give it whole.
fn title(s: &Sandbox) -> String {
    match s.edited_mark() {
        Some(mark) => format!("{} {mark}", s.scene_name()),
        None => s.scene_name(),
    }
}

#[test]
fn a_reset_that_drops_edits_says_so_and_undo_brings_them_back() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    s.apply(Command::Reset);
    assert_eq!(s.message(), Some("Scene reset"), "nothing edited");
    later(&mut s, 1.0);
    s.apply(Command::EditDisc {
        disc: 0,
        text: [Some("3".into()), None, None, None, None, None],
        from: EditPlace::Table,
    });
    assert_eq!(s.world.particles[0].mass, 3.0);
    later(&mut s, 1.0);
    s.apply(Command::Reset);
    assert_eq!(s.world.particles[0].mass, 1.0);
    let said = s.message().unwrap_or_default().to_string();
    assert!(
        said.contains("without your edits") && said.contains("Ctrl+Z"),
        "{said}"
    );
    later(&mut s, 1.0);
    s.apply(Command::Undo);
    assert_eq!(s.world.particles[0].mass, 3.0, "undo brings the edit back");
}

/// A teacher sets 3 kg, runs the collision and presses R to show it
/// again: the discs come back as the teacher set them up, not as the
/// lesson opened (the 3 kg was lost); R again gives the lesson as it
/// opened, and says so.
#[test]
fn a_reset_brings_back_the_set_up_first_and_then_the_scene_as_it_opened() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    later(&mut s, 1.0);
    s.apply(Command::EditDisc {
        disc: 0,
        text: [Some("3".into()), None, None, None, None, None],
        from: EditPlace::Table,
    });
    let (set_up, at) = (s.world.particles.clone(), s.world.time);
    s.apply(Command::NextCollision);
    assert!(s.world.time > at && s.world.total_pair_collisions == 1);
    s.apply(Command::TogglePause);
    assert!(!s.clock.paused, "running when R is pressed");
    later(&mut s, 1.0);
    s.apply(Command::Reset);
    assert_eq!(
        (&s.world.particles, s.world.time),
        (&set_up, at),
        "the set-up"
    );
    assert_eq!(s.world.total_pair_collisions, 0);
    let said = s.message().unwrap_or_default().to_string();
    assert!(said.starts_with("Back to your set-up at t = "), "{said}");
    assert!(said.ends_with("R again: the scene as it opened"), "{said}");
    assert!(s.open.edited, "the edits are kept");
    assert!(
        s.clock.paused,
        "paused at the set-up: R again is the scene as it opened"
    );
    later(&mut s, 1.0);
    s.apply(Command::Reset);
    assert_eq!(s.world.particles[0].mass, 1.0, "the lesson as it opened");
    assert!(s
        .message()
        .unwrap_or_default()
        .contains("without your edits"));
    later(&mut s, 1.0);
    s.apply(Command::Undo);
    assert_eq!(
        s.world.particles[0].mass, 3.0,
        "undo brings the set-up back"
    );
}

#[test]
fn a_named_scene_edited_says_so_in_its_title_and_undo_takes_the_mark_away() {
    use crate::app::model::command::Law;
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    let name = s.scene_name();
    assert_eq!(title(&s), name);
    later(&mut s, 1.0);
    s.apply(Command::SetLaw(Law::Restitution, 0.5));
    assert_eq!(title(&s), format!("{name} (edited)"));
    later(&mut s, 1.0);
    s.apply(Command::Undo);
    assert_eq!(title(&s), name);
}

/// Saved, exported and screenshot files are named after the scene as the
/// window shows it, in its language: a Spanish class's files all read
/// "sandbox" or "head-on-equal-masses" before.
#[test]
fn files_are_named_after_the_scene_in_the_windows_language() {
    use crate::app::lang::{set_language, Lang};
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    set_language(Lang::Es);
    let saved = s.save_scene();
    let said = s.messages.scene.as_ref().map(|n| n.text.clone());
    let stem = s.file_stem();
    s.apply(Command::OpenEmpty);
    let empty = s.file_stem();
    let note_after_open = s.messages.scene.clone();
    set_language(Lang::En);
    let saved = saved.unwrap();
    assert_eq!(
        saved.file_name().unwrap(),
        "choque-frontal-masas-iguales.toml"
    );
    assert_eq!(stem, "choque-frontal-masas-iguales");
    let folder = crate::files::shown(saved.parent().unwrap());
    assert_eq!(
        said.unwrap(),
        format!("Se guardó choque-frontal-masas-iguales.toml en {folder}"),
        "the name first, then the folder"
    );
    assert_eq!(
        empty, "caja-vacía",
        "the empty box, and a letter with its accent"
    );
    assert!(
        note_after_open.is_none(),
        "the note on the saved file went with its scene: {note_after_open:?}"
    );
}

/// A teacher names her own scene: the name heads the window in every
/// language, the preset's caption and "(edited)" go with the old name,
/// the saved file is named after it, and undo brings the old name back.
/// (She could not: her scene stayed "Empty box (edited)" in every save.)
#[test]
fn a_scene_renamed_is_saved_under_its_new_name() {
    use crate::app::lang::{set_language, Lang};
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    s.apply(Command::EditDisc {
        disc: 0,
        text: [Some("3".into()), None, None, None, None, None],
        from: EditPlace::Fields,
    });
    assert_eq!(title(&s), "Head-on, equal masses (edited)");
    s.apply(Command::RenameScene("  Schiefer Stoß, 4 kg  ".into()));
    assert_eq!(title(&s), "Schiefer Stoß, 4 kg");
    assert_eq!(
        s.scene_description(),
        None,
        "the preset's caption went with its name"
    );
    set_language(Lang::Es);
    let in_spanish = s.scene_name();
    set_language(Lang::En);
    assert_eq!(in_spanish, "Schiefer Stoß, 4 kg");
    let saved = s.save_scene().unwrap();
    assert_eq!(saved.file_name().unwrap(), "schiefer-stoß-4-kg.toml");
    let reopened = impulse::Scene::load(&saved).unwrap();
    assert_eq!(reopened.name.as_deref(), Some("Schiefer Stoß, 4 kg"));
    s.apply(Command::RenameScene(" !? ".into()));
    assert!(s.messages.scene.as_ref().is_some_and(|n| n.error));
    assert_eq!(s.scene_name(), "Schiefer Stoß, 4 kg", "refused: kept");
    s.apply(Command::Undo);
    assert_eq!(title(&s), "Head-on, equal masses (edited)");
}

/// Saved again, the scene goes back into the file this session saved it
/// as (each Ctrl+S made a file more); renamed, it gets a file of its own;
/// a file of the same name from before this session is left as it was.
#[test]
fn saving_again_writes_back_into_the_same_file() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-4-glancing.toml");
    let out = dir.path().join("out");
    std::fs::create_dir_all(&out).unwrap();
    let earlier = out.join("glancing-collision.toml");
    std::fs::write(&earlier, "from before").unwrap();
    let first = s.save_scene().unwrap();
    assert_eq!(first.file_name().unwrap(), "glancing-collision-2.toml");
    s.apply(Command::ToggleGravity);
    let second = s.save_scene().unwrap();
    assert_eq!(second, first, "back into the same file");
    let saved = impulse::Scene::load(&second).unwrap();
    assert_eq!(saved.world.gravity, s.world.laws.gravity, "with the change");
    assert_eq!(std::fs::read_to_string(&earlier).unwrap(), "from before");
    s.apply(Command::RenameScene("Mein Stoß".into()));
    let third = s.save_scene().unwrap();
    assert_eq!(third.file_name().unwrap(), "mein-stoß.toml");
    let files = std::fs::read_dir(&out).unwrap().count();
    assert_eq!(
        files, 3,
        "the earlier file, the glancing one, the renamed one"
    );
}

/// The Save note names the file alone ("Saved schiefer-stoß.toml"); typed
/// back into the path field, with or without ".toml", the scene opens from
/// the save folder (it was "cannot read: No such file", in English). A
/// name found nowhere is said in the window's language.
#[test]
fn a_saved_scene_opens_again_by_the_name_the_save_gave() {
    use crate::app::lang::{set_language, Lang};
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    s.apply(Command::RenameScene("Aula 3".into()));
    let saved = s.save_scene().unwrap();
    let file = saved.file_name().unwrap().to_string_lossy().to_string();
    assert_eq!(file, "aula-3.toml");
    assert_eq!(
        s.message(),
        Some("Saved aula-3.toml"),
        "at t = 0, no moment said"
    );
    for typed in [file.as_str(), "aula-3", " aula-3 "] {
        s.apply(Command::OpenEmpty);
        assert_ne!(s.scene_name(), "Aula 3");
        s.apply(Command::OpenFile(typed.into()));
        assert_eq!(s.scene_name(), "Aula 3", "typed {typed:?}");
        assert!(s.messages.scene.as_ref().is_some_and(|n| !n.error));
    }
    set_language(Lang::PtBr);
    s.apply(Command::OpenFile("aula-4".into()));
    let note = s.messages.scene.clone().unwrap();
    set_language(Lang::En);
    assert!(note.error);
    assert!(
        note.text.starts_with("Não há arquivo de cena aula-4"),
        "{}",
        note.text
    );
    assert_eq!(s.scene_name(), "Aula 3", "the scene was kept");
    // Saved after the clock has run, the note says which moment the file
    // holds: one saved after the collision had reopened with none left.
    s.apply(Command::NextCollision);
    let time = crate::app::numbers::plain(s.world.time, 2);
    s.save_scene().unwrap();
    let said = s.message().unwrap().to_string();
    assert!(said.starts_with("Saved aula-3"), "{said}");
    assert!(
        said.ends_with(&format!("the discs as they are at t = {time} s")),
        "{said}"
    );
}

/// A caption that says what to do ("Drag on empty space to launch discs")
/// stays as it is after an edit; a lesson's, whose answer may no longer
/// hold, begins "Before the edits:". (Two reviews read "Before the edits:
/// Drag on empty space…" as nonsense.)
#[test]
fn only_a_lessons_caption_says_before_the_edits() {
    let dir = tempfile::tempdir().unwrap();
    let sandbox = |file: &str| match file {
        "default" => {
            let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
            let scene = Scene::parse(impulse::catalogue::DEFAULT.text, "built-in").unwrap();
            s.open_scene(scene, "built-in".into()).unwrap();
            s
        }
        _ => sandbox_in(dir.path(), file),
    };
    for (file, prefixed) in [
        ("default", false),
        ("preset-empty.toml", false),
        ("preset-1-head-on.toml", true),
    ] {
        let mut s = sandbox(file);
        let before = s.shown_caption().unwrap();
        s.apply(Command::LaunchAtCentre);
        assert!(s.open.edited, "{file}");
        let after = s.shown_caption().unwrap();
        assert_eq!(
            after.starts_with("Before the edits: "),
            prefixed,
            "{file}: {after}"
        );
        assert!(after.ends_with(&before), "{file}: {after}");
    }
}
