//! Playing the clicks the model chose each frame
//! ([`super::model::Sandbox::take_sounds`]): synthesised ([`synth`]), on
//! the desktop through ALSA loaded at run time ([`alsa`], Linux), in the
//! browser through Web Audio (`web/impulse.js`, by way of `crate::web`).
//! The device opens with the first click, so a sandbox that never turns
//! sound on never loads the library nor says anything about it.
//! `IMPULSE_SOUND_DEVICE` names another ALSA device than `default` (the
//! tests use `null`).

#[cfg(target_os = "linux")]
pub mod alsa;
// The browser plays the tones with Web Audio: no mixer there.
#[cfg_attr(target_arch = "wasm32", allow(dead_code))]
pub mod synth;

use super::model::sound::{SoundEvent, SoundKind};

/// The click an event makes.
pub fn click_of(event: &SoundEvent) -> synth::Click {
    synth::Click {
        tone: match event.kind {
            SoundKind::Disc => synth::DISC,
            SoundKind::Wall => synth::WALL,
        },
        amplitude: synth::amplitude(event.loudness),
        delay: event.delay,
    }
}

/// Plays this frame's clicks, each at its delay from now; never blocks.
pub fn play(events: Vec<SoundEvent>) {
    if events.is_empty() {
        return;
    }
    let clicks: Vec<synth::Click> = events.iter().map(click_of).collect();
    out(clicks);
}

#[cfg(target_arch = "wasm32")]
fn out(clicks: Vec<synth::Click>) {
    for c in clicks {
        let t = c.tone;
        crate::web::click(t.hz, c.amplitude, t.attack, t.decay, t.seconds, c.delay);
    }
}

#[cfg(target_os = "linux")]
fn out(clicks: Vec<synth::Click>) {
    thread_local! {
        /// The player, once the first click has tried to open it (`None`:
        /// no sound here, already said).
        static PLAYER: std::cell::OnceCell<Option<alsa::Player>> =
            const { std::cell::OnceCell::new() };
    }
    PLAYER.with(|player| {
        let player = player.get_or_init(|| {
            let device = std::env::var("IMPULSE_SOUND_DEVICE");
            alsa::Player::start_or_say(device.as_deref().unwrap_or("default"))
        });
        if let Some(player) = player {
            player.play(clicks);
        }
    });
}

#[cfg(not(any(target_os = "linux", target_arch = "wasm32")))]
fn out(_clicks: Vec<synth::Click>) {
    static SAID: std::sync::Once = std::sync::Once::new();
    SAID.call_once(|| {
        eprintln!(
            "impulse: no sound device (sound plays on Linux and in the browser); sound stays off"
        )
    });
}
