//! Fields typed into and settings kept, under Xvfb with xdotool: the
//! Discs table at a projector's size follows Tab to each field and the
//! rest of its row; Ctrl with a letter types nothing there, and Ctrl+S
//! applies what was typed and saves it; the text size and theme chosen are
//! where the next start opens; a disc is placed by its typed position, and
//! a field the edit was refused for is marked until typed again.

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use serde_json::Value;

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "tab_in_the_discs_table_shows_each_rows_last_columns_and_brings_back_its_first",
            tab_in_the_discs_table_shows_each_rows_last_columns_and_brings_back_its_first,
        ),
        (
            "the_text_size_and_theme_chosen_are_kept_for_the_next_start",
            the_text_size_and_theme_chosen_are_kept_for_the_next_start,
        ),
        (
            "a_disc_is_placed_from_the_keyboard_by_its_position_fields",
            a_disc_is_placed_from_the_keyboard_by_its_position_fields,
        ),
        (
            "a_refused_field_is_marked_until_typed_again",
            a_refused_field_is_marked_until_typed_again,
        ),
    ])
}

/// At 1024×768 and text size 2 the Discs table is wider than the window.
/// Tab to a row's last field (v_y) shows the row's last columns too (|v|,
/// |p| and the energy, which hold no control), and Tab on to the next row
/// scrolls down to it and brings its first columns back. Ctrl+A and Ctrl+C
/// there type nothing; a mass typed and Ctrl+S is applied and saved.
fn tab_in_the_discs_table_shows_each_rows_last_columns_and_brings_back_its_first() {
    let x = Xvfb::start("discs table");
    let out = tempfile::tempdir().unwrap();
    let out_dir = out.path().to_str().unwrap();
    let app = projector_discs_tab(&x, &["--paused", "--out", out_dir]);
    let width = 1024.0;
    let cell = |s: &Value, name: &str| -> Option<[f64; 4]> {
        let r = &s["panel_widgets"][name];
        (0..4)
            .map(|k| r[k].as_f64())
            .collect::<Option<Vec<_>>>()
            .map(|v| [v[0], v[1], v[2], v[3]])
    };
    // Inside the window's width and the tab's height.
    let in_sight = |s: &Value, name: &str| {
        let tab = tab_content(s);
        let r = cell(s, name);
        let inside = r.is_some_and(|r| {
            r[0] >= -0.5
                && r[0] + r[2] <= width + 0.5
                && r[1] >= tab[1] - 0.5
                && r[1] + r[3] <= tab[1] + tab[3] + 0.5
        });
        assert!(inside, "{name} {r:?} out of sight of the tab {tab:?}");
    };
    tab_to(&app, "discs_vy_0", 80);
    let s = app.wait_frames(2);
    in_sight(&s, "discs_vy_0");
    // The energy's column starts with room for its numbers (its heading's
    // cell runs on past the window).
    let last = cell(&s, "discs_last_column");
    assert!(
        last.is_some_and(|r| r[0] <= width - 100.0),
        "the energy's column: {last:?}"
    );
    // Shift+Tab back to the row's mass: the field comes out from under the
    // disc numbers kept at the table's left (it stayed hidden there, its
    // heading too).
    for _ in 0..6 {
        app.xdo(&["key", "shift+Tab"]);
        if focus(&app.wait_frames(3)).as_deref() == Some("discs_mass_0") {
            break;
        }
    }
    let s = app.wait_frames(3);
    assert_eq!(focus(&s).as_deref(), Some("discs_mass_0"));
    let (mass, number) = (cell(&s, "discs_mass_0"), cell(&s, "discs_number_0"));
    assert!(
        matches!((mass, number), (Some(m), Some(n)) if m[0] >= n[0] + n[2] - 0.5),
        "the mass field {mass:?} under the disc's number {number:?}"
    );
    // The next row, below the one row the tab has room for.
    tab_to(&app, "discs_mass_1", 6);
    let s = app.wait_frames(2);
    in_sight(&s, "discs_mass_1");
    // Keys with Ctrl in a field type nothing (each had typed its letter
    // over the selected number), and Enter leaves the mass as it was.
    let mass = |s: &Value| s["particles"][1]["mass"].as_f64().unwrap();
    let before = mass(&s);
    for key in ["ctrl+a", "ctrl+c", "Return"] {
        app.xdo(&["key", key]);
        app.wait_frames(2);
    }
    let s = app.wait_frames(3);
    assert_eq!(
        s["ui"]["table_note"],
        Value::Null,
        "the field took a letter"
    );
    assert_eq!(mass(&s), before);
    // A mass typed and Ctrl+S: applied, as Enter does, then saved with it.
    tab_to(&app, "discs_mass_1", 30);
    app.xdo(&["type", "2"]);
    app.wait_frames(2);
    app.xdo(&["key", "ctrl+s"]);
    app.wait_for("the mass applied", 60, |s| mass(s) == 2.0);
    let s = app.wait_frames(2);
    in_sight(&s, "discs_mass_1");
    let saved = saved_scenes(out.path());
    assert_eq!(saved.len(), 1, "one scene saved: {saved:?}");
    let scene = impulse::Scene::load(&saved[0])
        .unwrap()
        .build("saved")
        .unwrap();
    assert_eq!(scene.particles[1].mass, 2.0, "the file has the mass typed");
    // Another, with Enter: its answer is in the strip, and the row edited
    // stays in sight (a line above the table in this short tab had pushed
    // it out).
    tab_to(&app, "discs_mass_1", 30);
    app.xdo(&["type", "3"]);
    app.xdo(&["key", "Return"]);
    let s = app.wait_for("the mass applied", 60, |s| mass(s) == 3.0);
    assert!(
        s["ui"]["message"]
            .as_str()
            .is_some_and(|n| n.contains("mass = 3")),
        "{}",
        s["ui"]
    );
    let s = app.wait_frames(3);
    in_sight(&s, "discs_mass_1");
    app.quit();
}

