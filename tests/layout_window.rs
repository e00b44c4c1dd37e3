//! The classroom screen under Xvfb: at 1024×768, 1280×800 and 1920×1080, at
//! UI scales 1 and 2, with every preset, no docked panel covers the world
//! and no text is too small to read from the back of a room; the Discs
//! table is edited as a person would (click, select all, type, Enter); a
//! bad number is refused with a message in view; the docks hide with S
//! while PAUSED stays in the top bar; at the projector scale the layout
//! holds in English, German and the pseudo-language (nothing cut off or
//! overlapping); and a machine too slow for real time
//! slows the simulation, says so, and keeps physics to half of each frame.

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use serde_json::Value;
use std::thread::sleep;
use std::time::{Duration, Instant};

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "no_panel_covers_the_world_and_text_is_large_enough_at_every_size_scale_and_preset",
            no_panel_covers_the_world_and_text_is_large_enough_at_every_size_scale_and_preset,
        ),
        (
            "s_hides_the_docks_for_a_full_size_world_and_paused_stays_in_the_top_bar",
            s_hides_the_docks_for_a_full_size_world_and_paused_stays_in_the_top_bar,
        ),
        (
            "a_mass_is_edited_in_the_discs_table_and_a_bad_number_is_refused_in_view",
            a_mass_is_edited_in_the_discs_table_and_a_bad_number_is_refused_in_view,
        ),
        (
            "the_rough_presets_fit_with_their_spin_values_at_the_smallest_size_and_both_scales",
            the_rough_presets_fit_with_their_spin_values_at_the_smallest_size_and_both_scales,
        ),
        (
            "a_machine_too_slow_for_real_time_slows_the_simulation_and_says_by_how_much",
            a_machine_too_slow_for_real_time_slows_the_simulation_and_says_by_how_much,
        ),
        (
            "at_the_projector_scale_the_ledger_opens_beside_a_world_that_keeps_its_room",
            at_the_projector_scale_the_ledger_opens_beside_a_world_that_keeps_its_room,
        ),
        (
            "in_german_at_the_projector_scale_nothing_is_cut_off_or_overlapping",
            in_german_at_the_projector_scale_nothing_is_cut_off_or_overlapping,
        ),
        (
            "in_spanish_french_and_portuguese_at_the_projector_scale_every_tab_is_on_the_row",
            in_spanish_french_and_portuguese_at_the_projector_scale_every_tab_is_on_the_row,
        ),
        (
            "in_the_pseudo_language_at_the_projector_scale_nothing_is_cut_off_or_overlapping",
            in_the_pseudo_language_at_the_projector_scale_nothing_is_cut_off_or_overlapping,
        ),
        (
            "at_the_projector_scale_the_discs_table_scrolls_sideways_to_its_last_column",
            at_the_projector_scale_the_discs_table_scrolls_sideways_to_its_last_column,
        ),
        (
            "tabs_captions_rewinds_and_the_end_of_the_pi_run_never_move_the_world",
            tabs_captions_rewinds_and_the_end_of_the_pi_run_never_move_the_world,
        ),
    ])
}

/// Whether two rectangles share any area (touching edges do not count).
fn overlap(a: [f64; 4], b: [f64; 4]) -> bool {
    let e = 0.5; // half a pixel: egui rounds panel edges
    a[0] + e < b[0] + b[2]
        && b[0] + e < a[0] + a[2]
        && a[1] + e < b[1] + b[3]
        && b[1] + e < a[1] + a[3]
}

