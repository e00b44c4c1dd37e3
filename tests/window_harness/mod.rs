//! What the window tests share: a private Xvfb, the `impulse` binary on it
//! with a state dump, xdotool to drive it, and the camera maths to aim at
//! world points, the layout's common checks ([`check_layout`]), and the
//! `main` of every window test binary ([`run`]:
//! each `tests/*window.rs` has `harness = false`). Each binary uses a part
//! of it, hence the `dead_code` allowance.
#![allow(dead_code)]

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::{Mutex, MutexGuard};
use std::thread::sleep;
use std::time::{Duration, Instant};

/// What this machine lacks to run the window tests, if anything.
pub fn missing_tools() -> Option<String> {
    let missing: Vec<&str> = ["Xvfb", "xdotool"]
        .into_iter()
        .filter(|p| !have(p))
        .collect();
    (!missing.is_empty()).then(|| {
        format!(
            "{} not installed (apt-get install xvfb xdotool libgl1-mesa-dri libxi6 libxkbcommon0)",
            missing.join(" and ")
        )
    })
}

/// The window tests' `main` (each window test file has `harness = false`):
/// runs `tests` as libtest does, or, when Xvfb or xdotool is missing,
/// reports each as *ignored*, with the reason, instead of passing it.
/// With `CI` set a missing tool fails every test instead.
pub fn run(tests: Vec<(&'static str, fn())>) -> std::process::ExitCode {
    let args = libtest_mimic::Arguments::from_args();
    let missing = missing_tools();
    let ci = std::env::var_os("CI").is_some();
    if let Some(why) = &missing {
        if ci {
            eprintln!("CI is set, so the window tests must run, but {why}");
        } else {
            eprintln!("window tests ignored: {why}");
        }
    }
    let trials = tests
        .into_iter()
        .map(|(name, test)| {
            let why = missing.clone();
            let trial = libtest_mimic::Trial::test(name, move || match why {
                Some(why) if ci => {
                    Err(format!("CI is set, so the window tests must run: {why}").into())
                }
                Some(why) => Err(format!("cannot run here: {why}").into()),
                None => {
                    test();
                    Ok(())
                }
            });
            match &missing {
                Some(_) if !ci => trial
                    .with_ignored_flag(true)
                    .with_kind("needs Xvfb and xdotool"),
                _ => trial,
            }
        })
        .collect();
    libtest_mimic::run(&args, trials).exit_code()
}

/// One window at a time: two cores cannot render several at a usable rate.
static ONE_WINDOW: Mutex<()> = Mutex::new(());

pub fn have(program: &str) -> bool {
    Command::new("sh")
        .args(["-c", &format!("command -v {program}")])
        .stdout(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// A private X server; killed when dropped. While it lives, its test holds
/// [`ONE_WINDOW`], so the window tests of one binary run one at a time.
pub struct Xvfb {
    pub child: Child,
    pub display: String,
    _one: MutexGuard<'static, ()>,
}

impl Xvfb {
    /// Starts one (the tools were checked by [`run`]).
    pub fn start(test: &str) -> Xvfb {
        // A test that failed while holding the lock poisoned it; the next
        // one still runs.
        let one = ONE_WINDOW.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(why) = missing_tools() {
            panic!("{test}: {why}");
        }
        // Xvfb picks a free display itself and writes its number on stdout
        // once it accepts connections (-displayfd), so stale lock files of
        // killed servers and parallel runs cannot collide. By default an X
        // server resets when its last client leaves, and a window opened
        // during the reset fails (XOpenDisplay): -noreset, since a test may
        // close its window and open another on the same server.
        let mut child = Command::new("Xvfb")
            .args([
                "-noreset",
                "-displayfd",
                "1",
                "-screen",
                "0",
                "1920x1080x24",
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
        Xvfb {
            child,
            display,
            _one: one,
        }
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

/// How a window is started: on the start screen or straight on the scene;
/// with its edges smoothed as shipped or not.
#[derive(Default)]
struct Launch {
    start_screen: bool,
    as_shipped: bool,
}

/// The `impulse` window running on an Xvfb display.
pub struct Sandbox {
    pub child: Child,
    pub dump: PathBuf,
    pub display: String,
    /// Its `XDG_STATE_HOME` (recovery and settings files under `impulse/`).
    pub state: PathBuf,
    pub _dir: tempfile::TempDir,
}

impl Sandbox {
    /// The window with its own state folder (so its autosave is its own).
    /// Its edges are drawn unsmoothed (`--no-antialias`): under Xvfb the
    /// software renderer then draws a frame in less than half the time, and
    /// the tests read layout and behaviour, which the smoothing does not
    /// touch. [`Sandbox::start_as_shipped`] keeps the smoothing.
    pub fn start(x: &Xvfb, args: &[&str]) -> Sandbox {
        Sandbox::start_in(x, args, None, Launch::default())
    }

    /// The window with everything as shipped: its edges smoothed.
    pub fn start_as_shipped(x: &Xvfb, args: &[&str]) -> Sandbox {
        let launch = Launch {
            as_shipped: true,
            ..Launch::default()
        };
        Sandbox::start_in(x, args, None, launch)
    }

    /// The window keeping its recovery file in `state` (`XDG_STATE_HOME`).
    pub fn start_with_state(x: &Xvfb, args: &[&str], state: &Path) -> Sandbox {
        Sandbox::start_in(x, args, Some(state), Launch::default())
    }

    /// The window as a plain start opens it: on the start screen.
    pub fn start_plain(x: &Xvfb, args: &[&str]) -> Sandbox {
        let launch = Launch {
            start_screen: true,
            ..Launch::default()
        };
        Sandbox::start_in(x, args, None, launch)
    }

    fn start_in(x: &Xvfb, args: &[&str], state: Option<&Path>, launch: Launch) -> Sandbox {
        let dir = tempfile::tempdir().expect("temp dir");
        let state = state.unwrap_or(dir.path()).to_path_buf();
        let dump = dir.path().join("state.json");
        // English, unless the test asks for a language: the messages the
        // tests read are English, whatever the machine's locale.
        let lang = !args.contains(&"--lang");
        let child = Command::new(env!("CARGO_BIN_EXE_impulse"))
            .args(args)
            .args(if launch.start_screen {
                &[][..]
            } else {
                &["--no-start"][..]
            })
            .args(if launch.as_shipped {
                &[][..]
            } else {
                &["--no-antialias"][..]
            })
            .args(if lang { &["--lang", "en"][..] } else { &[][..] })
            .arg("--dump-state")
            .arg(&dump)
            .args(["--exit-after", "120"])
            .env("DISPLAY", &x.display)
            .env("XDG_STATE_HOME", &state)
            .stdout(Stdio::null())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("impulse starts");
        let sandbox = Sandbox {
            child,
            dump,
            display: x.display.clone(),
            state,
            _dir: dir,
        };
        sandbox.wait_frames(5);
        sandbox
    }

    /// The latest state dump.
    pub fn state(&self) -> Value {
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

    /// Waits, frame by frame for at most `frames`, until the state meets
    /// `ready`, and returns it; `what` names it in the failure.
    pub fn wait_for(&self, what: &str, frames: u64, ready: impl Fn(&Value) -> bool) -> Value {
        for _ in 0..frames {
            let s = self.wait_frames(1);
            if ready(&s) {
                return s;
            }
        }
        panic!("{what} did not happen within {frames} frames");
    }

    /// Waits until a panel's animations are over: the same widget
    /// rectangles two frames running (a folding section slides for a few).
    pub fn wait_still(&self) -> Value {
        let mut last = self.wait_frames(1);
        for _ in 0..120 {
            let s = self.wait_frames(1);
            if s["panel_widgets"] == last["panel_widgets"] {
                return s;
            }
            last = s;
        }
        panic!("the panels kept moving for 120 frames");
    }

    /// Waits until `n` more frames have been drawn, and returns the state.
    pub fn wait_frames(&self, n: u64) -> Value {
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

    pub fn xdo(&self, args: &[&str]) {
        let status = Command::new("xdotool")
            .args(args)
            .env("DISPLAY", &self.display)
            .status()
            .expect("xdotool runs");
        assert!(status.success(), "xdotool {args:?} failed");
    }

    /// A left drag from `from` to `to` (px) as a person makes it: press,
    /// six moves 30 ms apart, release.
    pub fn drag(&self, from: [f64; 2], to: [f64; 2]) {
        self.move_to(from);
        self.wait_frames(2);
        self.xdo(&["mousedown", "1"]);
        self.wait_frames(2);
        for k in 1..=6 {
            let t = k as f64 / 6.0;
            self.move_to([
                from[0] + t * (to[0] - from[0]),
                from[1] + t * (to[1] - from[1]),
            ]);
            std::thread::sleep(std::time::Duration::from_millis(30));
        }
        self.wait_frames(2);
        self.xdo(&["mouseup", "1"]);
    }

    /// A left click at `p` as a person makes it: move, press, release,
    /// with a frame between each.
    pub fn click(&self, p: [f64; 2]) {
        self.move_to(p);
        self.wait_frames(1);
        self.xdo(&["mousedown", "1"]);
        self.wait_frames(1);
        self.xdo(&["mouseup", "1"]);
        self.wait_frames(2);
    }

    pub fn move_to(&self, p: [f64; 2]) {
        self.xdo(&[
            "mousemove",
            &format!("{}", p[0].round()),
            &format!("{}", p[1].round()),
        ]);
    }

    /// Presses Ctrl+Q and returns the final state once the window has closed.
    pub fn quit(mut self) -> Value {
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
pub struct View {
    pub center: [f64; 2],
    pub scale: f64,
    /// Size of the world's rectangle (px).
    pub viewport: [f64; 2],
    /// Its top-left corner in the window (px).
    pub origin: [f64; 2],
}

impl View {
    pub fn of(state: &Value) -> View {
        let c = &state["camera"];
        let pair = |v: &Value| [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()];
        View {
            center: pair(&c["center"]),
            scale: c["scale"].as_f64().unwrap(),
            viewport: pair(&c["viewport"]),
            origin: pair(&c["origin"]),
        }
    }
    pub fn to_screen(&self, w: [f64; 2]) -> [f64; 2] {
        [
            self.origin[0] + self.viewport[0] / 2.0 + (w[0] - self.center[0]) * self.scale,
            self.origin[1] + self.viewport[1] / 2.0 - (w[1] - self.center[1]) * self.scale,
        ]
    }
    pub fn to_world(&self, s: [f64; 2]) -> [f64; 2] {
        [
            self.center[0] + (s[0] - self.origin[0] - self.viewport[0] / 2.0) / self.scale,
            self.center[1] - (s[1] - self.origin[1] - self.viewport[1] / 2.0) / self.scale,
        ]
    }
    /// The centre of the world's rectangle on screen.
    pub fn world_center(&self) -> [f64; 2] {
        [
            self.origin[0] + self.viewport[0] / 2.0,
            self.origin[1] + self.viewport[1] / 2.0,
        ]
    }
}

pub fn vec2(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

pub fn scene_file(dir: &Path, text: &str) -> PathBuf {
    let path = dir.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    path
}

pub fn asset(name: &str) -> String {
    format!("{}/assets/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// The centre of a rectangle [x, y, width, height] the dump gives for a
/// widget of the side panel, or a point a fraction `t` along its width.
pub fn widget(state: &Value, name: &str, t: f64) -> [f64; 2] {
    let r = &state["panel_widgets"][name];
    let r: Vec<f64> = (0..4)
        .map(|k| r[k].as_f64().unwrap_or_else(|| panic!("no widget {name}")))
        .collect();
    [r[0] + t * r[2], r[1] + 0.5 * r[3]]
}

/// [x, y, w, h] of a dump rectangle.
pub fn rect(v: &Value) -> [f64; 4] {
    std::array::from_fn(|k| {
        v[k].as_f64()
            .unwrap_or_else(|| panic!("not a rectangle: {v}"))
    })
}

/// The caption strip's rectangle [x, y, w, h]: the panel under the world.
pub fn caption_strip(s: &Value) -> [f64; 4] {
    let world = rect(&s["layout"]["world"]);
    panel_at(s, world[1] + world[3])
}

/// The panel whose top is at `top`.
fn panel_at(s: &Value, top: f64) -> [f64; 4] {
    s["layout"]["panels"]
        .as_array()
        .unwrap()
        .iter()
        .map(rect)
        .find(|r| (r[1] - top).abs() < 0.5 && r[3] > 0.0)
        .unwrap_or_else(|| panic!("no panel at y = {top} in {}", s["layout"]))
}

/// The open tab's content rectangle [x, y, w, h]: under the world and its
/// caption strip (a row, or taller for a long caption).
pub fn tab_content(s: &Value) -> [f64; 4] {
    let strip = caption_strip(s);
    panel_at(s, strip[1] + strip[3])
}

/// The window at a projector's size (1024×768, text size 2) in `lang`, on
/// the glancing hit run to its instant (J), the ledger open.
pub fn projector_at_impact(x: &Xvfb, lang: &str) -> Sandbox {
    let args = ["--size", "1024x768", "--ui-scale", "2", "--lang", lang];
    let app = Sandbox::start(x, &args);
    app.move_to([500.0, 200.0]);
    app.xdo(&["key", "4"]);
    app.wait_frames(3);
    app.xdo(&["key", "j"]);
    app.wait_for("the collision", 60, |s| s["ui"]["tab"] == "Collisions");
    app
}

pub fn focus(s: &Value) -> Option<String> {
    s["ui"]["focus"].as_str().map(str::to_string)
}

/// Presses Tab until `name` has the keys (at most `most` times).
pub fn tab_to(app: &Sandbox, name: &str, most: usize) -> Value {
    let mut seen = Vec::new();
    for _ in 0..most {
        app.xdo(&["key", "Tab"]);
        let s = app.wait_frames(3);
        if focus(&s).as_deref() == Some(name) {
            return s;
        }
        seen.push(focus(&s));
    }
    panic!("Tab never reached {name}: {seen:?}");
}

/// The glancing preset, paused, its first disc selected with Q, in a window
/// of `size` at text size `scale`.
pub fn glancing_disc_selected(x: &Xvfb, size: &str, scale: &str) -> Sandbox {
    let app = Sandbox::start(x, &["--paused", "--size", size, "--ui-scale", scale]);
    app.move_to([300.0, 300.0]);
    app.xdo(&["key", "4"]);
    app.wait_frames(3);
    app.xdo(&["key", "q"]);
    app
}

/// The head-on preset, paused, at `size` ("1366x768") and text size
/// `scale`, the pointer over the world.
pub fn head_on_paused(x: &Xvfb, size: &str, scale: &str) -> Sandbox {
    let preset = asset("preset-1-head-on.toml");
    let args = ["--paused", "--size", size, "--ui-scale", scale, &preset];
    let app = Sandbox::start(x, &args);
    app.move_to([500.0, 300.0]);
    app
}

/// The glancing preset at 1024×768 and text size 2 (with `more` on the
/// command line), its Discs tab open: a table wider than the window.
pub fn projector_discs_tab(x: &Xvfb, more: &[&str]) -> Sandbox {
    let args = [&["--size", "1024x768", "--ui-scale", "2"][..], more].concat();
    let app = Sandbox::start(x, &args);
    app.move_to([500.0, 200.0]);
    app.xdo(&["key", "4"]);
    app.wait_frames(3);
    let s = app.state();
    app.click(widget(&s, "tab_discs", 0.5));
    app.wait_for("the Discs tab", 60, |s| s["ui"]["tab"] == "Discs");
    app
}

/// The scene files saved in `dir`.
pub fn saved_scenes(dir: &Path) -> Vec<PathBuf> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect()
}

/// The scenes the sweep opens: the digit keys, then Ctrl+N.
pub const PRESET_KEYS: [&str; 11] = ["1", "2", "3", "4", "5", "6", "7", "8", "9", "0", "ctrl+n"];

/// Whether two rectangles share any area (touching edges do not count).
pub fn overlap(a: [f64; 4], b: [f64; 4]) -> bool {
    let e = 0.5; // half a pixel: egui rounds panel edges
    a[0] + e < b[0] + b[2]
        && b[0] + e < a[0] + a[2]
        && a[1] + e < b[1] + b[3]
        && b[1] + e < a[1] + a[3]
}

/// Checks one frame's layout; `what` names it in messages.
pub fn check_layout(s: &Value, what: &str, scale: f64, window: [f64; 2]) {
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

/// How far the list `name` is scrolled down, and how far it can be (px).
pub fn list_scroll(s: &Value, name: &str) -> (f64, f64) {
    let l = &s["ui"]["lists"][name];
    let y = |v: &Value| {
        v[1].as_f64()
            .unwrap_or_else(|| panic!("{name} in {}", s["ui"]))
    };
    (y(&l["offset"]), y(&l["max"]))
}
