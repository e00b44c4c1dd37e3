//! The help and the start screen cover the world: nothing changes behind
//! them, but a screenshot can be taken of them.

use super::*;

/// Keys pressed while the help is open (to scroll it: Home, Enter, the
/// arrows) made a disc, changed the new discs' mass and panned the view
/// out of sight; Esc closes it, and then they act again.
#[test]
fn while_the_help_is_open_nothing_changes_behind_it() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    s.apply(Command::ToggleHelp);
    assert!(s.panels.help_open);
    let before = |s: &Sandbox| {
        (
            s.world.particles.len(),
            s.new_discs.disc.mass,
            s.view.camera.center,
            s.scene_name(),
            s.clock.paused,
        )
    };
    let (discs, ..) = before(&s);
    for c in [
        Command::LaunchAtCentre,
        Command::StepNewMass(Dir::Up),
        Command::Pan(DVec2::new(40.0, 0.0)),
        Command::OpenPreset(3),
        Command::TogglePause,
    ] {
        let was = before(&s);
        s.apply(c.clone());
        assert_eq!(before(&s), was, "{c:?} changed the world behind the help");
        assert!(s.panels.help_open);
    }
    s.apply(Command::Screenshot);
    assert!(
        s.session.requests.screenshot.is_some(),
        "F12 takes the key list, for a handout"
    );
    s.apply(Command::SetScale(2.0));
    assert_eq!(s.panels.scale, 2.0, "the window's own settings go through");
    s.apply(Command::Escape);
    assert!(!s.panels.help_open, "Esc closes it");
    s.apply(Command::LaunchAtCentre);
    assert_eq!(s.world.particles.len(), discs + 1, "and the keys act again");
}

/// F12 on the start screen saves it (it saved nothing: the tiles wait for
/// a choice, and let only a few keys through).
#[test]
fn the_start_screen_can_be_saved_as_a_picture() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    s.apply(Command::ShowStart);
    assert!(s.panels.start_open);
    s.apply(Command::Screenshot);
    assert!(s.session.requests.screenshot.is_some());
}
