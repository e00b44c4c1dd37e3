//! The clicks, headlessly: the π blocks' 31, silence when paused or fast,
//! the cap on a gas, loudness and kind.

use super::super::tests::sandbox_with;
use super::super::Command;
use super::*;
use glam::DVec2;
use impulse::ledger::{Collision, Wall, WallHit};

/// Frames of 1/60 s.
const FRAME: f64 = 1.0 / 60.0;

/// A running sandbox on `file` with sound on at time scale `scale`.
fn sounding(dir: &std::path::Path, file: &str, scale: f64) -> Sandbox {
    let mut s = sandbox_with(dir, file, false, 0.0);
    // Remembered in `dir` from an earlier sandbox there, or turned on now.
    if !s.session.sound.on {
        s.apply(Command::ToggleSound);
    }
    assert!(s.session.sound.on);
    let k = super::super::clock::TIME_SCALES
        .iter()
        .position(|&x| x == scale)
        .unwrap();
    s.apply(Command::SetTimeScale(k));
    s
}

/// Runs `seconds` of real time in frames of 1/60 s; every click with the
/// real time it plays at (the frame's start plus its delay).
fn run(s: &mut Sandbox, seconds: f64) -> Vec<(f64, SoundEvent)> {
    let mut heard = Vec::new();
    let frames = (seconds / FRAME).round() as usize;
    for k in 0..frames {
        s.tick(FRAME, 1.0);
        let now = k as f64 * FRAME;
        heard.extend(s.take_sounds().into_iter().map(|e| (now + e.delay, e)));
    }
    heard
}

/// The shortest time between two clicks (s).
fn closest(heard: &[(f64, SoundEvent)]) -> f64 {
    heard
        .windows(2)
        .map(|w| w[1].0 - w[0].0)
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn the_pi_blocks_click_31_times_apart_in_slow_motion() {
    let dir = tempfile::tempdir().unwrap();
    for (scale, seconds, apart) in [(1.0, 14.0, 0.025), (0.1, 120.0, 0.25)] {
        let mut s = sounding(dir.path(), "preset-7-pi-blocks.toml", scale);
        let heard = run(&mut s, seconds);
        let w = &s.world;
        assert_eq!(w.total_pair_collisions + w.total_wall_hits, 31, "×{scale}");
        assert_eq!(heard.len(), 31, "×{scale}: every impact clicks");
        assert_eq!(s.session.sound.played, 31);
        let walls = heard
            .iter()
            .filter(|(_, e)| e.kind == SoundKind::Wall)
            .count();
        assert_eq!(walls as u64, w.total_wall_hits, "the wall hits thud");
        let gap = closest(&heard);
        println!("×{scale}: the closest clicks are {:.1} ms apart", gap * 1e3);
        assert!(gap >= apart, "×{scale}: {gap} s");
        // In order, and loudest while the light disc is fastest.
        assert!(heard.windows(2).all(|w| w[0].0 <= w[1].0));
        let loudest = heard.iter().map(|(_, e)| e.loudness).fold(0.0, f32::max);
        assert!(loudest > heard[0].1.loudness && loudest > heard[30].1.loudness);
    }
}

#[test]
fn a_paused_world_a_single_step_and_a_fast_one_are_silent() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sounding(dir.path(), "preset-8-gas.toml", 1.0);
    s.apply(Command::TogglePause);
    assert!(run(&mut s, 1.0).is_empty(), "paused");
    for _ in 0..30 {
        s.apply(Command::Step);
        s.tick(FRAME, 1.0);
    }
    assert!(s.world.total_pair_collisions > 0, "the steps collided");
    assert!(s.take_sounds().is_empty(), "single steps");
    for fast in [4.0, 8.0] {
        let mut s = sounding(dir.path(), "preset-7-pi-blocks.toml", fast);
        assert!(run(&mut s, 6.0).is_empty(), "×{fast}");
        assert_eq!(s.world.total_pair_collisions + s.world.total_wall_hits, 31);
    }
    // Off (the default where nothing was remembered): nothing, and ×2
    // still clicks.
    let fresh = tempfile::tempdir().unwrap();
    let mut s = sandbox_with(fresh.path(), "preset-8-gas.toml", false, 0.0);
    assert!(!s.session.sound.on && run(&mut s, 1.0).is_empty(), "off");
    let mut s = sounding(dir.path(), "preset-8-gas.toml", 2.0);
    assert!(!run(&mut s, 1.0).is_empty(), "×2");
}

#[test]
fn sound_turned_on_is_on_at_the_next_start_and_off_stays_off() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_with(dir.path(), "preset-8-gas.toml", false, 0.0);
    assert!(!s.session.sound.on, "off where it was never turned on");
    s.apply(Command::ToggleSound);
    let again = sandbox_with(dir.path(), "preset-8-gas.toml", false, 0.0);
    assert!(again.session.sound.on, "remembered on");
    s.apply(Command::ToggleSound);
    let again = sandbox_with(dir.path(), "preset-8-gas.toml", false, 0.0);
    assert!(!again.session.sound.on, "remembered off");
}

