//! What the screen says, tried as a teacher tries it, under Xvfb: one count
//! in the top bar, the ledger and the dump, `J` stopping at a wall impact;
//! a click that only selects; the start screen a plain start opens on, its
//! lessons showing only the controls they need; and the simulation waiting
//! behind it.

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use serde_json::Value;

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "two_discs_in_the_empty_box_count_the_same_everywhere_and_j_stops_at_walls",
            two_discs_in_the_empty_box_count_the_same_everywhere_and_j_stops_at_walls,
        ),
        (
            "j_in_the_spin_preset_stops_at_its_bounce",
            j_in_the_spin_preset_stops_at_its_bounce,
        ),
        (
            "a_click_on_a_disc_selects_it_and_is_not_an_edit",
            a_click_on_a_disc_selects_it_and_is_not_an_edit,
        ),
        (
            "a_plain_start_opens_on_the_tiles_and_a_lesson_shows_only_its_controls",
            a_plain_start_opens_on_the_tiles_and_a_lesson_shows_only_its_controls,
        ),
    ])
}

/// The counts the dump gives: (pairs, walls) counted, (pairs, walls) in the
/// ledger, and the top bar's line.
fn counts(s: &Value) -> ((u64, u64), (u64, u64), String) {
    let n = |k: &str| s[k].as_u64().unwrap();
    (
        (n("pair_collisions"), n("wall_hits")),
        (n("collisions_recorded"), n("wall_hits_recorded")),
        s["count_line"].as_str().unwrap().to_string(),
    )
}

fn two_discs_in_the_empty_box_count_the_same_everywhere_and_j_stops_at_walls() {
    let x = Xvfb::start("counts");
    let app = Sandbox::start(&x, &[&asset("preset-empty.toml")]);
    app.drag([300.0, 400.0], [420.0, 330.0]);
    app.wait_frames(3);
    app.drag([700.0, 300.0], [560.0, 380.0]);
    let s = app.wait_frames(3);
    assert_eq!(s["particles"].as_array().unwrap().len(), 2);
    // Let them bounce about, then compare the counts.
    app.wait_for("impacts with walls and between discs", 1800, |s| {
        s["wall_hits"].as_u64() >= Some(3)
    });
    // Paused, so that no impact slips in between reading the counts and J.
    app.xdo(&["key", "space"]);
    let s = app.wait_for("a pause", 60, |s| s["paused"] == true);
    let s = app.wait_for("the same counts twice", 60, |a| counts(a) == counts(&s));
    let (counted, recorded, line) = counts(&s);
    assert_eq!(
        counted, recorded,
        "the ledger records what the top bar counts"
    );
    assert!(
        line.contains(&format!("{} between discs", counted.0))
            && line.contains(&format!("{} with walls", counted.1)),
        "{line}"
    );
    // J stops at the next impact, whichever it is, and the counts move by one.
    app.xdo(&["key", "j"]);
    let after = app.wait_for("J", 120, |a| {
        a["paused"] == true && a["ui"]["tab"] == "Collisions"
    });
    let (counted_after, recorded_after, _) = counts(&after);
    assert_eq!(
        counted_after.0 + counted_after.1,
        counted.0 + counted.1 + 1,
        "one impact further: {counted:?} → {counted_after:?}"
    );
    assert_eq!(counted_after, recorded_after);
    // J again until a wall is met: it stops there too.
    let mut s = after;
    for _ in 0..6 {
        if counts(&s).0 .1 > counted.1 {
            break;
        }
        app.xdo(&["key", "j"]);
        s = app.wait_frames(3);
    }
    assert!(
        counts(&s).0 .1 > counted.1,
        "J stopped at a wall impact: {:?}",
        counts(&s)
    );
    let message = s["ui"]["message"].as_str().unwrap_or("");
    assert!(
        message.contains("wall") || message.contains("discs"),
        "{message}"
    );
    app.quit();
}

