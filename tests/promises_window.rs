//! What the screen says is what happens, in the real window under Xvfb:
//! undo brings a cleared scene back bit for bit, the centre-of-mass view
//! changes no velocity, a rewind and replay keeps the ledger and the
//! counters in step, a field left with Enter keeps the keyboard from the
//! shortcuts, a method that cannot keep e = 1 says so, and the π blocks end
//! on their count.

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use serde_json::Value;

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "clear_then_ctrl_z_restores_every_disc_bit_for_bit_and_never_the_com_view",
            clear_then_ctrl_z_restores_every_disc_bit_for_bit_and_never_the_com_view,
        ),
        (
            "the_centre_of_mass_view_on_and_off_leaves_every_velocity_bit_for_bit",
            the_centre_of_mass_view_on_and_off_leaves_every_velocity_bit_for_bit,
        ),
        (
            "a_rewind_and_replay_keeps_the_ledger_and_the_counters_equal",
            a_rewind_and_replay_keeps_the_ledger_and_the_counters_equal,
        ),
        (
            "after_enter_in_a_field_only_the_clock_keys_act_until_esc",
            after_enter_in_a_field_only_the_clock_keys_act_until_esc,
        ),
        (
            "switching_to_verlet_is_said_in_the_top_bar_and_switching_away_clears_it",
            switching_to_verlet_is_said_in_the_top_bar_and_switching_away_clears_it,
        ),
        (
            "the_pi_blocks_end_on_their_count",
            the_pi_blocks_end_on_their_count,
        ),
        (
            "a_one_dimensional_preset_keeps_every_y_velocity_zero_through_a_collision",
            a_one_dimensional_preset_keeps_every_y_velocity_zero_through_a_collision,
        ),
        (
            "with_size_following_mass_an_edit_resizes_the_disc_or_is_refused_if_it_would_overlap",
            with_size_following_mass_an_edit_resizes_the_disc_or_is_refused_if_it_would_overlap,
        ),
    ])
}

fn key(app: &Sandbox, k: &str) -> Value {
    app.xdo(&["key", k]);
    app.wait_frames(3)
}

fn clear_then_ctrl_z_restores_every_disc_bit_for_bit_and_never_the_com_view() {
    let x = Xvfb::start("undo");
    let app = Sandbox::start(&x, &["--paused", &asset("preset-9-billiards.toml")]);
    app.move_to([300.0, 300.0]);
    let before = app.wait_frames(2);
    assert!(before["particles"].as_array().unwrap().len() > 5);
    let s = key(&app, "c");
    assert_eq!(s["particles"].as_array().unwrap().len(), 0, "cleared");
    let s = key(&app, "ctrl+z");
    assert_eq!(
        s["particles"], before["particles"],
        "every disc, bit for bit"
    );
    assert_eq!(s["time"], before["time"]);
    assert_eq!(s["ui"]["center_of_mass_view"], false, "Ctrl+Z is not Z");
    // Redo clears again, and undo once more brings them back.
    let s = key(&app, "ctrl+y");
    assert_eq!(s["particles"].as_array().unwrap().len(), 0);
    let s = key(&app, "ctrl+shift+z");
    assert_eq!(s["ui"]["undo_levels"][1], 0, "nothing left to redo");
    let s = key(&app, "ctrl+z");
    assert_eq!(s["particles"], before["particles"]);
    // Ctrl+Z with nothing to undo still does not turn the view on.
    for _ in 0..3 {
        key(&app, "ctrl+z");
    }
    let s = app.wait_frames(2);
    assert_eq!(s["ui"]["center_of_mass_view"], false);
    app.quit();
}

fn the_centre_of_mass_view_on_and_off_leaves_every_velocity_bit_for_bit() {
    let x = Xvfb::start("com view");
    let app = Sandbox::start(&x, &["--paused", &asset("preset-3-light-hits-heavy.toml")]);
    app.move_to([300.0, 300.0]);
    let before = app.wait_frames(2);
    let s = key(&app, "z");
    assert_eq!(s["ui"]["center_of_mass_view"], true);
    assert_eq!(
        s["particles"], before["particles"],
        "the view rewrites nothing"
    );
    let s = key(&app, "z");
    assert_eq!(s["ui"]["center_of_mass_view"], false, "Z again leaves it");
    assert_eq!(s["particles"], before["particles"]);
    app.quit();
}

