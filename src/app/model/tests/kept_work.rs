//! Work kept for recovery: only the person's unsaved work, written at a
//! quit too; the question a start asks about it, and its answers.

use super::*;

#[test]
fn a_waiting_question_pauses_the_simulation_and_only_its_answers_go_through() {
    let dir = tempfile::tempdir().unwrap();
    let kept = scenes::PRESETS[0].text;
    std::fs::write(dir.path().join(recovery::FILE_NAME), kept).unwrap();
    let mut s = sandbox_with(dir.path(), "preset-8-gas.toml", false, 5.0);
    assert!(
        s.modal_open() && s.clock.paused,
        "paused behind the question"
    );
    let t = s.world.time;
    s.tick(1.0 / 60.0, 1.0);
    s.apply(Command::TogglePause);
    s.apply(Command::OpenPreset(2));
    s.tick(1.0 / 60.0, 1.0);
    assert_eq!(s.world.time, t, "nothing ran and nothing opened");
    assert!(s.clock.paused);
    // R answers it: the kept sandbox opens, paused as it was left (it ran
    // on at once, before anyone had seen it was back).
    s.apply(Command::Reset);
    assert!(!s.modal_open() && s.clock.paused);
    assert_eq!(s.world.particles.len(), 2, "preset 1's two discs");
}

#[test]
fn only_unsaved_work_is_kept_for_recovery() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_with(dir.path(), "preset-8-gas.toml", false, 0.5);
    let file = dir.path().join(recovery::FILE_NAME);
    let run = |s: &mut Sandbox, seconds: f64| {
        for _ in 0..(seconds * 60.0) as usize {
            later(s, 1.0 / 60.0);
            s.tick(1.0 / 60.0, 1.0);
        }
    };
    run(&mut s, 2.0);
    assert!(
        !file.exists(),
        "a running preset is nothing of the person's to keep"
    );
    s.apply(Command::ToggleGravity);
    run(&mut s, 1.0);
    assert!(file.exists(), "a change of theirs is kept");
    s.apply(Command::Save);
    run(&mut s, 1.0);
    assert!(!file.exists(), "saved: nothing left to recover");
    // A quit with nothing unsaved leaves nothing; with a change not saved
    // (within the autosave's interval) it writes the change, for the next
    // start to offer: a Ctrl+Q lost it.
    s.on_close();
    assert!(!file.exists(), "nothing unsaved: nothing kept");
    s.apply(Command::ToggleGravity);
    s.on_close();
    let kept = Scene::load(&file).expect("the change is kept at the close");
    assert_eq!(kept.world.gravity, s.world.laws.gravity);
    let mut next = sandbox_with(dir.path(), "preset-8-gas.toml", false, 0.5);
    assert!(next.recovery.offered.is_some(), "the next start offers it");
    // Restored, it waits, paused, and says it is back (it ran on at once).
    next.apply(Command::RestoreRecovery);
    assert!(next.clock.paused);
    let said = next.message().unwrap_or_default();
    assert!(said.starts_with("Restored Gas in a box"), "{said}");
}
