//! The classroom in the real window under Xvfb: presets and saving, the
//! side panel, running to the next collision, rewinding, exporting, and
//! aiming a disc by its velocity arrow (see `window.rs` for the packages).

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use impulse::Scene;
use std::path::PathBuf;

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "number_keys_open_presets_and_ctrl_s_saves_a_scene_that_reopens_exactly",
            number_keys_open_presets_and_ctrl_s_saves_a_scene_that_reopens_exactly,
        ),
        (
            "the_side_panel_opens_scene_files_keeps_the_scene_on_a_bad_one_and_sets_restitution",
            the_side_panel_opens_scene_files_keeps_the_scene_on_a_bad_one_and_sets_restitution,
        ),
        (
            "j_stops_at_the_next_collision_comma_rewinds_space_resumes_and_x_exports",
            j_stops_at_the_next_collision_comma_rewinds_space_resumes_and_x_exports,
        ),
        (
            "dragging_the_selected_discs_arrow_tip_sets_its_velocity",
            dragging_the_selected_discs_arrow_tip_sets_its_velocity,
        ),
        (
            "the_spin_preset_opens_from_the_menu_and_leaves_the_wall_at_its_captions_angle",
            the_spin_preset_opens_from_the_menu_and_leaves_the_wall_at_its_captions_angle,
        ),
    ])
}

fn number_keys_open_presets_and_ctrl_s_saves_a_scene_that_reopens_exactly() {
    let x = Xvfb::start("presets");
    let out = tempfile::tempdir().expect("temp dir");
    let out_dir = out.path().to_str().expect("utf-8 temp path").to_string();
    let app = Sandbox::start(&x, &["--paused", "--out", &out_dir]);
    app.move_to([640.0, 400.0]);

    // Key 2 opens "heavy hits light", exactly as its file builds.
    app.xdo(&["key", "2"]);
    let opened = app.wait_frames(3);
    let path = "assets/scenes/preset-2-heavy-hits-light.toml";
    assert_eq!(opened["scene_origin"], path);
    let text = std::fs::read_to_string(asset("preset-2-heavy-hits-light.toml")).unwrap();
    let built = Scene::parse(&text, path).unwrap().build(path).unwrap();
    assert_eq!(
        opened["particles"],
        serde_json::to_value(&built.particles).unwrap()
    );

    // Let it run into the collision, pause, save.
    app.xdo(&["key", "space"]);
    app.wait_frames(30);
    app.xdo(&["key", "space"]);
    let paused = app.wait_frames(3);
    assert!(paused["time"].as_f64().unwrap() > 0.0);
    app.xdo(&["key", "ctrl+s"]);
    let after_save = app.wait_frames(3);
    assert_eq!(after_save["paused"], true);
    assert_eq!(after_save["steps"], paused["steps"], "no step while paused");
    let saved = saved_scenes(out.path());
    assert_eq!(saved.len(), 1, "one scene saved in {out_dir}: {saved:?}");
    let reloaded = Scene::load(&saved[0]).unwrap().build("saved").unwrap();
    assert_eq!(
        serde_json::to_value(&reloaded.particles).unwrap(),
        after_save["particles"],
        "the saved file holds the state bit for bit"
    );
    app.quit();

    // Reopening it shows the same discs.
    let saved_path = saved[0].to_str().unwrap().to_string();
    let again = Sandbox::start(&x, &["--paused", &saved_path]);
    let reopened = again.wait_frames(3);
    assert_eq!(reopened["particles"], after_save["particles"]);
    assert_eq!(reopened["dt"], paused["dt"]);
    again.quit();
}