/// Checks one frame's layout; `what` names it in messages.
fn check_layout(s: &Value, what: &str, scale: f64, window: [f64; 2]) {
    let layout = &s["layout"];
    assert_eq!(layout["ui_scale"].as_f64(), Some(scale), "{what}: {layout}");
    let size = [
        layout["window"][0].as_f64().unwrap(),
        layout["window"][1].as_f64().unwrap(),
    ];
    assert!(
        (size[0] - window[0]).abs() < 1.0 && (size[1] - window[1]).abs() < 1.0,
        "{what}: {size:?}"
    );
    let world = rect(&layout["world"]);
    assert!(
        world[2] > 100.0 && world[3] > 100.0,
        "{what}: a world to see: {world:?}"
    );
    let panels = layout["panels"].as_array().unwrap();
    assert!(
        panels.len() >= 2,
        "{what}: at least the top bar and the strip: {layout}"
    );
    for p in panels {
        let p = rect(p);
        assert!(
            !overlap(p, world),
            "{what}: panel {p:?} covers the world {world:?}"
        );
        assert!(
            p[0] >= -0.5
                && p[1] >= -0.5
                && p[0] + p[2] <= window[0] + 0.5
                && p[1] + p[3] <= window[1] + 0.5,
            "{what}: {p:?} leaves the window"
        );
    }
    let min_text = layout["min_text_px"].as_f64().unwrap();
    let floor = if scale >= 2.0 { 24.0 } else { 14.0 };
    assert!(
        min_text >= floor,
        "{what}: smallest text {min_text} px < {floor}"
    );
    // The world's guarantees (layout.rs): from 1024×768 up at scales 1–2,
    // at least 40 % of the window and 240 px each way; at scale 2.5 the
    // full width and 240 px of height.
    let share = world[2] * world[3] / (window[0] * window[1]);
    if window[0] >= 1024.0 && window[1] >= 768.0 && scale <= 2.0 {
        assert!(
            share >= 0.4 - 1e-3 && world[2] >= 240.0 && world[3] >= 240.0,
            "{what}: the world has {share:.2} of the window, {world:?}"
        );
    }
    if window[0] == 1024.0 && window[1] == 768.0 && scale == 1.0 {
        assert!(
            share >= 0.5,
            "{what}: the world has {share:.2} of the window"
        );
    }
    // The camera draws into that rectangle.
    let view = View::of(s);
    assert_eq!(
        [
            view.origin[0],
            view.origin[1],
            view.viewport[0],
            view.viewport[1]
        ]
        .map(|v| v.round()),
        world.map(|v| v.round()),
        "{what}"
    );
}

fn no_panel_covers_the_world_and_text_is_large_enough_at_every_size_scale_and_preset() {
    let x = Xvfb::start("layout");
    for (w, h) in [(1024, 768), (1280, 800), (1920, 1080)] {
        let size = format!("{w}x{h}");
        let app = Sandbox::start(&x, &["--paused", "--size", &size]);
        let window = [w as f64, h as f64];
        let s = app.wait_frames(3);
        check_layout(&s, &format!("{size}, default scene"), 1.0, window);
        assert_eq!(
            s["ui"]["dock_expanded"], true,
            "the dock is open at scale 1"
        );
        for scale in [1.0, 2.0] {
            if scale == 2.0 {
                // F2 cycles 1 → 1.5 → 2.
                app.xdo(&["key", "F2"]);
                let s = app.wait_frames(3);
                check_layout(&s, &format!("{size} at 1.5"), 1.5, window);
                app.xdo(&["key", "F2"]);
                let s = app.wait_frames(3);
                check_layout(&s, &format!("{size} at 2"), 2.0, window);
            }
            for key in PRESET_KEYS {
                app.xdo(&["key", key]);
                let s = app.wait_frames(3);
                let what = format!("{size}, scale {scale}, key {key} ({})", s["scene_name"]);
                check_layout(&s, &what, scale, window);
                // The fitted box lies inside the world's rectangle.
                let view = View::of(&s);
                let world = rect(&s["layout"]["world"]);
                let (a, b) = (view.to_screen([0.0, 0.0]), view.to_screen(vec2(&s["size"])));
                for p in [a, b] {
                    assert!(
                        p[0] >= world[0] - 0.5
                            && p[0] <= world[0] + world[2] + 0.5
                            && p[1] >= world[1] - 0.5
                            && p[1] <= world[1] + world[3] + 0.5,
                        "{what}: the box corner {p:?} is outside {world:?}"
                    );
                }
            }
        }
        app.quit();
    }
}

