//! Keys that reach what the mouse reaches, under Xvfb with xdotool: Ctrl
//! and a digit show the bottom dock's tab at that place in the row, the
//! help is read with its keys at once while nothing changes behind it, and
//! F6 jumps between the window's parts.

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "ctrl_and_a_digit_show_the_tab_at_that_place_in_the_row",
            ctrl_and_a_digit_show_the_tab_at_that_place_in_the_row,
        ),
        (
            "the_help_is_read_with_the_keys_at_once_and_nothing_changes_behind_it",
            the_help_is_read_with_the_keys_at_once_and_nothing_changes_behind_it,
        ),
        (
            "f6_jumps_to_the_selected_discs_mass_then_the_tabs_the_top_bar_and_the_world",
            f6_jumps_to_the_selected_discs_mass_then_the_tabs_the_top_bar_and_the_world,
        ),
    ])
}

/// Every tab has a key: Ctrl and its place in the row, as a browser's own
/// tabs; the digit alone still opens a preset.
fn ctrl_and_a_digit_show_the_tab_at_that_place_in_the_row() {
    let x = Xvfb::start("tab keys");
    let app = Sandbox::start(&x, &["--paused"]);
    app.move_to([300.0, 300.0]);
    let scene = app.wait_frames(3)["scene_name"].clone();
    for (key, tab) in [
        ("ctrl+3", "Discs"),
        ("ctrl+6", "Words"),
        ("ctrl+1", "Totals"),
    ] {
        app.xdo(&["key", key]);
        let s = app.wait_frames(3);
        assert_eq!(s["ui"]["tab"], tab, "{key}");
        assert_eq!(s["ui"]["dock_expanded"], true, "{key}");
        assert_eq!(s["scene_name"], scene, "{key} opened no preset");
    }
    app.quit();
}

/// The help opened with H is read with Page Down at once (it needed a Tab
/// to its list first); the keys that scroll it (Home, Enter, the arrows)
/// no longer make a disc or move the view behind it; Esc closes it, and it
/// opens again at its top. "?" opens it too.
fn the_help_is_read_with_the_keys_at_once_and_nothing_changes_behind_it() {
    let x = Xvfb::start("help keys");
    let app = Sandbox::start(&x, &["--paused", "--size", "1024x768", "--ui-scale", "2"]);
    app.move_to([300.0, 300.0]);
    app.xdo(&["key", "1"]);
    let s = app.wait_frames(3);
    let discs = s["particles"].as_array().unwrap().len();
    let view = s["camera"].clone();
    app.xdo(&["key", "h"]);
    app.wait_frames(3);
    app.xdo(&["key", "Next"]);
    let s = app.wait_frames(3);
    let (offset, max) = list_scroll(&s, "scroll_keys");
    assert!(
        offset > 0.0 && max > 0.0,
        "Page Down scrolled the help: {offset} of {max}"
    );
    for key in ["Home", "Return", "Up", "Left", "space"] {
        app.xdo(&["key", key]);
    }
    let s = app.wait_frames(3);
    assert_eq!(
        s["particles"].as_array().unwrap().len(),
        discs,
        "no disc behind the help"
    );
    assert_eq!(s["camera"], view, "the view stayed");
    assert_eq!(
        s["paused"], true,
        "Space scrolled; it did not run the clock"
    );
    assert_eq!(s["ui"]["help_open"], true);
    let (offset, _) = list_scroll(&s, "scroll_keys");
    assert!(offset > 0.0, "Space scrolled the help down: {offset}");
    app.xdo(&["key", "Escape"]);
    let s = app.wait_frames(3);
    assert_eq!(s["ui"]["help_open"], false, "Esc closed the help");
    app.xdo(&["key", "h"]);
    let s = app.wait_frames(3);
    let (offset, _) = list_scroll(&s, "scroll_keys");
    assert_eq!(offset, 0.0, "the help opened again at its top");
    app.xdo(&["key", "Escape"]);
    app.wait_frames(3);
    // With a control in the help holding the keys, one Esc still closes it.
    app.xdo(&["key", "h"]);
    app.wait_frames(3);
    app.xdo(&["key", "Tab"]);
    let s = app.wait_frames(3);
    assert!(
        s["ui"]["focus"].is_string(),
        "Tab gave a control the keys: {}",
        s["ui"]
    );
    app.xdo(&["key", "Escape"]);
    let s = app.wait_frames(3);
    assert_eq!(s["ui"]["help_open"], false, "one Esc closed the help");
    // "?" opens it too, as its button ("? Help") suggests.
    app.xdo(&["key", "question"]);
    app.wait_for("the help opened by ?", 60, |s| s["ui"]["help_open"] == true);
    app.quit();
}

