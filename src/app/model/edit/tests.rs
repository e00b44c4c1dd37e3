//! Edits of a disc: the fields read, applied, refused and undone.
use super::*;
use crate::app::model::command::{Command, EditPlace};
use crate::app::model::tests::sandbox_in;
use glam::DVec2;
use impulse::Color as DiscColor;
use impulse::Scene;

#[test]
fn edits_parse_only_what_changed_and_refuse_bad_numbers() {
    let edit =
        parse_disc_edit([Some("2.5"), None, Some(" -1e-3 "), None, None, None], 4.0).unwrap();
    assert_eq!(
        edit,
        DiscEdit {
            mass: Some(2.5),
            radius: None,
            vx: Some(-1e-3),
            vy: None,
            x: None,
            y: None
        }
    );
    assert!(parse_disc_edit([None; 6], 4.0).unwrap().is_empty());
    let error = |fields| parse_disc_edit(fields, 4.0).unwrap_err();
    assert_eq!(
        error([Some("abc"), None, None, None, None, None]),
        "mass: “abc” is not a number"
    );
    assert_eq!(
        error([Some("0"), None, None, None, None, None]),
        "mass must be more than 0"
    );
    assert_eq!(
        error([None, Some("-1"), None, None, None, None]),
        "radius must be more than 0"
    );
    assert_eq!(
        error([None, Some("5"), None, None, None, None]),
        "radius must be at most 4 m here"
    );
    assert_eq!(
        error([None, None, Some("inf"), None, None, None]),
        "v_x must be a finite number"
    );
    assert_eq!(
        error([None, None, None, Some("1e999"), None, None]),
        "v_y must be a finite number"
    );
    assert_eq!(
        error([None, None, None, Some("NaN"), None, None]),
        "v_y must be a finite number"
    );
    assert_eq!(
        error([None, None, Some("  "), None, None, None]),
        "v_x: type a number"
    );
    assert_eq!(
        parse_disc_edit([None, Some("1,5"), None, None, None, None], 4.0)
            .unwrap()
            .radius,
        Some(1.5),
        "a decimal comma"
    );
    assert_eq!(
        error([None, Some("1,5.2"), None, None, None, None]),
        "radius: “1,5.2” is not a number"
    );
    assert_eq!(
        parse_disc_edit([None, None, Some("−2"), None, None, None], 4.0)
            .unwrap()
            .vx,
        Some(-2.0),
        "a typographic minus"
    );
}

#[test]
fn a_thousand_typed_with_the_other_separator_is_asked_about_not_taken_as_one() {
    use crate::app::lang::{set_language, Lang};
    let mass = |typed| parse_disc_edit([Some(typed), None, None, None, None, None], 4.0);
    // "1,000" was read as 1 kg in English: a thousand times lighter, said nowhere.
    assert_eq!(
        mass("1,000").unwrap_err(),
        "mass: “1,000” could be 1 or 1000; type the one you mean"
    );
    assert_eq!(mass("1,000.0").unwrap().mass, Some(1000.0));
    assert_eq!(mass("2,5").unwrap().mass, Some(2.5));
    // With the field's own unit (a student typed "3 kg": "not a number").
    assert_eq!(mass("3 kg").unwrap().mass, Some(3.0));
    assert_eq!(mass("3kg").unwrap().mass, Some(3.0));
    assert_eq!(mass("3 g").unwrap_err(), "mass: “3 g” is not a number");
    let speed = parse_disc_edit([None, None, Some("-2 m/s"), None, None, None], 4.0);
    assert_eq!(speed.unwrap().vx, Some(-2.0));
    let polar = polar_velocity(Some("2 m/s"), Some("90 °"), DVec2::X)
        .unwrap()
        .unwrap();
    assert!((polar - DVec2::new(0.0, 2.0)).length() < 1e-12, "{polar}");
    set_language(Lang::Fr);
    // A French teacher's thousand, with the space French writes in it.
    assert_eq!(mass("1 000").unwrap().mass, Some(1000.0));
    assert_eq!(mass("1 000,5").unwrap().mass, Some(1000.5));
    assert_eq!(mass("1,000").unwrap().mass, Some(1.0));
    assert_eq!(
        mass("2.500").unwrap_err(),
        "masse : « 2.500 » peut se lire 2,5 ou 2500 ; tapez celui que vous voulez dire"
    );
    set_language(Lang::En);
}

#[test]
fn an_edit_changes_only_its_quantities() {
    let mut p = Particle::new(
        DVec2::new(1.0, 2.0),
        DVec2::new(3.0, 4.0),
        1.0,
        0.5,
        DiscColor::rgb(1, 2, 3),
    );
    DiscEdit {
        radius: Some(0.25),
        vy: Some(-1.0),
        ..DiscEdit::default()
    }
    .apply(&mut p);
    assert_eq!(
        (p.mass, p.radius, p.vel),
        (1.0, 0.25, DVec2::new(3.0, -1.0))
    );
    assert_eq!(p.pos, DVec2::new(1.0, 2.0));
}

