//! The model without a window: commands applied in sequence, and the state
//! they leave.

use super::command::{Dir, EditPlace, Law};
use super::*;
use impulse::Scene;

/// A sandbox on the preset whose file is `file`, its recovery folder
/// `dir` with autosave every `autosave` seconds (0: off).
pub(crate) fn sandbox_with(
    dir: &std::path::Path,
    file: &str,
    paused: bool,
    autosave: f64,
) -> Sandbox {
    let preset = scenes::PRESETS
        .iter()
        .find(|p| p.path.ends_with(file))
        .unwrap_or_else(|| panic!("no preset {file}"));
    let scene = Scene::parse(preset.text, preset.path).unwrap();
    let world = scene.build(preset.path).unwrap();
    Sandbox::new(Start {
        scene,
        origin: preset.path.to_string(),
        world,
        paused,
        dt: None,
        out: dir.join("out"),
        recovery: (dir.to_path_buf(), autosave),
        scale: None,
        theme: None,
        start_screen: false,
        from_link: false,
        lang: Some(crate::app::lang::Lang::En),
        system_lang: None,
    })
}

/// A paused sandbox on `file`'s preset in a 1000 × 700 px world, autosave
/// off.
pub(super) fn sandbox_in(dir: &std::path::Path, file: &str) -> Sandbox {
    let mut s = sandbox_with(dir, file, true, 0.0);
    s.place_world([0.0, 0.0, 1000.0, 700.0], 0.0);
    s.fit_camera();
    s
}

fn levels(s: &Sandbox) -> usize {
    s.undo.levels().0
}

/// Advances the window's clock by `seconds` (undo merges changes of one
/// kind closer together than 0.75 s).
pub(super) fn later(s: &mut Sandbox, seconds: f64) {
    let now = s.session.now + seconds;
    s.begin_frame(now);
}

#[test]
fn a_click_on_a_disc_selects_it_and_is_not_an_edit() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    let before = s.fingerprint();
    let at = s.view.camera.world_to_screen(s.world.particles[0].pos);
    s.apply(Command::PointerDown(at));
    later(&mut s, 0.1);
    s.apply(Command::PointerUp(at));
    assert_eq!(s.selected, Some(0));
    assert_eq!(levels(&s), 0, "no undo level for a click");
    assert!(!s.open.edited, "the caption still holds");
    assert_eq!(s.fingerprint(), before, "the disc is exactly as it was");
    // A click on empty space deselects, and changes nothing either.
    let empty = s.view.camera.world_to_screen(glam::DVec2::new(0.3, 0.3));
    s.apply(Command::PointerDown(empty));
    s.apply(Command::PointerUp(empty));
    assert_eq!(s.selected, None);
    assert_eq!((levels(&s), s.open.edited), (0, false));
}

#[test]
fn a_drag_launches_a_disc_that_undo_takes_back() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-empty.toml");
    assert!(s.world.particles.is_empty());
    let from = s.view.camera.world_to_screen(glam::DVec2::new(2.0, 2.0));
    s.apply(Command::PointerDown(from));
    later(&mut s, 0.05);
    s.apply(Command::PointerMove(from + glam::DVec2::new(40.0, -30.0)));
    s.apply(Command::PointerUp(from + glam::DVec2::new(80.0, -60.0)));
    assert_eq!(s.world.particles.len(), 1);
    assert!(s.world.particles[0].vel.x > 0.0 && s.world.particles[0].vel.y > 0.0);
    assert_eq!((levels(&s), s.open.edited), (1, true));
    later(&mut s, 1.0);
    s.apply(Command::Undo);
    assert!(s.world.particles.is_empty() && !s.open.edited);
    s.apply(Command::Redo);
    assert_eq!(s.world.particles.len(), 1);
}