/// A teacher at a projector (1024×768, text size 2, the controls in a
/// closed drawer) changes the selected disc's mass from the keyboard: F6
/// opens the drawer on the mass field (about thirty Tabs from the top bar
/// before), the number typed replaces the one there and is applied with
/// Enter, Tab goes on to the next field, and F6 goes on to the
/// tabs (closing the drawer it opened, which stayed over the world), the
/// top bar and back to the world, whose keys work again; Shift+F6 goes the
/// other way, and into the controls opens the drawer again.
fn f6_jumps_to_the_selected_discs_mass_then_the_tabs_the_top_bar_and_the_world() {
    let x = Xvfb::start("F6");
    let app = glancing_disc_selected(&x, "1024x768", "2");
    let s = app.wait_frames(3);
    assert_eq!(s["ui"]["drawer_open"], false, "{}", s["layout"]);
    app.xdo(&["key", "F6"]);
    let s = app.wait_for("the mass field has the keys", 60, |s| {
        s["ui"]["focus"] == "disc_mass"
    });
    assert_eq!(s["ui"]["drawer_open"], true);
    // Its value selected, as Tab selects it: "2" typed is 2 kg, not 12.
    app.xdo(&["type", "2"]);
    app.xdo(&["key", "Return"]);
    app.wait_for("the mass applied", 60, |s| s["particles"][0]["mass"] == 2.0);
    // Tab goes on from the field Enter left (it went to the window's first
    // control, Shift+Tab to its last).
    app.xdo(&["key", "Tab"]);
    app.wait_for("Tab goes on to the radius", 60, |s| {
        s["ui"]["focus"] == "disc_radius"
    });
    app.xdo(&["key", "F6"]);
    let s = app.wait_for("a tab has the keys", 60, |s| {
        s["ui"]["focus"] == "tab_totals"
    });
    assert_eq!(s["ui"]["tab"], "Totals");
    app.wait_for("the drawer F6 opened closed", 60, |s| {
        s["ui"]["drawer_open"] == false
    });
    app.xdo(&["key", "F6"]);
    let s = app.wait_for("the top bar has the keys", 60, |s| {
        s["ui"]["focus"].as_str().is_some_and(|f| {
            let r = &s["panel_widgets"][f];
            r[1].as_f64().unwrap() < s["layout"]["world"][1].as_f64().unwrap()
        })
    });
    let top = s["ui"]["focus"].clone();
    app.xdo(&["key", "F6"]);
    app.wait_for("the world has the keys", 60, |s| {
        s["ui"]["focus"].is_null() && s["ui"]["typing"] == false
    });
    app.xdo(&["key", "space"]);
    app.wait_for("Space runs the clock", 60, |s| s["paused"] == false);
    app.xdo(&["key", "shift+F6"]);
    app.wait_for("back to the top bar", 60, |s| s["ui"]["focus"] == top);
    app.xdo(&["key", "shift+F6"]);
    app.wait_for("back to the tabs", 60, |s| s["ui"]["focus"] == "tab_totals");
    app.xdo(&["key", "shift+F6"]);
    let s = app.wait_for("back to the mass", 60, |s| s["ui"]["focus"] == "disc_mass");
    assert_eq!(s["ui"]["drawer_open"], true, "opened again");
    app.quit();
}
