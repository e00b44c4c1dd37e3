//! The real window under Xvfb, driven with xdotool as a person would use it,
//! checked through the state dump (`--dump-state`) and screenshots.
//!
//! Needs the Debian packages xvfb, libgl1-mesa-dri, libxi6, libxkbcommon0 and
//! xdotool (`.ci/run` installs them). Without them the tests are reported as
//! ignored, with the reason; with `CI` set, a missing package is a failure.

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use serde_json::Value;
use std::process::Command;
use std::thread::sleep;
use std::time::Duration;

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "dragging_on_empty_space_launches_a_disc_along_the_drag",
            dragging_on_empty_space_launches_a_disc_along_the_drag,
        ),
        (
            "wheel_zooms_at_the_cursor_and_grabbing_works_at_any_zoom",
            wheel_zooms_at_the_cursor_and_grabbing_works_at_any_zoom,
        ),
        (
            "space_pauses_n_steps_once_and_y_switches_the_method",
            space_pauses_n_steps_once_and_y_switches_the_method,
        ),
        (
            "screenshot_saves_the_frame_as_a_png",
            screenshot_saves_the_frame_as_a_png,
        ),
        (
            "edges_are_smoothed_unless_the_window_is_told_not_to",
            edges_are_smoothed_unless_the_window_is_told_not_to,
        ),
        (
            "a_gas_of_many_discs_opens_draws_them_and_reports_frame_times",
            a_gas_of_many_discs_opens_draws_them_and_reports_frame_times,
        ),
        (
            "an_idle_window_sleeps_and_wakes_at_the_first_key",
            an_idle_window_sleeps_and_wakes_at_the_first_key,
        ),
        (
            "switching_an_impulse_pile_to_exact_says_what_it_separated",
            switching_an_impulse_pile_to_exact_says_what_it_separated,
        ),
    ])
}

fn dragging_on_empty_space_launches_a_disc_along_the_drag() {
    let x = Xvfb::start("launch");
    let app = Sandbox::start(&x, &[&asset("empty.toml"), "--paused"]);
    let view = View::of(&app.state());
    let (from, to) = ([400.0, 450.0], [640.0, 330.0]); // right and up on screen
    app.drag(from, to);
    let s = app.wait_frames(3);

    let discs = s["particles"].as_array().unwrap();
    assert_eq!(discs.len(), 1, "one disc launched");
    let (pos, vel) = (vec2(&discs[0]["pos"]), vec2(&discs[0]["vel"]));
    let (start, end) = (view.to_world(from), view.to_world(to));
    for k in 0..2 {
        assert!(
            (pos[k] - start[k]).abs() < 1e-9,
            "launched where pressed: {pos:?} vs {start:?}"
        );
        // The interaction module's gain: 1.5 m/s per metre of drag.
        let want = 1.5 * (end[k] - start[k]);
        assert!(
            (vel[k] - want).abs() < 1e-9,
            "velocity follows the drag: {vel:?}"
        );
    }
    assert!(
        vel[0] > 0.0 && vel[1] > 0.0,
        "screen right-and-up is world +x, +y: {vel:?}"
    );
    assert_eq!(s["selected"], 0, "the new disc is selected");

    // Running again moves it along its velocity.
    app.xdo(&["key", "space"]);
    let later = app.wait_frames(10);
    assert_eq!(later["paused"], false);
    let moved = vec2(&later["particles"][0]["pos"]);
    assert!(
        moved[0] > pos[0] && moved[1] > pos[1],
        "{pos:?} -> {moved:?}"
    );
    app.quit();
}