#[test]
fn commands_that_change_the_scene_can_be_undone_and_the_others_leave_no_level() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-8-gas.toml");
    let quiet = [
        Command::TogglePause,
        Command::TogglePause,
        Command::Faster,
        Command::Slower,
        Command::ToggleVelocity,
        Command::ToggleMomentum,
        Command::CycleReadouts,
        Command::ToggleCenterOfMass,
        Command::ToggleTrails,
        Command::TogglePalette,
        Command::ZoomIn,
        Command::ZoomOut,
        Command::Fit,
        Command::ShowTab(DockTab::Discs),
        Command::ToggleDocks,
        Command::ToggleDocks,
        Command::ToggleHelp,
        Command::Escape,
        Command::SetScale(1.5),
        Command::SetTabHeight(Some(250.0)),
        Command::SetTheme(Theme::Light),
        Command::Select(Some(3)),
        Command::SetNewMass(2.0),
        Command::SizeFollowsMass(true),
        Command::SizeFollowsMass(false),
        // Setting a law to the value it has changes nothing.
        Command::SetLaw(Law::Restitution, s.world.laws.restitution),
        Command::SetMethod(s.world.method),
    ];
    for c in quiet {
        later(&mut s, 1.0);
        s.apply(c.clone());
        assert_eq!(levels(&s), 0, "{c:?} left an undo level");
    }
    let original = s.fingerprint();
    // Each of these changes the scene: one level each, and undo puts back
    // exactly what was there.
    let changes = [
        Command::NudgeLaw(Law::Restitution, Dir::Down),
        Command::SetLaw(Law::WallRestitution, 0.5),
        Command::SetLaw(Law::Roughness, 0.3),
        Command::SetFriction(Some(0.4)),
        Command::ToggleGravity,
        Command::SetBoundary(impulse::Boundary::Box),
        Command::CycleMethod,
        Command::CycleBroadPhase,
        Command::CycleSubsteps,
        Command::EditDisc {
            disc: 2,
            text: [
                Some("3".into()),
                None,
                Some("-1.5".into()),
                None,
                None,
                None,
            ],
            from: EditPlace::Table,
        },
        Command::Select(Some(4)),
        Command::DeleteSelected,
        Command::Clear,
        Command::OpenPreset(0),
    ];
    let mut expected = 0;
    let mut prints = vec![s.fingerprint()];
    for c in changes {
        later(&mut s, 1.0);
        let before = s.fingerprint();
        s.apply(c.clone());
        if s.fingerprint() != before {
            expected += 1;
            prints.push(s.fingerprint());
        }
        assert_eq!(levels(&s), expected, "{c:?}");
    }
    assert!(
        expected >= 12,
        "the commands above change the scene: {expected}"
    );
    for k in (0..expected).rev() {
        later(&mut s, 1.0);
        s.apply(Command::Undo);
        assert_eq!(s.fingerprint(), prints[k], "undo {k}");
    }
    assert_eq!(s.fingerprint(), original);
    for (k, print) in prints.iter().enumerate().skip(1) {
        s.apply(Command::Redo);
        assert_eq!(s.fingerprint(), *print, "redo {k}");
    }
}

#[test]
fn a_bad_edit_is_refused_where_it_was_typed_and_changes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    let before = s.fingerprint();
    s.apply(Command::EditDisc {
        disc: 0,
        text: [Some("-2".into()), None, None, None, None, None],
        from: EditPlace::Table,
    });
    assert_eq!(s.fingerprint(), before);
    assert_eq!(levels(&s), 0);
    let note = s.messages.table.clone().unwrap();
    assert!(note.error && note.text.contains("more than 0"), "{note:?}");
    assert!(s.messages.fields.is_none(), "said where it was typed");
    s.apply(Command::EditDisc {
        disc: 0,
        text: [Some("2.5".into()), None, None, None, None, None],
        from: EditPlace::Fields,
    });
    assert_eq!(s.world.particles[0].mass, 2.5);
    assert!(s.open.edited && levels(&s) == 1);
    assert!(!s.messages.fields.clone().unwrap().error);
}

#[test]
fn the_bindings_name_every_command_a_key_gives_and_the_tooltips_follow() {
    use super::bindings::{command_for, tooltip, Key, Trigger};
    for (key, cmd) in [
        (Key::Letter('J'), Command::NextCollision),
        (Key::Letter('T'), Command::ShowTab(DockTab::Totals)),
        (Key::F(2), Command::NextScale),
    ] {
        assert_eq!(
            command_for(key, false, false, Trigger::Press),
            Some(cmd.clone())
        );
        assert!(!tooltip(&cmd).is_empty());
    }
}