fn the_side_panel_opens_scene_files_keeps_the_scene_on_a_bad_one_and_sets_restitution() {
    let x = Xvfb::start("panel");
    let dir = tempfile::tempdir().unwrap();
    // The names hold keys that must not act while typed: '1' opens a
    // preset, 'c' clears the discs, 'r' resets, 'e' changes restitution.
    let good = dir.path().join("good-scene-1-cr.toml");
    std::fs::write(
        &good,
        "name = \"Good\"\n[world]\nsize = [16.0, 10.0]\n\
         [[particles]]\npos = [4.0, 5.0]\nmass = 1.0\nradius = 0.5\n\
         [[particles]]\npos = [9.0, 5.0]\nmass = 2.0\nradius = 0.6\n",
    )
    .unwrap();
    let bad = dir.path().join("bad-scene-1-cr.toml");
    std::fs::write(&bad, "name = \"Bad\"\n[world]\nsize = [16.0, 10.0\n").unwrap();
    let out = tempfile::tempdir().unwrap();
    let out_dir = out.path().to_str().expect("utf-8 temp path");
    let app = Sandbox::start(&x, &["--paused", "--out", out_dir]);
    let s0 = app.wait_frames(2);
    assert_eq!(s0["panel_visible"], true, "the panel is shown by default");
    let world = &s0["layout"]["world"];
    let world_right = world[0].as_f64().unwrap() + world[2].as_f64().unwrap();
    let right_wall = View::of(&s0).to_screen(vec2(&s0["size"]))[0];
    assert!(
        right_wall < world_right,
        "the fit leaves the box clear of the panel: wall at {right_wall}, world ends at {world_right}"
    );
    let click = |at: [f64; 2]| {
        app.move_to(at);
        app.wait_frames(1);
        app.xdo(&["mousedown", "1"]);
        app.wait_frames(1);
        app.xdo(&["mouseup", "1"]);
        app.wait_frames(2);
    };
    // Fold "Show" and open "Scene", so the file field is in view.
    // (Each click waits for the sections to stop sliding: on a loaded
    // machine two frames were not always enough, and a click missed.)
    click(widget(&s0, "section_show", 0.5));
    let s = app.wait_still();
    click(widget(&s, "section_scene", 0.5));
    app.wait_for("the Scene section to open", 120, |s| {
        s["panel_widgets"]["scene_path"].is_array()
    });
    let s0 = app.wait_still();
    let field = widget(&s0, "scene_path", 0.5);
    assert!(field[1] < 800.0, "the field is on screen: {field:?}");

    // Type the good file's path into the (empty) scene field; Enter opens it.
    click(widget(&s0, "scene_path", 0.5));
    app.xdo(&["type", "--delay", "30", good.to_str().unwrap()]);
    app.wait_frames(2);
    app.xdo(&["key", "Return"]);
    let s1 = app.wait_frames(3);
    assert_eq!(
        s1["scene_origin"],
        good.to_str().unwrap(),
        "opened from the panel"
    );
    assert_eq!(s1["particles"].as_array().unwrap().len(), 2);
    assert_eq!(s1["restitution"], 1.0);
    assert_eq!(s1["gravity"], serde_json::json!([0.0, 0.0]));

    // Drag the restitution slider's handle from the right end to a quarter.
    app.move_to(widget(&s1, "restitution", 1.0));
    app.wait_frames(2);
    app.xdo(&["mousedown", "1"]);
    app.wait_frames(2);
    for t in [0.8, 0.6, 0.4, 0.25] {
        app.move_to(widget(&s1, "restitution", t));
        app.wait_frames(1);
    }
    app.xdo(&["mouseup", "1"]);
    let s2 = app.wait_frames(3);
    let e = s2["restitution"].as_f64().unwrap();
    // egui's handle travels the track inset by its radius (height / 2.5).
    let track = &s1["panel_widgets"]["restitution"];
    let (w, h) = (track[2].as_f64().unwrap(), track[3].as_f64().unwrap());
    let inset = h / 2.5;
    let want = (0.25 * w - inset) / (w - 2.0 * inset);
    assert!(
        (e - want).abs() <= 0.015,
        "restitution follows the slider: {e}, want {want:.3}"
    );
    assert_eq!(s2["wall_restitution"], s1["wall_restitution"]);
    assert_eq!(
        s2["particles"], s1["particles"],
        "a drag on the panel launches no disc"
    );

    // Replace the path (Ctrl+A, then type) with the bad file's; press Open.
    click(widget(&s2, "scene_path", 0.5));
    app.xdo(&["keydown", "ctrl"]);
    app.wait_frames(1);
    app.xdo(&["key", "a"]);
    app.wait_frames(1);
    app.xdo(&["keyup", "ctrl"]);
    app.wait_frames(1);
    app.xdo(&["type", "--delay", "30", bad.to_str().unwrap()]);
    app.wait_frames(2);
    // Ctrl+S in the path's field saves the scene, as anywhere; it opens
    // nothing (Enter there would open the file typed).
    app.xdo(&["key", "ctrl+s"]);
    let saved = app.wait_frames(3);
    assert_eq!(
        saved_scenes(out.path()).len(),
        1,
        "Ctrl+S in the path's field saved into {out_dir}"
    );
    assert_eq!(
        saved["scene_origin"], s1["scene_origin"],
        "and opened nothing"
    );
    click(widget(&s2, "open", 0.5));
    let s3 = app.wait_frames(3);
    assert_eq!(
        s3["scene_origin"], s1["scene_origin"],
        "a bad file keeps the current scene"
    );
    assert_eq!(s3["particles"], s2["particles"]);
    assert_eq!(
        s3["restitution"], s2["restitution"],
        "nothing typed acted as a key"
    );
    assert_eq!(s3["paused"], true);

    // Enter in a field gave the panel the keyboard; a click in the world
    // gives it back, and keys are shortcuts again: L hides the panel.
    assert_eq!(s3["ui"]["panel_keyboard"], true);
    click([300.0, 300.0]);
    app.xdo(&["key", "l"]);
    let s4 = app.wait_frames(3);
    assert_eq!(s4["panel_visible"], false);
    for gone in ["scene_path", "restitution", "open"] {
        assert!(
            s4["panel_widgets"].get(gone).is_none(),
            "{gone} still drawn"
        );
    }
    app.quit();
}

