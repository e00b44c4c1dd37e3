//! The dock's tabs chosen by click and by menu, and the Totals record
//! started afresh by the person's edits.

use super::*;

/// A second click on the tab in sight folds the dock; choosing that tab
/// from the tab menu (the row's narrow form) or pressing its key shows it
/// and never folds it: both had, and the Collisions chosen from the menu
/// vanished, as did the Totals of a teacher pressing T to show them.
#[test]
fn a_tab_chosen_from_the_menu_or_by_its_key_is_shown_and_a_second_click_folds_it() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-4-glancing.toml");
    s.apply(Command::ClickTab(DockTab::Collisions));
    assert!(s.panels.dock_expanded && s.panels.tab == DockTab::Collisions);
    s.apply(Command::ShowTab(DockTab::Collisions));
    assert!(s.panels.dock_expanded && s.panels.tab == DockTab::Collisions);
    s.apply(Command::ClickTab(DockTab::Collisions));
    assert!(!s.panels.dock_expanded, "a second click folds the dock");
    s.apply(Command::ShowTab(DockTab::Collisions));
    assert!(s.panels.dock_expanded, "the menu unfolds it");
    s.apply(Command::ShowTab(DockTab::Collisions));
    assert!(s.panels.dock_expanded, "its key again keeps it");
    s.apply(Command::ToggleDocks);
    s.apply(Command::ShowTab(DockTab::Speeds));
    assert!(s.panels.docks_open && s.panels.dock_expanded && s.panels.tab == DockTab::Speeds);
}

/// The Totals tab's change is the physics', not the person's: a disc
/// launched by a drag or a moving one deleted starts the record afresh (a
/// review read "Δp (6.000, 1.500) kg·m/s" after a launch, with nothing to
/// say a disc had come); a law changed or a disc launched at rest, which
/// move no total, keep it.
#[test]
fn an_edit_that_moves_a_total_starts_the_totals_afresh_and_a_law_does_not() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-4-glancing.toml");
    s.apply(Command::TogglePause);
    let run = |s: &mut Sandbox, frames: usize| {
        for _ in 0..frames {
            later(s, 1.0 / 60.0);
            s.tick(1.0 / 60.0, 1.0);
        }
    };
    run(&mut s, 30);
    let began = |s: &Sandbox| s.record.totals.first().map(|f| f.time);
    let first = began(&s).expect("a record");
    s.apply(Command::SetLaw(Law::Restitution, 0.5));
    run(&mut s, 5);
    assert_eq!(began(&s), Some(first), "a law keeps the record");
    type Edit = fn(&mut Sandbox);
    let cases: [(&str, Edit); 3] = [
        ("a drag launch", |s| {
            let from = s.view.camera.world_to_screen(glam::DVec2::new(1.0, 1.0));
            s.apply(Command::PointerDown(from));
            later(s, 0.05);
            s.apply(Command::PointerMove(from + glam::DVec2::new(40.0, -30.0)));
            s.apply(Command::PointerUp(from + glam::DVec2::new(80.0, -60.0)));
        }),
        ("a launch at the centre", |s| {
            s.apply(Command::LaunchAtCentre)
        }),
        ("a deletion", |s| {
            s.apply(Command::Select(Some(0)));
            s.apply(Command::DeleteSelected);
        }),
    ];
    for (what, edit) in cases {
        let count = s.world.particles.len();
        let before = s.world.time;
        edit(&mut s);
        assert_ne!(s.world.particles.len(), count, "{what}");
        run(&mut s, 5);
        // A disc launched at rest moves no total: its record may go on.
        let now = began(&s).expect("a record");
        assert!(
            now >= before || what == "a launch at the centre",
            "{what}: the record began at {now}, before the edit at {before}"
        );
        let drift = s.record.totals.drift().expect("a drift");
        assert!(drift.0 < 1e-9 && drift.1.abs() < 1e-9, "{what}: {drift:?}");
    }
    // Aimed with the arrows (paused): a new velocity starts the record
    // afresh; an aim that rounds to the same velocity changes nothing and
    // keeps it.
    s.apply(Command::TogglePause);
    s.apply(Command::Select(Some(0)));
    run(&mut s, 5);
    let kept = began(&s);
    s.apply(Command::AimSelected(glam::DVec2::new(0.0, 0.01)));
    assert_eq!(
        began(&s),
        kept,
        "an aim that moved nothing keeps the record"
    );
    s.world.time += 1.0; // as if the class had watched a while, paused
    s.apply(Command::AimSelected(glam::DVec2::new(0.0, 0.1)));
    assert_eq!(
        began(&s),
        Some(s.world.time),
        "an aim starts the record afresh"
    );
}

/// A scene opened running counts its change from t = 0, the instant it
/// opened, not from the end of its first frame ("since t = 0.02 s").
#[test]
fn a_scene_opened_running_counts_its_totals_from_its_start() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-4-glancing.toml");
    if s.clock.paused {
        s.apply(Command::TogglePause);
    }
    s.apply(Command::OpenPreset(1));
    assert!(!s.clock.paused);
    for _ in 0..3 {
        later(&mut s, 1.0 / 60.0);
        s.tick(1.0 / 60.0, 1.0);
    }
    assert!(s.world.time > 0.04, "{}", s.world.time);
    assert_eq!(s.record.totals.first().map(|f| f.time), Some(0.0));
}
