//! The window from the keyboard alone, under Xvfb with xdotool: Tab and
//! Shift+Tab walk the controls in reading order with a ring round the one
//! that has the keys (in both themes); while a control has them, the
//! world's keys rest and Space presses the control; Esc gives them back;
//! every stop is a control, not a window's frame or a scroll area's part;
//! a list without controls takes Tab and its keys scroll it; a drop-down
//! steps through its choices with the arrows; the dock's tab is made
//! taller by its top edge, dragged or moved by the keys;
//! and the world itself answers keys: Q selects a disc, the arrow keys aim
//! it while paused, Enter puts a new disc at the centre.

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use serde_json::Value;

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "tab_walks_the_controls_in_reading_order_with_a_ring_in_the_dark_theme",
            tab_walks_the_controls_in_reading_order_with_a_ring_in_the_dark_theme,
        ),
        (
            "the_ring_shows_in_the_light_theme_too",
            the_ring_shows_in_the_light_theme_too,
        ),
        (
            "while_a_control_has_the_keys_the_world_rests_and_esc_gives_them_back",
            while_a_control_has_the_keys_the_world_rests_and_esc_gives_them_back,
        ),
        (
            "on_the_start_screen_tab_reaches_the_tiles_first_and_enter_opens_one",
            on_the_start_screen_tab_reaches_the_tiles_first_and_enter_opens_one,
        ),
        (
            "every_tab_stop_is_a_control_never_a_frame_round_others",
            every_tab_stop_is_a_control_never_a_frame_round_others,
        ),
        (
            "a_list_without_controls_takes_tab_and_the_keys_scroll_it",
            a_list_without_controls_takes_tab_and_the_keys_scroll_it,
        ),
        (
            "a_drop_down_steps_through_its_choices_with_the_arrows",
            a_drop_down_steps_through_its_choices_with_the_arrows,
        ),
        (
            "the_tab_is_made_taller_by_its_edge_dragged_or_moved_by_the_keys",
            the_tab_is_made_taller_by_its_edge_dragged_or_moved_by_the_keys,
        ),
        (
            "q_selects_a_disc_the_arrows_aim_it_and_enter_puts_one_at_the_centre",
            q_selects_a_disc_the_arrows_aim_it_and_enter_puts_one_at_the_centre,
        ),
    ])
}

/// Presses Tab `n` times and returns the named control that had the keys
/// after each press.
fn tabs(app: &Sandbox, n: usize) -> Vec<Option<String>> {
    (0..n)
        .map(|_| {
            app.xdo(&["key", "Tab"]);
            focus(&app.wait_frames(3))
        })
        .collect()
}

/// Walks to `name` with Tab, with the window's screenshot taken when it
/// closes, and checks the ring round it there in `ring` (RGB).
fn ring_round_a_focused_button(x: &Xvfb, args: &[&str], ring: [u8; 3]) {
    let dir = tempfile::tempdir().unwrap();
    let shot = dir.path().join("ring.png");
    let shot_arg = shot.to_str().unwrap().to_string();
    let mut all = vec!["--paused", "--screenshot", &shot_arg];
    all.extend_from_slice(args);
    let app = Sandbox::start(x, &all);
    app.move_to([300.0, 300.0]);
    app.wait_frames(3);
    let seen = tabs(&app, 3);
    let Some(name) = seen.last().cloned().flatten() else {
        panic!("no named control has the keys after three Tabs: {seen:?}");
    };
    let s = app.wait_frames(3);
    let r = s["panel_widgets"][&name].as_array().unwrap().clone();
    let [x0, y0, w, _] = [0, 1, 2, 3].map(|k| r[k].as_f64().unwrap());
    app.quit();
    let image = image::open(&shot).unwrap().to_rgb8();
    // Above the control's top edge, across its width: the ring's colour.
    let near = |p: &image::Rgb<u8>| (0..3).all(|k| (p[k] as i32 - ring[k] as i32).abs() <= 40);
    let mut hits = 0;
    let mut looked = 0;
    for dy in 1..=7 {
        let y = (y0 - dy as f64).round();
        if y < 0.0 {
            continue;
        }
        for k in 0..20 {
            let x = (x0 + w * (k as f64 + 0.5) / 20.0).round();
            looked += 1;
            if near(image.get_pixel(x as u32, y as u32)) {
                hits += 1;
            }
        }
    }
    assert!(
        hits >= 20,
        "a ring of {ring:?} above {name} ({r:?}): {hits} of {looked} pixels"
    );
}

