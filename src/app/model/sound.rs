//! Sound: which clicks a frame plays, decided here without a window or a
//! sound card and played by the window (`super::super::audio`: ALSA on the
//! desktop, Web Audio in the browser).
//!
//! Each impact the core's ledger recorded during the frame's steps, between
//! discs or on a wall, is a [`SoundEvent`]: its kind (the pitch: a high
//! click between discs, a lower thud on a wall), its loudness and its delay
//! into the frame.
//!
//! - **Loudness** follows the impulse J on a log scale
//!   ([`loudness`]): [`QUIET_IMPULSE`] = 0.01 kg·m/s and less is the
//!   quietest click ([`QUIETEST`] = 0.15), [`LOUD_IMPULSE`] = 100 kg·m/s and
//!   more the loudest (1), evenly in log J between: each factor of 10 in
//!   the impulse adds 0.2125. A 1 kg disc into another at 2 m/s (J ≈ 2)
//!   is 0.64; the gas preset's discs (0.126 kg at about 2 m/s, J ≈ 0.1 to
//!   0.5) 0.36 to 0.51; the π blocks' from 0.62 (the last, J ≈ 1.5) and
//!   0.68 (the first, J ≈ 3) to 0.89 (J ≈ 30, the light disc at its
//!   fastest).
//!   The synthesiser's amplitude is the square of the loudness (a range of
//!   about 33 dB), so a gas patters softly beside a hard hit.
//! - **The cap**: a token bucket, [`RATE`] = 30 clicks a second with a
//!   burst of [`BURST`] = 8, in real time: at most 38 in any second, about
//!   one every other frame in a steady gas. Impacts closer together than
//!   the bucket allows are merged into the click before them (it takes the
//!   louder loudness and kind), so the loudest impact of a crowd is heard.
//!   Impacts 1/30 s apart or more are never dropped: the π blocks' 31 all
//!   play: their densest stretch, 13 clicks within 0.53 s at ×1 (28 to
//!   60 ms apart), stays below the rate. In the gas preset, about 400
//!   impacts a second become 31 clicks a second.
//! - **When**: only with sound on, the clock running and its time scale at
//!   most [`MAX_TIME_SCALE`] (×2): faster, the clicks would be a buzz. A
//!   paused world, a single step (N) and a rewind are silent.
//! - **The delay** is the impact's simulated time since the frame's first
//!   step, divided by the time scale: real seconds after the frame. In slow
//!   motion (×0.1) the π blocks' closest clicks are 0.27 s apart (0.28 s
//!   of their time; the steps fall on frames, which moves a click by up to
//!   a frame).

use super::clock::FixedStepClock;
use super::Sandbox;
use impulse::ledger::Impact;

/// Which click: the pitch says disc against disc or disc against wall.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SoundKind {
    Disc,
    Wall,
}

/// One click to play.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SoundEvent {
    pub kind: SoundKind,
    /// 0 (silent) to 1, already on a log scale of the impulse.
    pub loudness: f32,
    /// Real seconds after the frame that produced it.
    pub delay: f64,
}

/// At or below this impulse (kg·m/s), the quietest click.
pub const QUIET_IMPULSE: f64 = 0.01;
/// At or above this impulse (kg·m/s), the loudest.
pub const LOUD_IMPULSE: f64 = 100.0;
/// The loudness of the quietest click (an impact is never silent).
pub const QUIETEST: f32 = 0.15;
/// Clicks a second the cap lets through in the long run.
pub const RATE: f64 = 30.0;
/// Clicks the cap lets through at once after a quiet spell.
pub const BURST: f64 = 8.0;
/// Faster than this time scale, no sound.
pub const MAX_TIME_SCALE: f64 = 2.0;

/// The loudness of an impact of impulse `j` (kg·m/s): [`QUIETEST`] to 1,
/// evenly in log j from [`QUIET_IMPULSE`] to [`LOUD_IMPULSE`].
pub fn loudness(j: f64) -> f32 {
    if j.is_nan() || j <= QUIET_IMPULSE {
        return QUIETEST; // also NaN
    }
    let span = (LOUD_IMPULSE / QUIET_IMPULSE).log10();
    let x = ((j / QUIET_IMPULSE).log10() / span).min(1.0) as f32;
    QUIETEST + (1.0 - QUIETEST) * x
}

/// The impulse an impact gave (kg·m/s): to either disc of a pair (equal
/// and opposite), or the wall's to the disc.
pub fn impulse_of(impact: &Impact) -> f64 {
    match impact {
        Impact::Pair(c) => (c.masses[0] * (c.after[0] - c.before[0])).length(),
        Impact::Wall(w) => w.wall_impulse().length(),
    }
}

/// The kind of click an impact makes.
pub fn kind_of(impact: &Impact) -> SoundKind {
    match impact {
        Impact::Pair(_) => SoundKind::Disc,
        Impact::Wall(_) => SoundKind::Wall,
    }
}

