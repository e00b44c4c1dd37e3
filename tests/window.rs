//! The real window under Xvfb, driven with xdotool as a person would use it,
//! checked through the state dump (`--dump-state`) and screenshots.
//!
//! Needs the Debian packages xvfb, libgl1-mesa-dri, libxi6, libxkbcommon0 and
//! xdotool (`.ci/run` installs them). Without them the tests print why they
//! skip; with `CI` set, a missing package is a failure.

use impulse::Scene;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::Mutex;
use std::thread::sleep;
use std::time::{Duration, Instant};

/// One window at a time: two cores cannot render several at a usable rate.
static ONE_WINDOW: Mutex<()> = Mutex::new(());

fn have(program: &str) -> bool {
    Command::new("sh")
        .args(["-c", &format!("command -v {program}")])
        .stdout(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// A private X server; killed when dropped.
struct Xvfb {
    child: Child,
    display: String,
}

impl Xvfb {
    /// Starts one, or returns `None` (after saying why) when it cannot here.
    fn start(test: &str) -> Option<Xvfb> {
        let missing: Vec<&str> = ["Xvfb", "xdotool"]
            .into_iter()
            .filter(|p| !have(p))
            .collect();
        if !missing.is_empty() {
            let why = format!(
                "{test}: {} not installed (apt-get install xvfb xdotool)",
                missing.join(", ")
            );
            if std::env::var_os("CI").is_some() {
                panic!("CI is set, so the window tests must run: {why}");
            }
            eprintln!("SKIPPED {why}");
            return None;
        }
        // Xvfb picks a free display itself and writes its number on stdout
        // once it accepts connections (-displayfd), so stale lock files of
        // killed servers and parallel runs cannot collide.
        let mut child = Command::new("Xvfb")
            .args([
                "-displayfd",
                "1",
                "-screen",
                "0",
                "1280x800x24",
                "-nolisten",
                "tcp",
            ])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("Xvfb starts");
        let mut line = String::new();
        let stdout = child.stdout.take().expect("Xvfb's stdout");
        std::io::BufRead::read_line(&mut std::io::BufReader::new(stdout), &mut line)
            .expect("Xvfb reports its display");
        let number: u32 = line
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("Xvfb said {line:?}"));
        let display = format!(":{number}");
        // Ready means a client can connect: wait for xdotool to manage it
        // (on a loaded machine the first connections can still fail).
        let deadline = Instant::now() + Duration::from_secs(20);
        while !Command::new("xdotool")
            .arg("getmouselocation")
            .env("DISPLAY", &display)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
        {
            assert!(
                Instant::now() < deadline,
                "Xvfb {display} accepts no clients"
            );
            sleep(Duration::from_millis(100));
        }
        Some(Xvfb { child, display })
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        // SIGTERM lets Xvfb remove its socket and lock file; SIGKILL would not.
        let _ = Command::new("kill")
            .args(["-TERM", &self.child.id().to_string()])
            .status();
        let _ = self.child.wait();
    }
}

/// The `impulse` window running on an Xvfb display.
struct Sandbox {
    child: Child,
    dump: PathBuf,
    display: String,
    _dir: tempfile::TempDir,
}

impl Sandbox {
    fn start(x: &Xvfb, args: &[&str]) -> Sandbox {
        let dir = tempfile::tempdir().expect("temp dir");
        let dump = dir.path().join("state.json");
        let child = Command::new(env!("CARGO_BIN_EXE_impulse"))
            .args(args)
            .arg("--dump-state")
            .arg(&dump)
            .args(["--exit-after", "120"])
            .env("DISPLAY", &x.display)
            .stdout(Stdio::null())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("impulse starts");
        let sandbox = Sandbox {
            child,
            dump,
            display: x.display.clone(),
            _dir: dir,
        };
        sandbox.wait_frames(5);
        sandbox
    }

    /// The latest state dump.
    fn state(&self) -> Value {
        let deadline = Instant::now() + Duration::from_secs(60);
        loop {
            if let Ok(text) = std::fs::read_to_string(&self.dump) {
                if let Ok(v) = serde_json::from_str(&text) {
                    return v;
                }
            }
            assert!(
                Instant::now() < deadline,
                "no state dump appeared at {}",
                self.dump.display()
            );
            sleep(Duration::from_millis(50));
        }
    }

    /// Waits until `n` more frames have been drawn, and returns the state.
    fn wait_frames(&self, n: u64) -> Value {
        let start = self.state()["frame"].as_u64().unwrap_or(0);
        let deadline = Instant::now() + Duration::from_secs(60);
        loop {
            let s = self.state();
            if s["frame"].as_u64().unwrap_or(0) >= start + n {
                return s;
            }
            assert!(
                Instant::now() < deadline,
                "the window stopped drawing frames"
            );
            sleep(Duration::from_millis(20));
        }
    }

    fn xdo(&self, args: &[&str]) {
        let status = Command::new("xdotool")
            .args(args)
            .env("DISPLAY", &self.display)
            .status()
            .expect("xdotool runs");
        assert!(status.success(), "xdotool {args:?} failed");
    }

    fn move_to(&self, p: [f64; 2]) {
        self.xdo(&[
            "mousemove",
            &format!("{}", p[0].round()),
            &format!("{}", p[1].round()),
        ]);
    }

    /// Presses Ctrl+Q and returns the final state once the window has closed.
    fn quit(mut self) -> Value {
        self.xdo(&["key", "ctrl+q"]);
        let deadline = Instant::now() + Duration::from_secs(30);
        loop {
            if let Some(status) = self.child.try_wait().expect("wait") {
                assert!(status.success(), "impulse exited with {status}");
                return self.state();
            }
            assert!(Instant::now() < deadline, "Ctrl+Q did not close the window");
            sleep(Duration::from_millis(50));
        }
    }
}

impl Drop for Sandbox {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The camera of a dump: world point → screen pixel and back.
struct View {
    center: [f64; 2],
    scale: f64,
    viewport: [f64; 2],
}

impl View {
    fn of(state: &Value) -> View {
        let c = &state["camera"];
        let pair = |v: &Value| [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()];
        View {
            center: pair(&c["center"]),
            scale: c["scale"].as_f64().unwrap(),
            viewport: pair(&c["viewport"]),
        }
    }
    fn to_screen(&self, w: [f64; 2]) -> [f64; 2] {
        [
            self.viewport[0] / 2.0 + (w[0] - self.center[0]) * self.scale,
            self.viewport[1] / 2.0 - (w[1] - self.center[1]) * self.scale,
        ]
    }
    fn to_world(&self, s: [f64; 2]) -> [f64; 2] {
        [
            self.center[0] + (s[0] - self.viewport[0] / 2.0) / self.scale,
            self.center[1] - (s[1] - self.viewport[1] / 2.0) / self.scale,
        ]
    }
}

fn vec2(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

fn scene_file(dir: &Path, text: &str) -> PathBuf {
    let path = dir.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    path
}

fn asset(name: &str) -> String {
    format!("{}/assets/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn dragging_on_empty_space_launches_a_disc_along_the_drag() {
    let _one = ONE_WINDOW.lock().unwrap_or_else(|e| e.into_inner());
    let Some(x) = Xvfb::start("launch") else {
        return;
    };
    let app = Sandbox::start(&x, &[&asset("empty.toml"), "--paused"]);
    let view = View::of(&app.state());
    let (from, to) = ([400.0, 450.0], [640.0, 330.0]); // right and up on screen
    app.move_to(from);
    app.wait_frames(2);
    app.xdo(&["mousedown", "1"]);
    app.wait_frames(2);
    for k in 1..=6 {
        let t = k as f64 / 6.0;
        app.move_to([
            from[0] + t * (to[0] - from[0]),
            from[1] + t * (to[1] - from[1]),
        ]);
        sleep(Duration::from_millis(30));
    }
    app.wait_frames(2);
    app.xdo(&["mouseup", "1"]);
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

#[test]
fn wheel_zooms_at_the_cursor_and_grabbing_works_at_any_zoom() {
    let _one = ONE_WINDOW.lock().unwrap_or_else(|e| e.into_inner());
    let Some(x) = Xvfb::start("zoom") else { return };
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
    for k in 5..=10 {
        app.move_to([grab[0] + 15.0 * k as f64, grab[1]]);
        sleep(Duration::from_millis(25));
    }
    app.xdo(&["mouseup", "1"]);
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

#[test]
fn space_pauses_n_steps_once_and_y_switches_the_method() {
    let _one = ONE_WINDOW.lock().unwrap_or_else(|e| e.into_inner());
    let Some(x) = Xvfb::start("pause") else {
        return;
    };
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

#[test]
fn screenshot_saves_the_frame_as_a_png() {
    let _one = ONE_WINDOW.lock().unwrap_or_else(|e| e.into_inner());
    let Some(x) = Xvfb::start("screenshot") else {
        return;
    };
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

#[test]
fn number_keys_open_presets_and_ctrl_s_saves_a_scene_that_reopens_exactly() {
    let _one = ONE_WINDOW.lock().unwrap_or_else(|e| e.into_inner());
    let Some(x) = Xvfb::start("presets") else {
        return;
    };
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
    let saved: Vec<PathBuf> = std::fs::read_dir(out.path())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
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

/// The centre of a rectangle [x, y, width, height] the dump gives for a
/// widget of the side panel, or a point a fraction `t` along its width.
fn widget(state: &Value, name: &str, t: f64) -> [f64; 2] {
    let r = &state["panel_widgets"][name];
    let r: Vec<f64> = (0..4)
        .map(|k| r[k].as_f64().unwrap_or_else(|| panic!("no widget {name}")))
        .collect();
    [r[0] + t * r[2], r[1] + 0.5 * r[3]]
}

#[test]
fn the_side_panel_opens_scene_files_keeps_the_scene_on_a_bad_one_and_sets_restitution() {
    let _one = ONE_WINDOW.lock().unwrap_or_else(|e| e.into_inner());
    let Some(x) = Xvfb::start("panel") else {
        return;
    };
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
    let app = Sandbox::start(&x, &["--paused"]);
    let s0 = app.wait_frames(2);
    assert_eq!(s0["panel_visible"], true, "the panel is shown by default");
    let panel_left = s0["panel_widgets"]["panel"][0].as_f64().unwrap();
    let right_wall = View::of(&s0).to_screen(vec2(&s0["size"]))[0];
    assert!(
        right_wall < panel_left,
        "the fit leaves the box clear of the panel: wall at {right_wall}, panel at {panel_left}"
    );
    let click = |at: [f64; 2]| {
        app.move_to(at);
        app.wait_frames(1);
        app.xdo(&["mousedown", "1"]);
        app.wait_frames(1);
        app.xdo(&["mouseup", "1"]);
        app.wait_frames(1);
    };

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
    assert!(
        (e - 0.25).abs() <= 0.02,
        "restitution follows the slider: {e}"
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

    // Out of the field, keys are shortcuts again: L hides the panel.
    app.xdo(&["key", "l"]);
    let s4 = app.wait_frames(3);
    assert_eq!(s4["panel_visible"], false);
    assert_eq!(s4["panel_widgets"], serde_json::json!({}));
    app.quit();
}

#[test]
fn j_stops_at_the_next_collision_comma_rewinds_space_resumes_and_x_exports() {
    let _one = ONE_WINDOW.lock().unwrap_or_else(|e| e.into_inner());
    let Some(x) = Xvfb::start("lesson") else {
        return;
    };
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
    let hit = app.wait_frames(3);
    assert_eq!(hit["paused"], true);
    assert_eq!(hit["collisions_recorded"], 1);
    let t = hit["time"].as_f64().unwrap();
    assert!(
        (t - contact).abs() < 1e-9,
        "stopped at t = {t}, contact at {contact}"
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
    assert_eq!(csv.len(), 3, "{csv:?}");

    // F12 saves what the window shows into the same folder.
    app.xdo(&["key", "F12"]);
    app.wait_frames(4);
    let png = out.path().join("head-on-equal-masses.png");
    let shot = image::open(&png)
        .unwrap_or_else(|e| panic!("{}: {e}", png.display()))
        .to_rgb8();
    assert_eq!(shot.dimensions(), (1280, 800));

    // Space resumes from the rewound moment and time runs on.
    app.xdo(&["key", "space"]);
    let resumed = app.wait_frames(20);
    assert_eq!(resumed["paused"], false);
    assert!(resumed["history_cursor"].is_null());
    assert!(resumed["time"].as_f64().unwrap() > back["time"].as_f64().unwrap());
    app.quit();
}

#[test]
fn dragging_the_selected_discs_arrow_tip_sets_its_velocity() {
    let _one = ONE_WINDOW.lock().unwrap_or_else(|e| e.into_inner());
    let Some(x) = Xvfb::start("aim") else {
        return;
    };
    let app = Sandbox::start(&x, &["--paused"]);
    app.move_to([300.0, 400.0]);
    app.xdo(&["key", "1"]); // head-on: disc 0 moves, at 0.5 s per arrow
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
    app.move_to(tip);
    app.wait_frames(2);
    app.xdo(&["mousedown", "1"]);
    app.wait_frames(2);
    for k in 1..=5 {
        let t = k as f64 / 5.0;
        app.move_to([
            tip[0] + t * (target[0] - tip[0]),
            tip[1] + t * (target[1] - tip[1]),
        ]);
        sleep(Duration::from_millis(30));
    }
    app.wait_frames(2);
    app.xdo(&["mouseup", "1"]);
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