fn wheel_zooms_at_the_cursor_and_grabbing_works_at_any_zoom() {
    let x = Xvfb::start("zoom");
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_file(
        dir.path(),
        "[world]\nsize = [16.0, 10.0]\n[[particles]]\npos = [8.0, 5.0]\nmass = 1.0\nradius = 0.5\n",
    );
    let app = Sandbox::start(&x, &[scene.to_str().unwrap(), "--paused"]);
    let before = View::of(&app.state());
    // The cursor sits on whole pixels: anchor the world point under one.
    let anchor = before.to_screen([9.0, 5.5]).map(f64::round);
    let anchor_world = before.to_world(anchor);
    app.move_to(anchor);
    app.wait_frames(2);
    for _ in 0..4 {
        app.xdo(&["click", "4"]);
        app.wait_frames(1);
    }
    let zoomed = View::of(&app.wait_frames(2));
    assert!(
        zoomed.scale > before.scale * 1.5,
        "wheel up zooms in: {} -> {}",
        before.scale,
        zoomed.scale
    );
    let still = zoomed.to_world(anchor);
    assert!(
        (still[0] - anchor_world[0]).abs() < 1e-6 && (still[1] - anchor_world[1]).abs() < 1e-6,
        "the point under the cursor stays put: {still:?}"
    );

    // Grab the disc off-centre where it is drawn now, and fling it right.
    let grab_world = [8.3, 5.2];
    let grab = zoomed.to_screen(grab_world);
    app.move_to(grab);
    app.wait_frames(2);
    app.xdo(&["mousedown", "1"]);
    app.wait_frames(2);
    let release = [grab[0] + 150.0, grab[1]];
    for k in 1..=4 {
        app.move_to([grab[0] + 15.0 * k as f64, grab[1]]);
        sleep(Duration::from_millis(25));
    }
    let held = app.wait_frames(1);
    assert_eq!(held["held"], 0, "the disc under the cursor was grabbed");
    // Keep moving up to the release, as a fling does: a cursor that rests
    // before letting go drops the disc at rest.
    for k in 5..=9 {
        app.move_to([grab[0] + 15.0 * k as f64, grab[1]]);
        sleep(Duration::from_millis(25));
    }
    // The last move and the release in one xdotool call: two calls can be
    // far enough apart (process start-up) for the cursor to seem to rest.
    let last = [
        release[0].round().to_string(),
        release[1].round().to_string(),
    ];
    app.xdo(&["mousemove", &last[0], &last[1], "mouseup", "1"]);
    let s = app.wait_frames(2);
    assert_eq!(s["held"], Value::Null);
    assert_eq!(s["selected"], 0);
    let disc = &s["particles"][0];
    let (pos, vel) = (vec2(&disc["pos"]), vec2(&disc["vel"]));
    let target = zoomed.to_world(release);
    let offset = [8.0 - grab_world[0], 5.0 - grab_world[1]];
    for k in 0..2 {
        assert!(
            (pos[k] - (target[k] + offset[k])).abs() < 1e-6,
            "the disc kept its grab offset: {pos:?}"
        );
    }
    assert!(vel[0] > 0.0, "flung to the right: {vel:?}");
    app.quit();
}

fn space_pauses_n_steps_once_and_y_switches_the_method() {
    let x = Xvfb::start("pause");
    let app = Sandbox::start(&x, &[]);
    let running = app.wait_frames(5);
    assert_eq!(running["paused"], false);
    assert!(
        running["time"].as_f64().unwrap() > 0.0,
        "the default scene runs"
    );
    app.move_to([640.0, 400.0]);
    app.xdo(&["key", "space"]);
    let paused = app.wait_frames(3);
    assert_eq!(paused["paused"], true);
    let held = app.wait_frames(10);
    assert_eq!(held["steps"], paused["steps"], "no steps while paused");
    assert_eq!(
        held["particles"], paused["particles"],
        "nothing moves while paused"
    );
    app.xdo(&["key", "n"]);
    let stepped = app.wait_frames(3);
    assert_eq!(
        stepped["steps"].as_u64(),
        paused["steps"].as_u64().map(|s| s + 1),
        "N runs one step"
    );
    app.xdo(&["key", "space"]);
    let resumed = app.wait_frames(10);
    assert!(
        resumed["steps"].as_u64() > stepped["steps"].as_u64(),
        "Space resumes"
    );

    // Y cycles the method live: auto -> seed -> impulse -> verlet -> exact.
    assert_eq!(resumed["method"], "auto", "scenes default to auto");
    for want in ["seed", "impulse", "verlet", "exact"] {
        app.xdo(&["key", "y"]);
        let s = app.wait_frames(4);
        assert_eq!(s["method"], want);
        assert_eq!(s["plan"]["method"], want, "the steps use it");
    }
    let last = app.quit();
    assert!(last["metrics"]["count"].as_u64().unwrap() > 2);
}