#[test]
fn a_gas_patters_within_the_cap() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sounding(dir.path(), "preset-8-gas.toml", 1.0);
    let seconds = 5.0;
    let heard = run(&mut s, seconds);
    let impacts = s.world.total_pair_collisions + s.world.total_wall_hits;
    let most = (RATE + BURST) as usize;
    for (k, (t, _)) in heard.iter().enumerate() {
        let within = heard[k..].iter().take_while(|(u, _)| *u < t + 1.0).count();
        assert!(within <= most, "{within} clicks in the second from {t}");
    }
    let per_second = heard.len() as f64 / seconds;
    println!(
        "gas: {impacts} impacts in {seconds} s, {} clicks ({per_second:.1} a second), closest {:.1} ms",
        heard.len(),
        closest(&heard) * 1e3
    );
    assert!(impacts as f64 > 3.0 * heard.len() as f64, "most are merged");
    assert!(per_second > 0.8 * RATE, "a steady patter: {per_second}");
    assert!(per_second <= RATE + BURST / seconds + 1e-9);
    // Soft: no click in the gas is loud.
    assert!(heard.iter().all(|(_, e)| e.loudness < 0.6));
}

#[test]
fn loudness_follows_the_impulse_on_a_log_scale_clamped() {
    assert_eq!(loudness(0.0), QUIETEST);
    assert_eq!(loudness(f64::NAN), QUIETEST);
    assert_eq!(loudness(QUIET_IMPULSE), QUIETEST);
    assert_eq!(loudness(LOUD_IMPULSE), 1.0);
    assert_eq!(loudness(1e9), 1.0);
    let decade = loudness(10.0) - loudness(1.0);
    assert!((decade - (1.0 - QUIETEST) / 4.0).abs() < 1e-6);
    assert!((loudness(1.0) - loudness(0.1) - decade).abs() < 1e-6);
    let mut last = 0.0;
    for k in -30..=30 {
        let l = loudness(10f64.powf(k as f64 / 10.0));
        assert!((QUIETEST..=1.0).contains(&l) && l >= last);
        last = l;
    }
}

fn pair(speed: f64) -> Impact {
    Impact::Pair(Collision {
        time: 0.0,
        discs: [0, 1],
        normal: DVec2::X,
        masses: [1.0, 1.0],
        before: [DVec2::new(speed, 0.0), DVec2::ZERO],
        after: [DVec2::ZERO, DVec2::new(speed, 0.0)],
        radii: [0.5; 2],
        spins_before: [0.0; 2],
        spins_after: [0.0; 2],
    })
}

fn wall(speed: f64) -> Impact {
    Impact::Wall(WallHit {
        time: 0.0,
        disc: 0,
        wall: Wall::Left,
        mass: 1.0,
        radius: 0.5,
        before: DVec2::new(-speed, 0.0),
        after: DVec2::new(speed, 0.0),
        spin_before: 0.0,
        spin_after: 0.0,
    })
}

#[test]
fn a_harder_impact_is_louder_and_a_wall_is_told_from_a_disc() {
    assert_eq!(impulse_of(&pair(2.0)), 2.0);
    assert_eq!(impulse_of(&wall(2.0)), 4.0);
    let mut sound = Sound::new(true);
    let impacts = [pair(0.5), pair(5.0), wall(0.5), wall(5.0)];
    sound.hear(&impacts, 0.0, 1.0, FRAME);
    let e = sound.take();
    assert_eq!(e.len(), 4);
    assert!(e[1].loudness > e[0].loudness && e[3].loudness > e[2].loudness);
    assert_eq!((e[0].kind, e[2].kind), (SoundKind::Disc, SoundKind::Wall));
    assert_eq!(sound.played, 4);
}

#[test]
fn the_cap_keeps_spaced_clicks_and_merges_a_crowd_into_the_loudest() {
    let mut cap = RateCap::default();
    assert!((0..1000).all(|k| cap.admit(k as f64 / RATE)), "never drops");
    // A crowd in one frame: the burst plays, the rest merge into it.
    let mut sound = Sound::new(true);
    let mut impacts: Vec<Impact> = (0..20).map(|_| pair(0.1)).collect();
    impacts.push(wall(50.0));
    sound.hear(&impacts, 0.0, 1.0, FRAME);
    let e = sound.take();
    assert_eq!(e.len(), BURST as usize);
    let last = e.last().unwrap();
    assert_eq!(last.kind, SoundKind::Wall, "the loudest is heard");
    assert_eq!(last.loudness, loudness(100.0));
    // The next frame, the bucket has refilled half a token: nothing yet.
    sound.hear(&impacts[..1], 0.0, 1.0, FRAME);
    assert!(sound.take().is_empty());
}

#[test]
fn the_delay_is_simulated_time_over_the_time_scale() {
    let mut sound = Sound::new(true);
    let mut late = pair(1.0);
    if let Impact::Pair(c) = &mut late {
        c.time = 10.004;
    }
    sound.hear([&late], 10.0, 0.1, FRAME);
    assert!((sound.take()[0].delay - 0.04).abs() < 1e-9);
}

#[test]
fn the_sound_switch_is_not_an_edit() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_with(dir.path(), "preset-8-gas.toml", false, 0.0);
    s.apply(Command::ToggleSound);
    assert!(s.session.sound.on);
    assert_eq!(s.undo.levels().0, 0);
    assert!(s.message().is_some_and(|m| m.starts_with("Sound on")));
    s.apply(Command::ToggleSound);
    assert!(!s.session.sound.on);
}