fn j_in_the_spin_preset_stops_at_its_bounce() {
    let x = Xvfb::start("spin bounce");
    let app = Sandbox::start(&x, &["--paused", &asset("preset-spin-off-a-wall.toml")]);
    app.move_to([300.0, 300.0]);
    app.xdo(&["key", "j"]);
    let s = app.wait_for("J", 300, |s| s["ui"]["tab"] == "Collisions");
    let time = s["time"].as_f64().unwrap();
    assert!(
        time < 60.0 && s["wall_hits"] == 1,
        "stopped at the bounce: t = {time}, {}",
        s["count_line"]
    );
    let message = s["ui"]["message"].as_str().unwrap();
    assert!(message.contains("wall"), "{message}");
    app.quit();
}

fn a_click_on_a_disc_selects_it_and_is_not_an_edit() {
    let x = Xvfb::start("click");
    let app = Sandbox::start(&x, &["--paused", &asset("preset-1-head-on.toml")]);
    let s = app.wait_frames(3);
    let levels = s["ui"]["undo_levels"].clone();
    let disc = View::of(&s).to_screen(vec2(&s["particles"][0]["pos"]));
    app.click(disc);
    let s = app.wait_frames(3);
    assert_eq!(s["selected"], 0, "selected");
    assert_eq!(s["ui"]["scene_edited"], false, "the caption still holds");
    assert_eq!(s["ui"]["undo_levels"], levels, "no undo level for a click");
    app.quit();
}

fn a_plain_start_opens_on_the_tiles_and_a_lesson_shows_only_its_controls() {
    let x = Xvfb::start("start screen");
    let app = Sandbox::start_plain(&x, &["--size", "1280x800"]);
    app.move_to([640.0, 100.0]);
    let s = app.wait_for("the tiles", 60, |s| {
        s["panel_widgets"]["tile_head_on"].is_array()
    });
    assert_eq!(s["ui"]["start_open"], true);
    assert_eq!(s["paused"], true, "nothing runs behind the start screen");
    let t = s["time"].clone();
    let s = app.wait_frames(10);
    assert_eq!(s["time"], t);
    app.click(widget(&s, "tile_glancing", 0.5));
    let s = app.wait_for("the lesson", 60, |s| s["ui"]["start_open"] == false);
    assert!(
        s["scene_origin"].as_str().unwrap().contains("glancing"),
        "{}",
        s["scene_origin"]
    );
    assert_eq!(s["ui"]["tab"], "Momenta", "the tab that shows it");
    // It waits on its question for the class to guess, a Play button at
    // the strip's end beside it; played, it runs, and the button goes (the
    // answer has the strip's width).
    let s = app.wait_for("the lesson's Play button", 60, |s| {
        s["panel_widgets"]["lesson_play"].is_array()
    });
    assert_eq!(s["paused"], true, "a lesson waits to be played");
    let (play, caption) = (
        rect(&s["panel_widgets"]["lesson_play"]),
        rect(&s["panel_widgets"]["caption"]),
    );
    assert!(
        caption[0] + caption[2] <= play[0] && play[0] + play[2] <= 1280.0,
        "the caption {caption:?}, the button {play:?}"
    );
    let strip_middle = caption[1] + caption[3] / 2.0;
    assert!(play[1] <= strip_middle && strip_middle <= play[1] + play[3]);
    app.click(widget(&s, "lesson_play", 0.5));
    app.wait_for("the lesson running", 60, |s| {
        s["paused"] == false && s["panel_widgets"]["lesson_play"].is_null()
    });
    let s = app.wait_frames(3);
    let widgets = &s["panel_widgets"];
    assert!(widgets["section_collisions"].is_array() && widgets["section_show"].is_array());
    assert!(
        widgets["section_more"].is_null() && widgets["section_scene"].is_null(),
        "only what the lesson needs: {:?}",
        widgets
            .as_object()
            .unwrap()
            .keys()
            .filter(|k| k.starts_with("section"))
            .collect::<Vec<_>>()
    );
    // All controls brings the rest back; Start the tiles.
    app.click(widget(&s, "all_controls", 0.5));
    let s = app.wait_frames(3);
    assert!(s["panel_widgets"]["section_more"].is_array());
    app.click(widget(&s, "start", 0.5));
    let s = app.wait_frames(3);
    assert_eq!(s["ui"]["start_open"], true);
    app.xdo(&["key", "Escape"]);
    let s = app.wait_frames(3);
    assert_eq!(
        s["ui"]["start_open"], false,
        "Esc keeps the scene that is open"
    );
    app.quit();
}