fn tab_walks_the_controls_in_reading_order_with_a_ring_in_the_dark_theme() {
    let x = Xvfb::start("tab order");
    let app = Sandbox::start(&x, &["--paused"]);
    app.move_to([300.0, 300.0]);
    app.wait_frames(3);
    let seen = tabs(&app, 8);
    let at = |name: &str| {
        seen.iter()
            .position(|f| f.as_deref() == Some(name))
            .unwrap_or_else(|| panic!("Tab never reached {name}: {seen:?}"))
    };
    // The top bar's buttons left to right, then the side dock from its
    // first row.
    assert!(
        at("sound") < at("start")
            && at("start") < at("play")
            && at("play") < at("step")
            && at("step") < at("reset"),
        "{seen:?}"
    );
    // Shift+Tab goes back one.
    let before = seen.last().cloned().flatten();
    app.xdo(&["key", "shift+Tab"]);
    let back = focus(&app.wait_frames(3));
    assert_ne!(back, before, "Shift+Tab moved: {seen:?}");
    assert!(back.is_some(), "to a named control: {seen:?}");
    app.quit();
    ring_round_a_focused_button(&x, &[], [255, 200, 0]);
}

fn the_ring_shows_in_the_light_theme_too() {
    let x = Xvfb::start("ring");
    ring_round_a_focused_button(&x, &["--light"], [0, 80, 200]);
}

fn while_a_control_has_the_keys_the_world_rests_and_esc_gives_them_back() {
    let x = Xvfb::start("keys");
    let app = Sandbox::start(&x, &["--paused"]);
    app.move_to([300.0, 300.0]);
    app.xdo(&["key", "1"]); // head-on: two discs that meet
    let start = app.wait_frames(3);
    let seen = tabs(&app, 8);
    let k = seen
        .iter()
        .position(|f| f.as_deref() == Some("step"))
        .unwrap_or_else(|| panic!("Tab reaches Step: {seen:?}"));
    // Back to Step.
    for _ in k + 1..seen.len() {
        app.xdo(&["key", "shift+Tab"]);
        app.wait_frames(2);
    }
    assert_eq!(
        focus(&app.wait_frames(3)).as_deref(),
        Some("step"),
        "{seen:?}"
    );
    // J is the world's: it waits.
    app.xdo(&["key", "j"]);
    let s = app.wait_frames(5);
    assert_eq!(s["ui"]["tab"], start["ui"]["tab"]);
    assert_eq!(s["time"], start["time"], "J did not run");
    assert_eq!(s["ui"]["typing"], true);
    // Space presses the focused Step: one step, still paused.
    app.xdo(&["key", "space"]);
    let s = app.wait_frames(3);
    assert_eq!(s["paused"], true);
    assert!(
        s["time"].as_f64().unwrap() > start["time"].as_f64().unwrap(),
        "a step"
    );
    assert_eq!(focus(&s).as_deref(), Some("step"), "Space kept it there");
    // Esc gives the keys back.
    app.xdo(&["key", "Escape"]);
    let s = app.wait_frames(3);
    assert_eq!(focus(&s), None);
    app.xdo(&["key", "j"]);
    let s = app.wait_for("J", 60, |s| s["ui"]["tab"] == "Collisions");
    assert!(
        s["collisions_recorded"].as_u64().unwrap() >= 1,
        "J ran to the collision"
    );
    app.quit();
}