fn j_stops_at_the_next_collision_comma_rewinds_space_resumes_and_x_exports() {
    let x = Xvfb::start("lesson");
    let out = tempfile::tempdir().expect("temp dir");
    let out_dir = out.path().to_str().expect("utf-8 temp path").to_string();
    let app = Sandbox::start(&x, &["--paused", "--out", &out_dir]);
    app.move_to([400.0, 400.0]);

    // Head-on: the discs touch when the gap between their edges has closed.
    app.xdo(&["key", "1"]);
    let opened = app.wait_frames(3);
    let p = &opened["particles"];
    let (a, b) = (&p[0], &p[1]);
    let gap = (vec2(&b["pos"])[0] - vec2(&a["pos"])[0]).abs()
        - a["radius"].as_f64().unwrap()
        - b["radius"].as_f64().unwrap();
    let closing = (vec2(&a["vel"])[0] - vec2(&b["vel"])[0]).abs();
    let contact = gap / closing;
    app.xdo(&["key", "j"]);
    let hit = app.wait_for("the newest impact's table", 60, |s| {
        s["panel_widgets"]["ledger_total_p"].is_array()
    });
    assert_eq!(hit["paused"], true);
    assert_eq!(hit["collisions_recorded"], 1);
    let t = hit["time"].as_f64().unwrap();
    assert!(
        (t - contact).abs() < 1e-9,
        "stopped at t = {t}, contact at {contact}"
    );
    // The Collisions tab opened on the impact shows, without scrolling,
    // the two discs' momenta and their total before and after (under the
    // count and a heading, the total had been out of sight).
    let (total, tab) = (
        rect(&hit["panel_widgets"]["ledger_total_p"]),
        tab_content(&hit),
    );
    assert!(
        total[1] >= tab[1] - 0.5 && total[1] + total[3] <= tab[1] + tab[3] + 0.5,
        "the total momentum's row {total:?} in the tab {tab:?}"
    );

    // Rewind three snapshots: earlier, and the discs are back apart.
    for _ in 0..3 {
        app.xdo(&["key", "comma"]);
        app.wait_frames(2);
    }
    let back = app.wait_frames(2);
    assert!(back["history_cursor"].is_u64(), "rewound: {back}");
    assert!(back["time"].as_f64().unwrap() < t);
    assert_eq!(
        back["particles"].as_array().map(Vec::len),
        Some(2),
        "the rewind stays within the head-on scene"
    );

    // X exports three CSV files into the output folder.
    app.xdo(&["key", "x"]);
    app.wait_frames(3);
    let csv: Vec<PathBuf> = std::fs::read_dir(out.path())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "csv"))
        .collect();
    assert_eq!(csv.len(), 4, "totals, discs, collisions, walls: {csv:?}");

    // F12 saves what the window shows into the same folder.
    app.xdo(&["key", "F12"]);
    app.wait_frames(4);
    let png = out.path().join("head-on-equal-masses.png");
    let shot = image::open(&png)
        .unwrap_or_else(|e| panic!("{}: {e}", png.display()))
        .to_rgb8();
    assert_eq!(shot.dimensions(), (1280, 800));
    // And says where, in words of the window's language (they were English
    // whatever the language): the file's name alone, which a projector's
    // one line shows whole (the Scene section says where saves go).
    let said = app.wait_frames(1);
    assert_eq!(
        said["ui"]["message"], "Screenshot saved: head-on-equal-masses.png",
        "{}",
        said["ui"]
    );

    // Space resumes from the rewound moment and time runs on.
    app.xdo(&["key", "space"]);
    let resumed = app.wait_frames(20);
    assert_eq!(resumed["paused"], false);
    assert!(resumed["history_cursor"].is_null());
    assert!(resumed["time"].as_f64().unwrap() > back["time"].as_f64().unwrap());
    app.quit();
}

