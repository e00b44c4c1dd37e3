//! The classroom screen under Xvfb: at 1024×768, 1280×800 and 1920×1080, at
//! UI scales 1 and 2, with every preset, no docked panel covers the world
//! and no text is too small to read from the back of a room; the Discs
//! table is edited as a person would (click, select all, type, Enter); a
//! bad number is refused with a message in view; the docks hide with S
//! while PAUSED stays in the top bar; and a machine too slow for real time
//! slows the simulation, says so, and keeps physics to half of each frame.
//! The projector's case in every language is `projector_window.rs`.

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use serde_json::Value;
use std::thread::sleep;
use std::time::{Duration, Instant};

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "a_scene_without_a_caption_has_the_world_of_one_with_a_long_caption",
            a_scene_without_a_caption_has_the_world_of_one_with_a_long_caption,
        ),
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
            "tabs_captions_rewinds_and_the_end_of_the_pi_run_never_move_the_world",
            tabs_captions_rewinds_and_the_end_of_the_pi_run_never_move_the_world,
        ),
        (
            "the_side_buttons_keep_their_places_as_the_clock_starts_and_stops",
            the_side_buttons_keep_their_places_as_the_clock_starts_and_stops,
        ),
        (
            "a_tab_clicked_without_room_says_what_makes_room",
            a_tab_clicked_without_room_says_what_makes_room,
        ),
        (
            "a_one_dimensional_lesson_fits_its_line_not_the_whole_box",
            a_one_dimensional_lesson_fits_its_line_not_the_whole_box,
        ),
    ])
}

/// On a projector's wide, short world (1366×768 at text size 2: 1366 by
/// 348 px) the head-on discs were 42 px wide: the view fitted the box's
/// 10 m across the line, where nothing moves and no wall is drawn. It
/// fits the line's 16 m and a band of 2 m each side (three radii of the
/// largest disc where that is more): at least 4 m across, so 348 / 4 px
/// a metre at most, and the 1.2-m discs about twice as wide.
fn a_one_dimensional_lesson_fits_its_line_not_the_whole_box() {
    let x = Xvfb::start("one-dimensional view");
    let app = head_on_paused(&x, "1366x768", "2");
    let s = app.wait_frames(3);
    let view = View::of(&s);
    let world = rect(&s["layout"]["world"]);
    let box_height_px = 10.0 * view.scale;
    assert!(
        box_height_px > world[3],
        "the whole box fitted: {box_height_px} px"
    );
    let band_px = 4.0 * view.scale;
    assert!(
        band_px <= world[3] + 0.5,
        "less than 4 m across: {band_px} px"
    );
    let diameter = 2.0 * s["particles"][0]["radius"].as_f64().unwrap() * view.scale;
    assert!(diameter > 80.0, "the discs are {diameter} px wide");
    let (left, right) = (view.to_screen([0.0, 5.0]), view.to_screen([16.0, 5.0]));
    assert!(
        left[0] >= world[0] && right[0] <= world[0] + world[2],
        "{left:?} {right:?}"
    );
    app.quit();
}

/// A browser window of 1024×768 is a page of 1024×625: at text size 2 the
/// world keeps its least height and the tabs have no room. A click on one
/// showed nothing, and the row's note, cut to "no room here: L hides …",
/// named L, which beside a drawer opens the drawer. The strip says what
/// makes room: another text size (F2).
fn a_tab_clicked_without_room_says_what_makes_room() {
    let x = Xvfb::start("no room for a tab");
    let app = head_on_paused(&x, "1024x625", "2");
    let s = app.wait_frames(3);
    assert_eq!(s["layout"]["tab_folded"], true, "{}", s["layout"]);
    app.click(widget(&s, "tab_collisions", 0.5));
    let s = app.wait_for("a note", 60, |s| s["ui"]["message"].is_string());
    let said = s["ui"]["message"].as_str().unwrap();
    assert!(said.contains("text size") && said.contains("F2"), "{said}");
    app.quit();
}