/// A teacher sets the projector's text size and the light theme once: the
/// next start opens with them, `--ui-scale` overrides them for one run
/// only, and a start after that has them again.
fn the_text_size_and_theme_chosen_are_kept_for_the_next_start() {
    let x = Xvfb::start("remembered");
    let state = tempfile::tempdir().unwrap();
    let chosen = |s: &Value| {
        let ui = &s["ui"];
        let size = s["layout"]["ui_scale"].as_f64().unwrap();
        (size, ui["theme"].to_string())
    };
    let first = Sandbox::start_with_state(&x, &["--paused"], state.path());
    assert_eq!(chosen(&first.state()), (1.0, "\"dark\"".into()));
    first.move_to([5.0, 400.0]);
    tab_to(&first, "section_view", 60);
    first.xdo(&["key", "space"]);
    first.wait_frames(3);
    tab_to(&first, "theme", 20);
    first.xdo(&["key", "space"]);
    first.wait_frames(3);
    first.xdo(&["key", "Escape"]);
    first.wait_frames(3);
    first.xdo(&["key", "F2"]);
    first.wait_frames(3);
    first.xdo(&["key", "F2"]);
    assert_eq!(chosen(&first.wait_frames(3)), (2.0, "\"light\"".into()));
    first.quit();

    let second = Sandbox::start_with_state(&x, &["--paused"], state.path());
    assert_eq!(chosen(&second.state()), (2.0, "\"light\"".into()));
    second.quit();
    let once = Sandbox::start_with_state(&x, &["--paused", "--ui-scale", "1"], state.path());
    assert_eq!(chosen(&once.state()), (1.0, "\"light\"".into()));
    once.quit();
    let third = Sandbox::start_with_state(&x, &["--paused"], state.path());
    assert_eq!(
        chosen(&third.state()),
        (2.0, "\"light\"".into()),
        "--ui-scale is for one run"
    );
    third.quit();
}