fn dragging_the_selected_discs_arrow_tip_sets_its_velocity() {
    let x = Xvfb::start("aim");
    let app = Sandbox::start(&x, &["--paused"]);
    app.move_to([300.0, 400.0]);
    // Glancing (in two dimensions: the head-on hit keeps to its line): the
    // first disc moves, at 0.5 s per arrow.
    app.xdo(&["key", "4"]);
    let s = app.wait_frames(3);
    let view = View::of(&s);
    let disc = &s["particles"][0];
    let (pos, vel) = (vec2(&disc["pos"]), vec2(&disc["vel"]));
    // Select it with a click on its centre.
    let centre = view.to_screen(pos);
    app.move_to(centre);
    app.xdo(&["click", "1"]);
    let selected = app.wait_frames(3);
    assert_eq!(selected["selected"], 0);
    // Drag its arrow's tip straight up by 60 px.
    let tip = view.to_screen([pos[0] + 0.5 * vel[0], pos[1] + 0.5 * vel[1]]);
    // Whole pixels: that is where xdotool puts the cursor.
    let target = [centre[0].round(), (centre[1] - 60.0).round()];
    app.drag(tip, target);
    let after = app.wait_frames(3);
    let d = &after["particles"][0];
    assert_eq!(vec2(&d["pos"]), pos, "aiming does not move the disc");
    let want = [
        (view.to_world(target)[0] - pos[0]) / 0.5,
        (view.to_world(target)[1] - pos[1]) / 0.5,
    ];
    let got = vec2(&d["vel"]);
    assert!(
        (got[0] - want[0]).abs() < 1e-9 && (got[1] - want[1]).abs() < 1e-9,
        "velocity {got:?}, expected {want:?}"
    );
    assert!(got[1] > 0.0, "dragged up on screen: +y in the world");
    app.quit();
}

/// The spin preset's place in the preset menu (after the ten digit keys'
/// presets and the π blocks at three more mass ratios).
const SPIN_PRESET: usize = 13;

