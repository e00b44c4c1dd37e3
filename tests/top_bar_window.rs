//! The top bar under Xvfb: the scene's name gets the room its other items
//! leave, and says in the dump when it is cut (whole on hover).

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use serde_json::Value;

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "the_scene_name_gets_the_room_the_top_bar_leaves",
            the_scene_name_gets_the_room_the_top_bar_leaves,
        ),
        (
            "the_pi_blocks_count_is_always_in_the_top_bar",
            the_pi_blocks_count_is_always_in_the_top_bar,
        ),
        (
            "the_momentum_is_in_the_top_bar_at_a_projectors_size",
            the_momentum_is_in_the_top_bar_at_a_projectors_size,
        ),
    ])
}

/// The momentum is the lesson: at 1024×768 at text size 1.5 and 1366×768
/// at size 2 the name kept its room and the momentum went under "… more"
/// (a browser review: "the one number the lesson is about is not on the
/// projected screen"). The name is cut further, and the buttons' words and
/// the state's word give way, where that shows it; at 1024×768 at size 2,
/// where nothing can, the state keeps its word.
fn the_momentum_is_in_the_top_bar_at_a_projectors_size() {
    let x = Xvfb::start("top bar momentum");
    for (size, scale, shown) in [
        ("1024x768", "1.5", true),
        ("1366x768", "2", true),
        ("1280x800", "2", true),
        ("1024x768", "2", false),
    ] {
        let app = head_on_paused(&x, size, scale);
        let s = app.wait_frames(4);
        let case = format!("{size} at size {scale}");
        assert_eq!(s["panel_widgets"]["momentum"].is_array(), shown, "{case}");
        if shown {
            let r = &s["panel_widgets"]["momentum"];
            let right = r[0].as_f64().unwrap() + r[2].as_f64().unwrap();
            let more = s["panel_widgets"]["top_bar_more"][0].as_f64().unwrap();
            assert!(right < more, "{case}: the momentum runs into “… more”");
        } else {
            let state = &s["panel_widgets"]["run_state"];
            assert!(state[2].as_f64().unwrap() > 100.0, "{case}: {state}");
        }
        app.quit();
    }
}

/// In the π blocks the count is the lesson, yet at a projector's size the
/// top bar kept it under "… more" until the end. It is always shown now,
/// after the state, which takes its sign alone to make room; the name, the
/// count, "… more" and the buttons stay apart and inside the window.
fn the_pi_blocks_count_is_always_in_the_top_bar() {
    let x = Xvfb::start("pi count");
    let app = Sandbox::start(&x, &["--size", "1024x768", "--ui-scale", "2"]);
    app.move_to([500.0, 200.0]);
    app.xdo(&["key", "7"]);
    let s = app.wait_for("a first collision of the π blocks", 600, |s| {
        s["scene_name"] == "Blocks that count π" && s["pair_collisions"].as_u64() >= Some(1)
    });
    let row = [
        "scene_name",
        "run_state",
        "pi_count",
        "top_bar_more",
        "drawer_toggle",
        "sound",
        "start",
    ];
    let rects: Vec<[f64; 4]> = row
        .iter()
        .map(|name| {
            assert!(s["panel_widgets"][*name].is_array(), "{name} not shown");
            rect(&s["panel_widgets"][*name])
        })
        .collect();
    for (k, r) in rects.iter().enumerate() {
        assert!(r[0] >= -0.5 && r[0] + r[2] <= 1024.5, "{}: {r:?}", row[k]);
    }
    // Left to right in this order, none over the next (the buttons are laid
    // out from the right end).
    for k in 0..4 {
        let (a, b) = (rects[k], rects[k + 1]);
        assert!(
            a[0] + a[2] <= b[0] + 0.5,
            "{} {a:?} runs into {} {b:?}",
            row[k],
            row[k + 1]
        );
    }
    assert!(
        rects[0][2] >= 60.0,
        "the name keeps some room: {:?}",
        rects[0]
    );
    app.quit();
}

/// The top bar took the room between two items off the scene's name twice:
/// at 1024×768 at size 2 the French glancing hit read "Choc obli…", with
/// room to spare before the buttons. Its name is whole now; a longer one is
/// still cut, and says so in the dump (whole on hover). On a wide window no
/// preset's name is cut.
fn the_scene_name_gets_the_room_the_top_bar_leaves() {
    let x = Xvfb::start("top bar name");
    let cut = |s: &Value| {
        s["ui"]["cut"]
            .as_array()
            .expect("the dump lists what is cut")
            .iter()
            .any(|c| c == "scene_name")
    };
    let app = Sandbox::start(
        &x,
        &[
            "--paused",
            "--size",
            "1024x768",
            "--ui-scale",
            "2",
            "--lang",
            "fr",
        ],
    );
    app.move_to([500.0, 200.0]);
    app.xdo(&["key", "4"]);
    app.wait_for("the glancing hit", 60, |s| {
        s["scene_name"] == "Glancing collision"
    });
    let s = app.wait_frames(3);
    // (The dump names scenes in English.)
    assert!(!cut(&s), "Choc oblique: cut");
    app.xdo(&["key", "1"]);
    app.wait_for("the head-on hit", 60, |s| {
        s["scene_name"] == "Head-on, equal masses"
    });
    let s = app.wait_frames(3);
    assert!(
        cut(&s),
        "Choc frontal, masses égales: not cut at 1024×768, size 2"
    );
    app.quit();
    let app = Sandbox::start(&x, &["--paused", "--size", "1920x1080"]);
    app.move_to([500.0, 200.0]);
    for key in PRESET_KEYS {
        app.xdo(&["key", key]);
        let s = app.wait_frames(3);
        assert!(!cut(&s), "{}: cut at 1920×1080", s["scene_name"]);
    }
    app.quit();
}