fn a_rewind_and_replay_keeps_the_ledger_and_the_counters_equal() {
    let x = Xvfb::start("rewind");
    let app = Sandbox::start(&x, &[&asset("preset-5-inelastic.toml")]);
    app.move_to([300.0, 300.0]);
    let agree = |s: &Value| {
        assert_eq!(
            s["collisions_recorded"], s["pair_collisions"],
            "ledger and counter at t = {}",
            s["time"]
        );
    };
    // Run past the collision, then rewind to before it and replay.
    let mut s = app.wait_frames(2);
    while s["pair_collisions"].as_u64() == Some(0) {
        s = app.wait_frames(10);
        assert!(s["time"].as_f64().unwrap() < 30.0, "no collision");
    }
    let s = key(&app, "space");
    agree(&s);
    let mut s = s;
    for _ in 0..40 {
        s = key(&app, "shift+comma");
        agree(&s);
        if s["pair_collisions"].as_u64() == Some(0) {
            break;
        }
    }
    assert_eq!(s["pair_collisions"].as_u64(), Some(0), "rewound before it");
    let s = key(&app, "space");
    let mut s = s;
    while s["pair_collisions"].as_u64() == Some(0) {
        s = app.wait_frames(10);
        assert!(s["time"].as_f64().unwrap() < 30.0, "no collision on replay");
    }
    agree(&s);
    assert_eq!(s["pair_collisions"].as_u64(), Some(1));
    app.quit();
}

fn after_enter_in_a_field_only_the_clock_keys_act_until_esc() {
    let x = Xvfb::start("panel keyboard");
    let app = Sandbox::start(&x, &["--paused", &asset("preset-1-head-on.toml")]);
    let s = app.wait_frames(3);
    app.click(widget(&s, "tab_discs", 0.5));
    let s = app.wait_frames(2);
    // Enter in a cell left as it was keeps the keys with the panel too: it
    // had given them to the world, and a 2 typed next opened a preset.
    app.click(widget(&s, "discs_mass_1", 0.5));
    let s = key(&app, "Return");
    assert_eq!(s["ui"]["panel_keyboard"], true);
    let s = key(&app, "2");
    assert_eq!(s["scene_name"], "Head-on, equal masses");
    assert_eq!(s["ui"]["scene_edited"], false, "nothing was edited");
    let s = key(&app, "Escape");
    assert_eq!(s["ui"]["panel_keyboard"], false);
    app.click(widget(&s, "discs_mass_0", 0.5));
    app.xdo(&["key", "ctrl+a"]);
    app.xdo(&["type", "--delay", "40", "3"]);
    let s = key(&app, "Return");
    assert_eq!(s["particles"][0]["mass"].as_f64(), Some(3.0));
    assert_eq!(s["ui"]["panel_keyboard"], true);
    assert_eq!(s["ui"]["scene_edited"], true, "a mass was edited");
    let s = key(&app, "2");
    assert_eq!(
        s["scene_name"], "Head-on, equal masses",
        "2 opened no preset"
    );
    // Backspace deletes no disc and Enter launches none, but Space, which
    // a teacher who set a mass presses next, runs and pauses the clock.
    let s = key(&app, "BackSpace");
    let s2 = key(&app, "Return");
    for s in [&s, &s2] {
        assert_eq!(s["particles"].as_array().map(Vec::len), Some(2));
    }
    let s = key(&app, "space");
    assert_eq!(s["paused"], false, "Space still runs the clock");
    let s = key(&app, "space");
    assert_eq!(s["paused"], true);
    assert_eq!(s["ui"]["panel_keyboard"], true);
    let s = key(&app, "Escape");
    assert_eq!(s["ui"]["panel_keyboard"], false);
    let s = key(&app, "2");
    assert_ne!(
        s["scene_name"], "Head-on, equal masses",
        "now 2 opens preset 2"
    );
    // The edit and the preset switch are both undone, in order.
    let s = key(&app, "ctrl+z");
    assert_eq!(s["scene_name"], "Head-on, equal masses");
    assert_eq!(s["particles"][0]["mass"].as_f64(), Some(3.0));
    let s = key(&app, "ctrl+z");
    assert_eq!(s["particles"][0]["mass"].as_f64(), Some(1.0));
    assert_eq!(s["ui"]["scene_edited"], false);
    app.quit();
}