/// What the Discs table takes, a scene file takes: every edit it accepts
/// leaves a scene that saves and opens again; numbers past a scene file's
/// ranges are refused, saying the range. Each answer is in the strip too.
#[test]
fn an_edit_the_table_takes_saves_a_scene_that_opens_again() {
    let dir = tempfile::tempdir().unwrap();
    for file in ["preset-4-glancing.toml", "preset-1-head-on.toml"] {
        let mut s = sandbox_in(dir.path(), file);
        let edit = |s: &mut Sandbox, k: usize, text: &str| {
            let mut fields: [Option<String>; 6] = Default::default();
            fields[k] = Some(text.into());
            s.apply(Command::EditDisc {
                disc: 0,
                text: fields,
                from: EditPlace::Table,
            });
            let note = s.messages.table.clone().unwrap();
            // Also in the strip, where a projector's short tab has it.
            assert_eq!(s.message(), Some(note.text.as_str()));
            note
        };
        for (k, text, range) in [
            (0, "1e13", "10¹² kg"),
            (0, "1e-13", "10⁻¹² kg"),
            (1, "1e10", "10⁹ m"),
            (2, "-2e8", "10⁸ m/s"),
            (3, "1e300", "10⁸ m/s"),
        ] {
            let before = s.fingerprint();
            let note = edit(&mut s, k, text);
            assert!(
                note.error && note.text.contains(range),
                "{file} {text}: {note:?}"
            );
            assert_eq!(s.fingerprint(), before, "{file} {text}");
        }
        // Each component inside its range, the speed past it.
        edit(&mut s, 2, "9e7");
        let note = edit(&mut s, 3, "9e7");
        assert!(
            note.error && note.text.contains("10⁸ m/s"),
            "{file}: {note:?}"
        );
        for (k, text) in [(0, "1e12"), (3, "1"), (2, "-3e7"), (0, "2e-12"), (3, "0")] {
            let note = edit(&mut s, k, text);
            if file.contains("head-on") && text == "1" {
                assert!(note.error && note.text.contains("one line"), "{note:?}");
            }
            let saved = s.current_scene().to_toml();
            let reopened = Scene::parse(&saved, "saved.toml").and_then(|sc| sc.build("saved.toml"));
            assert!(
                note.error || reopened.is_ok(),
                "{file}: {text} taken ({note:?}), but the saved scene does not open: {:?}",
                reopened.err()
            );
        }
    }
}

/// The caption ("the moving disc stops dead") is voided by a change to
/// the discs or to a law they obey, not by the method; undo takes the
/// change back with the note that reported it.
#[test]
fn a_law_changed_voids_the_caption_and_undo_takes_edits_with_their_notes() {
    use crate::app::model::command::Law;
    use crate::app::model::tests::later;
    use impulse::method::{Method, Setting};
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    s.apply(Command::SetMethod(Setting::Fixed(Method::Verlet)));
    assert!(!s.open.edited, "the method keeps the caption");
    later(&mut s, 1.0);
    s.apply(Command::SetLaw(Law::Restitution, 0.5));
    assert!(
        s.open.edited,
        "at e = 0.5 the moving disc does not stop dead"
    );
    later(&mut s, 1.0);
    s.apply(Command::Undo);
    assert!(!s.open.edited && s.world.laws.restitution == 1.0);
    later(&mut s, 1.0);
    s.apply(Command::ToggleGravity);
    assert!(s.open.edited, "under gravity the momentum does not stay");
    later(&mut s, 1.0);
    s.apply(Command::Undo);
    for from in [EditPlace::Table, EditPlace::Fields] {
        later(&mut s, 1.0);
        s.apply(Command::EditDisc {
            disc: 0,
            text: [Some("2.5".into()), None, None, None, None, None],
            from,
        });
        assert!(s.messages.table.is_some() || s.messages.fields.is_some());
        // The strip says it, over what it said of the disc before.
        assert!(
            s.message().is_some_and(|m| m.contains("mass = 2.5 kg")),
            "{from:?}: {:?}",
            s.message()
        );
        later(&mut s, 1.0);
        s.apply(Command::Undo);
        assert_eq!(s.world.particles[0].mass, 1.0);
        assert_eq!(
            (&s.messages.table, &s.messages.fields),
            (&None, &None),
            "{from:?}: the note went with the edit"
        );
    }
}