/// Opens `file` of the presets in an existing sandbox.
fn open(s: &mut Sandbox, file: &str) {
    let k = scenes::PRESETS
        .iter()
        .position(|p| p.path.ends_with(file))
        .unwrap();
    s.apply(Command::OpenPreset(k));
}

#[test]
fn next_collision_stops_at_a_wall_and_every_count_agrees() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-empty.toml");
    // Two discs launched towards each other, off-centre, in the empty box.
    for (from, to) in [((2.0, 2.0), (3.0, 2.4)), ((8.0, 3.0), (7.0, 2.8))] {
        let a = s.view.camera.world_to_screen(glam::DVec2::from(from));
        let b = s.view.camera.world_to_screen(glam::DVec2::from(to));
        s.apply(Command::PointerDown(a));
        later(&mut s, 0.05);
        s.apply(Command::PointerUp(b));
    }
    assert_eq!(s.world.particles.len(), 2);
    s.apply(Command::TogglePause);
    for _ in 0..600 {
        later(&mut s, 1.0 / 60.0);
        s.tick(1.0 / 60.0, 1.0);
    }
    let w = &s.world;
    assert!(
        w.total_pair_collisions + w.total_wall_hits > 2,
        "they met and bounced"
    );
    // One count, defined once: what the top bar says is what the ledger
    // recorded.
    assert_eq!(w.ledger.recorded, w.total_pair_collisions);
    assert_eq!(w.ledger.recorded_walls, w.total_wall_hits);
    let line = lesson::count_line(w);
    assert!(line.contains(&format!("{} between discs", w.total_pair_collisions)));
    assert!(line.contains(&format!("{} with walls", w.total_wall_hits)));
    // J stops at the next impact, wall or disc, at its instant.
    let walls = w.total_wall_hits;
    let pairs = w.total_pair_collisions;
    s.apply(Command::NextCollision);
    let w = &s.world;
    assert_eq!(
        w.total_wall_hits + w.total_pair_collisions,
        walls + pairs + 1
    );
    let newest = w.ledger.last_impact().unwrap();
    assert!(
        (newest.time() - w.time).abs() < 1e-9
            || w.method != impulse::method::Setting::Fixed(impulse::method::Method::Exact)
    );
    assert!(s.clock.paused && s.panels.tab == DockTab::Collisions);
}

#[test]
fn the_spin_preset_stops_at_its_bounce_in_every_method() {
    use impulse::method::{Method, Setting};
    let dir = tempfile::tempdir().unwrap();
    for method in [
        Setting::Auto,
        Setting::Fixed(Method::Impulse),
        Setting::Fixed(Method::Exact),
    ] {
        let mut s = sandbox_in(dir.path(), "preset-empty.toml");
        open(&mut s, "preset-spin-off-a-wall.toml");
        s.apply(Command::SetMethod(method));
        s.apply(Command::NextCollision);
        let impact = s.world.ledger.last_impact().copied();
        let Some(impulse::ledger::Impact::Wall(hit)) = impact else {
            panic!("{method}: no wall hit: {impact:?}, {:?}", s.message());
        };
        assert!(s.world.time < 10.0, "{method}: at {}", s.world.time);
        // Off the wall: the velocity into it reversed.
        let ((n0, _), (n1, _)) = hit.components();
        assert!(n0 < 0.0 && n1 > 0.0, "{method}: {n0} → {n1}");
        assert!(s.message().is_some_and(|m| m.contains("wall")), "{method}");
    }
}

#[test]
fn next_collision_with_verlet_stops_at_a_collision_it_cannot_record_and_says_so() {
    use impulse::method::{Method, Setting};
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    s.apply(Command::SetMethod(Setting::Fixed(Method::Verlet)));
    s.apply(Command::NextCollision);
    assert_eq!(s.world.total_pair_collisions, 1, "stopped at the collision");
    let message = s.message().unwrap_or("");
    assert!(
        message.contains("verlet") && !message.contains("No collision"),
        "{message}"
    );
}

