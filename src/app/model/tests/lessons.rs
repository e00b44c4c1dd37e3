//! A lesson from the start screen: it waits, paused, on its tile's
//! question (predict), runs when asked (observe), and gives its answer
//! once the answer has been seen (explain).

use super::*;
use crate::app::model::start::Tile;

/// Runs `s` frame by frame (1/60 s) until `done` or `seconds` have
/// passed.
fn run_until(s: &mut Sandbox, seconds: f64, done: impl Fn(&Sandbox) -> bool) {
    for _ in 0..(seconds * 60.0).round() as usize {
        if done(s) {
            return;
        }
        later(s, 1.0 / 60.0);
        s.tick(1.0 / 60.0, 1.0);
    }
}

/// `tile`'s lesson, opened from the start screen over a running gas.
fn lesson(dir: &std::path::Path, tile: Tile) -> Sandbox {
    let mut s = sandbox_with(dir, "preset-8-gas.toml", false, 0.0);
    s.place_world([0.0, 0.0, 1000.0, 700.0], 0.0);
    s.apply(Command::StartWith(tile));
    s
}

#[test]
fn a_lesson_asks_its_question_until_its_answer_has_been_seen() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = lesson(dir.path(), Tile::HeadOn);
    let answer = s.scene_description().unwrap();
    let question = Tile::HeadOn.blurb();
    assert!(s.clock.paused, "a lesson waits for the class to guess");
    assert!(s.lesson_waiting());
    assert_eq!(s.shown_caption().as_deref(), Some(question.as_str()));
    assert!(s.describe().contains(&question), "{}", s.describe());
    let said = &s.messages.narration.said;
    assert_eq!(said.back().map(|(_, l)| l), Some(&question), "{said:?}");
    assert!(!s.describe().contains(&answer), "{}", s.describe());
    // Enter (as on its tile) plays it, and adds no disc; the question stays
    // while the discs close in (the hit is at t = 2.4 s), and the answer
    // comes with the collision, said once.
    s.apply(Command::LaunchAtCentre);
    assert_eq!(s.world.particles.len(), 2);
    assert!(!s.lesson_waiting(), "running, nothing waits");
    run_until(&mut s, 2.0, |_| false);
    assert_eq!(s.world.total_pair_collisions, 0);
    assert_eq!(s.shown_caption().as_deref(), Some(question.as_str()));
    run_until(&mut s, 2.0, |s| s.world.total_pair_collisions > 0);
    s.tick(1.0 / 60.0, 1.0);
    assert_eq!(s.shown_caption().as_deref(), Some(answer.as_str()));
    let said: Vec<&str> = s
        .messages
        .narration
        .said
        .iter()
        .map(|(_, l)| l.as_str())
        .collect();
    assert_eq!(said.iter().filter(|l| **l == answer).count(), 1, "{said:?}");
    // A reset, running, replays the lesson: paused on the question again,
    // in the strip at once.
    assert!(!s.clock.paused);
    s.apply(Command::Reset);
    assert!(s.clock.paused && s.lesson_waiting());
    assert_eq!(s.message(), None, "nothing hides the question");
    assert_eq!(s.shown_caption().as_deref(), Some(question.as_str()));
    // Edited, the lesson's question no longer fits its discs.
    s.apply(Command::TogglePause);
    s.apply(Command::LaunchAtCentre);
    assert!(s.shown_caption().unwrap().starts_with("Before the edits: "));
}

#[test]
fn the_pi_blocks_answer_once_their_count_is_final() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = lesson(dir.path(), Tile::PiBlocks);
    let question = Tile::PiBlocks.blurb();
    s.apply(Command::TogglePause);
    run_until(&mut s, 30.0, |s| s.world.total_pair_collisions > 0);
    assert!(s.world.total_pair_collisions > 0);
    assert_eq!(
        s.shown_caption().as_deref(),
        Some(question.as_str()),
        "the first bump does not give the count away"
    );
    run_until(&mut s, 60.0, |s| lesson::pi_result(&s.world).is_some());
    assert_eq!(s.shown_caption(), s.scene_description());
}

#[test]
fn free_play_and_the_presets_menu_run_at_once_without_a_question() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_with(dir.path(), "preset-1-head-on.toml", true, 0.0);
    s.apply(Command::StartWith(Tile::FreePlay));
    assert!(!s.clock.paused && !s.lesson_waiting());
    assert!(s.lesson_question().is_none());
    // A lesson, then a preset from the menu: that scene is no lesson.
    s.apply(Command::StartWith(Tile::Glancing));
    assert!(s.lesson_question().is_some());
    let head_on = scenes::PRESETS
        .iter()
        .position(|p| p.path.ends_with("preset-1-head-on.toml"))
        .unwrap();
    s.apply(Command::OpenPreset(head_on));
    assert!(s.lesson_question().is_none());
    assert_eq!(s.shown_caption(), s.scene_description());
}

#[test]
fn a_momentum_lesson_pauses_at_its_first_wall_hit_and_says_why() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = lesson(dir.path(), Tile::HeadOn);
    s.apply(Command::TogglePause);
    run_until(&mut s, 10.0, |s| s.clock.paused);
    // Disc 2 leaves at 2 m/s after the hit at 2.4 s and meets the right wall.
    assert!(s.clock.paused, "still running at t = {}", s.world.time);
    assert_eq!(s.world.total_wall_hits, 1);
    let said = s.message().unwrap_or_default().to_owned();
    assert!(
        said.starts_with("Paused: disc 2 hit the right wall") && said.contains("total momentum"),
        "{said}"
    );
    // Played on, the next walls do not stop it.
    s.apply(Command::TogglePause);
    run_until(&mut s, 10.0, |s| s.world.total_wall_hits >= 2);
    assert!(!s.clock.paused && s.world.total_wall_hits >= 2);
    // A gas is all walls: its lesson runs on.
    let mut s = lesson(dir.path(), Tile::Gas);
    s.apply(Command::TogglePause);
    run_until(&mut s, 3.0, |s| s.clock.paused);
    assert!(!s.clock.paused && s.world.total_wall_hits > 0);
}