/// The presets reached only through the menu (P), with spin shown: more
/// in the top bar, the Discs table's spin columns, the Speeds tab's two
/// plots. Checked at the smallest window, at scales 1 and 2, with each of
/// those tabs open.
fn the_rough_presets_fit_with_their_spin_values_at_the_smallest_size_and_both_scales() {
    let x = Xvfb::start("rough layout");
    let window = [1024.0, 768.0];
    for file in ["preset-spin-off-a-wall.toml", "preset-rough-gas.toml"] {
        let app = Sandbox::start(&x, &["--size", "1024x768", &asset(file)]);
        app.move_to([5.0, 5.0]);
        let s = app.wait_frames(3);
        assert_eq!(s["spin_shown"], true, "{file}");
        check_layout(&s, &format!("{file}, scale 1"), 1.0, window);
        for tab in ["tab_discs", "tab_speeds", "tab_totals"] {
            app.click(widget(&s, tab, 0.5));
            let s = app.wait_frames(3);
            check_layout(&s, &format!("{file}, scale 1, {tab}"), 1.0, window);
        }
        app.xdo(&["key", "F2"]);
        app.wait_frames(2);
        app.xdo(&["key", "F2"]);
        let s = app.wait_frames(3);
        check_layout(&s, &format!("{file}, scale 2"), 2.0, window);
        // Opened at the projector's scale, the dock still fits.
        app.click(widget(&s, "tab_speeds", 0.5));
        let s = app.wait_frames(3);
        assert_eq!(s["ui"]["dock_expanded"], true, "{file}");
        check_layout(&s, &format!("{file}, scale 2, Speeds"), 2.0, window);
        app.quit();
    }
}

fn s_hides_the_docks_for_a_full_size_world_and_paused_stays_in_the_top_bar() {
    let x = Xvfb::start("hide");
    let app = Sandbox::start(&x, &["--paused"]);
    let before = app.wait_frames(3);
    let world_before = rect(&before["layout"]["world"]);
    app.move_to([300.0, 300.0]);
    app.xdo(&["key", "s"]);
    let s = app.wait_frames(3);
    assert_eq!(s["ui"]["docks_open"], false);
    let world = rect(&s["layout"]["world"]);
    assert!(
        world[2] * world[3] > 1.3 * world_before[2] * world_before[3],
        "{world:?} vs {world_before:?}"
    );
    check_layout(&s, "docks hidden", 1.0, [1280.0, 800.0]);
    let state = rect(&s["panel_widgets"]["run_state"]);
    assert!(
        state[1] >= 0.0 && state[1] + state[3] <= world[1] + 0.5,
        "PAUSED is in the top bar: {state:?}"
    );
    assert_eq!(s["paused"], true);
    app.xdo(&["key", "s"]);
    let s = app.wait_frames(3);
    assert_eq!(s["ui"]["docks_open"], true);
    app.quit();
}