/// Seeded random commands, as keys, buttons and the mouse send them, with
/// frames of random length between: every disc stays finite and inside the
/// walls its box has (a side without a wall lets discs out, as the π blocks
/// leave), and an undo followed by a redo gives back the very state.
#[test]
fn random_commands_keep_every_disc_finite_and_inside_its_walls() {
    use ::rand::{Rng, SeedableRng};
    let dir = tempfile::tempdir().unwrap();
    for seed in 0..40u64 {
        let mut rng = ::rand::rngs::StdRng::seed_from_u64(seed);
        let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
        let mut now = 0.0;
        let mut log: Vec<Command> = Vec::new();
        for step in 0..600 {
            let p = glam::DVec2::new(
                rng.random_range(-50.0..1050.0),
                rng.random_range(-50.0..750.0),
            );
            let d = if rng.random_bool(0.5) {
                Dir::Up
            } else {
                Dir::Down
            };
            let c = match rng.random_range(0..34) {
                0 => Command::TogglePause,
                1 => Command::Step,
                2 => Command::Slower,
                3 => Command::Faster,
                4 => Command::NextCollision,
                5 => Command::Scrub([-10, -1, 1, 10][rng.random_range(0..4)]),
                6 => Command::OpenPreset(rng.random_range(0..10)),
                7 => Command::OpenEmpty,
                8 => Command::Reset,
                9 => Command::Clear,
                10 => Command::Undo,
                11 => Command::Redo,
                12 => Command::NudgeLaw(Law::Restitution, d),
                13 => Command::NudgeLaw(Law::WallRestitution, d),
                14 => Command::ToggleGravity,
                15 => Command::CycleMethod,
                16 => Command::CycleBroadPhase,
                17 => Command::CycleSubsteps,
                18 => Command::StepNewRadius(d),
                19 => Command::StepNewMass(d),
                20 => Command::SelectNext(1),
                21 => Command::AimSelected(glam::DVec2::new(
                    rng.random_range(-3.0..3.0),
                    rng.random_range(-3.0..3.0),
                )),
                22 => Command::LaunchAtCentre,
                23 => Command::DeleteSelected,
                24 | 25 => Command::PointerDown(p),
                26 | 27 => Command::PointerMove(p),
                28 | 29 => Command::PointerUp(p),
                30 => Command::ZoomAt {
                    at: p,
                    factor: if rng.random_bool(0.5) { 2.0 } else { 0.5 },
                },
                31 => Command::Fit,
                32 => Command::ToggleCenterOfMassView,
                _ => Command::Escape,
            };
            log.push(c.clone());
            s.apply(c);
            // Undo then redo, between gestures, gives back the very state.
            let idle = matches!(s.pointer.gesture, super::gesture::Gesture::Idle);
            if rng.random_bool(0.1) && idle && levels(&s) > 0 {
                let before = s.fingerprint();
                s.apply(Command::Undo);
                s.apply(Command::Redo);
                log.extend([Command::Undo, Command::Redo]);
                assert_eq!(
                    s.fingerprint(),
                    before,
                    "seed {seed}, command {step}: undo and redo changed the scene; the last \
                     commands {:?}",
                    &log[log.len().saturating_sub(10)..]
                );
            }
            let dt = [0.0, 0.001, 0.016, 0.05][rng.random_range(0..4)];
            now += dt;
            s.begin_frame(now);
            s.tick(dt, 0.05);
            let laws = s.world.laws;
            let (size, walls) = (laws.size, laws.walls);
            for (i, q) in s.world.particles.iter().enumerate() {
                // A radius of −10⁻⁶ m: the centre, with room for rounding.
                let inside = laws.boundary != impulse::Boundary::Box
                    || laws.boundary.admits(walls, size, q.pos, -1e-6);
                assert!(
                    q.pos.is_finite() && q.vel.is_finite() && inside,
                    "seed {seed}, command {step}: disc {i} at {:?} moving {:?}, box {size:?} \
                     with {walls:?}; the last commands {:?}",
                    q.pos,
                    q.vel,
                    &log[log.len().saturating_sub(8)..]
                );
            }
        }
    }
}

mod help_covers;
mod kept_work;
mod lessons;
mod next_collision;
mod numbering;
mod picks;
mod reset_and_title;
mod tabs_and_totals;