/// The rate cap: a token bucket in real seconds.
#[derive(Clone, Debug, PartialEq)]
pub struct RateCap {
    tokens: f64,
    /// When the tokens were last counted (real s, the sound's clock).
    at: f64,
}

impl Default for RateCap {
    fn default() -> Self {
        RateCap {
            tokens: BURST,
            at: 0.0,
        }
    }
}

impl RateCap {
    /// Whether a click at real time `at` may play (it takes a token).
    pub fn admit(&mut self, at: f64) -> bool {
        if at > self.at {
            self.tokens = (self.tokens + (at - self.at) * RATE).min(BURST);
            self.at = at;
        }
        if self.tokens >= 1.0 {
            self.tokens -= 1.0;
            true
        } else {
            false
        }
    }
}

/// The sound switch, the cap and the clicks waiting for the window.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Sound {
    /// The switch (the top bar's button, S).
    pub on: bool,
    /// Clicks handed to the window so far (the dump's `sound.events_played`).
    pub played: u64,
    /// This frame's clicks, until the window takes them.
    pending: Vec<SoundEvent>,
    cap: RateCap,
    /// Real seconds of frames so far: the cap's clock.
    clock: f64,
}

impl Sound {
    /// Sound on or off from the start (the remembered choice).
    pub fn new(on: bool) -> Self {
        Sound {
            on,
            ..Sound::default()
        }
    }

    /// Whether impacts make clicks now: on, running, at most ×2.
    pub fn active(&self, clock: &FixedStepClock) -> bool {
        self.on && !clock.paused && clock.time_scale() <= MAX_TIME_SCALE
    }

    /// A frame of `frame_seconds` real seconds went by with these impacts
    /// (oldest first), its steps starting at simulated time `start`, at
    /// time scale `scale`: their clicks, capped, wait for the window.
    pub fn hear<'a>(
        &mut self,
        impacts: impl IntoIterator<Item = &'a Impact>,
        start: f64,
        scale: f64,
        frame_seconds: f64,
    ) {
        let first = self.pending.len();
        let mut events: Vec<SoundEvent> = impacts
            .into_iter()
            .map(|impact| SoundEvent {
                kind: kind_of(impact),
                loudness: loudness(impulse_of(impact)),
                delay: ((impact.time() - start) / scale).max(0.0),
            })
            .collect();
        events.sort_by(|a, b| a.delay.total_cmp(&b.delay));
        for event in events {
            if self.cap.admit(self.clock + event.delay) {
                self.pending.push(event);
            } else if let Some(kept) = self.pending[first..].last_mut() {
                // Merged into the click before: the louder is heard.
                if event.loudness > kept.loudness {
                    kept.loudness = event.loudness;
                    kept.kind = event.kind;
                }
            }
        }
        self.played += (self.pending.len() - first) as u64;
        self.clock += frame_seconds.clamp(0.0, 0.25);
    }

    /// A frame without sound: its time passes for the cap.
    pub fn silent_frame(&mut self, frame_seconds: f64) {
        self.clock += frame_seconds.clamp(0.0, 0.25);
    }

    /// The clicks waiting, for the window to play.
    pub fn take(&mut self) -> Vec<SoundEvent> {
        std::mem::take(&mut self.pending)
    }
}

impl Sandbox {
    /// This frame's clicks (empty while the sound is off); the window
    /// plays them, each `delay` after now.
    pub fn take_sounds(&mut self) -> Vec<SoundEvent> {
        self.session.sound.take()
    }

    /// Sound on or off (S, the top bar's button).
    pub(super) fn toggle_sound(&mut self) {
        let sound = &mut self.session.sound;
        sound.on = !sound.on;
        sound.pending.clear();
        let on = self.session.sound.on;
        self.toast(if on {
            crate::app::lang::tr!("sound-on")
        } else {
            crate::app::lang::tr!("sound-off")
        });
        // Remembered: on at the next start only if it was turned on.
        self.remember(|r| r.sound = on);
    }

    /// Before the frame's steps: the ledger's count and the simulated time,
    /// when impacts are to be heard.
    pub(super) fn listen(&self) -> Option<(u64, f64)> {
        let heard = self.session.sound.active(&self.clock);
        heard.then(|| (self.world.ledger.recorded_impacts(), self.world.time))
    }

    /// After the frame's steps: the clicks of the impacts recorded since
    /// [`Sandbox::listen`] (the newest the ledger keeps).
    pub(super) fn hear(&mut self, listened: Option<(u64, f64)>, frame_seconds: f64) {
        let sound = &mut self.session.sound;
        let Some((before, start)) = listened else {
            return sound.silent_frame(frame_seconds);
        };
        let ledger = &self.world.ledger;
        let new = ledger.recorded_impacts().saturating_sub(before);
        let new = usize::try_from(new).unwrap_or(usize::MAX).min(ledger.len());
        let mut impacts: Vec<&Impact> = ledger.impacts().rev().take(new).collect();
        impacts.reverse();
        let scale = self.clock.time_scale();
        sound.hear(impacts, start, scale, frame_seconds);
    }
}

#[cfg(test)]
mod tests;