fn screenshot_saves_the_frame_as_a_png() {
    let x = Xvfb::start("screenshot");
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("shot.png");
    let status = Command::new(env!("CARGO_BIN_EXE_impulse"))
        .args(["--exit-after", "2", "--screenshot"])
        .arg(&png)
        .env("DISPLAY", &x.display)
        .status()
        .expect("impulse runs");
    assert!(status.success());
    let img = image::open(&png).expect("a readable PNG").to_rgb8();
    assert_eq!(img.dimensions(), (1280, 800));
    let background = *img.get_pixel(640, 790);
    let differing = img.pixels().filter(|p| **p != background).count();
    assert!(
        differing > 20_000,
        "the frame shows discs and text, {differing} pixels differ"
    );
}

/// As shipped, the window asks for 4 samples per pixel (discs' and lines'
/// edges smoothed); `--no-antialias`, which the other window tests use,
/// asks for none. The dump says what OpenGL gave.
fn edges_are_smoothed_unless_the_window_is_told_not_to() {
    let x = Xvfb::start("samples");
    let shipped = Sandbox::start_as_shipped(&x, &["--paused"]);
    let samples = shipped.wait_frames(2)["samples"].as_i64();
    assert!(samples.is_some_and(|n| n >= 2), "as shipped: {samples:?}");
    shipped.quit();
    let plain = Sandbox::start(&x, &["--paused"]);
    let samples = plain.wait_frames(2)["samples"].as_i64();
    assert!(
        samples.is_some_and(|n| n <= 1),
        "--no-antialias: {samples:?}"
    );
    plain.quit();
}

