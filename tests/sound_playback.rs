//! The desktop's playback path through ALSA's `null` device (which plays
//! nothing, on any machine with `libasound.so.2`, sound card or not): the
//! library loads, a synthesised click is written whole, the player's thread
//! streams clicks, and a device that cannot open says so in one line with
//! nothing of ALSA's own.
//!
//! The window's `src/app/audio/{synth,alsa}.rs` are compiled here as they
//! are (they use nothing else of the crate). On libtest-mimic: where the
//! library is missing the tests are reported as *ignored*, with the reason;
//! with `CI` set they fail instead.

#[allow(dead_code)]
#[path = "../src/app/audio/synth.rs"]
mod synth;

#[allow(dead_code)]
#[path = "../src/app/audio/alsa.rs"]
mod alsa;

use std::process::{Command, ExitCode};
use std::sync::atomic::Ordering;
use std::time::{Duration, Instant};

/// Set in the child process [`one_line_without_a_device`] starts: it opens
/// this device as the window would and exits.
const CHILD: &str = "IMPULSE_SOUND_TEST_CHILD";

fn main() -> ExitCode {
    if let Some(device) = std::env::var_os(CHILD) {
        let device = device.to_string_lossy();
        let started = alsa::Player::start_or_say(&device).is_some();
        return if started {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(3)
        };
    }
    let args = libtest_mimic::Arguments::from_args();
    let missing = alsa::load().err();
    let ci = std::env::var_os("CI").is_some();
    if let Some(why) = &missing {
        if ci {
            eprintln!("CI is set, so the sound tests must run, but {why}");
        } else {
            eprintln!("sound tests ignored: {why} (apt-get install libasound2)");
        }
    }
    let tests: [(&str, fn()); 4] = [
        (
            "the_null_device_plays_a_synthesised_click",
            null_device_plays,
        ),
        ("the_player_streams_clicks_in_time", player_streams),
        ("one_line_without_a_device", one_line_without_a_device),
        ("the_default_device_plays_or_says_one_line", default_device),
    ];
    let trials = tests
        .into_iter()
        .map(|(name, test)| {
            let why = missing.clone();
            let trial = libtest_mimic::Trial::test(name, move || match why {
                Some(why) if ci => Err(format!("CI is set, so this must run: {why}").into()),
                Some(why) => Err(format!("cannot run here: {why}").into()),
                None => {
                    test();
                    Ok(())
                }
            });
            match &missing {
                Some(_) if !ci => trial
                    .with_ignored_flag(true)
                    .with_kind("needs libasound.so.2"),
                _ => trial,
            }
        })
        .collect();
    libtest_mimic::run(&args, trials).exit_code()
}

fn null_device_plays() {
    let mut pcm = alsa::Pcm::open("null").expect("ALSA's null device opens");
    for tone in [synth::DISC, synth::WALL] {
        let samples = synth::pcm16(&synth::click(tone, synth::amplitude(0.8)));
        assert_eq!(pcm.write(&samples), Ok(samples.len()), "{tone:?}");
    }
}

fn player_streams() {
    let player = alsa::Player::start("null").expect("the player starts on null");
    let click = |tone, delay| synth::Click {
        tone,
        amplitude: synth::amplitude(1.0),
        delay,
    };
    player.play(vec![click(synth::DISC, 0.0), click(synth::WALL, 0.2)]);
    // The last click ends LEAD + 0.2 s + 35 ms after it was sent.
    let rate = f64::from(synth::SAMPLE_RATE);
    let end = ((alsa::LEAD + 0.2 + f64::from(synth::WALL.seconds)) * rate) as u64;
    let deadline = Instant::now() + Duration::from_secs(5);
    while player.written.load(Ordering::Relaxed) < end && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(10));
    }
    let written = player.written.load(Ordering::Relaxed);
    assert!(written >= end, "{written} frames written, {end} wanted");
    // Then it stops writing: nothing more to play.
    std::thread::sleep(Duration::from_millis(100));
    let later = player.written.load(Ordering::Relaxed);
    std::thread::sleep(Duration::from_millis(100));
    assert_eq!(player.written.load(Ordering::Relaxed), later, "idle");
    assert!(later < end + 2 * alsa::CHUNK as u64, "{later}");
}

/// Opens `device` in a child process as the window would: its exit status
/// and what it printed on stderr.
fn child(device: &str) -> (Option<i32>, String) {
    let out = Command::new(std::env::current_exe().unwrap())
        .env(CHILD, device)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn one_line_without_a_device() {
    // A device ALSA does not know: without the silent handler ALSA would
    // print "ALSA lib pcm.c:…:(snd_pcm_open_noupdate) Unknown PCM …".
    let (code, stderr) = child("impulse_no_such_device");
    assert_eq!(code, Some(3));
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "one line, no ALSA lib lines: {stderr}");
    assert!(
        lines[0].starts_with("impulse: no sound device (impulse_no_such_device: ")
            && lines[0].ends_with("); sound stays off"),
        "{stderr}"
    );
    // A card that does not exist: the same.
    let (code, stderr) = child("hw:31");
    assert_eq!((code, stderr.lines().count()), (Some(3), 1), "{stderr}");
    assert!(!stderr.contains("ALSA lib"), "{stderr}");
}

fn default_device() {
    // With a sound card it plays, silently; without (this test's CI), one
    // line.
    let (code, stderr) = child("default");
    match code {
        Some(0) => assert!(stderr.is_empty(), "{stderr}"),
        _ => {
            assert_eq!(stderr.lines().count(), 1, "{stderr}");
            assert!(stderr.starts_with("impulse: no sound device ("));
        }
    }
    println!("default device: {}", stderr.trim());
}