/// Walks Tab once round and checks every stop: something has the keys, its
/// ring is not a sliver (a scroll bar) and is in sight, and it holds no
/// named control (a window's frame, a scroll area's content, a plot round
/// its legend).
fn every_tab_stop_is_a_control_never_a_frame_round_others() {
    let x = Xvfb::start("stops");
    let projector = &["--paused", "--size", "1024x768", "--ui-scale", "2"][..];
    for (args, clicks) in [
        (&["--paused"][..], &[][..]),
        (projector, &[]),
        // The controls in their drawer, scrolled as Tab goes; none of the
        // Collisions tab's under the drawer, whose ring could not be seen.
        (projector, &["tab_collisions", "drawer_toggle"]),
        // The glancing hit with the Discs tab's table of fields open.
        (&["--paused"][..], &["tab_discs"]),
    ] {
        let app = Sandbox::start(&x, args);
        app.move_to([5.0, 400.0]);
        let discs_tab = clicks.contains(&"tab_discs");
        if discs_tab {
            app.xdo(&["key", "4"]);
        }
        for &name in clicks {
            let s = app.wait_frames(5);
            app.click(widget(&s, name, 0.5));
            app.move_to([5.0, 400.0]);
        }
        let click = clicks.last();
        app.wait_frames(3);
        let mut seen: Vec<(Option<String>, Vec<i64>)> = Vec::new();
        for _ in 0..120 {
            app.xdo(&["key", "Tab"]);
            let s = app.wait_frames(3);
            let name = focus(&s);
            let Some(rect) = s["ui"]["focus_rect"].as_array() else {
                panic!("nothing has the keys after {seen:?}");
            };
            let r: Vec<f64> = rect.iter().map(|v| v.as_f64().unwrap()).collect();
            assert!(
                r[2].min(r[3]) >= 6.0,
                "a sliver has the keys: {name:?} {r:?}"
            );
            // In sight: a control Tab reaches in a scroll area is scrolled to.
            let window = &s["layout"]["window"];
            let (w, h) = (window[0].as_f64().unwrap(), window[1].as_f64().unwrap());
            assert!(
                r[0] >= -1.0 && r[1] >= -1.0 && r[0] + r[2] <= w + 1.0 && r[1] + r[3] <= h + 1.0,
                "out of sight: {name:?} at {r:?} ({args:?} {click:?})"
            );
            let widgets = s["panel_widgets"].as_object().unwrap();
            let inside: Vec<&String> = widgets
                .iter()
                .filter(|(n, _)| Some(n.as_str()) != name.as_deref())
                .filter(|(_, w)| {
                    let w: Vec<f64> = w
                        .as_array()
                        .unwrap()
                        .iter()
                        .map(|v| v.as_f64().unwrap())
                        .collect();
                    w[2] * w[3] > 0.0
                        && w[0] >= r[0] - 1.0
                        && w[1] >= r[1] - 1.0
                        && w[0] + w[2] <= r[0] + r[2] + 1.0
                        && w[1] + w[3] <= r[1] + r[3] + 1.0
                })
                .map(|(n, _)| n)
                .collect();
            assert!(
                inside.is_empty(),
                "{name:?} at {r:?} holds {inside:?} ({args:?})"
            );
            // Not under the drawer: the dump leaves out what a dialog
            // covers, so a control named there is in sight.
            if let (Some(n), true) = (&name, s["layout"]["drawer"].is_array()) {
                assert!(
                    widgets.contains_key(n),
                    "{n} at {r:?} has the keys under the drawer"
                );
            }
            let key = (name, r.iter().map(|v| v.round() as i64).collect());
            if seen.first() == Some(&key) {
                break;
            }
            seen.push(key);
        }
        let names = seen.iter().filter(|(n, _)| n.is_some()).count();
        assert!(names >= 10 && seen.len() < 120, "{args:?}: {seen:?}");
        // Tab going on from the side dock's scroll bar reaches the table.
        if discs_tab {
            for cell in ["discs_mass_0", "discs_vy_1"] {
                assert!(
                    seen.iter().any(|(n, _)| n.as_deref() == Some(cell)),
                    "{cell}: {seen:?}"
                );
            }
        }
        // What the top bar has no room for (at text size 2) is reached too.
        let more = seen
            .iter()
            .any(|(n, _)| n.as_deref() == Some("top_bar_more"));
        assert_eq!(more, args.contains(&"--ui-scale"), "{args:?}: {seen:?}");
        // The top bar in reading order: "… more" at the line's end, then its
        // buttons from the left.
        let at = |name: &str| seen.iter().position(|(n, _)| n.as_deref() == Some(name));
        if more {
            assert!(
                at("top_bar_more") < at("sound") && at("sound") < at("start"),
                "{args:?}: {seen:?}"
            );
        }
        app.quit();
    }
}