/// Clicks at a point as a person would: move, press, release.
fn a_mass_is_edited_in_the_discs_table_and_a_bad_number_is_refused_in_view() {
    let x = Xvfb::start("discs table");
    let app = Sandbox::start(&x, &["--paused", &asset("preset-1-head-on.toml")]);
    let s = app.wait_frames(3);
    let before: Vec<f64> = s["particles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["mass"].as_f64().unwrap())
        .collect();
    assert_eq!(before.len(), 2);
    app.click(widget(&s, "tab_discs", 0.5));
    let s = app.wait_frames(3);
    assert_eq!(s["ui"]["tab"], "Discs");

    // Click the first disc's mass, select all, type 5, Enter.
    app.click(widget(&s, "discs_mass_0", 0.5));
    let s = app.wait_frames(2);
    assert_eq!(s["ui"]["typing"], true, "the cell has the keyboard");
    app.xdo(&["key", "ctrl+a"]);
    app.xdo(&["type", "--delay", "40", "5"]);
    app.xdo(&["key", "Return"]);
    let s = app.wait_frames(4);
    assert_eq!(s["particles"][0]["mass"].as_f64(), Some(5.0), "{}", s["ui"]);
    assert_eq!(
        s["particles"][1]["mass"].as_f64(),
        Some(before[1]),
        "the other disc is untouched"
    );
    assert_eq!(
        s["scene_name"], "Head-on, equal masses",
        "typing 5 opened no preset"
    );
    assert!(
        s["ui"]["table_note"].as_str().unwrap().contains("mass = 5"),
        "{}",
        s["ui"]
    );

    // A velocity that is not a number: refused, the disc as it was, the
    // message on screen inside the dock without scrolling.
    let vx = s["particles"][1]["vel"][0].as_f64().unwrap();
    app.click(widget(&s, "discs_vx_1", 0.5));
    app.xdo(&["key", "ctrl+a"]);
    app.xdo(&["type", "--delay", "40", "fast"]);
    app.xdo(&["key", "Return"]);
    let s = app.wait_frames(4);
    assert_eq!(s["particles"][1]["vel"][0].as_f64(), Some(vx));
    let note = s["ui"]["table_note"].as_str().unwrap();
    assert!(
        note.contains("not a number") && note.contains("nothing changed"),
        "{note}"
    );
    let shown = rect(&s["panel_widgets"]["table_note"]);
    let dock = s["layout"]["panels"]
        .as_array()
        .unwrap()
        .iter()
        .map(rect)
        .find(|p| overlap(*p, shown))
        .expect("the message is in a docked panel");
    assert!(
        shown[1] >= dock[1]
            && shown[1] + shown[3] <= dock[1] + dock[3]
            && shown[1] + shown[3] <= 800.0,
        "{shown:?} in {dock:?}"
    );
    assert!(shown[2] > 50.0, "{shown:?}");
    app.quit();
}

fn a_machine_too_slow_for_real_time_slows_the_simulation_and_says_by_how_much() {
    let x = Xvfb::start("frame budget");
    let app = Sandbox::start(&x, &["--gas", "100000"]);
    // Ask for eight times real time: 1,920 steps a second of 10⁵ discs,
    // more than two cores can run.
    app.move_to([300.0, 300.0]);
    for _ in 0..3 {
        app.xdo(&["key", "bracketright"]);
        app.wait_frames(2);
    }
    assert_eq!(app.wait_frames(1)["time_scale"], 8.0);
    // Let the meter fill, then measure over the meter's own window (10 s,
    // two autosaves' pauses), so both see the same frames.
    let deadline = Instant::now() + Duration::from_secs(90);
    let first = loop {
        let s = app.state();
        if s["realtime"]["ratio"].is_number() && s["timing"]["frames"].as_u64().unwrap_or(0) >= 30 {
            break s;
        }
        assert!(
            Instant::now() < deadline,
            "no ratio measured: {}",
            s["realtime"]
        );
        sleep(Duration::from_millis(200));
    };
    let t0 = (Instant::now(), first["time"].as_f64().unwrap());
    sleep(Duration::from_secs(10));
    let last = app.state();
    let measured = (last["time"].as_f64().unwrap() - t0.1) / t0.0.elapsed().as_secs_f64();
    let shown = last["realtime"]["shown"]
        .as_str()
        .unwrap_or_else(|| panic!("the top bar says nothing: {}", last["realtime"]));
    let number: f64 = shown
        .trim_start_matches("running at ")
        .split('×')
        .next()
        .and_then(|n| n.trim().parse().ok())
        .unwrap_or_else(|| panic!("{shown:?}"));
    assert!(
        measured < 0.9 * 8.0,
        "the test needs a machine that cannot keep up: {measured}"
    );
    assert!(
        (number - measured).abs() <= 0.1 * measured,
        "shown {number}, measured {measured}"
    );
    let t = &last["timing"];
    let (step, frame) = (
        t["step_ms"].as_f64().unwrap(),
        t["frame_ms"].as_f64().unwrap(),
    );
    assert!(
        step <= 0.5 * frame * 1.05,
        "physics {step} ms of a {frame} ms frame (medians)"
    );
    app.quit();
}

/// The teacher's case: 1024×768 at the projector's scale 2, the glancing
/// preset, J. The world keeps 40 % of the window and 240 px each way, the
/// controls become a drawer that floats over the world when opened, the
/// tab row and its Hide button are on screen, and the ledger's rows are
/// one under the other.
///
/// In `lang`: German's long words and the pseudo-language's 40 % longer
/// text must fit too: every named control of the top bar, the tab row and
/// the ledger inside the window and none over another.
fn projector_ledger(lang: &str) {
    let x = Xvfb::start("projector");
    let window = [1024.0, 768.0];
    let app = projector_at_impact(&x, lang);
    let s = app.wait_frames(3);
    check_layout(&s, "1024x768 scale 2 after J", 2.0, window);
    assert_eq!(s["layout"]["side"], "drawer", "{}", s["layout"]);
    assert_eq!(s["layout"]["tab_folded"], false, "the ledger is open");
    assert_eq!(s["ui"]["language"], lang);
    // The impact's lesson in sight without scrolling: both discs' momenta
    // and their total (under the count, the total was out of sight). Not in
    // the pseudo-language, whose names are longer than any language's and
    // take two lines here: for it, nothing cut off is what counts.
    let (total, tab) = (rect(&s["panel_widgets"]["ledger_total_p"]), tab_content(&s));
    assert!(
        lang == "qps" || total[1] >= tab[1] - 0.5 && total[1] + total[3] <= tab[1] + tab[3] + 0.5,
        "{lang}: the total momentum's row {total:?} in the tab {tab:?}"
    );
    // The tabs one by one, or, where their names do not fit, as a list.
    let tabs = [
        "tab_totals",
        "tab_collisions",
        "tab_discs",
        "tab_speeds",
        "tab_momenta",
        "tab_words",
        "dock_toggle",
    ];
    let menu = ["tab_menu", "dock_toggle"];
    let row = if s["panel_widgets"]["tab_menu"].is_array() {
        &menu[..]
    } else {
        &tabs[..]
    };
    // Every language's names fit the row, closed up where they must be
    // (Spanish and Portuguese had shown one list here); only the
    // pseudo-language's, 40 % longer, take the list.
    if lang != "qps" {
        assert_eq!(row, tabs, "{lang}: the tabs fit the row");
    }
    let mut bar = vec!["run_state", "sound", "start", "drawer_toggle"];
    if s["panel_widgets"]["top_bar_more"].is_array() {
        bar.push("top_bar_more");
    }
    // The count with its Next collision, under the newest impact's rows
    // in the tab's page: the page scrolls far enough to show it whole.
    let count = rect(&s["panel_widgets"]["ledger_count"]);
    let below = count[1] + count[3] - (tab[1] + tab[3]);
    let page = &s["ui"]["lists"]["scroll_ledger_stacked"]["max"][1];
    assert!(
        below <= 0.5 || page.as_f64().is_some_and(|max| max >= below - 0.5),
        "{lang}: the count {count:?} is {below} px below the tab, the page scrolls {page}"
    );
    for name in row.iter().chain(&bar) {
        let r = rect(&s["panel_widgets"][*name]);
        assert!(
            r[0] >= -0.5 && r[0] + r[2] <= window[0] + 0.5 && r[1] + r[3] <= window[1] + 0.5,
            "{lang}: {name} is cut off: {r:?}"
        );
    }
    for names in [row, &bar[..]] {
        for (k, a) in names.iter().enumerate() {
            for b in &names[k + 1..] {
                let (ra, rb) = (rect(&s["panel_widgets"][*a]), rect(&s["panel_widgets"][*b]));
                assert!(!overlap(ra, rb), "{lang}: {a} {ra:?} over {b} {rb:?}");
            }
        }
    }
    // The scale bar measures what is on screen, not kilometres.
    let view = View::of(&s);
    assert!(view.scale > 10.0, "{} px per metre", view.scale);
    // The drawer opens over the world, like a popup; the world stays put,
    // and the box, fitted, moves into what the drawer leaves in sight (it
    // had hidden the box's right half, in Glancing the disc hit).
    let world = rect(&s["layout"]["world"]);
    let size = [
        s["size"][0].as_f64().unwrap(),
        s["size"][1].as_f64().unwrap(),
    ];
    let right_edge = |s: &Value| View::of(s).to_screen(size)[0];
    let closed = View::of(&s);
    app.click(widget(&s, "drawer_toggle", 0.5));
    let s = app.wait_frames(3);
    assert_eq!(s["ui"]["drawer_open"], true);
    assert_eq!(rect(&s["layout"]["world"]), world);
    let drawer = rect(&s["layout"]["drawer"]);
    assert!(
        right_edge(&s) <= drawer[0] + 0.5,
        "{lang}: the box ends at {} under the drawer from {}",
        right_edge(&s),
        drawer[0]
    );
    assert!(
        s["panel_widgets"]["section_show"].is_array(),
        "the controls are in it"
    );
    // J closes the drawer, which hid the ledger it opens and its report's
    // end; the report is whole in the window.
    app.xdo(&["key", "j"]);
    let s = app.wait_for("J's report", 30, |s| {
        s["panel_widgets"]["message"].is_array()
    });
    assert_eq!(s["ui"]["drawer_open"], false, "{lang}: J closes the drawer");
    let said = rect(&s["panel_widgets"]["message"]);
    assert!(
        said[0] + said[2] <= window[0] + 0.5,
        "{lang}: the report {said:?}"
    );
    // With the drawer open again, a report stops short of it (N's here).
    app.click(widget(&s, "drawer_toggle", 0.5));
    app.wait_for("the drawer again", 30, |s| s["ui"]["drawer_open"] == true);
    app.xdo(&["key", "n"]);
    let s = app.wait_for("N's report beside the drawer", 30, |s| {
        s["panel_widgets"]["message"].is_array() && s["ui"]["drawer_open"] == true
    });
    let (said, drawer) = (
        rect(&s["panel_widgets"]["message"]),
        rect(&s["layout"]["drawer"]),
    );
    assert!(
        said[0] + said[2] <= drawer[0] + 0.5,
        "{lang}: the report {said:?} runs under the drawer {drawer:?}"
    );
    // The buttons leave the sections most of the drawer: those after Redo
    // are under "… more" (in German the ten took seven rows, and the first
    // section began three quarters of the way down).
    let first = rect(&s["panel_widgets"]["section_collisions"]);
    assert!(
        first[1] < 0.5 * window[1],
        "{lang}: the sections begin at {first:?}"
    );
    // Esc closes the menu, not the drawer under it (it closed both).
    app.click(widget(&s, "transport_more", 0.5));
    app.wait_for("the other buttons", 30, |s| {
        s["panel_widgets"]["help"].is_array()
    });
    app.xdo(&["key", "Escape"]);
    let s = app.wait_for("the menu closed", 30, |s| {
        !s["panel_widgets"]["help"].is_array()
    });
    assert_eq!(s["ui"]["drawer_open"], true, "{lang}: Esc on the menu");
    app.click(widget(&s, "transport_more", 0.5));
    let s = app.wait_for("the other buttons", 30, |s| {
        s["panel_widgets"]["help"].is_array()
    });
    app.click(widget(&s, "help", 0.5));
    app.wait_for("the help from the menu", 30, |s| {
        s["ui"]["help_open"] == true
    });
    app.xdo(&["key", "Escape"]);
    app.wait_for("the help put away", 30, |s| s["ui"]["help_open"] == false);
    let s = app.state();
    if s["ui"]["drawer_open"] == false {
        app.click(widget(&s, "drawer_toggle", 0.5));
        app.wait_for("the drawer again", 30, |s| s["ui"]["drawer_open"] == true);
    }
    app.xdo(&["key", "Escape"]);
    let s = app.wait_frames(3);
    assert_eq!(s["ui"]["drawer_open"], false, "Esc closes it");
    let open = View::of(&s);
    assert_eq!(
        (open.center, open.scale),
        (closed.center, closed.scale),
        "{lang}: the view as it was before the drawer"
    );
    // L (show or hide the controls) opens and shuts the drawer here; it
    // does not hide the drawer's button, and the controls with it.
    for open in [true, false] {
        app.xdo(&["key", "l"]);
        let s = app.wait_frames(3);
        assert_eq!(s["ui"]["drawer_open"], open, "L");
        assert!(s["panel_widgets"]["drawer_toggle"].is_array(), "L");
    }
    // The key list fits the window.
    app.xdo(&["key", "h"]);
    app.wait_for("the help", 30, |s| {
        s["panel_widgets"]["help_first_meaning"].is_array()
    });
    // egui lays a new box out once unseen; the frame after is the first shown.
    let s = app.wait_frames(1);
    let first = rect(&s["panel_widgets"]["help_first_meaning"]);
    let s = app.wait_frames(3);
    let help = rect(&s["panel_widgets"]["help_window"]);
    // Each key's meaning has the room to read on one line where its keys do
    // (no column of keys squeezes it into three), and nothing moves after H.
    let keys = rect(&s["panel_widgets"]["help_first_keys"]);
    let meaning = rect(&s["panel_widgets"]["help_first_meaning"]);
    assert!(
        meaning[3] < 1.5 * keys[3],
        "{lang}: the first key's meaning wraps: {meaning:?}, its keys {keys:?}"
    );
    assert_eq!(first, meaning, "{lang}: the key list moved after it opened");
    assert!(
        help[0] >= 0.0
            && help[1] >= 0.0
            && help[0] + help[2] <= window[0] + 0.5
            && help[1] + help[3] <= window[1] + 0.5,
        "the help is inside the window: {help:?}"
    );
    app.quit();
}

fn at_the_projector_scale_the_ledger_opens_beside_a_world_that_keeps_its_room() {
    projector_ledger("en");
}

fn in_german_at_the_projector_scale_nothing_is_cut_off_or_overlapping() {
    projector_ledger("de");
}

/// Spanish and Portuguese had given the tab row as one list here (their
/// names a little longer than English's): now they close up on the row.
fn in_spanish_french_and_portuguese_at_the_projector_scale_every_tab_is_on_the_row() {
    for lang in ["es", "fr", "pt-BR"] {
        projector_ledger(lang);
    }
}

fn in_the_pseudo_language_at_the_projector_scale_nothing_is_cut_off_or_overlapping() {
    projector_ledger("qps");
}

/// At 1024×768 and text size 2 the Discs table is wider than the window:
/// it scrolls sideways (a touchpad, a sideways wheel, its bar) to its last
/// column, the kinetic energy, which had been cut off out of reach.
fn at_the_projector_scale_the_discs_table_scrolls_sideways_to_its_last_column() {
    let x = Xvfb::start("discs");
    let app = projector_discs_tab(&x, &[]);
    let s = app.state();
    // Both discs' rows in sight in the short tab: the line on how to edit
    // gives way to the headings' tooltips (it took the second row's room).
    let area = tab_content(&s);
    for cell in ["discs_mass_0", "discs_mass_1"] {
        let r = rect(&s["panel_widgets"][cell]);
        assert!(
            r[1] >= area[1] && r[1] + r[3] <= area[1] + area[3] + 0.5,
            "{cell} {r:?} is not inside the tab {area:?}"
        );
    }
    // Where the last column starts (out of sight: nowhere, or past the
    // window's edge less the 100 px it needs).
    let start = |s: &Value| {
        s["panel_widgets"]["discs_last_column"][0]
            .as_f64()
            .unwrap_or(f64::INFINITY)
    };
    assert!(
        start(&s) > 1024.0 - 100.0,
        "already in sight: {}",
        start(&s)
    );
    let table = rect(&s["panel_widgets"]["tab_discs"]);
    app.move_to([500.0, table[1] - 60.0]);
    app.wait_frames(2);
    app.xdo(&["click", "--repeat", "12", "--delay", "40", "7"]);
    let s = app.wait_for("the table scrolled", 60, |s| start(s) < 1024.0 - 100.0);
    // Each row still says whose it is: the discs' numbers stay at the
    // table's left edge (they had scrolled out with their column).
    let area = tab_content(&s);
    for disc in 0..2 {
        let name = format!("discs_number_{disc}");
        let r = rect(&s["panel_widgets"][name.as_str()]);
        assert!(
            r[0] >= area[0] - 0.5 && r[0] + r[2] <= area[0] + 120.0 && r[2] > 5.0,
            "{name} {r:?} is not at the left of the tab {area:?}"
        );
    }
    app.quit();
}

/// Switching the dock's tabs, a long caption, a rewind and the end of the
/// π run keep the world's rectangle and the view exactly where they were.
fn tabs_captions_rewinds_and_the_end_of_the_pi_run_never_move_the_world() {
    let x = Xvfb::start("steady");
    for size in ["1024x768", "1280x800"] {
        let app = Sandbox::start(&x, &["--size", size, &asset("preset-7-pi-blocks.toml")]);
        app.move_to([500.0, 200.0]);
        let first = app.wait_frames(3);
        let place = |s: &Value| {
            (
                rect(&s["layout"]["world"]),
                rect(&s["panel_widgets"]["tab_totals"]),
            )
        };
        let (world, tab) = place(&first);
        for name in [
            "tab_collisions",
            "tab_discs",
            "tab_speeds",
            "tab_momenta",
            "tab_totals",
        ] {
            let s = app.wait_frames(2);
            app.click(widget(&s, name, 0.5));
            let s = app.wait_frames(3);
            assert_eq!(
                place(&s),
                (world, tab),
                "{size}: {name} moved the world or the tab row"
            );
        }
        // The π run ends (its line replaces the caption): nothing moves.
        let s = app.wait_for("the π result", 3000, |s| s["pi_result"].is_string());
        assert_eq!(place(&s).0, world, "{size}: the end of the π run");
        // A rewind adds its line to the top bar: nothing moves.
        app.xdo(&["key", "comma"]);
        let s = app.wait_for("the rewind", 30, |s| s["history_cursor"].is_number());
        assert_eq!(place(&s).0, world, "{size}: a rewind");
        assert_eq!(
            rect(&s["panel_widgets"]["run_state"])[1],
            rect(&first["panel_widgets"]["run_state"])[1]
        );
        app.quit();
    }
}