fn a_gas_of_many_discs_opens_draws_them_and_reports_frame_times() {
    let x = Xvfb::start("gas");
    let dir = tempfile::tempdir().unwrap();
    let (csv, png) = (dir.path().join("times.csv"), dir.path().join("gas.png"));
    // The frame times a person would see: edges smoothed.
    let app = Sandbox::start_as_shipped(
        &x,
        &[
            "--gas",
            "10000",
            "--paused",
            "--frame-stats",
            csv.to_str().unwrap(),
            "--screenshot",
            png.to_str().unwrap(),
        ],
    );
    let s = app.wait_frames(8);
    assert_eq!(s["metrics"]["count"], 10000);
    assert_eq!(s["scene_name"], "Gas of 10000 discs");
    assert_eq!(s["scene_origin"], "--gas 10000");
    for setting in ["method", "broad_phase", "substeps"] {
        assert_eq!(s[setting], "auto", "a big gas must not open on brute force");
    }
    let timing = &s["timing"];
    assert!(timing["frames"].as_u64().unwrap() >= 8, "{timing}");
    let ms = |k: &str| timing[k].as_f64().unwrap();
    assert!(ms("frame_ms") > 0.0 && ms("draw_ms") > 0.0 && ms("present_ms") > 0.0);
    assert!(ms("frame_ms") >= ms("draw_ms"), "{timing}");

    // A disc picked out of the crowd gets its values beside it, over its
    // neighbours, rather than a notice that there is no room.
    let view = View::of(&s);
    app.click(view.to_screen(vec2(&s["particles"][0]["pos"])));
    let s = app.wait_frames(3);
    assert_eq!(s["selected"], 0, "a click on a disc picks it");
    assert_eq!(
        s["readouts_shown"],
        serde_json::json!([1, 1]),
        "the picked disc's values are drawn"
    );

    // A quick fling: the press on a disc and the move away reach the window
    // within one of its slow frames. The press takes the disc where the
    // button went down, not where the pointer had got to by the frame
    // (that would launch a new disc, or take another one).
    let view = View::of(&s);
    let middle = view.to_world(view.world_center());
    let nearest = |s: &serde_json::Value| {
        let parts = s["particles"].as_array().unwrap();
        (0..parts.len())
            .min_by(|&a, &b| {
                let d = |i: usize| {
                    let p = vec2(&parts[i]["pos"]);
                    (p[0] - middle[0]).hypot(p[1] - middle[1])
                };
                d(a).total_cmp(&d(b))
            })
            .unwrap()
    };
    let flung = nearest(&s);
    let from = view.to_screen(vec2(&s["particles"][flung]["pos"]));
    app.move_to(from);
    app.wait_frames(1);
    let to = [from[0] + 80.0, from[1] + 40.0];
    app.xdo(&[
        "mousedown",
        "1",
        "mousemove",
        &format!("{}", to[0].round()),
        &format!("{}", to[1].round()),
    ]);
    app.wait_frames(2);
    app.xdo(&["mouseup", "1"]);
    let s = app.wait_frames(2);
    assert_eq!(s["metrics"]["count"], 10000, "a fling launches nothing");
    assert_eq!(s["selected"], flung, "the disc pressed is the one flung");
    let at = view.to_screen(vec2(&s["particles"][flung]["pos"]));
    assert!(
        (at[0] - to[0]).hypot(at[1] - to[1]) < 3.0,
        "the flung disc is let go where the pointer was: {at:?}, not {to:?}"
    );
    let last = app.quit();

    let text = std::fs::read_to_string(&csv).expect("the frame times were written");
    let mut rows = text.lines();
    assert_eq!(
        rows.next(),
        Some("frame,discs,velocity,momentum,readouts,steps,frame_ms,step_ms,draw_ms,present_ms")
    );
    let rows: Vec<Vec<&str>> = rows.map(|r| r.split(',').collect()).collect();
    assert!(rows.len() as u64 + 1 >= last["frame"].as_u64().unwrap());
    assert!(rows.iter().all(|r| r.len() == 10 && r[1] == "10000"));
    assert!(rows.iter().all(|r| r[5] == "0"), "paused: no physics steps");

    // The discs are on screen: thousands of pixels in the palette's colours.
    let img = image::open(&png).expect("a readable PNG").to_rgb8();
    let palette: Vec<[u8; 3]> = (0..8)
        .map(|i| {
            let c = impulse::Color::palette(i);
            [c.r, c.g, c.b]
        })
        .collect();
    let coloured = img.pixels().filter(|p| palette.contains(&p.0)).count();
    assert!(coloured > 30_000, "{coloured} pixels in disc colours");
}

/// The CPU time (user + system, s) process `pid` has used so far.
fn cpu_seconds(pid: u32) -> f64 {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).expect("/proc/PID/stat");
    // The fields after the command name, which is in parentheses.
    let rest = &stat[stat.rfind(')').expect("a stat line") + 2..];
    let fields: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = fields[11].parse::<f64>().unwrap() + fields[12].parse::<f64>().unwrap();
    let hz = Command::new("getconf")
        .arg("CLK_TCK")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .and_then(|s| s.trim().parse::<f64>().ok())
        .unwrap_or(100.0);
    ticks / hz
}

