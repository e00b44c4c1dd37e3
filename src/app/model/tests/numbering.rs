//! Discs are counted from 1 wherever a person reads their number.

use super::*;

/// The first disc is disc 1 in what the keys say, in J's message and in
/// the last disc's "of": a review read "Disc 0" and "Disc 1 of 2" for the
/// last of two, counted from 0 as the world's list counts.
#[test]
fn the_messages_count_discs_from_one() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    let n = s.world.particles.len();
    assert_eq!(n, 2);
    let said = |s: &mut Sandbox| {
        let mut lines = s.take_announcements();
        lines.extend(s.message().map(str::to_owned));
        lines.join(" | ")
    };
    s.apply(Command::SelectNext(1));
    assert_eq!(s.selected, Some(0));
    let first = said(&mut s);
    assert!(first.contains("Disc 1 of 2 selected"), "{first}");
    s.apply(Command::SelectNext(1));
    let last = said(&mut s);
    assert!(last.contains("Disc 2 of 2 selected"), "{last}");
    s.apply(Command::NextCollision);
    let hit = said(&mut s);
    assert!(hit.contains("Discs 1 and 2,"), "{hit}");
    assert!(!hit.contains("disc 0") && !hit.contains("Disc 0"), "{hit}");
}