/// "What if e = 0.3?" tried after J and undone: the plot and the rewind
/// keep the way to the impact (an undo cleared both).
#[test]
fn an_edit_undone_keeps_the_plot_and_the_rewind_of_the_run_so_far() {
    use crate::app::model::command::Law;
    use crate::app::model::tests::later;
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    s.apply(Command::NextCollision);
    let hit = s.world.time;
    let (samples, snapshots) = (s.record.totals.samples().count(), s.record.history.len());
    assert!(samples > 100 && snapshots > 100, "{samples} {snapshots}");
    later(&mut s, 1.0);
    s.apply(Command::SetLaw(Law::Restitution, 0.3));
    later(&mut s, 1.0);
    s.apply(Command::Undo);
    assert_eq!(s.world.laws.restitution, 1.0);
    assert_eq!(s.world.time, hit);
    assert!(s.record.totals.samples().count() >= samples - 1);
    assert!(s.record.history.len() >= snapshots - 1);
    s.apply(Command::Scrub(-1));
    assert!(
        s.world.time < hit && s.world.time > hit - 0.1,
        "one step back from {hit} is {}",
        s.world.time
    );
    // Across a reset or another scene, the past starts afresh: what was
    // recorded since belongs to another run.
    for change in [Command::Reset, Command::OpenPreset(0)] {
        later(&mut s, 1.0);
        s.apply(change);
        for _ in 0..30 {
            later(&mut s, 1.0 / 60.0);
            s.apply(Command::Step);
            s.tick(1.0 / 60.0, 1.0);
        }
        later(&mut s, 1.0);
        s.apply(Command::Undo);
        assert!(s.record.history.len() <= 1, "{}", s.record.history.len());
    }
}

/// A preset opened over changed work (a digit key pressed when a click
/// meant for a field missed it) says the undo that brings it back, and
/// that undo does; over a scene only opened, it just says what opened
/// (to a screen reader only: a lesson's caption takes the strip).
#[test]
fn another_scene_opened_over_changes_says_how_to_get_them_back() {
    use crate::app::model::command::Law;
    let dir = tempfile::tempdir().unwrap();
    let preset = |file: &str| {
        let k = crate::app::model::scenes::PRESETS
            .iter()
            .position(|p| p.path.ends_with(file));
        Command::OpenPreset(k.unwrap())
    };
    let (head_on, heavy) = (preset("1-head-on.toml"), preset("2-heavy-hits-light.toml"));
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    s.apply(heavy.clone());
    // A lesson: its caption in the strip at once, its name said.
    assert_eq!(s.message(), None);
    let said = s
        .messages
        .narration
        .said
        .back()
        .map(|(_, line)| line.as_str());
    assert_eq!(said, Some("Opened Heavy hits light"));
    s.apply(head_on);
    s.apply(Command::SetLaw(Law::Restitution, 0.3));
    s.session.now += 2.0;
    s.apply(heavy);
    assert_eq!(
        s.message(),
        Some("Opened Heavy hits light. Ctrl+Z brings back Head-on, equal masses as you left it")
    );
    s.apply(Command::Undo);
    assert_eq!(s.world.laws.restitution, 0.3);
    assert!(s.open.origin.contains("head-on"), "{}", s.open.origin);
}

/// A speed and a direction typed give the velocity they describe, the
/// untyped one kept from the disc's; what is not a number, or a negative
/// speed, is refused with the field's name.
#[test]
fn a_speed_and_a_direction_typed_give_their_velocity() {
    use super::polar_velocity;
    use glam::DVec2;
    let near = |a: DVec2, b: DVec2| (a - b).length() < 1e-12;
    let now = DVec2::new(3.0, 4.0); // 5 m/s at 53.13°
    assert_eq!(polar_velocity(None, None, now), Ok(None));
    let v = polar_velocity(Some("3"), Some("30"), now).unwrap().unwrap();
    assert!(near(v, DVec2::new(3.0 * 3f64.sqrt() / 2.0, 1.5)), "{v}");
    let v = polar_velocity(Some("10"), None, now).unwrap().unwrap();
    assert!(near(v, DVec2::new(6.0, 8.0)), "the direction kept: {v}");
    let v = polar_velocity(None, Some("-90"), now).unwrap().unwrap();
    assert!(near(v, DVec2::new(0.0, -5.0)), "the speed kept: {v}");
    let v = polar_velocity(Some("2,5"), Some("180"), now)
        .unwrap()
        .unwrap();
    assert!(near(v, DVec2::new(-2.5, 0.0)), "a decimal comma: {v}");
    let refused = |speed, direction| polar_velocity(speed, direction, now).unwrap_err();
    assert!(refused(Some("fast"), None).contains("fast"));
    assert!(refused(None, Some("")).contains("direction"));
    assert_eq!(
        refused(Some("-1"), None),
        crate::app::lang::tr!("edit-speed-negative")
    );
}

/// A speed and a direction typed are said back as typed ("speed = 2.5
/// m/s; direction = 30°"), not as the components they were sent as (v_x =
/// 2.165064 m/s, six decimals the student never typed).
#[test]
fn a_polar_edit_is_said_as_a_speed_and_a_direction() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-4-glancing.toml");
    let v = polar_velocity(Some("2.5"), Some("30"), DVec2::X)
        .unwrap()
        .unwrap();
    let v = (v * 1e12).round() / 1e12; // as the fields send it
    s.apply(Command::EditDisc {
        disc: 0,
        text: [
            None,
            None,
            Some(v.x.to_string()),
            Some(v.y.to_string()),
            None,
            None,
        ],
        from: EditPlace::Polar,
    });
    assert_eq!(s.world.particles[0].vel, v);
    let said = s.message().unwrap_or_default().to_string();
    assert!(
        said.contains("speed |v| = 2.5 m/s") && said.contains("direction = 30°"),
        "{said}"
    );
    assert!(!said.contains("v_x"), "{said}");
}

mod placed;
