//! Never lose work, tested as it happens: the window autosaves, is killed
//! (as by a crash), and the next start offers the sandbox back; `R`
//! restores it exactly, a quit keeps unsaved work for the next start and
//! leaves nothing once it is saved, and a folder
//! that cannot be written gives a message while the window carries on.
//! Under Xvfb, driven by xdotool, read back through `--dump-state`.

mod window_harness;

use impulse::Scene;
use std::path::Path;
use std::thread::sleep;
use std::time::{Duration, Instant};
use window_harness::{Sandbox, Xvfb};

fn main() -> std::process::ExitCode {
    window_harness::run(vec![
        (
            "a_killed_window_is_offered_back_and_restored_exactly",
            a_killed_window_is_offered_back_and_restored_exactly,
        ),
        (
            "a_folder_that_cannot_be_written_gives_a_message_and_the_window_goes_on",
            a_folder_that_cannot_be_written_gives_a_message_and_the_window_goes_on,
        ),
    ])
}

/// Waits until the dump satisfies `ready`, and returns it.
fn wait_for(
    app: &Sandbox,
    what: &str,
    ready: impl Fn(&serde_json::Value) -> bool,
) -> serde_json::Value {
    let deadline = Instant::now() + Duration::from_secs(60);
    loop {
        let s = app.state();
        if ready(&s) {
            return s;
        }
        assert!(
            Instant::now() < deadline,
            "timed out waiting for {what}: {}",
            s["recovery"]
        );
        sleep(Duration::from_millis(50));
    }
}

fn positions(scene: &Scene) -> Vec<[f64; 2]> {
    scene.particles.iter().map(|p| p.pos.to_array()).collect()
}

fn a_killed_window_is_offered_back_and_restored_exactly() {
    let x = Xvfb::start("recovery");
    let state = tempfile::tempdir().unwrap();
    let file = state.path().join("impulse").join("recovery.toml");

    // A session that autosaves every half second, then dies. With nothing
    // of the person's in it, nothing is kept: the next start would not ask.
    let mut first = Sandbox::start_with_state(&x, &["--autosave", "0.5"], state.path());
    sleep(Duration::from_millis(1500));
    let s = first.wait_frames(2);
    assert_eq!(s["recovery"]["saves"], 0, "nothing of the person's to keep");
    assert!(!file.exists());
    // A change of theirs (gravity on): now it is kept.
    first.move_to([300.0, 300.0]);
    first.xdo(&["key", "g"]);
    let s = wait_for(&first, "two autosaves", |s| {
        s["recovery"]["saves"].as_u64() >= Some(2)
    });
    assert_eq!(s["recovery"]["file"], file.display().to_string());
    assert_eq!(s["recovery"]["offered"], false);
    first.child.kill().expect("kill");
    first.child.wait().expect("reaped");
    let saved = Scene::load(&file).expect("the recovery file is a readable scene");
    let count = s["metrics"]["count"].as_u64().unwrap() as usize;
    assert_eq!(saved.particles.len(), count);

    // The next start offers it and does not overwrite it meanwhile.
    let second = Sandbox::start_with_state(&x, &["--autosave", "0.5", "--paused"], state.path());
    let s = second.wait_frames(10);
    assert_eq!(s["recovery"]["offered"], true);
    sleep(Duration::from_millis(800));
    let s = second.wait_frames(2);
    assert_eq!(
        s["recovery"]["saves"], 0,
        "no autosave over an unanswered offer"
    );
    assert_eq!(
        Scene::load(&file).unwrap(),
        saved,
        "the offered file is untouched"
    );

    // R restores it, disc for disc.
    second.xdo(&["key", "r"]);
    let s = wait_for(&second, "the restore", |s| {
        s["recovery"]["offered"] == false
    });
    assert!(
        s["scene_origin"]
            .as_str()
            .unwrap()
            .starts_with("recovered from"),
        "{}",
        s["scene_origin"]
    );
    let restored: Vec<[f64; 2]> = s["particles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| [p["pos"][0].as_f64().unwrap(), p["pos"][1].as_f64().unwrap()])
        .collect();
    assert_eq!(
        restored,
        positions(&saved),
        "paused, so exactly where they were saved"
    );

    // The restored work is not saved yet: Ctrl+Q keeps it for the next
    // start (it used to go with the quit) …
    second.quit();
    let kept = Scene::load(&file).expect("Ctrl+Q with unsaved work keeps it");
    assert_eq!(positions(&kept), positions(&saved));
    let out = tempfile::tempdir().unwrap();
    let out_dir = out.path().to_str().expect("utf-8 temp path");
    let third = Sandbox::start_with_state(
        &x,
        &["--autosave", "0.5", "--paused", "--out", out_dir],
        state.path(),
    );
    let s = third.wait_frames(10);
    assert_eq!(
        s["recovery"]["offered"], true,
        "and the next start offers it"
    );
    // … and once it is saved, a close leaves nothing to recover.
    third.xdo(&["key", "r"]);
    wait_for(&third, "the restore", |s| s["recovery"]["offered"] == false);
    third.xdo(&["key", "ctrl+s"]);
    third.wait_frames(3);
    third.quit();
    assert_eq!(std::fs::read_dir(out.path()).unwrap().count(), 1, "saved");
    assert!(!file.exists(), "saved, then Ctrl+Q: no recovery file");
}

fn a_folder_that_cannot_be_written_gives_a_message_and_the_window_goes_on() {
    let x = Xvfb::start("recovery-fail");
    let dir = tempfile::tempdir().unwrap();
    // The state folder would have to be inside a regular file.
    let blocker = dir.path().join("not-a-folder");
    std::fs::write(&blocker, "").unwrap();
    let app = Sandbox::start_with_state(&x, &["--autosave", "0.3"], &blocker);
    // Something to keep (gravity on), so autosave tries.
    app.move_to([300.0, 300.0]);
    app.xdo(&["key", "g"]);
    let s = wait_for(&app, "the failure", |s| s["recovery"]["error"].is_string());
    assert!(s["recovery"]["error"]
        .as_str()
        .unwrap()
        .contains("Autosave"));
    assert_eq!(s["recovery"]["saves"], 0);
    let before = s["steps"].as_u64().unwrap();
    let s = app.wait_frames(20);
    assert!(
        s["steps"].as_u64().unwrap() > before,
        "the sandbox keeps running"
    );
    app.quit();
    assert!(!Path::new(&blocker).is_dir());
}