/// A teacher with no mouse places a disc: Q selects it and opens *Selected
/// disc* (it stayed folded), Tab reaches its x field, and x and y typed
/// with the number pad's Enter move it there (only a drag could); until Enter the panel
/// says they wait. Folded by hand, the section stays folded. Every
/// field's name is whole.
fn a_disc_is_placed_from_the_keyboard_by_its_position_fields() {
    let x = Xvfb::start("position fields");
    let app = glancing_disc_selected(&x, "1280x800", "1.5");
    let s = app.wait_frames(3);
    assert!(
        s["panel_widgets"]["disc_x"].is_array(),
        "selecting a disc opened its section"
    );
    // Every field's name in the dock (at text size 1.5, "speed |v| (m/s)"
    // ran past the window's edge).
    for (name, rect) in s["panel_widgets"].as_object().unwrap() {
        if name.starts_with("disc_") && name.ends_with("_label") {
            let right = rect[0].as_f64().unwrap() + rect[2].as_f64().unwrap();
            assert!(right <= 1280.0, "{name} ends at x {right}");
        }
    }
    let s = tab_to(&app, "disc_x", 60);
    // Wide enough for its number whole (four characters showed "13,4" for
    // 13,457): 80 points at text size 1.5.
    let width = s["panel_widgets"]["disc_x"][2].as_f64().unwrap();
    assert!(width >= 100.0, "the x field is {width} px wide");
    app.xdo(&["type", "3"]);
    app.xdo(&["key", "Tab"]);
    app.wait_frames(2);
    app.xdo(&["type", "2.5"]);
    // Typed, not applied: the panel says so (Tab applied nothing, silently).
    let s = app.wait_frames(3);
    assert!(
        s["panel_widgets"]["edit_pending"].is_array(),
        "no word that the typed values wait for Enter"
    );
    // The number pad's Enter, as a teacher typing numbers on the pad
    // presses it (egui-macroquad passed on only the main Enter).
    app.xdo(&["key", "KP_Enter"]);
    let pos = |s: &Value| {
        let p = &s["particles"][0]["pos"];
        [p[0].as_f64().unwrap(), p[1].as_f64().unwrap()]
    };
    app.wait_for("the disc moved", 60, |s| pos(s) == [3.0, 2.5]);
    let s = app.wait_frames(3);
    assert!(
        s["panel_widgets"]["edit_pending"].is_null(),
        "applied: nothing waits"
    );
    assert!(
        s["ui"]["message"].is_null() || !s["ui"]["message"].as_str().unwrap().contains("overlap"),
        "{}",
        s["ui"]
    );
    tab_to(&app, "section_selected", 60);
    app.xdo(&["key", "Return"]);
    let s = app.wait_frames(10);
    assert!(s["panel_widgets"]["disc_x"].is_null(), "folded by hand");
    app.xdo(&["key", "Escape"]);
    app.wait_frames(3);
    app.xdo(&["key", "q"]);
    let s = app.wait_frames(3);
    assert!(s["selected"].is_number(), "Q selected a disc");
    assert!(
        s["panel_widgets"]["disc_x"].is_null(),
        "a section folded by hand stays folded"
    );
    app.quit();
}

/// A student types a mass out of range and Enter: the mass is marked as
/// refused, not as waiting for Enter. A speed typed next is refused for
/// the mass, which stays marked (the speed does not); the mass typed
/// again, both apply. After each refusal the mass keeps the keyboard with
/// its text selected, so the number typed next replaces it (egui's field
/// let go of the keys on Enter, and the student had to Tab back). Esc
/// takes a refused number back, and so does the clock as it runs.
fn a_refused_field_is_marked_until_typed_again() {
    let x = Xvfb::start("refused field");
    let app = glancing_disc_selected(&x, "1280x800", "1.5");
    app.wait_frames(3);
    let marks = |s: &Value| {
        let w = &s["panel_widgets"];
        (
            w["disc_mass_refused"].is_array(),
            w["disc_vx_refused"].is_array(),
            w["edit_pending"].is_array(),
        )
    };
    // Tab to `field`, type `text` and Enter: the state after the answer.
    let enter_in = |field: &str, text: &str| {
        tab_to(&app, field, 80);
        app.xdo(&["type", text]);
        app.xdo(&["key", "Return"]);
        app.wait_frames(5)
    };
    let s = enter_in("disc_mass", "1e30");
    assert_eq!(marks(&s), (true, false, false), "the mass refused");
    assert_eq!(focus(&s).as_deref(), Some("disc_mass"), "kept the keys");
    let s = enter_in("disc_vx", "3");
    assert_eq!(marks(&s), (true, false, true), "refused for the mass");
    assert_eq!(s["particles"][0]["vel"][0], 2.5, "nothing applied");
    assert_eq!(s["particles"][0]["mass"], 1.0);
    assert_eq!(
        focus(&s).as_deref(),
        Some("disc_mass"),
        "the keys went to the field to mend"
    );
    app.xdo(&["type", "2"]);
    app.xdo(&["key", "Return"]);
    let s = app.wait_for("the edit", 60, |s| s["particles"][0]["mass"] == 2.0);
    assert_eq!(s["particles"][0]["vel"][0], 3.0);
    let s = app.wait_frames(3);
    assert_eq!(marks(&s), (false, false, false), "applied: nothing marked");
    // Esc takes a refused number back; and one left in its field goes
    // once the clock runs ("1e30" stayed in red beside a moving disc).
    let s = enter_in("disc_mass", "1e30");
    assert_eq!(marks(&s), (true, false, false), "refused again");
    app.xdo(&["key", "Escape"]);
    let s = app.wait_frames(3);
    assert_eq!(marks(&s), (false, false, false), "Esc took it back");
    let s = enter_in("disc_vx", "1e30");
    assert_eq!(marks(&s), (false, true, false), "v_x refused");
    app.click(widget(&s, "play", 0.5));
    app.wait_for("the refused v_x gone as the clock runs", 60, |s| {
        s["paused"] == false && marks(s) == (false, false, false)
    });
    app.quit();
}