fn a_list_without_controls_takes_tab_and_the_keys_scroll_it() {
    let x = Xvfb::start("lists");
    let projector = ["--paused", "--size", "1024x768", "--ui-scale", "2"];
    // The key list at a projector's scale: far longer than its box.
    let app = Sandbox::start(&x, &projector);
    app.move_to([5.0, 400.0]);
    app.xdo(&["key", "F1"]);
    let s = app.wait_frames(3);
    let (offset, max) = list_scroll(&s, "scroll_keys");
    assert!(offset == 0.0 && max > 1000.0, "{offset} of {max}");
    // It is modal: Tab goes round the box alone, the list its second stop.
    let s = tab_to(&app, "scroll_keys", 2);
    let view = s["ui"]["focus_rect"][3].as_f64().unwrap();
    let press = |key: &str| {
        app.xdo(&["key", key]);
        let s = app.wait_frames(3);
        assert_eq!(
            focus(&s).as_deref(),
            Some("scroll_keys"),
            "{key} took the keys away"
        );
        list_scroll(&s, "scroll_keys")
    };
    let line = press("Down").0;
    assert!(
        line > 0.0 && line < view / 2.0,
        "Down: {line} (view {view})"
    );
    let page = press("Next").0 - line;
    assert!(
        page > view / 2.0 && page < view,
        "Page Down: {page} (view {view})"
    );
    let (end, max) = press("End");
    assert_eq!(end, max, "End");
    assert!(
        (press("Up").0 - (max - line)).abs() < 0.5,
        "Up from the end"
    );
    assert_eq!(press("Home").0, 0.0, "Home");
    app.xdo(&["key", "Escape"]);
    let s = app.wait_frames(3);
    assert_eq!(focus(&s), None, "Esc gives the keys back");
    app.quit();

    // The ledger at the same scale: the newest collision's table, the
    // count with Next collision and the list of the last ones, one page
    // in one scroll area. Tab reaches the page and shows it, the keys
    // scroll it, and Tab on reaches the button and shows it.
    let app = Sandbox::start(&x, &projector);
    app.move_to([5.0, 400.0]);
    app.xdo(&["key", "u"]);
    app.xdo(&["key", "space"]);
    app.wait_for("the run", 120, |s| s["paused"] == false);
    std::thread::sleep(std::time::Duration::from_secs(3));
    app.xdo(&["key", "space"]);
    app.wait_for("the pause", 120, |s| s["paused"] == true);
    app.xdo(&["key", "j"]);
    let s = app.wait_frames(5);
    // One list to read: the newest impact's rows, and the list, in it
    // (each in an area of its own had scrolled alone, the list in the two
    // rows left under the count).
    let lists: Vec<String> = s["ui"]["lists"]
        .as_object()
        .unwrap()
        .keys()
        .cloned()
        .collect();
    assert_eq!(lists, ["scroll_ledger_stacked"], "{}", s["ui"]);
    let (_, max) = list_scroll(&s, "scroll_ledger_stacked");
    assert!(max > 0.0, "{}", s["ui"]);
    tab_to(&app, "scroll_ledger_stacked", 60);
    // Shown within a few frames (egui's scrolling lands a frame later).
    let s = app.wait_frames(3);
    let window = s["layout"]["window"][1].as_f64().unwrap();
    let shown = |s: &Value| {
        let r: Vec<f64> = s["ui"]["focus_rect"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let tab = tab_content(s);
        assert!(
            r[1] >= tab[1] - 0.5 && r[1] + r[3] <= window + 1.0,
            "{:?} is out of sight: {r:?}",
            focus(s)
        );
    };
    shown(&s);
    app.xdo(&["key", "Down"]);
    let s = app.wait_frames(3);
    assert!(
        list_scroll(&s, "scroll_ledger_stacked").0 > 0.0,
        "{}",
        s["ui"]
    );
    app.xdo(&["key", "End"]);
    let s = app.wait_frames(3);
    let (end, max) = list_scroll(&s, "scroll_ledger_stacked");
    assert!((end - max).abs() < 1.0, "End: {end} of {max}");
    tab_to(&app, "next_collision_in_tab", 3);
    let s = app.wait_frames(3);
    shown(&s);
    let button = rect(&s["panel_widgets"]["next_collision_in_tab"]);
    let tab = tab_content(&s);
    assert!(
        button[1] >= tab[1] - 0.5 && button[1] + button[3] <= tab[1] + tab[3] + 0.5,
        "Next collision {button:?} is outside the tab {tab:?}"
    );
    // Another scene's ledger from its top (it kept this one's scroll).
    app.xdo(&["key", "Escape"]);
    app.wait_frames(3);
    app.xdo(&["key", "4"]);
    app.wait_frames(3);
    app.xdo(&["key", "j"]);
    app.wait_for("the glancing impact", 300, |s| s["pair_collisions"] == 1);
    let s = app.wait_frames(3);
    let (top, _) = list_scroll(&s, "scroll_ledger_stacked");
    assert_eq!(top, 0.0, "{}", s["ui"]);
    app.quit();
}

/// The window, paused, with the side dock's section `header` opened from
/// the keyboard (Tab to its header, Space).
fn with_section_open(x: &Xvfb, header: &str) -> Sandbox {
    let app = Sandbox::start(x, &["--paused"]);
    app.move_to([5.0, 400.0]);
    tab_to(&app, header, 60);
    app.xdo(&["key", "space"]);
    app.wait_frames(3);
    app
}

fn a_drop_down_steps_through_its_choices_with_the_arrows() {
    let x = Xvfb::start("drop-downs");
    let app = Sandbox::start(&x, &["--paused"]);
    app.move_to([5.0, 400.0]);
    tab_to(&app, "edges", 40);
    let press = |key: &str| {
        app.xdo(&["key", key]);
        let s = app.wait_frames(3);
        assert_eq!(focus(&s).as_deref(), Some("edges"), "{key} took the keys");
        s["boundary"].as_str().unwrap().to_string()
    };
    assert_eq!(press("Down"), "open");
    assert_eq!(press("Down"), "periodic");
    assert_eq!(press("Down"), "periodic", "the last stays the last");
    assert_eq!(press("Up"), "open");
    assert_eq!(press("Home"), "box");
    assert_eq!(press("End"), "periodic");
    // Open, its list over the controls below: the arrows still choose.
    assert_eq!(press("space"), "periodic");
    assert_eq!(press("Up"), "open");
    app.xdo(&["key", "Escape"]);
    app.quit();

    // Under More, the friction's value box is off while friction is off:
    // Tab goes from its tick box straight on to the method's drop-down
    // (egui's value box took the keyboard there and dropped it).
    let app = with_section_open(&x, "section_more");
    tab_to(&app, "friction_on", 20);
    let after: Vec<_> = tabs(&app, 3);
    assert_eq!(
        after,
        [Some("method"), Some("broad_phase"), Some("substeps")].map(|n| n.map(str::to_string)),
    );
    app.quit();

    // The language's box keeps the keyboard through a change of language
    // (its label, in the language, changes), and stays in sight as the
    // text above it reflows.
    let app = with_section_open(&x, "section_view");
    let s = tab_to(&app, "language", 30);
    let mut seen = vec![s["ui"]["language"].as_str().unwrap().to_string()];
    for _ in 0..3 {
        app.xdo(&["key", "Down"]);
        app.wait_frames(3);
        let s = app.wait_frames(3);
        assert_eq!(focus(&s).as_deref(), Some("language"), "after {seen:?}");
        let r = &s["ui"]["focus_rect"];
        let bottom = r[1].as_f64().unwrap() + r[3].as_f64().unwrap();
        assert!(
            bottom <= s["layout"]["window"][1].as_f64().unwrap() + 1.0,
            "out of sight in {}: {r}",
            s["ui"]["language"]
        );
        seen.push(s["ui"]["language"].as_str().unwrap().to_string());
    }
    seen.dedup();
    assert_eq!(seen.len(), 4, "each Down a language: {seen:?}");
    app.quit();
}

fn q_selects_a_disc_the_arrows_aim_it_and_enter_puts_one_at_the_centre() {
    let x = Xvfb::start("world keys");
    let app = Sandbox::start(&x, &["--paused"]);
    app.move_to([300.0, 300.0]);
    // Glancing: in two dimensions (the head-on hit's discs keep to a line).
    app.xdo(&["key", "4"]);
    let s = app.wait_frames(3);
    let n = s["particles"].as_array().unwrap().len();
    app.xdo(&["key", "q"]);
    let s = app.wait_frames(3);
    assert_eq!(s["selected"], 0);
    let vy = |s: &Value| s["particles"][0]["vel"][1].as_f64().unwrap();
    let before = vy(&s);
    let camera = View::of(&s).center;
    for _ in 0..3 {
        app.xdo(&["key", "Up"]);
        app.wait_frames(2);
    }
    let s = app.wait_frames(3);
    assert!(
        (vy(&s) - before - 0.3).abs() < 1e-9,
        "{} → {}",
        before,
        vy(&s)
    );
    assert_eq!(
        View::of(&s).center,
        camera,
        "the arrows aimed, they did not pan"
    );
    app.xdo(&["key", "shift+q"]);
    let s = app.wait_frames(3);
    assert_eq!(
        s["selected"],
        n - 1,
        "Shift+Q: the previous one, round the end"
    );
    app.xdo(&["key", "Return"]);
    let s = app.wait_frames(3);
    assert_eq!(s["particles"].as_array().unwrap().len(), n + 1);
    assert_eq!(s["selected"], n);
    app.quit();
}

fn on_the_start_screen_tab_reaches_the_tiles_first_and_enter_opens_one() {
    let x = Xvfb::start("start keys");
    // A projector's scale in a small window: the tiles scroll.
    let app = Sandbox::start_plain(&x, &["--size", "1024x768", "--ui-scale", "2"]);
    let s = app.wait_for("the start screen", 60, |s| {
        s["ui"]["start_open"] == true && s["panel_widgets"]["start_screen"].is_array()
    });
    // The tiles lie below the top bar, which stays whole behind them (their
    // box had cut through its line of words), and inside the window.
    let bar = rect(&s["layout"]["panels"][0]);
    let tiles = rect(&s["panel_widgets"]["start_screen"]);
    assert!(
        tiles[1] >= bar[1] + bar[3] - 0.5 && tiles[1] + tiles[3] <= 768.5,
        "the tiles {tiles:?}, the top bar {bar:?}"
    );
    // The first press is on the first tile, and the walk goes round the
    // start screen alone: its tiles and its language list, then the first
    // tile again (nothing behind it).
    let seen = tabs(&app, 9);
    assert_eq!(seen[0].as_deref(), Some("tile_head_on"), "{seen:?}");
    assert!(
        seen.iter().all(|f| f
            .as_deref()
            .is_some_and(|f| f.starts_with("tile_") || f == "language")),
        "{seen:?}"
    );
    assert_eq!(
        seen[7].as_deref(),
        Some("tile_head_on"),
        "round again: {seen:?}"
    );
    // Shift+Tab from the first tile goes round backwards, to the last
    // (each press in a frame of its own: egui moves the keys once a frame).
    app.xdo(&["key", "shift+Tab"]);
    assert_eq!(focus(&app.wait_frames(3)).as_deref(), Some("tile_head_on"));
    app.xdo(&["key", "shift+Tab"]);
    assert_eq!(focus(&app.wait_frames(3)).as_deref(), Some("language"));
    // A tile out of sight is scrolled to when Tab reaches it.
    app.xdo(&["key", "shift+Tab"]);
    let s = app.wait_frames(5);
    assert_eq!(focus(&s).as_deref(), Some("tile_free_play"));
    let r = s["ui"]["focus_rect"].as_array().unwrap();
    let bottom = r[1].as_f64().unwrap() + r[3].as_f64().unwrap();
    assert!(bottom <= 768.0, "the ring is below the window: {r:?}");
    // Back to the first tile, then Enter opens its lesson.
    for _ in 0..10 {
        if focus(&app.wait_frames(2)).as_deref() == Some("tile_head_on") {
            break;
        }
        app.xdo(&["key", "shift+Tab"]);
    }
    app.xdo(&["key", "Return"]);
    let s = app.wait_for("the lesson", 60, |s| s["ui"]["start_open"] == false);
    assert!(
        s["scene_name"].as_str().unwrap_or("").contains("Head-on"),
        "{}",
        s["scene_name"]
    );
    app.quit();
}

/// At a projector's size (1024×768, text size 2) the ledger's tab opens
/// 200 px high, with its table's numbers in sight (the names wrap). Its top
/// edge dragged up gives it what the world can spare (the world keeps 40 %
/// of the window and 240 px each way); from the keyboard, Tab reaches the
/// edge, End and Home take it to the shortest and the tallest, Up adds a
/// row, Enter gives the tab its own height back. The next start opens the
/// tab at the height last set.
fn the_tab_is_made_taller_by_its_edge_dragged_or_moved_by_the_keys() {
    let x = Xvfb::start("edge");
    let app = projector_at_impact(&x, "pt-BR");
    let s = app.wait_frames(3);
    let own = tab_content(&s)[3];
    let table = &s["panel_widgets"]["ledger_newest"];
    let right = table[0].as_f64().unwrap() + table[2].as_f64().unwrap();
    assert!(
        right <= 1024.5,
        "the newest impact's table runs to x = {right}"
    );
    // Dragged up by 150 px.
    let edge = widget(&s, "tab_edge", 0.7);
    app.drag(edge, [edge[0], edge[1] - 150.0]);
    let s = app.wait_frames(5);
    let dragged = tab_content(&s)[3];
    let world = &s["layout"]["world"];
    let (ww, wh) = (world[2].as_f64().unwrap(), world[3].as_f64().unwrap());
    // All the world could spare (here the caption's two lines take 40 px
    // of it): the world is at its least.
    assert!(dragged > own + 30.0, "{own} px, then {dragged} px");
    assert!(
        ww * wh >= 0.4 * 1024.0 * 768.0 - 1.0 && wh >= 240.0,
        "{world}"
    );
    assert!(
        ww * wh < 0.4 * 1024.0 * 768.0 + 2.0 * ww,
        "{world}: more to spare"
    );
    // From the keyboard.
    app.move_to([500.0, 200.0]);
    let s = tab_to(&app, "tab_edge", 80);
    assert_eq!(tab_content(&s)[3], dragged);
    let row = s["layout"]["panels"][0][3].as_f64().unwrap();
    for (key, height) in [
        ("End", 3.0 * row),
        ("Up", 4.0 * row),
        ("Home", dragged),
        ("Return", own),
    ] {
        app.xdo(&["key", key]);
        let s = app.wait_for(key, 30, |s| (tab_content(s)[3] - height).abs() < 0.5);
        assert_eq!(
            focus(&s).as_deref(),
            Some("tab_edge"),
            "{key} kept the keys"
        );
    }
    // The height set is where the next start opens the tab (a row more,
    // or as much more as the world spares).
    app.xdo(&["key", "Up"]);
    let more = (own + row).min(dragged);
    let set = app.wait_for("a row more", 30, |s| (tab_content(s)[3] - more).abs() < 0.5);
    assert!(more > own, "{own} px, then {more} px");
    let settings = |state: &std::path::Path| state.join("impulse").join("settings.toml");
    let kept = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(kept.path().join("impulse")).unwrap();
    // (None written: the next start opens the tab at its own height.)
    let _ = std::fs::copy(settings(&app.state), settings(kept.path()));
    app.quit();
    let args = ["--size", "1024x768", "--ui-scale", "2", "--lang", "pt-BR"];
    let again = Sandbox::start_with_state(&x, &args, kept.path());
    let s = again.wait_frames(3);
    assert_eq!(tab_content(&s)[3], tab_content(&set)[3], "the next start");
    again.quit();
}