fn the_spin_preset_opens_from_the_menu_and_leaves_the_wall_at_its_captions_angle() {
    let file = "preset-spin-off-a-wall.toml";
    let scene = Scene::load(std::path::Path::new(&asset(file))).unwrap();
    // The caption promises the angle: "... out at 63.4° to the floor."
    let caption = scene.description.clone().unwrap();
    let promised: f64 = caption
        .split("out at ")
        .nth(1)
        .and_then(|rest| rest.split('°').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no outgoing angle in the caption {caption:?}"));
    let decimals = 1;

    let x = Xvfb::start("spin preset");
    let app = Sandbox::start(&x, &["--paused"]);
    app.move_to([300.0, 300.0]);
    // P opens the menu; the wheel scrolls it until the preset is in view.
    app.xdo(&["key", "p"]);
    let s = app.wait_for("the preset menu", 60, |s| {
        s["panel_widgets"]["preset_menu"].is_array()
    });
    let name = format!("preset_{SPIN_PRESET}");
    let menu = s["panel_widgets"]["preset_menu"].clone();
    let centre = [
        menu[0].as_f64().unwrap() + 0.5 * menu[2].as_f64().unwrap(),
        menu[1].as_f64().unwrap() + 0.5 * menu[3].as_f64().unwrap(),
    ];
    app.move_to(centre);
    app.wait_frames(2);
    let in_view = |s: &serde_json::Value| {
        let (m, r) = (
            &s["panel_widgets"]["preset_menu"],
            &s["panel_widgets"][&name],
        );
        let (top, bottom) = (
            m[1].as_f64().unwrap(),
            m[1].as_f64().unwrap() + m[3].as_f64().unwrap(),
        );
        r[1].as_f64().unwrap() >= top && r[1].as_f64().unwrap() + r[3].as_f64().unwrap() <= bottom
    };
    let mut s = app.wait_frames(1);
    for _ in 0..60 {
        if in_view(&s) {
            break;
        }
        app.xdo(&["click", "5"]); // the wheel, down a notch
        s = app.wait_frames(3);
    }
    let s = app.wait_still();
    assert!(
        in_view(&s),
        "the wheel did not bring {name} into the menu's view"
    );
    app.click(widget(&s, &name, 0.5));
    let opened = app.wait_for("the spin preset to open", 60, |s| {
        s["scene_origin"] == format!("assets/scenes/{file}")
    });
    assert_eq!(opened["ui"]["presets_open"], false);
    assert_eq!(
        opened["spin_shown"], true,
        "spin lines and values are shown"
    );
    let disc = &opened["particles"][0];
    let spin = disc["spin"]
        .as_f64()
        .expect("the dump has each disc's spin");
    assert_eq!(spin, scene.particles[0].spin);
    let v_in = vec2(&disc["vel"]);
    let angle_in = v_in[1].abs().atan2(v_in[0].abs()).to_degrees();
    assert!((angle_in - 45.0).abs() < 1e-9, "in at {angle_in}°");
    let energy = opened["total_energy"].as_f64().unwrap();
    let m = &opened["metrics"];
    assert!(
        (m["kinetic_energy"].as_f64().unwrap() + m["rotational_energy"].as_f64().unwrap() - energy)
            .abs()
            < 1e-12
    );

    // Run it until the disc has left the floor (moving up), then pause.
    app.move_to([5.0, 5.0]);
    app.xdo(&["key", "space"]);
    let after = app.wait_for("the bounce off the floor", 3000, |s| {
        s["particles"][0]["vel"][1].as_f64().unwrap() > 0.0
    });
    app.xdo(&["key", "space"]);
    assert_eq!(after["wall_hits"], 1, "one hit, on the floor");
    let p = &after["particles"][0];
    let v = vec2(&p["vel"]);
    assert!(v[0] < 0.0, "the backspin sends it back: {v:?}");
    let angle_out = v[1].atan2(v[0].abs()).to_degrees();
    let shown = format!("{angle_out:.decimals$}");
    assert_eq!(
        shown.parse::<f64>().unwrap(),
        promised,
        "out at {angle_out}° to the floor; the caption says {promised}°"
    );
    assert!(
        (angle_out - promised).abs() <= 0.05,
        "{angle_out} vs {promised}"
    );
    // The spin is in the dump: the slip reversed, so it turns the other
    // way, and the disc has turned (its line with it).
    let spin_out = p["spin"].as_f64().unwrap();
    assert!(spin_out < 0.0, "spin after the bounce {spin_out}");
    assert!(p["angle"].as_f64().unwrap_or(0.0) != 0.0, "{p}");
    // The total energy shown includes the turning, and is kept (β = 1, e = 1).
    let m = &after["metrics"];
    assert!(m["rotational_energy"].as_f64().unwrap() > 0.0);
    assert!(m["angular_momentum"].is_number());
    let energy_out = after["total_energy"].as_f64().unwrap();
    assert!(
        (energy_out - energy).abs() < 1e-9 * energy,
        "energy {energy} before, {energy_out} after"
    );

    // Friction is switched on beside the roughness sliders, and undone as
    // a change of the laws.
    let s = app.wait_frames(2);
    assert!(s["friction"].is_null(), "no friction in the scene");
    assert!(s["panel_widgets"]["tangential_restitution"].is_array());
    app.click(widget(&s, "friction_on", 0.1));
    let s = app.wait_for("friction on", 30, |s| s["friction"].is_number());
    assert_eq!(s["friction"], 0.5);
    app.move_to([5.0, 5.0]);
    app.xdo(&["key", "ctrl+z"]);
    let s = app.wait_for("the undo", 30, |s| s["friction"].is_null());
    assert!(
        s["ui"]["message"]
            .as_str()
            .is_some_and(|m| m.contains("friction")),
        "{}",
        s["ui"]
    );
    app.quit();
}