fn switching_to_verlet_is_said_in_the_top_bar_and_switching_away_clears_it() {
    let x = Xvfb::start("warnings");
    let app = Sandbox::start(&x, &["--paused", &asset("preset-1-head-on.toml")]);
    app.move_to([300.0, 300.0]);
    let s = app.wait_frames(2);
    assert_eq!(
        s["warnings"].as_array().unwrap().len(),
        0,
        "{}",
        s["warnings"]
    );
    let mut s = s;
    for _ in 0..3 {
        s = key(&app, "y"); // auto → seed → impulse → verlet
    }
    assert_eq!(s["method"], "verlet");
    let codes: Vec<&str> = s["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["code"].as_str().unwrap())
        .collect();
    assert_eq!(codes, ["verlet_loses_energy"]);
    assert!(
        s["panel_widgets"]["warning_verlet_loses_energy"].is_array(),
        "drawn in the top bar"
    );
    let s = key(&app, "y"); // → exact
    assert_eq!(s["warnings"].as_array().unwrap().len(), 0);
    app.quit();
}

fn the_pi_blocks_end_on_their_count() {
    let x = Xvfb::start("pi end");
    let app = Sandbox::start(&x, &[&asset("pi-blocks-1.toml")]);
    app.move_to([300.0, 300.0]);
    // Equal masses: three collisions, over by about 8 s of simulated time.
    let mut s = app.wait_frames(2);
    while s["pi_result"].is_null() {
        s = app.wait_frames(10);
        assert!(s["time"].as_f64().unwrap() < 40.0, "never ended");
    }
    assert_eq!(s["pi_result"], "3 collisions: π ≈ 3");
    assert_eq!(s["walls"], serde_json::json!(["left"]));
    // The result is drawn from the frame after the one that found it.
    app.wait_for("the π result shown under the world", 30, |s| {
        s["panel_widgets"]["pi_result"].is_array()
    });
    app.quit();
}

fn a_one_dimensional_preset_keeps_every_y_velocity_zero_through_a_collision() {
    let x = Xvfb::start("one dimension");
    let app = Sandbox::start(&x, &[&asset("preset-4-glancing.toml")]);
    app.move_to([300.0, 300.0]);
    // Key 2: heavy hits light, on a track.
    let mut s = key(&app, "2");
    assert_eq!(s["constrain"], "x");
    let ys: Vec<Value> = s["particles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["pos"][1].clone())
        .collect();
    while s["pair_collisions"].as_u64() == Some(0) || s["time"].as_f64().unwrap() < 3.0 {
        for (p, y) in s["particles"].as_array().unwrap().iter().zip(&ys) {
            assert_eq!(p["vel"][1].as_f64(), Some(0.0), "t = {}", s["time"]);
            assert_eq!(&p["pos"][1], y);
        }
        s = app.wait_frames(5);
        assert!(s["time"].as_f64().unwrap() < 30.0, "no collision");
    }
    app.quit();
}

fn with_size_following_mass_an_edit_resizes_the_disc_or_is_refused_if_it_would_overlap() {
    let x = Xvfb::start("size follows mass");
    let app = Sandbox::start(&x, &["--paused", &asset("preset-1-head-on.toml")]);
    app.wait_frames(3);
    // Fold the two open sections so "New discs" opens in view.
    // (Each click waits for the sections to stop sliding first.)
    for section in ["section_show", "section_collisions", "section_new_discs"] {
        let s = app.wait_still();
        app.click(widget(&s, section, 0.5));
    }
    app.wait_for("the New discs section to open", 120, |s| {
        s["panel_widgets"]["size_follows_mass"].is_array()
    });
    let s = app.wait_still();
    let at = widget(&s, "size_follows_mass", 0.05);
    assert!(at[1] < 800.0, "in view: {at:?}");
    app.click(at);
    let s = app.wait_frames(2);
    assert_eq!(s["ui"]["size_follows_mass"], true);
    app.click(widget(&s, "tab_discs", 0.5));
    let s = app.wait_frames(2);
    app.click(widget(&s, "discs_mass_0", 0.5));
    app.xdo(&["key", "ctrl+a"]);
    app.xdo(&["type", "--delay", "40", "4"]);
    let s = key(&app, "Return");
    // r = 0.4·√m: 0.8 m at 4 kg.
    assert_eq!(s["particles"][0]["mass"].as_f64(), Some(4.0));
    let r = s["particles"][0]["radius"].as_f64().unwrap();
    assert!((r - 0.8).abs() < 1e-12, "{r}");
    // 100 kg would be 4 m in radius: it would cross the left wall.
    app.click(widget(&s, "discs_mass_0", 0.5));
    app.xdo(&["key", "ctrl+a"]);
    app.xdo(&["type", "--delay", "40", "100"]);
    let s = key(&app, "Return");
    assert_eq!(s["particles"][0]["mass"].as_f64(), Some(4.0), "refused");
    let note = s["ui"]["table_note"].as_str().unwrap();
    assert!(
        note.contains("cross a wall") && note.contains("nothing changed"),
        "{note}"
    );
    app.quit();
}