/// Paused, the window stops drawing after a second: at most one frame a
/// second and under a tenth of a core; a key then answers at once, not at
/// the next timer frame; running, it draws at its full rate again; and a
/// running scene where nothing moves sleeps too.
fn an_idle_window_sleeps_and_wakes_at_the_first_key() {
    let x = Xvfb::start("idle");
    let app = Sandbox::start(&x, &[&asset("preset-1-head-on.toml"), "--paused"]);
    let deadline = std::time::Instant::now() + Duration::from_secs(10);
    while app.state()["sleeping"] != true {
        assert!(std::time::Instant::now() < deadline, "never went idle");
        sleep(Duration::from_millis(50));
    }
    let (before, cpu_before) = (app.state(), cpu_seconds(app.child.id()));
    let span = 6.0;
    sleep(Duration::from_secs_f64(span));
    let (after, cpu_after) = (app.state(), cpu_seconds(app.child.id()));
    let frames = after["frame"].as_u64().unwrap() - before["frame"].as_u64().unwrap();
    assert!(
        frames as f64 <= span + 2.0,
        "{frames} frames in {span} s while idle"
    );
    assert!(frames >= 3, "the idle timer still draws ({frames} frames)");
    let share = (cpu_after - cpu_before) / span;
    assert!(
        share < 0.10,
        "idle, the window used {:.1} % of a core",
        share * 100.0
    );

    // A key after a long idle: seen well before the next timer frame. It is
    // pressed as a timer frame is drawn (just after its dump is written), the
    // moment a key used to wait for the next one.
    let frame = after["frame"].as_u64().unwrap();
    while app.state()["frame"].as_u64().unwrap() == frame {
        sleep(Duration::from_millis(2));
    }
    let pressed = std::time::Instant::now();
    app.xdo(&["key", "space"]);
    let answered = loop {
        let s = app.state();
        if s["paused"] == false {
            break pressed.elapsed();
        }
        assert!(
            pressed.elapsed() < Duration::from_secs(5),
            "Space was not seen"
        );
        sleep(Duration::from_millis(10));
    };
    assert!(
        answered < Duration::from_millis(500),
        "Space answered after {answered:?}"
    );
    let start = app.state();
    sleep(Duration::from_secs(1));
    let later = app.state();
    let drawn = later["frame"].as_u64().unwrap() - start["frame"].as_u64().unwrap();
    assert!(drawn >= 20, "running, {drawn} frames in a second");
    assert_eq!(later["sleeping"], false);
    drop(app);

    // Running, but nothing to move: asleep as well.
    let still = Sandbox::start(&x, &[&asset("empty.toml")]);
    let deadline = std::time::Instant::now() + Duration::from_secs(10);
    while still.state()["sleeping"] != true {
        assert!(
            std::time::Instant::now() < deadline,
            "an empty scene never went idle"
        );
        sleep(Duration::from_millis(50));
    }
    assert_eq!(still.state()["paused"], false);
}

fn switching_an_impulse_pile_to_exact_says_what_it_separated() {
    // The pile preset under impulse, whose resting discs overlap a little.
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("pile-impulse.toml");
    let text = std::fs::read_to_string(asset("preset-0-pile.toml")).unwrap();
    assert!(
        !text.contains("[simulation]"),
        "the preset leaves the method to auto"
    );
    let text = format!("{text}\n[simulation]\nmethod = \"impulse\"\n");
    std::fs::write(&scene, text).unwrap();
    let x = Xvfb::start("takeover");
    let app = Sandbox::start(&x, &[scene.to_str().unwrap()]);
    app.wait_for("two seconds of settling", 2_000, |s| {
        s["time"].as_f64().unwrap() > 2.0
    });
    assert_eq!(app.state()["plan"]["method"], "impulse");
    app.move_to([640.0, 400.0]);
    // Y: impulse -> verlet -> exact (one press a frame: two in one frame
    // are one press).
    for want in ["verlet", "exact"] {
        app.xdo(&["key", "y"]);
        app.wait_for(want, 60, |s| s["method"] == want);
    }
    let s = app.wait_for("exact's message", 60, |s| {
        s["plan"]["method"] == "exact"
            && s["ui"]["message"]
                .as_str()
                .is_some_and(|m| m.starts_with("The exact method"))
    });
    let message = s["ui"]["message"].as_str().unwrap();
    assert!(
        message.starts_with("The exact method needs discs apart: it separated ")
            && message.contains(" overlapping pairs of discs"),
        "{message}"
    );
    // Lifting discs off the floor raises the energy: the number is positive.
    let joules: f64 = message
        .rsplit("raised the energy by ")
        .next()
        .and_then(|t| t.strip_suffix(" J"))
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("an energy in {message:?}"));
    assert!(joules > 0.0, "{message}");
    app.quit();
}