/// "⏸ Pause" is wider than "▶ Play": at 1024×768 the buttons after it
/// moved a place as the clock started (Undo went up a row, Redo took its
/// place), and a teacher who paused and clicked where Undo was pressed
/// Redo. The play button keeps the wider label's width, in every language.
fn the_side_buttons_keep_their_places_as_the_clock_starts_and_stops() {
    let x = Xvfb::start("play button");
    for lang in ["en", "de", "es", "fr", "pt-BR"] {
        let args = [
            "--paused",
            "--size",
            "1024x768",
            "--lang",
            lang,
            &asset("preset-1-head-on.toml"),
        ];
        let app = Sandbox::start(&x, &args);
        app.move_to([300.0, 300.0]);
        let places = |s: &Value| -> Vec<String> {
            [
                "step", "reset", "undo", "redo", "slower", "faster", "presets",
            ]
            .iter()
            .map(|name| format!("{name} {}", s["panel_widgets"][name]))
            .collect()
        };
        let paused = app.wait_frames(3);
        assert_eq!(paused["paused"], true);
        app.xdo(&["key", "space"]);
        app.wait_for("the clock running", 60, |s| s["paused"] == false);
        let running = app.wait_frames(2);
        assert_eq!(places(&paused), places(&running), "{lang}");
        app.quit();
    }
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
                // The fitted box lies inside the world's rectangle; in a
                // one-dimensional world, its length and a band round the
                // discs' line (every disc in it).
                let view = View::of(&s);
                let world = rect(&s["layout"]["world"]);
                let inside = |p: [f64; 2], across: bool| {
                    p[0] >= world[0] - 0.5
                        && p[0] <= world[0] + world[2] + 0.5
                        && (!across
                            || (p[1] >= world[1] - 0.5 && p[1] <= world[1] + world[3] + 0.5))
                };
                let one_dimension = s["constrain"] == "x";
                let (a, b) = (view.to_screen([0.0, 0.0]), view.to_screen(vec2(&s["size"])));
                for p in [a, b] {
                    assert!(
                        inside(p, !one_dimension),
                        "{what}: the box corner {p:?} is outside {world:?}"
                    );
                }
                for disc in s["particles"].as_array().unwrap() {
                    let (c, r) = (vec2(&disc["pos"]), disc["radius"].as_f64().unwrap());
                    for corner in [[c[0] - r, c[1] - r], [c[0] + r, c[1] + r]] {
                        let p = view.to_screen(corner);
                        assert!(
                            inside(p, true),
                            "{what}: a disc's edge {p:?} is outside {world:?}"
                        );
                    }
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
    // The refused cell kept the keyboard, its text selected: the number
    // typed next replaces it (the cell had let go of the keys on Enter).
    assert_eq!(focus(&s).as_deref(), Some("discs_vx_1"));
    app.xdo(&["type", "--delay", "40", "--", "-1"]);
    app.xdo(&["key", "Return"]);
    app.wait_for("the mended velocity", 60, |s| {
        s["particles"][1]["vel"][0].as_f64() == Some(-1.0)
    });
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

/// Switching the dock's tabs, a long caption, a rewind, the end of the π
/// run and captions of one line and of two keep the world's rectangle and
/// the view exactly where they were.
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
        // Captions of one line and of two (the empty box's, the head-on
        // hit's, a first edit's "Before the edits:"): the strip kept its
        // height, the world where it was (the strip had grown and shrunk
        // with them).
        for (key, what) in [
            ("ctrl+n", "the empty box"),
            ("1", "the head-on hit"),
            ("Right", "an edit"),
        ] {
            if key == "Right" {
                // Paused, Right aims the selected disc (along the line).
                if app.state()["paused"] == false {
                    app.xdo(&["key", "space"]);
                }
                app.xdo(&["key", "q"]);
            }
            app.xdo(&["key", key]);
            let s = app.wait_frames(5);
            assert_eq!(place(&s).0, world, "{size}: {what}");
            if key == "Right" {
                assert_eq!(s["ui"]["scene_edited"], true, "{size}: edited");
            }
        }
        app.quit();
    }
}

/// A scene named by the teacher has no caption: at a projector's size its
/// strip had shrunk to one line, and the world grew, its box moved and its
/// scale bar jumped from 2 m to 5 m. The world is the same as beside the
/// head-on hit's caption of two lines.
fn a_scene_without_a_caption_has_the_world_of_one_with_a_long_caption() {
    let x = Xvfb::start("caption lines");
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(asset("preset-1-head-on.toml")).unwrap();
    let bare: String = text
        .lines()
        .filter(|l| !l.starts_with("description"))
        .map(|l| format!("{l}\n"))
        .collect();
    assert_ne!(bare, text, "the caption was taken out");
    let file = dir.path().join("aula-3.toml");
    std::fs::write(&file, bare).unwrap();
    for size in ["1366x768", "1024x768"] {
        let world = |scene: &str| {
            let app = Sandbox::start(&x, &["--paused", "--size", size, "--ui-scale", "2", scene]);
            let s = app.wait_frames(3);
            app.quit();
            (rect(&s["layout"]["world"]), s["camera"]["scale"].clone())
        };
        let captioned = world(&asset("preset-1-head-on.toml"));
        let bare = world(file.to_str().unwrap());
        assert_eq!(bare, captioned, "{size}");
    }
}
