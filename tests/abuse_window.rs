//! The window under abuse, as a restless class would treat it: for a minute
//! (`IMPULSE_ABUSE_SECONDS`), seeded random clicks, drags, flings, wheel
//! zooms to the limits, clears, resets, deletes, presets, pauses, single
//! steps, method switches and overlay toggles, under Xvfb through xdotool.
//! Checked all along: the process lives, keeps drawing frames, writes a
//! sane state (finite, discs inside a closed box), and its memory does not
//! keep growing; at the end Ctrl+Q still closes it cleanly.

mod window_harness;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::{Duration, Instant};
use window_harness::{Sandbox, Xvfb};

fn main() -> std::process::ExitCode {
    window_harness::run(vec![(
        "a_minute_of_random_input_neither_crashes_nor_stalls_nor_leaks",
        a_minute_of_random_input_neither_crashes_nor_stalls_nor_leaks,
    )])
}

/// Keys a user may press at random (no quit, no full screen).
const KEYS: &[&str] = &[
    "space",
    "n",
    "n",
    "c",
    "r",
    "Delete",
    "BackSpace",
    "v",
    "m",
    "i",
    "Tab",
    "g",
    "e",
    "shift+e",
    "w",
    "shift+w",
    "y",
    "b",
    "k",
    "bracketleft",
    "bracketright",
    "1",
    "2",
    "3",
    "4",
    "5",
    "6",
    "7",
    "8",
    "9",
    "0",
    "f",
    "plus",
    "minus",
    "Escape",
    "a",
    "t",
    "o",
    "d",
    "z",
    "u",
    "j",
    "comma",
    "period",
    "shift+comma",
    "h",
    "Left",
    "Right",
    "Up",
    "Down",
    "Prior",
    "Next",
    "Home",
    "End",
    "l",
    "p",
    "ctrl+n",
    "ctrl+s",
    "x",
    "F2",
    "F3",
    "F4",
];

/// Resident memory of a process (kB), from /proc.
fn rss_kb(pid: u32) -> Option<u64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// Every number in the dump's discs is finite and, in a closed box, every
/// disc is inside the walls it has (a side without a wall lets discs out, as
/// the π blocks leave).
fn check_sane(s: &serde_json::Value) {
    let size = [
        s["size"][0].as_f64().unwrap(),
        s["size"][1].as_f64().unwrap(),
    ];
    let closed = s["boundary"] == "box";
    // `walls` (the sides that have one) is in the dump only when a box lacks
    // some.
    let wall = |side: &str| {
        s["walls"]
            .as_array()
            .is_none_or(|sides| sides.iter().any(|w| w == side))
    };
    for p in s["particles"].as_array().unwrap() {
        let pos = [p["pos"][0].as_f64(), p["pos"][1].as_f64()];
        let vel = [p["vel"][0].as_f64(), p["vel"][1].as_f64()];
        assert!(
            pos.iter()
                .chain(&vel)
                .all(|v| v.is_some_and(f64::is_finite)),
            "a disc went non-finite: {p}"
        );
        if closed {
            let (x, y) = (pos[0].unwrap(), pos[1].unwrap());
            let inside = (x >= -1e-6 || !wall("left"))
                && (x <= size[0] + 1e-6 || !wall("right"))
                && (y >= -1e-6 || !wall("bottom"))
                && (y <= size[1] + 1e-6 || !wall("top"));
            assert!(
                inside,
                "a disc outside the walls of the {size:?} m box (frame {}, walls {}): {p}",
                s["frame"], s["walls"]
            );
        }
    }
}

fn a_minute_of_random_input_neither_crashes_nor_stalls_nor_leaks() {
    let x = Xvfb::start("abuse");
    let seconds: f64 = std::env::var("IMPULSE_ABUSE_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(60.0);
    let out = tempfile::tempdir().unwrap();
    let mut app = Sandbox::start(
        &x,
        &["--out", out.path().to_str().unwrap(), "--autosave", "1"],
    );
    let pid = app.child.id();
    let mut rng = ChaCha8Rng::seed_from_u64(2026);
    let start = Instant::now();
    let (mut actions, mut memory) = (0u64, Vec::new());
    let mut last_frame = app.state()["frame"].as_u64().unwrap_or(0);
    let mut last_progress = Instant::now();
    let mut last_check = Instant::now();
    while start.elapsed().as_secs_f64() < seconds {
        let (px, py) = (
            rng.random_range(0..1280).to_string(),
            rng.random_range(0..800).to_string(),
        );
        match rng.random_range(0..10) {
            0..=3 => app.xdo(&["key", KEYS[rng.random_range(0..KEYS.len())]]),
            4 => app.xdo(&["mousemove", &px, &py, "click", "1"]),
            5 | 6 => {
                let (qx, qy) = (
                    rng.random_range(0..1280).to_string(),
                    rng.random_range(0..800).to_string(),
                );
                let button = ["1", "1", "2", "3"][rng.random_range(0..4)];
                app.xdo(&[
                    "mousemove",
                    &px,
                    &py,
                    "mousedown",
                    button,
                    "mousemove",
                    &qx,
                    &qy,
                    "mouseup",
                    button,
                ]);
            }
            7 => {
                // Zoom to a limit and some way back.
                let wheel = if rng.random_bool(0.5) { "4" } else { "5" };
                let clicks = rng.random_range(5..40).to_string();
                app.xdo(&[
                    "mousemove",
                    &px,
                    &py,
                    "click",
                    "--repeat",
                    &clicks,
                    "--delay",
                    "15",
                    wheel,
                ]);
            }
            8 => app.xdo(&[
                "mousemove",
                &px,
                &py,
                "click",
                "--repeat",
                "8",
                "--delay",
                "15",
                "1",
            ]),
            _ => app.xdo(&["key", "--repeat", "5", "--delay", "15", "n"]),
        }
        actions += 1;
        assert!(
            app.child.try_wait().expect("wait").is_none(),
            "the window died after {actions} actions"
        );
        if last_check.elapsed() >= Duration::from_secs(1) {
            last_check = Instant::now();
            let s = app.state();
            check_sane(&s);
            let frame = s["frame"].as_u64().unwrap_or(0);
            if frame > last_frame {
                last_frame = frame;
                last_progress = Instant::now();
            }
            assert!(
                last_progress.elapsed() < Duration::from_secs(15),
                "no frame drawn for 15 s after {actions} actions"
            );
            if let Some(kb) = rss_kb(pid) {
                memory.push((start.elapsed().as_secs_f64(), kb));
            }
        }
    }
    // Responsive at the end: it still draws and answers Ctrl+Q.
    let s = app.wait_frames(3);
    check_sane(&s);
    eprintln!("{actions} random actions in {seconds} s; memory (s, kB): {memory:?}");
    // Memory: the last third of the run may not exceed the middle third by
    // more than the rewind budget's worth of growth would allow for a small
    // scene (the history is capped; nothing else should accumulate).
    let third = |k: usize| -> u64 {
        let n = memory.len();
        memory[k * n / 3..((k + 1) * n / 3).max(k * n / 3 + 1).min(n)]
            .iter()
            .map(|&(_, kb)| kb)
            .max()
            .unwrap_or(0)
    };
    if memory.len() >= 6 {
        let (middle, last) = (third(1), third(2));
        assert!(
            last <= middle + middle / 2 + 64 * 1024,
            "memory kept growing: {middle} kB then {last} kB"
        );
    }
    app.quit();
}
