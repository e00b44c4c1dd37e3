//! A disc the person picks (a click, Q, a row of the Discs table) is
//! counted, so the side dock opens its section; a disc selected for them
//! is not.

use super::*;

#[test]
fn a_pick_is_counted_and_a_selection_made_for_the_person_is_not() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    let picks = |s: &Sandbox| s.panels.picks;
    let at = s.view.camera.world_to_screen(s.world.particles[0].pos);
    s.apply(Command::PointerDown(at));
    s.apply(Command::PointerUp(at));
    assert_eq!((s.selected, picks(&s)), (Some(0), 1), "a click on a disc");
    s.apply(Command::SelectNext(1));
    assert_eq!((s.selected, picks(&s)), (Some(1), 2), "Q");
    s.apply(Command::Select(Some(0)));
    assert_eq!((s.selected, picks(&s)), (Some(0), 3), "a row of the table");
    s.apply(Command::Select(None));
    s.apply(Command::Select(Some(99)));
    let empty = s.view.camera.world_to_screen(glam::DVec2::new(0.3, 0.3));
    s.apply(Command::PointerDown(empty));
    s.apply(Command::PointerUp(empty));
    assert_eq!((s.selected, picks(&s)), (None, 3), "nothing picked");
    // The spin preset selects its disc, to show its values: not a pick.
    let spin = scenes::PRESETS
        .iter()
        .position(|p| p.path == impulse::catalogue::PRESET_SPIN_OFF_A_WALL.path)
        .unwrap();
    s.apply(Command::OpenPreset(spin));
    assert_eq!(
        (s.selected, picks(&s)),
        (Some(0), 3),
        "a preset's selection"
    );
}
