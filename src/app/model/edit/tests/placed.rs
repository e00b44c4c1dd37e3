//! Edits that place a disc (a position typed, a radius grown) and what an
//! edit takes away (the Δp arrows of a collision before it).
use super::*;

/// A disc placed by its typed position (the keyboard's way to place
/// one): moved where it has room, refused with the reason where it would
/// overlap another or cross a wall, and undone in one step.
#[test]
fn a_typed_position_moves_the_disc_where_it_has_room() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-4-glancing.toml");
    let place = |s: &mut Sandbox, x: &str, y: &str| {
        s.apply(Command::EditDisc {
            disc: 0,
            text: [None, None, None, None, Some(x.into()), Some(y.into())],
            from: EditPlace::Fields,
        });
        s.messages.fields.clone().unwrap()
    };
    let (start, other) = (s.world.particles[0].pos, s.world.particles[1]);
    let r = s.world.particles[0].radius;
    let note = place(&mut s, "3", "2,5");
    assert!(!note.error, "{}", note.text);
    assert_eq!(s.world.particles[0].pos, DVec2::new(3.0, 2.5));
    let on_top = format!("{}", other.pos.x + 0.5 * r);
    let note = place(&mut s, &on_top, &format!("{}", other.pos.y));
    assert!(
        note.error && note.text.ends_with("overlap disc 2"),
        "{}",
        note.text
    );
    let note = place(&mut s, "0", "2,5");
    assert!(
        note.error && note.text.ends_with("cross a wall"),
        "{}",
        note.text
    );
    assert_eq!(
        s.world.particles[0].pos,
        DVec2::new(3.0, 2.5),
        "refused: unmoved"
    );
    s.apply(Command::Undo);
    assert_eq!(s.world.particles[0].pos, start, "undo puts it back");
    // On a one-dimensional world's line a disc moves only along it.
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    let start = s.world.particles[0].pos;
    let note = place(
        &mut s,
        &format!("{}", start.x),
        &format!("{}", start.y + 1.0),
    );
    assert!(note.error && note.text.contains("y stays"), "{}", note.text);
    let note = place(
        &mut s,
        &format!("{}", start.x - 1.0),
        &format!("{}", start.y),
    );
    assert!(!note.error, "{}", note.text);
    assert_eq!(s.world.particles[0].pos, start - DVec2::X);
}

/// A disc grown where it stands is placed as a moved one is: into its
/// neighbour or through a wall, refused, saying which (a radius of 2 m put
/// disc 2 inside disc 1, and the next step shoved them apart); made
/// smaller, always taken.
#[test]
fn a_larger_radius_into_a_neighbour_or_a_wall_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-4-glancing.toml");
    let radius = |s: &mut Sandbox, r: &str, from: EditPlace| {
        s.apply(Command::EditDisc {
            disc: 0,
            text: [None, Some(r.into()), None, None, None, None],
            from,
        });
        match from {
            EditPlace::Fields | EditPlace::Polar => s.messages.fields.clone().unwrap(),
            EditPlace::Table => s.messages.table.clone().unwrap(),
        }
    };
    // Disc 1 just left of disc 2, far from the walls.
    let b = s.world.particles[1];
    let r = s.world.particles[0].radius;
    let x = b.pos.x - b.radius - r - 0.2;
    s.apply(Command::EditDisc {
        disc: 0,
        text: [
            None,
            None,
            None,
            None,
            Some(x.to_string()),
            Some(b.pos.y.to_string()),
        ],
        from: EditPlace::Table,
    });
    let a = s.world.particles[0];
    assert_eq!(a.pos.x, x);
    let gap = a.pos.distance(b.pos) - b.radius;
    let wall = [a.pos.x, a.pos.y, s.world.laws.size.y - a.pos.y]
        .into_iter()
        .fold(f64::INFINITY, f64::min);
    assert!(gap + 0.1 < wall, "{gap} {wall}");
    let note = radius(&mut s, &format!("{}", gap + 0.1), EditPlace::Table);
    assert!(
        note.error && note.text.contains("would overlap disc 2"),
        "{}",
        note.text
    );
    assert_eq!(s.world.particles[0].radius, a.radius, "refused: unchanged");
    let fits = format!("{}", 0.5 * gap.min(wall));
    let note = radius(&mut s, &fits, EditPlace::Table);
    assert!(!note.error, "{}", note.text);
    let note = radius(&mut s, "0.1", EditPlace::Table);
    assert!(!note.error, "smaller: {}", note.text);
    assert_eq!(s.world.particles[0].radius, 0.1);
    // By the left wall, grown through it.
    s.apply(Command::EditDisc {
        disc: 0,
        text: [None, None, None, None, Some("0.2".into()), None],
        from: EditPlace::Table,
    });
    assert_eq!(s.world.particles[0].pos.x, 0.2);
    let note = radius(&mut s, "0.3", EditPlace::Fields);
    assert!(
        note.error && note.text.ends_with("cross a wall"),
        "{}",
        note.text
    );
    assert_eq!(s.world.particles[0].radius, 0.1);
}

/// A collision's Δp arrows say what it did to the discs: once the person
/// changes one (its velocity typed into the table), they describe discs no
/// longer there, and go; an undo brings them back with the discs.
#[test]
fn an_edit_takes_away_the_arrows_of_the_collision_before_it() {
    use crate::app::model::overlays::momentum_changes;
    use crate::app::model::tests::later;
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    let arrows = |s: &Sandbox| momentum_changes(&s.world, s.record.totals.edited_at());
    assert!(arrows(&s).is_empty(), "no collision yet");
    s.apply(Command::NextCollision);
    let shown = arrows(&s);
    assert_eq!(shown.len(), 2, "{shown:?}");
    let sum = shown[0].change + shown[1].change;
    assert!(
        sum.length() < 1e-9 * shown[0].change.length(),
        "equal and opposite: {shown:?}"
    );
    // The value it has typed again changes nothing, and keeps them.
    let stopped = crate::app::numbers::field(s.world.particles[0].vel.x);
    s.apply(Command::EditDisc {
        disc: 0,
        text: [None, None, Some(stopped), None, None, None],
        from: EditPlace::Table,
    });
    assert_eq!(arrows(&s), shown);
    later(&mut s, 1.0);
    s.apply(Command::EditDisc {
        disc: 0,
        text: [None, None, Some("−1".into()), None, None, None],
        from: EditPlace::Table,
    });
    assert_eq!(s.world.particles[0].vel.x, -1.0);
    assert_eq!(arrows(&s), vec![], "the arrows of discs no longer there");
    later(&mut s, 1.0);
    s.apply(Command::Undo);
    assert_eq!(arrows(&s), shown, "back with the discs they describe");
}
