//! The top bar under Xvfb: the scene's name gets the room its other items
//! leave, and says in the dump when it is cut (whole on hover).

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use serde_json::Value;

fn main() -> std::process::ExitCode {
    harness::run(vec![(
        "the_scene_name_gets_the_room_the_top_bar_leaves",
        the_scene_name_gets_the_room_the_top_bar_leaves,
    )])
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
